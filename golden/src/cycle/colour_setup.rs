//! Cycle-accurate model of the colour-setup block (`hdl/src/cs/colour_setup.rs`), seed 001 §2.3.2
//! eqs. 6-7 and §3.1: one command in, one TdbS record out, exactly one reciprocal per triangle.
//!
//! Written from the timing specification below and the algorithmic model ([`colour_setup`],
//! [`flat_setup`]); it does not look at the RTL's registers, only at its ports.
//!
//! ## Ports (one clock)
//! * command stream in: `cmd_valid`, `cmd` ([`SetupCmd`]), `cmd_ready` (out);
//! * TdbS write port out: `tdbs_write_enable`, `tdbs_write_address` (the triangle index),
//!   `tdbs_write_data` (the record, [`TdbsEntry`]); the memory takes the write at the rising edge;
//! * `busy` (out): a command is being processed (its record is not yet written).
//!
//! ## Timing (cycle 0 = the cycle in which `cmd_valid && cmd_ready`; the command is taken at its edge)
//! A pipeline with a fixed schedule (the RTL's module documentation gives it stage by stage):
//! | cycles after taking | what happens |
//! |---|---|
//! | 1 ..= 4 | the 14 products of det and the six plane numerators (four multipliers) |
//! | 5 | \|det\| and its leading one start the reciprocal |
//! | 6 ..= 30 | the reciprocal's 25 restoring steps, one per cycle |
//! | 33 ..= 37 | A and B of the three channels (two multipliers), rounded and saturated |
//! | 36 ..= 40 | C of the three channels (two multipliers) |
//! | 41 ([`SETUP_LATENCY`]) | the TdbS write of `record()` |
//!
//! Every command takes this path: flat (its colour at every vertex, material 0), shaded, and zero area
//! (`det == 0`: constant planes at vertex 0's values, which the algorithmic model never needs: the RC
//! never flags a zero-area triangle visible). `cmd_ready` is low in the 3 cycles after a command is
//! taken, so commands are at least [`SETUP_INTERVAL`] = 4 cycles apart and up to 11 are in flight.
//! `busy` is high while any command is between the cycle after it was taken and its write cycle.

use crate::format::{Plane, WinVertex, WINDOW_BITS, WINDOW_MAX, WINDOW_MIN};
use crate::render::SetupCommand;
use crate::shade::{colour_setup, flat_setup, TdbsEntry};

/// Cycles from taking a command to its TdbS write (`hdl::cs::colour_setup::SETUP_LATENCY`).
pub const SETUP_LATENCY: u64 = 41;
/// Cycles between commands taken back to back (`hdl::cs::colour_setup::SETUP_INTERVAL`).
pub const SETUP_INTERVAL: u64 = 4;
/// Width of the triangle index (TdbS address) on the block's ports.
pub const SETUP_INDEX_BITS: u32 = 16;

/// One colour-setup command as it travels on the block's input stream: the fields are the port
/// widths (20-bit S11.8 coordinates, 16-bit signed vertex values, 16-bit index and material).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct SetupCmd {
    pub index: u16,
    /// S11.8 subpixels, [`WINDOW_MIN`]..=[`WINDOW_MAX`] (20 bits on the port).
    pub x: [i32; 3],
    pub y: [i32; 3],
    /// `values[k][c]`: vertex k, channel c (RGB888 or Q1.14 normal components).
    pub values: [[i16; 3]; 3],
    pub material: u16,
    pub flat: bool,
    pub flat_rgb: [u8; 3],
}

impl SetupCmd {
    /// The port form of a host command; an out-of-range field is an error naming it.
    pub fn from_command(c: &SetupCommand) -> Result<SetupCmd, String> {
        if c.index == 0 || c.index >= 1 << SETUP_INDEX_BITS {
            return Err(format!(
                "colour setup: triangle index {} does not fit the block's {}-bit TdbS address (1..={})",
                c.index,
                SETUP_INDEX_BITS,
                (1u32 << SETUP_INDEX_BITS) - 1
            ));
        }
        let coord = |v: i32, what: &str, k: usize| -> Result<i32, String> {
            if (WINDOW_MIN..=WINDOW_MAX).contains(&v) {
                Ok(v)
            } else {
                Err(format!("colour setup of triangle {}: vertex {k} {what} = {v} subpixels is outside the {WINDOW_BITS}-bit S11.8 range", c.index))
            }
        };
        let mut x = [0i32; 3];
        let mut y = [0i32; 3];
        for k in 0..3 {
            x[k] = coord(c.v[k].x, "x", k)?;
            y[k] = coord(c.v[k].y, "y", k)?;
        }
        let mut values = [[0i16; 3]; 3];
        if c.flat.is_none() {
            for (k, (out, vin)) in values.iter_mut().zip(&c.values).enumerate() {
                for (ch, (o, &v)) in out.iter_mut().zip(vin).enumerate() {
                    *o = i16::try_from(v).map_err(|_| {
                        format!("colour setup of triangle {}: vertex {k} channel {ch} value {v} does not fit 16 signed bits", c.index)
                    })?;
                }
            }
        }
        Ok(SetupCmd {
            index: c.index as u16,
            x,
            y,
            values,
            material: c.material,
            flat: c.flat.is_some(),
            flat_rgb: c.flat.unwrap_or([0; 3]),
        })
    }

