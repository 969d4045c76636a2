//! `color_shader_tex` (top `cs_tex`): the Color Shader with texture mapping (issue 17; seed 000 §III,
//! seed 001 §3: "texture mapping is also applied here"). The untextured CS
//! ([`crate::cs::color_shader`]) and this block share the scan and shading pipeline
//! ([`ScanPipe`]); a frame started with `texture_enable` low is scanned exactly as by `cs`. A textured
//! frame also reads TdbT beside TdbS and, per visible pixel, evaluates the texture planes, takes one
//! reciprocal and forms the level of detail ([`TexCoord`], [`TexLod`]), then samples, filters and
//! MODULATEs the texture with the shaded colour ([`TextureSampler`], four texture banks behind ports).
//! `golden::cycle::color_shader` (its section "Texture") is the reference, cycle for cycle.
//!
//! ```text
//!  issue (credit: 32 pending, 64 textured; trilinear: not two cycles in a row)
//!    | t+1 index, t+2 TdbS and TdbT reads, t+3 records
//!    |-- ScanPipe: flat / Gouraud / Phong colour ------------------ t+26 --> 3 registers --+
//!    |-- visible pixel: tex_coord (14) -> tex_lod (12), gradients wait 14 ------- t+29 -----+
//!    v                                                                                      v
//!  t+29: the texture unit takes the pixel (a held register keeps a trilinear pixel between two
//!        levels for its second cycle); background pixels pass untextured
//!  t+37: MODULATEd colour (+ the SOF, EOL that waited 8 cycles) -> 64-deep FIFO -> video, t+38
//! ```
//!
//! The texture's settings are latched at start; the level table is written while the CS is idle.
//! An untextured frame writes the pipeline's beat into the FIFO at t+26, as `cs` does.

