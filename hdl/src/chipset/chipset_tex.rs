//! `chipset_tex`: the `chipset` top with texture mapping (issue 17; seed 000 §III, seed 001 §3): the
//! same RC, `textured_setup` in place of `colour_setup`, and `cs_tex` in place of `cs` (`back_tex`).
//!
//! ```text
//!  host, upper pipeline                                          memories (outside the top)
//!   rc_cmd, rc_result: as `chipset` ----> [ rc ] -- z_*, id_* -> Z-buffer, I-buffer draw bank
//!  host, lower pipeline
//!   setup_cmd + setup_tex (9 texture values) -> [ textured_setup ] -- t_we/t_wr_*  -> TdbS bank draw_bank
//!                                                                 -- tt_we/tt_wr_* -> TdbT bank draw_bank
//!  scan_*, Phong constants as `chipset`;
//!  scan_texture, tex_w0_log2, tex_h0_log2, tex_last_level, tex_filter, tex_clamp (latched at start),
//!  tex_base_* (the level table, written while scan_busy is low) -> [ cs_tex ] -- is_*, t_re/t_rd_*,
//!                                                                    |           tt_re/tt_rd_* (scan bank)
//!                                                                    |  -- tex_rd, tex_addr0..3 ----> four texture banks
//!                                                                    |  <- tex_data0..3 (latency 1)
//!                                                                    +--> video (AXI4-Stream)
//! ```
//!
//! * TdbT (2 banks of 2^16 records of 408 bits, address bit 16 the bank) follows TdbS: written by
//!   texture setup into the draw bank 23 cycles after the command is taken (TdbS: 41), read by the CS
//!   in the scan bank beside TdbS.
//! * The texture (four banks of RGB888 words, `golden::texbank`; the level table of each level's
//!   first word) is the frame's, loaded by the host while no scan is running; it has one bank.
//! * Every other port and the host's protocol are `chipset`'s. A frame started with `scan_texture` low
//!   is scanned exactly as by `chipset`.

