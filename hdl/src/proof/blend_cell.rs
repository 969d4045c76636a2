//! One subpixel of PROOF's blending filter (seed 002 §6: "the filter algorithm is able to process
//! both opaque and transparent objects"; issue 22): front-to-back compositing of the list entries
//! that cover the subpixel. The pixel state `spent` is the part of the subpixel's 256 (1.0 in Q1.8)
//! that nearer entries took, so the transmittance left is `T = 256 - spent`; an entry of opacity `a`
//! (Q1.4, 0..=16) covering the subpixel takes the weight `w = (T a + 8) >> 4` and leaves `T - w`.
//! The 9x5-bit product is written as shifted adds (`T a = Σ a_k T 2^k`, k = 0..3, or `T 2^4` when
//! a = 16), so that synthesis keeps it in LUTs: with `*`, Yosys gave each of the 64 cells an ECP5
//! MULT18X18D (70 of the LFE5U-45F's 72). An opaque entry (a = 16) takes `w = T`: the whole subpixel if no nearer entry
//! covered it, nothing if one did. [`super::filter_front::FilterFront`] holds 64 of these, one per
//! subpixel, at its F4. Golden form: `golden::proof::filter::blend_subpixels`; cycle behaviour: the
//! F4 step of `golden::proof::cycle_filter::FilterFront`.
//!
//! ```text
//!            +──────────────────────────────────────────────+
//!  hit   ──▶ | w = hit ? (((256 - spent) a + 8) >> 4) : 0    |──▶ w (F4)
//!  a     ──▶ | F4 w        <= w                  (on adv)   |
//!  valid ──▶ | spent       <= last ? 0 : spent + w (on adv,  |
//!  last  ──▶ |                               F3 valid)      |
//!  adv   ──▶ +──────────────────────────────────────────────+
//! ```
//! `spent` stays within 0..=256 because `w <= T` for `a <= 16` (the front clamps the table's value to
//! 16; the product below is exact for `a <= 16`). Every statement changes width at most once
//! (GUIDE §1).

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct BlendCell {
    pub clock: Signal<In, Clock>,
    // From the front end
    /// Move on at this edge (the stage's global stall).
    pub adv: Signal<In, Bit>,
    /// The subpixel is in F3's entry mask.
    pub hit: Signal<In, Bit>,
    /// F3 holds a slot of the stream (the pixel state changes only then).
    pub valid: Signal<In, Bit>,
    /// F3's slot is its pixel's last.
    pub last: Signal<In, Bit>,
    /// F3's entry's opacity, Q1.4 (0..=16).
    pub a: Signal<In, Bits<5>>,
    // To the sum tree
    /// F4's weight, 0..=256.
    pub w: Signal<Out, Bits<9>>,

    // Registers (pub: the benches compare them with the model).
    /// Pixel state: 256 - the transmittance left.
    pub spent: DFF<Bits<9>>,
    /// F4: the weight of F3's entry, moved on.
    pub f4_w: DFF<Bits<9>>,

    t: Signal<Local, Bits<9>>,
    // T a as shifted adds: the partial products T 2^k for the set bits a_k, k = 0..3, their sum,
    // and T 2^4 for a = 16.
    tw: Signal<Local, Bits<14>>,
    pp0: Signal<Local, Bits<14>>,
    pp1: Signal<Local, Bits<14>>,
    pp2: Signal<Local, Bits<14>>,
    pp3: Signal<Local, Bits<14>>,
    p01: Signal<Local, Bits<14>>,
    p23: Signal<Local, Bits<14>>,
    prod: Signal<Local, Bits<14>>,
    rounded: Signal<Local, Bits<14>>,
    wn: Signal<Local, Bits<9>>,
    wsel: Signal<Local, Bits<9>>,
    one: Constant<Bits<9>>,
    half: Constant<Bits<14>>,
    zero9: Constant<Bits<9>>,
    zero14: Constant<Bits<14>>,
    sh1: Constant<Bits<14>>,
    sh2: Constant<Bits<14>>,
    sh3: Constant<Bits<14>>,
    sh4: Constant<Bits<14>>,
}

