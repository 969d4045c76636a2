//! Number formats of the chipset: the one source of truth that the RTL in `hdl/` implements.
//!
//! Every width here is chosen for a reason that is written next to it. The guiding rules:
//! per-pixel work must be adds and small multiplies (16x16-class, one iCE40 `SB_MAC16` each), and the
//! wide arithmetic is confined to per-triangle setup, where it may take several cycles.
//!
//! | quantity | format | bits | why |
//! |---|---|---|---|
//! | window x, y | signed fixed point S11.8 | 20 | 8 subpixel bits (as Direct3D 10 and later require, and llvmpipe uses). Screen up to 1024x1024 with a guard band of one screen on each side: x in [-W, 2W) px = [-262144, 524288) subpixels, which fits an `i20` (its top is the `i20`'s). |
//! | edge delta dx, dy | signed, subpixels | 21 | difference of two S11.8 values in the guard band: up to 3W*256 = 786432 |
//! | edge function E | signed, subpixel^2 | 44 | `dx*dy` products of 21-bit operands plus one add: < 2^42 in magnitude; 44 bits leave headroom for the incremental stepping inside the clamped bounding box |
//! | twice the area `det` | signed, subpixel^2 | 44 | same arithmetic as E |
//! | depth | unsigned | 24 | the issue prefers 24 bits; 0 = near plane, 2^24-1 = far plane and the clear value |
//! | colour | RGB888 | 3x8 | |
//! | normal component (Phong) | signed Q1.14 | 16 | a unit vector's component in [-1, 1] with 14 fraction bits: a 16x16 multiplier operand |
//! | triangle index | unsigned | `INDEX_BITS` (16) | 0 = background, so 2^16-1 triangles per frame |
//! | reciprocal of det | mantissa r in [2^23, 2^24] and a shift s | 25 + 6 | one reciprocal per triangle (seed 001 eq. 6, Ka). 24 significant bits keep a 640x480 triangle's colour within 1 LSB (see [`Plane`]) |
//! | plane coefficients A, B | signed, 16 fraction bits of the channel's LSB per pixel | 40 | colour gradients up to +/-2^23 LSB/pixel before saturation |
//! | plane constant C | signed, 16 fraction bits | 56 | C = value at pixel (0,0) = v0 - A*x0 - B*y0: needs |A|*2^11 more range than A |
//!
//! Coordinates use the top-left rule and pixel centres at (X + 0.5, Y + 0.5); image row 0 is at the top
//! (window y grows downwards).

/// Subpixel bits of window coordinates (S11.8).
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in subpixel units.
pub const SUBPIXEL_ONE: i32 = 1 << SUBPIXEL_BITS;
/// Half a pixel in subpixel units: the pixel centre offset.
pub const SUBPIXEL_HALF: i32 = SUBPIXEL_ONE / 2;
/// Bits of a window coordinate on the ports (S11.8): [-2^19, 2^19) subpixels, the guard band of
/// the largest screen.
pub const WINDOW_BITS: u32 = 12 + SUBPIXEL_BITS;
pub const WINDOW_MIN: i32 = -(1 << (WINDOW_BITS - 1));
pub const WINDOW_MAX: i32 = (1 << (WINDOW_BITS - 1)) - 1;

/// Largest supported screen width or height in pixels (the RTL's 10-bit pixel counters).
pub const MAX_SCREEN: u32 = 1024;

/// Depth bits.
pub const DEPTH_BITS: u32 = 24;
/// Depth of the far plane, and the value the Z-buffer is cleared to.
pub const DEPTH_MAX: u32 = (1 << DEPTH_BITS) - 1;

/// Default triangle-index width (the RTL parameter's default).
pub const INDEX_BITS_DEFAULT: u32 = 16;
/// The index that marks a background pixel in the I-buffer.
pub const INDEX_BACKGROUND: u32 = 0;

/// Fraction bits of plane coefficients (in units of the channel's LSB).
pub const PLANE_FRAC: u32 = 16;
/// Width of the plane gradients A and B.
pub const PLANE_AB_BITS: u32 = 40;
/// Width of the plane constant C.
pub const PLANE_C_BITS: u32 = 56;

/// Fraction bits of a normal-vector component (Q1.14).
pub const NORMAL_FRAC: u32 = 14;

/// Lights the Color Shader's Phong datapath holds (one light unit each, all working on every pixel).
pub const CS_LIGHTS: usize = 2;
/// Materials the Color Shader's Phong datapath holds (its material memory; TdbS's material field is
/// read through its low `CS_MATERIAL_BITS` bits).
pub const CS_MATERIAL_BITS: u32 = 4;
pub const CS_MATERIALS: usize = 1 << CS_MATERIAL_BITS;
/// Largest log2 of the gloss the Phong datapath squares for (gloss 1..=16: 4 squaring stages).
pub const CS_GLOSS_LOG2_MAX: u32 = 4;

