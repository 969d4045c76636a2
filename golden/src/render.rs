//! A whole frame through seed 001's dual pipeline (Fig. 7b), with the chipset behind a trait so that
//! the same host program drives the algorithmic model here and the RTL in `tb/`.
//!
//! 1. Upper pipeline (host): transform, clip and map every triangle; send them to the RC.
//! 2. RC: frame start, then per triangle cull / rasterize / Z-test; a visibility flag comes back.
//! 3. Lower pipeline (host), enhanced deferred lighting: only for source triangles with a visible
//!    piece, transform the normals and light the vertices (Phong: normals only).
//! 4. Colour setup (chipset): planes into TdbS at the triangle's index.
//! 5. CS: scan the I-buffer out, evaluate, produce RGB888; with a texture, sample it at the pixel's
//!    texture coordinate (from three more planes in TdbS) and MODULATE the colour by it (issue 17:
//!    golden model only so far).

use crate::format::{max_index, Screen, WinVertex, INDEX_BACKGROUND};
use crate::host::{eye_normals, normalize, to_rgb8, upper_pipeline, Camera, ClipStats, Geometry, HostOps, Lighting, Ops};
use crate::raster::{Culled, CullMode, FrontFace, RcCounts, RcType, Rasterizer, TriResult};
use crate::scene::Mesh;
use crate::shade::{colour_setup, flat_setup, normal_q14, PhongLights, Shading, TdbsEntry};
use crate::texcoord::{Coords, TexPlanes};
use crate::texture::{modulate, Filter, Texture, Wrap};
use std::sync::Arc;

/// Texture mapping for a frame (issue 17): one texture, bound for the whole frame as OpenGL's
/// GL_TEXTURE_2D state is, applied to every triangle (a triangle without texture coordinates has
/// (0, 0) at its corners, as OpenGL's current texture coordinate defaults).
#[derive(Clone, Debug, serde::Serialize)]
pub struct Texturing {
    #[serde(skip)]
    pub texture: Arc<Texture>,
    /// Where the texture came from (a file, or `built-in checker`), for reports.
    pub source: String,
    pub filter: Filter,
    pub coords: Coords,
    pub wrap: Wrap,
}

/// A triangle command for the RC: its hardware index (1..) and window vertices.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct RcCommand {
    pub index: u32,
    pub v: [WinVertex; 3],
}

/// A colour-setup command: the triangle's index and vertices (as sent to the RC) and its three vertex
/// values; `flat` carries the one colour of a flat-shaded triangle instead.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SetupCommand {
    pub index: u32,
    pub v: [WinVertex; 3],
    pub values: [[i64; 3]; 3],
    pub material: u16,
    pub flat: Option<[u8; 3]>,
    /// The texture planes' vertex values (s/w, t/w, 1/w; [`crate::texcoord::vertex_values`]) when
    /// the frame is textured.
    pub tex: Option<[[i64; 3]; 3]>,
}

/// What the CS produced: RGB888 in raster order, and the I-buffer it read (hardware indices).
#[derive(Clone, Debug, PartialEq)]
pub struct ScanOut {
    pub rgb: Vec<u8>,
    pub ibuf: Vec<u32>,
    pub zbuf: Vec<u32>,
}

/// One frame as the host hands it to the chipset: the RC's commands and what its scan-out needs.
#[derive(Clone, Debug)]
pub struct FrameJob {
    pub tris: Vec<RcCommand>,
    pub cull: CullMode,
    pub front: FrontFace,
    pub shading: Shading,
    pub lights: PhongLights,
    pub background: [u8; 3],
    pub texturing: Option<Texturing>,
}

/// The host's lower pipeline (enhanced deferred lighting) as the chipset sees it: asked for a
/// triangle's colour-setup command as soon as the RC reports the triangle visible.
pub trait LowerPipeline {
    /// Triangle `position` (0-based, in command order) of frame `frame` was reported visible: light it
    /// (if its source triangle is not lit yet) and return its colour-setup command.
    fn visible(&mut self, frame: usize, position: usize) -> Result<SetupCommand, String>;
}

