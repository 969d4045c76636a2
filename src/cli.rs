//! Command-line arguments and the commands they run.

use clap::{Parser, Subcommand, ValueEnum};
use golden::format::{Screen, INDEX_BITS_DEFAULT};
use golden::host::Camera;
use golden::raster::{CullMode, FrontFace};
use golden::render::RenderOptions;
use golden::scene::{builtin, obj, Mesh, Winding};
use golden::shade::Shading;
use std::path::PathBuf;

#[derive(Parser, Debug)]
#[command(name = "idxrender", version, about = "Index-rendering 3-D chipset: render, generate Verilog, analyse")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render a scene: writes frame.png, index.bin, index.png and stats.json into --out.
    Render(RenderArgs),
    /// Write the Verilog of an RTL top (or of every top) into --out.
    Verilog(crate::verilog::VerilogArgs),
    /// Reproduce the seeds' analysis (lighting operations, CPU cost, buffer sizes, bandwidth).
    Analyze(crate::analyze::AnalyzeArgs),
    /// Synthesize and place and route the tops on iCE40 UP5K/HX8K; write a utilisation and Fmax table.
    FpgaReport(crate::fpga::FpgaArgs),
    /// Compare two VCD traces of the same top cycle by cycle on its ports; report the first difference.
    VcdDiff(crate::vcd_diff::VcdDiffArgs),
    /// Measure golden, RustHDL and Verilator speed, the chipset's work per clock and frames/s at Fmax; write bench.md.
    Bench(crate::bench::BenchArgs),
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum ArchArg {
    /// Index rendering: seed 001's RC + CS chipset.
    Index,
    /// PROOF's object-processor pipeline (seed 002), anti-aliased.
    Proof,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum BackendArg {
    /// The algorithmic golden model.
    Golden,
    /// The RustHDL simulation of the RTL.
    Rtl,
    /// The generated Verilog of chipset under Verilator.
    Verilator,
}

#[derive(Copy, Clone, Debug, ValueEnum)]
pub enum ShadingArg {
    Flat,
    Gouraud,
    Phong,
}

#[derive(Copy, Clone, Debug, ValueEnum)]
pub enum CullArg {
    Back,
    Front,
    None,
}

#[derive(Copy, Clone, Debug, ValueEnum)]
pub enum FrontArg {
    Ccw,
    Cw,
}

#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    /// A built-in scene: polyhedron, teapot, castle, dolphins.
    #[arg(long, conflicts_with = "obj")]
    pub scene: Option<String>,
    /// A Wavefront OBJ file to render instead of a built-in scene.
    #[arg(long)]
    pub obj: Option<PathBuf>,
    /// Teapot tessellation (GLUT's grid; 14 as glutSolidTeapot).
    #[arg(long, default_value_t = 14)]
    pub grid: u32,
    /// Image size WxH (each 1..=1024).
    #[arg(long, default_value = "320x200")]
    pub size: String,
    /// Eye position x,y,z (gluLookAt). Default: frames the whole model.
    #[arg(long, allow_hyphen_values = true)]
    pub eye: Option<String>,
    /// Point looked at x,y,z. Default: the model's bounding-sphere centre.
    #[arg(long, allow_hyphen_values = true)]
    pub center: Option<String>,
    /// Up vector x,y,z.
    #[arg(long, default_value = "0,1,0", allow_hyphen_values = true)]
    pub up: String,
    /// Vertical field of view in degrees (gluPerspective).
    #[arg(long, default_value_t = 40.0, allow_hyphen_values = true)]
    pub fovy: f64,
    /// Near plane distance. Default: from the bounding sphere.
    #[arg(long, allow_hyphen_values = true)]
    pub near: Option<f64>,
    /// Far plane distance. Default: from the bounding sphere.
    #[arg(long, allow_hyphen_values = true)]
    pub far: Option<f64>,
    #[arg(long, value_enum, default_value_t = ShadingArg::Gouraud)]
    pub shading: ShadingArg,
    /// Which faces to cull.
    #[arg(long, value_enum, default_value_t = CullArg::Back)]
    pub cull: CullArg,
    /// Front-face winding. Default: the scene's own (ccw; cw for GLUT's teapot, which GLUT emits clockwise).
    #[arg(long, value_enum)]
    pub front_face: Option<FrontArg>,
    /// Triangle-index width in bits (0 is reserved for background).
    #[arg(long, default_value_t = INDEX_BITS_DEFAULT)]
    pub index_bits: u32,
    /// Output directory.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// PROOF: object processors in the OPP (default: as many as the frame needs with OP reuse).
    #[arg(long)]
    pub ops: Option<usize>,
    /// PROOF: FIFO depth of each object processor, in list slots.
    #[arg(long, default_value_t = 1)]
    pub fifo_depth: usize,
    /// PROOF: filter area, 1x1 (default) or 2x2 pixels.
    #[arg(long, default_value = "1x1")]
    pub filter: String,
    /// Rendering architecture.
    #[arg(long, value_enum, default_value_t = ArchArg::Index)]
    pub arch: ArchArg,
    /// What computes the frame.
    #[arg(long, value_enum, default_value_t = BackendArg::Golden)]
    pub backend: BackendArg,
    /// Also write the simulation's waveform (frame.vcd) into --out (RTL backends): the top-level ports.
    #[arg(long)]
    pub vcd: bool,
    /// With --vcd: every signal of every block instead of the top-level ports (hundreds of MB per frame).
    #[arg(long, requires = "vcd")]
    pub vcd_full: bool,
    /// Render the scene this many times back to back (1..=64; RTL backends overlap the frames as the
    /// chipset does) and write the last frame's files; every frame is compared with the golden one.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=MAX_FRAMES as i64))]
    pub frames: u32,
}

