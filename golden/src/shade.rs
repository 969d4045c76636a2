//! Colour setup and the Color Shader (seed 001 §2.3.2, §3.1; seed 000 §III), untimed.
//!
//! Colour setup turns a visible triangle's three vertex values into one [`Plane`] per channel with
//! exactly one reciprocal per triangle, and stores them in TdbS at the triangle's index. The CS scans
//! the I-buffer out in raster order, fetches TdbS by index and evaluates the planes at the pixel.
//!
//! * Flat: three constant planes (the triangle's one lit colour).
//! * Gouraud: planes through the three lit RGB888 vertex colours (seed 001 eqs. 6-7).
//! * Phong: planes through the three eye-space normals' components (Q1.14); the CS normalises the
//!   interpolated normal and lights it per pixel with [`PhongLights`], all in integer arithmetic, in the
//!   steps the RTL takes (see [`normalize_q14`] and [`PhongLights::shade`]).

use crate::format::{reciprocal, round_shift, rsqrt, Plane, WinVertex, NORMAL_FRAC};
use crate::host::{normalize, Lighting, Vec3};
use crate::raster::{canonical_order, det};
use crate::scene::Material;

/// How colour is produced.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Shading {
    Flat,
    Gouraud,
    Phong,
}

/// One TdbS record: three planes (R, G, B, or the normal's x, y, z for Phong) and the material
/// (used by Phong only).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub struct TdbsEntry {
    pub planes: [Plane; 3],
    pub material: u16,
}

/// Colour setup for one triangle: `values[k]` are vertex k's three channel values (RGB888 or Q1.14
/// normal components) in the order the triangle was sent to the RC. One reciprocal.
pub fn colour_setup(v: &[WinVertex; 3], values: [[i64; 3]; 3], material: u16) -> TdbsEntry {
    TdbsEntry { planes: three_planes(v, values), material }
}

/// The three planes through `values[k][c]` at window vertex k (c = 0, 1, 2), vertices in the order
/// the triangle was sent: the triangle put in the order with det > 0, one reciprocal for all three.
/// Colour setup's arithmetic, also used for the texture planes ([`crate::texcoord::setup`]).
pub fn three_planes(v: &[WinVertex; 3], values: [[i64; 3]; 3]) -> [Plane; 3] {
    let d = det(v);
    assert!(d != 0, "plane setup of a zero-area triangle (the RC never flags one visible)");
    let o = canonical_order(v);
    let vv = [v[o[0]], v[o[1]], v[o[2]]];
    let r = reciprocal(d.abs());
    [0, 1, 2].map(|c| Plane::setup(&vv, [values[o[0]][c], values[o[1]][c], values[o[2]][c]], d.abs(), r))
}

/// Flat colour setup: constant planes, no reciprocal.
pub fn flat_setup(rgb: [u8; 3]) -> TdbsEntry {
    TdbsEntry { planes: rgb.map(|c| Plane::constant(c as i64)), material: 0 }
}

/// A normal vector in Q1.14.
pub fn normal_q14(n: Vec3) -> [i64; 3] {
    let n = normalize(n);
    n.map(|c| (c * (1 << NORMAL_FRAC) as f64).round() as i64)
}

/// Lighting constants in the CS's fixed-point form, precomputed by the host once per frame.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PhongLights {
    /// Per light: direction L and halfway vector H, unit vectors in Q1.14.
    pub l: Vec<[i64; 3]>,
    pub h: Vec<[i64; 3]>,
    /// Per material: ambient term Ka*Ia*255, and per light Kd*Ii*255 and Ks*Ii*255, all with 8 fraction
    /// bits; and log2 of the gloss.
    pub materials: Vec<PhongMaterial>,
}

#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PhongMaterial {
    pub ambient: [i64; 3],
    pub diffuse: Vec<[i64; 3]>,
    pub specular: Vec<[i64; 3]>,
    pub gloss_log2: u32,
}

/// A lighting coefficient (0..1) as colour x 255 with 8 fraction bits, in the CS's 16 unsigned bits.
fn q8(v: f64) -> i64 {
    (v * 255.0 * 256.0).round().clamp(0.0, 65535.0) as i64
}

/// RGB888 of a light sum (14 + 8 fraction bits per channel): rounded by 22 bits and saturated, as the
/// CS and PROOF's shading stage end.
pub fn rgb_of_intensity(acc: [i64; 3]) -> [u8; 3] {
    acc.map(|a| round_shift(a as i128, NORMAL_FRAC + 8).clamp(0, 255) as u8)
}

/// Q1.14 one.
pub const ONE_Q14: i64 = 1 << NORMAL_FRAC;

