//! The filter stage (seed 002 §6): an 8x8 subpixel mask per pixel, the visible object per subpixel,
//! and the colours combined with weights equal to the number of subpixels each object covers.
//!
//! Subpixel centres are at offsets `(2i - 7)/16` px from the pixel centre (i = 0..7, left to right;
//! j = 0..7, top to bottom, window y down). The distance of a subpixel centre to an edge follows from
//! the OP's distance at the pixel centre (seed 002 §6.1, "dsp = d + xi cos a + yi sin a"); in integers,
//! scaled by 16 so that everything is exact:
//!
//! `16 dsp(i, j) = (16 d - 7 cos a - 7 sin a) + i (2 cos a) + j (2 sin a)`
//!
//! The multiples `i (2 cos a)`, i = 0..7, are the leaves of the paper's tree: level L adds 2^L (2 cos a)
//! on the right branch. A subpixel is covered by a partial entry if `dsp >= 0` for all three edges; a
//! full entry covers all 64. Going down the list (nearest first), each entry gets the subpixels no
//! earlier entry took; the rest show the background.
//!
//! Transparency (issue 22, seed 002 §6 "both opaque and transparent objects"): when the frame has a
//! transparent object, each subpixel is composited front to back ([`blend_subpixels`]). Its
//! transmittance `T` starts at [`T_ONE`] (1.0 in Q1.8); an entry of opacity `a` (Q1.4, sixteenths:
//! [`super::format::ALPHA_FRAC`]) covering the subpixel adds its colour with the weight
//! `w = (T a + 8) >> 4` and leaves `T - w`, so the weights
//! and the final `T` (the background's weight) always sum to exactly 256 per subpixel. An opaque entry
//! takes `w = T`: on lists of opaque entries this is the unblended filter scaled by 256, and the
//! result is the same byte for byte (tested), so frames without transparency do not change.
//!
//! Filter area: [`FilterArea::Box1`] averages the pixel's 64 subpixels; [`FilterArea::Box2`] is the
//! paper's 2x2 area: a 2x2-pixel box centred on the pixel centre (its own 64 subpixels, half of each
//! edge neighbour's and a quarter of each corner neighbour's; pixels beyond the screen edge repeat the
//! edge pixel), computed from per-quadrant sums of 4x4 subpixels. Blended, each quadrant's sum of
//! its 16 composited subpixels (in 1/256) is rounded to whole units before the box
//! ([`quadrant_sums_blended`]), so the hardware's box and line buffer keep their opaque widths; the
//! box then adds 16 such sums, so this rounding moves a pixel by at most 16 x 0.5 / 256 of a unit
//! before the box's own rounding.

use super::format::{Entry, ALPHA_FRAC, ALPHA_ONE, SUBPIXELS};

/// Filter area.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum FilterArea {
    /// 1x1 pixel box (default).
    Box1,
    /// The paper's 2x2 pixels.
    Box2,
}

/// The paper's tree of multiples: `[0, 1, .., 7] x step`, built from nodes that pass the main input to
/// the left and add the level's auxiliary input (2^L step) to the right.
pub fn multiples_tree(step: i64) -> [i64; 8] {
    let mut level = vec![0i64];
    for l in (0..3).rev() {
        let aux = step << l;
        level = level.iter().flat_map(|&m| [m, m + aux]).collect();
    }
    // Left to right, the leaves hold 0, 1, .., 7 steps.
    let mut out = [0i64; 8];
    out.copy_from_slice(&level);
    out
}

/// The 8x8 subpixel mask of one entry (bit `8 j + i`), given its edges' directions (cos, sin) Q1.14.
pub fn subpixel_mask(e: &Entry, dirs: &[(i16, i16); 3]) -> u64 {
    if e.full {
        return u64::MAX;
    }
    let mut mask = u64::MAX;
    for k in 0..3 {
        let (c, s) = (dirs[k].0 as i64, dirs[k].1 as i64);
        let base = 16 * e.dist[k] as i64 - 7 * c - 7 * s;
        let mx = multiples_tree(2 * c);
        let my = multiples_tree(2 * s);
        let mut m = 0u64;
        for j in 0..SUBPIXELS as usize {
            for i in 0..SUBPIXELS as usize {
                if base + mx[i] + my[j] >= 0 {
                    m |= 1 << (8 * j + i);
                }
            }
        }
        mask &= m;
    }
    mask
}

