//! `colour_setup`: planes for a visible triangle's three channels with ONE reciprocal (seed 001 §2.3.2
//! eqs. 6-7: `dR/dx = Ka*[(R2-R1)*dy.. - ...]`, `Ka = 1/det`; the scan's subscripts are garbled, the
//! form used is `golden::format::Plane::setup`), written into TdbS at the triangle's index (seed 000
//! §III-B). Bit-exact with `golden::shade::colour_setup` / `flat_setup`.
//!
//! ```text
//!                  +-----------------------------------------+
//!  cmd.data  ----->| SetupCommand                            |
//!  cmd.valid ----->|  det (2 products) -> canonical order    |--> tdbs_write_enable
//!  cmd.ready <-----|  -> reciprocal (rc::Reciprocal, 25 st.) |--> tdbs_write_address (index, 16 b)
//!                  |  || 6 numerators (12 products)          |--> tdbs_write_data (TdbsRecord, 424 b)
//!                  |  -> A, B: sat40(round(n*mant >> s+4))   |
//!  clock --------->|  -> C: v0*2^16 + round((A*(8-x0) +     |--> busy
//!                  |        B*(8-y0)) / 16), sat56           |
//!                  |  one shared 40x26 signed multiplier     |
//!                  +-----------------------------------------+
//! ```
//!
//! Timing (c0 = the cycle a command is taken; `golden::cycle::colour_setup` is the reference):
//! Det0 c0+1, Det1 c0+2 (the two products' operands), Det2 c0+3 (first product), Det3 c0+4 (det =
//! dx10*dy20 - dx20*dy10), Norm c0+5 (swap vertices 1, 2 if det < 0, |det| to the reciprocal), Div
//! c0+6..=c0+31 (reciprocal; the 12 numerator products run meanwhile), PlaneAB c0+32..=c0+39, PlaneC
//! c0+40..=c0+47, Write c0+48. Flat: Write at c0+1. Zero area: A = B = 0, then PlaneC c0+6..=c0+13,
//! Write c0+14. `cmd.ready` is high in Idle and Write: back-to-back shaded triangles take 48 cycles
//! each, flat ones 1. All payload outputs are 0 while
//! their enable is low.
//!
//! Pipelining: the multiplier's operands and its product are registered (`opa_r`/`opb_r`, `prod`),
//! and whoever uses a product does so two cycles after its operands were chosen, told by a tag
//! (`tag_v`, channel, phase, k; `tag1_*` is the same tag one stage earlier) which product it holds.
//! Without the product register the operand mux, the 40x26 product, the 64-bit rounding shift and the
//! saturation were one path of 42.6 ns on an ECP5 (23.5 MHz, the whole chipset's limit); without the
//! operand register the channel mux, the vertex difference and the product were 29.2 ns in the chipset
//! with the Phong CS (34.3 MHz). Each register costs 3 cycles per triangle (a det cycle, and one drain
//! cycle each for A/B and C): 48 instead of 42.
//!
//! Widths: coordinates and values are 16-bit, so every intermediate is bounded for ANY port input:
//! |det| < 2^33, |numerator| < 2^33 (35-bit register), |n*mant| < 2^58, |A*(8-x0)| < 2^56 — the
//! 64-bit product and sums never wrap.

use crate::common::{signed_bit_cast_safe, MulS, StreamIn};
use crate::cs::{SetupCommand, TdbsRecord};
use crate::rc::reciprocal::Reciprocal;
use rust_hdl::prelude::*;

#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum SetupState {
    Idle,
    Det0,
    Det1,
    Det2,
    Det3,
    Norm,
    Div,
    PlaneAB,
    PlaneC,
    Write,
}

#[derive(LogicBlock)]
pub struct ColourSetup {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Setup commands (valid/ready); taken in Idle and in the Write cycle.
    pub cmd: StreamIn<SetupCommand>,
    // To the TdbS memory (write port; the memory takes the write at the rising edge)
    /// Write the record this cycle.
    pub tdbs_write_enable: Signal<Out, Bit>,
    /// The triangle index.
    pub tdbs_write_address: Signal<Out, Bits<16>>,
    /// The record.
    pub tdbs_write_data: Signal<Out, TdbsRecord>,
    // To the controller
    /// A command is in progress (from the cycle after it was taken up to its write cycle).
    pub busy: Signal<Out, Bit>,

