//! The texture memory as the Color Shader reads it (issue 17, item 4): four interleaved banks, so that
//! the 2x2 footprint of a bilinear sample is one read of each bank in one clock, and the footprint
//! ([`footprint`]) the CS's address unit (`hdl::cs::texel_address`) computes from a pixel's (s, t).
//!
//! Texel (x, y) of a mipmap level lives in bank `(x & 1) | (y & 1) << 1`, at word
//! `base + (y >> 1) * ceil(w / 2) + (x >> 1)` of that bank, where `base` is the level's first word
//! ([`layout`]: the levels one after another, level 0 first). Two horizontally neighbouring texels
//! differ in `x & 1`, two vertical ones in `y & 1`, so the four texels of a footprint are in four
//! different banks, except where clamping or a one-texel-wide level makes two of them the same texel,
//! which is then one read. A 1024x1024 texture and its mipmaps take 349,526 words per bank (19 address
//! bits, [`TEXEL_ADDR_BITS`] gives one to spare).
//!
//! A sample is then the texel filter's blend of the four words: nearest is the footprint of one texel
//! with weights 0 (the blend then returns it exactly). `tests` check that reading the banks this way
//! gives [`Texture::sample_level`]'s colour for every filter, wrap, level and shape.

use crate::texture::{Texture, Wrap, TEXCOORD_FRAC, WEIGHT_FRAC};

/// Banks of the texture memory.
pub const TEXTURE_BANKS: usize = 4;
/// Bits of a bank's word address.
pub const TEXEL_ADDR_BITS: u32 = 20;

/// Where one mipmap level is: its size and its first word in every bank.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct LevelGeom {
    pub w_log2: u32,
    pub h_log2: u32,
    pub base: u32,
}

impl LevelGeom {
    /// Words per bank-row: ceil(width / 2), as a shift (width 1 still takes a word per row pair).
    fn row_shift(&self) -> u32 {
        self.w_log2.saturating_sub(1)
    }

    /// Bank and word of texel (x, y).
    pub fn locate(&self, x: u32, y: u32) -> (usize, u32) {
        ((x & 1 | (y & 1) << 1) as usize, self.base + ((y >> 1) << self.row_shift()) + (x >> 1))
    }

    /// Words this level takes in each bank.
    pub fn words(&self) -> u32 {
        (1 << self.row_shift()) * (1 << self.h_log2.saturating_sub(1))
    }
}

/// The levels of `texture` and their places in the banks.
pub fn layout(texture: &Texture) -> Vec<LevelGeom> {
    let mut base = 0;
    texture
        .levels
        .iter()
        .map(|l| {
            let g = LevelGeom { w_log2: l.w_log2, h_log2: l.h_log2, base };
            base += g.words();
            g
        })
        .collect()
}

/// The four banks' contents (RGB888 words; a word no texel uses is black).
pub fn banks(texture: &Texture) -> [Vec<[u8; 3]>; TEXTURE_BANKS] {
    let geoms = layout(texture);
    let total = geoms.last().map_or(0, |g| g.base + g.words()) as usize;
    let mut banks: [Vec<[u8; 3]>; TEXTURE_BANKS] = std::array::from_fn(|_| vec![[0; 3]; total]);
    for (g, l) in geoms.iter().zip(&texture.levels) {
        for y in 0..1u32 << g.h_log2 {
            for x in 0..1u32 << g.w_log2 {
                let (b, w) = g.locate(x, y);
                banks[b][w as usize] = l.texels[((y as usize) << g.w_log2) + x as usize];
            }
        }
    }
    banks
}

/// What the CS reads for one sample: a word address and a read enable per bank, the bank each
/// footprint slot (t00, t10, t01, t11: x then y) takes its texel from, and the blend's weights.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct Footprint {
    pub read: [bool; TEXTURE_BANKS],
    /// A bank's address; 0 where it is not read.
    pub addr: [u32; TEXTURE_BANKS],
    pub route: [u8; 4],
    pub fx: u8,
    pub fy: u8,
}

impl Footprint {
    /// Words read from the banks for this sample (the texels fetched at the port).
    pub fn reads(&self) -> u32 {
        self.read.iter().filter(|&&r| r).count() as u32
    }

    /// The footprint's texels [t00, t10, t01, t11] from the banks' contents.
    pub fn texels(&self, banks: &[Vec<[u8; 3]>; TEXTURE_BANKS]) -> [[u8; 3]; 4] {
        self.route.map(|b| banks[b as usize][self.addr[b as usize] as usize])
    }
}

/// Texel index `i` of a dimension of `1 << log2` texels, wrapped or clamped.
fn wrap_index(i: i64, log2: u32, wrap: Wrap) -> u32 {
    let n = 1i64 << log2;
    (match wrap {
        Wrap::Repeat => i & (n - 1),
        Wrap::ClampToEdge => i.clamp(0, n - 1),
    }) as u32
}

