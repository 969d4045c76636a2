//! `idxrender bench`: the project's performance side by side, in one Markdown table file (`bench.md`)
//! and the same figures with their raw counts in `bench.json` beside it.
//!
//! * **Golden model**: frames per second of `render --scene S --size WxH` for every scene at 320x200
//!   and 640x480. The frame is all of `golden::render::render`: the host's transform, clipping and
//!   deferred lighting, the RC, colour setup and the CS. Each frame is repeated for a minimum time.
//! * **Simulators**: cycles per second and seconds per frame of the RustHDL simulation (`RtlChipset`)
//!   and of the generated Verilog under Verilator (`VerilatorChipset`). The frames are driven by the
//!   same host program and compared with the golden frame as `render --backend` compares them.
//! * **Hardware efficiency**: cycles per phase (the backends' accounting, `cycles.json`), RC candidates
//!   and fragments per clock, RC and colour-setup cycles per triangle, CS pixels per clock, against the
//!   limits of one fragment per clock (traversal and the Z port: one Z read per clock) and one pixel per
//!   clock (scan-out). Each scene and size runs [`FRAMES_PER_RUN`] frames back to back on one chipset
//!   (the RC draws frame N+1 while the CS scans frame N out); the steady state is the last frame, and
//!   its frame interval (scan start to scan start) is the time per frame.
//! * **Frames per second at Fmax**: from the `chipset` rows of `fpga-report`'s JSON, against seed 000
//!   Table IV's frame rates (`golden::analysis::levels`). Without an Fmax the table says why and gives
//!   no frame rate; it never assumes a clock.
//!
//! Arguments are checked (scenes, the FPGA report, the output path) before anything is measured, and
//! the files are written only at the end, each through a rename: a failed run leaves earlier output.

use crate::args::{load_scene, render_options, RenderArgs};
use golden::analysis::levels::{HardwareLevel, TABLE_IV};
use golden::format::Screen;
use golden::raster::TriResult;
use golden::render::{render, Frame, RenderOptions};
use golden::scene::{builtin, Mesh};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use tb::backend::{render_timed, render_timed_frames, CycleChipset, TimedFrame};
use tb::chipset::{PhaseCycles, RtlChipset};
use tb::verilator::VerilatorChipset;

#[derive(clap::Args, Debug)]
pub struct BenchArgs {
    /// The Markdown file to write; bench.json (the same figures with their raw counts) goes beside it.
    #[arg(long, default_value = "out/bench.md")]
    pub out: PathBuf,
    /// Shorter measurements (for CI): golden frames timed for 0.1 s instead of 1 s; the RustHDL
    /// simulation runs a polyhedron frame at 80x50 instead of a teapot frame at 320x200.
    #[arg(long)]
    pub quick: bool,
    /// fpga-report's JSON (`chipset` rows with `fmax_mhz`). Default out/fpga-report.json, where a
    /// missing file means "no Fmax"; a file named here must exist.
    #[arg(long)]
    pub fpga_report: Option<PathBuf>,
    /// Built-in scenes to measure, comma-separated (default: polyhedron, teapot, castle, dolphins).
    #[arg(long, value_delimiter = ',')]
    pub scenes: Vec<String>,
    /// Instead of the chipset figures: seed 002's real-time claim, PROOF's frames per second at
    /// 512x512 against the number of object processors (writes out/proof-realtime.md, .json, .png
    /// unless --out names another file).
    #[arg(long)]
    pub proof_realtime: bool,
    /// fpga-report JSON files holding the `opp`, `proof_shade` and `proof_filter` rows on ecp5-45k
    /// (comma-separated or repeated), for --proof-realtime's clock.
    #[arg(long, value_delimiter = ',')]
    pub proof_fpga: Vec<PathBuf>,
}

/// The two screen sizes of the issue: seed 001's size (Table IV's low end) and the models' native size.
const SIZES: [(u32, u32); 2] = [(320, 200), (640, 480)];
const DEFAULT_FPGA_REPORT: &str = "out/fpga-report.json";

pub fn run(args: &BenchArgs) -> Result<(), String> {
    let t_start = Instant::now();
    // Everything that can be wrong with the arguments is found before the first measurement.
    let scenes = scene_names(&args.scenes)?;
    if args.proof_realtime {
        let out = if args.out == Path::new("out/bench.md") { PathBuf::from("out/proof-realtime.md") } else { args.out.clone() };
        return crate::proof_realtime::run(&out, &args.proof_fpga, &scenes);
    }
    if !args.proof_fpga.is_empty() {
        return Err("--proof-fpga applies to --proof-realtime".into());
    }
    let fpga = read_fpga_report(args.fpga_report.as_deref())?;
    let (out_dir, md_name, json_name) = output_paths(&args.out)?;
    let load_start = load_average();
    let mode = if args.quick { Mode::quick() } else { Mode::full() };

    // Steps: the Verilator builds, a golden and a Verilator step per scene and size, RustHDL, RC setup.
    let steps = (scenes.len() * SIZES.len() * 2 + 3) as u64;
    let bar = ProgressBar::new(steps);
    bar.set_style(
        ProgressStyle::with_template("{elapsed:>4} [{bar:30}] {pos}/{len} {msg}").map_err(|e| format!("progress bar: {e}"))?.progress_chars("=> "),
    );

    // Verilator first: a missing tool or a failed build stops the run before the long parts.
    bar.set_message("building the Verilated chipset");
    let mut builds = Vec::new();
    for (w, h) in SIZES {
        builds.push(tb::verilator::build(Screen::new(w, h)?, None)?);
    }
    bar.inc(1);

    // The golden frames: timed, and kept as the reference of every simulated frame.
    let mut cases = Vec::new();
    let mut golden_rows = Vec::new();
    for &(w, h) in &SIZES {
        for name in &scenes {
            bar.set_message(format!("golden {name} {w}x{h}"));
            let (mesh, opts) = scene_options(name, w, h)?;
            let (frame, timing) = time_golden(&mesh, &opts, mode.golden_min)?;
            golden_rows.push(GoldenRow {
                scene: name.clone(),
                size: [w, h],
                triangles_in: frame.stats.triangles_in,
                sent_to_rc: frame.stats.sent_to_rc,
                frames: timing.0,
                seconds: timing.1,
                ms_per_frame: 1e3 * timing.1 / timing.0 as f64,
                frames_per_second: timing.0 as f64 / timing.1,
            });
            cases.push(Case { scene: name.clone(), mesh, opts, golden: frame });
            bar.inc(1);
        }
    }

    // Verilator: every scene and size, FRAMES_PER_RUN frames back to back on one chipset (the last is
    // the steady state).
    let mut frames = Vec::new();
    let mut sim_rows = Vec::new();
    for case in &cases {
        let (w, h) = (case.opts.screen.width, case.opts.screen.height);
        bar.set_message(format!("Verilator {} {w}x{h}", case.scene));
        let build = builds[SIZES.iter().position(|&s| s == (w, h)).expect("a size of SIZES")].clone();
        let mut chip = VerilatorChipset::from_build(case.opts.screen, build)?;
        let c0 = chip.cycle;
        let runs = render_timed_frames(&case.mesh, &case.opts, FRAMES_PER_RUN as usize, &mut chip);
        let rows: Vec<FrameRow> = runs.iter().enumerate().map(|(k, run)| FrameRow::new(case, k as u32 + 1, run)).collect();
        let verdict = rows.iter().map(|r| r.equals_golden.clone()).find(|v| !v.equal).unwrap_or_else(|| rows[rows.len() - 1].equals_golden.clone());
        let done = rows.iter().all(|r| r.phases.is_some());
        sim_rows.push(SimRow::new("Verilator", case, FRAMES_PER_RUN, done.then_some(chip.cycle - c0), runs[0].secs, &verdict));
        frames.extend(rows);
        bar.inc(1);
    }

    // The traversal's walk (not visible at the chipset's ports): the RC cycle model on each case's
    // steady-state commands; the model equals the RTL in every cycle (tb/tests/rc_rtl.rs).
    let mut traversal = Vec::new();
    for case in &cases {
        bar.set_message(format!("traversal {} {}x{}", case.scene, case.opts.screen.width, case.opts.screen.height));
        traversal.push(traversal_row(case, &frames)?);
    }

    // RustHDL: one whole frame, measured. Quick mode keeps it short with a small screen.
    let rtl = {
        let (scene, (w, h)) = if args.quick {
            ("polyhedron".to_string(), (80, 50))
        } else {
            (if scenes.iter().any(|s| s == "teapot") { "teapot".to_string() } else { scenes[0].clone() }, (320, 200))
        };
        let (mesh, opts) = scene_options(&scene, w, h)?;
        let golden = render(&mesh, &opts)?;
        let case = Case { scene: scene.clone(), mesh, opts, golden };
        let b = bar.clone();
        let label = format!("RustHDL {scene} {w}x{h}");
        let progress: tb::chipset::Progress = Box::new(move |phase: &str, done: u64, total: u64| b.set_message(format!("{label}: {phase} {done}/{total}")));
        let mut chip = RtlChipset::new(case.opts.screen, None)?.with_progress(progress);
        let run = render_timed(&case.mesh, &case.opts, &mut chip);
        let row = FrameRow::new(&case, 1, &run);
        let sim = SimRow::new("RustHDL", &case, 1, row.phases.is_some().then_some(chip.cycle), run.secs, &row.equals_golden);
        bar.inc(1);
        RtlResult { frame: row, sim }
    };
    let rtl_check = rusthdl_against_verilator(&rtl, &frames);
    let teapot_estimate = if args.quick { teapot_seconds_estimate(&rtl.sim, &frames) } else { None };
    sim_rows.insert(0, rtl.sim.clone());

    // RC setup back to back, in both simulators.
    bar.set_message("RC setup, back to back");
    let setup = setup_back_to_back(&builds[0])?;
    bar.inc(1);
    bar.finish_and_clear();

    let load_end = load_average();
    let fmax = fmax_section(&fpga, &steady_frames(&frames, &cases));
    let report = Report {
        command: std::iter::once("idxrender".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" "),
        mode: mode.name.to_string(),
        rc_type: golden::raster::RcType::IV.name(),
        golden_min_seconds: mode.golden_min.0.as_secs_f64(),
        golden_min_frames: mode.golden_min.1,
        seconds: t_start.elapsed().as_secs_f64(),
        machine: Machine::probe(load_start, load_end),
        verilator_builds: SIZES.iter().zip(&builds).map(|(&(w, h), b)| BuildRow { size: [w, h], fresh: b.fresh, seconds: b.seconds }).collect(),
        golden: golden_rows,
        simulators: sim_rows,
        rusthdl_cycles_equal_verilators: rtl_check,
        rusthdl_teapot_seconds_estimate: teapot_estimate,
        frames,
        traversal,
        setup,
        fmax,
    };
    let md = markdown(&report);
    let json = serde_json::to_string_pretty(&report).map_err(|e| format!("bench.json: {e}"))?;
    let written = crate::output::write_set(&out_dir, &[(&md_name, md.as_bytes()), (&json_name, json.as_bytes())])?;
    let (p1, p2) = (written[0].clone(), written[1].clone());
    for line in summary(&report) {
        crate::say!("{line}");
    }
    crate::say!("wrote {} and {} ({:.0} s)", p1.display(), p2.display(), report.seconds);
    Ok(())
}

