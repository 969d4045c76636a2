//! Combinational multipliers of any width as leaf blocks: hdl_gen's `*` exists only for 16x16
//! (GUIDE §1). In Verilog each is `p = a * b`, which yosys `synth_ice40 -dsp` maps onto SB_MAC16
//! blocks (a 24x18 product takes 3); the Rust simulation multiplies in i128 (operands up to 64 bits,
//! product truncated to P <= 128 bits).

use super::{bits_from_u128, from_i128, to_i128};
use rust_hdl::prelude::*;

/// Signed A x B -> P bits (two's complement, truncated if P is narrower than A + B).
#[derive(LogicBlock, Default)]
pub struct MulS<const A: usize, const B: usize, const P: usize> {
    pub a: Signal<In, Signed<A>>,
    pub b: Signal<In, Signed<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize> Logic for MulS<A, B, P> {
    fn update(&mut self) {
        // Inputs unchanged since the last evaluation: the product stands (the conversions to and from
        // i128 are most of the Rust simulation's cost of a wide product). Both start at 0, 0 * 0 = 0.
        if !self.a.changed && !self.b.changed {
            return;
        }
        let prod = to_i128(self.a.val()).wrapping_mul(to_i128(self.b.val()));
        self.p.next = from_i128::<P>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom("always @(*) p = a * b;".into())
    }
}

/// Unsigned A x B -> P bits.
#[derive(LogicBlock, Default)]
pub struct MulU<const A: usize, const B: usize, const P: usize> {
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<B>>,
    pub p: Signal<Out, Bits<P>>,
}

impl<const A: usize, const B: usize, const P: usize> Logic for MulU<A, B, P> {
    fn update(&mut self) {
        if !self.a.changed && !self.b.changed {
            return;
        }
        let prod = self.a.val().to_u128().wrapping_mul(self.b.val().to_u128());
        self.p.next = bits_from_u128::<P>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom("always @(*) p = a * b;".into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{from_i64, to_i128};

    #[test]
    fn signed_wide_product_is_exact() {
        let mut m = MulS::<44, 25, 69>::default();
        m.connect_all();
        for (a, b) in [(-(1i64 << 43), (1i64 << 24) - 1), ((1 << 43) - 1, -(1 << 24)), (-12345, 678)] {
            m.a.next = from_i64::<44>(a);
            m.b.next = from_i64::<25>(b);
            assert!(simulate(&mut m, 10));
            assert_eq!(to_i128(m.p.val()), a as i128 * b as i128);
        }
    }
}