/// The most frames one `render --frames` run takes (each frame's host state is kept until the run ends).
pub const MAX_FRAMES: u32 = 64;

fn parse_size(s: &str) -> Result<Screen, String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("--size '{s}' is not WxH (e.g. 320x200)"))?;
    let w: u32 = w.trim().parse().map_err(|_| format!("--size '{s}': width '{w}' is not a whole number"))?;
    let h: u32 = h.trim().parse().map_err(|_| format!("--size '{s}': height '{h}' is not a whole number"))?;
    Screen::new(w, h).map_err(|e| format!("--size: {e}"))
}

fn parse_vec3(name: &str, s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(format!("--{name} '{s}' is not three comma-separated numbers x,y,z"));
    }
    let mut v = [0.0f64; 3];
    for (k, p) in parts.iter().enumerate() {
        v[k] = p.trim().parse().map_err(|_| format!("--{name} '{s}': '{p}' is not a number"))?;
        if !v[k].is_finite() {
            return Err(format!("--{name} '{s}': '{p}' is not a finite number"));
        }
    }
    Ok(v)
}

/// Load the scene the arguments name.
pub fn load_scene(args: &RenderArgs) -> Result<Mesh, String> {
    match (&args.scene, &args.obj) {
        (_, Some(path)) => obj::load_obj(path),
        (Some(name), None) if name == "teapot" => {
            if !(1..=64).contains(&args.grid) {
                return Err(format!("--grid {} is not in 1..=64", args.grid));
            }
            Ok(builtin::teapot(args.grid))
        }
        (Some(name), None) => builtin::scene(name),
        (None, None) => Err(format!("say what to render: --scene NAME (one of {}) or --obj FILE", builtin::SCENES.join(", "))),
    }
}

/// Build the render options from the arguments and the scene.
pub fn render_options(args: &RenderArgs, mesh: &Mesh) -> Result<RenderOptions, String> {
    let screen = parse_size(&args.size)?;
    let up = parse_vec3("up", &args.up)?;
    let mut camera = Camera::framing_aspect(mesh, [0.3, 0.45, 1.0], args.fovy, screen.width as f64 / screen.height as f64);
    camera.up = up;
    if let Some(c) = &args.center {
        camera.center = parse_vec3("center", c)?;
    }
    if let Some(e) = &args.eye {
        camera.eye = parse_vec3("eye", e)?;
        let (n, f) = Camera::near_far_for(mesh, camera.eye);
        camera.near = n;
        camera.far = f;
    }
    if let Some(n) = args.near {
        camera.near = n;
    }
    if let Some(f) = args.far {
        camera.far = f;
    }
    camera.validate()?;
    let front = match args.front_face {
        Some(FrontArg::Ccw) => FrontFace::Ccw,
        Some(FrontArg::Cw) => FrontFace::Cw,
        None => match mesh.front_face {
            Winding::Ccw => FrontFace::Ccw,
            Winding::Cw => FrontFace::Cw,
        },
    };
    let shading = match args.shading {
        ShadingArg::Flat => Shading::Flat,
        ShadingArg::Gouraud => Shading::Gouraud,
        ShadingArg::Phong => Shading::Phong,
    };
    Ok(RenderOptions {
        camera,
        cull: match args.cull {
            CullArg::Back => CullMode::Back,
            CullArg::Front => CullMode::Front,
            CullArg::None => CullMode::None,
        },
        front,
        index_bits: args.index_bits,
        ..RenderOptions::for_scene(mesh, screen, shading)
    })
}

pub fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Render(args) => run_render(&args),
        Command::Verilog(args) => crate::verilog::run(&args),
        Command::Analyze(args) => crate::analyze::run(&args),
        Command::FpgaReport(args) => crate::fpga::run(&args),
        Command::VcdDiff(args) => crate::vcd_diff::run(&args),
        Command::Bench(args) => crate::bench::run(&args),
    }
}

fn run_render(args: &RenderArgs) -> Result<(), String> {
    let mesh = load_scene(args)?;
    let opts = render_options(args, &mesh)?;
    match args.arch {
        ArchArg::Proof if args.frames != 1 => Err("--frames applies to --arch index (the chipset); PROOF renders one frame".into()),
        ArchArg::Proof => crate::proof::run_render(args, &mesh, &opts),
        ArchArg::Index => crate::render::run_render(args, &mesh, &opts),
    }
}
