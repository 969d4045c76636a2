//! `texel_filter`: the Color Shader's texel arithmetic for texture mapping (issue 17, item 4): the
//! bilinear blend of a 2x2 footprint with 8-bit weights ([`Bilinear`], two stages), then OpenGL's
//! MODULATE with the pixel's shaded colour ([`crate::cs::modulate::Modulate`]). One pixel per clock,
//! latency 3, no stalls (the CS is a fixed-latency pipeline with credits). The texture unit
//! (`texture_sampler`) uses [`Bilinear`] alone, with trilinear's blend between it and MODULATE.
//!
//! ```text
//!               +--------------------------------------------------------------------------+
//!  t00..t11 --->| stage 1: per channel  h0 = t00 (256-fx) + t10 fx,  h1 = t01 (256-fx) + t11 fx |
//!  fx, fy ----->|          (12 products 8x9)                                                |
//!  colour ----->| stage 2: per channel  (h0 (256-fy) + h1 fy + 2^15) >> 16  (6 products 17x9) |
//!  valid_in --->| stage 3: per channel  p = texel colour + 128, (p + (p >> 8)) >> 8 (3 x 8x8) |--> rgb_out, valid_out
//!               +--------------------------------------------------------------------------+
//! ```
//!
//! Texels and colours are RGB888 packed R in 23:16, G in 15:8, B in 7:0. `golden::texture::bilinear`
//! and `golden::texture::modulate` are the reference: the blend is the exact four-term weighted sum
//! with one rounding (the two-step form is the same sum), and `h0`, `h1` are at most 255 x 256, so no
//! stage loses bits. `rgb_out` is 0 while `valid_out` is low.

use crate::common::MulU;
use crate::cs::modulate::Modulate;
use rust_hdl::prelude::*;

/// Cycles from a pixel's inputs to its `rgb_out`.
pub const TEXEL_FILTER_LATENCY: u64 = 3;
/// Cycles from a footprint to [`Bilinear`]'s `texel_out`.
pub const BILINEAR_LATENCY: u64 = 2;

/// The bilinear blend of a footprint: `golden::texture::bilinear`, latency 2.
#[derive(LogicBlock)]
pub struct Bilinear {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    /// The footprint: t00 at (x0, y0), t10 at (x0 + 1, y0), t01 at (x0, y0 + 1), t11 at both + 1.
    pub t00: Signal<In, Bits<24>>,
    pub t10: Signal<In, Bits<24>>,
    pub t01: Signal<In, Bits<24>>,
    pub t11: Signal<In, Bits<24>>,
    /// Weights towards t10 / t11 (x) and t01 / t11 (y), in 1/256.
    pub fx: Signal<In, Bits<8>>,
    pub fy: Signal<In, Bits<8>>,
    pub valid_out: Signal<Out, Bit>,
    pub texel_out: Signal<Out, Bits<24>>,

    // Weights, 9 bits (256 - f reaches 256).
    wx0: Signal<Local, Bits<9>>,
    wx1: Signal<Local, Bits<9>>,
    wy0_in: Signal<Local, Bits<9>>,
    // Stage 1: horizontal blends, [channel] with channel 0 = R.
    mh: [MulU<8, 9, 17>; 12],
    h0_sum: [Signal<Local, Bits<17>>; 3],
    h1_sum: [Signal<Local, Bits<17>>; 3],
    h0: [DFF<Bits<17>>; 3],
    h1: [DFF<Bits<17>>; 3],
    wy0: DFF<Bits<9>>,
    wy1: DFF<Bits<9>>,
    valid1: DFF<Bit>,
    // Stage 2: vertical blend and rounding.
    mv: [MulU<17, 9, 26>; 6],
    v_sum: [Signal<Local, Bits<26>>; 3],
    v_round: [Signal<Local, Bits<26>>; 3],
    texel: [DFF<Bits<8>>; 3],
    valid2: DFF<Bit>,
    packed: [Signal<Local, Bits<24>>; 3],
    k256_9: Constant<Bits<9>>,
    khalf_26: Constant<Bits<26>>,
}

impl Default for Bilinear {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            t00: Default::default(),
            t10: Default::default(),
            t01: Default::default(),
            t11: Default::default(),
            fx: Default::default(),
            fy: Default::default(),
            valid_out: Default::default(),
            texel_out: Default::default(),
            wx0: Default::default(),
            wx1: Default::default(),
            wy0_in: Default::default(),
            mh: Default::default(),
            h0_sum: Default::default(),
            h1_sum: Default::default(),
            h0: Default::default(),
            h1: Default::default(),
            wy0: Default::default(),
            wy1: Default::default(),
            valid1: Default::default(),
            mv: Default::default(),
            v_sum: Default::default(),
            v_round: Default::default(),
            texel: Default::default(),
            valid2: Default::default(),
            packed: Default::default(),
            k256_9: Constant::new(256u64.into()),
            khalf_26: Constant::new((1u64 << 15).into()),
        }
    }
}

