//! `texel_address`: the Color Shader's texture address unit (issue 17, item 4). From a pixel's texture
//! coordinate (s, t), the mipmap level's size and first word, the filter (nearest or bilinear) and the
//! wrap mode it computes the footprint of `golden::texbank::footprint`: a word address and read enable
//! for each of the four interleaved texture banks, the bank each footprint slot takes its texel from
//! (`route`), and the bilinear weights. The four banks are read in the same clock and
//! `texel_filter` blends what they return, so one pixel per clock. Not yet instantiated in the CS (the
//! per-pixel reciprocal that makes s and t comes next; docs/texture.md).
//!
//! ```text
//!  s, t (Q15.16) ----> stage 1: p = (s << w_log2) - half     (half = 2^15 bilinear, 0 nearest)
//!  w_log2, h_log2        x0 = p >> 16 (27 bits), fx = p[15:8] (0 nearest); the same for t
//!  bilinear ---------> stage 2: xa = wrap(x0), xb = wrap(x0 + bilinear)  (repeat: mask; clamp: 0..n-1)
//!  clamp                        the same for y
//!  base -------------> stage 3: slot (dx, dy): bank = x[0] | y[0] << 1,
//!  valid_in                      word = base + (y >> 1) << max(w_log2 - 1, 0) + (x >> 1);
//!                                 each bank takes the word of a slot routed to it
//!                    --> valid_out, rd (4 bits), addr0..addr3, route (2 bits per slot), fx, fy
//! ```
//!
//! Two slots routed to one bank are the same texel (clamping at an edge, or a one-texel dimension),
//! so their words agree. Every output is 0 while `valid_out` is low. Latency 3, no stalls.

use rust_hdl::prelude::*;

/// Cycles from a pixel's inputs to its footprint.
pub const TEXEL_ADDRESS_LATENCY: u64 = 3;
/// Bits of a bank word address (`golden::texbank::TEXEL_ADDR_BITS`).
pub const ADDR_BITS: usize = 20;

#[derive(LogicBlock)]
pub struct TexelAddress {
    pub clock: Signal<In, Clock>,
    pub valid_in: Signal<In, Bit>,
    /// Texture coordinate, two's complement Q15.16 of the texture (65536 = one whole texture).
    pub s: Signal<In, Bits<32>>,
    pub t: Signal<In, Bits<32>>,
    /// The level's size (log2, 0..=10) and its first word in every bank.
    pub w_log2: Signal<In, Bits<4>>,
    pub h_log2: Signal<In, Bits<4>>,
    pub base: Signal<In, Bits<ADDR_BITS>>,
    /// 1: the 2x2 footprint with weights; 0: the one texel under (s, t), weights 0.
    pub bilinear: Signal<In, Bit>,
    /// 1: clamp to the edge; 0: repeat.
    pub clamp: Signal<In, Bit>,
    pub valid_out: Signal<Out, Bit>,
    /// Read enable of bank k at bit k.
    pub rd: Signal<Out, Bits<4>>,
    pub addr0: Signal<Out, Bits<ADDR_BITS>>,
    pub addr1: Signal<Out, Bits<ADDR_BITS>>,
    pub addr2: Signal<Out, Bits<ADDR_BITS>>,
    pub addr3: Signal<Out, Bits<ADDR_BITS>>,
    /// The bank of slot k (t00, t10, t01, t11) at bits 2k+1:2k.
    pub route: Signal<Out, Bits<8>>,
    pub fx: Signal<Out, Bits<8>>,
    pub fy: Signal<Out, Bits<8>>,

