//! Level 1 for PROOF: the RustHDL OPP (direct drive, GUIDE §5) and `golden::proof::cycle_opp::OppModel`
//! get the same inputs every cycle; every output port (and each OP's `free` and output register) is
//! compared before each rising edge. The first difference stops the run with the cycle, the port and
//! both values. Optionally writes a VCD and records the vectors for the Verilog replay.

use crate::common::{Trace, Watchdog};
use super::convert::{hex_of, params_to_rtl, slot_from_rtl, slot_to_rtl};
use super::replay::{inp, out, Port, Recorder};
use super::StageTop;
use golden::proof::cycle_opp::{drive_frame, Gaps, OppDrive, OppIn, OppModel, OppOut, OppRun};
use golden::proof::format::ObjectParams;
use golden::format::Screen;
use hdl::proof::{ObjParams, Opp, ProofSlot};
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

/// Iterations allowed for the combinational settling (the ready path crosses every OP).
const SETTLE: usize = 100_000;

/// Cycles with no load, no slot taken and none given before a PROOF bench gives up (no list needs
/// more than a few cycles per OP to pass).
pub const PROGRESS_LIMIT: u64 = 10_000;

/// The `opp` top's ports in the order of the recorded vectors' columns (inputs, then outputs). Every
/// output is compared in every cycle: the OPP's registers are all reset, so none is don't-care.
pub fn opp_ports() -> Vec<Port> {
    vec![
        inp("load", 1),
        inp("load_op", 16),
        inp("load_params", ObjParams::BITS),
        inp("upstream$valid", 1),
        inp("upstream$data", ProofSlot::BITS),
        inp("downstream$ready", 1),
        out("upstream$ready", 1, None),
        out("downstream$valid", 1, None),
        out("downstream$data", ProofSlot::BITS, None),
        out("any_free", 1, None),
        out("free_op", 16, None),
    ]
}

/// One cycle's values in `opp_ports` order, as hex.
pub fn opp_vector(inp: &OppIn, exp: &OppOut) -> Vec<String> {
    let params: Bits<{ ObjParams::BITS }> = params_to_rtl(&inp.load.map(|l| l.1).unwrap_or_default()).into();
    let up: Bits<{ ProofSlot::BITS }> = slot_to_rtl(&inp.up_data).into();
    let down: Bits<{ ProofSlot::BITS }> = slot_to_rtl(&exp.down_data).into();
    let any_free = exp.free.iter().any(|&f| f);
    let free_op = exp.free.iter().rposition(|&f| f).unwrap_or(0);
    let bit = |b: bool| (b as u8).to_string();
    vec![
        bit(inp.load.is_some()),
        format!("{:04x}", inp.load.map(|l| l.0).unwrap_or(0)),
        hex_of(params),
        bit(inp.up_valid),
        hex_of(up),
        bit(inp.down_ready),
        bit(exp.up_ready),
        bit(exp.down_valid),
        hex_of(down),
        bit(any_free),
        format!("{free_op:04x}"),
    ]
}

pub struct OppBench {
    pub uut: Opp,
    pub model: OppModel,
    pub cycle: u64,
    trace: Trace,
    pub vectors: Option<Recorder>,
}

impl OppBench {
    pub fn new(n: usize, fifo_depth: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<OppBench, String> {
        let mut uut = Opp::new(n, fifo_depth)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("opp: design check failed: {e:?}"))?;
        let trace = Trace::new(&uut, vcd)?;
        Ok(OppBench {
            uut,
            model: OppModel::new(n, fifo_depth)?,
            cycle: 0,
            trace,
            vectors: vectors.map(|p| Recorder::create(p, &opp_ports())).transpose()?,
        })
    }

    fn fail(&self, what: String) -> String {
        self.trace.fail(self.cycle, what)
    }

