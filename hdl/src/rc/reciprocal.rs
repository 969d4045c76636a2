//! `reciprocal`: one reciprocal per triangle (seed 001 eq. 6, Ka = 1/det), as the 25-step restoring
//! division of `golden::format::reciprocal`: `mant = floor(2^(shift+24) / det)`, `shift = floor(log2 det)`,
//! so `1/det = mant * 2^-(shift+24)` with `mant` in [2^23, 2^24].
//!
//! ```text
//!                 +--------------------+
//!  request.data ->| det (36 b, > 0)    |
//!  request.valid->|                    |-> result.valid
//!  request.ready<-|  25-step restoring |-> result.data {mant: 25 b, shift: 6 b}
//!                 |  divider           |<- result.ready
//!  clock -------->|                    |
//!                 +--------------------+
//! ```
//!
//! Timing: `request.ready` is high in `Idle`. A request accepted in cycle t is normalised in that cycle
//! (a priority encoder finds `shift`, the partial remainder starts at `2^shift`), the 25 steps run in
//! cycles t+1..t+9, three per clock (three [`DivStep`]s in a chain: compare, subtract, shift, three
//! quotient bits; the ninth clock takes the first step's result only, 25 = 8*3 + 1), and `result.valid`
//! is high from cycle t+10 until the result is taken; the block is `Idle` again the cycle after. So the
//! latency is 10 cycles ([`RECIP_LATENCY`]; 26 with one step per clock) and, with `result.ready` high,
//! one reciprocal every 11 cycles. `det = 0` is not a valid
//! request (the RC never sends it): it returns `mant = 2^25 - 1`, `shift = 0`.

use crate::common::{StreamIn, StreamOut};
use crate::common::{DivStep, LeadingOne36};
use rust_hdl::prelude::*;

/// The divider's answer: `1/det = mant * 2^-(shift + 24)`.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RecipResult {
    pub mant: Bits<25>,
    pub shift: Bits<6>,
}

#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum RecipState {
    Idle,
    Run,
    Done,
}

/// Steps of the division: RECIP_BITS + 1 (one quotient bit each).
pub const RECIP_STEPS: u64 = 25;
/// Steps per clock (chained `DivStep`s).
pub const RECIP_STEPS_PER_CLOCK: u64 = 3;
/// Clocks of steps: ceil(RECIP_STEPS / RECIP_STEPS_PER_CLOCK).
pub const RECIP_CLOCKS: u64 = RECIP_STEPS.div_ceil(RECIP_STEPS_PER_CLOCK);
/// Cycles from the request's acceptance to `result.valid`.
pub const RECIP_LATENCY: u64 = RECIP_CLOCKS + 1;

#[derive(LogicBlock)]
pub struct Reciprocal {
    pub clock: Signal<In, Clock>,
    // From the requester
    /// The positive determinant, 36 bits unsigned.
    pub request: StreamIn<Bits<36>>,
    // To the requester
    /// The reciprocal, held until taken.
    pub result: StreamOut<RecipResult>,

    state: DFF<RecipState>,
    /// Partial remainder, always < 2 * den.
    rem: DFF<Bits<37>>,
    den: DFF<Bits<37>>,
    quo: DFF<Bits<25>>,
    shift: DFF<Bits<6>>,
    count: DFF<Bits<5>>,
    /// Normalisation: the divisor's leading one (where the partial remainder starts) and its index.
    lead: LeadingOne36,
    /// Three division steps in a chain (one clock).
    step: DivStep,
    step2: DivStep,
    step3: DivStep,
    take: Signal<Local, Bit>,
    out_valid: Signal<Local, Bit>,
    out_mant: Signal<Local, Bits<25>>,
    out_shift: Signal<Local, Bits<6>>,
    k0_6: Constant<Bits<6>>,
    k1_5: Constant<Bits<5>>,
    k0_5: Constant<Bits<5>>,
    k_last: Constant<Bits<5>>,
    k0_25: Constant<Bits<25>>,
}

impl Default for Reciprocal {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            request: Default::default(),
            result: Default::default(),
            state: Default::default(),
            rem: Default::default(),
            den: Default::default(),
            quo: Default::default(),
            shift: Default::default(),
            count: Default::default(),
            lead: Default::default(),
            step: Default::default(),
            step2: Default::default(),
            step3: Default::default(),
            take: Default::default(),
            out_valid: Default::default(),
            out_mant: Default::default(),
            out_shift: Default::default(),
            k0_6: Constant::new(0.into()),
            k1_5: Constant::new(1.into()),
            k0_5: Constant::new(0.into()),
            k_last: Constant::new((RECIP_CLOCKS - 1).into()),
            k0_25: Constant::new(0.into()),
        }
    }
}