// ---------------------------------------------------------------------------------------------------
// Arguments

/// How long each part measures.
struct Mode {
    name: &'static str,
    /// A golden frame is repeated until both this time and this many frames are reached.
    golden_min: (Duration, u64),
}

impl Mode {
    fn full() -> Mode {
        Mode { name: "full", golden_min: (Duration::from_secs(1), 5) }
    }
    fn quick() -> Mode {
        Mode { name: "quick", golden_min: (Duration::from_millis(100), 1) }
    }
}

fn scene_names(given: &[String]) -> Result<Vec<String>, String> {
    if given.is_empty() {
        return Ok(builtin::SCENES.iter().map(|s| s.to_string()).collect());
    }
    let mut names: Vec<String> = Vec::new();
    for s in given.iter().map(|s| s.trim()) {
        if !builtin::SCENES.contains(&s) {
            return Err(format!("--scenes: unknown scene '{s}'; the built-in scenes are: {}", builtin::SCENES.join(", ")));
        }
        if !names.iter().any(|n| n == s) {
            names.push(s.to_string());
        }
    }
    Ok(names)
}

/// `--out`'s directory, the Markdown file's name and the JSON file's name; the directory is created
/// and shown writable now, so that a bad path fails before the measurements, not after.
fn output_paths(out: &Path) -> Result<(PathBuf, String, String), String> {
    if out.is_dir() {
        return Err(format!("--out {} is a directory; name the Markdown file, e.g. {}", out.display(), out.join("bench.md").display()));
    }
    let name = out.file_name().map(|n| n.to_string_lossy().to_string()).ok_or_else(|| format!("--out {} is not a file path", out.display()))?;
    let json = Path::new(&name).with_extension("json").to_string_lossy().to_string();
    if json == name {
        return Err(format!("--out {}: the Markdown file must not end in .json (bench.json is written beside it)", out.display()));
    }
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&dir).map_err(|e| format!("--out {}: cannot create {}: {e}", out.display(), dir.display()))?;
    let probe = dir.join(format!(".{name}.probe"));
    std::fs::write(&probe, b"").map_err(|e| format!("--out {}: cannot write in {}: {e}", out.display(), dir.display()))?;
    let _ = std::fs::remove_file(&probe);
    Ok((dir, name, json))
}

/// The frame that `idxrender render --scene NAME --size WxH` renders: the same arguments, parsed by
/// the same definitions, so that the bench measures exactly the command's defaults (camera, Gouraud,
/// back-face culling, the scene's winding, 16-bit index).
fn scene_options(name: &str, w: u32, h: u32) -> Result<(Mesh, RenderOptions), String> {
    use clap::Parser;
    #[derive(Parser)]
    struct RenderCommand {
        #[command(flatten)]
        args: RenderArgs,
    }
    let size = format!("{w}x{h}");
    let r = RenderCommand::try_parse_from(["render", "--scene", name, "--size", &size]).map_err(|e| e.to_string())?;
    let mesh = load_scene(&r.args)?;
    let opts = render_options(&r.args, &mesh)?;
    Ok((mesh, opts))
}

// ---------------------------------------------------------------------------------------------------
// Measurements

/// A scene at one size, with its golden frame (the reference of every simulated frame).
struct Case {
    scene: String,
    mesh: Mesh,
    opts: RenderOptions,
    golden: Frame,
}

/// The golden frame (one untimed frame first, which warms caches and is the reference), then frames
/// repeated until the minimum time and count; returns (frames, seconds).
fn time_golden(mesh: &Mesh, opts: &RenderOptions, (min_time, min_frames): (Duration, u64)) -> Result<(Frame, (u64, f64)), String> {
    let reference = render(mesh, opts)?;
    let t0 = Instant::now();
    let mut n = 0u64;
    loop {
        std::hint::black_box(render(mesh, opts)?);
        n += 1;
        if n >= min_frames && t0.elapsed() >= min_time {
            break;
        }
    }
    Ok((reference, (n, t0.elapsed().as_secs_f64())))
}

#[derive(Serialize)]
struct GoldenRow {
    scene: String,
    size: [u32; 2],
    /// (a): triangles in the scene.
    triangles_in: u64,
    /// Triangles the host sent to the RC (after clipping).
    sent_to_rc: u64,
    frames: u64,
    seconds: f64,
    ms_per_frame: f64,
    frames_per_second: f64,
}

/// Whether a simulated frame equals the golden frame, and the first difference if not.
#[derive(Serialize, Clone)]
struct Verdict {
    equal: bool,
    difference: Option<String>,
}

