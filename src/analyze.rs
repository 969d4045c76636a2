//! `idxrender analyze`: the seeds' analysis (issue 6) from the golden model's measured counts.
//!
//! Renders every scene (built-in, or `--scene`/`--obj`) with the same camera as `render`, at every
//! resolution of seed 000 Table IV ([`golden::analysis::levels::TABLE_IV`]) and at seed 001's 320x200,
//! once per shading method; runs [`golden::analysis::analyze`]; prints a summary (or `--json`), and
//! with `--out DIR` writes `analysis.md` and PNG bar charts in the style of the papers' figures.
//!
//! Charts are drawn with plotters' bitmap backend into memory and encoded by the project's PNG writer;
//! text uses the DejaVu Sans font compiled in from the `dejavu` crate (plotters' `ab_glyph` feature), so
//! no system font is needed.

use crate::args::{CullArg, RenderArgs};
use crate::output::{png_bytes, write_atomic};
use golden::analysis::buffers::{Arch, Buffer};
use golden::analysis::levels::{self, paper, HardwareLevel, TABLE_IV};
use golden::analysis::measure::{measure, reorder, DrawOrder, Measured};
use golden::analysis::{self, Analysis, BandwidthRow, Range, WidthSet, BUFFER_SHADINGS, SEED001_SCREEN};
use golden::scene::builtin;
use golden::shade::Shading;
use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::PathBuf;

use crate::say;

#[derive(clap::Args, Debug)]
pub struct AnalyzeArgs {
    /// A built-in scene to analyse (repeat for several): polyhedron, teapot, castle, dolphins. Default: all.
    #[arg(long, conflicts_with = "obj")]
    pub scene: Vec<String>,
    /// A Wavefront OBJ file to analyse instead of the built-in scenes.
    #[arg(long)]
    pub obj: Option<PathBuf>,
    /// A hardware level of seed 000 Table IV (repeat for several): high, middle, low. Default: all.
    #[arg(long)]
    pub level: Vec<String>,
    /// Which faces the rasterizer culls (seed 000 simulated its Teapot and Polyhedron without culling).
    #[arg(long, value_enum, default_value_t = CullArg::Back)]
    pub cull: CullArg,
    /// The order the triangles are drawn in: the scene's own, or sorted by distance from the eye.
    #[arg(long, value_enum, default_value_t = OrderArg::Scene)]
    pub order: OrderArg,
    /// Depth complexity assumed by the worst-case bandwidth (seed 000 Fig. 11): fragments per pixel.
    #[arg(long, default_value_t = 4.0)]
    pub worst_depth: f64,
    /// Write analysis.md and the charts (PNG) into this directory, replaced as a whole (a folder
    /// holding other files is refused).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the full results as JSON on stdout instead of the summary.
    #[arg(long)]
    pub json: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OrderArg {
    /// The scene's own order (as `render` draws it).
    Scene,
    /// Nearest triangle first: deferred lighting then lights few hidden triangles.
    FrontToBack,
    /// Farthest first: the painter's order, the worst case for deferred lighting.
    BackToFront,
}

impl OrderArg {
    fn golden(self) -> DrawOrder {
        match self {
            OrderArg::Scene => DrawOrder::Scene,
            OrderArg::FrontToBack => DrawOrder::FrontToBack,
            OrderArg::BackToFront => DrawOrder::BackToFront,
        }
    }
    fn name(self) -> &'static str {
        match self {
            OrderArg::Scene => "scene",
            OrderArg::FrontToBack => "front-to-back",
            OrderArg::BackToFront => "back-to-front",
        }
    }
}

/// Where a scene comes from.
enum Source {
    Builtin(String),
    Obj(PathBuf),
}

/// The `render` command's arguments for a scene at a size, parsed by the same parser as the command
/// line so that the camera, culling and front face are exactly `render`'s defaults. The index is made
/// wide (24 bits): the analysis counts, it does not model an index width.
fn render_args(src: &Source, (w, h): (u32, u32), cull: CullArg) -> Result<RenderArgs, String> {
    let mut argv: Vec<OsString> = vec!["render".into()];
    match src {
        Source::Builtin(n) => argv.extend(["--scene".into(), n.into()]),
        Source::Obj(p) => argv.extend(["--obj".into(), p.clone().into_os_string()]),
    }
    argv.extend(["--size".into(), format!("{w}x{h}").into(), "--index-bits".into(), "24".into()]);
    argv.extend(["--cull".into(), cull_name(cull).into()]);
    // Parsed by the same definitions as `render`'s arguments.
    #[derive(clap::Parser)]
    struct RenderCommand {
        #[command(flatten)]
        args: RenderArgs,
    }
    Ok(<RenderCommand as clap::Parser>::try_parse_from(argv).map_err(|e| e.to_string())?.args)
}

fn cull_name(c: CullArg) -> &'static str {
    match c {
        CullArg::Back => "back",
        CullArg::Front => "front",
        CullArg::None => "none",
    }
}

/// The resolutions to render: every selected level's, and seed 001's 320x200; largest first.
fn resolutions(levels: &[&HardwareLevel]) -> Vec<(u32, u32)> {
    let mut r: Vec<(u32, u32)> = levels.iter().flat_map(|l| l.resolutions).collect();
    r.push(SEED001_SCREEN);
    r.sort_by_key(|&(w, h)| std::cmp::Reverse((w as u64 * h as u64, w)));
    r.dedup();
    r
}

/// The files `analyze --out DIR` writes: analysis.md and the charts (`fig*.png`, `seed001_*.png`).
fn is_analysis_output(n: &str) -> bool {
    n == "analysis.md" || (n.ends_with(".png") && (n.starts_with("fig") || n.starts_with("seed001_")))
}