use crate::common::{StreamIn, StreamOut};
use crate::cs::texel_address::ADDR_BITS;
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, TdbtRecord, TexValues, CS_MATERIAL_BITS};
use super::back_tex::BackTex;
use crate::rc::{Rc, RcCommand, RcResult};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ChipsetTex {
    pub clock: Signal<In, Clock>,
    // From / to the host: geometry (upper pipeline)
    /// Frame start, triangles, end of frame.
    pub rc_cmd: StreamIn<RcCommand>,
    /// Per-triangle culled/visible flags, then end of frame.
    pub rc_result: StreamOut<RcResult>,
    // From / to the host: shading (lower pipeline, enhanced deferred lighting)
    /// Colour-setup commands for the visible triangles.
    pub setup_cmd: StreamIn<SetupCommand>,
    /// The command's texture values (s/w, t/w, 1/w of each vertex), valid with `setup_cmd`.
    pub setup_tex: Signal<In, TexValues>,
    /// Colour setup is working on a command.
    pub setup_busy: Signal<Out, Bit>,
    // From / to the host: scan-out control
    /// Start scanning a frame out (taken when `scan_busy` is low).
    pub scan_start: Signal<In, Bit>,
    /// Background colour, packed as `video_tdata`.
    pub scan_background: Signal<In, Bits<24>>,
    /// Clear the I- and Z-buffer behind the scan for the next frame.
    pub scan_clear_behind: Signal<In, Bit>,
    /// Light the interpolated normals per pixel (Phong) instead of evaluating colours (latched at start).
    pub scan_phong: Signal<In, Bit>,
    /// The CS's Phong constants (see `cs::color_shader`), written while `scan_busy` is low: load light
    /// `light_write_address`'s L and H.
    pub light_write_enable: Signal<In, Bit>,
    pub light_write_address: Signal<In, Bits<2>>,
    pub light_write_data: Signal<In, LightVectors>,
    /// The CS's Phong constants, written while `scan_busy` is low: word `material_write_slot` of
    /// material `material_write_address` (slot 0 = ambient and log2 of the gloss, slot 1 + l = light
    /// l's diffuse and specular coefficients).
    pub material_write_enable: Signal<In, Bit>,
    pub material_write_address: Signal<In, Bits<CS_MATERIAL_BITS>>,
    pub material_write_slot: Signal<In, Bits<3>>,
    pub material_write_data: Signal<In, MaterialWord>,
    /// A frame is being scanned out.
    pub scan_busy: Signal<Out, Bit>,
    // To the display (AXI4-Stream video)
    /// RGB888: R 23:16, B 15:8, G 7:0.
    pub video_tdata: Signal<Out, Bits<24>>,
    pub video_tvalid: Signal<Out, Bit>,
    pub video_tready: Signal<In, Bit>,
    /// Start of frame.
    pub video_tuser: Signal<Out, Bit>,
    /// End of line.
    pub video_tlast: Signal<Out, Bit>,
    // Z-buffer (W*H words of 24 bits; address y*W + x): the RC's alone, one bank, never cleared
    // between frames (a depth under a background index counts as far, see `rc::z_test`).
    /// Read enable and address (the RC's Z-test); `z_rd_data` holds the word one cycle later.
    pub z_re: Signal<Out, Bit>,
    pub z_rd_addr: Signal<Out, Bits<20>>,
    pub z_rd_data: Signal<In, Bits<24>>,
    /// Write port (the RC's passes and clear).
    pub z_we: Signal<Out, Bit>,
    pub z_wr_addr: Signal<Out, Bits<20>>,
    pub z_wr_data: Signal<Out, Bits<24>>,
    // I-buffer: two banks of W*H words of 16 bits; address bit 20 is the bank, bits 19:0 y*W + x.
    /// Draw side (the RC, in the draw bank): the index read with the depth (same address as `z_rd_addr`).
    pub id_re: Signal<Out, Bit>,
    pub id_rd_addr: Signal<Out, Bits<21>>,
    pub id_rd_data: Signal<In, Bits<16>>,
    /// Draw side: the RC's passes and clear.
    pub id_we: Signal<Out, Bit>,
    pub id_wr_addr: Signal<Out, Bits<21>>,
    pub id_wr_data: Signal<Out, Bits<16>>,
    /// Scan side (the CS, in the scan bank): the scan-out's reads.
    pub is_re: Signal<Out, Bit>,
    pub is_rd_addr: Signal<Out, Bits<21>>,
    pub is_rd_data: Signal<In, Bits<16>>,
    /// Scan side: the CS's clear-behind.
    pub is_we: Signal<Out, Bit>,
    pub is_wr_addr: Signal<Out, Bits<21>>,
    pub is_wr_data: Signal<Out, Bits<16>>,
    // TdbS: two banks of 2^16 records of 424 bits; address bit 16 is the bank, bits 15:0 the index.
    /// Read port (the CS, in the scan bank).
    pub t_re: Signal<Out, Bit>,
    pub t_rd_addr: Signal<Out, Bits<17>>,
    pub t_rd_data: Signal<In, TdbsRecord>,
    /// Write port (colour setup, in the draw bank).
    pub t_we: Signal<Out, Bit>,
    pub t_wr_addr: Signal<Out, Bits<17>>,
    pub t_wr_data: Signal<Out, TdbsRecord>,
    // TdbT: two banks of 2^16 records of 408 bits; address bit 16 is the bank, bits 15:0 the index.
    /// Read port (the CS, in the scan bank, beside `t_re`).
    pub tt_re: Signal<Out, Bit>,
    pub tt_rd_addr: Signal<Out, Bits<17>>,
    pub tt_rd_data: Signal<In, TdbtRecord>,
    /// Write port (texture setup, in the draw bank).
    pub tt_we: Signal<Out, Bit>,
    pub tt_wr_addr: Signal<Out, Bits<17>>,
    pub tt_wr_data: Signal<Out, TdbtRecord>,
    // The texture (see `cs::color_shader_tex`): settings latched at `scan_start`.
    /// Texture this frame.
    pub scan_texture: Signal<In, Bit>,
    /// Level 0's size (log2), the last mipmap level, the filter (0 nearest, 1 bilinear, 2 trilinear)
    /// and clamp-to-edge (else repeat).
    pub tex_w0_log2: Signal<In, Bits<4>>,
    pub tex_h0_log2: Signal<In, Bits<4>>,
    pub tex_last_level: Signal<In, Bits<4>>,
    pub tex_filter: Signal<In, Bits<2>>,
    pub tex_clamp: Signal<In, Bit>,
    /// The level table, written while `scan_busy` is low: level `tex_base_sel` starts at bank word
    /// `tex_base_data`.
    pub tex_base_we: Signal<In, Bit>,
    pub tex_base_sel: Signal<In, Bits<4>>,
    pub tex_base_data: Signal<In, Bits<ADDR_BITS>>,
    /// The four texture banks: bank k is read at `tex_addrk` when bit k of `tex_rd` is set, and its
    /// word (RGB888 as `video_tdata`) is on `tex_datak` one cycle later.
    pub tex_rd: Signal<Out, Bits<4>>,
    pub tex_addr0: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr1: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr2: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr3: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_data0: Signal<In, Bits<24>>,
    pub tex_data1: Signal<In, Bits<24>>,
    pub tex_data2: Signal<In, Bits<24>>,
    pub tex_data3: Signal<In, Bits<24>>,
    /// The bank the RC and colour setup draw into (the address bit above, for a memory wrapper or a
    /// waveform reader); the CS scans the other one once a scan has started.
    pub draw_bank: Signal<Out, Bit>,

    rc: Rc,
    back: BackTex,
}

