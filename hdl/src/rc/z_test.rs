//! `z_test`: the RC's Z-test stage (seed 001 §3.1: the index of a visible pixel goes to the I-buffer)
//! and its result queue (four results).
//!
//! ```text
//!                 +-----------------------------------+
//!  tok_* -------->| F0 token register                 |--> z_re, z_rd_addr (covered fragments)
//!                 | F1 token register                 |--> z_we, z_wr_addr, z_wr_data
//!  z_rd_data ---->| old = forwarded ? last write      |--> i_we, i_wr_addr, i_wr_data
//!  i_rd_data ---->|   : i_rd_data == 0 ? 2^24-1       |--> result (valid/ready/data)
//!                 |   : z_rd_data                     |
//!                 | pass = covered & z < old          |--> result_free
//!  clock -------->| visible |= pass; result queue (4) |
//!                 +-----------------------------------+
//! ```
//!
//! A token issued by the traversal in cycle t is registered in F0 in cycle t+1, which issues its Z and
//! I read; it is in F1 in cycle t+2, when the read data arrive. F0 keeps the memory ports off the
//! traversal's walk decision, which was the `rc` top's critical path while the read went out with the
//! token (issue 15, item 5). A read returns the memory's contents *before* the write of the same edge,
//! so the only write a fragment can miss is the one performed at the end of the cycle of its read, i.e.
//! by the token in F1 then. That write (address, data) is kept in a forwarding register and used
//! instead of `z_rd_data` when the addresses match: a fragment of the next triangle on the same pixel
//! sees the new depth without a stall. The I-buffer word read with the depth tells whether the depth
//! is of this frame: where it is the background index (0) the depth counts as 2^24-1, so the Z-buffer
//! needs no clear when the I-buffer was cleared (by the RC's clear or behind the Color Shader's
//! scan-out). On a pass, Z and I are written in the same cycle (combinationally from `z_rd_data`). A
//! clear token writes 2^24-1 and 0. Every output is 0 when its enable or valid is low. A result token
//! is issued only while the queue's length plus the results in F0 and F1 is below four (`result_free`),
//! which sustains one result per clock.

use super::RcResult;
use super::traversal::{RcToken, TOK_CLEAR, TOK_FRAG, TOK_RESULT};
use super::result_queue::ResultQueue;
use crate::common::StreamOut;
use rust_hdl::prelude::*;

/// Results the queue holds: with two tokens in flight (F0, F1), four sustain one result per clock.
pub const RESULT_QUEUE: u64 = 4;

#[derive(LogicBlock)]
pub struct ZTest {
    pub clock: Signal<In, Clock>,
    // From the traversal
    pub tok: Signal<In, RcToken>,
    // To the traversal
    /// A result token issued this cycle will find room in the result queue.
    pub result_free: Signal<Out, Bit>,
    // To the Z-buffer and the I-buffer: the read of F0's fragment
    /// Read enable; `z_rd_data` and `i_rd_data` hold the words at `z_rd_addr` in the next cycle.
    pub z_re: Signal<Out, Bit>,
    pub z_rd_addr: Signal<Out, Bits<20>>,
    // From the Z-buffer
    /// Depth read one cycle earlier.
    pub z_rd_data: Signal<In, Bits<24>>,
    /// The I-buffer word read with it: the background index marks the depth as stale (far).
    pub i_rd_data: Signal<In, Bits<16>>,
    // To the Z-buffer and the I-buffer
    pub z_we: Signal<Out, Bit>,
    pub z_wr_addr: Signal<Out, Bits<20>>,
    pub z_wr_data: Signal<Out, Bits<24>>,
    pub i_we: Signal<Out, Bit>,
    pub i_wr_addr: Signal<Out, Bits<20>>,
    pub i_wr_data: Signal<Out, Bits<16>>,
    // To the result port
    pub result: StreamOut<RcResult>,

    /// The token issued in the previous cycle (F0: its Z and I read goes out), and the one before (F1:
    /// its read data are here).
    f0: DFF<RcToken>,
    f1: DFF<RcToken>,
    fwd_valid: DFF<Bit>,
    fwd_addr: DFF<Bits<20>>,
    fwd_z: DFF<Bits<24>>,
    queue: ResultQueue,

    old_z: Signal<Local, Bits<24>>,
    pass: Signal<Local, Bit>,
    push0: Signal<Local, Bits<3>>,
    push1: Signal<Local, Bits<3>>,
    pending: Signal<Local, Bits<3>>,

    depth_max: Constant<Bits<24>>,
    k0_24: Constant<Bits<24>>,
    k0_20: Constant<Bits<20>>,
    k0_16: Constant<Bits<16>>,
    tok_clear: Constant<Bits<2>>,
    tok_frag: Constant<Bits<2>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    depth_3: Constant<Bits<3>>,
    tok_result: Constant<Bits<2>>,
}

