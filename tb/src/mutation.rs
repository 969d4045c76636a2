//! Mutation cover of the generated netlists, by the method of YosysHQ's mcy: Yosys draws mutations of a
//! top's netlist (`mutate -list N`), each mutant is written out as Verilog and replayed under Icarus
//! (Verilator for `cs_tex`, and for `cs`'s 1024x1024 frame, reached only by a mutant that survives the rest) on the vectors that the top's Verilog replay test uses (every cycle's inputs and the cycle model's
//! outputs). A mutant is **killed** when any port differs in any cycle (or the simulation never ends).
//! A mutant that survives is checked for equivalence with the original: its cell dead in the flattened
//! top, or Yosys's `equiv_make`, `equiv_simple` and `equiv_induct` (an induction proof over the mutated
//! module, then over the whole top, submodules flattened in, memories mapped to registers):
//! **equivalent** when every equivalence is proven, else **surviving**. A mutation of a live clock is
//! never called equivalent ([`CLOCK_UNDECIDED`]).
//!
//! Run by `bash scripts/mutation.sh TOP N` (`tb/src/bin/mutation.rs`); results in
//! `target/mutation/TOP.json`. The tops: `rc`, `rc3`, `colour_setup`, `cs`, `cs_tex`, `opp`, and the
//! texture setup block `tex_setup` (not yet in a `verilog` top).

use crate::common::{workspace_target, Rng};
use golden::format::Screen;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The tops this cover knows, with the stimulus each is replayed on.
pub const TOPS: [&str; 7] = ["rc", "rc3", "colour_setup", "cs", "cs_tex", "opp", "tex_setup"];

type Replay = Box<dyn Fn(&str, &Path) -> Result<(), String> + Send + Sync>;

/// A top: its generated Verilog, what its vectors are, and the replay of a Verilog text (the original
/// or a mutant) in a work directory, Ok when every port matches in every cycle.
pub struct Target {
    pub top: &'static str,
    pub verilog: String,
    pub stimulus: String,
    replay: Replay,
}

impl Target {
    pub fn replay(&self, verilog: &str, dir: &Path) -> Result<(), String> {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        (self.replay)(verilog, dir)
    }
}