    recip: Reciprocal,
    mul: MulS<40, 26, 64>,
    state: DFF<SetupState>,
    index: DFF<Bits<16>>,
    material: DFF<Bits<16>>,
    x0: DFF<Signed<16>>,
    y0: DFF<Signed<16>>,
    x1: DFF<Signed<16>>,
    y1: DFF<Signed<16>>,
    x2: DFF<Signed<16>>,
    y2: DFF<Signed<16>>,
    v0r: DFF<Signed<16>>,
    v0g: DFF<Signed<16>>,
    v0b: DFF<Signed<16>>,
    v1r: DFF<Signed<16>>,
    v1g: DFF<Signed<16>>,
    v1b: DFF<Signed<16>>,
    v2r: DFF<Signed<16>>,
    v2g: DFF<Signed<16>>,
    v2b: DFF<Signed<16>>,
    /// The shared multiplier's product, registered: every consumer reads the product of the operands
    /// presented in the cycle before (a pipeline stage between the multiplier and the shift,
    /// saturation and sums behind it, which were one 42 ns path).
    prod: DFF<Signed<64>>,
    /// The multiplier's operands, registered: the operand multiplexers and the product are two
    /// clock periods (a product is in `prod` two cycles after its operands were chosen).
    opa_r: DFF<Signed<40>>,
    opb_r: DFF<Signed<26>>,
    /// The tag of the operands in `opa_r`/`opb_r` (it moves to `tag_*` with their product).
    tag1_v: DFF<Bit>,
    tag1_ch: DFF<Bits<2>>,
    tag1_ph: DFF<Bits<2>>,
    tag1_k: DFF<Bits<3>>,
    /// `prod` holds a product of the numerator, A/B or C sequence, and which one: (channel, phase) or k.
    tag_v: DFF<Bit>,
    tag_ch: DFF<Bits<2>>,
    tag_ph: DFF<Bits<2>>,
    tag_k: DFF<Bits<3>>,
    /// The numerator or C sequence has issued its last product.
    issued: DFF<Bit>,
    /// First product of a difference of two products.
    acc: DFF<Signed<64>>,
    det: DFF<Signed<36>>,
    /// Channel (0..2) and phase (0..3) of the numerator and C sequences; k (0..5) of the A/B one.
    ch: DFF<Bits<2>>,
    ph: DFF<Bits<2>>,
    k: DFF<Bits<3>>,
    n_done: DFF<Bit>,
    na_r: DFF<Signed<35>>,
    nb_r: DFF<Signed<35>>,
    na_g: DFF<Signed<35>>,
    nb_g: DFF<Signed<35>>,
    na_b: DFF<Signed<35>>,
    nb_b: DFF<Signed<35>>,
    mant: DFF<Bits<25>>,
    plane_r_a: DFF<Bits<40>>,
    plane_r_b: DFF<Bits<40>>,
    plane_r_c: DFF<Bits<56>>,
    plane_g_a: DFF<Bits<40>>,
    plane_g_b: DFF<Bits<40>>,
    plane_g_c: DFF<Bits<56>>,
    plane_b_a: DFF<Bits<40>>,
    plane_b_b: DFF<Bits<40>>,
    plane_b_c: DFF<Bits<56>>,
    // Combinational (no `let` in hdl_gen; one width change per statement, GUIDE §1)
    accept: Signal<Local, Bit>,
    op_a: Signal<Local, Signed<40>>,
    op_b: Signal<Local, Signed<26>>,
    req_valid: Signal<Local, Bit>,
    res_ready: Signal<Local, Bit>,
    dx10: Signal<Local, Signed<17>>,
    dy10: Signal<Local, Signed<17>>,
    dx20: Signal<Local, Signed<17>>,
    dy20: Signal<Local, Signed<17>>,
    cv0: Signal<Local, Signed<16>>,
    cv1: Signal<Local, Signed<16>>,
    cv2: Signal<Local, Signed<16>>,
    /// Vertex 0's value of the channel whose C the registered product belongs to.
    tv0: Signal<Local, Signed<16>>,
    dv10: Signal<Local, Signed<17>>,
    dv20: Signal<Local, Signed<17>>,
    diff: Signal<Local, Signed<64>>,
    det_abs: Signal<Local, Signed<36>>,
    n_sel: Signal<Local, Signed<35>>,
    mant26: Signal<Local, Signed<26>>,
    sh_r: DFF<Bits<7>>,
    half_r: DFF<Bits<64>>,
    sh_m1: Signal<Local, Bits<7>>,
    sh: Signal<Local, Bits<7>>,
    rs_half: Signal<Local, Bits<64>>,
    rs_y: Signal<Local, Signed<64>>,
    rs_yb: Signal<Local, Bits<64>>,
    rs_sh: Signal<Local, Bits<64>>,
    rs_top: Signal<Local, Bits<25>>,
    ab40: Signal<Local, Bits<40>>,
    ca: Signal<Local, Bits<40>>,
    cb: Signal<Local, Bits<40>>,
    ox: Signal<Local, Signed<17>>,
    oy: Signal<Local, Signed<17>>,
    cx: Signal<Local, Signed<64>>,
    cx8: Signal<Local, Signed<64>>,
    cxr: Signal<Local, Signed<64>>,
    v0w: Signal<Local, Signed<64>>,
    v0s: Signal<Local, Bits<64>>,
    csum: Signal<Local, Signed<64>>,
    c_top: Signal<Local, Bits<9>>,
    c56: Signal<Local, Bits<56>>,
    k0_2: Constant<Bits<2>>,
    k1_2: Constant<Bits<2>>,
    k2_2: Constant<Bits<2>>,
    k3_2: Constant<Bits<2>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    k2_3: Constant<Bits<3>>,
    k3_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
    k5_3: Constant<Bits<3>>,
    k6_3: Constant<Bits<3>>,
    k7_3: Constant<Bits<3>>,
    k3_7: Constant<Bits<7>>,
    k4_7: Constant<Bits<7>>,
    k16_7: Constant<Bits<7>>,
    k1_64: Constant<Bits<64>>,
    k8_64: Constant<Signed<64>>,
    k8_17: Constant<Signed<17>>,
    k0_36: Constant<Signed<36>>,
    k0_40: Constant<Bits<40>>,
    k0_56: Constant<Bits<56>>,
    k0_16: Constant<Bits<16>>,
    kmin_40: Constant<Bits<40>>,
    kmax_40: Constant<Bits<40>>,
    kmin_56: Constant<Bits<56>>,
    kmax_56: Constant<Bits<56>>,
}

