//! Testbenches for PROOF (seed 002): the RTL OPP beside `golden::proof`'s cycle models.
//! * [`bench`]: every cycle on the ports, RustHDL direct drive vs `OppModel`, random gaps, VCDs;
//! * [`replay`]: the generated Verilog of the OPP replays the recorded vectors (Icarus / Verilator);
//! * [`backend`]: the RTL backend of `idxrender render --arch proof --backend rtl`.

pub mod backend;
pub mod bench;
pub mod convert;
pub mod replay;
pub mod shade_bench;
pub mod stage_replay;
#[cfg(test)]
mod stage_tests;
#[cfg(test)]
mod tests;
