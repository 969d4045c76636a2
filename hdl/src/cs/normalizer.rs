//! `normalizer`: the Color Shader's per-pixel normalisation of the interpolated normal (Phong, seed 001
//! §3.3: the lower pipeline carries vertex normals; the CS lights each visible pixel). A pipeline with
//! no stalls: a new normal every clock, its unit vector [`NORMALIZER_LATENCY`] clocks later.
//! Bit-exact with `golden::shade::normalize_q14` (the reciprocal square root is `golden::format::rsqrt`).
//!
//! ```text
//!                +-----------------------------------------------------------------+
//!  n_x, n_y, --->| N1  n_k^2 (3 squares 16 b, in logic)                            |
//!  n_z (Q1.14,   | N2  len2 = sum (32 b)                                           |
//!  16 b signed)  | N3  k = lz(len2)/2, m = len2 << 2k in [2^30, 2^32), zero flag   |
//!                | N4  seed table address m[31:24] (seed_rom, 256 x 34 ROM: y0, t) |
//!                | N5  y0, t = round(y0^2 / 2^14) from the ROM                     |
//!                | N6  p = (m >> 14) * t            (18 x 18)                      |
//!                | N7  e = round((3*2^34 - p) / 2^18)                              |
//!                | N8  y0 * e                       (16 x 18)                      |
//!                | N9  y1 = round(y0 e / 2^17): 2^16/sqrt(m/2^30), 17 b            |
//!                | N10 q_k = n_k * y1               (3 products 16 x 18)           |
//!                | N11 r_k = (q_k << k) + 2^16                                     |
//!                | N12 u_k = sat16(r_k >> 17), 0 if len2 = 0                       |--> u_x, u_y, u_z
//!  clock ------->|                                                                 |    (Q1.14, unit)
//!                +-----------------------------------------------------------------+
//! ```
//!
//! Why this form: `u = n / |n|` needs one reciprocal square root per pixel at one pixel per clock. An
//! even left shift brings `|n|^2` into `[1, 4)` (as `m / 2^30`), where a 192-entry table (index
//! `m[31:24]`) is good to 2^-8 and one Newton-Raphson step `y (3 - x y^2) / 2` to 1.9 units of 2^-16
//! over every input (`golden::format::tests`); the shift comes back as a left shift by k of the product.
//! All products fit 18x18 multipliers; `y0^2` is stored beside `y0` in the ROM. The three squares of N1
//! are in LUTs (`SquareLogicS`, 610 LUT4 each on the ECP5), so that the chipset fits the LFE5U-45F's 72
//! MULT18X18D (issue 15 item 5).

use crate::common::{signed_bit_cast_safe, MulS, MulU, SquareLogicS};
use rust_hdl::prelude::*;

/// Clocks from `n` on the inputs to `u` on the outputs.
pub const NORMALIZER_LATENCY: usize = 12;

/// The seed table: for `i` in 64..=255, `round(2^19 / sqrt(i + 1/2))` (2^16 / sqrt(x) at the middle of
/// `x = m/2^30` in `[i/64, (i+1)/64)`); entries below 64 are never addressed (m >= 2^30) and hold 0.
pub fn rsqrt_table_entry(i: u64) -> u64 {
    if (64..256).contains(&i) {
        ((1u64 << 19) as f64 / (i as f64 + 0.5).sqrt()).round() as u64
    } else {
        0
    }
}

/// The ROM word at `i`: the seed `y0` in bits 15:0 and the Newton step's `t = round(y0^2 / 2^14)` in
/// bits 33:16 (a function of the seed, so it is stored rather than computed: one multiplier block less).
pub fn seed_rom_word(i: u64) -> u64 {
    let y0 = rsqrt_table_entry(i);
    y0 | (((y0 * y0 + (1 << 13)) >> 14) << 16)
}

#[derive(LogicBlock)]
pub struct Normalizer {
    pub clock: Signal<In, Clock>,
    // From the plane evaluation
    /// The interpolated normal, Q1.14, not unit.
    pub n_x: Signal<In, Signed<16>>,
    pub n_y: Signal<In, Signed<16>>,
    pub n_z: Signal<In, Signed<16>>,
    // To the light units
    /// The unit normal, Q1.14, [`NORMALIZER_LATENCY`] clocks after `n`.
    pub u_x: Signal<Out, Signed<16>>,
    pub u_y: Signal<Out, Signed<16>>,
    pub u_z: Signal<Out, Signed<16>>,

