//! `tex_coord`: the Color Shader's per-pixel texture coordinate (issue 17, item 2): the three texture
//! planes of a pixel's triangle (s/w, t/w and 1/w from TdbS) evaluated at the pixel, one reciprocal
//! per pixel, and s = (s/w) / (1/w), t likewise. `golden::texcoord::TexPlanes::coord` is the
//! reference, bit for bit, in the widths of its module table; it also gives the reciprocal
//! (`m`, `e`: 1/Q ~ m 2^-(e + 24)) that the level of detail is formed with (the next block, not yet
//! written). One pixel per clock, no stall (like the CS's other pipelines: its issue credit keeps
//! back-pressure out of them).
//!
//! ```text
//!  valid_in, x, y, planes (sw, tw, q: a, b 40 b, c 56 b)
//!    | stage 1: a X, b Y for the three planes (PlaneMul, 2 multiplier blocks each)
//!    | stage 2: S, T, Q = c + a X + b Y (57 b)
//!    | stage 3: Q clamped to 1..2^41 - 1; e = its leading one; n = its top 36 bits
//!    | stage 4: S' = sat34((S << 20) >>> e), T' likewise      | the RC's reciprocal unit: 1/n
//!    | stages 5-13: S', T', e wait for the reciprocal         | (10 stations, one per clock)
//!    | stage 14: s = sat32((S' m + 2^23) >> 24), t likewise (34 x 26 products)
//!    v
//!  valid_out, s, t (Q15.16), m (25 b), e (6 b); all 0 while valid_out is low
//! ```
//!
//! A pixel accepted in cycle c leaves in cycle c + [`TEX_COORD_LATENCY`].

use crate::common::{signed_bit_cast_safe, LeadingOne36, MulS};
use crate::cs::plane_mul::PlaneMul;
use crate::rc::reciprocal::Reciprocal;
use rust_hdl::prelude::*;

/// Cycles from a pixel's cycle on the inputs to its cycle on the outputs.
pub const TEX_COORD_LATENCY: u64 = 14;
/// Stations between the normalisation (stage 4) and the products (stage 14): the reciprocal's
/// latency less one. `update` writes 9 as a literal (hdl_gen knows no constants).
pub const SIDE_STATIONS: usize = 10;

#[derive(LogicBlock)]
pub struct TexCoord {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    /// The pixel, 0..1023.
    pub x: Signal<In, Bits<11>>,
    pub y: Signal<In, Bits<11>>,
    /// The triangle's planes (TdbS's texture part, `golden::texcoord::TexPlanes`).
    pub sw_a: Signal<In, Signed<40>>,
    pub sw_b: Signal<In, Signed<40>>,
    pub sw_c: Signal<In, Signed<56>>,
    pub tw_a: Signal<In, Signed<40>>,
    pub tw_b: Signal<In, Signed<40>>,
    pub tw_c: Signal<In, Signed<56>>,
    pub q_a: Signal<In, Signed<40>>,
    pub q_b: Signal<In, Signed<40>>,
    pub q_c: Signal<In, Signed<56>>,
    pub valid_out: Signal<Out, Bit>,
    /// s and t, Q15.16 of the texture, two's complement.
    pub s: Signal<Out, Bits<32>>,
    pub t: Signal<Out, Bits<32>>,
    /// The reciprocal's mantissa and Q's leading one: 1/Q ~ m 2^-(e + 24).
    pub m: Signal<Out, Bits<25>>,
    pub e: Signal<Out, Bits<6>>,

