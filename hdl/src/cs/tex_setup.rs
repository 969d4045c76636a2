//! `tex_setup`: the texture planes s/w, t/w and 1/w of a visible triangle (issue 17, item 4), written
//! into TdbT (the texture half of the triangle database) at the triangle's index. Bit-exact with
//! `golden::texcoord::setup` (the colour planes' arithmetic, `golden::format::Plane::setup`, on wider
//! values) and timed as `golden::cycle::tex_setup`: the same handshake as `colour_setup` (a command
//! every 4 cycles), so that the two, given one command stream, take each triangle together; the record
//! is written 23 cycles after the command is taken.
//!
//! ```text
//!  cmd (valid/ready, one per 4 cycles): index, x0..y2 (20 b), per vertex s/w, t/w, 1/w (33 b)
//!   | station 1 (cycles 1-4): det = dx10 dy20 - dx20 dy10 (2 x 21x21, cycles 1-3)
//!   | cycle 4: |det| -> reciprocal unit (the RC's, pipelined, 10 cycles) -> mant, shift in cycle 14
//!   | stations 2, 3: the command waits for the reciprocal
//!   | station 4 (cycles 13-15): one plane per cycle, s/w then t/w then 1/w:
//!   |   cycle 13+c: dv10, dv20 (34 b); 14+c: 4 products 34x21; 15+c: na, nb (55 b)
//!   |   16+c: n negated if det < 0, 0 if det == 0; 17+c: n mant (2 x 55x26); 18+c: A, B = sat40(round)
//!   |   19+c: A (128 - x0), B (128 - y0) (2 x 40x21); 20+c: C = sat56(v0 2^16 + round(sum / 256))
//!   v cycle 23: tdbt_write {s/w plane (held from 21), t/w (from 22), 1/w}
//! ```
//!
//! Widths: values are 33-bit two's complement (|s/w| <= 2^31 from `golden::texcoord::vertex_values`),
//! and coordinates 20-bit (S11.8), so |dv| < 2^34, |n| < 2^54, |n mant| < 2^78 (80-bit products,
//! `PlaneRoundWide`), |A (128 - x0)| < 2^59: nothing wraps for any port input.
//!
//! The reciprocal of det is computed here again, not taken from `colour_setup`, which has the same
//! quotient only in cycle 31 (its iterative divider): taking it there would hold every plane's
//! numerators 17 cycles longer, more flip-flops than the pipelined divider costs. The command's
//! stations (4 x 433 bits) are most of the block's flip-flops.

use crate::common::{signed_bit_cast_safe, MulSplitS, StreamIn};
use crate::cs::plane_round::PlaneRoundWide;
use crate::cs::{TdbtRecord, TexSetupCommand, TexValues};
use crate::rc::reciprocal::Reciprocal;
use rust_hdl::prelude::*;

/// Cycles from taking a command to its TdbT write (`golden::cycle::tex_setup::TEX_SETUP_LATENCY`).
pub const TEX_SETUP_LATENCY: u64 = 23;