pub fn run(args: &AnalyzeArgs) -> Result<(), String> {
    // --out is one unit (crate::output::OutputDir), checked before the work: staged, then moved into
    // place whole; an error on the way leaves the previous folder as it was.
    let od = match &args.out {
        Some(dir) => Some(crate::output::OutputDir::begin_with(dir, &is_analysis_output)?),
        None => None,
    };
    if !(args.worst_depth.is_finite() && args.worst_depth >= 1.0 && args.worst_depth <= 1000.0) {
        return Err(format!("--worst-depth {} is not a depth complexity in 1..=1000 (fragments per pixel)", args.worst_depth));
    }
    let mut selected: Vec<&'static HardwareLevel> = Vec::new();
    for name in &args.level {
        let l = levels::level(name)?;
        if !selected.iter().any(|s| s.name == l.name) {
            selected.push(l);
        }
    }
    if selected.is_empty() {
        selected = TABLE_IV.iter().collect();
    }
    // Keep Table IV's order.
    selected.sort_by_key(|l| TABLE_IV.iter().position(|t| t.name == l.name));
    let sources: Vec<Source> = match (&args.obj, args.scene.is_empty()) {
        (Some(p), _) => vec![Source::Obj(p.clone())],
        (None, true) => builtin::SCENES.iter().map(|s| Source::Builtin(s.to_string())).collect(),
        (None, false) => args.scene.iter().map(|s| Source::Builtin(s.clone())).collect(),
    };

    let t0 = std::time::Instant::now();
    let sizes = resolutions(&selected);
    let mut measured: Vec<Measured> = Vec::new();
    let mut names = Vec::new();
    for src in &sources {
        let first = render_args(src, sizes[0], args.cull)?;
        let mesh = crate::args::load_scene(&first)?;
        names.push(mesh.name.clone());
        for &size in &sizes {
            let opts = crate::args::render_options(&render_args(src, size, args.cull)?, &mesh)?;
            let ordered = reorder(&mesh, &opts.camera, args.order.golden());
            measured.push(measure(&ordered, &opts).map_err(|e| format!("{} at {}x{}: {e}", mesh.name, size.0, size.1))?);
        }
    }
    let a = analysis::analyze(&selected, &measured, args.worst_depth);
    let secs = t0.elapsed().as_secs_f64();

    let command = command_line(args);
    if args.json {
        let v = serde_json::json!({ "command": command, "scenes": names, "analysis": a });
        say!("{}", serde_json::to_string_pretty(&v).map_err(|e| format!("JSON encoding failed: {e}"))?);
    } else {
        say!("{}", summary(&a).trim_end());
        say!("({} frames rendered in {:.1} s)", measured.len() * 3, secs);
    }
    if args.out.is_some() {
        let charts = charts(&a)?;
        let md = report(&a, &command, &charts.iter().map(|c| c.0.clone()).collect::<Vec<_>>());
        let od = od.ok_or("internal: --out given but not staged")?;
        let mut files = Vec::new();
        for (name, png) in &charts {
            files.push(od.final_path(&write_atomic(od.dir(), name, png)?));
        }
        files.push(od.final_path(&write_atomic(od.dir(), "analysis.md", md.as_bytes())?));
        od.commit()?;
        if !args.json {
            for f in files {
                say!("  wrote {}", f.display());
            }
        }
    }
    Ok(())
}

/// The command that reproduces this report.
fn command_line(args: &AnalyzeArgs) -> String {
    let mut s = String::from("cargo run --release -- analyze");
    for n in &args.scene {
        let _ = write!(s, " --scene {n}");
    }
    if let Some(p) = &args.obj {
        let _ = write!(s, " --obj {}", p.display());
    }
    for l in &args.level {
        let _ = write!(s, " --level {l}");
    }
    if !matches!(args.cull, CullArg::Back) {
        let _ = write!(s, " --cull {}", cull_name(args.cull));
    }
    if args.order != OrderArg::Scene {
        let _ = write!(s, " --order {}", args.order.name());
    }
    if args.worst_depth != 4.0 {
        let _ = write!(s, " --worst-depth {}", args.worst_depth);
    }
    if let Some(o) = &args.out {
        let _ = write!(s, " --out {}", o.display());
    }
    s
}

// ---------------------------------------------------------------------------------------------
// Text

fn range(r: Range, unit: &str) -> String {
    if r.min.is_nan() {
        "n/a".into()
    } else {
        format!("{:.1}{unit} to {:.1}{unit}", r.min, r.max)
    }
}

fn shading_name(s: Shading) -> &'static str {
    match s {
        Shading::Flat => "flat",
        Shading::Gouraud => "Gouraud",
        Shading::Phong => "Phong",
    }
}

/// Which RC drew the frames the analysis counts (`analyze` names the type it measured).
const MEASURED_BY: &str = "measured: every frame drawn by the Type IV RC (Z-buffer); Type III's TdbV reads counted by drawing it again with the Type III RC (no Z-buffer), whose I-buffer is checked equal";