impl Verdict {
    /// Compared as `render --backend` compares (image, I-buffer, Z-buffer, per-triangle results). A frame
    /// that `render_with` refused (its I-buffer differs from the algorithmic model's) is compared from
    /// what the chipset returned, to name the first differing pixel.
    fn of(golden: &Frame, run: &TimedFrame) -> Verdict {
        let no = |d: String| Verdict { equal: false, difference: Some(d) };
        match (&run.frame, &run.scanout) {
            (Ok(f), _) => match crate::render::compare(golden, f) {
                None => Verdict { equal: true, difference: None },
                Some(d) => no(d),
            },
            (Err(e), Some(s)) if s.ibuf.len() == golden.hw_index.len() && s.zbuf.len() == golden.zbuf.len() && s.rgb.len() == golden.rgb.len() => {
                let chip = Frame {
                    screen: golden.screen,
                    rgb: s.rgb.clone(),
                    index: Vec::new(),
                    hw_index: s.ibuf.clone(),
                    zbuf: s.zbuf.clone(),
                    results: run.results.clone(),
                    stats: Default::default(),
                };
                no(crate::render::compare(golden, &chip).unwrap_or_else(|| e.clone()))
            }
            (Err(e), Some(_)) => no(e.clone()),
            (Err(e), None) => no(format!("the frame did not complete: {e}")),
        }
    }
    fn cell(&self) -> String {
        match &self.difference {
            None => "yes".into(),
            Some(d) => format!("**no**: {d}"),
        }
    }
}

/// `PhaseCycles` with serde (tb does not depend on serde).
#[derive(Serialize, Clone, Copy, PartialEq)]
struct Phases {
    clear: u64,
    geometry_transfer: u64,
    rasterization: u64,
    colour_setup: u64,
    scan_out: u64,
    total: u64,
    /// From the previous frame's scan start to this one's (none for a run's first frame).
    frame_interval: Option<u64>,
    z_reads: u64,
}

impl From<&PhaseCycles> for Phases {
    fn from(p: &PhaseCycles) -> Phases {
        Phases {
            clear: p.clear,
            geometry_transfer: p.geometry_transfer,
            rasterization: p.rasterization,
            colour_setup: p.colour_setup,
            scan_out: p.scan_out,
            total: p.total,
            frame_interval: p.frame_interval,
            z_reads: p.z_reads,
        }
    }
}

/// Work per clock, from one frame's counts.
#[derive(Serialize, Clone)]
struct Rates {
    /// Candidates (bounding-box pixels) per rasterization cycle; limit 1 (traversal).
    candidates_per_clock: f64,
    /// Z reads (fragments Z-tested) per rasterization cycle; limit 1 (the Z port).
    fragments_per_clock: f64,
    /// (rasterization - clear) / triangles sent.
    rc_cycles_per_triangle: f64,
    /// colour-setup span / setup commands (None: nothing to set up); the span runs beside
    /// rasterization, so this is the rate at which the RC delivered visible triangles when it is larger
    /// than colour setup's own 48 cycles per triangle.
    colour_setup_cycles_per_triangle: Option<f64>,
    /// pixels / scan-out cycles; limit 1.
    cs_pixels_per_clock: f64,
}

/// One simulated frame's cycle accounting and the counts to divide it by.
#[derive(Serialize, Clone)]
struct FrameRow {
    scene: String,
    size: [u32; 2],
    frame: u32,
    pixels: u64,
    /// None: the frame stopped before the end of its scan-out.
    phases: Option<Phases>,
    /// Triangles the host sent to the RC (the same for every backend: the host's upper pipeline).
    triangles_sent: u64,
    /// Of those, the chipset's results: not culled / culled (facing or zero area).
    drawn: u64,
    culled: u64,
    /// Colour-setup commands the host sent: the triangles the chipset flagged visible.
    setup_commands: u64,
    /// Bounding-box pixels of the drawn triangles, from the algorithmic RC on the same commands: the
    /// candidates the traversal walks one per clock (not visible at the chipset's ports).
    candidates: u64,
    /// Fragments by the algorithmic RC (the hardware's are `phases.z_reads`).
    fragments_model: u64,
    rates: Option<Rates>,
    equals_golden: Verdict,
}

impl FrameRow {
    fn new(case: &Case, frame: u32, run: &TimedFrame) -> FrameRow {
        let s = case.opts.screen;
        let pixels = s.pixels() as u64;
        let phases = run.phases.as_ref().map(Phases::from);
        let drawn = run.results.iter().filter(|r: &&TriResult| r.culled.is_none()).count() as u64;
        let triangles_sent = case.golden.stats.sent_to_rc;
        let rates = phases.map(|p| {
            let per = |a: u64, b: u64| a as f64 / b.max(1) as f64;
            Rates {
                candidates_per_clock: per(case.golden.stats.rc.candidates, p.rasterization),
                fragments_per_clock: per(p.z_reads, p.rasterization),
                rc_cycles_per_triangle: per(p.rasterization - p.clear, triangles_sent),
                colour_setup_cycles_per_triangle: (run.setup_commands > 0).then(|| per(p.colour_setup, run.setup_commands)),
                cs_pixels_per_clock: per(pixels, p.scan_out),
            }
        });
        FrameRow {
            scene: case.scene.clone(),
            size: [s.width, s.height],
            frame,
            pixels,
            phases,
            triangles_sent,
            drawn,
            culled: run.results.len() as u64 - drawn,
            setup_commands: run.setup_commands,
            candidates: case.golden.stats.rc.candidates,
            fragments_model: case.golden.stats.rc.fragments,
            rates,
            equals_golden: Verdict::of(&case.golden, run),
        }
    }
}

/// Speed of one simulated frame.
#[derive(Serialize, Clone)]
struct SimRow {
    simulator: String,
    scene: String,
    size: [u32; 2],
    /// Frames in the run (back to back on one chipset).
    frames: u32,
    /// Cycles of the whole run (None: it stopped early).
    cycles: Option<u64>,
    /// The host program and the simulation of the run, not building the simulator.
    seconds: f64,
    cycles_per_second: Option<f64>,
    equals_golden: Verdict,
}

impl SimRow {
    fn new(simulator: &str, case: &Case, frames: u32, cycles: Option<u64>, secs: f64, verdict: &Verdict) -> SimRow {
        SimRow {
            simulator: simulator.into(),
            scene: case.scene.clone(),
            size: [case.opts.screen.width, case.opts.screen.height],
            frames,
            cycles,
            seconds: secs,
            cycles_per_second: cycles.map(|c| c as f64 / secs.max(1e-9)),
            equals_golden: verdict.clone(),
        }
    }
}

struct RtlResult {
    frame: FrameRow,
    sim: SimRow,
}

/// Whether the RustHDL frame's accounting equals the Verilated frame's of the same scene, size and
/// frame number (None: Verilator did not run that frame, as in quick mode's small screen).
fn rusthdl_against_verilator(rtl: &RtlResult, frames: &[FrameRow]) -> Option<bool> {
    let r = &rtl.frame;
    let v = frames.iter().find(|f| f.scene == r.scene && f.size == r.size && f.frame == r.frame)?;
    Some(r.phases.is_some() && r.phases == v.phases)
}

/// Quick mode: the RustHDL simulation's seconds for the teapot frame that Verilator counted, at the
/// RustHDL speed just measured (an estimate; full mode measures the frame).
fn teapot_seconds_estimate(rtl: &SimRow, frames: &[FrameRow]) -> Option<f64> {
    let rate = rtl.cycles_per_second?;
    let teapot = frames.iter().find(|f| f.scene == "teapot" && f.size == [320, 200] && f.frame == 1)?;
    Some(teapot.phases?.total as f64 / rate)
}

#[derive(Serialize)]
struct BuildRow {
    size: [u32; 2],
    fresh: bool,
    seconds: f64,
}

