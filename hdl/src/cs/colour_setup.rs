//! `colour_setup`: planes for a visible triangle's three channels with ONE reciprocal (seed 001 §2.3.2
//! eqs. 6-7: `dR/dx = Ka*[(R2-R1)*dy.. - ...]`, `Ka = 1/det`; the scan's subscripts are garbled, the
//! form used is `golden::format::Plane::setup`), written into TdbS at the triangle's index (seed 000
//! §III-B). Bit-exact with `golden::shade::colour_setup` / `flat_setup`. A pipeline that takes a new
//! command every 4 cycles and writes its record 41 cycles after taking it, whatever the command
//! (flat, Gouraud, Phong, zero area).
//!
//! ```text
//!  cmd (valid/ready, one per 4 cycles)
//!   |   window 1        window 2          windows 3..8         window 9       window 10      11
//!   v   cycles 1-4      5-8               9-32                 33-36          37-40          41
//!  [S1]-> det, 12 numerator products -> [S2] |det| -> 2^s, 3 division steps -> [S3..S8] 4 steps
//!         (4 x 21x21, 14 products)            (leading one)                   each (22 steps)
//!   -> [S9] A, B = sat40(round(n * mant >> s)) (2 x 40x26) -> [S10] C = sat56(v0*2^16 +
//!      round((A*(128-x0) + B*(128-y0)) / 256)) (2 x 40x21) -> [S11] -> tdbs_write (cycle 41)
//! ```
//!
//! Schedule. A command taken in cycle 0 is in window j during cycles 4j-3 ..= 4j, and its data in
//! station j (register arrays: `c_*` the carried fields, `na_*`/`nb_*` the numerators,
//! `rem`/`den`/`quo`/`shift`/`neg`/`zero` the division, `r_a`..`b_c` the planes; each holds only the
//! stations where some later stage reads it, so entry i of an array whose first station is f is
//! station f + i, as each declaration says); station j is loaded from station j-1 at the end of cycle
//! 4(j-1). A value computed in cycle c is written into the
//! station of cycle c+1 (when c ends a window, into the next station as it loads). Commands are at
//! least 4 cycles apart (`cmd.ready` is low for 3 cycles after a command is taken), so every station
//! and multiplier is used by one command at a time. `tok` (bit o-1 set in cycle o of a command) times
//! everything.
//!
//! * Cycles 1-4: the 14 products of det and the six numerators (na = dv10*dy20 - dv20*dy10,
//!   nb = dv20*dx10 - dv10*dx20, in the vertex order as sent) on four 21x21 multipliers, operands and
//!   products registered; each difference two cycles later: det and na_r in 3, nb_r and na_g in 4, nb_g
//!   and na_b in 5, nb_b in 6.
//! * Cycle 5: |det| and its leading one start the division (rem = 2^s, the sign and det == 0 kept).
//!   Swapping vertices 1 and 2 (`golden::raster::canonical_order`) negates det and every numerator
//!   and keeps vertex 0, so the planes use the numerators negated when det < 0 and |det|.
//! * Cycles 6-30: the 25 restoring steps (`golden::format::reciprocal`), one per cycle, three in
//!   station 2, four in each of stations 3-7, two in station 8: mant = quotient, valid from cycle 31.
//! * Cycles 33-35: A and B of R, G, B on two pipelined 40x26 multipliers (`MulPipeS`), their operands
//!   registered in 32-34 and their sums in 34-36 (the blocks and the sum of their partial products in
//!   one cycle were the chipset's critical path, issue 15 item 5); rounded, shifted and saturated
//!   (`plane_round`, two cycles: the shift registered, then the increment and saturation) in 35-36,
//!   36-37 and 37-38. det == 0 (never sent by the host: the RC does not flag
//!   a zero-area triangle visible) gives A = B = 0, so C is the constant vertex-0 value.
//! * Cycles 36-38: A*(128-x0) and B*(128-y0) of R, G, B on two 40x21 multipliers; C two cycles later
//!   (38-40).
//! * Cycle 41: the TdbS write (enable, index, record).
//!
//! A flat command enters with all three vertex values set to its colour and material 0: every
//! numerator is 0, so A = B = 0 and C = colour * 2^16, `flat_setup`'s record.
//!
//! Widths: coordinates are 20-bit (S11.8) and values 16-bit, so every intermediate is bounded for ANY
//! port input: |det| < 2^41 (44-bit divisor), |numerator| < 2^37 (38 bits), |n*mant| < 2^61,
//! |A*(128-x0)| < 2^59: the 64-bit products and sums never wrap. All payload outputs are 0 while their enable is low.

use crate::common::{signed_bit_cast_safe, DivStep45, LeadingOne44, MulPipeS, MulSplitS, StreamIn};
use crate::cs::plane_round::PlaneRound;
use crate::cs::{SetupCommand, TdbsRecord};
use rust_hdl::prelude::*;

/// Cycles from taking a command to its TdbS write.
pub const SETUP_LATENCY: u64 = 41;
/// Cycles between two commands taken back to back.
pub const SETUP_INTERVAL: u64 = 4;