fn summary(a: &Analysis) -> String {
    let c = &a.claims;
    let mut s = String::new();
    let _ = writeln!(s, "{MEASURED_BY}");
    let _ = writeln!(s, "seed 000 (Types I-IV), lighting operations saved by index rendering against Type I:");
    let _ = writeln!(s, "  flat/Gouraud {} (paper 10-70%), Phong {} (paper 30-95%)", range(c.lighting_saved_flat_gouraud, "%"), range(c.lighting_saved_phong, "%"));
    let _ = writeln!(s, "seed 000, Types III/IV against deferred shading (Type II):");
    let _ = writeln!(s, "  buffer size saved {} with our widths, {} with the paper's (paper 70%)", range(c.buffer_saved_ours, "%"), range(c.buffer_saved_paper_widths, "%"));
    let _ = writeln!(
        s,
        "  bandwidth saved {} simulated ({} with a one-record TdbS cache), {} worst case (paper 50-70%); TdbV on chip: {} / {}",
        range(c.bandwidth_saved_simulated, "%"),
        range(c.bandwidth_saved_simulated_cached, "%"),
        range(c.bandwidth_saved_worst, "%"),
        range(c.bandwidth_saved_simulated_off_chip, "%"),
        range(c.bandwidth_saved_worst_off_chip, "%")
    );
    let _ = writeln!(
        s,
        "seed 001, proposed CPU cost at 320x200: {} of its Type II (paper 36.6-52.6%), {} of its Type I (paper 56.1-78.4%); as built {} of Type II",
        range(c.cpu_percent_of_type_ii, "%"),
        range(c.cpu_percent_of_type_i, "%"),
        range(c.cpu_as_built_percent_of_type_ii, "%")
    );
    for m in a.cpu.iter() {
        let _ = writeln!(
            s,
            "  {}: (a) {} (b) {} flagged {} (c) {}: proposed {:.1}% of Type II, {:.1}% of Type I; as built {:.1}% of Type II",
            m.scene,
            m.counts.a,
            m.counts.b,
            m.flagged,
            m.counts.c,
            m.table3[2].percent_of_type_ii,
            m.table3[2].percent_of_type_i,
            m.as_built.percent_of_type_ii
        );
    }
    s
}

fn size(w: u32, h: u32) -> String {
    format!("{w}x{h}")
}

fn kb(bytes: f64) -> String {
    format!("{:.1}", bytes / 1000.0)
}

