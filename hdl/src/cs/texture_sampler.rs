//! `texture_sampler`: the Color Shader's texture unit from a pixel's (s, t) and level of detail to its
//! MODULATEd colour (issue 17, item 4): the level chosen from the level of detail, the address unit
//! ([`TexelAddress`]), four external texture banks (read latency 1) and the texel filter
//! ([`Bilinear`]), then trilinear's blend of two levels and MODULATE ([`Modulate`]). `golden::texture::Texture::
//! sample` followed by `golden::texture::modulate` is the reference. Nearest and bilinear take one
//! pixel per clock; a trilinear pixel between two levels takes two (its two footprints go through the
//! same address unit and filter one after the other: `ready` is low in the first), one on a whole level
//! or at the last level. A pixel with `textured` low (the CS's background) reads no texel and leaves with
//! its colour unchanged (MODULATE with white), after the same latency. Not yet instantiated in the CS (the per-pixel reciprocal that makes s, t and
//! the level of detail comes next; docs/texture.md).
//!
//! ```text
//!  valid_in/ready, s, t, lod, colour
//!    | level L = min(lod >> 4, last); a trilinear pixel with lod's fraction f != 0 and L < last
//!    | issues L, then L + 1 (ready low in between)
//!    v
//!  [ texel_address ] --tex_rd, tex_addr0..3--> banks --tex_data0..3 (1 cycle later)--> route
//!    (3)                                                                                 v
//!                                                  [ texel_filter's Bilinear: the texel ] (2)
//!                                                                                        v
//!          blend: second of a pair with the texel before it: (a (16 - f) + b f + 8) >> 4; others as they are (1)
//!                                                                                        v
//!                                          MODULATE with the pixel's colour --> valid_out, rgb_out (1)
//! ```
//!
//! A pixel's colour leaves [`TEXTURE_SAMPLER_LATENCY`] cycles after the cycle it was accepted in. The
//! level table (each level's first word, `golden::texbank::layout`) is written by the host through
//! `base_we`/`base_sel`/`base_data`; `w0_log2`, `h0_log2`, `last_level`, `filter` and `clamp` are the
//! texture's settings, held for the frame.

use crate::common::MulLogicU;
use crate::cs::texel_address::{TexelAddress, ADDR_BITS};
use crate::cs::modulate::Modulate;
use crate::cs::texel_filter::Bilinear;
use rust_hdl::prelude::*;

/// Cycles from the cycle a pixel is accepted to its `rgb_out`.
pub const TEXTURE_SAMPLER_LATENCY: u64 = 8;
/// Levels in the table (1024 down to 1).
pub const LEVELS: usize = 11; // written as 11 in `update` (hdl_gen knows no constants)
/// Cycles from an issue to the bilinear blend's output: address 3, bank read 1, blend 2 (the tag
/// delay lines; `update` writes 6 and 5 = TO_FILTER_OUT - 1 as literals, since hdl_gen knows no
/// constants).
const TO_FILTER_OUT: usize = 6;

#[derive(LogicBlock)]
pub struct TextureSampler {
    pub clock: Signal<In, Clock>,
    // Pixel stream (valid/ready).
    pub valid_in: Signal<In, Bit>,
    pub ready: Signal<Out, Bit>,
    pub s: Signal<In, Bits<32>>,
    pub t: Signal<In, Bits<32>>,
    /// Level of detail, Q4.4.
    pub lod: Signal<In, Bits<8>>,
    pub colour: Signal<In, Bits<24>>,
    /// Low: the pixel passes untextured (the CS's background): no footprint, `colour` out after the
    /// same latency (MODULATE with a white texel).
    pub textured: Signal<In, Bit>,
    // The texture's settings.
    pub w0_log2: Signal<In, Bits<4>>,
    pub h0_log2: Signal<In, Bits<4>>,
    pub last_level: Signal<In, Bits<4>>,
    /// 0 nearest, 1 bilinear, 2 trilinear.
    pub filter: Signal<In, Bits<2>>,
    pub clamp: Signal<In, Bit>,
    // Level table write port.
    pub base_we: Signal<In, Bit>,
    pub base_sel: Signal<In, Bits<4>>,
    pub base_data: Signal<In, Bits<ADDR_BITS>>,
    // The four texture banks: read enable and address, data one cycle later.
    pub tex_rd: Signal<Out, Bits<4>>,
    pub tex_addr0: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr1: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr2: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr3: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_data0: Signal<In, Bits<24>>,
    pub tex_data1: Signal<In, Bits<24>>,
    pub tex_data2: Signal<In, Bits<24>>,
    pub tex_data3: Signal<In, Bits<24>>,
    // Result.
    pub valid_out: Signal<Out, Bit>,
    pub rgb_out: Signal<Out, Bits<24>>,