/// The top `top` with its stimulus, recorded from the cycle model (for `rc`) or from the RustHDL bench
/// checked against the cycle model (the others), into `dir`.
pub fn target(top: &str, dir: &Path) -> Result<Target, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    match top {
        "rc" => rc_target(dir),
        "rc3" => rc3_target(dir),
        "colour_setup" => {
            // Ten times the replay test's 60 commands: with 60 (278 cycles), 43 of 100 mutants survived.
            let rec = crate::cs::stimulus::colour_setup_replay_recording(0xC0105E7, 600)?;
            let stimulus = format!("{} cycles: 600 random commands of the colour setup replay test's kinds, 30% gaps", rec.cycles());
            let replay: Replay = Box::new(move |v, d| crate::cs::replay::replay_iverilog(v, "colour_setup", &rec, d).map(|_| ()));
            Ok(Target { top: "colour_setup", verilog: hdl::verilog_top("colour_setup")?, stimulus, replay })
        }
        "cs" => {
            // The replay test's recording (the first cover run's stimulus), then three Phong frames with
            // unit-scale normals (added for its survivors), then six light sets, Gouraud frames
            // with fine planes and Gouraud frames at rounding edges (added for the survivors of the
            // 2026-11-29 draw), then a Phong frame with every pixel's light sum at a rounding edge
            // (added for those that survived them), then one with every pixel's N.L or N.H on its
            // rounding edge (for the survivors in the light units' dot products), each from reset,
            // under Icarus; and a mutant that survives them all replays the largest frame, 1024x1024,
            // under Verilator (for the I-buffer address's high bits; about a million cycles, which
            // Icarus would take minutes per mutant over).
            let mut recs = vec![crate::cs::stimulus::cs_replay_recording(0xC5)?, crate::cs::stimulus::cs_unit_normal_recording(0xC5)?];
            recs.extend(crate::cs::stimulus::cs_light_set_recordings(0x11647, 6)?);
            recs.push(crate::cs::stimulus::cs_gouraud_fraction_recording(0x60_0AD)?);
            recs.extend(crate::cs::stimulus::cs_rounding_edge_recordings(0xED6E)?);
            recs.push(crate::cs::stimulus::cs_phong_rounding_edge_recording(0xF0E)?);
            recs.push(crate::cs::stimulus::cs_phong_dot_edge_recording(0xD07)?);
            let largest = crate::cs::stimulus::cs_largest_frame_recording(0x1A26E)?;
            let stimulus = format!(
                "{} + {} + {} + {} + {} + {} + {} cycles under Icarus: the CS replay test's four frames (Phong, Gouraud, clear behind, 2000x1), then three Phong frames of 64x32 with unit-scale normals, then six light sets, each a 48x24 Phong frame and 3x1000 frames in Phong and Gouraud, then Gouraud frames of 48x24, 3x1000 and 1000x3 over planes within 0..=255, then Gouraud frames of 48x24, 2x1000 and 1000x2 with every pixel's planes at a rounding edge, then a 24x16 Phong frame with every pixel's light sum (both lights lighting it) within 16 units of a rounding edge, then a 24x16 Phong frame with every pixel's N.L or N.H of one light on its rounding edge, 35% stalls; then, for a mutant that survives them, {} cycles under Verilator: a 1024x1024 Gouraud frame",
                recs[0].cycles(),
                recs[1].cycles(),
                recs[2..8].iter().map(|r| r.cycles()).sum::<usize>(),
                recs[8].cycles(),
                recs[9..12].iter().map(|r| r.cycles()).sum::<usize>(),
                recs[12].cycles(),
                recs[13].cycles(),
                largest.cycles()
            );
            let replay: Replay = Box::new(move |v, d| {
                recs.iter().try_for_each(|rec| crate::cs::replay::replay_iverilog(v, "cs", rec, d).map(|_| ()))?;
                crate::cs::replay::replay_verilator(v, "cs", &largest, d).map(|_| ())
            });
            Ok(Target { top: "cs", verilog: hdl::verilog_top("cs")?, stimulus, replay })
        }
        "cs_tex" => {
            // One recording per filter (Phong with bilinear) and a mirrored one, one Verilator build and four runs per
            // mutant: Icarus replays cs_tex at about two cycles per second. (The replay test's own recording,
            // trilinear Gouraud on 40x24, killed the same 2 of the first 12 mutants drawn.)
            let recs = crate::cs::stimulus::cs_tex_filter_recordings(0x7E57)?;
            let cycles: Vec<String> = recs.iter().map(|r| r.cycles().to_string()).collect();
            let stimulus = format!(
                "{} cycles: per filter (nearest with clamping, bilinear with Phong, trilinear), then trilinear Phong with the texture mirrored in s and t, a textured and an untextured 48x32 frame of the checkered teapot-floor scene, 30% stalls, starts offered while busy",
                cycles.join(" + ")
            );
            let replay: Replay = Box::new(move |v, d| crate::cs::replay::replay_verilator_all(v, "cs_tex", &recs, d).map(|_| ()));
            Ok(Target { top: "cs_tex", verilog: hdl::cs::color_shader_tex::verilog()?, stimulus, replay })
        }
        "opp" => opp_target(dir),
        "tex_setup" => {
            // The random test's kinds (both signs of det, zero area, saturating and real-range values).
            let mut rng = crate::common::Rng::new(0x7E5E);
            let cmds = crate::cs::tex_setup_bench::random_commands(600, &mut rng);
            let run = crate::cs::tex_setup_bench::run("mutation_tex_setup", &cmds, &cmds, 30, 0x7E5E, true)?;
            let rec = run.recording.expect("recorded");
            let stimulus = format!("{} cycles: 600 random commands of the texture setup bench's kinds, 30% gaps", rec.cycles());
            let replay: Replay = Box::new(move |v, d| crate::cs::replay::replay_iverilog(v, "tex_setup", &rec, d).map(|_| ()));
            Ok(Target { top: "tex_setup", verilog: hdl::cs::tex_setup::verilog()?, stimulus, replay })
        }
        _ => Err(format!("unknown top '{top}': the mutation cover knows {}", TOPS.join(", "))),
    }
}

/// `rc` at 32x24: the hand-made cases (every hazard the tests name) and six random triangle lists, one
/// stream, random gaps and back-pressure.
fn rc_target(dir: &Path) -> Result<Target, String> {
    use crate::rc::bench::{run_model, Drive};
    use crate::rc::replay::{replay_verilog, Simulator, VectorWriter};
    let (screen, cmds) = rc_stream();
    let mut w = VectorWriter::create(dir.join("rc.vec"))?;
    let drive = Drive { garbage: false, ..Drive::random("mutation_rc", 0x1ca5) };
    run_model(screen, &cmds, drive, Some(&mut w))?;
    let (vectors, cycles) = w.finish()?;
    let replay: Replay = Box::new(move |v, d| {
        let file = d.join("rc.v");
        std::fs::write(&file, v).map_err(|e| format!("cannot write {}: {e}", file.display()))?;
        let n = replay_verilog(Simulator::Icarus, screen, &file, d, &vectors, None)?;
        if n == cycles { Ok(()) } else { Err(format!("the replay stopped after {n} of {cycles} cycles")) }
    });
    let stimulus = format!("{cycles} {RC_STREAM}");
    Ok(Target { top: "rc", verilog: hdl::rc::verilog(screen.width, screen.height)?, stimulus, replay })
}