    seed_rom: SyncROM<Bits<34>, 8>,
    sq_x: SquareLogicS<16, 32>,
    sq_y: SquareLogicS<16, 32>,
    sq_z: SquareLogicS<16, 32>,
    mul_p: MulU<18, 18, 36>,
    mul_y1: MulU<16, 18, 34>,
    q_x: MulS<16, 18, 34>,
    q_y: MulS<16, 18, 34>,
    q_z: MulS<16, 18, 34>,
    // The normal, delayed alongside (stages N1..N9; N10 reads n[8])
    n_xd: [DFF<Signed<16>>; 9],
    n_yd: [DFF<Signed<16>>; 9],
    n_zd: [DFF<Signed<16>>; 9],
    // k and the zero flag, delayed from N3 to N11 / N12
    kd: [DFF<Bits<4>>; 8],
    zd: [DFF<Bit>; 9],
    // N1
    s1_x: DFF<Bits<31>>,
    s1_y: DFF<Bits<31>>,
    s1_z: DFF<Bits<31>>,
    // N2
    len2: DFF<Bits<32>>,
    // N3..N5: m
    m3: DFF<Bits<32>>,
    m4: DFF<Bits<32>>,
    m5: DFF<Bits<32>>,
    // N5..N7: y0
    y0_5: DFF<Bits<16>>,
    y0_6: DFF<Bits<16>>,
    y0_7: DFF<Bits<16>>,
    t5: DFF<Bits<18>>,
    p6: DFF<Bits<36>>,
    e7: DFF<Bits<18>>,
    y0e8: DFF<Bits<34>>,
    y1_9: DFF<Bits<17>>,
    q10_x: DFF<Signed<34>>,
    q10_y: DFF<Signed<34>>,
    q10_z: DFF<Signed<34>>,
    r11_x: DFF<Bits<50>>,
    r11_y: DFF<Bits<50>>,
    r11_z: DFF<Bits<50>>,
    u12_x: DFF<Signed<16>>,
    u12_y: DFF<Signed<16>>,
    u12_z: DFF<Signed<16>>,
    // Combinational
    ext_x: Signal<Local, Bits<32>>,
    ext_y: Signal<Local, Bits<32>>,
    ext_z: Signal<Local, Bits<32>>,
    sum_xy: Signal<Local, Bits<32>>,
    sum_xyz: Signal<Local, Bits<32>>,
    k: Signal<Local, Bits<4>>,
    k5: Signal<Local, Bits<5>>,
    two_k: Signal<Local, Bits<5>>,
    rom_word: Signal<Local, Bits<34>>,
    e_full: Signal<Local, Bits<36>>,
    y1_full: Signal<Local, Bits<34>>,
    y1_s: Signal<Local, Signed<18>>,
    sq_x_u: Signal<Local, Bits<32>>,
    sq_y_u: Signal<Local, Bits<32>>,
    sq_z_u: Signal<Local, Bits<32>>,
    qs_x: Signal<Local, Signed<50>>,
    qs_y: Signal<Local, Signed<50>>,
    qs_z: Signal<Local, Signed<50>>,
    qw_x: Signal<Local, Bits<50>>,
    qw_y: Signal<Local, Bits<50>>,
    qw_z: Signal<Local, Bits<50>>,
    sh_x: Signal<Local, Bits<50>>,
    sh_y: Signal<Local, Bits<50>>,
    sh_z: Signal<Local, Bits<50>>,
    hi_x: Signal<Local, Bits<18>>,
    hi_y: Signal<Local, Bits<18>>,
    hi_z: Signal<Local, Bits<18>>,
    k0_4: Constant<Bits<4>>,
    k0_32: Constant<Bits<32>>,
    k0_2: Constant<Bits<2>>,
    k_e_36: Constant<Bits<36>>,
    khalf16_34: Constant<Bits<34>>,
    khalf16_50: Constant<Bits<50>>,
    kones_18: Constant<Bits<18>>,
    k0_18: Constant<Bits<18>>,
    kmax_16: Constant<Signed<16>>,
    kmin_16: Constant<Signed<16>>,
    kzero_16: Constant<Signed<16>>,
    kk: [Constant<Bits<4>>; 16],
}