impl ChipsetTex {
    /// A textured chipset for a `width` x `height` screen (1..=1024 each).
    pub fn new(width: u32, height: u32) -> Result<ChipsetTex, String> {
        Ok(ChipsetTex {
            clock: Default::default(),
            rc_cmd: Default::default(),
            rc_result: Default::default(),
            setup_cmd: Default::default(),
            setup_tex: Default::default(),
            setup_busy: Default::default(),
            scan_start: Default::default(),
            scan_background: Default::default(),
            scan_clear_behind: Default::default(),
            scan_phong: Default::default(),
            light_write_enable: Default::default(),
            light_write_address: Default::default(),
            light_write_data: Default::default(),
            material_write_enable: Default::default(),
            material_write_address: Default::default(),
            material_write_slot: Default::default(),
            material_write_data: Default::default(),
            scan_busy: Default::default(),
            video_tdata: Default::default(),
            video_tvalid: Default::default(),
            video_tready: Default::default(),
            video_tuser: Default::default(),
            video_tlast: Default::default(),
            z_re: Default::default(),
            z_rd_addr: Default::default(),
            z_rd_data: Default::default(),
            z_we: Default::default(),
            z_wr_addr: Default::default(),
            z_wr_data: Default::default(),
            id_re: Default::default(),
            id_rd_addr: Default::default(),
            id_rd_data: Default::default(),
            id_we: Default::default(),
            id_wr_addr: Default::default(),
            id_wr_data: Default::default(),
            is_re: Default::default(),
            is_rd_addr: Default::default(),
            is_rd_data: Default::default(),
            is_we: Default::default(),
            is_wr_addr: Default::default(),
            is_wr_data: Default::default(),
            t_re: Default::default(),
            t_rd_addr: Default::default(),
            t_rd_data: Default::default(),
            t_we: Default::default(),
            t_wr_addr: Default::default(),
            t_wr_data: Default::default(),
            tt_re: Default::default(),
            tt_rd_addr: Default::default(),
            tt_rd_data: Default::default(),
            tt_we: Default::default(),
            tt_wr_addr: Default::default(),
            tt_wr_data: Default::default(),
            scan_texture: Default::default(),
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
            draw_bank: Default::default(),
            rc: Rc::new(width, height)?,
            back: BackTex::new(width, height),
        })
    }
}

