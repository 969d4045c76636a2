//! Real frames for the CS benches: a built-in scene rendered by the golden pipeline
//! (`golden::render::render_with`) through a recording `Chipset`, which keeps the colour-setup commands
//! the host sent, the TdbS the golden chipset built from them, and the hardware I-buffer.

use golden::cycle::color_shader::CsMemories;
use golden::format::Screen;
use golden::host::Camera;
use golden::raster::{CullMode, FrontFace};
use golden::render::{render_with, Frame, GoldenChipset, RenderOptions, Texturing};
use golden::scene::{builtin, Winding};
use golden::shade::{PhongLights, Shading};
use golden::texcoord::TexPlanes;

/// The golden chipset, which keeps the colour-setup commands it was sent (`setups`).
pub type Recorder = GoldenChipset;

/// A rendered frame and what the chipset saw.
pub struct RecordedFrame {
    pub frame: Frame,
    pub chip: Recorder,
    pub background: [u8; 3],
    /// The frame's Phong constants (what the host loads into the CS for a Phong scan-out).
    pub lights: PhongLights,
}

impl RecordedFrame {
    /// The memories as the CS finds them after colour setup: I-buffer (16-bit hardware indices),
    /// Z-buffer, TdbS.
    pub fn memories(&self) -> CsMemories {
        let ibuf = self.frame.hw_index.iter().map(|&i| i as u16).collect();
        CsMemories::new(ibuf, self.frame.zbuf.clone(), self.chip.tdbs.clone())
    }

    /// The same with the TdbT of a textured frame (records of untextured triangles are 0).
    pub fn textured_memories(&self) -> CsMemories {
        self.textured_memories_mapped(|t| t)
    }

    /// [`Self::textured_memories`] with every TdbT record passed through `f` first.
    pub fn textured_memories_mapped(&self, f: impl Fn(TexPlanes) -> TexPlanes) -> CsMemories {
        let tdbt = self.chip.tdbt.iter().map(|t| f(t.unwrap_or_default())).collect();
        self.memories().with_tdbt(tdbt)
    }
}

/// The textured built-in scene (teapot-floor) rendered with `texturing` at `width` x `height`.
pub fn record_textured(shading: Shading, texturing: &Texturing, width: u32, height: u32) -> Result<RecordedFrame, String> {
    let mesh = builtin::teapot_floor();
    let screen = Screen::new(width, height)?;
    let background = [24, 24, 40];
    let opts = RenderOptions { texturing: Some(texturing.clone()), background, ..RenderOptions::for_scene(&mesh, screen, shading) };
    let mut chip = GoldenChipset::new(screen);
    let frame = render_with(&mesh, &opts, &mut chip)?;
    let lights = PhongLights::new(&opts.lighting, &mesh.materials);
    Ok(RecordedFrame { frame, chip, background, lights })
}

/// Render built-in scene `name` (the teapot at grid 6 to keep benches short) at `width` x `height`.
pub fn record(name: &str, shading: Shading, width: u32, height: u32) -> Result<RecordedFrame, String> {
    let mesh = if name == "teapot" { builtin::teapot(6) } else { builtin::scene(name)? };
    let screen = Screen::new(width, height)?;
    let background = [24, 24, 40];
    let opts = RenderOptions {
        screen,
        camera: Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0),
        shading,
        cull: CullMode::Back,
        front: if mesh.front_face == Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw },
        lighting: Default::default(),
        index_bits: 16,
        rc_type: golden::raster::RcType::IV,
        texturing: None,
        background,
    };
    let mut chip = GoldenChipset::new(screen);
    let frame = render_with(&mesh, &opts, &mut chip)?;
    let lights = PhongLights::new(&opts.lighting, &mesh.materials);
    Ok(RecordedFrame { frame, chip, background, lights })
}