    /// The record the block writes for this command (the algorithmic model, plus the defined
    /// zero-area case).
    pub fn record(&self) -> TdbsEntry {
        if self.flat {
            return flat_setup(self.flat_rgb);
        }
        let v = [0, 1, 2].map(|k| WinVertex { x: self.x[k] as i32, y: self.y[k] as i32, z: 0 });
        let values = self.values.map(|vk| vk.map(|c| c as i64));
        if crate::raster::det(&v) == 0 {
            return TdbsEntry { planes: values[0].map(Plane::constant), material: self.material };
        }
        colour_setup(&v, values, self.material)
    }

}

/// The block's inputs in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct SetupInputs {
    pub cmd_valid: bool,
    pub cmd: SetupCmd,
}

/// The TdbS memory write port in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct TdbsWrite {
    pub enable: bool,
    pub address: u16,
    pub data: TdbsEntry,
}

/// The block's outputs in one cycle (before its rising edge).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct SetupOutputs {
    pub cmd_ready: bool,
    pub busy: bool,
    pub tdbs_write: TdbsWrite,
}

/// The timing both setup blocks share (colour setup here, texture setup in
/// [`crate::cycle::tex_setup`]): a command taken when `ready`, at most one per `interval` cycles, its
/// record written `latency` cycles after the cycle it was taken in, `busy` in between.
#[derive(Clone, Debug)]
pub struct SetupPipe<R> {
    latency: u64,
    interval: u64,
    /// Commands in flight: (cycles left until the write cycle, index, record); the write cycle itself
    /// has 1 left.
    flight: std::collections::VecDeque<(u64, u16, R)>,
    /// Cycles since the last command was taken (saturating; `interval` or more: ready).
    since: u64,
    /// Commands taken so far.
    pub taken: u64,
}

impl<R: Copy> SetupPipe<R> {
    pub fn new(latency: u64, interval: u64) -> SetupPipe<R> {
        SetupPipe { latency, interval, flight: Default::default(), since: interval, taken: 0 }
    }

    /// This cycle's (ready, busy, write): they depend on the state only.
    pub fn outputs(&self) -> (bool, bool, Option<(u16, R)>) {
        let write = self.flight.front().filter(|f| f.0 == 1).map(|&(_, a, r)| (a, r));
        (self.since >= self.interval, !self.flight.is_empty(), write)
    }

    /// One clock: this cycle's outputs, then the rising edge, taking `cmd` (index and the record it
    /// will write) if it is valid and the block ready.
    pub fn step(&mut self, cmd: Option<(u16, R)>) -> (bool, bool, Option<(u16, R)>) {
        let out = self.outputs();
        if out.2.is_some() {
            self.flight.pop_front();
        }
        for f in self.flight.iter_mut() {
            f.0 -= 1;
        }
        self.since = (self.since + 1).min(self.interval);
        if let (true, Some((index, record))) = (out.0, cmd) {
            self.flight.push_back((self.latency, index, record));
            self.since = 1;
            self.taken += 1;
        }
        out
    }
}

/// The cycle-accurate model.
#[derive(Clone, Debug)]
pub struct ColourSetupModel {
    pipe: SetupPipe<TdbsEntry>,
}

impl Default for ColourSetupModel {
    fn default() -> Self {
        Self::new()
    }
}

impl ColourSetupModel {
    pub fn new() -> ColourSetupModel {
        ColourSetupModel { pipe: SetupPipe::new(SETUP_LATENCY, SETUP_INTERVAL) }
    }

    /// Commands taken so far.
    pub fn taken(&self) -> u64 {
        self.pipe.taken
    }

    fn outputs_of((cmd_ready, busy, write): (bool, bool, Option<(u16, TdbsEntry)>)) -> SetupOutputs {
        let tdbs_write = write.map_or(TdbsWrite::default(), |(address, data)| TdbsWrite { enable: true, address, data });
        SetupOutputs { cmd_ready, busy, tdbs_write }
    }

    /// The outputs in the current cycle (they depend on the state only).
    pub fn outputs(&self) -> SetupOutputs {
        Self::outputs_of(self.pipe.outputs())
    }

