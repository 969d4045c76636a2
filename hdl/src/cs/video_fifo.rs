//! `video_fifo`: the Color Shader's output FIFO, 32 entries of 26 bits (RGB888 + SOF + EOL), held in
//! registers so that the head is on the output in the cycle after it was written (show-ahead).
//!
//! ```text
//!               +---------------------+
//!  write ------>|                     |---> read_valid   (not empty)
//!  write_data ->|  32 x 26 registers  |---> read_data    (the head; 0 when empty)
//!               |  wr_ptr rd_ptr count|<--- read         (pop the head if not empty)
//!  clock ------>|                     |---> overflow     (sticky: a write while full was dropped)
//!               +---------------------+
//! ```
//!
//! A write and a pop can happen at the same edge. The CS never writes a full FIFO (its credit counter
//! limits the pixels in flight to the depth); `overflow` exists to make a broken credit visible.

use rust_hdl::prelude::*;

/// Entries.
pub const VIDEO_FIFO_DEPTH: usize = 32;
/// Entry width: RGB888 (bits 23:0), SOF (24), EOL (25).
pub const VIDEO_FIFO_BITS: usize = 26;

#[derive(LogicBlock)]
pub struct VideoFifo {
    pub clock: Signal<In, Clock>,
    // From the producer
    /// Push `write_data` at the edge (dropped, and `overflow` set, if full).
    pub write: Signal<In, Bit>,
    pub write_data: Signal<In, Bits<26>>,
    // To the consumer
    /// The FIFO holds at least one entry.
    pub read_valid: Signal<Out, Bit>,
    /// The head entry (0 when empty).
    pub read_data: Signal<Out, Bits<26>>,
    /// Pop the head at the edge (ignored when empty).
    pub read: Signal<In, Bit>,
    /// Sticky: some write found the FIFO full.
    pub overflow: Signal<Out, Bit>,

    mem: [DFF<Bits<26>>; 32],
    wr_ptr: DFF<Bits<5>>,
    rd_ptr: DFF<Bits<5>>,
    count: DFF<Bits<6>>,
    overflowed: DFF<Bit>,
    push: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    full: Signal<Local, Bit>,
    k0_6: Constant<Bits<6>>,
    k1_6: Constant<Bits<6>>,
    kdepth_6: Constant<Bits<6>>,
    k1_5: Constant<Bits<5>>,
    k0_26: Constant<Bits<26>>,
}

impl Default for VideoFifo {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            write: Default::default(),
            write_data: Default::default(),
            read_valid: Default::default(),
            read_data: Default::default(),
            read: Default::default(),
            overflow: Default::default(),
            mem: Default::default(),
            wr_ptr: Default::default(),
            rd_ptr: Default::default(),
            count: Default::default(),
            overflowed: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            full: Default::default(),
            k0_6: Constant::new(0.into()),
            k1_6: Constant::new(1.into()),
            kdepth_6: Constant::new((VIDEO_FIFO_DEPTH as u64).into()),
            k1_5: Constant::new(1.into()),
            k0_26: Constant::new(0.into()),
        }
    }
}

impl Logic for VideoFifo {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wr_ptr, rd_ptr, count, overflowed);
        for i in 0..32 {
            self.mem[i].clock.next = self.clock.val();
            self.mem[i].d.next = self.mem[i].q.val();
        }
        self.full.next = self.count.q.val() == self.kdepth_6.val();
        self.read_valid.next = self.count.q.val() != self.k0_6.val();
        self.push.next = self.write.val() & !self.full.val();
        self.pop.next = self.read.val() & self.read_valid.val();
        self.read_data.next = self.k0_26.val();
        for i in 0..32 {
            if self.read_valid.val() & (self.rd_ptr.q.val().index() == i) {
                self.read_data.next = self.mem[i].q.val();
            }
            if self.push.val() & (self.wr_ptr.q.val().index() == i) {
                self.mem[i].d.next = self.write_data.val();
            }
        }
        if self.push.val() {
            self.wr_ptr.d.next = self.wr_ptr.q.val() + self.k1_5.val();
        }
        if self.pop.val() {
            self.rd_ptr.d.next = self.rd_ptr.q.val() + self.k1_5.val();
        }
        if self.push.val() & !self.pop.val() {
            self.count.d.next = self.count.q.val() + self.k1_6.val();
        }
        if !self.push.val() & self.pop.val() {
            self.count.d.next = self.count.q.val() - self.k1_6.val();
        }
        if self.write.val() & self.full.val() {
            self.overflowed.d.next = true;
        }
        self.overflow.next = self.overflowed.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::VecDeque;

    #[test]
    fn video_fifo_behaves_as_a_queue_under_random_pushes_and_pops() {
        let mut uut = VideoFifo::default();
        uut.connect_all();
        let mut q: VecDeque<u64> = VecDeque::new();
        let mut x = 0x1234_5678_9abc_def1u64;
        let mut next = 1u64;
        for cycle in 0..5000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let write = x & 3 != 0 && q.len() < VIDEO_FIFO_DEPTH;
            let read = (x >> 8) & 3 != 0;
            uut.write.next = write;
            uut.write_data.next = next.into();
            uut.read.next = read;
            uut.clock.next = false.into();
            assert!(simulate(&mut uut, 100));
            let head = q.front().copied();
            assert_eq!(uut.read_valid.val(), head.is_some(), "cycle {cycle}");
            assert_eq!(uut.read_data.val().to_u64(), head.unwrap_or(0), "cycle {cycle}");
            if read && head.is_some() {
                q.pop_front();
            }
            if write {
                q.push_back(next);
                next = (next + 1) & ((1 << VIDEO_FIFO_BITS) - 1);
            }
            uut.clock.next = true.into();
            assert!(simulate(&mut uut, 100));
        }
        assert!(!uut.overflow.val());
    }
}