    // Stage 1.
    s_lo: Signal<Local, Bits<43>>,
    s_ext: Signal<Local, Bits<43>>,
    s_sh: Signal<Local, Bits<43>>,
    t_lo: Signal<Local, Bits<43>>,
    t_ext: Signal<Local, Bits<43>>,
    t_sh: Signal<Local, Bits<43>>,
    half: Signal<Local, Bits<43>>,
    px: Signal<Local, Bits<43>>,
    py: Signal<Local, Bits<43>>,
    x0: DFF<Bits<27>>,
    y0: DFF<Bits<27>>,
    fx1: DFF<Bits<8>>,
    fy1: DFF<Bits<8>>,
    w1: DFF<Bits<4>>,
    h1: DFF<Bits<4>>,
    base1: DFF<Bits<ADDR_BITS>>,
    bil1: DFF<Bit>,
    clamp1: DFF<Bit>,
    valid1: DFF<Bit>,
    // Stage 2.
    step: Signal<Local, Bits<27>>,
    x1: Signal<Local, Bits<27>>,
    y1: Signal<Local, Bits<27>>,
    wmax: Signal<Local, Bits<27>>,
    hmax: Signal<Local, Bits<27>>,
    wpow: Signal<Local, Bits<27>>,
    hpow: Signal<Local, Bits<27>>,
    idx: [Signal<Local, Bits<27>>; 4],
    lim: [Signal<Local, Bits<27>>; 4],
    masked: [Signal<Local, Bits<27>>; 4],
    /// The wrapped or clamped [xa, xb, ya, yb].
    wrapped: [DFF<Bits<10>>; 4],
    fx2: DFF<Bits<8>>,
    fy2: DFF<Bits<8>>,
    w2: DFF<Bits<4>>,
    base2: DFF<Bits<ADDR_BITS>>,
    valid2: DFF<Bit>,
    // Stage 3: slot k = (dx, dy) = (k & 1, k >> 1).
    row_shift: Signal<Local, Bits<4>>,
    sx: [Signal<Local, Bits<ADDR_BITS>>; 4],
    sy: [Signal<Local, Bits<ADDR_BITS>>; 4],
    bank_x: [Signal<Local, Bits<2>>; 4],
    bank_y: [Signal<Local, Bits<2>>; 4],
    bank: [Signal<Local, Bits<2>>; 4],
    onehot: [Signal<Local, Bits<4>>; 4],
    row_word: [Signal<Local, Bits<ADDR_BITS>>; 4],
    row_off: [Signal<Local, Bits<ADDR_BITS>>; 4],
    col_word: [Signal<Local, Bits<ADDR_BITS>>; 4],
    word_b: [Signal<Local, Bits<ADDR_BITS>>; 4],
    word: [Signal<Local, Bits<ADDR_BITS>>; 4],
    route_part: [Signal<Local, Bits<8>>; 4],
    addr: [DFF<Bits<ADDR_BITS>>; 4],
    rd_q: DFF<Bits<4>>,
    route_q: DFF<Bits<8>>,
    fx3: DFF<Bits<8>>,
    fy3: DFF<Bits<8>>,
    valid3: DFF<Bit>,
    k_sext_43: Constant<Bits<43>>,
    k_half_43: Constant<Bits<43>>,
    k1_27: Constant<Bits<27>>,
    k1_4: Constant<Bits<4>>,
    k1_2: Constant<Bits<2>>,
    k1_ab: Constant<Bits<ADDR_BITS>>,
}

impl Default for TexelAddress {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            s: Default::default(),
            t: Default::default(),
            w_log2: Default::default(),
            h_log2: Default::default(),
            base: Default::default(),
            bilinear: Default::default(),
            clamp: Default::default(),
            valid_out: Default::default(),
            rd: Default::default(),
            addr0: Default::default(),
            addr1: Default::default(),
            addr2: Default::default(),
            addr3: Default::default(),
            route: Default::default(),
            fx: Default::default(),
            fy: Default::default(),
            s_lo: Default::default(),
            s_ext: Default::default(),
            s_sh: Default::default(),
            t_lo: Default::default(),
            t_ext: Default::default(),
            t_sh: Default::default(),
            half: Default::default(),
            px: Default::default(),
            py: Default::default(),
            x0: Default::default(),
            y0: Default::default(),
            fx1: Default::default(),
            fy1: Default::default(),
            w1: Default::default(),
            h1: Default::default(),
            base1: Default::default(),
            bil1: Default::default(),
            clamp1: Default::default(),
            valid1: Default::default(),
            step: Default::default(),
            x1: Default::default(),
            y1: Default::default(),
            wmax: Default::default(),
            hmax: Default::default(),
            wpow: Default::default(),
            hpow: Default::default(),
            idx: Default::default(),
            lim: Default::default(),
            masked: Default::default(),
            wrapped: Default::default(),
            fx2: Default::default(),
            fy2: Default::default(),
            w2: Default::default(),
            base2: Default::default(),
            valid2: Default::default(),
            row_shift: Default::default(),
            sx: Default::default(),
            sy: Default::default(),
            bank_x: Default::default(),
            bank_y: Default::default(),
            bank: Default::default(),
            onehot: Default::default(),
            row_word: Default::default(),
            row_off: Default::default(),
            col_word: Default::default(),
            word_b: Default::default(),
            word: Default::default(),
            route_part: Default::default(),
            addr: Default::default(),
            rd_q: Default::default(),
            route_q: Default::default(),
            fx3: Default::default(),
            fy3: Default::default(),
            valid3: Default::default(),
            k_sext_43: Constant::new((((1u64 << 43) - 1) ^ ((1u64 << 32) - 1)).into()),
            k_half_43: Constant::new((1u64 << 15).into()),
            k1_27: Constant::new(1u64.into()),
            k1_4: Constant::new(1u64.into()),
            k1_2: Constant::new(1u64.into()),
            k1_ab: Constant::new(1u64.into()),
        }
    }
}