/// What [`rc_stream`] holds, after its cycle count.
const RC_STREAM: &str = "cycles at 32x24: the hand-made cases, 6 random lists of 40 triangles, 8 lists of 80 triangles on one pixel each (fragments back to back; random, near or stepping depths; 16-bit indices), 2 lists of 40 right triangles with power-of-two determinants and 2 queue-filling lists (40 small, then 40 random triangles behind a screen-size one), 2 lists of 40 triangles with a fragment's depth within 2 and 32 units of 2^-16 of a rounding edge, 40 random triangles queued behind a far screen-size one, 2 lists of 40 wide triangles with a long-skip test within 128 and 512 square sixteenths of a pixel of an edge, 2 lists of 40 slivers under 1/8 pixel with a fragment's depth within 2 and 8 units of a rounding edge, random gaps and stalls";

/// The RCs' stream at 32x24: the hand-made cases, then six random lists of 40 triangles, then eight
/// lists of 80 triangles on one pixel each (four with random depths, four with a staircase) ([`hazard_triangles`](crate::rc::stimulus::hazard_triangles),
/// added for the survivors of the first run: forwarded depths and high index bits), then two lists of
/// 40 right triangles with power-of-two determinants ([`power_of_two_triangles`](crate::rc::stimulus::power_of_two_triangles),
/// added for a survivor in the reciprocal's remainder), then two queue-filling lists: a screen-size
/// triangle with 40 small ones piling up behind it
/// ([`queue_filling_triangles_on`](crate::rc::stimulus::queue_filling_triangles_on)), and with 40
/// random ones ([`queue_filling_random_triangles`](crate::rc::stimulus::queue_filling_random_triangles));
/// added for a survivor in a queue entry's hold; then, for the survivors in the depth's arithmetic,
/// two cleared frames of 40 triangles each with a fragment whose raw depth is within 2 and 32 units
/// of 2^-16 of a rounding edge ([`depth_rounding_edge_triangles`](crate::rc::stimulus::depth_rounding_edge_triangles)),
/// and for those in the record queue, 40 random triangles queued behind a screen-size one at the far
/// end, so that they are visible ([`queue_filling_random_triangles_in_front`](crate::rc::stimulus::queue_filling_random_triangles_in_front)),
/// and for those in the long skip's step multiples, two cleared frames of 40 wide triangles each
/// with a long-skip test where an edge's value at x + 15 is negative by at most 128 and 512 square
/// sixteenths of a pixel (times 256 in S11.8's subpixel^2)
/// ([`long_skip_edge_triangles`](crate::rc::stimulus::long_skip_edge_triangles)), and for the
/// survivor in the gradient product's low bits, two cleared frames of 40 slivers under 1/8 pixel
/// with a fragment's raw depth within 2 and 8 units of a rounding edge
/// ([`sliver_depth_rounding_edge_triangles`](crate::rc::stimulus::sliver_depth_rounding_edge_triangles)).
fn rc_stream() -> (Screen, Vec<golden::cycle::rc::RcCmd>) {
    use crate::rc::stimulus::{depth_rounding_edge_triangles, frame, hand_made, hand_made_screen, hazard_triangles, power_of_two_triangles, queue_filling_random_triangles, queue_filling_random_triangles_in_front, queue_filling_triangles_on, long_skip_edge_triangles, random_triangles, sliver_depth_rounding_edge_triangles};
    let screen = hand_made_screen();
    let mut cmds: Vec<_> = hand_made().into_iter().flat_map(|(_, c)| c).collect();
    let mut rng = Rng::new(0x3_7a7e);
    for _ in 0..6 {
        cmds.extend(frame(true, random_triangles(&mut rng, screen, 40)));
    }
    for staircase in [false, false, false, false, true, true, true, true] {
        cmds.extend(frame(true, hazard_triangles(&mut rng, screen, 80, staircase)));
    }
    for _ in 0..2 {
        cmds.extend(frame(true, power_of_two_triangles(&mut rng, screen, 40)));
    }
    cmds.extend(queue_filling_triangles_on(screen));
    cmds.extend(queue_filling_random_triangles(&mut rng, screen, 40));
    for band in [2, 32] {
        cmds.extend(frame(true, depth_rounding_edge_triangles(&mut rng, screen, 40, band)));
    }
    cmds.extend(queue_filling_random_triangles_in_front(&mut rng, screen, 40));
    let sixteenth_sq = (golden::format::SUBPIXEL_ONE as i64 / 16).pow(2);
    for band in [128 * sixteenth_sq, 512 * sixteenth_sq] {
        cmds.extend(frame(true, long_skip_edge_triangles(&mut rng, screen, 40, band)));
    }
    for band in [2, 8] {
        cmds.extend(frame(true, sliver_depth_rounding_edge_triangles(&mut rng, screen, 40, band)));
    }
    (screen, cmds)
}