/// The Markdown report.
fn report(a: &Analysis, command: &str, charts: &[String]) -> String {
    let mut s = String::new();
    let chart = |s: &mut String, name: &str, alt: &str| {
        if charts.iter().any(|c| c == name) {
            let _ = writeln!(s, "\n![{alt}]({name})\n");
        }
    };
    let _ = writeln!(s, "# Analysis: lighting operations, CPU cost, buffer sizes and bandwidth\n");
    let _ = writeln!(s, "Produced by `{command}` from the golden model's counts. Every number in a column not labelled *paper* was measured on our scenes; the paper's numbers appear only in columns and rows labelled as the paper's.\n");
    let _ = writeln!(s, "{MEASURED_BY}\n");
    let _ = writeln!(s, "Two numbering schemes: **seed 000 Types I-IV** are hardware architectures (I traditional, II deferred shading, III index rendering with TdbV + I-buffer, IV index rendering with Z-buffer + I-buffer); **seed 001 Type I/II** are host pipelines (cull before lighting / cull before setup) against its proposed dual pipeline.\n");

    // Table IV
    let _ = writeln!(s, "## Hardware levels (seed 000 Table IV)\n");
    let _ = writeln!(s, "| level | triangles/s | frames/s | triangles/frame | resolutions | reconstructed |\n|---|---|---|---|---|---|");
    for l in &a.levels {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} |",
            l.name,
            l.triangles_per_second,
            l.frames_per_second,
            l.triangles_per_frame(),
            l.resolutions.iter().map(|&(w, h)| size(w, h)).collect::<Vec<_>>().join(", "),
            l.reconstructed
        );
    }
    let _ = writeln!(s, "\nScenes are framed by `render`'s default camera at every size, so a scene covers the same part of the screen at every resolution (the paper scaled its models with the resolution, §IV.A.2).\n");

    // Seed 001
    let _ = writeln!(s, "## Seed 001 Tables 1-3: triangles and CPU cost at {}x{}\n", SEED001_SCREEN.0, SEED001_SCREEN.1);
    let _ = writeln!(s, "(a) triangles in the scene, (b) after back-face culling, *flagged* = some fragment passed the Z-test when drawn (what the host lights), (c) visible in the final image.\n");
    let _ = writeln!(s, "| scene | (a) | (b) | flagged | (c) | (c)/(b) | (c)/(a) |\n|---|---|---|---|---|---|---|");
    for c in &a.cpu {
        let _ = writeln!(s, "| {} | {} | {} | {} | {} | {:.1}% | {:.1}% |", c.scene, c.counts.a, c.counts.b, c.flagged, c.counts.c, c.visible_of_b, c.visible_of_a);
    }
    let _ = writeln!(s, "| *paper: Dolphins* | *3000* | *1451* | | *~1206 (reconstructed)* | *83%* | *40%* |");
    let _ = writeln!(s, "| *paper: Castle* | *unreadable* | | | | *44%* | *20%* |");
    let _ = writeln!(s, "\nTable 2 (operations per frame; reconstructed from the text of §4, the scan keeps only fragments of the table): viewing and perspective transforms of the vertices (a)x3 in every architecture; viewing transforms of the normals (a)x3 in Types I/II and (c)x3 proposed; lighting (b)x3 in Type I, (a)x3 in Type II, (c)x3 proposed. Costs per Fig. 9: viewing 12 MUL + 9 ADD, perspective 5 MUL + 1 ADD, lighting 34 MUL + 19 ADD + 3 rsqrt; ADD = 1, MUL = 2, rsqrt = 16. *As built* is the golden host's own count (Gouraud), which lights the flagged triangles.\n");
    let _ = writeln!(s, "| scene | architecture | MUL | ADD | rsqrt | cost | % of Type I | % of Type II |\n|---|---|---|---|---|---|---|---|");
    for c in &a.cpu {
        for r in c.table3.iter().chain(std::iter::once(&c.as_built)) {
            let name = if std::ptr::eq(r, &c.as_built) { "proposed, as built (flagged lit)".to_string() } else { r.arch.label().to_string() };
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} | {:.1}% | {:.1}% |",
                c.scene, name, r.instructions.mul, r.instructions.add, r.instructions.rsqrt, r.cost, r.percent_of_type_i, r.percent_of_type_ii
            );
        }
    }
    let _ = writeln!(s, "| *paper: Dolphins* | *seed 001 Type I* | *409,002* | *254K* | *13K* | *1281K* | | |");
    let _ = writeln!(s, "| *paper: Dolphins* | *proposed* | | | | | *78.4%* | *52.6%* |");
    let _ = writeln!(s, "| *paper: Castle* | *proposed* | | | | | *56.1%* | *36.6%* |");
    let _ = writeln!(s, "\nThe paper's worked example reproduces exactly from its own formula (unit test `dolphins_worked_example_of_seed_001_reproduces_exactly`): 409,002 MUL, 253,707 ADD, 13,059 rsqrt, cost 1,280,655.");
    chart(&mut s, "seed001_cpu_cost.png", "Equivalent CPU cost per scene");

    // Fig. 9
    let _ = writeln!(s, "## Seed 000 Fig. 9: lighting operations against the traditional pipeline (Type I = 100%)\n");
    let _ = writeln!(s, "Phong lights per pixel: Type I every Z-passing fragment (reduced pixel rate), Types II-IV every covered pixel at scan-out. Flat and Gouraud light per triangle (1 or 3 per light): Types I and II every triangle after back-face culling (triangle rate), Types III/IV the triangles the RC flagged visible (reduced triangle rate). *(c) only* would light just the triangles visible in the final image.\n");
    for sh in [Shading::Phong, Shading::Gouraud, Shading::Flat] {
        let _ = writeln!(s, "### {}\n", shading_name(sh));
        let _ = writeln!(s, "| scene | size | Type I operations | Type II | Types III/IV | (c) only |\n|---|---|---|---|---|---|");
        for r in &a.lighting {
            let l = match sh {
                Shading::Phong => r.phong,
                Shading::Gouraud => r.gouraud,
                Shading::Flat => r.flat,
            };
            let _ = writeln!(s, "| {} | {} | {} | {:.1}% | {:.1}% | {:.1}% |", r.scene, size(r.width, r.height), l.type_i, l.type_ii_percent, l.type_iii_iv_percent, l.ideal_percent);
        }
        chart(&mut s, &format!("fig9_{}.png", shading_name(sh).to_lowercase()), &format!("Fig. 9, {}", shading_name(sh)));
    }
    let _ = writeln!(s, "Paper: Types III/IV save 10-70% for flat and Gouraud, 30-95% for Phong (Type II the same for Phong, nothing for flat and Gouraud).\n");

    // Texture
    let _ = writeln!(s, "## Texture operations: reduced pixel rate against scan-out rate (seed 000 §IV.B.5)\n");
    let _ = writeln!(s, "Texture fetches per frame for one fetch per pixel (multiply by 2, 4, 8 for other filter modes: the ratio stays).\n");
    let _ = writeln!(s, "| scene | size | pixel rate (fragments) | reduced pixel rate (Z passes, Type I) | scan-out, covered (Types II-IV) | scan-out, all pixels | Types II-IV / Type I |\n|---|---|---|---|---|---|---|");
    for r in &a.lighting {
        let t = r.texture;
        let _ = writeln!(s, "| {} | {} | {} | {} | {} | {} | {:.1}% |", r.scene, size(r.width, r.height), t.pixel_rate, t.reduced_pixel_rate, t.scan_out_covered, t.scan_out_all, t.percent);
    }

    // Table VII / Fig. 10
    let _ = writeln!(s, "\n## Seed 000 Table VII and Fig. 10: buffers and their sizes\n");
    let _ = writeln!(s, "| buffer | in types | one entry holds | size depends on | bits/entry, ours (Gouraud / Phong) | bits/entry, paper |\n|---|---|---|---|---|---|");
    let low = &TABLE_IV[2];
    for b in Buffer::ALL {
        let types: Vec<&str> = Arch::ALL.iter().filter(|t| t.buffers().contains(&b)).map(|t| t.numeral()).collect();
        let og = WidthSet::Ours.widths(low, Shading::Gouraud).of(b);
        let op = WidthSet::Ours.widths(low, Shading::Phong).of(b);
        let ours = if b == Buffer::I { "12-17 (log2 of triangles/frame)".to_string() } else if og == op { format!("{og}") } else { format!("{og} / {op}") };
        let paper_w = match b {
            Buffer::Frame => "16-32 (stated); 24 used",
            Buffer::Z => "not stated; 24 used (16 at the low end, reconstructed)",
            Buffer::Pixel => "\"over 100-200\" (stated); 100 / 200 used",
            Buffer::I => "10-20 (stated); log2 of triangles/frame",
            Buffer::TdbS => "not stated; 100 / 200 used (same parameters as a pixel-buffer entry)",
            Buffer::TdbV => "86.4 / 84 / 60 (from the stated 720 / 168 / 30 kB)",
        };
        let _ = writeln!(s, "| {} | {} | {} | {} | {} | {} |", b.name(), types.join(", "), b.entry(), b.depends_on(), ours, paper_w);
    }
    let _ = writeln!(s, "\nOur records: colour RGB888, depth 24 bits, a plane is A, B (40 bits) and C (56 bits) = 136 bits; a TdbS record is three planes (+ a 16-bit material number for Phong); the pixel buffer of deferred shading holds a copy of that record per pixel (the paper's *direct method*). Screen-size buffers have one entry per pixel; TdbS and TdbV one per triangle the level allows per frame. 1 kB = 1000 bytes.\n");
    for sh in BUFFER_SHADINGS {
        let _ = writeln!(s, "### {} (kB)\n", shading_name(sh));
        let _ = writeln!(s, "| level | size | type | frame | Z | pixel | I | TdbS | TdbV | total, ours | total, paper widths |\n|---|---|---|---|---|---|---|---|---|---|---|");
        for r in a.buffers.iter().filter(|r| r.shading == sh && r.widths == WidthSet::Ours) {
            let p = a.buffers.iter().find(|p| p.widths == WidthSet::Paper && (p.level, p.width, p.height, p.shading, p.arch) == (r.level, r.width, r.height, r.shading, r.arch));
            let cell = |b: Buffer| r.buffers.iter().find(|x| x.0 == b).map(|x| kb(x.1)).unwrap_or_default();
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.level,
                size(r.width, r.height),
                r.arch.numeral(),
                cell(Buffer::Frame),
                cell(Buffer::Z),
                cell(Buffer::Pixel),
                cell(Buffer::I),
                cell(Buffer::TdbS),
                cell(Buffer::TdbV),
                kb(r.total_bytes),
                p.map(|p| kb(p.total_bytes)).unwrap_or_default()
            );
        }
        chart(&mut s, &format!("fig10_{}_ours.png", shading_name(sh).to_lowercase()), "Fig. 10, our widths");
        chart(&mut s, &format!("fig10_{}_paper.png", shading_name(sh).to_lowercase()), "Fig. 10, the paper's widths");
    }
    let _ = writeln!(s, "Paper (stated): TdbV about 720 kB (high), 168 kB (middle), 30 kB (low end); index rendering at the low end 130-224 kB in all.\n");

    // Fig. 11 / 12
    let _ = writeln!(s, "## Seed 000 Fig. 11: worst-case bandwidth (MB/s)\n");
    let _ = writeln!(s, "Every triangle the level allows per frame is visible, every pixel covered, depth complexity {} (assumed: the paper's pixel rate for this case is in the lost Table IV), every fragment passes (back to front). Access model: see `golden/src/analysis/bandwidth.rs`. *Off chip* leaves out TdbV, which the paper puts on chip for Type III.\n", a.worst_depth_complexity);
    bandwidth_table(&mut s, &a.worst_bandwidth, true);
    for sh in BUFFER_SHADINGS {
        chart(&mut s, &format!("fig11_{}_ours.png", shading_name(sh).to_lowercase()), "Fig. 11");
    }
    let _ = writeln!(s, "## Seed 000 Fig. 12: simulated bandwidth (MB/s) of our scenes\n");
    let _ = writeln!(s, "Measured counts of each scene at the level's resolution, times the level's frame rate. Without a cache the shader of Types III/IV fetches a TdbS record for every covered pixel; *TdbS cache* keeps the last record and refetches only when the index changes along the scan (measured from the I-buffer).\n");
    bandwidth_table(&mut s, &a.simulated_bandwidth, false);
    for sh in BUFFER_SHADINGS {
        chart(&mut s, &format!("fig12_{}_ours.png", shading_name(sh).to_lowercase()), "Fig. 12");
    }
    let _ = writeln!(s, "Paper (stated): index rendering at the low end 15-81 MB/s.\n");

    // Claims
    let c = &a.claims;
    let _ = writeln!(s, "## Against the papers' claims\n");
    let _ = writeln!(s, "| claim | paper | ours |\n|---|---|---|");
    let rows: [(&str, String, String); 13] = [
        ("lighting saved by index rendering, flat and Gouraud (vs Type I)", "10-70%".into(), range(c.lighting_saved_flat_gouraud, "%")),
        ("the same, lighting only final-visible triangles", "-".into(), range(c.lighting_saved_flat_gouraud_ideal, "%")),
        ("lighting saved, Phong (Types II-IV vs Type I)", "30-95%".into(), range(c.lighting_saved_phong, "%")),
        ("buffer size saved, Types III/IV vs Type II, our widths", "70%".into(), range(c.buffer_saved_ours, "%")),
        ("buffer size saved, paper widths", "70%".into(), range(c.buffer_saved_paper_widths, "%")),
        ("bandwidth saved, simulated, Types III/IV vs Type II", "50-70%".into(), range(c.bandwidth_saved_simulated, "%")),
        ("the same, TdbV on chip", "50-70%".into(), range(c.bandwidth_saved_simulated_off_chip, "%")),
        ("the same, one-record TdbS cache in the shader", "50-70%".into(), range(c.bandwidth_saved_simulated_cached, "%")),
        ("bandwidth saved, worst case (TdbV on chip)", "50-70%".into(), format!("{} ({})", range(c.bandwidth_saved_worst, "%"), range(c.bandwidth_saved_worst_off_chip, "%"))),
        ("seed 001 proposed CPU cost, % of its Type II / Type I", "36.6-52.6% / 56.1-78.4%".into(), format!("{} / {}", range(c.cpu_percent_of_type_ii, "%"), range(c.cpu_percent_of_type_i, "%"))),
        ("the same, as built (flagged triangles lit), % of Type II", "-".into(), range(c.cpu_as_built_percent_of_type_ii, "%")),
        ("low-end index rendering buffers (kB), ours / paper widths", format!("{}-{}", paper::LOW_END_BUFFER_KB.0, paper::LOW_END_BUFFER_KB.1), format!("{} / {}", range(c.low_end_buffer_kb_ours, ""), range(c.low_end_buffer_kb_paper_widths, ""))),
        ("low-end index rendering bandwidth (MB/s), ours / paper widths", format!("{}-{}", paper::LOW_END_BANDWIDTH_MBS.0, paper::LOW_END_BANDWIDTH_MBS.1), format!("{} / {}", range(c.low_end_bandwidth_mbs_ours, ""), range(c.low_end_bandwidth_mbs_paper_widths, ""))),
    ];
    for (claim, p, o) in rows {
        let _ = writeln!(s, "| {claim} | {p} | {o} |");
    }
    let pc = |x: Option<f64>| x.map(|v| format!("{v:.1}%")).unwrap_or_else(|| "-".into());
    let _ = writeln!(s, "\nPer scene (ranges over the sizes; bandwidth also over levels and shading methods):\n");
    let _ = writeln!(s, "| scene | lighting saved, flat/Gouraud | (c) only | lighting saved, Phong | bandwidth saved vs Type II | with TdbS cache | seed 001 proposed, % of Type II / Type I | as built, % of Type II |\n|---|---|---|---|---|---|---|---|");
    for p in &c.per_scene {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} / {} | {} |",
            p.scene,
            range(p.lighting_saved_flat_gouraud, "%"),
            range(p.lighting_saved_flat_gouraud_ideal, "%"),
            range(p.lighting_saved_phong, "%"),
            range(p.bandwidth_saved_simulated, "%"),
            range(p.bandwidth_saved_simulated_cached, "%"),
            pc(p.cpu_percent_of_type_ii),
            pc(p.cpu_percent_of_type_i),
            pc(p.cpu_as_built_percent_of_type_ii)
        );
    }
    let _ = writeln!(s, "\nWhy the numbers differ from the paper's is discussed in `docs/analysis.md`.");
    s
}

