//! Colour setup and the Color Shader (seed 001 §2.3.2, §3.1; seed 000 §III), untimed.
//!
//! Colour setup turns a visible triangle's three vertex values into one [`Plane`] per channel with
//! exactly one reciprocal per triangle, and stores them in TdbS at the triangle's index. The CS scans
//! the I-buffer out in raster order, fetches TdbS by index and evaluates the planes at the pixel.
//!
//! * Flat: three constant planes (the triangle's one lit colour).
//! * Gouraud: planes through the three lit RGB888 vertex colours (seed 001 eqs. 6-7).
//! * Phong: planes through the three eye-space normals' components (Q1.14); the CS normalises the
//!   interpolated normal and lights it per pixel with [`PhongLights`], all in integer arithmetic.

use crate::format::{reciprocal, round_shift, Plane, WinVertex, NORMAL_FRAC};
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
    let d = det(v);
    assert!(d != 0, "colour setup of a zero-area triangle (the RC never flags one visible)");
    let o = canonical_order(v);
    let vv = [v[o[0]], v[o[1]], v[o[2]]];
    let r = reciprocal(d.abs());
    let planes = [0, 1, 2].map(|c| Plane::setup(&vv, [values[o[0]][c], values[o[1]][c], values[o[2]][c]], d.abs(), r));
    TdbsEntry { planes, material }
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

/// Integer square root (floor). The RTL uses a digit-by-digit (restoring) square root: the same value.
pub fn isqrt(x: u128) -> u128 {
    if x == 0 {
        return 0;
    }
    let mut r = (x as f64).sqrt() as u128;
    while r * r > x {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= x {
        r += 1;
    }
    r
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

fn q8(v: f64) -> i64 {
    (v * 255.0 * 256.0).round() as i64
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

    /// Light one pixel from its interpolated (not unit) Q1.14 normal. Integer arithmetic throughout:
    /// normalise with `r = isqrt(2^56 / |n|^2)` (so n*r/2^14 is unit in Q1.14), then seed 001 eq. 4 with
    /// the gloss as repeated squaring (n a power of two), clamped dot products, RGB rounded and saturated.
    pub fn shade(&self, n: [i64; 3], material: u16) -> [u8; 3] {
        let m = &self.materials[material as usize];
        let len2 = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) as u128;
        let u = if len2 == 0 {
            [0; 3]
        } else {
            let r = isqrt((1u128 << 56) / len2) as i128;
            n.map(|c| round_shift(c as i128 * r, NORMAL_FRAC) as i64)
        };
        let dotq = |a: [i64; 3], b: [i64; 3]| -> i64 {
            round_shift((a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) as i128, NORMAL_FRAC).max(0) as i64
        };
        let mut acc = m.ambient.map(|a| (a as i128) << NORMAL_FRAC);
        for li in 0..self.l.len() {
            let nl = dotq(u, self.l[li]);
            let mut sp = if nl > 0 { dotq(u, self.h[li]) } else { 0 };
            for _ in 0..m.gloss_log2 {
                sp = round_shift(sp as i128 * sp as i128, NORMAL_FRAC) as i64;
            }
            for k in 0..3 {
                acc[k] += m.diffuse[li][k] as i128 * nl as i128 + m.specular[li][k] as i128 * sp as i128;
            }
        }
        acc.map(|a| round_shift(a, NORMAL_FRAC + 8).clamp(0, 255) as u8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn isqrt_is_the_floor_of_the_square_root() {
        for x in [0u128, 1, 2, 3, 4, 15, 16, 17, 1 << 56, (1 << 56) - 1, 12345678901234567] {
            let r = isqrt(x);
            assert!(r * r <= x && (r + 1) * (r + 1) > x, "{x}");
        }
    }

    #[test]
    fn phong_in_fixed_point_is_close_to_the_float_model() {
        let lighting = Lighting::default();
        let m = Material::plastic([0.7, 0.3, 0.2]);
        let pl = PhongLights::new(&lighting, &[m.clone()]);
        for i in 0..200 {
            let a = i as f64 * 0.37;
            let n = normalize([a.cos(), (a * 1.3).sin(), 0.5 + (a * 0.7).cos().abs()]);
            // An un-normalised interpolated normal (scaled by 0.8) must light the same.
            let q = normal_q14(n).map(|c| c * 4 / 5);
            let fixed = pl.shade(q, 0);
            let float = crate::host::to_rgb8(lighting.shade(&m, n));
            for k in 0..3 {
                assert!((fixed[k] as i32 - float[k] as i32).abs() <= 2, "n {n:?}: {fixed:?} vs {float:?}");
            }
        }
    }
}
