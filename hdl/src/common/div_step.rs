//! `DivStepN<R>` (`DivStep`, 37 bits, and `DivStep45`): one step of the restoring division of `golden::format::reciprocal` (combinational): the
//! partial remainder is compared with the divisor, the divisor subtracted if it fits, one quotient bit
//! shifted in. The RC's pipelined reciprocal (`rc::fast_reciprocal`) chains two per station, the
//! texture units' (`rc::reciprocal`) three; colour setup's pipelined one has one per station.
//!
//! A leaf written as Verilog (like [`super::MulS`]): rust-hdl 0.46 keeps any `Bits` wider than 32 bits
//! as an array of bools, so the 37/45-bit compare and subtract of an `hdl_gen` version cost more than
//! the rest of the RC in the Rust simulation (the RC's reciprocal has 25 of them). The Rust model below
//! and the Verilog in `hdl()` are the same function; `tb/tests/rc_verilog.rs` and the colour-setup
//! Verilog replays run the generated Verilog against the cycle models, and the test below checks the
//! Rust side against the golden divider.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DivStepN<const R: usize> {
    /// Partial remainder (< 2 * den) and divisor, R bits (one more than the divisor's).
    pub rem: Signal<In, Bits<R>>,
    pub den: Signal<In, Bits<R>>,
    pub quo: Signal<In, Bits<25>>,
    /// After the step.
    pub rem_next: Signal<Out, Bits<R>>,
    pub quo_next: Signal<Out, Bits<25>>,
}

/// A step for 36-bit divisors.
pub type DivStep = DivStepN<37>;
/// A step for 44-bit divisors (the RC's reciprocal of det with S11.8 coordinates).
pub type DivStep45 = DivStepN<45>;

impl<const R: usize> Default for DivStepN<R> {
    /// The outputs start as the step of the all-zero inputs (0 >= 0: remainder 0, quotient 1), so that
    /// `update` may skip every evaluation whose inputs did not change, the first one included.
    fn default() -> Self {
        let mut s = Self { rem: Default::default(), den: Default::default(), quo: Default::default(), rem_next: Default::default(), quo_next: Default::default() };
        s.quo_next.next = 1u64.into();
        s
    }
}

impl<const R: usize> Logic for DivStepN<R> {
    fn update(&mut self) {
        let mask: u64 = (1 << R) - 1;
        const M25: u64 = (1 << 25) - 1;
        // Inputs unchanged since the last evaluation: the outputs stand (see `Default`).
        if !self.rem.changed && !self.den.changed && !self.quo.changed {
            return;
        }
        let (rem, den, quo) = (self.rem.val().to_u64(), self.den.val().to_u64(), self.quo.val().to_u64());
        let (r, q) = if rem >= den { ((rem - den) << 1, (quo << 1) | 1) } else { (rem << 1, quo << 1) };
        self.rem_next.next = (r & mask).into();
        self.quo_next.next = (q & M25).into();
    }
    fn connect(&mut self) {
        self.rem_next.connect();
        self.quo_next.connect();
    }
    fn hdl(&self) -> Verilog {
        // In an R-bit (25-bit) assignment the subtraction and the shifts are done in 37 (25) bits, so
        // the top bit falls off exactly as in the Rust model's masks.
        Verilog::Custom(
            "always @(*) begin
    if (rem >= den) begin
        rem_next = (rem - den) << 1;
        quo_next = (quo << 1) | 25'd1;
    end else begin
        rem_next = rem << 1;
        quo_next = quo << 1;
    end
end"
            .into(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 25 steps from the normalised start equal the golden divider's quotient (the restoring division
    /// `floor(2^(s+24) / det)`), on values across the 36-bit range.
    #[test]
    fn twenty_five_steps_give_the_floor_of_two_to_the_s_plus_24_over_det() {
        let mut step = DivStep45::default();
        step.connect_all();
        for det in [1u64, 3, 7, 1000, 65535, 123_456_789, (1 << 35) + 12345, (1 << 36) - 1, (1 << 43) + 98765, (1 << 44) - 1] {
            let s = 63 - det.leading_zeros() as u64;
            let (mut rem, mut quo) = (1u64 << s, 0u64);
            for _ in 0..25 {
                step.rem.next = rem.into();
                step.den.next = det.into();
                step.quo.next = quo.into();
                assert!(simulate(&mut step, 10));
                rem = step.rem_next.val().to_u64();
                quo = step.quo_next.val().to_u64();
            }
            assert_eq!(quo as u128, (1u128 << (s + 24)) / det as u128, "det {det}");
        }
    }

    /// A step whose inputs never change from the all-zero start still shows that step's result.
    #[test]
    fn the_all_zero_start_shows_its_own_step() {
        let mut step = DivStep::default();
        step.connect_all();
        assert!(simulate(&mut step, 10));
        assert_eq!((step.rem_next.val().to_u64(), step.quo_next.val().to_u64()), (0, 1));
    }
}