fn bandwidth_table(s: &mut String, rows: &[BandwidthRow], per_buffer: bool) {
    for sh in BUFFER_SHADINGS {
        let _ = writeln!(s, "### {}\n", shading_name(sh));
        let ours: Vec<&BandwidthRow> = rows.iter().filter(|r| r.shading == sh && r.widths == WidthSet::Ours).collect();
        if per_buffer {
            let _ = writeln!(s, "| level | size | type | frame | Z | pixel | I | TdbS | TdbV | total | off chip | total, paper widths |\n|---|---|---|---|---|---|---|---|---|---|---|---|");
            for r in &ours {
                let p = rows.iter().find(|p| p.widths == WidthSet::Paper && (p.level, p.width, p.height, p.shading, p.arch, &p.case) == (r.level, r.width, r.height, r.shading, r.arch, &r.case));
                let cell = |b: Buffer| r.buffers.iter().find(|x| x.0 == b).map(|x| format!("{:.1}", x.1)).unwrap_or_default();
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.1} | {:.1} | {} |",
                    r.level,
                    size(r.width, r.height),
                    r.arch.numeral(),
                    cell(Buffer::Frame),
                    cell(Buffer::Z),
                    cell(Buffer::Pixel),
                    cell(Buffer::I),
                    cell(Buffer::TdbS),
                    cell(Buffer::TdbV),
                    r.total_mbs,
                    r.off_chip_mbs,
                    p.map(|p| format!("{:.1}", p.total_mbs)).unwrap_or_default()
                );
            }
        } else {
            let _ = writeln!(s, "| level | size | scene | Type I | Type II | Type III | Type III off chip | Type IV | III / IV, TdbS cache | III/IV saved vs II | with TdbS cache |\n|---|---|---|---|---|---|---|---|---|---|---|");
            let mut keys: Vec<(&str, u32, u32, &str)> = Vec::new();
            for r in &ours {
                let k = (r.level, r.width, r.height, r.case.as_str());
                if !keys.contains(&k) {
                    keys.push(k);
                }
            }
            for k in keys {
                let get = |a: Arch| ours.iter().find(|r| (r.level, r.width, r.height, r.case.as_str()) == k && r.arch == a).copied();
                let (Some(i), Some(ii), Some(iii), Some(iv)) = (get(Arch::TypeI), get(Arch::TypeII), get(Arch::TypeIII), get(Arch::TypeIV)) else { continue };
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} / {:.1} | {:.0}% / {:.0}% | {:.0}% / {:.0}% |",
                    k.0,
                    size(k.1, k.2),
                    k.3,
                    i.total_mbs,
                    ii.total_mbs,
                    iii.total_mbs,
                    iii.off_chip_mbs,
                    iv.total_mbs,
                    iii.cached_mbs,
                    iv.cached_mbs,
                    100.0 * (1.0 - iii.total_mbs / ii.total_mbs),
                    100.0 * (1.0 - iv.total_mbs / ii.total_mbs),
                    100.0 * (1.0 - iii.cached_mbs / ii.total_mbs),
                    100.0 * (1.0 - iv.cached_mbs / ii.total_mbs)
                );
            }
        }
        let _ = writeln!(s);
    }
}