    /// One clock on both sides; returns the (equal) outputs before the edge.
    pub fn cycle(&mut self, inp: &OppIn) -> Result<OppOut, String> {
        let u = &mut self.uut;
        u.load.next = inp.load.is_some();
        u.load_op.next = (inp.load.map(|l| l.0).unwrap_or(0) as u64).into();
        u.load_params.next = params_to_rtl(&inp.load.map(|l| l.1).unwrap_or_default());
        u.upstream.valid.next = inp.up_valid;
        u.upstream.data.next = slot_to_rtl(&inp.up_data);
        u.downstream.ready.next = inp.down_ready;
        u.clock.next = false.into();
        if !simulate(u, SETTLE) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle)?;
        let exp = self.model.outputs(inp.down_ready);
        let u = &self.uut;
        let got_ready = u.upstream.ready.val();
        let got_valid = u.downstream.valid.val();
        let got_data = slot_from_rtl(&u.downstream.data.val());
        if got_ready != exp.up_ready {
            return Err(self.fail(format!("upstream.ready rtl {got_ready} model {}", exp.up_ready)));
        }
        if got_valid != exp.down_valid {
            return Err(self.fail(format!("downstream.valid rtl {got_valid} model {}", exp.down_valid)));
        }
        if got_data != exp.down_data {
            return Err(self.fail(format!("downstream.data rtl {got_data:?} model {:?}", exp.down_data)));
        }
        for k in 0..self.model.ops.len() {
            let (f, mf) = (u.ops[k].free.val(), exp.free[k]);
            if f != mf {
                return Err(self.fail(format!("OP {k} free rtl {f} model {mf}")));
            }
            let (v, mv) = (u.ops[k].downstream.valid.val(), self.model.ops[k].out_valid);
            let d = slot_from_rtl(&u.ops[k].downstream.data.val());
            if v != mv || d != self.model.ops[k].out_data {
                return Err(self.fail(format!("OP {k} output rtl {v} {d:?} model {mv} {:?}", self.model.ops[k].out_data)));
            }
        }
        let any_free = exp.free.iter().any(|&f| f);
        let free_op = exp.free.iter().rposition(|&f| f).unwrap_or(0) as u64;
        if u.any_free.val() != any_free || u.free_op.val().to_u64() != free_op {
            return Err(self.fail(format!(
                "any_free/free_op rtl {}/{} model {any_free}/{free_op}",
                u.any_free.val(),
                u.free_op.val().to_u64()
            )));
        }
        if let Some(w) = self.vectors.as_mut() {
            w.cycle(&opp_vector(inp, &exp))?;
        }
        self.model.step(inp)?;
        let u = &mut self.uut;
        u.clock.next = true.into();
        if !simulate(u, SETTLE) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle + 5)?;
        self.cycle += 1;
        Ok(exp)
    }
}

/// An OPP top beside its cycle model (the RustHDL bench, and the generated Verilog under Verilator in
/// `super::verilated`): a [`StageTop`] whose model's OPs drive the object loader.
pub trait OppTop: StageTop<OppIn, OppOut> {
    /// The cycle model.
    fn model(&self) -> &OppModel;
}

super::rusthdl_stage_top!(OppBench, OppIn, OppOut);

impl OppTop for OppBench {
    fn model(&self) -> &OppModel {
        &self.model
    }
}

/// A frame through the RTL OPP beside its cycle model, driven by the golden feeder and sink; with
/// optional random gaps. Returns the lists and counts (equal to `golden::proof::cycle_opp::run_opp`'s).
/// With fewer OPs than the frame needs, the frame takes several passes (see [`run_frame_top`]).
pub fn run_frame(
    screen: Screen,
    objects: &[ObjectParams],
    n_ops: usize,
    fifo_depth: usize,
    gaps: Option<Gaps>,
    vcd: Option<&Path>,
    vectors: Option<PathBuf>,
) -> Result<(OppRun, Option<(PathBuf, u64)>), String> {
    let mut bench = OppBench::new(n_ops, fifo_depth, vcd, vectors)?;
    run_frame_top(&mut bench, screen, objects, fifo_depth, gaps)
}

/// A frame through an OPP top (FIFO depth `fifo_depth`) driven by the golden feeder and sink
/// (`golden::proof::cycle_opp::drive_frame`, the cycle model's own loop), with optional random gaps:
/// the lists and counts, and the recorded vectors if the top records. With fewer OPs than the frame
/// needs, the objects are split into passes and each pass's output stream is fed back as the next
/// pass's input, through the same top without a reset, exactly as `run_opp` does with the model.
pub fn run_frame_top<B: OppTop>(
    bench: &mut B,
    screen: Screen,
    objects: &[ObjectParams],
    fifo_depth: usize,
    gaps: Option<Gaps>,
) -> Result<(OppRun, Option<(PathBuf, u64)>), String> {
    let run = drive_frame(&mut Watched { top: bench, watchdog: Watchdog::new(PROGRESS_LIMIT) }, screen, objects, fifo_depth, gaps, &mut |_, _| {})?;
    let vec = match bench.take_vectors() {
        Some(w) => Some(w.finish()?),
        None => None,
    };
    Ok((run, vec))
}

/// An OPP top under the benches' watchdog (which names the waveform when it fires).
struct Watched<'a, B: OppTop> {
    top: &'a mut B,
    watchdog: Watchdog,
}

impl<B: OppTop> OppDrive for Watched<'_, B> {
    fn model(&self) -> &OppModel {
        self.top.model()
    }
    fn cycle(&mut self, inp: &OppIn) -> Result<OppOut, String> {
        self.top.cycle(inp)
    }
    fn watch(&mut self, progress: bool, phase: &dyn Fn() -> String) -> Result<(), String> {
        self.watchdog.check(self.top.cycles(), progress, phase, self.top.trace())
    }
}

