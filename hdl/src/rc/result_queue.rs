//! `result_queue`: the RC's queue of per-triangle results in front of its result port, shared by the
//! Z-test (Type IV, three deep) and the TdbV test (Type III, five deep). Up to five registers, head
//! first; each cycle the head leaves if the port takes it, then a pushed result goes behind what
//! stays. The owner keeps the length within its depth: it issues a result token only when the length
//! plus the results in flight is below the depth (`len` is the length at the start of the cycle).
//! Slots beyond the owner's depth are never written.

use super::RcResult;
use crate::common::StreamOut;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ResultQueue {
    pub clock: Signal<In, Clock>,
    /// Push `push_data` at this edge.
    pub push: Signal<In, Bit>,
    pub push_data: Signal<In, RcResult>,
    /// Results held at the start of the cycle.
    pub len: Signal<Out, Bits<3>>,
    pub result: StreamOut<RcResult>,

    r0: DFF<RcResult>,
    r1: DFF<RcResult>,
    r2: DFF<RcResult>,
    r3: DFF<RcResult>,
    r4: DFF<RcResult>,
    r_len: DFF<Bits<3>>,
    r_pop: Signal<Local, Bit>,
    r_after: Signal<Local, Bits<3>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    k2_3: Constant<Bits<3>>,
    k3_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
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
            push: Default::default(),
            push_data: Default::default(),
            len: Default::default(),
            result: Default::default(),
            r0: Default::default(),
            r1: Default::default(),
            r2: Default::default(),
            r3: Default::default(),
            r4: Default::default(),
            r_len: Default::default(),
            r_pop: Default::default(),
            r_after: Default::default(),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k2_3: Constant::new(2.into()),
            k3_3: Constant::new(3.into()),
            k4_3: Constant::new(4.into()),
            k0_16: Constant::new(0.into()),
        }
    }
}

impl Logic for ResultQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r0, r1, r2, r3, r4, r_len);
        self.len.next = self.r_len.q.val();
        // Pop the head, then push behind what stays.
        self.r_pop.next = (self.r_len.q.val() != self.k0_3.val()) & self.result.ready.val();
        self.r_after.next = self.r_len.q.val();
        if self.r_pop.val() {
            self.r_after.next = self.r_len.q.val() - self.k1_3.val();
            self.r0.d.next = self.r1.q.val();
            self.r1.d.next = self.r2.q.val();
            self.r2.d.next = self.r3.q.val();
            self.r3.d.next = self.r4.q.val();
        }
        self.r_len.d.next = self.r_after.val();
        if self.push.val() {
            self.r_len.d.next = self.r_after.val() + self.k1_3.val();
            if self.r_after.val() == self.k0_3.val() {
                self.r0.d.next = self.push_data.val();
            }
            if self.r_after.val() == self.k1_3.val() {
                self.r1.d.next = self.push_data.val();
            }
            if self.r_after.val() == self.k2_3.val() {
                self.r2.d.next = self.push_data.val();
            }
            if self.r_after.val() == self.k3_3.val() {
                self.r3.d.next = self.push_data.val();
            }
            if self.r_after.val() == self.k4_3.val() {
                self.r4.d.next = self.push_data.val();
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
