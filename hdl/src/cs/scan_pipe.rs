//! `scan_pipe`: the Color Shader's scan and shading pipeline without its output FIFO and credit, so
//! that the untextured CS ([`crate::cs::color_shader::ColorShader`], top `cs`) and the textured one
//! ([`crate::cs::color_shader_tex::ColorShaderTex`], top `cs_tex`) share it. The pipeline, its ports
//! and its timing are described in [`crate::cs::color_shader`]; here:
//! * `start` is taken whenever it is high (the owner passes it only while the CS is not busy);
//! * a pixel is issued in a cycle where the frame is `active` and `issue_ok` is high (the owner's
//!   credit): `ibuf_read_enable` high;
//! * `tap_*`: the pixel whose TdbS record arrives in this cycle (t+3): valid, x, y, background;
//! * `beat_valid`, `beat_data` (RGB888 in 23:0, SOF 24, EOL 25): the pixel's colour at t+26, which
//!   the owner writes into its FIFO at that edge (untextured) or passes to the texture unit.

use crate::common::{signed_bit_cast_safe, FastRAM};
use crate::cs::plane_mul::PlaneMul;
use crate::cs::light_unit::LightUnit;
use crate::cs::normalizer::Normalizer;
use crate::cs::{LightVectors, MaterialWord, TdbsRecord, CS_LIGHTS, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ScanPipe {
    pub clock: Signal<In, Clock>,
    // From the controller
    /// Start a frame (taken whenever high: the owner gates it with its busy).
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
    /// A frame is being issued (from the cycle after the start to the cycle of its last issue).
    pub active: Signal<Out, Bit>,
    /// The owner's credit: a pixel may be issued in this cycle.
    pub issue_ok: Signal<In, Bit>,
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
    // To the I-buffer and the Z-buffer (clear-behind write ports)
    /// Write `ibuf_write_data` (0, background) at `ibuf_write_address`.
    pub ibuf_write_enable: Signal<Out, Bit>,
    pub ibuf_write_address: Signal<Out, Bits<20>>,
    pub ibuf_write_data: Signal<Out, Bits<16>>,
    /// Write `zbuf_write_data` (2^24-1, far) at `zbuf_write_address`.
    pub zbuf_write_enable: Signal<Out, Bit>,
    pub zbuf_write_address: Signal<Out, Bits<20>>,
    pub zbuf_write_data: Signal<Out, Bits<24>>,
    // To the owner
    /// The pixel whose record arrives in this cycle (t+3): valid, position, background (index 0).
    pub tap_valid: Signal<Out, Bit>,
    pub tap_x: Signal<Out, Bits<10>>,
    pub tap_y: Signal<Out, Bits<10>>,
    pub tap_bg: Signal<Out, Bit>,
    /// The colour of the pixel issued 26 cycles ago: RGB888 (UG934 order) in 23:0, SOF 24, EOL 25.
    pub beat_valid: Signal<Out, Bit>,
    pub beat_data: Signal<Out, Bits<26>>,

    normalizer: Normalizer,
    lights: [LightUnit; CS_LIGHTS],
    gloss_ram: FastRAM<Bits<3>, CS_MATERIAL_BITS>,
    ambient_ram: FastRAM<MaterialWord, CS_MATERIAL_BITS>,
    mul_ra: PlaneMul,
    mul_rb: PlaneMul,
    mul_ga: PlaneMul,
    mul_gb: PlaneMul,
    mul_ba: PlaneMul,
    mul_bb: PlaneMul,
    // Frame control
    running: DFF<Bit>,
    size_err: DFF<Bit>,
    last_x: DFF<Bits<10>>,
    last_y: DFF<Bits<10>>,
    bg: DFF<Bits<24>>,
    clear: DFF<Bit>,
    phong: DFF<Bit>,
    x: DFF<Bits<10>>,
    y: DFF<Bits<10>>,
    addr: DFF<Bits<20>>,
    // s1: waiting for the index
    s1_valid: DFF<Bit>,
    s1_x: DFF<Bits<10>>,
    s1_y: DFF<Bits<10>>,
    s1_addr: DFF<Bits<20>>,
    s1_sof: DFF<Bit>,
    s1_eol: DFF<Bit>,
    // s2: TdbS read
    s2_valid: DFF<Bit>,
    s2_x: DFF<Bits<10>>,
    s2_y: DFF<Bits<10>>,
    s2_sof: DFF<Bit>,
    s2_eol: DFF<Bit>,
    s2_idx: DFF<Bits<16>>,
    // s3: record arrives, products
    s3_valid: DFF<Bit>,
    s3_x: DFF<Bits<10>>,
    s3_y: DFF<Bits<10>>,
    s3_sof: DFF<Bit>,
    s3_eol: DFF<Bit>,
    s3_bg: DFF<Bit>,
    // s4: sums
    s4_valid: DFF<Bit>,
    s4_sof: DFF<Bit>,
    s4_eol: DFF<Bit>,
    s4_bg: DFF<Bit>,
    s4_pa_r: DFF<Signed<51>>,
    s4_pb_r: DFF<Signed<51>>,
    s4_c_r: DFF<Signed<56>>,
    s4_pa_g: DFF<Signed<51>>,
    s4_pb_g: DFF<Signed<51>>,
    s4_c_g: DFF<Signed<56>>,
    s4_pa_b: DFF<Signed<51>>,
    s4_pb_b: DFF<Signed<51>>,
    s4_c_b: DFF<Signed<56>>,
    // s5: round, clamp, into the FIFO
    s5_valid: DFF<Bit>,
    s5_sof: DFF<Bit>,
    s5_eol: DFF<Bit>,
    s5_bg: DFF<Bit>,
    s5_sum_r: DFF<Signed<58>>,
    s5_sum_g: DFF<Signed<58>>,
    s5_sum_b: DFF<Signed<58>>,
    // The material of the pixel whose record arrived j + 1 cycles ago (t+4+j).
    mat: [DFF<Bits<CS_MATERIAL_BITS>>; 21],
    // From t+5 to t+26: {eol, sof, bg, valid, rgb (flat / Gouraud)} of the pixel in stage t+6+j.
    tags: [DFF<Bits<28>>; 21],
    // C1: ambient + lights, 22 fraction bits
    acc_r: DFF<Bits<34>>,
    acc_g: DFF<Bits<34>>,
    acc_b: DFF<Bits<34>>,
    // Combinational
    issue: Signal<Local, Bit>,
    at_eol: Signal<Local, Bit>,
    px: Signal<Local, Signed<11>>,
    py: Signal<Local, Signed<11>>,
    sum_r: Signal<Local, Signed<58>>,
    sum_g: Signal<Local, Signed<58>>,
    sum_b: Signal<Local, Signed<58>>,
    ch_r: Signal<Local, Bits<8>>,
    ch_g: Signal<Local, Bits<8>>,
    ch_b: Signal<Local, Bits<8>>,
    rgb: Signal<Local, Bits<24>>,
    hi_r: Signal<Local, Bits<33>>,
    sof_bit: Signal<Local, Bits<26>>,
    eol_bit: Signal<Local, Bits<26>>,
    hi_g: Signal<Local, Bits<33>>,
    hi_b: Signal<Local, Bits<33>>,
    n_r: Signal<Local, Signed<16>>,
    n_g: Signal<Local, Signed<16>>,
    n_b: Signal<Local, Signed<16>>,
    mw3: Signal<Local, Bits<16>>,
    rec_material: Signal<Local, Bits<16>>,
    us_r: Signal<Local, Bits<58>>,
    us_g: Signal<Local, Bits<58>>,
    us_b: Signal<Local, Bits<58>>,
    top_r: Signal<Local, Bits<27>>,
    top_g: Signal<Local, Bits<27>>,
    top_b: Signal<Local, Bits<27>>,
    tag_in: Signal<Local, Bits<28>>,
    g_rgb: Signal<Local, Bits<24>>,
    t_valid: Signal<Local, Bits<28>>,
    t_bg: Signal<Local, Bits<28>>,
    t_sof: Signal<Local, Bits<28>>,
    t_eol: Signal<Local, Bits<28>>,
    tag_out: Signal<Local, Bits<28>>,
    light_sel: Signal<Local, Bits<4>>,
    slot_sel: Signal<Local, Bits<8>>,
    amb_r: Signal<Local, Bits<34>>,
    amb_g: Signal<Local, Bits<34>>,
    amb_b: Signal<Local, Bits<34>>,
    rnd_r: Signal<Local, Bits<34>>,
    rnd_g: Signal<Local, Bits<34>>,
    rnd_b: Signal<Local, Bits<34>>,
    ph_r: Signal<Local, Bits<8>>,
    ph_g: Signal<Local, Bits<8>>,
    ph_b: Signal<Local, Bits<8>>,
    w_ok: Signal<Local, Bit>,
    h_ok: Signal<Local, Bit>,
    w_m1: Signal<Local, Bits<11>>,
    h_m1: Signal<Local, Bits<11>>,
    k1_lsel: Constant<Bits<4>>,
    k1_ssel: Constant<Bits<8>>,
    k0_3: Constant<Bits<3>>,
    k0_27: Constant<Bits<27>>,
    kones_27: Constant<Bits<27>>,
    kmax_16: Constant<Signed<16>>,
    kmin_16: Constant<Signed<16>>,
    khalf_34: Constant<Bits<34>>,
    k255_12: Constant<Bits<12>>,
    k0_28: Constant<Bits<28>>,
    kvalid_28: Constant<Bits<28>>,
    kbg_28: Constant<Bits<28>>,
    ksof_28: Constant<Bits<28>>,
    keol_28: Constant<Bits<28>>,
    k0_10: Constant<Bits<10>>,
    k1_10: Constant<Bits<10>>,
    k0_11: Constant<Bits<11>>,
    k1_11: Constant<Bits<11>>,
    k1024_11: Constant<Bits<11>>,
    k1_20: Constant<Bits<20>>,
    k0_20: Constant<Bits<20>>,
    k0_16: Constant<Bits<16>>,
    k0_24: Constant<Bits<24>>,
    kfar_24: Constant<Bits<24>>,
    khalf_58: Constant<Signed<58>>,
    k255_8: Constant<Bits<8>>,
    k0_8: Constant<Bits<8>>,
    k0_26: Constant<Bits<26>>,
    k_sof_26: Constant<Bits<26>>,
    k_eol_26: Constant<Bits<26>>,
}

impl Default for ScanPipe {
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
            active: Default::default(),
            issue_ok: Default::default(),
            size_error: Default::default(),
            ibuf_read_enable: Default::default(),
            ibuf_read_address: Default::default(),
            ibuf_read_data: Default::default(),
            tdbs_read_enable: Default::default(),
            tdbs_read_address: Default::default(),
            tdbs_read_data: Default::default(),
            ibuf_write_enable: Default::default(),
            ibuf_write_address: Default::default(),
            ibuf_write_data: Default::default(),
            zbuf_write_enable: Default::default(),
            zbuf_write_address: Default::default(),
            zbuf_write_data: Default::default(),
            tap_valid: Default::default(),
            tap_x: Default::default(),
            tap_y: Default::default(),
            tap_bg: Default::default(),
            beat_valid: Default::default(),
            beat_data: Default::default(),
            normalizer: Default::default(),
            lights: Default::default(),
            gloss_ram: Default::default(),
            ambient_ram: Default::default(),
            mul_ra: Default::default(),
            mul_rb: Default::default(),
            mul_ga: Default::default(),
            mul_gb: Default::default(),
            mul_ba: Default::default(),
            mul_bb: Default::default(),
            running: Default::default(),
            size_err: Default::default(),
            last_x: Default::default(),
            last_y: Default::default(),
            bg: Default::default(),
            clear: Default::default(),
            phong: Default::default(),
            x: Default::default(),
            y: Default::default(),
            addr: Default::default(),
            s1_valid: Default::default(),
            s1_x: Default::default(),
            s1_y: Default::default(),
            s1_addr: Default::default(),
            s1_sof: Default::default(),
            s1_eol: Default::default(),
            s2_valid: Default::default(),
            s2_x: Default::default(),
            s2_y: Default::default(),
            s2_sof: Default::default(),
            s2_eol: Default::default(),
            s2_idx: Default::default(),
            s3_valid: Default::default(),
            s3_x: Default::default(),
            s3_y: Default::default(),
            s3_sof: Default::default(),
            s3_eol: Default::default(),
            s3_bg: Default::default(),
            s4_valid: Default::default(),
            s4_sof: Default::default(),
            s4_eol: Default::default(),
            s4_bg: Default::default(),
            s4_pa_r: Default::default(),
            s4_pb_r: Default::default(),
            s4_c_r: Default::default(),
            s4_pa_g: Default::default(),
            s4_pb_g: Default::default(),
            s4_c_g: Default::default(),
            s4_pa_b: Default::default(),
            s4_pb_b: Default::default(),
            s4_c_b: Default::default(),
            s5_valid: Default::default(),
            s5_sof: Default::default(),
            s5_eol: Default::default(),
            s5_bg: Default::default(),
            s5_sum_r: Default::default(),
            s5_sum_g: Default::default(),
            s5_sum_b: Default::default(),
            mat: Default::default(),
            tags: Default::default(),
            acc_r: Default::default(),
            acc_g: Default::default(),
            acc_b: Default::default(),
            issue: Default::default(),
            at_eol: Default::default(),
            px: Default::default(),
            py: Default::default(),
            sum_r: Default::default(),
            sum_g: Default::default(),
            sum_b: Default::default(),
            ch_r: Default::default(),
            ch_g: Default::default(),
            ch_b: Default::default(),
            rgb: Default::default(),
            hi_r: Default::default(),
            sof_bit: Default::default(),
            eol_bit: Default::default(),
            hi_g: Default::default(),
            hi_b: Default::default(),
            n_r: Default::default(),
            n_g: Default::default(),
            n_b: Default::default(),
            mw3: Default::default(),
            rec_material: Default::default(),
            us_r: Default::default(),
            us_g: Default::default(),
            us_b: Default::default(),
            top_r: Default::default(),
            top_g: Default::default(),
            top_b: Default::default(),
            tag_in: Default::default(),
            g_rgb: Default::default(),
            t_valid: Default::default(),
            t_bg: Default::default(),
            t_sof: Default::default(),
            t_eol: Default::default(),
            tag_out: Default::default(),
            light_sel: Default::default(),
            slot_sel: Default::default(),
            amb_r: Default::default(),
            amb_g: Default::default(),
            amb_b: Default::default(),
            rnd_r: Default::default(),
            rnd_g: Default::default(),
            rnd_b: Default::default(),
            ph_r: Default::default(),
            ph_g: Default::default(),
            ph_b: Default::default(),
            w_ok: Default::default(),
            h_ok: Default::default(),
            w_m1: Default::default(),
            h_m1: Default::default(),
            k1_lsel: Constant::new(1.into()),
            k1_ssel: Constant::new(1.into()),
            k0_3: Constant::new(0.into()),
            k0_27: Constant::new(0.into()),
            kones_27: Constant::new(((1u64 << 27) - 1).into()),
            kmax_16: Constant::new(Signed::<16>::from(i16::MAX as i64)),
            kmin_16: Constant::new(Signed::<16>::from(i16::MIN as i64)),
            khalf_34: Constant::new((1u64 << 21).into()),
            k255_12: Constant::new(255.into()),
            k0_28: Constant::new(0.into()),
            kvalid_28: Constant::new((1u64 << 24).into()),
            kbg_28: Constant::new((1u64 << 25).into()),
            ksof_28: Constant::new((1u64 << 26).into()),
            keol_28: Constant::new((1u64 << 27).into()),
            k0_10: Constant::new(0.into()),
            k1_10: Constant::new(1.into()),
            k0_11: Constant::new(0.into()),
            k1_11: Constant::new(1.into()),
            k1024_11: Constant::new(1024.into()),
            k1_20: Constant::new(1.into()),
            k0_20: Constant::new(0.into()),
            k0_16: Constant::new(0.into()),
            k0_24: Constant::new(0.into()),
            kfar_24: Constant::new(0xff_ffff.into()),
            khalf_58: Constant::new((1i64 << 15).into()),
            k255_8: Constant::new(255.into()),
            k0_8: Constant::new(0.into()),
            k0_26: Constant::new(0.into()),
            k_sof_26: Constant::new((1u64 << 24).into()),
            k_eol_26: Constant::new((1u64 << 25).into()),
        }
    }
}