// ---------------------------------------------------------------------------------------------------
// RC setup back to back

/// Back-to-back triangles: a frame of `FEW` and one of `MANY`; the difference of their rasterization
/// cycles per added triangle is the steady per-triangle cost, without the frame's start and end.
const FEW: usize = 32;
const MANY: usize = 96;

#[derive(Serialize)]
struct SetupRow {
    triangle: String,
    /// Screen of the RustHDL chipset (small: the frame command clears it) and of the Verilated one.
    rusthdl_screen: [u32; 2],
    verilator_screen: [u32; 2],
    rusthdl_cycles_per_triangle: f64,
    verilator_cycles_per_triangle: f64,
}

#[derive(Copy, Clone, PartialEq)]
enum Stim {
    /// rc_figures' one-pixel triangle: setup-bound, one candidate.
    Drawn,
    /// rc_figures' culled triangle: wound clockwise, culled as a back face with `FrontFace::Cw`.
    Culled,
}

fn stimulus(kind: Stim, n: usize) -> (Vec<golden::render::RcCommand>, golden::raster::CullMode, golden::raster::FrontFace) {
    use golden::format::WinVertex;
    use golden::raster::{CullMode, FrontFace};
    let v = |x: i32, y: i32| WinVertex { x: x * golden::format::SUBPIXEL_ONE, y: y * golden::format::SUBPIXEL_ONE, z: 100 };
    let (tri, cull, front) = match kind {
        Stim::Drawn => ([v(2, 2), v(3, 2), v(2, 3)], CullMode::None, FrontFace::Ccw),
        Stim::Culled => ([v(2, 2), v(2, 12), v(12, 2)], CullMode::Back, FrontFace::Cw),
    };
    ((0..n).map(|i| golden::render::RcCommand { index: i as u32 + 1, v: tri }).collect(), cull, front)
}

/// The traversal of one scene and size: clocks spent walking triangles and those that delivered a
/// fragment to the Z-test (the rest looked at candidates outside the triangle or ended a row).
#[derive(Serialize, Clone)]
struct TraversalRow {
    scene: String,
    size: [u32; 2],
    walk_clocks: u64,
    fragment_clocks: u64,
    /// fragment_clocks / walk_clocks.
    share: f64,
    /// Z reads of the cycle model's frame, and whether they equal the Verilated steady-state frame's
    /// (the check that the model ran the same commands as the chipset).
    z_reads: u64,
    z_reads_equal_verilators: Option<bool>,
}

/// Records the frames a render hands the chipset, and draws them with the golden chipset.
struct JobTap {
    inner: golden::render::GoldenChipset,
    jobs: Vec<golden::render::FrameJob>,
}

impl golden::render::Chipset for JobTap {
    fn run(&mut self, frames: &[golden::render::FrameJob], host: &mut dyn golden::render::LowerPipeline) -> Result<Vec<golden::render::FrameOut>, String> {
        self.jobs.extend(frames.iter().cloned());
        self.inner.run(frames, host)
    }
}

fn traversal_row(case: &Case, frames: &[FrameRow]) -> Result<TraversalRow, String> {
    let s = case.opts.screen;
    let mut tap = JobTap { inner: golden::render::GoldenChipset::new(s), jobs: Vec::new() };
    golden::render::render_with(&case.mesh, &case.opts, &mut tap)?;
    let job = tap.jobs.last().ok_or_else(|| format!("traversal bench: rendering {} handed the chipset no frame", case.scene))?;
    let cmds = tb::rc::stimulus::job_frame(job, true)?;
    let run = tb::rc::bench::run_model(s, &cmds, tb::rc::bench::Drive::ideal(), None)?;
    let steady = frames.iter().filter(|f| f.scene == case.scene && f.size == [s.width, s.height]).last();
    Ok(TraversalRow {
        scene: case.scene.clone(),
        size: [s.width, s.height],
        walk_clocks: run.walk_clocks,
        fragment_clocks: run.walk_fragment_clocks,
        share: run.walk_fragment_clocks as f64 / run.walk_clocks.max(1) as f64,
        z_reads: run.z_reads,
        z_reads_equal_verilators: steady.and_then(|f| f.phases.map(|p| p.z_reads == run.z_reads)),
    })
}

/// A host that answers every visible triangle with a flat white colour-setup command.
struct FlatHost(Vec<golden::render::RcCommand>);

impl golden::render::LowerPipeline for FlatHost {
    fn visible(&mut self, _frame: usize, position: usize) -> Result<golden::render::SetupCommand, String> {
        let t = self.0.get(position).ok_or("RC setup bench: a result for a triangle never sent")?;
        Ok(golden::render::SetupCommand { index: t.index, v: t.v, values: [[0; 3]; 3], material: 0, flat: Some([255; 3]), tex: None })
    }
}

/// Rasterization cycles per triangle, back to back, through a chipset's RC.
fn per_triangle(chip: &mut dyn CycleChipset, kind: Stim) -> Result<f64, String> {
    let mut cycles = |n: usize| -> Result<u64, String> {
        let (cmds, cull, front) = stimulus(kind, n);
        let job = golden::render::FrameJob {
            tris: cmds.clone(),
            cull,
            front,
            shading: golden::shade::Shading::Flat,
            lights: golden::shade::PhongLights { l: vec![], h: vec![], materials: vec![] },
            background: [0; 3],
            texturing: None,
        };
        let results = chip.run(&[job], &mut FlatHost(cmds))?.remove(0).results;
        // The stimulus must be what it claims, or the figure means something else.
        if results.len() != n || results.iter().any(|r| r.culled.is_some() != (kind == Stim::Culled)) {
            return Err(format!("RC setup bench: the {} stimulus was not {} by the chipset", if kind == Stim::Culled { "culled" } else { "drawn" }, if kind == Stim::Culled { "culled" } else { "drawn" }));
        }
        Ok(chip.phases().rasterization)
    };
    let (few, many) = (cycles(FEW)?, cycles(MANY)?);
    Ok((many as f64 - few as f64) / (MANY - FEW) as f64)
}

fn setup_back_to_back(build: &tb::verilator::Build) -> Result<Vec<SetupRow>, String> {
    let small = Screen::new(32, 32)?;
    let (w, h) = SIZES[0];
    let mut rows = Vec::new();
    for (kind, name) in [(Stim::Drawn, "drawn (one pixel)"), (Stim::Culled, "culled (back face)")] {
        let mut rtl = RtlChipset::new(small, None)?;
        let mut vl = VerilatorChipset::from_build(Screen::new(w, h)?, build.clone())?;
        rows.push(SetupRow {
            triangle: name.into(),
            rusthdl_screen: [small.width, small.height],
            verilator_screen: [w, h],
            rusthdl_cycles_per_triangle: per_triangle(&mut rtl, kind)?,
            verilator_cycles_per_triangle: per_triangle(&mut vl, kind)?,
        });
    }
    Ok(rows)
}

// ---------------------------------------------------------------------------------------------------
// Frames per second at Fmax

#[derive(Serialize, Clone, Debug, PartialEq)]
struct FpgaRow {
    top: String,
    device: String,
    fmax_mhz: Option<f64>,
    fits: Option<bool>,
}

#[derive(Debug)]
enum FpgaReport {
    /// The default path does not exist.
    Missing(PathBuf),
    Read(PathBuf, Vec<FpgaRow>),
}

fn read_fpga_report(given: Option<&Path>) -> Result<FpgaReport, String> {
    let (path, named) = match given {
        Some(p) => (p.to_path_buf(), true),
        None => (PathBuf::from(DEFAULT_FPGA_REPORT), false),
    };
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        // Without a report there is no Fmax, which the table says; a report named on the command line
        // must be there.
        Err(e) if !named && e.kind() == std::io::ErrorKind::NotFound => return Ok(FpgaReport::Missing(path)),
        Err(e) => return Err(format!("--fpga-report {}: cannot read it: {e}", path.display())),
    };
    let rows = parse_fpga_report(&text).map_err(|e| format!("--fpga-report {}: {e}", path.display()))?;
    Ok(FpgaReport::Read(path, rows))
}

