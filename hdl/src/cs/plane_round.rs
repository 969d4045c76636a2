//! `PlaneRound`: a plane gradient from its product, `sat40(round(p / 2^sh))`, in two cycles: an
//! arithmetic shift registered, then an increment, a halving and the saturation.
//! `golden::format::Plane::setup`'s `saturate(round_shift(n * mant, s), 40)`, with `sh` = s in 0..=43.
//!
//! Round half up is `floor((p + 2^(s-1)) / 2^s)`, which equals `floor((floor(2p / 2^s) + 1) / 2)` for
//! every s >= 1 (write `p = q 2^(s-1) + r` with `0 <= r < 2^(s-1)`: both are `floor((q + 1) / 2)`), and
//! for s = 0 the right side is `floor((2p + 1) / 2) = p`, no rounding, as `round_shift` does. So the
//! first cycle only shifts `2p` (|p| < 2^62, so 2p fits 64 bits) and the adder moves to the second: the
//! add, the shift and the saturation in one cycle were the chipset's critical path (issue 15 item 5,
//! 6.9 ns of logic and 12.1 ns of routing on the LFE5U-45F).

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct PlaneRound {
    pub clock: Signal<In, Clock>,
    /// The product n * mant (|p| < 2^62).
    pub p: Signal<In, Signed<64>>,
    /// The shift.
    pub sh: Signal<In, Bits<7>>,
    /// Give 0 (det == 0) instead of the product's gradient; taken with `p`.
    pub clear: Signal<In, Bit>,
    /// The rounded, shifted, saturated gradient (two's complement) of the `p`, `sh`, `clear` taken at
    /// the last edge.
    pub out: Signal<Out, Bits<40>>,
    /// `floor(2p / 2^sh)`, or 0 when cleared.
    fl: DFF<Bits<64>>,
    p2: Signal<Local, Bits<64>>,
    qs: Signal<Local, Bits<64>>,
    s: Signal<Local, Bits<64>>,
    top: Signal<Local, Bits<24>>,
    o40: Signal<Local, Bits<40>>,
    k1_7: Constant<Bits<7>>,
    k0_64: Constant<Bits<64>>,
    k1_64: Constant<Bits<64>>,
    kmin_40: Constant<Bits<40>>,
    kmax_40: Constant<Bits<40>>,
}

impl Default for PlaneRound {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            p: Default::default(),
            sh: Default::default(),
            clear: Default::default(),
            out: Default::default(),
            fl: Default::default(),
            p2: Default::default(),
            qs: Default::default(),
            s: Default::default(),
            top: Default::default(),
            o40: Default::default(),
            k1_7: Constant::new(1.into()),
            k0_64: Constant::new(0.into()),
            k1_64: Constant::new(1.into()),
            kmin_40: Constant::new((1u64 << 39).into()),
            kmax_40: Constant::new(((1u64 << 39) - 1).into()),
        }
    }
}

impl Logic for PlaneRound {
    #[hdl_gen]
    fn update(&mut self) {
        self.fl.clock.next = self.clock.val();
        // First cycle: fl = 2p >> sh, arithmetic (through the one's complement for negative values).
        self.p2.next = unsigned_cast(self.p.val()) << self.k1_7.val();
        self.qs.next = self.p2.val() >> self.sh.val();
        if self.p2.val().get_bit(63) {
            self.qs.next = !((!self.p2.val()) >> self.sh.val());
        }
        self.fl.d.next = self.qs.val();
        if self.clear.val() {
            self.fl.d.next = self.k0_64.val();
        }
        // Second cycle: (fl + 1) >> 1 is bits 1.. of s = fl + 1; it fits 40 bits when bits 40..=63 of s
        // agree.
        self.s.next = self.fl.q.val() + self.k1_64.val();
        self.top.next = self.s.val().get_bits::<24>(40);
        self.o40.next = self.s.val().get_bits::<40>(1);
        if !(self.top.val().all() | !self.top.val().any()) {
            if self.s.val().get_bit(63) {
                self.o40.next = self.kmin_40.val();
            } else {
                self.o40.next = self.kmax_40.val();
            }
        }
        self.out.next = self.o40.val();
    }
}

