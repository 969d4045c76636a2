//! Population count of a 64-bit subpixel mask (the filter stage's weights, seed 002 §6.2: "weights
//! equal to the number of subpixels each object covers"). Combinational. Each 32-bit half is counted
//! by the usual adder tree in SWAR form (pairs, nibbles, bytes, halves: 2+2 -> 4 -> 8 -> 16 -> 32),
//! every statement one 32-bit operation on sized constants, so the Verilog and the simulation agree
//! bit for bit (GUIDE §1 rules 1-2).
//!
//! ```text
//!            +-------------------+
//!   x[63:0] ─▶| popcount (0..=64) |──▶ count[6:0]
//!            +-------------------+
//! ```

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Popcount64 {
    // From the stage's register
    /// The mask.
    pub x: Signal<In, Bits<64>>,
    // To the stage's next register
    /// The number of ones in `x`.
    pub count: Signal<Out, Bits<7>>,

    lo: Signal<Local, Bits<32>>,
    hi: Signal<Local, Bits<32>>,
    lo_a: Signal<Local, Bits<32>>,
    lo_a1: Signal<Local, Bits<32>>,
    lo_b: Signal<Local, Bits<32>>,
    lo_b1: Signal<Local, Bits<32>>,
    lo_b2: Signal<Local, Bits<32>>,
    lo_c: Signal<Local, Bits<32>>,
    lo_c1: Signal<Local, Bits<32>>,
    lo_d: Signal<Local, Bits<32>>,
    lo_e: Signal<Local, Bits<32>>,
    hi_a: Signal<Local, Bits<32>>,
    hi_a1: Signal<Local, Bits<32>>,
    hi_b: Signal<Local, Bits<32>>,
    hi_b1: Signal<Local, Bits<32>>,
    hi_b2: Signal<Local, Bits<32>>,
    hi_c: Signal<Local, Bits<32>>,
    hi_c1: Signal<Local, Bits<32>>,
    hi_d: Signal<Local, Bits<32>>,
    hi_e: Signal<Local, Bits<32>>,
    n_lo: Signal<Local, Bits<7>>,
    n_hi: Signal<Local, Bits<7>>,
    k55: Constant<Bits<32>>,
    k33: Constant<Bits<32>>,
    k0f: Constant<Bits<32>>,
}

impl Default for Popcount64 {
    fn default() -> Self {
        Popcount64 {
            x: Default::default(),
            count: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            lo_a: Default::default(),
            lo_a1: Default::default(),
            lo_b: Default::default(),
            lo_b1: Default::default(),
            lo_b2: Default::default(),
            lo_c: Default::default(),
            lo_c1: Default::default(),
            lo_d: Default::default(),
            lo_e: Default::default(),
            hi_a: Default::default(),
            hi_a1: Default::default(),
            hi_b: Default::default(),
            hi_b1: Default::default(),
            hi_b2: Default::default(),
            hi_c: Default::default(),
            hi_c1: Default::default(),
            hi_d: Default::default(),
            hi_e: Default::default(),
            n_lo: Default::default(),
            n_hi: Default::default(),
            k55: Constant::new(0x5555_5555u64.into()),
            k33: Constant::new(0x3333_3333u64.into()),
            k0f: Constant::new(0x0f0f_0f0fu64.into()),
        }
    }
}

impl Logic for Popcount64 {
    #[hdl_gen]
    fn update(&mut self) {
        self.lo.next = self.x.val().get_bits::<32>(0);
        self.hi.next = self.x.val().get_bits::<32>(32);
        // Pairs: a = x - ((x >> 1) & 0x55..) holds the count of each bit pair.
        self.lo_a1.next = (self.lo.val() >> 1) & self.k55.val();
        self.lo_a.next = self.lo.val() - self.lo_a1.val();
        self.hi_a1.next = (self.hi.val() >> 1) & self.k55.val();
        self.hi_a.next = self.hi.val() - self.hi_a1.val();
        // Nibbles.
        self.lo_b1.next = self.lo_a.val() & self.k33.val();
        self.lo_b2.next = (self.lo_a.val() >> 2) & self.k33.val();
        self.lo_b.next = self.lo_b1.val() + self.lo_b2.val();
        self.hi_b1.next = self.hi_a.val() & self.k33.val();
        self.hi_b2.next = (self.hi_a.val() >> 2) & self.k33.val();
        self.hi_b.next = self.hi_b1.val() + self.hi_b2.val();
        // Bytes.
        self.lo_c1.next = self.lo_b.val() + (self.lo_b.val() >> 4);
        self.lo_c.next = self.lo_c1.val() & self.k0f.val();
        self.hi_c1.next = self.hi_b.val() + (self.hi_b.val() >> 4);
        self.hi_c.next = self.hi_c1.val() & self.k0f.val();
        // Halves, then the whole word: the count is in the low 6 bits.
        self.lo_d.next = self.lo_c.val() + (self.lo_c.val() >> 8);
        self.lo_e.next = self.lo_d.val() + (self.lo_d.val() >> 16);
        self.hi_d.next = self.hi_c.val() + (self.hi_c.val() >> 8);
        self.hi_e.next = self.hi_d.val() + (self.hi_d.val() >> 16);
        self.n_lo.next = bit_cast::<7, 6>(self.lo_e.val().get_bits::<6>(0));
        self.n_hi.next = bit_cast::<7, 6>(self.hi_e.val().get_bits::<6>(0));
        self.count.next = self.n_lo.val() + self.n_hi.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn popcount_counts_the_ones_of_random_and_extreme_masks() {
        let mut uut = Popcount64::default();
        uut.connect_all();
        check_all(&uut).unwrap();
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut cases = vec![0u64, u64::MAX, 1, 1 << 63, 0x8000_0001_8000_0001, 0xffff_ffff, 0xffff_ffff_0000_0000];
        for _ in 0..2000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            cases.push(x & (x >> (x % 7)));
        }
        for v in cases {
            uut.x.next = v.into();
            assert!(simulate(&mut uut, 100));
            assert_eq!(uut.count.val().to_u64(), v.count_ones() as u64, "{v:#x}");
        }
    }
}
