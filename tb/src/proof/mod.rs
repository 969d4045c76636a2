//! Testbenches for PROOF (seed 002): the RTL OPP beside `golden::proof`'s cycle models.
//! * [`bench`]: every cycle on the ports, RustHDL direct drive vs `OppModel`, random gaps, VCDs;
//! * [`shade_bench`], [`filter_bench`], [`filter2x2_bench`]: every cycle, the shading stage and the
//!   filter stage (1x1 and 2x2 area, and the 2x2 box alone) vs their cycle models;
//! * [`replay`]: one port-list testbench; the generated Verilog of every PROOF top replays its recorded vectors (Icarus / Verilator);
//! * [`verilated`]: the same tops as generated Verilog under Verilator, beside the same cycle models;
//! * [`backend`]: the RTL and Verilator backends of `idxrender render --arch proof --backend rtl|verilator`.

pub mod backend;
pub mod bench;
pub mod convert;
pub mod filter2x2_bench;
pub mod filter_bench;
pub mod replay;
pub mod shade_bench;
pub mod verilated;
#[cfg(test)]
mod filter2x2_tests;
#[cfg(test)]
mod filter_tests;
#[cfg(test)]
mod stage_tests;
#[cfg(test)]
mod tests;
