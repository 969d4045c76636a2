//! `tex_lod`: the Color Shader's per-pixel level of detail (issue 17, item 3), the second half of the
//! texture coordinate unit after [`crate::cs::tex_coord`]: from s, t, Q's reciprocal (m, e) and the
//! planes' gradients, the larger of the four derivatives ds/dx, ds/dy, dt/dx, dt/dy in level 0's
//! texels, as a level of detail in Q4.4. `golden::texcoord::TexPlanes::lod` is the reference, bit for
//! bit: each derivative's numerator A_sw 2^20 - s A_q is formed from 18-bit mantissas
//! (`golden::texcoord::Float`), the largest is taken, and only it is multiplied by 1/Q. One pixel per
//! clock, no stall.
//!
//! ```text
//!  valid_in, s, t, m, e, w_log2, h_log2, sw/tw/q a and b
//!    | 1: magnitudes and signs of sw.a, sw.b, tw.a, tw.b, q.a, q.b, s, t
//!    | 2: their 18-bit mantissas and exponents (Normalize18); the A_sw terms times 2^20
//!    | 3: s q.a, s q.b, t q.a, t q.b: four 18 x 18 products
//!    | 4: the products' mantissas
//!    | 5: each pair aligned 22 bits above its larger term, as two's complement (41 b)
//!    | 6: the difference's magnitude (42 b)
//!    | 7: its mantissa; the exponent scaled by 2^w_log2 (s) or 2^h_log2 (t)
//!    | 8: leading one and the bits below it (LeftAlign)
//!    | 9: the largest of the four
//!    | 10: times m's top 18 bits
//!    | 11: the product's mantissa, rho's exponent E2 = exp - e - 24
//!    | 12: rho rounded to 16 fraction bits, log2 in Q4.4 (golden::texture::lod_q4)
//!    v
//!  valid_out, lod
//! ```
//!
//! A pixel accepted in cycle c leaves in cycle c + [`TEX_LOD_LATENCY`]. Exponents are 9-bit two's
//! complement; they are compared with their sign bit flipped.
//!
//! Naming: a register is `<what><stage>_<lane>` (`mant2_6`: stage 2's mantissa of operand 6, s),
//! a combinational local of stage n ends in n or carries the lane. Operands 0..7 are sw.a, sw.b, tw.a,
//! tw.b, q.a, q.b, s, t; lanes 0..3 of stages 3-9 are the numerators of ds/dx, ds/dy, dt/dx, dt/dy.
//! The lanes are written out rather than looped over because rust-hdl's `hdl_gen` cannot take a loop
//! index inside a cast (`bit_cast`), and most statements here have one.

use crate::common::{LeftAlign, MulU, Normalize18};
use rust_hdl::prelude::*;

/// Cycles from a pixel's cycle on the inputs to its cycle on the outputs.
pub const TEX_LOD_LATENCY: u64 = 12;

