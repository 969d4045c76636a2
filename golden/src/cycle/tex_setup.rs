//! Cycle-accurate model of texture setup (`hdl/src/cs/tex_setup.rs`, issue 17 item 4): the texture
//! planes s/w, t/w and 1/w of a visible triangle ([`crate::texcoord::setup`]) written into TdbT, the
//! texture half of the triangle database, at the triangle's index.
//!
//! Written from the timing below and the algorithmic model; it does not look at the RTL's registers.
//!
//! ## Ports (one clock)
//! * command stream in: `cmd_valid`, `cmd` ([`TexSetupCmd`]), `cmd_ready` (out);
//! * TdbT write port out: `tdbt_write_enable`, `tdbt_write_address` (the triangle index),
//!   `tdbt_write_data` (the record, [`TexPlanes`]); 0 while the enable is low;
//! * `busy` (out): a command is being processed.
//!
//! ## Timing (cycle 0 = the cycle in which `cmd_valid && cmd_ready`)
//! The same handshake as colour setup ([`crate::cycle::colour_setup`]): `cmd_ready` is low in the 3
//! cycles after a command is taken, so the two blocks, given the same stream, take each command in
//! the same cycle. The record is written [`TEX_SETUP_LATENCY`] = 23 cycles after it was taken: det
//! (cycles 1-3), its reciprocal (cycles 4-14), then the three planes one after another, one per
//! cycle, through the numerators, A and B, and C (cycles 13-22). Zero area (`det == 0`, never sent by
//! the host) gives constant planes at vertex 0's values, as colour setup does.

use crate::cycle::colour_setup::{SetupCmd, SetupPipe, SETUP_INTERVAL};
use crate::format::{Plane, WinVertex};
use crate::render::SetupCommand;
use crate::texcoord::{setup, TexPlanes};

/// Cycles from taking a command to its TdbT write (`hdl::cs::tex_setup::TEX_SETUP_LATENCY`).
pub const TEX_SETUP_LATENCY: u64 = 23;
/// Width of a vertex value (s/w, t/w or 1/w) on the command port, two's complement.
pub const TEX_VALUE_BITS: u32 = 33;

/// One texture-setup command at the port widths.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct TexSetupCmd {
    pub index: u16,
    pub x: [i32; 3],
    pub y: [i32; 3],
    /// `values[k]`: vertex k's s/w, t/w and 1/w ([`crate::texcoord::vertex_values`]).
    pub values: [[i64; 3]; 3],
}

impl TexSetupCmd {
    /// The port form of a textured host command; a missing texture or an out-of-range field is an
    /// error naming it.
    pub fn from_command(c: &SetupCommand) -> Result<TexSetupCmd, String> {
        let geometry = SetupCmd::from_command(c)?;
        let tex = c.tex.ok_or_else(|| format!("texture setup of triangle {}: the command has no texture values", c.index))?;
        let lim = 1i64 << (TEX_VALUE_BITS - 1);
        for (k, vk) in tex.iter().enumerate() {
            for (ch, &v) in vk.iter().enumerate() {
                if !(-lim..lim).contains(&v) {
                    let name = ["s/w", "t/w", "1/w"][ch];
                    return Err(format!("texture setup of triangle {}: vertex {k} {name} = {v} does not fit {TEX_VALUE_BITS} signed bits", c.index));
                }
            }
        }
        Ok(TexSetupCmd { index: geometry.index, x: geometry.x, y: geometry.y, values: tex })
    }

    /// The record the block writes for this command.
    pub fn record(&self) -> TexPlanes {
        let v = [0, 1, 2].map(|k| WinVertex { x: self.x[k] as i32, y: self.y[k] as i32, z: 0 });
        if crate::raster::det(&v) == 0 {
            let [sw, tw, q] = self.values[0].map(Plane::constant);
            return TexPlanes { sw, tw, q };
        }
        setup(&v, self.values)
    }
}

/// The block's inputs in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct TexSetupInputs {
    pub cmd_valid: bool,
    pub cmd: TexSetupCmd,
}

/// The block's outputs in one cycle (before its rising edge).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct TexSetupOutputs {
    pub cmd_ready: bool,
    pub busy: bool,
    pub write_enable: bool,
    pub write_address: u16,
    pub write_data: TexPlanes,
}