/// The Phong datapath's view of an interpolated normal component: the plane's value rounded to an
/// integer (`Plane::eval`) and saturated to 16 signed bits (a unit normal's components are within
/// +/-2^14; only a corrupt record reaches the limits).
pub fn normal_component(v: i64) -> i64 {
    v.clamp(i16::MIN as i64, i16::MAX as i64)
}

/// Normalise an interpolated Q1.14 normal as the CS's normaliser does: `len2 = |n|^2` (32 bits),
/// an even left shift `2k` so that `m = len2 << 2k` is in `[2^30, 2^32)`, `y = rsqrt(m)`, and then
/// `u = round(n * y * 2^(k - 17))` saturated to 16 bits. A zero normal stays zero.
pub fn normalize_q14(n: [i64; 3]) -> [i64; 3] {
    let n = n.map(normal_component);
    let len2 = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) as u64;
    if len2 == 0 {
        return [0; 3];
    }
    let k = (len2 as u32).leading_zeros() / 2;
    let m = (len2 as u32) << (2 * k);
    let y = rsqrt(m) as i128;
    n.map(|c| normal_component(round_shift((c as i128 * y) << k, 17) as i64))
}

/// The raw sum of products of a normal with a vector, Q2.28 for Q1.14 operands: what [`dot_q14`]
/// rounds.
pub fn dot_raw(n: [i64; 3], b: [i64; 3]) -> i64 {
    (0..3).map(|k| n[k] * b[k]).sum()
}

/// The clamped dot product of a normal with a unit vector, Q1.14 in [0, 1] (seed 002's light-source
/// processors and the CS's light units).
pub fn dot_q14(n: [i64; 3], b: [i64; 3]) -> i64 {
    round_shift(dot_raw(n, b) as i128, NORMAL_FRAC).clamp(0, ONE_Q14 as i128) as i64
}

/// x^(2^k) in Q1.14 by k roundings of a square (x in [0, 1] stays in [0, 1]).
pub fn power_q14(mut x: i64, log2m: u32) -> i64 {
    for _ in 0..log2m {
        x = round_shift((x * x) as i128, NORMAL_FRAC) as i64;
    }
    x
}

impl PhongLights {
    pub fn new(lighting: &Lighting, materials: &[Material]) -> PhongLights {
        let dirs: Vec<Vec3> = lighting.lights.iter().map(|l| normalize(l.direction)).collect();
        let l = dirs.iter().map(|&d| normal_q14(d)).collect();
        let h = dirs.iter().map(|&d| normal_q14([d[0], d[1], d[2] + 1.0])).collect();
        let materials = materials
            .iter()
            .map(|m| PhongMaterial {
                ambient: [0, 1, 2].map(|k| q8(lighting.ambient[k] * m.ambient[k])),
                diffuse: lighting.lights.iter().map(|li| [0, 1, 2].map(|k| q8(li.intensity[k] * m.diffuse[k]))).collect(),
                specular: lighting.lights.iter().map(|li| [0, 1, 2].map(|k| q8(li.intensity[k] * m.specular[k]))).collect(),
                gloss_log2: m.gloss.trailing_zeros(),
            })
            .collect();
        PhongLights { l, h, materials }
    }

    /// The unrounded light sum for one normal `n` (not normalised here), per channel, with 14 + 8
    /// fraction bits: seed 001 eq. 4 with the ambient term, then per light the diffuse term `Kd Il (N.L)`
    /// and the specular term `Ks Il (N.H)^gloss` (the gloss by repeated squaring, only where N.L > 0),
    /// dot products clamped to [0, 1]. The same sum as seed 002's light-source pipeline.
    pub fn intensity(&self, n: [i64; 3], material: u16) -> [i64; 3] {
        let m = &self.materials[material as usize];
        let mut acc = m.ambient.map(|a| a << NORMAL_FRAC);
        for li in 0..self.l.len() {
            let nl = dot_q14(n, self.l[li]);
            let sp = if nl > 0 { power_q14(dot_q14(n, self.h[li]), m.gloss_log2) } else { 0 };
            for k in 0..3 {
                acc[k] += m.diffuse[li][k] * nl + m.specular[li][k] * sp;
            }
        }
        acc
    }

    /// Light one pixel from its interpolated (not unit) Q1.14 normal, as the CS's Phong datapath does:
    /// [`normalize_q14`], [`PhongLights::intensity`], then RGB rounded by 22 bits and saturated.
    ///
    /// Against the f64 model (`Lighting::shade` and `to_rgb8`) this is within 1 LSB per channel on unit
    /// and shortened normals (`phong_in_fixed_point_is_close_to_the_float_model`): the normaliser's
    /// error is below 1 LSB of Q1.14 and the Q1.14 dot products and squarings add the rest.
    pub fn shade(&self, n: [i64; 3], material: u16) -> [u8; 3] {
        rgb_of_intensity(self.intensity(normalize_q14(n), material))
    }

