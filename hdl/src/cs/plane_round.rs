//! `PlaneRound`: a plane gradient from its product, `sat40(round(p / 2^sh))` (combinational): add
//! half, arithmetic shift right (through the one's complement for negative values, on `Bits`), saturate
//! to 40 bits. `golden::format::Plane::setup`'s `saturate(round_shift(n * mant, s), 40)`, with
//! `sh` = s in 0..=43 (the half is `(1 << sh) >> 1`, so 0 when `sh` is 0: no rounding).

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct PlaneRound {
    /// The product n * mant (|p| < 2^62).
    pub p: Signal<In, Signed<64>>,
    /// The shift.
    pub sh: Signal<In, Bits<7>>,
    /// The rounded, shifted, saturated gradient (two's complement).
    pub out: Signal<Out, Bits<40>>,
    one_sh: Signal<Local, Bits<64>>,
    half: Signal<Local, Bits<64>>,
    y: Signal<Local, Signed<64>>,
    yb: Signal<Local, Bits<64>>,
    ys: Signal<Local, Bits<64>>,
    top: Signal<Local, Bits<25>>,
    o40: Signal<Local, Bits<40>>,
    k1_7: Constant<Bits<7>>,
    k1_64: Constant<Bits<64>>,
    kmin_40: Constant<Bits<40>>,
    kmax_40: Constant<Bits<40>>,
}

impl Default for PlaneRound {
    fn default() -> Self {
        Self {
            p: Default::default(),
            sh: Default::default(),
            out: Default::default(),
            one_sh: Default::default(),
            half: Default::default(),
            y: Default::default(),
            yb: Default::default(),
            ys: Default::default(),
            top: Default::default(),
            o40: Default::default(),
            k1_7: Constant::new(1.into()),
            k1_64: Constant::new(1.into()),
            kmin_40: Constant::new((1u64 << 39).into()),
            kmax_40: Constant::new(((1u64 << 39) - 1).into()),
        }
    }
}

impl Logic for PlaneRound {
    #[hdl_gen]
    fn update(&mut self) {
        self.one_sh.next = self.k1_64.val() << self.sh.val();
        self.half.next = self.one_sh.val() >> self.k1_7.val();
        self.y.next = self.p.val() + signed_cast(self.half.val());
        self.yb.next = unsigned_cast(self.y.val());
        self.ys.next = self.yb.val() >> self.sh.val();
        if self.yb.val().get_bit(63) {
            self.ys.next = !((!self.yb.val()) >> self.sh.val());
        }
        self.top.next = self.ys.val().get_bits::<25>(39);
        self.o40.next = self.ys.val().get_bits::<40>(0);
        if !(self.top.val().all() | !self.top.val().any()) {
            if self.ys.val().get_bit(63) {
                self.o40.next = self.kmin_40.val();
            } else {
                self.o40.next = self.kmax_40.val();
            }
        }
        self.out.next = self.o40.val();
    }
}

/// `PlaneRound` for texture setup's wider products (`tex_setup`: a 55-bit numerator times the 26-bit
/// reciprocal, |p| < 2^78), on 80-bit two's-complement `Bits`. Same rounding, shift and saturation.
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
    fn plane_round_is_the_golden_round_shift_and_saturation() {
        let mut u = PlaneRound::default();
        u.connect_all();
        for p in [0i64, 1, -1, 7, 8, -8, -9, 123456789, -123456789, (1 << 61) - 1, -(1 << 61), 1 << 50, -(1 << 50) - 3] {
            for sh in [0u64, 1, 4, 5, 17, 36, 40, 43] {
                u.p.next = from_i64::<64>(p);
                u.sh.next = sh.into();
                assert!(simulate(&mut u, 100));
                // Round half up, then clamp to 40 signed bits (written out here: hdl does not use golden).
                let half = (1i128 << sh) >> 1;
                let want = ((p as i128 + half) >> sh).clamp(-(1i128 << 39), (1i128 << 39) - 1) as i64;
                let got = to_i64(signed_cast(u.out.val()));
                assert_eq!(got, want, "p {p} sh {sh}");
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