#[derive(LogicBlock)]
pub struct TexLod {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    /// s and t from `tex_coord` (Q15.16, two's complement).
    pub s: Signal<In, Bits<32>>,
    pub t: Signal<In, Bits<32>>,
    /// 1/Q ~ m 2^-(e + 24), from `tex_coord`.
    pub m: Signal<In, Bits<25>>,
    pub e: Signal<In, Bits<6>>,
    /// Level 0's size: 2^w_log2 x 2^h_log2.
    pub w_log2: Signal<In, Bits<4>>,
    pub h_log2: Signal<In, Bits<4>>,
    /// The planes' gradients (TdbS's texture part).
    pub sw_a: Signal<In, Signed<40>>,
    pub sw_b: Signal<In, Signed<40>>,
    pub tw_a: Signal<In, Signed<40>>,
    pub tw_b: Signal<In, Signed<40>>,
    pub q_a: Signal<In, Signed<40>>,
    pub q_b: Signal<In, Signed<40>>,
    pub valid_out: Signal<Out, Bit>,
    /// The level of detail, Q4.4 (0 while valid_out is low).
    pub lod: Signal<Out, Bits<8>>,
    k1_40: Constant<Bits<40>>,
    k1_32: Constant<Bits<32>>,
    k20_9: Constant<Bits<9>>,
    k18_9: Constant<Bits<9>>,
    k40_9: Constant<Bits<9>>,
    k7_9: Constant<Bits<9>>,
    k24_9: Constant<Bits<9>>,
    k2_9: Constant<Bits<9>>,
    kflip_9: Constant<Bits<9>>,
    k22_5: Constant<Bits<5>>,
    k2_5: Constant<Bits<5>>,
    k63_6: Constant<Bits<6>>,
    k1_41: Constant<Bits<41>>,
    k1_42: Constant<Bits<42>>,
    ksign_42: Constant<Bits<42>>,
    km1_9: Constant<Bits<9>>,
    kfm1_9: Constant<Bits<9>>,
    kf16_9: Constant<Bits<9>>,
    k16_9: Constant<Bits<9>>,
    k10_9: Constant<Bits<9>>,
    k4_21: Constant<Bits<21>>,
    k160_8: Constant<Bits<8>>,
    k4_8: Constant<Bits<8>>,
    ub0: Signal<Local, Bits<40>>,
    mag1_0: DFF<Bits<40>>,
    sg1_0: DFF<Bit>,
    ub1: Signal<Local, Bits<40>>,
    mag1_1: DFF<Bits<40>>,
    sg1_1: DFF<Bit>,
    ub2: Signal<Local, Bits<40>>,
    mag1_2: DFF<Bits<40>>,
    sg1_2: DFF<Bit>,
    ub3: Signal<Local, Bits<40>>,
    mag1_3: DFF<Bits<40>>,
    sg1_3: DFF<Bit>,
    ub4: Signal<Local, Bits<40>>,
    mag1_4: DFF<Bits<40>>,
    sg1_4: DFF<Bit>,
    ub5: Signal<Local, Bits<40>>,
    mag1_5: DFF<Bits<40>>,
    sg1_5: DFF<Bit>,
    mag1_6: DFF<Bits<32>>,
    sg1_6: DFF<Bit>,
    mag1_7: DFF<Bits<32>>,
    sg1_7: DFF<Bit>,
    m1: DFF<Bits<25>>,
    e1: DFF<Bits<6>>,
    wl1: DFF<Bits<4>>,
    hl1: DFF<Bits<4>>,
    v1: DFF<Bit>,
    n2_0: Normalize18<40>,
    mant2_0: DFF<Bits<18>>,
    exp2_0: DFF<Bits<9>>,
    sg2_0: DFF<Bit>,
    dr2_0: Signal<Local, Bits<9>>,
    n2_1: Normalize18<40>,
    mant2_1: DFF<Bits<18>>,
    exp2_1: DFF<Bits<9>>,
    sg2_1: DFF<Bit>,
    dr2_1: Signal<Local, Bits<9>>,
    n2_2: Normalize18<40>,
    mant2_2: DFF<Bits<18>>,
    exp2_2: DFF<Bits<9>>,
    sg2_2: DFF<Bit>,
    dr2_2: Signal<Local, Bits<9>>,
    n2_3: Normalize18<40>,
    mant2_3: DFF<Bits<18>>,
    exp2_3: DFF<Bits<9>>,
    sg2_3: DFF<Bit>,
    dr2_3: Signal<Local, Bits<9>>,
    n2_4: Normalize18<40>,
    mant2_4: DFF<Bits<18>>,
    exp2_4: DFF<Bits<9>>,
    sg2_4: DFF<Bit>,
    n2_5: Normalize18<40>,
    mant2_5: DFF<Bits<18>>,
    exp2_5: DFF<Bits<9>>,
    sg2_5: DFF<Bit>,
    n2_6: Normalize18<32>,
    mant2_6: DFF<Bits<18>>,
    exp2_6: DFF<Bits<9>>,
    sg2_6: DFF<Bit>,
    n2_7: Normalize18<32>,
    mant2_7: DFF<Bits<18>>,
    exp2_7: DFF<Bits<9>>,
    sg2_7: DFF<Bit>,
    m2: DFF<Bits<25>>,
    e2: DFF<Bits<6>>,
    wl2: DFF<Bits<4>>,
    hl2: DFF<Bits<4>>,
    v2: DFF<Bit>,
    mul0: MulU<18, 18, 36>,
    pm3_0: DFF<Bits<36>>,
    psg3_0: DFF<Bit>,
    pexp3_0: DFF<Bits<9>>,
    xm3_0: DFF<Bits<18>>,
    xsg3_0: DFF<Bit>,
    xexp3_0: DFF<Bits<9>>,
    mul1: MulU<18, 18, 36>,
    pm3_1: DFF<Bits<36>>,
    psg3_1: DFF<Bit>,
    pexp3_1: DFF<Bits<9>>,
    xm3_1: DFF<Bits<18>>,
    xsg3_1: DFF<Bit>,
    xexp3_1: DFF<Bits<9>>,
    mul2: MulU<18, 18, 36>,
    pm3_2: DFF<Bits<36>>,
    psg3_2: DFF<Bit>,
    pexp3_2: DFF<Bits<9>>,
    xm3_2: DFF<Bits<18>>,
    xsg3_2: DFF<Bit>,
    xexp3_2: DFF<Bits<9>>,
    mul3: MulU<18, 18, 36>,
    pm3_3: DFF<Bits<36>>,
    psg3_3: DFF<Bit>,
    pexp3_3: DFF<Bits<9>>,
    xm3_3: DFF<Bits<18>>,
    xsg3_3: DFF<Bit>,
    xexp3_3: DFF<Bits<9>>,
    m3: DFF<Bits<25>>,
    e3: DFF<Bits<6>>,
    wl3: DFF<Bits<4>>,
    hl3: DFF<Bits<4>>,
    v3: DFF<Bit>,
    n4_0: Normalize18<36>,
    dr4_0: Signal<Local, Bits<9>>,
    ym4_0: DFF<Bits<18>>,
    ysg4_0: DFF<Bit>,
    yexp4_0: DFF<Bits<9>>,
    xm4_0: DFF<Bits<18>>,
    xsg4_0: DFF<Bit>,
    xexp4_0: DFF<Bits<9>>,
    n4_1: Normalize18<36>,
    dr4_1: Signal<Local, Bits<9>>,
    ym4_1: DFF<Bits<18>>,
    ysg4_1: DFF<Bit>,
    yexp4_1: DFF<Bits<9>>,
    xm4_1: DFF<Bits<18>>,
    xsg4_1: DFF<Bit>,
    xexp4_1: DFF<Bits<9>>,
    n4_2: Normalize18<36>,
    dr4_2: Signal<Local, Bits<9>>,
    ym4_2: DFF<Bits<18>>,
    ysg4_2: DFF<Bit>,
    yexp4_2: DFF<Bits<9>>,
    xm4_2: DFF<Bits<18>>,
    xsg4_2: DFF<Bit>,
    xexp4_2: DFF<Bits<9>>,
    n4_3: Normalize18<36>,
    dr4_3: Signal<Local, Bits<9>>,
    ym4_3: DFF<Bits<18>>,
    ysg4_3: DFF<Bit>,
    yexp4_3: DFF<Bits<9>>,
    xm4_3: DFF<Bits<18>>,
    xsg4_3: DFF<Bit>,
    xexp4_3: DFF<Bits<9>>,
    m4: DFF<Bits<25>>,
    e4: DFF<Bits<6>>,
    wl4: DFF<Bits<4>>,
    hl4: DFF<Bits<4>>,
    v4: DFF<Bit>,
    topx0: Signal<Local, Bits<9>>,
    topy0: Signal<Local, Bits<9>>,
    big0: Signal<Local, Bits<9>>,
    kx0: Signal<Local, Bits<9>>,
    ky0: Signal<Local, Bits<9>>,
    shx0: Signal<Local, Bits<6>>,
    shy0: Signal<Local, Bits<6>>,
    vx0: Signal<Local, Bits<41>>,
    vy0: Signal<Local, Bits<41>>,
    ix0: Signal<Local, Bits<41>>,
    iy0: Signal<Local, Bits<41>>,
    nx0: Signal<Local, Bits<41>>,
    ny0: Signal<Local, Bits<41>>,
    px0: Signal<Local, Bits<41>>,
    py0: Signal<Local, Bits<41>>,
    ax5_0: DFF<Bits<41>>,
    ay5_0: DFF<Bits<41>>,
    base5_0: DFF<Bits<9>>,
    topx1: Signal<Local, Bits<9>>,
    topy1: Signal<Local, Bits<9>>,
    big1: Signal<Local, Bits<9>>,
    kx1: Signal<Local, Bits<9>>,
    ky1: Signal<Local, Bits<9>>,
    shx1: Signal<Local, Bits<6>>,
    shy1: Signal<Local, Bits<6>>,
    vx1: Signal<Local, Bits<41>>,
    vy1: Signal<Local, Bits<41>>,
    ix1: Signal<Local, Bits<41>>,
    iy1: Signal<Local, Bits<41>>,
    nx1: Signal<Local, Bits<41>>,
    ny1: Signal<Local, Bits<41>>,
    px1: Signal<Local, Bits<41>>,
    py1: Signal<Local, Bits<41>>,
    ax5_1: DFF<Bits<41>>,
    ay5_1: DFF<Bits<41>>,
    base5_1: DFF<Bits<9>>,
    topx2: Signal<Local, Bits<9>>,
    topy2: Signal<Local, Bits<9>>,
    big2: Signal<Local, Bits<9>>,
    kx2: Signal<Local, Bits<9>>,
    ky2: Signal<Local, Bits<9>>,
    shx2: Signal<Local, Bits<6>>,
    shy2: Signal<Local, Bits<6>>,
    vx2: Signal<Local, Bits<41>>,
    vy2: Signal<Local, Bits<41>>,
    ix2: Signal<Local, Bits<41>>,
    iy2: Signal<Local, Bits<41>>,
    nx2: Signal<Local, Bits<41>>,
    ny2: Signal<Local, Bits<41>>,
    px2: Signal<Local, Bits<41>>,
    py2: Signal<Local, Bits<41>>,
    ax5_2: DFF<Bits<41>>,
    ay5_2: DFF<Bits<41>>,
    base5_2: DFF<Bits<9>>,
    topx3: Signal<Local, Bits<9>>,
    topy3: Signal<Local, Bits<9>>,
    big3: Signal<Local, Bits<9>>,
    kx3: Signal<Local, Bits<9>>,
    ky3: Signal<Local, Bits<9>>,
    shx3: Signal<Local, Bits<6>>,
    shy3: Signal<Local, Bits<6>>,
    vx3: Signal<Local, Bits<41>>,
    vy3: Signal<Local, Bits<41>>,
    ix3: Signal<Local, Bits<41>>,
    iy3: Signal<Local, Bits<41>>,
    nx3: Signal<Local, Bits<41>>,
    ny3: Signal<Local, Bits<41>>,
    px3: Signal<Local, Bits<41>>,
    py3: Signal<Local, Bits<41>>,
    ax5_3: DFF<Bits<41>>,
    ay5_3: DFF<Bits<41>>,
    base5_3: DFF<Bits<9>>,
    m5: DFF<Bits<25>>,
    e5: DFF<Bits<6>>,
    wl5: DFF<Bits<4>>,
    hl5: DFF<Bits<4>>,
    v5: DFF<Bit>,
    ex0: Signal<Local, Bits<42>>,
    ey0: Signal<Local, Bits<42>>,
    dd0: Signal<Local, Bits<42>>,
    dm6_0: DFF<Bits<42>>,
    base6_0: DFF<Bits<9>>,
    ex1: Signal<Local, Bits<42>>,
    ey1: Signal<Local, Bits<42>>,
    dd1: Signal<Local, Bits<42>>,
    dm6_1: DFF<Bits<42>>,
    base6_1: DFF<Bits<9>>,
    ex2: Signal<Local, Bits<42>>,
    ey2: Signal<Local, Bits<42>>,
    dd2: Signal<Local, Bits<42>>,
    dm6_2: DFF<Bits<42>>,
    base6_2: DFF<Bits<9>>,
    ex3: Signal<Local, Bits<42>>,
    ey3: Signal<Local, Bits<42>>,
    dd3: Signal<Local, Bits<42>>,
    dm6_3: DFF<Bits<42>>,
    base6_3: DFF<Bits<9>>,
    m6: DFF<Bits<25>>,
    e6: DFF<Bits<6>>,
    wl6: DFF<Bits<4>>,
    hl6: DFF<Bits<4>>,
    v6: DFF<Bit>,
    n7_0: Normalize18<42>,
    dr7_0: Signal<Local, Bits<9>>,
    eb7_0: Signal<Local, Bits<9>>,
    lg7_0: Signal<Local, Bits<9>>,
    fm7_0: DFF<Bits<18>>,
    fexp7_0: DFF<Bits<9>>,
    n7_1: Normalize18<42>,
    dr7_1: Signal<Local, Bits<9>>,
    eb7_1: Signal<Local, Bits<9>>,
    lg7_1: Signal<Local, Bits<9>>,
    fm7_1: DFF<Bits<18>>,
    fexp7_1: DFF<Bits<9>>,
    n7_2: Normalize18<42>,
    dr7_2: Signal<Local, Bits<9>>,
    eb7_2: Signal<Local, Bits<9>>,
    lg7_2: Signal<Local, Bits<9>>,
    fm7_2: DFF<Bits<18>>,
    fexp7_2: DFF<Bits<9>>,
    n7_3: Normalize18<42>,
    dr7_3: Signal<Local, Bits<9>>,
    eb7_3: Signal<Local, Bits<9>>,
    lg7_3: Signal<Local, Bits<9>>,
    fm7_3: DFF<Bits<18>>,
    fexp7_3: DFF<Bits<9>>,
    m7: DFF<Bits<25>>,
    e7: DFF<Bits<6>>,
    v7: DFF<Bit>,
    la8_0: LeftAlign<18>,
    ms8_0: Signal<Local, Bits<9>>,
    lk8_0: DFF<Bits<9>>,
    nm8_0: DFF<Bits<18>>,
    nz8_0: DFF<Bit>,
    fm8_0: DFF<Bits<18>>,
    fexp8_0: DFF<Bits<9>>,
    lks8_0: Signal<Local, Bits<9>>,
    la8_1: LeftAlign<18>,
    ms8_1: Signal<Local, Bits<9>>,
    lk8_1: DFF<Bits<9>>,
    nm8_1: DFF<Bits<18>>,
    nz8_1: DFF<Bit>,
    fm8_1: DFF<Bits<18>>,
    fexp8_1: DFF<Bits<9>>,
    lks8_1: Signal<Local, Bits<9>>,
    la8_2: LeftAlign<18>,
    ms8_2: Signal<Local, Bits<9>>,
    lk8_2: DFF<Bits<9>>,
    nm8_2: DFF<Bits<18>>,
    nz8_2: DFF<Bit>,
    fm8_2: DFF<Bits<18>>,
    fexp8_2: DFF<Bits<9>>,
    lks8_2: Signal<Local, Bits<9>>,
    la8_3: LeftAlign<18>,
    ms8_3: Signal<Local, Bits<9>>,
    lk8_3: DFF<Bits<9>>,
    nm8_3: DFF<Bits<18>>,
    nz8_3: DFF<Bit>,
    fm8_3: DFF<Bits<18>>,
    fexp8_3: DFF<Bits<9>>,
    lks8_3: Signal<Local, Bits<9>>,
    m8: DFF<Bits<25>>,
    e8: DFF<Bits<6>>,
    v8: DFF<Bit>,
    al0: Signal<Local, Bits<9>>,
    anm0: Signal<Local, Bits<18>>,
    anz0: Signal<Local, Bit>,
    am0: Signal<Local, Bits<18>>,
    ae0: Signal<Local, Bits<9>>,
    al1: Signal<Local, Bits<9>>,
    anm1: Signal<Local, Bits<18>>,
    anz1: Signal<Local, Bit>,
    am1: Signal<Local, Bits<18>>,
    ae1: Signal<Local, Bits<9>>,
    al2: Signal<Local, Bits<9>>,
    anm2: Signal<Local, Bits<18>>,
    anz2: Signal<Local, Bit>,
    am2: Signal<Local, Bits<18>>,
    ae2: Signal<Local, Bits<9>>,
    al3: Signal<Local, Bits<9>>,
    anm3: Signal<Local, Bits<18>>,
    anz3: Signal<Local, Bit>,
    am3: Signal<Local, Bits<18>>,
    ae3: Signal<Local, Bits<9>>,
    rm9: DFF<Bits<18>>,
    rexp9: DFF<Bits<9>>,
    m9: DFF<Bits<25>>,
    e9: DFF<Bits<6>>,
    v9: DFF<Bit>,
    mul_r: MulU<18, 18, 36>,
    pr10: DFF<Bits<36>>,
    pexp10: DFF<Bits<9>>,
    e10: DFF<Bits<6>>,
    v10: DFF<Bit>,
    n11: Normalize18<36>,
    t11a: Signal<Local, Bits<9>>,
    t11b: Signal<Local, Bits<9>>,
    t11c: Signal<Local, Bits<9>>,
    e11: Signal<Local, Bits<9>>,
    sm11: DFF<Bits<18>>,
    e2_11: DFF<Bits<9>>,
    v11: DFF<Bit>,
    c21: Signal<Local, Bits<21>>,
    m21: Signal<Local, Bits<21>>,
    mr4: Signal<Local, Bits<21>>,
    la12: LeftAlign<21>,
    ms12: Signal<Local, Bits<9>>,
    lt12: Signal<Local, Bits<9>>,
    l12: Signal<Local, Bits<9>>,
    lm12: Signal<Local, Bits<9>>,
    hi12: Signal<Local, Bits<8>>,
    fr12: Signal<Local, Bits<8>>,
    lod12: DFF<Bits<8>>,
    v12: DFF<Bit>,
}

