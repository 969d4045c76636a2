//! Every-cycle bench of texture setup: the RTL (`hdl::cs::tex_setup::TexSetup`, RustHDL, direct
//! drive) and the cycle model (`golden::cycle::tex_setup::TexSetupModel`) get the same command stream
//! with random gaps (a presented command is held until taken); every output port is compared in every
//! cycle, and the vectors are recorded for the Verilog replay. The first mismatch stops the run with
//! the cycle, the port, both values and the path of a VCD up to that cycle.

use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use crate::cs::pack::{tex_command_of, tex_planes_of, BitVector};
use crate::cs::replay::{port, PortSpec, Recording};
use golden::cycle::tex_setup::{TexSetupCmd, TexSetupInputs, TexSetupModel, TexSetupOutputs, TEX_SETUP_LATENCY};
use golden::texcoord::TexPlanes;
use hdl::cs::tex_setup::TexSetup;
use rust_hdl::prelude::*;

/// What a run produced.
#[derive(Clone, Debug, Default)]
pub struct TexSetupRun {
    /// TdbT writes in order: (index, record).
    pub writes: Vec<(u16, TexPlanes)>,
    /// Cycles until the last write was done and the block idle.
    pub cycles: u64,
    pub recording: Option<Recording>,
}

/// Ports of the `tex_setup` top in the replay's order.
pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![port("cmd$valid", 1), port("cmd$data", hdl::cs::TEX_SETUP_COMMAND_BITS)],
        vec![port("cmd$ready", 1), port("busy", 1), port("tdbt_write_enable", 1), port("tdbt_write_address", 16), port("tdbt_write_data", hdl::cs::TDBT_RECORD_BITS)],
    )
}

fn vectors(i: &TexSetupInputs, o: &TexSetupOutputs) -> (BitVector, BitVector) {
    let mut vin = BitVector::default();
    vin.push(i.cmd_valid as u128, 1);
    vin.push_tex_command(&i.cmd);
    let mut vout = BitVector::default();
    vout.push(o.cmd_ready as u128, 1);
    vout.push(o.busy as u128, 1);
    vout.push(o.write_enable as u128, 1);
    vout.push(o.write_address as u128, 16);
    vout.push_tex_planes(&o.write_data);
    (vin, vout)
}

fn rtl_outputs(u: &TexSetup) -> TexSetupOutputs {
    TexSetupOutputs {
        cmd_ready: u.cmd.ready.val(),
        busy: u.busy.val(),
        write_enable: u.tdbt_write_enable.val(),
        write_address: u.tdbt_write_address.val().to_u64() as u16,
        write_data: tex_planes_of(&u.tdbt_write_data.val()),
    }
}

