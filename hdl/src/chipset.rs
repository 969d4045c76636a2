//! `chipset`: seed 001's raster chipset (Fig. 5) as one top: the Rasterizer Controller, colour setup
//! and the Color Shader around the shared buffers, whose memory ports are at the top so that the same
//! RTL can use FPGA block RAM or external SRAM.
//!
//! ```text
//!  host (upper pipeline)                                               +-------------------+
//!   rc_cmd ---(valid/ready)--> [ rc ] --- z read/write ---------------->| Z-buffer  (W*H x 24)
//!   rc_result <-(valid/ready)-   |   \--- i write -------+------------->| I-buffer  (W*H x 16)
//!                                |                       |  +---------->|                   |
//!  host (lower pipeline)         |                       |  |  i read <-|                   |
//!   setup_cmd -(valid/ready)-> [ colour_setup ] -- tdbs write --------->| TdbS (2^16 x 424) |
//!                                                        |  |  tdbs rd <-+-------------------+
//!  scan_start, scan_background,                          |  |
//!  scan_clear_behind, scan_phong,                        |  |
//!  light_write_*, material_write_* -> [ cs ] -- i read, tdbs read, clear-behind i/z writes
//!                               +--> video (AXI4-Stream: tdata RGB888, tvalid/tready, tuser, tlast)
//! ```
//!
//! The three blocks work in phases that the host sequences as seed 001's dual pipeline does:
//! geometry (the RC, until its end-of-frame result), colour setup of the visible triangles, scan-out.
//! The Z- and I-buffer write ports are shared by the RC and the CS's clear-behind: the CS's write wins
//! when both are enabled, which the host's phases never let happen. Clear strategy: the CS clears both
//! buffers behind its scan-out (`scan_clear_behind`), so the next frame starts with a frame command
//! whose `clear` bit is 0 and costs no clear cycles; `clear` = 1 (a W*H-cycle clear by the RC) is for
//! the first frame after reset, when the buffers hold whatever the memory powered up with.
//!
//! Ports are the blocks' own (see `rc`, `cs::colour_setup`, `cs::color_shader`); memory read ports
//! have latency 1 and a read of an address being written returns the old word.

use crate::common::{StreamIn, StreamOut};
use crate::cs::color_shader::ColorShader;
use crate::cs::colour_setup::ColourSetup;
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, CS_MATERIAL_BITS};
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
    /// The CS's Phong constants (see `cs::color_shader`): write while `scan_busy` is low.
    pub light_write_enable: Signal<In, Bit>,
    pub light_write_address: Signal<In, Bits<2>>,
    pub light_write_data: Signal<In, LightVectors>,
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
    // Z-buffer (W*H words of 24 bits; address y*W + x)
    /// Read enable and address (the RC's Z-test); `z_rd_data` holds the word one cycle later.
    pub z_re: Signal<Out, Bit>,
    pub z_rd_addr: Signal<Out, Bits<20>>,
    pub z_rd_data: Signal<In, Bits<24>>,
    /// Write port (the RC's Z-test passes and clear, the CS's clear-behind).
    pub z_we: Signal<Out, Bit>,
    pub z_wr_addr: Signal<Out, Bits<20>>,
    pub z_wr_data: Signal<Out, Bits<24>>,
    // I-buffer (W*H words of 16 bits)
    /// Read port (the CS's scan-out).
    pub i_re: Signal<Out, Bit>,
    pub i_rd_addr: Signal<Out, Bits<20>>,
    pub i_rd_data: Signal<In, Bits<16>>,
    /// Write port (the RC's passes and clear, the CS's clear-behind).
    pub i_we: Signal<Out, Bit>,
    pub i_wr_addr: Signal<Out, Bits<20>>,
    pub i_wr_data: Signal<Out, Bits<16>>,
    // TdbS (2^16 records of 424 bits, address = triangle index)
    /// Read port (the CS).
    pub t_re: Signal<Out, Bit>,
    pub t_rd_addr: Signal<Out, Bits<16>>,
    pub t_rd_data: Signal<In, TdbsRecord>,
    /// Write port (colour setup).
    pub t_we: Signal<Out, Bit>,
    pub t_wr_addr: Signal<Out, Bits<16>>,
    pub t_wr_data: Signal<Out, TdbsRecord>,

    rc: Rc,
    colour_setup: ColourSetup,
    cs: ColorShader,
    width: Constant<Bits<11>>,
    height: Constant<Bits<11>>,
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
            i_re: Default::default(),
            i_rd_addr: Default::default(),
            i_rd_data: Default::default(),
            i_we: Default::default(),
            i_wr_addr: Default::default(),
            i_wr_data: Default::default(),
            t_re: Default::default(),
            t_rd_addr: Default::default(),
            t_rd_data: Default::default(),
            t_we: Default::default(),
            t_wr_addr: Default::default(),
            t_wr_data: Default::default(),
            rc: Rc::new(width, height)?,
            colour_setup: ColourSetup::default(),
            cs: ColorShader::default(),
            width: Constant::new((width as u64).into()),
            height: Constant::new((height as u64).into()),
        })
    }
}