/// Which subpixels each entry wins, nearest first: (owner masks, union).
pub fn visible_masks(list: &[Entry], dirs: &dyn Fn(u16) -> [(i16, i16); 3]) -> (Vec<u64>, u64) {
    let mut taken = 0u64;
    let owners = list
        .iter()
        .map(|e| {
            let m = subpixel_mask(e, &dirs(e.id)) & !taken;
            taken |= m;
            m
        })
        .collect();
    (owners, taken)
}

/// The 1x1 filter: the pixel colour from the owners' colours and the background, rounded.
pub fn combine(owners: &[u64], colours: &[[u8; 3]], taken: u64, bg: [u8; 3]) -> [u8; 3] {
    let wbg = 64 - taken.count_ones() as u32;
    [0, 1, 2].map(|k| {
        let mut s = wbg * bg[k] as u32;
        for (m, c) in owners.iter().zip(colours) {
            s += m.count_ones() * c[k] as u32;
        }
        ((s + 32) >> 6) as u8
    })
}

/// Per-quadrant colour sums (quadrant q = 2 qy + qx, 4x4 subpixels each) for the 2x2 filter.
pub fn quadrant_sums(owners: &[u64], colours: &[[u8; 3]], taken: u64, bg: [u8; 3]) -> [[u32; 3]; 4] {
    let mut out = [[0u32; 3]; 4];
    for q in 0..4 {
        let (qx, qy) = (q % 2, q / 2);
        let mut qm = 0u64;
        for j in 0..4 {
            qm |= 0xfu64 << (8 * (4 * qy + j) + 4 * qx);
        }
        let wbg = 16 - (taken & qm).count_ones();
        for k in 0..3 {
            let mut s = wbg * bg[k] as u32;
            for (m, c) in owners.iter().zip(colours) {
                s += (m & qm).count_ones() * c[k] as u32;
            }
            out[q][k] = s;
        }
    }
    out
}

/// The transmittance of an uncovered subpixel: 1.0 in Q1.8.
pub const T_ONE: u32 = 256;

/// Front-to-back compositing per subpixel (module doc): for each of the 64 subpixels, the sum of
/// `weight x colour` over the entries covering it and the background (weights in 1/256, summing to
/// 256), and the union of the entries' masks. `alpha(id)` is the object's opacity, Q1.4.
pub fn blend_subpixels(
    list: &[Entry],
    dirs: &dyn Fn(u16) -> [(i16, i16); 3],
    alpha: &dyn Fn(u16) -> u16,
    colours: &[[u8; 3]],
    bg: [u8; 3],
) -> ([[u32; 3]; 64], u64) {
    let mut t = [T_ONE; 64];
    let mut acc = [[0u32; 3]; 64];
    let mut taken = 0u64;
    for (e, c) in list.iter().zip(colours) {
        let m = subpixel_mask(e, &dirs(e.id));
        taken |= m;
        let a = alpha(e.id).min(ALPHA_ONE) as u32;
        for i in 0..64 {
            if m >> i & 1 == 1 && t[i] > 0 {
                let w = (t[i] * a + (1 << (ALPHA_FRAC - 1))) >> ALPHA_FRAC;
                for k in 0..3 {
                    acc[i][k] += w * c[k] as u32;
                }
                t[i] -= w;
            }
        }
    }
    for i in 0..64 {
        for k in 0..3 {
            acc[i][k] += t[i] * bg[k] as u32;
        }
    }
    (acc, taken)
}

/// The 1x1 filter of blended subpixels: the mean of the 64, rounded.
pub fn combine_blended(acc: &[[u32; 3]; 64]) -> [u8; 3] {
    [0, 1, 2].map(|k| ((acc.iter().map(|a| a[k]).sum::<u32>() + (1 << 13)) >> 14) as u8)
}

/// The quadrant (`q = 2 qy + qx`, 4x4 subpixels each) of subpixel bit `i = 8 j + i`.
pub fn quadrant_of(i: usize) -> usize {
    2 * (i / 32) + (i % 8) / 4
}