impl Default for BlendCell {
    fn default() -> BlendCell {
        BlendCell {
            clock: Default::default(),
            adv: Default::default(),
            hit: Default::default(),
            valid: Default::default(),
            last: Default::default(),
            a: Default::default(),
            w: Default::default(),
            spent: Default::default(),
            f4_w: Default::default(),
            t: Default::default(),
            tw: Default::default(),
            pp0: Default::default(),
            pp1: Default::default(),
            pp2: Default::default(),
            pp3: Default::default(),
            p01: Default::default(),
            p23: Default::default(),
            prod: Default::default(),
            rounded: Default::default(),
            wn: Default::default(),
            wsel: Default::default(),
            one: Constant::new(256u64.into()),
            half: Constant::new(8u64.into()),
            zero9: Constant::new(0u64.into()),
            zero14: Constant::new(0u64.into()),
            sh1: Constant::new(1u64.into()),
            sh2: Constant::new(2u64.into()),
            sh3: Constant::new(3u64.into()),
            sh4: Constant::new(4u64.into()),
        }
    }
}

impl Logic for BlendCell {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, spent, f4_w);
        self.t.next = self.one.val() - self.spent.q.val();
        self.tw.next = bit_cast::<14, 9>(self.t.val());
        self.pp0.next = self.zero14.val();
        self.pp1.next = self.zero14.val();
        self.pp2.next = self.zero14.val();
        self.pp3.next = self.zero14.val();
        if self.a.val().get_bit(0) {
            self.pp0.next = self.tw.val();
        }
        if self.a.val().get_bit(1) {
            self.pp1.next = self.tw.val() << self.sh1.val();
        }
        if self.a.val().get_bit(2) {
            self.pp2.next = self.tw.val() << self.sh2.val();
        }
        if self.a.val().get_bit(3) {
            self.pp3.next = self.tw.val() << self.sh3.val();
        }
        self.p01.next = self.pp0.val() + self.pp1.val();
        self.p23.next = self.pp2.val() + self.pp3.val();
        self.prod.next = self.p01.val() + self.p23.val();
        if self.a.val().get_bit(4) {
            self.prod.next = self.tw.val() << self.sh4.val();
        }
        self.rounded.next = self.prod.val() + self.half.val();
        self.wn.next = self.rounded.val().get_bits::<9>(4);
        self.wsel.next = self.zero9.val();
        if self.hit.val() {
            self.wsel.next = self.wn.val();
        }
        self.w.next = self.f4_w.q.val();
        if self.adv.val() {
            self.f4_w.d.next = self.wsel.val();
            if self.valid.val() {
                self.spent.d.next = self.spent.q.val() + self.wsel.val();
                if self.last.val() {
                    self.spent.d.next = self.zero9.val();
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every transmittance 0..=256 and opacity 0..=16 against `(T a + 8) >> 4`.
    #[test]
    fn the_shifted_adds_give_the_rounded_product_for_every_transmittance_and_opacity() {
        let mut c = BlendCell::default();
        c.connect_all();
        c.hit.next = true;
        for spent in 0..=256u64 {
            c.spent.q.next = spent.into();
            for a in 0..=16u64 {
                c.a.next = a.into();
                assert!(simulate(&mut c, 100));
                assert_eq!(c.wsel.val().to_u64(), ((256 - spent) * a + 8) >> 4, "T {} a {a}", 256 - spent);
            }
        }
    }

    #[test]
    fn an_entry_of_opacity_nine_sixteenths_three_times_takes_144_63_and_28() {
        // By hand: 256 x 9/16 = 144 leaves 112; 112 x 9/16 = 63 leaves 49; 49 x 9/16 = 27.56 -> 28.
        let mut c = BlendCell::default();
        c.connect_all();
        c.adv.next = true;
        c.hit.next = true;
        c.valid.next = true;
        c.a.next = 9u64.into();
        let mut got = Vec::new();
        for n in 0..3 {
            c.last.next = n == 2;
            c.clock.next = false.into();
            assert!(simulate(&mut c, 100));
            c.clock.next = true.into();
            assert!(simulate(&mut c, 100));
            got.push(c.w.val().to_u64());
        }
        assert_eq!(got, [144, 63, 28]);
        assert_eq!(c.spent.q.val().to_u64(), 0, "back to 0 after the pixel's last slot");
    }
}
