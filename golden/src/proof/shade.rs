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

use crate::format::{round_shift, NORMAL_FRAC};
use crate::shade::PhongLights;

/// Q1.14 one.
pub const ONE_Q14: i64 = 1 << NORMAL_FRAC;

/// The clamped dot product of a (not unit) normal with a unit vector, Q1.14 in [0, 1].
pub fn dot_q14(n: [i16; 3], b: [i64; 3]) -> i64 {
    let s: i64 = (0..3).map(|k| n[k] as i64 * b[k]).sum();
    round_shift(s as i128, NORMAL_FRAC).clamp(0, ONE_Q14 as i128) as i64
}

/// x^(2^k) in Q1.14 by k roundings of a square.
pub fn power_q14(mut x: i64, log2m: u32) -> i64 {
    for _ in 0..log2m {
        x = round_shift((x * x) as i128, NORMAL_FRAC) as i64;
    }
    x
}

/// The unrounded intensity sum of the light-source pipeline for one entry, per channel, with
/// 14 + 8 fraction bits.
pub fn intensity(lights: &PhongLights, n: [i16; 3], material: u16) -> [i64; 3] {
    let m = &lights.materials[material as usize];
    let mut acc = m.ambient.map(|a| a << NORMAL_FRAC);
    for li in 0..lights.l.len() {
        let nl = dot_q14(n, lights.l[li]);
        let sp = if nl > 0 { power_q14(dot_q14(n, lights.h[li]), m.gloss_log2) } else { 0 };
        for k in 0..3 {
            acc[k] += m.diffuse[li][k] * nl + m.specular[li][k] * sp;
        }
    }
    acc
}

/// The colour of one list entry.
pub fn shade_entry(lights: &PhongLights, n: [i16; 3], material: u16) -> [u8; 3] {
    intensity(lights, n, material).map(|a| round_shift(a as i128, NORMAL_FRAC + 8).clamp(0, 255) as u8)
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
