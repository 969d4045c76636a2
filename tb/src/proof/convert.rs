//! Conversions between the golden model's PROOF types and the RTL's payload structs.

use golden::proof::format::{Entry, ObjectParams, Slot};
use hdl::proof::{ObjParams, ProofSlot};
use rust_hdl::prelude::*;

fn b<const N: usize>(v: i64) -> Bits<N> {
    let m = if N >= 64 { u64::MAX } else { (1u64 << N) - 1 };
    Bits::<N>::from(v as u64 & m)
}

fn sext(v: u64, bits: usize) -> i64 {
    ((v << (64 - bits)) as i64) >> (64 - bits)
}

pub fn slot_to_rtl(s: &Slot) -> ProofSlot {
    let e = &s.entry;
    ProofSlot {
        x: b(s.x as i64),
        y: b(s.y as i64),
        last: s.last,
        has_entry: s.has_entry,
        id: b(e.id as i64),
        depth: b(e.depth as i64),
        full: e.full,
        nx: b(e.normal[0] as i64),
        ny: b(e.normal[1] as i64),
        nz: b(e.normal[2] as i64),
        d0: b(e.dist[0] as i64),
        d1: b(e.dist[1] as i64),
        d2: b(e.dist[2] as i64),
    }
}

pub fn slot_from_rtl(s: &ProofSlot) -> Slot {
    let i16_of = |x: Bits<16>| sext(x.to_u64(), 16) as i16;
    Slot {
        x: s.x.to_u64() as u16,
        y: s.y.to_u64() as u16,
        last: s.last,
        has_entry: s.has_entry,
        entry: Entry {
            id: s.id.to_u64() as u16,
            depth: s.depth.to_u64() as u32,
            full: s.full,
            normal: [i16_of(s.nx), i16_of(s.ny), i16_of(s.nz)],
            dist: [i16_of(s.d0), i16_of(s.d1), i16_of(s.d2)],
        },
    }
}

pub fn params_to_rtl(p: &ObjectParams) -> ObjParams {
    let e = &p.edges;
    ObjParams {
        id: b(p.id as i64),
        x0: b(p.x0 as i64),
        x1: b(p.x1 as i64),
        y0: b(p.y0 as i64),
        y1: b(p.y1 as i64),
        e0_d: b(e[0].d0 as i64),
        e0_sx: b(2 * e[0].cos as i64),
        e0_sy: b(2 * e[0].sin as i64),
        e0_tn: b(e[0].t_none as i64),
        e0_tf: b(e[0].t_full as i64),
        e1_d: b(e[1].d0 as i64),
        e1_sx: b(2 * e[1].cos as i64),
        e1_sy: b(2 * e[1].sin as i64),
        e1_tn: b(e[1].t_none as i64),
        e1_tf: b(e[1].t_full as i64),
        e2_d: b(e[2].d0 as i64),
        e2_sx: b(2 * e[2].cos as i64),
        e2_sy: b(2 * e[2].sin as i64),
        e2_tn: b(e[2].t_none as i64),
        e2_tf: b(e[2].t_full as i64),
        z_v: b(p.z.v0),
        z_dx: b(p.z.dx),
        z_dy: b(p.z.dy),
        nx_v: b(p.n[0].v0),
        nx_dx: b(p.n[0].dx),
        nx_dy: b(p.n[0].dy),
        ny_v: b(p.n[1].v0),
        ny_dx: b(p.n[1].dx),
        ny_dy: b(p.n[1].dy),
        nz_v: b(p.n[2].v0),
        nz_dx: b(p.n[2].dx),
        nz_dy: b(p.n[2].dy),
        opaque: p.alpha >= golden::proof::format::ALPHA_ONE,
    }
}

/// Hex digits of a Bits value of any width, most significant first.
pub fn hex_of<const N: usize>(v: Bits<N>) -> String {
    let digits = N.div_ceil(4);
    (0..digits)
        .rev()
        .map(|d| {
            let nibble = (0..4).filter(|j| 4 * d + j < N && v.get_bit(4 * d + j)).map(|j| 1u32 << j).sum::<u32>();
            char::from_digit(nibble, 16).unwrap()
        })
        .collect()
}

/// A 128-bit configuration word on the 96-bit `cfg_data` port.
pub fn bits96(v: u128) -> Bits<96> {
    Bits::<96>::from(v as u64) | (Bits::<96>::from((v >> 64) as u64) << 64)
}

/// One cycle of recorded vectors of a configured stage top (shading, 1x1 and 2x2 filter: the same
/// ports, `cfg_*`, `upstream`, `downstream`), given the stream payloads as hex.
#[allow(clippy::too_many_arguments)]
pub fn cfg_stage_row(
    cfg: Option<golden::proof::cycle_shade::CfgWrite>,
    up_valid: bool,
    up: String,
    down_ready: bool,
    up_ready: bool,
    down_valid: bool,
    down: String,
) -> Vec<String> {
    let c = cfg.unwrap_or_default();
    vec![
        format!("{}", cfg.is_some() as u8),
        format!("{:x}", c.sel),
        format!("{:x}", c.addr),
        hex_of(bits96(c.data)),
        format!("{}", up_valid as u8),
        up,
        format!("{}", down_ready as u8),
        format!("{}", up_ready as u8),
        format!("{}", down_valid as u8),
        down,
    ]
}
