//! `setup`: the RC's triangle setup (seed 001 §2.3.1: Pineda edge functions, eq. 5; the depth plane
//! with one reciprocal per triangle, eqs. 6-7), bit-exact with `golden::raster::setup`, as a pipeline
//! of eight stages with a pipelined reciprocal and a queue of set-up records in front of the traversal.
//!
//! ```text
//!          +------+  +-------+  +---------+  +----+----+----+  +--------+  +---------+  +---------+
//!  cmd --->| S0   |->| S1    |->| S2      |->| S3 | S4 | S5 |->| S6     |->| S7      |->| record  |-> rec_*
//! (valid/  | Det  |  | Order |  | Edges   |  |Hold|Hold|Hold|  | Grad   |  | Plane   |  | queue   |   (valid/
//!  ready)  | 2x   |  |       |  | 4x      |  |    |    |    |  | 1x     |  | 2x      |  | 4 deep  |    ready)
//!          |21x21 |  |       |  | 25x21   |  |    |    |    |  | 47x26  |  | 40x21   |  +---------+
//!          +------+  +---+---+  +---------+  +----+----+----+  +---^----+  +---------+
//!                        | abs(det)  +----------------------------+  | mant, shift
//!                        +---------->| reciprocal, 13 stations    |--+
//!                                    +----------------------------+
//! ```
//!
//! Each stage holds one record (docs/rc.md, "Setup"; `golden::cycle::rc` models the same schedule).
//! A drawn triangle spends 1, 1, 4, 1, 1, 1, 4 and 4 cycles in S0..S7 when nothing waits; any other
//! command (frame start, end of frame, a culled or empty-box triangle) one cycle in each.
//! * S0 `Det`: det = dx10*dy20 - dx20*dy10 (two pipelined 21x21 products, `MulPipeS`: their blocks
//!   and rows take the deltas of the command port at the edge where S0 takes the command, so S0 only
//!   sums the registered partial products; issue 15 item 5); the clamped bounding box
//!   `[(min+127)>>8, (max-128)>>8]`, each vertex's bound formed and clamped beside the min/max
//!   compares, which then choose one of three (clamping and shifting keep the order; issue 15 item 5:
//!   the compares, the choice, the add and the clamp in series were a critical path).
//! * S1 `Order`: zero area / cull decision from det's sign, the cull mode and the front face;
//!   canonical order (swap vertices 1 and 2 if det < 0); all three edges' multiplier operands, fill-rule
//!   flags and steps (-256*dy, 256*dx); the start address Y0*W + X0; the reciprocal request of abs(det).
//! * S2 `Edges` on two dot units (a*b - c*d each) of pipelined products (`MulPipeS`: the blocks'
//!   partial products are registered, their sum a cycle later; issue 15 item 5): a product chosen in
//!   phase k is in the product registers in phase k+2, where it is subtracted. Operands: phase 0 E0,
//!   E1; phase 1 E2 and na = dz10*dy20 - dz20*dy10; phase 2 nb = dz20*dx10 - dz10*dx20. E0, E1 are
//!   formed in phase 2, E2 and na in the first cycle of phase 3, and nb in S3's first cycle (unit b
//!   keeps nb's operands until S2 takes its next record, whose first products land a cycle after
//!   that). The operands sit in registers that move on with the phases, so no choice stands in front
//!   of a product. (Four cycles since issue 15 item 5: choosing, multiplying and subtracting in one
//!   cycle was the RC's critical path; then the product and its sum in one cycle was.)
//!   `E = dx*(256*Y0+128-a.y) - dy*(256*X0+128-a.x) - bias` (bias 0 on a top or left edge, else 1).
//! * S3, S4, S5 `Hold`: keep records while their reciprocals run (the reciprocal's latency, 13, is
//!   longer than S2's four cycles). S5 is the third since issue 15 item 5: with two, the longer
//!   reciprocal left culled triangles waiting behind a drawn one (teapot 320x200 rasterization 45 321
//!   cycles against 45 000 asked; docs/rc.md).
//! * S6 `Grad`: waits in phase 0 for the reciprocal and multiplies na by its mantissa; phase 1 shifts
//!   twice that product right by shift (= the product by shift-1) and forms nb*mant; phase 2
//!   `A = sat40((shifted + 1) >> 1)` (which is `round(na*mant >> shift)`, also for shift 0) and shifts nb*mant; phase 3 B likewise. The shift and the rounding
//!   are a cycle each since issue 15 item 5 (the one-cycle form was the RC's critical path). The
//!   multiplier's first operand comes from a register (na loaded as the record enters S6, nb at the
//!   end of phase 0).
//! * S7 `Plane` (two pipelined 40x21 products per cycle, `MulPipeS`: a product's partial products are
//!   registered at the end of the phase that presents its operands, their sum goes into `p_prod`,
//!   `q_prod` at the end of the next): phase 0 presents A*(128-x0), B*(128-y0); phase 1 A*X0, B*Y0;
//!   phase 2 forms `acc + 128` = A*(128-x0) + B*(128-y0) + 128 from the product registers; phase 3
//!   `C = (z0 << 16) + (acc + 128) >> 8` and raw = C + A*X0 + B*Y0 (the depth plane's raw value at the
//!   box's first pixel) from registers, into the queue with the record. (Since issue 15 item 5: a
//!   multiplier block and its partial sums in one cycle were setup's worst path in the chipset; the
//!   four phases and what leaves S7 are unchanged.) The multipliers' operands come straight from
//!   registers: A and B from the record, `128 - x0` and `128 - y0` formed as the record enters S7, X0
//!   and Y0 loaded at the end of phase 0.
//!
//! Handshake, from the registers at the start of a cycle, last stage first: stage k hands its record on
//! when it has spent its cycles and stage k+1 is empty or hands its own on in the same cycle; S7 when the
//! queue holds fewer than four records; S1 hands a drawn triangle on only when the reciprocal advances
//! (takes its request). `cmd.ready` = S0 is empty or hands on. The reciprocal advances when its result
//! station is empty or S6 takes the result. Everything is first in, first out: records leave in command
//! order.
//!
//! Widths: inputs are any 20-bit S11.8 values, so |dx|, |dy| < 2^20 and |det| < 2^41 (44 bits, the
//! reciprocal's 44-bit request); E stays below 2^41 in magnitude on the screen (44-bit registers). na,
//! nb < 2^45 (47-bit dot products); na*mant < 2^69 (73-bit product, doubled for the shift). C never
//! saturates at 56 bits (|A| <= 2^39, |128-x0| <= 2^19 + 128: |C| < 2^52), so the golden model's saturation
//! of C needs no hardware; raw < 2^52 anywhere in the box (56-bit registers).

use super::fast_reciprocal::FastReciprocal;
use super::RcCommand;
use crate::common::{signed_bit_cast_safe, MulPipeS, MulS, StreamIn};
use rust_hdl::prelude::*;

/// Record kinds handed to the traversal.
pub const REC_FRAME: u64 = 0;
pub const REC_SKIP: u64 = 1;
pub const REC_WALK: u64 = 2;
pub const REC_EOF: u64 = 3;
/// Records the queue in front of the traversal holds.
pub const RECORD_QUEUE: u64 = 4;

/// A record on its way through S2..S7 and the queue: what the traversal takes. Signed values are kept
/// as their bits.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct SetupRec {
    /// REC_FRAME, REC_SKIP, REC_WALK or REC_EOF.
    pub kind: Bits<2>,
    pub clear: Bit,
    pub index: Bits<16>,
    pub culled: Bit,
    pub zero_area: Bit,
    pub bx0: Bits<10>,
    pub bx1: Bits<10>,
    pub by0: Bits<10>,
    pub by1: Bits<10>,
    pub addr: Bits<20>,
    pub e0: Bits<44>,
    pub e1: Bits<44>,
    pub e2: Bits<44>,
    pub sx0: Bits<30>,
    pub sx1: Bits<30>,
    pub sx2: Bits<30>,
    pub sy0: Bits<30>,
    pub sy1: Bits<30>,
    pub sy2: Bits<30>,
    pub a: Bits<40>,
    pub b: Bits<40>,
    pub raw: Bits<56>,
    /// The depth plane's C (its value at pixel (0, 0)): Type III's TdbV record with a and b.
    pub c: Bits<56>,
    /// The multiples of the steps that are not shifts, 3*sx and 15*sx per edge and 3*A, formed as the
    /// record enters the queue (issue 15 item 5): the traversal takes them with the record instead
    /// of adding them up behind the queue's head, where two adders in series stood on the record take.
    pub sx3_0: Bits<32>,
    pub sx3_1: Bits<32>,
    pub sx3_2: Bits<32>,
    pub sx15_0: Bits<34>,
    pub sx15_1: Bits<34>,
    pub sx15_2: Bits<34>,
    pub a3: Bits<42>,
}

/// What S2..S7 carry beside a [`SetupRec`] to find the depth plane (not queued).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct PlaneIn {
    pub na: Bits<47>,
    pub nb: Bits<47>,
    pub x0: Bits<20>,
    pub y0: Bits<20>,
    pub z0: Bits<24>,
    pub shift: Bits<6>,
}

#[derive(LogicBlock)]
pub struct Setup {
    pub clock: Signal<In, Clock>,
    // From the command port
    /// Commands; `ready` when S0 is empty or hands its command on in this cycle.
    pub cmd: StreamIn<RcCommand>,
    // To the traversal: the queue's head (held while `rec_valid`, taken with `rec_ready`)
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
    pub rec_e0: Signal<Out, Signed<44>>,
    pub rec_e1: Signal<Out, Signed<44>>,
    pub rec_e2: Signal<Out, Signed<44>>,
    /// Edge increments per pixel in x (-256*dy) and per row (256*dx).
    pub rec_sx0: Signal<Out, Signed<30>>,
    pub rec_sx1: Signal<Out, Signed<30>>,
    pub rec_sx2: Signal<Out, Signed<30>>,
    pub rec_sy0: Signal<Out, Signed<30>>,
    pub rec_sy1: Signal<Out, Signed<30>>,
    pub rec_sy2: Signal<Out, Signed<30>>,
    /// Depth plane: raw value (16 fraction bits) at (bx0, by0), and its increments A (x), B (y).
    pub rec_raw: Signal<Out, Signed<56>>,
    pub rec_a: Signal<Out, Signed<40>>,
    pub rec_b: Signal<Out, Signed<40>>,
    pub rec_c: Signal<Out, Signed<56>>,
    /// 3 and 15 times each edge's x step, 3 times A (the record's `sx3_k`, `sx15_k`, `a3`).
    pub rec_sx3_0: Signal<Out, Signed<32>>,
    pub rec_sx3_1: Signal<Out, Signed<32>>,
    pub rec_sx3_2: Signal<Out, Signed<32>>,
    pub rec_sx15_0: Signal<Out, Signed<34>>,
    pub rec_sx15_1: Signal<Out, Signed<34>>,
    pub rec_sx15_2: Signal<Out, Signed<34>>,
    pub rec_a3: Signal<Out, Signed<42>>,

    // Children
    recip: FastReciprocal,
    /// S0: det's two products, pipelined: their partial products are taken from the command port as
    /// S0 takes the command, and summed while S0 holds it.
    mul_d0: MulPipeS<21, 21, 42, 3, 3>,
    mul_d1: MulPipeS<21, 21, 42, 3, 3>,
    /// S2: two dot units, a0*b0 - a1*b1 and c0*d0 - c1*d1. One MULT18X18D each (7 + 3 low bits in
    /// logic; two with 0 + 3): with the chipset's other blocks the 45F's 72 were too few (issue 15 item 5).
    /// Pipelined (`MulPipeS`): the partial products are registered, their sum lands a cycle later.
    mul_a0: MulPipeS<25, 21, 46, 7, 3>,
    mul_a1: MulPipeS<25, 21, 46, 7, 3>,
    mul_b0: MulPipeS<25, 21, 46, 7, 3>,
    mul_b1: MulPipeS<25, 21, 46, 7, 3>,
    /// S6: the gradients.
    mul_g: MulS<47, 26, 73>,
    /// S7: the plane's two products per cycle, two MULT18X18D each (5 + 3 low bits in logic).
    /// Pipelined (`MulPipeS`): the partial products are registered, their sum goes into `p_prod` and
    /// `q_prod` a cycle later (issue 15 item 5: a multiplier block and the partial sums in one cycle
    /// were setup's worst path in the chipset).
    mul_p: MulPipeS<40, 21, 61, 5, 3>,
    mul_q: MulPipeS<40, 21, 61, 5, 3>,