    /// One clock: returns this cycle's outputs, then takes the rising edge with `inp`.
    pub fn step(&mut self, inp: &SetupInputs) -> SetupOutputs {
        let cmd = (inp.cmd_valid && self.pipe.outputs().0).then(|| (inp.cmd.index, inp.cmd.record()));
        Self::outputs_of(self.pipe.step(cmd))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::Screen;
    use crate::host::Camera;
    use crate::raster::{CullMode, FrontFace};
    use crate::render::{render_with, GoldenChipset, RenderOptions};
    use crate::scene::{builtin, Winding};
    use crate::shade::Shading;

    fn record_frame(name: &str, shading: Shading) -> GoldenChipset {
        let mesh = if name == "teapot" { builtin::teapot(6) } else { builtin::scene(name).unwrap() };
        let screen = Screen::new(160, 100).unwrap();
        let opts = RenderOptions {
            screen,
            camera: Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0),
            shading,
            cull: CullMode::Back,
            front: if mesh.front_face == Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw },
            lighting: Default::default(),
            index_bits: 16,
            rc_type: crate::raster::RcType::IV,
            texturing: None,
            background: [10, 20, 30],
        };
        let mut rec = GoldenChipset::new(screen);
        render_with(&mesh, &opts, &mut rec).unwrap();
        rec
    }

    /// Drive the model with the commands (with gaps of `gap` idle cycles) and collect the TdbS it writes.
    fn run_model(cmds: &[SetupCmd], gap: u64) -> (Vec<TdbsEntry>, u64) {
        let mut m = ColourSetupModel::new();
        let mut tdbs = Vec::new();
        let mut next = 0;
        let mut idle = 0;
        let mut cycles = 0;
        while next < cmds.len() || m.outputs().busy {
            let valid = next < cmds.len() && idle == 0;
            let inp = SetupInputs { cmd_valid: valid, cmd: if valid { cmds[next] } else { SetupCmd::default() } };
            let out = m.step(&inp);
            cycles += 1;
            if out.tdbs_write.enable {
                let a = out.tdbs_write.address as usize;
                if tdbs.len() <= a {
                    tdbs.resize(a + 1, TdbsEntry::default());
                }
                tdbs[a] = out.tdbs_write.data;
            }
            if valid && out.cmd_ready {
                next += 1;
                idle = gap;
            } else if idle > 0 {
                idle -= 1;
            }
        }
        (tdbs, cycles)
    }

    #[test]
    fn colour_setup_model_writes_the_golden_tdbs_of_real_frames() {
        for name in builtin::SCENES {
            for shading in [Shading::Gouraud, Shading::Flat, Shading::Phong] {
                let rec = record_frame(name, shading);
                assert!(!rec.setups.is_empty(), "{name}: no visible triangle");
                let cmds: Vec<SetupCmd> = rec.setups.iter().map(|c| SetupCmd::from_command(c).unwrap()).collect();
                let (tdbs, _) = run_model(&cmds, 0);
                for c in &rec.setups {
                    let i = c.index as usize;
                    assert_eq!(tdbs[i], rec.tdbs[i], "{name} {shading:?}: TdbS record {i}");
                }
            }
        }
    }

    #[test]
    fn back_to_back_commands_are_taken_every_four_cycles_and_written_41_cycles_later() {
        assert_eq!((SETUP_INTERVAL, SETUP_LATENCY), (4, 41), "the figures in the test's name");
        let mut cmd = SetupCmd { index: 3, x: [0, 160, 0], y: [0, 0, 160], ..Default::default() };
        cmd.values = [[255, 0, 0], [0, 255, 0], [0, 0, 255]];
        for cmds in [vec![cmd; 10], vec![SetupCmd { flat: true, index: 1, ..Default::default() }; 10]] {
            let (_, cycles) = run_model(&cmds, 0);
            // Taken in cycles 0, 4, ..., 36; the last written in 36 + 41; plus the cycle seen idle.
            assert_eq!(cycles, 9 * SETUP_INTERVAL + SETUP_LATENCY + 1);
        }
    }

    #[test]
    fn out_of_range_commands_are_rejected_with_the_field_named() {
        let good = SetupCommand {
            index: 5,
            v: [WinVertex { x: 0, y: 0, z: 0 }; 3],
            values: [[0; 3]; 3],
            material: 0,
            flat: None,
            tex: None,
        };
        assert!(SetupCmd::from_command(&good).is_ok());
        let e = SetupCmd::from_command(&SetupCommand { index: 70000, ..good }).unwrap_err();
        assert!(e.contains("index 70000"), "{e}");
        let mut v = good.v;
        v[2].y = 600_000;
        let e = SetupCmd::from_command(&SetupCommand { v, ..good }).unwrap_err();
        assert!(e.contains("vertex 2 y"), "{e}");
        let mut values = good.values;
        values[1][2] = -40000;
        let e = SetupCmd::from_command(&SetupCommand { values, ..good }).unwrap_err();
        assert!(e.contains("vertex 1 channel 2"), "{e}");
    }
}