/// `rc3` (Type III) at 32x24 on the same stream as `rc`, every port a column of the vectors (TdbV's
/// read data are inputs, as the bench's memory model returned them).
fn rc3_target(dir: &Path) -> Result<Target, String> {
    use crate::rc::bench::{run_model_of, Drive};
    use crate::rc::replay::{rc3_ports, Rc3Vectors};
    let (screen, cmds) = rc_stream();
    let mut w = Rc3Vectors::create(dir.join("rc3.vec"))?;
    let drive = Drive { garbage: false, ..Drive::random("mutation_rc3", 0x3ca5) };
    run_model_of(golden::raster::RcType::III, screen, &cmds, drive, Some(&mut w))?;
    let (vectors, cycles) = w.0.finish()?;
    let replay: Replay = Box::new(move |v, d| crate::proof::replay::replay("iverilog", d, "rc3", &rc3_ports(), v, &vectors, cycles).map(|_| ()));
    let stimulus = format!("{cycles} {RC_STREAM}");
    Ok(Target { top: "rc3", verilog: hdl::rc::rc3::verilog(screen.width, screen.height)?, stimulus, replay })
}

/// `opp` (eight OPs, FIFO depth 1): random frames of 14, 20 and 20 objects at 24x16, 25% gaps on both
/// sides (the third with 60% output stalls), a fourth of 20 with every other object transparent
/// (issue 22's `opaque` bit), and three added for the survivors of round 3, which all sit in OP 0's
/// parameters and comparisons: 48 small objects (OP 0 reloaded many times), 20 with vertices up to
/// 40 pixels off a centre (edge distances and depths far from the screen's), 24 at depths 0-3
/// (lists of near-equal depths, ties broken by the id); and three for the survivors of the draw after
/// the parameter trim: 40 right triangles with axis-aligned legs on pixel corners
/// ([`axis_aligned_objects`](crate::proof::bench::axis_aligned_objects): distance plus threshold
/// exactly 0), 20 random objects on a 1024x2 screen (pixel columns above 511), and there 12 right
/// triangles with legs of 1500-2000 pixels (edge distances above 1024 pixels); and one for the two
/// survivors after that, thresholds moved by 1 or 16 LSB: three frames of 48 small objects (ids up
/// to 47) with every edge's distance exactly on a threshold at one pixel
/// ([`threshold_objects`](crate::proof::bench::threshold_objects): on `t_full`, on `-t_none`, one above).
fn opp_target(dir: &Path) -> Result<Target, String> {
    use crate::proof::bench::{axis_aligned_objects, opp_ports, random_objects, random_objects_shaped, run_frame, threshold_objects, ObjectShape, Threshold};
    use golden::proof::cycle_opp::Gaps;
    let s = Screen::new(24, 16)?;
    let mut rng = Rng::new(0x7e91a7);
    let mut recs = Vec::new();
    // Frames 0 and 1 as in the first cover run; frame 2 (added for its survivors) holds the output
    // back 60 % of the time. (Random 16-bit ids are not possible: an id is the object's position in
    // the frame's list in every model.)
    let shaped = [
        ObjectShape { span: 3, big_span: 6, big_percent: 20, depths: 1 << 24 },
        ObjectShape { span: 24, big_span: 80, big_percent: 50, depths: 1 << 24 },
        ObjectShape { span: 12, big_span: 24, big_percent: 30, depths: 4 },
    ];
    let wide = Screen::new(1024, 2)?;
    for (i, count) in [14, 20, 20, 20, 48, 20, 24, 40, 20, 12, 48, 48, 48].into_iter().enumerate() {
        let screen = if i == 8 || i == 9 { wide } else { s };
        let mut objs = match i {
            0..=3 => random_objects(&mut rng, screen, count, 8),
            4..=6 => random_objects_shaped(&mut rng, screen, count, 8, shaped[i - 4]),
            7 => axis_aligned_objects(&mut rng, screen, count, 8, (1, 6)),
            8 => random_objects_shaped(&mut rng, screen, count, 8, ObjectShape { span: 40, big_span: 200, big_percent: 30, depths: 1 << 24 }),
            9 => axis_aligned_objects(&mut rng, screen, count, 8, (1500, 2000)),
            10 => threshold_objects(&mut rng, screen, count, 8, Threshold::Full),
            11 => threshold_objects(&mut rng, screen, count, 8, Threshold::None(0)),
            _ => threshold_objects(&mut rng, screen, count, 8, Threshold::None(1)),
        };
        if i == 3 {
            for o in objs.iter_mut().step_by(2) {
                o.alpha = 128;
            }
        }
        let sink_gap_percent = if i == 2 { 60 } else { 25 };
        let gaps = Gaps { seed: rng.next_u64(), source_gap_percent: 25, sink_gap_percent };
        let (_, rec) = run_frame(screen, &objs, 8, 1, Some(gaps), None, Some(dir.join(format!("opp{i}.vec"))))?;
        recs.push(rec.ok_or("the OPP bench wrote no vectors")?);
    }
    let stimulus = format!(
        "{} cycles: thirteen random frames, 25% gaps: at 24x16 14, 20, 20 and 20 objects (the third with 60% output stalls, the fourth with every other object transparent), 48 small ones, 20 far-reaching ones, 24 at depths 0-3, 40 axis-aligned right triangles on pixel corners; at 1024x2 20 objects, 12 right triangles with legs of 1500-2000 pixels; at 24x16 three frames of 48 small objects with every edge's distance exactly on a threshold at one pixel (t_full, -t_none, -t_none + 1)",
        recs.iter().map(|r| r.1).sum::<u64>()
    );
    let replay: Replay = Box::new(move |v, d| {
        for (path, cycles) in &recs {
            crate::proof::replay::replay("iverilog", d, "opp", &opp_ports(), v, path, *cycles)?;
        }
        Ok(())
    });
    Ok(Target { top: "opp", verilog: hdl::verilog_top("opp")?, stimulus, replay })
}