/// Index bits of the reciprocal-square-root seed table: `m[31:24]` of the normalised |n|^2.
pub const RSQRT_TABLE_BITS: u32 = 8;

/// The seed table of [`rsqrt`]: for `i` in 64..=255, `round(2^19 / sqrt(i + 1/2))` = 2^16/sqrt(x) at the
/// middle of the interval `x = m/2^30` in `[i/64, (i+1)/64)`; entries below 64 are never read (0).
pub fn rsqrt_seed(i: u32) -> u32 {
    if (64..256).contains(&i) {
        ((1u64 << 19) as f64 / (i as f64 + 0.5).sqrt()).round() as u32
    } else {
        0
    }
}

/// The reciprocal square root of the Color Shader's normaliser, in the hardware's integer steps.
///
/// Input: `m` in `[2^30, 2^32)`, a squared length normalised by an even left shift. Output
/// `y ~ 2^16 / sqrt(m / 2^30)` in `[2^15 - 2, 2^16]` (17 bits):
/// 1. `y0 = rsqrt_seed(m >> 24)` (a 192-entry table, relative error below 2^-8),
/// 2. one Newton-Raphson step `y1 = y0 (3 - x y0^2) / 2` on 18-bit operands:
///    `t = round(y0^2 / 2^14)`, `p = (m >> 14) * t` (= x y0^2 * 2^34), `e = round((3 * 2^34 - p) / 2^18)`,
///    `y1 = round(y0 * e / 2^17)` (each rounding: add half, shift).
///
/// Its error against `2^16/sqrt(m/2^30)` is checked for every `m >> 14` (the only bits it reads) in
/// `rsqrt_is_within_its_bound_over_the_whole_input_range` (the bound is [`RSQRT_MAX_ERROR`]).
pub fn rsqrt(m: u32) -> u32 {
    debug_assert!(m >= 1 << 30);
    let y0 = rsqrt_seed(m >> 24) as u64;
    let t = (y0 * y0 + (1 << 13)) >> 14;
    let p = (m as u64 >> 14) * t;
    let e = ((3u64 << 34) - p + (1 << 17)) >> 18;
    ((y0 * e + (1 << 16)) >> 17) as u32
}

/// The largest error of [`rsqrt`], in units of its last place (2^-16 of 1/sqrt(x)); measured over the
/// whole input range by the test named there.
pub const RSQRT_MAX_ERROR: f64 = 2.0;

/// Significant bits of the reciprocal mantissa: r = floor(2^(s+RECIP_BITS) / det), in [2^23, 2^24].
pub const RECIP_BITS: u32 = 24;

/// Screen size, checked against the formats.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Screen {
    pub width: u32,
    pub height: u32,
}

impl Screen {
    /// A screen of `width` x `height` pixels; both must be 1..=[`MAX_SCREEN`].
    pub fn new(width: u32, height: u32) -> Result<Screen, String> {
        if width == 0 || height == 0 || width > MAX_SCREEN || height > MAX_SCREEN {
            return Err(format!(
                "screen size {width}x{height} is not supported: width and height must be 1..={MAX_SCREEN}"
            ));
        }
        Ok(Screen { width, height })
    }
    pub fn pixels(&self) -> usize {
        (self.width * self.height) as usize
    }
    /// Guard band in subpixels: a vertex must satisfy `gb_min <= x < gb_max` (one screen beyond each edge).
    pub fn guard_x(&self) -> (i32, i32) {
        (-(self.width as i32) * SUBPIXEL_ONE, 2 * self.width as i32 * SUBPIXEL_ONE)
    }
    pub fn guard_y(&self) -> (i32, i32) {
        (-(self.height as i32) * SUBPIXEL_ONE, 2 * self.height as i32 * SUBPIXEL_ONE)
    }
}

/// The largest triangle index an index width allows (0 is background).
pub fn max_index(index_bits: u32) -> u32 {
    ((1u64 << index_bits) - 1) as u32
}

/// A vertex in window coordinates: x, y in S11.8 subpixels (row 0 at the top), depth in 24 bits.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub struct WinVertex {
    pub x: i32,
    pub y: i32,
    pub z: u32,
}

/// Round to nearest, ties upwards, dividing by 2^n (n >= 1), on i128: what the RTL does with
/// "add half, arithmetic shift right".
pub fn round_shift(x: i128, n: u32) -> i128 {
    if n == 0 {
        x
    } else {
        (x + (1i128 << (n - 1))) >> n
    }
}