/// `{"rows": [{"top": "chipset", "device": "up5k", "fmax_mhz": 41.3 | null, "fits": true, ...}]}`;
/// other fields are ignored.
fn parse_fpga_report(text: &str) -> Result<Vec<FpgaRow>, String> {
    use serde_json::Value;
    let v: Value = serde_json::from_str(text).map_err(|e| format!("not valid JSON: {e}"))?;
    let rows = v.get("rows").and_then(Value::as_array).ok_or("no \"rows\" array (expected {\"rows\": [{\"top\": ..., \"device\": ..., \"fmax_mhz\": ...}, ...]})")?;
    let mut out = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        let text_field = |k: &str| r.get(k).and_then(Value::as_str).map(str::to_string).ok_or_else(|| format!("row {i} has no \"{k}\" string"));
        let (top, device) = (text_field("top")?, text_field("device")?);
        let fmax_mhz = match r.get("fmax_mhz") {
            None | Some(Value::Null) => None,
            Some(x) => match x.as_f64() {
                Some(f) if f.is_finite() && f > 0.0 => Some(f),
                _ => return Err(format!("row {i} ({top} on {device}): \"fmax_mhz\" is {x}, not a positive number or null")),
            },
        };
        let fits = match r.get("fits") {
            None | Some(Value::Null) => None,
            Some(Value::Bool(b)) => Some(*b),
            Some(x) => return Err(format!("row {i} ({top} on {device}): \"fits\" is {x}, not true or false")),
        };
        if fits == Some(false) && fmax_mhz.is_some() {
            return Err(format!("row {i} ({top} on {device}) does not fit but has an Fmax"));
        }
        out.push(FpgaRow { top, device, fmax_mhz, fits });
    }
    Ok(out)
}

/// Frames per scene and size in the Verilator runs, back to back on one chipset: frames 1 and 2 clear
/// their I-buffer bank (the first use of each after reset), frame 3 is the steady state.
pub const FRAMES_PER_RUN: u32 = 3;

/// A steady-state frame (the last of a run) of one scene and size, as the frame-rate tables need it;
/// `cycles` is its frame interval, the time per frame of a long run.
struct Steady {
    scene: String,
    size: [u32; 2],
    cycles: u64,
    triangles_in: u64,
    equal: bool,
}

fn steady_frames(frames: &[FrameRow], cases: &[Case]) -> Vec<Steady> {
    frames
        .iter()
        .filter(|f| f.frame == FRAMES_PER_RUN)
        .filter_map(|f| {
            let case = cases.iter().find(|c| c.scene == f.scene && [c.opts.screen.width, c.opts.screen.height] == f.size)?;
            Some(Steady { scene: f.scene.clone(), size: f.size, cycles: f.phases?.frame_interval?, triangles_in: case.golden.stats.triangles_in, equal: f.equals_golden.equal })
        })
        .collect()
}

/// Seed 000 Table IV's level for a screen size, and whether that size is reconstructed (the scan lost
/// the table's cells; docs/analysis.md).
fn level_of(size: [u32; 2]) -> Option<(&'static HardwareLevel, bool)> {
    let [w, h] = size;
    TABLE_IV.iter().find(|l| l.resolutions.contains(&(w, h))).map(|l| (l, l.reconstructed.starts_with(&format!("{w}x{h}"))))
}

#[derive(Serialize)]
struct TargetRow {
    scene: String,
    size: [u32; 2],
    level: Option<String>,
    size_reconstructed: bool,
    target_frames_per_second: Option<u32>,
    /// The scene's triangles (a) and the level's triangles per frame (its triangle rate / frame rate).
    triangles_in: u64,
    level_triangles_per_frame: Option<u64>,
    cycles_per_frame: u64,
    /// The clock at which the steady-state frame reaches the level's frame rate.
    mhz_for_target: Option<f64>,
    frame_equals_golden: bool,
}

#[derive(Serialize)]
struct FpsRow {
    device: String,
    fmax_mhz: f64,
    scene: String,
    size: [u32; 2],
    cycles_per_frame: u64,
    frames_per_second: f64,
    triangles_per_second: f64,
    target_frames_per_second: Option<u32>,
    level_triangles_per_second: Option<u64>,
    frame_equals_golden: bool,
}

#[derive(Serialize)]
struct DeviceNote {
    device: String,
    fmax_mhz: Option<f64>,
    fits: Option<bool>,
    note: String,
}

#[derive(Serialize)]
struct FmaxSection {
    report: String,
    report_found: bool,
    /// Every `chipset` row of the report, with what it means here.
    devices: Vec<DeviceNote>,
    /// Why there is no frame rate at Fmax (None when some device has one).
    no_fmax: Option<String>,
    rows: Vec<FpsRow>,
    targets: Vec<TargetRow>,
}

fn fmax_section(report: &FpgaReport, steady: &[Steady]) -> FmaxSection {
    let targets = steady
        .iter()
        .map(|s| {
            let level = level_of(s.size);
            TargetRow {
                scene: s.scene.clone(),
                size: s.size,
                level: level.map(|(l, _)| l.name.to_string()),
                size_reconstructed: level.map(|(_, r)| r).unwrap_or(false),
                target_frames_per_second: level.map(|(l, _)| l.frames_per_second),
                triangles_in: s.triangles_in,
                level_triangles_per_frame: level.map(|(l, _)| l.triangles_per_frame()),
                cycles_per_frame: s.cycles,
                mhz_for_target: level.map(|(l, _)| l.frames_per_second as f64 * s.cycles as f64 / 1e6),
                frame_equals_golden: s.equal,
            }
        })
        .collect();
    let (path, found, chipset_rows): (&Path, bool, Vec<&FpgaRow>) = match report {
        FpgaReport::Missing(p) => (p, false, Vec::new()),
        FpgaReport::Read(p, rows) => (p, true, rows.iter().filter(|r| r.top == "chipset").collect()),
    };
    let devices: Vec<DeviceNote> = chipset_rows
        .iter()
        .map(|r| DeviceNote {
            device: r.device.clone(),
            fmax_mhz: r.fmax_mhz,
            fits: r.fits,
            note: match (r.fmax_mhz, r.fits) {
                (Some(f), _) => format!("Fmax {f} MHz"),
                (None, Some(false)) => "does not fit: no Fmax, so no frame rate".into(),
                (None, _) => "no Fmax in the report (not placed and routed, or no timing): no frame rate".into(),
            },
        })
        .collect();
    let mut rows = Vec::new();
    for d in chipset_rows.iter().filter(|r| r.fmax_mhz.is_some()) {
        let f = d.fmax_mhz.unwrap_or_default();
        for s in steady {
            let fps = f * 1e6 / s.cycles as f64;
            let level = level_of(s.size);
            rows.push(FpsRow {
                device: d.device.clone(),
                fmax_mhz: f,
                scene: s.scene.clone(),
                size: s.size,
                cycles_per_frame: s.cycles,
                frames_per_second: fps,
                triangles_per_second: fps * s.triangles_in as f64,
                target_frames_per_second: level.map(|(l, _)| l.frames_per_second),
                level_triangles_per_second: level.map(|(l, _)| l.triangles_per_second),
                frame_equals_golden: s.equal,
            });
        }
    }
    let no_fmax = if !rows.is_empty() {
        None
    } else if !found {
        Some(format!(
            "No FPGA report at `{}` (the JSON of `idxrender fpga-report`), so there is no Fmax and no frame rate at Fmax.",
            path.display()
        ))
    } else if devices.is_empty() {
        Some(format!("`{}` has no `chipset` row, so there is no Fmax and no frame rate at Fmax.", path.display()))
    } else {
        Some(format!(
            "No `chipset` row of `{}` has an Fmax ({}), so there is no frame rate at Fmax.",
            path.display(),
            devices.iter().map(|d| format!("{}: {}", d.device, d.note)).collect::<Vec<_>>().join("; ")
        ))
    };
    FmaxSection { report: path.display().to_string(), report_found: found, devices, no_fmax, rows, targets }
}

