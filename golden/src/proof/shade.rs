//! The shading stage (seed 002 §5): a pipeline of light-source processors per list entry.
//!
//! Every light-source processor computes `I(i+1) = M (N . B)^m + I(i)` (seed 002 §5.2.2): the ambient
//! processor starts the sum (`M` = Ka Ia, no dot product), then for each light a diffuse processor
//! (`M` = Kd Il, `B` = L, m = 1) and a specular processor (`M` = Ks Il, `B` = H, m = the gloss, a power of
//! two, by repeated squaring). Directional lights and a viewer at infinity make L and H constants
//! (§5.2.2). The normal is the OP's interpolated normal, *not normalised*: the paper's hypothesis
//! (§5.2.2 and its appendix) that normalisation can be omitted.
//!
//! Fixed point as [`PhongLights`] (the project's CS): N, L, H in Q1.14; `M` per channel as colour x 255
//! with 8 fraction bits; dot products rounded to Q1.14 and clamped to [0, 1]; the specular term only
//! where N . L > 0; the sum rounded by 22 bits and clamped to 0..=255.

use crate::shade::PhongLights;

pub use crate::shade::{dot_q14, power_q14, rgb_of_intensity, ONE_Q14};

/// The unrounded intensity sum of the light-source pipeline for one entry, per channel, with
/// 14 + 8 fraction bits: the project's one light sum ([`PhongLights::intensity`]) on the OP's normal.
pub fn intensity(lights: &PhongLights, n: [i16; 3], material: u16) -> [i64; 3] {
    lights.intensity(n.map(|c| c as i64), material)
}

/// The colour of one list entry.
pub fn shade_entry(lights: &PhongLights, n: [i16; 3], material: u16) -> [u8; 3] {
    rgb_of_intensity(intensity(lights, n, material))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::host::{normalize, Lighting};
    use crate::scene::Material;
    use crate::shade::normal_q14;

    #[test]
    fn unit_normals_light_like_the_projects_phong() {
        let lighting = Lighting::default();
        let m = Material::plastic([0.2, 0.6, 0.3]);
        let pl = PhongLights::new(&lighting, &[m]);
        for i in 0..100 {
            let a = i as f64 * 0.29;
            let n = normalize([a.sin(), (a * 0.7).cos(), 0.6 + (a * 1.1).sin().abs()]);
            let q = normal_q14(n).map(|c| c as i16);
            let ours = shade_entry(&pl, q, 0);
            let cs = pl.shade(q.map(|c| c as i64), 0);
            for k in 0..3 {
                assert!((ours[k] as i32 - cs[k] as i32).abs() <= 1, "{n:?}: {ours:?} vs {cs:?}");
            }
        }
    }
}