#[derive(LogicBlock)]
pub struct TexSetup {
    pub clock: Signal<In, Clock>,
    /// Texture-setup commands (valid/ready); `ready` is low in the 3 cycles after a command is taken.
    pub cmd: StreamIn<TexSetupCommand>,
    /// Write the record this cycle (the TdbT memory takes it at the rising edge).
    pub tdbt_write_enable: Signal<Out, Bit>,
    /// The triangle index.
    pub tdbt_write_address: Signal<Out, Bits<16>>,
    /// The record; 0 while the enable is low.
    pub tdbt_write_data: Signal<Out, TdbtRecord>,
    /// Some command is in progress (from the cycle after it was taken up to its write cycle).
    pub busy: Signal<Out, Bit>,
    tok: DFF<Bits<23>>,
    cmd1: DFF<TexSetupCommand>,
    cmd2: DFF<TexSetupCommand>,
    cmd3: DFF<TexSetupCommand>,
    cmd4: DFF<TexSetupCommand>,
    opd_a: [DFF<Signed<21>>; 2],
    opd_b: [DFF<Signed<21>>; 2],
    pd: [DFF<Signed<42>>; 2],
    det: DFF<Signed<44>>,
    neg2: DFF<Bit>,
    neg3: DFF<Bit>,
    neg4: DFF<Bit>,
    zero2: DFF<Bit>,
    zero3: DFF<Bit>,
    zero4: DFF<Bit>,
    rm: DFF<Bits<25>>,
    rsh: DFF<Bits<6>>,
    rneg: DFF<Bit>,
    rzero: DFF<Bit>,
    opn_a: [DFF<Signed<34>>; 4],
    opn_b: [DFF<Signed<21>>; 4],
    pn: [DFF<Signed<55>>; 4],
    na: DFF<Signed<55>>,
    nb: DFF<Signed<55>>,
    side: [DFF<Bits<73>>; 7],
    opab_n: [DFF<Signed<55>>; 2],
    opab_m: DFF<Signed<26>>,
    sh1: DFF<Bits<7>>,
    sh2: DFF<Bits<7>>,
    pab: [DFF<Signed<80>>; 2],
    ab: [DFF<Bits<40>>; 2],
    pc: [DFF<Signed<61>>; 2],
    ab7: [DFF<Bits<40>>; 2],
    pl_a: DFF<Bits<40>>,
    pl_b: DFF<Bits<40>>,
    pl_c: DFF<Bits<56>>,
    rs_a: DFF<Bits<40>>,
    rs_b: DFF<Bits<40>>,
    rs_c: DFF<Bits<56>>,
    rt_a: DFF<Bits<40>>,
    rt_b: DFF<Bits<40>>,
    rt_c: DFF<Bits<56>>,
    idx5: DFF<Bits<16>>,
    idx6: DFF<Bits<16>>,
    md: [MulSplitS<21, 21, 42, 3, 3>; 2],
    recip: Reciprocal,
    mn: [MulSplitS<34, 21, 55, 0, 3>; 4],
    mab: [MulSplitS<55, 26, 80, 3, 0>; 2],
    round: [PlaneRoundWide; 2],
    mc: [MulSplitS<40, 21, 61, 0, 3>; 2],
    ready: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
    ax0: Signal<Local, Signed<20>>,
    ay0: Signal<Local, Signed<20>>,
    ax1: Signal<Local, Signed<20>>,
    ay1: Signal<Local, Signed<20>>,
    ax2: Signal<Local, Signed<20>>,
    ay2: Signal<Local, Signed<20>>,
    det_abs: Signal<Local, Signed<44>>,
    det_absu: Signal<Local, Bits<44>>,
    det_zero: Signal<Local, Bit>,
    gx0: Signal<Local, Signed<20>>,
    gy0: Signal<Local, Signed<20>>,
    gx1: Signal<Local, Signed<20>>,
    gy1: Signal<Local, Signed<20>>,
    gx2: Signal<Local, Signed<20>>,
    gy2: Signal<Local, Signed<20>>,
    dx10: Signal<Local, Signed<21>>,
    dy10: Signal<Local, Signed<21>>,
    dx20: Signal<Local, Signed<21>>,
    dy20: Signal<Local, Signed<21>>,
    ex10: Signal<Local, Signed<21>>,
    ey10: Signal<Local, Signed<21>>,
    ex20: Signal<Local, Signed<21>>,
    ey20: Signal<Local, Signed<21>>,
    vals4: Signal<Local, TexValues>,
    vs0: Signal<Local, Bits<33>>,
    vs1: Signal<Local, Bits<33>>,
    vs2: Signal<Local, Bits<33>>,
    sv0: Signal<Local, Signed<33>>,
    sv1: Signal<Local, Signed<33>>,
    sv2: Signal<Local, Signed<33>>,
    dv10: Signal<Local, Signed<34>>,
    dv20: Signal<Local, Signed<34>>,
    side_in: Signal<Local, Bits<73>>,
    wn_a: Signal<Local, Signed<55>>,
    wn_b: Signal<Local, Signed<55>>,
    cx0: Signal<Local, Bits<20>>,
    cy0: Signal<Local, Bits<20>>,
    scx0: Signal<Local, Signed<20>>,
    scy0: Signal<Local, Signed<20>>,
    ox: Signal<Local, Signed<21>>,
    oy: Signal<Local, Signed<21>>,
    cx: Signal<Local, Signed<64>>,
    cx8: Signal<Local, Signed<64>>,
    cx8u: Signal<Local, Bits<64>>,
    cx56: Signal<Local, Bits<56>>,
    scx56: Signal<Local, Signed<56>>,
    cxr: Signal<Local, Signed<64>>,
    cv: Signal<Local, Bits<33>>,
    scv: Signal<Local, Signed<33>>,
    v0w: Signal<Local, Signed<64>>,
    v0s: Signal<Local, Bits<64>>,
    csum: Signal<Local, Signed<64>>,
    csumu: Signal<Local, Bits<64>>,
    c_top: Signal<Local, Bits<9>>,
    c56: Signal<Local, Bits<56>>,
    k1_23: Constant<Bits<23>>,
    k0_16: Constant<Bits<16>>,
    k0_44: Constant<Signed<44>>,
    k0_55: Constant<Signed<55>>,
    k16_7: Constant<Bits<7>>,
    k33_7: Constant<Bits<7>>,
    k53_7: Constant<Bits<7>>,
    k128_64: Constant<Signed<64>>,
    k128_21: Constant<Signed<21>>,
    k0_40: Constant<Bits<40>>,
    k0_56: Constant<Bits<56>>,
    kmin_56: Constant<Bits<56>>,
    kmax_56: Constant<Bits<56>>,
}

