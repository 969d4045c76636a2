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

/// A PROOF top beside its cycle model, one clock at a time: the RustHDL benches and the generated
/// Verilog under Verilator ([`verilated`]) alike, so that one driving loop per stage serves both
/// (`bench::run_frame_top`, `shade_bench::run_shade_top`, `filter_bench::run_filter_top`).
pub trait StageTop<I, O> {
    /// One clock on both sides, compared; the model's outputs before the edge.
    fn cycle(&mut self, i: &I) -> Result<O, String>;
    /// Clocks so far.
    fn cycles(&self) -> u64;
    /// The vector recorder, if the run records.
    fn take_vectors(&mut self) -> Option<replay::Recorder>;
    /// The waveform, for failure messages.
    fn trace(&self) -> Option<&crate::common::Trace>;
}

/// `StageTop` for a RustHDL bench with fields `cycle`, `vectors`, `trace` and a method `cycle`.
macro_rules! rusthdl_stage_top {
    ($bench:ty, $in:ty, $out:ty) => {
        impl $crate::proof::StageTop<$in, $out> for $bench {
            fn cycle(&mut self, i: &$in) -> Result<$out, String> {
                <$bench>::cycle(self, i)
            }
            fn cycles(&self) -> u64 {
                self.cycle
            }
            fn take_vectors(&mut self) -> Option<$crate::proof::replay::Recorder> {
                self.vectors.take()
            }
            fn trace(&self) -> Option<&$crate::common::Trace> {
                Some(&self.trace)
            }
        }
    };
}
pub(crate) use rusthdl_stage_top;