#[derive(LogicBlock)]
pub struct ColourSetup {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Setup commands (valid/ready); `ready` is low in the 3 cycles after a command is taken.
    pub cmd: StreamIn<SetupCommand>,
    // To the TdbS memory (write port; the memory takes the write at the rising edge)
    /// Write the record this cycle.
    pub tdbs_write_enable: Signal<Out, Bit>,
    /// The triangle index.
    pub tdbs_write_address: Signal<Out, Bits<16>>,
    /// The record.
    pub tdbs_write_data: Signal<Out, TdbsRecord>,
    // To the controller
    /// Some command is in progress (from the cycle after it was taken up to its write cycle).
    pub busy: Signal<Out, Bit>,
    tok: DFF<Bits<41>>,
    cmd1: DFF<SetupCommand>,
    det1: DFF<Signed<44>>,
    det2: DFF<Signed<44>>,
    sh_ab1: DFF<Bits<7>>,
    sh_ab2: DFF<Bits<7>>,
    z_ab1: DFF<Bit>,
    z_ab2: DFF<Bit>,
    opab_m: DFF<Signed<26>>,
    cv1: DFF<Signed<16>>,
    cv2: DFF<Signed<16>>,
    /// Stations 1..=11 (`c_index[j - 1]`: station j).
    c_index: [DFF<Bits<16>>; 11],
    /// Stations 1..=11 (`c_material[j - 1]`: station j).
    c_material: [DFF<Bits<16>>; 11],
    /// Stations 1..=10 (`c_x0[j - 1]`: station j).
    c_x0: [DFF<Bits<20>>; 10],
    /// Stations 1..=10 (`c_y0[j - 1]`: station j).
    c_y0: [DFF<Bits<20>>; 10],
    /// Stations 1..=10 (`c_v0r[j - 1]`: station j).
    c_v0r: [DFF<Bits<16>>; 10],
    /// Stations 1..=10 (`c_v0g[j - 1]`: station j).
    c_v0g: [DFF<Bits<16>>; 10],
    /// Stations 1..=10 (`c_v0b[j - 1]`: station j).
    c_v0b: [DFF<Bits<16>>; 10],
    /// Stations 1..=9 (`na_r[j - 1]`: station j).
    na_r: [DFF<Bits<38>>; 9],
    /// Stations 2..=9 (`nb_r[j - 2]`: station j).
    nb_r: [DFF<Bits<38>>; 8],
    /// Stations 2..=9 (`na_g[j - 2]`: station j).
    na_g: [DFF<Bits<38>>; 8],
    /// Stations 2..=9 (`nb_g[j - 2]`: station j).
    nb_g: [DFF<Bits<38>>; 8],
    /// Stations 2..=9 (`na_b[j - 2]`: station j).
    na_b: [DFF<Bits<38>>; 8],
    /// Stations 2..=9 (`nb_b[j - 2]`: station j).
    nb_b: [DFF<Bits<38>>; 8],
    /// Stations 2..=8 (`rem[j - 2]`: station j).
    rem: [DFF<Bits<45>>; 7],
    /// Stations 2..=8 (`den[j - 2]`: station j).
    den: [DFF<Bits<45>>; 7],
    /// Stations 2..=9 (`quo[j - 2]`: station j).
    quo: [DFF<Bits<25>>; 8],
    /// Stations 2..=9 (`shift[j - 2]`: station j).
    shift: [DFF<Bits<6>>; 8],
    /// Stations 2..=9 (`neg[j - 2]`: station j).
    neg: [DFF<Bit>; 8],
    /// Stations 2..=9 (`zero[j - 2]`: station j).
    zero: [DFF<Bit>; 8],
    /// Stations 10..=11 (`r_a[j - 10]`: station j).
    r_a: [DFF<Bits<40>>; 2],
    /// Stations 10..=11 (`r_b[j - 10]`: station j).
    r_b: [DFF<Bits<40>>; 2],
    /// Stations 10..=11 (`r_c[j - 10]`: station j).
    r_c: [DFF<Bits<56>>; 2],
    /// Stations 10..=11 (`g_a[j - 10]`: station j).
    g_a: [DFF<Bits<40>>; 2],
    /// Stations 10..=11 (`g_b[j - 10]`: station j).
    g_b: [DFF<Bits<40>>; 2],
    /// Stations 10..=11 (`g_c[j - 10]`: station j).
    g_c: [DFF<Bits<56>>; 2],
    /// Stations 10..=11 (`b_a[j - 10]`: station j).
    b_a: [DFF<Bits<40>>; 2],
    /// Stations 10..=11 (`b_b[j - 10]`: station j).
    b_b: [DFF<Bits<40>>; 2],
    /// Stations 11..=11 (`b_c[j - 11]`: station j).
    b_c: [DFF<Bits<56>>; 1],
    opn_a: [DFF<Signed<21>>; 4],
    opn_b: [DFF<Signed<21>>; 4],
    pn: [DFF<Signed<42>>; 4],
    opab_n: [DFF<Signed<40>>; 2],
    pab: [DFF<Signed<64>>; 2],
    opc_a: [DFF<Signed<40>>; 2],
    opc_o: [DFF<Signed<21>>; 2],
    pc: [DFF<Signed<64>>; 2],
    lead: LeadingOne44,
    mn: [MulSplitS<21, 21, 42, 3, 3>; 4],
    /// A's and B's products, two MULT18X18D each (the low 8 bits of the mantissa and 5 of the numerator
    /// in logic; four with 5 + 0), and C's, two each (5 + 3; three with 0 + 3): issue 15 item 5, the
    /// chipset on the LFE5U-45F's 72 blocks.
    mab: [MulPipeS<40, 26, 64, 5, 8>; 2],
    mc: [MulSplitS<40, 21, 64, 5, 3>; 2],
    round: [PlaneRound; 2],
    /// One division step per station 2..=8 (`step[k]` steps station k + 2).
    step: [DivStep45; 7],
    ready: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
    fr16: Signal<Local, Bits<16>>,
    fg16: Signal<Local, Bits<16>>,
    fb16: Signal<Local, Bits<16>>,
    sx0: Signal<Local, Signed<20>>,
    sy0: Signal<Local, Signed<20>>,
    sx1: Signal<Local, Signed<20>>,
    sy1: Signal<Local, Signed<20>>,
    sx2: Signal<Local, Signed<20>>,
    sy2: Signal<Local, Signed<20>>,
    s0r: Signal<Local, Signed<16>>,
    s0g: Signal<Local, Signed<16>>,
    s0b: Signal<Local, Signed<16>>,
    s1r: Signal<Local, Signed<16>>,
    s1g: Signal<Local, Signed<16>>,
    s1b: Signal<Local, Signed<16>>,
    s2r: Signal<Local, Signed<16>>,
    s2g: Signal<Local, Signed<16>>,
    s2b: Signal<Local, Signed<16>>,
    dx10: Signal<Local, Signed<21>>,
    dy10: Signal<Local, Signed<21>>,
    dx20: Signal<Local, Signed<21>>,
    dy20: Signal<Local, Signed<21>>,
    dv10r: Signal<Local, Signed<21>>,
    dv20r: Signal<Local, Signed<21>>,
    dv10g: Signal<Local, Signed<21>>,
    dv20g: Signal<Local, Signed<21>>,
    dv10b: Signal<Local, Signed<21>>,
    dv20b: Signal<Local, Signed<21>>,
    d01: Signal<Local, Signed<42>>,
    d23: Signal<Local, Signed<42>>,
    d01u: Signal<Local, Bits<42>>,
    d23u: Signal<Local, Bits<42>>,
    n01: Signal<Local, Bits<38>>,
    n23: Signal<Local, Bits<38>>,
    det_abs: Signal<Local, Signed<44>>,
    det_absu: Signal<Local, Bits<44>>,
    n_a: Signal<Local, Bits<38>>,
    n_b: Signal<Local, Bits<38>>,
    sn_a: Signal<Local, Signed<38>>,
    sn_b: Signal<Local, Signed<38>>,
    wn_a: Signal<Local, Signed<40>>,
    wn_b: Signal<Local, Signed<40>>,
    neg_ab: Signal<Local, Bit>,
    ab_a: Signal<Local, Bits<40>>,
    ab_b: Signal<Local, Bits<40>>,
    cx0: Signal<Local, Bits<20>>,
    cy0: Signal<Local, Bits<20>>,
    cv: Signal<Local, Bits<16>>,
    scx0: Signal<Local, Signed<20>>,
    scy0: Signal<Local, Signed<20>>,
    ox: Signal<Local, Signed<21>>,
    oy: Signal<Local, Signed<21>>,
    cx: Signal<Local, Signed<64>>,
    cx8: Signal<Local, Signed<64>>,
    cxr: Signal<Local, Signed<64>>,
    cx8u: Signal<Local, Bits<64>>,
    cx56: Signal<Local, Bits<56>>,
    scx56: Signal<Local, Signed<56>>,
    v0w: Signal<Local, Signed<64>>,
    v0s: Signal<Local, Bits<64>>,
    csum: Signal<Local, Signed<64>>,
    csumu: Signal<Local, Bits<64>>,
    c_top: Signal<Local, Bits<9>>,
    c56: Signal<Local, Bits<56>>,
    k0_16: Constant<Bits<16>>,
    k1_tok: Constant<Bits<41>>,
    k1_41: Constant<Bits<41>>,
    k0_38: Constant<Bits<38>>,
    k0_25: Constant<Bits<25>>,
    k0_44: Constant<Signed<44>>,
    k0_21: Constant<Signed<21>>,
    k0_40: Constant<Bits<40>>,
    k0_56: Constant<Bits<56>>,
    k0_40s: Constant<Signed<40>>,
    k16_7: Constant<Bits<7>>,
    k128_64: Constant<Signed<64>>,
    k128_21: Constant<Signed<21>>,
    kmin_56: Constant<Bits<56>>,
    kmax_56: Constant<Bits<56>>,
}