impl Default for TexSetup {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            cmd: Default::default(),
            tdbt_write_enable: Default::default(),
            tdbt_write_address: Default::default(),
            tdbt_write_data: Default::default(),
            busy: Default::default(),
            tok: Default::default(),
            cmd1: Default::default(),
            cmd2: Default::default(),
            cmd3: Default::default(),
            cmd4: Default::default(),
            opd_a: Default::default(),
            opd_b: Default::default(),
            pd: Default::default(),
            det: Default::default(),
            neg2: Default::default(),
            neg3: Default::default(),
            neg4: Default::default(),
            zero2: Default::default(),
            zero3: Default::default(),
            zero4: Default::default(),
            rm: Default::default(),
            rsh: Default::default(),
            rneg: Default::default(),
            rzero: Default::default(),
            opn_a: Default::default(),
            opn_b: Default::default(),
            pn: Default::default(),
            na: Default::default(),
            nb: Default::default(),
            side: Default::default(),
            opab_n: Default::default(),
            opab_m: Default::default(),
            sh1: Default::default(),
            sh2: Default::default(),
            pab: Default::default(),
            ab: Default::default(),
            pc: Default::default(),
            ab7: Default::default(),
            pl_a: Default::default(),
            pl_b: Default::default(),
            pl_c: Default::default(),
            rs_a: Default::default(),
            rs_b: Default::default(),
            rs_c: Default::default(),
            rt_a: Default::default(),
            rt_b: Default::default(),
            rt_c: Default::default(),
            idx5: Default::default(),
            idx6: Default::default(),
            md: std::array::from_fn(|_| Default::default()),
            recip: Default::default(),
            mn: std::array::from_fn(|_| Default::default()),
            mab: std::array::from_fn(|_| Default::default()),
            round: std::array::from_fn(|_| Default::default()),
            mc: std::array::from_fn(|_| Default::default()),
            ready: Default::default(),
            accept: Default::default(),
            ax0: Default::default(),
            ay0: Default::default(),
            ax1: Default::default(),
            ay1: Default::default(),
            ax2: Default::default(),
            ay2: Default::default(),
            det_abs: Default::default(),
            det_absu: Default::default(),
            det_zero: Default::default(),
            gx0: Default::default(),
            gy0: Default::default(),
            gx1: Default::default(),
            gy1: Default::default(),
            gx2: Default::default(),
            gy2: Default::default(),
            dx10: Default::default(),
            dy10: Default::default(),
            dx20: Default::default(),
            dy20: Default::default(),
            ex10: Default::default(),
            ey10: Default::default(),
            ex20: Default::default(),
            ey20: Default::default(),
            vals4: Default::default(),
            vs0: Default::default(),
            vs1: Default::default(),
            vs2: Default::default(),
            sv0: Default::default(),
            sv1: Default::default(),
            sv2: Default::default(),
            dv10: Default::default(),
            dv20: Default::default(),
            side_in: Default::default(),
            wn_a: Default::default(),
            wn_b: Default::default(),
            cx0: Default::default(),
            cy0: Default::default(),
            scx0: Default::default(),
            scy0: Default::default(),
            ox: Default::default(),
            oy: Default::default(),
            cx: Default::default(),
            cx8: Default::default(),
            cx8u: Default::default(),
            cx56: Default::default(),
            scx56: Default::default(),
            cxr: Default::default(),
            cv: Default::default(),
            scv: Default::default(),
            v0w: Default::default(),
            v0s: Default::default(),
            csum: Default::default(),
            csumu: Default::default(),
            c_top: Default::default(),
            c56: Default::default(),
            k1_23: Constant::new(1.into()),
            k0_16: Constant::new(0.into()),
            k0_44: Constant::new(0.into()),
            k0_55: Constant::new(0.into()),
            k16_7: Constant::new(16.into()),
            k33_7: Constant::new(33.into()),
            k53_7: Constant::new(53.into()),
            k128_64: Constant::new(128.into()),
            k128_21: Constant::new(128.into()),
            k0_40: Constant::new(0.into()),
            k0_56: Constant::new(0.into()),
            kmin_56: Constant::new((1u64 << 55).into()),
            kmax_56: Constant::new(((1u64 << 55) - 1).into()),
        }
    }
}

