//! The bench loop of the CS's fixed-latency blocks (`texel_filter`, `texel_address`, `tex_coord`,
//! `tex_lod`): each takes one input per cycle, never stalls, and shows its answer a fixed number of
//! cycles later. The loop drives the RustHDL block, compares its outputs in every cycle with the
//! reference of the inputs `latency` cycles earlier, writes the VCD if asked, and records the vectors
//! for the Verilog replay (`crate::cs::replay`).

use crate::common::Trace;
use crate::cs::pack::BitVector;
use crate::cs::replay::{PortSpec, Recording};
use rust_hdl::prelude::*;
use std::fmt::Debug;
use std::path::Path;

/// How a bench talks to its block.
pub struct Pipeline<U, I, O> {
    /// The block's name, in messages.
    pub name: &'static str,
    /// Cycles from an input to its outputs.
    pub latency: usize,
    /// Drive one cycle's inputs.
    pub drive: fn(&mut U, &I),
    /// Set the clock.
    pub clock: fn(&mut U, bool),
    /// The output ports' values, in the order `outputs` names them.
    pub read: fn(&U) -> O,
    /// The output ports, for messages: `"(valid_out, rgb_out)"`.
    pub outputs: &'static str,
    /// One cycle's inputs and the outputs expected in it, as the replay's vectors.
    pub vectors: fn(&I, &O) -> (BitVector, BitVector),
    /// The replay's input and output ports.
    pub ports: (Vec<PortSpec>, Vec<PortSpec>),
}

impl<U: Block + Default, I: Debug, O: PartialEq + Debug> Pipeline<U, I, O> {
    /// Run `inputs` through the RustHDL block, comparing its outputs in every cycle with `want` of the
    /// inputs `latency` cycles earlier (`None` before the first). Returns the recording.
    pub fn run(&self, inputs: &[I], want: &dyn Fn(Option<&I>) -> O, vcd: Option<&Path>) -> Result<Recording, String> {
        let mut uut = U::default();
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("{} design check: {e:?}", self.name))?;
        let mut trace = Trace::new(&uut, vcd)?;
        let mut rec = Recording::new(self.ports.0.clone(), self.ports.1.clone());
        let lat = self.latency;
        for (t, inp) in inputs.iter().enumerate() {
            (self.drive)(&mut uut, inp);
            (self.clock)(&mut uut, false);
            if !simulate(&mut uut, 200) {
                return Err(format!("{} did not settle in cycle {t}", self.name));
            }
            trace.dump(&uut, 10 * t as u64)?;
            let earlier = t.checked_sub(lat).map(|k| &inputs[k]);
            let expected = want(earlier);
            let got = (self.read)(&uut);
            if got != expected {
                return Err(trace.fail(
                    t as u64,
                    format!("{} = {got:?}, expected {expected:?} (inputs of cycle {}: {earlier:?})", self.outputs, t as i64 - lat as i64),
                ));
            }
            let (vin, vout) = (self.vectors)(inp, &expected);
            rec.push(vin, vout);
            (self.clock)(&mut uut, true);
            if !simulate(&mut uut, 200) {
                return Err(format!("{} did not settle in cycle {t}", self.name));
            }
            trace.dump(&uut, 10 * t as u64 + 5)?;
        }
        trace.end(10 * inputs.len() as u64);
        Ok(rec)
    }
}