/// The footprint of a sample at (s, t) (Q15.16 of the texture) in level `g`: the 2x2 texels around the
/// point and their weights (`bilinear`), or the one texel under it with weights 0 (nearest).
pub fn footprint(g: LevelGeom, s: i32, t: i32, bilinear: bool, wrap: Wrap) -> Footprint {
    // Position in texels, 16 fraction bits; bilinear measures from the texel centres.
    let half = if bilinear { 1i64 << (TEXCOORD_FRAC - 1) } else { 0 };
    let px = ((s as i64) << g.w_log2) - half;
    let py = ((t as i64) << g.h_log2) - half;
    let (x0, y0) = (px >> TEXCOORD_FRAC, py >> TEXCOORD_FRAC);
    let step = bilinear as i64;
    let xs = [wrap_index(x0, g.w_log2, wrap), wrap_index(x0 + step, g.w_log2, wrap)];
    let ys = [wrap_index(y0, g.h_log2, wrap), wrap_index(y0 + step, g.h_log2, wrap)];
    let mut f = Footprint::default();
    if bilinear {
        f.fx = ((px >> (TEXCOORD_FRAC - WEIGHT_FRAC)) & 0xff) as u8;
        f.fy = ((py >> (TEXCOORD_FRAC - WEIGHT_FRAC)) & 0xff) as u8;
    }
    for slot in 0..4 {
        let (b, w) = g.locate(xs[slot & 1], ys[slot >> 1]);
        f.route[slot] = b as u8;
        f.read[b] = true;
        f.addr[b] = w;
    }
    f
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{bilinear, Filter};
    use proptest::prelude::*;

    /// A texture of distinct-looking random texels.
    fn random_texture(w_log2: u32, h_log2: u32, seed: u64) -> Texture {
        let mut x = seed | 1;
        let texels = (0..1usize << (w_log2 + h_log2))
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                [x as u8, (x >> 8) as u8, (x >> 16) as u8]
            })
            .collect();
        Texture::new(1 << w_log2, 1 << h_log2, texels).unwrap()
    }

    #[test]
    fn a_1024_texture_with_its_mipmaps_fits_the_bank_address_and_every_texel_has_its_own_word() {
        let t = random_texture(10, 10, 3);
        let g = layout(&t);
        let last = g.last().unwrap();
        assert_eq!(last.base + last.words(), 349_526);
        assert!(last.base + last.words() <= 1 << TEXEL_ADDR_BITS);
        // No two texels of any level share a bank word (a non-square texture, where rows of one
        // texel occur).
        let t = random_texture(6, 2, 4);
        let mut seen = std::collections::HashSet::new();
        for g in layout(&t) {
            for y in 0..1 << g.h_log2 {
                for x in 0..1 << g.w_log2 {
                    assert!(seen.insert(g.locate(x, y)), "{g:?} ({x}, {y})");
                }
            }
        }
    }

    #[test]
    fn a_bilinear_footprint_inside_the_texture_reads_each_bank_once_and_at_the_edge_clamp_reads_fewer() {
        let g = layout(&random_texture(4, 4, 5))[0];
        let inside = footprint(g, 5 << 12, 9 << 12, true, Wrap::Repeat);
        assert_eq!(inside.reads(), 4);
        let mut routes = inside.route;
        routes.sort();
        assert_eq!(routes, [0, 1, 2, 3]);
        // Left of the first texel centre and above the first row: clamped to one texel.
        assert_eq!(footprint(g, 0, 0, true, Wrap::ClampToEdge).reads(), 1);
        assert_eq!(footprint(g, 0, 0, true, Wrap::Repeat).reads(), 4);
        assert_eq!(footprint(g, 0, 0, false, Wrap::Repeat).reads(), 1);
    }

    proptest! {
        /// Reading the banks at the footprint and blending is the sampler's colour: every level of
        /// textures from 1x1 to 1024x8, both filters, both wraps, coordinates far outside [0, 1).
        #[test]
        fn the_banked_footprint_reads_what_the_sampler_samples(
            w_log2 in 0u32..=10, h_log2 in 0u32..=3, level in 0usize..11,
            s in any::<i32>(), t in -(4i32 << 16)..(4 << 16), bil in any::<bool>(), clamp in any::<bool>(), seed in any::<u64>(),
        ) {
            let tex = random_texture(w_log2, h_log2, seed);
            let level = level.min(tex.levels.len() - 1);
            let wrap = if clamp { Wrap::ClampToEdge } else { Wrap::Repeat };
            let filter = if bil { Filter::Bilinear } else { Filter::Nearest };
            let b = banks(&tex);
            let f = footprint(layout(&tex)[level], s, t, bil, wrap);
            let got = bilinear(f.texels(&b), f.fx as u32, f.fy as u32);
            prop_assert_eq!(got, tex.sample_level(level, s, t, filter, wrap));
            prop_assert!(f.reads() >= 1 && f.reads() <= tex.texels_read(0, filter));
            for k in 0..TEXTURE_BANKS {
                prop_assert!(f.read[k] || f.addr[k] == 0);
            }
        }
    }
}
