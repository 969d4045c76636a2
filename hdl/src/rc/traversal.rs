//! `traversal`: walks a triangle's clamped bounding box in raster order with incremental edge
//! functions (seed 001 eq. 5: `E += -256*dy` per pixel, `+256*dx` per row) and incremental depth
//! (`raw += A` per pixel, `+B` per row: the same integers as `Plane::raw`), issuing at most one
//! fragment per clock; runs the clear engine; and issues one token per cycle to the z-test stage.
//!
//! ```text
//!                 +--------------------------------------+
//!  rec_* -------->| Idle: take a record                  |--> tok_kind (none/clear/frag/result)
//!  rec_valid ---->| Clear: W*H clear tokens, 1/clock     |--> tok_addr, tok_z, tok_index,
//!  rec_ready <----| Walk: a window of 4 candidates/clock |    tok_covered, tok_last,
//!  result_free -->|       one fragment/clock             |    tok_eof, tok_culled, tok_zero_area
//!  clock -------->|                                      |
//!                 +--------------------------------------+
//! ```
//!
//! Cycle behaviour (`golden::cycle::rc::walk_step` is the rule, docs/rc.md the description):
//! * `Idle` takes a frame start (`Clear` from the next cycle if it asks for it), a triangle to walk
//!   (loaded this cycle, `Walk` from the next) or, when `result_free`, a skipped triangle or end of frame
//!   (its result token is issued in the same cycle).
//! * `Walk` at candidate x looks at x..=x+3 (not past the box): covered candidates by the signs of
//!   the edge values there. Those signs are **registered a cycle ahead** (look-ahead, issue 15 item
//!   5): with x the traversal holds, per edge, E at x and the signs of `E + j*step` for j = 1, 2, 3,
//!   15. In the cycle at x the decision, made from flip-flops only, picks the step (x+1, +2, +3,
//!   +4, +16, the next row's start, a load); the step's branch forms the new E and the signs at the
//!   window after it (offsets 2..7, 16..19, 31 from x). The sums are independent of the decision,
//!   which only selects among them. Offsets 1..4, 15, 16 add a registered multiple of the step to
//!   E; offsets 5..7 add one to `E + 4*step`, 17..19 and 31 to `E + 16*step` (two adders in series,
//!   off the decision's path). So six multiples (j = 1, 2, 3, 4, 15, 16) per edge are registered
//!   when the triangle is loaded. The next row's start `ern` is a register, with its own window of
//!   four sums. It issues the first covered one as a fragment and goes on at the next covered one;
//!   with none left it skips past the window, or past 16 candidates (`long`) when none is covered
//!   and an edge is negative at x and at x+15. It ends the row instead when the skip reaches the
//!   box's edge, or an edge is negative at the skip's last candidate with a step that
//!   does not grow (`nonpos`). Ending the last row ends the walk; that cycle's token (the
//!   fragment, or an uncovered end token) carries the triangle's result and waits for `result_free`,
//!   and the same cycle takes the next record if it is a triangle or a frame start (no idle cycle).
//! * The candidates left in the row (`rm` = bx1 - x) and the flags `rm > 0, 1, 2, 3, 15` are
//!   registers, set at a load and a row start from the box and at each step by comparing the old `rm`
//!   with the step added (`rm - a > k` is `rm > k + a`): the decision starts from flags, not from a
//!   subtraction (issue 15 item 5). Same cycles as before; `x` is kept for the waveforms.
//! * `Clear`: tokens for addresses 0..W*H-1, then `Idle`.
//!
//! Depth of a fragment: `round(raw / 2^16)` clamped to 0..=2^24-1, as `Plane::eval_clamped`; the
//! registers hold raw + 2^15, so the rounding is a shift.

use super::setup::{REC_EOF, REC_FRAME, REC_WALK};
use crate::common::signed_bit_cast_safe;
use rust_hdl::prelude::*;

/// Token kinds into the z-test stage.
pub const TOK_NONE: u64 = 0;
pub const TOK_CLEAR: u64 = 1;
pub const TOK_FRAG: u64 = 2;
pub const TOK_RESULT: u64 = 3;

