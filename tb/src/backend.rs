//! What the CLI needs of a cycle-counting chipset backend beyond `golden::render::Chipset`, so that
//! `render --backend rtl` (the RustHDL simulation, [`crate::chipset::RtlChipset`]) and
//! `render --backend verilator` (the generated Verilog, [`crate::verilator::VerilatorChipset`]) share
//! one code path. [`render_timed`] runs one timed frame through either and keeps what the chipset
//! returned, for the figures (`chipset_figures`, `idxrender bench`).

use crate::chipset::{PhaseCycles, RtlChipset};
use crate::verilator::VerilatorChipset;
use golden::raster::{CullMode, FrontFace, RcCounts, TriResult};
use golden::render::{render_with, Chipset, Frame, RcCommand, RenderOptions, ScanOut, SetupCommand};
use golden::scene::Mesh;
use golden::shade::{PhongLights, Shading};

/// A chipset simulation that counts cycles per phase and may write a VCD.
pub trait CycleChipset: Chipset {
    /// Cycles per phase of the last frame.
    fn phases(&self) -> PhaseCycles;
    /// Close (flush) the VCD, if any.
    fn finish_vcd(&mut self);
}

impl CycleChipset for RtlChipset {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn finish_vcd(&mut self) {
        RtlChipset::finish_vcd(self)
    }
}

impl CycleChipset for VerilatorChipset {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn finish_vcd(&mut self) {
        VerilatorChipset::finish_vcd(self)
    }
}

/// One frame through a cycle-counting backend, timed, with what the chipset returned kept even when
/// `render_with` rejects the frame (a chipset whose I-buffer differs from the algorithmic model's), so
/// that a wrong frame can still be measured and compared rather than only refused.
pub struct TimedFrame {
    /// The frame, or why `render_with` refused it.
    pub frame: Result<Frame, String>,
    /// Seconds in `render_with`: the host program and the simulation (not building the simulator).
    pub secs: f64,
    /// Cycles per phase; `None` if the frame stopped before its scan-out ended.
    pub phases: Option<PhaseCycles>,
    /// The per-triangle results the chipset returned.
    pub results: Vec<TriResult>,
    /// Colour-setup commands the host sent: the triangles the chipset flagged visible.
    pub setup_commands: u64,
    /// What the scan-out produced.
    pub scanout: Option<ScanOut>,
}

/// Render one frame of `mesh` through `chip` (see [`TimedFrame`]).
pub fn render_timed(mesh: &Mesh, opts: &RenderOptions, chip: &mut dyn CycleChipset) -> TimedFrame {
    let mut rec = Recorder { chip, results: Vec::new(), setup_commands: 0, scanout: None };
    let t0 = std::time::Instant::now();
    let frame = render_with(mesh, opts, &mut rec);
    let secs = t0.elapsed().as_secs_f64();
    let phases = rec.scanout.is_some().then(|| rec.chip.phases());
    TimedFrame { frame, secs, phases, results: rec.results, setup_commands: rec.setup_commands, scanout: rec.scanout }
}

/// Passes every call through to the chipset and keeps what went in and came out.
struct Recorder<'a> {
    chip: &'a mut dyn CycleChipset,
    results: Vec<TriResult>,
    setup_commands: u64,
    scanout: Option<ScanOut>,
}

impl Chipset for Recorder<'_> {
    fn rasterize(&mut self, tris: &[RcCommand], cull: CullMode, front: FrontFace) -> Result<Vec<TriResult>, String> {
        let r = self.chip.rasterize(tris, cull, front)?;
        self.results = r.clone();
        Ok(r)
    }
    fn colour_setup(&mut self, cmds: &[SetupCommand]) -> Result<(), String> {
        self.setup_commands = cmds.len() as u64;
        self.chip.colour_setup(cmds)
    }
    fn scanout(&mut self, shading: Shading, lights: &PhongLights, background: [u8; 3]) -> Result<ScanOut, String> {
        let s = self.chip.scanout(shading, lights, background)?;
        self.scanout = Some(s.clone());
        Ok(s)
    }
    fn rc_counts(&self) -> Option<RcCounts> {
        self.chip.rc_counts()
    }
}