/// Per-quadrant sums of blended subpixels (background included), rounded to whole units:
/// `(Σ_{i in q} acc_i + 128) >> 8`, so that the 2x2 box ([`box2`]) takes the same 12-bit quadrant
/// sums as for opaque lists. This rounding is the 2x2 area's one simplification of the blend (module
/// doc); on opaque lists every subpixel's value is a multiple of 256 and the sums are exact.
pub fn quadrant_sums_blended(acc: &[[u32; 3]; 64]) -> [[u32; 3]; 4] {
    let mut out = [[0u32; 3]; 4];
    for (i, a) in acc.iter().enumerate() {
        for k in 0..3 {
            out[quadrant_of(i)][k] += a[k];
        }
    }
    out.map(|q| q.map(|v| (v + 128) >> 8))
}

/// The same compositing in f64 with the unquantised opacities: the reference that the fixed-point
/// form's error is measured against (the same subpixel masks; colours as given). The pixel's mean of
/// [`blend_reference_subpixels`].
pub fn blend_reference(
    list: &[Entry],
    dirs: &dyn Fn(u16) -> [(i16, i16); 3],
    opacity: &dyn Fn(u16) -> f64,
    colours: &[[u8; 3]],
    bg: [u8; 3],
) -> [f64; 3] {
    let sub = blend_reference_subpixels(list, dirs, opacity, colours, bg);
    [0, 1, 2].map(|k| sub.iter().map(|s| s[k]).sum::<f64>() / 64.0)
}

/// The f64 composite of each of the 64 subpixels (bit order of [`subpixel_mask`]).
pub fn blend_reference_subpixels(
    list: &[Entry],
    dirs: &dyn Fn(u16) -> [(i16, i16); 3],
    opacity: &dyn Fn(u16) -> f64,
    colours: &[[u8; 3]],
    bg: [u8; 3],
) -> [[f64; 3]; 64] {
    let mut out = [[0f64; 3]; 64];
    let masks: Vec<u64> = list.iter().map(|e| subpixel_mask(e, &dirs(e.id))).collect();
    for (i, o) in out.iter_mut().enumerate() {
        let mut t = 1.0f64;
        for ((e, c), m) in list.iter().zip(colours).zip(&masks) {
            if m >> i & 1 == 1 {
                let a = opacity(e.id);
                for k in 0..3 {
                    o[k] += t * a * c[k] as f64;
                }
                t *= 1.0 - a;
            }
        }
        for k in 0..3 {
            o[k] += t * bg[k] as f64;
        }
    }
    out
}

/// The 2x2 filter over a whole image of quadrant sums (row-major pixels).
pub fn box2(width: u32, height: u32, quads: &[[[u32; 3]; 4]]) -> Vec<u8> {
    let (w, h) = (width as i64, height as i64);
    let at = |qx: i64, qy: i64, k: usize| -> u32 {
        // Quadrant coordinates; beyond the screen, the edge pixel's nearest quadrant repeats.
        let qx = qx.clamp(0, 2 * w - 1);
        let qy = qy.clamp(0, 2 * h - 1);
        quads[((qy / 2) * w + qx / 2) as usize][((qy % 2) * 2 + qx % 2) as usize][k]
    };
    let mut out = Vec::with_capacity((w * h * 3) as usize);
    for y in 0..h {
        for x in 0..w {
            for k in 0..3 {
                let mut s = 0u64;
                for qy in 2 * y - 1..=2 * y + 2 {
                    for qx in 2 * x - 1..=2 * x + 2 {
                        s += at(qx, qy, k) as u64;
                    }
                }
                out.push(((s + 128) >> 8) as u8);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tree_of_multiples_gives_zero_to_seven_steps() {
        assert_eq!(multiples_tree(3), [0, 3, 6, 9, 12, 15, 18, 21]);
        assert_eq!(multiples_tree(-5), [0, -5, -10, -15, -20, -25, -30, -35]);
    }

    #[test]
    fn a_vertical_edge_through_the_pixel_centre_covers_the_right_half() {
        // Interior to the right: normal (1, 0), distance 0 at the centre.
        let e = Entry { dist: [0, 16384, 16384], ..Default::default() };
        let dirs = [(16384, 0), (16384, 0), (16384, 0)];
        let m = subpixel_mask(&e, &dirs);
        assert_eq!(m.count_ones(), 32);
        for j in 0..8 {
            assert_eq!((m >> (8 * j)) & 0xff, 0xf0, "row {j}");
        }
        let c = combine(&[m], &[[255, 0, 0]], m, [0, 0, 255]);
        assert_eq!(c, [128, 0, 128]);
    }
}
