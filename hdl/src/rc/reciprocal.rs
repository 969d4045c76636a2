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
//! cycles t+1..t+25 (one quotient bit per clock: compare, subtract, shift), and `result.valid` is high
//! from cycle t+26 until the result is taken; the block is `Idle` again the cycle after. So the latency
//! is 26 cycles and, with `result.ready` high, one reciprocal every 27 cycles. `det = 0` is not a valid
//! request (the RC never sends it): it returns `mant = 2^25 - 1`, `shift = 0`.

use crate::common::{StreamIn, StreamOut};
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
/// Cycles from the request's acceptance to `result.valid`.
pub const RECIP_LATENCY: u64 = RECIP_STEPS + 1;

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
    // Priority encoder: smear the top set bit down, isolate it, encode it with six masks.
    smear1: Signal<Local, Bits<36>>,
    smear2: Signal<Local, Bits<36>>,
    smear4: Signal<Local, Bits<36>>,
    smear8: Signal<Local, Bits<36>>,
    smear16: Signal<Local, Bits<36>>,
    smear32: Signal<Local, Bits<36>>,
    onehot: Signal<Local, Bits<36>>,
    enc0: Signal<Local, Bits<6>>,
    enc1: Signal<Local, Bits<6>>,
    enc2: Signal<Local, Bits<6>>,
    enc3: Signal<Local, Bits<6>>,
    enc4: Signal<Local, Bits<6>>,
    enc5: Signal<Local, Bits<6>>,
    // One division step.
    diff: Signal<Local, Bits<37>>,
    quo_shifted: Signal<Local, Bits<25>>,
    take: Signal<Local, Bit>,
    out_valid: Signal<Local, Bit>,
    out_mant: Signal<Local, Bits<25>>,
    out_shift: Signal<Local, Bits<6>>,
    mask0: Constant<Bits<36>>,
    mask1: Constant<Bits<36>>,
    mask2: Constant<Bits<36>>,
    mask3: Constant<Bits<36>>,
    mask4: Constant<Bits<36>>,
    mask5: Constant<Bits<36>>,
    k1_6: Constant<Bits<6>>,
    k2_6: Constant<Bits<6>>,
    k4_6: Constant<Bits<6>>,
    k8_6: Constant<Bits<6>>,
    k16_6: Constant<Bits<6>>,
    k32_6: Constant<Bits<6>>,
    k0_6: Constant<Bits<6>>,
    k1_5: Constant<Bits<5>>,
    k0_5: Constant<Bits<5>>,
    k_last: Constant<Bits<5>>,
    k1_25: Constant<Bits<25>>,
    k0_25: Constant<Bits<25>>,
    k1_1: Constant<Bits<1>>,
}

/// Bit j of the mask is set where bit `bit` of j is set: the encoder's OR-planes.
fn encoder_mask(bit: u32) -> Bits<36> {
    let m: u64 = (0..36u64).filter(|j| j >> bit & 1 == 1).map(|j| 1u64 << j).sum();
    Bits::<36>::from(m)
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
            smear1: Default::default(),
            smear2: Default::default(),
            smear4: Default::default(),
            smear8: Default::default(),
            smear16: Default::default(),
            smear32: Default::default(),
            onehot: Default::default(),
            enc0: Default::default(),
            enc1: Default::default(),
            enc2: Default::default(),
            enc3: Default::default(),
            enc4: Default::default(),
            enc5: Default::default(),
            diff: Default::default(),
            quo_shifted: Default::default(),
            take: Default::default(),
            out_valid: Default::default(),
            out_mant: Default::default(),
            out_shift: Default::default(),
            mask0: Constant::new(encoder_mask(0)),
            mask1: Constant::new(encoder_mask(1)),
            mask2: Constant::new(encoder_mask(2)),
            mask3: Constant::new(encoder_mask(3)),
            mask4: Constant::new(encoder_mask(4)),
            mask5: Constant::new(encoder_mask(5)),
            k1_6: Constant::new(1.into()),
            k2_6: Constant::new(2.into()),
            k4_6: Constant::new(4.into()),
            k8_6: Constant::new(8.into()),
            k16_6: Constant::new(16.into()),
            k32_6: Constant::new(32.into()),
            k0_6: Constant::new(0.into()),
            k1_5: Constant::new(1.into()),
            k0_5: Constant::new(0.into()),
            k_last: Constant::new((RECIP_STEPS - 1).into()),
            k1_25: Constant::new(1.into()),
            k0_25: Constant::new(0.into()),
            k1_1: Constant::new(1.into()),
        }
    }
}

