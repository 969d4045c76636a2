//! `rc`: the Rasterizer Controller (seed 001 §2.3.1, §3): triangle setup, traversal with Pineda edge
//! functions, Z-test, Z-buffer and I-buffer writes, visibility flags. The Verilog top module is `rc`.
//!
//! ```text
//!                +---------+   record   +-----------+  token   +--------+
//!  cmd --------->|  setup  |----------->| traversal |--------->| z_test |---> result (valid/ready)
//!  (valid/ready) | (recip, |            | (clear,   |          |        |---> z_we/z_wr_addr/z_wr_data
//!                |  MulS)  |            |  walk)    |--+       |        |---> i_we/i_wr_addr/i_wr_data
//!                +---------+            +-----------+  |       +--------+<--- z_rd_data, i_rd_data
//!                                                      +------------------> z_re/z_rd_addr
//! ```
//!
//! Ports (one clock):
//! * `cmd` (StreamIn<[`RcCommand`]>): frame start (`clear`: the RC clears both buffers itself, W*H
//!   cycles), triangle, end of frame.
//! * `result` (StreamOut<[`RcResult`]>): one word per triangle in command order, then an `eof` word
//!   after the last triangle's result, once every write of the frame has been performed.
//! * Z-buffer: read port `z_re`/`z_rd_addr` with `z_rd_data` one cycle later (a read returns the contents
//!   before a write at the same edge); write port `z_we`/`z_wr_addr`/`z_wr_data`. I-buffer: write port
//!   `i_we`/`i_wr_addr`/`i_wr_data`, and `i_rd_data`, the index read with the depth (`z_re`/
//!   `z_rd_addr`): a background index marks the depth stale, so only the I-buffer needs clearing
//!   between frames (no Z clear pass). Address = y * width + x, 20 bits.
//!   Every data/address output is 0 while its enable/valid is low.
//!
//! Timing: see `docs/rc.md` and `golden::cycle::rc`, the cycle-accurate model it is checked against.
//! Index width: 16 bits (rust-hdl 0.46's `LogicStruct` cannot be generic, so the width is fixed).

pub mod front;
pub mod rc3;
pub mod fast_reciprocal;
pub mod reciprocal;
pub mod result_queue;
pub mod setup;
pub mod tdbv_test;
pub mod traversal;
pub mod z_test;

use crate::common::{StreamIn, StreamOut};
use rust_hdl::prelude::*;
use front::RcFront;
use z_test::ZTest;

/// Command kinds (`RcCommand::kind`); 3 is reserved and acts as a frame start without clear.
pub const CMD_FRAME: u64 = 0;
pub const CMD_TRIANGLE: u64 = 1;
pub const CMD_END_OF_FRAME: u64 = 2;
/// Cull modes (`RcCommand::cull`); 2 and 3 disable culling.
pub const CULL_BACK: u64 = 0;
pub const CULL_FRONT: u64 = 1;
pub const CULL_NONE: u64 = 2;

/// One command word: 214 bits, `kind` at bit 0.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RcCommand {
    /// CMD_FRAME, CMD_TRIANGLE or CMD_END_OF_FRAME.
    pub kind: Bits<2>,
    /// Frame start: the RC clears the Z-buffer (to 2^24-1) and the I-buffer (to 0) itself.
    pub clear: Bit,
    /// Triangle index, written to the I-buffer (0 is the background).
    pub index: Bits<16>,
    /// CULL_BACK, CULL_FRONT or CULL_NONE.
    pub cull: Bits<2>,
    /// The front face is clockwise on the screen (glFrontFace(GL_CW)).
    pub front_cw: Bit,
    /// Window vertices: x, y signed S11.8 (20 bits), z unsigned 24 bits.
    pub x0: Bits<20>,
    pub y0: Bits<20>,
    pub z0: Bits<24>,
    pub x1: Bits<20>,
    pub y1: Bits<20>,
    pub z1: Bits<24>,
    pub x2: Bits<20>,
    pub y2: Bits<20>,
    pub z2: Bits<24>,
}

/// One result word: 20 bits, `eof` at bit 0.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct RcResult {
    /// End of frame: every earlier triangle's result has been sent and its writes performed.
    pub eof: Bit,
    pub index: Bits<16>,
    /// Removed by culling (zero area or facing).
    pub culled: Bit,
    /// Culled because det = 0.
    pub zero_area: Bit,
    /// Some fragment passed the Z-test.
    pub visible: Bit,
}