/// What became of one mutant.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// A port differed (the first mismatch), or the run did not end.
    Killed(String),
    /// Proven equivalent to the original netlist, over the mutated module or over the whole top.
    Equivalent(Scope),
    /// Passed the replay and not proven equivalent (Yosys's last words).
    Surviving(String),
    /// The mutant could not be built or run (a tool error, not a verdict).
    Error(String),
}

impl Outcome {
    pub fn name(&self) -> &'static str {
        match self {
            Outcome::Killed(_) => "killed",
            Outcome::Equivalent(_) => "equivalent",
            Outcome::Surviving(_) => "surviving",
            Outcome::Error(_) => "error",
        }
    }
    /// The first mismatch, Yosys's last words or the error; empty for an equivalent mutant.
    pub fn detail(&self) -> &str {
        match self {
            Outcome::Killed(d) | Outcome::Surviving(d) | Outcome::Error(d) => d,
            Outcome::Equivalent(Scope::Dead) => "the mutated cell reaches no port of the flattened top",
            Outcome::Equivalent(Scope::Module) => "equiv_induct proves every equivalence of the mutated module",
            Outcome::Equivalent(Scope::Top) => "equiv_induct proves every equivalence of the whole top, flattened",
        }
    }
}

fn run(cmd: &mut Command, what: &str) -> Result<String, String> {
    let o = cmd.output().map_err(|e| format!("{what}: cannot run: {e}"))?;
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    if !o.status.success() {
        let tail: Vec<&str> = text.lines().rev().take(15).collect();
        return Err(format!("{what} failed ({}):\n{}", o.status, tail.into_iter().rev().collect::<Vec<_>>().join("\n")));
    }
    Ok(text)
}

/// The work directory of a top's cover.
pub fn work_dir(top: &str) -> PathBuf {
    workspace_target().join("mutation").join(top)
}

/// Yosys's netlist of the top (`prep -top`): kept as `orig.il` in `dir` for the mutations, and returned
/// as Verilog. It must replay as the generated Verilog does, or Yosys and the simulators read the
/// generated Verilog differently (as they did before `hdl::common::sized_localparams`).
pub fn yosys_netlist(t: &Target, dir: &Path) -> Result<String, String> {
    std::fs::write(dir.join("orig.v"), &t.verilog).map_err(|e| e.to_string())?;
    let script = format!("read_verilog -sv orig.v; prep -top {}; write_rtlil orig.il; write_verilog -noattr netlist.v", t.top);
    run(Command::new("yosys").current_dir(dir).args(["-q", "-p", &script]), "yosys prep")?;
    std::fs::read_to_string(dir.join("netlist.v")).map_err(|e| format!("{}: {e}", dir.join("netlist.v").display()))
}

/// Draw `n` mutations of `orig.il` in `dir` (written by [`yosys_netlist`]) with `seed`; returns Yosys's
/// `mutate` commands, one per mutant.
pub fn draw(n: usize, seed: u64, dir: &Path) -> Result<Vec<String>, String> {
    let script = format!("read_rtlil orig.il; mutate -list {n} -seed {seed} -o mutations.ys");
    run(Command::new("yosys").current_dir(dir).args(["-q", "-p", &script]), "yosys mutate -list")?;
    let list = std::fs::read_to_string(dir.join("mutations.ys")).map_err(|e| e.to_string())?;
    let cmds: Vec<String> = list.lines().filter(|l| l.starts_with("mutate ")).map(str::to_string).collect();
    if cmds.len() != n {
        return Err(format!("yosys drew {} mutations, not {n}", cmds.len()));
    }
    Ok(cmds)
}