impl Logic for Reciprocal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, state, rem, den, quo, shift, count);
        // Normalisation of the incoming determinant (used when a request is accepted).
        self.smear1.next = self.request.data.val() | (self.request.data.val() >> self.k1_1.val());
        self.smear2.next = self.smear1.val() | (self.smear1.val() >> self.k2_6.val());
        self.smear4.next = self.smear2.val() | (self.smear2.val() >> self.k4_6.val());
        self.smear8.next = self.smear4.val() | (self.smear4.val() >> self.k8_6.val());
        self.smear16.next = self.smear8.val() | (self.smear8.val() >> self.k16_6.val());
        self.smear32.next = self.smear16.val() | (self.smear16.val() >> self.k32_6.val());
        self.onehot.next = self.smear32.val() ^ (self.smear32.val() >> self.k1_1.val());
        self.enc0.next = self.k0_6.val();
        self.enc1.next = self.k0_6.val();
        self.enc2.next = self.k0_6.val();
        self.enc3.next = self.k0_6.val();
        self.enc4.next = self.k0_6.val();
        self.enc5.next = self.k0_6.val();
        if (self.onehot.val() & self.mask0.val()).any() {
            self.enc0.next = self.k1_6.val();
        }
        if (self.onehot.val() & self.mask1.val()).any() {
            self.enc1.next = self.k2_6.val();
        }
        if (self.onehot.val() & self.mask2.val()).any() {
            self.enc2.next = self.k4_6.val();
        }
        if (self.onehot.val() & self.mask3.val()).any() {
            self.enc3.next = self.k8_6.val();
        }
        if (self.onehot.val() & self.mask4.val()).any() {
            self.enc4.next = self.k16_6.val();
        }
        if (self.onehot.val() & self.mask5.val()).any() {
            self.enc5.next = self.k32_6.val();
        }
        // One restoring step.
        self.diff.next = self.rem.q.val() - self.den.q.val();
        self.quo_shifted.next = self.quo.q.val() << self.k1_1.val();

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
                    self.rem.d.next = bit_cast::<37, 36>(self.onehot.val());
                    self.shift.d.next =
                        self.enc0.val() | self.enc1.val() | self.enc2.val() | self.enc3.val() | self.enc4.val() | self.enc5.val();
                    self.quo.d.next = self.k0_25.val();
                    self.count.d.next = self.k0_5.val();
                    self.state.d.next = RecipState::Run;
                }
            }
            RecipState::Run => {
                if self.rem.q.val() >= self.den.q.val() {
                    self.rem.d.next = self.diff.val() << self.k1_1.val();
                    self.quo.d.next = self.quo_shifted.val() | self.k1_25.val();
                } else {
                    self.rem.d.next = self.rem.q.val() << self.k1_1.val();
                    self.quo.d.next = self.quo_shifted.val();
                }
                self.count.d.next = self.count.q.val() + self.k1_5.val();
                if self.count.q.val() == self.k_last.val() {
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
    fn reciprocal_is_floor_of_two_to_the_shift_plus_24_over_det_after_26_cycles() {
        let mut uut = Reciprocal::default();
        uut.connect_all();
        for det in [1u64, 2, 3, 5, 7, 255, 256, 1000, 65535, 65536, 123456789, (1 << 34) - 1, (1 << 35) + 12345, (1 << 36) - 1] {
            let (mant, shift, cycles) = divide(&mut uut, det);
            let s = 63 - det.leading_zeros() as u64;
            let exact = (1u128 << (s + 24)) / det as u128;
            assert_eq!((mant as u128, shift), (exact, s), "det {det}");
            assert_eq!(cycles, RECIP_LATENCY, "det {det}");
        }
    }
}
