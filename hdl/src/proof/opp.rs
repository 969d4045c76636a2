//! The object-processor pipeline (seed 002 §4, Fig. 1): N object processors in a chain; pixels enter
//! in raster order as empty lists and leave with their depth-sorted object lists. The object loader
//! (geometry processor) sees the highest-numbered free OP and loads objects by OP number; OP reuse
//! (§4.2) is the loader's policy (`golden::proof::cycle_opp::Feeder`). Cycle behaviour:
//! `golden::proof::cycle_opp::OppModel`.
//!
//! ```text
//!             load  load_op  load_params          any_free  free_op
//!               │      │         │                    ▲        ▲
//!             +─┴──────┴─────────┴────────────────────┴────────┴─+
//!  upstream ─▶| OP 0 ─▶ OP 1 ─▶ ... ─▶ OP N-1                      |─▶ downstream
//!             +--------------------------------------------------+
//! ```
//! The ready path is combinational from `downstream.ready` back to `upstream.ready` through every OP
//! (an OP's FIFO takes a slot in the cycle its head leaves), which is what lets a FIFO of one slot keep
//! the full rate.

use super::object_processor::ObjectProcessor;
use super::types::{ObjParams, ProofSlot};
use crate::common::{StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Opp {
    pub clock: Signal<In, Clock>,
    // From the object loader
    /// Load `load_params` into OP `load_op` at this edge.
    pub load: Signal<In, Bit>,
    pub load_op: Signal<In, Bits<16>>,
    pub load_params: Signal<In, ObjParams>,
    // From the pixel source
    /// Pixels as empty lists, raster order.
    pub upstream: StreamIn<ProofSlot>,
    // To the shading stage
    /// The object lists, one slot per entry (an empty list keeps one slot).
    pub downstream: StreamOut<ProofSlot>,
    // To the object loader
    /// Some OP is free.
    pub any_free: Signal<Out, Bit>,
    /// The highest-numbered free OP.
    pub free_op: Signal<Out, Bits<16>>,
    pub ops: Vec<ObjectProcessor>,
    op_ids: Vec<Constant<Bits<16>>>,
    zero16: Constant<Bits<16>>,
    _last: usize,
}

impl Opp {
    /// An OPP of `n` object processors (1..=65535), each with a FIFO of `fifo_depth` slots (1..=8).
    pub fn new(n: usize, fifo_depth: usize) -> Result<Opp, String> {
        if n == 0 || n > 65535 {
            return Err(format!("an OPP of {n} object processors is not supported: 1..=65535"));
        }
        Ok(Opp {
            clock: Default::default(),
            load: Default::default(),
            load_op: Default::default(),
            load_params: Default::default(),
            upstream: Default::default(),
            downstream: Default::default(),
            any_free: Default::default(),
            free_op: Default::default(),
            ops: (0..n).map(|_| ObjectProcessor::new(fifo_depth)).collect::<Result<_, _>>()?,
            op_ids: (0..n).map(|i| Constant::new((i as u64).into())).collect(),
            zero16: Constant::new(0.into()),
            _last: n - 1,
        })
    }
}

impl Logic for Opp {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..self.ops.len() {
            self.ops[i].clock.next = self.clock.val();
            self.ops[i].load.next = self.load.val() & (self.load_op.val() == self.op_ids[i].val());
            self.ops[i].load_params.next = self.load_params.val();
        }
        self.ops[0].upstream.data.next = self.upstream.data.val();
        self.ops[0].upstream.valid.next = self.upstream.valid.val();
        self.upstream.ready.next = self.ops[0].upstream.ready.val();
        for i in 1..self.ops.len() {
            self.ops[i].upstream.data.next = self.ops[i - 1].downstream.data.val();
            self.ops[i].upstream.valid.next = self.ops[i - 1].downstream.valid.val();
            self.ops[i - 1].downstream.ready.next = self.ops[i].upstream.ready.val();
        }
        for i in self._last..self.ops.len() {
            self.downstream.data.next = self.ops[i].downstream.data.val();
            self.downstream.valid.next = self.ops[i].downstream.valid.val();
            self.ops[i].downstream.ready.next = self.downstream.ready.val();
        }
        // Highest-numbered free OP: the last match in the scan wins.
        self.any_free.next = false;
        self.free_op.next = self.zero16.val();
        for i in 0..self.ops.len() {
            if self.ops[i].free.val() {
                self.any_free.next = true;
                self.free_op.next = self.op_ids[i].val();
            }
        }
    }
}