impl Default for TexLod {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            s: Default::default(),
            t: Default::default(),
            m: Default::default(),
            e: Default::default(),
            w_log2: Default::default(),
            h_log2: Default::default(),
            sw_a: Default::default(),
            sw_b: Default::default(),
            tw_a: Default::default(),
            tw_b: Default::default(),
            q_a: Default::default(),
            q_b: Default::default(),
            valid_out: Default::default(),
            lod: Default::default(),
            k1_40: Constant::new(1.into()),
            k1_32: Constant::new(1.into()),
            k20_9: Constant::new(20.into()),
            k18_9: Constant::new(18.into()),
            k40_9: Constant::new(40.into()),
            k7_9: Constant::new(7.into()),
            k24_9: Constant::new(24.into()),
            k2_9: Constant::new(2.into()),
            kflip_9: Constant::new(256.into()),
            k22_5: Constant::new(22.into()),
            k2_5: Constant::new(2.into()),
            k63_6: Constant::new(63.into()),
            k1_41: Constant::new(1.into()),
            k1_42: Constant::new(1.into()),
            ksign_42: Constant::new(crate::common::bits_from_u128::<42>(1u128 << 41)),
            km1_9: Constant::new(511.into()),
            kfm1_9: Constant::new(255.into()),
            kf16_9: Constant::new(272.into()),
            k16_9: Constant::new(16.into()),
            k10_9: Constant::new(10.into()),
            k4_21: Constant::new(4.into()),
            k160_8: Constant::new(160.into()),
            k4_8: Constant::new(4.into()),
            ub0: Default::default(),
            mag1_0: Default::default(),
            sg1_0: Default::default(),
            ub1: Default::default(),
            mag1_1: Default::default(),
            sg1_1: Default::default(),
            ub2: Default::default(),
            mag1_2: Default::default(),
            sg1_2: Default::default(),
            ub3: Default::default(),
            mag1_3: Default::default(),
            sg1_3: Default::default(),
            ub4: Default::default(),
            mag1_4: Default::default(),
            sg1_4: Default::default(),
            ub5: Default::default(),
            mag1_5: Default::default(),
            sg1_5: Default::default(),
            mag1_6: Default::default(),
            sg1_6: Default::default(),
            mag1_7: Default::default(),
            sg1_7: Default::default(),
            m1: Default::default(),
            e1: Default::default(),
            wl1: Default::default(),
            hl1: Default::default(),
            v1: Default::default(),
            n2_0: Default::default(),
            mant2_0: Default::default(),
            exp2_0: Default::default(),
            sg2_0: Default::default(),
            dr2_0: Default::default(),
            n2_1: Default::default(),
            mant2_1: Default::default(),
            exp2_1: Default::default(),
            sg2_1: Default::default(),
            dr2_1: Default::default(),
            n2_2: Default::default(),
            mant2_2: Default::default(),
            exp2_2: Default::default(),
            sg2_2: Default::default(),
            dr2_2: Default::default(),
            n2_3: Default::default(),
            mant2_3: Default::default(),
            exp2_3: Default::default(),
            sg2_3: Default::default(),
            dr2_3: Default::default(),
            n2_4: Default::default(),
            mant2_4: Default::default(),
            exp2_4: Default::default(),
            sg2_4: Default::default(),
            n2_5: Default::default(),
            mant2_5: Default::default(),
            exp2_5: Default::default(),
            sg2_5: Default::default(),
            n2_6: Default::default(),
            mant2_6: Default::default(),
            exp2_6: Default::default(),
            sg2_6: Default::default(),
            n2_7: Default::default(),
            mant2_7: Default::default(),
            exp2_7: Default::default(),
            sg2_7: Default::default(),
            m2: Default::default(),
            e2: Default::default(),
            wl2: Default::default(),
            hl2: Default::default(),
            v2: Default::default(),
            mul0: Default::default(),
            pm3_0: Default::default(),
            psg3_0: Default::default(),
            pexp3_0: Default::default(),
            xm3_0: Default::default(),
            xsg3_0: Default::default(),
            xexp3_0: Default::default(),
            mul1: Default::default(),
            pm3_1: Default::default(),
            psg3_1: Default::default(),
            pexp3_1: Default::default(),
            xm3_1: Default::default(),
            xsg3_1: Default::default(),
            xexp3_1: Default::default(),
            mul2: Default::default(),
            pm3_2: Default::default(),
            psg3_2: Default::default(),
            pexp3_2: Default::default(),
            xm3_2: Default::default(),
            xsg3_2: Default::default(),
            xexp3_2: Default::default(),
            mul3: Default::default(),
            pm3_3: Default::default(),
            psg3_3: Default::default(),
            pexp3_3: Default::default(),
            xm3_3: Default::default(),
            xsg3_3: Default::default(),
            xexp3_3: Default::default(),
            m3: Default::default(),
            e3: Default::default(),
            wl3: Default::default(),
            hl3: Default::default(),
            v3: Default::default(),
            n4_0: Default::default(),
            dr4_0: Default::default(),
            ym4_0: Default::default(),
            ysg4_0: Default::default(),
            yexp4_0: Default::default(),
            xm4_0: Default::default(),
            xsg4_0: Default::default(),
            xexp4_0: Default::default(),
            n4_1: Default::default(),
            dr4_1: Default::default(),
            ym4_1: Default::default(),
            ysg4_1: Default::default(),
            yexp4_1: Default::default(),
            xm4_1: Default::default(),
            xsg4_1: Default::default(),
            xexp4_1: Default::default(),
            n4_2: Default::default(),
            dr4_2: Default::default(),
            ym4_2: Default::default(),
            ysg4_2: Default::default(),
            yexp4_2: Default::default(),
            xm4_2: Default::default(),
            xsg4_2: Default::default(),
            xexp4_2: Default::default(),
            n4_3: Default::default(),
            dr4_3: Default::default(),
            ym4_3: Default::default(),
            ysg4_3: Default::default(),
            yexp4_3: Default::default(),
            xm4_3: Default::default(),
            xsg4_3: Default::default(),
            xexp4_3: Default::default(),
            m4: Default::default(),
            e4: Default::default(),
            wl4: Default::default(),
            hl4: Default::default(),
            v4: Default::default(),
            topx0: Default::default(),
            topy0: Default::default(),
            big0: Default::default(),
            kx0: Default::default(),
            ky0: Default::default(),
            shx0: Default::default(),
            shy0: Default::default(),
            vx0: Default::default(),
            vy0: Default::default(),
            ix0: Default::default(),
            iy0: Default::default(),
            nx0: Default::default(),
            ny0: Default::default(),
            px0: Default::default(),
            py0: Default::default(),
            ax5_0: Default::default(),
            ay5_0: Default::default(),
            base5_0: Default::default(),
            topx1: Default::default(),
            topy1: Default::default(),
            big1: Default::default(),
            kx1: Default::default(),
            ky1: Default::default(),
            shx1: Default::default(),
            shy1: Default::default(),
            vx1: Default::default(),
            vy1: Default::default(),
            ix1: Default::default(),
            iy1: Default::default(),
            nx1: Default::default(),
            ny1: Default::default(),
            px1: Default::default(),
            py1: Default::default(),
            ax5_1: Default::default(),
            ay5_1: Default::default(),
            base5_1: Default::default(),
            topx2: Default::default(),
            topy2: Default::default(),
            big2: Default::default(),
            kx2: Default::default(),
            ky2: Default::default(),
            shx2: Default::default(),
            shy2: Default::default(),
            vx2: Default::default(),
            vy2: Default::default(),
            ix2: Default::default(),
            iy2: Default::default(),
            nx2: Default::default(),
            ny2: Default::default(),
            px2: Default::default(),
            py2: Default::default(),
            ax5_2: Default::default(),
            ay5_2: Default::default(),
            base5_2: Default::default(),
            topx3: Default::default(),
            topy3: Default::default(),
            big3: Default::default(),
            kx3: Default::default(),
            ky3: Default::default(),
            shx3: Default::default(),
            shy3: Default::default(),
            vx3: Default::default(),
            vy3: Default::default(),
            ix3: Default::default(),
            iy3: Default::default(),
            nx3: Default::default(),
            ny3: Default::default(),
            px3: Default::default(),
            py3: Default::default(),
            ax5_3: Default::default(),
            ay5_3: Default::default(),
            base5_3: Default::default(),
            m5: Default::default(),
            e5: Default::default(),
            wl5: Default::default(),
            hl5: Default::default(),
            v5: Default::default(),
            ex0: Default::default(),
            ey0: Default::default(),
            dd0: Default::default(),
            dm6_0: Default::default(),
            base6_0: Default::default(),
            ex1: Default::default(),
            ey1: Default::default(),
            dd1: Default::default(),
            dm6_1: Default::default(),
            base6_1: Default::default(),
            ex2: Default::default(),
            ey2: Default::default(),
            dd2: Default::default(),
            dm6_2: Default::default(),
            base6_2: Default::default(),
            ex3: Default::default(),
            ey3: Default::default(),
            dd3: Default::default(),
            dm6_3: Default::default(),
            base6_3: Default::default(),
            m6: Default::default(),
            e6: Default::default(),
            wl6: Default::default(),
            hl6: Default::default(),
            v6: Default::default(),
            n7_0: Default::default(),
            dr7_0: Default::default(),
            eb7_0: Default::default(),
            lg7_0: Default::default(),
            fm7_0: Default::default(),
            fexp7_0: Default::default(),
            n7_1: Default::default(),
            dr7_1: Default::default(),
            eb7_1: Default::default(),
            lg7_1: Default::default(),
            fm7_1: Default::default(),
            fexp7_1: Default::default(),
            n7_2: Default::default(),
            dr7_2: Default::default(),
            eb7_2: Default::default(),
            lg7_2: Default::default(),
            fm7_2: Default::default(),
            fexp7_2: Default::default(),
            n7_3: Default::default(),
            dr7_3: Default::default(),
            eb7_3: Default::default(),
            lg7_3: Default::default(),
            fm7_3: Default::default(),
            fexp7_3: Default::default(),
            m7: Default::default(),
            e7: Default::default(),
            v7: Default::default(),
            la8_0: Default::default(),
            ms8_0: Default::default(),
            lk8_0: Default::default(),
            nm8_0: Default::default(),
            nz8_0: Default::default(),
            fm8_0: Default::default(),
            fexp8_0: Default::default(),
            lks8_0: Default::default(),
            la8_1: Default::default(),
            ms8_1: Default::default(),
            lk8_1: Default::default(),
            nm8_1: Default::default(),
            nz8_1: Default::default(),
            fm8_1: Default::default(),
            fexp8_1: Default::default(),
            lks8_1: Default::default(),
            la8_2: Default::default(),
            ms8_2: Default::default(),
            lk8_2: Default::default(),
            nm8_2: Default::default(),
            nz8_2: Default::default(),
            fm8_2: Default::default(),
            fexp8_2: Default::default(),
            lks8_2: Default::default(),
            la8_3: Default::default(),
            ms8_3: Default::default(),
            lk8_3: Default::default(),
            nm8_3: Default::default(),
            nz8_3: Default::default(),
            fm8_3: Default::default(),
            fexp8_3: Default::default(),
            lks8_3: Default::default(),
            m8: Default::default(),
            e8: Default::default(),
            v8: Default::default(),
            al0: Default::default(),
            anm0: Default::default(),
            anz0: Default::default(),
            am0: Default::default(),
            ae0: Default::default(),
            al1: Default::default(),
            anm1: Default::default(),
            anz1: Default::default(),
            am1: Default::default(),
            ae1: Default::default(),
            al2: Default::default(),
            anm2: Default::default(),
            anz2: Default::default(),
            am2: Default::default(),
            ae2: Default::default(),
            al3: Default::default(),
            anm3: Default::default(),
            anz3: Default::default(),
            am3: Default::default(),
            ae3: Default::default(),
            rm9: Default::default(),
            rexp9: Default::default(),
            m9: Default::default(),
            e9: Default::default(),
            v9: Default::default(),
            mul_r: Default::default(),
            pr10: Default::default(),
            pexp10: Default::default(),
            e10: Default::default(),
            v10: Default::default(),
            n11: Default::default(),
            t11a: Default::default(),
            t11b: Default::default(),
            t11c: Default::default(),
            e11: Default::default(),
            sm11: Default::default(),
            e2_11: Default::default(),
            v11: Default::default(),
            c21: Default::default(),
            m21: Default::default(),
            mr4: Default::default(),
            la12: Default::default(),
            ms12: Default::default(),
            lt12: Default::default(),
            l12: Default::default(),
            lm12: Default::default(),
            hi12: Default::default(),
            fr12: Default::default(),
            lod12: Default::default(),
            v12: Default::default(),
        }
    }
}

