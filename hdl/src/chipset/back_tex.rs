//! `BackTex`: [`super::back::Back`] with texture mapping (issue 17), behind the `chipset_tex` top's RC:
//! `textured_setup` (colour setup and texture setup on one command stream) in place of
//! `colour_setup`, and `cs_tex` in place of `cs`. TdbT, the texture half of the triangle database, is
//! banked as TdbS is (address bit 16 of `tt_*`): `textured_setup` writes the draw bank, the CS reads
//! the scan bank. The four texture banks and the CS's level table are the frame's texture, which the
//! host loads before it starts the scan, so they have one bank.
//!
//! * The bank swap and every port `Back` has work as there (see `chipset`).
//! * The texture's ports are `cs_tex`'s (see `cs::color_shader_tex`), named `tex_*`; `setup_tex` is
//!   `textured_setup`'s `tex`, valid with `setup_cmd`.

use crate::common::StreamIn;
use crate::cs::color_shader_tex::ColorShaderTex;
use crate::cs::texel_address::ADDR_BITS;
use crate::cs::textured_setup::TexturedSetup;
use crate::cs::{LightVectors, MaterialWord, SetupCommand, TdbsRecord, TdbtRecord, TexValues, CS_MATERIAL_BITS};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct BackTex {
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
    pub setup_tex: Signal<In, TexValues>,
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
    pub tt_re: Signal<Out, Bit>,
    pub tt_rd_addr: Signal<Out, Bits<17>>,
    pub tt_rd_data: Signal<In, TdbtRecord>,
    pub tt_we: Signal<Out, Bit>,
    pub tt_wr_addr: Signal<Out, Bits<17>>,
    pub tt_wr_data: Signal<Out, TdbtRecord>,
    pub scan_texture: Signal<In, Bit>,
    pub tex_w0_log2: Signal<In, Bits<4>>,
    pub tex_h0_log2: Signal<In, Bits<4>>,
    pub tex_last_level: Signal<In, Bits<4>>,
    pub tex_filter: Signal<In, Bits<2>>,
    pub tex_clamp: Signal<In, Bit>,
    pub tex_base_we: Signal<In, Bit>,
    pub tex_base_sel: Signal<In, Bits<4>>,
    pub tex_base_data: Signal<In, Bits<ADDR_BITS>>,
    pub tex_rd: Signal<Out, Bits<4>>,
    pub tex_addr0: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr1: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr2: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_addr3: Signal<Out, Bits<ADDR_BITS>>,
    pub tex_data0: Signal<In, Bits<24>>,
    pub tex_data1: Signal<In, Bits<24>>,
    pub tex_data2: Signal<In, Bits<24>>,
    pub tex_data3: Signal<In, Bits<24>>,
    pub draw_bank: Signal<Out, Bit>,

    setup: TexturedSetup,
    cs: ColorShaderTex,
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
    tta_rd: Signal<Local, Bits<17>>,
    tta_wr: Signal<Local, Bits<17>>,
    bank_i: Constant<Bits<21>>,
    bank_t: Constant<Bits<17>>,
    width: Constant<Bits<11>>,
    height: Constant<Bits<11>>,
}

impl BackTex {
    /// For a `width` x `height` screen (checked by the RC's constructor).
    pub fn new(width: u32, height: u32) -> BackTex {
        BackTex {
            clock: Default::default(),
            draw_re: Default::default(),
            draw_rd_addr: Default::default(),
            draw_rd_data: Default::default(),
            draw_we: Default::default(),
            draw_wr_addr: Default::default(),
            draw_wr_data: Default::default(),
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
            setup: TexturedSetup::default(),
            cs: ColorShaderTex::default(),
            draw_bank_r: Default::default(),
            scan_bank_r: Default::default(),
            scan_taken: Default::default(),
            ia_draw_rd: Default::default(),
            ia_draw_wr: Default::default(),
            ia_scan_rd: Default::default(),
            ia_scan_wr: Default::default(),
            ta_rd: Default::default(),
            ta_wr: Default::default(),
            tta_rd: Default::default(),
            tta_wr: Default::default(),
            bank_i: Constant::new((1u64 << 20).into()),
            bank_t: Constant::new((1u64 << 16).into()),
            width: Constant::new((width as u64).into()),
            height: Constant::new((height as u64).into()),
        }
    }
}