/// Random triangles on a small screen, at most `max_ops` OPs needed with reuse; some big and some in
/// front of others so that lists have partial and full entries, insertions and drops.
pub fn random_objects(rng: &mut crate::common::Rng, screen: Screen, count: usize, max_ops: usize) -> Vec<ObjectParams> {
    let big_span = screen.width.max(screen.height) as i64;
    random_objects_shaped(rng, screen, count, max_ops, ObjectShape { span: 12, big_span, big_percent: 20, depths: 1 << 24 })
}

/// Right triangles with axis-aligned legs and every vertex on a pixel corner (legs of `legs.0` to
/// `legs.1` pixels, the right angle in any of the four corners, the legs any two of the three edges):
/// at the pixel centres beside a leg the distance plus the "none" threshold (half a pixel there) is
/// exactly 0, the one value where `d + t_none <= 0` tells a pixel outside from one inside.
pub fn axis_aligned_objects(rng: &mut crate::common::Rng, screen: Screen, count: usize, max_ops: usize, legs: (u64, u64)) -> Vec<ObjectParams> {
    set_up_objects(rng, screen, count, max_ops, |rng| {
        let (x, y) = (rng.below(screen.width as u64 + 2) as i32 - 1, rng.below(screen.height as u64 + 2) as i32 - 1);
        let mut leg = || (legs.0 + rng.below(legs.1 - legs.0 + 1)) as i32;
        let (a, b) = (leg(), leg());
        let (sx, sy) = (if rng.chance(50) { 1 } else { -1 }, if rng.chance(50) { 1 } else { -1 });
        let z = rng.below(1 << 24) as u32;
        let one = golden::format::SUBPIXEL_ONE;
        let corner = |px: i32, py: i32| golden::format::WinVertex { x: px * one, y: py * one, z };
        // Rotated, so that each of the three edges (in the order with det > 0) is a leg in some objects.
        let mut v = [corner(x, y), corner(x + sx * a, y), corner(x, y + sy * b)];
        v.rotate_left(rng.below(3) as usize);
        v
    })
}

/// Which threshold [`threshold_objects`] puts its edges on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Threshold {
    /// `d = t_full`: the one value where `d >= t_full` tells full from partial.
    Full,
    /// `d = -t_none + offset`: with offset 0 or 1, a value where `d <= -t_none` and a threshold 16
    /// LSB higher (offset 0) or lower (offset 1) disagree.
    None(i64),
}

/// The objects [`threshold_objects`] starts from: vertices within 4 pixels of a centre, a fifth within 10.
const THRESHOLD_OBJECT_SHAPE: ObjectShape = ObjectShape { span: 8, big_span: 20, big_percent: 20, depths: 1 << 24 };

/// `count` small random objects ([`THRESHOLD_OBJECT_SHAPE`]) with every
/// edge moved (its `d0` only, by at most half a pixel step) so that at one pixel of the box its
/// distance sits exactly on `threshold` while the other two edges there are past theirs (for `Full`:
/// at least their `t_full`; else above their `-t_none`). A threshold moved by one LSB (`Full`) or 16
/// LSB (`None`) then changes that pixel's entry.
pub fn threshold_objects(rng: &mut crate::common::Rng, screen: Screen, count: usize, max_ops: usize, threshold: Threshold) -> Vec<ObjectParams> {
    use golden::proof::format::{wrap, EDGE_BITS};
    let mut objs = random_objects_shaped(rng, screen, count, max_ops, THRESHOLD_OBJECT_SHAPE);
    for o in objs.iter_mut() {
        for k in 0..3 {
            let e = o.edges[k];
            let target = match threshold {
                Threshold::Full => e.t_full as i64,
                Threshold::None(offset) => -(e.t_none as i64) + offset,
            };
            // The pixel where edge k is nearest its target and the other edges are past theirs.
            let best = (o.y0..=o.y1)
                .flat_map(|y| (o.x0..=o.x1).map(move |x| (x, y)))
                .filter_map(|(x, y)| {
                    let (d, _, _) = o.accumulators_at(x, y);
                    let others_past = (0..3).filter(|&m| m != k).all(|m| match threshold {
                        Threshold::Full => d[m] >= o.edges[m].t_full as i64,
                        Threshold::None(_) => d[m] > -(o.edges[m].t_none as i64),
                    });
                    others_past.then_some(d[k] - target)
                })
                .min_by_key(|off| off.abs());
            if let Some(off) = best {
                o.edges[k].d0 = wrap(e.d0 as i64 - off, EDGE_BITS) as i32;
            }
        }
    }
    objs
}

