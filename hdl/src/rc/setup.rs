//! `setup`: the RC's triangle setup (seed 001 §2.3.1: Pineda edge functions, eq. 5; the depth plane
//! with one reciprocal per triangle, eqs. 6-7), bit-exact with `golden::raster::setup`.
//!
//! ```text
//!              +--------------------------------------------+
//!  cmd ------->| first stage: Idle -> Det -> Order ->       |
//!  (valid/     |   Edges(6) -> WaitRecip -> Hand            |
//!   ready)     |   2 x MulS 25x18 (a*b - c*d per clock),    |
//!              |   reciprocal (25 steps, 3 per clock)       |
//!              |        | record copied at Hand (b_*)       |
//!              |        v                                   |--> rec_valid, rec_kind, rec_index,
//!              | second stage: Empty -> Plane(7) -> Out     |    rec_culled, rec_zero_area,
//!              |   1 x MulS 44x26 (plane products)          |    rec_bx0/bx1/by0/by1, rec_addr,
//!  clock ----->|                                            |    rec_e0..2, rec_sx0..2, rec_sy0..2,
//!              +--------------------------------------------+    rec_raw, rec_a, rec_b <-- rec_ready
//! ```
//!
//! Two stages, each holding one triangle, so that the first stage works on the next triangle while
//! the second computes the depth plane of the last (`golden::cycle::rc` models the same schedule).
//! Schedule of a command accepted in cycle t (one state per cycle unless said otherwise):
//! * t+1 `Det`: det = dx10*dy20 - dx20*dy10 (two 17x17 products on the dot-difference unit).
//! * t+1 `Det` also finds the clamped bounding box `[(min+7)>>4, (max-8)>>4]` (it does not depend on
//!   the vertex order) and registers it.
//! * t+2 `Order`: zero area / cull decision from det's sign, the cull mode and the front face; swap
//!   vertices 1 and 2 if det < 0 (canonical order); start the reciprocal of |det|. Culled or empty
//!   box: go to `Hand`. (A frame start or end of frame goes from `Idle` to `Hand` at t+1.)
//! * t+3..t+8 `Edges` 0..5 (during the division; edge k's operands are found in phase k and multiplied
//!   in phase k + 1): edge k's value at the box's first pixel
//!   `E = dx*(16*Y0+8-a.y) - dy*(16*X0+8-a.x) - bias` and its steps (-16*dy, 16*dx); then the depth
//!   numerators na = dz10*dy20 - dz20*dy10 and nb = dz20*dx10 - dz10*dx20; the start address
//!   Y0*W + X0.
//! * `WaitRecip` until the reciprocal is ready (t+12 for a request accepted in t+2: three division
//!   steps per clock).
//! * t+13 `Hand`: when the second stage is `Empty` in this cycle, the record (and the vertex 0, the
//!   numerators and the reciprocal the plane needs) is copied into its `b_*` registers and the first
//!   stage is `Idle` (`cmd.ready`) from the next cycle; otherwise it waits in `Hand`.
//! * Second stage, t+14..t+20 `Plane` 0..6 (a drawn triangle) on one 44x26 multiplier whose product is
//!   registered (each product is used in the phase after its operands):
//!   `A = sat40(round(na*mant >> (shift+4)))`, B likewise, `C = (z0 << 16) + round(A*(8-x0) +
//!   B*(8-y0) >> 4)`, raw = C + A*X0 + B*Y0 (the depth plane's raw value at the box's first pixel).
//! * t+21 `Out` (any other record: the cycle after its hand-over): the record is offered until
//!   `rec_ready`; `Empty` the cycle after. Drawn triangles back to back: one every 14 cycles.
//!
//! Widths: inputs are any 16-bit S11.4 values, so |dx|, |dy| < 2^16; E stays below 2^34 in magnitude
//! on the screen (36-bit registers). na, nb < 2^42; na*mant < 2^67 (70-bit product). C never
//! saturates at 56 bits (|A| <= 2^39, |8-x0| <= 2^15: |C| < 2^51), so the golden model's saturation
//! of C needs no hardware; raw < 2^52 anywhere in the box (56-bit registers).

use super::reciprocal::Reciprocal;
use super::RcCommand;
use crate::common::{signed_bit_cast_safe, MulS, StreamIn};
use rust_hdl::prelude::*;

/// Record kinds handed to the traversal.
pub const REC_FRAME: u64 = 0;
pub const REC_SKIP: u64 = 1;
pub const REC_WALK: u64 = 2;
pub const REC_EOF: u64 = 3;

/// The first stage: a command from `Idle` to `Hand` (its record moves to the second stage).
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum SetupState {
    Idle,
    Det,
    Order,
    Edges,
    WaitRecip,
    Hand,
}

/// The second stage: a drawn triangle's depth plane, then the record offered to the traversal.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum PlaneState {
    Empty,
    Plane,
    Out,
}

#[derive(LogicBlock)]
pub struct Setup {
    pub clock: Signal<In, Clock>,
    // From the command port
    /// Commands; `ready` is high exactly in `Idle`.
    pub cmd: StreamIn<RcCommand>,
    // To the traversal (held while `rec_valid`, taken with `rec_ready`)
    /// A record is offered.
    pub rec_valid: Signal<Out, Bit>,
    /// The traversal takes the record this cycle.
    pub rec_ready: Signal<In, Bit>,
    /// REC_FRAME, REC_SKIP (result without traversal), REC_WALK or REC_EOF.
    pub rec_kind: Signal<Out, Bits<2>>,
    /// Frame start: clear the buffers.
    pub rec_clear: Signal<Out, Bit>,
    /// Triangle index.
    pub rec_index: Signal<Out, Bits<16>>,
    /// Skip: culled (zero area or by the cull mode); zero area.
    pub rec_culled: Signal<Out, Bit>,
    pub rec_zero_area: Signal<Out, Bit>,
    /// Clamped bounding box, inclusive, in pixels.
    pub rec_bx0: Signal<Out, Bits<10>>,
    pub rec_bx1: Signal<Out, Bits<10>>,
    pub rec_by0: Signal<Out, Bits<10>>,
    pub rec_by1: Signal<Out, Bits<10>>,
    /// Address of (bx0, by0): by0 * width + bx0.
    pub rec_addr: Signal<Out, Bits<20>>,
    /// Biased edge functions at (bx0, by0); inside is all >= 0.
    pub rec_e0: Signal<Out, Signed<36>>,
    pub rec_e1: Signal<Out, Signed<36>>,
    pub rec_e2: Signal<Out, Signed<36>>,
    /// Edge increments per pixel in x (-16*dy) and per row (16*dx).
    pub rec_sx0: Signal<Out, Signed<22>>,
    pub rec_sx1: Signal<Out, Signed<22>>,
    pub rec_sx2: Signal<Out, Signed<22>>,
    pub rec_sy0: Signal<Out, Signed<22>>,
    pub rec_sy1: Signal<Out, Signed<22>>,
    pub rec_sy2: Signal<Out, Signed<22>>,
    /// Depth plane: raw value (16 fraction bits) at (bx0, by0), and its increments A (x), B (y).
    pub rec_raw: Signal<Out, Signed<56>>,
    pub rec_a: Signal<Out, Signed<40>>,
    pub rec_b: Signal<Out, Signed<40>>,

