//! The every-cycle bench: the RTL (`hdl::rc::Rc`, RustHDL simulation, direct drive as in GUIDE §5)
//! and the cycle-accurate model (`golden::cycle::rc::RcModel`) get the same inputs in every cycle,
//! including random gaps on the command port and random back-pressure on the result port; every output
//! port is compared in every cycle. The memory models answer the RTL's (= the model's) memory ports.
//!
//! The first mismatch stops the run with the cycle, the port, expected and actual values, and the path
//! of a VCD of the run up to that cycle (rerun with VCD on if it was off). `VCD=1` writes the VCD of
//! every run. Runs can also record their per-cycle vectors for the Verilog replay ([`super::replay`]).

use super::memory::Sram;
use super::pack::command_word;
use super::replay::{RcVectors, VectorWriter};
use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use golden::cycle::rc::{CmdKind, RcCmd, RcInputs, RcModel, RcOutputs, RcResult};
use golden::format::{Plane, Screen, DEPTH_MAX, INDEX_BACKGROUND};
use golden::raster::RcType;
use hdl::common::to_i64;
use hdl::rc::rc3::Rc3;
use hdl::rc::Rc;
use rust_hdl::prelude::*;
use std::path::PathBuf;

/// How the bench drives the handshakes and what the buffers hold at the start.
#[derive(Copy, Clone, Debug)]
pub struct Drive {
    /// Percentage of cycles in which the producer holds back the next command.
    pub gap_percent: u64,
    /// Percentage of cycles in which the result consumer is not ready.
    pub stall_percent: u64,
    pub seed: u64,
    /// Fill the buffers with random words first (the first command must then be a clearing frame).
    pub garbage: bool,
    /// Fill the Z-buffer with random words and the I-buffer with the background index: what a frame
    /// after the Color Shader's clear-behind finds (the RC must take every depth as far).
    pub stale_depth: bool,
}

impl Drive {
    /// Commands as fast as accepted, results always taken, buffers cleared.
    pub fn ideal() -> Drive {
        Drive { gap_percent: 0, stall_percent: 0, seed: 1, garbage: false, stale_depth: false }
    }
    /// Random gaps and back-pressure from a seed (overridden by `SEED`), printed so that it can be replayed.
    pub fn random(test: &str, default_seed: u64) -> Drive {
        let seed = Rng::new(default_seed).seed();
        println!("{test}: seed {seed} (set SEED={seed} to replay)");
        Drive { gap_percent: 30, stall_percent: 40, seed, garbage: true, stale_depth: false }
    }
}

/// What a run produced.
#[derive(Clone, Debug)]
pub struct Run {
    pub results: Vec<RcResult>,
    pub zbuf: Vec<u32>,
    pub ibuf: Vec<u32>,
    /// Cycles until the end-of-frame result was taken.
    pub cycles: u64,
    /// Cycles with a Z read (covered candidates) and with a fragment's Z write (passes).
    pub z_reads: u64,
    pub z_passes: u64,
    /// Cycles whose Z read is of the address read in the cycle before: the read-after-write hazard
    /// that only the z-test's forwarding resolves (it cannot see the previous fragment's write).
    pub same_address_reads_back_to_back: u64,
    /// Reads of the address read 1, 2, 3 and 4 cycles before: the distances at which Type III's
    /// visibility test must forward a write its I-buffer read cannot have seen.
    pub same_address_reads_within: [u64; 4],
    /// Clocks the traversal walked triangles, and those that delivered a fragment (cycle model).
    pub walk_clocks: u64,
    pub walk_fragment_clocks: u64,
    /// Hazard coverage from the model: cycles with the record queue full, the result queue full, the
    /// reciprocal's result waiting.
    pub record_queue_full_cycles: u64,
    pub result_queue_full_cycles: u64,
    pub recip_stall_cycles: u64,
    /// Simulation speed of the RTL in cycles per second (0 for model-only runs).
    pub rtl_cycles_per_second: f64,
    /// Words moved on the memory ports: I-buffer reads (Type IV: with every Z read) and writes, TdbV
    /// reads and writes (Type III).
    pub i_reads: u64,
    pub i_writes: u64,
    pub tdbv_reads: u64,
    pub tdbv_writes: u64,
}

