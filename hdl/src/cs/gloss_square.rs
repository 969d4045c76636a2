//! `gloss_square`: one stage of a light unit's specular power (seed 001 eq. 4, `(N.H)^n` with the gloss
//! n a power of two): `sp = round(sp^2 / 2^14)` when this stage is below log2 of the gloss, else `sp`
//! passes. Registered; the diffuse term `nl` and the gloss travel alongside. Four in a row give gloss
//! 1..16 (`golden::shade::power_q14`).
//!
//! ```text
//!               +------------------------------------------+
//!  sp_in ------>| square (in logic), + 2^13, >> 14         |--> sp_out   (registered)
//!  gloss_in --->| gloss_in > stage ? square : sp_in        |--> gloss_out
//!  stage ------>|                                          |
//!  nl_in ------>|                                          |--> nl_out
//!  clock ------>|                                          |
//!               +------------------------------------------+
//! ```
//!
//! `sp` is Q1.14 in [0, 1] (at most 2^14), so the square is at most 2^28 and the result stays in [0, 1].
//! The square is in LUTs ([`SquareLogicU`], 569 LUT4 on the ECP5), not on a MULT18X18D: the chipset's
//! eight squarers did not leave it room on the LFE5U-45F's 72 blocks (issue 15 item 5).

use crate::common::SquareLogicU;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct GlossSquare {
    pub clock: Signal<In, Clock>,
    // From the stage before
    /// The specular dot product so far, Q1.14 in [0, 1].
    pub sp_in: Signal<In, Bits<15>>,
    /// The diffuse dot product (passes).
    pub nl_in: Signal<In, Bits<15>>,
    /// log2 of the pixel's gloss (passes).
    pub gloss_in: Signal<In, Bits<3>>,
    /// This stage's number, 0..=3: it squares when `gloss_in` is above it.
    pub stage: Signal<In, Bits<3>>,
    // To the stage after
    pub sp_out: Signal<Out, Bits<15>>,
    pub nl_out: Signal<Out, Bits<15>>,
    pub gloss_out: Signal<Out, Bits<3>>,

    sq: SquareLogicU<15, 30>,
    sp: DFF<Bits<15>>,
    nl: DFF<Bits<15>>,
    gloss: DFF<Bits<3>>,
    rounded: Signal<Local, Bits<30>>,
    khalf_30: Constant<Bits<30>>,
}

impl Default for GlossSquare {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            sp_in: Default::default(),
            nl_in: Default::default(),
            gloss_in: Default::default(),
            stage: Default::default(),
            sp_out: Default::default(),
            nl_out: Default::default(),
            gloss_out: Default::default(),
            sq: Default::default(),
            sp: Default::default(),
            nl: Default::default(),
            gloss: Default::default(),
            rounded: Default::default(),
            khalf_30: Constant::new((1u64 << 13).into()),
        }
    }
}

impl Logic for GlossSquare {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, sp, nl, gloss);
        self.sq.a.next = self.sp_in.val();
        self.rounded.next = self.sq.p.val() + self.khalf_30.val();
        self.sp.d.next = self.sp_in.val();
        if self.gloss_in.val() > self.stage.val() {
            self.sp.d.next = self.rounded.val().get_bits::<15>(14);
        }
        self.nl.d.next = self.nl_in.val();
        self.gloss.d.next = self.gloss_in.val();
        self.sp_out.next = self.sp.q.val();
        self.nl_out.next = self.nl.q.val();
        self.gloss_out.next = self.gloss.q.val();
    }
}
