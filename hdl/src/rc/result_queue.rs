//! `result_queue`: the RC's per-triangle results, shared by the Z-test (Type IV, three deep) and the
//! TdbV test (Type III, six deep). It takes the token its owner decides on in this cycle and whether
//! it passed: a triangle's visible flag is the OR of its fragments' passes, and its result is pushed
//! with its last token (or a result token: culled, empty box, end of frame). Up to six registers, head
//! first; each cycle the head leaves if the port takes it, then a pushed result goes behind what
//! stays. The owner keeps the length within its depth: it issues a result token only when the length
//! plus the results in flight is below the depth (`len` is the length at the start of the cycle).
//! Slots beyond the owner's depth are never written.

use super::traversal::{RcToken, TOK_FRAG, TOK_RESULT};
use super::RcResult;
use crate::common::StreamOut;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ResultQueue {
    pub clock: Signal<In, Clock>,
    /// The token decided on in this cycle, and whether it passed the visibility test.
    pub tok: Signal<In, RcToken>,
    pub pass: Signal<In, Bit>,
    /// The token pushes a result at this edge.
    pub pushes: Signal<Out, Bit>,
    /// Results held at the start of the cycle.
    pub len: Signal<Out, Bits<3>>,
    pub result: StreamOut<RcResult>,

    visible: DFF<Bit>,
    r_new: Signal<Local, RcResult>,
    tok_frag: Constant<Bits<2>>,
    tok_result: Constant<Bits<2>>,
    r0: DFF<RcResult>,
    r1: DFF<RcResult>,
    r2: DFF<RcResult>,
    r3: DFF<RcResult>,
    r4: DFF<RcResult>,
    r5: DFF<RcResult>,
    r_len: DFF<Bits<3>>,
    r_pop: Signal<Local, Bit>,
    r_after: Signal<Local, Bits<3>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    k2_3: Constant<Bits<3>>,
    k3_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
    k5_3: Constant<Bits<3>>,
    k0_16: Constant<Bits<16>>,
}

impl Default for ResultQueue {
    fn default() -> Self {
        ResultQueue::new()
    }
}

impl ResultQueue {
    pub fn new() -> ResultQueue {
        ResultQueue {
            clock: Default::default(),
            tok: Default::default(),
            pass: Default::default(),
            pushes: Default::default(),
            visible: Default::default(),
            r_new: Default::default(),
            tok_frag: Constant::new(TOK_FRAG.into()),
            tok_result: Constant::new(TOK_RESULT.into()),
            len: Default::default(),
            result: Default::default(),
            r0: Default::default(),
            r1: Default::default(),
            r2: Default::default(),
            r3: Default::default(),
            r4: Default::default(),
            r5: Default::default(),
            r_len: Default::default(),
            r_pop: Default::default(),
            r_after: Default::default(),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k2_3: Constant::new(2.into()),
            k3_3: Constant::new(3.into()),
            k4_3: Constant::new(4.into()),
            k5_3: Constant::new(5.into()),
            k0_16: Constant::new(0.into()),
        }
    }
}

impl Logic for ResultQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, visible, r0, r1, r2, r3, r4, r5, r_len);
        self.len.next = self.r_len.q.val();
        // The result of a triangle's last token, or of a result token.
        self.pushes.next = (self.tok.val().kind == self.tok_result.val()) | ((self.tok.val().kind == self.tok_frag.val()) & self.tok.val().last);
        if self.tok.val().kind == self.tok_frag.val() {
            self.visible.d.next = self.visible.q.val() | self.pass.val();
            if self.tok.val().last {
                self.visible.d.next = false;
            }
        }
        self.r_new.next.index = self.tok.val().index;
        self.r_new.next.eof = self.tok.val().eof;
        self.r_new.next.culled = self.tok.val().culled;
        self.r_new.next.zero_area = self.tok.val().zero_area;
        self.r_new.next.visible = false;
        if self.tok.val().kind == self.tok_frag.val() {
            self.r_new.next.eof = false;
            self.r_new.next.culled = false;
            self.r_new.next.zero_area = false;
            self.r_new.next.visible = self.visible.q.val() | self.pass.val();
        }
        // Pop the head, then push behind what stays.
        self.r_pop.next = (self.r_len.q.val() != self.k0_3.val()) & self.result.ready.val();
        self.r_after.next = self.r_len.q.val();
        if self.r_pop.val() {
            self.r_after.next = self.r_len.q.val() - self.k1_3.val();
            self.r0.d.next = self.r1.q.val();
            self.r1.d.next = self.r2.q.val();
            self.r2.d.next = self.r3.q.val();
            self.r3.d.next = self.r4.q.val();
            self.r4.d.next = self.r5.q.val();
        }
        self.r_len.d.next = self.r_after.val();
        if self.pushes.val() {
            self.r_len.d.next = self.r_after.val() + self.k1_3.val();
            if self.r_after.val() == self.k0_3.val() {
                self.r0.d.next = self.r_new.val();
            }
            if self.r_after.val() == self.k1_3.val() {
                self.r1.d.next = self.r_new.val();
            }
            if self.r_after.val() == self.k2_3.val() {
                self.r2.d.next = self.r_new.val();
            }
            if self.r_after.val() == self.k3_3.val() {
                self.r3.d.next = self.r_new.val();
            }
            if self.r_after.val() == self.k4_3.val() {
                self.r4.d.next = self.r_new.val();
            }
            if self.r_after.val() == self.k5_3.val() {
                self.r5.d.next = self.r_new.val();
            }
        }
        self.result.valid.next = self.r_len.q.val() != self.k0_3.val();
        self.result.data.next = self.r0.q.val();
        if self.r_len.q.val() == self.k0_3.val() {
            self.result.data.next.index = self.k0_16.val();
            self.result.data.next.eof = false;
            self.result.data.next.culled = false;
            self.result.data.next.zero_area = false;
            self.result.data.next.visible = false;
        }
    }
}
