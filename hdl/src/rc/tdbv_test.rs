//! `tdbv_test`: Type III's visibility test (seed 000 §II, Type III): no Z-buffer; the old depth of a
//! pixel is regenerated from TdbV, the depth plane of the triangle whose index the I-buffer holds,
//! evaluated at the pixel. Four stages and a result queue of six.
//!
//! ```text
//!            F1                     F2                       F3                         F4
//!  tok --> | token |------->  | token, owned |-------> | token, owned,     |-----> | token, old depth       |
//!  i_rd_data-> tdbv_re =      tdbv_rd_a/b/c ->        |  A*X, B*Y, C      |       | old = newest of the    |--> i_we, i_wr_*
//!            covered &        A*X, B*Y (40x11)        | owned ? clamp(    |       |  last four writes to   |--> result
//!            index != 0;                              |  round(C + A*X +  |       |  the pixel, else F3's  |--> result_free
//!            tdbv_rd_addr =                           |  B*Y)) : far      |       | pass = covered & z<old |
//!            index
//! ```
//!
//! A fragment issued by the traversal in cycle t (with its I-buffer read) is in F1 in t+1, when the
//! I-buffer word arrives; F1 reads TdbV at that index (not at the background index 0: the pixel is
//! free and its old depth is far). In t+2 the record arrives in F2, which forms the products A*X and
//! B*Y. In t+3 F3 regenerates the old depth `clamp(round((C + A*X + B*Y) / 2^16))`, exactly the value
//! the traversal stepped to when the owner was drawn (the same integers: `raw = C + A*X + B*Y`), so
//! Type III decides as Type IV does. In t+4 F4 compares and writes.
//!
//! Hazards: the I-buffer read of cycle t returns the word before the writes of t, t+1, t+2 and t+3
//! (all made by F4). F4 keeps those four writes (address, depth written) and takes the newest one to
//! the same pixel instead of the regenerated depth: a fragment right behind another on the same pixel
//! (same triangle or the next, no gap) sees its depth without a stall. A TdbV record cannot be in
//! flight when it is read: it is written in the cycle the traversal takes the triangle, before the
//! triangle's first fragment, and an index reaches the I-buffer only through such a fragment.
//! A clear token writes the background index (its depth counts as far). Every output is 0 when its
//! enable or valid is low.

use super::traversal::{RcToken, TOK_CLEAR, TOK_FRAG, TOK_RESULT};
use super::RcResult;
use super::result_queue::ResultQueue;
use crate::common::{signed_bit_cast_safe, MulS, StreamOut};
use rust_hdl::prelude::*;

/// Results the queue holds: with four tokens in flight, six sustain one result per clock.
pub const RESULT_QUEUE_III: u64 = 6;

#[derive(LogicBlock)]
pub struct TdbvTest {
    pub clock: Signal<In, Clock>,
    // From the traversal
    pub tok: Signal<In, RcToken>,
    // To the traversal
    /// A result token issued this cycle will find room in the result queue.
    pub result_free: Signal<Out, Bit>,
    // From the I-buffer: the index at the fragment's pixel, read one cycle earlier.
    pub i_rd_data: Signal<In, Bits<16>>,
    // TdbV read port: the stored index's depth plane, one cycle after the read.
    pub tdbv_re: Signal<Out, Bit>,
    pub tdbv_rd_addr: Signal<Out, Bits<16>>,
    pub tdbv_rd_a: Signal<In, Signed<40>>,
    pub tdbv_rd_b: Signal<In, Signed<40>>,
    pub tdbv_rd_c: Signal<In, Signed<56>>,
    // To the I-buffer
    pub i_we: Signal<Out, Bit>,
    pub i_wr_addr: Signal<Out, Bits<20>>,
    pub i_wr_data: Signal<Out, Bits<16>>,
    // To the result port
    pub result: StreamOut<RcResult>,