impl Default for ZTest {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            tok: Default::default(),
            result_free: Default::default(),
            z_re: Default::default(),
            z_rd_addr: Default::default(),
            z_rd_data: Default::default(),
            i_rd_data: Default::default(),
            z_we: Default::default(),
            z_wr_addr: Default::default(),
            z_wr_data: Default::default(),
            i_we: Default::default(),
            i_wr_addr: Default::default(),
            i_wr_data: Default::default(),
            result: Default::default(),
            f0: Default::default(),
            f1: Default::default(),
            fwd_valid: Default::default(),
            fwd_addr: Default::default(),
            fwd_z: Default::default(),
            queue: ResultQueue::new(),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            depth_3: Constant::new(RESULT_QUEUE.into()),
            tok_result: Constant::new(TOK_RESULT.into()),
            old_z: Default::default(),
            pass: Default::default(),
            push0: Default::default(),
            push1: Default::default(),
            pending: Default::default(),
            depth_max: Constant::new(((1u64 << 24) - 1).into()),
            k0_24: Constant::new(0.into()),
            k0_20: Constant::new(0.into()),
            k0_16: Constant::new(0.into()),
            tok_clear: Constant::new(TOK_CLEAR.into()),
            tok_frag: Constant::new(TOK_FRAG.into()),
        }
    }
}

impl Logic for ZTest {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, f0, f1, fwd_valid,
            fwd_addr, fwd_z
        );
        // F0 takes every token and reads Z and I for a covered fragment; F1 takes F0's token.
        self.f0.d.next = self.tok.val();
        self.f1.d.next = self.f0.q.val();
        self.z_re.next = (self.f0.q.val().kind == self.tok_frag.val()) & self.f0.q.val().covered;
        self.z_rd_addr.next = self.k0_20.val();
        if self.z_re.val() {
            self.z_rd_addr.next = self.f0.q.val().addr;
        }

        // The Z-test with forwarding of last cycle's write. A pixel whose I-buffer word is the
        // background index has no depth of this frame: its Z word is stale and counts as far.
        self.old_z.next = self.z_rd_data.val();
        if self.i_rd_data.val() == self.k0_16.val() {
            self.old_z.next = self.depth_max.val();
        }
        if self.fwd_valid.q.val() & (self.fwd_addr.q.val() == self.f1.q.val().addr) {
            self.old_z.next = self.fwd_z.q.val();
        }
        self.pass.next = (self.f1.q.val().kind == self.tok_frag.val()) & self.f1.q.val().covered & (self.f1.q.val().z < self.old_z.val());
        self.z_we.next = false;
        self.z_wr_addr.next = self.k0_20.val();
        self.z_wr_data.next = self.k0_24.val();
        self.i_wr_data.next = self.k0_16.val();
        if self.pass.val() {
            self.z_we.next = true;
            self.z_wr_addr.next = self.f1.q.val().addr;
            self.z_wr_data.next = self.f1.q.val().z;
            self.i_wr_data.next = self.f1.q.val().index;
        }
        if self.f1.q.val().kind == self.tok_clear.val() {
            self.z_we.next = true;
            self.z_wr_addr.next = self.f1.q.val().addr;
            self.z_wr_data.next = self.depth_max.val();
        }
        self.i_we.next = self.z_we.val();
        self.i_wr_addr.next = self.z_wr_addr.val();
        self.fwd_valid.d.next = self.z_we.val();
        self.fwd_addr.d.next = self.z_wr_addr.val();
        self.fwd_z.d.next = self.z_wr_data.val();

        // Results: the last fragment of a triangle, or a result token.
        // Room for a result token issued now: the queue's length plus the results in F0 and F1 below
        // the queue's depth.
        self.push0.next = self.k0_3.val();
        if (self.f0.q.val().kind == self.tok_result.val()) | ((self.f0.q.val().kind == self.tok_frag.val()) & self.f0.q.val().last) {
            self.push0.next = self.k1_3.val();
        }
        self.push1.next = self.k0_3.val();
        if self.queue.pushes.val() {
            self.push1.next = self.k1_3.val();
        }
        self.pending.next = self.queue.len.val() + self.push0.val() + self.push1.val();
        self.result_free.next = self.pending.val() < self.depth_3.val();
        // The result queue.
        clock!(self, clock, queue);
        self.queue.tok.next = self.f1.q.val();
        self.queue.pass.next = self.pass.val();
        StreamOut::<RcResult>::link(&mut self.result, &mut self.queue.result);
    }
}