    // Children
    recip: Reciprocal,
    mul_l: MulS<25, 18, 43>,
    mul_r: MulS<25, 18, 43>,
    mul_w: MulS<44, 26, 70>,

    // Registers
    state: DFF<SetupState>,
    phase: DFF<Bits<3>>,
    kind: DFF<Bits<2>>,
    /// The clamped bounding box and whether it is empty, found in `Det` (order-independent).
    nbx0: DFF<Bits<10>>,
    nbx1: DFF<Bits<10>>,
    nby0: DFF<Bits<10>>,
    nby1: DFF<Bits<10>>,
    nbox_empty: DFF<Bit>,
    clear: DFF<Bit>,
    index: DFF<Bits<16>>,
    cull: DFF<Bits<2>>,
    front_cw: DFF<Bit>,
    vx0: DFF<Signed<16>>,
    vy0: DFF<Signed<16>>,
    vz0: DFF<Bits<24>>,
    vx1: DFF<Signed<16>>,
    vy1: DFF<Signed<16>>,
    vz1: DFF<Bits<24>>,
    vx2: DFF<Signed<16>>,
    vy2: DFF<Signed<16>>,
    vz2: DFF<Bits<24>>,
    det: DFF<Signed<36>>,
    culled: DFF<Bit>,
    zero_area: DFF<Bit>,
    bx0: DFF<Bits<10>>,
    bx1: DFF<Bits<10>>,
    by0: DFF<Bits<10>>,
    by1: DFF<Bits<10>>,
    addr: DFF<Bits<20>>,
    e0: DFF<Signed<36>>,
    e1: DFF<Signed<36>>,
    e2: DFF<Signed<36>>,
    sx0: DFF<Signed<22>>,
    /// An edge's multiplier operands, fill-rule flag and steps, found in the `Edges` phase of its
    /// number and used in the next: the vertex mux and differences and the products are never one
    /// clock period.
    r_la: DFF<Signed<25>>,
    r_lb: DFF<Signed<18>>,
    r_ra: DFF<Signed<25>>,
    r_rb: DFF<Signed<18>>,
    r_tl: DFF<Bit>,
    r_sx: DFF<Signed<22>>,
    r_sy: DFF<Signed<22>>,
    sx1: DFF<Signed<22>>,
    sx2: DFF<Signed<22>>,
    sy0: DFF<Signed<22>>,
    sy1: DFF<Signed<22>>,
    sy2: DFF<Signed<22>>,
    na: DFF<Signed<44>>,
    nb: DFF<Signed<44>>,
    mant: DFF<Bits<25>>,
    shamt: DFF<Bits<6>>,
    prod: DFF<Bits<70>>,
    grad_a: DFF<Signed<40>>,
    grad_b: DFF<Signed<40>>,
    acc: DFF<Signed<58>>,
    raw: DFF<Signed<56>>,
    /// The second stage's state, phase and copy of the record (taken at the hand-over).
    bstate: DFF<PlaneState>,
    bphase: DFF<Bits<3>>,
    b_kind: DFF<Bits<2>>,
    b_clear: DFF<Bit>,
    b_index: DFF<Bits<16>>,
    b_culled: DFF<Bit>,
    b_zero_area: DFF<Bit>,
    b_bx0: DFF<Bits<10>>,
    b_bx1: DFF<Bits<10>>,
    b_by0: DFF<Bits<10>>,
    b_by1: DFF<Bits<10>>,
    b_addr: DFF<Bits<20>>,
    b_e0: DFF<Signed<36>>,
    b_e1: DFF<Signed<36>>,
    b_e2: DFF<Signed<36>>,
    b_sx0: DFF<Signed<22>>,
    b_sx1: DFF<Signed<22>>,
    b_sx2: DFF<Signed<22>>,
    b_sy0: DFF<Signed<22>>,
    b_sy1: DFF<Signed<22>>,
    b_sy2: DFF<Signed<22>>,
    b_na: DFF<Signed<44>>,
    b_nb: DFF<Signed<44>>,
    b_mant: DFF<Bits<25>>,
    b_shamt: DFF<Bits<6>>,
    b_vx0: DFF<Signed<16>>,
    b_vy0: DFF<Signed<16>>,
    b_vz0: DFF<Bits<24>>,

