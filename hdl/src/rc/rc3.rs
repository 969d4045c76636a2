//! `rc3`: the Rasterizer Controller of seed 000's Type III (index rendering without a Z-buffer). The
//! setup and the traversal are the Type IV RC's (`rc`), the same [`RcFront`]; the Z-test is replaced by [`TdbvTest`], which
//! regenerates the old depth of a pixel from TdbV, the depth plane of the triangle the I-buffer names.
//! The Verilog top module is `rc3`.
//!
//! ```text
//!                +---------+  record  +-----------+  token   +-----------+
//!  cmd --------->|  setup  |--------->| traversal |--------->| tdbv_test |---> result (valid/ready)
//!  (valid/ready) |         |    |     |           |--+       |  F1 F2 F3 |---> i_we/i_wr_addr/i_wr_data
//!                +---------+    |     +-----------+  |       +-----------+<--- i_rd_data
//!                               |                    |          |     ^
//!                               |                    |          v     +------ tdbv_rd_a/b/c
//!                               +--> tdbv_we/...     +--> i_re/i_rd_addr    tdbv_re/tdbv_rd_addr
//! ```
//!
//! Ports (one clock; the command and result ports are `rc`'s):
//! * I-buffer: read port `i_re`/`i_rd_addr` with `i_rd_data` one cycle later (the contents before a
//!   write at the same edge); write port `i_we`/`i_wr_addr`/`i_wr_data`. Address = y * width + x.
//! * TdbV (2^16 records of a depth plane: A and B 40 bits, C 56 bits, `golden::format::Plane`): read
//!   port `tdbv_re`/`tdbv_rd_addr` (a triangle index) with `tdbv_rd_a`/`_b`/`_c` one cycle later;
//!   write port `tdbv_we`/`tdbv_wr_addr`/`tdbv_wr_a`/`_b`/`_c`, written in the cycle the traversal
//!   takes a triangle to walk, before its first fragment. TdbV is behind a port, as the I-buffer and
//!   TdbS are: at 16 index bits it holds 2^16 x 136 bits = 1.1 MB, more than the block RAM of the
//!   LFE5U-45F (243 KB); a design with a narrower index can put it in block RAM behind the same port
//!   (synchronous read, one cycle: what EBR does).
//! * No Z-buffer port.
//!
//! Timing: `golden::cycle::rc` with `RcType::III` (docs/rc.md, "Type III").

