//! `reciprocal`: one reciprocal per triangle (seed 001 eq. 6, Ka = 1/det), as the 25-step restoring
//! division of `golden::format::reciprocal`: `mant = floor(2^(shift+24) / det)`, `shift = floor(log2 det)`,
//! so `1/det = mant * 2^-(shift+24)` with `mant` in [2^23, 2^24]. Pipelined: one request per clock.
//! Since issue 15 item 5 the RC's setup uses [`super::fast_reciprocal`] (13 stations of two steps);
//! this ten-station unit serves the texture units, whose cycle models are built on its latency.
//!
//! ```text
//!                 +---------------------------------------------+
//!  request.data ->| st0: normalise (leading one -> rem, shift)  |
//!  request.valid->| st1..st8: three restoring steps each        |-> result.valid
//!  request.ready<-| st9: the 25th step                          |-> result.data {mant: 25 b, shift: 6 b}
//!  clock -------->| (ten stations, one global enable)           |<- result.ready
//!                 +---------------------------------------------+
//! ```
//!
//! Timing: the pipeline advances (every station takes its predecessor's contents, station 0 the
//! request) in each cycle where its last station is empty or its result is taken (`result.ready`), and
//! `request.ready` is that enable. A request accepted in cycle t is normalised in that cycle (a priority
//! encoder finds `shift`; the partial remainder starts at `2^shift`) into station 0, and with no stall
//! its result is valid in cycle t+10 ([`RECIP_LATENCY`]), one result per clock behind it. Results leave
//! in the order of their requests. The quotient is exact (the floor of the true quotient): the error
//! bound is below one unit in the last place, `0 <= 1/det - mant*2^-(shift+24) < 2^-(shift+24)`,
//! the golden model's `format::reciprocal` is checked against that over its input range and this block
//! against the golden model. `det = 0` is not a valid request (the RC never sends it): it returns
//! `mant = 2^25 - 1`, `shift = 0`.

use crate::common::{StreamIn, StreamOut};
use crate::common::{DivStep45 as DivStep, LeadingOne44};
use rust_hdl::prelude::*;

/// The divider's answer: `1/det = mant * 2^-(shift + 24)`.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RecipResult {
    pub mant: Bits<25>,
    pub shift: Bits<6>,
}

/// One station of the pipeline: a division in progress.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RecipStation {
    pub valid: Bit,
    /// Partial remainder, always < 2 * den.
    pub rem: Bits<45>,
    pub den: Bits<45>,
    pub quo: Bits<25>,
    pub shift: Bits<6>,
}

/// Steps of the division: RECIP_BITS + 1 (one quotient bit each).
pub const RECIP_STEPS: u64 = 25;
/// Stations: the normalisation, eight of three steps, one of the last step.
pub const RECIP_STATIONS: u64 = 10;
/// Cycles from a request's acceptance to its result, with no stall.
pub const RECIP_LATENCY: u64 = RECIP_STATIONS;

#[derive(LogicBlock)]
pub struct Reciprocal {
    pub clock: Signal<In, Clock>,
    // From the requester
    /// The positive determinant, 44 bits unsigned.
    pub request: StreamIn<Bits<44>>,
    // To the requester
    /// The reciprocal, held until taken.
    pub result: StreamOut<RecipResult>,

    /// Normalisation of the request: the divisor's leading one and its index.
    lead: LeadingOne44,
    st0: DFF<RecipStation>,
    st1: DFF<RecipStation>,
    st2: DFF<RecipStation>,
    st3: DFF<RecipStation>,
    st4: DFF<RecipStation>,
    st5: DFF<RecipStation>,
    st6: DFF<RecipStation>,
    st7: DFF<RecipStation>,
    st8: DFF<RecipStation>,
    st9: DFF<RecipStation>,
    d1_0: DivStep,
    d1_1: DivStep,
    d1_2: DivStep,
    d2_0: DivStep,
    d2_1: DivStep,
    d2_2: DivStep,
    d3_0: DivStep,
    d3_1: DivStep,
    d3_2: DivStep,
    d4_0: DivStep,
    d4_1: DivStep,
    d4_2: DivStep,
    d5_0: DivStep,
    d5_1: DivStep,
    d5_2: DivStep,
    d6_0: DivStep,
    d6_1: DivStep,
    d6_2: DivStep,
    d7_0: DivStep,
    d7_1: DivStep,
    d7_2: DivStep,
    d8_0: DivStep,
    d8_1: DivStep,
    d8_2: DivStep,
    d9_0: DivStep,
    advance: Signal<Local, Bit>,
    norm: Signal<Local, RecipStation>,
    k0_25: Constant<Bits<25>>,
}

