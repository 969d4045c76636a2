//! The number of ones in each quadrant of 4x4 subpixels of a 64-bit subpixel mask (the 2x2 filter
//! area's weights, seed 002 §6: "the filter area will be 2 x 2 pixels"; a 2x2 box centred on a pixel
//! covers whole quadrants of it and of its neighbours). Combinational.
//!
//! Bit `8 j + i` is subpixel column i, row j; quadrant `q = 2 qy + qx` holds rows 4qy..4qy+3 and
//! columns 4qx..4qx+3: q0 top left, q1 top right, q2 bottom left, q3 bottom right. Each 32-bit half
//! (rows 0-3, rows 4-7) is counted as in [`super::popcount::Popcount64`] down to one count per nibble
//! (per row and quadrant); the low nibbles of the bytes are the left quadrant's rows and the high
//! nibbles the right quadrant's, so two masks and two byte-folds give the four counts. Every
//! statement is one 32-bit operation on sized constants (GUIDE §1 rules 1-2).
//!
//! ```text
//!             +------------------------+──▶ q0[4:0]  (0..=16)
//!   x[63:0] ─▶| quadrant popcount      |──▶ q1[4:0]
//!             |  (4x4 subpixels each)  |──▶ q2[4:0]
//!             +------------------------+──▶ q3[4:0]
//! ```

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct QuadrantPopcount {
    // From the stage's register
    /// The 8x8 mask (bit 8 j + i).
    pub x: Signal<In, Bits<64>>,
    // To the stage's next register
    /// Ones in the top-left quadrant (rows 0-3, columns 0-3).
    pub q0: Signal<Out, Bits<5>>,
    /// Ones in the top-right quadrant (rows 0-3, columns 4-7).
    pub q1: Signal<Out, Bits<5>>,
    /// Ones in the bottom-left quadrant (rows 4-7, columns 0-3).
    pub q2: Signal<Out, Bits<5>>,
    /// Ones in the bottom-right quadrant (rows 4-7, columns 4-7).
    pub q3: Signal<Out, Bits<5>>,

    lo: Signal<Local, Bits<32>>,
    hi: Signal<Local, Bits<32>>,
    lo_a1: Signal<Local, Bits<32>>,
    lo_a: Signal<Local, Bits<32>>,
    lo_b1: Signal<Local, Bits<32>>,
    lo_b2: Signal<Local, Bits<32>>,
    lo_b: Signal<Local, Bits<32>>,
    hi_a1: Signal<Local, Bits<32>>,
    hi_a: Signal<Local, Bits<32>>,
    hi_b1: Signal<Local, Bits<32>>,
    hi_b2: Signal<Local, Bits<32>>,
    hi_b: Signal<Local, Bits<32>>,
    // Left (low nibbles) and right (high nibbles) per half, then folded over the four bytes.
    ll: Signal<Local, Bits<32>>,
    lr1: Signal<Local, Bits<32>>,
    lr: Signal<Local, Bits<32>>,
    hl: Signal<Local, Bits<32>>,
    hr1: Signal<Local, Bits<32>>,
    hr: Signal<Local, Bits<32>>,
    ll8: Signal<Local, Bits<32>>,
    lr8: Signal<Local, Bits<32>>,
    hl8: Signal<Local, Bits<32>>,
    hr8: Signal<Local, Bits<32>>,
    ll16: Signal<Local, Bits<32>>,
    lr16: Signal<Local, Bits<32>>,
    hl16: Signal<Local, Bits<32>>,
    hr16: Signal<Local, Bits<32>>,
    k55: Constant<Bits<32>>,
    k33: Constant<Bits<32>>,
    k0f: Constant<Bits<32>>,
}

impl Default for QuadrantPopcount {
    fn default() -> Self {
        QuadrantPopcount {
            x: Default::default(),
            q0: Default::default(),
            q1: Default::default(),
            q2: Default::default(),
            q3: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            lo_a1: Default::default(),
            lo_a: Default::default(),
            lo_b1: Default::default(),
            lo_b2: Default::default(),
            lo_b: Default::default(),
            hi_a1: Default::default(),
            hi_a: Default::default(),
            hi_b1: Default::default(),
            hi_b2: Default::default(),
            hi_b: Default::default(),
            ll: Default::default(),
            lr1: Default::default(),
            lr: Default::default(),
            hl: Default::default(),
            hr1: Default::default(),
            hr: Default::default(),
            ll8: Default::default(),
            lr8: Default::default(),
            hl8: Default::default(),
            hr8: Default::default(),
            ll16: Default::default(),
            lr16: Default::default(),
            hl16: Default::default(),
            hr16: Default::default(),
            k55: Constant::new(0x5555_5555u64.into()),
            k33: Constant::new(0x3333_3333u64.into()),
            k0f: Constant::new(0x0f0f_0f0fu64.into()),
        }
    }
}

