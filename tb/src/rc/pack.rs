//! The RC's port words from the cycle model's commands (`golden::cycle::rc::RcCmd` into
//! `hdl::rc::RcCommand`), shared by the RC bench, its Verilog replay and the chipset backends.

use golden::cycle::rc::{CmdKind, RcCmd};
use golden::raster::{CullMode, FrontFace};
use hdl::rc::{RcCommand, CMD_END_OF_FRAME, CMD_FRAME, CMD_TRIANGLE, CULL_BACK, CULL_FRONT, CULL_NONE};
use rust_hdl::prelude::*;

/// The RC's command port word for a command.
pub fn command_word(c: &RcCmd) -> RcCommand {
    let b20 = crate::common::window_bits;
    let b24 = |v: u32| Bits::<24>::from(v as u64);
    RcCommand {
        kind: match c.kind {
            CmdKind::Frame => CMD_FRAME,
            CmdKind::Triangle => CMD_TRIANGLE,
            CmdKind::EndOfFrame => CMD_END_OF_FRAME,
        }
        .into(),
        clear: c.clear,
        index: (c.index as u64).into(),
        cull: match c.cull {
            CullMode::Back => CULL_BACK,
            CullMode::Front => CULL_FRONT,
            CullMode::None => CULL_NONE,
        }
        .into(),
        front_cw: c.front == FrontFace::Cw,
        x0: b20(c.v[0].x),
        y0: b20(c.v[0].y),
        z0: b24(c.v[0].z),
        x1: b20(c.v[1].x),
        y1: b20(c.v[1].y),
        z1: b24(c.v[1].z),
        x2: b20(c.v[2].x),
        y2: b20(c.v[2].y),
        z2: b24(c.v[2].z),
    }
}
