//! `video_fifo`: the Color Shader's output FIFO, 2^P entries of 26 bits (RGB888 + SOF + EOL), held in
//! registers so that the head is on the output in the cycle after it was written (show-ahead). The
//! untextured CS uses 32 entries ([`VideoFifo32`]), the textured one 64 ([`VideoFifo64`]).
//!
//! ```text
//!               +---------------------+
//!  write ------>|                     |---> read_valid   (not empty)
//!  write_data ->| 2^P x 26 registers  |---> read_data    (the head; 0 when empty)
//!               |  wr_ptr rd_ptr count|<--- read         (pop the head if not empty)
//!  clock ------>|                     |---> overflow     (sticky: a write while full was dropped)
//!               +---------------------+
//! ```
//!
//! A write and a pop can happen at the same edge. The CS never writes a full FIFO (its credit counter
//! limits the pixels in flight to the depth); `overflow` exists to make a broken credit visible.

use rust_hdl::prelude::*;

/// Entries of the untextured CS's FIFO.
pub const VIDEO_FIFO_DEPTH: usize = 32;
/// The untextured CS's FIFO: 32 entries (5-bit pointers, 6-bit count).
pub type VideoFifo32 = VideoFifo<5, 6>;
/// The textured CS's FIFO: 64 entries.
pub type VideoFifo64 = VideoFifo<6, 7>;
/// Entry width: RGB888 (bits 23:0), SOF (24), EOL (25).
pub const VIDEO_FIFO_BITS: usize = 26;

#[derive(LogicBlock)]
/// `P`: pointer bits (2^P entries); `C` = P + 1: count bits.
pub struct VideoFifo<const P: usize, const C: usize> {
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

    mem: Vec<DFF<Bits<26>>>,
    wr_ptr: DFF<Bits<P>>,
    rd_ptr: DFF<Bits<P>>,
    count: DFF<Bits<C>>,
    overflowed: DFF<Bit>,
    push: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    full: Signal<Local, Bit>,
    k0_c: Constant<Bits<C>>,
    k1_c: Constant<Bits<C>>,
    kdepth_c: Constant<Bits<C>>,
    k1_p: Constant<Bits<P>>,
    k0_26: Constant<Bits<26>>,
}

impl<const P: usize, const C: usize> Default for VideoFifo<P, C> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            write: Default::default(),
            write_data: Default::default(),
            read_valid: Default::default(),
            read_data: Default::default(),
            read: Default::default(),
            overflow: Default::default(),
            mem: (0..1usize << P).map(|_| Default::default()).collect(),
            wr_ptr: Default::default(),
            rd_ptr: Default::default(),
            count: Default::default(),
            overflowed: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            full: Default::default(),
            k0_c: Constant::new(0.into()),
            k1_c: Constant::new(1.into()),
            kdepth_c: Constant::new((1u64 << P).into()),
            k1_p: Constant::new(1.into()),
            k0_26: Constant::new(0.into()),
        }
    }
}

impl<const P: usize, const C: usize> Logic for VideoFifo<P, C> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wr_ptr, rd_ptr, count, overflowed);
        for i in 0..self.mem.len() {
            self.mem[i].clock.next = self.clock.val();
            self.mem[i].d.next = self.mem[i].q.val();
        }
        self.full.next = self.count.q.val() == self.kdepth_c.val();
        self.read_valid.next = self.count.q.val() != self.k0_c.val();
        self.push.next = self.write.val() & !self.full.val();
        self.pop.next = self.read.val() & self.read_valid.val();
        self.read_data.next = self.k0_26.val();
        for i in 0..self.mem.len() {
            if self.read_valid.val() & (self.rd_ptr.q.val().index() == i) {
                self.read_data.next = self.mem[i].q.val();
            }
            if self.push.val() & (self.wr_ptr.q.val().index() == i) {
                self.mem[i].d.next = self.write_data.val();
            }
        }
        if self.push.val() {
            self.wr_ptr.d.next = self.wr_ptr.q.val() + self.k1_p.val();
        }
        if self.pop.val() {
            self.rd_ptr.d.next = self.rd_ptr.q.val() + self.k1_p.val();
        }
        if self.push.val() & !self.pop.val() {
            self.count.d.next = self.count.q.val() + self.k1_c.val();
        }
        if !self.push.val() & self.pop.val() {
            self.count.d.next = self.count.q.val() - self.k1_c.val();
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
        queue_test(VideoFifo32::default(), VIDEO_FIFO_DEPTH);
        queue_test(VideoFifo64::default(), 64);
    }

    fn queue_test<const P: usize, const C: usize>(mut uut: VideoFifo<P, C>, depth: usize) {
        uut.connect_all();
        let mut q: VecDeque<u64> = VecDeque::new();
        let mut x = 0x1234_5678_9abc_def1u64;
        let mut next = 1u64;
        let mut full_seen = false;
        for cycle in 0..5000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let write = x & 3 != 0 && q.len() < depth;
            // Reads are rare in the first 600 cycles of every 2000, so the queue fills up.
            let read = if cycle % 2000 < 600 { (x >> 8) & 3 == 0 } else { (x >> 8) & 3 != 0 };
            full_seen |= q.len() == depth;
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
        assert!(full_seen, "the {depth}-entry queue never filled");
    }
}
