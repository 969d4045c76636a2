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

/// Signed A x B -> P bits with fewer multiplier blocks: the low `LA` bits of `a` and the low `LB` bits
/// of `b` are multiplied in logic (shifted copies added in a tree), only the high parts on `*`:
///
/// ```text
///   a = ah * 2^LA + al,  b = bh * 2^LB + bl        (al, bl unsigned; ah, bh signed)
///   a * b = (ah * bh) << (LA + LB)                 one `*`: multiplier blocks
///         + (ah * bl) << LA                        LB shifted copies of ah, in logic
///         +  al * b                                LA shifted copies of b, in logic
/// ```
///
/// Why: yosys `synth_ecp5` splits each operand into 18-bit pieces (a 40x18 product takes three
/// MULT18X18D, 25x18 two, 44x26 six), so a few low bits past a multiple of 18 cost a whole block.
/// Choosing LA, LB so that the high parts fill whole pieces trades one block for a small adder
/// tree (`docs/figures.md`, "DSP budget"). The product is exact (mod 2^P), as [`MulS`]; the Rust
/// simulation is the same i128 product, and `tb/tests/mul_split_verilog.rs` checks the Verilog form
/// against it under Icarus.
#[derive(LogicBlock, Default)]
pub struct MulSplit<const A: usize, const B: usize, const P: usize, const LA: usize, const LB: usize> {
    pub a: Signal<In, Signed<A>>,
    pub b: Signal<In, Signed<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize, const LA: usize, const LB: usize> Logic for MulSplit<A, B, P, LA, LB> {
    fn update(&mut self) {
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
        Verilog::Custom(mul_split_verilog(A, B, P, LA, LB))
    }
}

/// A balanced sum of `terms` (Verilog expressions), or `zero` when there are none.
fn tree_sum(terms: &[String], zero: &str) -> String {
    match terms.len() {
        0 => zero.to_string(),
        1 => terms[0].clone(),
        n => format!("({} + {})", tree_sum(&terms[..n / 2], zero), tree_sum(&terms[n / 2..], zero)),
    }
}

/// The Verilog body of [`MulSplit`] (ports `a`, `b`, `p` declared by rust-hdl).
pub fn mul_split_verilog(a: usize, b: usize, p: usize, la: usize, lb: usize) -> String {
    assert!(la < a && lb < b, "MulSplit: the split must leave a high part on each operand");
    let (ha, hb) = (a - la, b - lb);
    // al * b fits b + la bits (signed), ah * bl fits ha + lb bits: the trees are that wide, plus one.
    let (wa, wb) = (b + la + 1, ha + lb + 1);
    let mut v = String::new();
    v.push_str(&format!("wire signed [{}:0] a_h = a[{}:{}];\n", ha - 1, a - 1, la));
    v.push_str(&format!("wire signed [{}:0] b_h = b[{}:{}];\n", hb - 1, b - 1, lb));
    v.push_str(&format!("wire signed [{}:0] p_hh = a_h * b_h;\n", p - 1));
    v.push_str(&format!("wire signed [{}:0] b_w = b;\n", wa - 1));
    v.push_str(&format!("wire signed [{}:0] ah_w = a_h;\n", wb - 1));
    let la_terms: Vec<String> = (0..la)
        .map(|i| {
            v.push_str(&format!("wire signed [{}:0] pa{i} = a[{i}] ? (b_w <<< {i}) : {wa}'sd0;\n", wa - 1));
            format!("pa{i}")
        })
        .collect();
    let lb_terms: Vec<String> = (0..lb)
        .map(|i| {
            v.push_str(&format!("wire signed [{}:0] pb{i} = b[{i}] ? (ah_w <<< {i}) : {wb}'sd0;\n", wb - 1));
            format!("pb{i}")
        })
        .collect();
    v.push_str(&format!("wire signed [{}:0] s_a = {};\n", wa - 1, tree_sum(&la_terms, &format!("{wa}'sd0"))));
    v.push_str(&format!("wire signed [{}:0] s_b = {};\n", wb - 1, tree_sum(&lb_terms, &format!("{wb}'sd0"))));
    v.push_str(&format!("wire signed [{}:0] s_a_p = s_a;\n", p - 1));
    v.push_str(&format!("wire signed [{}:0] s_b_p = s_b;\n", p - 1));
    v.push_str(&format!("always @(*) p = ((p_hh <<< {}) + (s_b_p <<< {la})) + s_a_p;", la + lb));
    v
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