    /// The tokens in F1, F2, F3.
    f1: DFF<RcToken>,
    f2: DFF<RcToken>,
    f3: DFF<RcToken>,
    f4: DFF<RcToken>,
    /// F4's old depth from TdbV (far where the pixel was free).
    f4_base: DFF<Bits<24>>,
    f2_owned: DFF<Bit>,
    f3_owned: DFF<Bit>,
    f3_ax: DFF<Signed<51>>,
    f3_by: DFF<Signed<51>>,
    f3_c: DFF<Signed<56>>,
    /// The last three writes, newest first: valid, address, depth written.
    h1_v: DFF<Bit>,
    h1_addr: DFF<Bits<20>>,
    h1_z: DFF<Bits<24>>,
    h2_v: DFF<Bit>,
    h2_addr: DFF<Bits<20>>,
    h2_z: DFF<Bits<24>>,
    h3_v: DFF<Bit>,
    h3_addr: DFF<Bits<20>>,
    h3_z: DFF<Bits<24>>,
    h4_v: DFF<Bit>,
    h4_addr: DFF<Bits<20>>,
    h4_z: DFF<Bits<24>>,
    queue: ResultQueue,

    mul_ax: MulS<40, 11, 51>,
    mul_by: MulS<40, 11, 51>,
    x11: Signal<Local, Bits<11>>,
    y11: Signal<Local, Bits<11>>,
    ax56: Signal<Local, Signed<56>>,
    by56: Signal<Local, Signed<56>>,
    raw_ab: Signal<Local, Signed<56>>,
    raw_c: Signal<Local, Signed<56>>,
    rawh: Signal<Local, Signed<56>>,
    rounded_u: Signal<Local, Bits<56>>,
    plane_z: Signal<Local, Bits<24>>,
    base_z: Signal<Local, Bits<24>>,
    old_z: Signal<Local, Bits<24>>,
    pass: Signal<Local, Bit>,
    write_z: Signal<Local, Bits<24>>,
    push1: Signal<Local, Bits<3>>,
    push2: Signal<Local, Bits<3>>,
    push3: Signal<Local, Bits<3>>,
    push4: Signal<Local, Bits<3>>,
    pending: Signal<Local, Bits<3>>,

    depth_max: Constant<Bits<24>>,
    half: Constant<Signed<56>>,
    k0_24: Constant<Bits<24>>,
    k0_20: Constant<Bits<20>>,
    k0_16: Constant<Bits<16>>,
    k0_15: Constant<Bits<15>>,
    tok_clear: Constant<Bits<2>>,
    tok_frag: Constant<Bits<2>>,
    tok_result: Constant<Bits<2>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    k5_3: Constant<Bits<3>>,
}

impl Default for TdbvTest {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            tok: Default::default(),
            result_free: Default::default(),
            i_rd_data: Default::default(),
            tdbv_re: Default::default(),
            tdbv_rd_addr: Default::default(),
            tdbv_rd_a: Default::default(),
            tdbv_rd_b: Default::default(),
            tdbv_rd_c: Default::default(),
            i_we: Default::default(),
            i_wr_addr: Default::default(),
            i_wr_data: Default::default(),
            result: Default::default(),
            f1: Default::default(),
            f2: Default::default(),
            f3: Default::default(),
            f4: Default::default(),
            f4_base: Default::default(),
            f2_owned: Default::default(),
            f3_owned: Default::default(),
            f3_ax: Default::default(),
            f3_by: Default::default(),
            f3_c: Default::default(),
            h1_v: Default::default(),
            h1_addr: Default::default(),
            h1_z: Default::default(),
            h2_v: Default::default(),
            h2_addr: Default::default(),
            h2_z: Default::default(),
            h3_v: Default::default(),
            h3_addr: Default::default(),
            h3_z: Default::default(),
            h4_v: Default::default(),
            h4_addr: Default::default(),
            h4_z: Default::default(),
            queue: ResultQueue::new(),
            mul_ax: Default::default(),
            mul_by: Default::default(),
            x11: Default::default(),
            y11: Default::default(),
            ax56: Default::default(),
            by56: Default::default(),
            raw_ab: Default::default(),
            raw_c: Default::default(),
            rawh: Default::default(),
            rounded_u: Default::default(),
            plane_z: Default::default(),
            base_z: Default::default(),
            old_z: Default::default(),
            pass: Default::default(),
            write_z: Default::default(),
            push1: Default::default(),
            push2: Default::default(),
            push3: Default::default(),
            push4: Default::default(),
            pending: Default::default(),
            depth_max: Constant::new(((1u64 << 24) - 1).into()),
            half: Constant::new((1i64 << 15).into()),
            k0_24: Constant::new(0.into()),
            k0_20: Constant::new(0.into()),
            k0_16: Constant::new(0.into()),
            k0_15: Constant::new(0.into()),
            tok_clear: Constant::new(TOK_CLEAR.into()),
            tok_frag: Constant::new(TOK_FRAG.into()),
            tok_result: Constant::new(TOK_RESULT.into()),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k5_3: Constant::new(RESULT_QUEUE_III.into()),
        }
    }
}