#[derive(LogicBlock)]
pub struct Rc {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Commands.
    pub cmd: StreamIn<RcCommand>,
    // To the host
    /// Per-triangle results and the end-of-frame marker.
    pub result: StreamOut<RcResult>,
    // To the Z-buffer
    /// Read enable; `z_rd_data` holds the depth at `z_rd_addr` in the next cycle.
    pub z_re: Signal<Out, Bit>,
    pub z_rd_addr: Signal<Out, Bits<20>>,
    /// Write enable, address and depth, written at the rising edge.
    pub z_we: Signal<Out, Bit>,
    pub z_wr_addr: Signal<Out, Bits<20>>,
    pub z_wr_data: Signal<Out, Bits<24>>,
    // From the Z-buffer
    /// The depth read in the previous cycle.
    pub z_rd_data: Signal<In, Bits<24>>,
    // To the I-buffer
    /// Write enable, address and triangle index, written at the rising edge.
    pub i_we: Signal<Out, Bit>,
    pub i_wr_addr: Signal<Out, Bits<20>>,
    pub i_wr_data: Signal<Out, Bits<16>>,
    // From the I-buffer
    /// The index at `z_rd_addr`, read with `z_re` (same address, same cycle, same latency as the
    /// depth): where it is the background index (0) the depth read with it counts as 2^24-1.
    pub i_rd_data: Signal<In, Bits<16>>,

    front: RcFront,
    z_test: ZTest,
}

impl Rc {
    /// An RC for a `width` x `height` screen, 1..=1024 each.
    pub fn new(width: u32, height: u32) -> Result<Rc, String> {
        if !(1..=1024).contains(&width) || !(1..=1024).contains(&height) {
            return Err(format!("rc: screen size {width}x{height} is not supported: width and height must be 1..=1024"));
        }
        Ok(Rc {
            clock: Default::default(),
            cmd: Default::default(),
            result: Default::default(),
            z_re: Default::default(),
            z_rd_addr: Default::default(),
            z_we: Default::default(),
            z_wr_addr: Default::default(),
            z_wr_data: Default::default(),
            z_rd_data: Default::default(),
            i_we: Default::default(),
            i_wr_addr: Default::default(),
            i_wr_data: Default::default(),
            i_rd_data: Default::default(),
            front: RcFront::new(width, height),
            z_test: ZTest::default(),
        })
    }
}

impl Logic for Rc {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, front, z_test);
        StreamIn::<RcCommand>::link(&mut self.cmd, &mut self.front.cmd);
        StreamOut::<RcResult>::link(&mut self.result, &mut self.z_test.result);

        self.z_test.tok.next = self.front.tok.val();
        self.front.result_free.next = self.z_test.result_free.val();

        // Memory ports.
        self.z_re.next = self.z_test.z_re.val();
        self.z_rd_addr.next = self.z_test.z_rd_addr.val();
        self.z_test.z_rd_data.next = self.z_rd_data.val();
        self.z_test.i_rd_data.next = self.i_rd_data.val();
        self.z_we.next = self.z_test.z_we.val();
        self.z_wr_addr.next = self.z_test.z_wr_addr.val();
        self.z_wr_data.next = self.z_test.z_wr_data.val();
        self.i_we.next = self.z_test.i_we.val();
        self.i_wr_addr.next = self.z_test.i_wr_addr.val();
        self.i_wr_data.next = self.z_test.i_wr_data.val();
    }
}

/// The top as Verilog (module `rc`) for a `width` x `height` screen.
pub fn verilog(width: u32, height: u32) -> Result<String, String> {
    let mut uut = Rc::new(width, height)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("rc: design check failed: {e:?}"))?;
    Ok(crate::common::rename_top(&generate_verilog(&uut), "rc"))
}


#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rc_rejects_screen_sizes_outside_one_to_1024_with_the_reason() {
        assert!(Rc::new(0, 10).err().unwrap().contains("0x10"));
        assert!(Rc::new(1025, 10).err().unwrap().contains("1..=1024"));
        assert!(Rc::new(1024, 1024).is_ok());
    }

    #[test]
    fn generated_verilog_names_every_module_after_rc() {
        let v = verilog(64, 48).unwrap();
        assert!(v.contains("module rc(clock,"));
        assert!(v.contains("module rc$front$setup$recip("));
        assert!(!v.contains("top$") && !v.contains("module top"));
    }
}