impl Logic for BackTex {
    #[hdl_gen]
    fn update(&mut self) {
        self.setup.clock.next = self.clock.val();
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

        // Shading: colour and texture setup write the draw banks of TdbS and TdbT.
        StreamIn::<SetupCommand>::link(&mut self.setup_cmd, &mut self.setup.cmd);
        self.setup.tex.next = self.setup_tex.val();
        self.setup_busy.next = self.setup.busy.val();
        self.ta_wr.next = bit_cast::<17, 16>(self.setup.tdbs_write_address.val());
        self.t_we.next = self.setup.tdbs_write_enable.val();
        self.t_wr_addr.next = self.ta_wr.val();
        if self.setup.tdbs_write_enable.val() & self.draw_bank_r.q.val() {
            self.t_wr_addr.next = self.ta_wr.val() | self.bank_t.val();
        }
        self.t_wr_data.next = self.setup.tdbs_write_data.val();
        self.tta_wr.next = bit_cast::<17, 16>(self.setup.tdbt_write_address.val());
        self.tt_we.next = self.setup.tdbt_write_enable.val();
        self.tt_wr_addr.next = self.tta_wr.val();
        if self.setup.tdbt_write_enable.val() & self.draw_bank_r.q.val() {
            self.tt_wr_addr.next = self.tta_wr.val() | self.bank_t.val();
        }
        self.tt_wr_data.next = self.setup.tdbt_write_data.val();

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
        self.tta_rd.next = bit_cast::<17, 16>(self.cs.tdbt_read_address.val());
        self.tt_re.next = self.cs.tdbt_read_enable.val();
        self.tt_rd_addr.next = self.tta_rd.val();
        if self.cs.tdbt_read_enable.val() & self.scan_bank_r.q.val() {
            self.tt_rd_addr.next = self.tta_rd.val() | self.bank_t.val();
        }
        self.cs.tdbt_read_data.next = self.tt_rd_data.val();
        // The texture: settings latched at start, the level table written while idle, four banks.
        self.cs.texture_enable.next = self.scan_texture.val();
        self.cs.tex_w0_log2.next = self.tex_w0_log2.val();
        self.cs.tex_h0_log2.next = self.tex_h0_log2.val();
        self.cs.tex_last_level.next = self.tex_last_level.val();
        self.cs.tex_filter.next = self.tex_filter.val();
        self.cs.tex_clamp.next = self.tex_clamp.val();
        self.cs.tex_base_we.next = self.tex_base_we.val();
        self.cs.tex_base_sel.next = self.tex_base_sel.val();
        self.cs.tex_base_data.next = self.tex_base_data.val();
        self.tex_rd.next = self.cs.tex_rd.val();
        self.tex_addr0.next = self.cs.tex_addr0.val();
        self.tex_addr1.next = self.cs.tex_addr1.val();
        self.tex_addr2.next = self.cs.tex_addr2.val();
        self.tex_addr3.next = self.cs.tex_addr3.val();
        self.cs.tex_data0.next = self.tex_data0.val();
        self.cs.tex_data1.next = self.tex_data1.val();
        self.cs.tex_data2.next = self.tex_data2.val();
        self.cs.tex_data3.next = self.tex_data3.val();
        self.video_tdata.next = self.cs.video_tdata.val();
        self.video_tvalid.next = self.cs.video_tvalid.val();
        self.cs.video_tready.next = self.video_tready.val();
        self.video_tuser.next = self.cs.video_tuser.val();
        self.video_tlast.next = self.cs.video_tlast.val();
    }
}
