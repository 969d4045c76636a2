//! `traversal`: walks a triangle's clamped bounding box in raster order, one candidate pixel per clock,
//! with incremental edge functions (seed 001 eq. 5: `E += -16*dy` per pixel, `+16*dx` per row) and
//! incremental depth (`raw += A` per pixel, `+B` per row: the same integers as `Plane::raw`); runs the
//! clear engine; and issues one token per cycle to the z-test stage.
//!
//! ```text
//!                 +------------------------------------+
//!  rec_* -------->| Idle: take a record                |--> tok_kind (none/clear/frag/result)
//!  rec_valid ---->| Clear: W*H clear tokens, 1/clock   |--> tok_addr, tok_z, tok_index,
//!  rec_ready <----| Walk: 1 candidate/clock            |    tok_covered, tok_last,
//!  result_free -->|                                    |    tok_eof, tok_culled, tok_zero_area
//!  clock -------->|                                    |
//!                 +------------------------------------+
//! ```
//!
//! Cycle behaviour:
//! * `Idle` takes a frame start (`Clear` from the next cycle if it asks for it), a triangle to walk
//!   (loaded this cycle, `Walk` from the next) or, when `result_free`, a skipped triangle or end of frame
//!   (its result token is issued in the same cycle).
//! * `Walk`: a fragment token for every covered candidate and for the last one (which carries the
//!   triangle's result); the last candidate waits for `result_free`. `Idle` after the last candidate.
//! * `Clear`: tokens for addresses 0..W*H-1, then `Idle`.
//!
//! Depth of a candidate: `round(raw / 2^16)` clamped to 0..=2^24-1, as `Plane::eval_clamped`.

use super::setup::{REC_EOF, REC_FRAME, REC_WALK};
use crate::common::signed_bit_cast_safe;
use rust_hdl::prelude::*;

/// Token kinds into the z-test stage.
pub const TOK_NONE: u64 = 0;
pub const TOK_CLEAR: u64 = 1;
pub const TOK_FRAG: u64 = 2;
pub const TOK_RESULT: u64 = 3;

#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum TravState {
    Idle,
    Clear,
    Walk,
}

#[derive(LogicBlock)]
pub struct Traversal {
    pub clock: Signal<In, Clock>,
    // From the setup
    pub rec_valid: Signal<In, Bit>,
    pub rec_kind: Signal<In, Bits<2>>,
    pub rec_clear: Signal<In, Bit>,
    pub rec_index: Signal<In, Bits<16>>,
    pub rec_culled: Signal<In, Bit>,
    pub rec_zero_area: Signal<In, Bit>,
    pub rec_bx0: Signal<In, Bits<10>>,
    pub rec_bx1: Signal<In, Bits<10>>,
    pub rec_by0: Signal<In, Bits<10>>,
    pub rec_by1: Signal<In, Bits<10>>,
    pub rec_addr: Signal<In, Bits<20>>,
    pub rec_e0: Signal<In, Signed<36>>,
    pub rec_e1: Signal<In, Signed<36>>,
    pub rec_e2: Signal<In, Signed<36>>,
    pub rec_sx0: Signal<In, Signed<22>>,
    pub rec_sx1: Signal<In, Signed<22>>,
    pub rec_sx2: Signal<In, Signed<22>>,
    pub rec_sy0: Signal<In, Signed<22>>,
    pub rec_sy1: Signal<In, Signed<22>>,
    pub rec_sy2: Signal<In, Signed<22>>,
    pub rec_raw: Signal<In, Signed<56>>,
    pub rec_a: Signal<In, Signed<40>>,
    pub rec_b: Signal<In, Signed<40>>,
    // To the setup
    /// The record is taken this cycle.
    pub rec_ready: Signal<Out, Bit>,
    // From the z-test stage
    /// A result token issued now will find the result register empty.
    pub result_free: Signal<In, Bit>,
    // To the z-test stage (and the Z read port)
    pub tok_kind: Signal<Out, Bits<2>>,
    pub tok_covered: Signal<Out, Bit>,
    pub tok_last: Signal<Out, Bit>,
    pub tok_addr: Signal<Out, Bits<20>>,
    pub tok_z: Signal<Out, Bits<24>>,
    pub tok_index: Signal<Out, Bits<16>>,
    pub tok_eof: Signal<Out, Bit>,
    pub tok_culled: Signal<Out, Bit>,
    pub tok_zero_area: Signal<Out, Bit>,