/// Write every mutant of `orig.il` (`mutant_I.v`) as Verilog, in one Yosys run.
pub fn write_mutants(cmds: &[String], dir: &Path) -> Result<(), String> {
    let mut ys = String::from("read_rtlil orig.il\ndesign -save orig\n");
    for (i, c) in cmds.iter().enumerate() {
        ys += &format!("design -load orig\n{c}\nwrite_verilog -noattr mutant_{i}.v\n");
    }
    std::fs::write(dir.join("write_mutants.ys"), ys).map_err(|e| e.to_string())?;
    run(Command::new("yosys").current_dir(dir).args(["-q", "-s", "write_mutants.ys"]), "yosys write mutants")?;
    Ok(())
}

/// The wall-time limit of the equivalence check over the mutated module.
pub const EQUIV_SECONDS: u32 = 60;
/// The wall-time limit of the equivalence check over the whole flattened top (colour setup's took
/// 80 s to 5 min per mutant with two jobs on the 2-core VM).
pub const TOP_EQUIV_SECONDS: u32 = 600;

/// Where an equivalence was proven.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scope {
    /// The mutated cell drives nothing that reaches a port of the top: the flattened top without it
    /// is the same circuit (any mutation of it, a clock's included).
    Dead,
    /// The mutated module alone, from any register values: equivalent in every context.
    Module,
    /// The whole top, flattened, from its initial values: the mutation cannot reach a port.
    Top,
}

/// Is the mutant `cmd` equivalent to the original? First whether the mutated cell is dead in the top
/// ([`cell_is_dead_in_top`]), then the mutated module alone, then the whole top. Each side is the
/// module (or top) with its submodules flattened in and memories mapped to registers; Yosys's `equiv_make` pairs every signal of the same name, `equiv_simple -seq 4` and
/// `equiv_induct -seq 4` prove the pairs, and `equiv_status -assert` demands that every pair be proven,
/// within [`EQUIV_SECONDS`] (module) or [`TOP_EQUIV_SECONDS`] (top) of wall time.
///
/// `equiv_simple` proves a pair assuming the pairs in its input cone, so a single unproven pair leaves
/// the others conditional: only "every pair proven" is a proof (an induction over all pairs together,
/// whose base is the common initial state). A mutation inside a register's own module can never be
/// proven there (the register's output differs by construction); over the top it is proven when the
/// changed bit is never read, or never differs, in any reachable state that the pairs describe.
/// Returns the scope of the proof, or the last failure.
pub fn equivalent(cmd: &str, top: &str, dir: &Path, i: usize) -> Result<Scope, String> {
    if cell_is_dead_in_top(cmd, top, dir, i)? {
        return Ok(Scope::Dead);
    }
    if touches_a_clock(cmd) {
        return Err(CLOCK_UNDECIDED.into());
    }
    let module = mutate_arg(cmd, "-module")?;
    if module != top && prove_equivalent(cmd, module, dir, &format!("equiv_{i}.ys"), EQUIV_SECONDS).is_ok() {
        return Ok(Scope::Module);
    }
    prove_equivalent(cmd, top, dir, &format!("equiv_top_{i}.ys"), TOP_EQUIV_SECONDS).map(|_| Scope::Top)
}

/// The word after `flag` in a `mutate` command.
fn mutate_arg<'a>(cmd: &'a str, flag: &str) -> Result<&'a str, String> {
    cmd.split_whitespace().skip_while(|w| *w != flag).nth(1).ok_or(format!("no {flag} in '{cmd}'"))
}

/// Yosys's selection of the marked cell if it is a primitive cell.
const PRIMITIVE: &str = "a:mutation_target t:$* %i";