use super::front::RcFront;
use super::tdbv_test::TdbvTest;
use super::traversal::TOK_FRAG;
use super::{RcCommand, RcResult};
use crate::common::{StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Rc3 {
    pub clock: Signal<In, Clock>,
    /// Commands (as `rc`'s).
    pub cmd: StreamIn<RcCommand>,
    /// Per-triangle results and the end-of-frame marker (as `rc`'s).
    pub result: StreamOut<RcResult>,
    /// I-buffer read enable; `i_rd_data` holds the index at `i_rd_addr` in the next cycle.
    pub i_re: Signal<Out, Bit>,
    pub i_rd_addr: Signal<Out, Bits<20>>,
    /// The index read in the previous cycle (0: the background, a free pixel).
    pub i_rd_data: Signal<In, Bits<16>>,
    /// I-buffer write enable, address and triangle index, written at the rising edge.
    pub i_we: Signal<Out, Bit>,
    pub i_wr_addr: Signal<Out, Bits<20>>,
    pub i_wr_data: Signal<Out, Bits<16>>,
    /// TdbV read enable and address (a triangle index); the record arrives in the next cycle.
    pub tdbv_re: Signal<Out, Bit>,
    pub tdbv_rd_addr: Signal<Out, Bits<16>>,
    /// The TdbV record read in the previous cycle: the depth plane's A, B (40 bits) and C (56 bits).
    pub tdbv_rd_a: Signal<In, Signed<40>>,
    pub tdbv_rd_b: Signal<In, Signed<40>>,
    pub tdbv_rd_c: Signal<In, Signed<56>>,
    /// TdbV write: a walked triangle's depth plane at its index, at the rising edge.
    pub tdbv_we: Signal<Out, Bit>,
    pub tdbv_wr_addr: Signal<Out, Bits<16>>,
    pub tdbv_wr_a: Signal<Out, Signed<40>>,
    pub tdbv_wr_b: Signal<Out, Signed<40>>,
    pub tdbv_wr_c: Signal<Out, Signed<56>>,

    front: RcFront,
    vis: TdbvTest,
    tok_frag: Constant<Bits<2>>,
    k0_20: Constant<Bits<20>>,
}

impl Rc3 {
    /// A Type III RC for a `width` x `height` screen, 1..=1024 each.
    pub fn new(width: u32, height: u32) -> Result<Rc3, String> {
        if !(1..=1024).contains(&width) || !(1..=1024).contains(&height) {
            return Err(format!("rc3: screen size {width}x{height} is not supported: width and height must be 1..=1024"));
        }
        Ok(Rc3 {
            clock: Default::default(),
            cmd: Default::default(),
            result: Default::default(),
            i_re: Default::default(),
            i_rd_addr: Default::default(),
            i_rd_data: Default::default(),
            i_we: Default::default(),
            i_wr_addr: Default::default(),
            i_wr_data: Default::default(),
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
            front: RcFront::new(width, height),
            vis: TdbvTest::default(),
            tok_frag: Constant::new(TOK_FRAG.into()),
            k0_20: Constant::new(0.into()),
        })
    }
}

impl Logic for Rc3 {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, front, vis);
        StreamIn::<RcCommand>::link(&mut self.cmd, &mut self.front.cmd);
        StreamOut::<RcResult>::link(&mut self.result, &mut self.vis.result);

        self.vis.tok.next = self.front.tok.val();
        self.front.result_free.next = self.vis.result_free.val();
        self.tdbv_we.next = self.front.tdbv_we.val();
        self.tdbv_wr_addr.next = self.front.tdbv_wr_addr.val();
        self.tdbv_wr_a.next = self.front.tdbv_wr_a.val();
        self.tdbv_wr_b.next = self.front.tdbv_wr_b.val();
        self.tdbv_wr_c.next = self.front.tdbv_wr_c.val();

        // Memory ports.
        self.i_re.next = (self.front.tok.val().kind == self.tok_frag.val()) & self.front.tok.val().covered;
        self.i_rd_addr.next = self.k0_20.val();
        if self.i_re.val() {
            self.i_rd_addr.next = self.front.tok.val().addr;
        }
        self.vis.i_rd_data.next = self.i_rd_data.val();
        self.tdbv_re.next = self.vis.tdbv_re.val();
        self.tdbv_rd_addr.next = self.vis.tdbv_rd_addr.val();
        self.vis.tdbv_rd_a.next = self.tdbv_rd_a.val();
        self.vis.tdbv_rd_b.next = self.tdbv_rd_b.val();
        self.vis.tdbv_rd_c.next = self.tdbv_rd_c.val();
        self.i_we.next = self.vis.i_we.val();
        self.i_wr_addr.next = self.vis.i_wr_addr.val();
        self.i_wr_data.next = self.vis.i_wr_data.val();
    }
}

/// The Type III top as Verilog (module `rc3`) for a `width` x `height` screen.
pub fn verilog(width: u32, height: u32) -> Result<String, String> {
    let mut uut = Rc3::new(width, height)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("rc3: design check failed: {e:?}"))?;
    Ok(crate::common::rename_top(&generate_verilog(&uut), "rc3"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_verilog_names_the_type_iii_top_rc3_and_has_no_z_buffer_port() {
        let v = verilog(64, 48).unwrap();
        assert!(v.contains("module rc3(clock,"));
        assert!(v.contains("tdbv_rd_c") && v.contains("i_rd_addr"));
        let header = &v[v.find("module rc3(").unwrap()..];
        let header = &header[..header.find(';').unwrap()];
        assert!(!header.contains("z_"), "{header}");
    }
}
