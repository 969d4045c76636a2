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
use super::replay::VectorWriter;
use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use golden::cycle::rc::{CmdKind, RcCmd, RcInputs, RcModel, RcOutputs, RcResult};
use golden::format::{Screen, DEPTH_MAX, INDEX_BACKGROUND};
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
}

/// The RTL's outputs in the model's terms.
fn rtl_outputs(u: &Rc) -> RcOutputs {
    let r = u.result.data.val();
    RcOutputs {
        cmd_ready: u.cmd.ready.val(),
        res_valid: u.result.valid.val(),
        res: RcResult {
            eof: r.eof,
            index: r.index.to_u64() as u32,
            culled: r.culled,
            zero_area: r.zero_area,
            visible: r.visible,
        },
        z_re: u.z_re.val(),
        z_rd_addr: u.z_rd_addr.val().to_u64() as u32,
        z_we: u.z_we.val(),
        z_wr_addr: u.z_wr_addr.val().to_u64() as u32,
        z_wr_data: u.z_wr_data.val().to_u64() as u32,
        i_we: u.i_we.val(),
        i_wr_addr: u.i_wr_addr.val().to_u64() as u32,
        i_wr_data: u.i_wr_data.val().to_u64() as u32,
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
    fn inputs(&mut self, cmds: &[RcCmd], z_rd_data: u32, i_rd_data: u32) -> RcInputs {
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

/// The RTL under direct drive, with an optional VCD.
struct RtlSim {
    uut: Rc,
    trace: Trace,
}

impl RtlSim {
    fn new(screen: Screen, vcd: Option<&PathBuf>) -> Result<RtlSim, String> {
        let mut uut = Rc::new(screen.width, screen.height)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("rc design check: {e:?}"))?;
        let trace = Trace::new(&uut, vcd.map(PathBuf::as_path))?;
        Ok(RtlSim { uut, trace })
    }
    fn settle(&mut self, t: u64) -> Result<(), String> {
        if !simulate(&mut self.uut, 200) {
            return Err(format!("the RTL did not settle at time {t} (combinational loop?)"));
        }
        self.trace.dump(&self.uut, t)
    }
    /// Drive the inputs with the falling edge and return the outputs of the cycle.
    fn cycle(&mut self, cycle: u64, inp: &RcInputs) -> Result<RcOutputs, String> {
        self.uut.cmd.valid.next = inp.cmd_valid;
        self.uut.cmd.data.next = command_word(&inp.cmd);
        self.uut.result.ready.next = inp.res_ready;
        self.uut.z_rd_data.next = (inp.z_rd_data as u64).into();
        self.uut.i_rd_data.next = (inp.i_rd_data as u64).into();
        self.uut.clock.next = false.into();
        self.settle(cycle * 10)?;
        Ok(rtl_outputs(&self.uut))
    }
    fn rising_edge(&mut self, cycle: u64) -> Result<(), String> {
        self.uut.clock.next = true.into();
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

fn run_inner(
    mode: Mode,
    screen: Screen,
    cmds: &[RcCmd],
    drive: Drive,
    vcd: Option<&PathBuf>,
    stop_after: Option<u64>,
    mut vectors: Option<&mut VectorWriter>,
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
    let mut driver = Driver { rng, drive, next: 0, presenting: false };
    let mut model = RcModel::new(screen);
    let mut rtl = match mode {
        Mode::RtlVsModel => Some(RtlSim::new(screen, vcd).map_err(Stop::Error)?),
        Mode::ModelOnly => None,
    };
    let (mut results, mut z_reads, mut z_passes) = (Vec::new(), 0u64, 0u64);
    let (mut back_to_back, mut last_read) = (0u64, None::<u32>);
    let start = std::time::Instant::now();
    let mut watchdog = Watchdog::new(screen.pixels() as u64 + 1024);
    let eofs = cmds.iter().filter(|c| c.kind == CmdKind::EndOfFrame).count();
    let mut eofs_seen = 0usize;
    for cycle in 0..max_cycles {
        let inp = driver.inputs(cmds, zmem.read_data(), imem.read_data());
        let expected = model.step(&inp);
        if let Some(r) = rtl.as_mut() {
            let actual = r.cycle(cycle, &inp).map_err(Stop::Error)?;
            for ((port, e), (_, a)) in expected.ports().iter().zip(actual.ports().iter()) {
                if e != a {
                    return Err(Stop::Mismatch(Mismatch { cycle, port, expected: *e, actual: *a }));
                }
            }
        }
        if let Some(v) = vectors.as_deref_mut() {
            v.cycle(&inp, &expected).map_err(Stop::Error)?;
        }
        let out = expected;
        driver.edge(&inp, &out);
        z_reads += out.z_re as u64;
        let read = out.z_re.then_some(out.z_rd_addr);
        back_to_back += (read.is_some() && read == last_read) as u64;
        last_read = read;
        // A passing fragment writes a depth below the far value; a clear writes the far value.
        z_passes += (out.z_we && out.z_wr_data != DEPTH_MAX) as u64;
        zmem.edge(out.z_re.then_some(out.z_rd_addr), out.z_we.then_some((out.z_wr_addr, out.z_wr_data))).map_err(|e| Stop::Error(format!("cycle {cycle}: Z-buffer: {e}")))?;
        imem.edge(out.z_re.then_some(out.z_rd_addr), out.i_we.then_some((out.i_wr_addr, out.i_wr_data))).map_err(|e| Stop::Error(format!("cycle {cycle}: I-buffer: {e}")))?;
        if let Some(r) = rtl.as_mut() {
            r.rising_edge(cycle).map_err(Stop::Error)?;
        }
        let taken = out.res_valid && inp.res_ready;
        if taken {
            results.push(out.res);
        }
        // Watchdog: no command or result taken and no memory access for longer than any one
        // triangle can need (its setup, then a box of the whole screen with no covered pixel).
        let progress = taken || (inp.cmd_valid && out.cmd_ready) || out.z_re || out.z_we || out.i_we;
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
            return Ok(Run { results, zbuf: zmem.words, ibuf: imem.words, cycles: cycle + 1, z_reads, z_passes, same_address_reads_back_to_back: back_to_back, walk_clocks: model.walk_clocks, walk_fragment_clocks: model.walk_fragment_clocks, record_queue_full_cycles: model.record_queue_full_cycles, result_queue_full_cycles: model.result_queue_full_cycles, recip_stall_cycles: model.recip_stall_cycles, rtl_cycles_per_second: rate });
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

/// Run a command stream (which must end with an end-of-frame command) through the model alone,
/// optionally recording the vectors for the Verilog replay.
pub fn run_model(screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut VectorWriter>) -> Result<Run, String> {
    check_stream(cmds)?;
    run_inner(Mode::ModelOnly, screen, cmds, drive, None, None, vectors, cycle_budget(screen, cmds)).map_err(|s| match s {
        Stop::Error(e) => e,
        Stop::Mismatch(_) => unreachable!("the model alone cannot mismatch"),
    })
}

/// Run a command stream through the RTL and the model, comparing every port every cycle. `test` names
/// the VCD (`target/vcd/rc/<test>.vcd`), written when `VCD=1` and always on a mismatch.
pub fn run_rtl(test: &str, screen: Screen, cmds: &[RcCmd], drive: Drive, vectors: Option<&mut VectorWriter>) -> Result<Run, String> {
    check_stream(cmds)?;
    let path = vcd_path("rc", test);
    let budget = cycle_budget(screen, cmds);
    let want = vcd_wanted();
    match run_inner(Mode::RtlVsModel, screen, cmds, drive, want.then_some(&path), None, vectors, budget) {
        Ok(r) => Ok(r),
        Err(Stop::Error(e)) => Err(format!("{test}: {e}")),
        Err(Stop::Mismatch(m)) => {
            if !want {
                // Deterministic: the same seed reproduces the run; record it up to the mismatch.
                let _ = run_inner(Mode::RtlVsModel, screen, cmds, drive, Some(&path), Some(m.cycle), None, budget);
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
