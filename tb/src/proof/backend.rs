//! The RTL backend of `idxrender render --arch proof --backend rtl`: the frame's object lists come from
//! the RustHDL OPP, checked against the cycle model in every cycle (`bench`), and every list entry is
//! coloured by the RustHDL shading stage, checked against its cycle model in every cycle
//! (`shade_bench`). The filter stage is still the golden model's (its RTL is not written yet).

use super::bench::run_frame;
use super::shade_bench::run_shade;
use golden::proof::cycle_opp::OppRun;
use golden::proof::cycle_shade::{shade_config, slots_of_lists};
use golden::proof::format::Entry;
use golden::proof::setup::ProofScene;
use std::path::Path;

/// The object lists of a frame built by the RTL OPP of `n_ops` OPs (FIFO depth `fifo_depth`).
pub fn opp_lists_rtl(scene: &ProofScene, n_ops: usize, fifo_depth: usize, vcd: Option<&Path>) -> Result<(Vec<Vec<Entry>>, OppRun), String> {
    let (run, _) = run_frame(scene.screen, &scene.objects, n_ops, fifo_depth, None, vcd, None)?;
    Ok((run.lists.clone(), run))
}

/// Address bits of the object table the RTL backend's shading stage needs for `objects` objects.
pub fn table_bits(objects: usize) -> usize {
    (usize::BITS - objects.max(2).saturating_sub(1).leading_zeros()) as usize
}

/// The colour of every list entry, from the RTL shading stage (one light-source processor per light);
/// returns the colours per pixel and the stage's cycles.
pub fn shade_lists_rtl(scene: &ProofScene, lists: &[Vec<Entry>], vcd: Option<&Path>) -> Result<(Vec<Vec<[u8; 3]>>, u64), String> {
    let n_lights = scene.lights.l.len();
    let bits = table_bits(scene.objects.len());
    let cfg = shade_config(&scene.lights, &scene.material, n_lights, bits as u32)?;
    let slots = slots_of_lists(scene.screen.width, lists);
    let (out, cycles, _) = run_shade(n_lights, bits, &cfg, &slots, None, vcd, None)?;
    let mut colours: Vec<Vec<[u8; 3]>> = lists.iter().map(|l| Vec::with_capacity(l.len())).collect();
    let w = scene.screen.width as usize;
    for o in out.iter().filter(|o| o.has_entry) {
        colours[o.y as usize * w + o.x as usize].push(o.rgb);
    }
    Ok((colours, cycles))
}
