//! `texel_filter`: the Color Shader's texel arithmetic for texture mapping (issue 17, item 4): the
//! bilinear blend of a 2x2 footprint with 8-bit weights ([`Bilinear`], two stages), then OpenGL's
//! MODULATE with the pixel's shaded colour ([`crate::cs::modulate::Modulate`]). One pixel per clock,
//! latency 3, no stalls (the CS is a fixed-latency pipeline with credits). The texture unit
//! (`texture_sampler`) uses [`Bilinear`] alone, with trilinear's blend between it and MODULATE.
//!
//! ```text
//!               +--------------------------------------------------------------------------+
//!  t00..t11 --->| stage 1: per channel  h0 = t00 (256-fx) + t10 fx,  h1 = t01 (256-fx) + t11 fx |
//!  fx, fy ----->|          as lerps (t00 << 8) + (t10 - t00) fx (6 products 9x8, in logic)  |
//!  colour ----->| stage 2: per channel  (h0 (256-fy) + h1 fy + 2^15) >> 16  (3 lerps 18x8)    |
//!  valid_in --->| stage 3: per channel  p = texel colour + 128, (p + (p >> 8)) >> 8 (3 x 8x8) |--> rgb_out, valid_out
//!               +--------------------------------------------------------------------------+
//! ```
//!
//! Texels and colours are RGB888 packed R in 23:16, G in 15:8, B in 7:0. `golden::texture::bilinear`
//! and `golden::texture::modulate` are the reference: the blend is the exact four-term weighted sum
//! with one rounding (the two-step form is the same sum), and `h0`, `h1` are at most 255 x 256, so no
//! stage loses bits. `rgb_out` is 0 while `valid_out` is low.

use crate::common::{LerpDeltaLogic, MulS};
use crate::cs::modulate::Modulate;
use rust_hdl::prelude::*;

/// Cycles from a pixel's inputs to its `rgb_out`.
pub const TEXEL_FILTER_LATENCY: u64 = 3;
/// Cycles from a footprint to [`Bilinear`]'s `texel_out`.
pub const BILINEAR_LATENCY: u64 = 2;

/// The bilinear blend of a footprint: `golden::texture::bilinear`, latency 2.
///
/// Each blend is written as a lerp, `a (256 - f) + b f = (a << 8) + (b - a) f`, the same integer
/// with one product in place of two: the six horizontal products (signed 9 x 8) are in logic
/// ([`LerpDeltaLogic`]), the three vertical ones (signed 18 x 8) on one multiplier block each.
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

    // Stage 1: horizontal lerps, [channel] with channel 0 = R; row 0 (t00, t10) and row 1 (t01, t11).
    mh0: [LerpDeltaLogic<8, 8, 17>; 3],
    mh1: [LerpDeltaLogic<8, 8, 17>; 3],
    base0: [Signal<Local, Bits<17>>; 3],
    base1: [Signal<Local, Bits<17>>; 3],
    h0: [DFF<Bits<17>>; 3],
    h1: [DFF<Bits<17>>; 3],
    fy1: DFF<Bits<8>>,
    fy1_9: Signal<Local, Bits<9>>,
    valid1: DFF<Bit>,
    // Stage 2: vertical lerp and rounding.
    h0_18: [Signal<Local, Bits<18>>; 3],
    h1_18: [Signal<Local, Bits<18>>; 3],
    dv: [Signal<Local, Bits<18>>; 3],
    mv: [MulS<18, 9, 26>; 3],
    vbase: [Signal<Local, Bits<26>>; 3],
    v_sum: [Signal<Local, Bits<26>>; 3],
    v_round: [Signal<Local, Bits<26>>; 3],
    texel: [DFF<Bits<8>>; 3],
    valid2: DFF<Bit>,
    packed: [Signal<Local, Bits<24>>; 3],
    k8_17: Constant<Bits<17>>,
    k8_26: Constant<Bits<26>>,
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
            mh0: Default::default(),
            mh1: Default::default(),
            base0: Default::default(),
            base1: Default::default(),
            h0: Default::default(),
            h1: Default::default(),
            fy1: Default::default(),
            fy1_9: Default::default(),
            valid1: Default::default(),
            h0_18: Default::default(),
            h1_18: Default::default(),
            dv: Default::default(),
            mv: Default::default(),
            vbase: Default::default(),
            v_sum: Default::default(),
            v_round: Default::default(),
            texel: Default::default(),
            valid2: Default::default(),
            packed: Default::default(),
            k8_17: Constant::new(8u64.into()),
            k8_26: Constant::new(8u64.into()),
            khalf_26: Constant::new((1u64 << 15).into()),
        }
    }
}

