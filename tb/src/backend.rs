//! What the CLI needs of a cycle-counting chipset backend beyond `golden::render::Chipset`, so that
//! `render --backend rtl` (the RustHDL simulation, [`crate::chipset::RtlChipset`]) and
//! `render --backend verilator` (the generated Verilog, [`crate::verilator::VerilatorChipset`]) share
//! one code path.

use crate::chipset::{PhaseCycles, RtlChipset};
use crate::verilator::VerilatorChipset;
use golden::render::Chipset;

/// A chipset simulation that counts cycles per phase and may write a VCD.
pub trait CycleChipset: Chipset {
    /// Cycles per phase of the last frame.
    fn phases(&self) -> PhaseCycles;
    /// Close (flush) the VCD, if any.
    fn finish_vcd(&mut self);
}

impl CycleChipset for RtlChipset {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn finish_vcd(&mut self) {
        RtlChipset::finish_vcd(self)
    }
}

impl CycleChipset for VerilatorChipset {
    fn phases(&self) -> PhaseCycles {
        self.phases.clone()
    }
    fn finish_vcd(&mut self) {
        VerilatorChipset::finish_vcd(self)
    }
}