impl Default for ColourSetup {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            cmd: Default::default(),
            tdbs_write_enable: Default::default(),
            tdbs_write_address: Default::default(),
            tdbs_write_data: Default::default(),
            busy: Default::default(),
            recip: Default::default(),
            mul: Default::default(),
            state: Default::default(),
            index: Default::default(),
            material: Default::default(),
            x0: Default::default(),
            y0: Default::default(),
            x1: Default::default(),
            y1: Default::default(),
            x2: Default::default(),
            y2: Default::default(),
            v0r: Default::default(),
            v0g: Default::default(),
            v0b: Default::default(),
            v1r: Default::default(),
            v1g: Default::default(),
            v1b: Default::default(),
            v2r: Default::default(),
            v2g: Default::default(),
            v2b: Default::default(),
            prod: Default::default(),
            opa_r: Default::default(),
            opb_r: Default::default(),
            tag1_v: Default::default(),
            tag1_ch: Default::default(),
            tag1_ph: Default::default(),
            tag1_k: Default::default(),
            tag_v: Default::default(),
            tag_ch: Default::default(),
            tag_ph: Default::default(),
            tag_k: Default::default(),
            issued: Default::default(),
            acc: Default::default(),
            det: Default::default(),
            ch: Default::default(),
            ph: Default::default(),
            k: Default::default(),
            n_done: Default::default(),
            na_r: Default::default(),
            nb_r: Default::default(),
            na_g: Default::default(),
            nb_g: Default::default(),
            na_b: Default::default(),
            nb_b: Default::default(),
            mant: Default::default(),
            plane_r_a: Default::default(),
            plane_r_b: Default::default(),
            plane_r_c: Default::default(),
            plane_g_a: Default::default(),
            plane_g_b: Default::default(),
            plane_g_c: Default::default(),
            plane_b_a: Default::default(),
            plane_b_b: Default::default(),
            plane_b_c: Default::default(),
            accept: Default::default(),
            op_a: Default::default(),
            op_b: Default::default(),
            req_valid: Default::default(),
            res_ready: Default::default(),
            dx10: Default::default(),
            dy10: Default::default(),
            dx20: Default::default(),
            dy20: Default::default(),
            cv0: Default::default(),
            cv1: Default::default(),
            cv2: Default::default(),
            tv0: Default::default(),
            dv10: Default::default(),
            dv20: Default::default(),
            diff: Default::default(),
            det_abs: Default::default(),
            n_sel: Default::default(),
            mant26: Default::default(),
            sh_r: Default::default(),
            half_r: Default::default(),
            sh_m1: Default::default(),
            sh: Default::default(),
            rs_half: Default::default(),
            rs_y: Default::default(),
            rs_yb: Default::default(),
            rs_sh: Default::default(),
            rs_top: Default::default(),
            ab40: Default::default(),
            ca: Default::default(),
            cb: Default::default(),
            ox: Default::default(),
            oy: Default::default(),
            cx: Default::default(),
            cx8: Default::default(),
            cxr: Default::default(),
            v0w: Default::default(),
            v0s: Default::default(),
            csum: Default::default(),
            c_top: Default::default(),
            c56: Default::default(),
            k0_2: Constant::new(0.into()),
            k1_2: Constant::new(1.into()),
            k2_2: Constant::new(2.into()),
            k3_2: Constant::new(3.into()),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k2_3: Constant::new(2.into()),
            k3_3: Constant::new(3.into()),
            k4_3: Constant::new(4.into()),
            k5_3: Constant::new(5.into()),
            k6_3: Constant::new(6.into()),
            k7_3: Constant::new(7.into()),
            k3_7: Constant::new(3.into()),
            k4_7: Constant::new(4.into()),
            k16_7: Constant::new(16.into()),
            k1_64: Constant::new(1.into()),
            k8_64: Constant::new(8.into()),
            k8_17: Constant::new(8.into()),
            k0_36: Constant::new(0.into()),
            k0_40: Constant::new(0.into()),
            k0_56: Constant::new(0.into()),
            k0_16: Constant::new(0.into()),
            kmin_40: Constant::new((1u64 << 39).into()),
            kmax_40: Constant::new(((1u64 << 39) - 1).into()),
            kmin_56: Constant::new((1u64 << 55).into()),
            kmax_56: Constant::new(((1u64 << 55) - 1).into()),
        }
    }
}

