//! Texture sampling, bit-exact (issue 17, item 3): the texel lookup the Color Shader will do at
//! scan-out, after it has turned the interpolated texture coordinates into `s`, `t` and a level of
//! detail, and [`load`] for a material's `map_Kd` image (PNG or JPEG). Not yet used by the renderer:
//! the planes that carry texture coordinates, the CS's texture port and the textured scenes are still
//! to come (see issue 17's note).
//!
//! | quantity | format | why |
//! |---|---|---|
//! | texel | RGB888 | the framebuffer's colour format |
//! | texture size | 2^w x 2^h, w, h in 0..=10 | powers of two make addressing a shift and a mask; 1024 is the minimum |
//! | coordinate s, t | signed Q15.16 of the texture's size (65536 = one whole texture) | 16 fraction bits address a 1024-texel texture with 6 bits of sub-texel position left for the weights; 15 integer bits let a floor repeat the texture thousands of times |
//! | bilinear weight | unsigned 8-bit fraction (0..=255 of 256) | the products texel x weight x weight stay within 8x9x9 bits, small multiplies |
//! | level of detail | unsigned Q4.4 | the level (0..=10) and 16 steps between two levels for trilinear |
//!
//! Texel centres are at (i + 0.5) / size, as in OpenGL. Mipmaps are built once per texture by the
//! host: each level is the rounded 2x2 box average of the one above, a dimension of 1 stays 1.

use std::fmt;

/// Largest log2 of a texture's width or height (1024 texels).
pub const TEXTURE_MAX_LOG2: u32 = 10;
/// Fraction bits of a texture coordinate: 1 << TEXCOORD_FRAC is one whole texture.
pub const TEXCOORD_FRAC: u32 = 16;
/// Fraction bits of a bilinear weight.
pub const WEIGHT_FRAC: u32 = 8;
/// Fraction bits of the level of detail.
pub const LOD_FRAC: u32 = 4;

/// What a texture coordinate outside [0, 1) does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Wrap {
    /// The texture repeats (OpenGL's GL_REPEAT).
    Repeat,
    /// The edge texels continue (GL_CLAMP_TO_EDGE).
    ClampToEdge,
}

/// How a texel colour is formed from the footprint.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Filter {
    Nearest,
    Bilinear,
    /// Bilinear in the two levels around the level of detail, blended by its fraction.
    Trilinear,
}

/// Why an image cannot be a texture.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TextureError {
    NotPowerOfTwo { width: u32, height: u32 },
    TooLarge { width: u32, height: u32 },
    Empty,
    WrongLength { expected: usize, got: usize },
}

impl fmt::Display for TextureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let max = 1u32 << TEXTURE_MAX_LOG2;
        match self {
            TextureError::NotPowerOfTwo { width, height } => {
                write!(f, "texture is {width}x{height}: width and height must be powers of two")
            }
            TextureError::TooLarge { width, height } => {
                write!(f, "texture is {width}x{height}: at most {max}x{max} texels")
            }
            TextureError::Empty => write!(f, "texture has no texels"),
            TextureError::WrongLength { expected, got } => {
                write!(f, "texture data has {got} texels where its size needs {expected}")
            }
        }
    }
}

impl std::error::Error for TextureError {}

/// One mipmap level: `1 << w_log2` by `1 << h_log2` texels, row-major, row 0 at t = 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Level {
    pub w_log2: u32,
    pub h_log2: u32,
    pub texels: Vec<[u8; 3]>,
}

impl Level {
    fn texel(&self, x: i64, y: i64) -> [u8; 3] {
        self.texels[((y as usize) << self.w_log2) + x as usize]
    }