impl Logic for TdbvTest {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, f1, f2, f3, f4, f4_base, f2_owned,
            f3_owned, f3_ax, f3_by, f3_c, h1_v, h1_addr, h1_z,
            h2_v, h2_addr, h2_z, h3_v, h3_addr, h3_z, h4_v, h4_addr, h4_z
        );
        // ---- F1 takes every token; it reads TdbV at the index the I-buffer returned ----
        self.f1.d.next = self.tok.val();
        self.tdbv_re.next = (self.f1.q.val().kind == self.tok_frag.val()) & self.f1.q.val().covered & (self.i_rd_data.val() != self.k0_16.val());
        self.tdbv_rd_addr.next = self.k0_16.val();
        if self.tdbv_re.val() {
            self.tdbv_rd_addr.next = self.i_rd_data.val();
        }

        // ---- F2: the record arrives; the products A*X and B*Y ----
        self.f2.d.next = self.f1.q.val();
        self.f2_owned.d.next = self.tdbv_re.val();
        self.x11.next = bit_cast::<11, 10>(self.f2.q.val().x);
        self.y11.next = bit_cast::<11, 10>(self.f2.q.val().y);
        self.mul_ax.a.next = self.tdbv_rd_a.val();
        self.mul_ax.b.next = signed_cast(self.x11.val());
        self.mul_by.a.next = self.tdbv_rd_b.val();
        self.mul_by.b.next = signed_cast(self.y11.val());

        self.f3.d.next = self.f2.q.val();
        self.f3_owned.d.next = self.f2_owned.q.val();
        self.f3_ax.d.next = self.mul_ax.p.val();
        self.f3_by.d.next = self.mul_by.p.val();
        self.f3_c.d.next = self.tdbv_rd_c.val();

        // ---- F3: the regenerated depth ----
        self.ax56.next = signed_bit_cast_safe::<56, 51>(self.f3_ax.q.val());
        self.by56.next = signed_bit_cast_safe::<56, 51>(self.f3_by.q.val());
        self.raw_ab.next = self.ax56.val() + self.by56.val();
        self.raw_c.next = self.f3_c.q.val() + self.half.val();
        self.rawh.next = self.raw_ab.val() + self.raw_c.val();
        self.rounded_u.next = unsigned_cast(self.rawh.val());
        self.plane_z.next = self.rounded_u.val().get_bits::<24>(16);
        if self.rounded_u.val().get_bits::<15>(40) != self.k0_15.val() {
            self.plane_z.next = self.depth_max.val();
        }
        if self.rawh.val().get_bit(55) {
            self.plane_z.next = self.k0_24.val();
        }
        self.base_z.next = self.depth_max.val();
        if self.f3_owned.q.val() {
            self.base_z.next = self.plane_z.val();
        }
        self.f4.d.next = self.f3.q.val();
        self.f4_base.d.next = self.base_z.val();

        // ---- F4: the forwarding, the decision and the write ----
        self.old_z.next = self.f4_base.q.val();
        // Newest last: the write of four cycles ago, three, two, one.
        if self.h4_v.q.val() & (self.h4_addr.q.val() == self.f4.q.val().addr) {
            self.old_z.next = self.h4_z.q.val();
        }
        if self.h3_v.q.val() & (self.h3_addr.q.val() == self.f4.q.val().addr) {
            self.old_z.next = self.h3_z.q.val();
        }
        if self.h2_v.q.val() & (self.h2_addr.q.val() == self.f4.q.val().addr) {
            self.old_z.next = self.h2_z.q.val();
        }
        if self.h1_v.q.val() & (self.h1_addr.q.val() == self.f4.q.val().addr) {
            self.old_z.next = self.h1_z.q.val();
        }
        self.pass.next = (self.f4.q.val().kind == self.tok_frag.val()) & self.f4.q.val().covered & (self.f4.q.val().z < self.old_z.val());
        self.i_we.next = false;
        self.i_wr_addr.next = self.k0_20.val();
        self.i_wr_data.next = self.k0_16.val();
        self.write_z.next = self.depth_max.val();
        if self.pass.val() {
            self.i_we.next = true;
            self.i_wr_addr.next = self.f4.q.val().addr;
            self.i_wr_data.next = self.f4.q.val().index;
            self.write_z.next = self.f4.q.val().z;
        }
        if self.f4.q.val().kind == self.tok_clear.val() {
            self.i_we.next = true;
            self.i_wr_addr.next = self.f4.q.val().addr;
        }
        self.h1_v.d.next = self.i_we.val();
        self.h1_addr.d.next = self.i_wr_addr.val();
        self.h1_z.d.next = self.write_z.val();
        self.h2_v.d.next = self.h1_v.q.val();
        self.h2_addr.d.next = self.h1_addr.q.val();
        self.h2_z.d.next = self.h1_z.q.val();
        self.h4_v.d.next = self.h3_v.q.val();
        self.h4_addr.d.next = self.h3_addr.q.val();
        self.h4_z.d.next = self.h3_z.q.val();
        self.h3_v.d.next = self.h2_v.q.val();
        self.h3_addr.d.next = self.h2_addr.q.val();
        self.h3_z.d.next = self.h2_z.q.val();

        // ---- Results: a triangle's last fragment or a result token, from F4 ----
        self.push1.next = self.k0_3.val();
        if (self.f1.q.val().kind == self.tok_result.val()) | ((self.f1.q.val().kind == self.tok_frag.val()) & self.f1.q.val().last) {
            self.push1.next = self.k1_3.val();
        }
        self.push2.next = self.k0_3.val();
        if (self.f2.q.val().kind == self.tok_result.val()) | ((self.f2.q.val().kind == self.tok_frag.val()) & self.f2.q.val().last) {
            self.push2.next = self.k1_3.val();
        }
        self.push3.next = self.k0_3.val();
        if (self.f3.q.val().kind == self.tok_result.val()) | ((self.f3.q.val().kind == self.tok_frag.val()) & self.f3.q.val().last) {
            self.push3.next = self.k1_3.val();
        }
        self.push4.next = self.k0_3.val();
        if self.queue.pushes.val() {
            self.push4.next = self.k1_3.val();
        }
        // Room for a result token issued now: the queue's length plus the results in flight below six.
        self.pending.next = self.queue.len.val() + self.push1.val() + self.push2.val() + self.push3.val() + self.push4.val();
        self.result_free.next = self.pending.val() < self.k5_3.val();
        // The result queue.
        clock!(self, clock, queue);
        self.queue.tok.next = self.f4.q.val();
        self.queue.pass.next = self.pass.val();
        StreamOut::<RcResult>::link(&mut self.result, &mut self.queue.result);
    }
}