/// TdbV behind Type III's ports: 2^16 depth planes, read data one cycle after the read enable, a
/// read of the record being written returns the old one.
struct Tdbv {
    words: Vec<Plane>,
    rd: Plane,
}

impl Tdbv {
    /// TdbV for an RC of type `ty` (Type IV has none: an empty memory that is never addressed), of
    /// random records when the drive asks for garbage.
    fn new(ty: RcType, garbage: Option<&mut Rng>) -> Tdbv {
        let n = if ty == RcType::III { 1usize << golden::cycle::rc::INDEX_BITS } else { 0 };
        let words = match garbage {
            Some(rng) => (0..n).map(|_| Plane { a: rng.next_u64() as i64 >> 24, b: rng.next_u64() as i64 >> 24, c: rng.next_u64() as i64 >> 8 }).collect(),
            None => vec![Plane::default(); n],
        };
        Tdbv { words, rd: Plane::default() }
    }
    fn edge(&mut self, read: Option<u32>, write: Option<(u32, Plane)>) {
        if let Some(a) = read {
            self.rd = self.words[a as usize];
        }
        if let Some((a, p)) = write {
            self.words[a as usize] = p;
        }
    }
}

fn result_of(r: hdl::rc::RcResult) -> RcResult {
    RcResult { eof: r.eof, index: r.index.to_u64() as u32, culled: r.culled, zero_area: r.zero_area, visible: r.visible }
}

/// The Type III RTL's outputs in the model's terms (its I-buffer read is the model's `z_re`).
fn rtl3_outputs(u: &Rc3) -> RcOutputs {
    RcOutputs {
        cmd_ready: u.cmd.ready.val(),
        res_valid: u.result.valid.val(),
        res: result_of(u.result.data.val()),
        z_re: u.i_re.val(),
        z_rd_addr: u.i_rd_addr.val().to_u64() as u32,
        i_we: u.i_we.val(),
        i_wr_addr: u.i_wr_addr.val().to_u64() as u32,
        i_wr_data: u.i_wr_data.val().to_u64() as u32,
        tdbv_re: u.tdbv_re.val(),
        tdbv_rd_addr: u.tdbv_rd_addr.val().to_u64() as u32,
        tdbv_we: u.tdbv_we.val(),
        tdbv_wr_addr: u.tdbv_wr_addr.val().to_u64() as u32,
        tdbv_wr_data: Plane { a: to_i64(u.tdbv_wr_a.val()), b: to_i64(u.tdbv_wr_b.val()), c: to_i64(u.tdbv_wr_c.val()) },
        ..RcOutputs::default()
    }
}

/// The RTL's outputs in the model's terms.
fn rtl_outputs(u: &Rc) -> RcOutputs {
    RcOutputs {
        cmd_ready: u.cmd.ready.val(),
        res_valid: u.result.valid.val(),
        res: result_of(u.result.data.val()),
        z_re: u.z_re.val(),
        z_rd_addr: u.z_rd_addr.val().to_u64() as u32,
        z_we: u.z_we.val(),
        z_wr_addr: u.z_wr_addr.val().to_u64() as u32,
        z_wr_data: u.z_wr_data.val().to_u64() as u32,
        i_we: u.i_we.val(),
        i_wr_addr: u.i_wr_addr.val().to_u64() as u32,
        i_wr_data: u.i_wr_data.val().to_u64() as u32,
        ..RcOutputs::default()
    }
}

/// The producer and consumer of the handshakes: valid is held until the command is taken.
struct Driver {
    rng: Rng,
    drive: Drive,
    next: usize,
    presenting: bool,
}

