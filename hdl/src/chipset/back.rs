//! `Back`: what the `chipset` and `chipset3` tops share behind their RC: colour setup, the Color
//! Shader and the bank swap of the I-buffer and TdbS (seed 001's lower pipeline and scan-out). The RC
//! (`rc` or `rc3`) hands its I-buffer accesses in bank-free (`draw_*`, a pixel address y*W + x); this
//! block puts them in the draw bank, and the CS's in the scan bank.
//!
//! * The I-buffer and TdbS have two banks each (address bit 20 of `id_*`/`is_*`, bit 16 of `t_*`). The
//!   RC and colour setup use bank `draw_bank`, the CS the other. A `scan_start` that the CS takes (it
//!   is idle) swaps them.
//! * The ports are the tops' own, documented there (`chipset`).

use crate::common::StreamIn;
use crate::cs::color_shader::ColorShader;
use crate::cs::colour_setup::ColourSetup;
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Back {
    pub clock: Signal<In, Clock>,
    // The RC's I-buffer accesses, without the bank.
    pub draw_re: Signal<In, Bit>,
    pub draw_rd_addr: Signal<In, Bits<20>>,
    pub draw_rd_data: Signal<Out, Bits<16>>,
    pub draw_we: Signal<In, Bit>,
    pub draw_wr_addr: Signal<In, Bits<20>>,
    pub draw_wr_data: Signal<In, Bits<16>>,
    // The tops' ports (see `chipset`).
    pub setup_cmd: StreamIn<SetupCommand>,
    pub setup_busy: Signal<Out, Bit>,
    pub scan_start: Signal<In, Bit>,
    pub scan_background: Signal<In, Bits<24>>,
    pub scan_clear_behind: Signal<In, Bit>,
    pub scan_phong: Signal<In, Bit>,
    pub light_write_enable: Signal<In, Bit>,
    pub light_write_address: Signal<In, Bits<2>>,
    pub light_write_data: Signal<In, LightVectors>,
    pub material_write_enable: Signal<In, Bit>,
    pub material_write_address: Signal<In, Bits<CS_MATERIAL_BITS>>,
    pub material_write_slot: Signal<In, Bits<3>>,
    pub material_write_data: Signal<In, MaterialWord>,
    pub scan_busy: Signal<Out, Bit>,
    pub video_tdata: Signal<Out, Bits<24>>,
    pub video_tvalid: Signal<Out, Bit>,
    pub video_tready: Signal<In, Bit>,
    pub video_tuser: Signal<Out, Bit>,
    pub video_tlast: Signal<Out, Bit>,
    pub id_re: Signal<Out, Bit>,
    pub id_rd_addr: Signal<Out, Bits<21>>,
    pub id_rd_data: Signal<In, Bits<16>>,
    pub id_we: Signal<Out, Bit>,
    pub id_wr_addr: Signal<Out, Bits<21>>,
    pub id_wr_data: Signal<Out, Bits<16>>,
    pub is_re: Signal<Out, Bit>,
    pub is_rd_addr: Signal<Out, Bits<21>>,
    pub is_rd_data: Signal<In, Bits<16>>,
    pub is_we: Signal<Out, Bit>,
    pub is_wr_addr: Signal<Out, Bits<21>>,
    pub is_wr_data: Signal<Out, Bits<16>>,
    pub t_re: Signal<Out, Bit>,
    pub t_rd_addr: Signal<Out, Bits<17>>,
    pub t_rd_data: Signal<In, TdbsRecord>,
    pub t_we: Signal<Out, Bit>,
    pub t_wr_addr: Signal<Out, Bits<17>>,
    pub t_wr_data: Signal<Out, TdbsRecord>,
    pub draw_bank: Signal<Out, Bit>,

    colour_setup: ColourSetup,
    cs: ColorShader,
    /// Bank of the frame being drawn, and of the frame being scanned out: swapped when a scan starts.
    draw_bank_r: DFF<Bit>,
    scan_bank_r: DFF<Bit>,
    scan_taken: Signal<Local, Bit>,
    ia_draw_rd: Signal<Local, Bits<21>>,
    ia_draw_wr: Signal<Local, Bits<21>>,
    ia_scan_rd: Signal<Local, Bits<21>>,
    ia_scan_wr: Signal<Local, Bits<21>>,
    ta_rd: Signal<Local, Bits<17>>,
    ta_wr: Signal<Local, Bits<17>>,
    bank_i: Constant<Bits<21>>,
    bank_t: Constant<Bits<17>>,
    width: Constant<Bits<11>>,
    height: Constant<Bits<11>>,
}