    state: DFF<TravState>,
    x: DFF<Bits<10>>,
    y: DFF<Bits<10>>,
    bx0: DFF<Bits<10>>,
    bx1: DFF<Bits<10>>,
    by1: DFF<Bits<10>>,
    index: DFF<Bits<16>>,
    addr: DFF<Bits<20>>,
    addr_row: DFF<Bits<20>>,
    e0: DFF<Signed<36>>,
    e1: DFF<Signed<36>>,
    e2: DFF<Signed<36>>,
    er0: DFF<Signed<36>>,
    er1: DFF<Signed<36>>,
    er2: DFF<Signed<36>>,
    sx0: DFF<Signed<36>>,
    sx1: DFF<Signed<36>>,
    sx2: DFF<Signed<36>>,
    sy0: DFF<Signed<36>>,
    sy1: DFF<Signed<36>>,
    sy2: DFF<Signed<36>>,
    raw: DFF<Signed<56>>,
    raw_row: DFF<Signed<56>>,
    grad_a: DFF<Signed<56>>,
    grad_b: DFF<Signed<56>>,

    covered: Signal<Local, Bit>,
    at_last: Signal<Local, Bit>,
    row_end: Signal<Local, Bit>,
    rounded: Signal<Local, Signed<56>>,
    rounded_u: Signal<Local, Bits<56>>,
    depth: Signal<Local, Bits<24>>,
    e0_row: Signal<Local, Signed<36>>,
    e1_row: Signal<Local, Signed<36>>,
    e2_row: Signal<Local, Signed<36>>,
    raw_next_row: Signal<Local, Signed<56>>,
    addr_next_row: Signal<Local, Bits<20>>,

    width: Constant<Bits<20>>,
    last_addr: Constant<Bits<20>>,
    half: Constant<Signed<56>>,
    depth_max: Constant<Bits<24>>,
    k0_24: Constant<Bits<24>>,
    k0_15: Constant<Bits<15>>,
    k1_10: Constant<Bits<10>>,
    k1_20: Constant<Bits<20>>,
    k0_20: Constant<Bits<20>>,
    tok_none: Constant<Bits<2>>,
    tok_clear: Constant<Bits<2>>,
    tok_frag: Constant<Bits<2>>,
    tok_result: Constant<Bits<2>>,
    rec_frame: Constant<Bits<2>>,
    rec_walk: Constant<Bits<2>>,
    rec_eof: Constant<Bits<2>>,
}

