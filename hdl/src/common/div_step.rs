//! `DivStep`: one step of the restoring division of `golden::format::reciprocal` (combinational): the
//! partial remainder is compared with the divisor, the divisor subtracted if it fits, one quotient bit
//! shifted in. The RC's sequential reciprocal takes one per cycle; colour setup's pipelined one is a
//! chain of them, one per station.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DivStep {
    /// Partial remainder (< 2 * den) and divisor.
    pub rem: Signal<In, Bits<37>>,
    pub den: Signal<In, Bits<37>>,
    pub quo: Signal<In, Bits<25>>,
    /// After the step.
    pub rem_next: Signal<Out, Bits<37>>,
    pub quo_next: Signal<Out, Bits<25>>,
    diff: Signal<Local, Bits<37>>,
    shifted: Signal<Local, Bits<25>>,
    k1_1: Constant<Bits<1>>,
    k1_25: Constant<Bits<25>>,
}

impl Default for DivStep {
    fn default() -> Self {
        Self {
            rem: Default::default(),
            den: Default::default(),
            quo: Default::default(),
            rem_next: Default::default(),
            quo_next: Default::default(),
            diff: Default::default(),
            shifted: Default::default(),
            k1_1: Constant::new(1.into()),
            k1_25: Constant::new(1.into()),
        }
    }
}

impl Logic for DivStep {
    #[hdl_gen]
    fn update(&mut self) {
        self.diff.next = self.rem.val() - self.den.val();
        self.shifted.next = self.quo.val() << self.k1_1.val();
        self.rem_next.next = self.rem.val() << self.k1_1.val();
        self.quo_next.next = self.shifted.val();
        if self.rem.val() >= self.den.val() {
            self.rem_next.next = self.diff.val() << self.k1_1.val();
            self.quo_next.next = self.shifted.val() | self.k1_25.val();
        }
    }
}
