//! The arguments of `render` (and of the commands that render the same frames: `analyze`, `bench`):
//! their types, and the scene and render options they make. Below every command module, so that the
//! commands use it without importing each other.

use clap::ValueEnum;
use golden::format::{Screen, INDEX_BITS_DEFAULT};
use golden::host::{Camera, CAMERA_RANGE};
use golden::raster::{CullMode, FrontFace};
use golden::render::{RenderOptions, Texturing};
use golden::texcoord::Coords;
use golden::texture::{Filter, Wrap};
use golden::scene::{builtin, obj, Mesh, Winding};
use golden::shade::Shading;
use std::path::PathBuf;

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

/// Seed 000's index-rendering architecture (`--type`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum TypeArg {
    /// No Z-buffer: the old depth is regenerated from TdbV, the triangles' depth planes.
    #[value(name = "III")]
    Iii,
    /// I-buffer and Z-buffer.
    #[value(name = "IV")]
    Iv,
}

#[derive(Copy, Clone, Debug, ValueEnum)]
pub enum ShadingArg {
    Flat,
    Gouraud,
    Phong,
}

/// How the texture is filtered (`--texture-filter`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum TextureFilterArg {
    Nearest,
    Bilinear,
    /// Mipmapped: bilinear in the two levels around the pixel's level of detail, blended.
    Trilinear,
}

/// How texture coordinates are interpolated (`--texture-coords`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum TextureCoordsArg {
    /// s/w, t/w and 1/w planes and a division per pixel.
    Perspective,
    /// s and t planes, seed 000's linear expressions (wrong under perspective).
    Affine,
}

/// What texture coordinates outside [0, 1) do (`--texture-wrap`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum TextureWrapArg {
    Repeat,
    Clamp,
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
    /// A built-in scene: polyhedron, teapot, castle, dolphins; teapot-floor (textured); glass (transparent, --arch proof).
    #[arg(long, conflicts_with = "obj")]
    pub scene: Option<String>,
    /// A Wavefront OBJ file to render instead of a built-in scene.
    #[arg(long)]
    pub obj: Option<PathBuf>,
    /// Teapot tessellation (GLUT's grid, 1..=64; default 14 as glutSolidTeapot). Only with --scene teapot.
    #[arg(long)]
    pub grid: Option<u32>,
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
    /// Triangle-index width in bits (0 is reserved for background; default 16). Only with --arch index.
    #[arg(long)]
    pub index_bits: Option<u32>,
    /// Seed 000's index-rendering type: IV keeps a Z-buffer, III regenerates depth from TdbV (the
    /// triangles' depth planes) instead. Only with --arch index.
    #[arg(long = "type", value_enum)]
    pub rc_type: Option<TypeArg>,
    /// Output directory.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// PROOF: object processors in the OPP (default: as many as the frame needs with OP reuse).
    #[arg(long)]
    pub ops: Option<usize>,
    /// PROOF: FIFO depth of each object processor, in list slots (default 1).
    #[arg(long)]
    pub fifo_depth: Option<usize>,
    /// PROOF: filter area, 1x1 (default) or 2x2 pixels.
    #[arg(long)]
    pub filter: Option<String>,
    /// Every material's opacity, 0..=1 (1 = opaque; default: the scene's own, MTL `d` or 1 - `Tr`).
    /// Below 1 only --arch proof (golden backend) renders it.
    #[arg(long, allow_hyphen_values = true)]
    pub opacity: Option<f64>,
    /// Texture every triangle with this PNG or JPEG (width and height powers of two, at most 1024),
    /// instead of the scene's own texture (OBJ `map_Kd`, or teapot-floor's built-in checker). The
    /// scene needs texture coordinates (OBJ `vt`; the built-in teapot has GLUT's). Golden or rtl backend.
    #[arg(long)]
    pub texture: Option<PathBuf>,
    /// Draw a textured scene (OBJ `map_Kd`, teapot-floor) without its texture.
    #[arg(long, conflicts_with_all = ["texture", "texture_filter", "texture_coords", "texture_wrap"])]
    pub no_texture: bool,
    /// Texture filter (textured scenes only).
    #[arg(long, value_enum)]
    pub texture_filter: Option<TextureFilterArg>,
    /// Texture-coordinate interpolation (textured scenes only).
    #[arg(long, value_enum)]
    pub texture_coords: Option<TextureCoordsArg>,
    /// Texture addressing outside [0, 1) (textured scenes only).
    #[arg(long, value_enum)]
    pub texture_wrap: Option<TextureWrapArg>,
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