/// What the chipset returns for one frame.
#[derive(Clone, Debug)]
pub struct FrameOut {
    /// One result per triangle, in command order.
    pub results: Vec<TriResult>,
    pub scan: ScanOut,
    /// The RC's fragment counters, if the chipset keeps them.
    pub rc_counts: Option<RcCounts>,
    /// The CS's texture counters, if the frame was textured and the chipset keeps them.
    pub texture_counts: Option<TextureCounts>,
}

/// What the CS's texture path did in a frame.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct TextureCounts {
    /// Pixels textured (one sample each).
    pub samples: u64,
    /// Texels the filters combined (1 nearest, 4 bilinear, 4 or 8 trilinear per sample).
    pub texels_read: u64,
    /// Words read from the four texture banks (`texbank::footprint`): a texel that clamping or a
    /// one-texel level puts in a footprint twice is one read.
    pub bank_words: u64,
}

/// The chipset as the host sees it. Implemented by [`GoldenChipset`] (the algorithmic model) and, in
/// `tb/`, by the RTL simulations, which overlap the frames as the hardware does (seed 001's two
/// pipelines in parallel, and the scan-out of one frame beside the drawing of the next).
pub trait Chipset {
    /// Draw and scan out `frames` in order. Every triangle the RC reports visible is handed to
    /// `host.visible` at once and its colour-setup command sent to colour setup.
    fn run(&mut self, frames: &[FrameJob], host: &mut dyn LowerPipeline) -> Result<Vec<FrameOut>, String>;
}

/// The algorithmic model of the chipset: one frame after the other, colour setup of a triangle right
/// after its visibility result.
pub struct GoldenChipset {
    pub rc: Rasterizer,
    pub tdbs: Vec<TdbsEntry>,
    /// The texture planes of each index (TdbS's texture part), when the frame is textured.
    pub tdbt: Vec<Option<TexPlanes>>,
    /// The colour-setup commands of the last run, in the order they were sent.
    pub setups: Vec<SetupCommand>,
}

impl GoldenChipset {
    /// The Type IV chipset (Z-buffer).
    pub fn new(screen: Screen) -> GoldenChipset {
        GoldenChipset::of_type(screen, RcType::IV)
    }

    pub fn of_type(screen: Screen, ty: RcType) -> GoldenChipset {
        GoldenChipset { rc: Rasterizer::of_type(screen, ty), tdbs: Vec::new(), tdbt: Vec::new(), setups: Vec::new() }
    }

    fn colour_setup(&mut self, c: &SetupCommand) {
        if self.tdbs.len() <= c.index as usize {
            self.tdbs.resize(c.index as usize + 1, TdbsEntry::default());
            self.tdbt.resize(c.index as usize + 1, None);
        }
        self.tdbt[c.index as usize] = c.tex.map(|values| crate::texcoord::setup(&c.v, values));
        self.tdbs[c.index as usize] = match c.flat {
            Some(rgb) => flat_setup(rgb),
            None => colour_setup(&c.v, c.values, c.material),
        };
        self.setups.push(*c);
    }

    /// The frame's pixels, and with a texture what texturing did.
    fn scanout(&self, shading: Shading, lights: &PhongLights, background: [u8; 3], texturing: Option<&Texturing>) -> (ScanOut, Option<TextureCounts>) {
        let s = self.rc.screen;
        let mut counts = TextureCounts::default();
        let geoms = texturing.map(|tx| crate::texbank::layout(&tx.texture)).unwrap_or_default();
        let mut rgb = Vec::with_capacity(s.pixels() * 3);
        for y in 0..s.height {
            for x in 0..s.width {
                let i = self.rc.ibuf[(y * s.width + x) as usize];
                let px = if i == INDEX_BACKGROUND {
                    background
                } else {
                    let e = &self.tdbs[i as usize];
                    let colour = match shading {
                        Shading::Phong => lights.shade([0, 1, 2].map(|k| e.planes[k].eval(x, y)), e.material),
                        _ => [0, 1, 2].map(|k| e.planes[k].eval_clamped(x, y, 255) as u8),
                    };
                    match (texturing, self.tdbt[i as usize]) {
                        (Some(tx), Some(planes)) => {
                            let l0 = &tx.texture.levels[0];
                            let c = planes.eval(x, y, l0.w_log2, l0.h_log2);
                            counts.texels_read += tx.texture.texels_read(c.lod, tx.filter) as u64;
                            counts.bank_words += bank_words(&geoms, c, tx) as u64;
                            counts.samples += 1;
                            modulate(tx.texture.sample(c.s, c.t, c.lod, tx.filter, tx.wrap), colour)
                        }
                        _ => colour,
                    }
                };
                rgb.extend_from_slice(&px);
            }
        }
        (ScanOut { rgb, ibuf: self.rc.ibuf.clone(), zbuf: self.rc.depths() }, texturing.map(|_| counts))
    }
}