/// The first differing port, as (port, expected, actual).
fn first_difference(e: &TexSetupOutputs, a: &TexSetupOutputs) -> Option<(&'static str, String, String)> {
    let ports: [(&'static str, String, String); 5] = [
        ("cmd.ready", e.cmd_ready.to_string(), a.cmd_ready.to_string()),
        ("busy", e.busy.to_string(), a.busy.to_string()),
        ("tdbt_write_enable", e.write_enable.to_string(), a.write_enable.to_string()),
        ("tdbt_write_address", e.write_address.to_string(), a.write_address.to_string()),
        ("tdbt_write_data", format!("{:?}", e.write_data), format!("{:?}", a.write_data)),
    ];
    ports.into_iter().find(|(_, x, y)| x != y)
}

/// Drive `cmds` into the RTL and `model_cmds` (the same commands, unless a test breaks the reference
/// on purpose) into the cycle model; `gap_percent` of the cycles in which the producer could present
/// the next command it holds back. `test` names the VCD (`target/vcd/cs/<test>.vcd`, written with
/// `VCD=1` and for a failing run).
pub fn run(test: &str, cmds: &[TexSetupCmd], model_cmds: &[TexSetupCmd], gap_percent: u64, seed: u64, record: bool) -> Result<TexSetupRun, String> {
    let path = vcd_path("cs", test);
    let vcd = vcd_wanted().then_some(path.as_path());
    run_inner(cmds, model_cmds, gap_percent, seed, record, vcd, None).map_err(|(cycle, e)| match (cycle, vcd) {
        // Rerun with the waveform on, up to and including the failing cycle.
        (Some(c), None) => match run_inner(cmds, model_cmds, gap_percent, seed, false, Some(&path), Some(c + 1)) {
            Err((_, e)) => e,
            Ok(_) => e,
        },
        _ => e,
    })
}

/// A failure: its cycle (for a mismatch) and the message.
type Failure = (Option<u64>, String);

fn run_inner(cmds: &[TexSetupCmd], model_cmds: &[TexSetupCmd], gap_percent: u64, seed: u64, record: bool, vcd: Option<&std::path::Path>, stop_at: Option<u64>) -> Result<TexSetupRun, Failure> {
    assert_eq!(cmds.len(), model_cmds.len());
    let err = |e: String| (None, e);
    let mut uut = TexSetup::default();
    uut.connect_all();
    check_all(&uut).map_err(|e| err(format!("tex_setup design check: {e:?}")))?;
    let mut trace = Trace::new(&uut, vcd).map_err(err)?;
    let (ins, outs) = replay_ports();
    let mut rec = Recording::new(ins, outs);
    let mut rng = Rng::new(seed);
    let mut model = TexSetupModel::default();
    let mut out = TexSetupRun::default();
    let (mut next, mut presenting, mut cycle) = (0usize, false, 0u64);
    let mut watchdog = Watchdog::new(4 * TEX_SETUP_LATENCY);
    let settle = |uut: &mut TexSetup, trace: &mut Trace, t: u64| -> Result<(), String> {
        if !simulate(uut, 200) {
            return Err(format!("tex_setup did not settle at time {t}"));
        }
        trace.dump(uut, t)
    };
    loop {
        if !presenting && next < cmds.len() && !rng.chance(gap_percent) {
            presenting = true;
        }
        let pick = |list: &[TexSetupCmd]| if presenting { list[next] } else { TexSetupCmd::default() };
        let inp = TexSetupInputs { cmd_valid: presenting, cmd: pick(cmds) };
        let expected = model.step(&TexSetupInputs { cmd_valid: presenting, cmd: pick(model_cmds) });
        uut.cmd.valid.next = inp.cmd_valid;
        uut.cmd.data.next = tex_command_of(&inp.cmd);
        uut.clock.next = false.into();
        settle(&mut uut, &mut trace, cycle * 10).map_err(err)?;
        let actual = rtl_outputs(&uut);
        if let Some((p, e, a)) = first_difference(&expected, &actual) {
            let msg = format!("tex_setup differs from its cycle model (seed {seed}), port {p}:\n  expected {e}\n  actual   {a}");
            trace.end(cycle * 10 + 10);
            return Err((Some(cycle), trace.fail(cycle, msg)));
        }
        if record {
            let (vin, vout) = vectors(&inp, &expected);
            rec.push(vin, vout);
        }
        uut.clock.next = true.into();
        settle(&mut uut, &mut trace, cycle * 10 + 5).map_err(err)?;
        if expected.write_enable {
            out.writes.push((expected.write_address, expected.write_data));
        }
        let taken = presenting && expected.cmd_ready;
        if taken {
            presenting = false;
            next += 1;
        }
        let progress = taken || expected.write_enable || (!presenting && next < cmds.len());
        let phase = || format!("texture setup ({next} of {} commands taken, {} writes)", cmds.len(), out.writes.len());
        watchdog.check(cycle, progress, phase, Some(&trace)).map_err(err)?;
        cycle += 1;
        if (next == cmds.len() && !model.outputs().busy) || Some(cycle) == stop_at {
            break;
        }
    }
    trace.end(cycle * 10 + 10);
    out.cycles = cycle;
    out.recording = record.then_some(rec);
    Ok(out)
}

/// Random commands reaching every path: coordinates over the whole 20-bit range and small ones,
/// det > 0, < 0 and = 0, values over the whole 33-bit range (planes saturating) and in the range real
/// frames use.
pub fn random_commands(n: usize, rng: &mut Rng) -> Vec<TexSetupCmd> {
    let (wmin, wmax) = (golden::format::WINDOW_MIN, golden::format::WINDOW_MAX);
    let coord = |rng: &mut Rng, lo: i32, span: i32| (lo + rng.below(span as u64 + 1) as i32).clamp(wmin, wmax);
    (0..n)
        .map(|i| {
            let kind = rng.below(8);
            let mut c = TexSetupCmd { index: 1 + rng.below(65535) as u16, ..Default::default() };
            let (x0, y0) = (coord(rng, wmin, wmax - wmin), coord(rng, wmin, wmax - wmin));
            let span = if kind == 0 { wmax - wmin } else if kind == 1 { 8 } else { 4000 * 16 };
            for k in 0..3 {
                let d = |rng: &mut Rng| if k == 0 { 0 } else { rng.below(2 * span as u64 + 1) as i32 - span };
                c.x[k] = (x0 + d(rng)).clamp(wmin, wmax);
                c.y[k] = (y0 + d(rng)).clamp(wmin, wmax);
            }
            if kind == 2 {
                // Zero area: vertex 2 on the line through vertices 0 and 1.
                c.x[2] = (2 * c.x[1] - c.x[0]).clamp(wmin, wmax);
                c.y[2] = (2 * c.y[1] - c.y[0]).clamp(wmin, wmax);
                if i % 2 == 0 {
                    c.x = [c.x[0]; 3];
                    c.y = [c.y[0]; 3];
                }
            }
            for vk in c.values.iter_mut() {
                for (ch, v) in vk.iter_mut().enumerate() {
                    *v = match (kind, ch) {
                        (0 | 3, _) => rng.below(1 << 33) as i64 - (1 << 32),
                        (_, 2) => 1 + rng.below(1 << 24) as i64,
                        (4 | 5, _) => rng.below(1 << 32) as i64 - (1 << 31),
                        // What frames send: a few textures across the triangle.
                        _ => rng.below(1 << 24) as i64 - (1 << 23),
                    };
                }
            }
            c
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{require_tools, scratch_dir};
    use crate::cs::replay::replay_iverilog;
    use golden::cycle::colour_setup::SETUP_INTERVAL;

    fn seeded(test: &str, default: u64) -> (Rng, u64) {
        let rng = Rng::new(default);
        let seed = rng.seed();
        println!("{test}: seed {seed} (set SEED={seed} to replay)");
        (rng, seed)
    }

    /// The setup commands of teapot-floor at 320x200, textured (`coords`), with the TdbT the golden
    /// chipset built from them.
    fn floor_commands(coords: golden::texcoord::Coords) -> Vec<(TexSetupCmd, TexPlanes)> {
        use golden::format::Screen;
        use golden::render::{render_with, GoldenChipset, RenderOptions, Texturing};
        use golden::shade::Shading;
        use golden::texture::{checker, Filter, Wrap};
        let mesh = golden::scene::builtin::teapot_floor();
        let screen = Screen::new(320, 200).unwrap();
        let texturing = Texturing { texture: std::sync::Arc::new(checker()), source: "test".into(), filter: Filter::Bilinear, coords, wrap: Wrap::Repeat };
        let opts = RenderOptions { texturing: Some(texturing), ..RenderOptions::for_scene(&mesh, screen, Shading::Gouraud) };
        let mut chip = GoldenChipset::new(screen);
        render_with(&mesh, &opts, &mut chip).unwrap();
        chip.setups.iter().map(|c| (TexSetupCmd::from_command(c).unwrap(), chip.tdbt[c.index as usize].unwrap())).collect()
    }

    #[test]
    fn texture_setup_matches_its_cycle_model_every_cycle_on_random_commands_with_gaps() {
        let (mut rng, seed) = seeded("tex_setup_random", 0x7E5E);
        let cmds = random_commands(400, &mut rng);
        let run = run("tex_setup_random", &cmds, &cmds, 30, seed, false).unwrap();
        assert_eq!(run.writes.len(), cmds.len());
        // What the stimulus reached: each sign of det, zero area, and saturated gradients.
        let v = |c: &TexSetupCmd| [0, 1, 2].map(|k| golden::format::WinVertex { x: c.x[k] as i32, y: c.y[k] as i32, z: 0 });
        let dets: Vec<i64> = cmds.iter().map(|c| golden::raster::det(&v(c))).collect();
        let saturated = run.writes.iter().filter(|(_, p)| p.saturated()).count();
        let (neg, zero) = (dets.iter().filter(|&&d| d < 0).count(), dets.iter().filter(|&&d| d == 0).count());
        println!("tex_setup: {} commands ({neg} det < 0, {zero} det = 0, {saturated} with a saturated gradient), {} cycles", cmds.len(), run.cycles);
        assert!(neg >= 100 && zero >= 20 && saturated >= 20 && saturated <= cmds.len() - 100, "det < 0: {neg}, det = 0: {zero}, saturated: {saturated}");
    }

    #[test]
    fn texture_setup_writes_the_golden_tdbt_of_teapot_floor_back_to_back() {
        for coords in [golden::texcoord::Coords::Perspective, golden::texcoord::Coords::Affine] {
            let frame = floor_commands(coords);
            let cmds: Vec<TexSetupCmd> = frame.iter().map(|f| f.0).collect();
            let run = run(&format!("tex_setup_floor_{coords:?}").to_lowercase(), &cmds, &cmds, 0, 1, false).unwrap();
            assert_eq!(run.writes.len(), cmds.len());
            for ((cmd, want), (index, got)) in frame.iter().zip(&run.writes) {
                assert_eq!((*index, got), (cmd.index, want), "{coords:?}: TdbT record of triangle {}", cmd.index);
            }
            // Back to back: one command every SETUP_INTERVAL cycles, the last written TEX_SETUP_LATENCY later.
            assert_eq!(run.cycles, (cmds.len() as u64 - 1) * SETUP_INTERVAL + TEX_SETUP_LATENCY + 1);
            println!("tex_setup, teapot-floor {coords:?}: {} triangles in {} cycles", cmds.len(), run.cycles);
        }
    }

    #[test]
    fn the_texture_setup_bench_fails_when_the_model_gets_another_command() {
        let (mut rng, seed) = seeded("tex_setup_broken", 0x7E5E);
        let cmds = random_commands(40, &mut rng);
        // Command 17 or the first after it whose record a changed 1/w at vertex 1 changes (a saturated
        // or zero-area record may not change).
        let k = (17..cmds.len())
            .find(|&k| {
                let mut w = cmds[k];
                w.values[1][2] += 1;
                w.record() != cmds[k].record()
            })
            .expect("a command whose record depends on vertex 1's 1/w");
        let mut wrong = cmds.clone();
        wrong[k].values[1][2] += 1;
        let e = run("tex_setup_broken", &cmds, &wrong, 30, seed, false).unwrap_err();
        assert!(e.contains("port tdbt_write_data"), "{e}");
    }

    #[test]
    fn the_texture_setup_verilog_replays_the_vectors_and_a_changed_rounding_is_caught() {
        if !require_tools("the_texture_setup_verilog_replays_the_vectors_and_a_changed_rounding_is_caught", &["iverilog"]) {
            return;
        }
        let (mut rng, seed) = seeded("tex_setup_replay", 0x7E5E);
        let cmds = random_commands(150, &mut rng);
        let rec = run("tex_setup_replay", &cmds, &cmds, 30, seed, true).unwrap().recording.unwrap();
        let v = hdl::cs::tex_setup::verilog().unwrap();
        let r = replay_iverilog(&v, "tex_setup", &rec, &scratch_dir("cs/tex_setup_replay")).unwrap();
        println!("tex_setup Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
        // C's rounding (+128 before >> 8) made 0: the replay must fail.
        let half = "localparam signed [63:0] k128_64 = 64'h80;";
        assert!(v.contains(half), "the rounding constant `{half}` is not in the Verilog");
        let e = replay_iverilog(&v.replacen(half, "localparam signed [63:0] k128_64 = 64'h0;", 1), "tex_setup", &rec, &scratch_dir("cs/tex_setup_replay_broken")).unwrap_err();
        assert!(e.contains("port tdbt_write_data"), "{e}");
    }

    #[test]
    fn the_texture_setup_passes_verilator_lint() {
        if !require_tools("the_texture_setup_passes_verilator_lint", &["verilator"]) {
            return;
        }
        let v = hdl::cs::tex_setup::verilog().unwrap();
        crate::lint::lint(&v, "tex_setup", &scratch_dir("cs/lint_tex_setup")).unwrap_or_else(|e| panic!("{e}"));
    }
}