impl Logic for TexSetup {
    #[hdl_gen]
    fn update(&mut self) {
        self.tok.clock.next = self.clock.val();
        self.tok.d.next = self.tok.q.val();
        self.cmd1.clock.next = self.clock.val();
        self.cmd1.d.next = self.cmd1.q.val();
        self.cmd2.clock.next = self.clock.val();
        self.cmd2.d.next = self.cmd2.q.val();
        self.cmd3.clock.next = self.clock.val();
        self.cmd3.d.next = self.cmd3.q.val();
        self.cmd4.clock.next = self.clock.val();
        self.cmd4.d.next = self.cmd4.q.val();
        for u in 0..2 {
            self.opd_a[u].clock.next = self.clock.val();
            self.opd_a[u].d.next = self.opd_a[u].q.val();
        }
        for u in 0..2 {
            self.opd_b[u].clock.next = self.clock.val();
            self.opd_b[u].d.next = self.opd_b[u].q.val();
        }
        for u in 0..2 {
            self.pd[u].clock.next = self.clock.val();
            self.pd[u].d.next = self.pd[u].q.val();
        }
        self.det.clock.next = self.clock.val();
        self.det.d.next = self.det.q.val();
        self.neg2.clock.next = self.clock.val();
        self.neg2.d.next = self.neg2.q.val();
        self.neg3.clock.next = self.clock.val();
        self.neg3.d.next = self.neg3.q.val();
        self.neg4.clock.next = self.clock.val();
        self.neg4.d.next = self.neg4.q.val();
        self.zero2.clock.next = self.clock.val();
        self.zero2.d.next = self.zero2.q.val();
        self.zero3.clock.next = self.clock.val();
        self.zero3.d.next = self.zero3.q.val();
        self.zero4.clock.next = self.clock.val();
        self.zero4.d.next = self.zero4.q.val();
        self.rm.clock.next = self.clock.val();
        self.rm.d.next = self.rm.q.val();
        self.rsh.clock.next = self.clock.val();
        self.rsh.d.next = self.rsh.q.val();
        self.rneg.clock.next = self.clock.val();
        self.rneg.d.next = self.rneg.q.val();
        self.rzero.clock.next = self.clock.val();
        self.rzero.d.next = self.rzero.q.val();
        for u in 0..4 {
            self.opn_a[u].clock.next = self.clock.val();
            self.opn_a[u].d.next = self.opn_a[u].q.val();
        }
        for u in 0..4 {
            self.opn_b[u].clock.next = self.clock.val();
            self.opn_b[u].d.next = self.opn_b[u].q.val();
        }
        for u in 0..4 {
            self.pn[u].clock.next = self.clock.val();
            self.pn[u].d.next = self.pn[u].q.val();
        }
        self.na.clock.next = self.clock.val();
        self.na.d.next = self.na.q.val();
        self.nb.clock.next = self.clock.val();
        self.nb.d.next = self.nb.q.val();
        for u in 0..7 {
            self.side[u].clock.next = self.clock.val();
            self.side[u].d.next = self.side[u].q.val();
        }
        for u in 0..2 {
            self.opab_n[u].clock.next = self.clock.val();
            self.opab_n[u].d.next = self.opab_n[u].q.val();
        }
        self.opab_m.clock.next = self.clock.val();
        self.opab_m.d.next = self.opab_m.q.val();
        self.sh1.clock.next = self.clock.val();
        self.sh1.d.next = self.sh1.q.val();
        self.sh2.clock.next = self.clock.val();
        self.sh2.d.next = self.sh2.q.val();
        for u in 0..2 {
            self.pab[u].clock.next = self.clock.val();
            self.pab[u].d.next = self.pab[u].q.val();
        }
        for u in 0..2 {
            self.ab[u].clock.next = self.clock.val();
            self.ab[u].d.next = self.ab[u].q.val();
        }
        for u in 0..2 {
            self.pc[u].clock.next = self.clock.val();
            self.pc[u].d.next = self.pc[u].q.val();
        }
        for u in 0..2 {
            self.ab7[u].clock.next = self.clock.val();
            self.ab7[u].d.next = self.ab7[u].q.val();
        }
        self.pl_a.clock.next = self.clock.val();
        self.pl_a.d.next = self.pl_a.q.val();
        self.pl_b.clock.next = self.clock.val();
        self.pl_b.d.next = self.pl_b.q.val();
        self.pl_c.clock.next = self.clock.val();
        self.pl_c.d.next = self.pl_c.q.val();
        self.rs_a.clock.next = self.clock.val();
        self.rs_a.d.next = self.rs_a.q.val();
        self.rs_b.clock.next = self.clock.val();
        self.rs_b.d.next = self.rs_b.q.val();
        self.rs_c.clock.next = self.clock.val();
        self.rs_c.d.next = self.rs_c.q.val();
        self.rt_a.clock.next = self.clock.val();
        self.rt_a.d.next = self.rt_a.q.val();
        self.rt_b.clock.next = self.clock.val();
        self.rt_b.d.next = self.rt_b.q.val();
        self.rt_c.clock.next = self.clock.val();
        self.rt_c.d.next = self.rt_c.q.val();
        self.idx5.clock.next = self.clock.val();
        self.idx5.d.next = self.idx5.q.val();
        self.idx6.clock.next = self.clock.val();
        self.idx6.d.next = self.idx6.q.val();

        // Tokens: bit o-1 of `tok` is set in cycle o of a command (cycle 0: taken).
        self.ready.next = !(self.tok.q.val().get_bit(0) | self.tok.q.val().get_bit(1) | self.tok.q.val().get_bit(2));
        self.accept.next = self.cmd.valid.val() & self.ready.val();
        self.cmd.ready.next = self.ready.val();
        self.tok.d.next = self.tok.q.val() << self.k1_23.val();
        if self.accept.val() {
            self.tok.d.next = (self.tok.q.val() << self.k1_23.val()) | self.k1_23.val();
        }
        self.busy.next = self.tok.q.val().any();

        // The command's stations: 1 (cycles 1-4), 2 (5-8), 3 (9-12), 4 (13-16).
        if self.accept.val() {
            self.cmd1.d.next = self.cmd.data.val();
        }
        if self.tok.q.val().get_bit(3) {
            self.cmd2.d.next = self.cmd1.q.val();
        }
        if self.tok.q.val().get_bit(7) {
            self.cmd3.d.next = self.cmd2.q.val();
        }
        if self.tok.q.val().get_bit(11) {
            self.cmd4.d.next = self.cmd3.q.val();
        }

        // Cycles 1-3: det = dx10 dy20 - dx20 dy10 (operands, products, difference registered).
        self.ax0.next = signed_cast(self.cmd1.q.val().x0);
        self.ay0.next = signed_cast(self.cmd1.q.val().y0);
        self.ax1.next = signed_cast(self.cmd1.q.val().x1);
        self.ay1.next = signed_cast(self.cmd1.q.val().y1);
        self.ax2.next = signed_cast(self.cmd1.q.val().x2);
        self.ay2.next = signed_cast(self.cmd1.q.val().y2);
        self.ex10.next = signed_bit_cast_safe::<21, 20>(self.ax1.val()) - signed_bit_cast_safe::<21, 20>(self.ax0.val());
        self.ey10.next = signed_bit_cast_safe::<21, 20>(self.ay1.val()) - signed_bit_cast_safe::<21, 20>(self.ay0.val());
        self.ex20.next = signed_bit_cast_safe::<21, 20>(self.ax2.val()) - signed_bit_cast_safe::<21, 20>(self.ax0.val());
        self.ey20.next = signed_bit_cast_safe::<21, 20>(self.ay2.val()) - signed_bit_cast_safe::<21, 20>(self.ay0.val());
        self.opd_a[0].d.next = self.ex10.val();
        self.opd_b[0].d.next = self.ey20.val();
        self.opd_a[1].d.next = self.ex20.val();
        self.opd_b[1].d.next = self.ey10.val();
        for u in 0..2 {
            self.md[u].a.next = self.opd_a[u].q.val();
            self.md[u].b.next = self.opd_b[u].q.val();
            self.pd[u].d.next = self.md[u].p.val();
        }
        self.det.d.next = signed_bit_cast_safe::<44, 42>(self.pd[0].q.val()) - signed_bit_cast_safe::<44, 42>(self.pd[1].q.val());

        // Cycle 4: |det| into the reciprocal unit (result in cycle 14); its sign and det == 0 wait
        // beside it in the stations.
        self.det_abs.next = self.det.q.val();
        if self.det.q.val().get_bit(43) {
            self.det_abs.next = self.k0_44.val() - self.det.q.val();
        }
        self.det_absu.next = unsigned_cast(self.det_abs.val());
        self.det_zero.next = self.det.q.val() == self.k0_44.val();
        self.recip.clock.next = self.clock.val();
        self.recip.request.data.next = self.det_absu.val();
        self.recip.request.valid.next = self.tok.q.val().get_bit(3);
        self.recip.result.ready.next = true;
        if self.tok.q.val().get_bit(3) {
            self.neg2.d.next = self.det.q.val().get_bit(43);
            self.zero2.d.next = self.det_zero.val();
        }
        if self.tok.q.val().get_bit(7) {
            self.neg3.d.next = self.neg2.q.val();
            self.zero3.d.next = self.zero2.q.val();
        }
        if self.tok.q.val().get_bit(11) {
            self.neg4.d.next = self.neg3.q.val();
            self.zero4.d.next = self.zero3.q.val();
        }
        // Cycle 14: the reciprocal arrives; held for the three planes' products (cycles 16-18).
        if self.recip.result.valid.val() {
            self.rm.d.next = self.recip.result.data.val().mant;
            self.rsh.d.next = self.recip.result.data.val().shift;
        }
        if self.tok.q.val().get_bit(13) {
            self.rneg.d.next = self.neg4.q.val();
            self.rzero.d.next = self.zero4.q.val();
        }

        // Cycles 13-15: one plane per cycle (s/w, t/w, 1/w) from station 4: its vertex differences
        // into the four numerator products (dv10 dy20, dv20 dy10, dv20 dx10, dv10 dx20).
        self.gx0.next = signed_cast(self.cmd4.q.val().x0);
        self.gy0.next = signed_cast(self.cmd4.q.val().y0);
        self.gx1.next = signed_cast(self.cmd4.q.val().x1);
        self.gy1.next = signed_cast(self.cmd4.q.val().y1);
        self.gx2.next = signed_cast(self.cmd4.q.val().x2);
        self.gy2.next = signed_cast(self.cmd4.q.val().y2);
        self.dx10.next = signed_bit_cast_safe::<21, 20>(self.gx1.val()) - signed_bit_cast_safe::<21, 20>(self.gx0.val());
        self.dy10.next = signed_bit_cast_safe::<21, 20>(self.gy1.val()) - signed_bit_cast_safe::<21, 20>(self.gy0.val());
        self.dx20.next = signed_bit_cast_safe::<21, 20>(self.gx2.val()) - signed_bit_cast_safe::<21, 20>(self.gx0.val());
        self.dy20.next = signed_bit_cast_safe::<21, 20>(self.gy2.val()) - signed_bit_cast_safe::<21, 20>(self.gy0.val());
        self.vals4.next = self.cmd4.q.val().values;
        self.vs0.next = self.vals4.val().v0s;
        self.vs1.next = self.vals4.val().v1s;
        self.vs2.next = self.vals4.val().v2s;
        if self.tok.q.val().get_bit(13) {
            self.vs0.next = self.vals4.val().v0t;
            self.vs1.next = self.vals4.val().v1t;
            self.vs2.next = self.vals4.val().v2t;
        }
        if self.tok.q.val().get_bit(14) {
            self.vs0.next = self.vals4.val().v0q;
            self.vs1.next = self.vals4.val().v1q;
            self.vs2.next = self.vals4.val().v2q;
        }
        self.sv0.next = signed_cast(self.vs0.val());
        self.sv1.next = signed_cast(self.vs1.val());
        self.sv2.next = signed_cast(self.vs2.val());
        self.dv10.next = signed_bit_cast_safe::<34, 33>(self.sv1.val()) - signed_bit_cast_safe::<34, 33>(self.sv0.val());
        self.dv20.next = signed_bit_cast_safe::<34, 33>(self.sv2.val()) - signed_bit_cast_safe::<34, 33>(self.sv0.val());
        self.opn_a[0].d.next = self.dv10.val();
        self.opn_b[0].d.next = self.dy20.val();
        self.opn_a[1].d.next = self.dv20.val();
        self.opn_b[1].d.next = self.dy10.val();
        self.opn_a[2].d.next = self.dv20.val();
        self.opn_b[2].d.next = self.dx10.val();
        self.opn_a[3].d.next = self.dv10.val();
        self.opn_b[3].d.next = self.dx20.val();
        // What the plane needs later, {y0, x0, v0}, one cycle behind the plane's operands per entry.
        self.side_in.next = bit_cast::<73, 33>(self.vs0.val()) | (bit_cast::<73, 20>(self.cmd4.q.val().x0) << self.k33_7.val()) | (bit_cast::<73, 20>(self.cmd4.q.val().y0) << self.k53_7.val());
        self.side[0].d.next = self.side_in.val();
        for u in 1..7 {
            self.side[u].d.next = self.side[u - 1].q.val();
        }
        for u in 0..4 {
            self.mn[u].a.next = self.opn_a[u].q.val();
            self.mn[u].b.next = self.opn_b[u].q.val();
            self.pn[u].d.next = self.mn[u].p.val();
        }
        self.na.d.next = self.pn[0].q.val() - self.pn[1].q.val();
        self.nb.d.next = self.pn[2].q.val() - self.pn[3].q.val();

        // Cycles 16-18: A, B = sat40(round(n mant / 2^(shift + 4))), n negated when det < 0 (the
        // vertex order with det > 0 swaps vertices 1 and 2) and 0 when det == 0.
        self.wn_a.next = self.na.q.val();
        self.wn_b.next = self.nb.q.val();
        if self.rneg.q.val() {
            self.wn_a.next = self.k0_55.val() - self.na.q.val();
            self.wn_b.next = self.k0_55.val() - self.nb.q.val();
        }
        if self.rzero.q.val() {
            self.wn_a.next = self.k0_55.val();
            self.wn_b.next = self.k0_55.val();
        }
        self.opab_n[0].d.next = self.wn_a.val();
        self.opab_n[1].d.next = self.wn_b.val();
        self.opab_m.d.next = signed_cast(bit_cast::<26, 25>(self.rm.q.val()));
        self.sh1.d.next = bit_cast::<7, 6>(self.rsh.q.val());
        self.sh2.d.next = self.sh1.q.val();
        for u in 0..2 {
            self.mab[u].a.next = self.opab_n[u].q.val();
            self.mab[u].b.next = self.opab_m.q.val();
            self.pab[u].d.next = self.mab[u].p.val();
            self.round[u].p.next = unsigned_cast(self.pab[u].q.val());
            self.round[u].sh.next = self.sh2.q.val();
            self.ab[u].d.next = self.round[u].out.val();
        }

        // Cycles 19-21: A (8 - x0) and B (8 - y0); C = sat56(v0 2^16 + round((..) / 16)) a cycle later.
        self.cx0.next = self.side[5].q.val().get_bits::<20>(33);
        self.cy0.next = self.side[5].q.val().get_bits::<20>(53);
        self.scx0.next = signed_cast(self.cx0.val());
        self.scy0.next = signed_cast(self.cy0.val());
        self.ox.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(self.scx0.val());
        self.oy.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(self.scy0.val());
        self.mc[0].a.next = signed_cast(self.ab[0].q.val());
        self.mc[0].b.next = self.ox.val();
        self.mc[1].a.next = signed_cast(self.ab[1].q.val());
        self.mc[1].b.next = self.oy.val();
        for u in 0..2 {
            self.pc[u].d.next = self.mc[u].p.val();
            self.ab7[u].d.next = self.ab[u].q.val();
        }
        self.cx.next = signed_bit_cast_safe::<64, 61>(self.pc[0].q.val()) + signed_bit_cast_safe::<64, 61>(self.pc[1].q.val());
        self.cx8.next = self.cx.val() + self.k128_64.val();
        self.cx8u.next = unsigned_cast(self.cx8.val());
        self.cx56.next = self.cx8u.val().get_bits::<56>(8);
        self.scx56.next = signed_cast(self.cx56.val());
        self.cxr.next = signed_bit_cast_safe::<64, 56>(self.scx56.val());
        self.cv.next = self.side[6].q.val().get_bits::<33>(0);
        self.scv.next = signed_cast(self.cv.val());
        self.v0w.next = signed_bit_cast_safe::<64, 33>(self.scv.val());
        self.v0s.next = unsigned_cast(self.v0w.val()) << self.k16_7.val();
        self.csum.next = signed_cast(self.v0s.val()) + self.cxr.val();
        self.csumu.next = unsigned_cast(self.csum.val());
        self.c_top.next = self.csumu.val().get_bits::<9>(55);
        self.c56.next = self.csumu.val().get_bits::<56>(0);
        if !(self.c_top.val().all() | !self.c_top.val().any()) {
            if self.csumu.val().get_bit(63) {
                self.c56.next = self.kmin_56.val();
            } else {
                self.c56.next = self.kmax_56.val();
            }
        }
        self.pl_a.d.next = self.ab7[0].q.val();
        self.pl_b.d.next = self.ab7[1].q.val();
        self.pl_c.d.next = self.c56.val();

        // Cycles 21-23: the planes of s/w and t/w wait for 1/w's; the write in cycle 23.
        if self.tok.q.val().get_bit(15) {
            self.idx5.d.next = self.cmd4.q.val().index;
        }
        if self.tok.q.val().get_bit(19) {
            self.idx6.d.next = self.idx5.q.val();
        }
        if self.tok.q.val().get_bit(20) {
            self.rs_a.d.next = self.pl_a.q.val();
            self.rs_b.d.next = self.pl_b.q.val();
            self.rs_c.d.next = self.pl_c.q.val();
        }
        if self.tok.q.val().get_bit(21) {
            self.rt_a.d.next = self.pl_a.q.val();
            self.rt_b.d.next = self.pl_b.q.val();
            self.rt_c.d.next = self.pl_c.q.val();
        }
        self.tdbt_write_enable.next = false;
        self.tdbt_write_address.next = self.k0_16.val();
        self.tdbt_write_data.next.s_a = self.k0_40.val();
        self.tdbt_write_data.next.s_b = self.k0_40.val();
        self.tdbt_write_data.next.s_c = self.k0_56.val();
        self.tdbt_write_data.next.t_a = self.k0_40.val();
        self.tdbt_write_data.next.t_b = self.k0_40.val();
        self.tdbt_write_data.next.t_c = self.k0_56.val();
        self.tdbt_write_data.next.q_a = self.k0_40.val();
        self.tdbt_write_data.next.q_b = self.k0_40.val();
        self.tdbt_write_data.next.q_c = self.k0_56.val();
        if self.tok.q.val().get_bit(22) {
            self.tdbt_write_enable.next = true;
            self.tdbt_write_address.next = self.idx6.q.val();
            self.tdbt_write_data.next.s_a = self.rs_a.q.val();
            self.tdbt_write_data.next.s_b = self.rs_b.q.val();
            self.tdbt_write_data.next.s_c = self.rs_c.q.val();
            self.tdbt_write_data.next.t_a = self.rt_a.q.val();
            self.tdbt_write_data.next.t_b = self.rt_b.q.val();
            self.tdbt_write_data.next.t_c = self.rt_c.q.val();
            self.tdbt_write_data.next.q_a = self.pl_a.q.val();
            self.tdbt_write_data.next.q_b = self.pl_b.q.val();
            self.tdbt_write_data.next.q_c = self.pl_c.q.val();
        }
    }
}

/// Verilog of the texture-setup top (module `tex_setup`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexSetup::default();
    uut.connect_all();
    crate::common::verilog_named(&uut, "tex_setup")
}