// ---------------------------------------------------------------------------------------------------
// The machine

#[derive(Serialize)]
struct Machine {
    cpu: String,
    logical_cpus: usize,
    memory_gib: Option<f64>,
    os: String,
    kernel: String,
    rustc: String,
    verilator: String,
    date_utc: String,
    /// 1-minute load average at the start and the end: other jobs on the machine slow the timings.
    load_average: [Option<f64>; 2],
}

impl Machine {
    fn probe(load_start: Option<f64>, load_end: Option<f64>) -> Machine {
        let read = |p: &str| std::fs::read_to_string(p).unwrap_or_default();
        let cpuinfo = read("/proc/cpuinfo");
        let cpu = cpuinfo.lines().find_map(|l| l.strip_prefix("model name").and_then(|r| r.split_once(':')).map(|(_, v)| v.trim().to_string()));
        let memory_gib = read("/proc/meminfo")
            .lines()
            .find_map(|l| l.strip_prefix("MemTotal:").and_then(|r| r.trim().trim_end_matches("kB").trim().parse::<f64>().ok()))
            .map(|kb| kb / (1024.0 * 1024.0));
        let os = read("/etc/os-release").lines().find_map(|l| l.strip_prefix("PRETTY_NAME=").map(|v| v.trim_matches('"').to_string()));
        let first_line = |cmd: &str| {
            std::process::Command::new(cmd)
                .arg("--version")
                .output()
                .ok()
                .filter(|o| o.status.success())
                .and_then(|o| String::from_utf8_lossy(&o.stdout).lines().next().map(str::to_string))
                .unwrap_or_else(|| format!("{cmd} not found"))
        };
        Machine {
            cpu: cpu.unwrap_or_else(|| "unknown CPU".into()),
            logical_cpus: std::thread::available_parallelism().map(|n| n.get()).unwrap_or(0),
            memory_gib,
            os: os.unwrap_or_else(|| std::env::consts::OS.into()),
            kernel: read("/proc/sys/kernel/osrelease").trim().to_string(),
            rustc: first_line("rustc"),
            verilator: first_line("verilator"),
            date_utc: utc_now(),
            load_average: [load_start, load_end],
        }
    }
}

fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg").ok()?.split_whitespace().next()?.parse().ok()
}

/// The date and time in UTC to the minute, from the system clock: "2026-11-22 23:40 UTC".
fn utc_now() -> String {
    // RFC 3339 to the second is "2026-11-22T23:40:05Z": keep the date and the minutes.
    let t = humantime::format_rfc3339_seconds(std::time::SystemTime::now()).to_string();
    format!("{} {} UTC", &t[..10], &t[11..16])
}

// ---------------------------------------------------------------------------------------------------
// The report

#[derive(Serialize)]
struct Report {
    command: String,
    mode: String,
    /// Seed 000's index-rendering type of the chipset measured (the RTL builds Type IV).
    rc_type: &'static str,
    /// Each golden frame was repeated for at least this time and this many frames.
    golden_min_seconds: f64,
    golden_min_frames: u64,
    seconds: f64,
    machine: Machine,
    verilator_builds: Vec<BuildRow>,
    golden: Vec<GoldenRow>,
    simulators: Vec<SimRow>,
    /// Full mode: the RustHDL frame's cycles per phase equal the Verilated frame's (None: not compared).
    rusthdl_cycles_equal_verilators: Option<bool>,
    /// Quick mode: seconds of a teapot 320x200 frame at the RustHDL speed measured (an estimate).
    rusthdl_teapot_seconds_estimate: Option<f64>,
    /// The Verilated frames' accounting: every scene and size, frames 1 and 2.
    frames: Vec<FrameRow>,
    /// The traversal's clocks per scene and size (cycle model, steady-state commands).
    traversal: Vec<TraversalRow>,
    setup: Vec<SetupRow>,
    fmax: FmaxSection,
}

fn size_str(s: [u32; 2]) -> String {
    format!("{}x{}", s[0], s[1])
}

fn pct(x: f64) -> String {
    format!("{:.1}%", 100.0 * x)
}

/// A Markdown table from a header and rows of cells.
fn table(head: &[&str], rows: &[Vec<String>]) -> String {
    let mut t = format!("| {} |\n|{}\n", head.join(" | "), "---|".repeat(head.len()));
    for r in rows {
        let _ = writeln!(t, "| {} |", r.join(" | "));
    }
    t
}

/// The steady-state figure furthest from its limit and the one closest to it, over the frames that
/// equal golden: (what, scene, size, value).
fn extremes(frames: &[FrameRow]) -> Option<((&'static str, String, f64), (&'static str, String, f64))> {
    let mut all = Vec::new();
    for f in frames.iter().filter(|f| f.frame == FRAMES_PER_RUN && f.equals_golden.equal) {
        let Some(r) = &f.rates else { continue };
        let at = format!("{} {}", f.scene, size_str(f.size));
        all.push(("RC candidates per clock", at.clone(), r.candidates_per_clock));
        all.push(("RC fragments per clock", at.clone(), r.fragments_per_clock));
        all.push(("CS pixels per clock", at, r.cs_pixels_per_clock));
    }
    let lo = all.iter().cloned().min_by(|a, b| a.2.total_cmp(&b.2))?;
    let hi = all.iter().cloned().max_by(|a, b| a.2.total_cmp(&b.2))?;
    Some((lo, hi))
}

fn summary(r: &Report) -> Vec<String> {
    let mut lines = vec![format!("chipset: seed 000 Type {}", r.rc_type)];
    for g in &r.golden {
        lines.push(format!("golden {} {}: {:.1} frames/s", g.scene, size_str(g.size), g.frames_per_second));
    }
    for s in &r.simulators {
        lines.push(format!(
            "{} {} {} {} frame(s): {} cycles in {:.2} s ({}), equals golden: {}",
            s.simulator,
            s.scene,
            size_str(s.size),
            s.frames,
            s.cycles.map(|c| c.to_string()).unwrap_or("-".into()),
            s.seconds,
            s.cycles_per_second.map(|c| format!("{c:.0} cycles/s")).unwrap_or("-".into()),
            if s.equals_golden.equal { "yes" } else { "no" }
        ));
    }
    if let Some(((what, at, v), _)) = extremes(&r.frames) {
        lines.push(format!("furthest from its limit (steady state): {what} on {at}: {v:.3} ({} of 1)", pct(v)));
    }
    lines
}

