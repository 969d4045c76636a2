//! Every-cycle bench of colour setup: the RTL (`hdl::cs::colour_setup::ColourSetup`, RustHDL, direct
//! drive as in GUIDE §5) and the cycle model (`golden::cycle::colour_setup::ColourSetupModel`) get the
//! same command stream, with random gaps (a presented command is held until taken, as the handshake
//! requires); every output port is compared in every cycle. The first mismatch stops the run with the
//! cycle, the port, both values and the path of a VCD of the run up to that cycle.

use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use crate::cs::pack::{command_of, entry_of, BitVector};
use crate::cs::replay::{port, Recording};
use golden::cycle::colour_setup::{ColourSetupModel, SetupCmd, SetupInputs, SetupOutputs, TdbsWrite};
use golden::shade::TdbsEntry;
use hdl::cs::colour_setup::ColourSetup;
use rust_hdl::prelude::*;
use std::path::PathBuf;

/// How the command producer behaves.
#[derive(Copy, Clone, Debug)]
pub struct SetupDrive {
    /// Percentage of cycles in which the producer, free to present the next command, holds it back.
    pub gap_percent: u64,
    pub seed: u64,
}

/// What a run produced.
#[derive(Clone, Debug, Default)]
pub struct SetupRun {
    /// TdbS writes in order: (index, record).
    pub writes: Vec<(u16, TdbsEntry)>,
    /// Cycles until the last write was done and the block idle.
    pub cycles: u64,
    /// RustHDL simulation speed, cycles per second.
    pub rtl_cycles_per_second: f64,
    /// The vectors for the Verilog replay, if asked for.
    pub recording: Option<Recording>,
}

/// Ports of the `colour_setup` top in the replay's order.
pub fn replay_ports() -> (Vec<crate::cs::replay::PortSpec>, Vec<crate::cs::replay::PortSpec>) {
    (
        vec![port("cmd$valid", 1), port("cmd$data", hdl::cs::SETUP_COMMAND_BITS)],
        vec![
            port("cmd$ready", 1),
            port("busy", 1),
            port("tdbs_write_enable", 1),
            port("tdbs_write_address", 16),
            port("tdbs_write_data", hdl::cs::TDBS_RECORD_BITS),
        ],
    )
}

fn in_vector(i: &SetupInputs) -> BitVector {
    let mut v = BitVector::default();
    v.push(i.cmd_valid as u128, 1);
    v.push_command(&i.cmd);
    v
}

fn out_vector(o: &SetupOutputs) -> BitVector {
    let mut v = BitVector::default();
    v.push(o.cmd_ready as u128, 1);
    v.push(o.busy as u128, 1);
    v.push(o.tdbs_write.enable as u128, 1);
    v.push(o.tdbs_write.address as u128, 16);
    v.push_record(&o.tdbs_write.data);
    v
}

fn rtl_outputs(u: &ColourSetup) -> SetupOutputs {
    SetupOutputs {
        cmd_ready: u.cmd.ready.val(),
        busy: u.busy.val(),
        tdbs_write: TdbsWrite {
            enable: u.tdbs_write_enable.val(),
            address: u.tdbs_write_address.val().to_u64() as u16,
            data: entry_of(&u.tdbs_write_data.val()),
        },
    }
}

/// The first differing port, as (port, expected, actual).
fn first_difference(e: &SetupOutputs, a: &SetupOutputs) -> Option<(&'static str, String, String)> {
    if e.cmd_ready != a.cmd_ready {
        return Some(("cmd.ready", e.cmd_ready.to_string(), a.cmd_ready.to_string()));
    }
    if e.busy != a.busy {
        return Some(("busy", e.busy.to_string(), a.busy.to_string()));
    }
    if e.tdbs_write.enable != a.tdbs_write.enable {
        return Some(("tdbs_write_enable", e.tdbs_write.enable.to_string(), a.tdbs_write.enable.to_string()));
    }
    if e.tdbs_write.address != a.tdbs_write.address {
        return Some(("tdbs_write_address", e.tdbs_write.address.to_string(), a.tdbs_write.address.to_string()));
    }
    if e.tdbs_write.data != a.tdbs_write.data {
        return Some(("tdbs_write_data", format!("{:?}", e.tdbs_write.data), format!("{:?}", a.tdbs_write.data)));
    }
    None
}

struct Rtl {
    uut: ColourSetup,
    trace: Trace,
}

impl Rtl {
    fn new(vcd: Option<&PathBuf>) -> Result<Rtl, String> {
        let mut uut = ColourSetup::default();
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("colour_setup design check: {e:?}"))?;
        let trace = Trace::new(&uut, vcd.map(PathBuf::as_path))?;
        Ok(Rtl { uut, trace })
    }
    fn settle(&mut self, t: u64) -> Result<(), String> {
        if !simulate(&mut self.uut, 200) {
            return Err(format!("colour_setup did not settle at time {t}"));
        }
        self.trace.dump(&self.uut, t)
    }
}