/// Words one sample reads from the texture banks: the footprint in each level it reads
/// ([`crate::texture::Texture::levels_for`]).
fn bank_words(geoms: &[crate::texbank::LevelGeom], c: crate::texcoord::TexCoord, tx: &Texturing) -> u32 {
    let (level, second) = tx.texture.levels_for(c.lod, tx.filter);
    let bilinear = tx.filter != crate::texture::Filter::Nearest;
    let at = |l: usize| crate::texbank::footprint(geoms[l], c.s, c.t, bilinear, tx.wrap).reads();
    at(level) + second.map_or(0, |(next, _)| at(next))
}

impl Chipset for GoldenChipset {
    fn run(&mut self, frames: &[FrameJob], host: &mut dyn LowerPipeline) -> Result<Vec<FrameOut>, String> {
        self.setups.clear();
        let mut out = Vec::with_capacity(frames.len());
        for (f, job) in frames.iter().enumerate() {
            self.rc.clear();
            let mut results = Vec::with_capacity(job.tris.len());
            for (p, t) in job.tris.iter().enumerate() {
                let r = self.rc.draw(t.index, &t.v, job.cull, job.front);
                if r.visible {
                    let c = host.visible(f, p)?;
                    self.colour_setup(&c);
                }
                results.push(r);
            }
            let (scan, texture_counts) = self.scanout(job.shading, &job.lights, job.background, job.texturing.as_ref());
            out.push(FrameOut { results, scan, rc_counts: Some(self.rc.counts), texture_counts });
        }
        Ok(out)
    }
}

/// Everything that decides a frame.
#[derive(Clone, Debug, serde::Serialize)]
pub struct RenderOptions {
    pub screen: Screen,
    pub camera: Camera,
    pub shading: Shading,
    pub cull: CullMode,
    pub front: FrontFace,
    pub lighting: Lighting,
    pub index_bits: u32,
    pub background: [u8; 3],
    /// Seed 000's Type IV (Z-buffer, the default) or Type III (depth regenerated from TdbV).
    pub rc_type: RcType,
    /// Texture mapping (issue 17), off by default.
    pub texturing: Option<Texturing>,
}

/// The background colour of every frame (index 0 in the I-buffer).
pub const BACKGROUND: [u8; 3] = [24, 24, 40];

impl RenderOptions {
    /// What `idxrender render --scene S --size WxH --shading X` uses when nothing else is given: the
    /// default view of the mesh, back faces culled, the mesh's own front face, the default lights, the
    /// default index width and [`BACKGROUND`]. The CLI, the figure programs and the frame tests all
    /// start here, so they render the same frame.
    pub fn for_scene(mesh: &crate::scene::Mesh, screen: Screen, shading: Shading) -> RenderOptions {
        RenderOptions {
            screen,
            camera: Camera::default_view(mesh, screen),
            shading,
            cull: CullMode::Back,
            front: match mesh.front_face {
                crate::scene::Winding::Ccw => FrontFace::Ccw,
                crate::scene::Winding::Cw => FrontFace::Cw,
            },
            lighting: Lighting::default(),
            index_bits: crate::format::INDEX_BITS_DEFAULT,
            background: BACKGROUND,
            rc_type: RcType::IV,
            texturing: None,
        }
    }
}

