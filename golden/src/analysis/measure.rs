//! The measured counts the analysis starts from: one scene at one screen size, rendered through the
//! golden model ([`crate::render::render`]) once per shading method.
//!
//! The frame statistics give (a), (b), (c), the flagged-visible triangles, the RC's fragment counters,
//! the covered pixels, the TdbS writes and the host's and CS's lighting counts. One number the
//! bandwidth of seed 000's Type III needs is not among them: how many fragments land on a pixel that
//! some triangle already owns (each fetches that triangle's depth plane from TdbV). [`tdbv_reads`]
//! counts it by drawing the frame again with the Type III RC ([`crate::raster::RcType::III`]), and
//! checks that frame against the Type IV one (same I-buffer, same counters) before it is used.

use crate::format::INDEX_BACKGROUND;
use crate::host::HostOps;
use crate::raster::{RcCounts, RcType};
use crate::render::{render, Frame, RenderOptions};
use crate::host::Camera;
use crate::scene::{Mesh, Triangle};
use crate::shade::Shading;

/// The order the host sends the triangles in. Deferred lighting lights what the RC flags visible *when
/// drawn*, so the order decides how many hidden triangles are lit: front to back, a triangle is flagged
/// only if nothing drawn before covers it.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum DrawOrder {
    /// The scene's own order.
    Scene,
    /// Sorted by the eye-space distance of the triangle's centroid, nearest first.
    FrontToBack,
    /// Farthest first (the painter's order: the worst case for deferred lighting).
    BackToFront,
}

/// `mesh` with its triangles in `order` for the camera `cam` (a stable sort; the scene order is kept
/// among equal distances).
pub fn reorder(mesh: &Mesh, cam: &Camera, order: DrawOrder) -> Mesh {
    if order == DrawOrder::Scene {
        return mesh.clone();
    }
    let v = cam.view_matrix();
    let dist = |t: &Triangle| -> f64 {
        let c = [0, 1, 2].map(|k| t.v.iter().map(|&i| mesh.positions[i as usize][k]).sum::<f64>() / 3.0);
        -(v[2][0] * c[0] + v[2][1] * c[1] + v[2][2] * c[2] + v[2][3])
    };
    let mut keyed: Vec<(f64, usize)> = mesh.triangles.iter().enumerate().map(|(i, t)| (dist(t), i)).collect();
    keyed.sort_by(|a, b| if order == DrawOrder::FrontToBack { a.0.total_cmp(&b.0) } else { b.0.total_cmp(&a.0) });
    // Texture coordinates are per triangle too, so they move with their triangles.
    let triangle_texcoords = if mesh.triangle_texcoords.is_empty() { Vec::new() } else { keyed.iter().map(|k| mesh.triangle_texcoords[k.1]).collect() };
    Mesh { triangles: keyed.iter().map(|k| mesh.triangles[k.1]).collect(), triangle_texcoords, ..mesh.clone() }
}

/// What one shading method costs in lighting, as the golden frame counted it.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ShadingCounts {
    /// The host's operations with enhanced deferred lighting (the pipeline as built).
    pub host: HostOps,
    /// The same frame with lighting before culling is skipped: seed 001 Type I (culled before lighting).
    pub host_type_i: HostOps,
    /// Seed 001 Type II: every triangle lit.
    pub host_type_ii: HostOps,
    /// Per-pixel lightings in the CS (Phong).
    pub cs_lightings: u64,
}

/// Everything measured for one scene at one screen size.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Measured {
    pub scene: String,
    pub width: u32,
    pub height: u32,
    pub lights: u64,
    /// (a) triangles in the scene.
    pub a: u64,
    /// (b) source triangles that passed back-face culling.
    pub b: u64,
    /// Source triangles with a fragment that passed the Z-test when drawn (what the host lights).
    pub flagged: u64,
    /// (c) source triangles owning a pixel of the final image.
    pub c: u64,
    /// Triangles sent to the RC (after clipping).
    pub sent_to_rc: u64,
    /// Rasterizer triangles set up (sent and not culled).
    pub set_up: u64,
    pub rc: RcCounts,
    pub covered_pixels: u64,
    /// TdbS records written (rasterizer triangles flagged visible).
    pub tdbs_writes: u64,
    /// Fragments that found a triangle already in the I-buffer.
    pub tdbv_reads: u64,
    /// TdbS records the shader fetches at scan-out with a one-record cache (a fetch whenever a covered
    /// pixel's index differs from the last one fetched, in raster order); without a cache it fetches
    /// once per covered pixel.
    pub tdbs_fetches_cached: u64,
    pub flat: ShadingCounts,
    pub gouraud: ShadingCounts,
    pub phong: ShadingCounts,
}

