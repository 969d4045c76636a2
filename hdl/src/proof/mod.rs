//! PROOF's blocks (seed 002): the object processor and its FIFO, the object-processor pipeline, the
//! shading stage (light-source processors, look-up table RAMs), the filter stage (edge masks by the tree
//! of multiples, blending cells per subpixel, popcounts) with the 1x1 area and with the paper's 2x2 area (quadrant sums, a streaming
//! box with a line buffer).
//! Payload formats in [`types`]; cycle behaviour specified by `golden::proof::cycle_op` and
//! `golden::proof::cycle_opp`, `cycle_shade`, `cycle_filter` and `cycle_filter2x2`.

pub mod background_share;
pub mod blend_cell;
pub mod box2x2;
pub mod edge_mask;
pub mod filter;
pub mod filter2x2;
pub mod filter_front;
pub mod light_processor;
pub mod object_processor;
pub mod opp;
pub mod popcount;
pub mod quadrant_popcount;
pub mod shading;
pub mod slot_fifo;
pub mod table_ram;
pub mod types;

pub use box2x2::{verilog_box2x2, Box2x2};
pub use filter::{verilog_filter, FilterStage};
pub use filter2x2::{verilog_filter2x2, Filter2x2Stage};
pub use filter_front::FilterFront;
pub use object_processor::ObjectProcessor;
pub use opp::Opp;
pub use slot_fifo::SlotFifo;
pub use shading::{verilog_shading, ShadingStage};
pub use types::{BoxA, BoxH, BoxLine, BoxV, FilterTag, FilteredPixel, ObjParams, ProofSlot, QuadPixel, ShadeWork, ShadedSlot};

use rust_hdl::prelude::*;

/// The Verilog of an OPP of `n` OPs with FIFOs of `fifo_depth` slots, top module named `name`; the
/// N copies of the object processor that rust-hdl writes are merged into one module
/// ([`crate::common::merge_identical_modules`]), so the text grows by one instance per OP.
pub fn verilog_opp(name: &str, n: usize, fifo_depth: usize) -> Result<String, String> {
    let mut uut = Opp::new(n, fifo_depth)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(crate::common::merge_identical_modules(&rename_top(&generate_verilog(&uut), name)))
}

pub use crate::common::rename_top;