    // Combinational
    dx10: Signal<Local, Signed<17>>,
    dy10: Signal<Local, Signed<17>>,
    dx20: Signal<Local, Signed<17>>,
    dy20: Signal<Local, Signed<17>>,
    dz10: Signal<Local, Signed<25>>,
    dz20: Signal<Local, Signed<25>>,
    op_la: Signal<Local, Signed<25>>,
    op_lb: Signal<Local, Signed<18>>,
    op_ra: Signal<Local, Signed<25>>,
    op_rb: Signal<Local, Signed<18>>,
    op_wa: Signal<Local, Signed<44>>,
    op_wb: Signal<Local, Signed<26>>,
    dot: Signal<Local, Signed<44>>,
    det_abs: Signal<Local, Bits<36>>,
    det_neg: Signal<Local, Bit>,
    det_zero: Signal<Local, Bit>,
    is_front: Signal<Local, Bit>,
    culled_now: Signal<Local, Bit>,
    xmin: Signal<Local, Signed<16>>,
    xmax: Signal<Local, Signed<16>>,
    ymin: Signal<Local, Signed<16>>,
    ymax: Signal<Local, Signed<16>>,
    lo_x: Signal<Local, Signed<17>>,
    hi_x: Signal<Local, Signed<17>>,
    lo_y: Signal<Local, Signed<17>>,
    hi_y: Signal<Local, Signed<17>>,
    box_x0: Signal<Local, Signed<13>>,
    box_x1: Signal<Local, Signed<13>>,
    box_y0: Signal<Local, Signed<13>>,
    box_y1: Signal<Local, Signed<13>>,
    box_empty: Signal<Local, Bit>,
    lo_x_u: Signal<Local, Bits<17>>,
    hi_x_u: Signal<Local, Bits<17>>,
    lo_y_u: Signal<Local, Bits<17>>,
    hi_y_u: Signal<Local, Bits<17>>,
    box_x1_raw: Signal<Local, Signed<13>>,
    box_y1_raw: Signal<Local, Signed<13>>,
    box_x0_u: Signal<Local, Bits<13>>,
    box_x1_u: Signal<Local, Bits<13>>,
    box_y0_u: Signal<Local, Bits<13>>,
    box_y1_u: Signal<Local, Bits<13>>,
    prod_u: Signal<Local, Bits<70>>,
    // edge k's endpoints a -> b
    ea_x: Signal<Local, Signed<16>>,
    ea_y: Signal<Local, Signed<16>>,
    eb_x: Signal<Local, Signed<16>>,
    eb_y: Signal<Local, Signed<16>>,
    edx: Signal<Local, Signed<17>>,
    edy: Signal<Local, Signed<17>>,
    cx16: Signal<Local, Bits<18>>,
    cy16: Signal<Local, Bits<18>>,
    px: Signal<Local, Signed<18>>,
    py: Signal<Local, Signed<18>>,
    top_left: Signal<Local, Bit>,
    e_val: Signal<Local, Signed<36>>,
    neg_dy: Signal<Local, Signed<17>>,
    neg_dy_w: Signal<Local, Signed<22>>,
    edx_w: Signal<Local, Signed<22>>,
    step_x: Signal<Local, Signed<22>>,
    step_y: Signal<Local, Signed<22>>,
    addr_prod: Signal<Local, Bits<32>>,
    // plane
    round_half: Signal<Local, Bits<70>>,
    rounded: Signal<Local, Bits<70>>,
    shifted: Signal<Local, Bits<70>>,
    grad_hi: Signal<Local, Bits<31>>,
    grad: Signal<Local, Signed<40>>,
    off_x: Signal<Local, Signed<17>>,
    off_y: Signal<Local, Signed<17>>,
    acc_round: Signal<Local, Bits<58>>,
    c_frac: Signal<Local, Signed<56>>,
    z0_plane: Signal<Local, Signed<56>>,
    prod56: Signal<Local, Signed<56>>,
    c_plane: Signal<Local, Signed<56>>,

    // Constants
    w_minus_1: Constant<Signed<13>>,
    h_minus_1: Constant<Signed<13>>,
    width: Constant<Bits<16>>,
    k7_17: Constant<Signed<17>>,
    k8_17: Constant<Signed<17>>,
    k8_18: Constant<Bits<18>>,
    k4_6: Constant<Bits<6>>,
    k8_70: Constant<Bits<70>>,
    k0_13: Constant<Signed<13>>,
    k0_36: Constant<Signed<36>>,
    k1_36: Constant<Signed<36>>,
    k0_17: Constant<Signed<17>>,
    k1_3: Constant<Bits<3>>,
    k0_3: Constant<Bits<3>>,
    k2_3: Constant<Bits<3>>,
    k3_3: Constant<Bits<3>>,
    k5_3: Constant<Bits<3>>,
    k6_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
    k0_31: Constant<Bits<31>>,
    k0_70: Constant<Bits<70>>,
    k0_56: Constant<Signed<56>>,
    k16_6: Constant<Bits<6>>,
    k1s_31: Constant<Bits<31>>,
    k8_58: Constant<Bits<58>>,
    max40: Constant<Signed<40>>,
    min40: Constant<Signed<40>>,
    kind_frame: Constant<Bits<2>>,
    kind_tri: Constant<Bits<2>>,
    kind_eof: Constant<Bits<2>>,
    rec_frame: Constant<Bits<2>>,
    rec_skip: Constant<Bits<2>>,
    rec_walk: Constant<Bits<2>>,
    rec_eof: Constant<Bits<2>>,
    cull_back: Constant<Bits<2>>,
    cull_front: Constant<Bits<2>>,
}