impl Driver {
    fn inputs(&mut self, cmds: &[RcCmd], z_rd_data: u32, i_rd_data: u32, tdbv_rd_data: Plane) -> RcInputs {
        if !self.presenting && self.next < cmds.len() && !self.rng.chance(self.drive.gap_percent) {
            self.presenting = true;
        }
        let res_ready = !self.rng.chance(self.drive.stall_percent);
        RcInputs {
            cmd_valid: self.presenting,
            cmd: if self.presenting { cmds[self.next] } else { RcCmd::idle() },
            res_ready,
            z_rd_data,
            i_rd_data,
            tdbv_rd_data,
        }
    }
    fn edge(&mut self, inp: &RcInputs, out: &RcOutputs) {
        if inp.cmd_valid && out.cmd_ready {
            self.presenting = false;
            self.next += 1;
        }
    }
}

/// A mismatch between RTL and model.
#[derive(Clone, Debug)]
pub struct Mismatch {
    pub cycle: u64,
    pub port: &'static str,
    pub expected: u64,
    pub actual: u64,
}

/// The top of either type.
enum Top {
    Iv(Box<Rc>),
    Iii(Box<Rc3>),
}

/// The RTL under direct drive, with an optional VCD.
struct RtlSim {
    uut: Top,
    trace: Trace,
}

impl RtlSim {
    fn new(ty: RcType, screen: Screen, vcd: Option<&PathBuf>) -> Result<RtlSim, String> {
        let vcd = vcd.map(PathBuf::as_path);
        let (uut, trace) = match ty {
            RcType::IV => {
                let mut u = Rc::new(screen.width, screen.height)?;
                u.connect_all();
                check_all(&u).map_err(|e| format!("rc design check: {e:?}"))?;
                let t = Trace::new(&u, vcd)?;
                (Top::Iv(Box::new(u)), t)
            }
            RcType::III => {
                let mut u = Rc3::new(screen.width, screen.height)?;
                u.connect_all();
                check_all(&u).map_err(|e| format!("rc3 design check: {e:?}"))?;
                let t = Trace::new(&u, vcd)?;
                (Top::Iii(Box::new(u)), t)
            }
        };
        Ok(RtlSim { uut, trace })
    }
    fn settle(&mut self, t: u64) -> Result<(), String> {
        let settled = match &mut self.uut {
            Top::Iv(u) => simulate(u.as_mut(), 200),
            Top::Iii(u) => simulate(u.as_mut(), 200),
        };
        if !settled {
            return Err(format!("the RTL did not settle at time {t} (combinational loop?)"));
        }
        match &self.uut {
            Top::Iv(u) => self.trace.dump(u.as_ref(), t),
            Top::Iii(u) => self.trace.dump(u.as_ref(), t),
        }
    }
    fn set_clock(&mut self, high: bool) {
        match &mut self.uut {
            Top::Iv(u) => u.clock.next = high.into(),
            Top::Iii(u) => u.clock.next = high.into(),
        }
    }
    /// Drive the inputs with the falling edge and return the outputs of the cycle.
    fn cycle(&mut self, cycle: u64, inp: &RcInputs) -> Result<RcOutputs, String> {
        match &mut self.uut {
            Top::Iv(u) => {
                u.cmd.valid.next = inp.cmd_valid;
                u.cmd.data.next = command_word(&inp.cmd);
                u.result.ready.next = inp.res_ready;
                u.z_rd_data.next = (inp.z_rd_data as u64).into();
                u.i_rd_data.next = (inp.i_rd_data as u64).into();
            }
            Top::Iii(u) => {
                u.cmd.valid.next = inp.cmd_valid;
                u.cmd.data.next = command_word(&inp.cmd);
                u.result.ready.next = inp.res_ready;
                u.i_rd_data.next = (inp.i_rd_data as u64).into();
                u.tdbv_rd_a.next = hdl::common::from_i64::<40>(inp.tdbv_rd_data.a);
                u.tdbv_rd_b.next = hdl::common::from_i64::<40>(inp.tdbv_rd_data.b);
                u.tdbv_rd_c.next = hdl::common::from_i64::<56>(inp.tdbv_rd_data.c);
            }
        }
        self.set_clock(false);
        self.settle(cycle * 10)?;
        Ok(match &self.uut {
            Top::Iv(u) => rtl_outputs(u),
            Top::Iii(u) => rtl3_outputs(u),
        })
    }
    fn rising_edge(&mut self, cycle: u64) -> Result<(), String> {
        self.set_clock(true);
        self.settle(cycle * 10 + 5)
    }
}