/// Per-frame statistics (issue 2 §6); source-triangle counts are seed 001 Table 1's (a), (b), (c).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct FrameStats {
    /// (a) triangles in the scene.
    pub triangles_in: u64,
    /// Source triangles wholly outside the view volume (never sent to the RC).
    pub clipped_away: u64,
    /// Source triangles split by clipping.
    pub split_by_clipping: u64,
    /// Triangles sent to the RC (clipping can make more than one per source triangle).
    pub sent_to_rc: u64,
    /// Source triangles of zero area on the screen.
    pub zero_area: u64,
    /// (b) source triangles that passed back-face culling (and have an area).
    pub after_culling: u64,
    /// Source triangles with some fragment that passed the Z-test when drawn: what the host lights.
    pub flagged_visible: u64,
    /// (c) source triangles that own at least one pixel of the final image.
    pub visible_final: u64,
    /// RC counters (hardware triangles).
    pub rc: RcCounts,
    /// Screen pixels covered by some triangle in the final image.
    pub covered_pixels: u64,
    /// Fragments per covered pixel (depth complexity).
    pub depth_complexity: f64,
    /// Z-test passes per covered pixel (writes per final pixel).
    pub overdraw: f64,
    /// TdbS records written by colour setup.
    pub tdbs_writes: u64,
    /// Per-pixel lighting operations in the CS (Phong only).
    pub cs_lightings: u64,
    /// Host operations with enhanced deferred lighting (this pipeline).
    pub host: HostOps,
    pub host_ops: Ops,
    /// The same frame in seed 001's Type I (cull before lighting): all normals transformed, (b) lit.
    pub host_type_i: HostOps,
    /// Type II (lighting before culling): all normals transformed, all (a) lit.
    pub host_type_ii: HostOps,
    pub clip: ClipStats,
    /// Texture mapping's counts, when the frame is textured.
    pub texture: Option<TextureStats>,
}

/// What texturing a frame cost, deferred (the CS textures each covered pixel once, seed 000 §III)
/// against a traditional pipeline that textures every fragment it writes.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct TextureStats {
    /// Pixels the CS textured: one texture sample each (every covered pixel).
    pub samples: u64,
    /// Texels the CS read (1 per sample nearest, 4 bilinear, 4 or 8 trilinear).
    pub texels_read: u64,
    pub texels_per_sample: f64,
    /// Words read from the four texture banks (the traffic at the texture port): fewer than the
    /// texels where a clamped edge or a one-texel level repeats a texel in a footprint.
    pub bank_words_read: u64,
    pub bank_words_per_sample: f64,
    /// Samples a traditional pipeline takes: one per fragment that passes an early Z-test (the RC's
    /// Z passes), and one per fragment when texturing comes before the Z-test.
    pub traditional_samples_early_z: u64,
    pub traditional_samples: u64,
    /// Deferred samples as a percentage of the traditional pipeline's with early Z.
    pub percent_of_early_z: f64,
    /// Visible triangles whose texture values the host scaled down to keep the planes in range
    /// (`texcoord::fit`: slivers, coordinates less precise).
    pub scaled_triangles: u64,
}

/// A rendered frame.
#[derive(Clone, Debug)]
pub struct Frame {
    pub screen: Screen,
    pub rgb: Vec<u8>,
    /// The I-buffer as source triangle numbers: 0 background, else input position + 1.
    pub index: Vec<u32>,
    /// The I-buffer as the hardware holds it.
    pub hw_index: Vec<u32>,
    pub zbuf: Vec<u32>,
    pub results: Vec<TriResult>,
    pub stats: FrameStats,
}

/// The host program's state for one frame: geometry done by the upper pipeline, lighting deferred
/// until the chipset reports a triangle visible.
struct HostFrame<'a> {
    mesh: &'a Mesh,
    opts: &'a RenderOptions,
    geo: Geometry,
    cmds: Vec<RcCommand>,
    host: HostOps,
    lit: Vec<Option<[[i64; 3]; 3]>>,
    flat_rgb: Vec<Option<[u8; 3]>>,
    /// Colour-setup commands handed out.
    setups: u64,
    /// Of those, the ones whose texture values `texcoord::fit` scaled down.
    tex_scaled: u64,
}