impl Logic for Bilinear {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wy0, wy1, valid1, valid2);
        for c in 0..3 {
            self.h0[c].clock.next = self.clock.val();
            self.h1[c].clock.next = self.clock.val();
            self.texel[c].clock.next = self.clock.val();
        }
        // Weights.
        self.wx1.next = bit_cast::<9, 8>(self.fx.val());
        self.wx0.next = self.k256_9.val() - self.wx1.val();
        self.wy0_in.next = bit_cast::<9, 8>(self.fy.val());
        // Stage 1: the texel channels into the horizontal products (R, G, B at 16, 8, 0).
        self.mh[0].a.next = self.t00.val().get_bits::<8>(16);
        self.mh[1].a.next = self.t10.val().get_bits::<8>(16);
        self.mh[2].a.next = self.t01.val().get_bits::<8>(16);
        self.mh[3].a.next = self.t11.val().get_bits::<8>(16);
        self.mh[4].a.next = self.t00.val().get_bits::<8>(8);
        self.mh[5].a.next = self.t10.val().get_bits::<8>(8);
        self.mh[6].a.next = self.t01.val().get_bits::<8>(8);
        self.mh[7].a.next = self.t11.val().get_bits::<8>(8);
        self.mh[8].a.next = self.t00.val().get_bits::<8>(0);
        self.mh[9].a.next = self.t10.val().get_bits::<8>(0);
        self.mh[10].a.next = self.t01.val().get_bits::<8>(0);
        self.mh[11].a.next = self.t11.val().get_bits::<8>(0);
        for c in 0..3 {
            self.mh[4 * c].b.next = self.wx0.val();
            self.mh[4 * c + 1].b.next = self.wx1.val();
            self.mh[4 * c + 2].b.next = self.wx0.val();
            self.mh[4 * c + 3].b.next = self.wx1.val();
            self.h0_sum[c].next = self.mh[4 * c].p.val() + self.mh[4 * c + 1].p.val();
            self.h1_sum[c].next = self.mh[4 * c + 2].p.val() + self.mh[4 * c + 3].p.val();
            self.h0[c].d.next = self.h0_sum[c].val();
            self.h1[c].d.next = self.h1_sum[c].val();
        }
        self.wy1.d.next = self.wy0_in.val();
        self.wy0.d.next = self.k256_9.val() - self.wy0_in.val();
        self.valid1.d.next = self.valid_in.val();
        // Stage 2: vertical blend, + 2^15, >> 16.
        for c in 0..3 {
            self.mv[2 * c].a.next = self.h0[c].q.val();
            self.mv[2 * c].b.next = self.wy0.q.val();
            self.mv[2 * c + 1].a.next = self.h1[c].q.val();
            self.mv[2 * c + 1].b.next = self.wy1.q.val();
            self.v_sum[c].next = self.mv[2 * c].p.val() + self.mv[2 * c + 1].p.val();
            self.v_round[c].next = self.v_sum[c].val() + self.khalf_26.val();
            self.texel[c].d.next = self.v_round[c].val().get_bits::<8>(16);
        }
        self.valid2.d.next = self.valid1.q.val();
        self.packed[0].next = bit_cast::<24, 8>(self.texel[0].q.val()) << 16;
        self.packed[1].next = bit_cast::<24, 8>(self.texel[1].q.val()) << 8;
        self.packed[2].next = bit_cast::<24, 8>(self.texel[2].q.val());
        self.texel_out.next = self.packed[0].val() | self.packed[1].val() | self.packed[2].val();
        self.valid_out.next = self.valid2.q.val();
    }
}

/// The bilinear blend, then MODULATE with the pixel's colour; latency 3.
#[derive(LogicBlock, Default)]
pub struct TexelFilter {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    /// The footprint, as [`Bilinear`]'s.
    pub t00: Signal<In, Bits<24>>,
    pub t10: Signal<In, Bits<24>>,
    pub t01: Signal<In, Bits<24>>,
    pub t11: Signal<In, Bits<24>>,
    pub fx: Signal<In, Bits<8>>,
    pub fy: Signal<In, Bits<8>>,
    /// The pixel's shaded colour, which the texel modulates.
    pub colour: Signal<In, Bits<24>>,
    pub valid_out: Signal<Out, Bit>,
    pub rgb_out: Signal<Out, Bits<24>>,
    bil: Bilinear,
    colour1: DFF<Bits<24>>,
    colour2: DFF<Bits<24>>,
    modulate: Modulate,
}

impl Logic for TexelFilter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, colour1, colour2);
        self.bil.clock.next = self.clock.val();
        self.modulate.clock.next = self.clock.val();
        self.bil.valid_in.next = self.valid_in.val();
        self.bil.t00.next = self.t00.val();
        self.bil.t10.next = self.t10.val();
        self.bil.t01.next = self.t01.val();
        self.bil.t11.next = self.t11.val();
        self.bil.fx.next = self.fx.val();
        self.bil.fy.next = self.fy.val();
        self.colour1.d.next = self.colour.val();
        self.colour2.d.next = self.colour1.q.val();
        self.modulate.valid_in.next = self.bil.valid_out.val();
        self.modulate.texel.next = self.bil.texel_out.val();
        self.modulate.colour.next = self.colour2.q.val();
        self.valid_out.next = self.modulate.valid_out.val();
        self.rgb_out.next = self.modulate.rgb_out.val();
    }
}

/// Verilog of the texel filter (module `texel_filter`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexelFilter::default();
    uut.connect_all();
    crate::cs::verilog_named(&uut, "texel_filter")
}