/// What to run: the model alone, or the RTL against the model.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Mode {
    ModelOnly,
    RtlVsModel,
}

enum Stop {
    Mismatch(Mismatch),
    Error(String),
}

#[allow(clippy::too_many_arguments)]
fn run_inner(
    mode: Mode,
    ty: RcType,
    screen: Screen,
    cmds: &[RcCmd],
    drive: Drive,
    vcd: Option<&PathBuf>,
    stop_after: Option<u64>,
    mut vectors: Option<&mut dyn RcVectors>,
    max_cycles: u64,
) -> Result<Run, Stop> {
    let mut rng = Rng::new(drive.seed);
    let (mut zmem, mut imem) = if drive.stale_depth {
        (Sram::garbage(screen.pixels(), 24, &mut rng), Sram::new(screen.pixels(), 16, INDEX_BACKGROUND))
    } else if drive.garbage {
        (Sram::garbage(screen.pixels(), 24, &mut rng), Sram::garbage(screen.pixels(), 16, &mut rng))
    } else {
        (Sram::new(screen.pixels(), 24, DEPTH_MAX), Sram::new(screen.pixels(), 16, INDEX_BACKGROUND))
    };
    let mut tdbv = Tdbv::new(ty, drive.garbage.then_some(&mut rng));
    let (mut i_reads, mut i_writes, mut tdbv_reads, mut tdbv_writes) = (0u64, 0u64, 0u64, 0u64);
    let mut driver = Driver { rng, drive, next: 0, presenting: false };
    let mut model = RcModel::of_type(screen, ty);
    let mut rtl = match mode {
        Mode::RtlVsModel => Some(RtlSim::new(ty, screen, vcd).map_err(Stop::Error)?),
        Mode::ModelOnly => None,
    };
    let (mut results, mut z_reads, mut z_passes) = (Vec::new(), 0u64, 0u64);
    let (mut back_to_back, mut last_read) = (0u64, None::<u32>);
    let (mut within, mut recent) = ([0u64; 4], [None::<u32>; 4]);
    let start = std::time::Instant::now();
    let mut watchdog = Watchdog::new(screen.pixels() as u64 + 1024);
    let eofs = cmds.iter().filter(|c| c.kind == CmdKind::EndOfFrame).count();
    let mut eofs_seen = 0usize;
    for cycle in 0..max_cycles {
        let inp = driver.inputs(cmds, zmem.read_data(), imem.read_data(), tdbv.rd);
        let expected = model.step(&inp);
        if let Some(r) = rtl.as_mut() {
            let actual = r.cycle(cycle, &inp).map_err(Stop::Error)?;
            for ((port, e), (_, a)) in expected.ports(ty).iter().zip(actual.ports(ty).iter()) {
                if e != a {
                    return Err(Stop::Mismatch(Mismatch { cycle, port, expected: *e, actual: *a }));
                }
            }
        }
        if let Some(v) = vectors.as_deref_mut() {
            v.cycle(ty, &inp, &expected).map_err(Stop::Error)?;
        }
        let out = expected;
        driver.edge(&inp, &out);
        z_reads += out.z_re as u64;
        let read = out.z_re.then_some(out.z_rd_addr);
        back_to_back += (read.is_some() && read == last_read) as u64;
        last_read = read;
        for k in 0..4 {
            within[k] += (read.is_some() && read == recent[k]) as u64;
        }
        recent.rotate_right(1);
        recent[0] = read;
        // A passing fragment writes a depth below the far value; a clear writes the far value.
        z_passes += (out.z_we && out.z_wr_data != DEPTH_MAX) as u64;
        zmem.edge(out.z_re.then_some(out.z_rd_addr), out.z_we.then_some((out.z_wr_addr, out.z_wr_data))).map_err(|e| Stop::Error(format!("cycle {cycle}: Z-buffer: {e}")))?;
        imem.edge(out.z_re.then_some(out.z_rd_addr), out.i_we.then_some((out.i_wr_addr, out.i_wr_data))).map_err(|e| Stop::Error(format!("cycle {cycle}: I-buffer: {e}")))?;
        tdbv.edge(out.tdbv_re.then_some(out.tdbv_rd_addr), out.tdbv_we.then_some((out.tdbv_wr_addr, out.tdbv_wr_data)));
        // Fragment writes only (a clear writes the background index).
        (i_reads, i_writes) = (i_reads + out.z_re as u64, i_writes + (out.i_we && out.i_wr_data != INDEX_BACKGROUND) as u64);
        (tdbv_reads, tdbv_writes) = (tdbv_reads + out.tdbv_re as u64, tdbv_writes + out.tdbv_we as u64);
        if let Some(r) = rtl.as_mut() {
            r.rising_edge(cycle).map_err(Stop::Error)?;
        }
        let taken = out.res_valid && inp.res_ready;
        if taken {
            results.push(out.res);
        }
        // Watchdog: no command or result taken and no memory access for longer than any one
        // triangle can need (its setup, then a box of the whole screen with no covered pixel).
        let progress = taken || (inp.cmd_valid && out.cmd_ready) || out.z_re || out.z_we || out.i_we || out.tdbv_we;
        let phase = || format!("the RC: no command or result taken, no memory access ({} of {} commands accepted, {} results)", driver.next, cmds.len(), results.len());
        watchdog.check(cycle, progress, phase, rtl.as_ref().map(|r| &r.trace)).map_err(Stop::Error)?;
        if stop_after == Some(cycle) {
            break;
        }
        // The stream's last end-of-frame result (the setup pipeline may accept every command before
        // the first frame's end comes out).
        eofs_seen += (taken && out.res.eof) as usize;
        if taken && out.res.eof && driver.next == cmds.len() && eofs_seen == eofs {
            let secs = start.elapsed().as_secs_f64();
            let rate = if rtl.is_some() && secs > 0.0 { (cycle + 1) as f64 / secs } else { 0.0 };
            // Type III has no Z-buffer: its depths are regenerated from TdbV, as the RTL does.
            let zbuf = match ty {
                RcType::IV => zmem.words,
                RcType::III => regenerated_depths(screen, &imem.words, &tdbv.words),
            };
            return Ok(Run { results, zbuf, ibuf: imem.words, cycles: cycle + 1, z_reads, z_passes, same_address_reads_back_to_back: back_to_back, same_address_reads_within: within, walk_clocks: model.walk_clocks, walk_fragment_clocks: model.walk_fragment_clocks, record_queue_full_cycles: model.record_queue_full_cycles, result_queue_full_cycles: model.result_queue_full_cycles, recip_stall_cycles: model.recip_stall_cycles, rtl_cycles_per_second: rate, i_reads, i_writes, tdbv_reads, tdbv_writes });
        }
    }
    if stop_after.is_some() {
        return Err(Stop::Error("stopped".into()));
    }
    Err(Stop::Error(format!(
        "no end-of-frame result after {max_cycles} cycles ({} of {} commands accepted, {} results)",
        driver.next,
        cmds.len(),
        results.len()
    )))
}