impl Traversal {
    pub fn new(width: u32, height: u32) -> Traversal {
        Traversal {
            clock: Default::default(),
            rec_valid: Default::default(),
            rec_kind: Default::default(),
            rec_clear: Default::default(),
            rec_index: Default::default(),
            rec_culled: Default::default(),
            rec_zero_area: Default::default(),
            rec_bx0: Default::default(),
            rec_bx1: Default::default(),
            rec_by0: Default::default(),
            rec_by1: Default::default(),
            rec_addr: Default::default(),
            rec_e0: Default::default(),
            rec_e1: Default::default(),
            rec_e2: Default::default(),
            rec_sx0: Default::default(),
            rec_sx1: Default::default(),
            rec_sx2: Default::default(),
            rec_sy0: Default::default(),
            rec_sy1: Default::default(),
            rec_sy2: Default::default(),
            rec_raw: Default::default(),
            rec_a: Default::default(),
            rec_b: Default::default(),
            rec_ready: Default::default(),
            result_free: Default::default(),
            tok_kind: Default::default(),
            tok_covered: Default::default(),
            tok_last: Default::default(),
            tok_addr: Default::default(),
            tok_z: Default::default(),
            tok_index: Default::default(),
            tok_eof: Default::default(),
            tok_culled: Default::default(),
            tok_zero_area: Default::default(),
            state: Default::default(),
            x: Default::default(),
            y: Default::default(),
            bx0: Default::default(),
            bx1: Default::default(),
            by1: Default::default(),
            index: Default::default(),
            addr: Default::default(),
            addr_row: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            e2: Default::default(),
            er0: Default::default(),
            er1: Default::default(),
            er2: Default::default(),
            sx0: Default::default(),
            sx1: Default::default(),
            sx2: Default::default(),
            sy0: Default::default(),
            sy1: Default::default(),
            sy2: Default::default(),
            raw: Default::default(),
            raw_row: Default::default(),
            grad_a: Default::default(),
            grad_b: Default::default(),
            covered: Default::default(),
            at_last: Default::default(),
            row_end: Default::default(),
            rounded: Default::default(),
            rounded_u: Default::default(),
            depth: Default::default(),
            e0_row: Default::default(),
            e1_row: Default::default(),
            e2_row: Default::default(),
            raw_next_row: Default::default(),
            addr_next_row: Default::default(),
            width: Constant::new((width as u64).into()),
            last_addr: Constant::new(((width * height - 1) as u64).into()),
            half: Constant::new((1i64 << 15).into()),
            depth_max: Constant::new(((1u64 << 24) - 1).into()),
            k0_24: Constant::new(0.into()),
            k0_15: Constant::new(0.into()),
            k1_10: Constant::new(1.into()),
            k1_20: Constant::new(1.into()),
            k0_20: Constant::new(0.into()),
            tok_none: Constant::new(TOK_NONE.into()),
            tok_clear: Constant::new(TOK_CLEAR.into()),
            tok_frag: Constant::new(TOK_FRAG.into()),
            tok_result: Constant::new(TOK_RESULT.into()),
            rec_frame: Constant::new(REC_FRAME.into()),
            rec_walk: Constant::new(REC_WALK.into()),
            rec_eof: Constant::new(REC_EOF.into()),
        }
    }
}