enum Stop {
    Mismatch(u64, &'static str, String, String),
    Error(String),
}

fn run_inner(cmds: &[SetupCmd], drive: SetupDrive, with_rtl: bool, vcd: Option<&PathBuf>, stop_at: Option<u64>, record: bool) -> Result<SetupRun, Stop> {
    let mut rng = Rng::new(drive.seed);
    let mut model = ColourSetupModel::new();
    let mut rtl = if with_rtl { Some(Rtl::new(vcd).map_err(Stop::Error)?) } else { None };
    let mut rec = if record {
        let (i, o) = replay_ports();
        Some(Recording::new(i, o))
    } else {
        None
    };
    let mut run = SetupRun::default();
    let (mut next, mut presenting) = (0usize, false);
    let limit = 64 + 50 * (cmds.len() as u64 + 1) * (1 + drive.gap_percent);
    let t0 = std::time::Instant::now();
    let mut cycle = 0u64;
    // Every accepted command writes TdbS SETUP_LATENCY cycles later, and a presented command is taken
    // within SETUP_INTERVAL cycles: nothing moving for 4x the latency is a hang.
    let mut watchdog = Watchdog::new(4 * golden::cycle::colour_setup::SETUP_LATENCY);
    loop {
        if !presenting && next < cmds.len() && !rng.chance(drive.gap_percent) {
            presenting = true;
        }
        let inp = SetupInputs { cmd_valid: presenting, cmd: if presenting { cmds[next] } else { SetupCmd::default() } };
        let expected = model.step(&inp);
        if let Some(r) = rtl.as_mut() {
            r.uut.cmd.valid.next = inp.cmd_valid;
            r.uut.cmd.data.next = command_of(&inp.cmd);
            r.uut.clock.next = false.into();
            r.settle(cycle * 10).map_err(Stop::Error)?;
            let actual = rtl_outputs(&r.uut);
            if let Some((p, e, a)) = first_difference(&expected, &actual) {
                return Err(Stop::Mismatch(cycle, p, e, a));
            }
            r.uut.clock.next = true.into();
            r.settle(cycle * 10 + 5).map_err(Stop::Error)?;
        }
        if let Some(rc) = rec.as_mut() {
            rc.push(in_vector(&inp), out_vector(&expected));
        }
        if expected.tdbs_write.enable {
            run.writes.push((expected.tdbs_write.address, expected.tdbs_write.data));
        }
        let taken = presenting && expected.cmd_ready;
        if taken {
            presenting = false;
            next += 1;
        }
        let progress = taken || expected.tdbs_write.enable || (!inp.cmd_valid && next < cmds.len());
        let phase = || format!("colour setup ({} of {} commands taken, {} writes)", next, cmds.len(), run.writes.len());
        watchdog.check(cycle, progress, phase, rtl.as_ref().map(|r| &r.trace)).map_err(Stop::Error)?;
        cycle += 1;
        if Some(cycle) == stop_at {
            break;
        }
        if next == cmds.len() && !model.outputs().busy {
            break;
        }
        if cycle > limit {
            return Err(Stop::Error(format!("colour setup did not finish {} commands in {limit} cycles", cmds.len())));
        }
    }
    if let Some(r) = rtl.as_mut() {
        r.trace.end(cycle * 10 + 10);
    }
    let dt = t0.elapsed().as_secs_f64();
    run.cycles = cycle;
    run.rtl_cycles_per_second = if with_rtl && dt > 0.0 { cycle as f64 / dt } else { 0.0 };
    run.recording = rec;
    Ok(run)
}

/// The cycle model alone (fast): what the block writes and when.
pub fn run_model(cmds: &[SetupCmd], drive: SetupDrive) -> Result<SetupRun, String> {
    run_inner(cmds, drive, false, None, None, false).map_err(|s| match s {
        Stop::Error(e) => e,
        Stop::Mismatch(..) => unreachable!(),
    })
}

/// The RTL against the model, every port every cycle. `test` names the VCD
/// (`target/vcd/cs/<test>.vcd`): written for every run with `VCD=1`, and always for a failing run.
pub fn run_rtl_vs_model(test: &str, cmds: &[SetupCmd], drive: SetupDrive, record: bool) -> Result<SetupRun, String> {
    let path = vcd_path("cs", test);
    let vcd = if vcd_wanted() { Some(&path) } else { None };
    match run_inner(cmds, drive, true, vcd, None, record) {
        Ok(r) => Ok(r),
        Err(Stop::Error(e)) => Err(e),
        Err(Stop::Mismatch(cycle, port, e, a)) => {
            // Rerun with the VCD on, up to and including the failing cycle.
            let _ = run_inner(cmds, drive, true, Some(&path), Some(cycle + 1), false);
            Err(format!(
                "colour_setup differs from its cycle model in cycle {cycle} (seed {}), port {port}:\n  expected {e}\n  actual   {a}\n  VCD: {}",
                drive.seed,
                path.display()
            ))
        }
    }
}
