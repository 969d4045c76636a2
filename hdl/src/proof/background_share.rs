//! The background's share in a quadrant's covered subpixels, times one background channel, for the
//! 2x2 filter's quadrant word ([`super::filter2x2`]): `p = (256 cov - wsum - w) bg`, where `cov` is
//! the quadrant's covered subpixels, `wsum + w` the blend weights of the pixel's entries so far
//! (1/256 subpixels) and so `256 cov - wsum - w` the transmittance left in the covered subpixels
//! (0..=4096; never negative, as each covered subpixel's weights sum to at most 256; wraps at 13 bits
//! if the inputs break that). Combinational.
//!
//! ```text
//!   cov[4:0] ──▶+──────────────────────────────+
//!  wsum[12:0]──▶| rem = {cov, 8'b0} - wsum - w |──▶ p[19:0] = rem x bg
//!     w[12:0]──▶| (13 bits)                    |
//!     bg[7:0]──▶+──────────────────────────────+
//! ```
//!
//! A leaf block with its own Verilog rather than statements in the stage: with `rem` as a temporary
//! of the stage's always block feeding a multiplier whose product the same block reads, Verilator
//! could not split the block and reported a combinational loop (UNOPTFLAT) that is not there.

use crate::common::bits_from_u128;
use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct BackgroundShare {
    // From the stage's registers
    /// Covered subpixels of the quadrant, 0..=16.
    pub cov: Signal<In, Bits<5>>,
    /// The pixel's entries' quadrant weights before this entry (1/256 subpixels).
    pub wsum: Signal<In, Bits<13>>,
    /// This entry's quadrant weight.
    pub w: Signal<In, Bits<13>>,
    /// One background channel.
    pub bg: Signal<In, Bits<8>>,
    // To the stage's word
    /// `(256 cov - wsum - w) bg`, 0..=1 044 480.
    pub p: Signal<Out, Bits<20>>,
}

impl Logic for BackgroundShare {
    fn update(&mut self) {
        let rem = ((self.cov.val().to_u64() << 8).wrapping_sub(self.wsum.val().to_u64()).wrapping_sub(self.w.val().to_u64())) & 0x1fff;
        self.p.next = bits_from_u128::<20>(rem as u128 * self.bg.val().to_u64() as u128);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom("wire [12:0] rem = {cov, 8'b0} - wsum - w;\nalways @(*) p = rem * bg;".into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_share_is_the_left_transmittance_times_the_background() {
        let mut b = BackgroundShare::default();
        b.connect_all();
        // 16 covered subpixels, 144 x 16 + 63 x 16 taken: 49 x 16 left; times 255.
        for (cov, wsum, w, bg, want) in [(16u64, 144 * 16u64, 63 * 16u64, 255u64, 49 * 16 * 255u64), (16, 0, 0, 255, 4096 * 255), (3, 768, 0, 200, 0), (0, 0, 0, 9, 0)] {
            b.cov.next = cov.into();
            b.wsum.next = wsum.into();
            b.w.next = w.into();
            b.bg.next = bg.into();
            assert!(simulate(&mut b, 10));
            assert_eq!(b.p.val().to_u64(), want, "cov {cov} wsum {wsum} w {w} bg {bg}");
        }
    }
}
