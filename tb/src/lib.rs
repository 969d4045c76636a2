//! # tb: testbenches that put the RTL beside the golden model
//!
//! Three comparison levels (STYLE.md §5):
//! 1. every cycle on the ports: a RustHDL block (direct drive, GUIDE §5) and its cycle-accurate model
//!    in `golden::cycle` get the same stimulus; the first differing output stops the run with the
//!    cycle, the port, both values and the path of the VCD it leaves;
//! 2. per scene: buffers and images equal the algorithmic model's;
//! 3. the generated Verilog (Verilator or Icarus) replays the recorded vectors and is compared again.
//!
//! [`common`] holds what every bench shares: VCD locations, a seeded random source, tool discovery.

pub mod chipset;
pub mod common;
pub mod cs;
pub mod lint;
pub mod rc;
pub mod proof;
pub mod verilator;
pub mod backend;
pub mod mutation;