    // Stage 1.
    mul: [PlaneMul; 6],
    pa: [DFF<Signed<51>>; 3],
    pb: [DFF<Signed<51>>; 3],
    pc: [DFF<Signed<56>>; 3],
    v1: DFF<Bit>,
    // Stage 2.
    sum_ab: [Signal<Local, Signed<57>>; 3],
    raw: [DFF<Signed<57>>; 3],
    v2: DFF<Bit>,
    // Stage 3.
    qb: Signal<Local, Bits<57>>,
    q41: Signal<Local, Bits<41>>,
    lead_hi: LeadingOne36,
    lead_lo: LeadingOne36,
    e_hi: Signal<Local, Bits<6>>,
    lead: Signal<Local, Bits<6>>,
    drop: Signal<Local, Bits<6>>,
    n_sh: Signal<Local, Bits<41>>,
    n3: DFF<Bits<36>>,
    e3: DFF<Bits<6>>,
    raw3: [DFF<Signed<57>>; 2],
    v3: DFF<Bit>,
    // Stage 4: [S, T].
    rb: [Signal<Local, Bits<57>>; 2],
    ext: [Signal<Local, Bits<77>>; 2],
    shl: [Signal<Local, Bits<77>>; 2],
    inv: [Signal<Local, Bits<77>>; 2],
    inv_sh: [Signal<Local, Bits<77>>; 2],
    ash: [Signal<Local, Bits<77>>; 2],
    top: [Signal<Local, Bits<44>>; 2],
    norm: [Signal<Local, Bits<34>>; 2],
    recip: Reciprocal,
    /// {valid, e, T', S'} from stage 4 to stage 13.
    side: [DFF<Bits<75>>; SIDE_STATIONS],
    // Stage 14.
    prod: [MulS<34, 26, 60>; 2],
    m26: Signal<Local, Bits<26>>,
    rounded: [Signal<Local, Bits<60>>; 2],
    shifted: [Signal<Local, Bits<36>>; 2],
    top5: [Signal<Local, Bits<5>>; 2],
    coord: [Signal<Local, Bits<32>>; 2],
    out: [DFF<Bits<32>>; 2],
    m_q: DFF<Bits<25>>,
    e_q: DFF<Bits<6>>,
    v_q: DFF<Bit>,
    k1_41: Constant<Bits<41>>,
    kmax_41: Constant<Bits<41>>,
    k35_6: Constant<Bits<6>>,
    k36_6: Constant<Bits<6>>,
    ksext_77: Constant<Bits<77>>,
    k20_5: Constant<Bits<5>>,
    kones_44: Constant<Bits<44>>,
    kmin_34: Constant<Bits<34>>,
    kmax_34: Constant<Bits<34>>,
    khalf_60: Constant<Bits<60>>,
    kmin_32: Constant<Bits<32>>,
    kmax_32: Constant<Bits<32>>,
    kones_5: Constant<Bits<5>>,
    kvalid_75: Constant<Bits<75>>,
}

impl Default for TexCoord {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            x: Default::default(),
            y: Default::default(),
            sw_a: Default::default(),
            sw_b: Default::default(),
            sw_c: Default::default(),
            tw_a: Default::default(),
            tw_b: Default::default(),
            tw_c: Default::default(),
            q_a: Default::default(),
            q_b: Default::default(),
            q_c: Default::default(),
            valid_out: Default::default(),
            s: Default::default(),
            t: Default::default(),
            m: Default::default(),
            e: Default::default(),
            mul: Default::default(),
            pa: Default::default(),
            pb: Default::default(),
            pc: Default::default(),
            v1: Default::default(),
            sum_ab: Default::default(),
            raw: Default::default(),
            v2: Default::default(),
            qb: Default::default(),
            q41: Default::default(),
            lead_hi: Default::default(),
            lead_lo: Default::default(),
            e_hi: Default::default(),
            lead: Default::default(),
            drop: Default::default(),
            n_sh: Default::default(),
            n3: Default::default(),
            e3: Default::default(),
            raw3: Default::default(),
            v3: Default::default(),
            rb: Default::default(),
            ext: Default::default(),
            shl: Default::default(),
            inv: Default::default(),
            inv_sh: Default::default(),
            ash: Default::default(),
            top: Default::default(),
            norm: Default::default(),
            recip: Default::default(),
            side: Default::default(),
            prod: Default::default(),
            m26: Default::default(),
            rounded: Default::default(),
            shifted: Default::default(),
            top5: Default::default(),
            coord: Default::default(),
            out: Default::default(),
            m_q: Default::default(),
            e_q: Default::default(),
            v_q: Default::default(),
            k1_41: Constant::new(1.into()),
            kmax_41: Constant::new(((1u64 << 41) - 1).into()),
            k35_6: Constant::new(35.into()),
            k36_6: Constant::new(36.into()),
            ksext_77: Constant::new(crate::common::bits_from_u128::<77>(((1u128 << 77) - 1) ^ ((1u128 << 57) - 1))),
            k20_5: Constant::new(20.into()),
            kones_44: Constant::new(((1u64 << 44) - 1).into()),
            kmin_34: Constant::new((1u64 << 33).into()),
            kmax_34: Constant::new(((1u64 << 33) - 1).into()),
            khalf_60: Constant::new((1u64 << 23).into()),
            kmin_32: Constant::new((1u64 << 31).into()),
            kmax_32: Constant::new(((1u64 << 31) - 1).into()),
            kones_5: Constant::new(31.into()),
            kvalid_75: Constant::new(crate::common::bits_from_u128::<75>(1u128 << 74)),
        }
    }
}