/// Is the cell that `cmd` mutates removed when the unmutated top is flattened and everything that
/// reaches no port is cleaned away (`splitnets`, `opt_clean -purge`: wires split into bits, so that a
/// cell read only through unread bits goes too)? A mutation changes only that cell's connections, so
/// it cannot change a port then. The cell is marked with an attribute before
/// flattening, as rust-hdl's module names do not spell the instance path unambiguously.
pub fn cell_is_dead_in_top(cmd: &str, top: &str, dir: &Path, i: usize) -> Result<bool, String> {
    let (module, cell) = (mutate_arg(cmd, "-module")?, mutate_arg(cmd, "-cell")?);
    let file = format!("dead_{i}.ys");
    // The first count checks that the names match. The second, that the cell is a primitive (`$...`):
    // an instance of a module disappears in `flatten` whether its contents are used or not (a rule
    // without it called 6 of 19 killed colour-setup mutants dead). `hierarchy` drops a module that the top
    // no longer instantiates (Yosys's `prep` removes an instance whose outputs nothing reads).
    let ys = format!(
        "read_rtlil orig.il\nsetattr -set mutation_target 1 {module}/{cell}\nselect -assert-count 1 a:mutation_target\n\
         select -assert-count 1 {PRIMITIVE}\nhierarchy -top {top}\nflatten\nmemory_map\nsplitnets\nopt_clean -purge\nselect -assert-none a:mutation_target\n"
    );
    std::fs::write(dir.join(&file), ys).map_err(|e| e.to_string())?;
    match run(Command::new("timeout").current_dir(dir).args([TOP_EQUIV_SECONDS.to_string().as_str(), "yosys", "-q", "-s", &file]), "yosys dead-cell check") {
        Ok(_) => Ok(true),
        Err(e) if e.contains("Assertion failed: selection is not empty") => Ok(false),
        Err(e) if e.contains(&format!("instead of the asserted 1: {PRIMITIVE}")) => Ok(false),
        Err(e) => Err(e),
    }
}

/// `equiv_make`, `equiv_simple -seq 4`, `equiv_induct -seq 4`, `equiv_status -assert` of `module`
/// (flattened) with and without the mutation `cmd`, on `orig.il` in `dir`, in at most `seconds`.
fn prove_equivalent(cmd: &str, module: &str, dir: &Path, file: &str, seconds: u32) -> Result<(), String> {
    let prepare = |name: &str| format!("hierarchy -top {module}\nflatten\nmemory_map\nopt_clean -purge\nrename {module} {name}\ndesign -stash {name}\n");
    let ys = format!(
        "read_rtlil orig.il\ndesign -save orig\n{cmd}\n{}design -load orig\n{}\
         design -copy-from gold -as gold gold\ndesign -copy-from gate -as gate gate\n\
         equiv_make gold gate equiv\nhierarchy -top equiv\nequiv_simple -seq 4\nequiv_induct -seq 4\nequiv_status -assert\n",
        prepare("gate"),
        prepare("gold")
    );
    std::fs::write(dir.join(file), ys).map_err(|e| e.to_string())?;
    run(Command::new("timeout").current_dir(dir).args([seconds.to_string().as_str(), "yosys", "-q", "-s", file]), "yosys equiv").map(|_| ())
}

/// Why a clock mutation is never called equivalent: Yosys's SAT model of a flip-flop steps it every
/// cycle whatever its clock input does, so `equiv_induct` "proves" a register with its clock tied
/// to 0 or inverted equivalent to the original (it did, for three CS and five colour-setup mutants, before this rule).
pub const CLOCK_UNDECIDED: &str = "a clock mutation: equiv_* ignore flip-flop clocks, so they cannot decide it";

/// Does the mutation act on a flip-flop's clock (its CLK port or the `clock` net)?
pub fn touches_a_clock(cmd: &str) -> bool {
    let words: Vec<&str> = cmd.split_whitespace().collect();
    words.windows(2).any(|w| (w[0] == "-port" && w[1] == "CLK") || (w[0] == "-wire" && w[1] == "clock"))
}

/// Replay mutant `i` and, if it survives and `prove` is set, try to prove it equivalent (without
/// `prove`, a survivor is [`Outcome::Surviving`] with [`EQUIVALENCE_NOT_TRIED`]).
pub fn judge(t: &Target, cmd: &str, dir: &Path, i: usize, prove: bool) -> Outcome {
    let v = match std::fs::read_to_string(dir.join(format!("mutant_{i}.v"))) {
        Ok(v) => v,
        Err(e) => return Outcome::Error(format!("cannot read mutant_{i}.v: {e}")),
    };
    match t.replay(&v, &dir.join(format!("run_{i}"))) {
        Err(e) if KILLED.iter().any(|k| e.contains(k)) => Outcome::Killed(first_line_about_the_failure(&e)),
        Err(e) => Outcome::Error(e.lines().take(3).collect::<Vec<_>>().join(" / ")),
        Ok(()) if !prove => Outcome::Surviving(EQUIVALENCE_NOT_TRIED.into()),
        Ok(()) => match equivalent(cmd, t.top, dir, i) {
            Ok(scope) => Outcome::Equivalent(scope),
            Err(e) if e.contains("exit status: 124") => Outcome::Surviving(format!("equivalence not proven within {TOP_EQUIV_SECONDS} s (whole top)")),
            Err(e) => Outcome::Surviving(e.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("").trim().to_string()),
        },
    }
}

