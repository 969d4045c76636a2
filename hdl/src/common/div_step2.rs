//! `DivStep2x45`: two steps of the restoring division of `golden::format::reciprocal` in one
//! (combinational), for the RC's pipelined reciprocal (`rc::fast_reciprocal`, issue 15 item 5). The
//! same result as two [`super::DivStep45`] chained whenever the partial remainder is below twice the
//! divisor (the divider's invariant), with one carry chain on the path instead of two.
//!
//! Chained, the second step's compare waits for the first step's subtraction and its select. Here the
//! three subtractions the second step can need are formed side by side from the station's operands,
//! and the two quotient bits only select:
//!
//! ```text
//!  d1 = rem - den          first bit  b1 = (d1 >= 0)
//!  e1 = 2 rem - den        b1 = 0: second bit (e1 >= 0), remainder 2 e1 or 4 rem
//!  e3 = 2 rem - 3 den      b1 = 1: second bit (e3 >= 0), remainder 2 e3 or 4 d1
//! ```
//!
//! (after a first bit of 1 the remainder is 2 d1 = 2 rem - 2 den, and 2 d1 >= den is e3 >= 0). `den3`
//! (3 den) is the divider's constant, formed once per division by the caller. The remainder out is
//! kept to 45 bits as a `DivStep45` keeps it: under the invariant nothing is lost.
//!
//! A leaf written as Verilog, as `DivStepN` is (rust-hdl 0.46 keeps `Bits` over 32 bits as arrays of
//! bools). The Rust model below and the Verilog in `hdl()` are the same function for every input:
//! `tb/tests/logic_products.rs` checks the Verilog against two chained steps under Icarus, the test
//! below the Rust side.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DivStep2x45 {
    /// Partial remainder (< 2 * den) and divisor.
    pub rem: Signal<In, Bits<45>>,
    pub den: Signal<In, Bits<45>>,
    /// 3 * den.
    pub den3: Signal<In, Bits<47>>,
    pub quo: Signal<In, Bits<25>>,
    /// After the two steps.
    pub rem_next: Signal<Out, Bits<45>>,
    pub quo_next: Signal<Out, Bits<25>>,
}

impl Default for DivStep2x45 {
    /// The outputs start as the steps of the all-zero inputs (d1 = e1 = e3 = 0: quotient bits 11,
    /// remainder 0), so that `update` may skip every evaluation whose inputs did not change.
    fn default() -> Self {
        let mut s = Self {
            rem: Default::default(),
            den: Default::default(),
            den3: Default::default(),
            quo: Default::default(),
            rem_next: Default::default(),
            quo_next: Default::default(),
        };
        s.quo_next.next = 3u64.into();
        s
    }
}

/// The function of [`DivStep2x45`] on integers: (remainder, quotient) after the two steps.
pub fn div_step2(rem: u64, den: u64, den3: u64, quo: u64) -> (u64, u64) {
    const M45: u64 = (1 << 45) - 1;
    const M25: u64 = (1 << 25) - 1;
    let (rem, den, den3) = (rem as i64, den as i64, den3 as i64);
    let d1 = rem - den;
    let e1 = 2 * rem - den;
    let e3 = 2 * rem - den3;
    let (r, bits) = match (d1 >= 0, if d1 >= 0 { e3 >= 0 } else { e1 >= 0 }) {
        (true, true) => (2 * e3, 3),
        (true, false) => (4 * d1, 2),
        (false, true) => (2 * e1, 1),
        (false, false) => (4 * rem, 0),
    };
    ((r as u64) & M45, ((quo << 2) | bits) & M25)
}

impl Logic for DivStep2x45 {
    fn update(&mut self) {
        if !self.rem.changed && !self.den.changed && !self.den3.changed && !self.quo.changed {
            return;
        }
        let (r, q) = div_step2(self.rem.val().to_u64(), self.den.val().to_u64(), self.den3.val().to_u64(), self.quo.val().to_u64());
        self.rem_next.next = r.into();
        self.quo_next.next = q.into();
    }
    fn connect(&mut self) {
        self.rem_next.connect();
        self.quo_next.connect();
    }
    fn hdl(&self) -> Verilog {
        // 48-bit differences: |d1| < 2^45, -2^45 < e1 < 2^46, -2^47 <= e3 < 2^46, so bit 47 is the
        // sign of each, as the Rust model's i64 compares.
        Verilog::Custom(
            "wire [47:0] d1 = {3'b0, rem} - {3'b0, den};
wire [47:0] e1 = {2'b0, rem, 1'b0} - {3'b0, den};
wire [47:0] e3 = {2'b0, rem, 1'b0} - {1'b0, den3};
always @(*) begin
    if (!d1[47]) begin
        if (!e3[47]) begin
            rem_next = {e3[43:0], 1'b0};
            quo_next = {quo[22:0], 2'b11};
        end else begin
            rem_next = {d1[42:0], 2'b00};
            quo_next = {quo[22:0], 2'b10};
        end
    end else begin
        if (!e1[47]) begin
            rem_next = {e1[43:0], 1'b0};
            quo_next = {quo[22:0], 2'b01};
        end else begin
            rem_next = {rem[42:0], 2'b00};
            quo_next = {quo[22:0], 2'b00};
        end
    end
end"
            .into(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One `DivStep45` step on integers, as its model computes it.
    fn step(rem: u64, den: u64, quo: u64) -> (u64, u64) {
        let (r, q) = if rem >= den { ((rem - den) << 1, (quo << 1) | 1) } else { (rem << 1, quo << 1) };
        (r & ((1 << 45) - 1), q & ((1 << 25) - 1))
    }

    #[test]
    fn two_steps_in_one_equal_two_chained_steps_below_twice_the_divisor() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        // The start `Default` gives is the all-zero inputs' steps.
        assert_eq!(div_step2(0, 0, 0, 0), (0, 3));
        let mut u = DivStep2x45::default();
        assert_eq!((u.rem_next.next.to_u64(), u.quo_next.next.to_u64()), (0, 3));
        u.connect_all();
        for k in 0..20_000 {
            // Divisors of every width up to 44 bits, remainders in [0, 2 den).
            let den = ((next() >> (20 + k % 44)) & ((1 << 44) - 1)).max(1);
            let rem = match k % 4 {
                0 => next() % (2 * den),
                1 => den - 1,
                2 => 2 * den - 1,
                _ => den,
            };
            let quo = next() & ((1 << 25) - 1);
            let (r1, q1) = step(rem, den, quo);
            let want = step(r1, den, q1);
            assert_eq!(div_step2(rem, den, 3 * den, quo), want, "rem {rem} den {den}");
            if k % 97 == 0 {
                u.rem.next = rem.into();
                u.den.next = den.into();
                u.den3.next = (3 * den).into();
                u.quo.next = quo.into();
                assert!(simulate(&mut u, 100));
                assert_eq!((u.rem_next.val().to_u64(), u.quo_next.val().to_u64()), want, "block: rem {rem} den {den}");
            }
        }
    }
}