impl Logic for ColourSetup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, state, index, material, x0, y0, x1, y1, x2, y2, v0r, v0g, v0b, v1r, v1g, v1b, v2r, v2g, v2b,
            prod, sh_r, half_r, opa_r, opb_r, tag1_v, tag1_ch, tag1_ph, tag1_k, tag_v, tag_ch, tag_ph, tag_k, issued, acc, det, ch, ph, k, n_done, na_r, nb_r, na_g, nb_g, na_b, nb_b, mant, plane_r_a, plane_r_b,
            plane_r_c, plane_g_a, plane_g_b, plane_g_c, plane_b_a, plane_b_b, plane_b_c
        );
        clock!(self, clock, recip);

        // Vertex deltas of the current vertex order (17 bits: differences of 16-bit values).
        self.dx10.next = signed_bit_cast_safe::<17, 16>(self.x1.q.val()) - signed_bit_cast_safe::<17, 16>(self.x0.q.val());
        self.dy10.next = signed_bit_cast_safe::<17, 16>(self.y1.q.val()) - signed_bit_cast_safe::<17, 16>(self.y0.q.val());
        self.dx20.next = signed_bit_cast_safe::<17, 16>(self.x2.q.val()) - signed_bit_cast_safe::<17, 16>(self.x0.q.val());
        self.dy20.next = signed_bit_cast_safe::<17, 16>(self.y2.q.val()) - signed_bit_cast_safe::<17, 16>(self.y0.q.val());
        // The current channel's three vertex values.
        self.cv0.next = self.v0r.q.val();
        self.cv1.next = self.v1r.q.val();
        self.cv2.next = self.v2r.q.val();
        if self.ch.q.val() == self.k1_2.val() {
            self.cv0.next = self.v0g.q.val();
            self.cv1.next = self.v1g.q.val();
            self.cv2.next = self.v2g.q.val();
        }
        if self.ch.q.val() == self.k2_2.val() {
            self.cv0.next = self.v0b.q.val();
            self.cv1.next = self.v1b.q.val();
            self.cv2.next = self.v2b.q.val();
        }
        self.tv0.next = self.v0r.q.val();
        if self.tag_ch.q.val() == self.k1_2.val() {
            self.tv0.next = self.v0g.q.val();
        }
        if self.tag_ch.q.val() == self.k2_2.val() {
            self.tv0.next = self.v0b.q.val();
        }
        self.dv10.next = signed_bit_cast_safe::<17, 16>(self.cv1.val()) - signed_bit_cast_safe::<17, 16>(self.cv0.val());
        self.dv20.next = signed_bit_cast_safe::<17, 16>(self.cv2.val()) - signed_bit_cast_safe::<17, 16>(self.cv0.val());
        // |det| for the reciprocal (Norm).
        self.det_abs.next = self.det.q.val();
        if self.det.q.val().get_bit(35) {
            self.det_abs.next = self.k0_36.val() - self.det.q.val();
        }

        // The shared multiplier; its operands are chosen by the state below.
        self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dx10.val());
        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dy20.val());
        self.prod.d.next = self.mul.p.val();
        self.tag1_v.d.next = false;
        self.tag_v.d.next = self.tag1_v.q.val();
        self.tag_ch.d.next = self.tag1_ch.q.val();
        self.tag_ph.d.next = self.tag1_ph.q.val();
        self.tag_k.d.next = self.tag1_k.q.val();
        self.diff.next = self.acc.q.val() - self.prod.q.val();

        // A or B = sat40(round(n * mant / 2^(s+4))): add half, arithmetic shift (on Bits, through the
        // one's complement for negative values), saturate.
        self.n_sel.next = self.na_r.q.val();
        if self.k.q.val() == self.k1_3.val() {
            self.n_sel.next = self.nb_r.q.val();
        }
        if self.k.q.val() == self.k2_3.val() {
            self.n_sel.next = self.na_g.q.val();
        }
        if self.k.q.val() == self.k3_3.val() {
            self.n_sel.next = self.nb_g.q.val();
        }
        if self.k.q.val() == self.k4_3.val() {
            self.n_sel.next = self.na_b.q.val();
        }
        if self.k.q.val() == self.k5_3.val() {
            self.n_sel.next = self.nb_b.q.val();
        }
        self.mant26.next = signed_cast(bit_cast::<26, 25>(self.mant.q.val()));
        // The shift and the rounding half depend only on the reciprocal's shift: formed from its result
        // and registered with it (`sh_r`, `half_r`), so the plane path starts at a register.
        self.sh_m1.next = bit_cast::<7, 6>(self.recip.result.data.val().shift) + self.k3_7.val();
        self.sh.next = bit_cast::<7, 6>(self.recip.result.data.val().shift) + self.k4_7.val();
        self.rs_half.next = self.k1_64.val() << self.sh_m1.val();
        self.rs_y.next = self.prod.q.val() + signed_cast(self.half_r.q.val());
        self.rs_yb.next = unsigned_cast(self.rs_y.val());
        self.rs_sh.next = self.rs_yb.val() >> self.sh_r.q.val();
        if self.rs_yb.val().get_bit(63) {
            self.rs_sh.next = !((!self.rs_yb.val()) >> self.sh_r.q.val());
        }
        self.rs_top.next = self.rs_sh.val().get_bits::<25>(39);
        self.ab40.next = self.rs_sh.val().get_bits::<40>(0);
        if !(self.rs_top.val().all() | !self.rs_top.val().any()) {
            if self.rs_sh.val().get_bit(63) {
                self.ab40.next = self.kmin_40.val();
            } else {
                self.ab40.next = self.kmax_40.val();
            }
        }

        // C = sat56(v0 * 2^16 + round((A*(8-x0) + B*(8-y0)) / 16)).
        self.ca.next = self.plane_r_a.q.val();
        self.cb.next = self.plane_r_b.q.val();
        if self.ch.q.val() == self.k1_2.val() {
            self.ca.next = self.plane_g_a.q.val();
            self.cb.next = self.plane_g_b.q.val();
        }
        if self.ch.q.val() == self.k2_2.val() {
            self.ca.next = self.plane_b_a.q.val();
            self.cb.next = self.plane_b_b.q.val();
        }
        self.ox.next = self.k8_17.val() - signed_bit_cast_safe::<17, 16>(self.x0.q.val());
        self.oy.next = self.k8_17.val() - signed_bit_cast_safe::<17, 16>(self.y0.q.val());
        self.cx.next = self.acc.q.val() + self.prod.q.val();
        self.cx8.next = self.cx.val() + self.k8_64.val();
        self.cxr.next = signed_bit_cast_safe::<64, 60>(self.cx8.val().get_bits::<60>(4));
        self.v0w.next = signed_bit_cast_safe::<64, 16>(self.tv0.val());
        self.v0s.next = unsigned_cast(self.v0w.val()) << self.k16_7.val();
        self.csum.next = signed_cast(self.v0s.val()) + self.cxr.val();
        self.c_top.next = unsigned_cast(self.csum.val().get_bits::<9>(55));
        self.c56.next = unsigned_cast(self.csum.val().get_bits::<56>(0));
        if !(self.c_top.val().all() | !self.c_top.val().any()) {
            if self.csum.val().get_bit(63) {
                self.c56.next = self.kmin_56.val();
            } else {
                self.c56.next = self.kmax_56.val();
            }
        }

        // Defaults of the outputs and the reciprocal's handshake.
        self.cmd.ready.next = false;
        self.req_valid.next = false;
        self.recip.request.data.next = unsigned_cast(self.det_abs.val());
        self.res_ready.next = false;
        self.tdbs_write_enable.next = false;
        self.tdbs_write_address.next = self.k0_16.val();
        self.tdbs_write_data.next.r_a = self.k0_40.val();
        self.tdbs_write_data.next.r_b = self.k0_40.val();
        self.tdbs_write_data.next.r_c = self.k0_56.val();
        self.tdbs_write_data.next.g_a = self.k0_40.val();
        self.tdbs_write_data.next.g_b = self.k0_40.val();
        self.tdbs_write_data.next.g_c = self.k0_56.val();
        self.tdbs_write_data.next.b_a = self.k0_40.val();
        self.tdbs_write_data.next.b_b = self.k0_40.val();
        self.tdbs_write_data.next.b_c = self.k0_56.val();
        self.tdbs_write_data.next.material = self.k0_16.val();

        match self.state.q.val() {
            SetupState::Idle => {
                self.cmd.ready.next = true;
            }
            SetupState::Det0 => {
                self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dx10.val());
                self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dy20.val());
                self.state.d.next = SetupState::Det1;
            }
            SetupState::Det1 => {
                self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dx20.val());
                self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dy10.val());
                self.state.d.next = SetupState::Det2;
            }
            SetupState::Det2 => {
                self.acc.d.next = self.prod.q.val();
                self.state.d.next = SetupState::Det3;
            }
            SetupState::Det3 => {
                self.det.d.next = signed_bit_cast_safe::<36, 64>(self.diff.val());
                self.state.d.next = SetupState::Norm;
            }
            SetupState::Norm => {
                // Canonical order: swap vertices 1 and 2 when det < 0 (golden::raster::canonical_order).
                if self.det.q.val().get_bit(35) {
                    self.x1.d.next = self.x2.q.val();
                    self.y1.d.next = self.y2.q.val();
                    self.x2.d.next = self.x1.q.val();
                    self.y2.d.next = self.y1.q.val();
                    self.v1r.d.next = self.v2r.q.val();
                    self.v1g.d.next = self.v2g.q.val();
                    self.v1b.d.next = self.v2b.q.val();
                    self.v2r.d.next = self.v1r.q.val();
                    self.v2g.d.next = self.v1g.q.val();
                    self.v2b.d.next = self.v1b.q.val();
                }
                self.ch.d.next = self.k0_2.val();
                self.ph.d.next = self.k0_2.val();
                self.n_done.d.next = false;
                self.issued.d.next = false;
                if self.det.q.val() == self.k0_36.val() {
                    // Zero area (the RC never flags one visible): constant planes at vertex 0.
                    self.plane_r_a.d.next = self.k0_40.val();
                    self.plane_r_b.d.next = self.k0_40.val();
                    self.plane_g_a.d.next = self.k0_40.val();
                    self.plane_g_b.d.next = self.k0_40.val();
                    self.plane_b_a.d.next = self.k0_40.val();
                    self.plane_b_b.d.next = self.k0_40.val();
                    self.state.d.next = SetupState::PlaneC;
                } else {
                    self.req_valid.next = true;
                    if self.recip.request.ready.val() {
                        self.state.d.next = SetupState::Div;
                    }
                }
            }
            SetupState::Div => {
                // The six numerators, four products per channel, issued one per cycle and consumed from
                // `prod` in the next: na = dv10*dy20 - dv20*dy10, nb = dv20*dx10 - dv10*dx20.
                if !self.issued.q.val() {
                    self.tag1_v.d.next = true;
                    self.tag1_ch.d.next = self.ch.q.val();
                    self.tag1_ph.d.next = self.ph.q.val();
                    if self.ph.q.val() == self.k0_2.val() {
                        self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dv10.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dy20.val());
                    }
                    if self.ph.q.val() == self.k1_2.val() {
                        self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dv20.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dy10.val());
                    }
                    if self.ph.q.val() == self.k2_2.val() {
                        self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dv20.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dx10.val());
                    }
                    if self.ph.q.val() == self.k3_2.val() {
                        self.op_a.next = signed_bit_cast_safe::<40, 17>(self.dv10.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.dx20.val());
                        self.ch.d.next = self.ch.q.val() + self.k1_2.val();
                        if self.ch.q.val() == self.k2_2.val() {
                            self.issued.d.next = true;
                        }
                    }
                    self.ph.d.next = self.ph.q.val() + self.k1_2.val();
                }
                if self.tag_v.q.val() {
                    if (self.tag_ph.q.val() == self.k0_2.val()) | (self.tag_ph.q.val() == self.k2_2.val()) {
                        self.acc.d.next = self.prod.q.val();
                    }
                    if self.tag_ph.q.val() == self.k1_2.val() {
                        if self.tag_ch.q.val() == self.k0_2.val() {
                            self.na_r.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                        }
                        if self.tag_ch.q.val() == self.k1_2.val() {
                            self.na_g.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                        }
                        if self.tag_ch.q.val() == self.k2_2.val() {
                            self.na_b.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                        }
                    }
                    if self.tag_ph.q.val() == self.k3_2.val() {
                        if self.tag_ch.q.val() == self.k0_2.val() {
                            self.nb_r.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                        }
                        if self.tag_ch.q.val() == self.k1_2.val() {
                            self.nb_g.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                        }
                        if self.tag_ch.q.val() == self.k2_2.val() {
                            self.nb_b.d.next = signed_bit_cast_safe::<35, 64>(self.diff.val());
                            self.n_done.d.next = true;
                        }
                    }
                }
                if self.recip.result.valid.val() & self.n_done.q.val() {
                    self.res_ready.next = true;
                    self.mant.d.next = self.recip.result.data.val().mant;
                    self.sh_r.d.next = self.sh.val();
                    self.half_r.d.next = self.rs_half.val();
                    self.k.d.next = self.k0_3.val();
                    self.state.d.next = SetupState::PlaneAB;
                }
            }
            SetupState::PlaneAB => {
                // k = 0..5 issues n_k * mant; two cycles after, its rounded, shifted, saturated value is
                // written (k = 6 and 7 only drain the last two).
                if self.k.q.val() < self.k6_3.val() {
                    self.op_a.next = signed_bit_cast_safe::<40, 35>(self.n_sel.val());
                    self.op_b.next = self.mant26.val();
                    self.tag1_v.d.next = true;
                    self.tag1_k.d.next = self.k.q.val();
                }
                if self.tag_v.q.val() {
                    if self.tag_k.q.val() == self.k0_3.val() {
                        self.plane_r_a.d.next = self.ab40.val();
                    }
                    if self.tag_k.q.val() == self.k1_3.val() {
                        self.plane_r_b.d.next = self.ab40.val();
                    }
                    if self.tag_k.q.val() == self.k2_3.val() {
                        self.plane_g_a.d.next = self.ab40.val();
                    }
                    if self.tag_k.q.val() == self.k3_3.val() {
                        self.plane_g_b.d.next = self.ab40.val();
                    }
                    if self.tag_k.q.val() == self.k4_3.val() {
                        self.plane_b_a.d.next = self.ab40.val();
                    }
                    if self.tag_k.q.val() == self.k5_3.val() {
                        self.plane_b_b.d.next = self.ab40.val();
                    }
                }
                if self.k.q.val() == self.k7_3.val() {
                    self.ch.d.next = self.k0_2.val();
                    self.ph.d.next = self.k0_2.val();
                    self.issued.d.next = false;
                    self.state.d.next = SetupState::PlaneC;
                }
                self.k.d.next = self.k.q.val() + self.k1_3.val();
            }
            SetupState::PlaneC => {
                // Per channel: A*(8-x0), then B*(8-y0); C is formed the cycle after the second product.
                if !self.issued.q.val() {
                    self.tag1_v.d.next = true;
                    self.tag1_ch.d.next = self.ch.q.val();
                    self.tag1_ph.d.next = self.ph.q.val();
                    if self.ph.q.val() == self.k0_2.val() {
                        self.op_a.next = signed_cast(self.ca.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.ox.val());
                        self.ph.d.next = self.k1_2.val();
                    } else {
                        self.op_a.next = signed_cast(self.cb.val());
                        self.op_b.next = signed_bit_cast_safe::<26, 17>(self.oy.val());
                        self.ph.d.next = self.k0_2.val();
                        self.ch.d.next = self.ch.q.val() + self.k1_2.val();
                        if self.ch.q.val() == self.k2_2.val() {
                            self.issued.d.next = true;
                        }
                    }
                }
                if self.tag_v.q.val() {
                    if self.tag_ph.q.val() == self.k0_2.val() {
                        self.acc.d.next = self.prod.q.val();
                    } else {
                        if self.tag_ch.q.val() == self.k0_2.val() {
                            self.plane_r_c.d.next = self.c56.val();
                        }
                        if self.tag_ch.q.val() == self.k1_2.val() {
                            self.plane_g_c.d.next = self.c56.val();
                        }
                        if self.tag_ch.q.val() == self.k2_2.val() {
                            self.plane_b_c.d.next = self.c56.val();
                            self.state.d.next = SetupState::Write;
                        }
                    }
                }
            }
            SetupState::Write => {
                self.cmd.ready.next = true;
                self.tdbs_write_enable.next = true;
                self.tdbs_write_address.next = self.index.q.val();
                self.tdbs_write_data.next.r_a = self.plane_r_a.q.val();
                self.tdbs_write_data.next.r_b = self.plane_r_b.q.val();
                self.tdbs_write_data.next.r_c = self.plane_r_c.q.val();
                self.tdbs_write_data.next.g_a = self.plane_g_a.q.val();
                self.tdbs_write_data.next.g_b = self.plane_g_b.q.val();
                self.tdbs_write_data.next.g_c = self.plane_g_c.q.val();
                self.tdbs_write_data.next.b_a = self.plane_b_a.q.val();
                self.tdbs_write_data.next.b_b = self.plane_b_b.q.val();
                self.tdbs_write_data.next.b_c = self.plane_b_c.q.val();
                self.tdbs_write_data.next.material = self.material.q.val();
                self.state.d.next = SetupState::Idle;
            }
            _ => {
                self.state.d.next = SetupState::Idle;
            }
        }

        // Each multiplier and reciprocal input is driven exactly once per evaluation of this block: with a default
        // followed by an override, an event-driven simulator (Icarus) re-evaluates the product on the
        // intermediate value, re-runs this block, and never settles.
        self.opa_r.d.next = self.op_a.val();
        self.opb_r.d.next = self.op_b.val();
        self.mul.a.next = self.opa_r.q.val();
        self.mul.b.next = self.opb_r.q.val();
        self.recip.request.valid.next = self.req_valid.val();
        self.recip.result.ready.next = self.res_ready.val();

        // Take a command (Idle or Write).
        self.accept.next = self.cmd.ready.val() & self.cmd.valid.val();
        if self.accept.val() {
            self.index.d.next = self.cmd.data.val().index;
            self.x0.d.next = signed_cast(self.cmd.data.val().x0);
            self.y0.d.next = signed_cast(self.cmd.data.val().y0);
            self.x1.d.next = signed_cast(self.cmd.data.val().x1);
            self.y1.d.next = signed_cast(self.cmd.data.val().y1);
            self.x2.d.next = signed_cast(self.cmd.data.val().x2);
            self.y2.d.next = signed_cast(self.cmd.data.val().y2);
            self.v0r.d.next = signed_cast(self.cmd.data.val().v0r);
            self.v0g.d.next = signed_cast(self.cmd.data.val().v0g);
            self.v0b.d.next = signed_cast(self.cmd.data.val().v0b);
            self.v1r.d.next = signed_cast(self.cmd.data.val().v1r);
            self.v1g.d.next = signed_cast(self.cmd.data.val().v1g);
            self.v1b.d.next = signed_cast(self.cmd.data.val().v1b);
            self.v2r.d.next = signed_cast(self.cmd.data.val().v2r);
            self.v2g.d.next = signed_cast(self.cmd.data.val().v2g);
            self.v2b.d.next = signed_cast(self.cmd.data.val().v2b);
            if self.cmd.data.val().flat {
                // golden::shade::flat_setup: constant planes, material 0.
                self.material.d.next = self.k0_16.val();
                self.plane_r_a.d.next = self.k0_40.val();
                self.plane_r_b.d.next = self.k0_40.val();
                self.plane_r_c.d.next = bit_cast::<56, 8>(self.cmd.data.val().flat_r) << self.k16_7.val();
                self.plane_g_a.d.next = self.k0_40.val();
                self.plane_g_b.d.next = self.k0_40.val();
                self.plane_g_c.d.next = bit_cast::<56, 8>(self.cmd.data.val().flat_g) << self.k16_7.val();
                self.plane_b_a.d.next = self.k0_40.val();
                self.plane_b_b.d.next = self.k0_40.val();
                self.plane_b_c.d.next = bit_cast::<56, 8>(self.cmd.data.val().flat_b) << self.k16_7.val();
                self.state.d.next = SetupState::Write;
            } else {
                self.material.d.next = self.cmd.data.val().material;
                self.state.d.next = SetupState::Det0;
            }
        }
        self.busy.next = self.state.q.val() != SetupState::Idle;
    }
}