    /// The next smaller level: the rounded average of each 2x2 block (of each 2x1 or 1x2 block where
    /// a dimension is already 1).
    fn halved(&self) -> Level {
        let w_log2 = self.w_log2.saturating_sub(1);
        let h_log2 = self.h_log2.saturating_sub(1);
        let (sx, sy) = ((self.w_log2 > 0) as usize, (self.h_log2 > 0) as usize);
        let n = (1u32 << sx) * (1u32 << sy);
        let mut texels = Vec::with_capacity(1 << (w_log2 + h_log2));
        for y in 0..1usize << h_log2 {
            for x in 0..1usize << w_log2 {
                let mut sum = [0u32; 3];
                for dy in 0..=sy {
                    for dx in 0..=sx {
                        let t = self.texels[(((y << sy) + dy) << self.w_log2) + (x << sx) + dx];
                        for c in 0..3 {
                            sum[c] += t[c] as u32;
                        }
                    }
                }
                texels.push(sum.map(|s| ((s + n / 2) / n) as u8));
            }
        }
        Level { w_log2, h_log2, texels }
    }
}

/// A texture and its mipmaps, level 0 first, down to 1x1.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Texture {
    pub levels: Vec<Level>,
}

impl Texture {
    /// A texture of `width` x `height` RGB texels (row-major, row 0 first) with its mipmaps.
    pub fn new(width: u32, height: u32, texels: Vec<[u8; 3]>) -> Result<Texture, TextureError> {
        if width == 0 || height == 0 {
            return Err(TextureError::Empty);
        }
        if !width.is_power_of_two() || !height.is_power_of_two() {
            return Err(TextureError::NotPowerOfTwo { width, height });
        }
        if width > 1 << TEXTURE_MAX_LOG2 || height > 1 << TEXTURE_MAX_LOG2 {
            return Err(TextureError::TooLarge { width, height });
        }
        let expected = (width * height) as usize;
        if texels.len() != expected {
            return Err(TextureError::WrongLength { expected, got: texels.len() });
        }
        let mut levels = vec![Level { w_log2: width.trailing_zeros(), h_log2: height.trailing_zeros(), texels }];
        while levels.last().map_or(false, |l| l.w_log2 + l.h_log2 > 0) {
            let next = levels.last().unwrap().halved();
            levels.push(next);
        }
        Ok(Texture { levels })
    }

    /// The colour at (s, t) in level `level` (clamped to the last level).
    pub fn sample_level(&self, level: usize, s: i32, t: i32, filter: Filter, wrap: Wrap) -> [u8; 3] {
        let l = &self.levels[level.min(self.levels.len() - 1)];
        match filter {
            Filter::Nearest => {
                let x = address(s as i64 >> (TEXCOORD_FRAC - l.w_log2), l.w_log2, wrap);
                let y = address(t as i64 >> (TEXCOORD_FRAC - l.h_log2), l.h_log2, wrap);
                l.texel(x, y)
            }
            Filter::Bilinear | Filter::Trilinear => {
                // Position in texels with 16 fraction bits, relative to the texel centres.
                let half = 1i64 << (TEXCOORD_FRAC - 1);
                let px = ((s as i64) << l.w_log2) - half;
                let py = ((t as i64) << l.h_log2) - half;
                let (x0, y0) = (px >> TEXCOORD_FRAC, py >> TEXCOORD_FRAC);
                let fx = ((px >> (TEXCOORD_FRAC - WEIGHT_FRAC)) & 0xff) as u32;
                let fy = ((py >> (TEXCOORD_FRAC - WEIGHT_FRAC)) & 0xff) as u32;
                let (xa, xb) = (address(x0, l.w_log2, wrap), address(x0 + 1, l.w_log2, wrap));
                let (ya, yb) = (address(y0, l.h_log2, wrap), address(y0 + 1, l.h_log2, wrap));
                bilinear([l.texel(xa, ya), l.texel(xb, ya), l.texel(xa, yb), l.texel(xb, yb)], fx, fy)
            }
        }
    }

    /// The levels a sample at level of detail `lod` (Q4.4) reads: the level `lod` rounds down to (at
    /// most the last), and for trilinear with a fraction f != 0 below the last level, the next level
    /// and f (its weight, in sixteenths).
    pub fn levels_for(&self, lod: u8, filter: Filter) -> (usize, Option<(usize, u32)>) {
        let last = self.levels.len() - 1;
        let level = ((lod >> LOD_FRAC) as usize).min(last);
        let f = (lod & ((1 << LOD_FRAC) - 1)) as u32;
        let second = filter == Filter::Trilinear && f != 0 && ((lod >> LOD_FRAC) as usize) < last;
        (level, second.then_some((level + 1, f)))
    }

