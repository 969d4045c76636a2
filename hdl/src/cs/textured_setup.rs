//! `textured_setup`: colour setup and texture setup on one command stream (issue 17, item 4: "colour
//! setup produces the texture planes"), as the chipset will use them. A command is a colour-setup
//! command (`SetupCommand`) and, beside it on `tex`, the nine texture values of its vertices; both
//! blocks take it in the same cycle (they share the handshake: `ready` low for 3 cycles after a take),
//! and each writes its own memory at the triangle's index: TdbT 23 cycles later, TdbS 41.
//!
//! ```text
//!  cmd (valid/ready) ----------------------------+--> [ colour_setup ] --> tdbs_write_* (cycle 41)
//!  tex (9 x 33 b, with cmd) --> {index, x, y} + |
//!                                               +--> [ tex_setup ]    --> tdbt_write_* (cycle 23)
//! ```

use crate::common::StreamIn;
use crate::cs::colour_setup::ColourSetup;
use crate::cs::tex_setup::TexSetup;
use crate::cs::{SetupCommand, TdbsRecord, TdbtRecord, TexValues};
use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct TexturedSetup {
    pub clock: Signal<In, Clock>,
    /// Setup commands (valid/ready).
    pub cmd: StreamIn<SetupCommand>,
    /// The command's texture values, valid with it.
    pub tex: Signal<In, TexValues>,
    pub tdbs_write_enable: Signal<Out, Bit>,
    pub tdbs_write_address: Signal<Out, Bits<16>>,
    pub tdbs_write_data: Signal<Out, TdbsRecord>,
    pub tdbt_write_enable: Signal<Out, Bit>,
    pub tdbt_write_address: Signal<Out, Bits<16>>,
    pub tdbt_write_data: Signal<Out, TdbtRecord>,
    /// Either block has a command in progress.
    pub busy: Signal<Out, Bit>,
    colour: ColourSetup,
    texture: TexSetup,
}

impl Logic for TexturedSetup {
    #[hdl_gen]
    fn update(&mut self) {
        self.colour.clock.next = self.clock.val();
        self.texture.clock.next = self.clock.val();
        self.colour.cmd.valid.next = self.cmd.valid.val();
        self.colour.cmd.data.next = self.cmd.data.val();
        self.texture.cmd.valid.next = self.cmd.valid.val();
        self.texture.cmd.data.next.index = self.cmd.data.val().index;
        self.texture.cmd.data.next.x0 = self.cmd.data.val().x0;
        self.texture.cmd.data.next.y0 = self.cmd.data.val().y0;
        self.texture.cmd.data.next.x1 = self.cmd.data.val().x1;
        self.texture.cmd.data.next.y1 = self.cmd.data.val().y1;
        self.texture.cmd.data.next.x2 = self.cmd.data.val().x2;
        self.texture.cmd.data.next.y2 = self.cmd.data.val().y2;
        self.texture.cmd.data.next.values = self.tex.val();
        // The two ready signals are equal (one handshake rule); taking both keeps that visible.
        self.cmd.ready.next = self.colour.cmd.ready.val() & self.texture.cmd.ready.val();
        self.tdbs_write_enable.next = self.colour.tdbs_write_enable.val();
        self.tdbs_write_address.next = self.colour.tdbs_write_address.val();
        self.tdbs_write_data.next = self.colour.tdbs_write_data.val();
        self.tdbt_write_enable.next = self.texture.tdbt_write_enable.val();
        self.tdbt_write_address.next = self.texture.tdbt_write_address.val();
        self.tdbt_write_data.next = self.texture.tdbt_write_data.val();
        self.busy.next = self.colour.busy.val() | self.texture.busy.val();
    }
}

/// Verilog of the paired setup (module `textured_setup`).
pub fn verilog() -> Result<String, String> {
    let mut uut = TexturedSetup::default();
    uut.connect_all();
    crate::common::verilog_named(&uut, "textured_setup")
}