impl Logic for Reciprocal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, state, rem, den, quo, shift, count);
        // Normalisation of the incoming determinant (used when a request is accepted), and one step.
        self.lead.x.next = self.request.data.val();
        self.step.rem.next = self.rem.q.val();
        self.step.den.next = self.den.q.val();
        self.step.quo.next = self.quo.q.val();
        self.step2.rem.next = self.step.rem_next.val();
        self.step2.den.next = self.den.q.val();
        self.step2.quo.next = self.step.quo_next.val();
        self.step3.rem.next = self.step2.rem_next.val();
        self.step3.den.next = self.den.q.val();
        self.step3.quo.next = self.step2.quo_next.val();

        // Ports are driven once, after the state machine, from locals: a default-then-override write
        // to a port would wake the parent's logic twice in an event-driven simulator (Icarus), and a
        // parent doing the same to our inputs would never let the two settle.
        self.take.next = false;
        self.out_valid.next = false;
        self.out_mant.next = self.k0_25.val();
        self.out_shift.next = self.k0_6.val();
        match self.state.q.val() {
            RecipState::Idle => {
                self.take.next = true;
                if self.request.valid.val() {
                    self.den.d.next = bit_cast::<37, 36>(self.request.data.val());
                    self.rem.d.next = bit_cast::<37, 36>(self.lead.onehot.val());
                    self.shift.d.next = self.lead.index.val();
                    self.quo.d.next = self.k0_25.val();
                    self.count.d.next = self.k0_5.val();
                    self.state.d.next = RecipState::Run;
                }
            }
            RecipState::Run => {
                self.rem.d.next = self.step3.rem_next.val();
                self.quo.d.next = self.step3.quo_next.val();
                self.count.d.next = self.count.q.val() + self.k1_5.val();
                if self.count.q.val() == self.k_last.val() {
                    // The 25th step: the first of the chain only.
                    self.rem.d.next = self.step.rem_next.val();
                    self.quo.d.next = self.step.quo_next.val();
                    self.state.d.next = RecipState::Done;
                }
            }
            RecipState::Done => {
                self.out_valid.next = true;
                self.out_mant.next = self.quo.q.val();
                self.out_shift.next = self.shift.q.val();
                if self.result.ready.val() {
                    self.state.d.next = RecipState::Idle;
                }
            }
            _ => {
                self.state.d.next = RecipState::Idle;
            }
        }
        self.request.ready.next = self.take.val();
        self.result.valid.next = self.out_valid.val();
        self.result.data.next.mant = self.out_mant.val();
        self.result.data.next.shift = self.out_shift.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Drive one request through the block (direct drive); returns (mant, shift, cycles to result).
    fn divide(uut: &mut Reciprocal, det: u64) -> (u64, u64, u64) {
        uut.request.data.next = det.into();
        uut.request.valid.next = true;
        uut.result.ready.next = true;
        for cycle in 0..40u64 {
            uut.clock.next = false.into();
            assert!(simulate(uut, 100));
            if uut.result.valid.val() {
                let r = uut.result.data.val();
                uut.clock.next = true.into();
                assert!(simulate(uut, 100));
                return (r.mant.to_u64(), r.shift.to_u64(), cycle);
            }
            let accepted = uut.request.ready.val();
            uut.clock.next = true.into();
            assert!(simulate(uut, 100));
            if accepted {
                uut.request.valid.next = false;
            }
        }
        panic!("no result for det {det}");
    }

    #[test]
    fn reciprocal_is_floor_of_two_to_the_shift_plus_24_over_det_after_10_cycles() {
        let mut uut = Reciprocal::default();
        uut.connect_all();
        for det in [1u64, 2, 3, 5, 7, 255, 256, 1000, 65535, 65536, 123456789, (1 << 34) - 1, (1 << 35) + 12345, (1 << 36) - 1] {
            let (mant, shift, cycles) = divide(&mut uut, det);
            let s = 63 - det.leading_zeros() as u64;
            let exact = (1u128 << (s + 24)) / det as u128;
            assert_eq!((mant as u128, shift), (exact, s), "det {det}");
            assert_eq!(cycles, 10, "det {det}");
            assert_eq!(cycles, RECIP_LATENCY);
        }
    }
}