impl Default for ColourSetup {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            cmd: Default::default(),
            tdbs_write_enable: Default::default(),
            tdbs_write_address: Default::default(),
            tdbs_write_data: Default::default(),
            busy: Default::default(),
            tok: Default::default(),
            cmd1: Default::default(),
            det1: Default::default(),
            det2: Default::default(),
            sh_ab1: Default::default(),
            sh_ab2: Default::default(),
            z_ab1: Default::default(),
            z_ab2: Default::default(),
            opab_m: Default::default(),
            cv1: Default::default(),
            cv2: Default::default(),
            c_index: Default::default(),
            c_material: Default::default(),
            c_x0: Default::default(),
            c_y0: Default::default(),
            c_v0r: Default::default(),
            c_v0g: Default::default(),
            c_v0b: Default::default(),
            na_r: Default::default(),
            nb_r: Default::default(),
            na_g: Default::default(),
            nb_g: Default::default(),
            na_b: Default::default(),
            nb_b: Default::default(),
            rem: Default::default(),
            den: Default::default(),
            quo: Default::default(),
            shift: Default::default(),
            neg: Default::default(),
            zero: Default::default(),
            r_a: Default::default(),
            r_b: Default::default(),
            r_c: Default::default(),
            g_a: Default::default(),
            g_b: Default::default(),
            g_c: Default::default(),
            b_a: Default::default(),
            b_b: Default::default(),
            b_c: Default::default(),
            opn_a: Default::default(),
            opn_b: Default::default(),
            pn: Default::default(),
            opab_n: Default::default(),
            pab: Default::default(),
            opc_a: Default::default(),
            opc_o: Default::default(),
            pc: Default::default(),
            lead: Default::default(),
            mn: std::array::from_fn(|_| Default::default()),
            mab: std::array::from_fn(|_| Default::default()),
            mc: std::array::from_fn(|_| Default::default()),
            round: std::array::from_fn(|_| Default::default()),
            step: std::array::from_fn(|_| Default::default()),
            ready: Default::default(),
            accept: Default::default(),
            fr16: Default::default(),
            fg16: Default::default(),
            fb16: Default::default(),
            sx0: Default::default(),
            sy0: Default::default(),
            sx1: Default::default(),
            sy1: Default::default(),
            sx2: Default::default(),
            sy2: Default::default(),
            s0r: Default::default(),
            s0g: Default::default(),
            s0b: Default::default(),
            s1r: Default::default(),
            s1g: Default::default(),
            s1b: Default::default(),
            s2r: Default::default(),
            s2g: Default::default(),
            s2b: Default::default(),
            dx10: Default::default(),
            dy10: Default::default(),
            dx20: Default::default(),
            dy20: Default::default(),
            dv10r: Default::default(),
            dv20r: Default::default(),
            dv10g: Default::default(),
            dv20g: Default::default(),
            dv10b: Default::default(),
            dv20b: Default::default(),
            d01: Default::default(),
            d23: Default::default(),
            d01u: Default::default(),
            d23u: Default::default(),
            n01: Default::default(),
            n23: Default::default(),
            det_abs: Default::default(),
            det_absu: Default::default(),
            n_a: Default::default(),
            n_b: Default::default(),
            sn_a: Default::default(),
            sn_b: Default::default(),
            wn_a: Default::default(),
            wn_b: Default::default(),
            neg_ab: Default::default(),
            ab_a: Default::default(),
            ab_b: Default::default(),
            cx0: Default::default(),
            cy0: Default::default(),
            cv: Default::default(),
            scx0: Default::default(),
            scy0: Default::default(),
            ox: Default::default(),
            oy: Default::default(),
            cx: Default::default(),
            cx8: Default::default(),
            cxr: Default::default(),
            cx8u: Default::default(),
            cx56: Default::default(),
            scx56: Default::default(),
            v0w: Default::default(),
            v0s: Default::default(),
            csum: Default::default(),
            csumu: Default::default(),
            c_top: Default::default(),
            c56: Default::default(),
            k0_16: Constant::new(0.into()),
            k1_tok: Constant::new(1.into()),
            k1_41: Constant::new(1.into()),
            k0_38: Constant::new(0.into()),
            k0_25: Constant::new(0.into()),
            k0_44: Constant::new(0.into()),
            k0_21: Constant::new(0.into()),
            k0_40: Constant::new(0.into()),
            k0_56: Constant::new(0.into()),
            k0_40s: Constant::new(0.into()),
            k16_7: Constant::new(16.into()),
            k128_64: Constant::new(128.into()),
            k128_21: Constant::new(128.into()),
            kmin_56: Constant::new((1u64 << 55).into()),
            kmax_56: Constant::new(((1u64 << 55) - 1).into()),
        }
    }
}