impl Back {
    /// For a `width` x `height` screen (checked by the RC's constructor).
    pub fn new(width: u32, height: u32) -> Back {
        Back {
            clock: Default::default(),
            draw_re: Default::default(),
            draw_rd_addr: Default::default(),
            draw_rd_data: Default::default(),
            draw_we: Default::default(),
            draw_wr_addr: Default::default(),
            draw_wr_data: Default::default(),
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
            colour_setup: ColourSetup::default(),
            cs: ColorShader::default(),
            draw_bank_r: Default::default(),
            scan_bank_r: Default::default(),
            scan_taken: Default::default(),
            ia_draw_rd: Default::default(),
            ia_draw_wr: Default::default(),
            ia_scan_rd: Default::default(),
            ia_scan_wr: Default::default(),
            ta_rd: Default::default(),
            ta_wr: Default::default(),
            bank_i: Constant::new((1u64 << 20).into()),
            bank_t: Constant::new((1u64 << 16).into()),
            width: Constant::new((width as u64).into()),
            height: Constant::new((height as u64).into()),
        }
    }
}

impl Logic for Back {
    #[hdl_gen]
    fn update(&mut self) {
        self.colour_setup.clock.next = self.clock.val();
        self.cs.clock.next = self.clock.val();
        dff_setup!(self, clock, draw_bank_r, scan_bank_r);

        // Banks: a scan start the CS takes scans the bank just drawn, and drawing goes on in the other.
        self.scan_taken.next = self.scan_start.val() & !self.cs.busy.val();
        if self.scan_taken.val() {
            self.scan_bank_r.d.next = self.draw_bank_r.q.val();
            self.draw_bank_r.d.next = !self.draw_bank_r.q.val();
        }
        self.draw_bank.next = self.draw_bank_r.q.val();

        // The RC's I-buffer accesses, in the draw bank.
        self.ia_draw_rd.next = bit_cast::<21, 20>(self.draw_rd_addr.val());
        self.id_re.next = self.draw_re.val();
        self.id_rd_addr.next = self.ia_draw_rd.val();
        if self.draw_re.val() & self.draw_bank_r.q.val() {
            self.id_rd_addr.next = self.ia_draw_rd.val() | self.bank_i.val();
        }
        self.draw_rd_data.next = self.id_rd_data.val();
        self.ia_draw_wr.next = bit_cast::<21, 20>(self.draw_wr_addr.val());
        self.id_we.next = self.draw_we.val();
        self.id_wr_addr.next = self.ia_draw_wr.val();
        if self.draw_we.val() & self.draw_bank_r.q.val() {
            self.id_wr_addr.next = self.ia_draw_wr.val() | self.bank_i.val();
        }
        self.id_wr_data.next = self.draw_wr_data.val();

        // Shading: colour setup writes the draw bank of TdbS.
        StreamIn::<SetupCommand>::link(&mut self.setup_cmd, &mut self.colour_setup.cmd);
        self.setup_busy.next = self.colour_setup.busy.val();
        self.ta_wr.next = bit_cast::<17, 16>(self.colour_setup.tdbs_write_address.val());
        self.t_we.next = self.colour_setup.tdbs_write_enable.val();
        self.t_wr_addr.next = self.ta_wr.val();
        if self.colour_setup.tdbs_write_enable.val() & self.draw_bank_r.q.val() {
            self.t_wr_addr.next = self.ta_wr.val() | self.bank_t.val();
        }
        self.t_wr_data.next = self.colour_setup.tdbs_write_data.val();

        // Scan-out: the CS reads the scan bank of the I-buffer and TdbS and clears the I-buffer behind
        // (its Z-buffer clear-behind is not connected: no top needs a Z clear, see `chipset`).
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
        self.ia_scan_rd.next = bit_cast::<21, 20>(self.cs.ibuf_read_address.val());
        self.is_re.next = self.cs.ibuf_read_enable.val();
        self.is_rd_addr.next = self.ia_scan_rd.val();
        if self.cs.ibuf_read_enable.val() & self.scan_bank_r.q.val() {
            self.is_rd_addr.next = self.ia_scan_rd.val() | self.bank_i.val();
        }
        self.cs.ibuf_read_data.next = self.is_rd_data.val();
        self.ia_scan_wr.next = bit_cast::<21, 20>(self.cs.ibuf_write_address.val());
        self.is_we.next = self.cs.ibuf_write_enable.val();
        self.is_wr_addr.next = self.ia_scan_wr.val();
        if self.cs.ibuf_write_enable.val() & self.scan_bank_r.q.val() {
            self.is_wr_addr.next = self.ia_scan_wr.val() | self.bank_i.val();
        }
        self.is_wr_data.next = self.cs.ibuf_write_data.val();
        self.ta_rd.next = bit_cast::<17, 16>(self.cs.tdbs_read_address.val());
        self.t_re.next = self.cs.tdbs_read_enable.val();
        self.t_rd_addr.next = self.ta_rd.val();
        if self.cs.tdbs_read_enable.val() & self.scan_bank_r.q.val() {
            self.t_rd_addr.next = self.ta_rd.val() | self.bank_t.val();
        }
        self.cs.tdbs_read_data.next = self.t_rd_data.val();
        self.video_tdata.next = self.cs.video_tdata.val();
        self.video_tvalid.next = self.cs.video_tvalid.val();
        self.cs.video_tready.next = self.video_tready.val();
        self.video_tuser.next = self.cs.video_tuser.val();
        self.video_tlast.next = self.cs.video_tlast.val();
    }
}