/// What the traversal hands the visibility test each cycle: a clear, a fragment (or a walk's
/// uncovered end) or a result, with the pixel's address, position and depth and the triangle's index.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RcToken {
    /// TOK_NONE, TOK_CLEAR, TOK_FRAG or TOK_RESULT.
    pub kind: Bits<2>,
    /// A fragment: the pixel's centre is inside (else the walk's uncovered end token).
    pub covered: Bit,
    /// The triangle's last token.
    pub last: Bit,
    pub addr: Bits<20>,
    /// The pixel (Type III regenerates the old depth there; Type IV does not read them).
    pub x: Bits<10>,
    pub y: Bits<10>,
    pub z: Bits<24>,
    pub index: Bits<16>,
    /// A result token: end of frame, culled, zero area.
    pub eof: Bit,
    pub culled: Bit,
    pub zero_area: Bit,
}

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
    pub rec_e0: Signal<In, Signed<44>>,
    pub rec_e1: Signal<In, Signed<44>>,
    pub rec_e2: Signal<In, Signed<44>>,
    pub rec_sx0: Signal<In, Signed<30>>,
    pub rec_sx1: Signal<In, Signed<30>>,
    pub rec_sx2: Signal<In, Signed<30>>,
    pub rec_sy0: Signal<In, Signed<30>>,
    pub rec_sy1: Signal<In, Signed<30>>,
    pub rec_sy2: Signal<In, Signed<30>>,
    pub rec_raw: Signal<In, Signed<56>>,
    pub rec_a: Signal<In, Signed<40>>,
    pub rec_b: Signal<In, Signed<40>>,
    /// 3 and 15 times each edge's x step and 3 times A, formed by the setup as the record entered its
    /// queue, so the record take adds nothing up to load the multiples (issue 15 item 5).
    pub rec_sx3_0: Signal<In, Signed<32>>,
    pub rec_sx3_1: Signal<In, Signed<32>>,
    pub rec_sx3_2: Signal<In, Signed<32>>,
    pub rec_sx15_0: Signal<In, Signed<34>>,
    pub rec_sx15_1: Signal<In, Signed<34>>,
    pub rec_sx15_2: Signal<In, Signed<34>>,
    pub rec_a3: Signal<In, Signed<42>>,
    // To the setup
    /// The record is taken this cycle.
    pub rec_ready: Signal<Out, Bit>,
    // From the z-test stage
    /// A result token issued now will find room in the result queue.
    pub result_free: Signal<In, Bit>,
    // To the z-test stage (and the Z read port)
    /// The token issued this cycle (`TOK_NONE` when nothing is issued).
    pub tok: Signal<Out, RcToken>,

    // Registers: the walk's position and increments; sxJ_K is J times edge K's x step, gaJ J times A;
    // nonpos K: edge K's x step is <= 0 (it never grows to the right).
    state: DFF<TravState>,
    x: DFF<Bits<10>>,
    y: DFF<Bits<10>>,
    bx0: DFF<Bits<10>>,
    by1: DFF<Bits<10>>,
    index: DFF<Bits<16>>,
    addr: DFF<Bits<20>>,
    addr_row: DFF<Bits<20>>,
    e0: DFF<Signed<44>>,
    e1: DFF<Signed<44>>,
    e2: DFF<Signed<44>>,
    // ernK: edge K at the next row's start (bx0, y+1).
    ern0: DFF<Signed<44>>,
    ern1: DFF<Signed<44>>,
    ern2: DFF<Signed<44>>,
    sx1_0: DFF<Signed<44>>,
    sx2_0: DFF<Signed<44>>,
    sx3_0: DFF<Signed<44>>,
    sx4_0: DFF<Signed<44>>,
    sx15_0: DFF<Signed<44>>,
    sx1_1: DFF<Signed<44>>,
    sx2_1: DFF<Signed<44>>,
    sx3_1: DFF<Signed<44>>,
    sx4_1: DFF<Signed<44>>,
    sx15_1: DFF<Signed<44>>,
    sx1_2: DFF<Signed<44>>,
    sx2_2: DFF<Signed<44>>,
    sx3_2: DFF<Signed<44>>,
    sx4_2: DFF<Signed<44>>,
    sx15_2: DFF<Signed<44>>,
    sx16_0: DFF<Signed<44>>,
    sx16_1: DFF<Signed<44>>,
    sx16_2: DFF<Signed<44>>,
    // The look-ahead (issue 15 item 5): sJ_K is edge K negative at x+J, registered with the step
    // that leads to x, so the walk's decision starts from flip-flops, not from carry chains.
    s1_0: DFF<Bit>,
    s2_0: DFF<Bit>,
    s3_0: DFF<Bit>,
    s15_0: DFF<Bit>,
    s1_1: DFF<Bit>,
    s2_1: DFF<Bit>,
    s3_1: DFF<Bit>,
    s15_1: DFF<Bit>,
    s1_2: DFF<Bit>,
    s2_2: DFF<Bit>,
    s3_2: DFF<Bit>,
    s15_2: DFF<Bit>,
    sy0: DFF<Signed<44>>,
    sy1: DFF<Signed<44>>,
    sy2: DFF<Signed<44>>,
    nonpos0: DFF<Bit>,
    nonpos1: DFF<Bit>,
    nonpos2: DFF<Bit>,
    // The depth plane's raw value at x (and at the row's start) plus the rounding half 2^15: a
    // fragment's depth is then these bits shifted, with no rounding add in its path (issue 15 item 5).
    rawh: DFF<Signed<56>>,
    rawh_row: DFF<Signed<56>>,
    // The candidates left in the row after x (bx1 - x) and whether it is above 0, 1, 2, 3 and 15
    // (rgK); wrem and wgK the same at a row's start (bx1 - bx0). Registered so that the walk's decision
    // starts from flags, not from a subtraction and compare (issue 15 item 5: x into bx1 - x was the
    // start of the critical path).
    rm: DFF<Bits<10>>,
    rg0: DFF<Bit>,
    rg1: DFF<Bit>,
    rg2: DFF<Bit>,
    rg3: DFF<Bit>,
    rg15: DFF<Bit>,
    wrem: DFF<Bits<10>>,
    wg0: DFF<Bit>,
    wg1: DFF<Bit>,
    wg2: DFF<Bit>,
    wg3: DFF<Bit>,
    wg15: DFF<Bit>,
    ga1: DFF<Signed<56>>,
    ga2: DFF<Signed<56>>,
    ga3: DFF<Signed<56>>,
    ga4: DFF<Signed<56>>,
    ga16: DFF<Signed<56>>,
    grad_b: DFF<Signed<56>>,

    // The candidates: tJ_K is edge K at the window after the step taken, + J (J = 1, 2, 3, 15), whose
    // sign the step's branch registers in sJ_K; cov J: candidate x+J is covered and inside the box;
    // fsel the first covered one, nsel the next candidate after this clock.
    lw: Signal<Local, Bits<10>>,
    take: Signal<Local, Bit>,
    cov0: Signal<Local, Bit>,
    cov1: Signal<Local, Bit>,
    cov2: Signal<Local, Bit>,
    cov3: Signal<Local, Bit>,
    has_frag: Signal<Local, Bit>,
    fsel: Signal<Local, Bits<2>>,
    has_next: Signal<Local, Bit>,
    nsel: Signal<Local, Bits<3>>,
    dead4: Signal<Local, Bit>,
    dead16: Signal<Local, Bit>,
    long: Signal<Local, Bit>,
    row_done: Signal<Local, Bit>,
    walk_end: Signal<Local, Bit>,
    at_last_row: Signal<Local, Bit>,
    fraw: Signal<Local, Signed<56>>,
    rounded_u: Signal<Local, Bits<56>>,
    depth: Signal<Local, Bits<24>>,
    faddr: Signal<Local, Bits<20>>,
    fsel10: Signal<Local, Bits<10>>,
    load_walk: Signal<Local, Bit>,
    load_clear: Signal<Local, Bit>,
    rsx1_0: Signal<Local, Signed<44>>,
    rsx1_1: Signal<Local, Signed<44>>,
    rsx1_2: Signal<Local, Signed<44>>,
    rsx2_0: Signal<Local, Signed<44>>,
    rsx2_1: Signal<Local, Signed<44>>,
    rsx2_2: Signal<Local, Signed<44>>,
    rsx4_0: Signal<Local, Signed<44>>,
    rsx4_1: Signal<Local, Signed<44>>,
    rsx4_2: Signal<Local, Signed<44>>,
    rsx3_0: Signal<Local, Signed<44>>,
    rsx15_0: Signal<Local, Signed<44>>,
    rsx16_0: Signal<Local, Signed<44>>,
    rsx3_1: Signal<Local, Signed<44>>,
    rsx15_1: Signal<Local, Signed<44>>,
    rsx16_1: Signal<Local, Signed<44>>,
    rsx3_2: Signal<Local, Signed<44>>,
    rsx15_2: Signal<Local, Signed<44>>,
    rsx16_2: Signal<Local, Signed<44>>,
    // cJ_K: edge K at x+J (J = 4, 16), the base of the sums at offsets 5-7 and 17-19, 31.
    c4_0: Signal<Local, Signed<44>>,
    c16_0: Signal<Local, Signed<44>>,
    c4_1: Signal<Local, Signed<44>>,
    c16_1: Signal<Local, Signed<44>>,
    c4_2: Signal<Local, Signed<44>>,
    c16_2: Signal<Local, Signed<44>>,
    t1_0: Signal<Local, Signed<44>>,
    t2_0: Signal<Local, Signed<44>>,
    t3_0: Signal<Local, Signed<44>>,
    t15_0: Signal<Local, Signed<44>>,
    t1_1: Signal<Local, Signed<44>>,
    t2_1: Signal<Local, Signed<44>>,
    t3_1: Signal<Local, Signed<44>>,
    t15_1: Signal<Local, Signed<44>>,
    t1_2: Signal<Local, Signed<44>>,
    t2_2: Signal<Local, Signed<44>>,
    t3_2: Signal<Local, Signed<44>>,
    t15_2: Signal<Local, Signed<44>>,
    ub0: Signal<Local, Bits<44>>,
    ub1: Signal<Local, Bits<44>>,
    ub2: Signal<Local, Bits<44>>,
    lrn_0: Signal<Local, Signed<44>>,
    lrn_1: Signal<Local, Signed<44>>,
    lrn_2: Signal<Local, Signed<44>>,
    ra1: Signal<Local, Signed<56>>,
    ra2: Signal<Local, Signed<56>>,
    ra4: Signal<Local, Signed<56>>,
    // A's bits, for its multiples as shifts; 3 A from the record; 16 A.
    uab: Signal<Local, Bits<56>>,
    ra3: Signal<Local, Signed<56>>,
    ra16: Signal<Local, Signed<56>>,

    width: Constant<Bits<20>>,
    last_addr: Constant<Bits<20>>,
    half: Constant<Signed<56>>,
    depth_max: Constant<Bits<24>>,
    k0_24: Constant<Bits<24>>,
    k0_15: Constant<Bits<15>>,
    ks0_44: Constant<Signed<44>>,
    ks0_56: Constant<Signed<56>>,
    kz2: Constant<Bits<2>>,
    kz3: Constant<Bits<3>>,
    kz20: Constant<Bits<20>>,
    kz24: Constant<Bits<24>>,
    kz56: Constant<Bits<56>>,
    kz44: Constant<Bits<44>>,
    k0_10: Constant<Bits<10>>,
    k1_10: Constant<Bits<10>>,
    k15_10: Constant<Bits<10>>,
    k16_10: Constant<Bits<10>>,
    k5_10: Constant<Bits<10>>,
    k6_10: Constant<Bits<10>>,
    k7_10: Constant<Bits<10>>,
    k17_10: Constant<Bits<10>>,
    k18_10: Constant<Bits<10>>,
    k19_10: Constant<Bits<10>>,
    k31_10: Constant<Bits<10>>,
    k16_20: Constant<Bits<20>>,
    k2_10: Constant<Bits<10>>,
    k3_10: Constant<Bits<10>>,
    k4_10: Constant<Bits<10>>,
    k1_20: Constant<Bits<20>>,
    k2_20: Constant<Bits<20>>,
    k3_20: Constant<Bits<20>>,
    k4_20: Constant<Bits<20>>,
    k0_20: Constant<Bits<20>>,
    k0_2: Constant<Bits<2>>,
    k1_6: Constant<Bits<6>>,
    k2_6: Constant<Bits<6>>,
    k4_6: Constant<Bits<6>>,
    k1_2: Constant<Bits<2>>,
    k2_2: Constant<Bits<2>>,
    k3_2: Constant<Bits<2>>,
    k1_3: Constant<Bits<3>>,
    k2_3: Constant<Bits<3>>,
    k3_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
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
            rec_sx3_0: Default::default(),
            rec_sx3_1: Default::default(),
            rec_sx3_2: Default::default(),
            rec_sx15_0: Default::default(),
            rec_sx15_1: Default::default(),
            rec_sx15_2: Default::default(),
            rec_a3: Default::default(),
            rec_ready: Default::default(),
            result_free: Default::default(),
            tok: Default::default(),
            state: Default::default(),
            x: Default::default(),
            y: Default::default(),
            bx0: Default::default(),
            by1: Default::default(),
            index: Default::default(),
            addr: Default::default(),
            addr_row: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            e2: Default::default(),
            ern0: Default::default(),
            ern1: Default::default(),
            ern2: Default::default(),
            sx1_0: Default::default(),
            sx2_0: Default::default(),
            sx3_0: Default::default(),
            sx4_0: Default::default(),
            sx15_0: Default::default(),
            sx1_1: Default::default(),
            sx2_1: Default::default(),
            sx3_1: Default::default(),
            sx4_1: Default::default(),
            sx15_1: Default::default(),
            sx1_2: Default::default(),
            sx2_2: Default::default(),
            sx3_2: Default::default(),
            sx4_2: Default::default(),
            sx15_2: Default::default(),
            sx16_0: Default::default(),
            sx16_1: Default::default(),
            sx16_2: Default::default(),
            s1_0: Default::default(),
            s2_0: Default::default(),
            s3_0: Default::default(),
            s15_0: Default::default(),
            s1_1: Default::default(),
            s2_1: Default::default(),
            s3_1: Default::default(),
            s15_1: Default::default(),
            s1_2: Default::default(),
            s2_2: Default::default(),
            s3_2: Default::default(),
            s15_2: Default::default(),
            sy0: Default::default(),
            sy1: Default::default(),
            sy2: Default::default(),
            nonpos0: Default::default(),
            nonpos1: Default::default(),
            nonpos2: Default::default(),
            rawh: Default::default(),
            rawh_row: Default::default(),
            rm: Default::default(),
            rg0: Default::default(),
            rg1: Default::default(),
            rg2: Default::default(),
            rg3: Default::default(),
            rg15: Default::default(),
            wrem: Default::default(),
            wg0: Default::default(),
            wg1: Default::default(),
            wg2: Default::default(),
            wg3: Default::default(),
            wg15: Default::default(),
            ga1: Default::default(),
            ga2: Default::default(),
            ga3: Default::default(),
            ga4: Default::default(),
            ga16: Default::default(),
            grad_b: Default::default(),
            lw: Default::default(),
            take: Default::default(),
            cov0: Default::default(),
            cov1: Default::default(),
            cov2: Default::default(),
            cov3: Default::default(),
            has_frag: Default::default(),
            fsel: Default::default(),
            has_next: Default::default(),
            nsel: Default::default(),
            dead4: Default::default(),
            dead16: Default::default(),
            long: Default::default(),
            row_done: Default::default(),
            walk_end: Default::default(),
            at_last_row: Default::default(),
            fraw: Default::default(),
            rounded_u: Default::default(),
            depth: Default::default(),
            faddr: Default::default(),
            fsel10: Default::default(),
            load_walk: Default::default(),
            load_clear: Default::default(),
            rsx1_0: Default::default(),
            rsx1_1: Default::default(),
            rsx1_2: Default::default(),
            rsx2_0: Default::default(),
            rsx2_1: Default::default(),
            rsx2_2: Default::default(),
            rsx4_0: Default::default(),
            rsx4_1: Default::default(),
            rsx4_2: Default::default(),
            rsx3_0: Default::default(),
            rsx15_0: Default::default(),
            rsx16_0: Default::default(),
            rsx3_1: Default::default(),
            rsx15_1: Default::default(),
            rsx16_1: Default::default(),
            rsx3_2: Default::default(),
            rsx15_2: Default::default(),
            rsx16_2: Default::default(),
            c4_0: Default::default(),
            c16_0: Default::default(),
            c4_1: Default::default(),
            c16_1: Default::default(),
            c4_2: Default::default(),
            c16_2: Default::default(),
            t1_0: Default::default(),
            t2_0: Default::default(),
            t3_0: Default::default(),
            t15_0: Default::default(),
            t1_1: Default::default(),
            t2_1: Default::default(),
            t3_1: Default::default(),
            t15_1: Default::default(),
            t1_2: Default::default(),
            t2_2: Default::default(),
            t3_2: Default::default(),
            t15_2: Default::default(),
            ub0: Default::default(),
            ub1: Default::default(),
            ub2: Default::default(),
            lrn_0: Default::default(),
            lrn_1: Default::default(),
            lrn_2: Default::default(),
            ra1: Default::default(),
            ra2: Default::default(),
            ra4: Default::default(),
            uab: Default::default(),
            ra3: Default::default(),
            ra16: Default::default(),
            width: Constant::new((width as u64).into()),
            last_addr: Constant::new(((width * height - 1) as u64).into()),
            half: Constant::new((1i64 << 15).into()),
            depth_max: Constant::new(((1u64 << 24) - 1).into()),
            k0_24: Constant::new(0.into()),
            k0_15: Constant::new(0.into()),
            ks0_44: Constant::new(0i64.into()),
            ks0_56: Constant::new(0i64.into()),
            kz2: Constant::new(0.into()),
            kz3: Constant::new(0.into()),
            kz20: Constant::new(0.into()),
            kz24: Constant::new(0.into()),
            kz56: Constant::new(0.into()),
            kz44: Constant::new(0.into()),
            k0_10: Constant::new(0.into()),
            k1_10: Constant::new(1.into()),
            k15_10: Constant::new(15.into()),
            k16_10: Constant::new(16.into()),
            k5_10: Constant::new(5.into()),
            k6_10: Constant::new(6.into()),
            k7_10: Constant::new(7.into()),
            k17_10: Constant::new(17.into()),
            k18_10: Constant::new(18.into()),
            k19_10: Constant::new(19.into()),
            k31_10: Constant::new(31.into()),
            k16_20: Constant::new(16.into()),
            k2_10: Constant::new(2.into()),
            k3_10: Constant::new(3.into()),
            k4_10: Constant::new(4.into()),
            k1_20: Constant::new(1.into()),
            k2_20: Constant::new(2.into()),
            k3_20: Constant::new(3.into()),
            k4_20: Constant::new(4.into()),
            k0_20: Constant::new(0.into()),
            k0_2: Constant::new(0.into()),
            k1_6: Constant::new(1.into()),
            k2_6: Constant::new(2.into()),
            k4_6: Constant::new(4.into()),
            k1_2: Constant::new(1.into()),
            k2_2: Constant::new(2.into()),
            k3_2: Constant::new(3.into()),
            k1_3: Constant::new(1.into()),
            k2_3: Constant::new(2.into()),
            k3_3: Constant::new(3.into()),
            k4_3: Constant::new(4.into()),
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
            self, clock, state, x, y, bx0, by1, index, addr, addr_row, e0, e1, e2, ern0, ern1, ern2, sx1_0, sx2_0, sx3_0, sx4_0, sx15_0, sx1_1, sx2_1, sx3_1, sx4_1, sx15_1, sx1_2, sx2_2, sx3_2, sx4_2, sx15_2, sx16_0, sx16_1, sx16_2, s1_0, s2_0, s3_0, s15_0, s1_1, s2_1, s3_1, s15_1, s1_2, s2_2, s3_2, s15_2, sy0, sy1, sy2, nonpos0, nonpos1, nonpos2, rawh, rawh_row, rm, rg0, rg1, rg2, rg3, rg15, wrem, wg0, wg1, wg2, wg3, wg15, ga1, ga2, ga3, ga4, ga16, grad_b
        );
        // The sums behind the look-ahead signs of the step taken (set in its branch below).
        self.t1_0.next = self.ks0_44.val();
        self.t2_0.next = self.ks0_44.val();
        self.t3_0.next = self.ks0_44.val();
        self.t15_0.next = self.ks0_44.val();
        self.t1_1.next = self.ks0_44.val();
        self.t2_1.next = self.ks0_44.val();
        self.t3_1.next = self.ks0_44.val();
        self.t15_1.next = self.ks0_44.val();
        self.t1_2.next = self.ks0_44.val();
        self.t2_2.next = self.ks0_44.val();
        self.t3_2.next = self.ks0_44.val();
        self.t15_2.next = self.ks0_44.val();
        if self.state.q.val() == TravState::Walk {
            // ---- The window at (x, y) ----
            // The covered candidates, from the look-ahead signs only. The edge values of the step taken
            // and the signs at the window after it are summed in the step's branch below (every step's
            // sums are independent of the decision, which only selects among them; written per branch,
            // the RustHDL simulation forms only the taken step's sums).
            self.c4_0.next = self.e0.q.val() + self.sx4_0.q.val();
            self.c16_0.next = self.e0.q.val() + self.sx16_0.q.val();
            self.c4_1.next = self.e1.q.val() + self.sx4_1.q.val();
            self.c16_1.next = self.e1.q.val() + self.sx16_1.q.val();
            self.c4_2.next = self.e2.q.val() + self.sx4_2.q.val();
            self.c16_2.next = self.e2.q.val() + self.sx16_2.q.val();
            self.cov0.next = !self.e0.q.val().get_bit(43) & !self.e1.q.val().get_bit(43) & !self.e2.q.val().get_bit(43);
            self.cov1.next = !self.s1_0.q.val() & !self.s1_1.q.val() & !self.s1_2.q.val() & self.rg0.q.val();
            self.cov2.next = !self.s2_0.q.val() & !self.s2_1.q.val() & !self.s2_2.q.val() & self.rg1.q.val();
            self.cov3.next = !self.s3_0.q.val() & !self.s3_1.q.val() & !self.s3_2.q.val() & self.rg2.q.val();
            // The first covered candidate, and the next one after it (or the window's end, 4).
            self.has_frag.next = self.cov0.val() | self.cov1.val() | self.cov2.val() | self.cov3.val();
            self.fsel.next = self.k3_2.val();
            if self.cov2.val() {
                self.fsel.next = self.k2_2.val();
            }
            if self.cov1.val() {
                self.fsel.next = self.k1_2.val();
            }
            if self.cov0.val() {
                self.fsel.next = self.k0_2.val();
            }
            self.nsel.next = self.k4_3.val();
            self.has_next.next = false;
            if self.cov0.val() {
                if self.cov3.val() {
                    self.nsel.next = self.k3_3.val();
                    self.has_next.next = true;
                }
                if self.cov2.val() {
                    self.nsel.next = self.k2_3.val();
                    self.has_next.next = true;
                }
                if self.cov1.val() {
                    self.nsel.next = self.k1_3.val();
                    self.has_next.next = true;
                }
            } else if self.cov1.val() {
                if self.cov3.val() {
                    self.nsel.next = self.k3_3.val();
                    self.has_next.next = true;
                }
                if self.cov2.val() {
                    self.nsel.next = self.k2_3.val();
                    self.has_next.next = true;
                }
            } else if self.cov2.val() {
                if self.cov3.val() {
                    self.nsel.next = self.k3_3.val();
                    self.has_next.next = true;
                }
            }
            // The long skip: nothing covered in the window, and an edge negative at x and at x+15 (so at
            // every candidate between).
            self.long.next = !self.has_frag.val()
                & ((self.e0.q.val().get_bit(43) & self.s15_0.q.val())
                    | (self.e1.q.val().get_bit(43) & self.s15_1.q.val())
                    | (self.e2.q.val().get_bit(43) & self.s15_2.q.val()));
            // Nothing further right in this row: an edge negative at the skip's last candidate whose
            // step does not grow.
            self.dead4.next = (self.s3_0.q.val() & self.nonpos0.q.val())
                | (self.s3_1.q.val() & self.nonpos1.q.val())
                | (self.s3_2.q.val() & self.nonpos2.q.val());
            self.dead16.next = (self.s15_0.q.val() & self.nonpos0.q.val())
                | (self.s15_1.q.val() & self.nonpos1.q.val())
                | (self.s15_2.q.val() & self.nonpos2.q.val());
            self.row_done.next = !self.has_next.val() & (!self.rg3.q.val() | self.dead4.val());
            if self.long.val() {
                self.row_done.next = !self.rg15.q.val() | self.dead16.val();
            }
            self.at_last_row.next = self.y.q.val() == self.by1.q.val();
            self.walk_end.next = self.row_done.val() & self.at_last_row.val();
            // The fragment: its raw depth, address and depth.
            self.fraw.next = self.rawh.q.val();
            self.faddr.next = self.addr.q.val();
            // (The additions sit in the branches: the RustHDL simulation then does only the one taken.)
            if self.fsel.val() == self.k1_2.val() {
                self.fraw.next = self.rawh.q.val() + self.ga1.q.val();
                self.faddr.next = self.addr.q.val() + self.k1_20.val();
            }
            if self.fsel.val() == self.k2_2.val() {
                self.fraw.next = self.rawh.q.val() + self.ga2.q.val();
                self.faddr.next = self.addr.q.val() + self.k2_20.val();
            }
            if self.fsel.val() == self.k3_2.val() {
                self.fraw.next = self.rawh.q.val() + self.ga3.q.val();
                self.faddr.next = self.addr.q.val() + self.k3_20.val();
            }
            self.rounded_u.next = unsigned_cast(self.fraw.val());
            self.depth.next = self.rounded_u.val().get_bits::<24>(16);
            if self.rounded_u.val().get_bits::<15>(40) != self.k0_15.val() {
                self.depth.next = self.depth_max.val();
            }
            if self.fraw.val().get_bit(55) {
                self.depth.next = self.k0_24.val();
            }
        } else {
            self.c4_0.next = self.ks0_44.val();
            self.c16_0.next = self.ks0_44.val();
            self.c4_1.next = self.ks0_44.val();
            self.c16_1.next = self.ks0_44.val();
            self.c4_2.next = self.ks0_44.val();
            self.c16_2.next = self.ks0_44.val();
            self.cov0.next = false;
            self.cov1.next = false;
            self.cov2.next = false;
            self.cov3.next = false;
            self.has_frag.next = false;
            self.fsel.next = self.kz2.val();
            self.nsel.next = self.kz3.val();
            self.has_next.next = false;
            self.long.next = false;
            self.dead4.next = false;
            self.dead16.next = false;
            self.row_done.next = false;
            self.at_last_row.next = false;
            self.walk_end.next = false;
            self.fraw.next = self.ks0_56.val();
            self.faddr.next = self.kz20.val();
            self.rounded_u.next = self.kz56.val();
            self.depth.next = self.kz24.val();
        }
        if self.rec_valid.val() {
            // The multiples of a record's steps (the rest are summed in the load branch).
            self.rsx1_0.next = signed_bit_cast_safe::<44, 30>(self.rec_sx0.val());
            self.ub0.next = unsigned_cast(self.rsx1_0.val());
            self.rsx2_0.next = signed_cast(self.ub0.val() << self.k1_6.val());
            self.rsx4_0.next = signed_cast(self.ub0.val() << self.k2_6.val());
            self.rsx16_0.next = signed_cast(self.ub0.val() << self.k4_6.val());
            self.rsx3_0.next = signed_bit_cast_safe::<44, 32>(self.rec_sx3_0.val());
            self.rsx15_0.next = signed_bit_cast_safe::<44, 34>(self.rec_sx15_0.val());
            self.lrn_0.next = self.rec_e0.val() + signed_bit_cast_safe::<44, 30>(self.rec_sy0.val());
            self.rsx1_1.next = signed_bit_cast_safe::<44, 30>(self.rec_sx1.val());
            self.ub1.next = unsigned_cast(self.rsx1_1.val());
            self.rsx2_1.next = signed_cast(self.ub1.val() << self.k1_6.val());
            self.rsx4_1.next = signed_cast(self.ub1.val() << self.k2_6.val());
            self.rsx16_1.next = signed_cast(self.ub1.val() << self.k4_6.val());
            self.rsx3_1.next = signed_bit_cast_safe::<44, 32>(self.rec_sx3_1.val());
            self.rsx15_1.next = signed_bit_cast_safe::<44, 34>(self.rec_sx15_1.val());
            self.lrn_1.next = self.rec_e1.val() + signed_bit_cast_safe::<44, 30>(self.rec_sy1.val());
            self.rsx1_2.next = signed_bit_cast_safe::<44, 30>(self.rec_sx2.val());
            self.ub2.next = unsigned_cast(self.rsx1_2.val());
            self.rsx2_2.next = signed_cast(self.ub2.val() << self.k1_6.val());
            self.rsx4_2.next = signed_cast(self.ub2.val() << self.k2_6.val());
            self.rsx16_2.next = signed_cast(self.ub2.val() << self.k4_6.val());
            self.rsx3_2.next = signed_bit_cast_safe::<44, 32>(self.rec_sx3_2.val());
            self.rsx15_2.next = signed_bit_cast_safe::<44, 34>(self.rec_sx15_2.val());
            self.lrn_2.next = self.rec_e2.val() + signed_bit_cast_safe::<44, 30>(self.rec_sy2.val());
            self.ra1.next = signed_bit_cast_safe::<56, 40>(self.rec_a.val());
            self.uab.next = unsigned_cast(self.ra1.val());
            self.ra2.next = signed_cast(self.uab.val() << self.k1_6.val());
            self.ra4.next = signed_cast(self.uab.val() << self.k2_6.val());
            self.ra16.next = signed_cast(self.uab.val() << self.k4_6.val());
            self.ra3.next = signed_bit_cast_safe::<56, 42>(self.rec_a3.val());

        } else {
            self.rsx1_0.next = self.ks0_44.val();
            self.rsx2_0.next = self.ks0_44.val();
            self.rsx4_0.next = self.ks0_44.val();
            self.ub0.next = self.kz44.val();
            self.rsx3_0.next = self.ks0_44.val();
            self.rsx15_0.next = self.ks0_44.val();
            self.rsx16_0.next = self.ks0_44.val();
            self.lrn_0.next = self.ks0_44.val();
            self.rsx1_1.next = self.ks0_44.val();
            self.rsx2_1.next = self.ks0_44.val();
            self.rsx4_1.next = self.ks0_44.val();
            self.ub1.next = self.kz44.val();
            self.rsx3_1.next = self.ks0_44.val();
            self.rsx15_1.next = self.ks0_44.val();
            self.rsx16_1.next = self.ks0_44.val();
            self.lrn_1.next = self.ks0_44.val();
            self.rsx1_2.next = self.ks0_44.val();
            self.rsx2_2.next = self.ks0_44.val();
            self.rsx4_2.next = self.ks0_44.val();
            self.ub2.next = self.kz44.val();
            self.rsx3_2.next = self.ks0_44.val();
            self.rsx15_2.next = self.ks0_44.val();
            self.rsx16_2.next = self.ks0_44.val();
            self.lrn_2.next = self.ks0_44.val();
            self.ra1.next = self.ks0_56.val();
            self.ra2.next = self.ks0_56.val();
            self.ra4.next = self.ks0_56.val();
            self.uab.next = self.kz56.val();
            self.ra3.next = self.ks0_56.val();
            self.ra16.next = self.ks0_56.val();
        }
        self.rec_ready.next = false;
        self.load_walk.next = false;
        self.load_clear.next = false;
        self.tok.next.kind = self.tok_none.val();
        self.tok.next.covered = false;
        self.tok.next.last = false;
        self.tok.next.addr = self.k0_20.val();
        self.tok.next.z = self.k0_24.val();
        self.tok.next.index = self.index.q.val();
        self.fsel10.next = bit_cast::<10, 2>(self.fsel.val());
        self.tok.next.x = self.k0_10.val();
        self.tok.next.y = self.k0_10.val();
        self.tok.next.eof = false;
        self.tok.next.culled = false;
        self.tok.next.zero_area = false;
        match self.state.q.val() {
            TravState::Idle => {
                self.tok.next.index = self.rec_index.val();
                if self.rec_valid.val() {
                    if (self.rec_kind.val() == self.rec_frame.val()) | (self.rec_kind.val() == self.rec_walk.val()) {
                        self.rec_ready.next = true;
                    } else if self.result_free.val() {
                        self.rec_ready.next = true;
                        self.tok.next.kind = self.tok_result.val();
                        self.tok.next.eof = self.rec_kind.val() == self.rec_eof.val();
                        self.tok.next.culled = self.rec_culled.val();
                        self.tok.next.zero_area = self.rec_zero_area.val();
                    }
                    self.load_clear.next = (self.rec_kind.val() == self.rec_frame.val()) & self.rec_clear.val();
                    self.load_walk.next = self.rec_kind.val() == self.rec_walk.val();
                }
            }
            TravState::Clear => {
                self.tok.next.kind = self.tok_clear.val();
                self.tok.next.addr = self.addr.q.val();
                self.addr.d.next = self.addr.q.val() + self.k1_20.val();
                if self.addr.q.val() == self.last_addr.val() {
                    self.state.d.next = TravState::Idle;
                }
            }
            TravState::Walk => {
                if !self.walk_end.val() | self.result_free.val() {
                    if self.has_frag.val() | self.walk_end.val() {
                        self.tok.next.kind = self.tok_frag.val();
                        self.tok.next.covered = self.has_frag.val();
                        self.tok.next.last = self.walk_end.val();
                        self.tok.next.addr = self.faddr.val();
                        self.tok.next.x = self.x.q.val() + self.fsel10.val();
                        self.tok.next.y = self.y.q.val();
                    }
                    if self.has_frag.val() {
                        self.tok.next.z = self.depth.val();
                    }
                    if self.walk_end.val() {
                        self.state.d.next = TravState::Idle;
                        // The next triangle or frame start is taken in this cycle.
                        if self.rec_valid.val() & ((self.rec_kind.val() == self.rec_frame.val()) | (self.rec_kind.val() == self.rec_walk.val())) {
                            self.rec_ready.next = true;
                            self.load_clear.next = (self.rec_kind.val() == self.rec_frame.val()) & self.rec_clear.val();
                            self.load_walk.next = self.rec_kind.val() == self.rec_walk.val();
                        }
                    } else if self.row_done.val() {
                        self.x.d.next = self.bx0.q.val();
                        self.y.d.next = self.y.q.val() + self.k1_10.val();
                        self.rm.d.next = self.wrem.q.val();
                        self.rg0.d.next = self.wg0.q.val();
                        self.rg1.d.next = self.wg1.q.val();
                        self.rg2.d.next = self.wg2.q.val();
                        self.rg3.d.next = self.wg3.q.val();
                        self.rg15.d.next = self.wg15.q.val();
                        self.ern0.d.next = self.ern0.q.val() + self.sy0.q.val();
                        self.e0.d.next = self.ern0.q.val();
                        self.t1_0.next = self.ern0.q.val() + self.sx1_0.q.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.ern0.q.val() + self.sx2_0.q.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.ern0.q.val() + self.sx3_0.q.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.ern0.q.val() + self.sx15_0.q.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.ern1.d.next = self.ern1.q.val() + self.sy1.q.val();
                        self.e1.d.next = self.ern1.q.val();
                        self.t1_1.next = self.ern1.q.val() + self.sx1_1.q.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.ern1.q.val() + self.sx2_1.q.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.ern1.q.val() + self.sx3_1.q.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.ern1.q.val() + self.sx15_1.q.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.ern2.d.next = self.ern2.q.val() + self.sy2.q.val();
                        self.e2.d.next = self.ern2.q.val();
                        self.t1_2.next = self.ern2.q.val() + self.sx1_2.q.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.ern2.q.val() + self.sx2_2.q.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.ern2.q.val() + self.sx3_2.q.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.ern2.q.val() + self.sx15_2.q.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh_row.d.next = self.rawh_row.q.val() + self.grad_b.q.val();
                        self.rawh.d.next = self.rawh_row.q.val() + self.grad_b.q.val();
                        self.addr_row.d.next = self.addr_row.q.val() + self.width.val();
                        self.addr.d.next = self.addr_row.q.val() + self.width.val();
                    } else if self.nsel.val() == self.k1_3.val() {
                        self.x.d.next = self.x.q.val() + self.k1_10.val();
                        self.rm.d.next = self.rm.q.val() - self.k1_10.val();
                        self.rg0.d.next = self.rm.q.val() > self.k1_10.val();
                        self.rg1.d.next = self.rm.q.val() > self.k2_10.val();
                        self.rg2.d.next = self.rm.q.val() > self.k3_10.val();
                        self.rg3.d.next = self.rm.q.val() > self.k4_10.val();
                        self.rg15.d.next = self.rm.q.val() > self.k16_10.val();
                        self.e0.d.next = self.e0.q.val() + self.sx1_0.q.val();
                        self.t1_0.next = self.e0.q.val() + self.sx2_0.q.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.e0.q.val() + self.sx3_0.q.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.c4_0.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.c16_0.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.e1.d.next = self.e1.q.val() + self.sx1_1.q.val();
                        self.t1_1.next = self.e1.q.val() + self.sx2_1.q.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.e1.q.val() + self.sx3_1.q.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.c4_1.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.c16_1.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.e2.d.next = self.e2.q.val() + self.sx1_2.q.val();
                        self.t1_2.next = self.e2.q.val() + self.sx2_2.q.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.e2.q.val() + self.sx3_2.q.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.c4_2.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.c16_2.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh.d.next = self.rawh.q.val() + self.ga1.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k1_20.val();
                    } else if self.nsel.val() == self.k2_3.val() {
                        self.x.d.next = self.x.q.val() + self.k2_10.val();
                        self.rm.d.next = self.rm.q.val() - self.k2_10.val();
                        self.rg0.d.next = self.rm.q.val() > self.k2_10.val();
                        self.rg1.d.next = self.rm.q.val() > self.k3_10.val();
                        self.rg2.d.next = self.rm.q.val() > self.k4_10.val();
                        self.rg3.d.next = self.rm.q.val() > self.k5_10.val();
                        self.rg15.d.next = self.rm.q.val() > self.k17_10.val();
                        self.e0.d.next = self.e0.q.val() + self.sx2_0.q.val();
                        self.t1_0.next = self.e0.q.val() + self.sx3_0.q.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.c4_0.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.c4_0.val() + self.sx1_0.q.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.c16_0.val() + self.sx1_0.q.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.e1.d.next = self.e1.q.val() + self.sx2_1.q.val();
                        self.t1_1.next = self.e1.q.val() + self.sx3_1.q.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.c4_1.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.c4_1.val() + self.sx1_1.q.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.c16_1.val() + self.sx1_1.q.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.e2.d.next = self.e2.q.val() + self.sx2_2.q.val();
                        self.t1_2.next = self.e2.q.val() + self.sx3_2.q.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.c4_2.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.c4_2.val() + self.sx1_2.q.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.c16_2.val() + self.sx1_2.q.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh.d.next = self.rawh.q.val() + self.ga2.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k2_20.val();
                    } else if self.nsel.val() == self.k3_3.val() {
                        self.x.d.next = self.x.q.val() + self.k3_10.val();
                        self.rm.d.next = self.rm.q.val() - self.k3_10.val();
                        self.rg0.d.next = self.rm.q.val() > self.k3_10.val();
                        self.rg1.d.next = self.rm.q.val() > self.k4_10.val();
                        self.rg2.d.next = self.rm.q.val() > self.k5_10.val();
                        self.rg3.d.next = self.rm.q.val() > self.k6_10.val();
                        self.rg15.d.next = self.rm.q.val() > self.k18_10.val();
                        self.e0.d.next = self.e0.q.val() + self.sx3_0.q.val();
                        self.t1_0.next = self.c4_0.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.c4_0.val() + self.sx1_0.q.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.c4_0.val() + self.sx2_0.q.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.c16_0.val() + self.sx2_0.q.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.e1.d.next = self.e1.q.val() + self.sx3_1.q.val();
                        self.t1_1.next = self.c4_1.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.c4_1.val() + self.sx1_1.q.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.c4_1.val() + self.sx2_1.q.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.c16_1.val() + self.sx2_1.q.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.e2.d.next = self.e2.q.val() + self.sx3_2.q.val();
                        self.t1_2.next = self.c4_2.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.c4_2.val() + self.sx1_2.q.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.c4_2.val() + self.sx2_2.q.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.c16_2.val() + self.sx2_2.q.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh.d.next = self.rawh.q.val() + self.ga3.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k3_20.val();
                    } else if self.long.val() {
                        self.x.d.next = self.x.q.val() + self.k16_10.val();
                        self.rm.d.next = self.rm.q.val() - self.k16_10.val();
                        self.rg0.d.next = self.rm.q.val() > self.k16_10.val();
                        self.rg1.d.next = self.rm.q.val() > self.k17_10.val();
                        self.rg2.d.next = self.rm.q.val() > self.k18_10.val();
                        self.rg3.d.next = self.rm.q.val() > self.k19_10.val();
                        self.rg15.d.next = self.rm.q.val() > self.k31_10.val();
                        self.e0.d.next = self.c16_0.val();
                        self.t1_0.next = self.c16_0.val() + self.sx1_0.q.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.c16_0.val() + self.sx2_0.q.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.c16_0.val() + self.sx3_0.q.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.c16_0.val() + self.sx15_0.q.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.e1.d.next = self.c16_1.val();
                        self.t1_1.next = self.c16_1.val() + self.sx1_1.q.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.c16_1.val() + self.sx2_1.q.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.c16_1.val() + self.sx3_1.q.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.c16_1.val() + self.sx15_1.q.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.e2.d.next = self.c16_2.val();
                        self.t1_2.next = self.c16_2.val() + self.sx1_2.q.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.c16_2.val() + self.sx2_2.q.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.c16_2.val() + self.sx3_2.q.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.c16_2.val() + self.sx15_2.q.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh.d.next = self.rawh.q.val() + self.ga16.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k16_20.val();
                    } else {
                        self.x.d.next = self.x.q.val() + self.k4_10.val();
                        self.rm.d.next = self.rm.q.val() - self.k4_10.val();
                        self.rg0.d.next = self.rm.q.val() > self.k4_10.val();
                        self.rg1.d.next = self.rm.q.val() > self.k5_10.val();
                        self.rg2.d.next = self.rm.q.val() > self.k6_10.val();
                        self.rg3.d.next = self.rm.q.val() > self.k7_10.val();
                        self.rg15.d.next = self.rm.q.val() > self.k19_10.val();
                        self.e0.d.next = self.c4_0.val();
                        self.t1_0.next = self.c4_0.val() + self.sx1_0.q.val();
                        self.s1_0.d.next = self.t1_0.val().get_bit(43);
                        self.t2_0.next = self.c4_0.val() + self.sx2_0.q.val();
                        self.s2_0.d.next = self.t2_0.val().get_bit(43);
                        self.t3_0.next = self.c4_0.val() + self.sx3_0.q.val();
                        self.s3_0.d.next = self.t3_0.val().get_bit(43);
                        self.t15_0.next = self.c16_0.val() + self.sx3_0.q.val();
                        self.s15_0.d.next = self.t15_0.val().get_bit(43);
                        self.e1.d.next = self.c4_1.val();
                        self.t1_1.next = self.c4_1.val() + self.sx1_1.q.val();
                        self.s1_1.d.next = self.t1_1.val().get_bit(43);
                        self.t2_1.next = self.c4_1.val() + self.sx2_1.q.val();
                        self.s2_1.d.next = self.t2_1.val().get_bit(43);
                        self.t3_1.next = self.c4_1.val() + self.sx3_1.q.val();
                        self.s3_1.d.next = self.t3_1.val().get_bit(43);
                        self.t15_1.next = self.c16_1.val() + self.sx3_1.q.val();
                        self.s15_1.d.next = self.t15_1.val().get_bit(43);
                        self.e2.d.next = self.c4_2.val();
                        self.t1_2.next = self.c4_2.val() + self.sx1_2.q.val();
                        self.s1_2.d.next = self.t1_2.val().get_bit(43);
                        self.t2_2.next = self.c4_2.val() + self.sx2_2.q.val();
                        self.s2_2.d.next = self.t2_2.val().get_bit(43);
                        self.t3_2.next = self.c4_2.val() + self.sx3_2.q.val();
                        self.s3_2.d.next = self.t3_2.val().get_bit(43);
                        self.t15_2.next = self.c16_2.val() + self.sx3_2.q.val();
                        self.s15_2.d.next = self.t15_2.val().get_bit(43);
                        self.rawh.d.next = self.rawh.q.val() + self.ga4.q.val();
                        self.addr.d.next = self.addr.q.val() + self.k4_20.val();
                    }
                }
            }
            _ => {
                self.state.d.next = TravState::Idle;
            }
        }
        // Taking a record (from Idle, or in the cycle that ends a walk).
        if self.load_clear.val() {
            self.addr.d.next = self.k0_20.val();
            self.state.d.next = TravState::Clear;
        }
        self.lw.next = self.rec_bx1.val() - self.rec_bx0.val();
        // The per-triangle constants (steps and their multiples, the depth steps, the box's width and
        // flags): internal to the walk, so they follow the record head whenever no walk is on and in
        // the cycle that ends one (its end token issued). Their clock enable is then the walk's end, the
        // head's valid and `result_free`, not `load_walk` (which also decodes the record's kind): a
        // shorter path to some 1 300 enables.
        // A walk starts only by a load, from Idle or at a walk's end, and both cycles take them.
        self.take.next = (!(self.state.q.val() == TravState::Walk) & self.rec_valid.val()) | (self.walk_end.val() & self.result_free.val());
        if self.take.val() {
            self.wrem.d.next = self.lw.val();
            self.wg0.d.next = self.lw.val() > self.k0_10.val();
            self.wg1.d.next = self.lw.val() > self.k1_10.val();
            self.wg2.d.next = self.lw.val() > self.k2_10.val();
            self.wg3.d.next = self.lw.val() > self.k3_10.val();
            self.wg15.d.next = self.lw.val() > self.k15_10.val();
            self.bx0.d.next = self.rec_bx0.val();
            self.by1.d.next = self.rec_by1.val();
            self.sx1_0.d.next = self.rsx1_0.val();
            self.sx2_0.d.next = self.rsx2_0.val();
            self.sx3_0.d.next = self.rsx3_0.val();
            self.sx16_0.d.next = self.rsx16_0.val();
            self.sx4_0.d.next = self.rsx4_0.val();
            self.sx15_0.d.next = self.rsx15_0.val();
            self.sy0.d.next = signed_bit_cast_safe::<44, 30>(self.rec_sy0.val());
            self.nonpos0.d.next = self.rec_sx0.val().get_bit(29) | (self.rsx1_0.val() == self.ks0_44.val());
            self.sx1_1.d.next = self.rsx1_1.val();
            self.sx2_1.d.next = self.rsx2_1.val();
            self.sx3_1.d.next = self.rsx3_1.val();
            self.sx16_1.d.next = self.rsx16_1.val();
            self.sx4_1.d.next = self.rsx4_1.val();
            self.sx15_1.d.next = self.rsx15_1.val();
            self.sy1.d.next = signed_bit_cast_safe::<44, 30>(self.rec_sy1.val());
            self.nonpos1.d.next = self.rec_sx1.val().get_bit(29) | (self.rsx1_1.val() == self.ks0_44.val());
            self.sx1_2.d.next = self.rsx1_2.val();
            self.sx2_2.d.next = self.rsx2_2.val();
            self.sx3_2.d.next = self.rsx3_2.val();
            self.sx16_2.d.next = self.rsx16_2.val();
            self.sx4_2.d.next = self.rsx4_2.val();
            self.sx15_2.d.next = self.rsx15_2.val();
            self.sy2.d.next = signed_bit_cast_safe::<44, 30>(self.rec_sy2.val());
            self.nonpos2.d.next = self.rec_sx2.val().get_bit(29) | (self.rsx1_2.val() == self.ks0_44.val());
            self.ga1.d.next = self.ra1.val();
            self.ga2.d.next = self.ra2.val();
            self.ga3.d.next = self.ra3.val();
            self.ga4.d.next = self.ra4.val();
            self.ga16.d.next = self.ra16.val();
            self.grad_b.d.next = signed_bit_cast_safe::<56, 40>(self.rec_b.val());
        }
        if self.load_walk.val() {
            self.rm.d.next = self.lw.val();
            self.rg0.d.next = self.lw.val() > self.k0_10.val();
            self.rg1.d.next = self.lw.val() > self.k1_10.val();
            self.rg2.d.next = self.lw.val() > self.k2_10.val();
            self.rg3.d.next = self.lw.val() > self.k3_10.val();
            self.rg15.d.next = self.lw.val() > self.k15_10.val();
            self.x.d.next = self.rec_bx0.val();
            self.y.d.next = self.rec_by0.val();
            self.index.d.next = self.rec_index.val();
            self.addr.d.next = self.rec_addr.val();
            self.addr_row.d.next = self.rec_addr.val();
            self.e0.d.next = self.rec_e0.val();
            self.ern0.d.next = self.lrn_0.val();
            self.t1_0.next = self.rec_e0.val() + self.rsx1_0.val();
            self.s1_0.d.next = self.t1_0.val().get_bit(43);
            self.t2_0.next = self.rec_e0.val() + self.rsx2_0.val();
            self.s2_0.d.next = self.t2_0.val().get_bit(43);
            self.t3_0.next = self.rec_e0.val() + self.rsx3_0.val();
            self.s3_0.d.next = self.t3_0.val().get_bit(43);
            self.t15_0.next = self.rec_e0.val() + self.rsx15_0.val();
            self.s15_0.d.next = self.t15_0.val().get_bit(43);
            self.e1.d.next = self.rec_e1.val();
            self.ern1.d.next = self.lrn_1.val();
            self.t1_1.next = self.rec_e1.val() + self.rsx1_1.val();
            self.s1_1.d.next = self.t1_1.val().get_bit(43);
            self.t2_1.next = self.rec_e1.val() + self.rsx2_1.val();
            self.s2_1.d.next = self.t2_1.val().get_bit(43);
            self.t3_1.next = self.rec_e1.val() + self.rsx3_1.val();
            self.s3_1.d.next = self.t3_1.val().get_bit(43);
            self.t15_1.next = self.rec_e1.val() + self.rsx15_1.val();
            self.s15_1.d.next = self.t15_1.val().get_bit(43);
            self.e2.d.next = self.rec_e2.val();
            self.ern2.d.next = self.lrn_2.val();
            self.t1_2.next = self.rec_e2.val() + self.rsx1_2.val();
            self.s1_2.d.next = self.t1_2.val().get_bit(43);
            self.t2_2.next = self.rec_e2.val() + self.rsx2_2.val();
            self.s2_2.d.next = self.t2_2.val().get_bit(43);
            self.t3_2.next = self.rec_e2.val() + self.rsx3_2.val();
            self.s3_2.d.next = self.t3_2.val().get_bit(43);
            self.t15_2.next = self.rec_e2.val() + self.rsx15_2.val();
            self.s15_2.d.next = self.t15_2.val().get_bit(43);
            self.rawh.d.next = self.rec_raw.val() + self.half.val();
            self.rawh_row.d.next = self.rec_raw.val() + self.half.val();
            self.state.d.next = TravState::Walk;
        }
    }
}
