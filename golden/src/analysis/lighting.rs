//! Seed 000 §IV.B, Fig. 9: lighting operations of deferred shading (seed 000 Type II) and index
//! rendering (seed 000 Types III and IV, identical here: the visibility method does not change what is
//! lit) relative to the traditional pipeline (seed 000 Type I) = 100%; and the texture operations.
//!
//! Where each type lights (seed 000 Fig. 2 and §IV.B.4), counted from the golden frame:
//!
//! | shading | Type I | Type II | Types III/IV |
//! |---|---|---|---|
//! | Phong (per pixel) | reduced pixel rate: every fragment that passes the Z-test (`rc.z_passes`) | scan-out rate: every covered pixel once (`cs_lightings`) | scan-out rate (`cs_lightings`) |
//! | Gouraud (per vertex) | triangle rate: 3 per triangle after back-face culling (`host_type_i.lighting`) | triangle rate: the same | reduced triangle rate: 3 per triangle the RC flagged visible (`host.lighting`) |
//! | flat (per triangle) | 1 per triangle after culling | the same | 1 per flagged triangle |
//!
//! All per light source. Type I's triangle rate is taken after back-face culling because the paper
//! back-face culled its models before simulating (§IV.A.2). Index rendering lights what the RC flags
//! at draw time (some fragment passed the Z-test *when drawn*), which includes triangles later hidden:
//! the "ideal" column lights only triangles visible in the final image, (c), for comparison.
//!
//! Texture operations (§IV.B.5) sit where Phong lighting sits: per Z-passing fragment in Type I
//! (reduced pixel rate), per covered pixel at scan-out in Types II-IV; so their percentages equal
//! Fig. 9(a)'s. Reported with the pixel rate (all fragments) and the full scan-out rate (every pixel).

use super::measure::Measured;
use crate::shade::Shading;

/// Lighting operations of one frame in seed 000's types.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct LightingOps {
    pub shading: Shading,
    pub type_i: u64,
    pub type_ii: u64,
    pub type_iii_iv: u64,
    /// Index rendering if only triangles visible in the final image were lit (polygon-level shading);
    /// the same as `type_iii_iv` for Phong.
    pub ideal_iii_iv: u64,
    /// Percent of Type I.
    pub type_ii_percent: f64,
    pub type_iii_iv_percent: f64,
    pub ideal_percent: f64,
}

fn pct(x: u64, of: u64) -> f64 {
    super::cpu::percent(x, of)
}

/// Fig. 9 for one measured frame and one shading method.
pub fn fig9(m: &Measured, shading: Shading) -> LightingOps {
    let s = m.shading(shading);
    let (type_i, type_ii, type_iii_iv, ideal) = match shading {
        Shading::Phong => {
            let i = m.rc.z_passes * m.lights;
            (i, s.cs_lightings, s.cs_lightings, s.cs_lightings)
        }
        Shading::Gouraud | Shading::Flat => {
            let per_tri = if shading == Shading::Flat { 1 } else { 3 } * m.lights;
            (s.host_type_i.lighting, s.host_type_i.lighting, s.host.lighting, m.c * per_tri)
        }
    };
    LightingOps {
        shading,
        type_i,
        type_ii,
        type_iii_iv,
        ideal_iii_iv: ideal,
        type_ii_percent: pct(type_ii, type_i),
        type_iii_iv_percent: pct(type_iii_iv, type_i),
        ideal_percent: pct(ideal, type_i),
    }
}

/// Texture operations of one frame (per texture fetch mode; multiply by fetches per pixel).
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct TextureOps {
    /// Pixel rate: every fragment (texturing before the Z-test).
    pub pixel_rate: u64,
    /// Reduced pixel rate: fragments passing the Z-test (seed 000 Type I, Fig. 2(a)).
    pub reduced_pixel_rate: u64,
    /// Covered pixels at scan-out (Types II-IV).
    pub scan_out_covered: u64,
    /// Every pixel of the screen: the full scan-out rate.
    pub scan_out_all: u64,
    /// Types II-IV in percent of Type I.
    pub percent: f64,
}

pub fn texture(m: &Measured) -> TextureOps {
    TextureOps {
        pixel_rate: m.rc.fragments,
        reduced_pixel_rate: m.rc.z_passes,
        scan_out_covered: m.covered_pixels,
        scan_out_all: m.pixels(),
        percent: pct(m.covered_pixels, m.rc.z_passes),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::host::HostOps;
    use crate::raster::RcCounts;
    use crate::analysis::measure::ShadingCounts;

    fn measured() -> Measured {
        let sc = |lit: u64, lit_i: u64, cs: u64| ShadingCounts {
            host: HostOps { lighting: lit, ..Default::default() },
            host_type_i: HostOps { lighting: lit_i, ..Default::default() },
            host_type_ii: HostOps::default(),
            cs_lightings: cs,
        };
        Measured {
            scene: "t".into(),
            width: 10,
            height: 10,
            lights: 1,
            a: 100,
            b: 50,
            flagged: 30,
            c: 20,
            sent_to_rc: 100,
            set_up: 50,
            rc: RcCounts { fragments: 400, z_passes: 200, ..Default::default() },
            covered_pixels: 80,
            tdbs_writes: 30,
            tdbv_reads: 300,
            tdbs_fetches_cached: 20,
            flat: sc(30, 50, 0),
            gouraud: sc(90, 150, 0),
            phong: sc(0, 0, 80),
        }
    }

    #[test]
    fn polygon_level_lighting_drops_to_the_flagged_triangles_only_with_index_rendering() {
        let g = fig9(&measured(), Shading::Gouraud);
        assert_eq!((g.type_i, g.type_ii, g.type_iii_iv, g.ideal_iii_iv), (150, 150, 90, 60));
        assert_eq!((g.type_ii_percent, g.type_iii_iv_percent), (100.0, 60.0));
        let f = fig9(&measured(), Shading::Flat);
        assert_eq!(f.type_iii_iv_percent, g.type_iii_iv_percent);
    }

    #[test]
    fn phong_lighting_moves_from_z_passes_to_covered_pixels() {
        let p = fig9(&measured(), Shading::Phong);
        assert_eq!((p.type_i, p.type_ii, p.type_iii_iv), (200, 80, 80));
        assert_eq!(p.type_iii_iv_percent, 40.0);
        assert_eq!(texture(&measured()).percent, 40.0);
    }
}