impl Setup {
    /// Setup for a `width` x `height` screen (1..=1024 each; checked by the top).
    pub fn new(width: u32, height: u32) -> Setup {
        Setup {
            clock: Default::default(),
            cmd: Default::default(),
            rec_valid: Default::default(),
            rec_ready: Default::default(),
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
            recip: Default::default(),
            mul_l: Default::default(),
            mul_r: Default::default(),
            mul_w: Default::default(),
            state: Default::default(),
            phase: Default::default(),
            kind: Default::default(),
            nbx0: Default::default(),
            nbx1: Default::default(),
            nby0: Default::default(),
            nby1: Default::default(),
            nbox_empty: Default::default(),
            clear: Default::default(),
            index: Default::default(),
            cull: Default::default(),
            front_cw: Default::default(),
            vx0: Default::default(),
            vy0: Default::default(),
            vz0: Default::default(),
            vx1: Default::default(),
            vy1: Default::default(),
            vz1: Default::default(),
            vx2: Default::default(),
            vy2: Default::default(),
            vz2: Default::default(),
            det: Default::default(),
            culled: Default::default(),
            zero_area: Default::default(),
            bx0: Default::default(),
            bx1: Default::default(),
            by0: Default::default(),
            by1: Default::default(),
            addr: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            e2: Default::default(),
            sx0: Default::default(),
            r_la: Default::default(),
            r_lb: Default::default(),
            r_ra: Default::default(),
            r_rb: Default::default(),
            r_tl: Default::default(),
            r_sx: Default::default(),
            r_sy: Default::default(),
            sx1: Default::default(),
            sx2: Default::default(),
            sy0: Default::default(),
            sy1: Default::default(),
            sy2: Default::default(),
            na: Default::default(),
            nb: Default::default(),
            mant: Default::default(),
            shamt: Default::default(),
            bstate: Default::default(),
            bphase: Default::default(),
            b_kind: Default::default(),
            b_clear: Default::default(),
            b_index: Default::default(),
            b_culled: Default::default(),
            b_zero_area: Default::default(),
            b_bx0: Default::default(),
            b_bx1: Default::default(),
            b_by0: Default::default(),
            b_by1: Default::default(),
            b_addr: Default::default(),
            b_e0: Default::default(),
            b_e1: Default::default(),
            b_e2: Default::default(),
            b_sx0: Default::default(),
            b_sx1: Default::default(),
            b_sx2: Default::default(),
            b_sy0: Default::default(),
            b_sy1: Default::default(),
            b_sy2: Default::default(),
            b_na: Default::default(),
            b_nb: Default::default(),
            b_mant: Default::default(),
            b_shamt: Default::default(),
            b_vx0: Default::default(),
            b_vy0: Default::default(),
            b_vz0: Default::default(),
            prod: Default::default(),
            grad_a: Default::default(),
            grad_b: Default::default(),
            acc: Default::default(),
            raw: Default::default(),
            dx10: Default::default(),
            dy10: Default::default(),
            dx20: Default::default(),
            dy20: Default::default(),
            dz10: Default::default(),
            dz20: Default::default(),
            op_la: Default::default(),
            op_lb: Default::default(),
            op_ra: Default::default(),
            op_rb: Default::default(),
            op_wa: Default::default(),
            op_wb: Default::default(),
            dot: Default::default(),
            det_abs: Default::default(),
            det_neg: Default::default(),
            det_zero: Default::default(),
            is_front: Default::default(),
            culled_now: Default::default(),
            xmin: Default::default(),
            xmax: Default::default(),
            ymin: Default::default(),
            ymax: Default::default(),
            lo_x: Default::default(),
            hi_x: Default::default(),
            lo_y: Default::default(),
            hi_y: Default::default(),
            box_x0: Default::default(),
            box_x1: Default::default(),
            box_y0: Default::default(),
            box_y1: Default::default(),
            box_empty: Default::default(),
            lo_x_u: Default::default(),
            hi_x_u: Default::default(),
            lo_y_u: Default::default(),
            hi_y_u: Default::default(),
            box_x1_raw: Default::default(),
            box_y1_raw: Default::default(),
            box_x0_u: Default::default(),
            box_x1_u: Default::default(),
            box_y0_u: Default::default(),
            box_y1_u: Default::default(),
            prod_u: Default::default(),
            ea_x: Default::default(),
            ea_y: Default::default(),
            eb_x: Default::default(),
            eb_y: Default::default(),
            edx: Default::default(),
            edy: Default::default(),
            cx16: Default::default(),
            cy16: Default::default(),
            px: Default::default(),
            py: Default::default(),
            top_left: Default::default(),
            e_val: Default::default(),
            neg_dy: Default::default(),
            neg_dy_w: Default::default(),
            edx_w: Default::default(),
            step_x: Default::default(),
            step_y: Default::default(),
            addr_prod: Default::default(),
            round_half: Default::default(),
            rounded: Default::default(),
            shifted: Default::default(),
            grad_hi: Default::default(),
            grad: Default::default(),
            off_x: Default::default(),
            off_y: Default::default(),
            acc_round: Default::default(),
            c_frac: Default::default(),
            z0_plane: Default::default(),
            prod56: Default::default(),
            c_plane: Default::default(),
            w_minus_1: Constant::new((width as i64 - 1).into()),
            h_minus_1: Constant::new((height as i64 - 1).into()),
            width: Constant::new((width as u64).into()),
            k7_17: Constant::new(7.into()),
            k8_17: Constant::new(8.into()),
            k8_18: Constant::new(8.into()),
            k4_6: Constant::new(4.into()),
            k8_70: Constant::new(8.into()),
            k0_13: Constant::new(0.into()),
            k0_36: Constant::new(0.into()),
            k1_36: Constant::new(1.into()),
            k0_17: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k0_3: Constant::new(0.into()),
            k2_3: Constant::new(2.into()),
            k3_3: Constant::new(3.into()),
            k5_3: Constant::new(5.into()),
            k6_3: Constant::new(6.into()),
            k4_3: Constant::new(4.into()),
            k0_31: Constant::new(0.into()),
            k0_70: Constant::new(0.into()),
            k0_56: Constant::new(0.into()),
            k16_6: Constant::new(16.into()),
            k1s_31: Constant::new(((1u64 << 31) - 1).into()),
            k8_58: Constant::new(8.into()),
            max40: Constant::new(((1i64 << 39) - 1).into()),
            min40: Constant::new((-(1i64 << 39)).into()),
            kind_frame: Constant::new(super::CMD_FRAME.into()),
            kind_tri: Constant::new(super::CMD_TRIANGLE.into()),
            kind_eof: Constant::new(super::CMD_END_OF_FRAME.into()),
            rec_frame: Constant::new(REC_FRAME.into()),
            rec_skip: Constant::new(REC_SKIP.into()),
            rec_walk: Constant::new(REC_WALK.into()),
            rec_eof: Constant::new(REC_EOF.into()),
            cull_back: Constant::new(super::CULL_BACK.into()),
            cull_front: Constant::new(super::CULL_FRONT.into()),
        }
    }
}

