//! The RTL backend of `idxrender render --arch proof --backend rtl`: the frame's object lists come from
//! the RustHDL OPP, checked against the cycle model in every cycle (`bench`).

use super::bench::run_frame;
use golden::proof::cycle_opp::OppRun;
use golden::proof::format::Entry;
use golden::proof::setup::ProofScene;
use std::path::Path;

/// The object lists of a frame built by the RTL OPP of `n_ops` OPs (FIFO depth `fifo_depth`).
pub fn opp_lists_rtl(scene: &ProofScene, n_ops: usize, fifo_depth: usize, vcd: Option<&Path>) -> Result<(Vec<Vec<Entry>>, OppRun), String> {
    let (run, _) = run_frame(scene.screen, &scene.objects, n_ops, fifo_depth, None, vcd, None)?;
    Ok((run.lists.clone(), run))
}