// ---------------------------------------------------------------------------------------------
// Charts

/// One bar set: a label under it and one value per series (side by side, or stacked).
pub(crate) struct Bars {
    pub label: String,
    pub values: Vec<f64>,
}

pub(crate) struct Group {
    pub name: String,
    pub bars: Vec<Bars>,
}

pub(crate) struct Chart {
    pub title: String,
    pub y_label: String,
    pub series: Vec<String>,
    pub groups: Vec<Group>,
    pub stacked: bool,
    /// A dashed reference line (e.g. Type I = 100%).
    pub reference: Option<f64>,
}

const PALETTE: [(u8, u8, u8); 6] = [(68, 114, 196), (237, 125, 49), (112, 173, 71), (192, 80, 77), (128, 100, 162), (150, 150, 150)];

fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // DejaVu Sans is a valid TrueType font; a failure here would only lose the text.
        let _ = plotters::style::register_font("sans-serif", plotters::style::FontStyle::Normal, dejavu::sans::regular());
    });
}

pub(crate) fn draw(c: &Chart) -> Result<Vec<u8>, String> {
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    register_font();
    let slots = if c.stacked { 1.0 } else { c.series.len() as f64 };
    let (bar_gap, group_gap) = (0.7, 1.2);
    // Positions: (x of the bar set's left edge) per bar set, and group spans.
    let mut x = group_gap / 2.0;
    let mut sets = Vec::new();
    let mut spans = Vec::new();
    for g in &c.groups {
        let start = x;
        for b in &g.bars {
            sets.push((x, b));
            x += slots + bar_gap;
        }
        spans.push((start, x - bar_gap, &g.name));
        x += group_gap;
    }
    let total = x;
    let height_of = |b: &Bars| if c.stacked { b.values.iter().sum::<f64>() } else { b.values.iter().cloned().fold(0.0, f64::max) };
    let ymax = sets.iter().map(|s| height_of(s.1)).fold(c.reference.unwrap_or(0.0), f64::max).max(1e-9) * 1.15;
    // Pixels per x unit: every bar at least 18 px wide, and every bar set wide enough for its label
    // (about 7 px per character at 12 px).
    let longest = sets.iter().map(|s| s.1.label.chars().count()).max().unwrap_or(1) as f64;
    let min_bar = if c.stacked { 30.0 } else { 18.0 };
    let ppu = (longest * 7.0 + 8.0).max(min_bar * (slots + bar_gap)) / (slots + bar_gap);
    let w = ((total * ppu + 140.0) as u32).clamp(900, 3200);
    let h = 560u32;
    let mut buf = vec![255u8; (w * h * 3) as usize];
    let err = |e: &dyn std::fmt::Display| format!("drawing chart '{}': {e}", c.title);
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&c.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(46)
            .y_label_area_size(80)
            .build_cartesian_2d(0f64..total, 0f64..ymax)
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(0)
            .y_desc(c.y_label.as_str())
            .label_style(("sans-serif", 13))
            .axis_desc_style(("sans-serif", 14))
            .draw()
            .map_err(|e| err(&e))?;
        for (si, name) in c.series.iter().enumerate() {
            let (r, g, b) = PALETTE[si % PALETTE.len()];
            let colour = RGBColor(r, g, b);
            let rects: Vec<Rectangle<(f64, f64)>> = sets
                .iter()
                .filter_map(|&(x0, bars)| {
                    let v = *bars.values.get(si)?;
                    if v <= 0.0 {
                        return None;
                    }
                    let (lo, left) = if c.stacked { (bars.values[..si].iter().sum::<f64>(), x0) } else { (0.0, x0 + si as f64) };
                    Some(Rectangle::new([(left, lo), (left + 1.0, lo + v)], colour.filled()))
                })
                .collect();
            chart
                .draw_series(rects)
                .map_err(|e| err(&e))?
                .label(name.as_str())
                .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 12, y + 6)], colour.filled()));
        }
        if let Some(r) = c.reference {
            chart
                .draw_series(DashedLineSeries::new(vec![(0.0, r), (total, r)], 6, 4, BLACK.stroke_width(1)))
                .map_err(|e| err(&e))?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(|e| err(&e))?;
        // Values on top of the bars when there is room, bar labels and group names under the axis.
        let small = TextStyle::from(("sans-serif", 11).into_font()).pos(Pos::new(HPos::Center, VPos::Bottom));
        let under = TextStyle::from(("sans-serif", 12).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        let group_style = TextStyle::from(("sans-serif", 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        let room = (w as f64 - 140.0) / total >= 26.0 || (c.stacked && (w as f64 - 140.0) / total >= 24.0);
        for &(x0, bars) in &sets {
            let centre = x0 + slots / 2.0;
            let (px, py) = chart.backend_coord(&(centre, 0.0));
            root.draw_text(&bars.label, &under, (px, py + 4)).map_err(|e| err(&e))?;
            if room {
                let tops: Vec<(f64, f64)> = if c.stacked {
                    vec![(centre, height_of(bars))]
                } else {
                    bars.values.iter().enumerate().map(|(i, &v)| (x0 + i as f64 + 0.5, v)).collect()
                };
                for (tx, v) in tops {
                    let (qx, qy) = chart.backend_coord(&(tx, v));
                    root.draw_text(&format_value(v), &small, (qx, qy - 2)).map_err(|e| err(&e))?;
                }
            }
        }
        for &(x0, x1, name) in &spans {
            let (px, py) = chart.backend_coord(&((x0 + x1) / 2.0, 0.0));
            root.draw_text(name, &group_style, (px, py + 22)).map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    png_bytes(w, h, &buf)
}

fn format_value(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.1}")
    }
}

/// The values of one bar (level name, width, height, type), if there is such a row.
type BarValues<'a> = dyn Fn(&str, u32, u32, Arch) -> Option<Vec<f64>> + 'a;

/// Every chart of the report, as (file name, PNG bytes).
fn charts(a: &Analysis) -> Result<Vec<(String, Vec<u8>)>, String> {
    let mut out = Vec::new();
    let mut scenes: Vec<String> = Vec::new();
    for m in &a.measured {
        if !scenes.contains(&m.scene) {
            scenes.push(m.scene.clone());
        }
    }

    if !a.cpu.is_empty() {
        let c = Chart {
            title: format!("Seed 001 Table 3: equivalent CPU cost at {}x{} (K)", SEED001_SCREEN.0, SEED001_SCREEN.1),
            y_label: "cost (ADD 1, MUL 2, rsqrt 16), thousands".into(),
            series: vec!["seed 001 Type I".into(), "seed 001 Type II".into(), "proposed, (c) lit".into(), "proposed as built, flagged lit".into()],
            groups: a
                .cpu
                .iter()
                .map(|c| Group {
                    name: String::new(),
                    bars: vec![Bars {
                        label: c.scene.clone(),
                        values: c.table3.iter().map(|r| r.cost as f64 / 1000.0).chain([c.as_built.cost as f64 / 1000.0]).collect(),
                    }],
                })
                .collect(),
            stacked: false,
            reference: None,
        };
        out.push(("seed001_cpu_cost.png".to_string(), draw(&c)?));
    }

    for sh in [Shading::Phong, Shading::Gouraud, Shading::Flat] {
        let c = Chart {
            title: format!("Seed 000 Fig. 9: lighting operations, {} shading (Type I = 100%)", shading_name(sh)),
            y_label: "% of Type I".into(),
            series: vec!["Type II (deferred shading)".into(), "Types III/IV (index rendering)".into()],
            groups: scenes
                .iter()
                .map(|sc| Group {
                    name: sc.clone(),
                    bars: a
                        .lighting
                        .iter()
                        .filter(|r| &r.scene == sc)
                        .map(|r| {
                            let l = match sh {
                                Shading::Phong => r.phong,
                                Shading::Gouraud => r.gouraud,
                                Shading::Flat => r.flat,
                            };
                            Bars { label: size(r.width, r.height), values: vec![l.type_ii_percent, l.type_iii_iv_percent] }
                        })
                        .collect(),
                })
                .collect(),
            stacked: false,
            reference: Some(100.0),
        };
        out.push((format!("fig9_{}.png", shading_name(sh).to_lowercase()), draw(&c)?));
    }

    let level_groups = |f: &BarValues| -> Vec<Group> {
        let mut g = Vec::new();
        for l in &a.levels {
            for (w, h) in l.resolutions {
                let bars = Arch::ALL.iter().filter_map(|&arch| f(l.name, w, h, arch).map(|values| Bars { label: arch.numeral().into(), values })).collect();
                g.push(Group { name: format!("{} {}", l.name, size(w, h)), bars });
            }
        }
        g
    };
    let buffer_series: Vec<String> = Buffer::ALL.iter().map(|b| b.name().to_string()).collect();
    let per_buffer = |list: &[(Buffer, f64)], scale: f64| -> Vec<f64> {
        Buffer::ALL.iter().map(|b| list.iter().find(|x| x.0 == *b).map(|x| x.1 * scale).unwrap_or(0.0)).collect()
    };
    for sh in BUFFER_SHADINGS {
        for (ws, tag, what) in [(WidthSet::Ours, "ours", "our widths"), (WidthSet::Paper, "paper", "the paper's widths")] {
            let c = Chart {
                title: format!("Seed 000 Fig. 10: buffer sizes, {} shading, {}", shading_name(sh), what),
                y_label: "kB".into(),
                series: buffer_series.clone(),
                groups: level_groups(&|lv, w, h, arch| {
                    a.buffers
                        .iter()
                        .find(|r| (r.level, r.width, r.height, r.arch, r.shading, r.widths) == (lv, w, h, arch, sh, ws))
                        .map(|r| per_buffer(&r.buffers, 1e-3))
                }),
                stacked: true,
                reference: None,
            };
            out.push((format!("fig10_{}_{tag}.png", shading_name(sh).to_lowercase()), draw(&c)?));
        }
        let c = Chart {
            title: format!("Seed 000 Fig. 11: worst-case bandwidth, {} shading, our widths, depth complexity {}", shading_name(sh), a.worst_depth_complexity),
            y_label: "MB/s".into(),
            series: buffer_series.clone(),
            groups: level_groups(&|lv, w, h, arch| {
                a.worst_bandwidth
                    .iter()
                    .find(|r| (r.level, r.width, r.height, r.arch, r.shading, r.widths) == (lv, w, h, arch, sh, WidthSet::Ours))
                    .map(|r| per_buffer(&r.buffers, 1.0))
            }),
            stacked: true,
            reference: None,
        };
        out.push((format!("fig11_{}_ours.png", shading_name(sh).to_lowercase()), draw(&c)?));

        let mut groups = Vec::new();
        for l in &a.levels {
            for (w, h) in l.resolutions {
                let bars: Vec<Bars> = scenes
                    .iter()
                    .filter_map(|sc| {
                        let values: Option<Vec<f64>> = Arch::ALL
                            .iter()
                            .map(|&arch| {
                                a.simulated_bandwidth
                                    .iter()
                                    .find(|r| (r.level, r.width, r.height, r.arch, r.shading, r.widths) == (l.name, w, h, arch, sh, WidthSet::Ours) && &r.case == sc)
                                    .map(|r| r.total_mbs)
                            })
                            .collect();
                        values.map(|values| Bars { label: sc.clone(), values })
                    })
                    .collect();
                groups.push(Group { name: format!("{} {}", l.name, size(w, h)), bars });
            }
        }
        let c = Chart {
            title: format!("Seed 000 Fig. 12: simulated bandwidth, {} shading, our widths", shading_name(sh)),
            y_label: "MB/s".into(),
            series: Arch::ALL.iter().map(|t| format!("Type {}", t.numeral())).collect(),
            groups,
            stacked: false,
            reference: None,
        };
        out.push((format!("fig12_{}_ours.png", shading_name(sh).to_lowercase()), draw(&c)?));
    }
    Ok(out)
}