    // S0 `Det`: the command.
    s0_v: DFF<Bit>,
    s0: DFF<RcCommand>,
    // S1 `Order`: the command, det and the clamped box.
    s1_v: DFF<Bit>,
    s1: DFF<RcCommand>,
    s1_det: DFF<Signed<44>>,
    s1_bx0: DFF<Bits<10>>,
    s1_bx1: DFF<Bits<10>>,
    s1_by0: DFF<Bits<10>>,
    s1_by1: DFF<Bits<10>>,
    s1_box_empty: DFF<Bit>,
    /// det = 0, registered with det (issue 15 item 5: det's 44-bit zero test in front of S1's culling
    /// decision and the leave chain was the RC's critical path once the walk looked ahead).
    s1_det_zero: DFF<Bit>,
    /// |det|, registered with det (issue 15 item 5: the 44-bit negation in front of the reciprocal's
    /// leading-one detector was the RC's critical path).
    s1_det_abs: DFF<Bits<44>>,
    // S2 `Edges`: the record, its phase and the dot units' operands (edge k: la*lb - ra*rb). The
    // multipliers read `*0` (unit a) and `*1` (unit b) straight from these registers, which move on
    // with the phases (issue 15 item 5: the phase's choice in front of the products was the RC's
    // critical path): from S1 edges 0 and 1; after phase 0 unit a takes edge 2 and unit b na's
    // operands; after phase 1 unit b takes nb's.
    s2_v: DFF<Bit>,
    s2_phase: DFF<Bits<2>>,
    s2: DFF<SetupRec>,
    s2p: DFF<PlaneIn>,
    la0: DFF<Signed<25>>,
    lb0: DFF<Signed<21>>,
    ra0: DFF<Signed<25>>,
    rb0: DFF<Signed<21>>,
    tl0: DFF<Bit>,
    la1: DFF<Signed<25>>,
    lb1: DFF<Signed<21>>,
    ra1: DFF<Signed<25>>,
    rb1: DFF<Signed<21>>,
    tl1: DFF<Bit>,
    la2: DFF<Signed<25>>,
    lb2: DFF<Signed<21>>,
    ra2: DFF<Signed<25>>,
    rb2: DFF<Signed<21>>,
    tl2: DFF<Bit>,
    /// The dot units' products and fill-rule flags, registered: consumed in the phase after the one
    /// that chose their operands.
    pr_a0: DFF<Signed<46>>,
    pr_a1: DFF<Signed<46>>,
    pr_b0: DFF<Signed<46>>,
    pr_b1: DFF<Signed<46>>,
    prtl_a: DFF<Bit>,
    prtl_b: DFF<Bit>,
    /// The fill-rule flags a cycle later, beside the products (`MulPipeS`: a product lands two cycles
    /// after its operands, issue 15 item 5).
    prtl2_a: DFF<Bit>,
    prtl2_b: DFF<Bit>,
    /// S2 entered phase 3 at the last edge (na's product is in `pr_b*` in this cycle only).
    s2_fresh3: DFF<Bit>,
    /// S3 took its record at the last edge (nb's product is in `pr_b*`).
    s3_first: DFF<Bit>,
    n_dz10: DFF<Signed<25>>,
    n_dz20: DFF<Signed<25>>,
    n_dx10: DFF<Signed<21>>,
    n_dx20: DFF<Signed<21>>,
    n_dy10: DFF<Signed<21>>,
    n_dy20: DFF<Signed<21>>,
    // S3, S4, S5 `Hold`.
    s3_v: DFF<Bit>,
    s3: DFF<SetupRec>,
    s3p: DFF<PlaneIn>,
    s4_v: DFF<Bit>,
    s4: DFF<SetupRec>,
    s4p: DFF<PlaneIn>,
    s5_v: DFF<Bit>,
    s5: DFF<SetupRec>,
    s5p: DFF<PlaneIn>,
    // S6 `Grad`: the record, its phase, the product register.
    s6_v: DFF<Bit>,
    s6_phase: DFF<Bits<2>>,
    s6: DFF<SetupRec>,
    s6p: DFF<PlaneIn>,
    g_prod: DFF<Bits<73>>,
    /// The gradient multiplier's first operand, registered (issue 15 item 5: the phase's choice in
    /// front of the product was the RC's critical path): na from the record entering S6, nb from the
    /// end of phase 0 on.
    ga_op: DFF<Signed<47>>,
    /// Its second operand, registered: a copy of the reciprocal's result mantissa (loaded from the
    /// result station's input, `recip.next_mant`), held over the cycle after S6 takes it, when the
    /// station may already hold the next result: the mantissa for nb*mant in phase 1.
    gb_op: DFF<Bits<25>>,
    /// The product shifted right by shift + 3 (arithmetic): the gradient before its last bit's rounding.
    g_sh: DFF<Bits<73>>,
    // S7 `Plane`: the record, its phase, the two product registers, their sum, C and the sum of the
    // start terms.
    s7_v: DFF<Bit>,
    s7_phase: DFF<Bits<2>>,
    s7: DFF<SetupRec>,
    s7p: DFF<PlaneIn>,
    /// The plane multipliers' second operands, registered (issue 15 item 5: `128 - x0` and the phase's
    /// choice in front of the product were the RC's critical path): `128 - x0`, `128 - y0` from the
    /// record entering S7, then X0, Y0 from the end of phase 0 on. The first operands are A and B
    /// straight from `s7`.
    pb_op: DFF<Signed<21>>,
    qb_op: DFF<Signed<21>>,
    p_prod: DFF<Bits<61>>,
    q_prod: DFF<Bits<61>>,
    /// A*(128-x0) + B*(128-y0) + 128: C's sum with its rounding constant.
    p_acc: DFF<Bits<62>>,
    // The record queue: four slots written in turn (`q_wp`) and read in turn (`q_rp`), and its length.
    // A ring, not a shift register: taking a record moves only the read pointer, so `rec_ready` fans
    // out to two flip-flops instead of every slot's load select (issue 15 item 5: that fan-out was the
    // RC's critical path once S2's products were registered).
    q0: DFF<SetupRec>,
    q1: DFF<SetupRec>,
    q2: DFF<SetupRec>,
    q3: DFF<SetupRec>,
    q_wp: DFF<Bits<2>>,
    q_rp: DFF<Bits<2>>,
    q_len: DFF<Bits<3>>,

