//! Testbenches for PROOF (seed 002): the RTL OPP beside `golden::proof`'s cycle models.
//! * [`bench`]: every cycle on the ports, RustHDL direct drive vs `OppModel`, random gaps, VCDs;
//! * [`shade_bench`], [`filter_bench`]: every cycle, the shading and filter stages vs their cycle models;
//! * [`replay`], [`stage_replay`]: the generated Verilog replays the recorded vectors (Icarus / Verilator);
//! * [`backend`]: the RTL backend of `idxrender render --arch proof --backend rtl`.

pub mod backend;
pub mod bench;
pub mod convert;
pub mod filter_bench;
pub mod replay;
pub mod shade_bench;
pub mod stage_replay;
#[cfg(test)]
mod filter_tests;
#[cfg(test)]
mod stage_tests;
#[cfg(test)]
mod tests;