/// The depth of every pixel regenerated from TdbV where the I-buffer names a triangle, else far.
pub fn regenerated_depths(screen: Screen, ibuf: &[u32], tdbv: &[Plane]) -> Vec<u32> {
    let w = screen.width as usize;
    ibuf.iter()
        .enumerate()
        .map(|(a, &i)| match i {
            INDEX_BACKGROUND => DEPTH_MAX,
            i => tdbv[i as usize].eval_clamped((a % w) as u32, (a / w) as u32, DEPTH_MAX as i64) as u32,
        })
        .collect()
}

/// Run a command stream (which must end with an end-of-frame command) through the model alone,
/// optionally recording the vectors for the Verilog replay.
pub fn run_model(screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut VectorWriter>) -> Result<Run, String> {
    run_model_of(RcType::IV, screen, cmds, drive, vectors.map(|v| v as &mut dyn RcVectors))
}

/// [`run_model`] for the RC of type `ty`.
pub fn run_model_of(ty: RcType, screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut dyn RcVectors>) -> Result<Run, String> {
    check_stream(cmds)?;
    run_inner(Mode::ModelOnly, ty, screen, cmds, drive, None, None, vectors, cycle_budget(screen, cmds)).map_err(|s| match s {
        Stop::Error(e) => e,
        Stop::Mismatch(_) => unreachable!("the model alone cannot mismatch"),
    })
}

