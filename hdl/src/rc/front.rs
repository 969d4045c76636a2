//! `front`: the part of the RC that both of seed 000's types share: setup (with its record queue) and
//! the traversal, wired together. It takes commands and hands on one token per cycle to the
//! visibility test behind it: `z_test` (Type IV, top `rc`) or `tdbv_test` (Type III, top `rc3`).
//!
//! ```text
//!  cmd ---(valid/ready)--> [ setup ] --record--> [ traversal ] ---> tok (RcToken)
//!                                        |                    <--- result_free
//!                                        +--> tdbv_we, tdbv_wr_* (Type III: a walked triangle's depth
//!                                             plane, in the cycle the traversal takes it)
//! ```

use super::setup::{Setup, REC_WALK};
use super::traversal::{RcToken, Traversal};
use super::RcCommand;
use crate::common::StreamIn;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct RcFront {
    pub clock: Signal<In, Clock>,
    pub cmd: StreamIn<RcCommand>,
    /// The traversal's token of this cycle.
    pub tok: Signal<Out, RcToken>,
    /// A result token issued now will find room behind the visibility test.
    pub result_free: Signal<In, Bit>,
    /// TdbV write (Type III; `rc` leaves it unconnected): the depth plane of the triangle the traversal
    /// takes to walk in this cycle, at its index.
    pub tdbv_we: Signal<Out, Bit>,
    pub tdbv_wr_addr: Signal<Out, Bits<16>>,
    pub tdbv_wr_a: Signal<Out, Signed<40>>,
    pub tdbv_wr_b: Signal<Out, Signed<40>>,
    pub tdbv_wr_c: Signal<Out, Signed<56>>,

    setup: Setup,
    traversal: Traversal,
    rec_walk: Constant<Bits<2>>,
    k0_16: Constant<Bits<16>>,
    ks0_40: Constant<Signed<40>>,
    ks0_56: Constant<Signed<56>>,
}

impl RcFront {
    pub fn new(width: u32, height: u32) -> RcFront {
        RcFront {
            clock: Default::default(),
            cmd: Default::default(),
            tok: Default::default(),
            result_free: Default::default(),
            tdbv_we: Default::default(),
            tdbv_wr_addr: Default::default(),
            tdbv_wr_a: Default::default(),
            tdbv_wr_b: Default::default(),
            tdbv_wr_c: Default::default(),
            setup: Setup::new(width, height),
            traversal: Traversal::new(width, height),
            rec_walk: Constant::new(REC_WALK.into()),
            k0_16: Constant::new(0.into()),
            ks0_40: Constant::new(0i64.into()),
            ks0_56: Constant::new(0i64.into()),
        }
    }
}

impl Logic for RcFront {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, setup, traversal);
        StreamIn::<RcCommand>::link(&mut self.cmd, &mut self.setup.cmd);
        self.traversal.rec_valid.next = self.setup.rec_valid.val();
        self.setup.rec_ready.next = self.traversal.rec_ready.val();
        self.traversal.rec_kind.next = self.setup.rec_kind.val();
        self.traversal.rec_clear.next = self.setup.rec_clear.val();
        self.traversal.rec_index.next = self.setup.rec_index.val();
        self.traversal.rec_culled.next = self.setup.rec_culled.val();
        self.traversal.rec_zero_area.next = self.setup.rec_zero_area.val();
        self.traversal.rec_bx0.next = self.setup.rec_bx0.val();
        self.traversal.rec_bx1.next = self.setup.rec_bx1.val();
        self.traversal.rec_by0.next = self.setup.rec_by0.val();
        self.traversal.rec_by1.next = self.setup.rec_by1.val();
        self.traversal.rec_addr.next = self.setup.rec_addr.val();
        self.traversal.rec_e0.next = self.setup.rec_e0.val();
        self.traversal.rec_e1.next = self.setup.rec_e1.val();
        self.traversal.rec_e2.next = self.setup.rec_e2.val();
        self.traversal.rec_sx0.next = self.setup.rec_sx0.val();
        self.traversal.rec_sx1.next = self.setup.rec_sx1.val();
        self.traversal.rec_sx2.next = self.setup.rec_sx2.val();
        self.traversal.rec_sy0.next = self.setup.rec_sy0.val();
        self.traversal.rec_sy1.next = self.setup.rec_sy1.val();
        self.traversal.rec_sy2.next = self.setup.rec_sy2.val();
        self.traversal.rec_raw.next = self.setup.rec_raw.val();
        self.traversal.rec_a.next = self.setup.rec_a.val();
        self.traversal.rec_b.next = self.setup.rec_b.val();
        self.traversal.rec_sx3_0.next = self.setup.rec_sx3_0.val();
        self.traversal.rec_sx3_1.next = self.setup.rec_sx3_1.val();
        self.traversal.rec_sx3_2.next = self.setup.rec_sx3_2.val();
        self.traversal.rec_sx15_0.next = self.setup.rec_sx15_0.val();
        self.traversal.rec_sx15_1.next = self.setup.rec_sx15_1.val();
        self.traversal.rec_sx15_2.next = self.setup.rec_sx15_2.val();
        self.traversal.rec_a3.next = self.setup.rec_a3.val();
        self.tok.next = self.traversal.tok.val();
        self.traversal.result_free.next = self.result_free.val();

        self.tdbv_we.next = self.setup.rec_valid.val() & self.traversal.rec_ready.val() & (self.setup.rec_kind.val() == self.rec_walk.val());
        self.tdbv_wr_addr.next = self.k0_16.val();
        self.tdbv_wr_a.next = self.ks0_40.val();
        self.tdbv_wr_b.next = self.ks0_40.val();
        self.tdbv_wr_c.next = self.ks0_56.val();
        if self.tdbv_we.val() {
            self.tdbv_wr_addr.next = self.setup.rec_index.val();
            self.tdbv_wr_a.next = self.setup.rec_a.val();
            self.tdbv_wr_b.next = self.setup.rec_b.val();
            self.tdbv_wr_c.next = self.setup.rec_c.val();
        }
    }
}
