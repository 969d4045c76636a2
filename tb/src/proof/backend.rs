//! The RTL backend of `idxrender render --arch proof --backend rtl`: the frame's object lists come from
//! the RustHDL OPP, checked against the cycle model in every cycle (`bench`), and every list entry is
//! coloured by the RustHDL shading stage, checked against its cycle model in every cycle
//! (`shade_bench`), and the shaded slots are filtered by the RustHDL filter stage, 1x1 box
//! (`filter_bench`) or the paper's 2x2 area (`filter2x2_bench`), checked against its cycle model in
//! every cycle. The Verilator backend (`*_verilator`) drives the generated Verilog of the same tops
//! with the same stimulus, beside the same cycle models (`super::verilated`).

use super::bench::run_frame;
use super::filter2x2_bench::run_filter2x2;
use super::filter_bench::{run_filter, FilterRun};
use super::shade_bench::run_shade;
use golden::proof::cycle_opp::OppRun;
use golden::proof::cycle_filter::scene_filter_config;
use golden::proof::cycle_shade::{shade_config, slots_of_lists, ShadedSlot};
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
    let (out, cycles) = shade_slots_rtl(scene, lists, vcd)?;
    let mut colours: Vec<Vec<[u8; 3]>> = lists.iter().map(|l| Vec::with_capacity(l.len())).collect();
    let w = scene.screen.width as usize;
    for o in out.iter().filter(|o| o.has_entry) {
        colours[o.y as usize * w + o.x as usize].push(o.rgb);
    }
    Ok((colours, cycles))
}

/// Every time slot of the frame's lists through the RTL shading stage (one light-source processor per
/// light): the shaded slots in stream order and the stage's cycles.
pub fn shade_slots_rtl(scene: &ProofScene, lists: &[Vec<Entry>], vcd: Option<&Path>) -> Result<(Vec<ShadedSlot>, u64), String> {
    let n_lights = scene.lights.l.len();
    let bits = table_bits(scene.objects.len());
    let cfg = shade_config(&scene.lights, &scene.material, n_lights, bits as u32)?;
    let slots = slots_of_lists(scene.screen.width, lists);
    let (out, cycles, _) = run_shade(n_lights, bits, &cfg, &slots, None, vcd, None)?;
    Ok((out, cycles))
}

/// The shaded slots through the RTL filter stage (1x1 box), its direction table loaded with the
/// scene's edge directions: the RGB888 image, the covered subpixels per pixel and the stage's cycles
/// (after the table loads).
pub fn filter_rtl(scene: &ProofScene, slots: &[ShadedSlot], vcd: Option<&Path>) -> Result<(Vec<u8>, Vec<u8>, u64), String> {
    let bits = table_bits(scene.objects.len());
    let run = run_filter(bits, &filter_cfg(scene, bits)?, slots, None, vcd, None)?;
    image_of(scene, &run)
}

/// The shaded slots through the RTL filter stage with the paper's 2x2 area (`Filter2x2Stage`, its
/// line buffer sized to the scene's screen): the RGB888 image, the covered subpixels per pixel and the
/// stage's cycles (after the table loads, until the last pixel of the flush has left).
pub fn filter2x2_rtl(scene: &ProofScene, slots: &[ShadedSlot], vcd: Option<&Path>) -> Result<(Vec<u8>, Vec<u8>, u64), String> {
    let bits = table_bits(scene.objects.len());
    let s = scene.screen;
    let run = run_filter2x2(bits, s.width, s.height, &filter_cfg(scene, bits)?, slots, None, vcd, None)?;
    image_of(scene, &run)
}

/// The configuration writes of the filter stage: the scene's edge directions, opacities and
/// background.
fn filter_cfg(scene: &ProofScene, bits: usize) -> Result<Vec<golden::proof::cycle_shade::CfgWrite>, String> {
    scene_filter_config(scene, bits as u32)
}

/// The image and coverage of a filter run, checking that it is the whole frame in raster order.
fn image_of(scene: &ProofScene, run: &FilterRun) -> Result<(Vec<u8>, Vec<u8>, u64), String> {
    let s = scene.screen;
    if run.pixels.len() != s.pixels() {
        return Err(format!("the filter stage gave {} pixels for a {}x{} frame", run.pixels.len(), s.width, s.height));
    }
    let mut rgb = Vec::with_capacity(s.pixels() * 3);
    let mut covered = Vec::with_capacity(s.pixels());
    for (p, px) in run.pixels.iter().enumerate() {
        let want = ((p as u32 % s.width) as u16, (p as u32 / s.width) as u16);
        if (px.x, px.y) != want {
            return Err(format!("the filter stage gave pixel ({}, {}) where ({}, {}) was due", px.x, px.y, want.0, want.1));
        }
        rgb.extend_from_slice(&px.rgb);
        covered.push(px.covered);
    }
    Ok((rgb, covered, run.cycles))
}

/// The object lists of a frame built by the generated Verilog of an OPP of `n_ops` OPs under
/// Verilator, compared with the cycle model in every cycle.
pub fn opp_lists_verilator(scene: &ProofScene, n_ops: usize, fifo_depth: usize, vcd: Option<&Path>) -> Result<(Vec<Vec<Entry>>, OppRun), String> {
    let mut top = super::verilated::VlOpp::new(n_ops, fifo_depth, vcd, None)?;
    let (run, _) = super::bench::run_frame_top(&mut top, scene.screen, &scene.objects, fifo_depth, None)?;
    Ok((run.lists.clone(), run))
}

/// Every time slot of the frame's lists through the generated Verilog of the shading stage under
/// Verilator (object table of `verilated::TABLE_BITS` address bits): the shaded slots and the cycles.
pub fn shade_slots_verilator(scene: &ProofScene, lists: &[Vec<Entry>], vcd: Option<&Path>) -> Result<(Vec<ShadedSlot>, u64), String> {
    use super::verilated::TABLE_BITS;
    let n_lights = scene.lights.l.len();
    let cfg = shade_config(&scene.lights, &scene.material, n_lights, TABLE_BITS as u32)?;
    let slots = slots_of_lists(scene.screen.width, lists);
    let mut top = super::verilated::VlShade::new(n_lights, vcd, None)?;
    let (out, cycles, _) = super::shade_bench::run_shade_top(&mut top, &cfg, &slots, None)?;
    Ok((out, cycles))
}

/// The shaded slots through the generated Verilog of the filter stage under Verilator: the 1x1 box
/// (`box2 = false`) or the 2x2 area built for the scene's screen. Returns what [`filter_rtl`] does.
pub fn filter_verilator(scene: &ProofScene, slots: &[ShadedSlot], box2: bool, vcd: Option<&Path>) -> Result<(Vec<u8>, Vec<u8>, u64), String> {
    use super::verilated::{VlFilter, TABLE_BITS};
    let s = scene.screen;
    let mut top = if box2 { VlFilter::box2(s.width, s.height, vcd, None)? } else { VlFilter::box1(vcd, None)? };
    let run = super::filter_bench::run_filter_top(&mut top, &filter_cfg(scene, TABLE_BITS)?, slots, None)?;
    image_of(scene, &run)
}