impl Default for Normalizer {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            n_x: Default::default(),
            n_y: Default::default(),
            n_z: Default::default(),
            u_x: Default::default(),
            u_y: Default::default(),
            u_z: Default::default(),
            seed_rom: (0..256u64).map(|i| Bits::<34>::from(seed_rom_word(i))).into(),
            sq_x: Default::default(),
            sq_y: Default::default(),
            sq_z: Default::default(),
            mul_p: Default::default(),
            mul_y1: Default::default(),
            q_x: Default::default(),
            q_y: Default::default(),
            q_z: Default::default(),
            n_xd: Default::default(),
            n_yd: Default::default(),
            n_zd: Default::default(),
            kd: Default::default(),
            zd: Default::default(),
            s1_x: Default::default(),
            s1_y: Default::default(),
            s1_z: Default::default(),
            len2: Default::default(),
            m3: Default::default(),
            m4: Default::default(),
            m5: Default::default(),
            y0_5: Default::default(),
            y0_6: Default::default(),
            y0_7: Default::default(),
            t5: Default::default(),
            p6: Default::default(),
            e7: Default::default(),
            y0e8: Default::default(),
            y1_9: Default::default(),
            q10_x: Default::default(),
            q10_y: Default::default(),
            q10_z: Default::default(),
            r11_x: Default::default(),
            r11_y: Default::default(),
            r11_z: Default::default(),
            u12_x: Default::default(),
            u12_y: Default::default(),
            u12_z: Default::default(),
            ext_x: Default::default(),
            ext_y: Default::default(),
            ext_z: Default::default(),
            sum_xy: Default::default(),
            sum_xyz: Default::default(),
            k: Default::default(),
            k5: Default::default(),
            two_k: Default::default(),
            rom_word: Default::default(),
            e_full: Default::default(),
            y1_full: Default::default(),
            y1_s: Default::default(),
            sq_x_u: Default::default(),
            sq_y_u: Default::default(),
            sq_z_u: Default::default(),
            qs_x: Default::default(),
            qs_y: Default::default(),
            qs_z: Default::default(),
            qw_x: Default::default(),
            qw_y: Default::default(),
            qw_z: Default::default(),
            sh_x: Default::default(),
            sh_y: Default::default(),
            sh_z: Default::default(),
            hi_x: Default::default(),
            hi_y: Default::default(),
            hi_z: Default::default(),
            k0_4: Constant::new(0.into()),
            k0_32: Constant::new(0.into()),
            k0_2: Constant::new(0.into()),
            k_e_36: Constant::new(((3u64 << 34) + (1u64 << 17)).into()),
            khalf16_34: Constant::new((1u64 << 16).into()),
            khalf16_50: Constant::new((1u64 << 16).into()),
            kones_18: Constant::new(((1u64 << 18) - 1).into()),
            k0_18: Constant::new(0.into()),
            kmax_16: Constant::new(Signed::<16>::from(i16::MAX as i64)),
            kmin_16: Constant::new(Signed::<16>::from(i16::MIN as i64)),
            kzero_16: Constant::new(Signed::<16>::from(0i64)),
            kk: std::array::from_fn(|i| Constant::new((i as u64).into())),
        }
    }
}