pub fn parse_size(s: &str) -> Result<Screen, String> {
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

/// Load the scene the arguments name, with `--opacity` applied to every material.
pub fn load_scene(args: &RenderArgs) -> Result<Mesh, String> {
    let mut mesh = load_mesh(args)?;
    if let Some(a) = args.opacity {
        if !(0.0..=1.0).contains(&a) {
            return Err(format!("--opacity {a:?} is not in 0..=1 (1 = opaque)"));
        }
        for m in &mut mesh.materials {
            m.opacity = a;
        }
    }
    Ok(mesh)
}

fn load_mesh(args: &RenderArgs) -> Result<Mesh, String> {
    match (&args.scene, &args.obj) {
        (_, Some(path)) if args.grid.is_some() => Err(format!("--grid applies to --scene teapot only (GLUT's tessellation), not to {}", path.display())),
        (_, Some(path)) => {
            let (mesh, warnings) = obj::load_obj_with_warnings(path)?;
            for w in warnings {
                eprintln!("warning: {w}");
            }
            Ok(mesh)
        }
        (Some(name), None) if name == "teapot" => {
            let grid = args.grid.unwrap_or(builtin::TEAPOT_GRID);
            if !(1..=64).contains(&grid) {
                return Err(format!("--grid {grid} is not in 1..=64"));
            }
            Ok(builtin::teapot(grid))
        }
        (Some(name), None) if args.grid.is_some() => Err(format!("--grid applies to --scene teapot only (GLUT's tessellation); {name} has its own triangles")),
        (Some(name), None) => builtin::scene(name),
        (None, None) => Err(format!("say what to render: --scene NAME (one of {}; {} with --arch proof) or --obj FILE", builtin::SCENES.join(", "), builtin::TRANSPARENT_SCENES.join(", "))),
    }
}

/// Build the render options from the arguments and the scene.
pub fn render_options(args: &RenderArgs, mesh: &Mesh) -> Result<RenderOptions, String> {
    let screen = parse_size(&args.size)?;
    let up = parse_vec3("up", &args.up)?;
    if !(args.fovy.is_finite() && args.fovy > 0.0 && args.fovy < 180.0) {
        return Err(format!("--fovy {:?}: the vertical field of view must be in (0, 180) degrees", args.fovy));
    }
    let mut camera = Camera::for_mesh(mesh, args.fovy, screen.width as f64 / screen.height as f64);
    camera.up = up;
    let in_range = |name: &str, p: [f64; 3]| -> Result<[f64; 3], String> {
        match p.iter().find(|v| v.abs() > CAMERA_RANGE) {
            Some(v) => Err(format!("--{name} {}: {v:e} is outside +-{CAMERA_RANGE:e}, the range of camera positions", p.map(|c| format!("{c:?}")).join(","))),
            None => Ok(p),
        }
    };
    if let Some(c) = &args.center {
        camera.center = in_range("center", parse_vec3("center", c)?)?;
    }
    if args.eye.is_none() && camera.eye.iter().any(|v| v.abs() > CAMERA_RANGE) {
        return Err(format!(
            "--fovy {:?}: the default view would put the eye {:.3e} away to frame the whole model in so narrow a field; \
             camera positions are limited to +-{CAMERA_RANGE:e}: use a wider --fovy or give --eye",
            args.fovy,
            camera.eye.iter().fold(0.0f64, |m, v| m.max(v.abs()))
        ));
    }
    if let Some(e) = &args.eye {
        camera.eye = in_range("eye", parse_vec3("eye", e)?)?;
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
        index_bits: args.index_bits.unwrap_or(INDEX_BITS_DEFAULT),
        rc_type: match args.rc_type {
            Some(TypeArg::Iii) => golden::raster::RcType::III,
            Some(TypeArg::Iv) | None => golden::raster::RcType::IV,
        },
        texturing: texturing(args, mesh)?,
        ..RenderOptions::for_scene(mesh, screen, shading)
    })
}