    /// The colour at (s, t) with level of detail `lod` (Q4.4). Nearest and bilinear read the level
    /// `lod` rounds down to; trilinear blends it with the next by the fraction ([`Texture::levels_for`]).
    pub fn sample(&self, s: i32, t: i32, lod: u8, filter: Filter, wrap: Wrap) -> [u8; 3] {
        let (level, second) = self.levels_for(lod, filter);
        match (filter, second) {
            (Filter::Nearest, _) => self.sample_level(level, s, t, filter, wrap),
            (_, None) => self.sample_level(level, s, t, Filter::Bilinear, wrap),
            (_, Some((next, f))) => {
                let a = self.sample_level(level, s, t, Filter::Bilinear, wrap);
                let b = self.sample_level(next, s, t, Filter::Bilinear, wrap);
                let one = 1u32 << LOD_FRAC;
                let mut out = [0u8; 3];
                for c in 0..3 {
                    out[c] = ((a[c] as u32 * (one - f) + b[c] as u32 * f + one / 2) >> LOD_FRAC) as u8;
                }
                out
            }
        }
    }
}

/// The bilinear blend of a 2x2 footprint `[t00, t10, t01, t11]` (x then y) with 8-bit weights `fx`,
/// `fy` (0..=255, the fraction towards t10 and t01): the exact weighted sum, rounded to nearest once.
pub fn bilinear(t: [[u8; 3]; 4], fx: u32, fy: u32) -> [u8; 3] {
    let one = 1u32 << WEIGHT_FRAC;
    let mut out = [0u8; 3];
    for c in 0..3 {
        let sum = t[0][c] as u32 * (one - fx) * (one - fy) + t[1][c] as u32 * fx * (one - fy) + t[2][c] as u32 * (one - fx) * fy + t[3][c] as u32 * fx * fy;
        out[c] = ((sum + (1 << (2 * WEIGHT_FRAC - 1))) >> (2 * WEIGHT_FRAC)) as u8;
    }
    out
}

impl Texture {
    /// Texels [`Texture::sample`] reads for a pixel at level of detail `lod`: one (nearest), four
    /// (bilinear), eight (trilinear between two levels) or four (trilinear at a whole level or at the
    /// last level, where it is bilinear).
    pub fn texels_read(&self, lod: u8, filter: Filter) -> u32 {
        match (filter, self.levels_for(lod, filter).1) {
            (Filter::Nearest, _) => 1,
            (_, None) => 4,
            (_, Some(_)) => 8,
        }
    }

    /// Level 0's width and height.
    pub fn size(&self) -> (u32, u32) {
        (1 << self.levels[0].w_log2, 1 << self.levels[0].h_log2)
    }
}

/// The built-in texture: a 256x256 checkerboard of 8x8 squares, cream and brick red, with a thin dark
/// line along each square's top and left edge so that magnification and filtering show.
pub fn checker() -> Texture {
    let (cream, brick, line) = ([236, 226, 200], [170, 60, 40], [40, 36, 32]);
    let texels = (0..256u32 * 256)
        .map(|i| {
            let (x, y) = (i % 256, i / 256);
            if x % 32 == 0 || y % 32 == 0 {
                line
            } else if (x / 32 + y / 32) % 2 == 0 {
                cream
            } else {
                brick
            }
        })
        .collect();
    Texture::new(256, 256, texels).expect("256x256 is a valid texture size")
}

/// A texture from a PNG or JPEG file (any colour type, taken as RGB8: alpha is dropped), with its
/// mipmaps. Errors name the file: unreadable, not an image, or a size [`Texture::new`] refuses.
pub fn load(path: &std::path::Path) -> Result<Texture, String> {
    let image = image::ImageReader::open(path)
        .and_then(|r| r.with_guessed_format())
        .map_err(|e| format!("{}: cannot read texture: {e}", path.display()))?
        .decode()
        .map_err(|e| format!("{}: not a readable PNG or JPEG image: {e}", path.display()))?
        .to_rgb8();
    let (width, height) = image.dimensions();
    let texels = image.pixels().map(|p| p.0).collect();
    Texture::new(width, height, texels).map_err(|e| format!("{}: {e}", path.display()))
}

