//! `chipset`: seed 001's raster chipset (Fig. 5) as one top: the Rasterizer Controller, colour setup
//! and the Color Shader around the shared buffers, whose memory ports are at the top so that the same
//! RTL can use FPGA block RAM or external SRAM.
//!
//! ```text
//!  host, upper pipeline                                          memories (outside the top)
//!   rc_cmd ---(valid/ready)--> [ rc ] -- z read/write ---------> Z-buffer (W*H x 24), one bank
//!   rc_result <-(valid/ready)-   |    -- id_* read/write ------> I-buffer bank draw_bank   (W*H x 16)
//!  host, lower pipeline          |                                        |
//!   setup_cmd -(valid/ready)-> [ colour_setup ] -- t_we/t_wr_* -> TdbS bank draw_bank  (2^16 x 424)
//!                                                                         |
//!  scan_start, scan_background, scan_clear_behind, scan_phong,    I-buffer bank !draw_bank
//!  light_write_*, material_write_* -> [ cs ] -- is_* read/write ->        |  (clear-behind)
//!                                      |    -- t_re/t_rd_* ------> TdbS bank !draw_bank
//!                                      +--> video (AXI4-Stream: tdata RGB888, tvalid/tready, tuser, tlast)
//! ```
//!
//! Seed 001's two pipelines run in parallel and frames follow each other back to back:
//! * The host sends a triangle's colour-setup command as soon as the RC reports it visible; colour
//!   setup (a new triangle every 4 cycles) writes TdbS while the RC draws later triangles.
//! * The I-buffer and TdbS have two banks each (address bit 20 of `id_*`/`is_*`, bit 16 of `t_*`). The
//!   RC and colour setup use bank `draw_bank`, the CS the other. A `scan_start` that the CS takes (it
//!   is idle) swaps them: the frame just drawn is scanned out while the next one is drawn into the
//!   bank the CS scanned (and cleared behind it) before. The host starts a scan only when the frame is
//!   complete (the RC's end-of-frame result has come and colour setup is idle), and sends the next
//!   frame's commands only after the scan has started.
//! * The Z-buffer has one bank and is never cleared between frames: the RC reads the I-buffer word with
//!   each depth (`id_rd_*`, the same address and cycle as `z_rd_*`), and a depth under the background
//!   index counts as far (`rc::z_test`). Clearing the I-buffer behind the scan-out (`scan_clear_behind`)
//!   is therefore all the clearing a frame needs: no clear pass, and 24 bits per pixel less memory than
//!   a second Z bank. The CS's own Z clear-behind port is not connected.
//! * `clear` in a frame command (the RC clears its bank of the I-buffer and the Z-buffer, W*H cycles)
//!   is for the first use of each bank after reset, when the memories hold whatever they powered up with.
//!
//! Ports are the blocks' own (see `rc`, `cs::colour_setup`, `cs::color_shader`); memory read ports
//! have latency 1 and a read of an address being written returns the old word. The two I-buffer write
//! ports never write the same bank in one cycle.

pub mod back;
pub mod back_tex;
pub mod chipset3;
pub mod chipset_tex;

use crate::common::{StreamIn, StreamOut};
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, CS_MATERIAL_BITS};
use back::Back;
use crate::rc::{Rc, RcCommand, RcResult};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Chipset {
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
    /// The bank the RC and colour setup draw into (the address bit above, for a memory wrapper or a
    /// waveform reader); the CS scans the other one once a scan has started.
    pub draw_bank: Signal<Out, Bit>,

    rc: Rc,
    back: Back,
}

impl Chipset {
    /// A chipset for a `width` x `height` screen (1..=1024 each).
    pub fn new(width: u32, height: u32) -> Result<Chipset, String> {
        Ok(Chipset {
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
            draw_bank: Default::default(),
            rc: Rc::new(width, height)?,
            back: Back::new(width, height),
        })
    }
}

impl Logic for Chipset {
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

/// Verilog of the chipset for a `width` x `height` screen (module `chipset`).
pub fn verilog(width: u32, height: u32) -> Result<String, String> {
    let mut uut = Chipset::new(width, height)?;
    uut.connect_all();
    crate::common::verilog_named(&uut, "chipset")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chipset_passes_the_rust_hdl_checks_and_generates_a_top_named_chipset() {
        let v = verilog(32, 16).unwrap();
        assert!(v.contains("module chipset("), "no chipset module");
        assert!(Chipset::new(2000, 10).is_err());
    }
}