/// `PlaneRound` for texture setup's wider products (`tex_setup`: a 55-bit numerator times the 26-bit
/// reciprocal, |p| < 2^78), on 80-bit two's-complement `Bits`. The same result, combinational: the
/// half added, the arithmetic shift and the saturation in one cycle.
#[derive(LogicBlock)]
pub struct PlaneRoundWide {
    /// The product n * mant, two's complement.
    pub p: Signal<In, Bits<80>>,
    /// The shift.
    pub sh: Signal<In, Bits<7>>,
    /// The rounded, shifted, saturated gradient (two's complement).
    pub out: Signal<Out, Bits<40>>,
    one_sh: Signal<Local, Bits<80>>,
    half: Signal<Local, Bits<80>>,
    y: Signal<Local, Bits<80>>,
    ys: Signal<Local, Bits<80>>,
    top: Signal<Local, Bits<41>>,
    o40: Signal<Local, Bits<40>>,
    k1_7: Constant<Bits<7>>,
    k1_80: Constant<Bits<80>>,
    kmin_40: Constant<Bits<40>>,
    kmax_40: Constant<Bits<40>>,
}

impl Default for PlaneRoundWide {
    fn default() -> Self {
        Self {
            p: Default::default(),
            sh: Default::default(),
            out: Default::default(),
            one_sh: Default::default(),
            half: Default::default(),
            y: Default::default(),
            ys: Default::default(),
            top: Default::default(),
            o40: Default::default(),
            k1_7: Constant::new(1.into()),
            k1_80: Constant::new(crate::common::bits_from_u128::<80>(1)),
            kmin_40: Constant::new((1u64 << 39).into()),
            kmax_40: Constant::new(((1u64 << 39) - 1).into()),
        }
    }
}

impl Logic for PlaneRoundWide {
    #[hdl_gen]
    fn update(&mut self) {
        self.one_sh.next = self.k1_80.val() << self.sh.val();
        self.half.next = self.one_sh.val() >> self.k1_7.val();
        self.y.next = self.p.val() + self.half.val();
        self.ys.next = self.y.val() >> self.sh.val();
        if self.y.val().get_bit(79) {
            self.ys.next = !((!self.y.val()) >> self.sh.val());
        }
        self.top.next = self.ys.val().get_bits::<41>(39);
        self.o40.next = self.ys.val().get_bits::<40>(0);
        if !(self.top.val().all() | !self.top.val().any()) {
            if self.ys.val().get_bit(79) {
                self.o40.next = self.kmin_40.val();
            } else {
                self.o40.next = self.kmax_40.val();
            }
        }
        self.out.next = self.o40.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{from_i64, to_i64};

    #[test]
    fn plane_round_is_the_golden_round_shift_and_saturation_one_edge_later() {
        let mut u = PlaneRound::default();
        u.connect_all();
        let ps = [0i64, 1, -1, 2, -2, 3, -3, 7, 8, -8, -9, 123456789, -123456789, (1 << 61) - 1, -(1 << 61), 1 << 50, -(1 << 50) - 3, (1 << 62) - 1, -(1 << 62) + 1];
        for p in ps {
            for sh in [0u64, 1, 2, 4, 5, 17, 36, 40, 43] {
                for clear in [false, true] {
                    u.p.next = from_i64::<64>(p);
                    u.sh.next = sh.into();
                    u.clear.next = clear;
                    u.clock.next = false.into();
                    assert!(simulate(&mut u, 100));
                    u.clock.next = true.into();
                    assert!(simulate(&mut u, 100));
                    // Round half up, then clamp to 40 signed bits (written out here: hdl does not use golden).
                    let half = (1i128 << sh) >> 1;
                    let want = if clear { 0 } else { ((p as i128 + half) >> sh).clamp(-(1i128 << 39), (1i128 << 39) - 1) as i64 };
                    let got = to_i64(signed_cast(u.out.val()));
                    assert_eq!(got, want, "p {p} sh {sh} clear {clear}");
                }
            }
        }
    }

    #[test]
    fn the_wide_plane_round_is_the_same_rounding_on_80_bits() {
        let mut u = PlaneRoundWide::default();
        u.connect_all();
        let big = 1i128 << 78;
        for p in [0i128, 1, -1, 7, 8, -8, -9, 123456789, -123456789, (1 << 57) - 1, -(1 << 57), big - 1, -big, (1i128 << 60) + 12345, -(1i128 << 44) - 3, 1i128 << 43, -(1i128 << 43)] {
            for sh in [0u64, 1, 4, 5, 17, 36, 37, 43] {
                u.p.next = crate::common::bits_from_u128::<80>(p as u128);
                u.sh.next = sh.into();
                assert!(simulate(&mut u, 100));
                let half = (1i128 << sh) >> 1;
                let want = ((p + half) >> sh).clamp(-(1i128 << 39), (1i128 << 39) - 1) as i64;
                let got = to_i64(signed_cast(u.out.val()));
                assert_eq!(got, want, "p {p} sh {sh}");
            }
        }
    }
}