impl Logic for Normalizer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_x, s1_y, s1_z, len2, m3, m4, m5, y0_5, y0_6, y0_7, t5, p6, e7, y0e8, y1_9, q10_x, q10_y,
            q10_z, r11_x, r11_y, r11_z, u12_x, u12_y, u12_z
        );
        self.seed_rom.clock.next = self.clock.val();
        for i in 0..9 {
            self.n_xd[i].clock.next = self.clock.val();
            self.n_yd[i].clock.next = self.clock.val();
            self.n_zd[i].clock.next = self.clock.val();
            self.zd[i].clock.next = self.clock.val();
        }
        for i in 0..8 {
            self.kd[i].clock.next = self.clock.val();
        }
        // The normal travels with its pipeline stage.
        self.n_xd[0].d.next = self.n_x.val();
        self.n_yd[0].d.next = self.n_y.val();
        self.n_zd[0].d.next = self.n_z.val();
        for i in 1..9 {
            self.n_xd[i].d.next = self.n_xd[i - 1].q.val();
            self.n_yd[i].d.next = self.n_yd[i - 1].q.val();
            self.n_zd[i].d.next = self.n_zd[i - 1].q.val();
        }

        // N1: squares (each <= 2^30).
        self.sq_x.a.next = self.n_x.val();
        self.sq_y.a.next = self.n_y.val();
        self.sq_z.a.next = self.n_z.val();
        self.sq_x_u.next = unsigned_cast(self.sq_x.p.val());
        self.s1_x.d.next = self.sq_x_u.val().get_bits::<31>(0);
        self.sq_y_u.next = unsigned_cast(self.sq_y.p.val());
        self.s1_y.d.next = self.sq_y_u.val().get_bits::<31>(0);
        self.sq_z_u.next = unsigned_cast(self.sq_z.p.val());
        self.s1_z.d.next = self.sq_z_u.val().get_bits::<31>(0);

        // N2: |n|^2 < 3 * 2^30 fits 32 bits.
        self.ext_x.next = bit_cast::<32, 31>(self.s1_x.q.val());
        self.ext_y.next = bit_cast::<32, 31>(self.s1_y.q.val());
        self.ext_z.next = bit_cast::<32, 31>(self.s1_z.q.val());
        self.sum_xy.next = self.ext_x.val() + self.ext_y.val();
        self.sum_xyz.next = self.sum_xy.val() + self.ext_z.val();
        self.len2.d.next = self.sum_xyz.val();

        // N3: k = (leading zeros) / 2 from the highest non-zero bit pair; m = len2 << 2k.
        self.k.next = self.k0_4.val();
        for j in 0..16 {
            if self.len2.q.val().get_bits::<2>(2 * j) != self.k0_2.val() {
                self.k.next = self.kk[15 - j].val();
            }
        }
        self.k5.next = bit_cast::<5, 4>(self.k.val());
        self.two_k.next = self.k5.val() << 1;
        self.m3.d.next = self.len2.q.val() << self.two_k.val();
        self.kd[0].d.next = self.k.val();
        self.zd[0].d.next = self.len2.q.val() == self.k0_32.val();
        for i in 1..8 {
            self.kd[i].d.next = self.kd[i - 1].q.val();
        }
        for i in 1..9 {
            self.zd[i].d.next = self.zd[i - 1].q.val();
        }

        // N4: the seed table is read at m[31:24] (its data is registered: y0 in N5).
        self.seed_rom.address.next = self.m3.q.val().get_bits::<8>(24);
        self.m4.d.next = self.m3.q.val();

        // N5: y0 and t = round(y0^2 / 2^14) from the ROM.
        self.rom_word.next = self.seed_rom.data.val();
        self.t5.d.next = self.rom_word.val().get_bits::<18>(16);
        self.y0_5.d.next = self.rom_word.val().get_bits::<16>(0);
        self.m5.d.next = self.m4.q.val();

        // N6: p = (m >> 14) * t = x y0^2 2^34.
        self.mul_p.a.next = self.m5.q.val().get_bits::<18>(14);
        self.mul_p.b.next = self.t5.q.val();
        self.p6.d.next = self.mul_p.p.val();
        self.y0_6.d.next = self.y0_5.q.val();

        // N7: e = round((3 * 2^34 - p) / 2^18) (p < 3 * 2^34 for every m).
        self.e_full.next = self.k_e_36.val() - self.p6.q.val();
        self.e7.d.next = self.e_full.val().get_bits::<18>(18);
        self.y0_7.d.next = self.y0_6.q.val();

        // N8: y0 * e.
        self.mul_y1.a.next = self.y0_7.q.val();
        self.mul_y1.b.next = self.e7.q.val();
        self.y0e8.d.next = self.mul_y1.p.val();

        // N9: y1 = round(y0 e / 2^17) <= 2^16.
        self.y1_full.next = self.y0e8.q.val() + self.khalf16_34.val();
        self.y1_9.d.next = self.y1_full.val().get_bits::<17>(17);

        // N10: q_k = n_k * y1.
        self.y1_s.next = signed_cast(bit_cast::<18, 17>(self.y1_9.q.val()));
        self.q_x.a.next = self.n_xd[8].q.val();
        self.q_x.b.next = self.y1_s.val();
        self.q_y.a.next = self.n_yd[8].q.val();
        self.q_y.b.next = self.y1_s.val();
        self.q_z.a.next = self.n_zd[8].q.val();
        self.q_z.b.next = self.y1_s.val();
        self.q10_x.d.next = self.q_x.p.val();
        self.q10_y.d.next = self.q_y.p.val();
        self.q10_z.d.next = self.q_z.p.val();

        // N11: r_k = (q_k << k) + 2^16, two's complement in 50 bits (|q << k| < 2^49).
        self.qs_x.next = signed_bit_cast_safe::<50, 34>(self.q10_x.q.val());
        self.qw_x.next = unsigned_cast(self.qs_x.val());
        self.qs_y.next = signed_bit_cast_safe::<50, 34>(self.q10_y.q.val());
        self.qw_y.next = unsigned_cast(self.qs_y.val());
        self.qs_z.next = signed_bit_cast_safe::<50, 34>(self.q10_z.q.val());
        self.qw_z.next = unsigned_cast(self.qs_z.val());
        self.sh_x.next = self.qw_x.val() << self.kd[7].q.val();
        self.sh_y.next = self.qw_y.val() << self.kd[7].q.val();
        self.sh_z.next = self.qw_z.val() << self.kd[7].q.val();
        self.r11_x.d.next = self.sh_x.val() + self.khalf16_50.val();
        self.r11_y.d.next = self.sh_y.val() + self.khalf16_50.val();
        self.r11_z.d.next = self.sh_z.val() + self.khalf16_50.val();

        // N12: u_k = r_k >> 17 saturated to 16 bits (bits 49:32 must all equal the sign); 0 for n = 0.
        self.hi_x.next = self.r11_x.q.val().get_bits::<18>(32);
        self.hi_y.next = self.r11_y.q.val().get_bits::<18>(32);
        self.hi_z.next = self.r11_z.q.val().get_bits::<18>(32);
        self.u12_x.d.next = signed_cast(self.r11_x.q.val().get_bits::<16>(17));
        if self.r11_x.q.val().get_bit(49) & (self.hi_x.val() != self.kones_18.val()) {
            self.u12_x.d.next = self.kmin_16.val();
        }
        if !self.r11_x.q.val().get_bit(49) & (self.hi_x.val() != self.k0_18.val()) {
            self.u12_x.d.next = self.kmax_16.val();
        }
        self.u12_y.d.next = signed_cast(self.r11_y.q.val().get_bits::<16>(17));
        if self.r11_y.q.val().get_bit(49) & (self.hi_y.val() != self.kones_18.val()) {
            self.u12_y.d.next = self.kmin_16.val();
        }
        if !self.r11_y.q.val().get_bit(49) & (self.hi_y.val() != self.k0_18.val()) {
            self.u12_y.d.next = self.kmax_16.val();
        }
        self.u12_z.d.next = signed_cast(self.r11_z.q.val().get_bits::<16>(17));
        if self.r11_z.q.val().get_bit(49) & (self.hi_z.val() != self.kones_18.val()) {
            self.u12_z.d.next = self.kmin_16.val();
        }
        if !self.r11_z.q.val().get_bit(49) & (self.hi_z.val() != self.k0_18.val()) {
            self.u12_z.d.next = self.kmax_16.val();
        }
        if self.zd[8].q.val() {
            self.u12_x.d.next = self.kzero_16.val();
            self.u12_y.d.next = self.kzero_16.val();
            self.u12_z.d.next = self.kzero_16.val();
        }
        self.u_x.next = self.u12_x.q.val();
        self.u_y.next = self.u12_y.q.val();
        self.u_z.next = self.u12_z.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalizer_passes_the_rust_hdl_checks_and_generates_verilog() {
        let mut uut = Normalizer::default();
        uut.connect_all();
        let v = crate::common::verilog_named(&uut, "normalizer").unwrap();
        assert!(v.contains("module normalizer("));
    }
}