/// Saturate to a signed two's-complement range of `bits` bits.
pub fn saturate(x: i128, bits: u32) -> i64 {
    let max = (1i128 << (bits - 1)) - 1;
    let min = -(1i128 << (bits - 1));
    x.clamp(min, max) as i64
}

/// The reciprocal of a positive `det` in the form the hardware computes: `r = floor(2^(s+24) / det)`
/// with `s = floor(log2 det)`, so `1/det = r * 2^-(s+24)` and r is in [2^23, 2^24].
///
/// The RTL computes r with a restoring division of the normalised divisor: [`RECIP_BITS`] + 1 = 25
/// fixed steps of compare-and-subtract, one quotient bit per step, pipelined three steps per clock
/// (one request per clock). Exactly one per triangle. Error bound: r is the exact floor, so
/// `0 <= 1/det - r * 2^-(s+24) < 2^-(s+24)` (relative error below 2^-23).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Recip {
    pub mant: u32,
    pub shift: u32,
}

/// Compute [`Recip`] for `det > 0` step by step as the restoring divider does.
pub fn reciprocal(det: i64) -> Recip {
    assert!(det > 0, "reciprocal of a non-positive determinant");
    let s = 63 - det.leading_zeros();
    // Restoring division of 2^(s+24) by det: the dividend's 1 bit enters at the top, then 24 zero bits.
    // Partial remainder starts at 2^s (which is < 2*det), one quotient bit per step.
    let d = det as u64;
    let mut rem: u64 = 1u64 << s;
    let mut q: u32 = 0;
    for _ in 0..=RECIP_BITS {
        q <<= 1;
        if rem >= d {
            rem -= d;
            q |= 1;
        }
        rem <<= 1;
    }
    // After RECIP_BITS+1 steps q = floor(2^(s+24)/det) (the first step compares 2^s with det).
    Recip { mant: q, shift: s }
}

/// A linear function over the screen, `v(X, Y) = (C + A*X + B*Y) / 2^16` at pixel centre (X+0.5, Y+0.5),
/// with X, Y integer pixel coordinates: how TdbS stores colour, depth and normal planes.
///
/// Setup (seed 001 eqs. 6-7, with Ka the reciprocal of twice the area):
/// `A = 256 * (dv10*dy20 - dv20*dy10) / det`, `B = 256 * (dv20*dx10 - dv10*dx20) / det` (per pixel; the
/// 256 converts from subpixels), both rounded to 16 fraction bits and saturated to 40 bits; then
/// `C = v0 + A*(128 - x0)/256 + B*(128 - y0)/256` so that the plane passes through vertex 0 (rounded, 56 bits).
///
/// Accuracy: for a triangle inside 640x480 with gradients below 2^12 LSB/pixel (every triangle at least
/// 1/16 pixel high), the error of v at any pixel is at most
/// 640*(2^-17 + 2^12*2^-23) + 2^-17 < 0.33 LSB before the final rounding: within 1 LSB of exact evaluation.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub struct Plane {
    pub a: i64,
    pub b: i64,
    pub c: i64,
}

impl Plane {
    /// A constant plane (flat shading).
    pub fn constant(v: i64) -> Plane {
        Plane { a: 0, b: 0, c: saturate((v as i128) << PLANE_FRAC, PLANE_C_BITS) }
    }

    /// Set up the plane through the values `v` at the three window vertices `p` (det > 0 for this order).
    pub fn setup(p: &[WinVertex; 3], v: [i64; 3], det: i64, r: Recip) -> Plane {
        let dx10 = (p[1].x - p[0].x) as i128;
        let dy10 = (p[1].y - p[0].y) as i128;
        let dx20 = (p[2].x - p[0].x) as i128;
        let dy20 = (p[2].y - p[0].y) as i128;
        let dv10 = (v[1] - v[0]) as i128;
        let dv20 = (v[2] - v[0]) as i128;
        let na = dv10 * dy20 - dv20 * dy10;
        let nb = dv20 * dx10 - dv10 * dx20;
        let _ = det;
        // A = na * 256 * 2^16 / det = na * r * 2^(24 - s - 24): shift right by s.
        let sh = r.shift + RECIP_BITS - (PLANE_FRAC + SUBPIXEL_BITS);
        let a = saturate(round_shift(na * r.mant as i128, sh), PLANE_AB_BITS);
        let b = saturate(round_shift(nb * r.mant as i128, sh), PLANE_AB_BITS);
        let cx = a as i128 * (SUBPIXEL_HALF - p[0].x) as i128 + b as i128 * (SUBPIXEL_HALF - p[0].y) as i128;
        let c = ((v[0] as i128) << PLANE_FRAC) + round_shift(cx, SUBPIXEL_BITS);
        Plane { a, b, c: saturate(c, PLANE_C_BITS) }
    }