impl Logic for Chipset {
    #[hdl_gen]
    fn update(&mut self) {
        self.rc.clock.next = self.clock.val();
        self.colour_setup.clock.next = self.clock.val();
        self.cs.clock.next = self.clock.val();

        // Geometry: the RC.
        StreamIn::<RcCommand>::link(&mut self.rc_cmd, &mut self.rc.cmd);
        StreamOut::<RcResult>::link(&mut self.rc_result, &mut self.rc.result);
        self.z_re.next = self.rc.z_re.val();
        self.z_rd_addr.next = self.rc.z_rd_addr.val();
        self.rc.z_rd_data.next = self.z_rd_data.val();

        // Shading: colour setup writes TdbS.
        StreamIn::<SetupCommand>::link(&mut self.setup_cmd, &mut self.colour_setup.cmd);
        self.setup_busy.next = self.colour_setup.busy.val();
        self.t_we.next = self.colour_setup.tdbs_write_enable.val();
        self.t_wr_addr.next = self.colour_setup.tdbs_write_address.val();
        self.t_wr_data.next = self.colour_setup.tdbs_write_data.val();

        // Scan-out: the CS reads the I-buffer and TdbS.
        self.cs.start.next = self.scan_start.val();
        self.cs.width.next = self.width.val();
        self.cs.height.next = self.height.val();
        self.cs.background.next = self.scan_background.val();
        self.cs.clear_behind.next = self.scan_clear_behind.val();
        self.cs.shading_phong.next = self.scan_phong.val();
        self.cs.light_write_enable.next = self.light_write_enable.val();
        self.cs.light_write_address.next = self.light_write_address.val();
        self.cs.light_write_data.next = self.light_write_data.val();
        self.cs.material_write_enable.next = self.material_write_enable.val();
        self.cs.material_write_address.next = self.material_write_address.val();
        self.cs.material_write_slot.next = self.material_write_slot.val();
        self.cs.material_write_data.next = self.material_write_data.val();
        self.scan_busy.next = self.cs.busy.val();
        self.i_re.next = self.cs.ibuf_read_enable.val();
        self.i_rd_addr.next = self.cs.ibuf_read_address.val();
        self.cs.ibuf_read_data.next = self.i_rd_data.val();
        self.t_re.next = self.cs.tdbs_read_enable.val();
        self.t_rd_addr.next = self.cs.tdbs_read_address.val();
        self.cs.tdbs_read_data.next = self.t_rd_data.val();
        self.video_tdata.next = self.cs.video_tdata.val();
        self.video_tvalid.next = self.cs.video_tvalid.val();
        self.cs.video_tready.next = self.video_tready.val();
        self.video_tuser.next = self.cs.video_tuser.val();
        self.video_tlast.next = self.cs.video_tlast.val();

        // Shared write ports: the CS's clear-behind, else the RC.
        self.z_we.next = self.rc.z_we.val();
        self.z_wr_addr.next = self.rc.z_wr_addr.val();
        self.z_wr_data.next = self.rc.z_wr_data.val();
        if self.cs.zbuf_write_enable.val() {
            self.z_we.next = true;
            self.z_wr_addr.next = self.cs.zbuf_write_address.val();
            self.z_wr_data.next = self.cs.zbuf_write_data.val();
        }
        self.i_we.next = self.rc.i_we.val();
        self.i_wr_addr.next = self.rc.i_wr_addr.val();
        self.i_wr_data.next = self.rc.i_wr_data.val();
        if self.cs.ibuf_write_enable.val() {
            self.i_we.next = true;
            self.i_wr_addr.next = self.cs.ibuf_write_address.val();
            self.i_wr_data.next = self.cs.ibuf_write_data.val();
        }
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
