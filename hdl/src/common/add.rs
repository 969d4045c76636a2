//! A widening adder as a leaf block: `s = a + b` with `s` wider than the operands, so that a tree of
//! them can be wired in `for` loops (hdl_gen rejected `bit_cast` of an indexed element inside a `for`
//! loop, "cannot find value `k`", and a Local cannot accumulate across iterations). In Verilog each is `s = a + b`, where the operands are
//! extended to `s`'s width before the addition, so the carry is kept.

use super::bits_from_u128;
use rust_hdl::prelude::*;

/// Unsigned A + A -> S bits (S >= A; the sum truncated if S is narrower than A + 1).
#[derive(LogicBlock, Default)]
pub struct AddU<const A: usize, const S: usize> {
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<A>>,
    pub s: Signal<Out, Bits<S>>,
}

impl<const A: usize, const S: usize> Logic for AddU<A, S> {
    fn update(&mut self) {
        if !self.a.changed && !self.b.changed {
            return;
        }
        let sum = self.a.val().to_u128() + self.b.val().to_u128();
        self.s.next = bits_from_u128::<S>(sum);
    }
    fn connect(&mut self) {
        self.s.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom("always @(*) s = a + b;".into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sum_keeps_its_carry() {
        let mut x = AddU::<9, 10>::default();
        x.connect_all();
        for (a, b) in [(0u64, 0u64), (256, 256), (511, 511), (300, 1)] {
            x.a.next = a.into();
            x.b.next = b.into();
            assert!(simulate(&mut x, 10));
            assert_eq!(x.s.val().to_u64(), a + b);
        }
    }
}