/// The detail of a survivor judged without the equivalence check (`mutation --replay-only`).
pub const EQUIVALENCE_NOT_TRIED: &str = "not killed; equivalence not tried (--replay-only)";

/// What the replays print when a port differs or the run never ends (`timeout` exits 124).
const KILLED: [&str; 6] = ["FAILED", "MISMATCH", "differs from the cycle model", "did not finish", "stopped after", "exit status: 124"];

fn first_line_about_the_failure(e: &str) -> String {
    e.lines()
        .find(|l| KILLED.iter().any(|k| l.contains(k)))
        .unwrap_or_else(|| e.lines().next().unwrap_or(""))
        .trim()
        .chars()
        .take(160)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{equivalent, run, touches_a_clock, Scope, CLOCK_UNDECIDED};
    use crate::common::{require_tools, workspace_target};
    use std::process::Command;

    /// A top whose register module `held` is given 0 in its high 4 bits, and whose register `idle`
    /// only holds its own value, as a stage register that no stage uses.
    const TINY: &str = "module held(input wire clock, input wire [7:0] d, output reg [7:0] q);
    initial q = 8'h0;
    always @(posedge clock) q <= d;
endmodule
module idle(input wire clock, input wire [7:0] d, output reg [7:0] q);
    initial q = 8'h0;
    always @(posedge clock) q <= d;
endmodule
module tiny(input wire clock, input wire [7:0] a, output wire [7:0] y);
    wire [7:0] q, s;
    held r(.clock(clock), .d({4'b0000, a[3:0]}), .q(q));
    idle k(.clock(clock), .d(s), .q(s));
    assign y = q;
endmodule
";

    #[test]
    fn a_bit_the_top_keeps_constant_is_proven_over_the_top_a_dead_register_is_found_and_live_mutations_are_not_proven() {
        if !require_tools("a_bit_the_top_keeps_constant_is_proven_over_the_top_a_dead_register_is_found_and_live_mutations_are_not_proven", &["yosys", "timeout"]) {
            return;
        }
        let dir = workspace_target().join("mutation-test");
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("tiny.v"), TINY).unwrap();
        run(Command::new("yosys").current_dir(&dir).args(["-q", "-p", "read_verilog tiny.v; prep -top tiny; write_rtlil orig.il; mutate -list 1000 -seed 1 -o m.ys"]), "yosys").unwrap();
        let list = std::fs::read_to_string(dir.join("m.ys")).unwrap();
        let find = |mode: &str, module: &str, port: &str| {
            list.lines()
                .find(|l| l.starts_with(&format!("mutate -mode {mode} -module {module} ")) && l.contains(&format!(" -port {port} ")))
                .unwrap_or_else(|| panic!("yosys drew no {mode} mutation of {module}'s port {port}:\n{list}"))
                .to_string()
        };
        // Forcing held's output bit 6 to 0 (what it always holds in tiny, not in every context) or to 1.
        let pick = |mode: &str| find(mode, "held", "Q -portbit 6");
        assert_eq!(equivalent(&pick("const0"), "tiny", &dir, 0), Ok(Scope::Top), "held.q[6] is always 0 in tiny");
        let live = equivalent(&pick("const1"), "tiny", &dir, 1);
        assert!(live.as_ref().is_err_and(|e| e.contains("unproven")), "held.q[6] forced to 1 is y[6] = 1, yet: {live:?}");
        // An instance of a live module is not dead, though `flatten` removes the instance cell.
        let instance = list.lines().find(|l| l.starts_with("mutate -mode inv -module tiny -cell r ")).unwrap_or_else(|| panic!("no mutation of the instance r:\n{list}"));
        assert!(equivalent(instance, "tiny", &dir, 4).is_err(), "{instance}");
        // A clock mutation: decided only where the register reaches no port.
        assert_eq!(equivalent(&find("inv", "idle", "CLK"), "tiny", &dir, 2), Ok(Scope::Dead));
        assert_eq!(equivalent(&find("inv", "held", "CLK"), "tiny", &dir, 3), Err(CLOCK_UNDECIDED.to_string()));
    }

    #[test]
    fn mutations_of_a_clock_are_recognised_and_others_are_not() {
        assert!(touches_a_clock("mutate -mode const0 -module cs$fifo$mem$1 -cell $procdff$3564 -port CLK -portbit 0 -wire clock -wirebit 0"));
        assert!(touches_a_clock("mutate -mode inv -module m -cell c -port Y -portbit 0 -wire clock -wirebit 0"));
        assert!(!touches_a_clock("mutate -mode inv -module rc$z_test$queue$r4 -cell $procdff$5606 -port D -portbit 9 -wire d -wirebit 9"));
        assert!(!touches_a_clock("mutate -mode const1 -module m -cell c -port B -portbit 4 -wire clock_enable -wirebit 0"));
    }
}