    // Combinational: the handshake
    leave0: Signal<Local, Bit>,
    leave1: Signal<Local, Bit>,
    leave2: Signal<Local, Bit>,
    leave3: Signal<Local, Bit>,
    leave4: Signal<Local, Bit>,
    leave5: Signal<Local, Bit>,
    leave6: Signal<Local, Bit>,
    leave7: Signal<Local, Bit>,
    free1: Signal<Local, Bit>,
    free2: Signal<Local, Bit>,
    free3: Signal<Local, Bit>,
    free4: Signal<Local, Bit>,
    free5: Signal<Local, Bit>,
    free6: Signal<Local, Bit>,
    free7: Signal<Local, Bit>,
    done2: Signal<Local, Bit>,
    done6: Signal<Local, Bit>,
    done7: Signal<Local, Bit>,
    walk2: Signal<Local, Bit>,
    walk6: Signal<Local, Bit>,
    walk7: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    q_after: Signal<Local, Bits<3>>,
    pushed: Signal<Local, SetupRec>,
    head: Signal<Local, SetupRec>,
    // The multiples pushed with a record (`SetupRec::sx3_k`): mJ_K edge K's step widened to J bits,
    // m32d twice it, m34s sixteen times it; m42d twice A.
    m30_0: Signal<Local, Signed<30>>,
    m32_0: Signal<Local, Signed<32>>,
    m32d_0: Signal<Local, Signed<32>>,
    m34_0: Signal<Local, Signed<34>>,
    m34s_0: Signal<Local, Signed<34>>,
    m30_1: Signal<Local, Signed<30>>,
    m32_1: Signal<Local, Signed<32>>,
    m32d_1: Signal<Local, Signed<32>>,
    m34_1: Signal<Local, Signed<34>>,
    m34s_1: Signal<Local, Signed<34>>,
    m30_2: Signal<Local, Signed<30>>,
    m32_2: Signal<Local, Signed<32>>,
    m32d_2: Signal<Local, Signed<32>>,
    m34_2: Signal<Local, Signed<34>>,
    m34s_2: Signal<Local, Signed<34>>,
    m40: Signal<Local, Signed<40>>,
    m42: Signal<Local, Signed<42>>,
    m42d: Signal<Local, Signed<42>>,
    // S0
    c0x: Signal<Local, Signed<20>>,
    c0y: Signal<Local, Signed<20>>,
    c1x: Signal<Local, Signed<20>>,
    c1y: Signal<Local, Signed<20>>,
    c2x: Signal<Local, Signed<20>>,
    c2y: Signal<Local, Signed<20>>,
    dx10: Signal<Local, Signed<21>>,
    dy10: Signal<Local, Signed<21>>,
    dx20: Signal<Local, Signed<21>>,
    dy20: Signal<Local, Signed<21>>,
    det: Signal<Local, Signed<44>>,
    det_eq: Signal<Local, Bit>,
    ndet: Signal<Local, Signed<44>>,
    abs_now: Signal<Local, Bits<44>>,
    box_empty: Signal<Local, Bit>,
    /// The box's emptiness from each vertex's own bounds (`oz`: the offset-binary coordinate in 21 bits;
    /// `lo`, `hi`: (c + 127) >> 8 and (c - 128) >> 8 in bits 8..20, offset-binary), as compares side by side.
    oz0x: Signal<Local, Bits<21>>,
    lo0x: Signal<Local, Bits<21>>,
    hi0x: Signal<Local, Bits<21>>,
    oz1x: Signal<Local, Bits<21>>,
    lo1x: Signal<Local, Bits<21>>,
    hi1x: Signal<Local, Bits<21>>,
    oz2x: Signal<Local, Bits<21>>,
    lo2x: Signal<Local, Bits<21>>,
    hi2x: Signal<Local, Bits<21>>,
    oz0y: Signal<Local, Bits<21>>,
    lo0y: Signal<Local, Bits<21>>,
    hi0y: Signal<Local, Bits<21>>,
    oz1y: Signal<Local, Bits<21>>,
    lo1y: Signal<Local, Bits<21>>,
    hi1y: Signal<Local, Bits<21>>,
    oz2y: Signal<Local, Bits<21>>,
    lo2y: Signal<Local, Bits<21>>,
    hi2y: Signal<Local, Bits<21>>,
    k_lo21: Constant<Bits<21>>,
    k_hi21: Constant<Bits<21>>,
    o0x: Signal<Local, Bits<20>>,
    o0y: Signal<Local, Bits<20>>,
    o1x: Signal<Local, Bits<20>>,
    o1y: Signal<Local, Bits<20>>,
    o2x: Signal<Local, Bits<20>>,
    o2y: Signal<Local, Bits<20>>,
    /// S0's box per vertex: `(v + 127) >> 8` not below 0 (`c?0_i`), `(v - 128) >> 8` not above the
    /// screen's last row or column (`c?1_i`), 13-bit two's complement; the box takes the minimum's and
    /// the maximum's (issue 15 item 5: the clamp no longer waits for the compares).
    cx0_0: Signal<Local, Bits<13>>,
    cx0_1: Signal<Local, Bits<13>>,
    cx0_2: Signal<Local, Bits<13>>,
    cx1_0: Signal<Local, Bits<13>>,
    cx1_1: Signal<Local, Bits<13>>,
    cx1_2: Signal<Local, Bits<13>>,
    cy0_0: Signal<Local, Bits<13>>,
    cy0_1: Signal<Local, Bits<13>>,
    cy0_2: Signal<Local, Bits<13>>,
    cy1_0: Signal<Local, Bits<13>>,
    cy1_1: Signal<Local, Bits<13>>,
    cy1_2: Signal<Local, Bits<13>>,
    box_x0_u: Signal<Local, Bits<13>>,
    box_x1_u: Signal<Local, Bits<13>>,
    box_y0_u: Signal<Local, Bits<13>>,
    box_y1_u: Signal<Local, Bits<13>>,
    // S1
    is_tri: Signal<Local, Bit>,
    det_neg: Signal<Local, Bit>,
    det_zero: Signal<Local, Bit>,
    is_front: Signal<Local, Bit>,
    culled_now: Signal<Local, Bit>,
    walk1: Signal<Local, Bit>,
    det_abs: Signal<Local, Bits<44>>,
    rkind: Signal<Local, Bits<2>>,
    // canonical vertices
    cx0: Signal<Local, Signed<20>>,
    cy0: Signal<Local, Signed<20>>,
    cz0: Signal<Local, Bits<24>>,
    cx1: Signal<Local, Signed<20>>,
    cy1: Signal<Local, Signed<20>>,
    cz1: Signal<Local, Bits<24>>,
    cx2: Signal<Local, Signed<20>>,
    cy2: Signal<Local, Signed<20>>,
    cz2: Signal<Local, Bits<24>>,
    cdx10: Signal<Local, Signed<21>>,
    cdy10: Signal<Local, Signed<21>>,
    cdx20: Signal<Local, Signed<21>>,
    cdy20: Signal<Local, Signed<21>>,
    cdz10: Signal<Local, Signed<25>>,
    cdz20: Signal<Local, Signed<25>>,
    cx16: Signal<Local, Bits<21>>,
    cy16: Signal<Local, Bits<21>>,
    addr_prod: Signal<Local, Bits<32>>,
    edx_0: Signal<Local, Signed<21>>,
    edy_0: Signal<Local, Signed<21>>,
    px_0: Signal<Local, Signed<21>>,
    py_0: Signal<Local, Signed<21>>,
    tl_0: Signal<Local, Bit>,
    negdy_0: Signal<Local, Signed<21>>,
    negdyw_0: Signal<Local, Signed<30>>,
    edxw_0: Signal<Local, Signed<30>>,
    stx_0: Signal<Local, Signed<30>>,
    sty_0: Signal<Local, Signed<30>>,
    edx_1: Signal<Local, Signed<21>>,
    edy_1: Signal<Local, Signed<21>>,
    px_1: Signal<Local, Signed<21>>,
    py_1: Signal<Local, Signed<21>>,
    tl_1: Signal<Local, Bit>,
    negdy_1: Signal<Local, Signed<21>>,
    negdyw_1: Signal<Local, Signed<30>>,
    edxw_1: Signal<Local, Signed<30>>,
    stx_1: Signal<Local, Signed<30>>,
    sty_1: Signal<Local, Signed<30>>,
    edx_2: Signal<Local, Signed<21>>,
    edy_2: Signal<Local, Signed<21>>,
    px_2: Signal<Local, Signed<21>>,
    py_2: Signal<Local, Signed<21>>,
    tl_2: Signal<Local, Bit>,
    negdy_2: Signal<Local, Signed<21>>,
    negdyw_2: Signal<Local, Signed<30>>,
    edxw_2: Signal<Local, Signed<30>>,
    stx_2: Signal<Local, Signed<30>>,
    sty_2: Signal<Local, Signed<30>>,
    // S2
    dot_a: Signal<Local, Signed<47>>,
    dot_b: Signal<Local, Signed<47>>,
    e_a: Signal<Local, Signed<44>>,
    e_b: Signal<Local, Signed<44>>,
    // S6
    /// The product doubled: the gradient's shift is by `shift - 1`, done as `2*prod >> shift`.
    g_dbl: Signal<Local, Bits<73>>,
    shifted: Signal<Local, Bits<73>>,
    rounded: Signal<Local, Bits<73>>,
    halved: Signal<Local, Bits<73>>,
    grad_hi: Signal<Local, Bits<34>>,
    grad: Signal<Local, Signed<40>>,
    // S7
    off_x: Signal<Local, Signed<21>>,
    off_y: Signal<Local, Signed<21>>,
    pw: Signal<Local, Signed<62>>,
    qw: Signal<Local, Signed<62>>,
    p56: Signal<Local, Signed<56>>,
    q56: Signal<Local, Signed<56>>,
    acc_sum: Signal<Local, Signed<62>>,
    acc_round: Signal<Local, Bits<62>>,
    c_frac: Signal<Local, Signed<56>>,
    c_now: Signal<Local, Signed<56>>,
    s_now: Signal<Local, Signed<56>>,
    z0_plane: Signal<Local, Signed<56>>,
    raw_now: Signal<Local, Signed<56>>,

    // Constants
    w_minus_1: Constant<Bits<13>>,
    w_minus_1_o: Constant<Bits<13>>,
    h_minus_1_o: Constant<Bits<13>>,
    k_sign20: Constant<Bits<20>>,
    k_sign13: Constant<Bits<13>>,
    zb13: Constant<Bits<13>>,
    h_minus_1: Constant<Bits<13>>,
    width: Constant<Bits<16>>,
    k128_21: Constant<Signed<21>>,
    k128_21u: Constant<Bits<21>>,
    k8_6: Constant<Bits<6>>,
    k1_73: Constant<Bits<73>>,
    k1_6: Constant<Bits<6>>,
    k4_6: Constant<Bits<6>>,
    k0_73: Constant<Bits<73>>,
    k0_13u: Constant<Bits<13>>,
    k0_44: Constant<Signed<44>>,
    k1_44: Constant<Signed<44>>,
    k0_21: Constant<Signed<21>>,
    k0_2: Constant<Bits<2>>,
    k1_2: Constant<Bits<2>>,
    k2_2: Constant<Bits<2>>,
    k3_2: Constant<Bits<2>>,
    k0_3: Constant<Bits<3>>,
    k1_3: Constant<Bits<3>>,
    k4_3: Constant<Bits<3>>,
    k0_34: Constant<Bits<34>>,
    k16_6: Constant<Bits<6>>,
    k1s_34: Constant<Bits<34>>,
    k128_62: Constant<Bits<62>>,
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
    // zeros: the values of a stage's locals while it is empty
    zb21: Constant<Bits<21>>,
    zb2: Constant<Bits<2>>,
    zb24: Constant<Bits<24>>,
    zb32: Constant<Bits<32>>,
    zb44: Constant<Bits<44>>,
    zb62: Constant<Bits<62>>,
    zs20: Constant<Signed<20>>,
    zs21: Constant<Signed<21>>,
    zs30: Constant<Signed<30>>,
    zs25: Constant<Signed<25>>,
    zs44: Constant<Signed<44>>,
    zs40: Constant<Signed<40>>,
    zs47: Constant<Signed<47>>,
    zs56: Constant<Signed<56>>,
    zs62: Constant<Signed<62>>,
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
            rec_c: Default::default(),
            recip: Default::default(),
            mul_d0: Default::default(),
            mul_d1: Default::default(),
            mul_a0: Default::default(),
            mul_a1: Default::default(),
            mul_b0: Default::default(),
            mul_b1: Default::default(),
            mul_g: Default::default(),
            mul_p: Default::default(),
            mul_q: Default::default(),
            s0_v: Default::default(),
            s0: Default::default(),
            s1_v: Default::default(),
            s1: Default::default(),
            s1_det: Default::default(),
            s1_bx0: Default::default(),
            s1_bx1: Default::default(),
            s1_by0: Default::default(),
            s1_by1: Default::default(),
            s1_box_empty: Default::default(),
            s1_det_zero: Default::default(),
            s1_det_abs: Default::default(),
            s2_v: Default::default(),
            s2_phase: Default::default(),
            s2: Default::default(),
            s2p: Default::default(),
            la0: Default::default(),
            lb0: Default::default(),
            ra0: Default::default(),
            rb0: Default::default(),
            tl0: Default::default(),
            la1: Default::default(),
            lb1: Default::default(),
            ra1: Default::default(),
            rb1: Default::default(),
            tl1: Default::default(),
            la2: Default::default(),
            lb2: Default::default(),
            ra2: Default::default(),
            rb2: Default::default(),
            tl2: Default::default(),
            pr_a0: Default::default(),
            pr_a1: Default::default(),
            pr_b0: Default::default(),
            pr_b1: Default::default(),
            prtl_a: Default::default(),
            prtl_b: Default::default(),
            prtl2_a: Default::default(),
            prtl2_b: Default::default(),
            s2_fresh3: Default::default(),
            s3_first: Default::default(),
            n_dz10: Default::default(),
            n_dz20: Default::default(),
            n_dx10: Default::default(),
            n_dx20: Default::default(),
            n_dy10: Default::default(),
            n_dy20: Default::default(),
            s3_v: Default::default(),
            s3: Default::default(),
            s3p: Default::default(),
            s4_v: Default::default(),
            s4: Default::default(),
            s4p: Default::default(),
            s5_v: Default::default(),
            s5: Default::default(),
            s5p: Default::default(),
            s6_v: Default::default(),
            s6_phase: Default::default(),
            s6: Default::default(),
            s6p: Default::default(),
            g_prod: Default::default(),
            ga_op: Default::default(),
            gb_op: Default::default(),
            g_sh: Default::default(),
            s7_v: Default::default(),
            s7_phase: Default::default(),
            s7: Default::default(),
            s7p: Default::default(),
            pb_op: Default::default(),
            qb_op: Default::default(),
            p_prod: Default::default(),
            q_prod: Default::default(),
            p_acc: Default::default(),
            q0: Default::default(),
            q1: Default::default(),
            q2: Default::default(),
            q3: Default::default(),
            q_wp: Default::default(),
            q_rp: Default::default(),
            q_len: Default::default(),
            leave0: Default::default(),
            leave1: Default::default(),
            leave2: Default::default(),
            leave3: Default::default(),
            leave4: Default::default(),
            leave5: Default::default(),
            leave6: Default::default(),
            leave7: Default::default(),
            free1: Default::default(),
            free2: Default::default(),
            free3: Default::default(),
            free4: Default::default(),
            free5: Default::default(),
            free6: Default::default(),
            free7: Default::default(),
            done2: Default::default(),
            done6: Default::default(),
            done7: Default::default(),
            walk2: Default::default(),
            walk6: Default::default(),
            walk7: Default::default(),
            take: Default::default(),
            pop: Default::default(),
            q_after: Default::default(),
            pushed: Default::default(),
            head: Default::default(),
            m30_0: Default::default(),
            m32_0: Default::default(),
            m32d_0: Default::default(),
            m34_0: Default::default(),
            m34s_0: Default::default(),
            m30_1: Default::default(),
            m32_1: Default::default(),
            m32d_1: Default::default(),
            m34_1: Default::default(),
            m34s_1: Default::default(),
            m30_2: Default::default(),
            m32_2: Default::default(),
            m32d_2: Default::default(),
            m34_2: Default::default(),
            m34s_2: Default::default(),
            m40: Default::default(),
            m42: Default::default(),
            m42d: Default::default(),
            rec_sx3_0: Default::default(),
            rec_sx3_1: Default::default(),
            rec_sx3_2: Default::default(),
            rec_sx15_0: Default::default(),
            rec_sx15_1: Default::default(),
            rec_sx15_2: Default::default(),
            rec_a3: Default::default(),
            c0x: Default::default(),
            c0y: Default::default(),
            c1x: Default::default(),
            c1y: Default::default(),
            c2x: Default::default(),
            c2y: Default::default(),
            dx10: Default::default(),
            dy10: Default::default(),
            dx20: Default::default(),
            dy20: Default::default(),
            det: Default::default(),
            det_eq: Default::default(),
            ndet: Default::default(),
            abs_now: Default::default(),
            box_empty: Default::default(),
            oz0x: Default::default(),
            lo0x: Default::default(),
            hi0x: Default::default(),
            oz1x: Default::default(),
            lo1x: Default::default(),
            hi1x: Default::default(),
            oz2x: Default::default(),
            lo2x: Default::default(),
            hi2x: Default::default(),
            oz0y: Default::default(),
            lo0y: Default::default(),
            hi0y: Default::default(),
            oz1y: Default::default(),
            lo1y: Default::default(),
            hi1y: Default::default(),
            oz2y: Default::default(),
            lo2y: Default::default(),
            hi2y: Default::default(),
            k_lo21: Constant::new(((1u64 << 19) + 127).into()),
            k_hi21: Constant::new(((1u64 << 19) - 128).into()),
            o0x: Default::default(),
            o0y: Default::default(),
            o1x: Default::default(),
            o1y: Default::default(),
            o2x: Default::default(),
            o2y: Default::default(),
            cx0_0: Default::default(),
            cx0_1: Default::default(),
            cx0_2: Default::default(),
            cx1_0: Default::default(),
            cx1_1: Default::default(),
            cx1_2: Default::default(),
            cy0_0: Default::default(),
            cy0_1: Default::default(),
            cy0_2: Default::default(),
            cy1_0: Default::default(),
            cy1_1: Default::default(),
            cy1_2: Default::default(),
            box_x0_u: Default::default(),
            box_x1_u: Default::default(),
            box_y0_u: Default::default(),
            box_y1_u: Default::default(),
            is_tri: Default::default(),
            det_neg: Default::default(),
            det_zero: Default::default(),
            is_front: Default::default(),
            culled_now: Default::default(),
            walk1: Default::default(),
            det_abs: Default::default(),
            rkind: Default::default(),
            cx0: Default::default(),
            cy0: Default::default(),
            cz0: Default::default(),
            cx1: Default::default(),
            cy1: Default::default(),
            cz1: Default::default(),
            cx2: Default::default(),
            cy2: Default::default(),
            cz2: Default::default(),
            cdx10: Default::default(),
            cdy10: Default::default(),
            cdx20: Default::default(),
            cdy20: Default::default(),
            cdz10: Default::default(),
            cdz20: Default::default(),
            cx16: Default::default(),
            cy16: Default::default(),
            addr_prod: Default::default(),
            edx_0: Default::default(),
            edy_0: Default::default(),
            px_0: Default::default(),
            py_0: Default::default(),
            tl_0: Default::default(),
            negdy_0: Default::default(),
            negdyw_0: Default::default(),
            edxw_0: Default::default(),
            stx_0: Default::default(),
            sty_0: Default::default(),
            edx_1: Default::default(),
            edy_1: Default::default(),
            px_1: Default::default(),
            py_1: Default::default(),
            tl_1: Default::default(),
            negdy_1: Default::default(),
            negdyw_1: Default::default(),
            edxw_1: Default::default(),
            stx_1: Default::default(),
            sty_1: Default::default(),
            edx_2: Default::default(),
            edy_2: Default::default(),
            px_2: Default::default(),
            py_2: Default::default(),
            tl_2: Default::default(),
            negdy_2: Default::default(),
            negdyw_2: Default::default(),
            edxw_2: Default::default(),
            stx_2: Default::default(),
            sty_2: Default::default(),
            dot_a: Default::default(),
            dot_b: Default::default(),
            e_a: Default::default(),
            e_b: Default::default(),
            g_dbl: Default::default(),
            shifted: Default::default(),
            rounded: Default::default(),
            halved: Default::default(),
            grad_hi: Default::default(),
            grad: Default::default(),
            off_x: Default::default(),
            off_y: Default::default(),
            pw: Default::default(),
            qw: Default::default(),
            p56: Default::default(),
            q56: Default::default(),
            acc_sum: Default::default(),
            acc_round: Default::default(),
            c_frac: Default::default(),
            c_now: Default::default(),
            s_now: Default::default(),
            z0_plane: Default::default(),
            raw_now: Default::default(),
            w_minus_1: Constant::new((width as u64 - 1).into()),
            w_minus_1_o: Constant::new(((width as u64 - 1) ^ 0x1000).into()),
            h_minus_1_o: Constant::new(((height as u64 - 1) ^ 0x1000).into()),
            k_sign20: Constant::new(0x80000u64.into()),
            k_sign13: Constant::new(0x1000u64.into()),
            zb13: Constant::new(0.into()),
            h_minus_1: Constant::new((height as u64 - 1).into()),
            width: Constant::new((width as u64).into()),
            k128_21: Constant::new(128.into()),
            k128_21u: Constant::new(128.into()),
            k8_6: Constant::new(8.into()),
            k1_73: Constant::new(1.into()),
            k1_6: Constant::new(1.into()),
            k4_6: Constant::new(4.into()),
            k0_73: Constant::new(0.into()),
            k0_13u: Constant::new(0.into()),
            k0_44: Constant::new(0.into()),
            k1_44: Constant::new(1.into()),
            k0_21: Constant::new(0.into()),
            k0_2: Constant::new(0.into()),
            k1_2: Constant::new(1.into()),
            k2_2: Constant::new(2.into()),
            k3_2: Constant::new(3.into()),
            k0_3: Constant::new(0.into()),
            k1_3: Constant::new(1.into()),
            k4_3: Constant::new(4.into()),
            k0_34: Constant::new(0.into()),
            k16_6: Constant::new(16.into()),
            k1s_34: Constant::new(((1u64 << 34) - 1).into()),
            k128_62: Constant::new(128.into()),
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
            zb21: Constant::new(0.into()),
            zb2: Constant::new(0.into()),
            zb24: Constant::new(0.into()),
            zb32: Constant::new(0.into()),
            zb44: Constant::new(0.into()),
            zb62: Constant::new(0.into()),
            zs20: Constant::new(0.into()),
            zs21: Constant::new(0.into()),
            zs30: Constant::new(0.into()),
            zs25: Constant::new(0.into()),
            zs44: Constant::new(0.into()),
            zs40: Constant::new(0.into()),
            zs47: Constant::new(0.into()),
            zs56: Constant::new(0.into()),
            zs62: Constant::new(0.into()),
        }
    }
}