impl Measured {
    pub fn pixels(&self) -> u64 {
        self.width as u64 * self.height as u64
    }
    pub fn shading(&self, s: Shading) -> &ShadingCounts {
        match s {
            Shading::Flat => &self.flat,
            Shading::Gouraud => &self.gouraud,
            Shading::Phong => &self.phong,
        }
    }
}

fn shading_counts(f: &Frame) -> ShadingCounts {
    let s = &f.stats;
    ShadingCounts { host: s.host, host_type_i: s.host_type_i, host_type_ii: s.host_type_ii, cs_lightings: s.cs_lightings }
}

/// Render `mesh` with `opts` (its shading is replaced by each method in turn) and collect the counts.
/// The rasterizer's counts must not depend on the shading; that is checked.
pub fn measure(mesh: &Mesh, opts: &RenderOptions) -> Result<Measured, String> {
    let run = |sh: Shading| -> Result<Frame, String> { render(mesh, &RenderOptions { shading: sh, ..opts.clone() }) };
    let flat = run(Shading::Flat)?;
    let gouraud = run(Shading::Gouraud)?;
    let phong = run(Shading::Phong)?;
    for f in [&flat, &phong] {
        if f.stats.rc != gouraud.stats.rc || f.hw_index != gouraud.hw_index {
            return Err(format!("{}: the rasterizer's results differ between shading methods", mesh.name));
        }
    }
    let s = &gouraud.stats;
    let tdbv = tdbv_reads(mesh, opts, &gouraud)?;
    Ok(Measured {
        scene: mesh.name.clone(),
        width: opts.screen.width,
        height: opts.screen.height,
        lights: opts.lighting.lights.len() as u64,
        a: s.triangles_in,
        b: s.after_culling,
        flagged: s.flagged_visible,
        c: s.visible_final,
        sent_to_rc: s.sent_to_rc,
        set_up: s.rc.triangles - s.rc.culled_facing - s.rc.culled_zero_area,
        rc: s.rc,
        covered_pixels: s.covered_pixels,
        tdbs_writes: s.tdbs_writes,
        tdbv_reads: tdbv,
        tdbs_fetches_cached: cached_fetches(&gouraud.hw_index),
        flat: shading_counts(&flat),
        gouraud: shading_counts(&gouraud),
        phong: shading_counts(&phong),
    })
}

/// TdbS fetches in raster order with a one-record cache: background pixels fetch nothing and keep the
/// cached record.
pub fn cached_fetches(ibuf: &[u32]) -> u64 {
    let mut last = INDEX_BACKGROUND;
    let mut n = 0;
    for &i in ibuf {
        if i != INDEX_BACKGROUND && i != last {
            n += 1;
            last = i;
        }
    }
    n
}

