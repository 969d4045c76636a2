//! The one handshake of the project: valid/ready, AXI-Stream style. A word moves on a rising edge
//! where both `valid` and `ready` are high; a producer holds `data` and `valid` until then.
//!
//! ```text
//!   producer (StreamOut)        consumer (StreamIn)
//!        data  ───────────────▶  data
//!        valid ───────────────▶  valid
//!        ready ◀───────────────  ready
//! ```

use rust_hdl::prelude::*;

/// Producer side.
#[derive(Clone, Debug, Default, LogicInterface)]
#[join = "StreamIn"]
pub struct StreamOut<T: Synth> {
    /// The word offered.
    pub data: Signal<Out, T>,
    /// `data` is valid this cycle.
    pub valid: Signal<Out, Bit>,
    /// The consumer takes the word this cycle if `valid` is high.
    pub ready: Signal<In, Bit>,
}

/// Consumer side.
#[derive(Clone, Debug, Default, LogicInterface)]
#[join = "StreamOut"]
pub struct StreamIn<T: Synth> {
    pub data: Signal<In, T>,
    pub valid: Signal<In, Bit>,
    pub ready: Signal<Out, Bit>,
}