impl<'a> HostFrame<'a> {
    fn new(mesh: &'a Mesh, opts: &'a RenderOptions) -> Result<HostFrame<'a>, String> {
        mesh.validate()?;
        opts.camera.validate()?;
        if !(1..=31).contains(&opts.index_bits) {
            return Err(format!("index width {} bits is not supported (1..=31)", opts.index_bits));
        }
        let geo = upper_pipeline(mesh, &opts.camera, opts.screen);
        let limit = max_index(opts.index_bits) as usize;
        if geo.hw.len() > limit {
            return Err(format!(
                "{} triangles to draw after clipping, but a {}-bit triangle index allows only {} (0 is background): \
                 use a wider --index-bits or a smaller scene",
                geo.hw.len(),
                opts.index_bits,
                limit
            ));
        }
        if opts.texturing.is_some() && mesh.triangle_texcoords.is_empty() {
            return Err(format!("scene '{}' has no texture coordinates (OBJ `vt`), so it cannot be textured", mesh.name));
        }
        let cmds: Vec<RcCommand> = geo.hw.iter().enumerate().map(|(i, t)| RcCommand { index: i as u32 + 1, v: t.v }).collect();
        let n = mesh.triangles.len();
        let host = geo.ops;
        Ok(HostFrame { mesh, opts, geo, cmds, host, lit: vec![None; n], flat_rgb: vec![None; n], setups: 0, tex_scaled: 0 })
    }

    fn job(&self) -> FrameJob {
        FrameJob {
            tris: self.cmds.clone(),
            cull: self.opts.cull,
            front: self.opts.front,
            shading: self.opts.shading,
            lights: PhongLights::new(&self.opts.lighting, &self.mesh.materials),
            background: self.opts.background,
            texturing: self.opts.texturing.clone(),
        }
    }

    /// Lower pipeline for the piece at `position`: light its source triangle once (Phong: normals
    /// only), then the piece's colour-setup command.
    fn visible(&mut self, position: usize) -> Result<SetupCommand, String> {
        let t = self.geo.hw.get(position).ok_or_else(|| format!("the chipset reported triangle {position} visible, but only {} were sent", self.geo.hw.len()))?;
        let s = t.source as usize;
        let (mesh, opts) = (self.mesh, self.opts);
        let tri = &mesh.triangles[s];
        let m = &mesh.materials[tri.material as usize];
        if self.lit[s].is_none() && self.flat_rgb[s].is_none() {
            let nlights = opts.lighting.lights.len() as u64;
            self.host.view_normals += 3;
            let en = eye_normals(mesh, &opts.camera, tri);
            match opts.shading {
                Shading::Flat => {
                    self.host.lighting += nlights;
                    let fn_ = normalize([0, 1, 2].map(|k| en[0][k] + en[1][k] + en[2][k]));
                    self.flat_rgb[s] = Some(to_rgb8(opts.lighting.shade(m, fn_)));
                }
                Shading::Gouraud => {
                    self.host.lighting += 3 * nlights;
                    self.lit[s] = Some(en.map(|nv| to_rgb8(opts.lighting.shade(m, nv)).map(|c| c as i64)));
                }
                Shading::Phong => self.lit[s] = Some(en.map(normal_q14)),
            }
        }
        let (values, flat) = match (self.lit[s], self.flat_rgb[s]) {
            (_, Some(rgb)) => ([[0; 3]; 3], Some(rgb)),
            (Some(vals), None) => {
                // A clipped piece's vertex values are its barycentric mix of the source vertices'.
                let mix = |b: [f64; 3]| [0, 1, 2].map(|c| (b[0] * vals[0][c] as f64 + b[1] * vals[1][c] as f64 + b[2] * vals[2][c] as f64).round() as i64);
                (t.bary.map(mix), None)
            }
            (None, None) => unreachable!("lit above"),
        };
        // Texture coordinates: a clipped piece's are its barycentric mix of the source corners' (linear
        // in clip space), with the piece's own clip w.
        let tex = match &opts.texturing {
            None => None,
            Some(tx) => {
                let st = mesh.triangle_texcoords[s].map(|k| mesh.texcoords[k as usize]);
                let mix = |b: [f64; 3]| [0, 1].map(|c| b[0] * st[0][c] + b[1] * st[1][c] + b[2] * st[2][c]);
                let values = crate::texcoord::vertex_values(t.w, t.bary.map(mix), tx.coords)
                    .map_err(|e| format!("scene '{}', triangle {}: {e}", mesh.name, s + 1))?;
                let (values, k) = crate::texcoord::fit(&t.v, values);
                self.tex_scaled += (k > 0) as u64;
                Some(values)
            }
        };
        self.setups += 1;
        Ok(SetupCommand { index: position as u32 + 1, v: t.v, values, material: tri.material as u16, flat, tex })
    }

    /// The frame and its statistics from what the chipset returned.
    fn finish(self, out: FrameOut) -> Result<Frame, String> {
        let (mesh, opts, geo) = (self.mesh, self.opts, &self.geo);
        let FrameOut { results, scan: out, rc_counts, texture_counts } = out;
        if results.len() != self.cmds.len() {
            return Err(format!("chipset returned {} results for {} triangles", results.len(), self.cmds.len()));
        }
        let visible = results.iter().filter(|r| r.visible).count() as u64;
        if visible != self.setups {
            return Err(format!("the chipset reported {visible} triangles visible but asked the host for {} colour-setup commands", self.setups));
        }
        // Source-level bookkeeping.
        let n = mesh.triangles.len();
        let mut any_sent = vec![false; n];
        let mut passed_cull = vec![false; n];
        let mut all_zero = vec![true; n];
        let mut flagged = vec![false; n];
        for (t, r) in geo.hw.iter().zip(&results) {
            let s = t.source as usize;
            any_sent[s] = true;
            if r.culled != Some(Culled::ZeroArea) {
                all_zero[s] = false;
            }
            if r.culled.is_none() {
                passed_cull[s] = true;
            }
            flagged[s] |= r.visible;
        }
        let nlights = opts.lighting.lights.len() as u64;

        // Final-image statistics.
        // A chipset is checked, not trusted: an index it never received is an error, not a panic.
        if out.ibuf.len() != opts.screen.pixels() || out.rgb.len() != 3 * opts.screen.pixels() {
            return Err(format!("the chipset returned {} I-buffer words and {} colour bytes for {} pixels", out.ibuf.len(), out.rgb.len(), opts.screen.pixels()));
        }
        if let Some(p) = out.ibuf.iter().position(|&h| h as usize > geo.hw.len()) {
            let w = opts.screen.width as usize;
            return Err(format!(
                "the chipset's I-buffer holds index {} at pixel ({}, {}), but only {} triangles were sent",
                out.ibuf[p], p % w, p / w, geo.hw.len()
            ));
        }
        let index: Vec<u32> = out.ibuf.iter().map(|&h| if h == INDEX_BACKGROUND { 0 } else { geo.hw[h as usize - 1].source + 1 }).collect();
        let mut in_final = vec![false; n];
        let mut covered = 0u64;
        for &i in &index {
            if i != 0 {
                in_final[i as usize - 1] = true;
                covered += 1;
            }
        }
        let count = |v: &[bool]| v.iter().filter(|&&b| b).count() as u64;
        let a = n as u64;
        let b = count(&passed_cull);
        let zero_area = (0..n).filter(|&s| any_sent[s] && all_zero[s]).count() as u64;
        // Fragment counters: from the chipset if it keeps them, else from the algorithmic RC (the same
        // numbers for any chipset that produced the same I-buffer, which is checked).
        let rc = match rc_counts {
            Some(c) => c,
            None => {
                let mut model = Rasterizer::of_type(opts.screen, opts.rc_type);
                for c in &self.cmds {
                    model.draw(c.index, &c.v, opts.cull, opts.front);
                }
                if model.ibuf != out.ibuf {
                    return Err("the chipset's I-buffer differs from the algorithmic model's".into());
                }
                model.counts
            }
        };
        let per = |x: u64| if covered == 0 { 0.0 } else { x as f64 / covered as f64 };
        let geometry = HostOps { view_vertices: 3 * a, perspective: 3 * a, ..Default::default() };
        let lights_per_tri = if opts.shading == Shading::Flat { nlights } else { 3 * nlights };
        let (lit_b, lit_a) = if opts.shading == Shading::Phong { (0, 0) } else { (b * lights_per_tri, a * lights_per_tri) };
        let host = self.host;
        let stats = FrameStats {
            triangles_in: a,
            clipped_away: geo.clip.clipped_away,
            split_by_clipping: geo.clip.split,
            sent_to_rc: geo.clip.sent,
            zero_area,
            after_culling: b,
            flagged_visible: count(&flagged),
            visible_final: count(&in_final),
            rc,
            covered_pixels: covered,
            depth_complexity: per(rc.fragments),
            overdraw: per(rc.z_passes),
            tdbs_writes: self.setups,
            cs_lightings: if opts.shading == Shading::Phong { covered * nlights } else { 0 },
            host,
            host_ops: host.ops(),
            host_type_i: HostOps { view_normals: 3 * a, lighting: lit_b, ..geometry },
            host_type_ii: HostOps { view_normals: 3 * a, lighting: lit_a, ..geometry },
            clip: geo.clip,
            texture: match (&opts.texturing, texture_counts) {
                (None, _) => None,
                (Some(_), None) => return Err("the chipset did not report its texture counters for a textured frame".into()),
                (Some(_), Some(TextureCounts { samples, texels_read, bank_words })) => Some(TextureStats {
                    samples,
                    texels_read,
                    texels_per_sample: if samples == 0 { 0.0 } else { texels_read as f64 / samples as f64 },
                    bank_words_read: bank_words,
                    bank_words_per_sample: if samples == 0 { 0.0 } else { bank_words as f64 / samples as f64 },
                    traditional_samples_early_z: rc.z_passes,
                    traditional_samples: rc.fragments,
                    percent_of_early_z: if rc.z_passes == 0 { 0.0 } else { 100.0 * samples as f64 / rc.z_passes as f64 },
                    scaled_triangles: self.tex_scaled,
                }),
            },
        };
        Ok(Frame { screen: opts.screen, rgb: out.rgb, index, hw_index: out.ibuf, zbuf: out.zbuf, results, stats })
    }
}