impl Logic for QuadrantPopcount {
    #[hdl_gen]
    fn update(&mut self) {
        self.lo.next = self.x.val().get_bits::<32>(0);
        self.hi.next = self.x.val().get_bits::<32>(32);
        // Pairs, then nibbles: each nibble holds the ones of one row of one quadrant (0..=4).
        self.lo_a1.next = (self.lo.val() >> 1) & self.k55.val();
        self.lo_a.next = self.lo.val() - self.lo_a1.val();
        self.lo_b1.next = self.lo_a.val() & self.k33.val();
        self.lo_b2.next = (self.lo_a.val() >> 2) & self.k33.val();
        self.lo_b.next = self.lo_b1.val() + self.lo_b2.val();
        self.hi_a1.next = (self.hi.val() >> 1) & self.k55.val();
        self.hi_a.next = self.hi.val() - self.hi_a1.val();
        self.hi_b1.next = self.hi_a.val() & self.k33.val();
        self.hi_b2.next = (self.hi_a.val() >> 2) & self.k33.val();
        self.hi_b.next = self.hi_b1.val() + self.hi_b2.val();
        // Low nibbles: the left quadrant's rows; high nibbles: the right quadrant's.
        self.ll.next = self.lo_b.val() & self.k0f.val();
        self.lr1.next = self.lo_b.val() >> 4;
        self.lr.next = self.lr1.val() & self.k0f.val();
        self.hl.next = self.hi_b.val() & self.k0f.val();
        self.hr1.next = self.hi_b.val() >> 4;
        self.hr.next = self.hr1.val() & self.k0f.val();
        // Fold the four rows (bytes) into the low byte: at most 16, no carry between bytes.
        self.ll8.next = self.ll.val() + (self.ll.val() >> 8);
        self.lr8.next = self.lr.val() + (self.lr.val() >> 8);
        self.hl8.next = self.hl.val() + (self.hl.val() >> 8);
        self.hr8.next = self.hr.val() + (self.hr.val() >> 8);
        self.ll16.next = self.ll8.val() + (self.ll8.val() >> 16);
        self.lr16.next = self.lr8.val() + (self.lr8.val() >> 16);
        self.hl16.next = self.hl8.val() + (self.hl8.val() >> 16);
        self.hr16.next = self.hr8.val() + (self.hr8.val() >> 16);
        self.q0.next = self.ll16.val().get_bits::<5>(0);
        self.q1.next = self.lr16.val().get_bits::<5>(0);
        self.q2.next = self.hl16.val().get_bits::<5>(0);
        self.q3.next = self.hr16.val().get_bits::<5>(0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ones of quadrant q of a mask, the plain way (golden's `quadrant_sums` uses the same layout).
    fn quadrant_ones(m: u64, q: usize) -> u64 {
        let (qx, qy) = (q % 2, q / 2);
        let mut n = 0;
        for j in 4 * qy..4 * qy + 4 {
            for i in 4 * qx..4 * qx + 4 {
                n += (m >> (8 * j + i)) & 1;
            }
        }
        n
    }

    #[test]
    fn quadrant_popcount_counts_each_quadrant_of_random_and_extreme_masks() {
        let mut uut = QuadrantPopcount::default();
        uut.connect_all();
        check_all(&uut).unwrap();
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut cases = vec![0u64, u64::MAX, 1, 1 << 63, 0x0f0f_0f0f, 0xf0f0_f0f0, 0x0f0f_0f0f << 32, 0xf0f0_f0f0u64 << 32, 0x8000_0001_8000_0001];
        for _ in 0..2000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            cases.push(x & (x >> (x % 5)));
        }
        for v in cases {
            uut.x.next = v.into();
            assert!(simulate(&mut uut, 100));
            let got = [uut.q0.val(), uut.q1.val(), uut.q2.val(), uut.q3.val()].map(|c| c.to_u64());
            assert_eq!(got, [0, 1, 2, 3].map(|q| quadrant_ones(v, q)), "{v:#018x}");
        }
    }
}