impl Logic for Traversal {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, state, x, y, bx0, bx1, by1, index, addr, addr_row, e0, e1, e2, er0, er1, er2, sx0, sx1, sx2, sy0,
            sy1, sy2, raw, raw_row, grad_a, grad_b
        );
        // The candidate at (x, y).
        self.covered.next = !self.e0.q.val().get_bit(35) & !self.e1.q.val().get_bit(35) & !self.e2.q.val().get_bit(35);
        self.at_last.next = (self.x.q.val() == self.bx1.q.val()) & (self.y.q.val() == self.by1.q.val());
        self.row_end.next = self.x.q.val() == self.bx1.q.val();
        self.rounded.next = self.raw.q.val() + self.half.val();
        self.rounded_u.next = unsigned_cast(self.rounded.val());
        self.depth.next = self.rounded_u.val().get_bits::<24>(16);
        if self.rounded_u.val().get_bits::<15>(40) != self.k0_15.val() {
            self.depth.next = self.depth_max.val();
        }
        if self.rounded.val().get_bit(55) {
            self.depth.next = self.k0_24.val();
        }
        self.e0_row.next = self.er0.q.val() + self.sy0.q.val();
        self.e1_row.next = self.er1.q.val() + self.sy1.q.val();
        self.e2_row.next = self.er2.q.val() + self.sy2.q.val();
        self.raw_next_row.next = self.raw_row.q.val() + self.grad_b.q.val();
        self.addr_next_row.next = self.addr_row.q.val() + self.width.val();

        self.rec_ready.next = false;
        self.tok_kind.next = self.tok_none.val();
        self.tok_covered.next = false;
        self.tok_last.next = false;
        self.tok_addr.next = self.k0_20.val();
        self.tok_z.next = self.k0_24.val();
        self.tok_index.next = self.index.q.val();
        self.tok_eof.next = false;
        self.tok_culled.next = false;
        self.tok_zero_area.next = false;
        match self.state.q.val() {
            TravState::Idle => {
                self.tok_index.next = self.rec_index.val();
                if self.rec_valid.val() {
                    if (self.rec_kind.val() == self.rec_frame.val()) | (self.rec_kind.val() == self.rec_walk.val()) {
                        self.rec_ready.next = true;
                    } else if self.result_free.val() {
                        self.rec_ready.next = true;
                        self.tok_kind.next = self.tok_result.val();
                        self.tok_eof.next = self.rec_kind.val() == self.rec_eof.val();
                        self.tok_culled.next = self.rec_culled.val();
                        self.tok_zero_area.next = self.rec_zero_area.val();
                    }
                    if (self.rec_kind.val() == self.rec_frame.val()) & self.rec_clear.val() {
                        self.addr.d.next = self.k0_20.val();
                        self.state.d.next = TravState::Clear;
                    }
                    if self.rec_kind.val() == self.rec_walk.val() {
                        self.x.d.next = self.rec_bx0.val();
                        self.y.d.next = self.rec_by0.val();
                        self.bx0.d.next = self.rec_bx0.val();
                        self.bx1.d.next = self.rec_bx1.val();
                        self.by1.d.next = self.rec_by1.val();
                        self.index.d.next = self.rec_index.val();
                        self.addr.d.next = self.rec_addr.val();
                        self.addr_row.d.next = self.rec_addr.val();
                        self.e0.d.next = self.rec_e0.val();
                        self.e1.d.next = self.rec_e1.val();
                        self.e2.d.next = self.rec_e2.val();
                        self.er0.d.next = self.rec_e0.val();
                        self.er1.d.next = self.rec_e1.val();
                        self.er2.d.next = self.rec_e2.val();
                        self.sx0.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sx0.val());
                        self.sx1.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sx1.val());
                        self.sx2.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sx2.val());
                        self.sy0.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sy0.val());
                        self.sy1.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sy1.val());
                        self.sy2.d.next = signed_bit_cast_safe::<36, 22>(self.rec_sy2.val());
                        self.raw.d.next = self.rec_raw.val();
                        self.raw_row.d.next = self.rec_raw.val();
                        self.grad_a.d.next = signed_bit_cast_safe::<56, 40>(self.rec_a.val());
                        self.grad_b.d.next = signed_bit_cast_safe::<56, 40>(self.rec_b.val());
                        self.state.d.next = TravState::Walk;
                    }
                }
            }
            TravState::Clear => {
                self.tok_kind.next = self.tok_clear.val();
                self.tok_addr.next = self.addr.q.val();
                self.addr.d.next = self.addr.q.val() + self.k1_20.val();
                if self.addr.q.val() == self.last_addr.val() {
                    self.state.d.next = TravState::Idle;
                }
            }
            TravState::Walk => {
                if !self.at_last.val() | self.result_free.val() {
                    if self.covered.val() | self.at_last.val() {
                        self.tok_kind.next = self.tok_frag.val();
                        self.tok_covered.next = self.covered.val();
                        self.tok_last.next = self.at_last.val();
                        self.tok_addr.next = self.addr.q.val();
                    }
                    if self.covered.val() {
                        self.tok_z.next = self.depth.val();
                    }
                    if self.at_last.val() {
                        self.state.d.next = TravState::Idle;
                    } else if self.row_end.val() {
                        self.x.d.next = self.bx0.q.val();
                        self.y.d.next = self.y.q.val() + self.k1_10.val();
                        self.er0.d.next = self.e0_row.val();
                        self.er1.d.next = self.e1_row.val();
                        self.er2.d.next = self.e2_row.val();
                        self.e0.d.next = self.e0_row.val();
                        self.e1.d.next = self.e1_row.val();
                        self.e2.d.next = self.e2_row.val();
                        self.raw_row.d.next = self.raw_next_row.val();
                        self.raw.d.next = self.raw_next_row.val();
                        self.addr_row.d.next = self.addr_next_row.val();
                        self.addr.d.next = self.addr_next_row.val();
                    } else {
                        self.x.d.next = self.x.q.val() + self.k1_10.val();
                        self.e0.d.next = self.e0.q.val() + self.sx0.q.val();
                        self.e1.d.next = self.e1.q.val() + self.sx1.q.val();
                        self.e2.d.next = self.e2.q.val() + self.sx2.q.val();
                        self.raw.d.next = self.raw.q.val() + self.grad_a.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k1_20.val();
                    }
                }
            }
            _ => {
                self.state.d.next = TravState::Idle;
            }
        }
    }
}