    /// The raw value at pixel (X, Y), 16 fraction bits.
    pub fn raw(&self, x: u32, y: u32) -> i64 {
        self.c + self.a * x as i64 + self.b * y as i64
    }

    /// The value at pixel (X, Y) rounded to an integer.
    pub fn eval(&self, x: u32, y: u32) -> i64 {
        round_shift(self.raw(x, y) as i128, PLANE_FRAC) as i64
    }

    /// The value clamped to 0..=max (colour channels: max 255; depth: DEPTH_MAX).
    pub fn eval_clamped(&self, x: u32, y: u32, max: i64) -> i64 {
        self.eval(x, y).clamp(0, max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reciprocal_is_floor_of_two_to_the_s_plus_24_over_det() {
        for det in [1i64, 2, 3, 5, 7, 255, 256, 1000, 65535, 65536, 123456789, (1 << 34) - 1, (1 << 42) - 1] {
            let r = reciprocal(det);
            let exact = (1u128 << (r.shift + RECIP_BITS)) / det as u128;
            assert_eq!(r.mant as u128, exact, "det {det}");
            assert!(r.mant >= 1 << 23 && r.mant <= 1 << 24, "det {det}: mant {}", r.mant);
        }
    }

    /// The error bound of the RC's reciprocal (pipelined in the RTL, one station per three steps):
    /// `0 <= 1/det - mant * 2^-(s+24) < 2^-(s+24)`, i.e. the quotient is the exact floor, relative error
    /// below 2^-23. Checked for every det below 2^20, at both sides of every power of two up to the
    /// port's 2^44, and on 200 000 random values over the whole range.
    #[test]
    fn reciprocal_is_the_exact_floor_over_the_whole_input_range() {
        let check = |det: i64| {
            let r = reciprocal(det);
            let s = 63 - det.leading_zeros();
            let exact = (1u128 << (s + RECIP_BITS)) / det as u128;
            assert_eq!((r.mant as u128, r.shift), (exact, s), "det {det}");
            // mant * det <= 2^(s+24) < (mant + 1) * det
            let p = r.mant as u128 * det as u128;
            assert!(p <= 1u128 << (s + RECIP_BITS) && p + det as u128 > 1u128 << (s + RECIP_BITS), "det {det}");
        };
        (1..1i64 << 20).for_each(check);
        for k in 1..44 {
            for d in -3i64..=3 {
                let det = (1i64 << k) + d;
                if det > 0 && det < 1 << 44 {
                    check(det);
                }
            }
        }
        let mut x = 0x2545f4914f6cdd1du64;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            check(1 + (x % ((1 << 44) - 1)) as i64);
        }
    }

    #[test]
    fn rsqrt_is_within_its_bound_over_the_whole_input_range() {
        // rsqrt reads only m >> 14: every value of that is tried, at both ends of its interval.
        let mut worst = 0.0f64;
        for hi in (1u32 << 16)..(1u32 << 18) {
            for m in [hi << 14, (hi << 14) | 0x3fff] {
                let exact = 65536.0 / (m as f64 / (1u64 << 30) as f64).sqrt();
                let y = rsqrt(m);
                assert!(y >= (1 << 15) - 2 && y <= 1 << 16, "m {m:#x}: y {y}");
                worst = worst.max((y as f64 - exact).abs());
            }
        }
        assert!(worst <= RSQRT_MAX_ERROR, "worst error {worst} ulp");
        eprintln!("rsqrt: worst error {worst:.3} ulp of 2^-16");
    }

    #[test]
    fn round_shift_rounds_half_up_for_both_signs() {
        assert_eq!(round_shift(3, 1), 2);
        assert_eq!(round_shift(-3, 1), -1);
        assert_eq!(round_shift(-4, 1), -2);
        assert_eq!(round_shift(5, 2), 1);
        assert_eq!(round_shift(6, 2), 2);
    }

    #[test]
    fn screen_rejects_sizes_outside_the_formats() {
        assert!(Screen::new(0, 10).is_err());
        assert!(Screen::new(1025, 10).unwrap_err().contains("1025x10"));
        assert!(Screen::new(1024, 1024).is_ok());
    }

    #[test]
    fn guard_band_fits_the_window_format() {
        let s = Screen::new(MAX_SCREEN, MAX_SCREEN).unwrap();
        let (lo, hi) = s.guard_x();
        assert!(lo >= WINDOW_MIN && hi - 1 <= WINDOW_MAX);
        assert_eq!(hi - 1, WINDOW_MAX, "the guard band of the largest screen reaches the top of the format");
    }
}