impl Logic for ScanPipe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, running, size_err, last_x, last_y, bg, clear, x, y, addr, s1_valid, s1_x, s1_y,
            s1_addr, s1_sof, s1_eol, s2_valid, s2_x, s2_y, s2_sof, s2_eol, s2_idx, s3_valid, s3_x, s3_y, s3_sof,
            s3_eol, s3_bg, s4_valid, s4_sof, s4_eol, s4_bg, s4_pa_r, s4_pb_r, s4_c_r, s4_pa_g, s4_pb_g, s4_c_g,
            s4_pa_b, s4_pb_b, s4_c_b, s5_valid, s5_sof, s5_eol, s5_bg, s5_sum_r, s5_sum_g, s5_sum_b, phong, acc_r,
            acc_g, acc_b
        );
        clock!(self, clock, normalizer);
        for i in 0..21 {
            self.mat[i].clock.next = self.clock.val();
            self.tags[i].clock.next = self.clock.val();
        }
        self.gloss_ram.read_clock.next = self.clock.val();
        self.gloss_ram.write_clock.next = self.clock.val();
        self.ambient_ram.read_clock.next = self.clock.val();
        self.ambient_ram.write_clock.next = self.clock.val();

        // Phong constants: light vectors per unit, material words by slot.
        self.light_sel.next = self.k1_lsel.val() << self.light_write_address.val();
        self.slot_sel.next = self.k1_ssel.val() << self.material_write_slot.val();
        for k in 0..self.lights.len() {
            self.lights[k].clock.next = self.clock.val();
            self.lights[k].vectors_write_enable.next = self.light_write_enable.val() & self.light_sel.val().get_bit(k);
            self.lights[k].vectors_write_data.next = self.light_write_data.val();
            self.lights[k].coeff_write_enable.next = self.material_write_enable.val() & self.slot_sel.val().get_bit(k + 1);
            self.lights[k].coeff_write_address.next = self.material_write_address.val();
            self.lights[k].coeff_write_data.next = self.material_write_data.val();
        }
        self.gloss_ram.write_enable.next = self.material_write_enable.val() & (self.material_write_slot.val() == self.k0_3.val());
        self.gloss_ram.write_address.next = self.material_write_address.val();
        self.mw3.next = self.material_write_data.val().w3;
        self.gloss_ram.write_data.next = self.mw3.val().get_bits::<3>(0);
        self.ambient_ram.write_enable.next = self.material_write_enable.val() & (self.material_write_slot.val() == self.k0_3.val());
        self.ambient_ram.write_address.next = self.material_write_address.val();
        self.ambient_ram.write_data.next = self.material_write_data.val();

        // Issue under the owner's credit.
        self.issue.next = self.running.q.val() & self.issue_ok.val();

        // Issue: raster-order counters.
        self.at_eol.next = self.x.q.val() == self.last_x.q.val();
        self.s1_valid.d.next = self.issue.val();
        self.s1_x.d.next = self.x.q.val();
        self.s1_y.d.next = self.y.q.val();
        self.s1_addr.d.next = self.addr.q.val();
        self.s1_sof.d.next = (self.x.q.val() == self.k0_10.val()) & (self.y.q.val() == self.k0_10.val());
        self.s1_eol.d.next = self.at_eol.val();
        if self.issue.val() {
            self.addr.d.next = self.addr.q.val() + self.k1_20.val();
            if self.at_eol.val() {
                self.x.d.next = self.k0_10.val();
                if self.y.q.val() == self.last_y.q.val() {
                    self.running.d.next = false;
                } else {
                    self.y.d.next = self.y.q.val() + self.k1_10.val();
                }
            } else {
                self.x.d.next = self.x.q.val() + self.k1_10.val();
            }
        }

        // s1 -> s2: the index arrives.
        self.s2_valid.d.next = self.s1_valid.q.val();
        self.s2_x.d.next = self.s1_x.q.val();
        self.s2_y.d.next = self.s1_y.q.val();
        self.s2_sof.d.next = self.s1_sof.q.val();
        self.s2_eol.d.next = self.s1_eol.q.val();
        self.s2_idx.d.next = self.ibuf_read_data.val();

        // s2 -> s3: TdbS is read at the index.
        self.s3_valid.d.next = self.s2_valid.q.val();
        self.s3_x.d.next = self.s2_x.q.val();
        self.s3_y.d.next = self.s2_y.q.val();
        self.s3_sof.d.next = self.s2_sof.q.val();
        self.s3_eol.d.next = self.s2_eol.q.val();
        self.s3_bg.d.next = self.s2_idx.q.val() == self.k0_16.val();

        // s3 -> s4: the record arrives; a*X, b*Y for three channels.
        self.px.next = signed_cast(bit_cast::<11, 10>(self.s3_x.q.val()));
        self.py.next = signed_cast(bit_cast::<11, 10>(self.s3_y.q.val()));
        self.mul_ra.a.next = signed_cast(self.tdbs_read_data.val().r_a);
        self.mul_ra.b.next = self.px.val();
        self.mul_rb.a.next = signed_cast(self.tdbs_read_data.val().r_b);
        self.mul_rb.b.next = self.py.val();
        self.mul_ga.a.next = signed_cast(self.tdbs_read_data.val().g_a);
        self.mul_ga.b.next = self.px.val();
        self.mul_gb.a.next = signed_cast(self.tdbs_read_data.val().g_b);
        self.mul_gb.b.next = self.py.val();
        self.mul_ba.a.next = signed_cast(self.tdbs_read_data.val().b_a);
        self.mul_ba.b.next = self.px.val();
        self.mul_bb.a.next = signed_cast(self.tdbs_read_data.val().b_b);
        self.mul_bb.b.next = self.py.val();
        self.s4_valid.d.next = self.s3_valid.q.val();
        self.s4_sof.d.next = self.s3_sof.q.val();
        self.s4_eol.d.next = self.s3_eol.q.val();
        self.s4_bg.d.next = self.s3_bg.q.val();
        self.s4_pa_r.d.next = self.mul_ra.p.val();
        self.s4_pb_r.d.next = self.mul_rb.p.val();
        self.s4_c_r.d.next = signed_cast(self.tdbs_read_data.val().r_c);
        self.s4_pa_g.d.next = self.mul_ga.p.val();
        self.s4_pb_g.d.next = self.mul_gb.p.val();
        self.s4_c_g.d.next = signed_cast(self.tdbs_read_data.val().g_c);
        self.s4_pa_b.d.next = self.mul_ba.p.val();
        self.s4_pb_b.d.next = self.mul_bb.p.val();
        self.s4_c_b.d.next = signed_cast(self.tdbs_read_data.val().b_c);

        // s4 -> s5: c + a*X + b*Y + 2^15 (the rounding half), 58 bits: no overflow for any record.
        self.sum_r.next = signed_bit_cast_safe::<58, 56>(self.s4_c_r.q.val()) + signed_bit_cast_safe::<58, 51>(self.s4_pa_r.q.val());
        self.sum_g.next = signed_bit_cast_safe::<58, 56>(self.s4_c_g.q.val()) + signed_bit_cast_safe::<58, 51>(self.s4_pa_g.q.val());
        self.sum_b.next = signed_bit_cast_safe::<58, 56>(self.s4_c_b.q.val()) + signed_bit_cast_safe::<58, 51>(self.s4_pa_b.q.val());
        self.s5_valid.d.next = self.s4_valid.q.val();
        self.s5_sof.d.next = self.s4_sof.q.val();
        self.s5_eol.d.next = self.s4_eol.q.val();
        self.s5_bg.d.next = self.s4_bg.q.val();
        self.s5_sum_r.d.next = self.sum_r.val() + signed_bit_cast_safe::<58, 51>(self.s4_pb_r.q.val()) + self.khalf_58.val();
        self.s5_sum_g.d.next = self.sum_g.val() + signed_bit_cast_safe::<58, 51>(self.s4_pb_g.q.val()) + self.khalf_58.val();
        self.s5_sum_b.d.next = self.sum_b.val() + signed_bit_cast_safe::<58, 51>(self.s4_pb_b.q.val()) + self.khalf_58.val();

        // t+5: >> 16 and clamp to 0..=255 (negative -> 0; bits 56:24 not all 0 -> 255): flat / Gouraud.
        self.ch_r.next = unsigned_cast(self.s5_sum_r.q.val().get_bits::<8>(16));
        self.hi_r.next = unsigned_cast(self.s5_sum_r.q.val().get_bits::<33>(24));
        if self.hi_r.val().any() {
            self.ch_r.next = self.k255_8.val();
        }
        if self.s5_sum_r.q.val().get_bit(57) {
            self.ch_r.next = self.k0_8.val();
        }
        self.ch_g.next = unsigned_cast(self.s5_sum_g.q.val().get_bits::<8>(16));
        self.hi_g.next = unsigned_cast(self.s5_sum_g.q.val().get_bits::<33>(24));
        if self.hi_g.val().any() {
            self.ch_g.next = self.k255_8.val();
        }
        if self.s5_sum_g.q.val().get_bit(57) {
            self.ch_g.next = self.k0_8.val();
        }
        self.ch_b.next = unsigned_cast(self.s5_sum_b.q.val().get_bits::<8>(16));
        self.hi_b.next = unsigned_cast(self.s5_sum_b.q.val().get_bits::<33>(24));
        if self.hi_b.val().any() {
            self.ch_b.next = self.k255_8.val();
        }
        if self.s5_sum_b.q.val().get_bit(57) {
            self.ch_b.next = self.k0_8.val();
        }
        // UG934 RGB order: R 23:16, B 15:8, G 7:0.
        self.g_rgb.next = (bit_cast::<24, 8>(self.ch_r.val()) << 16) | (bit_cast::<24, 8>(self.ch_b.val()) << 8) | bit_cast::<24, 8>(self.ch_g.val());

        // t+5: the same sums as a normal (Phong): >> 16 saturated to 16 bits (bits 57:31 all the sign).
        self.us_r.next = unsigned_cast(self.s5_sum_r.q.val());
        self.top_r.next = self.us_r.val().get_bits::<27>(31);
        self.us_g.next = unsigned_cast(self.s5_sum_g.q.val());
        self.top_g.next = self.us_g.val().get_bits::<27>(31);
        self.us_b.next = unsigned_cast(self.s5_sum_b.q.val());
        self.top_b.next = self.us_b.val().get_bits::<27>(31);
        self.n_r.next = signed_cast(self.us_r.val().get_bits::<16>(16));
        if self.s5_sum_r.q.val().get_bit(57) & (self.top_r.val() != self.kones_27.val()) {
            self.n_r.next = self.kmin_16.val();
        }
        if !self.s5_sum_r.q.val().get_bit(57) & (self.top_r.val() != self.k0_27.val()) {
            self.n_r.next = self.kmax_16.val();
        }
        self.n_g.next = signed_cast(self.us_g.val().get_bits::<16>(16));
        if self.s5_sum_g.q.val().get_bit(57) & (self.top_g.val() != self.kones_27.val()) {
            self.n_g.next = self.kmin_16.val();
        }
        if !self.s5_sum_g.q.val().get_bit(57) & (self.top_g.val() != self.k0_27.val()) {
            self.n_g.next = self.kmax_16.val();
        }
        self.n_b.next = signed_cast(self.us_b.val().get_bits::<16>(16));
        if self.s5_sum_b.q.val().get_bit(57) & (self.top_b.val() != self.kones_27.val()) {
            self.n_b.next = self.kmin_16.val();
        }
        if !self.s5_sum_b.q.val().get_bit(57) & (self.top_b.val() != self.k0_27.val()) {
            self.n_b.next = self.kmax_16.val();
        }
        self.normalizer.n_x.next = self.n_r.val();
        self.normalizer.n_y.next = self.n_g.val();
        self.normalizer.n_z.next = self.n_b.val();

        // The pixel's tags and flat / Gouraud colour wait for the Phong path (t+5 .. t+26).
        self.t_valid.next = self.k0_28.val();
        if self.s5_valid.q.val() {
            self.t_valid.next = self.kvalid_28.val();
        }
        self.t_bg.next = self.k0_28.val();
        if self.s5_bg.q.val() {
            self.t_bg.next = self.kbg_28.val();
        }
        self.t_sof.next = self.k0_28.val();
        if self.s5_sof.q.val() {
            self.t_sof.next = self.ksof_28.val();
        }
        self.t_eol.next = self.k0_28.val();
        if self.s5_eol.q.val() {
            self.t_eol.next = self.keol_28.val();
        }
        self.tag_in.next = bit_cast::<28, 24>(self.g_rgb.val()) | self.t_valid.val() | self.t_bg.val() | self.t_sof.val() | self.t_eol.val();
        self.tags[0].d.next = self.tag_in.val();
        for i in 1..21 {
            self.tags[i].d.next = self.tags[i - 1].q.val();
        }

        // The material travels from the record (t+3) to the memories' reads (t+18, t+22, t+24).
        self.rec_material.next = self.tdbs_read_data.val().material;
        self.mat[0].d.next = self.rec_material.val().get_bits::<CS_MATERIAL_BITS>(0);
        for i in 1..21 {
            self.mat[i].d.next = self.mat[i - 1].q.val();
        }
        self.gloss_ram.read_address.next = self.mat[14].q.val();
        self.ambient_ram.read_address.next = self.mat[20].q.val();

        // t+17: the light units, chained from the ambient term (read at t+24, used at t+25).
        self.amb_r.next = bit_cast::<34, 16>(self.ambient_ram.read_data.val().w0) << 14;
        self.amb_g.next = bit_cast::<34, 16>(self.ambient_ram.read_data.val().w1) << 14;
        self.amb_b.next = bit_cast::<34, 16>(self.ambient_ram.read_data.val().w2) << 14;
        for k in 0..self.lights.len() {
            self.lights[k].u_x.next = self.normalizer.u_x.val();
            self.lights[k].u_y.next = self.normalizer.u_y.val();
            self.lights[k].u_z.next = self.normalizer.u_z.val();
            self.lights[k].gloss_log2.next = self.gloss_ram.read_data.val();
            self.lights[k].material.next = self.mat[18].q.val();
        }
        self.lights[0].acc_in_r.next = self.amb_r.val();
        self.lights[0].acc_in_g.next = self.amb_g.val();
        self.lights[0].acc_in_b.next = self.amb_b.val();
        for k in 1..self.lights.len() {
            self.lights[k].acc_in_r.next = self.lights[k - 1].acc_out_r.val();
            self.lights[k].acc_in_g.next = self.lights[k - 1].acc_out_g.val();
            self.lights[k].acc_in_b.next = self.lights[k - 1].acc_out_b.val();
        }
        // C1 (t+25): the last unit's sum.
        for k in 0..self.lights.len() {
            self.acc_r.d.next = self.lights[k].acc_out_r.val();
            self.acc_g.d.next = self.lights[k].acc_out_g.val();
            self.acc_b.d.next = self.lights[k].acc_out_b.val();
        }

        // C2 (t+26): round by 22 bits, clamp to 255 (the sum is never negative); pick the shading's
        // colour or the background; into the FIFO.
        self.rnd_r.next = self.acc_r.q.val() + self.khalf_34.val();
        self.rnd_g.next = self.acc_g.q.val() + self.khalf_34.val();
        self.rnd_b.next = self.acc_b.q.val() + self.khalf_34.val();
        self.ph_r.next = self.rnd_r.val().get_bits::<8>(22);
        if self.rnd_r.val().get_bits::<12>(22) > self.k255_12.val() {
            self.ph_r.next = self.k255_8.val();
        }
        self.ph_g.next = self.rnd_g.val().get_bits::<8>(22);
        if self.rnd_g.val().get_bits::<12>(22) > self.k255_12.val() {
            self.ph_g.next = self.k255_8.val();
        }
        self.ph_b.next = self.rnd_b.val().get_bits::<8>(22);
        if self.rnd_b.val().get_bits::<12>(22) > self.k255_12.val() {
            self.ph_b.next = self.k255_8.val();
        }
        self.tag_out.next = self.tags[20].q.val();
        self.rgb.next = self.tag_out.val().get_bits::<24>(0);
        if self.phong.q.val() {
            self.rgb.next = (bit_cast::<24, 8>(self.ph_r.val()) << 16) | (bit_cast::<24, 8>(self.ph_b.val()) << 8) | bit_cast::<24, 8>(self.ph_g.val());
        }
        if self.tag_out.val().get_bit(25) {
            self.rgb.next = self.bg.q.val();
        }
        self.beat_valid.next = self.tag_out.val().get_bit(24);
        self.sof_bit.next = self.k0_26.val();
        if self.tag_out.val().get_bit(26) {
            self.sof_bit.next = self.k_sof_26.val();
        }
        self.eol_bit.next = self.k0_26.val();
        if self.tag_out.val().get_bit(27) {
            self.eol_bit.next = self.k_eol_26.val();
        }
        self.beat_data.next = self.k0_26.val();
        if self.tag_out.val().get_bit(24) {
            self.beat_data.next = bit_cast::<26, 24>(self.rgb.val()) | self.sof_bit.val() | self.eol_bit.val();
        }

        // The record's pixel, for the owner's texture path.
        self.tap_valid.next = self.s3_valid.q.val();
        self.tap_x.next = self.s3_x.q.val();
        self.tap_y.next = self.s3_y.q.val();
        self.tap_bg.next = self.s3_bg.q.val();

        // Memory ports (payloads 0 while disabled).
        self.ibuf_read_enable.next = self.issue.val();
        self.ibuf_read_address.next = self.k0_20.val();
        if self.issue.val() {
            self.ibuf_read_address.next = self.addr.q.val();
        }
        self.tdbs_read_enable.next = self.s2_valid.q.val();
        self.tdbs_read_address.next = self.k0_16.val();
        if self.s2_valid.q.val() {
            self.tdbs_read_address.next = self.s2_idx.q.val();
        }
        self.ibuf_write_enable.next = self.s1_valid.q.val() & self.clear.q.val();
        self.ibuf_write_address.next = self.k0_20.val();
        self.ibuf_write_data.next = self.k0_16.val();
        self.zbuf_write_enable.next = self.s1_valid.q.val() & self.clear.q.val();
        self.zbuf_write_address.next = self.k0_20.val();
        self.zbuf_write_data.next = self.k0_24.val();
        if self.s1_valid.q.val() & self.clear.q.val() {
            self.ibuf_write_address.next = self.s1_addr.q.val();
            self.zbuf_write_address.next = self.s1_addr.q.val();
            self.zbuf_write_data.next = self.kfar_24.val();
        }

        // Frame start (the owner passes it only when idle).
        self.active.next = self.running.q.val();
        self.w_ok.next = (self.width.val() != self.k0_11.val()) & (self.width.val() <= self.k1024_11.val());
        self.h_ok.next = (self.height.val() != self.k0_11.val()) & (self.height.val() <= self.k1024_11.val());
        self.w_m1.next = self.width.val() - self.k1_11.val();
        self.h_m1.next = self.height.val() - self.k1_11.val();
        if self.start.val() {
            if self.w_ok.val() & self.h_ok.val() {
                self.size_err.d.next = false;
                self.running.d.next = true;
                self.last_x.d.next = self.w_m1.val().get_bits::<10>(0);
                self.last_y.d.next = self.h_m1.val().get_bits::<10>(0);
                self.bg.d.next = self.background.val();
                self.clear.d.next = self.clear_behind.val();
                self.phong.d.next = self.shading_phong.val();
                self.x.d.next = self.k0_10.val();
                self.y.d.next = self.k0_10.val();
                self.addr.d.next = self.k0_20.val();
            } else {
                self.size_err.d.next = true;
            }
        }
        self.size_error.next = self.size_err.q.val();
    }
}
