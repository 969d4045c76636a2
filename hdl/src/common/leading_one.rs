//! `LeadingOne<N>` (`LeadingOne36`, `LeadingOne44`): the most significant set bit of an N-bit word (N <= 64), as a one-hot word and as its index
//! (combinational). A reciprocal normalises its divisor with it: `2^shift` is where the restoring
//! division's partial remainder starts (`golden::format::reciprocal`). For 0 both outputs are 0.
//!
//! ```text
//!  x (N b) --> smear the top set bit down (x | x>>1 | x>>2 ...) --> isolate it --> onehot (N b)
//!                                                                  --> OR-planes --> index (6 b)
//! ```
//!
//! A leaf written as Verilog (like [`super::MulS`] and [`super::DivStep`]): the smear and the OR-planes
//! are the Verilog in `hdl()`; the Rust model computes the same function with `leading_zeros` and
//! skips re-evaluation while `x` is unchanged (rust-hdl keeps a wide `Bits` as an array of bools, and
//! this block sat on every simulation pass of the RC). The test below checks the Rust model; the RC's and
//! colour setup's Verilog replays run the Verilog.

use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct LeadingOne<const N: usize> {
    pub x: Signal<In, Bits<N>>,
    /// The top set bit of `x` alone.
    pub onehot: Signal<Out, Bits<N>>,
    /// Its index: floor(log2 x).
    pub index: Signal<Out, Bits<6>>,
}

/// Bit j of the mask is set where bit `bit` of j is set: the encoder's OR-planes.
fn encoder_mask(n: usize, bit: u32) -> u64 {
    (0..n as u64).filter(|j| j >> bit & 1 == 1).map(|j| 1u64 << j).sum()
}

/// Colour setup's and the texture coordinates' 36-bit normaliser.
pub type LeadingOne36 = LeadingOne<36>;
/// The RC reciprocal's normaliser: det of S11.8 coordinates is below 2^42.
pub type LeadingOne44 = LeadingOne<44>;

impl<const N: usize> Logic for LeadingOne<N> {
    fn update(&mut self) {
        if !self.x.changed {
            return;
        }
        let x = self.x.val().to_u64();
        let (hot, index) = if x == 0 { (0, 0) } else { let i = 63 - x.leading_zeros() as u64; (1u64 << i, i) };
        self.onehot.next = hot.into();
        self.index.next = index.into();
    }
    fn connect(&mut self) {
        self.onehot.connect();
        self.index.connect();
    }
    fn hdl(&self) -> Verilog {
        assert!(N <= 64, "LeadingOne<{N}>: at most 64 bits");
        let planes: Vec<String> = (0..6).rev().map(|b| format!("|(hot & {N}'h{:x})", encoder_mask(N, b))).collect();
        let top = N - 1;
        Verilog::Custom(format!(
            "wire [{top}:0] smear1 = x | (x >> 1);
wire [{top}:0] smear2 = smear1 | (smear1 >> 2);
wire [{top}:0] smear4 = smear2 | (smear2 >> 4);
wire [{top}:0] smear8 = smear4 | (smear4 >> 8);
wire [{top}:0] smear16 = smear8 | (smear8 >> 16);
wire [{top}:0] smear32 = smear16 | (smear16 >> 32);
wire [{top}:0] hot = smear32 ^ (smear32 >> 1);
always @(*) begin
    onehot = hot;
    index = {{{}}};
end",
            planes.join(", ")
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn leading_one_finds_the_top_set_bit_of_every_width() {
        let mut w = LeadingOne44::default();
        w.connect_all();
        for x in [1u64, 1 << 36, (1 << 44) - 1, 1 << 43, 0x9_8765_4321] {
            w.x.next = x.into();
            assert!(simulate(&mut w, 100));
            assert_eq!(w.index.val().to_u64(), 63 - x.leading_zeros() as u64, "x = {x:#x}");
        }
        let mut u = LeadingOne36::default();
        u.connect_all();
        for x in [0u64, 1, 2, 3, 5, 255, 256, (1 << 35) - 1, 1 << 35, 0x123456789] {
            u.x.next = x.into();
            assert!(simulate(&mut u, 100));
            let want = if x == 0 { 0 } else { 63 - x.leading_zeros() as u64 };
            assert_eq!(u.index.val().to_u64(), want, "x = {x:#x}");
            assert_eq!(u.onehot.val().to_u64(), if x == 0 { 0 } else { 1 << want }, "x = {x:#x}");
        }
    }
}