    addr: TexelAddress,
    filt: Bilinear,
    bases: [DFF<Bits<ADDR_BITS>>; LEVELS],
    base_onehot: Signal<Local, Bits<16>>,
    // Issue.
    pending: DFF<Bit>,
    lvl_raw: Signal<Local, Bits<4>>,
    lod_frac: Signal<Local, Bits<4>>,
    lvl: Signal<Local, Bits<4>>,
    pair: Signal<Local, Bit>,
    issue_lvl: Signal<Local, Bits<4>>,
    issue_onehot: Signal<Local, Bits<16>>,
    w_sub: Signal<Local, Bits<4>>,
    h_sub: Signal<Local, Bits<4>>,
    accept: Signal<Local, Bit>,
    first: Signal<Local, Bit>,
    // Tags alongside the datapath, one per cycle to the filter's output.
    tag_out: [DFF<Bit>; TO_FILTER_OUT],
    tag_second: [DFF<Bit>; TO_FILTER_OUT],
    tag_f: [DFF<Bits<4>>; TO_FILTER_OUT],
    tag_colour: [DFF<Bits<24>>; TO_FILTER_OUT],
    tag_white: [DFF<Bit>; TO_FILTER_OUT],
    // Bank data to the filter's slots, with the footprint delayed by the read.
    route_q: DFF<Bits<8>>,
    fx_q: DFF<Bits<8>>,
    fy_q: DFF<Bits<8>>,
    valid_q: DFF<Bit>,
    slot_bank: [Signal<Local, Bits<2>>; 4],
    slot_data: [Signal<Local, Bits<24>>; 4],
    // Trilinear blend.
    first_texel: DFF<Bits<24>>,
    mb: [MulLogicU<8, 5, 13>; 6],
    wa: Signal<Local, Bits<5>>,
    wb: Signal<Local, Bits<5>>,
    b_sum: [Signal<Local, Bits<13>>; 3],
    b_round: [Signal<Local, Bits<13>>; 3],
    b_shift: [Signal<Local, Bits<13>>; 3],
    b_chan: [Signal<Local, Bits<8>>; 3],
    texel_q: [DFF<Bits<8>>; 3],
    colour_q: DFF<Bits<24>>,
    blend_valid: DFF<Bit>,
    texel_parts: [Signal<Local, Bits<24>>; 3],
    texel_packed: Signal<Local, Bits<24>>,
    modulate: Modulate,
    k1_16: Constant<Bits<16>>,
    k255_8: Constant<Bits<8>>,
    k2_2: Constant<Bits<2>>,
    k0_2: Constant<Bits<2>>,
    k1_4: Constant<Bits<4>>,
    k16_5: Constant<Bits<5>>,
    k8_13: Constant<Bits<13>>,
    k4_13: Constant<Bits<13>>,
}

impl Default for TextureSampler {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            valid_in: Default::default(),
            ready: Default::default(),
            s: Default::default(),
            t: Default::default(),
            lod: Default::default(),
            colour: Default::default(),
            textured: Default::default(),
            w0_log2: Default::default(),
            h0_log2: Default::default(),
            last_level: Default::default(),
            filter: Default::default(),
            clamp: Default::default(),
            base_we: Default::default(),
            base_sel: Default::default(),
            base_data: Default::default(),
            tex_rd: Default::default(),
            tex_addr0: Default::default(),
            tex_addr1: Default::default(),
            tex_addr2: Default::default(),
            tex_addr3: Default::default(),
            tex_data0: Default::default(),
            tex_data1: Default::default(),
            tex_data2: Default::default(),
            tex_data3: Default::default(),
            valid_out: Default::default(),
            rgb_out: Default::default(),
            addr: Default::default(),
            filt: Default::default(),
            bases: Default::default(),
            base_onehot: Default::default(),
            pending: Default::default(),
            lvl_raw: Default::default(),
            lod_frac: Default::default(),
            lvl: Default::default(),
            pair: Default::default(),
            issue_lvl: Default::default(),
            issue_onehot: Default::default(),
            w_sub: Default::default(),
            h_sub: Default::default(),
            accept: Default::default(),
            first: Default::default(),
            tag_out: Default::default(),
            tag_second: Default::default(),
            tag_f: Default::default(),
            tag_colour: Default::default(),
            tag_white: Default::default(),
            route_q: Default::default(),
            fx_q: Default::default(),
            fy_q: Default::default(),
            valid_q: Default::default(),
            slot_bank: Default::default(),
            slot_data: Default::default(),
            first_texel: Default::default(),
            mb: Default::default(),
            wa: Default::default(),
            wb: Default::default(),
            b_sum: Default::default(),
            b_round: Default::default(),
            b_shift: Default::default(),
            b_chan: Default::default(),
            texel_q: Default::default(),
            colour_q: Default::default(),
            blend_valid: Default::default(),
            texel_parts: Default::default(),
            texel_packed: Default::default(),
            modulate: Default::default(),
            k1_16: Constant::new(1u64.into()),
            k255_8: Constant::new(255.into()),
            k2_2: Constant::new(2u64.into()),
            k0_2: Constant::new(0u64.into()),
            k1_4: Constant::new(1u64.into()),
            k16_5: Constant::new(16u64.into()),
            k8_13: Constant::new(8u64.into()),
            k4_13: Constant::new(4u64.into()),
        }
    }
}