impl Logic for Setup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s0_v, s0, s1_v, s1, s1_det, s1_bx0, s1_bx1, s1_by0, s1_by1, s1_box_empty, s1_det_zero, s1_det_abs, s2_v, s2_phase, s2, s2p, la0, lb0, ra0, rb0, tl0, la1, lb1, ra1, rb1, tl1, la2, lb2, ra2, rb2, tl2, pr_a0, pr_a1, pr_b0, pr_b1, prtl_a, prtl_b, prtl2_a, prtl2_b, s2_fresh3, s3_first, n_dz10, n_dz20, n_dx10, n_dx20, n_dy10, n_dy20, s3_v, s3, s3p, s4_v, s4, s4p, s5_v, s5, s5p, s6_v, s6_phase, s6, s6p, g_prod, ga_op, gb_op, g_sh, s7_v, s7_phase, s7, s7p, pb_op, qb_op, p_prod, q_prod, p_acc, q0, q1, q2, q3, q_wp, q_rp, q_len);
        clock!(self, clock, recip);

        // ---- S1 `Order` ----
        self.is_tri.next = false;
        self.det_neg.next = false;
        self.det_zero.next = false;
        self.is_front.next = false;
        self.culled_now.next = false;
        self.walk1.next = false;
        self.rkind.next = self.zb2.val();
        self.cx0.next = self.zs20.val();
        self.cy0.next = self.zs20.val();
        self.cz0.next = self.zb24.val();
        self.cx1.next = self.zs20.val();
        self.cy1.next = self.zs20.val();
        self.cz1.next = self.zb24.val();
        self.cx2.next = self.zs20.val();
        self.cy2.next = self.zs20.val();
        self.cz2.next = self.zb24.val();
        self.cdx10.next = self.zs21.val();
        self.cdy10.next = self.zs21.val();
        self.cdx20.next = self.zs21.val();
        self.cdy20.next = self.zs21.val();
        self.cdz10.next = self.zs25.val();
        self.cdz20.next = self.zs25.val();
        self.cx16.next = self.zb21.val();
        self.cy16.next = self.zb21.val();
        self.addr_prod.next = self.zb32.val();
        self.edx_0.next = self.zs21.val();
        self.edy_0.next = self.zs21.val();
        self.px_0.next = self.zs21.val();
        self.py_0.next = self.zs21.val();
        self.tl_0.next = false;
        self.negdy_0.next = self.zs21.val();
        self.negdyw_0.next = self.zs30.val();
        self.edxw_0.next = self.zs30.val();
        self.stx_0.next = self.zs30.val();
        self.sty_0.next = self.zs30.val();
        self.edx_1.next = self.zs21.val();
        self.edy_1.next = self.zs21.val();
        self.px_1.next = self.zs21.val();
        self.py_1.next = self.zs21.val();
        self.tl_1.next = false;
        self.negdy_1.next = self.zs21.val();
        self.negdyw_1.next = self.zs30.val();
        self.edxw_1.next = self.zs30.val();
        self.stx_1.next = self.zs30.val();
        self.sty_1.next = self.zs30.val();
        self.edx_2.next = self.zs21.val();
        self.edy_2.next = self.zs21.val();
        self.px_2.next = self.zs21.val();
        self.py_2.next = self.zs21.val();
        self.tl_2.next = false;
        self.negdy_2.next = self.zs21.val();
        self.negdyw_2.next = self.zs30.val();
        self.edxw_2.next = self.zs30.val();
        self.stx_2.next = self.zs30.val();
        self.sty_2.next = self.zs30.val();
        if self.s1_v.q.val() {
            self.is_tri.next = self.s1.q.val().kind == self.kind_tri.val();
            self.det_neg.next = self.s1_det.q.val().get_bit(43);
            self.det_zero.next = self.s1_det_zero.q.val();
            self.is_front.next = self.det_neg.val();
            if self.s1.q.val().front_cw {
                self.is_front.next = !self.det_neg.val();
            }
            self.culled_now.next = self.det_zero.val()
                | ((self.s1.q.val().cull == self.cull_back.val()) & !self.is_front.val())
                | ((self.s1.q.val().cull == self.cull_front.val()) & self.is_front.val());
            self.walk1.next = self.is_tri.val() & !self.culled_now.val() & !self.s1_box_empty.q.val();
            self.rkind.next = self.rec_frame.val();
            if self.s1.q.val().kind == self.kind_eof.val() {
                self.rkind.next = self.rec_eof.val();
            }
            if self.is_tri.val() {
                self.rkind.next = self.rec_skip.val();
                if self.walk1.val() {
                    self.rkind.next = self.rec_walk.val();
                }
            }
        }
        // ---- The handshake, last stage first ----
        self.walk2.next = self.s2.q.val().kind == self.rec_walk.val();
        self.walk6.next = self.s6.q.val().kind == self.rec_walk.val();
        self.walk7.next = self.s7.q.val().kind == self.rec_walk.val();
        self.done2.next = self.s2_v.q.val() & (!self.walk2.val() | (self.s2_phase.q.val() == self.k3_2.val()));
        self.done6.next = self.s6_v.q.val() & (!self.walk6.val() | (self.s6_phase.q.val() == self.k3_2.val()));
        self.done7.next = self.s7_v.q.val() & (!self.walk7.val() | (self.s7_phase.q.val() == self.k3_2.val()));
        self.take.next = self.recip.result.valid.val() & self.s6_v.q.val() & self.walk6.val() & (self.s6_phase.q.val() == self.k0_2.val());
        self.leave7.next = self.done7.val() & (self.q_len.q.val() < self.k4_3.val());
        self.free7.next = !self.s7_v.q.val() | self.leave7.val();
        self.leave6.next = self.done6.val() & self.free7.val();
        self.free6.next = !self.s6_v.q.val() | self.leave6.val();
        self.leave5.next = self.s5_v.q.val() & self.free6.val();
        self.free5.next = !self.s5_v.q.val() | self.leave5.val();
        self.leave4.next = self.s4_v.q.val() & self.free5.val();
        self.free4.next = !self.s4_v.q.val() | self.leave4.val();
        self.leave3.next = self.s3_v.q.val() & self.free4.val();
        self.free3.next = !self.s3_v.q.val() | self.leave3.val();
        self.leave2.next = self.done2.val() & self.free3.val();
        self.free2.next = !self.s2_v.q.val() | self.leave2.val();
        // S1 hands a drawn triangle on only when the reciprocal takes its request.
        self.leave1.next = self.s1_v.q.val() & self.free2.val() & (!self.walk1.val() | self.recip.request.ready.val());
        self.free1.next = !self.s1_v.q.val() | self.leave1.val();
        self.leave0.next = self.s0_v.q.val() & self.free1.val();
        self.cmd.ready.next = !self.s0_v.q.val() | self.leave0.val();

        // S1's canonical order and edges.
        if self.s1_v.q.val() {
            // Canonical order: vertices 1 and 2 swapped where det < 0.
            self.cx0.next = signed_cast(self.s1.q.val().x0);
            self.cy0.next = signed_cast(self.s1.q.val().y0);
            self.cz0.next = self.s1.q.val().z0;
            self.cx1.next = signed_cast(self.s1.q.val().x1);
            self.cy1.next = signed_cast(self.s1.q.val().y1);
            self.cz1.next = self.s1.q.val().z1;
            self.cx2.next = signed_cast(self.s1.q.val().x2);
            self.cy2.next = signed_cast(self.s1.q.val().y2);
            self.cz2.next = self.s1.q.val().z2;
            if self.det_neg.val() {
                self.cx1.next = signed_cast(self.s1.q.val().x2);
                self.cy1.next = signed_cast(self.s1.q.val().y2);
                self.cz1.next = self.s1.q.val().z2;
                self.cx2.next = signed_cast(self.s1.q.val().x1);
                self.cy2.next = signed_cast(self.s1.q.val().y1);
                self.cz2.next = self.s1.q.val().z1;
            }
            self.cdx10.next = signed_bit_cast_safe::<21, 20>(self.cx1.val()) - signed_bit_cast_safe::<21, 20>(self.cx0.val());
            self.cdy10.next = signed_bit_cast_safe::<21, 20>(self.cy1.val()) - signed_bit_cast_safe::<21, 20>(self.cy0.val());
            self.cdx20.next = signed_bit_cast_safe::<21, 20>(self.cx2.val()) - signed_bit_cast_safe::<21, 20>(self.cx0.val());
            self.cdy20.next = signed_bit_cast_safe::<21, 20>(self.cy2.val()) - signed_bit_cast_safe::<21, 20>(self.cy0.val());
            self.cdz10.next = signed_cast(bit_cast::<25, 24>(self.cz1.val())) - signed_cast(bit_cast::<25, 24>(self.cz0.val()));
            self.cdz20.next = signed_cast(bit_cast::<25, 24>(self.cz2.val())) - signed_cast(bit_cast::<25, 24>(self.cz0.val()));
            // Pixel centre of the box's first pixel in subpixels: 16*X0 + 8.
            self.cx16.next = (bit_cast::<21, 10>(self.s1_bx0.q.val()) << self.k8_6.val()) | self.k128_21u.val();
            self.cy16.next = (bit_cast::<21, 10>(self.s1_by0.q.val()) << self.k8_6.val()) | self.k128_21u.val();
            self.addr_prod.next = bit_cast::<16, 10>(self.s1_by0.q.val()) * self.width.val();
            // Edge 0: from (cx0, cy0) to (cx1, cy1).
            self.edx_0.next = signed_bit_cast_safe::<21, 20>(self.cx1.val()) - signed_bit_cast_safe::<21, 20>(self.cx0.val());
            self.edy_0.next = signed_bit_cast_safe::<21, 20>(self.cy1.val()) - signed_bit_cast_safe::<21, 20>(self.cy0.val());
            self.px_0.next = signed_cast(self.cx16.val()) - signed_bit_cast_safe::<21, 20>(self.cx0.val());
            self.py_0.next = signed_cast(self.cy16.val()) - signed_bit_cast_safe::<21, 20>(self.cy0.val());
            self.tl_0.next = self.edy_0.val().get_bit(20)
                | ((self.edy_0.val() == self.k0_21.val()) & !self.edx_0.val().get_bit(20) & (self.edx_0.val() != self.k0_21.val()));
            self.negdy_0.next = self.k0_21.val() - self.edy_0.val();
            self.negdyw_0.next = signed_bit_cast_safe::<30, 21>(self.negdy_0.val());
            self.edxw_0.next = signed_bit_cast_safe::<30, 21>(self.edx_0.val());
            self.stx_0.next = signed_cast(unsigned_cast(self.negdyw_0.val()) << self.k8_6.val());
            self.sty_0.next = signed_cast(unsigned_cast(self.edxw_0.val()) << self.k8_6.val());
            // Edge 1: from (cx1, cy1) to (cx2, cy2).
            self.edx_1.next = signed_bit_cast_safe::<21, 20>(self.cx2.val()) - signed_bit_cast_safe::<21, 20>(self.cx1.val());
            self.edy_1.next = signed_bit_cast_safe::<21, 20>(self.cy2.val()) - signed_bit_cast_safe::<21, 20>(self.cy1.val());
            self.px_1.next = signed_cast(self.cx16.val()) - signed_bit_cast_safe::<21, 20>(self.cx1.val());
            self.py_1.next = signed_cast(self.cy16.val()) - signed_bit_cast_safe::<21, 20>(self.cy1.val());
            self.tl_1.next = self.edy_1.val().get_bit(20)
                | ((self.edy_1.val() == self.k0_21.val()) & !self.edx_1.val().get_bit(20) & (self.edx_1.val() != self.k0_21.val()));
            self.negdy_1.next = self.k0_21.val() - self.edy_1.val();
            self.negdyw_1.next = signed_bit_cast_safe::<30, 21>(self.negdy_1.val());
            self.edxw_1.next = signed_bit_cast_safe::<30, 21>(self.edx_1.val());
            self.stx_1.next = signed_cast(unsigned_cast(self.negdyw_1.val()) << self.k8_6.val());
            self.sty_1.next = signed_cast(unsigned_cast(self.edxw_1.val()) << self.k8_6.val());
            // Edge 2: from (cx2, cy2) to (cx0, cy0).
            self.edx_2.next = signed_bit_cast_safe::<21, 20>(self.cx0.val()) - signed_bit_cast_safe::<21, 20>(self.cx2.val());
            self.edy_2.next = signed_bit_cast_safe::<21, 20>(self.cy0.val()) - signed_bit_cast_safe::<21, 20>(self.cy2.val());
            self.px_2.next = signed_cast(self.cx16.val()) - signed_bit_cast_safe::<21, 20>(self.cx2.val());
            self.py_2.next = signed_cast(self.cy16.val()) - signed_bit_cast_safe::<21, 20>(self.cy2.val());
            self.tl_2.next = self.edy_2.val().get_bit(20)
                | ((self.edy_2.val() == self.k0_21.val()) & !self.edx_2.val().get_bit(20) & (self.edx_2.val() != self.k0_21.val()));
            self.negdy_2.next = self.k0_21.val() - self.edy_2.val();
            self.negdyw_2.next = signed_bit_cast_safe::<30, 21>(self.negdy_2.val());
            self.edxw_2.next = signed_bit_cast_safe::<30, 21>(self.edx_2.val());
            self.stx_2.next = signed_cast(unsigned_cast(self.negdyw_2.val()) << self.k8_6.val());
            self.sty_2.next = signed_cast(unsigned_cast(self.edxw_2.val()) << self.k8_6.val());
        }
        // ---- S0 `Det` ----
        self.det.next = self.zs44.val();
        self.det_eq.next = false;
        self.ndet.next = self.zs44.val();
        self.abs_now.next = self.zb44.val();
        if self.s0_v.q.val() {
            self.det.next = signed_bit_cast_safe::<44, 42>(self.mul_d0.p.val()) - signed_bit_cast_safe::<44, 42>(self.mul_d1.p.val());
            // det = 0 exactly when the two products are equal: a compare beside the subtraction.
            self.det_eq.next = self.mul_d0.p.val() == self.mul_d1.p.val();
            // |det| from the two differences side by side, chosen by det's sign.
            self.ndet.next = signed_bit_cast_safe::<44, 42>(self.mul_d1.p.val()) - signed_bit_cast_safe::<44, 42>(self.mul_d0.p.val());
            self.abs_now.next = unsigned_cast(self.det.val());
            if self.det.val().get_bit(43) {
                self.abs_now.next = unsigned_cast(self.ndet.val());
            }
        }
        // det's products start on the command port: the multipliers take their operands at the edge
        // where S0 takes the command (issue 15 item 5: S0's deltas, products and difference in one cycle
        // were the chipset's critical path), so S0 only sums the partial products. (Evaluated only while
        // a command is offered, for the Rust simulation.)
        self.c0x.next = self.zs20.val();
        self.c0y.next = self.zs20.val();
        self.c1x.next = self.zs20.val();
        self.c1y.next = self.zs20.val();
        self.c2x.next = self.zs20.val();
        self.c2y.next = self.zs20.val();
        self.dx10.next = self.zs21.val();
        self.dy10.next = self.zs21.val();
        self.dx20.next = self.zs21.val();
        self.dy20.next = self.zs21.val();
        if self.cmd.valid.val() {
            self.c0x.next = signed_cast(self.cmd.data.val().x0);
            self.c0y.next = signed_cast(self.cmd.data.val().y0);
            self.c1x.next = signed_cast(self.cmd.data.val().x1);
            self.c1y.next = signed_cast(self.cmd.data.val().y1);
            self.c2x.next = signed_cast(self.cmd.data.val().x2);
            self.c2y.next = signed_cast(self.cmd.data.val().y2);
            self.dx10.next = signed_bit_cast_safe::<21, 20>(self.c1x.val()) - signed_bit_cast_safe::<21, 20>(self.c0x.val());
            self.dy10.next = signed_bit_cast_safe::<21, 20>(self.c1y.val()) - signed_bit_cast_safe::<21, 20>(self.c0y.val());
            self.dx20.next = signed_bit_cast_safe::<21, 20>(self.c2x.val()) - signed_bit_cast_safe::<21, 20>(self.c0x.val());
            self.dy20.next = signed_bit_cast_safe::<21, 20>(self.c2y.val()) - signed_bit_cast_safe::<21, 20>(self.c0y.val());
        }
        self.mul_d0.clock.next = self.clock.val();
        self.mul_d1.clock.next = self.clock.val();
        self.mul_d0.ce.next = self.cmd.valid.val() & self.cmd.ready.val();
        self.mul_d1.ce.next = self.cmd.valid.val() & self.cmd.ready.val();
        self.mul_d0.a.next = self.dx10.val();
        self.mul_d0.b.next = self.dy20.val();
        self.mul_d1.a.next = self.dx20.val();
        self.mul_d1.b.next = self.dy10.val();
        // The bounding box does not depend on the vertex order. (Signed compares are slow in the Rust
        // simulation: det and the box are evaluated only while S0 holds a command. Every stage's
        // arithmetic is gated by its own valid register, never by the handshake, which would put the
        // leave chain in front of the arithmetic: gating S0 by its `leave` took the RC from 45.5 to
        // 35.4 MHz on the ECP5.)
        // Signed order as unsigned order with the sign bits flipped (offset binary): the same compare in
        // hardware, and rust-hdl's Signed compare goes through BigInt.
        self.o0x.next = self.s0.q.val().x0 ^ self.k_sign20.val();
        self.o0y.next = self.s0.q.val().y0 ^ self.k_sign20.val();
        self.o1x.next = self.s0.q.val().x1 ^ self.k_sign20.val();
        self.o1y.next = self.s0.q.val().y1 ^ self.k_sign20.val();
        self.o2x.next = self.s0.q.val().x2 ^ self.k_sign20.val();
        self.o2y.next = self.s0.q.val().y2 ^ self.k_sign20.val();
        // The box is empty when max(min lo, 0) > min(max hi, W-1): some bound of every pair crosses, or every
        // hi is negative, or every lo is past the screen. With the offset 2^20 (the offset-binary 20-bit
        // coordinate plus 2^19), bits 8..20 of c + 2^20 + k are the offset-binary 13-bit (c + k) >> 8, so all
        // the compares are unsigned and side by side: no minimum, maximum or clamp in front of them.
        self.oz0x.next = bit_cast::<21, 20>(self.o0x.val());
        self.oz1x.next = bit_cast::<21, 20>(self.o1x.val());
        self.oz2x.next = bit_cast::<21, 20>(self.o2x.val());
        self.lo0x.next = self.oz0x.val() + self.k_lo21.val();
        self.hi0x.next = self.oz0x.val() + self.k_hi21.val();
        self.lo1x.next = self.oz1x.val() + self.k_lo21.val();
        self.hi1x.next = self.oz1x.val() + self.k_hi21.val();
        self.lo2x.next = self.oz2x.val() + self.k_lo21.val();
        self.hi2x.next = self.oz2x.val() + self.k_hi21.val();
        self.oz0y.next = bit_cast::<21, 20>(self.o0y.val());
        self.oz1y.next = bit_cast::<21, 20>(self.o1y.val());
        self.oz2y.next = bit_cast::<21, 20>(self.o2y.val());
        self.lo0y.next = self.oz0y.val() + self.k_lo21.val();
        self.hi0y.next = self.oz0y.val() + self.k_hi21.val();
        self.lo1y.next = self.oz1y.val() + self.k_lo21.val();
        self.hi1y.next = self.oz1y.val() + self.k_hi21.val();
        self.lo2y.next = self.oz2y.val() + self.k_lo21.val();
        self.hi2y.next = self.oz2y.val() + self.k_hi21.val();
        // The box: [(min + 127) >> 8, (max - 128) >> 8] clamped to the screen. Clamping and shifting keep
        // the order, so each vertex's bound is formed and clamped beside the compares, which then only
        // choose one of three (bits 8..20 of lo/hi are the offset-binary bound; bit 20 clear: negative).
        self.cx0_0.next = self.lo0x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo0x.val().get_bit(20) {
            self.cx0_0.next = self.k0_13u.val();
        }
        self.cx1_0.next = self.hi0x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi0x.val().get_bits::<13>(8) > self.w_minus_1_o.val() {
            self.cx1_0.next = self.w_minus_1.val();
        }
        self.cx0_1.next = self.lo1x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo1x.val().get_bit(20) {
            self.cx0_1.next = self.k0_13u.val();
        }
        self.cx1_1.next = self.hi1x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi1x.val().get_bits::<13>(8) > self.w_minus_1_o.val() {
            self.cx1_1.next = self.w_minus_1.val();
        }
        self.cx0_2.next = self.lo2x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo2x.val().get_bit(20) {
            self.cx0_2.next = self.k0_13u.val();
        }
        self.cx1_2.next = self.hi2x.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi2x.val().get_bits::<13>(8) > self.w_minus_1_o.val() {
            self.cx1_2.next = self.w_minus_1.val();
        }
        self.cy0_0.next = self.lo0y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo0y.val().get_bit(20) {
            self.cy0_0.next = self.k0_13u.val();
        }
        self.cy1_0.next = self.hi0y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi0y.val().get_bits::<13>(8) > self.h_minus_1_o.val() {
            self.cy1_0.next = self.h_minus_1.val();
        }
        self.cy0_1.next = self.lo1y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo1y.val().get_bit(20) {
            self.cy0_1.next = self.k0_13u.val();
        }
        self.cy1_1.next = self.hi1y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi1y.val().get_bits::<13>(8) > self.h_minus_1_o.val() {
            self.cy1_1.next = self.h_minus_1.val();
        }
        self.cy0_2.next = self.lo2y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if !self.lo2y.val().get_bit(20) {
            self.cy0_2.next = self.k0_13u.val();
        }
        self.cy1_2.next = self.hi2y.val().get_bits::<13>(8) ^ self.k_sign13.val();
        if self.hi2y.val().get_bits::<13>(8) > self.h_minus_1_o.val() {
            self.cy1_2.next = self.h_minus_1.val();
        }
        self.box_x0_u.next = self.k0_13u.val();
        self.box_x1_u.next = self.k0_13u.val();
        self.box_y0_u.next = self.k0_13u.val();
        self.box_y1_u.next = self.k0_13u.val();
        if self.s0_v.q.val() {
            self.box_x0_u.next = self.cx0_0.val();
            if self.o1x.val() < self.o0x.val() {
                self.box_x0_u.next = self.cx0_1.val();
            }
            if (self.o2x.val() < self.o1x.val()) & (self.o2x.val() < self.o0x.val()) {
                self.box_x0_u.next = self.cx0_2.val();
            }
            self.box_x1_u.next = self.cx1_0.val();
            if self.o1x.val() > self.o0x.val() {
                self.box_x1_u.next = self.cx1_1.val();
            }
            if (self.o2x.val() > self.o1x.val()) & (self.o2x.val() > self.o0x.val()) {
                self.box_x1_u.next = self.cx1_2.val();
            }
            self.box_y0_u.next = self.cy0_0.val();
            if self.o1y.val() < self.o0y.val() {
                self.box_y0_u.next = self.cy0_1.val();
            }
            if (self.o2y.val() < self.o1y.val()) & (self.o2y.val() < self.o0y.val()) {
                self.box_y0_u.next = self.cy0_2.val();
            }
            self.box_y1_u.next = self.cy1_0.val();
            if self.o1y.val() > self.o0y.val() {
                self.box_y1_u.next = self.cy1_1.val();
            }
            if (self.o2y.val() > self.o1y.val()) & (self.o2y.val() > self.o0y.val()) {
                self.box_y1_u.next = self.cy1_2.val();
            }
        }
        self.box_empty.next = false;
        if self.s0_v.q.val() {
            self.box_empty.next = ((self.lo0x.val().get_bits::<13>(8) > self.hi0x.val().get_bits::<13>(8)) & (self.lo0x.val().get_bits::<13>(8) > self.hi1x.val().get_bits::<13>(8)) & (self.lo0x.val().get_bits::<13>(8) > self.hi2x.val().get_bits::<13>(8)) & (self.lo1x.val().get_bits::<13>(8) > self.hi0x.val().get_bits::<13>(8)) & (self.lo1x.val().get_bits::<13>(8) > self.hi1x.val().get_bits::<13>(8)) & (self.lo1x.val().get_bits::<13>(8) > self.hi2x.val().get_bits::<13>(8)) & (self.lo2x.val().get_bits::<13>(8) > self.hi0x.val().get_bits::<13>(8)) & (self.lo2x.val().get_bits::<13>(8) > self.hi1x.val().get_bits::<13>(8)) & (self.lo2x.val().get_bits::<13>(8) > self.hi2x.val().get_bits::<13>(8)))
                | (!self.hi0x.val().get_bit(20) & !self.hi1x.val().get_bit(20) & !self.hi2x.val().get_bit(20))
                | ((self.lo0x.val().get_bits::<13>(8) > self.w_minus_1_o.val()) & (self.lo1x.val().get_bits::<13>(8) > self.w_minus_1_o.val()) & (self.lo2x.val().get_bits::<13>(8) > self.w_minus_1_o.val()))
                | ((self.lo0y.val().get_bits::<13>(8) > self.hi0y.val().get_bits::<13>(8)) & (self.lo0y.val().get_bits::<13>(8) > self.hi1y.val().get_bits::<13>(8)) & (self.lo0y.val().get_bits::<13>(8) > self.hi2y.val().get_bits::<13>(8)) & (self.lo1y.val().get_bits::<13>(8) > self.hi0y.val().get_bits::<13>(8)) & (self.lo1y.val().get_bits::<13>(8) > self.hi1y.val().get_bits::<13>(8)) & (self.lo1y.val().get_bits::<13>(8) > self.hi2y.val().get_bits::<13>(8)) & (self.lo2y.val().get_bits::<13>(8) > self.hi0y.val().get_bits::<13>(8)) & (self.lo2y.val().get_bits::<13>(8) > self.hi1y.val().get_bits::<13>(8)) & (self.lo2y.val().get_bits::<13>(8) > self.hi2y.val().get_bits::<13>(8)))
                | (!self.hi0y.val().get_bit(20) & !self.hi1y.val().get_bit(20) & !self.hi2y.val().get_bit(20))
                | ((self.lo0y.val().get_bits::<13>(8) > self.h_minus_1_o.val()) & (self.lo1y.val().get_bits::<13>(8) > self.h_minus_1_o.val()) & (self.lo2y.val().get_bits::<13>(8) > self.h_minus_1_o.val()));
        }

        // The reciprocal of abs(det), requested when S1 holds a drawn triangle that S2 can take.
        self.det_abs.next = self.zb44.val();
        if self.s1_v.q.val() {
            self.det_abs.next = self.s1_det_abs.q.val();

        }
        self.recip.request.data.next = self.det_abs.val();
        self.recip.request.valid.next = self.s1_v.q.val() & self.walk1.val() & self.free2.val();
        self.recip.result.ready.next = self.take.val();
        // ---- S2 `Edges`: two dot units ----
        // Each multiplier input is driven exactly once per evaluation (Icarus settles only then).
        self.mul_a0.a.next = self.la0.q.val();
        self.mul_a0.b.next = self.lb0.q.val();
        self.mul_a1.a.next = self.ra0.q.val();
        self.mul_a1.b.next = self.rb0.q.val();
        self.mul_b0.a.next = self.la1.q.val();
        self.mul_b0.b.next = self.lb1.q.val();
        self.mul_b1.a.next = self.ra1.q.val();
        self.mul_b1.b.next = self.rb1.q.val();
        self.pr_a0.d.next = self.mul_a0.p.val();
        self.pr_a1.d.next = self.mul_a1.p.val();
        self.pr_b0.d.next = self.mul_b0.p.val();
        self.pr_b1.d.next = self.mul_b1.p.val();
        self.mul_a0.clock.next = self.clock.val();
        self.mul_a1.clock.next = self.clock.val();
        self.mul_b0.clock.next = self.clock.val();
        self.mul_b1.clock.next = self.clock.val();
        self.mul_a0.ce.next = true;
        self.mul_a1.ce.next = true;
        self.mul_b0.ce.next = true;
        self.mul_b1.ce.next = true;
        self.prtl_a.d.next = self.tl0.q.val();
        self.prtl_b.d.next = self.tl1.q.val();
        self.prtl2_a.d.next = self.prtl_a.q.val();
        self.prtl2_b.d.next = self.prtl_b.q.val();
        self.dot_a.next = self.zs47.val();
        self.dot_b.next = self.zs47.val();
        self.e_a.next = self.zs44.val();
        self.e_b.next = self.zs44.val();
        if self.s2_v.q.val() | self.s3_first.q.val() {
            self.dot_a.next = signed_bit_cast_safe::<47, 46>(self.pr_a0.q.val()) - signed_bit_cast_safe::<47, 46>(self.pr_a1.q.val());
            self.dot_b.next = signed_bit_cast_safe::<47, 46>(self.pr_b0.q.val()) - signed_bit_cast_safe::<47, 46>(self.pr_b1.q.val());
            self.e_a.next = signed_bit_cast_safe::<44, 47>(self.dot_a.val()) - self.k1_44.val();
            if self.prtl2_a.q.val() {
                self.e_a.next = signed_bit_cast_safe::<44, 47>(self.dot_a.val());
            }
            self.e_b.next = signed_bit_cast_safe::<44, 47>(self.dot_b.val()) - self.k1_44.val();
            if self.prtl2_b.q.val() {
                self.e_b.next = signed_bit_cast_safe::<44, 47>(self.dot_b.val());
            }

        }
        // ---- S6 `Grad`: one 47x26 multiplier ----
        self.mul_g.a.next = self.ga_op.q.val();
        self.mul_g.b.next = signed_cast(bit_cast::<26, 25>(self.gb_op.q.val()));
        // The gradient sat40(round(prod / 2^sh)) with sh = shift (A = na * 2^8 * 2^16 / det, and the
        // mantissa's 2^24 is those 2^8 subpixels and 16 fraction bits), in two cycles (issue 15 item 5):
        // g_sh = 2*prod >> sh (= prod / 2^(sh-1), exact when sh is 0) from the product
        // register, then ((g_sh + 1) >> 1) and the saturation from g_sh. The same integer as
        // round_shift(prod, sh): floor((floor(2 prod / 2^sh) + 1) / 2) = floor((prod + 2^(sh-1)) / 2^sh),
        // and for sh = 0 it is (2 prod + 1) >> 1 = prod. (73-bit arithmetic is slow in the Rust
        // simulation: evaluated only in the phases that use it.)
        self.g_dbl.next = self.k0_73.val();
        self.shifted.next = self.k0_73.val();
        self.rounded.next = self.k0_73.val();
        self.halved.next = self.k0_73.val();
        self.grad_hi.next = self.k0_34.val();
        self.grad.next = self.min40.val();
        if self.s6_v.q.val() & ((self.s6_phase.q.val() == self.k1_2.val()) | (self.s6_phase.q.val() == self.k2_2.val())) {
            self.g_dbl.next = self.g_prod.q.val() << self.k1_6.val();
            self.shifted.next = self.g_dbl.val() >> self.s6p.q.val().shift;
            if self.g_prod.q.val().get_bit(72) {
                // arithmetic shift of a negative value: complement, shift, complement
                self.shifted.next = !((!self.g_dbl.val()) >> self.s6p.q.val().shift);
            }
        }
        if self.s6_v.q.val() & ((self.s6_phase.q.val() == self.k2_2.val()) | (self.s6_phase.q.val() == self.k3_2.val())) {
            self.rounded.next = self.g_sh.q.val() + self.k1_73.val();
            self.halved.next = self.rounded.val() >> self.k1_6.val();
            if self.rounded.val().get_bit(72) {
                self.halved.next = !((!self.rounded.val()) >> self.k1_6.val());
            }
            self.grad_hi.next = self.halved.val().get_bits::<34>(39);
            if (self.grad_hi.val() == self.k0_34.val()) | (self.grad_hi.val() == self.k1s_34.val()) {
                self.grad.next = signed_cast(self.halved.val().get_bits::<40>(0));
            } else if !self.rounded.val().get_bit(72) {
                self.grad.next = self.max40.val();
            }
        }

        // ---- S7 `Plane`: two 40x21 multipliers ----
        // `128 - x0`, `128 - y0` of the record in S6, for the operand registers as it enters S7.
        self.off_x.next = self.zs21.val();
        self.off_y.next = self.zs21.val();
        if self.s6_v.q.val() {
            self.off_x.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(signed_cast(self.s6p.q.val().x0));
            self.off_y.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(signed_cast(self.s6p.q.val().y0));
        }
        self.pw.next = self.zs62.val();
        self.qw.next = self.zs62.val();
        self.p56.next = self.zs56.val();
        self.q56.next = self.zs56.val();
        self.acc_sum.next = self.zs62.val();
        self.acc_round.next = self.zb62.val();
        self.c_frac.next = self.zs56.val();
        self.c_now.next = self.zs56.val();
        self.s_now.next = self.zs56.val();
        self.z0_plane.next = self.zs56.val();
        self.raw_now.next = self.zs56.val();
        if self.s7_v.q.val() {
            self.pw.next = signed_bit_cast_safe::<62, 61>(signed_cast(self.p_prod.q.val()));
            self.qw.next = signed_bit_cast_safe::<62, 61>(signed_cast(self.q_prod.q.val()));
            self.p56.next = signed_cast(self.p_prod.q.val().get_bits::<56>(0));
            self.q56.next = signed_cast(self.q_prod.q.val().get_bits::<56>(0));
            // Phase 2: acc + 128 from the products of C's terms.
            self.acc_sum.next = self.pw.val() + self.qw.val();
            self.acc_round.next = unsigned_cast(self.acc_sum.val()) + self.k128_62.val();
            // Phase 3: C = (z0 << 16) + round(acc >> 8) (never saturates, see the module doc), and
            // raw = C + (A*X0 + B*Y0), from registers.
            self.c_frac.next = signed_bit_cast_safe::<56, 54>(signed_cast(self.p_acc.q.val().get_bits::<54>(8)));
            self.z0_plane.next = signed_cast(bit_cast::<56, 24>(self.s7p.q.val().z0) << self.k16_6.val());
            self.c_now.next = self.z0_plane.val() + self.c_frac.val();
            self.s_now.next = self.p56.val() + self.q56.val();
            self.raw_now.next = self.c_now.val() + self.s_now.val();

        }
        // Straight from registers (what the products of an empty S7 are does not matter: they are
        // kept only while a record walks). |A| <= 2^39, |128-x0| <= 2^19 + 128, X0 < 2^10: every
        // product fits 61 bits (59 used).
        self.mul_p.a.next = signed_cast(self.s7.q.val().a);
        self.mul_p.b.next = self.pb_op.q.val();
        self.mul_q.a.next = signed_cast(self.s7.q.val().b);
        self.mul_q.b.next = self.qb_op.q.val();
        self.mul_p.clock.next = self.clock.val();
        self.mul_q.clock.next = self.clock.val();
        self.mul_p.ce.next = true;
        self.mul_q.ce.next = true;
        // ---- The record queue ----
        self.pop.next = self.rec_ready.val() & (self.q_len.q.val() != self.k0_3.val());
        self.q_after.next = self.q_len.q.val();
        if self.pop.val() {
            self.q_after.next = self.q_len.q.val() - self.k1_3.val();
            self.q_rp.d.next = self.q_rp.q.val() + self.k1_2.val();
        }
        self.pushed.next = self.s7.q.val();
        self.pushed.next.raw = unsigned_cast(self.raw_now.val());
        self.pushed.next.c = unsigned_cast(self.c_now.val());
        // The multiples the traversal takes with the record (adders off the record take).
        self.m30_0.next = signed_cast(self.s7.q.val().sx0);
        self.m32_0.next = signed_bit_cast_safe::<32, 30>(self.m30_0.val());
        self.m32d_0.next = signed_cast(unsigned_cast(self.m32_0.val()) << self.k1_6.val());
        self.pushed.next.sx3_0 = unsigned_cast(self.m32d_0.val() + self.m32_0.val());
        self.m34_0.next = signed_bit_cast_safe::<34, 30>(self.m30_0.val());
        self.m34s_0.next = signed_cast(unsigned_cast(self.m34_0.val()) << self.k4_6.val());
        self.pushed.next.sx15_0 = unsigned_cast(self.m34s_0.val() - self.m34_0.val());
        self.m30_1.next = signed_cast(self.s7.q.val().sx1);
        self.m32_1.next = signed_bit_cast_safe::<32, 30>(self.m30_1.val());
        self.m32d_1.next = signed_cast(unsigned_cast(self.m32_1.val()) << self.k1_6.val());
        self.pushed.next.sx3_1 = unsigned_cast(self.m32d_1.val() + self.m32_1.val());
        self.m34_1.next = signed_bit_cast_safe::<34, 30>(self.m30_1.val());
        self.m34s_1.next = signed_cast(unsigned_cast(self.m34_1.val()) << self.k4_6.val());
        self.pushed.next.sx15_1 = unsigned_cast(self.m34s_1.val() - self.m34_1.val());
        self.m30_2.next = signed_cast(self.s7.q.val().sx2);
        self.m32_2.next = signed_bit_cast_safe::<32, 30>(self.m30_2.val());
        self.m32d_2.next = signed_cast(unsigned_cast(self.m32_2.val()) << self.k1_6.val());
        self.pushed.next.sx3_2 = unsigned_cast(self.m32d_2.val() + self.m32_2.val());
        self.m34_2.next = signed_bit_cast_safe::<34, 30>(self.m30_2.val());
        self.m34s_2.next = signed_cast(unsigned_cast(self.m34_2.val()) << self.k4_6.val());
        self.pushed.next.sx15_2 = unsigned_cast(self.m34s_2.val() - self.m34_2.val());
        self.m40.next = signed_cast(self.s7.q.val().a);
        self.m42.next = signed_bit_cast_safe::<42, 40>(self.m40.val());
        self.m42d.next = signed_cast(unsigned_cast(self.m42.val()) << self.k1_6.val());
        self.pushed.next.a3 = unsigned_cast(self.m42d.val() + self.m42.val());
        self.q_len.d.next = self.q_after.val();
        if self.leave7.val() {
            self.q_len.d.next = self.q_after.val() + self.k1_3.val();
            self.q_wp.d.next = self.q_wp.q.val() + self.k1_2.val();
            if self.q_wp.q.val() == self.k0_2.val() {
                self.q0.d.next = self.pushed.val();
            }
            if self.q_wp.q.val() == self.k1_2.val() {
                self.q1.d.next = self.pushed.val();
            }
            if self.q_wp.q.val() == self.k2_2.val() {
                self.q2.d.next = self.pushed.val();
            }
            if self.q_wp.q.val() == self.k3_2.val() {
                self.q3.d.next = self.pushed.val();
            }
        }
        self.head.next = self.q0.q.val();
        if self.q_rp.q.val() == self.k1_2.val() {
            self.head.next = self.q1.q.val();
        }
        if self.q_rp.q.val() == self.k2_2.val() {
            self.head.next = self.q2.q.val();
        }
        if self.q_rp.q.val() == self.k3_2.val() {
            self.head.next = self.q3.q.val();
        }
        self.rec_valid.next = self.q_len.q.val() != self.k0_3.val();
        self.rec_kind.next = self.head.val().kind;
        self.rec_clear.next = self.head.val().clear;
        self.rec_index.next = self.head.val().index;
        self.rec_culled.next = self.head.val().culled;
        self.rec_zero_area.next = self.head.val().zero_area;
        self.rec_bx0.next = self.head.val().bx0;
        self.rec_bx1.next = self.head.val().bx1;
        self.rec_by0.next = self.head.val().by0;
        self.rec_by1.next = self.head.val().by1;
        self.rec_addr.next = self.head.val().addr;
        self.rec_e0.next = signed_cast(self.head.val().e0);
        self.rec_e1.next = signed_cast(self.head.val().e1);
        self.rec_e2.next = signed_cast(self.head.val().e2);
        self.rec_sx0.next = signed_cast(self.head.val().sx0);
        self.rec_sx1.next = signed_cast(self.head.val().sx1);
        self.rec_sx2.next = signed_cast(self.head.val().sx2);
        self.rec_sy0.next = signed_cast(self.head.val().sy0);
        self.rec_sy1.next = signed_cast(self.head.val().sy1);
        self.rec_sy2.next = signed_cast(self.head.val().sy2);
        self.rec_raw.next = signed_cast(self.head.val().raw);
        self.rec_a.next = signed_cast(self.head.val().a);
        self.rec_b.next = signed_cast(self.head.val().b);
        self.rec_c.next = signed_cast(self.head.val().c);
        self.rec_sx3_0.next = signed_cast(self.head.val().sx3_0);
        self.rec_sx15_0.next = signed_cast(self.head.val().sx15_0);
        self.rec_sx3_1.next = signed_cast(self.head.val().sx3_1);
        self.rec_sx15_1.next = signed_cast(self.head.val().sx15_1);
        self.rec_sx3_2.next = signed_cast(self.head.val().sx3_2);
        self.rec_sx15_2.next = signed_cast(self.head.val().sx15_2);
        self.rec_a3.next = signed_cast(self.head.val().a3);

        // ---- The stages' registers at the edge, last first ----
        // S7: phase 0 presents the products of C's terms, 1 those of raw's; 2 sums C's (acc + 128).
        if self.s7_v.q.val() & self.walk7.val() & !self.done7.val() {
            self.s7_phase.d.next = self.s7_phase.q.val() + self.k1_2.val();
            self.p_prod.d.next = unsigned_cast(self.mul_p.p.val());
            self.q_prod.d.next = unsigned_cast(self.mul_q.p.val());
            if self.s7_phase.q.val() == self.k0_2.val() {
                self.pb_op.d.next = signed_cast(bit_cast::<21, 10>(self.s7.q.val().bx0));
                self.qb_op.d.next = signed_cast(bit_cast::<21, 10>(self.s7.q.val().by0));
            }
            if self.s7_phase.q.val() == self.k2_2.val() {
                self.p_acc.d.next = self.acc_round.val();
            }
        }
        if self.leave7.val() {
            self.s7_v.d.next = false;
        }
        if self.leave6.val() {
            self.s7_v.d.next = true;
            self.s7_phase.d.next = self.k0_2.val();
            self.s7.d.next = self.s6.q.val();
            self.s7p.d.next = self.s6p.q.val();
            self.s7.d.next.b = unsigned_cast(self.grad.val());
            self.pb_op.d.next = self.off_x.val();
            self.qb_op.d.next = self.off_y.val();
        }
        // The copy of the reciprocal's result (held when S6 takes it, below): in phase 0 it equals
        // `recip.result`, whose station it mirrors; in phase 1 it is the mantissa taken.
        self.gb_op.d.next = self.recip.next_mant.val();
        // S6: phase 0 takes the reciprocal and forms na*mant; phase 1 shifts it and forms nb*mant;
        // phase 2 rounds A and shifts nb*mant; B is rounded on leaving (phase 3).
        if self.s6_v.q.val() & self.walk6.val() & !self.done6.val() {
            if self.s6_phase.q.val() == self.k0_2.val() {
                if self.take.val() {
                    self.s6_phase.d.next = self.k1_2.val();
                    self.g_prod.d.next = unsigned_cast(self.mul_g.p.val());
                    self.ga_op.d.next = signed_cast(self.s6p.q.val().nb);
                    self.gb_op.d.next = self.gb_op.q.val();
                    self.s6p.d.next.shift = self.recip.result.data.val().shift;
                }
            } else if self.s6_phase.q.val() == self.k1_2.val() {
                self.s6_phase.d.next = self.k2_2.val();
                self.g_prod.d.next = unsigned_cast(self.mul_g.p.val());
                self.g_sh.d.next = self.shifted.val();
            } else {
                self.s6_phase.d.next = self.k3_2.val();
                self.g_sh.d.next = self.shifted.val();
                self.s6.d.next.a = unsigned_cast(self.grad.val());
            }
        }
        if self.leave6.val() {
            self.s6_v.d.next = false;
        }
        if self.leave5.val() {
            self.s6_v.d.next = true;
            self.s6_phase.d.next = self.k0_2.val();
            self.s6.d.next = self.s5.q.val();
            self.s6p.d.next = self.s5p.q.val();
            self.ga_op.d.next = signed_cast(self.s5p.q.val().na);
        }
        // S5, S4, S3: hold.
        if self.leave5.val() {
            self.s5_v.d.next = false;
        }
        if self.leave4.val() {
            self.s5_v.d.next = true;
            self.s5.d.next = self.s4.q.val();
            self.s5p.d.next = self.s4p.q.val();
        }
        if self.leave4.val() {
            self.s4_v.d.next = false;
        }
        // S3's first cycle: nb's product pair is in `pr_b*` (its operands were chosen in S2's phase 2
        // and are held until S2 takes its next record, whose first products land a cycle after this
        // one), so nb is formed here and goes on with the record or stays in S3.
        self.s3_first.d.next = self.leave2.val();
        if self.s3_first.q.val() {
            self.s3p.d.next.nb = unsigned_cast(self.dot_b.val());
        }
        if self.leave3.val() {
            self.s4_v.d.next = true;
            self.s4.d.next = self.s3.q.val();
            self.s4p.d.next = self.s3p.q.val();
            if self.s3_first.q.val() {
                self.s4p.d.next.nb = unsigned_cast(self.dot_b.val());
            }
        }
        if self.leave3.val() {
            self.s3_v.d.next = false;
        }
        if self.leave2.val() {
            self.s3_v.d.next = true;
            self.s3.d.next = self.s2.q.val();
            self.s3p.d.next = self.s2p.q.val();
            // A record that leaves in its first cycle of phase 3 takes E2 and na from this cycle's
            // products (later cycles find them in `s2`, `s2p`).
            if self.s2_fresh3.q.val() {
                self.s3.d.next.e2 = unsigned_cast(self.e_a.val());
                self.s3p.d.next.na = unsigned_cast(self.dot_b.val());
            }
        }
        // S2: a product chosen in phase k lands in `pr_*` in phase k+2 (`MulPipeS`: the partial products
        // are registered at the end of phase k, their sum at the end of phase k+1): phase 2 E0, E1;
        // phase 3 (its first cycle) E2 and na; nb in S3's first cycle (above).
        self.s2_fresh3.d.next = false;
        if self.s2_fresh3.q.val() {
            self.s2.d.next.e2 = unsigned_cast(self.e_a.val());
            self.s2p.d.next.na = unsigned_cast(self.dot_b.val());
        }
        if self.s2_v.q.val() & self.walk2.val() & !self.done2.val() {
            self.s2_phase.d.next = self.s2_phase.q.val() + self.k1_2.val();
            if self.s2_phase.q.val() == self.k0_2.val() {
                // unit a: E2; unit b: na = dz10*dy20 - dz20*dy10
                self.la0.d.next = self.la2.q.val();
                self.lb0.d.next = self.lb2.q.val();
                self.ra0.d.next = self.ra2.q.val();
                self.rb0.d.next = self.rb2.q.val();
                self.tl0.d.next = self.tl2.q.val();
                self.la1.d.next = self.n_dz10.q.val();
                self.lb1.d.next = self.n_dy20.q.val();
                self.ra1.d.next = self.n_dz20.q.val();
                self.rb1.d.next = self.n_dy10.q.val();
            }
            if self.s2_phase.q.val() == self.k1_2.val() {
                // unit b: nb = dz20*dx10 - dz10*dx20 (phases 2 and 3: the product register keeps nb
                // while S2 waits)
                self.la1.d.next = self.n_dz20.q.val();
                self.lb1.d.next = self.n_dx10.q.val();
                self.ra1.d.next = self.n_dz10.q.val();
                self.rb1.d.next = self.n_dx20.q.val();
            }
            if self.s2_phase.q.val() == self.k2_2.val() {
                self.s2.d.next.e0 = unsigned_cast(self.e_a.val());
                self.s2.d.next.e1 = unsigned_cast(self.e_b.val());
                self.s2_fresh3.d.next = true;
            }
        }
        if self.leave2.val() {
            self.s2_v.d.next = false;
        }
        if self.leave1.val() {
            self.s2_v.d.next = true;
            self.s2_phase.d.next = self.k0_2.val();
            self.s2.d.next.kind = self.rkind.val();
            self.s2.d.next.clear = self.s1.q.val().clear & (self.s1.q.val().kind == self.kind_frame.val());
            self.s2.d.next.index = self.s1.q.val().index;
            self.s2.d.next.culled = self.is_tri.val() & self.culled_now.val();
            self.s2.d.next.zero_area = self.is_tri.val() & self.det_zero.val();
            self.s2.d.next.bx0 = self.s1_bx0.q.val();
            self.s2.d.next.bx1 = self.s1_bx1.q.val();
            self.s2.d.next.by0 = self.s1_by0.q.val();
            self.s2.d.next.by1 = self.s1_by1.q.val();
            self.s2.d.next.addr = self.addr_prod.val().get_bits::<20>(0) + bit_cast::<20, 10>(self.s1_bx0.q.val());
            self.s2.d.next.sx0 = unsigned_cast(self.stx_0.val());
            self.s2.d.next.sx1 = unsigned_cast(self.stx_1.val());
            self.s2.d.next.sx2 = unsigned_cast(self.stx_2.val());
            self.s2.d.next.sy0 = unsigned_cast(self.sty_0.val());
            self.s2.d.next.sy1 = unsigned_cast(self.sty_1.val());
            self.s2.d.next.sy2 = unsigned_cast(self.sty_2.val());
            self.s2p.d.next.x0 = unsigned_cast(self.cx0.val());
            self.s2p.d.next.y0 = unsigned_cast(self.cy0.val());
            self.s2p.d.next.z0 = self.cz0.val();
            self.la0.d.next = signed_bit_cast_safe::<25, 21>(self.edx_0.val());
            self.lb0.d.next = self.py_0.val();
            self.ra0.d.next = signed_bit_cast_safe::<25, 21>(self.edy_0.val());
            self.rb0.d.next = self.px_0.val();
            self.tl0.d.next = self.tl_0.val();
            self.la1.d.next = signed_bit_cast_safe::<25, 21>(self.edx_1.val());
            self.lb1.d.next = self.py_1.val();
            self.ra1.d.next = signed_bit_cast_safe::<25, 21>(self.edy_1.val());
            self.rb1.d.next = self.px_1.val();
            self.tl1.d.next = self.tl_1.val();
            self.la2.d.next = signed_bit_cast_safe::<25, 21>(self.edx_2.val());
            self.lb2.d.next = self.py_2.val();
            self.ra2.d.next = signed_bit_cast_safe::<25, 21>(self.edy_2.val());
            self.rb2.d.next = self.px_2.val();
            self.tl2.d.next = self.tl_2.val();
            self.n_dz10.d.next = self.cdz10.val();
            self.n_dz20.d.next = self.cdz20.val();
            self.n_dx10.d.next = self.cdx10.val();
            self.n_dx20.d.next = self.cdx20.val();
            self.n_dy10.d.next = self.cdy10.val();
            self.n_dy20.d.next = self.cdy20.val();
        }
        // S1 and S0.
        if self.leave1.val() {
            self.s1_v.d.next = false;
        }
        if self.leave0.val() {
            self.s1_v.d.next = true;
            self.s1.d.next = self.s0.q.val();
            self.s1_det.d.next = self.det.val();
            self.s1_bx0.d.next = self.box_x0_u.val().get_bits::<10>(0);
            self.s1_bx1.d.next = self.box_x1_u.val().get_bits::<10>(0);
            self.s1_by0.d.next = self.box_y0_u.val().get_bits::<10>(0);
            self.s1_by1.d.next = self.box_y1_u.val().get_bits::<10>(0);
            self.s1_box_empty.d.next = self.box_empty.val();
            self.s1_det_zero.d.next = self.det_eq.val();
            self.s1_det_abs.d.next = self.abs_now.val();
        }
        if self.leave0.val() {
            self.s0_v.d.next = false;
        }
        if self.cmd.valid.val() & self.cmd.ready.val() {
            self.s0_v.d.next = true;
            self.s0.d.next = self.cmd.data.val();
        }
    }
}