impl Logic for ChipsetTex {
    #[hdl_gen]
    fn update(&mut self) {
        self.rc.clock.next = self.clock.val();
        self.back.clock.next = self.clock.val();

        // Geometry: the RC, on the Z-buffer and (through `back`) the draw bank of the I-buffer, whose
        // word it reads with each depth.
        StreamIn::<RcCommand>::link(&mut self.rc_cmd, &mut self.rc.cmd);
        StreamOut::<RcResult>::link(&mut self.rc_result, &mut self.rc.result);
        self.z_re.next = self.rc.z_re.val();
        self.z_rd_addr.next = self.rc.z_rd_addr.val();
        self.rc.z_rd_data.next = self.z_rd_data.val();
        self.z_we.next = self.rc.z_we.val();
        self.z_wr_addr.next = self.rc.z_wr_addr.val();
        self.z_wr_data.next = self.rc.z_wr_data.val();
        self.back.draw_re.next = self.rc.z_re.val();
        self.back.draw_rd_addr.next = self.rc.z_rd_addr.val();
        self.rc.i_rd_data.next = self.back.draw_rd_data.val();
        self.back.draw_we.next = self.rc.i_we.val();
        self.back.draw_wr_addr.next = self.rc.i_wr_addr.val();
        self.back.draw_wr_data.next = self.rc.i_wr_data.val();

        // Shading and scan-out (`back`).
        StreamIn::<SetupCommand>::link(&mut self.setup_cmd, &mut self.back.setup_cmd);
        self.back.setup_tex.next = self.setup_tex.val();
        self.setup_busy.next = self.back.setup_busy.val();
        self.back.scan_start.next = self.scan_start.val();
        self.back.scan_background.next = self.scan_background.val();
        self.back.scan_clear_behind.next = self.scan_clear_behind.val();
        self.back.scan_phong.next = self.scan_phong.val();
        self.back.light_write_enable.next = self.light_write_enable.val();
        self.back.light_write_address.next = self.light_write_address.val();
        self.back.light_write_data.next = self.light_write_data.val();
        self.back.material_write_enable.next = self.material_write_enable.val();
        self.back.material_write_address.next = self.material_write_address.val();
        self.back.material_write_slot.next = self.material_write_slot.val();
        self.back.material_write_data.next = self.material_write_data.val();
        self.scan_busy.next = self.back.scan_busy.val();
        self.video_tdata.next = self.back.video_tdata.val();
        self.video_tvalid.next = self.back.video_tvalid.val();
        self.back.video_tready.next = self.video_tready.val();
        self.video_tuser.next = self.back.video_tuser.val();
        self.video_tlast.next = self.back.video_tlast.val();
        self.id_re.next = self.back.id_re.val();
        self.id_rd_addr.next = self.back.id_rd_addr.val();
        self.back.id_rd_data.next = self.id_rd_data.val();
        self.id_we.next = self.back.id_we.val();
        self.id_wr_addr.next = self.back.id_wr_addr.val();
        self.id_wr_data.next = self.back.id_wr_data.val();
        self.is_re.next = self.back.is_re.val();
        self.is_rd_addr.next = self.back.is_rd_addr.val();
        self.back.is_rd_data.next = self.is_rd_data.val();
        self.is_we.next = self.back.is_we.val();
        self.is_wr_addr.next = self.back.is_wr_addr.val();
        self.is_wr_data.next = self.back.is_wr_data.val();
        self.t_re.next = self.back.t_re.val();
        self.t_rd_addr.next = self.back.t_rd_addr.val();
        self.back.t_rd_data.next = self.t_rd_data.val();
        self.t_we.next = self.back.t_we.val();
        self.t_wr_addr.next = self.back.t_wr_addr.val();
        self.t_wr_data.next = self.back.t_wr_data.val();
        // Texture mapping: TdbT and the texture (`back_tex`).
        self.tt_re.next = self.back.tt_re.val();
        self.tt_rd_addr.next = self.back.tt_rd_addr.val();
        self.tt_we.next = self.back.tt_we.val();
        self.tt_wr_addr.next = self.back.tt_wr_addr.val();
        self.tt_wr_data.next = self.back.tt_wr_data.val();
        self.tex_rd.next = self.back.tex_rd.val();
        self.tex_addr0.next = self.back.tex_addr0.val();
        self.tex_addr1.next = self.back.tex_addr1.val();
        self.tex_addr2.next = self.back.tex_addr2.val();
        self.tex_addr3.next = self.back.tex_addr3.val();
        self.back.tt_rd_data.next = self.tt_rd_data.val();
        self.back.scan_texture.next = self.scan_texture.val();
        self.back.tex_w0_log2.next = self.tex_w0_log2.val();
        self.back.tex_h0_log2.next = self.tex_h0_log2.val();
        self.back.tex_last_level.next = self.tex_last_level.val();
        self.back.tex_filter.next = self.tex_filter.val();
        self.back.tex_clamp.next = self.tex_clamp.val();
        self.back.tex_base_we.next = self.tex_base_we.val();
        self.back.tex_base_sel.next = self.tex_base_sel.val();
        self.back.tex_base_data.next = self.tex_base_data.val();
        self.back.tex_data0.next = self.tex_data0.val();
        self.back.tex_data1.next = self.tex_data1.val();
        self.back.tex_data2.next = self.tex_data2.val();
        self.back.tex_data3.next = self.tex_data3.val();
        self.draw_bank.next = self.back.draw_bank.val();
    }
}

/// Verilog of the textured chipset for a `width` x `height` screen (module `chipset_tex`).
pub fn verilog(width: u32, height: u32) -> Result<String, String> {
    let mut uut = ChipsetTex::new(width, height)?;
    uut.connect_all();
    crate::common::verilog_named(&uut, "chipset_tex")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chipset_tex_passes_the_rust_hdl_checks_and_generates_a_top_named_chipset_tex() {
        let v = verilog(32, 16).unwrap();
        assert!(v.contains("module chipset_tex("), "no chipset_tex module");
        assert!(ChipsetTex::new(2000, 10).is_err());
    }
}