impl Default for Reciprocal {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            request: Default::default(),
            result: Default::default(),
            lead: Default::default(),
            st0: Default::default(),
            st1: Default::default(),
            st2: Default::default(),
            st3: Default::default(),
            st4: Default::default(),
            st5: Default::default(),
            st6: Default::default(),
            st7: Default::default(),
            st8: Default::default(),
            st9: Default::default(),
            d1_0: Default::default(),
            d1_1: Default::default(),
            d1_2: Default::default(),
            d2_0: Default::default(),
            d2_1: Default::default(),
            d2_2: Default::default(),
            d3_0: Default::default(),
            d3_1: Default::default(),
            d3_2: Default::default(),
            d4_0: Default::default(),
            d4_1: Default::default(),
            d4_2: Default::default(),
            d5_0: Default::default(),
            d5_1: Default::default(),
            d5_2: Default::default(),
            d6_0: Default::default(),
            d6_1: Default::default(),
            d6_2: Default::default(),
            d7_0: Default::default(),
            d7_1: Default::default(),
            d7_2: Default::default(),
            d8_0: Default::default(),
            d8_1: Default::default(),
            d8_2: Default::default(),
            d9_0: Default::default(),
            advance: Default::default(),
            norm: Default::default(),
            k0_25: Constant::new(0.into()),
        }
    }
}