/// The host program of several frames, answering the chipset's visibility reports frame by frame.
struct Host<'a> {
    frames: Vec<HostFrame<'a>>,
}

impl LowerPipeline for Host<'_> {
    fn visible(&mut self, frame: usize, position: usize) -> Result<SetupCommand, String> {
        let n = self.frames.len();
        self.frames.get_mut(frame).ok_or_else(|| format!("the chipset reported a triangle of frame {frame}, but {n} frames were sent"))?.visible(position)
    }
}

/// Render `frames` (mesh and options each) through `chip` in one run: back to back where the chipset
/// overlaps frames. Every frame must have the chipset's screen size.
pub fn render_frames_with(frames: &[(&Mesh, &RenderOptions)], chip: &mut dyn Chipset) -> Result<Vec<Frame>, String> {
    if frames.is_empty() {
        return Err("no frames to render".into());
    }
    let host_frames = frames.iter().map(|(m, o)| HostFrame::new(m, o)).collect::<Result<Vec<_>, _>>()?;
    let jobs: Vec<FrameJob> = host_frames.iter().map(|h| h.job()).collect();
    let mut host = Host { frames: host_frames };
    let outs = chip.run(&jobs, &mut host)?;
    if outs.len() != jobs.len() {
        return Err(format!("the chipset returned {} frames for {}", outs.len(), jobs.len()));
    }
    host.frames.into_iter().zip(outs).map(|(h, o)| h.finish(o)).collect()
}

/// Render one frame of `mesh` through `chip`.
pub fn render_with(mesh: &Mesh, opts: &RenderOptions, chip: &mut dyn Chipset) -> Result<Frame, String> {
    Ok(render_frames_with(&[(mesh, opts)], chip)?.remove(0))
}

/// Render one frame through the algorithmic model.
pub fn render(mesh: &Mesh, opts: &RenderOptions) -> Result<Frame, String> {
    let mut chip = GoldenChipset::of_type(opts.screen, opts.rc_type);
    render_with(mesh, opts, &mut chip)
}