impl Logic for ColourSetup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, tok, cmd1, det1, det2, sh_ab1, sh_ab2, z_ab1, z_ab2, opab_m, cv1, cv2);
        for j in 0..11 {
            self.c_index[j].clock.next = self.clock.val();
            self.c_index[j].d.next = self.c_index[j].q.val();
        }
        for j in 0..11 {
            self.c_material[j].clock.next = self.clock.val();
            self.c_material[j].d.next = self.c_material[j].q.val();
        }
        for j in 0..10 {
            self.c_x0[j].clock.next = self.clock.val();
            self.c_x0[j].d.next = self.c_x0[j].q.val();
        }
        for j in 0..10 {
            self.c_y0[j].clock.next = self.clock.val();
            self.c_y0[j].d.next = self.c_y0[j].q.val();
        }
        for j in 0..10 {
            self.c_v0r[j].clock.next = self.clock.val();
            self.c_v0r[j].d.next = self.c_v0r[j].q.val();
        }
        for j in 0..10 {
            self.c_v0g[j].clock.next = self.clock.val();
            self.c_v0g[j].d.next = self.c_v0g[j].q.val();
        }
        for j in 0..10 {
            self.c_v0b[j].clock.next = self.clock.val();
            self.c_v0b[j].d.next = self.c_v0b[j].q.val();
        }
        for j in 0..9 {
            self.na_r[j].clock.next = self.clock.val();
            self.na_r[j].d.next = self.na_r[j].q.val();
        }
        for j in 0..8 {
            self.nb_r[j].clock.next = self.clock.val();
            self.nb_r[j].d.next = self.nb_r[j].q.val();
        }
        for j in 0..8 {
            self.na_g[j].clock.next = self.clock.val();
            self.na_g[j].d.next = self.na_g[j].q.val();
        }
        for j in 0..8 {
            self.nb_g[j].clock.next = self.clock.val();
            self.nb_g[j].d.next = self.nb_g[j].q.val();
        }
        for j in 0..8 {
            self.na_b[j].clock.next = self.clock.val();
            self.na_b[j].d.next = self.na_b[j].q.val();
        }
        for j in 0..8 {
            self.nb_b[j].clock.next = self.clock.val();
            self.nb_b[j].d.next = self.nb_b[j].q.val();
        }
        for j in 0..7 {
            self.rem[j].clock.next = self.clock.val();
            self.rem[j].d.next = self.rem[j].q.val();
        }
        for j in 0..7 {
            self.den[j].clock.next = self.clock.val();
            self.den[j].d.next = self.den[j].q.val();
        }
        for j in 0..8 {
            self.quo[j].clock.next = self.clock.val();
            self.quo[j].d.next = self.quo[j].q.val();
        }
        for j in 0..8 {
            self.shift[j].clock.next = self.clock.val();
            self.shift[j].d.next = self.shift[j].q.val();
        }
        for j in 0..8 {
            self.neg[j].clock.next = self.clock.val();
            self.neg[j].d.next = self.neg[j].q.val();
        }
        for j in 0..8 {
            self.zero[j].clock.next = self.clock.val();
            self.zero[j].d.next = self.zero[j].q.val();
        }
        for j in 0..2 {
            self.r_a[j].clock.next = self.clock.val();
            self.r_a[j].d.next = self.r_a[j].q.val();
        }
        for j in 0..2 {
            self.r_b[j].clock.next = self.clock.val();
            self.r_b[j].d.next = self.r_b[j].q.val();
        }
        for j in 0..2 {
            self.r_c[j].clock.next = self.clock.val();
            self.r_c[j].d.next = self.r_c[j].q.val();
        }
        for j in 0..2 {
            self.g_a[j].clock.next = self.clock.val();
            self.g_a[j].d.next = self.g_a[j].q.val();
        }
        for j in 0..2 {
            self.g_b[j].clock.next = self.clock.val();
            self.g_b[j].d.next = self.g_b[j].q.val();
        }
        for j in 0..2 {
            self.g_c[j].clock.next = self.clock.val();
            self.g_c[j].d.next = self.g_c[j].q.val();
        }
        for j in 0..2 {
            self.b_a[j].clock.next = self.clock.val();
            self.b_a[j].d.next = self.b_a[j].q.val();
        }
        for j in 0..2 {
            self.b_b[j].clock.next = self.clock.val();
            self.b_b[j].d.next = self.b_b[j].q.val();
        }
        for j in 0..1 {
            self.b_c[j].clock.next = self.clock.val();
            self.b_c[j].d.next = self.b_c[j].q.val();
        }
        for u in 0..4 {
            self.opn_a[u].clock.next = self.clock.val();
            self.opn_a[u].d.next = self.opn_a[u].q.val();
        }
        for u in 0..4 {
            self.opn_b[u].clock.next = self.clock.val();
            self.opn_b[u].d.next = self.opn_b[u].q.val();
        }
        for u in 0..4 {
            self.pn[u].clock.next = self.clock.val();
            self.pn[u].d.next = self.pn[u].q.val();
        }
        for u in 0..2 {
            self.opab_n[u].clock.next = self.clock.val();
            self.opab_n[u].d.next = self.opab_n[u].q.val();
        }
        for u in 0..2 {
            self.pab[u].clock.next = self.clock.val();
            self.pab[u].d.next = self.pab[u].q.val();
        }
        for u in 0..2 {
            self.opc_a[u].clock.next = self.clock.val();
            self.opc_a[u].d.next = self.opc_a[u].q.val();
        }
        for u in 0..2 {
            self.opc_o[u].clock.next = self.clock.val();
            self.opc_o[u].d.next = self.opc_o[u].q.val();
        }
        for u in 0..2 {
            self.pc[u].clock.next = self.clock.val();
            self.pc[u].d.next = self.pc[u].q.val();
        }

        // Tokens: bit o-1 of `tok` is set in cycle o of a command (cycle 0: taken).
        self.ready.next = !(self.tok.q.val().get_bit(0) | self.tok.q.val().get_bit(1) | self.tok.q.val().get_bit(2));
        self.accept.next = self.cmd.valid.val() & self.ready.val();
        self.cmd.ready.next = self.ready.val();
        self.tok.d.next = self.tok.q.val() << self.k1_tok.val();
        if self.accept.val() {
            self.tok.d.next = (self.tok.q.val() << self.k1_tok.val()) | self.k1_41.val();
        }
        self.busy.next = self.tok.q.val().any();

        // Station 1: the command; a flat one with its colour at every vertex and material 0.
        self.fr16.next = bit_cast::<16, 8>(self.cmd.data.val().flat_r);
        self.fg16.next = bit_cast::<16, 8>(self.cmd.data.val().flat_g);
        self.fb16.next = bit_cast::<16, 8>(self.cmd.data.val().flat_b);
        if self.accept.val() {
            self.cmd1.d.next = self.cmd.data.val();
            if self.cmd.data.val().flat {
                self.cmd1.d.next.v0r = self.fr16.val();
                self.cmd1.d.next.v1r = self.fr16.val();
                self.cmd1.d.next.v2r = self.fr16.val();
                self.cmd1.d.next.v0g = self.fg16.val();
                self.cmd1.d.next.v1g = self.fg16.val();
                self.cmd1.d.next.v2g = self.fg16.val();
                self.cmd1.d.next.v0b = self.fb16.val();
                self.cmd1.d.next.v1b = self.fb16.val();
                self.cmd1.d.next.v2b = self.fb16.val();
                self.cmd1.d.next.material = self.k0_16.val();
            }
        }
        self.sx0.next = signed_cast(self.cmd1.q.val().x0);
        self.sy0.next = signed_cast(self.cmd1.q.val().y0);
        self.sx1.next = signed_cast(self.cmd1.q.val().x1);
        self.sy1.next = signed_cast(self.cmd1.q.val().y1);
        self.sx2.next = signed_cast(self.cmd1.q.val().x2);
        self.sy2.next = signed_cast(self.cmd1.q.val().y2);
        self.s0r.next = signed_cast(self.cmd1.q.val().v0r);
        self.s0g.next = signed_cast(self.cmd1.q.val().v0g);
        self.s0b.next = signed_cast(self.cmd1.q.val().v0b);
        self.s1r.next = signed_cast(self.cmd1.q.val().v1r);
        self.s1g.next = signed_cast(self.cmd1.q.val().v1g);
        self.s1b.next = signed_cast(self.cmd1.q.val().v1b);
        self.s2r.next = signed_cast(self.cmd1.q.val().v2r);
        self.s2g.next = signed_cast(self.cmd1.q.val().v2g);
        self.s2b.next = signed_cast(self.cmd1.q.val().v2b);
        self.dx10.next = signed_bit_cast_safe::<21, 20>(self.sx1.val()) - signed_bit_cast_safe::<21, 20>(self.sx0.val());
        self.dy10.next = signed_bit_cast_safe::<21, 20>(self.sy1.val()) - signed_bit_cast_safe::<21, 20>(self.sy0.val());
        self.dx20.next = signed_bit_cast_safe::<21, 20>(self.sx2.val()) - signed_bit_cast_safe::<21, 20>(self.sx0.val());
        self.dy20.next = signed_bit_cast_safe::<21, 20>(self.sy2.val()) - signed_bit_cast_safe::<21, 20>(self.sy0.val());
        self.dv10r.next = signed_bit_cast_safe::<21, 16>(self.s1r.val()) - signed_bit_cast_safe::<21, 16>(self.s0r.val());
        self.dv20r.next = signed_bit_cast_safe::<21, 16>(self.s2r.val()) - signed_bit_cast_safe::<21, 16>(self.s0r.val());
        self.dv10g.next = signed_bit_cast_safe::<21, 16>(self.s1g.val()) - signed_bit_cast_safe::<21, 16>(self.s0g.val());
        self.dv20g.next = signed_bit_cast_safe::<21, 16>(self.s2g.val()) - signed_bit_cast_safe::<21, 16>(self.s0g.val());
        self.dv10b.next = signed_bit_cast_safe::<21, 16>(self.s1b.val()) - signed_bit_cast_safe::<21, 16>(self.s0b.val());
        self.dv20b.next = signed_bit_cast_safe::<21, 16>(self.s2b.val()) - signed_bit_cast_safe::<21, 16>(self.s0b.val());
        // The carried fields enter station 1 from the command register in cycle 1.
        if self.tok.q.val().get_bit(0) {
            self.c_index[0].d.next = self.cmd1.q.val().index;
            self.c_material[0].d.next = self.cmd1.q.val().material;
            self.c_x0[0].d.next = self.cmd1.q.val().x0;
            self.c_y0[0].d.next = self.cmd1.q.val().y0;
            self.c_v0r[0].d.next = self.cmd1.q.val().v0r;
            self.c_v0g[0].d.next = self.cmd1.q.val().v0g;
            self.c_v0b[0].d.next = self.cmd1.q.val().v0b;
        }

        // Cycles 1-4: the 14 products of det and the numerators, operands and products registered.
        for u in 0..4 {
            self.opn_a[u].d.next = self.k0_21.val();
            self.opn_b[u].d.next = self.k0_21.val();
        }
        if self.tok.q.val().get_bit(0) {
            self.opn_a[0].d.next = self.dx10.val();
            self.opn_b[0].d.next = self.dy20.val();
            self.opn_a[1].d.next = self.dx20.val();
            self.opn_b[1].d.next = self.dy10.val();
            self.opn_a[2].d.next = self.dv10r.val();
            self.opn_b[2].d.next = self.dy20.val();
            self.opn_a[3].d.next = self.dv20r.val();
            self.opn_b[3].d.next = self.dy10.val();
        }
        if self.tok.q.val().get_bit(1) {
            self.opn_a[0].d.next = self.dv20r.val();
            self.opn_b[0].d.next = self.dx10.val();
            self.opn_a[1].d.next = self.dv10r.val();
            self.opn_b[1].d.next = self.dx20.val();
            self.opn_a[2].d.next = self.dv10g.val();
            self.opn_b[2].d.next = self.dy20.val();
            self.opn_a[3].d.next = self.dv20g.val();
            self.opn_b[3].d.next = self.dy10.val();
        }
        if self.tok.q.val().get_bit(2) {
            self.opn_a[0].d.next = self.dv20g.val();
            self.opn_b[0].d.next = self.dx10.val();
            self.opn_a[1].d.next = self.dv10g.val();
            self.opn_b[1].d.next = self.dx20.val();
            self.opn_a[2].d.next = self.dv10b.val();
            self.opn_b[2].d.next = self.dy20.val();
            self.opn_a[3].d.next = self.dv20b.val();
            self.opn_b[3].d.next = self.dy10.val();
        }
        if self.tok.q.val().get_bit(3) {
            self.opn_a[0].d.next = self.dv20b.val();
            self.opn_b[0].d.next = self.dx10.val();
            self.opn_a[1].d.next = self.dv10b.val();
            self.opn_b[1].d.next = self.dx20.val();
        }
        for u in 0..4 {
            self.mn[u].a.next = self.opn_a[u].q.val();
            self.mn[u].b.next = self.opn_b[u].q.val();
            self.pn[u].d.next = self.mn[u].p.val();
        }
        self.d01.next = self.pn[0].q.val() - self.pn[1].q.val();
        self.d23.next = self.pn[2].q.val() - self.pn[3].q.val();
        self.d01u.next = unsigned_cast(self.d01.val());
        self.d23u.next = unsigned_cast(self.d23.val());
        self.n01.next = self.d01u.val().get_bits::<38>(0);
        self.n23.next = self.d23u.val().get_bits::<38>(0);

        // Station loads: station j from station j-1 at the end of cycle 4(j-1).
        if self.tok.q.val().get_bit(3) {
            self.c_index[1].d.next = self.c_index[0].q.val();
            self.c_material[1].d.next = self.c_material[0].q.val();
            self.c_x0[1].d.next = self.c_x0[0].q.val();
            self.c_y0[1].d.next = self.c_y0[0].q.val();
            self.c_v0r[1].d.next = self.c_v0r[0].q.val();
            self.c_v0g[1].d.next = self.c_v0g[0].q.val();
            self.c_v0b[1].d.next = self.c_v0b[0].q.val();
            self.na_r[1].d.next = self.na_r[0].q.val();
        }
        if self.tok.q.val().get_bit(7) {
            self.c_index[2].d.next = self.c_index[1].q.val();
            self.c_material[2].d.next = self.c_material[1].q.val();
            self.c_x0[2].d.next = self.c_x0[1].q.val();
            self.c_y0[2].d.next = self.c_y0[1].q.val();
            self.c_v0r[2].d.next = self.c_v0r[1].q.val();
            self.c_v0g[2].d.next = self.c_v0g[1].q.val();
            self.c_v0b[2].d.next = self.c_v0b[1].q.val();
            self.na_r[2].d.next = self.na_r[1].q.val();
            self.nb_r[1].d.next = self.nb_r[0].q.val();
            self.na_g[1].d.next = self.na_g[0].q.val();
            self.nb_g[1].d.next = self.nb_g[0].q.val();
            self.na_b[1].d.next = self.na_b[0].q.val();
            self.nb_b[1].d.next = self.nb_b[0].q.val();
            self.den[1].d.next = self.den[0].q.val();
            self.shift[1].d.next = self.shift[0].q.val();
            self.neg[1].d.next = self.neg[0].q.val();
            self.zero[1].d.next = self.zero[0].q.val();
            self.rem[1].d.next = self.step[0].rem_next.val();
            self.quo[1].d.next = self.step[0].quo_next.val();
        }
        if self.tok.q.val().get_bit(11) {
            self.c_index[3].d.next = self.c_index[2].q.val();
            self.c_material[3].d.next = self.c_material[2].q.val();
            self.c_x0[3].d.next = self.c_x0[2].q.val();
            self.c_y0[3].d.next = self.c_y0[2].q.val();
            self.c_v0r[3].d.next = self.c_v0r[2].q.val();
            self.c_v0g[3].d.next = self.c_v0g[2].q.val();
            self.c_v0b[3].d.next = self.c_v0b[2].q.val();
            self.na_r[3].d.next = self.na_r[2].q.val();
            self.nb_r[2].d.next = self.nb_r[1].q.val();
            self.na_g[2].d.next = self.na_g[1].q.val();
            self.nb_g[2].d.next = self.nb_g[1].q.val();
            self.na_b[2].d.next = self.na_b[1].q.val();
            self.nb_b[2].d.next = self.nb_b[1].q.val();
            self.den[2].d.next = self.den[1].q.val();
            self.shift[2].d.next = self.shift[1].q.val();
            self.neg[2].d.next = self.neg[1].q.val();
            self.zero[2].d.next = self.zero[1].q.val();
            self.rem[2].d.next = self.step[1].rem_next.val();
            self.quo[2].d.next = self.step[1].quo_next.val();
        }
        if self.tok.q.val().get_bit(15) {
            self.c_index[4].d.next = self.c_index[3].q.val();
            self.c_material[4].d.next = self.c_material[3].q.val();
            self.c_x0[4].d.next = self.c_x0[3].q.val();
            self.c_y0[4].d.next = self.c_y0[3].q.val();
            self.c_v0r[4].d.next = self.c_v0r[3].q.val();
            self.c_v0g[4].d.next = self.c_v0g[3].q.val();
            self.c_v0b[4].d.next = self.c_v0b[3].q.val();
            self.na_r[4].d.next = self.na_r[3].q.val();
            self.nb_r[3].d.next = self.nb_r[2].q.val();
            self.na_g[3].d.next = self.na_g[2].q.val();
            self.nb_g[3].d.next = self.nb_g[2].q.val();
            self.na_b[3].d.next = self.na_b[2].q.val();
            self.nb_b[3].d.next = self.nb_b[2].q.val();
            self.den[3].d.next = self.den[2].q.val();
            self.shift[3].d.next = self.shift[2].q.val();
            self.neg[3].d.next = self.neg[2].q.val();
            self.zero[3].d.next = self.zero[2].q.val();
            self.rem[3].d.next = self.step[2].rem_next.val();
            self.quo[3].d.next = self.step[2].quo_next.val();
        }
        if self.tok.q.val().get_bit(19) {
            self.c_index[5].d.next = self.c_index[4].q.val();
            self.c_material[5].d.next = self.c_material[4].q.val();
            self.c_x0[5].d.next = self.c_x0[4].q.val();
            self.c_y0[5].d.next = self.c_y0[4].q.val();
            self.c_v0r[5].d.next = self.c_v0r[4].q.val();
            self.c_v0g[5].d.next = self.c_v0g[4].q.val();
            self.c_v0b[5].d.next = self.c_v0b[4].q.val();
            self.na_r[5].d.next = self.na_r[4].q.val();
            self.nb_r[4].d.next = self.nb_r[3].q.val();
            self.na_g[4].d.next = self.na_g[3].q.val();
            self.nb_g[4].d.next = self.nb_g[3].q.val();
            self.na_b[4].d.next = self.na_b[3].q.val();
            self.nb_b[4].d.next = self.nb_b[3].q.val();
            self.den[4].d.next = self.den[3].q.val();
            self.shift[4].d.next = self.shift[3].q.val();
            self.neg[4].d.next = self.neg[3].q.val();
            self.zero[4].d.next = self.zero[3].q.val();
            self.rem[4].d.next = self.step[3].rem_next.val();
            self.quo[4].d.next = self.step[3].quo_next.val();
        }
        if self.tok.q.val().get_bit(23) {
            self.c_index[6].d.next = self.c_index[5].q.val();
            self.c_material[6].d.next = self.c_material[5].q.val();
            self.c_x0[6].d.next = self.c_x0[5].q.val();
            self.c_y0[6].d.next = self.c_y0[5].q.val();
            self.c_v0r[6].d.next = self.c_v0r[5].q.val();
            self.c_v0g[6].d.next = self.c_v0g[5].q.val();
            self.c_v0b[6].d.next = self.c_v0b[5].q.val();
            self.na_r[6].d.next = self.na_r[5].q.val();
            self.nb_r[5].d.next = self.nb_r[4].q.val();
            self.na_g[5].d.next = self.na_g[4].q.val();
            self.nb_g[5].d.next = self.nb_g[4].q.val();
            self.na_b[5].d.next = self.na_b[4].q.val();
            self.nb_b[5].d.next = self.nb_b[4].q.val();
            self.den[5].d.next = self.den[4].q.val();
            self.shift[5].d.next = self.shift[4].q.val();
            self.neg[5].d.next = self.neg[4].q.val();
            self.zero[5].d.next = self.zero[4].q.val();
            self.rem[5].d.next = self.step[4].rem_next.val();
            self.quo[5].d.next = self.step[4].quo_next.val();
        }
        if self.tok.q.val().get_bit(27) {
            self.c_index[7].d.next = self.c_index[6].q.val();
            self.c_material[7].d.next = self.c_material[6].q.val();
            self.c_x0[7].d.next = self.c_x0[6].q.val();
            self.c_y0[7].d.next = self.c_y0[6].q.val();
            self.c_v0r[7].d.next = self.c_v0r[6].q.val();
            self.c_v0g[7].d.next = self.c_v0g[6].q.val();
            self.c_v0b[7].d.next = self.c_v0b[6].q.val();
            self.na_r[7].d.next = self.na_r[6].q.val();
            self.nb_r[6].d.next = self.nb_r[5].q.val();
            self.na_g[6].d.next = self.na_g[5].q.val();
            self.nb_g[6].d.next = self.nb_g[5].q.val();
            self.na_b[6].d.next = self.na_b[5].q.val();
            self.nb_b[6].d.next = self.nb_b[5].q.val();
            self.den[6].d.next = self.den[5].q.val();
            self.shift[6].d.next = self.shift[5].q.val();
            self.neg[6].d.next = self.neg[5].q.val();
            self.zero[6].d.next = self.zero[5].q.val();
            self.rem[6].d.next = self.step[5].rem_next.val();
            self.quo[6].d.next = self.step[5].quo_next.val();
        }
        if self.tok.q.val().get_bit(31) {
            self.c_index[8].d.next = self.c_index[7].q.val();
            self.c_material[8].d.next = self.c_material[7].q.val();
            self.c_x0[8].d.next = self.c_x0[7].q.val();
            self.c_y0[8].d.next = self.c_y0[7].q.val();
            self.c_v0r[8].d.next = self.c_v0r[7].q.val();
            self.c_v0g[8].d.next = self.c_v0g[7].q.val();
            self.c_v0b[8].d.next = self.c_v0b[7].q.val();
            self.na_r[8].d.next = self.na_r[7].q.val();
            self.nb_r[7].d.next = self.nb_r[6].q.val();
            self.na_g[7].d.next = self.na_g[6].q.val();
            self.nb_g[7].d.next = self.nb_g[6].q.val();
            self.na_b[7].d.next = self.na_b[6].q.val();
            self.nb_b[7].d.next = self.nb_b[6].q.val();
            self.shift[7].d.next = self.shift[6].q.val();
            self.neg[7].d.next = self.neg[6].q.val();
            self.zero[7].d.next = self.zero[6].q.val();
            self.quo[7].d.next = self.quo[6].q.val();
        }
        if self.tok.q.val().get_bit(35) {
            self.c_index[9].d.next = self.c_index[8].q.val();
            self.c_material[9].d.next = self.c_material[8].q.val();
            self.c_x0[9].d.next = self.c_x0[8].q.val();
            self.c_y0[9].d.next = self.c_y0[8].q.val();
            self.c_v0r[9].d.next = self.c_v0r[8].q.val();
            self.c_v0g[9].d.next = self.c_v0g[8].q.val();
            self.c_v0b[9].d.next = self.c_v0b[8].q.val();
        }
        if self.tok.q.val().get_bit(39) {
            self.c_index[10].d.next = self.c_index[9].q.val();
            self.c_material[10].d.next = self.c_material[9].q.val();
            self.r_a[1].d.next = self.r_a[0].q.val();
            self.r_b[1].d.next = self.r_b[0].q.val();
            self.r_c[1].d.next = self.r_c[0].q.val();
            self.g_a[1].d.next = self.g_a[0].q.val();
            self.g_b[1].d.next = self.g_b[0].q.val();
            self.g_c[1].d.next = self.g_c[0].q.val();
            self.b_a[1].d.next = self.b_a[0].q.val();
            self.b_b[1].d.next = self.b_b[0].q.val();
        }
        if self.tok.q.val().get_bit(3) {
            self.det2.d.next = self.det1.q.val();
        }
        // The numerators and det into the station of the cycle after (cycles 3-6).
        if self.tok.q.val().get_bit(2) {
            self.det1.d.next = signed_bit_cast_safe::<44, 42>(self.d01.val());
            self.na_r[0].d.next = self.n23.val();
        }
        if self.tok.q.val().get_bit(3) {
            self.nb_r[0].d.next = self.n01.val();
            self.na_g[0].d.next = self.n23.val();
        }
        if self.tok.q.val().get_bit(4) {
            self.nb_g[0].d.next = self.n01.val();
            self.na_b[0].d.next = self.n23.val();
        }
        if self.tok.q.val().get_bit(5) {
            self.nb_b[0].d.next = self.n01.val();
        }

        // Cycle 5: |det| and its leading one start the division.
        self.det_abs.next = self.det2.q.val();
        if self.det2.q.val().get_bit(43) {
            self.det_abs.next = self.k0_44.val() - self.det2.q.val();
        }
        self.det_absu.next = unsigned_cast(self.det_abs.val());
        self.lead.x.next = self.det_absu.val();
        if self.tok.q.val().get_bit(4) {
            self.rem[0].d.next = bit_cast::<45, 44>(self.lead.onehot.val());
            self.den[0].d.next = bit_cast::<45, 44>(self.det_absu.val());
            self.quo[0].d.next = self.k0_25.val();
            self.shift[0].d.next = self.lead.index.val();
            self.neg[0].d.next = self.det2.q.val().get_bit(43);
            self.zero[0].d.next = self.det2.q.val() == self.k0_44.val();
        }
        // The division steps of stations 2..=8: in place in the station's window, into the next
        // station at its end.
        for k in 0..7 {
            self.step[k].rem.next = self.rem[k].q.val();
            self.step[k].den.next = self.den[k].q.val();
            self.step[k].quo.next = self.quo[k].q.val();
        }
        if self.tok.q.val().get_bit(5) | self.tok.q.val().get_bit(6) {
            self.rem[0].d.next = self.step[0].rem_next.val();
            self.quo[0].d.next = self.step[0].quo_next.val();
        }
        if self.tok.q.val().get_bit(8) | self.tok.q.val().get_bit(9) | self.tok.q.val().get_bit(10) {
            self.rem[1].d.next = self.step[1].rem_next.val();
            self.quo[1].d.next = self.step[1].quo_next.val();
        }
        if self.tok.q.val().get_bit(12) | self.tok.q.val().get_bit(13) | self.tok.q.val().get_bit(14) {
            self.rem[2].d.next = self.step[2].rem_next.val();
            self.quo[2].d.next = self.step[2].quo_next.val();
        }
        if self.tok.q.val().get_bit(16) | self.tok.q.val().get_bit(17) | self.tok.q.val().get_bit(18) {
            self.rem[3].d.next = self.step[3].rem_next.val();
            self.quo[3].d.next = self.step[3].quo_next.val();
        }
        if self.tok.q.val().get_bit(20) | self.tok.q.val().get_bit(21) | self.tok.q.val().get_bit(22) {
            self.rem[4].d.next = self.step[4].rem_next.val();
            self.quo[4].d.next = self.step[4].quo_next.val();
        }
        if self.tok.q.val().get_bit(24) | self.tok.q.val().get_bit(25) | self.tok.q.val().get_bit(26) {
            self.rem[5].d.next = self.step[5].rem_next.val();
            self.quo[5].d.next = self.step[5].quo_next.val();
        }
        if self.tok.q.val().get_bit(28) | self.tok.q.val().get_bit(29) {
            self.rem[6].d.next = self.step[6].rem_next.val();
            self.quo[6].d.next = self.step[6].quo_next.val();
        }

        // Cycles 32-34: the operands of A and B of R, G, B: n (negated if det < 0) and mant, into
        // registers; the two pipelined multipliers register their partial products at the ends of
        // 33-35 and sum them into `pab` at the ends of 34-36 (issue 15 item 5: operands, blocks and sum in
        // one cycle were the chipset's critical path). R's operands come from station 8 (cycle 32),
        // G's and B's from station 9.
        self.n_a.next = self.na_r[7].q.val();
        self.n_b.next = self.nb_r[6].q.val();
        self.neg_ab.next = self.neg[6].q.val();
        if self.tok.q.val().get_bit(32) {
            self.n_a.next = self.na_g[7].q.val();
            self.n_b.next = self.nb_g[7].q.val();
            self.neg_ab.next = self.neg[7].q.val();
        }
        if self.tok.q.val().get_bit(33) {
            self.n_a.next = self.na_b[7].q.val();
            self.n_b.next = self.nb_b[7].q.val();
            self.neg_ab.next = self.neg[7].q.val();
        }
        self.sn_a.next = signed_cast(self.n_a.val());
        self.sn_b.next = signed_cast(self.n_b.val());
        self.wn_a.next = signed_bit_cast_safe::<40, 38>(self.sn_a.val());
        self.wn_b.next = signed_bit_cast_safe::<40, 38>(self.sn_b.val());
        if self.neg_ab.val() {
            self.wn_a.next = self.k0_40s.val() - signed_bit_cast_safe::<40, 38>(self.sn_a.val());
            self.wn_b.next = self.k0_40s.val() - signed_bit_cast_safe::<40, 38>(self.sn_b.val());
        }
        self.opab_n[0].d.next = self.wn_a.val();
        self.opab_n[1].d.next = self.wn_b.val();
        // The mantissa (final from cycle 31 in station 8) is loaded once and held for the three.
        if self.tok.q.val().get_bit(31) {
            self.opab_m.d.next = signed_cast(bit_cast::<26, 25>(self.quo[6].q.val()));
        }
        self.sh_ab1.d.next = bit_cast::<7, 6>(self.shift[7].q.val());
        self.z_ab1.d.next = self.zero[7].q.val();
        self.sh_ab2.d.next = self.sh_ab1.q.val();
        self.z_ab2.d.next = self.z_ab1.q.val();
        for u in 0..2 {
            self.mab[u].clock.next = self.clock.val();
            self.mab[u].ce.next = true;
            self.mab[u].a.next = self.opab_n[u].q.val();
            self.mab[u].b.next = self.opab_m.q.val();
            self.pab[u].d.next = self.mab[u].p.val();
            self.round[u].clock.next = self.clock.val();
            self.round[u].p.next = self.pab[u].q.val();
            self.round[u].sh.next = self.sh_ab2.q.val();
            self.round[u].clear.next = self.z_ab2.q.val();
        }
        // The rounds' outputs: R's A and B in cycle 36, G's in 37, B's in 38, each into the station
        // of the cycle after (10) and straight on to the C products' operands.
        self.ab_a.next = self.round[0].out.val();
        self.ab_b.next = self.round[1].out.val();
        if self.tok.q.val().get_bit(35) {
            self.r_a[0].d.next = self.ab_a.val();
            self.r_b[0].d.next = self.ab_b.val();
        }
        if self.tok.q.val().get_bit(36) {
            self.g_a[0].d.next = self.ab_a.val();
            self.g_b[0].d.next = self.ab_b.val();
        }
        if self.tok.q.val().get_bit(37) {
            self.b_a[0].d.next = self.ab_a.val();
            self.b_b[0].d.next = self.ab_b.val();
        }

        // Cycles 36-38: A*(128-x0) and B*(128-y0) of R, G, B, A and B from the rounds; C two cycles
        // later (38-40).
        self.cx0.next = self.c_x0[8].q.val();
        self.cy0.next = self.c_y0[8].q.val();
        self.cv.next = self.c_v0r[8].q.val();
        if self.tok.q.val().get_bit(36) {
            self.cx0.next = self.c_x0[9].q.val();
            self.cy0.next = self.c_y0[9].q.val();
            self.cv.next = self.c_v0g[9].q.val();
        }
        if self.tok.q.val().get_bit(37) {
            self.cx0.next = self.c_x0[9].q.val();
            self.cy0.next = self.c_y0[9].q.val();
            self.cv.next = self.c_v0b[9].q.val();
        }
        self.scx0.next = signed_cast(self.cx0.val());
        self.scy0.next = signed_cast(self.cy0.val());
        self.ox.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(self.scx0.val());
        self.oy.next = self.k128_21.val() - signed_bit_cast_safe::<21, 20>(self.scy0.val());
        self.opc_a[0].d.next = signed_cast(self.ab_a.val());
        self.opc_o[0].d.next = self.ox.val();
        self.opc_a[1].d.next = signed_cast(self.ab_b.val());
        self.opc_o[1].d.next = self.oy.val();
        self.cv1.d.next = signed_cast(self.cv.val());
        self.cv2.d.next = self.cv1.q.val();
        for u in 0..2 {
            self.mc[u].a.next = self.opc_a[u].q.val();
            self.mc[u].b.next = self.opc_o[u].q.val();
            self.pc[u].d.next = self.mc[u].p.val();
        }
        self.cx.next = self.pc[0].q.val() + self.pc[1].q.val();
        self.cx8.next = self.cx.val() + self.k128_64.val();
        self.cx8u.next = unsigned_cast(self.cx8.val());
        self.cx56.next = self.cx8u.val().get_bits::<56>(8);
        self.scx56.next = signed_cast(self.cx56.val());
        self.cxr.next = signed_bit_cast_safe::<64, 56>(self.scx56.val());
        self.v0w.next = signed_bit_cast_safe::<64, 16>(self.cv2.q.val());
        self.v0s.next = unsigned_cast(self.v0w.val()) << self.k16_7.val();
        self.csum.next = signed_cast(self.v0s.val()) + self.cxr.val();
        self.csumu.next = unsigned_cast(self.csum.val());
        self.c_top.next = self.csumu.val().get_bits::<9>(55);
        self.c56.next = self.csumu.val().get_bits::<56>(0);
        if !(self.c_top.val().all() | !self.c_top.val().any()) {
            if self.csumu.val().get_bit(63) {
                self.c56.next = self.kmin_56.val();
            } else {
                self.c56.next = self.kmax_56.val();
            }
        }
        if self.tok.q.val().get_bit(37) {
            self.r_c[0].d.next = self.c56.val();
        }
        if self.tok.q.val().get_bit(38) {
            self.g_c[0].d.next = self.c56.val();
        }
        if self.tok.q.val().get_bit(39) {
            self.b_c[0].d.next = self.c56.val();
        }

        // Cycle 41: the write.
        self.tdbs_write_enable.next = false;
        self.tdbs_write_address.next = self.k0_16.val();
        self.tdbs_write_data.next.r_a = self.k0_40.val();
        self.tdbs_write_data.next.r_b = self.k0_40.val();
        self.tdbs_write_data.next.r_c = self.k0_56.val();
        self.tdbs_write_data.next.g_a = self.k0_40.val();
        self.tdbs_write_data.next.g_b = self.k0_40.val();
        self.tdbs_write_data.next.g_c = self.k0_56.val();
        self.tdbs_write_data.next.b_a = self.k0_40.val();
        self.tdbs_write_data.next.b_b = self.k0_40.val();
        self.tdbs_write_data.next.b_c = self.k0_56.val();
        self.tdbs_write_data.next.material = self.k0_16.val();
        if self.tok.q.val().get_bit(40) {
            self.tdbs_write_enable.next = true;
            self.tdbs_write_address.next = self.c_index[10].q.val();
            self.tdbs_write_data.next.r_a = self.r_a[1].q.val();
            self.tdbs_write_data.next.r_b = self.r_b[1].q.val();
            self.tdbs_write_data.next.r_c = self.r_c[1].q.val();
            self.tdbs_write_data.next.g_a = self.g_a[1].q.val();
            self.tdbs_write_data.next.g_b = self.g_b[1].q.val();
            self.tdbs_write_data.next.g_c = self.g_c[1].q.val();
            self.tdbs_write_data.next.b_a = self.b_a[1].q.val();
            self.tdbs_write_data.next.b_b = self.b_b[1].q.val();
            self.tdbs_write_data.next.b_c = self.b_c[0].q.val();
            self.tdbs_write_data.next.material = self.c_material[10].q.val();
        }
    }
}