fn markdown(r: &Report) -> String {
    let m = &r.machine;
    let mut md = String::new();
    let _ = writeln!(md, "# Performance, side by side (`idxrender bench`)\n");
    let _ = writeln!(md, "Command: `{}` ({} mode, {:.0} s). Date: {}.\n", r.command, r.mode, r.seconds, m.date_utc);
    let _ = writeln!(md, "Chipset measured: seed 000 Type {} (I-buffer and Z-buffer).\n", r.rc_type);
    let load = |l: Option<f64>| l.map(|x| format!("{x:.2}")).unwrap_or("unknown".into());
    let _ = writeln!(
        md,
        "Machine: {}, {} logical CPUs, {} RAM; {}, Linux {}; {}; {}. Load average (1 min) {} at the start, {} at the end: \
         other jobs running on the machine slow every timing, so the times are upper bounds.\n",
        m.cpu,
        m.logical_cpus,
        m.memory_gib.map(|g| format!("{g:.1} GiB")).unwrap_or("unknown".into()),
        m.os,
        m.kernel,
        m.rustc,
        m.verilator,
        load(m.load_average[0]),
        load(m.load_average[1])
    );

    // Golden.
    let _ = writeln!(md, "## Golden model: frames per second\n");
    let _ = writeln!(
        md,
        "The frame of `idxrender render --scene S --size WxH` (Gouraud, back-face culling, the default camera) through \
         `golden::render::render`: the host's transform, clipping and viewport mapping of every triangle, the RC, the \
         host's deferred lighting of the flagged triangles, colour setup and the CS's scan-out, on one core. Not \
         included: loading or tessellating the scene and writing files. Each frame was rendered once untimed, then \
         repeated for at least {} s and {} frame(s).\n",
        r.golden_min_seconds,
        r.golden_min_frames
    );
    let rows: Vec<Vec<String>> = r
        .golden
        .iter()
        .map(|g| vec![g.scene.clone(), size_str(g.size), g.triangles_in.to_string(), g.frames.to_string(), format!("{:.3}", g.ms_per_frame), format!("{:.1}", g.frames_per_second)])
        .collect();
    md += &table(&["scene", "size", "triangles", "frames timed", "ms per frame", "frames/s"], &rows);

    // Simulators.
    let _ = writeln!(md, "\n## Simulation speed: RustHDL and Verilator\n");
    let _ = writeln!(
        md,
        "Whole frames through the `chipset` top, driven by the same host program (`render_with`) and compared with the \
         golden frame as `render --backend` compares them (image, I-buffer, Z-buffer, per-triangle results; every \
         frame of a run). Verilator runs {FRAMES_PER_RUN} frames back to back per scene and size; seconds are the host \
         program and the simulation of the run; cycles/s = cycles / seconds.\n"
    );
    let rows: Vec<Vec<String>> = r
        .simulators
        .iter()
        .map(|s| {
            vec![
                s.simulator.clone(),
                s.scene.clone(),
                size_str(s.size),
                s.frames.to_string(),
                s.cycles.map(|c| c.to_string()).unwrap_or("-".into()),
                format!("{:.3}", s.seconds),
                s.cycles_per_second.map(|c| format!("{c:.0}")).unwrap_or("-".into()),
                s.equals_golden.cell(),
            ]
        })
        .collect();
    md += &table(&["simulator", "scene", "size", "frames", "cycles", "seconds", "cycles/s", "equals golden"], &rows);
    md.push('\n');
    let rtl = r.simulators.iter().find(|s| s.simulator == "RustHDL");
    if let Some(s) = rtl {
        match (r.rusthdl_cycles_equal_verilators, r.rusthdl_teapot_seconds_estimate) {
            (Some(eq), _) => {
                let _ = writeln!(
                    md,
                    "The RustHDL frame ({} {}, the first after reset) is measured, not extrapolated. Its cycles per phase {} those of the Verilated run's frame 1.",
                    s.scene,
                    size_str(s.size),
                    if eq { "equal" } else { "**differ from**" }
                );
            }
            (None, Some(est)) => {
                let _ = writeln!(
                    md,
                    "Quick mode: the RustHDL simulation ran {} at {} only. At its speed, the teapot 320x200 frame that Verilator \
                     counted would take about {est:.0} s (an estimate; the full bench measures it).",
                    s.scene,
                    size_str(s.size)
                );
            }
            (None, None) => {
                let _ = writeln!(md, "The RustHDL frame was not compared with a Verilated frame (no Verilated frame of that scene and size).");
            }
        }
    }
    let builds: Vec<String> = r
        .verilator_builds
        .iter()
        .map(|b| format!("{}: {} ({:.1} s)", size_str(b.size), if b.fresh { "built" } else { "from the cache" }, b.seconds))
        .collect();
    let _ = writeln!(md, "Verilated chipset, not in the seconds above: {}.\n", builds.join(", "));

    // Efficiency.
    let _ = writeln!(md, "## Hardware efficiency\n");
    let _ = writeln!(
        md,
        "Cycles per phase from the Verilated chipset's accounting (the RustHDL backend counts the same: \
         `tb/tests/verilator_frames.rs`), {FRAMES_PER_RUN} frames back to back per scene and size. Rasterization runs \
         from the frame command to the end-of-frame result and includes the clear (frames 1 and 2 clear their \
         I-buffer bank, the first use of each after reset); geometry transfer and colour setup overlap it; scan-out \
         overlaps the next frame's rasterization; total runs from the frame command to the end of its scan-out; the \
         frame interval (scan start to scan start) is the time per frame of a long run.\n"
    );
    let rows: Vec<Vec<String>> = r
        .frames
        .iter()
        .map(|f| {
            let mut row = vec![f.scene.clone(), size_str(f.size), f.frame.to_string()];
            match f.phases {
                Some(p) => {
                    row.extend([p.clear, p.geometry_transfer, p.rasterization, p.colour_setup, p.scan_out, p.total].map(|c| c.to_string()));
                    row.push(p.frame_interval.map(|c| c.to_string()).unwrap_or("-".into()));
                }
                None => row.extend(std::iter::repeat("-".to_string()).take(7)),
            }
            row.push(f.equals_golden.cell());
            row
        })
        .collect();
    md += &table(&["scene", "size", "frame", "clear", "geometry transfer", "rasterization", "colour setup", "scan-out", "total", "frame interval", "equals golden"], &rows);
    let _ = writeln!(
        md,
        "\nRates against the limits, in the rasterization phase for the RC and the scan-out phase for the CS. Limits: \
         the traversal issues at most one fragment per clock (it looks at up to 16 candidates per clock), and the RC \
         reads the Z port at most once per clock (one fragment per clock per memory port); the CS sends one pixel per clock. Candidates are the drawn triangles' clamped \
         bounding-box pixels, counted by the algorithmic RC on the same commands (the traversal's walk is not \
         visible at the chipset's ports); fragments are the Z reads the chipset made (the algorithmic RC's count \
         in brackets where they differ). RC cycles per triangle = (rasterization - clear) / triangles sent; \
         colour setup per shaded triangle = colour-setup span / setup commands (the span runs beside rasterization, so \
         it is the RC's pace of visible results when that is slower than colour setup). The last frame is the steady state.\n"
    );
    let rows: Vec<Vec<String>> = r
        .frames
        .iter()
        .map(|f| {
            let mut row = vec![f.scene.clone(), size_str(f.size), f.frame.to_string()];
            match (&f.rates, f.phases) {
                (Some(q), Some(p)) => {
                    let frag = if p.z_reads == f.fragments_model { format!("{:.3}", q.fragments_per_clock) } else { format!("{:.3} ({})", q.fragments_per_clock, f.fragments_model) };
                    row.extend([
                        f.triangles_sent.to_string(),
                        format!("{} / {}", f.drawn, f.culled),
                        format!("{:.3}", q.candidates_per_clock),
                        p.z_reads.to_string(),
                        frag,
                        pct(q.fragments_per_clock),
                        format!("{:.1}", q.rc_cycles_per_triangle),
                        q.colour_setup_cycles_per_triangle.map(|c| format!("{c:.1}")).unwrap_or("-".into()),
                        format!("{:.4}", q.cs_pixels_per_clock),
                        pct(q.cs_pixels_per_clock),
                    ]);
                }
                _ => row.extend(std::iter::repeat("-".to_string()).take(10)),
            }
            row.push(if f.equals_golden.equal { "yes".into() } else { "**no**".into() });
            row
        })
        .collect();
    md += &table(
        &[
            "scene",
            "size",
            "frame",
            "triangles sent",
            "drawn / culled",
            "RC candidates/clk",
            "Z reads",
            "RC fragments/clk",
            "% of limit",
            "RC cycles/triangle",
            "colour setup cycles/shaded triangle",
            "CS px/clk",
            "% of limit",
            "equals golden",
        ],
        &rows,
    );
    if let Some(((lo_what, lo_at, lo), (hi_what, hi_at, hi))) = extremes(&r.frames) {
        let _ = writeln!(
            md,
            "\nSteady state, frames equal to golden: furthest from its limit is {lo_what} on {lo_at} ({lo:.3}, {} of 1); \
             closest is {hi_what} on {hi_at} ({hi:.4}, {} of 1).",
            pct(lo),
            pct(hi)
        );
    }
    let _ = writeln!(
        md,
        "\nThe traversal's walk, from the RC cycle model on each steady-state frame's commands (the model equals the \
         RTL in every cycle, `tb/tests/rc_rtl.rs`; the walk is not visible at the chipset's ports): clocks spent \
         walking triangles, and the share of them that delivered a fragment to the Z-test (the others skipped \
         candidates outside the triangle or ended a row). Z reads equal to the Verilated frame's show that the model \
         ran the chipset's commands.\n"
    );
    let rows: Vec<Vec<String>> = r
        .traversal
        .iter()
        .map(|t| {
            vec![
                t.scene.clone(),
                size_str(t.size),
                t.walk_clocks.to_string(),
                t.fragment_clocks.to_string(),
                pct(t.share),
                t.z_reads.to_string(),
                match t.z_reads_equal_verilators {
                    Some(true) => "yes".into(),
                    Some(false) => "**no**".into(),
                    None => "-".into(),
                },
            ]
        })
        .collect();
    md += &table(&["scene", "size", "walk clocks", "clocks with a fragment", "share", "Z reads (model)", "equal to Verilator's"], &rows);
    let _ = writeln!(
        md,
        "\nRC setup, back to back (rasterization cycles per added triangle between a frame of {FEW} and one of {MANY} \
         identical triangles, through the chipset's ports):\n"
    );
    let rows: Vec<Vec<String>> = r
        .setup
        .iter()
        .map(|s| {
            vec![
                s.triangle.clone(),
                format!("{:.2} ({})", s.rusthdl_cycles_per_triangle, size_str(s.rusthdl_screen)),
                format!("{:.2} ({})", s.verilator_cycles_per_triangle, size_str(s.verilator_screen)),
            ]
        })
        .collect();
    md += &table(&["triangle", "RustHDL cycles/triangle (screen)", "Verilator cycles/triangle (screen)"], &rows);

    // Fmax.
    let f = &r.fmax;
    let _ = writeln!(md, "\n## Frames per second at Fmax\n");
    let levels: Vec<String> =
        TABLE_IV.iter().map(|l| format!("{} {} frames/s and {} triangles/s", l.name, l.frames_per_second, l.triangles_per_second)).collect();
    let _ = writeln!(
        md,
        "Seed 000 Table IV's targets (`golden/src/analysis/levels.rs`, docs/analysis.md). The text states the frame and \
         triangle rates ({}) and the sizes 800x600 and 320x200; the scan lost the table's other sizes, so 640x480 as the \
         middle level's is **reconstructed** (the models' native size, seed 000 §IV.A.2). 320x200 is the low end's stated \
         size. Frame rates count the chipset's cycles of the steady-state frame only (the host's work between the phases \
         is not counted).\n",
        levels.join("; ")
    );
    if !f.devices.is_empty() {
        let notes: Vec<String> = f.devices.iter().map(|d| format!("{}: {}", d.device, d.note)).collect();
        let _ = writeln!(md, "`chipset` rows of `{}`: {}.\n", f.report, notes.join("; "));
    }
    match &f.no_fmax {
        Some(why) => {
            let _ = writeln!(md, "{why}\n");
        }
        None => {
            let rows: Vec<Vec<String>> = f
                .rows
                .iter()
                .map(|x| {
                    let meets = match x.target_frames_per_second {
                        Some(t) => format!("{} ({})", t, if x.frames_per_second >= t as f64 { "reached" } else { "**not reached**" }),
                        None => "-".into(),
                    };
                    vec![
                        x.device.clone(),
                        format!("{}", x.fmax_mhz),
                        x.scene.clone(),
                        size_str(x.size),
                        x.cycles_per_frame.to_string(),
                        format!("{:.1}", x.frames_per_second),
                        meets,
                        format!("{:.0}", x.triangles_per_second),
                        x.level_triangles_per_second.map(|t| t.to_string()).unwrap_or("-".into()),
                        if x.frame_equals_golden { "yes".into() } else { "**no**".into() },
                    ]
                })
                .collect();
            md += &table(
                &["device", "Fmax (MHz)", "scene", "size", "cycles/frame (frame interval)", "frames/s at Fmax", "Table IV frames/s", "triangles/s at Fmax", "Table IV triangles/s", "frame equals golden"],
                &rows,
            );
            md.push('\n');
        }
    }
    let _ = writeln!(md, "The clock each steady-state frame needs for its Table IV frame rate (from the measured cycles; no FPGA figure):\n");
    let rows: Vec<Vec<String>> = f
        .targets
        .iter()
        .map(|t| {
            vec![
                t.scene.clone(),
                size_str(t.size),
                match &t.level {
                    Some(l) => format!("{l}{}", if t.size_reconstructed { " (size reconstructed)" } else { " (size stated)" }),
                    None => "-".into(),
                },
                t.target_frames_per_second.map(|x| x.to_string()).unwrap_or("-".into()),
                format!("{} / {}", t.triangles_in, t.level_triangles_per_frame.map(|x| x.to_string()).unwrap_or("-".into())),
                t.cycles_per_frame.to_string(),
                t.mhz_for_target.map(|x| format!("{x:.2}")).unwrap_or("-".into()),
                if t.frame_equals_golden { "yes".into() } else { "**no**".into() },
            ]
        })
        .collect();
    md += &table(
        &["scene", "size", "Table IV level", "frames/s", "triangles: scene / level's per frame", "cycles/frame (frame interval)", "MHz for that rate", "frame equals golden"],
        &rows,
    );
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_default_report_gives_the_reason_and_no_frame_rate_but_still_the_clock_each_target_needs() {
        let steady = [Steady { scene: "teapot".into(), size: [320, 200], cycles: 480_000, triangles_in: 12544, equal: true }];
        let f = fmax_section(&FpgaReport::Missing(PathBuf::from("out/fpga-report.json")), &steady);
        assert!(f.rows.is_empty() && !f.report_found);
        assert!(f.no_fmax.as_deref().unwrap_or("").contains("No FPGA report at `out/fpga-report.json`"), "{:?}", f.no_fmax);
        // 24 frames/s (the low end's stated rate) of 480 000 cycles: 11.52 MHz.
        let t = &f.targets[0];
        assert_eq!((t.level.as_deref(), t.target_frames_per_second, t.size_reconstructed), (Some("low"), Some(24), false));
        assert!((t.mhz_for_target.unwrap() - 11.52).abs() < 1e-9);
    }

    #[test]
    fn table_iv_marks_640x480_as_reconstructed_and_320x200_as_stated() {
        assert_eq!(level_of([640, 480]).map(|(l, r)| (l.name, r)), Some(("middle", true)));
        assert_eq!(level_of([320, 200]).map(|(l, r)| (l.name, r)), Some(("low", false)));
        assert!(level_of([80, 50]).is_none());
    }

    #[test]
    fn a_chipset_row_that_does_not_fit_but_has_an_fmax_is_rejected() {
        let e = parse_fpga_report(r#"{"rows": [{"top": "chipset", "device": "up5k", "fmax_mhz": 12.0, "fits": false}]}"#).unwrap_err();
        assert!(e.contains("does not fit but has an Fmax"), "{e}");
        let ok = parse_fpga_report(r#"{"rows": [{"top": "chipset", "device": "hx8k", "fmax_mhz": 20.5, "lut4": 1}]}"#).unwrap();
        assert_eq!(ok, vec![FpgaRow { top: "chipset".into(), device: "hx8k".into(), fmax_mhz: Some(20.5), fits: None }]);
    }

    #[test]
    fn the_date_is_a_utc_calendar_date() {
        let d = utc_now();
        let (y, rest) = d.split_once('-').unwrap();
        assert!(y.parse::<u32>().unwrap() >= 2024 && rest.ends_with(" UTC") && d.len() == "2024-01-01 00:00 UTC".len(), "{d}");
    }
}