impl Logic for TextureSampler {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, pending, route_q, fx_q, fy_q, valid_q, first_texel, colour_q, blend_valid);
        self.addr.clock.next = self.clock.val();
        self.filt.clock.next = self.clock.val();
        for k in 0..11 {
            self.bases[k].clock.next = self.clock.val();
        }
        for k in 0..6 {
            self.tag_out[k].clock.next = self.clock.val();
            self.tag_second[k].clock.next = self.clock.val();
            self.tag_f[k].clock.next = self.clock.val();
            self.tag_colour[k].clock.next = self.clock.val();
            self.tag_white[k].clock.next = self.clock.val();
        }
        for c in 0..3 {
            self.texel_q[c].clock.next = self.clock.val();
        }

        // The level table.
        self.base_onehot.next = self.k1_16.val() << self.base_sel.val();
        for k in 0..11 {
            self.bases[k].d.next = self.bases[k].q.val();
            if self.base_we.val() & self.base_onehot.val().get_bit(k) {
                self.bases[k].d.next = self.base_data.val();
            }
        }

        // Issue: the level, and for a trilinear pixel between two levels the second footprint in the
        // next cycle.
        self.lvl_raw.next = self.lod.val().get_bits::<4>(4);
        self.lod_frac.next = self.lod.val().get_bits::<4>(0);
        self.lvl.next = self.lvl_raw.val();
        if self.lvl_raw.val() > self.last_level.val() {
            self.lvl.next = self.last_level.val();
        }
        self.pair.next = (self.filter.val() == self.k2_2.val()) & self.lod_frac.val().any() & (self.lvl_raw.val() < self.last_level.val()) & self.textured.val();
        self.issue_lvl.next = self.lvl.val();
        if self.pending.q.val() {
            self.issue_lvl.next = self.lvl.val() + self.k1_4.val();
        }
        self.first.next = self.valid_in.val() & self.pair.val() & !self.pending.q.val();
        self.accept.next = self.valid_in.val() & !self.first.val();
        self.ready.next = !self.first.val();
        self.pending.d.next = self.first.val();
        self.w_sub.next = 0.into();
        if self.w0_log2.val() > self.issue_lvl.val() {
            self.w_sub.next = self.w0_log2.val() - self.issue_lvl.val();
        }
        self.h_sub.next = 0.into();
        if self.h0_log2.val() > self.issue_lvl.val() {
            self.h_sub.next = self.h0_log2.val() - self.issue_lvl.val();
        }
        self.issue_onehot.next = self.k1_16.val() << self.issue_lvl.val();
        self.addr.base.next = 0.into();
        for k in 0..11 {
            if self.issue_onehot.val().get_bit(k) {
                self.addr.base.next = self.bases[k].q.val();
            }
        }
        self.addr.valid_in.next = self.valid_in.val() & self.textured.val();
        self.addr.s.next = self.s.val();
        self.addr.t.next = self.t.val();
        self.addr.w_log2.next = self.w_sub.val();
        self.addr.h_log2.next = self.h_sub.val();
        self.addr.bilinear.next = self.filter.val() != self.k0_2.val();
        self.addr.clamp.next = self.clamp.val();

        // Tags: [0] is the issue cycle's, registered.
        self.tag_out[0].d.next = self.accept.val();
        self.tag_second[0].d.next = self.accept.val() & self.pending.q.val();
        self.tag_f[0].d.next = self.lod_frac.val();
        self.tag_colour[0].d.next = self.colour.val();
        self.tag_white[0].d.next = !self.textured.val();
        for k in 1..6 {
            self.tag_out[k].d.next = self.tag_out[k - 1].q.val();
            self.tag_second[k].d.next = self.tag_second[k - 1].q.val();
            self.tag_f[k].d.next = self.tag_f[k - 1].q.val();
            self.tag_colour[k].d.next = self.tag_colour[k - 1].q.val();
            self.tag_white[k].d.next = self.tag_white[k - 1].q.val();
        }

        // The banks.
        self.tex_rd.next = self.addr.rd.val();
        self.tex_addr0.next = self.addr.addr0.val();
        self.tex_addr1.next = self.addr.addr1.val();
        self.tex_addr2.next = self.addr.addr2.val();
        self.tex_addr3.next = self.addr.addr3.val();
        self.route_q.d.next = self.addr.route.val();
        self.fx_q.d.next = self.addr.fx.val();
        self.fy_q.d.next = self.addr.fy.val();
        self.valid_q.d.next = self.addr.valid_out.val();
        self.slot_bank[0].next = self.route_q.q.val().get_bits::<2>(0);
        self.slot_bank[1].next = self.route_q.q.val().get_bits::<2>(2);
        self.slot_bank[2].next = self.route_q.q.val().get_bits::<2>(4);
        self.slot_bank[3].next = self.route_q.q.val().get_bits::<2>(6);
        for k in 0..4 {
            self.slot_data[k].next = self.tex_data0.val();
            if self.slot_bank[k].val().get_bit(1) {
                if self.slot_bank[k].val().get_bit(0) {
                    self.slot_data[k].next = self.tex_data3.val();
                } else {
                    self.slot_data[k].next = self.tex_data2.val();
                }
            } else if self.slot_bank[k].val().get_bit(0) {
                self.slot_data[k].next = self.tex_data1.val();
            }
        }
        self.filt.valid_in.next = self.valid_q.q.val();
        self.filt.t00.next = self.slot_data[0].val();
        self.filt.t10.next = self.slot_data[1].val();
        self.filt.t01.next = self.slot_data[2].val();
        self.filt.t11.next = self.slot_data[3].val();
        self.filt.fx.next = self.fx_q.q.val();
        self.filt.fy.next = self.fy_q.q.val();

        // Trilinear blend: a pair's two footprints leave the filter in consecutive cycles (the
        // second issued in the cycle after the first), so the texel of the cycle before the second
        // is the first level's. The second is blended with it by the level of detail's fraction; any
        // other texel passes (weights 0 and 16).
        self.first_texel.d.next = self.filt.texel_out.val();
        // wb: the filter's texel (the second level of a pair, else the only one); wa: the kept first.
        self.wb.next = self.k16_5.val();
        if self.tag_second[5].q.val() {
            self.wb.next = bit_cast::<5, 4>(self.tag_f[5].q.val());
        }
        self.wa.next = self.k16_5.val() - self.wb.val();
        self.mb[0].a.next = self.first_texel.q.val().get_bits::<8>(16);
        self.mb[1].a.next = self.first_texel.q.val().get_bits::<8>(8);
        self.mb[2].a.next = self.first_texel.q.val().get_bits::<8>(0);
        self.mb[3].a.next = self.filt.texel_out.val().get_bits::<8>(16);
        self.mb[4].a.next = self.filt.texel_out.val().get_bits::<8>(8);
        self.mb[5].a.next = self.filt.texel_out.val().get_bits::<8>(0);
        for c in 0..3 {
            self.mb[c].b.next = self.wa.val();
            self.mb[c + 3].b.next = self.wb.val();
            self.b_sum[c].next = self.mb[c].p.val() + self.mb[c + 3].p.val();
            self.b_round[c].next = self.b_sum[c].val() + self.k8_13.val();
            self.b_shift[c].next = self.b_round[c].val() >> self.k4_13.val();
            self.b_chan[c].next = self.b_shift[c].val().get_bits::<8>(0);
            self.texel_q[c].d.next = 0.into();
            if self.tag_out[5].q.val() {
                self.texel_q[c].d.next = self.b_chan[c].val();
                if self.tag_white[5].q.val() {
                    self.texel_q[c].d.next = self.k255_8.val();
                }
            }
        }
        self.colour_q.d.next = self.tag_colour[5].q.val();
        self.texel_parts[0].next = bit_cast::<24, 8>(self.texel_q[0].q.val()) << 16;
        self.texel_parts[1].next = bit_cast::<24, 8>(self.texel_q[1].q.val()) << 8;
        self.texel_parts[2].next = bit_cast::<24, 8>(self.texel_q[2].q.val());
        self.texel_packed.next = self.texel_parts[0].val() | self.texel_parts[1].val() | self.texel_parts[2].val();
        self.blend_valid.d.next = self.tag_out[5].q.val();

        // MODULATE.
        self.modulate.clock.next = self.clock.val();
        self.modulate.valid_in.next = self.blend_valid.q.val();
        self.modulate.texel.next = self.texel_packed.val();
        self.modulate.colour.next = self.colour_q.q.val();
        self.rgb_out.next = self.modulate.rgb_out.val();
        self.valid_out.next = self.modulate.valid_out.val();
    }
}

/// Verilog of the texture sampler (module `texture_sampler`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TextureSampler::default();
    uut.connect_all();
    crate::cs::verilog_named(&uut, "texture_sampler")
}