/// What [`random_objects_shaped`] draws: vertices within `span` pixels of a centre (`big_span` for
/// `big_percent` % of the objects), depths in `[0, depths)`.
#[derive(Clone, Copy, Debug)]
pub struct ObjectShape {
    pub span: i64,
    pub big_span: i64,
    pub big_percent: u64,
    pub depths: u64,
}

/// Random triangles of the given shape on a small screen, at most `max_ops` OPs needed with reuse.
pub fn random_objects_shaped(rng: &mut crate::common::Rng, screen: Screen, count: usize, max_ops: usize, shape: ObjectShape) -> Vec<ObjectParams> {
    let one = golden::format::SUBPIXEL_ONE as i64;
    let (w, h) = (screen.width as i64 * one, screen.height as i64 * one);
    set_up_objects(rng, screen, count, max_ops, |rng| {
        let big = rng.chance(shape.big_percent);
        let span = one * if big { shape.big_span } else { shape.span };
        let cx = rng.below((w + 4 * one) as u64) as i64 - 2 * one;
        let cy = rng.below((h + 4 * one) as u64) as i64 - 2 * one;
        [0, 1, 2].map(|_| golden::format::WinVertex {
            x: (cx + rng.below(span as u64) as i64 - span / 2) as i32,
            y: (cy + rng.below(span as u64) as i64 - span / 2) as i32,
            z: rng.below(shape.depths) as u32,
        })
    })
}

/// Up to `count` objects from the triangles `draw` gives (each with random vertex normals), skipping
/// those the setup rejects and those that would need more than `max_ops` OPs; at most `10 * count`
/// tries.
fn set_up_objects(
    rng: &mut crate::common::Rng,
    screen: Screen,
    count: usize,
    max_ops: usize,
    mut draw: impl FnMut(&mut crate::common::Rng) -> [golden::format::WinVertex; 3],
) -> Vec<ObjectParams> {
    let mut objs: Vec<ObjectParams> = Vec::new();
    let mut tries = 0;
    while objs.len() < count && tries < 10 * count {
        tries += 1;
        let v = draw(rng);
        let n = [0, 1, 2].map(|_| [0, 1, 2].map(|_| rng.below(32768) as i64 - 16384));
        if let Some(p) = golden::proof::setup::object_setup(&v, n, objs.len() as u16, screen) {
            objs.push(p);
            if golden::proof::render::ops_needed(screen, &objs) as usize > max_ops {
                objs.pop();
            }
        }
    }
    objs
}

#[cfg(test)]
mod threshold_tests {
    use super::*;
    use golden::proof::format::classify;

    /// Whether moving edge k's threshold (`t_full` by `full_by`, `t_none` by `none_by`) changes the
    /// coverage of some pixel of the object's box.
    fn moved_threshold_shows(o: &ObjectParams, k: usize, full_by: i64, none_by: i64) -> bool {
        let mut m = *o;
        m.edges[k].t_full = (m.edges[k].t_full as i64 + full_by) as u32;
        m.edges[k].t_none = (m.edges[k].t_none as i64 + none_by) as u32;
        (o.y0..=o.y1).any(|y| {
            (o.x0..=o.x1).any(|x| {
                let (d, _, _) = o.accumulators_at(x, y);
                classify(o, d) != classify(&m, d)
            })
        })
    }

    #[test]
    fn threshold_objects_change_coverage_when_a_threshold_moves_by_one_step() {
        let screen = Screen::new(24, 16).unwrap();
        let edges_showing = |threshold: Threshold, full_by: i64, none_by: i64| -> (usize, usize, usize) {
            let objs = threshold_objects(&mut crate::common::Rng::new(0x7e51d), screen, 48, 8, threshold);
            let plain = random_objects_shaped(&mut crate::common::Rng::new(0x7e51d), screen, 48, 8, THRESHOLD_OBJECT_SHAPE);
            let count = |objs: &[ObjectParams]| objs.iter().map(|o| (0..3).filter(|&k| moved_threshold_shows(o, k, full_by, none_by)).count()).sum::<usize>();
            (count(&objs), count(&plain), 3 * objs.len())
        };
        for (threshold, full_by, none_by) in [(Threshold::Full, 1, 0), (Threshold::None(0), 0, 16), (Threshold::None(1), 0, -16)] {
            let (shown, plain, edges) = edges_showing(threshold, full_by, none_by);
            eprintln!("{threshold:?}: t_full {full_by:+}, t_none {none_by:+} changes some pixel for {shown} of {edges} edges (random objects: {plain})");
            // Most edges meet their target (a later edge's move can undo an earlier one's pixel);
            // the same random objects without the moves almost never sit this exactly on a threshold.
            assert!(edges >= 120 && shown * 3 >= edges * 2, "{threshold:?}: {shown} of {edges}");
            assert!(plain * 10 < shown, "{threshold:?}: random objects {plain}, threshold objects {shown}");
        }
    }
}