    /// Whether the CS's RTL can hold these lights and materials; the error names the limit.
    pub fn check_rtl_limits(&self) -> Result<(), String> {
        use crate::format::{CS_GLOSS_LOG2_MAX, CS_LIGHTS, CS_MATERIALS};
        if self.l.len() > CS_LIGHTS {
            return Err(format!(
                "{} lights, but the Color Shader's Phong datapath holds at most {CS_LIGHTS} (format::CS_LIGHTS)",
                self.l.len()
            ));
        }
        if self.materials.len() > CS_MATERIALS {
            return Err(format!(
                "{} materials, but the Color Shader's material memory holds at most {CS_MATERIALS} (format::CS_MATERIALS)",
                self.materials.len()
            ));
        }
        if let Some(m) = self.materials.iter().find(|m| m.gloss_log2 > CS_GLOSS_LOG2_MAX) {
            return Err(format!("gloss 2^{} exceeds the Color Shader's 2^{CS_GLOSS_LOG2_MAX}", m.gloss_log2));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::host::Light;

    fn lightings() -> Vec<Lighting> {
        let two = Lighting {
            ambient: [0.15, 0.1, 0.2],
            lights: vec![
                Light { direction: normalize([-0.4, 0.6, 0.7]), intensity: [0.7, 0.6, 0.5] },
                Light { direction: normalize([0.8, -0.2, 0.5]), intensity: [0.3, 0.4, 0.45] },
            ],
        };
        vec![Lighting::default(), two]
    }

    #[test]
    fn normalised_normals_are_unit_within_one_q14_lsb() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let n = [0, 1, 2].map(|k| ((x >> (16 * k)) as u16 as i16) as i64 >> ((x >> 60) & 15).min(14));
            let u = normalize_q14(n);
            let len = ((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) as f64).sqrt();
            for k in 0..3 {
                let exact = if len == 0.0 { 0.0 } else { n[k] as f64 / len * ONE_Q14 as f64 };
                assert!((u[k] as f64 - exact).abs() <= 1.0, "n {n:?}: u {u:?}, exact component {k} {exact}");
            }
        }
    }

    #[test]
    fn phong_in_fixed_point_is_close_to_the_float_model() {
        // Every gloss the scenes allow, one and two lights, unit and shortened normals (an interpolated
        // normal is shorter than 1): within 1 LSB of f64 Phong per channel (the old integer form allowed 2).
        let mats: Vec<Material> = [1u32, 2, 4, 8, 16]
            .iter()
            .enumerate()
            .map(|(i, &g)| Material { gloss: g, ..Material::plastic([0.7, 0.3 + 0.1 * i as f64, 0.2]) })
            .collect();
        let mut worst = 0;
        for lighting in lightings() {
            let pl = PhongLights::new(&lighting, &mats);
            for i in 0..4000 {
                let a = i as f64 * 0.37;
                let n = normalize([a.cos(), (a * 1.3).sin(), 0.5 + (a * 0.7).cos().abs() - 0.4 * (a * 0.11).sin()]);
                let scale = [1.0, 0.8, 0.55, 0.3][i % 4];
                let q = normal_q14(n).map(|c| (c as f64 * scale).round() as i64);
                for (mi, m) in mats.iter().enumerate() {
                    let fixed = pl.shade(q, mi as u16);
                    let float = crate::host::to_rgb8(lighting.shade(m, n));
                    for k in 0..3 {
                        let d = (fixed[k] as i32 - float[k] as i32).abs();
                        worst = worst.max(d);
                        assert!(d <= 1, "n {n:?} x {scale}, gloss {}: {fixed:?} vs {float:?}", m.gloss);
                    }
                }
            }
        }
        eprintln!("fixed-point Phong: worst difference from f64 {worst} LSB");
    }

    #[test]
    fn rtl_limits_name_what_is_exceeded() {
        let mut lighting = lightings().pop().unwrap();
        let one = vec![Material::plastic([0.5, 0.5, 0.5])];
        assert!(PhongLights::new(&lighting, &one).check_rtl_limits().is_ok());
        lighting.lights.push(lighting.lights[0].clone());
        let e = PhongLights::new(&lighting, &one).check_rtl_limits().unwrap_err();
        assert!(e.contains("3 lights") && e.contains("at most 2"), "{e}");
        let many = vec![Material::plastic([0.5, 0.5, 0.5]); 17];
        let e = PhongLights::new(&Lighting::default(), &many).check_rtl_limits().unwrap_err();
        assert!(e.contains("17 materials") && e.contains("at most 16"), "{e}");
    }
}