impl Logic for Bilinear {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, fy1, valid1, valid2);
        for c in 0..3 {
            self.h0[c].clock.next = self.clock.val();
            self.h1[c].clock.next = self.clock.val();
            self.texel[c].clock.next = self.clock.val();
        }
        self.mh0[0].lo.next = self.t00.val().get_bits::<8>(16);
        self.mh0[0].hi.next = self.t10.val().get_bits::<8>(16);
        self.mh1[0].lo.next = self.t01.val().get_bits::<8>(16);
        self.mh1[0].hi.next = self.t11.val().get_bits::<8>(16);
        self.base0[0].next = bit_cast::<17, 8>(self.t00.val().get_bits::<8>(16)) << self.k8_17.val();
        self.base1[0].next = bit_cast::<17, 8>(self.t01.val().get_bits::<8>(16)) << self.k8_17.val();
        self.mh0[1].lo.next = self.t00.val().get_bits::<8>(8);
        self.mh0[1].hi.next = self.t10.val().get_bits::<8>(8);
        self.mh1[1].lo.next = self.t01.val().get_bits::<8>(8);
        self.mh1[1].hi.next = self.t11.val().get_bits::<8>(8);
        self.base0[1].next = bit_cast::<17, 8>(self.t00.val().get_bits::<8>(8)) << self.k8_17.val();
        self.base1[1].next = bit_cast::<17, 8>(self.t01.val().get_bits::<8>(8)) << self.k8_17.val();
        self.mh0[2].lo.next = self.t00.val().get_bits::<8>(0);
        self.mh0[2].hi.next = self.t10.val().get_bits::<8>(0);
        self.mh1[2].lo.next = self.t01.val().get_bits::<8>(0);
        self.mh1[2].hi.next = self.t11.val().get_bits::<8>(0);
        self.base0[2].next = bit_cast::<17, 8>(self.t00.val().get_bits::<8>(0)) << self.k8_17.val();
        self.base1[2].next = bit_cast::<17, 8>(self.t01.val().get_bits::<8>(0)) << self.k8_17.val();
        for c in 0..3 {
            // h = (left << 8) + (right - left) fx, with h (0..=65280) in 17 bits: the wrapping
            // sum is exact.
            self.mh0[c].f.next = self.fx.val();
            self.mh1[c].f.next = self.fx.val();
            self.h0[c].d.next = self.base0[c].val() + unsigned_cast(self.mh0[c].p.val());
            self.h1[c].d.next = self.base1[c].val() + unsigned_cast(self.mh1[c].p.val());
        }
        self.fy1.d.next = self.fy.val();
        self.fy1_9.next = bit_cast::<9, 8>(self.fy1.q.val());
        self.valid1.d.next = self.valid_in.val();
        // Stage 2: v = (h0 << 8) + (h1 - h0) fy, + 2^15, >> 16 (v at most 65280 x 256, in 26 bits).
        self.h0_18[0].next = bit_cast::<18, 17>(self.h0[0].q.val());
        self.h1_18[0].next = bit_cast::<18, 17>(self.h1[0].q.val());
        self.vbase[0].next = bit_cast::<26, 17>(self.h0[0].q.val()) << self.k8_26.val();
        self.h0_18[1].next = bit_cast::<18, 17>(self.h0[1].q.val());
        self.h1_18[1].next = bit_cast::<18, 17>(self.h1[1].q.val());
        self.vbase[1].next = bit_cast::<26, 17>(self.h0[1].q.val()) << self.k8_26.val();
        self.h0_18[2].next = bit_cast::<18, 17>(self.h0[2].q.val());
        self.h1_18[2].next = bit_cast::<18, 17>(self.h1[2].q.val());
        self.vbase[2].next = bit_cast::<26, 17>(self.h0[2].q.val()) << self.k8_26.val();
        for c in 0..3 {
            self.dv[c].next = self.h1_18[c].val() - self.h0_18[c].val();
            self.mv[c].a.next = signed_cast(self.dv[c].val());
            self.mv[c].b.next = signed_cast(self.fy1_9.val());
            self.v_sum[c].next = self.vbase[c].val() + unsigned_cast(self.mv[c].p.val());
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