/// Texel index `i` of a dimension of `1 << log2` texels, wrapped or clamped.
fn address(i: i64, log2: u32, wrap: Wrap) -> i64 {
    let n = 1i64 << log2;
    match wrap {
        Wrap::Repeat => i & (n - 1),
        Wrap::ClampToEdge => i.clamp(0, n - 1),
    }
}

/// The level of detail for a footprint of `rho` texels per pixel (16 fraction bits; the larger of
/// the coordinates' derivatives scaled to level 0's texels): log2(rho) in Q4.4, 0 when magnified,
/// the fraction read linearly from the four bits below the leading one (error below 0.09 + 1/16).
pub fn lod_q4(rho: u64) -> u8 {
    let one = 1u64 << TEXCOORD_FRAC;
    if rho <= one {
        return 0;
    }
    let msb = 63 - rho.leading_zeros();
    let int = msb - TEXCOORD_FRAC;
    let frac = ((rho >> (msb - LOD_FRAC)) & ((1 << LOD_FRAC) - 1)) as u32;
    let lod = (int << LOD_FRAC) | frac;
    lod.min(TEXTURE_MAX_LOG2 << LOD_FRAC) as u8
}

/// OpenGL's MODULATE: texel x colour / 255, rounded to nearest, per channel.
pub fn modulate(texel: [u8; 3], colour: [u8; 3]) -> [u8; 3] {
    let mut out = [0u8; 3];
    for c in 0..3 {
        let p = texel[c] as u32 * colour[c] as u32 + 128;
        out[c] = ((p + (p >> 8)) >> 8) as u8;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn grey(values: &[u8]) -> Vec<[u8; 3]> {
        values.iter().map(|&v| [v, v, v]).collect()
    }

    /// The coordinate of texel i's centre in a dimension of n texels.
    fn centre(i: i32, n: i32) -> i32 {
        ((2 * i + 1) << TEXCOORD_FRAC) / (2 * n)
    }

    fn temp_dir(tag: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("golden-texture-{tag}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn png_and_jpeg_files_load_as_textures_and_bad_ones_are_errors_naming_the_file() {
        let dir = temp_dir("load");
        let png = dir.join("t.png");
        let texels = [[255u8, 0, 0], [0, 255, 0], [0, 0, 255], [9, 99, 199]];
        image::RgbImage::from_fn(2, 2, |x, y| image::Rgb(texels[(2 * y + x) as usize])).save(&png).unwrap();
        let t = load(&png).unwrap();
        assert_eq!(t.levels[0].texels, texels.to_vec());
        assert_eq!(t.levels.len(), 2);
        // JPEG is lossy: a flat grey comes back within a few steps.
        let jpg = dir.join("t.jpg");
        image::RgbImage::from_pixel(8, 4, image::Rgb([128, 128, 128])).save(&jpg).unwrap();
        let t = load(&jpg).unwrap();
        assert_eq!((t.levels[0].w_log2, t.levels[0].h_log2), (3, 2));
        assert!(t.levels[0].texels.iter().all(|c| c.iter().all(|&v| v.abs_diff(128) <= 3)), "{:?}", t.levels[0].texels);
        // Not a power of two, not an image, missing.
        let odd = dir.join("odd.png");
        image::RgbImage::new(3, 2).save(&odd).unwrap();
        let e = load(&odd).unwrap_err();
        assert!(e.contains("odd.png") && e.contains("3x2") && e.contains("powers of two"), "{e}");
        let junk = dir.join("junk.png");
        std::fs::write(&junk, b"not an image").unwrap();
        let e = load(&junk).unwrap_err();
        assert!(e.contains("junk.png") && e.contains("not a readable"), "{e}");
        let e = load(&dir.join("gone.png")).unwrap_err();
        assert!(e.contains("gone.png") && e.contains("cannot read"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn sizes_that_are_not_powers_of_two_too_large_or_wrongly_filled_are_refused_by_name() {
        assert_eq!(Texture::new(3, 4, grey(&[0; 12])), Err(TextureError::NotPowerOfTwo { width: 3, height: 4 }));
        assert_eq!(Texture::new(2048, 1, grey(&[0; 2048])), Err(TextureError::TooLarge { width: 2048, height: 1 }));
        assert_eq!(Texture::new(0, 4, vec![]), Err(TextureError::Empty));
        assert_eq!(Texture::new(2, 2, grey(&[0; 3])), Err(TextureError::WrongLength { expected: 4, got: 3 }));
        assert!(TextureError::NotPowerOfTwo { width: 3, height: 4 }.to_string().contains("3x4"));
        assert!(Texture::new(1024, 1024, vec![[0; 3]; 1 << 20]).is_ok());
    }

    #[test]
    fn mipmaps_halve_down_to_one_texel_averaging_blocks_rounded() {
        // 4x2: rows [0 1 2 3] and [4 5 6 7]. Level 1 (2x1): (0+1+4+5)/4 = 2.5 -> 3, (2+3+6+7)/4 = 4.5 -> 5.
        // Level 2 (1x1): (3+5)/2 = 4.
        let t = Texture::new(4, 2, grey(&[0, 1, 2, 3, 4, 5, 6, 7])).unwrap();
        let dims: Vec<(u32, u32)> = t.levels.iter().map(|l| (l.w_log2, l.h_log2)).collect();
        assert_eq!(dims, vec![(2, 1), (1, 0), (0, 0)]);
        assert_eq!(t.levels[1].texels, grey(&[3, 5]));
        assert_eq!(t.levels[2].texels, grey(&[4]));
        assert_eq!(Texture::new(1024, 2, vec![[9; 3]; 2048]).unwrap().levels.len(), 11);
    }

    #[test]
    fn nearest_reads_the_texel_under_the_coordinate_and_repeat_and_clamp_differ_outside() {
        let t = Texture::new(4, 1, grey(&[10, 20, 30, 40])).unwrap();
        for i in 0..4 {
            let s = centre(i, 4);
            assert_eq!(t.sample(s, 0, 0, Filter::Nearest, Wrap::Repeat)[0], 10 * (i as u8 + 1));
            // One whole texture further is the same texel when repeating.
            assert_eq!(t.sample(s + (1 << 16), 0, 0, Filter::Nearest, Wrap::Repeat)[0], 10 * (i as u8 + 1));
        }
        // Just left of 0: the last texel when repeating, the first when clamping.
        assert_eq!(t.sample(-1, 0, 0, Filter::Nearest, Wrap::Repeat)[0], 40);
        assert_eq!(t.sample(-1, 0, 0, Filter::Nearest, Wrap::ClampToEdge)[0], 10);
        assert_eq!(t.sample(3 << 16, 0, 0, Filter::Nearest, Wrap::ClampToEdge)[0], 40);
    }

    #[test]
    fn bilinear_is_the_texel_at_its_centre_the_rounded_mean_halfway_and_wraps_at_the_edge() {
        let t = Texture::new(4, 1, grey(&[10, 20, 30, 41])).unwrap();
        for i in 0..4 {
            assert_eq!(t.sample(centre(i, 4), 0, 0, Filter::Bilinear, Wrap::Repeat), t.levels[0].texels[i as usize]);
        }
        // Halfway between texels 2 and 3 (s = 3/4): (30 + 41) / 2 = 35.5 -> 36.
        assert_eq!(t.sample(3 << 14, 0, 0, Filter::Bilinear, Wrap::Repeat)[0], 36);
        // At s = 0, halfway between texel 3 (wrapped) and texel 0: (41 + 10) / 2 = 25.5 -> 26; clamped: 10.
        assert_eq!(t.sample(0, 0, 0, Filter::Bilinear, Wrap::Repeat)[0], 26);
        assert_eq!(t.sample(0, 0, 0, Filter::Bilinear, Wrap::ClampToEdge)[0], 10);
    }

    #[test]
    fn trilinear_blends_two_levels_by_the_lod_fraction_and_stops_at_the_last_level() {
        // 2x1 [0, 200]: level 1 is [100]. At texel 0's centre level 0 gives 0, level 1 gives 100.
        let t = Texture::new(2, 1, grey(&[0, 200])).unwrap();
        let s = centre(0, 2);
        assert_eq!(t.sample(s, 0, 0, Filter::Trilinear, Wrap::ClampToEdge)[0], 0);
        assert_eq!(t.sample(s, 0, 4, Filter::Trilinear, Wrap::ClampToEdge)[0], 25); // 100 * 4/16
        assert_eq!(t.sample(s, 0, 8, Filter::Trilinear, Wrap::ClampToEdge)[0], 50);
        assert_eq!(t.sample(s, 0, 16, Filter::Trilinear, Wrap::ClampToEdge)[0], 100);
        assert_eq!(t.sample(s, 0, 0xff, Filter::Trilinear, Wrap::ClampToEdge)[0], 100);
        // Bilinear at lod 1.5 reads level 1 only.
        assert_eq!(t.sample(s, 0, 24, Filter::Bilinear, Wrap::ClampToEdge)[0], 100);
    }

    #[test]
    fn modulate_is_the_product_over_255_rounded_for_every_pair() {
        for a in 0..=255u32 {
            for b in 0..=255u32 {
                let exact = ((a * b) as f64 / 255.0).round() as u8;
                assert_eq!(modulate([a as u8, 0, 0], [b as u8, 0, 0])[0], exact, "{a} x {b}");
            }
        }
    }

    #[test]
    fn the_level_of_detail_is_log2_of_the_footprint_within_its_stated_error() {
        assert_eq!(lod_q4(1 << 15), 0);
        assert_eq!(lod_q4(1 << 16), 0);
        assert_eq!(lod_q4(1 << 17), 16);
        assert_eq!(lod_q4(1 << 30), (TEXTURE_MAX_LOG2 << LOD_FRAC) as u8);
        let mut rho = 1u64 << 16;
        while rho < 1 << 26 {
            let exact = (rho as f64 / 65536.0).log2();
            let got = lod_q4(rho) as f64 / 16.0;
            assert!(got <= exact + 1e-9 && exact - got < 0.09 + 1.0 / 16.0, "rho {rho}: {got} vs {exact}");
            rho += rho / 97 + 1;
        }
    }

    proptest! {
        /// Bilinear filtering is the same filter in f64 rounded to nearest (weights taken at 8 bits).
        #[test]
        fn bilinear_is_an_f64_filter_rounded_to_nearest(texels in proptest::collection::vec(any::<u8>(), 16),
                                                       s in -(1i32 << 17)..(1i32 << 17), t in -(1i32 << 17)..(1i32 << 17)) {
            let tex = Texture::new(4, 4, grey(&texels)).unwrap();
            let got = tex.sample(s, t, 0, Filter::Bilinear, Wrap::Repeat)[0] as f64;
            let px = s as f64 / 65536.0 * 4.0 - 0.5;
            let py = t as f64 / 65536.0 * 4.0 - 0.5;
            let (x0, y0) = (px.floor(), py.floor());
            // The weights at 8 bits, as the filter takes them (truncated).
            let (fx, fy) = (((px - x0) * 256.0).floor() / 256.0, ((py - y0) * 256.0).floor() / 256.0);
            let at = |x: f64, y: f64| texels[((y as i64).rem_euclid(4) * 4 + (x as i64).rem_euclid(4)) as usize] as f64;
            let exact = at(x0, y0) * (1.0 - fx) * (1.0 - fy) + at(x0 + 1.0, y0) * fx * (1.0 - fy)
                + at(x0, y0 + 1.0) * (1.0 - fx) * fy + at(x0 + 1.0, y0 + 1.0) * fx * fy;
            prop_assert!((got - exact).abs() <= 0.5 + 1e-9, "got {} exact {}", got, exact);
        }

        /// A texture of one colour gives that colour everywhere, with every filter and wrap.
        #[test]
        fn a_uniform_texture_samples_to_its_colour_everywhere(c in any::<[u8; 3]>(), s in any::<i32>(), t in any::<i32>(), lod in any::<u8>()) {
            let tex = Texture::new(8, 4, vec![c; 32]).unwrap();
            for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
                for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
                    prop_assert_eq!(tex.sample(s, t, lod, filter, wrap), c);
                }
            }
        }
    }
}