impl Logic for Setup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, state, phase, kind, r_la, r_lb, r_ra, r_rb, r_tl, r_sx, r_sy, nbx0, nbx1, nby0, nby1, nbox_empty, clear, index, cull, front_cw, vx0, vy0, vz0, vx1, vy1, vz1, vx2, vy2, vz2, det,
            culled, zero_area, bx0, bx1, by0, by1, addr, e0, e1, e2, sx0, sx1, sx2, sy0, sy1, sy2, na, nb, mant, shamt,
            prod, grad_a, grad_b, acc, raw, bstate, bphase, b_kind, b_clear, b_index, b_culled, b_zero_area, b_bx0, b_bx1, b_by0, b_by1, b_addr, b_e0, b_e1, b_e2, b_sx0, b_sx1, b_sx2, b_sy0, b_sy1, b_sy2, b_na, b_nb, b_mant, b_shamt, b_vx0, b_vy0, b_vz0
        );
        clock!(self, clock, recip);

        // Vertex differences (current vertex order).
        self.dx10.next = signed_bit_cast_safe::<17, 16>(self.vx1.q.val()) - signed_bit_cast_safe::<17, 16>(self.vx0.q.val());
        self.dy10.next = signed_bit_cast_safe::<17, 16>(self.vy1.q.val()) - signed_bit_cast_safe::<17, 16>(self.vy0.q.val());
        self.dx20.next = signed_bit_cast_safe::<17, 16>(self.vx2.q.val()) - signed_bit_cast_safe::<17, 16>(self.vx0.q.val());
        self.dy20.next = signed_bit_cast_safe::<17, 16>(self.vy2.q.val()) - signed_bit_cast_safe::<17, 16>(self.vy0.q.val());
        self.dz10.next = signed_cast(bit_cast::<25, 24>(self.vz1.q.val())) - signed_cast(bit_cast::<25, 24>(self.vz0.q.val()));
        self.dz20.next = signed_cast(bit_cast::<25, 24>(self.vz2.q.val())) - signed_cast(bit_cast::<25, 24>(self.vz0.q.val()));

        // Edge `phase` (0, 1, 2) runs from vertex a to vertex b.
        self.ea_x.next = self.vx0.q.val();
        self.ea_y.next = self.vy0.q.val();
        self.eb_x.next = self.vx1.q.val();
        self.eb_y.next = self.vy1.q.val();
        if self.phase.q.val() == self.k1_3.val() {
            self.ea_x.next = self.vx1.q.val();
            self.ea_y.next = self.vy1.q.val();
            self.eb_x.next = self.vx2.q.val();
            self.eb_y.next = self.vy2.q.val();
        }
        if self.phase.q.val() == self.k2_3.val() {
            self.ea_x.next = self.vx2.q.val();
            self.ea_y.next = self.vy2.q.val();
            self.eb_x.next = self.vx0.q.val();
            self.eb_y.next = self.vy0.q.val();
        }
        self.edx.next = signed_bit_cast_safe::<17, 16>(self.eb_x.val()) - signed_bit_cast_safe::<17, 16>(self.ea_x.val());
        self.edy.next = signed_bit_cast_safe::<17, 16>(self.eb_y.val()) - signed_bit_cast_safe::<17, 16>(self.ea_y.val());
        // Pixel centre of the box's first pixel in subpixels, relative to a: 16*X0 + 8 - a.x.
        self.cx16.next = (bit_cast::<18, 10>(self.bx0.q.val()) << self.k4_6.val()) | self.k8_18.val();
        self.cy16.next = (bit_cast::<18, 10>(self.by0.q.val()) << self.k4_6.val()) | self.k8_18.val();
        self.px.next = signed_cast(self.cx16.val()) - signed_bit_cast_safe::<18, 16>(self.ea_x.val());
        self.py.next = signed_cast(self.cy16.val()) - signed_bit_cast_safe::<18, 16>(self.ea_y.val());
        // Top-left rule: a top edge (dy == 0, dx > 0) or a left edge (dy < 0) keeps its centres.
        self.top_left.next = self.edy.val().get_bit(16)
            | ((self.edy.val() == self.k0_17.val()) & !self.edx.val().get_bit(16) & (self.edx.val() != self.k0_17.val()));
        // Steps per pixel: -16*dy in x, 16*dx in y.
        // Widen in a statement of its own, then shift: `signed_bit_cast_safe` emits `$signed(x)` without
        // the new width, so inside `$unsigned(...) << 4` the Verilog shifted in 17 bits and lost the top
        // bits of every step of an edge of 256 px or more (GUIDE §1, rule 1; the RustHDL simulation was
        // right). tb/tests/rc_verilog.rs replays such edges.
        self.neg_dy.next = self.k0_17.val() - self.edy.val();
        self.neg_dy_w.next = signed_bit_cast_safe::<22, 17>(self.neg_dy.val());
        self.edx_w.next = signed_bit_cast_safe::<22, 17>(self.edx.val());
        self.step_x.next = signed_cast(unsigned_cast(self.neg_dy_w.val()) << self.k4_6.val());
        self.step_y.next = signed_cast(unsigned_cast(self.edx_w.val()) << self.k4_6.val());

        // The dot-difference unit: dot = l.a*l.b - r.a*r.b; operands chosen by state and phase.
        self.op_la.next = signed_bit_cast_safe::<25, 17>(self.dx10.val());
        self.op_lb.next = signed_bit_cast_safe::<18, 17>(self.dy20.val());
        self.op_ra.next = signed_bit_cast_safe::<25, 17>(self.dx20.val());
        self.op_rb.next = signed_bit_cast_safe::<18, 17>(self.dy10.val());
        // Edge `phase` (0, 1, 2): its operands, fill-rule flag and steps into the r_ registers.
        self.r_la.d.next = signed_bit_cast_safe::<25, 17>(self.edx.val());
        self.r_lb.d.next = self.py.val();
        self.r_ra.d.next = signed_bit_cast_safe::<25, 17>(self.edy.val());
        self.r_rb.d.next = self.px.val();
        self.r_tl.d.next = self.top_left.val();
        self.r_sx.d.next = self.step_x.val();
        self.r_sy.d.next = self.step_y.val();
        if self.state.q.val() == SetupState::Edges {
            if (self.phase.q.val() != self.k0_3.val()) & (self.phase.q.val() < self.k4_3.val()) {
                self.op_la.next = self.r_la.q.val();
                self.op_lb.next = self.r_lb.q.val();
                self.op_ra.next = self.r_ra.q.val();
                self.op_rb.next = self.r_rb.q.val();
            }
            if self.phase.q.val() == self.k4_3.val() {
                self.op_la.next = self.dz10.val();
                self.op_lb.next = signed_bit_cast_safe::<18, 17>(self.dy20.val());
                self.op_ra.next = self.dz20.val();
                self.op_rb.next = signed_bit_cast_safe::<18, 17>(self.dy10.val());
            }
            if self.phase.q.val() == self.k5_3.val() {
                self.op_la.next = self.dz20.val();
                self.op_lb.next = signed_bit_cast_safe::<18, 17>(self.dx10.val());
                self.op_ra.next = self.dz10.val();
                self.op_rb.next = signed_bit_cast_safe::<18, 17>(self.dx20.val());
            }
        }
        self.dot.next = signed_bit_cast_safe::<44, 43>(self.mul_l.p.val()) - signed_bit_cast_safe::<44, 43>(self.mul_r.p.val());
        self.e_val.next = signed_bit_cast_safe::<36, 44>(self.dot.val()) - self.k1_36.val();
        if self.r_tl.q.val() {
            self.e_val.next = signed_bit_cast_safe::<36, 44>(self.dot.val());
        }
        self.addr_prod.next = bit_cast::<16, 10>(self.by0.q.val()) * self.width.val();

        // Culling (det > 0 is clockwise on the screen) and the bounding box.
        self.det_neg.next = self.det.q.val().get_bit(35);
        self.det_zero.next = self.det.q.val() == self.k0_36.val();
        self.is_front.next = self.det_neg.val();
        if self.front_cw.q.val() {
            self.is_front.next = !self.det_neg.val();
        }
        self.culled_now.next = self.det_zero.val()
            | ((self.cull.q.val() == self.cull_back.val()) & !self.is_front.val())
            | ((self.cull.q.val() == self.cull_front.val()) & self.is_front.val());
        self.xmin.next = self.vx0.q.val();
        self.xmax.next = self.vx0.q.val();
        self.ymin.next = self.vy0.q.val();
        self.ymax.next = self.vy0.q.val();
        self.lo_x.next = self.k0_17.val();
        self.hi_x.next = self.k0_17.val();
        self.lo_y.next = self.k0_17.val();
        self.hi_y.next = self.k0_17.val();
        self.box_x0.next = self.k0_13.val();
        self.box_x1.next = self.k0_13.val();
        self.box_y0.next = self.k0_13.val();
        self.box_y1.next = self.k0_13.val();
        self.box_empty.next = false;
        // The bounding box does not depend on the vertex order: it is found in `Det`, beside det, and
        // registered, so that `Order`'s reciprocal request does not wait for min/max, round and clamp.
        if self.state.q.val() == SetupState::Det {
            // Signed compares are slow in simulation: only evaluated where needed.
            if self.vx1.q.val() < self.vx0.q.val() {
                self.xmin.next = self.vx1.q.val();
            }
            if (self.vx2.q.val() < self.vx1.q.val()) & (self.vx2.q.val() < self.vx0.q.val()) {
                self.xmin.next = self.vx2.q.val();
            }
            if self.vx1.q.val() > self.vx0.q.val() {
                self.xmax.next = self.vx1.q.val();
            }
            if (self.vx2.q.val() > self.vx1.q.val()) & (self.vx2.q.val() > self.vx0.q.val()) {
                self.xmax.next = self.vx2.q.val();
            }
            if self.vy1.q.val() < self.vy0.q.val() {
                self.ymin.next = self.vy1.q.val();
            }
            if (self.vy2.q.val() < self.vy1.q.val()) & (self.vy2.q.val() < self.vy0.q.val()) {
                self.ymin.next = self.vy2.q.val();
            }
            if self.vy1.q.val() > self.vy0.q.val() {
                self.ymax.next = self.vy1.q.val();
            }
            if (self.vy2.q.val() > self.vy1.q.val()) & (self.vy2.q.val() > self.vy0.q.val()) {
                self.ymax.next = self.vy2.q.val();
            }
            self.lo_x.next = signed_bit_cast_safe::<17, 16>(self.xmin.val()) + self.k7_17.val();
            self.hi_x.next = signed_bit_cast_safe::<17, 16>(self.xmax.val()) - self.k8_17.val();
            self.lo_y.next = signed_bit_cast_safe::<17, 16>(self.ymin.val()) + self.k7_17.val();
            self.hi_y.next = signed_bit_cast_safe::<17, 16>(self.ymax.val()) - self.k8_17.val();
        }
        // Bits views for slicing (Verilog cannot slice a cast).
        self.lo_x_u.next = unsigned_cast(self.lo_x.val());
        self.hi_x_u.next = unsigned_cast(self.hi_x.val());
        self.lo_y_u.next = unsigned_cast(self.lo_y.val());
        self.hi_y_u.next = unsigned_cast(self.hi_y.val());
        self.box_x1_raw.next = signed_bit_cast_safe::<13, 13>(signed_cast(self.hi_x_u.val().get_bits::<13>(4)));
        self.box_y1_raw.next = signed_bit_cast_safe::<13, 13>(signed_cast(self.hi_y_u.val().get_bits::<13>(4)));
        if self.state.q.val() == SetupState::Det {
            // >> 4 (arithmetic), then clamp to the screen.
            self.box_x0.next = signed_bit_cast_safe::<13, 13>(signed_cast(self.lo_x_u.val().get_bits::<13>(4)));
            self.box_x1.next = self.box_x1_raw.val();
            self.box_y0.next = signed_bit_cast_safe::<13, 13>(signed_cast(self.lo_y_u.val().get_bits::<13>(4)));
            self.box_y1.next = self.box_y1_raw.val();
            if self.lo_x.val().get_bit(16) {
                self.box_x0.next = self.k0_13.val();
            }
            if self.lo_y.val().get_bit(16) {
                self.box_y0.next = self.k0_13.val();
            }
            if self.box_x1_raw.val() > self.w_minus_1.val() {
                self.box_x1.next = self.w_minus_1.val();
            }
            if self.box_y1_raw.val() > self.h_minus_1.val() {
                self.box_y1.next = self.h_minus_1.val();
            }
            self.box_empty.next = (self.box_x0.val() > self.box_x1.val()) | (self.box_y0.val() > self.box_y1.val());
        }
        self.box_x0_u.next = unsigned_cast(self.box_x0.val());
        self.box_x1_u.next = unsigned_cast(self.box_x1.val());
        self.box_y0_u.next = unsigned_cast(self.box_y0.val());
        self.box_y1_u.next = unsigned_cast(self.box_y1.val());
        self.prod_u.next = self.prod.q.val();

        // Plane gradient from the product register: sat40((prod + 2^(sh-1)) >> sh), sh = shift + 4.
        self.round_half.next = self.k8_70.val() << self.b_shamt.q.val();
        self.rounded.next = self.prod.q.val() + self.round_half.val();
        self.shifted.next = self.k0_70.val();
        self.grad_hi.next = self.k0_31.val();
        self.grad.next = self.min40.val();
        self.off_x.next = self.k0_17.val();
        self.off_y.next = self.k0_17.val();
        self.acc_round.next = self.k8_58.val();
        self.c_frac.next = self.k0_56.val();
        self.z0_plane.next = self.k0_56.val();
        self.prod56.next = self.k0_56.val();
        self.c_plane.next = self.k0_56.val();
        if self.bstate.q.val() == PlaneState::Plane {
            self.shifted.next = (self.rounded.val() >> self.b_shamt.q.val()) >> self.k4_6.val();
            if self.rounded.val().get_bit(69) {
                // arithmetic shift of a negative value: complement, shift, complement
                self.shifted.next = !((!self.rounded.val() >> self.b_shamt.q.val()) >> self.k4_6.val());
            }
            self.grad_hi.next = self.shifted.val().get_bits::<31>(39);
            if (self.grad_hi.val() == self.k0_31.val()) | (self.grad_hi.val() == self.k1s_31.val()) {
                self.grad.next = signed_cast(self.shifted.val().get_bits::<40>(0));
            } else if !self.rounded.val().get_bit(69) {
                self.grad.next = self.max40.val();
            }
            self.off_x.next = self.k8_17.val() - signed_bit_cast_safe::<17, 16>(self.b_vx0.q.val());
            self.off_y.next = self.k8_17.val() - signed_bit_cast_safe::<17, 16>(self.b_vy0.q.val());
            // C = (z0 << 16) + round(acc >> 4): never saturates (see the module doc).
            self.acc_round.next = unsigned_cast(self.acc.q.val()) + self.k8_58.val();
            self.c_frac.next = signed_bit_cast_safe::<56, 54>(signed_cast(self.acc_round.val().get_bits::<54>(4)));
            self.z0_plane.next = signed_cast(bit_cast::<56, 24>(self.b_vz0.q.val()) << self.k16_6.val());
            self.prod56.next = signed_cast(self.prod_u.val().get_bits::<56>(0));
            self.c_plane.next = self.z0_plane.val() + self.c_frac.val();
        }
        // The plane multiplier's operands by phase.
        self.op_wa.next = self.b_na.q.val();
        self.op_wb.next = signed_cast(bit_cast::<26, 25>(self.b_mant.q.val()));
        if self.bphase.q.val() == self.k1_3.val() {
            self.op_wa.next = self.b_nb.q.val();
        }
        if self.bphase.q.val() == self.k2_3.val() {
            self.op_wa.next = signed_bit_cast_safe::<44, 40>(self.grad_a.q.val());
            self.op_wb.next = signed_bit_cast_safe::<26, 17>(self.off_x.val());
        }
        if self.bphase.q.val() == self.k3_3.val() {
            self.op_wa.next = signed_bit_cast_safe::<44, 40>(self.grad_b.q.val());
            self.op_wb.next = signed_bit_cast_safe::<26, 17>(self.off_y.val());
        }
        if self.bphase.q.val() == self.k4_3.val() {
            self.op_wa.next = signed_bit_cast_safe::<44, 40>(self.grad_a.q.val());
            self.op_wb.next = signed_cast(bit_cast::<26, 10>(self.b_bx0.q.val()));
        }
        if self.bphase.q.val() == self.k5_3.val() {
            self.op_wa.next = signed_bit_cast_safe::<44, 40>(self.grad_b.q.val());
            self.op_wb.next = signed_cast(bit_cast::<26, 10>(self.b_by0.q.val()));
        }

        // Each multiplier input is driven exactly once per evaluation: an event-driven simulator
        // (Icarus) would otherwise see the default value first, re-evaluate the product, re-run this
        // block, and never settle.
        self.mul_l.a.next = self.op_la.val();
        self.mul_l.b.next = self.op_lb.val();
        self.mul_r.a.next = self.op_ra.val();
        self.mul_r.b.next = self.op_rb.val();
        self.mul_w.a.next = self.op_wa.val();
        self.mul_w.b.next = self.op_wb.val();
        // The reciprocal of |det|.
        self.det_abs.next = unsigned_cast(self.det.q.val());
        if self.det_neg.val() {
            self.det_abs.next = unsigned_cast(self.k0_36.val() - self.det.q.val());
        }
        self.recip.request.data.next = self.det_abs.val();
        self.recip.result.ready.next = self.state.q.val() == SetupState::WaitRecip;
        // Started in Order exactly when the triangle is drawn (not culled, box not empty).
        self.recip.request.valid.next = (self.state.q.val() == SetupState::Order) & !self.culled_now.val() & !self.nbox_empty.q.val();

        // Ports.
        self.cmd.ready.next = self.state.q.val() == SetupState::Idle;
        self.rec_valid.next = self.bstate.q.val() == PlaneState::Out;
        self.rec_kind.next = self.b_kind.q.val();
        self.rec_clear.next = self.b_clear.q.val();
        self.rec_index.next = self.b_index.q.val();
        self.rec_culled.next = self.b_culled.q.val();
        self.rec_zero_area.next = self.b_zero_area.q.val();
        self.rec_bx0.next = self.b_bx0.q.val();
        self.rec_bx1.next = self.b_bx1.q.val();
        self.rec_by0.next = self.b_by0.q.val();
        self.rec_by1.next = self.b_by1.q.val();
        self.rec_addr.next = self.b_addr.q.val();
        self.rec_e0.next = self.b_e0.q.val();
        self.rec_e1.next = self.b_e1.q.val();
        self.rec_e2.next = self.b_e2.q.val();
        self.rec_sx0.next = self.b_sx0.q.val();
        self.rec_sx1.next = self.b_sx1.q.val();
        self.rec_sx2.next = self.b_sx2.q.val();
        self.rec_sy0.next = self.b_sy0.q.val();
        self.rec_sy1.next = self.b_sy1.q.val();
        self.rec_sy2.next = self.b_sy2.q.val();
        self.rec_raw.next = self.raw.q.val();
        self.rec_a.next = self.grad_a.q.val();
        self.rec_b.next = self.grad_b.q.val();

        match self.state.q.val() {
            SetupState::Idle => {
                if self.cmd.valid.val() {
                    self.kind.d.next = self.rec_frame.val();
                    self.culled.d.next = false;
                    self.zero_area.d.next = false;
                    self.clear.d.next = self.cmd.data.val().clear;
                    self.index.d.next = self.cmd.data.val().index;
                    self.cull.d.next = self.cmd.data.val().cull;
                    self.front_cw.d.next = self.cmd.data.val().front_cw;
                    self.vx0.d.next = signed_cast(self.cmd.data.val().x0);
                    self.vy0.d.next = signed_cast(self.cmd.data.val().y0);
                    self.vz0.d.next = self.cmd.data.val().z0;
                    self.vx1.d.next = signed_cast(self.cmd.data.val().x1);
                    self.vy1.d.next = signed_cast(self.cmd.data.val().y1);
                    self.vz1.d.next = self.cmd.data.val().z1;
                    self.vx2.d.next = signed_cast(self.cmd.data.val().x2);
                    self.vy2.d.next = signed_cast(self.cmd.data.val().y2);
                    self.vz2.d.next = self.cmd.data.val().z2;
                    self.phase.d.next = self.k0_3.val();
                    self.state.d.next = SetupState::Hand;
                    if self.cmd.data.val().kind == self.kind_tri.val() {
                        self.state.d.next = SetupState::Det;
                    }
                    if self.cmd.data.val().kind == self.kind_eof.val() {
                        self.kind.d.next = self.rec_eof.val();
                    }
                    if self.cmd.data.val().kind != self.kind_frame.val() {
                        self.clear.d.next = false;
                    }
                }
            }
            SetupState::Det => {
                self.det.d.next = signed_bit_cast_safe::<36, 44>(self.dot.val());
                self.nbx0.d.next = self.box_x0_u.val().get_bits::<10>(0);
                self.nbx1.d.next = self.box_x1_u.val().get_bits::<10>(0);
                self.nby0.d.next = self.box_y0_u.val().get_bits::<10>(0);
                self.nby1.d.next = self.box_y1_u.val().get_bits::<10>(0);
                self.nbox_empty.d.next = self.box_empty.val();
                self.state.d.next = SetupState::Order;
            }
            SetupState::Order => {
                self.kind.d.next = self.rec_skip.val();
                self.culled.d.next = self.culled_now.val();
                self.zero_area.d.next = self.det_zero.val();
                self.state.d.next = SetupState::Hand;
                if !self.culled_now.val() {
                    if self.det_neg.val() {
                        self.vx1.d.next = self.vx2.q.val();
                        self.vy1.d.next = self.vy2.q.val();
                        self.vz1.d.next = self.vz2.q.val();
                        self.vx2.d.next = self.vx1.q.val();
                        self.vy2.d.next = self.vy1.q.val();
                        self.vz2.d.next = self.vz1.q.val();
                    }
                    self.bx0.d.next = self.nbx0.q.val();
                    self.bx1.d.next = self.nbx1.q.val();
                    self.by0.d.next = self.nby0.q.val();
                    self.by1.d.next = self.nby1.q.val();
                    if !self.nbox_empty.q.val() {
                        self.kind.d.next = self.rec_walk.val();
                        self.state.d.next = SetupState::Edges;
                    }
                }
            }
            SetupState::Edges => {
                // Phase p < 3 finds edge p's operands; phase p + 1 multiplies them: edges in 1..=3,
                // the depth numerators in 4 and 5 (all while the reciprocal runs).
                self.phase.d.next = self.phase.q.val() + self.k1_3.val();
                if self.phase.q.val() == self.k0_3.val() {
                    self.addr.d.next = self.addr_prod.val().get_bits::<20>(0) + bit_cast::<20, 10>(self.bx0.q.val());
                }
                if self.phase.q.val() == self.k1_3.val() {
                    self.e0.d.next = self.e_val.val();
                    self.sx0.d.next = self.r_sx.q.val();
                    self.sy0.d.next = self.r_sy.q.val();
                }
                if self.phase.q.val() == self.k2_3.val() {
                    self.e1.d.next = self.e_val.val();
                    self.sx1.d.next = self.r_sx.q.val();
                    self.sy1.d.next = self.r_sy.q.val();
                }
                if self.phase.q.val() == self.k3_3.val() {
                    self.e2.d.next = self.e_val.val();
                    self.sx2.d.next = self.r_sx.q.val();
                    self.sy2.d.next = self.r_sy.q.val();
                }
                if self.phase.q.val() == self.k4_3.val() {
                    self.na.d.next = self.dot.val();
                }
                if self.phase.q.val() == self.k5_3.val() {
                    self.nb.d.next = self.dot.val();
                    self.state.d.next = SetupState::WaitRecip;
                }
            }
            SetupState::WaitRecip => {
                if self.recip.result.valid.val() {
                    self.mant.d.next = self.recip.result.data.val().mant;
                    self.shamt.d.next = self.recip.result.data.val().shift;
                    self.state.d.next = SetupState::Hand;
                }
            }
            SetupState::Hand => {
                // The record moves to the second stage when that is empty in this cycle.
                if self.bstate.q.val() == PlaneState::Empty {
                    self.b_kind.d.next = self.kind.q.val();
                    self.b_clear.d.next = self.clear.q.val();
                    self.b_index.d.next = self.index.q.val();
                    self.b_culled.d.next = self.culled.q.val();
                    self.b_zero_area.d.next = self.zero_area.q.val();
                    self.b_bx0.d.next = self.bx0.q.val();
                    self.b_bx1.d.next = self.bx1.q.val();
                    self.b_by0.d.next = self.by0.q.val();
                    self.b_by1.d.next = self.by1.q.val();
                    self.b_addr.d.next = self.addr.q.val();
                    self.b_e0.d.next = self.e0.q.val();
                    self.b_e1.d.next = self.e1.q.val();
                    self.b_e2.d.next = self.e2.q.val();
                    self.b_sx0.d.next = self.sx0.q.val();
                    self.b_sx1.d.next = self.sx1.q.val();
                    self.b_sx2.d.next = self.sx2.q.val();
                    self.b_sy0.d.next = self.sy0.q.val();
                    self.b_sy1.d.next = self.sy1.q.val();
                    self.b_sy2.d.next = self.sy2.q.val();
                    self.b_na.d.next = self.na.q.val();
                    self.b_nb.d.next = self.nb.q.val();
                    self.b_mant.d.next = self.mant.q.val();
                    self.b_shamt.d.next = self.shamt.q.val();
                    self.b_vx0.d.next = self.vx0.q.val();
                    self.b_vy0.d.next = self.vy0.q.val();
                    self.b_vz0.d.next = self.vz0.q.val();
                    self.bphase.d.next = self.k0_3.val();
                    self.bstate.d.next = PlaneState::Out;
                    if self.kind.q.val() == self.rec_walk.val() {
                        self.bstate.d.next = PlaneState::Plane;
                    }
                    self.state.d.next = SetupState::Idle;
                }
            }
            _ => {
                self.state.d.next = SetupState::Idle;
            }
        }
        // The second stage.
        match self.bstate.q.val() {
            PlaneState::Empty => {}
            PlaneState::Plane => {
                // One product per phase into `prod`, each used in the next phase (the product and the
                // sum behind it are never one clock period): A and B in phases 1, 2; C's two terms
                // in 3, 4; raw's two terms in 5, 6.
                self.bphase.d.next = self.bphase.q.val() + self.k1_3.val();
                self.prod.d.next = unsigned_cast(self.mul_w.p.val());
                if self.bphase.q.val() == self.k1_3.val() {
                    self.grad_a.d.next = self.grad.val();
                }
                if self.bphase.q.val() == self.k2_3.val() {
                    self.grad_b.d.next = self.grad.val();
                }
                if self.bphase.q.val() == self.k3_3.val() {
                    self.acc.d.next = signed_cast(self.prod_u.val().get_bits::<58>(0));
                }
                if self.bphase.q.val() == self.k4_3.val() {
                    self.acc.d.next = self.acc.q.val() + signed_cast(self.prod_u.val().get_bits::<58>(0));
                }
                if self.bphase.q.val() == self.k5_3.val() {
                    self.raw.d.next = self.c_plane.val() + self.prod56.val();
                }
                if self.bphase.q.val() == self.k6_3.val() {
                    self.raw.d.next = self.raw.q.val() + self.prod56.val();
                    self.bstate.d.next = PlaneState::Out;
                }
            }
            PlaneState::Out => {
                if self.rec_ready.val() {
                    self.bstate.d.next = PlaneState::Empty;
                }
            }
            _ => {
                self.bstate.d.next = PlaneState::Empty;
            }
        }
    }
}
