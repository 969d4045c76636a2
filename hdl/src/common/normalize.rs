//! Two leaves for numbers carried as an 18-bit mantissa and an exponent (the texture unit's level of
//! detail, `golden::texcoord::Float`), combinational, written as Verilog like [`super::LeadingOne36`]:
//!
//! * [`Normalize18`]: `mag` (W bits) truncated to its top 18 bits: `mant = mag >> drop`, `drop =
//!   max(msb - 17, 0)` (`golden::texcoord::Float::of` on a magnitude).
//! * [`LeftAlign`]: the leading one of `x` (W bits) and `x` shifted left until it is the top bit
//!   (`nm`): how two such numbers are compared (by leading one, then by the bits below it).
//!
//! The Rust models compute the same functions with `leading_zeros`; the texture unit's Verilog
//! replays run the Verilog. For `mag = 0` / `x = 0` every output is 0.

use super::bits_from_u128;
use rust_hdl::prelude::*;

fn lead_loop(input: &str, width: usize) -> String {
    format!(
        "integer i;
reg [6:0] lead;
always @(*) begin
    lead = 7'd0;
    for (i = 0; i < {width}; i = i + 1)
        if ({input}[i]) lead = i[6:0];
end
"
    )
}

#[derive(LogicBlock, Default)]
pub struct Normalize18<const W: usize> {
    pub mag: Signal<In, Bits<W>>,
    pub mant: Signal<Out, Bits<18>>,
    pub drop: Signal<Out, Bits<6>>,
}

impl<const W: usize> Logic for Normalize18<W> {
    fn update(&mut self) {
        let v = self.mag.val().to_u128();
        let msb = 127 - v.leading_zeros() as i32;
        let drop = (msb - 17).max(0) as u32;
        self.mant.next = bits_from_u128::<18>(v >> drop);
        self.drop.next = (drop as u64).into();
    }
    fn connect(&mut self) {
        self.mant.connect();
        self.drop.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "{}always @(*) begin
    drop = (lead > 7'd17) ? (lead[5:0] - 6'd17) : 6'd0;
    mant = mag >> drop;
end",
            lead_loop("mag", W)
        ))
    }
}

#[derive(LogicBlock, Default)]
pub struct LeftAlign<const W: usize> {
    pub x: Signal<In, Bits<W>>,
    /// The index of the top set bit.
    pub msb: Signal<Out, Bits<6>>,
    /// `x << (W - 1 - msb)`.
    pub nm: Signal<Out, Bits<W>>,
}

impl<const W: usize> Logic for LeftAlign<W> {
    fn update(&mut self) {
        let v = self.x.val().to_u128();
        let (msb, nm) = if v == 0 { (0, 0) } else { let m = 127 - v.leading_zeros(); (m, v << (W as u32 - 1 - m)) };
        self.msb.next = (msb as u64).into();
        self.nm.next = bits_from_u128::<W>(nm);
    }
    fn connect(&mut self) {
        self.msb.connect();
        self.nm.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "{}always @(*) begin
    msb = lead[5:0];
    nm = x << (6'd{} - lead[5:0]);
end",
            lead_loop("x", W),
            W - 1
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize18_keeps_the_top_18_bits_and_left_align_puts_the_top_bit_first() {
        let mut n = Normalize18::<40>::default();
        let mut l = LeftAlign::<18>::default();
        n.connect_all();
        l.connect_all();
        for v in [0u64, 1, 5, (1 << 18) - 1, 1 << 18, (1 << 40) - 1, 0x9_8765_4321] {
            n.mag.next = v.into();
            assert!(simulate(&mut n, 10));
            let msb = 63 - v.leading_zeros() as i64;
            let drop = (msb - 17).max(0) as u64;
            assert_eq!((n.mant.val().to_u64(), n.drop.val().to_u64()), (v >> drop, drop), "{v:#x}");
        }
        for v in [0u64, 1, 3, 0x2_0000, 0x3_ffff, 0x1234] {
            l.x.next = v.into();
            assert!(simulate(&mut l, 10));
            let (msb, nm) = if v == 0 { (0, 0) } else { let m = 63 - v.leading_zeros() as u64; (m, (v << (17 - m)) & 0x3_ffff) };
            assert_eq!((l.msb.val().to_u64(), l.nm.val().to_u64()), (msb, nm), "{v:#x}");
        }
    }
}
