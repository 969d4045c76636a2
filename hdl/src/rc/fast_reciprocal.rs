//! `fast_reciprocal`: the RC's reciprocal of |det|, the same quotient as [`super::reciprocal`] and
//! `golden::format::reciprocal` (`mant = floor(2^(shift+24) / det)`, `shift = floor(log2 det)`), with two
//! restoring steps per station instead of three, for the clock (issue 15 item 5).
//!
//! ```text
//!                 +------------------------------------------------------+
//!  request.data ->| st0: normalise (leading one -> shift) and step 1     |
//!  request.valid->| st1..st12: two restoring steps each (steps 2..25)    |-> result.valid
//!  request.ready<-| (thirteen stations, one global enable)               |-> result.data {mant, shift}
//!  clock -------->|                                                      |<- result.ready
//!                 +------------------------------------------------------+
//! ```
//!
//! Step 1 costs no subtraction: the partial remainder starts at 2^shift and det lies in
//! [2^shift, 2^(shift+1)), so the first quotient bit is 1 exactly when det is 2^shift, and the remainder
//! after it is 0 then, else 2^(shift+1). Station 0 takes that from the leading one's one-hot word with an
//! equality, so the 25 steps fit in thirteen stations of at most two subtractions.
//!
//! Each station's two steps are one [`DivStep2x45`]: its three subtractions (rem - den, 2 rem - den,
//! 2 rem - 3 den) side by side and the two quotient bits selecting, so one carry chain per station
//! instead of two in series (two chained steps were the `rc` top's critical path, issue 15 item 5).
//! 3 den is formed with station 0 and travels with the division (`den3`).
//!
//! Timing, as [`super::reciprocal`]: the pipeline advances when its last station is empty or its result
//! is taken, and `request.ready` is that enable; a request accepted in cycle t gives its result in cycle
//! t+13 ([`FAST_RECIP_LATENCY`], `golden::cycle::rc::RECIP_LATENCY`) with no stall, one result per clock
//! behind it, in request order. `det = 0` is not a valid request (it returns `mant = 2^25 - 1`,
//! `shift = 0`, as the three-step unit does).
//!
//! The texture units (`cs::tex_setup`, `cs::tex_coord`) keep the ten-station [`super::reciprocal`]:
//! their cycle models are built on its latency, and they are not in the `rc` or `chipset` tops.

use super::reciprocal::{RecipResult, RecipStation};
use crate::common::{DivStep2x45, LeadingOne44, StreamIn, StreamOut};
use rust_hdl::prelude::*;

/// Stations: normalisation with step 1, then twelve of two steps.
pub const FAST_RECIP_STATIONS: u64 = 13;
/// Cycles from a request's acceptance to its result, with no stall.
pub const FAST_RECIP_LATENCY: u64 = FAST_RECIP_STATIONS;

#[derive(LogicBlock)]
pub struct FastReciprocal {
    pub clock: Signal<In, Clock>,
    // From the requester
    /// The positive determinant, 44 bits unsigned.
    pub request: StreamIn<Bits<44>>,
    // To the requester
    /// The reciprocal, held until taken.
    pub result: StreamOut<RecipResult>,
    /// The mantissa `result` holds from the next cycle on (the result station's input): lets the
    /// setup keep a copy of the result in its own operand register (issue 15 item 5).
    pub next_mant: Signal<Out, Bits<25>>,

    /// Normalisation of the request: the divisor's leading one and its index.
    lead: LeadingOne44,
    /// The stations; `st[k]` holds a division after steps 1..=2k+1.
    st: [DFF<RecipStation>; 13],
    /// 3 * den of the division in station k (`den3[k]`, stations 0..=11), formed once with station 0.
    den3: [DFF<Bits<47>>; 12],
    /// `step[k]` takes station k to station k+1 (two steps).
    step: [DivStep2x45; 12],
    advance: Signal<Local, Bit>,
    norm: Signal<Local, RecipStation>,
    /// The request is a power of two (step 1's quotient bit).
    pow2: Signal<Local, Bit>,
    onehot45: Signal<Local, Bits<45>>,
    den47: Signal<Local, Bits<47>>,
    den47x2: Signal<Local, Bits<47>>,
    den3_in: Signal<Local, Bits<47>>,
    k0_25: Constant<Bits<25>>,
    k1_25: Constant<Bits<25>>,
    k0_45: Constant<Bits<45>>,
    k1_6: Constant<Bits<6>>,
}

