//! `plane_mul`: the Color Shader's plane product `a * X` (a plane gradient, 40 bits signed, times a
//! pixel coordinate, 11 bits signed) on two 18x18 multiplier blocks instead of three.
//!
//! ```text
//!   a[39:22] (18 b, signed)          * b  -> one multiplier block, << 22
//!   {0, a[21:5]} (17 b, as signed 18) * b  -> one multiplier block, << 5
//!   a[4:0]   (5 b, unsigned)          * b  -> five shifted copies of b, added in a tree (LUTs)
//!   p = sum of the three                                         (51 b, exact)
//! ```
//!
//! Why: yosys splits a 40-bit operand into three 18-bit pieces, so the CS's six plane products took 18
//! MULT18X18D; with the Phong datapath the whole chipset needed 76 of the ECP5-45F's 72. The low five
//! bits of `a` cost a few LUTs instead of a third block. The product is exact (the Rust simulation
//! multiplies in i128, as [`crate::common::MulS`] does); the Verilog replays of the CS check the
//! Verilog form against it.

use crate::common::{from_i128, to_i128};
use rust_hdl::prelude::*;

/// Signed 40 x 11 -> 51 bits.
#[derive(LogicBlock, Default)]
pub struct PlaneMul {
    pub a: Signal<In, Signed<40>>,
    pub b: Signal<In, Signed<11>>,
    pub p: Signal<Out, Signed<51>>,
}

impl Logic for PlaneMul {
    fn update(&mut self) {
        let prod = to_i128(self.a.val()) * to_i128(self.b.val());
        self.p.next = from_i128::<51>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "wire signed [17:0] a_hi = a[39:22];
wire signed [17:0] a_mid = {1'b0, a[21:5]};
wire signed [50:0] b_x = b;
wire signed [50:0] p_hi = a_hi * b;
wire signed [50:0] p_mid = a_mid * b;
wire signed [50:0] l0 = a[0] ? b_x : 51'sd0;
wire signed [50:0] l1 = a[1] ? (b_x <<< 1) : 51'sd0;
wire signed [50:0] l2 = a[2] ? (b_x <<< 2) : 51'sd0;
wire signed [50:0] l3 = a[3] ? (b_x <<< 3) : 51'sd0;
wire signed [50:0] l4 = a[4] ? (b_x <<< 4) : 51'sd0;
wire signed [50:0] p_lo = ((l0 + l1) + (l2 + l3)) + l4;
always @(*) p = ((p_hi <<< 22) + (p_mid <<< 5)) + p_lo;"
                .into(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::from_i64;

    #[test]
    fn plane_product_is_exact_at_the_extremes() {
        let mut m = PlaneMul::default();
        m.connect_all();
        for (a, b) in [(-(1i64 << 39), -1024i64), ((1 << 39) - 1, 1023), (-(1 << 39), 1023), (0x1f, -1), (-12345678901, 777)] {
            m.a.next = from_i64::<40>(a);
            m.b.next = from_i64::<11>(b);
            assert!(simulate(&mut m, 10));
            assert_eq!(to_i128(m.p.val()), a as i128 * b as i128);
        }
    }
}