impl Logic for TexLod {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mag1_0, sg1_0, mag1_1, sg1_1, mag1_2, sg1_2, mag1_3, sg1_3, mag1_4, sg1_4, mag1_5, sg1_5, mag1_6, sg1_6, mag1_7, sg1_7, m1, e1, wl1, hl1, v1, mant2_0, exp2_0, sg2_0, mant2_1, exp2_1, sg2_1, mant2_2, exp2_2, sg2_2, mant2_3, exp2_3, sg2_3, mant2_4, exp2_4, sg2_4, mant2_5, exp2_5, sg2_5, mant2_6, exp2_6, sg2_6, mant2_7, exp2_7, sg2_7, m2, e2, wl2, hl2, v2, pm3_0, psg3_0, pexp3_0, xm3_0, xsg3_0, xexp3_0, pm3_1, psg3_1, pexp3_1, xm3_1, xsg3_1, xexp3_1, pm3_2, psg3_2, pexp3_2, xm3_2, xsg3_2, xexp3_2, pm3_3, psg3_3, pexp3_3, xm3_3, xsg3_3, xexp3_3, m3, e3, wl3, hl3, v3, ym4_0, ysg4_0, yexp4_0, xm4_0, xsg4_0, xexp4_0, ym4_1, ysg4_1, yexp4_1, xm4_1, xsg4_1, xexp4_1, ym4_2, ysg4_2, yexp4_2, xm4_2, xsg4_2, xexp4_2, ym4_3, ysg4_3, yexp4_3, xm4_3, xsg4_3, xexp4_3, m4, e4, wl4, hl4, v4, ax5_0, ay5_0, base5_0, ax5_1, ay5_1, base5_1, ax5_2, ay5_2, base5_2, ax5_3, ay5_3, base5_3, m5, e5, wl5, hl5, v5, dm6_0, base6_0, dm6_1, base6_1, dm6_2, base6_2, dm6_3, base6_3, m6, e6, wl6, hl6, v6, fm7_0, fexp7_0, fm7_1, fexp7_1, fm7_2, fexp7_2, fm7_3, fexp7_3, m7, e7, v7, lk8_0, nm8_0, nz8_0, fm8_0, fexp8_0, lk8_1, nm8_1, nz8_1, fm8_1, fexp8_1, lk8_2, nm8_2, nz8_2, fm8_2, fexp8_2, lk8_3, nm8_3, nz8_3, fm8_3, fexp8_3, m8, e8, v8, rm9, rexp9, m9, e9, v9, pr10, pexp10, e10, v10, sm11, e2_11, v11, lod12, v12);
        // Stage 1: magnitudes and signs of the eight operands (sw a, b; tw a, b; q a, b; s; t).
        self.ub0.next = unsigned_cast(self.sw_a.val());
        self.mag1_0.d.next = self.ub0.val();
        if self.ub0.val().get_bit(39) {
            self.mag1_0.d.next = !self.ub0.val() + self.k1_40.val();
        }
        self.sg1_0.d.next = self.ub0.val().get_bit(39);
        self.ub1.next = unsigned_cast(self.sw_b.val());
        self.mag1_1.d.next = self.ub1.val();
        if self.ub1.val().get_bit(39) {
            self.mag1_1.d.next = !self.ub1.val() + self.k1_40.val();
        }
        self.sg1_1.d.next = self.ub1.val().get_bit(39);
        self.ub2.next = unsigned_cast(self.tw_a.val());
        self.mag1_2.d.next = self.ub2.val();
        if self.ub2.val().get_bit(39) {
            self.mag1_2.d.next = !self.ub2.val() + self.k1_40.val();
        }
        self.sg1_2.d.next = self.ub2.val().get_bit(39);
        self.ub3.next = unsigned_cast(self.tw_b.val());
        self.mag1_3.d.next = self.ub3.val();
        if self.ub3.val().get_bit(39) {
            self.mag1_3.d.next = !self.ub3.val() + self.k1_40.val();
        }
        self.sg1_3.d.next = self.ub3.val().get_bit(39);
        self.ub4.next = unsigned_cast(self.q_a.val());
        self.mag1_4.d.next = self.ub4.val();
        if self.ub4.val().get_bit(39) {
            self.mag1_4.d.next = !self.ub4.val() + self.k1_40.val();
        }
        self.sg1_4.d.next = self.ub4.val().get_bit(39);
        self.ub5.next = unsigned_cast(self.q_b.val());
        self.mag1_5.d.next = self.ub5.val();
        if self.ub5.val().get_bit(39) {
            self.mag1_5.d.next = !self.ub5.val() + self.k1_40.val();
        }
        self.sg1_5.d.next = self.ub5.val().get_bit(39);
        self.mag1_6.d.next = self.s.val();
        if self.s.val().get_bit(31) {
            self.mag1_6.d.next = !self.s.val() + self.k1_32.val();
        }
        self.sg1_6.d.next = self.s.val().get_bit(31);
        self.mag1_7.d.next = self.t.val();
        if self.t.val().get_bit(31) {
            self.mag1_7.d.next = !self.t.val() + self.k1_32.val();
        }
        self.sg1_7.d.next = self.t.val().get_bit(31);
        self.m1.d.next = self.m.val();
        self.e1.d.next = self.e.val();
        self.wl1.d.next = self.w_log2.val();
        self.hl1.d.next = self.h_log2.val();
        self.v1.d.next = self.valid_in.val();
        // Stage 2: 18-bit mantissas; the a_sw terms' exponents carry their 2^20.
        self.n2_0.mag.next = self.mag1_0.q.val();
        self.mant2_0.d.next = self.n2_0.mant.val();
        self.dr2_0.next = bit_cast::<9, 6>(self.n2_0.drop.val());
        self.exp2_0.d.next = self.dr2_0.val() + self.k20_9.val();
        self.sg2_0.d.next = self.sg1_0.q.val();
        self.n2_1.mag.next = self.mag1_1.q.val();
        self.mant2_1.d.next = self.n2_1.mant.val();
        self.dr2_1.next = bit_cast::<9, 6>(self.n2_1.drop.val());
        self.exp2_1.d.next = self.dr2_1.val() + self.k20_9.val();
        self.sg2_1.d.next = self.sg1_1.q.val();
        self.n2_2.mag.next = self.mag1_2.q.val();
        self.mant2_2.d.next = self.n2_2.mant.val();
        self.dr2_2.next = bit_cast::<9, 6>(self.n2_2.drop.val());
        self.exp2_2.d.next = self.dr2_2.val() + self.k20_9.val();
        self.sg2_2.d.next = self.sg1_2.q.val();
        self.n2_3.mag.next = self.mag1_3.q.val();
        self.mant2_3.d.next = self.n2_3.mant.val();
        self.dr2_3.next = bit_cast::<9, 6>(self.n2_3.drop.val());
        self.exp2_3.d.next = self.dr2_3.val() + self.k20_9.val();
        self.sg2_3.d.next = self.sg1_3.q.val();
        self.n2_4.mag.next = self.mag1_4.q.val();
        self.mant2_4.d.next = self.n2_4.mant.val();
        self.exp2_4.d.next = bit_cast::<9, 6>(self.n2_4.drop.val());
        self.sg2_4.d.next = self.sg1_4.q.val();
        self.n2_5.mag.next = self.mag1_5.q.val();
        self.mant2_5.d.next = self.n2_5.mant.val();
        self.exp2_5.d.next = bit_cast::<9, 6>(self.n2_5.drop.val());
        self.sg2_5.d.next = self.sg1_5.q.val();
        self.n2_6.mag.next = self.mag1_6.q.val();
        self.mant2_6.d.next = self.n2_6.mant.val();
        self.exp2_6.d.next = bit_cast::<9, 6>(self.n2_6.drop.val());
        self.sg2_6.d.next = self.sg1_6.q.val();
        self.n2_7.mag.next = self.mag1_7.q.val();
        self.mant2_7.d.next = self.n2_7.mant.val();
        self.exp2_7.d.next = bit_cast::<9, 6>(self.n2_7.drop.val());
        self.sg2_7.d.next = self.sg1_7.q.val();
        self.m2.d.next = self.m1.q.val();
        self.e2.d.next = self.e1.q.val();
        self.wl2.d.next = self.wl1.q.val();
        self.hl2.d.next = self.hl1.q.val();
        self.v2.d.next = self.v1.q.val();
        // Stage 3: the products s A_q, s B_q, t A_q, t B_q.
        self.mul0.a.next = self.mant2_6.q.val();
        self.mul0.b.next = self.mant2_4.q.val();
        self.pm3_0.d.next = self.mul0.p.val();
        self.psg3_0.d.next = self.sg2_6.q.val() ^ self.sg2_4.q.val();
        self.pexp3_0.d.next = self.exp2_6.q.val() + self.exp2_4.q.val();
        self.xm3_0.d.next = self.mant2_0.q.val();
        self.xsg3_0.d.next = self.sg2_0.q.val();
        self.xexp3_0.d.next = self.exp2_0.q.val();
        self.mul1.a.next = self.mant2_6.q.val();
        self.mul1.b.next = self.mant2_5.q.val();
        self.pm3_1.d.next = self.mul1.p.val();
        self.psg3_1.d.next = self.sg2_6.q.val() ^ self.sg2_5.q.val();
        self.pexp3_1.d.next = self.exp2_6.q.val() + self.exp2_5.q.val();
        self.xm3_1.d.next = self.mant2_1.q.val();
        self.xsg3_1.d.next = self.sg2_1.q.val();
        self.xexp3_1.d.next = self.exp2_1.q.val();
        self.mul2.a.next = self.mant2_7.q.val();
        self.mul2.b.next = self.mant2_4.q.val();
        self.pm3_2.d.next = self.mul2.p.val();
        self.psg3_2.d.next = self.sg2_7.q.val() ^ self.sg2_4.q.val();
        self.pexp3_2.d.next = self.exp2_7.q.val() + self.exp2_4.q.val();
        self.xm3_2.d.next = self.mant2_2.q.val();
        self.xsg3_2.d.next = self.sg2_2.q.val();
        self.xexp3_2.d.next = self.exp2_2.q.val();
        self.mul3.a.next = self.mant2_7.q.val();
        self.mul3.b.next = self.mant2_5.q.val();
        self.pm3_3.d.next = self.mul3.p.val();
        self.psg3_3.d.next = self.sg2_7.q.val() ^ self.sg2_5.q.val();
        self.pexp3_3.d.next = self.exp2_7.q.val() + self.exp2_5.q.val();
        self.xm3_3.d.next = self.mant2_3.q.val();
        self.xsg3_3.d.next = self.sg2_3.q.val();
        self.xexp3_3.d.next = self.exp2_3.q.val();
        self.m3.d.next = self.m2.q.val();
        self.e3.d.next = self.e2.q.val();
        self.wl3.d.next = self.wl2.q.val();
        self.hl3.d.next = self.hl2.q.val();
        self.v3.d.next = self.v2.q.val();
        // Stage 4: the products' 18-bit mantissas.
        self.n4_0.mag.next = self.pm3_0.q.val();
        self.ym4_0.d.next = self.n4_0.mant.val();
        self.dr4_0.next = bit_cast::<9, 6>(self.n4_0.drop.val());
        self.yexp4_0.d.next = self.dr4_0.val() + self.pexp3_0.q.val();
        self.ysg4_0.d.next = self.psg3_0.q.val();
        self.xm4_0.d.next = self.xm3_0.q.val();
        self.xsg4_0.d.next = self.xsg3_0.q.val();
        self.xexp4_0.d.next = self.xexp3_0.q.val();
        self.n4_1.mag.next = self.pm3_1.q.val();
        self.ym4_1.d.next = self.n4_1.mant.val();
        self.dr4_1.next = bit_cast::<9, 6>(self.n4_1.drop.val());
        self.yexp4_1.d.next = self.dr4_1.val() + self.pexp3_1.q.val();
        self.ysg4_1.d.next = self.psg3_1.q.val();
        self.xm4_1.d.next = self.xm3_1.q.val();
        self.xsg4_1.d.next = self.xsg3_1.q.val();
        self.xexp4_1.d.next = self.xexp3_1.q.val();
        self.n4_2.mag.next = self.pm3_2.q.val();
        self.ym4_2.d.next = self.n4_2.mant.val();
        self.dr4_2.next = bit_cast::<9, 6>(self.n4_2.drop.val());
        self.yexp4_2.d.next = self.dr4_2.val() + self.pexp3_2.q.val();
        self.ysg4_2.d.next = self.psg3_2.q.val();
        self.xm4_2.d.next = self.xm3_2.q.val();
        self.xsg4_2.d.next = self.xsg3_2.q.val();
        self.xexp4_2.d.next = self.xexp3_2.q.val();
        self.n4_3.mag.next = self.pm3_3.q.val();
        self.ym4_3.d.next = self.n4_3.mant.val();
        self.dr4_3.next = bit_cast::<9, 6>(self.n4_3.drop.val());
        self.yexp4_3.d.next = self.dr4_3.val() + self.pexp3_3.q.val();
        self.ysg4_3.d.next = self.psg3_3.q.val();
        self.xm4_3.d.next = self.xm3_3.q.val();
        self.xsg4_3.d.next = self.xsg3_3.q.val();
        self.xexp4_3.d.next = self.xexp3_3.q.val();
        self.m4.d.next = self.m3.q.val();
        self.e4.d.next = self.e3.q.val();
        self.wl4.d.next = self.wl3.q.val();
        self.hl4.d.next = self.hl3.q.val();
        self.v4.d.next = self.v3.q.val();
        // Stage 5: both terms as two's complement, aligned 22 bits above the larger one's mantissa.
        self.topx0.next = self.xexp4_0.q.val() + self.k18_9.val();
        self.topy0.next = self.yexp4_0.q.val() + self.k18_9.val();
        self.big0.next = self.topx0.val();
        if !self.xm4_0.q.val().any() {
            self.big0.next = self.topy0.val();
        } else if self.ym4_0.q.val().any() & ((self.topy0.val() ^ self.kflip_9.val()) > (self.topx0.val() ^ self.kflip_9.val())) {
            self.big0.next = self.topy0.val();
        }
        self.kx0.next = self.big0.val() - self.topx0.val();
        self.shx0.next = self.kx0.val().get_bits::<6>(0);
        if self.kx0.val().get_bits::<3>(6).any() {
            self.shx0.next = self.k63_6.val();
        }
        self.px0.next = bit_cast::<41, 18>(self.xm4_0.q.val()) << self.k22_5.val();
        self.vx0.next = self.px0.val();
        if self.xsg4_0.q.val() {
            self.vx0.next = !self.px0.val() + self.k1_41.val();
        }
        self.ix0.next = !self.vx0.val();
        self.nx0.next = self.ix0.val() >> self.shx0.val();
        self.ax5_0.d.next = self.vx0.val() >> self.shx0.val();
        if self.vx0.val().get_bit(40) {
            self.ax5_0.d.next = !self.nx0.val();
        }
        self.ky0.next = self.big0.val() - self.topy0.val();
        self.shy0.next = self.ky0.val().get_bits::<6>(0);
        if self.ky0.val().get_bits::<3>(6).any() {
            self.shy0.next = self.k63_6.val();
        }
        self.py0.next = bit_cast::<41, 18>(self.ym4_0.q.val()) << self.k22_5.val();
        self.vy0.next = self.py0.val();
        if self.ysg4_0.q.val() {
            self.vy0.next = !self.py0.val() + self.k1_41.val();
        }
        self.iy0.next = !self.vy0.val();
        self.ny0.next = self.iy0.val() >> self.shy0.val();
        self.ay5_0.d.next = self.vy0.val() >> self.shy0.val();
        if self.vy0.val().get_bit(40) {
            self.ay5_0.d.next = !self.ny0.val();
        }
        self.base5_0.d.next = self.big0.val() - self.k40_9.val();
        self.topx1.next = self.xexp4_1.q.val() + self.k18_9.val();
        self.topy1.next = self.yexp4_1.q.val() + self.k18_9.val();
        self.big1.next = self.topx1.val();
        if !self.xm4_1.q.val().any() {
            self.big1.next = self.topy1.val();
        } else if self.ym4_1.q.val().any() & ((self.topy1.val() ^ self.kflip_9.val()) > (self.topx1.val() ^ self.kflip_9.val())) {
            self.big1.next = self.topy1.val();
        }
        self.kx1.next = self.big1.val() - self.topx1.val();
        self.shx1.next = self.kx1.val().get_bits::<6>(0);
        if self.kx1.val().get_bits::<3>(6).any() {
            self.shx1.next = self.k63_6.val();
        }
        self.px1.next = bit_cast::<41, 18>(self.xm4_1.q.val()) << self.k22_5.val();
        self.vx1.next = self.px1.val();
        if self.xsg4_1.q.val() {
            self.vx1.next = !self.px1.val() + self.k1_41.val();
        }
        self.ix1.next = !self.vx1.val();
        self.nx1.next = self.ix1.val() >> self.shx1.val();
        self.ax5_1.d.next = self.vx1.val() >> self.shx1.val();
        if self.vx1.val().get_bit(40) {
            self.ax5_1.d.next = !self.nx1.val();
        }
        self.ky1.next = self.big1.val() - self.topy1.val();
        self.shy1.next = self.ky1.val().get_bits::<6>(0);
        if self.ky1.val().get_bits::<3>(6).any() {
            self.shy1.next = self.k63_6.val();
        }
        self.py1.next = bit_cast::<41, 18>(self.ym4_1.q.val()) << self.k22_5.val();
        self.vy1.next = self.py1.val();
        if self.ysg4_1.q.val() {
            self.vy1.next = !self.py1.val() + self.k1_41.val();
        }
        self.iy1.next = !self.vy1.val();
        self.ny1.next = self.iy1.val() >> self.shy1.val();
        self.ay5_1.d.next = self.vy1.val() >> self.shy1.val();
        if self.vy1.val().get_bit(40) {
            self.ay5_1.d.next = !self.ny1.val();
        }
        self.base5_1.d.next = self.big1.val() - self.k40_9.val();
        self.topx2.next = self.xexp4_2.q.val() + self.k18_9.val();
        self.topy2.next = self.yexp4_2.q.val() + self.k18_9.val();
        self.big2.next = self.topx2.val();
        if !self.xm4_2.q.val().any() {
            self.big2.next = self.topy2.val();
        } else if self.ym4_2.q.val().any() & ((self.topy2.val() ^ self.kflip_9.val()) > (self.topx2.val() ^ self.kflip_9.val())) {
            self.big2.next = self.topy2.val();
        }
        self.kx2.next = self.big2.val() - self.topx2.val();
        self.shx2.next = self.kx2.val().get_bits::<6>(0);
        if self.kx2.val().get_bits::<3>(6).any() {
            self.shx2.next = self.k63_6.val();
        }
        self.px2.next = bit_cast::<41, 18>(self.xm4_2.q.val()) << self.k22_5.val();
        self.vx2.next = self.px2.val();
        if self.xsg4_2.q.val() {
            self.vx2.next = !self.px2.val() + self.k1_41.val();
        }
        self.ix2.next = !self.vx2.val();
        self.nx2.next = self.ix2.val() >> self.shx2.val();
        self.ax5_2.d.next = self.vx2.val() >> self.shx2.val();
        if self.vx2.val().get_bit(40) {
            self.ax5_2.d.next = !self.nx2.val();
        }
        self.ky2.next = self.big2.val() - self.topy2.val();
        self.shy2.next = self.ky2.val().get_bits::<6>(0);
        if self.ky2.val().get_bits::<3>(6).any() {
            self.shy2.next = self.k63_6.val();
        }
        self.py2.next = bit_cast::<41, 18>(self.ym4_2.q.val()) << self.k22_5.val();
        self.vy2.next = self.py2.val();
        if self.ysg4_2.q.val() {
            self.vy2.next = !self.py2.val() + self.k1_41.val();
        }
        self.iy2.next = !self.vy2.val();
        self.ny2.next = self.iy2.val() >> self.shy2.val();
        self.ay5_2.d.next = self.vy2.val() >> self.shy2.val();
        if self.vy2.val().get_bit(40) {
            self.ay5_2.d.next = !self.ny2.val();
        }
        self.base5_2.d.next = self.big2.val() - self.k40_9.val();
        self.topx3.next = self.xexp4_3.q.val() + self.k18_9.val();
        self.topy3.next = self.yexp4_3.q.val() + self.k18_9.val();
        self.big3.next = self.topx3.val();
        if !self.xm4_3.q.val().any() {
            self.big3.next = self.topy3.val();
        } else if self.ym4_3.q.val().any() & ((self.topy3.val() ^ self.kflip_9.val()) > (self.topx3.val() ^ self.kflip_9.val())) {
            self.big3.next = self.topy3.val();
        }
        self.kx3.next = self.big3.val() - self.topx3.val();
        self.shx3.next = self.kx3.val().get_bits::<6>(0);
        if self.kx3.val().get_bits::<3>(6).any() {
            self.shx3.next = self.k63_6.val();
        }
        self.px3.next = bit_cast::<41, 18>(self.xm4_3.q.val()) << self.k22_5.val();
        self.vx3.next = self.px3.val();
        if self.xsg4_3.q.val() {
            self.vx3.next = !self.px3.val() + self.k1_41.val();
        }
        self.ix3.next = !self.vx3.val();
        self.nx3.next = self.ix3.val() >> self.shx3.val();
        self.ax5_3.d.next = self.vx3.val() >> self.shx3.val();
        if self.vx3.val().get_bit(40) {
            self.ax5_3.d.next = !self.nx3.val();
        }
        self.ky3.next = self.big3.val() - self.topy3.val();
        self.shy3.next = self.ky3.val().get_bits::<6>(0);
        if self.ky3.val().get_bits::<3>(6).any() {
            self.shy3.next = self.k63_6.val();
        }
        self.py3.next = bit_cast::<41, 18>(self.ym4_3.q.val()) << self.k22_5.val();
        self.vy3.next = self.py3.val();
        if self.ysg4_3.q.val() {
            self.vy3.next = !self.py3.val() + self.k1_41.val();
        }
        self.iy3.next = !self.vy3.val();
        self.ny3.next = self.iy3.val() >> self.shy3.val();
        self.ay5_3.d.next = self.vy3.val() >> self.shy3.val();
        if self.vy3.val().get_bit(40) {
            self.ay5_3.d.next = !self.ny3.val();
        }
        self.base5_3.d.next = self.big3.val() - self.k40_9.val();
        self.m5.d.next = self.m4.q.val();
        self.e5.d.next = self.e4.q.val();
        self.wl5.d.next = self.wl4.q.val();
        self.hl5.d.next = self.hl4.q.val();
        self.v5.d.next = self.v4.q.val();
        // Stage 6: the difference's magnitude (42 bits).
        self.ex0.next = bit_cast::<42, 41>(self.ax5_0.q.val());
        if self.ax5_0.q.val().get_bit(40) {
            self.ex0.next = bit_cast::<42, 41>(self.ax5_0.q.val()) | self.ksign_42.val();
        }
        self.ey0.next = bit_cast::<42, 41>(self.ay5_0.q.val());
        if self.ay5_0.q.val().get_bit(40) {
            self.ey0.next = bit_cast::<42, 41>(self.ay5_0.q.val()) | self.ksign_42.val();
        }
        self.dd0.next = self.ex0.val() - self.ey0.val();
        self.dm6_0.d.next = self.dd0.val();
        if self.dd0.val().get_bit(41) {
            self.dm6_0.d.next = !self.dd0.val() + self.k1_42.val();
        }
        self.base6_0.d.next = self.base5_0.q.val();
        self.ex1.next = bit_cast::<42, 41>(self.ax5_1.q.val());
        if self.ax5_1.q.val().get_bit(40) {
            self.ex1.next = bit_cast::<42, 41>(self.ax5_1.q.val()) | self.ksign_42.val();
        }
        self.ey1.next = bit_cast::<42, 41>(self.ay5_1.q.val());
        if self.ay5_1.q.val().get_bit(40) {
            self.ey1.next = bit_cast::<42, 41>(self.ay5_1.q.val()) | self.ksign_42.val();
        }
        self.dd1.next = self.ex1.val() - self.ey1.val();
        self.dm6_1.d.next = self.dd1.val();
        if self.dd1.val().get_bit(41) {
            self.dm6_1.d.next = !self.dd1.val() + self.k1_42.val();
        }
        self.base6_1.d.next = self.base5_1.q.val();
        self.ex2.next = bit_cast::<42, 41>(self.ax5_2.q.val());
        if self.ax5_2.q.val().get_bit(40) {
            self.ex2.next = bit_cast::<42, 41>(self.ax5_2.q.val()) | self.ksign_42.val();
        }
        self.ey2.next = bit_cast::<42, 41>(self.ay5_2.q.val());
        if self.ay5_2.q.val().get_bit(40) {
            self.ey2.next = bit_cast::<42, 41>(self.ay5_2.q.val()) | self.ksign_42.val();
        }
        self.dd2.next = self.ex2.val() - self.ey2.val();
        self.dm6_2.d.next = self.dd2.val();
        if self.dd2.val().get_bit(41) {
            self.dm6_2.d.next = !self.dd2.val() + self.k1_42.val();
        }
        self.base6_2.d.next = self.base5_2.q.val();
        self.ex3.next = bit_cast::<42, 41>(self.ax5_3.q.val());
        if self.ax5_3.q.val().get_bit(40) {
            self.ex3.next = bit_cast::<42, 41>(self.ax5_3.q.val()) | self.ksign_42.val();
        }
        self.ey3.next = bit_cast::<42, 41>(self.ay5_3.q.val());
        if self.ay5_3.q.val().get_bit(40) {
            self.ey3.next = bit_cast::<42, 41>(self.ay5_3.q.val()) | self.ksign_42.val();
        }
        self.dd3.next = self.ex3.val() - self.ey3.val();
        self.dm6_3.d.next = self.dd3.val();
        if self.dd3.val().get_bit(41) {
            self.dm6_3.d.next = !self.dd3.val() + self.k1_42.val();
        }
        self.base6_3.d.next = self.base5_3.q.val();
        self.m6.d.next = self.m5.q.val();
        self.e6.d.next = self.e5.q.val();
        self.wl6.d.next = self.wl5.q.val();
        self.hl6.d.next = self.hl5.q.val();
        self.v6.d.next = self.v5.q.val();
        // Stage 7: the four derivatives' numerators as 18-bit mantissas, scaled to level 0's texels.
        self.n7_0.mag.next = self.dm6_0.q.val();
        self.fm7_0.d.next = self.n7_0.mant.val();
        self.dr7_0.next = bit_cast::<9, 6>(self.n7_0.drop.val());
        self.lg7_0.next = bit_cast::<9, 4>(self.wl6.q.val());
        self.eb7_0.next = self.dr7_0.val() + self.base6_0.q.val();
        self.fexp7_0.d.next = self.eb7_0.val() + self.lg7_0.val();
        self.n7_1.mag.next = self.dm6_1.q.val();
        self.fm7_1.d.next = self.n7_1.mant.val();
        self.dr7_1.next = bit_cast::<9, 6>(self.n7_1.drop.val());
        self.lg7_1.next = bit_cast::<9, 4>(self.wl6.q.val());
        self.eb7_1.next = self.dr7_1.val() + self.base6_1.q.val();
        self.fexp7_1.d.next = self.eb7_1.val() + self.lg7_1.val();
        self.n7_2.mag.next = self.dm6_2.q.val();
        self.fm7_2.d.next = self.n7_2.mant.val();
        self.dr7_2.next = bit_cast::<9, 6>(self.n7_2.drop.val());
        self.lg7_2.next = bit_cast::<9, 4>(self.hl6.q.val());
        self.eb7_2.next = self.dr7_2.val() + self.base6_2.q.val();
        self.fexp7_2.d.next = self.eb7_2.val() + self.lg7_2.val();
        self.n7_3.mag.next = self.dm6_3.q.val();
        self.fm7_3.d.next = self.n7_3.mant.val();
        self.dr7_3.next = bit_cast::<9, 6>(self.n7_3.drop.val());
        self.lg7_3.next = bit_cast::<9, 4>(self.hl6.q.val());
        self.eb7_3.next = self.dr7_3.val() + self.base6_3.q.val();
        self.fexp7_3.d.next = self.eb7_3.val() + self.lg7_3.val();
        self.m7.d.next = self.m6.q.val();
        self.e7.d.next = self.e6.q.val();
        self.v7.d.next = self.v6.q.val();
        // Stage 8: each one's leading one (exponent + msb) and its bits below, to compare.
        self.la8_0.x.next = self.fm7_0.q.val();
        self.ms8_0.next = bit_cast::<9, 6>(self.la8_0.msb.val());
        self.lks8_0.next = self.fexp7_0.q.val() + self.ms8_0.val();
        self.lk8_0.d.next = self.lks8_0.val() ^ self.kflip_9.val();
        self.nm8_0.d.next = self.la8_0.nm.val();
        self.nz8_0.d.next = self.fm7_0.q.val().any();
        self.fm8_0.d.next = self.fm7_0.q.val();
        self.fexp8_0.d.next = self.fexp7_0.q.val();
        self.la8_1.x.next = self.fm7_1.q.val();
        self.ms8_1.next = bit_cast::<9, 6>(self.la8_1.msb.val());
        self.lks8_1.next = self.fexp7_1.q.val() + self.ms8_1.val();
        self.lk8_1.d.next = self.lks8_1.val() ^ self.kflip_9.val();
        self.nm8_1.d.next = self.la8_1.nm.val();
        self.nz8_1.d.next = self.fm7_1.q.val().any();
        self.fm8_1.d.next = self.fm7_1.q.val();
        self.fexp8_1.d.next = self.fexp7_1.q.val();
        self.la8_2.x.next = self.fm7_2.q.val();
        self.ms8_2.next = bit_cast::<9, 6>(self.la8_2.msb.val());
        self.lks8_2.next = self.fexp7_2.q.val() + self.ms8_2.val();
        self.lk8_2.d.next = self.lks8_2.val() ^ self.kflip_9.val();
        self.nm8_2.d.next = self.la8_2.nm.val();
        self.nz8_2.d.next = self.fm7_2.q.val().any();
        self.fm8_2.d.next = self.fm7_2.q.val();
        self.fexp8_2.d.next = self.fexp7_2.q.val();
        self.la8_3.x.next = self.fm7_3.q.val();
        self.ms8_3.next = bit_cast::<9, 6>(self.la8_3.msb.val());
        self.lks8_3.next = self.fexp7_3.q.val() + self.ms8_3.val();
        self.lk8_3.d.next = self.lks8_3.val() ^ self.kflip_9.val();
        self.nm8_3.d.next = self.la8_3.nm.val();
        self.nz8_3.d.next = self.fm7_3.q.val().any();
        self.fm8_3.d.next = self.fm7_3.q.val();
        self.fexp8_3.d.next = self.fexp7_3.q.val();
        self.m8.d.next = self.m7.q.val();
        self.e8.d.next = self.e7.q.val();
        self.v8.d.next = self.v7.q.val();
        // Stage 9: the largest (the first of equals), in the golden fold's order.
        self.al0.next = self.lk8_0.q.val();
        self.anm0.next = self.nm8_0.q.val();
        self.anz0.next = self.nz8_0.q.val();
        self.am0.next = self.fm8_0.q.val();
        self.ae0.next = self.fexp8_0.q.val();
        self.al1.next = self.al0.val();
        self.anm1.next = self.anm0.val();
        self.anz1.next = self.anz0.val();
        self.am1.next = self.am0.val();
        self.ae1.next = self.ae0.val();
        if self.nz8_1.q.val() & (!self.anz0.val() | (self.lk8_1.q.val() > self.al0.val()) | ((self.lk8_1.q.val() == self.al0.val()) & (self.nm8_1.q.val() > self.anm0.val()))) {
            self.al1.next = self.lk8_1.q.val();
            self.anm1.next = self.nm8_1.q.val();
            self.anz1.next = self.nz8_1.q.val();
            self.am1.next = self.fm8_1.q.val();
            self.ae1.next = self.fexp8_1.q.val();
        }
        self.al2.next = self.al1.val();
        self.anm2.next = self.anm1.val();
        self.anz2.next = self.anz1.val();
        self.am2.next = self.am1.val();
        self.ae2.next = self.ae1.val();
        if self.nz8_2.q.val() & (!self.anz1.val() | (self.lk8_2.q.val() > self.al1.val()) | ((self.lk8_2.q.val() == self.al1.val()) & (self.nm8_2.q.val() > self.anm1.val()))) {
            self.al2.next = self.lk8_2.q.val();
            self.anm2.next = self.nm8_2.q.val();
            self.anz2.next = self.nz8_2.q.val();
            self.am2.next = self.fm8_2.q.val();
            self.ae2.next = self.fexp8_2.q.val();
        }
        self.al3.next = self.al2.val();
        self.anm3.next = self.anm2.val();
        self.anz3.next = self.anz2.val();
        self.am3.next = self.am2.val();
        self.ae3.next = self.ae2.val();
        if self.nz8_3.q.val() & (!self.anz2.val() | (self.lk8_3.q.val() > self.al2.val()) | ((self.lk8_3.q.val() == self.al2.val()) & (self.nm8_3.q.val() > self.anm2.val()))) {
            self.al3.next = self.lk8_3.q.val();
            self.anm3.next = self.nm8_3.q.val();
            self.anz3.next = self.nz8_3.q.val();
            self.am3.next = self.fm8_3.q.val();
            self.ae3.next = self.fexp8_3.q.val();
        }
        self.rm9.d.next = self.am3.val();
        self.rexp9.d.next = self.ae3.val();
        self.m9.d.next = self.m8.q.val();
        self.e9.d.next = self.e8.q.val();
        self.v9.d.next = self.v8.q.val();
        // Stage 10: times 1/Q's top 18 bits.
        self.mul_r.a.next = self.rm9.q.val();
        self.mul_r.b.next = self.m9.q.val().get_bits::<18>(7);
        self.pr10.d.next = self.mul_r.p.val();
        self.pexp10.d.next = self.rexp9.q.val() + self.k7_9.val();
        self.e10.d.next = self.e9.q.val();
        self.v10.d.next = self.v9.q.val();
        // Stage 11: its 18-bit mantissa and the exponent E2 of rho = mant 2^E2 (16 fraction bits).
        self.n11.mag.next = self.pr10.q.val();
        self.sm11.d.next = self.n11.mant.val();
        self.t11a.next = bit_cast::<9, 6>(self.n11.drop.val());
        self.t11b.next = self.t11a.val() + self.pexp10.q.val();
        self.e11.next = bit_cast::<9, 6>(self.e10.q.val());
        self.t11c.next = self.t11b.val() - self.e11.val();
        self.e2_11.d.next = self.t11c.val() - self.k24_9.val();
        self.v11.d.next = self.v10.q.val();
        // Stage 12: rho rounded to an integer, its leading one and four bits below: the level of detail.
        self.c21.next = 0.into();
        if self.e2_11.q.val() == self.km1_9.val() {
            self.c21.next = self.k4_21.val();
        }
        self.m21.next = bit_cast::<21, 18>(self.sm11.q.val()) << self.k2_5.val();
        self.mr4.next = self.m21.val() + self.c21.val();
        self.la12.x.next = self.mr4.val();
        self.ms12.next = bit_cast::<9, 6>(self.la12.msb.val());
        self.lt12.next = self.ms12.val() + self.e2_11.q.val();
        self.l12.next = self.lt12.val() - self.k2_9.val();
        self.lm12.next = self.l12.val() - self.k16_9.val();
        self.hi12.next = bit_cast::<8, 4>(self.lm12.val().get_bits::<4>(0)) << self.k4_8.val();
        self.fr12.next = bit_cast::<8, 4>(self.la12.nm.val().get_bits::<4>(16));
        self.lod12.d.next = 0.into();
        if self.v11.q.val() & ((self.e2_11.q.val() ^ self.kflip_9.val()) >= self.kfm1_9.val()) & self.mr4.val().any() & ((self.l12.val() ^ self.kflip_9.val()) >= self.kf16_9.val()) {
            self.lod12.d.next = self.hi12.val() | self.fr12.val();
            if self.lm12.val() >= self.k10_9.val() {
                self.lod12.d.next = self.k160_8.val();
            }
        }
        self.v12.d.next = self.v11.q.val();
        self.valid_out.next = self.v12.q.val();
        self.lod.next = self.lod12.q.val();
    }
}

/// Verilog of the level-of-detail unit (module `tex_lod`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexLod::default();
    uut.connect_all();
    crate::common::verilog_named(&uut, "tex_lod")
}