impl Default for FastReciprocal {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            request: Default::default(),
            result: Default::default(),
            next_mant: Default::default(),
            lead: Default::default(),
            st: Default::default(),
            den3: Default::default(),
            step: Default::default(),
            advance: Default::default(),
            norm: Default::default(),
            pow2: Default::default(),
            onehot45: Default::default(),
            den47: Default::default(),
            den47x2: Default::default(),
            den3_in: Default::default(),
            k0_25: Constant::new(0.into()),
            k1_25: Constant::new(1.into()),
            k0_45: Constant::new(0.into()),
            k1_6: Constant::new(1.into()),
        }
    }
}

impl Logic for FastReciprocal {
    #[hdl_gen]
    fn update(&mut self) {
        self.st[0].clock.next = self.clock.val();
        self.st[0].d.next = self.st[0].q.val();
        self.st[1].clock.next = self.clock.val();
        self.st[1].d.next = self.st[1].q.val();
        self.st[2].clock.next = self.clock.val();
        self.st[2].d.next = self.st[2].q.val();
        self.st[3].clock.next = self.clock.val();
        self.st[3].d.next = self.st[3].q.val();
        self.st[4].clock.next = self.clock.val();
        self.st[4].d.next = self.st[4].q.val();
        self.st[5].clock.next = self.clock.val();
        self.st[5].d.next = self.st[5].q.val();
        self.st[6].clock.next = self.clock.val();
        self.st[6].d.next = self.st[6].q.val();
        self.st[7].clock.next = self.clock.val();
        self.st[7].d.next = self.st[7].q.val();
        self.st[8].clock.next = self.clock.val();
        self.st[8].d.next = self.st[8].q.val();
        self.st[9].clock.next = self.clock.val();
        self.st[9].d.next = self.st[9].q.val();
        self.st[10].clock.next = self.clock.val();
        self.st[10].d.next = self.st[10].q.val();
        self.st[11].clock.next = self.clock.val();
        self.st[11].d.next = self.st[11].q.val();
        self.st[12].clock.next = self.clock.val();
        self.st[12].d.next = self.st[12].q.val();
        for k in 0..12 {
            self.den3[k].clock.next = self.clock.val();
            self.den3[k].d.next = self.den3[k].q.val();
        }
        self.advance.next = !self.st[12].q.val().valid | self.result.ready.val();
        // Station 0's input: the request, normalised, after step 1.
        self.lead.x.next = self.request.data.val();
        self.pow2.next = self.lead.onehot.val() == self.request.data.val();
        self.onehot45.next = bit_cast::<45, 44>(self.lead.onehot.val());
        self.norm.next.valid = self.request.valid.val();
        self.norm.next.den = bit_cast::<45, 44>(self.request.data.val());
        self.norm.next.shift = self.lead.index.val();
        // Twice the leading one: a shift, no carry chain.
        self.norm.next.rem = self.onehot45.val() << self.k1_6.val();
        self.norm.next.quo = self.k0_25.val();
        // 3 den for the stations' two-step leaves, beside the normalisation.
        self.den47.next = bit_cast::<47, 44>(self.request.data.val());
        self.den47x2.next = self.den47.val() << self.k1_6.val();
        self.den3_in.next = self.den47.val() + self.den47x2.val();
        if self.pow2.val() {
            self.norm.next.rem = self.k0_45.val();
            self.norm.next.quo = self.k1_25.val();
        }
        self.step[0].rem.next = self.st[0].q.val().rem;
        self.step[0].quo.next = self.st[0].q.val().quo;
        self.step[0].den.next = self.st[0].q.val().den;
        self.step[0].den3.next = self.den3[0].q.val();
        self.step[1].rem.next = self.st[1].q.val().rem;
        self.step[1].quo.next = self.st[1].q.val().quo;
        self.step[1].den.next = self.st[1].q.val().den;
        self.step[1].den3.next = self.den3[1].q.val();
        self.step[2].rem.next = self.st[2].q.val().rem;
        self.step[2].quo.next = self.st[2].q.val().quo;
        self.step[2].den.next = self.st[2].q.val().den;
        self.step[2].den3.next = self.den3[2].q.val();
        self.step[3].rem.next = self.st[3].q.val().rem;
        self.step[3].quo.next = self.st[3].q.val().quo;
        self.step[3].den.next = self.st[3].q.val().den;
        self.step[3].den3.next = self.den3[3].q.val();
        self.step[4].rem.next = self.st[4].q.val().rem;
        self.step[4].quo.next = self.st[4].q.val().quo;
        self.step[4].den.next = self.st[4].q.val().den;
        self.step[4].den3.next = self.den3[4].q.val();
        self.step[5].rem.next = self.st[5].q.val().rem;
        self.step[5].quo.next = self.st[5].q.val().quo;
        self.step[5].den.next = self.st[5].q.val().den;
        self.step[5].den3.next = self.den3[5].q.val();
        self.step[6].rem.next = self.st[6].q.val().rem;
        self.step[6].quo.next = self.st[6].q.val().quo;
        self.step[6].den.next = self.st[6].q.val().den;
        self.step[6].den3.next = self.den3[6].q.val();
        self.step[7].rem.next = self.st[7].q.val().rem;
        self.step[7].quo.next = self.st[7].q.val().quo;
        self.step[7].den.next = self.st[7].q.val().den;
        self.step[7].den3.next = self.den3[7].q.val();
        self.step[8].rem.next = self.st[8].q.val().rem;
        self.step[8].quo.next = self.st[8].q.val().quo;
        self.step[8].den.next = self.st[8].q.val().den;
        self.step[8].den3.next = self.den3[8].q.val();
        self.step[9].rem.next = self.st[9].q.val().rem;
        self.step[9].quo.next = self.st[9].q.val().quo;
        self.step[9].den.next = self.st[9].q.val().den;
        self.step[9].den3.next = self.den3[9].q.val();
        self.step[10].rem.next = self.st[10].q.val().rem;
        self.step[10].quo.next = self.st[10].q.val().quo;
        self.step[10].den.next = self.st[10].q.val().den;
        self.step[10].den3.next = self.den3[10].q.val();
        self.step[11].rem.next = self.st[11].q.val().rem;
        self.step[11].quo.next = self.st[11].q.val().quo;
        self.step[11].den.next = self.st[11].q.val().den;
        self.step[11].den3.next = self.den3[11].q.val();
        if self.advance.val() {
            self.st[0].d.next = self.norm.val();
            self.den3[0].d.next = self.den3_in.val();
            self.den3[1].d.next = self.den3[0].q.val();
            self.den3[2].d.next = self.den3[1].q.val();
            self.den3[3].d.next = self.den3[2].q.val();
            self.den3[4].d.next = self.den3[3].q.val();
            self.den3[5].d.next = self.den3[4].q.val();
            self.den3[6].d.next = self.den3[5].q.val();
            self.den3[7].d.next = self.den3[6].q.val();
            self.den3[8].d.next = self.den3[7].q.val();
            self.den3[9].d.next = self.den3[8].q.val();
            self.den3[10].d.next = self.den3[9].q.val();
            self.den3[11].d.next = self.den3[10].q.val();
            self.st[1].d.next = self.st[0].q.val();
            self.st[1].d.next.rem = self.step[0].rem_next.val();
            self.st[1].d.next.quo = self.step[0].quo_next.val();
            self.st[2].d.next = self.st[1].q.val();
            self.st[2].d.next.rem = self.step[1].rem_next.val();
            self.st[2].d.next.quo = self.step[1].quo_next.val();
            self.st[3].d.next = self.st[2].q.val();
            self.st[3].d.next.rem = self.step[2].rem_next.val();
            self.st[3].d.next.quo = self.step[2].quo_next.val();
            self.st[4].d.next = self.st[3].q.val();
            self.st[4].d.next.rem = self.step[3].rem_next.val();
            self.st[4].d.next.quo = self.step[3].quo_next.val();
            self.st[5].d.next = self.st[4].q.val();
            self.st[5].d.next.rem = self.step[4].rem_next.val();
            self.st[5].d.next.quo = self.step[4].quo_next.val();
            self.st[6].d.next = self.st[5].q.val();
            self.st[6].d.next.rem = self.step[5].rem_next.val();
            self.st[6].d.next.quo = self.step[5].quo_next.val();
            self.st[7].d.next = self.st[6].q.val();
            self.st[7].d.next.rem = self.step[6].rem_next.val();
            self.st[7].d.next.quo = self.step[6].quo_next.val();
            self.st[8].d.next = self.st[7].q.val();
            self.st[8].d.next.rem = self.step[7].rem_next.val();
            self.st[8].d.next.quo = self.step[7].quo_next.val();
            self.st[9].d.next = self.st[8].q.val();
            self.st[9].d.next.rem = self.step[8].rem_next.val();
            self.st[9].d.next.quo = self.step[8].quo_next.val();
            self.st[10].d.next = self.st[9].q.val();
            self.st[10].d.next.rem = self.step[9].rem_next.val();
            self.st[10].d.next.quo = self.step[9].quo_next.val();
            self.st[11].d.next = self.st[10].q.val();
            self.st[11].d.next.rem = self.step[10].rem_next.val();
            self.st[11].d.next.quo = self.step[10].quo_next.val();
            self.st[12].d.next = self.st[11].q.val();
            self.st[12].d.next.rem = self.step[11].rem_next.val();
            self.st[12].d.next.quo = self.step[11].quo_next.val();
        }
        self.request.ready.next = self.advance.val();
        self.result.valid.next = self.st[12].q.val().valid;
        self.result.data.next.mant = self.st[12].q.val().quo;
        self.result.data.next.shift = self.st[12].q.val().shift;
        self.next_mant.next = self.st[12].q.val().quo;
        if self.advance.val() {
            self.next_mant.next = self.step[11].quo_next.val();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::reciprocal::tests::{exact, run, RecipPorts};
    use super::*;

    impl RecipPorts for FastReciprocal {
        fn ports(&mut self) -> (&mut Signal<In, Clock>, &mut StreamIn<Bits<44>>, &mut StreamOut<RecipResult>) {
            (&mut self.clock, &mut self.request, &mut self.result)
        }
    }

    #[test]
    fn reciprocal_is_floor_of_two_to_the_shift_plus_24_over_det_after_13_cycles() {
        assert_eq!(FAST_RECIP_LATENCY, 13, "the figure in the test's name");
        // Powers of two (step 1's quotient bit set), their neighbours and the widest divisors.
        for det in [1u64, 2, 3, 4, 5, 7, 8, 255, 256, 257, 1000, 65535, 65536, 123456789, (1 << 34) - 1, (1 << 35) + 12345, (1 << 36) - 1, 1 << 43, (1 << 43) + 4321, (1 << 44) - 1] {
            let r = run::<FastReciprocal>(&[det], |_| true);
            assert_eq!((r[0].0, r[0].1), exact(det), "det {det}");
            assert_eq!(r[0].2, FAST_RECIP_LATENCY, "det {det}");
        }
    }

    #[test]
    fn back_to_back_requests_give_one_result_per_clock_in_request_order() {
        let dets: Vec<u64> = (0..40u64).map(|k| 1 + k * 0x1234567 % ((1 << 44) - 1)).chain((0..44).map(|s| 1u64 << s)).collect();
        let r = run::<FastReciprocal>(&dets, |_| true);
        for (k, (&det, &(mant, shift, cycle))) in dets.iter().zip(&r).enumerate() {
            assert_eq!((mant, shift), exact(det), "request {k}");
            assert_eq!(cycle, FAST_RECIP_LATENCY + k as u64, "request {k}");
        }
    }

    #[test]
    fn a_stalled_result_holds_the_pipeline_and_loses_nothing() {
        let dets: Vec<u64> = (0..30u64).map(|k| 3 + k * 0x9e3779b9 % ((1 << 44) - 3)).collect();
        // Taken on two clocks of every five only.
        let r = run::<FastReciprocal>(&dets, |c| c % 5 == 1 || c % 5 == 3);
        let got: Vec<(u64, u64)> = r.iter().map(|&(m, s, _)| (m, s)).collect();
        let want: Vec<(u64, u64)> = dets.iter().map(|&d| exact(d)).collect();
        assert_eq!(got, want);
    }
}