/// The TdbV reads of seed 000's Type III, which regenerates the stored depth from the plane of the
/// triangle a pixel holds instead of reading a Z-buffer: the frame drawn again by the Type III RC
/// ([`RcType::III`]), which counts the fragments whose pixel already holds a triangle index. Its
/// I-buffer and fragment counters must reproduce the frame's, else it is an error.
pub fn tdbv_reads(mesh: &Mesh, opts: &RenderOptions, frame: &Frame) -> Result<u64, String> {
    let iii = render(mesh, &RenderOptions { rc_type: RcType::III, ..opts.clone() })?;
    let (got, want) = (&iii.stats.rc, &frame.stats.rc);
    if iii.hw_index != frame.hw_index || got.fragments != want.fragments || got.z_passes != want.z_passes {
        return Err(format!(
            "{}: the Type III frame does not reproduce the golden frame ({} fragments, {} passes vs {} and {})",
            mesh.name, got.fragments, got.z_passes, want.fragments, want.z_passes
        ));
    }
    Ok(got.traffic.tdbv_reads)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::Screen;
    use crate::host::{Camera, Lighting};
    use crate::raster::{CullMode, FrontFace};
    use crate::scene::builtin;

    fn opts(mesh: &Mesh, w: u32, h: u32) -> RenderOptions {
        RenderOptions {
            screen: Screen::new(w, h).unwrap(),
            camera: Camera::framing(mesh, [0.3, 0.45, 1.0], 40.0),
            shading: Shading::Gouraud,
            cull: CullMode::Back,
            front: FrontFace::Ccw,
            lighting: Lighting::default(),
            index_bits: 16,
            rc_type: crate::raster::RcType::IV,
            texturing: None,
            background: [0, 0, 0],
        }
    }

    #[test]
    fn counts_are_consistent_with_each_other() {
        let mesh = builtin::castle();
        let m = measure(&mesh, &opts(&mesh, 160, 100)).unwrap();
        assert!(m.c <= m.flagged && m.flagged <= m.b && m.b <= m.a, "{m:?}");
        assert!(m.covered_pixels <= m.rc.z_passes && m.rc.z_passes <= m.rc.fragments);
        assert!(m.tdbs_fetches_cached > 0 && m.tdbs_fetches_cached <= m.covered_pixels);
        // The host lights what the RC flagged: 1 per flat triangle, 3 per Gouraud triangle, none for Phong.
        assert_eq!(m.flat.host.lighting, m.flagged * m.lights);
        assert_eq!(m.gouraud.host.lighting, 3 * m.flagged * m.lights);
        assert_eq!(m.phong.host.lighting, 0);
        assert_eq!(m.phong.cs_lightings, m.covered_pixels * m.lights);
    }

    /// The replay counts per pixel; the golden RC only counts totals. They must agree: a fragment that
    /// finds no triangle in the I-buffer is the first on its pixel and passes against the cleared
    /// far value (no fragment of these scenes lies exactly on the far plane), so every covered pixel
    /// has exactly one such fragment and all others read TdbV.
    #[test]
    fn tdbv_reads_are_the_fragments_beyond_the_first_on_each_pixel() {
        for mesh in [builtin::polyhedron(), builtin::castle(), builtin::dolphins()] {
            let m = measure(&mesh, &opts(&mesh, 160, 100)).unwrap();
            assert!(m.tdbv_reads > 0, "{}", mesh.name);
            assert_eq!(m.tdbv_reads, m.rc.fragments - m.covered_pixels, "{}", mesh.name);
        }
    }

    /// Front to back, a triangle is flagged only if no nearer one was drawn over it first: the flagged
    /// count drops towards (c), and back to front it rises towards (b). (a), (b), (c) and the image
    /// coverage do not depend on the order.
    #[test]
    fn front_to_back_order_lights_fewer_hidden_triangles() {
        let mesh = builtin::castle();
        let o = opts(&mesh, 320, 200);
        let m = |order| measure(&reorder(&mesh, &o.camera, order), &o).unwrap();
        let (f2b, scene, b2f) = (m(DrawOrder::FrontToBack), m(DrawOrder::Scene), m(DrawOrder::BackToFront));
        assert!(f2b.flagged < scene.flagged && scene.flagged <= b2f.flagged, "{} {} {}", f2b.flagged, scene.flagged, b2f.flagged);
        assert!(f2b.c <= f2b.flagged && b2f.flagged <= b2f.b);
        assert_eq!((f2b.a, f2b.b, f2b.covered_pixels), (scene.a, scene.b, scene.covered_pixels));
        assert!(f2b.rc.z_passes < b2f.rc.z_passes);
        let sorted = reorder(&mesh, &o.camera, DrawOrder::FrontToBack);
        let mut a = sorted.triangles.clone();
        let mut b = mesh.triangles.clone();
        a.sort_by_key(|t| (t.v, t.n, t.material));
        b.sort_by_key(|t| (t.v, t.n, t.material));
        assert_eq!(a, b, "reordering keeps every triangle");
    }

    #[test]
    fn the_cache_refetches_only_when_the_index_changes() {
        assert_eq!(cached_fetches(&[0, 3, 3, 0, 3, 4, 4, 3, 0]), 3);
        assert_eq!(cached_fetches(&[0, 0]), 0);
    }

    #[test]
    fn a_replay_of_another_frame_is_rejected() {
        let mesh = builtin::castle();
        let o = opts(&mesh, 64, 40);
        let mut f = render(&mesh, &o).unwrap();
        f.hw_index[0] ^= 1;
        assert!(tdbv_reads(&mesh, &o, &f).unwrap_err().contains("does not reproduce"));
    }
}
