//! What the CLI needs of a cycle-counting chipset backend beyond `golden::render::Chipset`, so that
//! `render --backend rtl` (the RustHDL simulation, [`crate::chipset::RtlChipset`]) and
//! `render --backend verilator` (the generated Verilog, [`crate::verilator::VerilatorChipset`]) share
//! one code path. [`render_timed`] runs one timed frame through either and keeps what the chipset
//! returned, for the figures (`chipset_figures`, `idxrender bench`).

use crate::chipset::{ChipsetTop, PhaseCycles, RtlChipsetOf};
use crate::verilator::VerilatorChipset;
use golden::raster::TriResult;
use golden::render::{render_frames_with, Chipset, Frame, FrameJob, FrameOut, LowerPipeline, RenderOptions, ScanOut};
use golden::scene::Mesh;

/// A chipset simulation that counts cycles per phase and may write a VCD.
pub trait CycleChipset: Chipset {
    /// Cycles per phase of the last frame.
    fn phases(&self) -> PhaseCycles;
    /// Cycles since reset.
    fn cycles(&self) -> u64;
    /// Cycles per phase of every frame of the last run.
    fn frame_phases(&self) -> Vec<PhaseCycles>;
    /// Close (flush) the VCD, if any.
    fn finish_vcd(&mut self);
}

impl<T: ChipsetTop> CycleChipset for RtlChipsetOf<T> {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn cycles(&self) -> u64 {
        self.cycle
    }
    fn frame_phases(&self) -> Vec<PhaseCycles> {
        self.frame_phases.clone()
    }
    fn finish_vcd(&mut self) {
        RtlChipsetOf::finish_vcd(self)
    }
}

impl CycleChipset for VerilatorChipset {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn cycles(&self) -> u64 {
        self.cycle
    }
    fn frame_phases(&self) -> Vec<PhaseCycles> {
        self.frame_phases.clone()
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
    render_timed_frames(mesh, opts, 1, chip).pop().expect("one frame")
}

/// Render `mesh` `frames` times back to back through `chip` in one run: a [`TimedFrame`] per frame
/// (`secs` is the whole run's; `phases` of frame k > 1 include the frame interval). When the run
/// fails, every frame carries the error and no phases.
pub fn render_timed_frames(mesh: &Mesh, opts: &RenderOptions, frames: usize, chip: &mut dyn CycleChipset) -> Vec<TimedFrame> {
    let mut rec = Recorder { chip, outs: Vec::new() };
    let t0 = std::time::Instant::now();
    let jobs: Vec<(&Mesh, &RenderOptions)> = (0..frames.max(1)).map(|_| (mesh, opts)).collect();
    let result = render_frames_with(&jobs, &mut rec);
    let secs = t0.elapsed().as_secs_f64();
    let outs = std::mem::take(&mut rec.outs);
    let phases = if outs.len() == jobs.len() { rec.chip.frame_phases() } else { Vec::new() };
    (0..jobs.len())
        .map(|k| {
            let out = outs.get(k).cloned();
            let (results, scanout) = match out {
                Some(o) => (o.results, Some(o.scan)),
                None => (Vec::new(), None),
            };
            let frame = match &result {
                Ok(v) => Ok(v[k].clone()),
                Err(e) => Err(e.clone()),
            };
            let setup_commands = results.iter().filter(|r| r.visible).count() as u64;
            TimedFrame { frame, secs, phases: phases.get(k).cloned(), results, setup_commands, scanout }
        })
        .collect()
}

/// Passes the run through to the chipset and keeps what came out.
struct Recorder<'a> {
    chip: &'a mut dyn CycleChipset,
    outs: Vec<FrameOut>,
}

impl Chipset for Recorder<'_> {
    fn run(&mut self, frames: &[FrameJob], host: &mut dyn LowerPipeline) -> Result<Vec<FrameOut>, String> {
        let out = self.chip.run(frames, host)?;
        self.outs = out.clone();
        Ok(out)
    }
}