impl Logic for TexelAddress {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, x0, y0, fx1, fy1, w1, h1, base1, bil1, clamp1, valid1, fx2, fy2, w2, base2, valid2, rd_q, route_q, fx3, fy3, valid3);
        for k in 0..4 {
            self.addr[k].clock.next = self.clock.val();
            self.wrapped[k].clock.next = self.clock.val();
        }
        // Stage 1: sign-extend, scale to the level's texels, step back half a texel for bilinear.
        self.s_lo.next = bit_cast::<43, 32>(self.s.val());
        self.s_ext.next = self.s_lo.val();
        if self.s.val().get_bit(31) {
            self.s_ext.next = self.s_lo.val() | self.k_sext_43.val();
        }
        self.s_sh.next = self.s_ext.val() << self.w_log2.val();
        self.t_lo.next = bit_cast::<43, 32>(self.t.val());
        self.t_ext.next = self.t_lo.val();
        if self.t.val().get_bit(31) {
            self.t_ext.next = self.t_lo.val() | self.k_sext_43.val();
        }
        self.t_sh.next = self.t_ext.val() << self.h_log2.val();
        self.half.next = 0.into();
        if self.bilinear.val() {
            self.half.next = self.k_half_43.val();
        }
        self.px.next = self.s_sh.val() - self.half.val();
        self.py.next = self.t_sh.val() - self.half.val();
        self.x0.d.next = self.px.val().get_bits::<27>(16);
        self.y0.d.next = self.py.val().get_bits::<27>(16);
        self.fx1.d.next = 0.into();
        self.fy1.d.next = 0.into();
        if self.bilinear.val() {
            self.fx1.d.next = self.px.val().get_bits::<8>(8);
            self.fy1.d.next = self.py.val().get_bits::<8>(8);
        }
        self.w1.d.next = self.w_log2.val();
        self.h1.d.next = self.h_log2.val();
        self.base1.d.next = self.base.val();
        self.bil1.d.next = self.bilinear.val();
        self.clamp1.d.next = self.clamp.val();
        self.valid1.d.next = self.valid_in.val();

        // Stage 2: the second column and row, then repeat (mask) or clamp (0..n-1).
        self.step.next = 0.into();
        if self.bil1.q.val() {
            self.step.next = self.k1_27.val();
        }
        self.x1.next = self.x0.q.val() + self.step.val();
        self.y1.next = self.y0.q.val() + self.step.val();
        self.wpow.next = self.k1_27.val() << self.w1.q.val();
        self.hpow.next = self.k1_27.val() << self.h1.q.val();
        self.wmax.next = self.wpow.val() - self.k1_27.val();
        self.hmax.next = self.hpow.val() - self.k1_27.val();
        // Indices [xa, xb, ya, yb] and their dimension's last texel.
        self.idx[0].next = self.x0.q.val();
        self.idx[1].next = self.x1.val();
        self.idx[2].next = self.y0.q.val();
        self.idx[3].next = self.y1.val();
        self.lim[0].next = self.wmax.val();
        self.lim[1].next = self.wmax.val();
        self.lim[2].next = self.hmax.val();
        self.lim[3].next = self.hmax.val();
        for k in 0..4 {
            self.masked[k].next = self.idx[k].val() & self.lim[k].val();
            self.wrapped[k].d.next = self.masked[k].val().get_bits::<10>(0);
            if self.clamp1.q.val() {
                if self.idx[k].val().get_bit(26) {
                    self.wrapped[k].d.next = 0.into();
                } else if self.idx[k].val() > self.lim[k].val() {
                    self.wrapped[k].d.next = self.lim[k].val().get_bits::<10>(0);
                }
            }
        }
        self.fx2.d.next = self.fx1.q.val();
        self.fy2.d.next = self.fy1.q.val();
        self.w2.d.next = self.w1.q.val();
        self.base2.d.next = self.base1.q.val();
        self.valid2.d.next = self.valid1.q.val();

        // Stage 3: each slot's bank and word; each bank the word of a slot routed to it.
        self.row_shift.next = 0.into();
        if self.w2.q.val().any() {
            self.row_shift.next = self.w2.q.val() - self.k1_4.val();
        }
        self.sx[0].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[0].q.val());
        self.sx[1].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[1].q.val());
        self.sx[2].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[0].q.val());
        self.sx[3].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[1].q.val());
        self.sy[0].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[2].q.val());
        self.sy[1].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[2].q.val());
        self.sy[2].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[3].q.val());
        self.sy[3].next = bit_cast::<ADDR_BITS, 10>(self.wrapped[3].q.val());
        for k in 0..4 {
            self.bank_x[k].next = self.sx[k].val().get_bits::<2>(0) & self.k1_2.val();
            self.bank_y[k].next = self.sy[k].val().get_bits::<2>(0) & self.k1_2.val();
            self.bank[k].next = self.bank_x[k].val() | (self.bank_y[k].val() << self.k1_2.val());
            self.onehot[k].next = self.k1_4.val() << self.bank[k].val();
            self.row_word[k].next = self.sy[k].val() >> self.k1_ab.val();
            self.row_off[k].next = self.row_word[k].val() << self.row_shift.val();
            self.col_word[k].next = self.sx[k].val() >> self.k1_ab.val();
            self.word_b[k].next = self.base2.q.val() + self.row_off[k].val();
            self.word[k].next = self.word_b[k].val() + self.col_word[k].val();
        }
        self.route_part[0].next = bit_cast::<8, 2>(self.bank[0].val());
        self.route_part[1].next = bit_cast::<8, 2>(self.bank[1].val()) << 2;
        self.route_part[2].next = bit_cast::<8, 2>(self.bank[2].val()) << 4;
        self.route_part[3].next = bit_cast::<8, 2>(self.bank[3].val()) << 6;
        for b in 0..4 {
            self.addr[b].d.next = 0.into();
            if self.valid2.q.val() {
                if self.onehot[3].val().get_bit(b) {
                    self.addr[b].d.next = self.word[3].val();
                }
                if self.onehot[2].val().get_bit(b) {
                    self.addr[b].d.next = self.word[2].val();
                }
                if self.onehot[1].val().get_bit(b) {
                    self.addr[b].d.next = self.word[1].val();
                }
                if self.onehot[0].val().get_bit(b) {
                    self.addr[b].d.next = self.word[0].val();
                }
            }
        }
        self.rd_q.d.next = 0.into();
        self.route_q.d.next = 0.into();
        self.fx3.d.next = 0.into();
        self.fy3.d.next = 0.into();
        if self.valid2.q.val() {
            self.rd_q.d.next = self.onehot[0].val() | self.onehot[1].val() | self.onehot[2].val() | self.onehot[3].val();
            self.route_q.d.next = self.route_part[0].val() | self.route_part[1].val() | self.route_part[2].val() | self.route_part[3].val();
            self.fx3.d.next = self.fx2.q.val();
            self.fy3.d.next = self.fy2.q.val();
        }
        self.valid3.d.next = self.valid2.q.val();

        self.valid_out.next = self.valid3.q.val();
        self.rd.next = self.rd_q.q.val();
        self.addr0.next = self.addr[0].q.val();
        self.addr1.next = self.addr[1].q.val();
        self.addr2.next = self.addr[2].q.val();
        self.addr3.next = self.addr[3].q.val();
        self.route.next = self.route_q.q.val();
        self.fx.next = self.fx3.q.val();
        self.fy.next = self.fy3.q.val();
    }
}

/// Verilog of the texture address unit (module `texel_address`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexelAddress::default();
    uut.connect_all();
    crate::cs::verilog_named(&uut, "texel_address")
}
