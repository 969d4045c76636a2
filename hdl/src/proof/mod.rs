//! PROOF's blocks (seed 002): the object processor and its FIFO, the object-processor pipeline, the
//! shading stage (light-source processors, look-up table RAMs), the filter stage (edge masks by the tree
//! of multiples, popcounts).
//! Payload formats in [`types`]; cycle behaviour specified by `golden::proof::cycle_op` and
//! `golden::proof::cycle_opp`, `cycle_shade` and `cycle_filter`.

pub mod edge_mask;
pub mod filter;
pub mod filter_front;
pub mod light_processor;
pub mod object_processor;
pub mod opp;
pub mod popcount;
pub mod shading;
pub mod slot_fifo;
pub mod table_ram;
pub mod types;

pub use filter::{verilog_filter, FilterStage};
pub use filter_front::FilterFront;
pub use object_processor::ObjectProcessor;
pub use opp::Opp;
pub use slot_fifo::SlotFifo;
pub use shading::{verilog_shading, ShadingStage};
pub use types::{FilterTag, FilteredPixel, ObjParams, ProofSlot, ShadeWork, ShadedSlot};

use rust_hdl::prelude::*;

/// The Verilog of an OPP of `n` OPs with FIFOs of `fifo_depth` slots, top module named `name`.
pub fn verilog_opp(name: &str, n: usize, fifo_depth: usize) -> Result<String, String> {
    let mut uut = Opp::new(n, fifo_depth)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(rename_top(&generate_verilog(&uut), name))
}

pub use crate::common::rename_top;
