//! The object processor's input FIFO (seed 002 §4.3: it "absorbs the jams and holes" that insertions
//! and deletions cause). Show-ahead: `data_out` is the oldest slot while `!empty`; `read` pops it,
//! `write` pushes `data_in`; both may happen in one cycle. Depth 1..=8 slots, a parameter, as
//! registers with binary read and write pointers (no block RAM: the depths are tiny).
//!
//! ```text
//!            +-----------------+
//!  data_in ─▶|                 |─▶ data_out
//!  write   ─▶|  slot_fifo (D)  |─▶ empty
//!  read    ─▶|                 |─▶ full
//!            +-----------------+
//! ```

use super::types::ProofSlot;
use rust_hdl::prelude::*;

/// Largest supported depth.
pub const FIFO_MAX_DEPTH: usize = 8;

#[derive(LogicBlock)]
pub struct SlotFifo {
    pub clock: Signal<In, Clock>,
    // From the previous object processor
    /// Slot to push.
    pub data_in: Signal<In, ProofSlot>,
    /// Push `data_in` at this edge (never while full).
    pub write: Signal<In, Bit>,
    // From the comparator
    /// Pop the oldest slot at this edge (never while empty).
    pub read: Signal<In, Bit>,
    // To the comparator
    /// The oldest slot.
    pub data_out: Signal<Out, ProofSlot>,
    /// No slot stored.
    pub empty: Signal<Out, Bit>,
    /// D slots stored.
    pub full: Signal<Out, Bit>,
    slots: Vec<DFF<ProofSlot>>,
    wr: DFF<Bits<4>>,
    rd: DFF<Bits<4>>,
    count: DFF<Bits<4>>,
    depth_k: Constant<Bits<4>>,
    last_k: Constant<Bits<4>>,
    zero_k: Constant<Bits<4>>,
    slot_ids: Vec<Constant<Bits<4>>>,
}

impl SlotFifo {
    /// A FIFO of `depth` slots, 1..=8.
    pub fn new(depth: usize) -> Result<SlotFifo, String> {
        if !(1..=FIFO_MAX_DEPTH).contains(&depth) {
            return Err(format!("FIFO depth {depth} is not supported by the RTL: 1..={FIFO_MAX_DEPTH} slots"));
        }
        Ok(SlotFifo {
            clock: Default::default(),
            data_in: Default::default(),
            write: Default::default(),
            read: Default::default(),
            data_out: Default::default(),
            empty: Default::default(),
            full: Default::default(),
            slots: (0..depth).map(|_| Default::default()).collect(),
            wr: Default::default(),
            rd: Default::default(),
            count: Default::default(),
            depth_k: Constant::new((depth as u64).into()),
            last_k: Constant::new((depth as u64 - 1).into()),
            zero_k: Constant::new(0.into()),
            slot_ids: (0..depth).map(|i| Constant::new((i as u64).into())).collect(),
        })
    }
}

impl Logic for SlotFifo {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wr, rd, count);
        for i in 0..self.slots.len() {
            self.slots[i].clock.next = self.clock.val();
            self.slots[i].d.next = self.slots[i].q.val();
        }
        self.data_out.next = self.slots[0].q.val();
        for i in 0..self.slots.len() {
            if self.rd.q.val() == self.slot_ids[i].val() {
                self.data_out.next = self.slots[i].q.val();
            }
        }
        if self.write.val() {
            for i in 0..self.slots.len() {
                if self.wr.q.val() == self.slot_ids[i].val() {
                    self.slots[i].d.next = self.data_in.val();
                }
            }
            if self.wr.q.val() == self.last_k.val() {
                self.wr.d.next = self.zero_k.val();
            } else {
                self.wr.d.next = self.wr.q.val() + 1;
            }
        }
        if self.read.val() {
            if self.rd.q.val() == self.last_k.val() {
                self.rd.d.next = self.zero_k.val();
            } else {
                self.rd.d.next = self.rd.q.val() + 1;
            }
        }
        if self.write.val() & !self.read.val() {
            self.count.d.next = self.count.q.val() + 1;
        }
        if !self.write.val() & self.read.val() {
            self.count.d.next = self.count.q.val() - 1;
        }
        self.empty.next = !self.count.q.val().any();
        self.full.next = self.count.q.val() == self.depth_k.val();
    }
}