/// The cycle-accurate model.
#[derive(Clone, Debug)]
pub struct TexSetupModel {
    pipe: SetupPipe<TexPlanes>,
}

impl Default for TexSetupModel {
    fn default() -> Self {
        TexSetupModel { pipe: SetupPipe::new(TEX_SETUP_LATENCY, SETUP_INTERVAL) }
    }
}

impl TexSetupModel {
    fn outputs_of((cmd_ready, busy, write): (bool, bool, Option<(u16, TexPlanes)>)) -> TexSetupOutputs {
        let (write_address, write_data) = write.unwrap_or_default();
        TexSetupOutputs { cmd_ready, busy, write_enable: write.is_some(), write_address, write_data }
    }

    /// The outputs in the current cycle.
    pub fn outputs(&self) -> TexSetupOutputs {
        Self::outputs_of(self.pipe.outputs())
    }

    /// One clock: this cycle's outputs, then the rising edge with `inp`.
    pub fn step(&mut self, inp: &TexSetupInputs) -> TexSetupOutputs {
        let cmd = (inp.cmd_valid && self.pipe.outputs().0).then(|| (inp.cmd.index, inp.cmd.record()));
        Self::outputs_of(self.pipe.step(cmd))
    }
}

/// Colour setup and texture setup on one command stream (`hdl::cs::textured_setup`): a colour-setup
/// command with its texture values beside it, taken by both in the same cycle.
#[derive(Clone, Debug, Default)]
pub struct TexturedSetupModel {
    pub colour: crate::cycle::colour_setup::ColourSetupModel,
    pub texture: TexSetupModel,
}

impl TexturedSetupModel {
    /// One clock: `cmd` (if valid) with its texture values; this cycle's outputs of both blocks.
    pub fn step(&mut self, cmd: Option<(&SetupCmd, &[[i64; 3]; 3])>) -> (crate::cycle::colour_setup::SetupOutputs, TexSetupOutputs) {
        use crate::cycle::colour_setup::SetupInputs;
        let (c, values) = match cmd {
            Some((c, v)) => (*c, *v),
            None => (SetupCmd::default(), [[0; 3]; 3]),
        };
        let t = TexSetupCmd { index: c.index, x: c.x, y: c.y, values };
        let a = self.colour.step(&SetupInputs { cmd_valid: cmd.is_some(), cmd: c });
        let b = self.texture.step(&TexSetupInputs { cmd_valid: cmd.is_some(), cmd: t });
        assert_eq!(a.cmd_ready, b.cmd_ready, "the two setup blocks share one handshake");
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cmd() -> SetupCommand {
        let v = [(0, 0), (10 * crate::format::SUBPIXEL_ONE, 0), (0, 10 * crate::format::SUBPIXEL_ONE)].map(|(x, y)| WinVertex { x, y, z: 0 });
        SetupCommand { index: 9, v, values: [[0; 3]; 3], material: 0, flat: None, tex: Some([[0, 0, 1 << 24], [1 << 20, 0, 1 << 24], [0, 1 << 20, 1 << 23]]) }
    }

    #[test]
    fn a_textured_command_is_written_23_cycles_after_it_is_taken_with_the_golden_planes() {
        let c = TexSetupCmd::from_command(&cmd()).unwrap();
        let mut m = TexSetupModel::default();
        let mut writes = Vec::new();
        for t in 0..40 {
            let o = m.step(&TexSetupInputs { cmd_valid: t == 0, cmd: c });
            if o.write_enable {
                writes.push((t, o.write_address, o.write_data));
            }
        }
        assert_eq!(writes, vec![(23, 9, setup(&cmd().v, cmd().tex.unwrap()))]);
    }

    #[test]
    fn commands_without_texture_or_with_too_wide_values_are_rejected_by_name() {
        let e = TexSetupCmd::from_command(&SetupCommand { tex: None, ..cmd() }).unwrap_err();
        assert!(e.contains("triangle 9") && e.contains("no texture"), "{e}");
        let mut tex = cmd().tex.unwrap();
        tex[2][1] = 1 << 32;
        let e = TexSetupCmd::from_command(&SetupCommand { tex: Some(tex), ..cmd() }).unwrap_err();
        assert!(e.contains("vertex 2 t/w"), "{e}");
        tex[2][1] = -(1 << 32);
        assert!(TexSetupCmd::from_command(&SetupCommand { tex: Some(tex), ..cmd() }).is_ok());
    }
}