impl Logic for TexCoord {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, v1, v2, n3, e3, v3, m_q, e_q, v_q);
        for k in 0..3 {
            self.pa[k].clock.next = self.clock.val();
            self.pb[k].clock.next = self.clock.val();
            self.pc[k].clock.next = self.clock.val();
            self.raw[k].clock.next = self.clock.val();
        }
        for k in 0..2 {
            self.raw3[k].clock.next = self.clock.val();
            self.out[k].clock.next = self.clock.val();
        }
        for k in 0..10 {
            self.side[k].clock.next = self.clock.val();
        }
        clock!(self, clock, recip);

        // Stage 1: the six plane products.
        self.mul[0].a.next = self.sw_a.val();
        self.mul[0].b.next = signed_cast(self.x.val());
        self.mul[1].a.next = self.sw_b.val();
        self.mul[1].b.next = signed_cast(self.y.val());
        self.mul[2].a.next = self.tw_a.val();
        self.mul[2].b.next = signed_cast(self.x.val());
        self.mul[3].a.next = self.tw_b.val();
        self.mul[3].b.next = signed_cast(self.y.val());
        self.mul[4].a.next = self.q_a.val();
        self.mul[4].b.next = signed_cast(self.x.val());
        self.mul[5].a.next = self.q_b.val();
        self.mul[5].b.next = signed_cast(self.y.val());
        self.pa[0].d.next = self.mul[0].p.val();
        self.pb[0].d.next = self.mul[1].p.val();
        self.pa[1].d.next = self.mul[2].p.val();
        self.pb[1].d.next = self.mul[3].p.val();
        self.pa[2].d.next = self.mul[4].p.val();
        self.pb[2].d.next = self.mul[5].p.val();
        self.pc[0].d.next = self.sw_c.val();
        self.pc[1].d.next = self.tw_c.val();
        self.pc[2].d.next = self.q_c.val();
        self.v1.d.next = self.valid_in.val();

        // Stage 2: S, T, Q.
        self.sum_ab[0].next = signed_bit_cast_safe::<57, 56>(self.pc[0].q.val()) + signed_bit_cast_safe::<57, 51>(self.pa[0].q.val());
        self.raw[0].d.next = self.sum_ab[0].val() + signed_bit_cast_safe::<57, 51>(self.pb[0].q.val());
        self.sum_ab[1].next = signed_bit_cast_safe::<57, 56>(self.pc[1].q.val()) + signed_bit_cast_safe::<57, 51>(self.pa[1].q.val());
        self.raw[1].d.next = self.sum_ab[1].val() + signed_bit_cast_safe::<57, 51>(self.pb[1].q.val());
        self.sum_ab[2].next = signed_bit_cast_safe::<57, 56>(self.pc[2].q.val()) + signed_bit_cast_safe::<57, 51>(self.pa[2].q.val());
        self.raw[2].d.next = self.sum_ab[2].val() + signed_bit_cast_safe::<57, 51>(self.pb[2].q.val());
        self.v2.d.next = self.v1.q.val();

        // Stage 3: Q clamped, its leading one, its top 36 bits.
        self.qb.next = unsigned_cast(self.raw[2].q.val());
        self.q41.next = self.qb.val().get_bits::<41>(0);
        if self.qb.val().get_bit(56) | !self.qb.val().any() {
            self.q41.next = self.k1_41.val();
        } else if self.qb.val().get_bits::<16>(41).any() {
            self.q41.next = self.kmax_41.val();
        }
        self.lead_hi.x.next = bit_cast::<36, 5>(self.q41.val().get_bits::<5>(36));
        self.lead_lo.x.next = self.q41.val().get_bits::<36>(0);
        self.e_hi.next = self.lead_hi.index.val() + self.k36_6.val();
        self.lead.next = self.lead_lo.index.val();
        if self.q41.val().get_bits::<5>(36).any() {
            self.lead.next = self.e_hi.val();
        }
        self.drop.next = 0.into();
        if self.lead.val() > self.k35_6.val() {
            self.drop.next = self.lead.val() - self.k35_6.val();
        }
        self.n_sh.next = self.q41.val() >> self.drop.val();
        self.n3.d.next = self.n_sh.val().get_bits::<36>(0);
        self.e3.d.next = self.lead.val();
        self.raw3[0].d.next = self.raw[0].q.val();
        self.raw3[1].d.next = self.raw[1].q.val();
        self.v3.d.next = self.v2.q.val();

        // Stage 4: the reciprocal starts; S and T normalised by 2^(20 - e), saturated to 34 bits.
        self.recip.request.data.next = bit_cast::<44, 36>(self.n3.q.val());
        self.recip.request.valid.next = self.v3.q.val();
        self.recip.result.ready.next = true;
        self.rb[0].next = unsigned_cast(self.raw3[0].q.val());
        self.ext[0].next = bit_cast::<77, 57>(self.rb[0].val());
        if self.rb[0].val().get_bit(56) {
            self.ext[0].next = bit_cast::<77, 57>(self.rb[0].val()) | self.ksext_77.val();
        }
        self.shl[0].next = self.ext[0].val() << self.k20_5.val();
        // An arithmetic shift on one shifter: a negative value is inverted before and after.
        self.inv[0].next = self.shl[0].val();
        if self.rb[0].val().get_bit(56) {
            self.inv[0].next = !self.shl[0].val();
        }
        self.inv_sh[0].next = self.inv[0].val() >> self.e3.q.val();
        self.ash[0].next = self.inv_sh[0].val();
        if self.rb[0].val().get_bit(56) {
            self.ash[0].next = !self.inv_sh[0].val();
        }
        self.top[0].next = self.ash[0].val().get_bits::<44>(33);
        self.norm[0].next = self.ash[0].val().get_bits::<34>(0);
        if self.rb[0].val().get_bit(56) {
            if self.top[0].val() != self.kones_44.val() {
                self.norm[0].next = self.kmin_34.val();
            }
        } else if self.top[0].val().any() {
            self.norm[0].next = self.kmax_34.val();
        }
        self.rb[1].next = unsigned_cast(self.raw3[1].q.val());
        self.ext[1].next = bit_cast::<77, 57>(self.rb[1].val());
        if self.rb[1].val().get_bit(56) {
            self.ext[1].next = bit_cast::<77, 57>(self.rb[1].val()) | self.ksext_77.val();
        }
        self.shl[1].next = self.ext[1].val() << self.k20_5.val();
        // An arithmetic shift on one shifter: a negative value is inverted before and after.
        self.inv[1].next = self.shl[1].val();
        if self.rb[1].val().get_bit(56) {
            self.inv[1].next = !self.shl[1].val();
        }
        self.inv_sh[1].next = self.inv[1].val() >> self.e3.q.val();
        self.ash[1].next = self.inv_sh[1].val();
        if self.rb[1].val().get_bit(56) {
            self.ash[1].next = !self.inv_sh[1].val();
        }
        self.top[1].next = self.ash[1].val().get_bits::<44>(33);
        self.norm[1].next = self.ash[1].val().get_bits::<34>(0);
        if self.rb[1].val().get_bit(56) {
            if self.top[1].val() != self.kones_44.val() {
                self.norm[1].next = self.kmin_34.val();
            }
        } else if self.top[1].val().any() {
            self.norm[1].next = self.kmax_34.val();
        }
        self.side[0].d.next = bit_cast::<75, 34>(self.norm[0].val())
            | (bit_cast::<75, 34>(self.norm[1].val()) << 34)
            | (bit_cast::<75, 6>(self.e3.q.val()) << 68);
        if self.v3.q.val() {
            self.side[0].d.next = bit_cast::<75, 34>(self.norm[0].val())
                | (bit_cast::<75, 34>(self.norm[1].val()) << 34)
                | (bit_cast::<75, 6>(self.e3.q.val()) << 68)
                | self.kvalid_75.val();
        }
        // Stages 5-13.
        for k in 0..9 {
            self.side[k + 1].d.next = self.side[k].q.val();
        }

        // Stage 14: s = sat32((S' m + 2^23) >> 24), t likewise.
        self.m26.next = bit_cast::<26, 25>(self.recip.result.data.val().mant);
        self.prod[0].b.next = signed_cast(self.m26.val());
        self.prod[1].b.next = signed_cast(self.m26.val());
        self.prod[0].a.next = signed_cast(self.side[9].q.val().get_bits::<34>(0));
        self.prod[1].a.next = signed_cast(self.side[9].q.val().get_bits::<34>(34));
        self.rounded[0].next = unsigned_cast(self.prod[0].p.val()) + self.khalf_60.val();
        self.shifted[0].next = self.rounded[0].val().get_bits::<36>(24);
        self.top5[0].next = self.shifted[0].val().get_bits::<5>(31);
        self.coord[0].next = self.shifted[0].val().get_bits::<32>(0);
        if self.top5[0].val().any() & (self.top5[0].val() != self.kones_5.val()) {
            if self.shifted[0].val().get_bit(35) {
                self.coord[0].next = self.kmin_32.val();
            } else {
                self.coord[0].next = self.kmax_32.val();
            }
        }
        self.out[0].d.next = 0.into();
        if self.side[9].q.val().get_bit(74) {
            self.out[0].d.next = self.coord[0].val();
        }
        self.rounded[1].next = unsigned_cast(self.prod[1].p.val()) + self.khalf_60.val();
        self.shifted[1].next = self.rounded[1].val().get_bits::<36>(24);
        self.top5[1].next = self.shifted[1].val().get_bits::<5>(31);
        self.coord[1].next = self.shifted[1].val().get_bits::<32>(0);
        if self.top5[1].val().any() & (self.top5[1].val() != self.kones_5.val()) {
            if self.shifted[1].val().get_bit(35) {
                self.coord[1].next = self.kmin_32.val();
            } else {
                self.coord[1].next = self.kmax_32.val();
            }
        }
        self.out[1].d.next = 0.into();
        if self.side[9].q.val().get_bit(74) {
            self.out[1].d.next = self.coord[1].val();
        }
        self.m_q.d.next = 0.into();
        self.e_q.d.next = 0.into();
        if self.side[9].q.val().get_bit(74) {
            self.m_q.d.next = self.recip.result.data.val().mant;
            self.e_q.d.next = self.side[9].q.val().get_bits::<6>(68);
        }
        self.v_q.d.next = self.side[9].q.val().get_bit(74);

        self.valid_out.next = self.v_q.q.val();
        self.s.next = self.out[0].q.val();
        self.t.next = self.out[1].q.val();
        self.m.next = self.m_q.q.val();
        self.e.next = self.e_q.q.val();
    }
}

/// Verilog of the texture coordinate unit (module `tex_coord`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexCoord::default();
    uut.connect_all();
    crate::common::verilog_named(&uut, "tex_coord")
}