/// The frame's texture: `--texture FILE`, else the scene's (the built-in checker for the textured
/// built-in scenes, an OBJ material's `map_Kd`), else none; none with `--no-texture`. The filter,
/// coordinate and wrap options need a texture. PROOF draws no texture: there the texture options are
/// errors and a scene's own texture is left out with a warning.
fn texturing(args: &RenderArgs, mesh: &Mesh) -> Result<Option<Texturing>, String> {
    if args.no_texture {
        return Ok(None);
    }
    let builtin_textured = args.scene.as_deref().is_some_and(|n| builtin::TEXTURED_SCENES.contains(&n));
    if args.arch == ArchArg::Proof {
        let given = args.texture.is_some() || args.texture_filter.is_some() || args.texture_coords.is_some() || args.texture_wrap.is_some();
        if given {
            return Err("texture mapping is for --arch index; PROOF's shading has no texture".into());
        }
        if builtin_textured || mesh.materials.iter().any(|m| m.texture.is_some()) {
            eprintln!("warning: PROOF draws no texture: scene '{}' is drawn without its texture", mesh.name);
        }
        return Ok(None);
    }
    let (texture, source) = if let Some(path) = &args.texture {
        (golden::texture::load(path)?, path.display().to_string())
    } else if builtin_textured {
        (golden::texture::checker(), "built-in checker".to_string())
    } else {
        // An OBJ's map_Kd: the first textured material's, in triangle order (the chipset holds one
        // texture per frame).
        let mut named: Vec<&std::path::Path> = Vec::new();
        for t in &mesh.triangles {
            if let Some(p) = mesh.materials.get(t.material as usize).and_then(|m| m.texture.as_deref()) {
                if !named.contains(&p) {
                    named.push(p);
                }
            }
        }
        match named.first() {
            None => {
                for (given, name) in [
                    (args.texture_filter.is_some(), "--texture-filter"),
                    (args.texture_coords.is_some(), "--texture-coords"),
                    (args.texture_wrap.is_some(), "--texture-wrap"),
                ] {
                    if given {
                        return Err(format!("{name} needs a texture: scene '{}' has none; give one with --texture FILE", mesh.name));
                    }
                }
                return Ok(None);
            }
            Some(first) => {
                if named.len() > 1 {
                    eprintln!(
                        "warning: scene '{}' names {} textures (map_Kd); the chipset holds one per frame, so {} textures every triangle",
                        mesh.name,
                        named.len(),
                        first.display()
                    );
                }
                (golden::texture::load(first)?, first.display().to_string())
            }
        }
    };
    Ok(Some(Texturing {
        texture: std::sync::Arc::new(texture),
        source,
        filter: match args.texture_filter.unwrap_or(TextureFilterArg::Bilinear) {
            TextureFilterArg::Nearest => Filter::Nearest,
            TextureFilterArg::Bilinear => Filter::Bilinear,
            TextureFilterArg::Trilinear => Filter::Trilinear,
        },
        coords: match args.texture_coords.unwrap_or(TextureCoordsArg::Perspective) {
            TextureCoordsArg::Perspective => Coords::Perspective,
            TextureCoordsArg::Affine => Coords::Affine,
        },
        wrap: match args.texture_wrap.unwrap_or(TextureWrapArg::Repeat) {
            TextureWrapArg::Repeat => Wrap::Repeat,
            TextureWrapArg::Clamp => Wrap::ClampToEdge,
        },
    }))
}