use crate::cs::scan_pipe::ScanPipe;
use crate::cs::tex_coord::TexCoord;
use crate::cs::tex_lod::TexLod;
use crate::cs::texel_address::ADDR_BITS;
use crate::cs::texture_sampler::TextureSampler;
use crate::cs::video_fifo::VideoFifo64;
use crate::cs::{LightVectors, MaterialWord, TdbsRecord, TdbtRecord, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

/// Cycles the planes' gradients wait beside `tex_coord` (its latency).
const GRAD_DELAY: usize = 14;
/// Cycles s and t wait beside `tex_lod` (its latency).
const LOD_DELAY: usize = 12;
/// Cycles the pixel's SOF and EOL wait beside the texture unit (its latency).
const TAG_DELAY: usize = 8;

#[derive(LogicBlock)]
pub struct ColorShaderTex {
    pub clock: Signal<In, Clock>,
    // From the controller
    /// Start a frame (taken when not busy).
    pub start: Signal<In, Bit>,
    /// Screen width in pixels, 1..=1024 (latched at start).
    pub width: Signal<In, Bits<11>>,
    /// Screen height in pixels, 1..=1024 (latched at start).
    pub height: Signal<In, Bits<11>>,
    /// Background colour where the index is 0, packed as `video_tdata` (latched at start).
    pub background: Signal<In, Bits<24>>,
    /// Clear the I-buffer (to 0) and the Z-buffer (to far) behind the scan (latched at start).
    pub clear_behind: Signal<In, Bit>,
    /// Phong: the planes are the normal, lit per pixel (latched at start); else they are R, G, B.
    pub shading_phong: Signal<In, Bit>,
    // From the host (Phong constants; write while not busy)
    /// Load light `light_write_address`'s L and H (a light the scene lacks keeps zero coefficients).
    pub light_write_enable: Signal<In, Bit>,
    pub light_write_address: Signal<In, Bits<2>>,
    pub light_write_data: Signal<In, LightVectors>,
    /// Write word `material_write_slot` of material `material_write_address`: slot 0 = ambient and
    /// log2 of the gloss, slot 1 + l = light l's diffuse and specular coefficients ([`MaterialWord`]).
    pub material_write_enable: Signal<In, Bit>,
    pub material_write_address: Signal<In, Bits<CS_MATERIAL_BITS>>,
    pub material_write_slot: Signal<In, Bits<3>>,
    pub material_write_data: Signal<In, MaterialWord>,
    // To the controller
    /// A frame is being scanned (from the cycle after the start to the cycle its last beat is taken).
    pub busy: Signal<Out, Bit>,
    /// The last start had a size outside 1..=1024 and was refused.
    pub size_error: Signal<Out, Bit>,
    // To / from the I-buffer (synchronous read, latency 1)
    /// Read the I-buffer at `ibuf_read_address` this cycle.
    pub ibuf_read_enable: Signal<Out, Bit>,
    /// Pixel address `y*width + x`.
    pub ibuf_read_address: Signal<Out, Bits<20>>,
    /// The index at the address of the previous cycle.
    pub ibuf_read_data: Signal<In, Bits<16>>,
    // To / from TdbS (synchronous read, latency 1)
    /// Read TdbS at `tdbs_read_address` this cycle.
    pub tdbs_read_enable: Signal<Out, Bit>,
    /// The triangle index.
    pub tdbs_read_address: Signal<Out, Bits<16>>,
    /// The record at the address of the previous cycle.
    pub tdbs_read_data: Signal<In, TdbsRecord>,
    // To / from TdbT (synchronous read, latency 1), textured frames only
    /// Read TdbT at `tdbt_read_address` (the TdbS address, in the same cycle).
    pub tdbt_read_enable: Signal<Out, Bit>,
    pub tdbt_read_address: Signal<Out, Bits<16>>,
    /// The texture planes at the address of the previous cycle.
    pub tdbt_read_data: Signal<In, TdbtRecord>,
    // The texture (settings latched at start; the level table written while not busy)
    /// Texture the frame (latched at start).
    pub texture_enable: Signal<In, Bit>,
    /// Level 0's size 2^w0_log2 x 2^h0_log2, the last level, the filter (0 nearest, 1 bilinear,
    /// 2 trilinear) and clamp-to-edge (else repeat), latched at start.
    pub tex_w0_log2: Signal<In, Bits<4>>,
    pub tex_h0_log2: Signal<In, Bits<4>>,
    pub tex_last_level: Signal<In, Bits<4>>,
    pub tex_filter: Signal<In, Bits<2>>,
    pub tex_clamp: Signal<In, Bit>,
    /// Write level `tex_base_sel`'s first bank word (`golden::texbank::layout`).
    pub tex_base_we: Signal<In, Bit>,
    pub tex_base_sel: Signal<In, Bits<4>>,
    pub tex_base_data: Signal<In, Bits<ADDR_BITS>>,
    // To / from the four texture banks (synchronous read, latency 1)
    /// Bank k reads `tex_addr<k>` when bit k is set.
    pub tex_rd: Signal<Out, Bits<4>>,
    pub tex_addr0: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr1: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr2: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr3: Signal<Out, Bits<ADDR_BITS>>,
    /// Bank k's texel (RGB888, UG934 order) at the address of the previous cycle.
    pub tex_data0: Signal<In, Bits<24>>,
    pub tex_data1: Signal<In, Bits<24>>,
    pub tex_data2: Signal<In, Bits<24>>,
    pub tex_data3: Signal<In, Bits<24>>,
    // To the I-buffer and the Z-buffer (clear-behind write ports)
    /// Write `ibuf_write_data` (0, background) at `ibuf_write_address`.
    pub ibuf_write_enable: Signal<Out, Bit>,
    pub ibuf_write_address: Signal<Out, Bits<20>>,
    pub ibuf_write_data: Signal<Out, Bits<16>>,
    /// Write `zbuf_write_data` (2^24-1, far) at `zbuf_write_address`.
    pub zbuf_write_enable: Signal<Out, Bit>,
    pub zbuf_write_address: Signal<Out, Bits<20>>,
    pub zbuf_write_data: Signal<Out, Bits<24>>,
    // To the display (AXI4-Stream video)
    /// RGB888: R 23:16, B 15:8, G 7:0.
    pub video_tdata: Signal<Out, Bits<24>>,
    pub video_tvalid: Signal<Out, Bit>,
    /// The consumer takes the beat at this edge if `video_tvalid`.
    pub video_tready: Signal<In, Bit>,
    /// Start of frame: the beat is pixel (0, 0).
    pub video_tuser: Signal<Out, Bit>,
    /// End of line: the beat is the last pixel of its row.
    pub video_tlast: Signal<Out, Bit>,

    pipe: ScanPipe,
    coord: TexCoord,
    lod_unit: TexLod,
    sampler: TextureSampler,
    fifo: VideoFifo64,
    /// Pixels issued and not yet taken by the consumer.
    pending: DFF<Bits<7>>,
    /// The last cycle issued a pixel (trilinear spacing).
    issued_last: DFF<Bit>,
    // The frame's texture settings.
    tex_on: DFF<Bit>,
    w0_log2: DFF<Bits<4>>,
    h0_log2: DFF<Bits<4>>,
    last_level: DFF<Bits<4>>,
    filter: DFF<Bits<2>>,
    clamp: DFF<Bit>,
    // The planes' gradients beside tex_coord.
    g_sw_a: [DFF<Signed<40>>; GRAD_DELAY],
    g_sw_b: [DFF<Signed<40>>; GRAD_DELAY],
    g_tw_a: [DFF<Signed<40>>; GRAD_DELAY],
    g_tw_b: [DFF<Signed<40>>; GRAD_DELAY],
    g_q_a: [DFF<Signed<40>>; GRAD_DELAY],
    g_q_b: [DFF<Signed<40>>; GRAD_DELAY],
    /// s and t from tex_coord (t+17) to t+29: {t, s}.
    st: [DFF<Bits<64>>; LOD_DELAY],
    /// The pipeline's beat from t+26 to t+29: {valid, eol, sof, rgb}.
    col: [DFF<Bits<27>>; 3],
    /// A pixel the texture unit did not take (a trilinear pixel between two levels): {valid, textured,
    /// eol, sof, rgb} and its s, t, lod.
    hold: DFF<Bits<28>>,
    hold_s: DFF<Bits<32>>,
    hold_t: DFF<Bits<32>>,
    hold_lod: DFF<Bits<8>>,
    /// {eol, sof} of the pixel the texture unit took j + 1 cycles ago.
    tags: [DFF<Bits<2>>; TAG_DELAY],
    issue: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    trilinear: Signal<Local, Bit>,
    visible: Signal<Local, Bit>,
    beat: Signal<Local, Bits<27>>,
    offer: Signal<Local, Bits<28>>,
    credit_ok: Signal<Local, Bit>,
    o_valid: Signal<Local, Bit>,
    o_tex: Signal<Local, Bit>,
    o_colour: Signal<Local, Bits<24>>,
    o_s: Signal<Local, Bits<32>>,
    o_t: Signal<Local, Bits<32>>,
    o_lod: Signal<Local, Bits<8>>,
    offer_tex: Signal<Local, Bits<28>>,
    hold_tex: Signal<Local, Bits<28>>,
    hold_tags: Signal<Local, Bits<28>>,
    taken: Signal<Local, Bit>,
    tex_tags: Signal<Local, Bits<26>>,
    st_in: Signal<Local, Bits<64>>,
    st_out: Signal<Local, Bits<64>>,
    col_out: Signal<Local, Bits<27>>,
    tag_in: Signal<Local, Bits<2>>,
    tag_out: Signal<Local, Bits<2>>,
    k0_7: Constant<Bits<7>>,
    k1_7: Constant<Bits<7>>,
    k32_7: Constant<Bits<7>>,
    k64_7: Constant<Bits<7>>,
    k0_2: Constant<Bits<2>>,
    k2_2: Constant<Bits<2>>,
    k0_16: Constant<Bits<16>>,
    k0_28: Constant<Bits<28>>,
    kvalid_27: Constant<Bits<27>>,
    kvalid_28: Constant<Bits<28>>,
    ktex_28: Constant<Bits<28>>,
}

impl Default for ColorShaderTex {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            start: Default::default(),
            width: Default::default(),
            height: Default::default(),
            background: Default::default(),
            clear_behind: Default::default(),
            shading_phong: Default::default(),
            light_write_enable: Default::default(),
            light_write_address: Default::default(),
            light_write_data: Default::default(),
            material_write_enable: Default::default(),
            material_write_address: Default::default(),
            material_write_slot: Default::default(),
            material_write_data: Default::default(),
            busy: Default::default(),
            size_error: Default::default(),
            ibuf_read_enable: Default::default(),
            ibuf_read_address: Default::default(),
            ibuf_read_data: Default::default(),
            tdbs_read_enable: Default::default(),
            tdbs_read_address: Default::default(),
            tdbs_read_data: Default::default(),
            tdbt_read_enable: Default::default(),
            tdbt_read_address: Default::default(),
            tdbt_read_data: Default::default(),
            texture_enable: Default::default(),
            tex_w0_log2: Default::default(),
            tex_h0_log2: Default::default(),
            tex_last_level: Default::default(),
            tex_filter: Default::default(),
            tex_clamp: Default::default(),
            tex_base_we: Default::default(),
            tex_base_sel: Default::default(),
            tex_base_data: Default::default(),
            tex_rd: Default::default(),
            tex_addr0: Default::default(),
            tex_addr1: Default::default(),
            tex_addr2: Default::default(),
            tex_addr3: Default::default(),
            tex_data0: Default::default(),
            tex_data1: Default::default(),
            tex_data2: Default::default(),
            tex_data3: Default::default(),
            ibuf_write_enable: Default::default(),
            ibuf_write_address: Default::default(),
            ibuf_write_data: Default::default(),
            zbuf_write_enable: Default::default(),
            zbuf_write_address: Default::default(),
            zbuf_write_data: Default::default(),
            video_tdata: Default::default(),
            video_tvalid: Default::default(),
            video_tready: Default::default(),
            video_tuser: Default::default(),
            video_tlast: Default::default(),
            pipe: Default::default(),
            coord: Default::default(),
            lod_unit: Default::default(),
            sampler: Default::default(),
            fifo: Default::default(),
            pending: Default::default(),
            issued_last: Default::default(),
            tex_on: Default::default(),
            w0_log2: Default::default(),
            h0_log2: Default::default(),
            last_level: Default::default(),
            filter: Default::default(),
            clamp: Default::default(),
            g_sw_a: Default::default(),
            g_sw_b: Default::default(),
            g_tw_a: Default::default(),
            g_tw_b: Default::default(),
            g_q_a: Default::default(),
            g_q_b: Default::default(),
            col: Default::default(),
            hold: Default::default(),
            hold_s: Default::default(),
            hold_t: Default::default(),
            hold_lod: Default::default(),
            tags: Default::default(),
            issue: Default::default(),
            pop: Default::default(),
            trilinear: Default::default(),
            visible: Default::default(),
            beat: Default::default(),
            offer: Default::default(),
            credit_ok: Default::default(),
            o_valid: Default::default(),
            o_tex: Default::default(),
            o_colour: Default::default(),
            o_s: Default::default(),
            o_t: Default::default(),
            o_lod: Default::default(),
            offer_tex: Default::default(),
            hold_tex: Default::default(),
            hold_tags: Default::default(),
            taken: Default::default(),
            tex_tags: Default::default(),
            st: Default::default(),
            st_in: Default::default(),
            st_out: Default::default(),
            col_out: Default::default(),
            tag_in: Default::default(),
            tag_out: Default::default(),
            k0_7: Constant::new(0.into()),
            k1_7: Constant::new(1.into()),
            k32_7: Constant::new(32.into()),
            k64_7: Constant::new(64.into()),
            k0_2: Constant::new(0.into()),
            k2_2: Constant::new(2.into()),
            k0_16: Constant::new(0.into()),
            k0_28: Constant::new(0.into()),
            kvalid_27: Constant::new((1u64 << 26).into()),
            kvalid_28: Constant::new((1u64 << 27).into()),
            ktex_28: Constant::new((1u64 << 26).into()),
        }
    }
}