impl Logic for Reciprocal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, st0, st1, st2, st3, st4, st5, st6, st7, st8, st9);
        self.advance.next = !self.st9.q.val().valid | self.result.ready.val();
        // Station 0's input: the request, normalised.
        self.lead.x.next = self.request.data.val();
        self.norm.next.valid = self.request.valid.val();
        self.norm.next.den = bit_cast::<45, 44>(self.request.data.val());
        self.norm.next.rem = bit_cast::<45, 44>(self.lead.onehot.val());
        self.norm.next.quo = self.k0_25.val();
        self.norm.next.shift = self.lead.index.val();
        self.d1_0.rem.next = self.st0.q.val().rem;
        self.d1_0.quo.next = self.st0.q.val().quo;
        self.d1_0.den.next = self.st0.q.val().den;
        self.d1_1.rem.next = self.d1_0.rem_next.val();
        self.d1_1.quo.next = self.d1_0.quo_next.val();
        self.d1_1.den.next = self.st0.q.val().den;
        self.d1_2.rem.next = self.d1_1.rem_next.val();
        self.d1_2.quo.next = self.d1_1.quo_next.val();
        self.d1_2.den.next = self.st0.q.val().den;
        self.d2_0.rem.next = self.st1.q.val().rem;
        self.d2_0.quo.next = self.st1.q.val().quo;
        self.d2_0.den.next = self.st1.q.val().den;
        self.d2_1.rem.next = self.d2_0.rem_next.val();
        self.d2_1.quo.next = self.d2_0.quo_next.val();
        self.d2_1.den.next = self.st1.q.val().den;
        self.d2_2.rem.next = self.d2_1.rem_next.val();
        self.d2_2.quo.next = self.d2_1.quo_next.val();
        self.d2_2.den.next = self.st1.q.val().den;
        self.d3_0.rem.next = self.st2.q.val().rem;
        self.d3_0.quo.next = self.st2.q.val().quo;
        self.d3_0.den.next = self.st2.q.val().den;
        self.d3_1.rem.next = self.d3_0.rem_next.val();
        self.d3_1.quo.next = self.d3_0.quo_next.val();
        self.d3_1.den.next = self.st2.q.val().den;
        self.d3_2.rem.next = self.d3_1.rem_next.val();
        self.d3_2.quo.next = self.d3_1.quo_next.val();
        self.d3_2.den.next = self.st2.q.val().den;
        self.d4_0.rem.next = self.st3.q.val().rem;
        self.d4_0.quo.next = self.st3.q.val().quo;
        self.d4_0.den.next = self.st3.q.val().den;
        self.d4_1.rem.next = self.d4_0.rem_next.val();
        self.d4_1.quo.next = self.d4_0.quo_next.val();
        self.d4_1.den.next = self.st3.q.val().den;
        self.d4_2.rem.next = self.d4_1.rem_next.val();
        self.d4_2.quo.next = self.d4_1.quo_next.val();
        self.d4_2.den.next = self.st3.q.val().den;
        self.d5_0.rem.next = self.st4.q.val().rem;
        self.d5_0.quo.next = self.st4.q.val().quo;
        self.d5_0.den.next = self.st4.q.val().den;
        self.d5_1.rem.next = self.d5_0.rem_next.val();
        self.d5_1.quo.next = self.d5_0.quo_next.val();
        self.d5_1.den.next = self.st4.q.val().den;
        self.d5_2.rem.next = self.d5_1.rem_next.val();
        self.d5_2.quo.next = self.d5_1.quo_next.val();
        self.d5_2.den.next = self.st4.q.val().den;
        self.d6_0.rem.next = self.st5.q.val().rem;
        self.d6_0.quo.next = self.st5.q.val().quo;
        self.d6_0.den.next = self.st5.q.val().den;
        self.d6_1.rem.next = self.d6_0.rem_next.val();
        self.d6_1.quo.next = self.d6_0.quo_next.val();
        self.d6_1.den.next = self.st5.q.val().den;
        self.d6_2.rem.next = self.d6_1.rem_next.val();
        self.d6_2.quo.next = self.d6_1.quo_next.val();
        self.d6_2.den.next = self.st5.q.val().den;
        self.d7_0.rem.next = self.st6.q.val().rem;
        self.d7_0.quo.next = self.st6.q.val().quo;
        self.d7_0.den.next = self.st6.q.val().den;
        self.d7_1.rem.next = self.d7_0.rem_next.val();
        self.d7_1.quo.next = self.d7_0.quo_next.val();
        self.d7_1.den.next = self.st6.q.val().den;
        self.d7_2.rem.next = self.d7_1.rem_next.val();
        self.d7_2.quo.next = self.d7_1.quo_next.val();
        self.d7_2.den.next = self.st6.q.val().den;
        self.d8_0.rem.next = self.st7.q.val().rem;
        self.d8_0.quo.next = self.st7.q.val().quo;
        self.d8_0.den.next = self.st7.q.val().den;
        self.d8_1.rem.next = self.d8_0.rem_next.val();
        self.d8_1.quo.next = self.d8_0.quo_next.val();
        self.d8_1.den.next = self.st7.q.val().den;
        self.d8_2.rem.next = self.d8_1.rem_next.val();
        self.d8_2.quo.next = self.d8_1.quo_next.val();
        self.d8_2.den.next = self.st7.q.val().den;
        self.d9_0.rem.next = self.st8.q.val().rem;
        self.d9_0.quo.next = self.st8.q.val().quo;
        self.d9_0.den.next = self.st8.q.val().den;
        if self.advance.val() {
            self.st0.d.next = self.norm.val();
            self.st1.d.next = self.st0.q.val();
            self.st1.d.next.rem = self.d1_2.rem_next.val();
            self.st1.d.next.quo = self.d1_2.quo_next.val();
            self.st2.d.next = self.st1.q.val();
            self.st2.d.next.rem = self.d2_2.rem_next.val();
            self.st2.d.next.quo = self.d2_2.quo_next.val();
            self.st3.d.next = self.st2.q.val();
            self.st3.d.next.rem = self.d3_2.rem_next.val();
            self.st3.d.next.quo = self.d3_2.quo_next.val();
            self.st4.d.next = self.st3.q.val();
            self.st4.d.next.rem = self.d4_2.rem_next.val();
            self.st4.d.next.quo = self.d4_2.quo_next.val();
            self.st5.d.next = self.st4.q.val();
            self.st5.d.next.rem = self.d5_2.rem_next.val();
            self.st5.d.next.quo = self.d5_2.quo_next.val();
            self.st6.d.next = self.st5.q.val();
            self.st6.d.next.rem = self.d6_2.rem_next.val();
            self.st6.d.next.quo = self.d6_2.quo_next.val();
            self.st7.d.next = self.st6.q.val();
            self.st7.d.next.rem = self.d7_2.rem_next.val();
            self.st7.d.next.quo = self.d7_2.quo_next.val();
            self.st8.d.next = self.st7.q.val();
            self.st8.d.next.rem = self.d8_2.rem_next.val();
            self.st8.d.next.quo = self.d8_2.quo_next.val();
            self.st9.d.next = self.st8.q.val();
            self.st9.d.next.rem = self.d9_0.rem_next.val();
            self.st9.d.next.quo = self.d9_0.quo_next.val();
        }
        self.request.ready.next = self.advance.val();
        self.result.valid.next = self.st9.q.val().valid;
        self.result.data.next.mant = self.st9.q.val().quo;
        self.result.data.next.shift = self.st9.q.val().shift;
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The exact answer: `(floor(2^(s+24) / det), s)` with `s = floor(log2 det)`.
    pub(crate) fn exact(det: u64) -> (u64, u64) {
        let s = 63 - det.leading_zeros() as u64;
        (((1u128 << (s + 24)) / det as u128) as u64, s)
    }

    /// The ports the pipelined reciprocal units share (this one and `fast_reciprocal`).
    pub(crate) trait RecipPorts: Block + Default {
        fn ports(&mut self) -> (&mut Signal<In, Clock>, &mut StreamIn<Bits<44>>, &mut StreamOut<RecipResult>);
    }

    impl RecipPorts for Reciprocal {
        fn ports(&mut self) -> (&mut Signal<In, Clock>, &mut StreamIn<Bits<44>>, &mut StreamOut<RecipResult>) {
            (&mut self.clock, &mut self.request, &mut self.result)
        }
    }

    /// Requests on every clock that accepts one; results taken on the clocks `take` says; returns
    /// each result with the cycle it was taken in.
    pub(crate) fn run<U: RecipPorts>(dets: &[u64], take: impl Fn(u64) -> bool) -> Vec<(u64, u64, u64)> {
        let mut uut = U::default();
        uut.connect_all();
        let (mut next, mut out) = (0, Vec::new());
        for cycle in 0..10_000u64 {
            {
                let (clock, request, result) = uut.ports();
                request.valid.next = next < dets.len();
                request.data.next = dets.get(next).copied().unwrap_or(0).into();
                result.ready.next = take(cycle);
                clock.next = false.into();
            }
            assert!(simulate(&mut uut, 100));
            let (_, request, result) = uut.ports();
            if result.valid.val() && take(cycle) {
                let r = result.data.val();
                out.push((r.mant.to_u64(), r.shift.to_u64(), cycle));
            }
            if next < dets.len() && request.ready.val() {
                next += 1;
            }
            uut.ports().0.next = true.into();
            assert!(simulate(&mut uut, 100));
            if out.len() == dets.len() {
                return out;
            }
        }
        panic!("results missing: {} of {}", out.len(), dets.len());
    }

    #[test]
    fn reciprocal_is_floor_of_two_to_the_shift_plus_24_over_det_after_10_cycles() {
        assert_eq!(RECIP_LATENCY, 10, "the figure in the test's name");
        for det in [1u64, 2, 3, 5, 7, 255, 256, 1000, 65535, 65536, 123456789, (1 << 34) - 1, (1 << 35) + 12345, (1 << 36) - 1, (1 << 43) + 4321, (1 << 44) - 1] {
            let r = run::<Reciprocal>(&[det], |_| true);
            let (mant, shift) = exact(det);
            assert_eq!((r[0].0, r[0].1), (mant, shift), "det {det}");
            assert_eq!(r[0].2, RECIP_LATENCY, "det {det}");
        }
    }

    #[test]
    fn back_to_back_requests_give_one_result_per_clock_in_request_order() {
        let dets: Vec<u64> = (0..40u64).map(|k| 1 + k * 0x1234567 % ((1 << 44) - 1)).collect();
        let r = run::<Reciprocal>(&dets, |_| true);
        for (k, (&det, &(mant, shift, cycle))) in dets.iter().zip(&r).enumerate() {
            assert_eq!((mant, shift), exact(det), "request {k}");
            assert_eq!(cycle, RECIP_LATENCY + k as u64, "request {k}");
        }
    }

    #[test]
    fn a_stalled_result_holds_the_pipeline_and_loses_nothing() {
        let dets: Vec<u64> = (0..30u64).map(|k| 3 + k * 0x9e3779b9 % ((1 << 44) - 3)).collect();
        // Taken on two clocks of every five only.
        let r = run::<Reciprocal>(&dets, |c| c % 5 == 1 || c % 5 == 3);
        let got: Vec<(u64, u64)> = r.iter().map(|&(m, s, _)| (m, s)).collect();
        let want: Vec<(u64, u64)> = dets.iter().map(|&d| exact(d)).collect();
        assert_eq!(got, want);
    }
}