/// Run a command stream through the RTL and the model, comparing every port every cycle. `test` names
/// the VCD (`target/vcd/rc/<test>.vcd`), written when `VCD=1` and always on a mismatch.
pub fn run_rtl(test: &str, screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut VectorWriter>) -> Result<Run, String> {
    run_rtl_of(RcType::IV, test, screen, cmds, drive, vectors.map(|v| v as &mut dyn RcVectors))
}

/// [`run_rtl`] for the RC of type `ty` (`rc` or `rc3`).
pub fn run_rtl_of(ty: RcType, test: &str, screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut dyn RcVectors>) -> Result<Run, String> {
    check_stream(cmds)?;
    let path = vcd_path("rc", test);
    let budget = cycle_budget(screen, cmds);
    let want = vcd_wanted();
    match run_inner(Mode::RtlVsModel, ty, screen, cmds, drive, want.then_some(&path), None, vectors, budget) {
        Ok(r) => Ok(r),
        Err(Stop::Error(e)) => Err(format!("{test}: {e}")),
        Err(Stop::Mismatch(m)) => {
            if !want {
                // Deterministic: the same seed reproduces the run; record it up to the mismatch.
                let _ = run_inner(Mode::RtlVsModel, ty, screen, cmds, drive, Some(&path), Some(m.cycle), None, budget);
            }
            Err(format!(
                "{test}: RTL and cycle model differ at cycle {}, port {}: expected {:#x}, actual {:#x} (seed {}; VCD: {})",
                m.cycle,
                m.port,
                m.expected,
                m.actual,
                drive.seed,
                path.display()
            ))
        }
    }
}

fn check_stream(cmds: &[RcCmd]) -> Result<(), String> {
    for c in cmds {
        c.check()?;
    }
    match cmds.last() {
        Some(c) if c.kind == CmdKind::EndOfFrame => Ok(()),
        _ => Err("a command stream must end with an end-of-frame command".into()),
    }
}

/// A generous bound on a stream's cycles: setup and every bounding-box pixel of every triangle, every
/// clear, three times over for gaps and back-pressure.
fn cycle_budget(screen: Screen, cmds: &[RcCmd]) -> u64 {
    let work: u64 = cmds
        .iter()
        .map(|c| match c.kind {
            CmdKind::Frame if c.clear => screen.pixels() as u64 + 8,
            CmdKind::Triangle => 64 + golden::raster::setup(&c.v, c.cull, c.front, screen).map(|s| s.bbox.pixels()).unwrap_or(0),
            _ => 8,
        })
        .sum();
    3 * work + 1000
}
