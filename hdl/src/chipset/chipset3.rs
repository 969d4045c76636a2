//! `chipset3`: the `chipset` top with seed 000's Type III Rasterizer Controller (`rc::rc3`): no
//! Z-buffer. The visibility test reads the I-buffer word at the pixel, fetches that triangle's depth
//! plane from TdbV and evaluates it at the pixel (docs/rc.md, "Type III").
//!
//! ```text
//!  host, upper pipeline                                         memories (outside the top)
//!   rc_cmd ---(valid/ready)--> [ rc3 ] -- tdbv read/write ------> TdbV (2^16 x 136), one bank
//!   rc_result <-(valid/ready)-   |     -- id_* read/write ------> I-buffer bank draw_bank (W*H x 16)
//!                                |
//!   everything else as `chipset`: [ back: colour_setup, cs, bank swap ] -- is_*, t_*, video
//! ```
//!
//! * TdbV is behind a port, as `rc3`'s is: at 16 index bits it holds 2^16 x 136 bits = 1.1 MB, more
//!   than the LFE5U-45F's block RAM (243 KB). Its port is block-RAM shaped (synchronous read, latency
//!   1, read before write).
//! * TdbV has one bank. The RC reads TdbV only at an index the draw bank of the I-buffer holds; the
//!   clear behind the scan-out leaves that bank holding nothing but the background, so every index the
//!   RC finds there was written this frame, after its plane. The CS never reads TdbV.
//! * The other ports, the banks and the host's protocol are `chipset`'s.

use crate::common::{StreamIn, StreamOut};
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, CS_MATERIAL_BITS};
use super::back::Back;
use crate::rc::rc3::Rc3;
use crate::rc::{RcCommand, RcResult};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Chipset3 {
    pub clock: Signal<In, Clock>,
    // From / to the host: geometry (upper pipeline)
    /// Frame start, triangles, end of frame.
    pub rc_cmd: StreamIn<RcCommand>,
    /// Per-triangle culled/visible flags, then end of frame.
    pub rc_result: StreamOut<RcResult>,
    // From / to the host: shading (lower pipeline, enhanced deferred lighting)
    /// Colour-setup commands for the visible triangles.
    pub setup_cmd: StreamIn<SetupCommand>,
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
    // TdbV (2^16 records, one bank; address = triangle index): the depth plane of each triangle the RC
    // walks, A and B 40 bits, C 56 bits (`golden::format::Plane`), the RC's alone.
    /// Read enable and address (an index the I-buffer holds); the plane arrives one cycle later.
    pub tdbv_re: Signal<Out, Bit>,
    pub tdbv_rd_addr: Signal<Out, Bits<16>>,
    pub tdbv_rd_a: Signal<In, Signed<40>>,
    pub tdbv_rd_b: Signal<In, Signed<40>>,
    pub tdbv_rd_c: Signal<In, Signed<56>>,
    /// Write port: a triangle's plane, written as the traversal starts walking it.
    pub tdbv_we: Signal<Out, Bit>,
    pub tdbv_wr_addr: Signal<Out, Bits<16>>,
    pub tdbv_wr_a: Signal<Out, Signed<40>>,
    pub tdbv_wr_b: Signal<Out, Signed<40>>,
    pub tdbv_wr_c: Signal<Out, Signed<56>>,
    // I-buffer: two banks of W*H words of 16 bits; address bit 20 is the bank, bits 19:0 y*W + x.
    /// Draw side (the RC, in the draw bank): the index whose depth plane the visibility test regenerates.
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
    /// The bank the RC and colour setup draw into (the address bit above, for a memory wrapper or a
    /// waveform reader); the CS scans the other one once a scan has started.
    pub draw_bank: Signal<Out, Bit>,

    rc: Rc3,
    back: Back,
}

impl Chipset3 {
    /// A Type III chipset for a `width` x `height` screen (1..=1024 each).
    pub fn new(width: u32, height: u32) -> Result<Chipset3, String> {
        Ok(Chipset3 {
            clock: Default::default(),
            rc_cmd: Default::default(),
            rc_result: Default::default(),
            setup_cmd: Default::default(),
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
            tdbv_re: Default::default(),
            tdbv_rd_addr: Default::default(),
            tdbv_rd_a: Default::default(),
            tdbv_rd_b: Default::default(),
            tdbv_rd_c: Default::default(),
            tdbv_we: Default::default(),
            tdbv_wr_addr: Default::default(),
            tdbv_wr_a: Default::default(),
            tdbv_wr_b: Default::default(),
            tdbv_wr_c: Default::default(),
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
            draw_bank: Default::default(),
            rc: Rc3::new(width, height)?,
            back: Back::new(width, height),
        })
    }
}

impl Logic for Chipset3 {
    #[hdl_gen]
    fn update(&mut self) {
        self.rc.clock.next = self.clock.val();
        self.back.clock.next = self.clock.val();

        // Geometry: the Type III RC, on TdbV and (through `back`) the draw bank of the I-buffer.
        StreamIn::<RcCommand>::link(&mut self.rc_cmd, &mut self.rc.cmd);
        StreamOut::<RcResult>::link(&mut self.rc_result, &mut self.rc.result);
        self.tdbv_re.next = self.rc.tdbv_re.val();
        self.tdbv_rd_addr.next = self.rc.tdbv_rd_addr.val();
        self.rc.tdbv_rd_a.next = self.tdbv_rd_a.val();
        self.rc.tdbv_rd_b.next = self.tdbv_rd_b.val();
        self.rc.tdbv_rd_c.next = self.tdbv_rd_c.val();
        self.tdbv_we.next = self.rc.tdbv_we.val();
        self.tdbv_wr_addr.next = self.rc.tdbv_wr_addr.val();
        self.tdbv_wr_a.next = self.rc.tdbv_wr_a.val();
        self.tdbv_wr_b.next = self.rc.tdbv_wr_b.val();
        self.tdbv_wr_c.next = self.rc.tdbv_wr_c.val();
        self.back.draw_re.next = self.rc.i_re.val();
        self.back.draw_rd_addr.next = self.rc.i_rd_addr.val();
        self.rc.i_rd_data.next = self.back.draw_rd_data.val();
        self.back.draw_we.next = self.rc.i_we.val();
        self.back.draw_wr_addr.next = self.rc.i_wr_addr.val();
        self.back.draw_wr_data.next = self.rc.i_wr_data.val();

        // Shading and scan-out (`back`).
        StreamIn::<SetupCommand>::link(&mut self.setup_cmd, &mut self.back.setup_cmd);
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
        self.draw_bank.next = self.back.draw_bank.val();
    }
}

/// Verilog of the Type III chipset for a `width` x `height` screen (module `chipset3`).
pub fn verilog(width: u32, height: u32) -> Result<String, String> {
    let mut uut = Chipset3::new(width, height)?;
    uut.connect_all();
    crate::common::verilog_named(&uut, "chipset3")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chipset3_passes_the_rust_hdl_checks_and_has_no_z_buffer_port() {
        let v = verilog(32, 16).unwrap();
        assert!(v.contains("module chipset3("), "no chipset3 module");
        assert!(v.contains("tdbv_rd_addr") && !v.contains("z_rd_addr"), "TdbV port missing or a Z port left");
        assert!(Chipset3::new(10, 2000).is_err());
    }
}