impl Logic for ColorShaderTex {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, pending, issued_last, tex_on, w0_log2, h0_log2, last_level, filter, clamp, hold, hold_s,
            hold_t, hold_lod
        );
        clock!(self, clock, pipe, coord, lod_unit, sampler, fifo);
        for i in 0..14 {
            self.g_sw_a[i].clock.next = self.clock.val();
            self.g_sw_b[i].clock.next = self.clock.val();
            self.g_tw_a[i].clock.next = self.clock.val();
            self.g_tw_b[i].clock.next = self.clock.val();
            self.g_q_a[i].clock.next = self.clock.val();
            self.g_q_b[i].clock.next = self.clock.val();
        }
        for i in 0..3 {
            self.col[i].clock.next = self.clock.val();
        }
        for i in 0..12 {
            self.st[i].clock.next = self.clock.val();
        }
        for i in 0..8 {
            self.tags[i].clock.next = self.clock.val();
        }

        // Controller and host inputs; a start is passed only while not busy.
        self.busy.next = self.pipe.active.val() | (self.pending.q.val() != self.k0_7.val());
        self.pipe.start.next = self.start.val() & !self.busy.val();
        self.pipe.width.next = self.width.val();
        self.pipe.height.next = self.height.val();
        self.pipe.background.next = self.background.val();
        self.pipe.clear_behind.next = self.clear_behind.val();
        self.pipe.shading_phong.next = self.shading_phong.val();
        self.pipe.light_write_enable.next = self.light_write_enable.val();
        self.pipe.light_write_address.next = self.light_write_address.val();
        self.pipe.light_write_data.next = self.light_write_data.val();
        self.pipe.material_write_enable.next = self.material_write_enable.val();
        self.pipe.material_write_address.next = self.material_write_address.val();
        self.pipe.material_write_slot.next = self.material_write_slot.val();
        self.pipe.material_write_data.next = self.material_write_data.val();
        self.size_error.next = self.pipe.size_error.val();
        // The texture's settings, latched with a start the pipeline takes (a size error's too:
        // that frame never issues).
        if self.start.val() & !self.busy.val() {
            self.tex_on.d.next = self.texture_enable.val();
            self.w0_log2.d.next = self.tex_w0_log2.val();
            self.h0_log2.d.next = self.tex_h0_log2.val();
            self.last_level.d.next = self.tex_last_level.val();
            self.filter.d.next = self.tex_filter.val();
            self.clamp.d.next = self.tex_clamp.val();
        }

        // Credit: 32 pending pixels, 64 in a textured frame; a trilinear frame issues at most every
        // other cycle. A pixel stops pending when taken.
        self.trilinear.next = self.tex_on.q.val() & (self.filter.q.val() == self.k2_2.val());
        // (Computed in a local and passed once: a child input assigned twice in one evaluation glitches,
        // and through the child's combinational output Icarus would re-run this block for ever.)
        self.credit_ok.next = !(self.trilinear.val() & self.issued_last.q.val());
        if self.tex_on.q.val() {
            if self.pending.q.val() == self.k64_7.val() {
                self.credit_ok.next = false;
            }
        } else if self.pending.q.val() == self.k32_7.val() {
            self.credit_ok.next = false;
        }
        self.pipe.issue_ok.next = self.credit_ok.val();
        self.issue.next = self.pipe.ibuf_read_enable.val();
        self.issued_last.d.next = self.issue.val();
        self.pop.next = self.fifo.read_valid.val() & self.video_tready.val();
        if self.issue.val() & !self.pop.val() {
            self.pending.d.next = self.pending.q.val() + self.k1_7.val();
        }
        if !self.issue.val() & self.pop.val() {
            self.pending.d.next = self.pending.q.val() - self.k1_7.val();
        }

        // Memory ports; TdbT is read beside TdbS in a textured frame.
        self.ibuf_read_enable.next = self.pipe.ibuf_read_enable.val();
        self.ibuf_read_address.next = self.pipe.ibuf_read_address.val();
        self.pipe.ibuf_read_data.next = self.ibuf_read_data.val();
        self.tdbs_read_enable.next = self.pipe.tdbs_read_enable.val();
        self.tdbs_read_address.next = self.pipe.tdbs_read_address.val();
        self.pipe.tdbs_read_data.next = self.tdbs_read_data.val();
        self.tdbt_read_enable.next = self.pipe.tdbs_read_enable.val() & self.tex_on.q.val();
        self.tdbt_read_address.next = self.k0_16.val();
        if self.tex_on.q.val() {
            self.tdbt_read_address.next = self.pipe.tdbs_read_address.val();
        }
        self.ibuf_write_enable.next = self.pipe.ibuf_write_enable.val();
        self.ibuf_write_address.next = self.pipe.ibuf_write_address.val();
        self.ibuf_write_data.next = self.pipe.ibuf_write_data.val();
        self.zbuf_write_enable.next = self.pipe.zbuf_write_enable.val();
        self.zbuf_write_address.next = self.pipe.zbuf_write_address.val();
        self.zbuf_write_data.next = self.pipe.zbuf_write_data.val();

        // t+3: a visible pixel of a textured frame enters the coordinate unit with its planes.
        self.visible.next = self.pipe.tap_valid.val() & !self.pipe.tap_bg.val() & self.tex_on.q.val();
        self.coord.valid_in.next = self.visible.val();
        self.coord.x.next = bit_cast::<11, 10>(self.pipe.tap_x.val());
        self.coord.y.next = bit_cast::<11, 10>(self.pipe.tap_y.val());
        self.coord.sw_a.next = signed_cast(self.tdbt_read_data.val().s_a);
        self.coord.sw_b.next = signed_cast(self.tdbt_read_data.val().s_b);
        self.coord.sw_c.next = signed_cast(self.tdbt_read_data.val().s_c);
        self.coord.tw_a.next = signed_cast(self.tdbt_read_data.val().t_a);
        self.coord.tw_b.next = signed_cast(self.tdbt_read_data.val().t_b);
        self.coord.tw_c.next = signed_cast(self.tdbt_read_data.val().t_c);
        self.coord.q_a.next = signed_cast(self.tdbt_read_data.val().q_a);
        self.coord.q_b.next = signed_cast(self.tdbt_read_data.val().q_b);
        self.coord.q_c.next = signed_cast(self.tdbt_read_data.val().q_c);
        self.g_sw_a[0].d.next = signed_cast(self.tdbt_read_data.val().s_a);
        self.g_sw_b[0].d.next = signed_cast(self.tdbt_read_data.val().s_b);
        self.g_tw_a[0].d.next = signed_cast(self.tdbt_read_data.val().t_a);
        self.g_tw_b[0].d.next = signed_cast(self.tdbt_read_data.val().t_b);
        self.g_q_a[0].d.next = signed_cast(self.tdbt_read_data.val().q_a);
        self.g_q_b[0].d.next = signed_cast(self.tdbt_read_data.val().q_b);
        for i in 1..14 {
            self.g_sw_a[i].d.next = self.g_sw_a[i - 1].q.val();
            self.g_sw_b[i].d.next = self.g_sw_b[i - 1].q.val();
            self.g_tw_a[i].d.next = self.g_tw_a[i - 1].q.val();
            self.g_tw_b[i].d.next = self.g_tw_b[i - 1].q.val();
            self.g_q_a[i].d.next = self.g_q_a[i - 1].q.val();
            self.g_q_b[i].d.next = self.g_q_b[i - 1].q.val();
        }
        // t+17: the level of detail, with the gradients that waited.
        self.lod_unit.valid_in.next = self.coord.valid_out.val();
        self.lod_unit.s.next = self.coord.s.val();
        self.lod_unit.t.next = self.coord.t.val();
        self.lod_unit.m.next = self.coord.m.val();
        self.lod_unit.e.next = self.coord.e.val();
        self.lod_unit.w_log2.next = self.w0_log2.q.val();
        self.lod_unit.h_log2.next = self.h0_log2.q.val();
        for i in 13..14 {
            self.lod_unit.sw_a.next = self.g_sw_a[i].q.val();
            self.lod_unit.sw_b.next = self.g_sw_b[i].q.val();
            self.lod_unit.tw_a.next = self.g_tw_a[i].q.val();
            self.lod_unit.tw_b.next = self.g_tw_b[i].q.val();
            self.lod_unit.q_a.next = self.g_q_a[i].q.val();
            self.lod_unit.q_b.next = self.g_q_b[i].q.val();
        }
        // s and t wait beside tex_lod (which passes neither): {t, s}.
        self.st_in.next = (bit_cast::<64, 32>(self.coord.t.val()) << 32) | bit_cast::<64, 32>(self.coord.s.val());
        self.st[0].d.next = self.st_in.val();
        for i in 1..12 {
            self.st[i].d.next = self.st[i - 1].q.val();
        }

        // t+26 .. t+29: the pipeline's beat waits for the coordinates.
        self.beat.next = bit_cast::<27, 26>(self.pipe.beat_data.val());
        if self.pipe.beat_valid.val() {
            self.beat.next = bit_cast::<27, 26>(self.pipe.beat_data.val()) | self.kvalid_27.val();
        }
        self.col[0].d.next = self.beat.val();
        for i in 1..3 {
            self.col[i].d.next = self.col[i - 1].q.val();
        }

        // t+29: the pixel offered to the texture unit: {valid, textured, eol, sof, rgb}, s, t, lod; a
        // pixel it did not take last cycle (held) goes first. The trilinear spacing guarantees that no
        // new pixel arrives then.
        for i in 2..3 {
            self.col_out.next = self.col[i].q.val();
        }
        for i in 11..12 {
            self.st_out.next = self.st[i].q.val();
        }
        self.offer_tex.next = self.k0_28.val();
        if self.lod_unit.valid_out.val() {
            self.offer_tex.next = self.ktex_28.val();
        }
        self.offer.next = self.k0_28.val();
        if self.col_out.val().get_bit(26) {
            self.offer.next = self.kvalid_28.val() | self.offer_tex.val() | bit_cast::<28, 26>(self.col_out.val().get_bits::<26>(0));
        }
        self.o_valid.next = self.offer.val().get_bit(27);
        self.o_tex.next = self.offer.val().get_bit(26);
        self.o_colour.next = self.offer.val().get_bits::<24>(0);
        self.o_s.next = self.st_out.val().get_bits::<32>(0);
        self.o_t.next = self.st_out.val().get_bits::<32>(32);
        self.o_lod.next = self.lod_unit.lod.val();
        self.tag_in.next = self.offer.val().get_bits::<2>(24);
        if self.hold.q.val().get_bit(27) {
            self.o_valid.next = true;
            self.o_tex.next = self.hold.q.val().get_bit(26);
            self.o_colour.next = self.hold.q.val().get_bits::<24>(0);
            self.o_s.next = self.hold_s.q.val();
            self.o_t.next = self.hold_t.q.val();
            self.o_lod.next = self.hold_lod.q.val();
            self.tag_in.next = self.hold.q.val().get_bits::<2>(24);
        }
        // Each of the unit's inputs assigned once (its `ready` depends on them combinationally).
        self.sampler.valid_in.next = self.o_valid.val();
        self.sampler.textured.next = self.o_tex.val();
        self.sampler.colour.next = self.o_colour.val();
        self.sampler.s.next = self.o_s.val();
        self.sampler.t.next = self.o_t.val();
        self.sampler.lod.next = self.o_lod.val();
        self.taken.next = self.o_valid.val() & self.sampler.ready.val();
        self.hold_tex.next = self.k0_28.val();
        if self.o_tex.val() {
            self.hold_tex.next = self.ktex_28.val();
        }
        self.hold_tags.next = bit_cast::<28, 2>(self.tag_in.val()) << 24;
        self.hold.d.next = self.k0_28.val();
        if self.o_valid.val() & !self.sampler.ready.val() {
            self.hold.d.next = self.kvalid_28.val() | self.hold_tex.val() | self.hold_tags.val() | bit_cast::<28, 24>(self.o_colour.val());
            self.hold_s.d.next = self.o_s.val();
            self.hold_t.d.next = self.o_t.val();
            self.hold_lod.d.next = self.o_lod.val();
        }
        self.sampler.w0_log2.next = self.w0_log2.q.val();
        self.sampler.h0_log2.next = self.h0_log2.q.val();
        self.sampler.last_level.next = self.last_level.q.val();
        self.sampler.filter.next = self.filter.q.val();
        self.sampler.clamp.next = self.clamp.q.val();
        self.sampler.base_we.next = self.tex_base_we.val();
        self.sampler.base_sel.next = self.tex_base_sel.val();
        self.sampler.base_data.next = self.tex_base_data.val();
        self.tex_rd.next = self.sampler.tex_rd.val();
        self.tex_addr0.next = self.sampler.tex_addr0.val();
        self.tex_addr1.next = self.sampler.tex_addr1.val();
        self.tex_addr2.next = self.sampler.tex_addr2.val();
        self.tex_addr3.next = self.sampler.tex_addr3.val();
        self.sampler.tex_data0.next = self.tex_data0.val();
        self.sampler.tex_data1.next = self.tex_data1.val();
        self.sampler.tex_data2.next = self.tex_data2.val();
        self.sampler.tex_data3.next = self.tex_data3.val();
        // The SOF and EOL of the pixel taken wait beside the unit.
        self.tags[0].d.next = self.k0_2.val();
        if self.taken.val() {
            self.tags[0].d.next = self.tag_in.val();
        }
        for i in 1..8 {
            self.tags[i].d.next = self.tags[i - 1].q.val();
        }
        for i in 7..8 {
            self.tag_out.next = self.tags[i].q.val();
        }

        // Into the FIFO: the unit's colour (textured frame, t+37) or the pipeline's beat (t+26).
        self.tex_tags.next = bit_cast::<26, 2>(self.tag_out.val()) << 24;
        self.fifo.write.next = self.pipe.beat_valid.val();
        self.fifo.write_data.next = self.pipe.beat_data.val();
        if self.tex_on.q.val() {
            self.fifo.write.next = self.sampler.valid_out.val();
            self.fifo.write_data.next = bit_cast::<26, 24>(self.sampler.rgb_out.val()) | self.tex_tags.val();
        }
        self.fifo.read.next = self.video_tready.val();
        self.video_tvalid.next = self.fifo.read_valid.val();
        self.video_tdata.next = self.fifo.read_data.val().get_bits::<24>(0);
        self.video_tuser.next = self.fifo.read_data.val().get_bit(24);
        self.video_tlast.next = self.fifo.read_data.val().get_bit(25);
    }
}

/// The `cs_tex` top's Verilog.
pub fn verilog() -> Result<String, String> {
    let mut uut = ColorShaderTex::default();
    uut.connect_all();
    crate::common::verilog_named(&uut, "cs_tex")
}
