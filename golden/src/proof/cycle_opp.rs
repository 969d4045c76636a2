//! Cycle-accurate model of the object-processor pipeline (seed 002 §4): a chain of N object processors
//! ([`OpModel`]), and of what drives it: the geometry processor's object loader and pixel source
//! ([`Feeder`]) and the consumer of the lists ([`Sink`]). The RTL top `hdl::proof::opp` must match
//! [`OppModel`] on every port in every cycle.
//!
//! ```text
//!              load, load_op, load_params          free[N]
//!                 │                                  ▲
//!   up_data  ──▶ OP 0 ──▶ OP 1 ──▶ ... ──▶ OP N-1 ──▶ down_data
//!   up_valid ──▶                                    ──▶ down_valid
//!   up_ready ◀── (combinational through the chain)  ◀── down_ready
//! ```
//!
//! OP reuse (§4.2, "utilize a single OP several times per frame by objects that do not overlap in the
//! y-coordinate"): the feeder keeps the objects sorted by the raster position of their box's first
//! pixel (line first, then column, then id), loads the next one into the highest-numbered free OP (one
//! load per cycle), and does not push a pixel into the pipeline while an object whose box starts at or
//! before that pixel is still unloaded. An OP becomes free once its object's last box pixel has passed
//! it. With N at least [`super::render::ops_needed`] a frame is one pass.
//!
//! Fewer OPs than the frame needs (§4.2's proposal for scenes with more objects than OPs): the
//! objects are split into passes ([`passes`]), each of which needs at most N OPs, and the OPP's
//! output list stream of one pass is stored and goes round again as the input of the next pass, with
//! the next batch of objects ([`Feeder::pass`]). List insertion orders entries by (depth, id) and cuts
//! behind the first full entry, so the final lists do not depend on the batches.

use super::cycle_op::{Action, Decision, OpIn, OpModel, OpOut};
use super::format::{Entry, ObjectParams, Slot};
use crate::format::Screen;

/// Inputs of the OPP in one cycle.
#[derive(Clone, Debug, Default)]
pub struct OppIn {
    pub up_valid: bool,
    pub up_data: Slot,
    pub down_ready: bool,
    /// Load `params` into OP `op` at this edge.
    pub load: Option<(usize, ObjectParams)>,
}

/// Outputs of the OPP in one cycle.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OppOut {
    pub up_ready: bool,
    pub down_valid: bool,
    pub down_data: Slot,
    pub free: Vec<bool>,
}

/// The chain of object processors.
#[derive(Clone, Debug)]
pub struct OppModel {
    pub ops: Vec<OpModel>,
    /// This cycle's decisions and outputs, last OP first (kept to save an allocation per cycle).
    scratch: Vec<(Decision, OpOut)>,
}

impl OppModel {
    pub fn new(n: usize, fifo_depth: usize) -> Result<OppModel, String> {
        if n == 0 {
            return Err("an OPP needs at least one object processor".into());
        }
        Ok(OppModel { ops: (0..n).map(|_| OpModel::new(fifo_depth)).collect::<Result<_, _>>()?, scratch: Vec::with_capacity(n) })
    }

    /// Each OP's decisions and outputs this cycle, the ready path resolved from the last OP back;
    /// `into` gets them last OP first.
    fn resolve_into(&self, down_ready: bool, into: &mut Vec<(Decision, OpOut)>) {
        into.clear();
        let mut ready = down_ready;
        for op in self.ops.iter().rev() {
            let (d, o) = op.decide_outputs(ready);
            ready = o.up_ready;
            into.push((d, o));
        }
    }

    /// The OPP's outputs from OP outputs listed last OP first.
    fn opp_out(resolved: &[(Decision, OpOut)]) -> OppOut {
        let (first, last) = (resolved[resolved.len() - 1].1, resolved[0].1);
        OppOut { up_ready: first.up_ready, down_valid: last.down_valid, down_data: last.down_data, free: resolved.iter().rev().map(|x| x.1.free).collect() }
    }

    pub fn outputs(&self, down_ready: bool) -> OppOut {
        let mut resolved = Vec::with_capacity(self.ops.len());
        self.resolve_into(down_ready, &mut resolved);
        Self::opp_out(&resolved)
    }

    /// One clock; returns the outputs before the edge.
    pub fn step(&mut self, inp: &OppIn) -> Result<OppOut, String> {
        let n = self.ops.len();
        if let Some((k, _)) = inp.load {
            if k >= n {
                return Err(format!("load into OP {k}, but the OPP has {n}"));
            }
        }
        // Each OP decides once (the ready path resolved from the last OP back), then every OP steps
        // on those decisions: the same as `OpModel::step` on each, at half the cost.
        let mut scratch = std::mem::take(&mut self.scratch);
        self.resolve_into(inp.down_ready, &mut scratch);
        let at = |k: usize| &scratch[n - 1 - k];
        for k in 0..n {
            let (up_valid, up_data) = if k == 0 { (inp.up_valid, inp.up_data) } else { (at(k - 1).1.down_valid, at(k - 1).1.down_data) };
            let down_ready = if k == n - 1 { inp.down_ready } else { at(k + 1).1.up_ready };
            let load = match inp.load {
                Some((j, p)) if j == k => Some(p),
                _ => None,
            };
            self.ops[k].step_decided(&OpIn { up_valid, up_data, down_ready, load }, at(k).0);
        }
        let out = Self::opp_out(&scratch);
        self.scratch = scratch;
        Ok(out)
    }
}

/// What the feeder presents in a cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct FeedOut {
    pub valid: bool,
    pub data: Slot,
    /// (OP, object id) to load at this edge.
    pub load: Option<(usize, u16)>,
}

/// The geometry processor's side: object loader and pixel source in raster order.
#[derive(Clone, Debug)]
pub struct Feeder {
    pub width: u32,
    pub height: u32,
    /// Object ids in loading order, with the raster position of their first box pixel.
    pub order: Vec<(u64, u16)>,
    pub next_load: usize,
    /// The next slot of the input stream to push: the next pixel when the input is empty lists.
    pub next_pixel: u64,
    /// The input stream of a later pass (the lists of the previous pass), or None: one empty slot per
    /// pixel.
    pub input: Option<Vec<Slot>>,
    /// A pixel is being offered and must stay offered until taken.
    pub holding: bool,
}

impl Feeder {
    pub fn new(screen: Screen, objects: &[ObjectParams]) -> Feeder {
        let mut order: Vec<(u64, u16)> = objects.iter().map(|o| (o.first_pixel(screen.width), o.id)).collect();
        order.sort();
        Feeder { width: screen.width, height: screen.height, order, next_load: 0, next_pixel: 0, input: None, holding: false }
    }

    /// The feeder of one pass: the objects `ids` (of `objects`, indexed by id) and, after the first
    /// pass, the previous pass's output stream as input.
    pub fn pass(screen: Screen, objects: &[ObjectParams], ids: &[u16], input: Option<Vec<Slot>>) -> Feeder {
        let mut order: Vec<(u64, u16)> = ids.iter().map(|&i| (objects[i as usize].first_pixel(screen.width), i)).collect();
        order.sort();
        Feeder { width: screen.width, height: screen.height, order, next_load: 0, next_pixel: 0, input, holding: false }
    }

    pub fn pixels(&self) -> u64 {
        self.width as u64 * self.height as u64
    }

    /// All pixels (all input slots) pushed.
    pub fn finished(&self) -> bool {
        match &self.input {
            None => self.next_pixel >= self.pixels(),
            Some(v) => self.next_pixel >= v.len() as u64,
        }
    }

    /// This cycle's offer, given the OPs' free flags and whether the source has a pixel ready (`go`
    /// false makes a gap; an offered pixel is never withdrawn).
    pub fn offer(&self, free: &[bool], go: bool) -> FeedOut {
        let load = if self.next_load < self.order.len() { free.iter().rposition(|&f| f).map(|k| (k, self.order[self.next_load].1)) } else { None };
        let after = self.next_load + load.is_some() as usize;
        let w = self.width as u64;
        let (p, data) = match &self.input {
            None => (self.next_pixel, Slot::empty((self.next_pixel % w) as u16, (self.next_pixel / w) as u16)),
            Some(v) => match v.get(self.next_pixel as usize) {
                Some(s) => (s.y as u64 * w + s.x as u64, *s),
                None => (self.pixels(), Slot::default()),
            },
        };
        let allowed = p < self.pixels() && (after >= self.order.len() || self.order[after].0 > p);
        let valid = allowed && (go || self.holding);
        FeedOut { valid, data: if valid { data } else { Slot::default() }, load }
    }

    /// The edge: `accepted` = the OPP took the offered pixel.
    pub fn commit(&mut self, out: &FeedOut, accepted: bool) {
        if out.load.is_some() {
            self.next_load += 1;
        }
        if out.valid && accepted {
            self.next_pixel += 1;
            self.holding = false;
        } else {
            self.holding = out.valid;
        }
    }
}

/// Collects the OPP's output slots into per-pixel lists and checks the raster order.
#[derive(Clone, Debug, Default)]
pub struct Sink {
    pub width: u32,
    pub lists: Vec<Vec<Entry>>,
    pub cur: Vec<Entry>,
    pub slots: u64,
    /// Every slot taken, in order, when asked for ([`Sink::keeping_slots`]): the stream that goes
    /// round again in the next pass.
    pub stream: Option<Vec<Slot>>,
}

impl Sink {
    pub fn new(screen: Screen) -> Sink {
        Sink { width: screen.width, lists: Vec::with_capacity(screen.pixels()), ..Default::default() }
    }
    /// A sink that also keeps the raw slot stream.
    pub fn keeping_slots(screen: Screen) -> Sink {
        Sink { stream: Some(Vec::with_capacity(screen.pixels())), ..Sink::new(screen) }
    }
    /// Take one slot.
    pub fn take(&mut self, s: &Slot) -> Result<(), String> {
        let n = self.lists.len() as u64;
        let expect = ((n % self.width as u64) as u16, (n / self.width as u64) as u16);
        if (s.x, s.y) != expect {
            return Err(format!("slot for pixel ({}, {}) while pixel {:?} was expected", s.x, s.y, expect));
        }
        self.slots += 1;
        if let Some(v) = self.stream.as_mut() {
            v.push(*s);
        }
        if s.has_entry {
            self.cur.push(s.entry);
        }
        if s.last {
            self.lists.push(std::mem::take(&mut self.cur));
        }
        Ok(())
    }
}

/// Random gaps in the pixel stream: the source pauses and the sink refuses in a share of the cycles.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Gaps {
    pub seed: u64,
    pub source_gap_percent: u64,
    pub sink_gap_percent: u64,
}

/// A small xorshift source for the gaps (the golden crate has no random-number dependency).
#[derive(Clone, Debug)]
pub struct GapRng(pub u64);

impl GapRng {
    pub fn percent(&mut self, p: u64) -> bool {
        let mut x = self.0.max(1);
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545F4914F6CDD1D) % 100 < p
    }
}

/// The outcome of a frame through the OPP cycle model.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct OppRun {
    #[serde(skip)]
    pub lists: Vec<Vec<Entry>>,
    pub ops: usize,
    pub fifo_depth: usize,
    /// Cycles from the first cycle until the last pixel's last slot has left the OPP.
    pub cycles: u64,
    pub pixels: u64,
    pub slots_out: u64,
    /// Cycles in which the feeder could not push because an object still had to be loaded.
    pub waits_for_load: u64,
    /// Cycles in which a pixel was offered but the OPP was not ready.
    pub input_stalls: u64,
    /// Own entries inserted before the head or appended (jams), and slots dropped behind full entries.
    pub insertions: u64,
    pub drops: u64,
    /// Passes of the pixel stream through the OPP (1 when the OPP has the OPs the frame needs).
    pub passes: usize,
    /// The most slots stored between two passes (the feedback memory, in slots; 0 for one pass).
    pub feedback_slots: u64,
}

impl OppRun {
    /// The feedback memory in bytes: [`OppRun::feedback_slots`] slots of
    /// [`super::format::SLOT_BITS`] bits.
    pub fn feedback_bytes(&self) -> u64 {
        (self.feedback_slots * super::format::SLOT_BITS).div_ceil(8)
    }
}

/// Object ids split into passes of an OPP of `n_ops` OPs, in loading order: each object goes to the
/// first pass in which fewer than `n_ops` of that pass's objects span its first pixel (raster-order
/// spans, counted as [`super::render::ops_needed`] counts them), so each pass needs at most `n_ops`
/// OPs with reuse. One pass when `n_ops` >= `ops_needed`. `n_ops` must be at least 1.
pub fn passes(screen: Screen, objects: &[ObjectParams], n_ops: usize) -> Vec<Vec<u16>> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    let mut order: Vec<(u64, u16)> = objects.iter().map(|o| (o.first_pixel(screen.width), o.id)).collect();
    order.sort();
    // Per pass: the ids, and the last pixels of its objects still spanning the current position.
    let mut out: Vec<(Vec<u16>, BinaryHeap<Reverse<u64>>)> = Vec::new();
    for (first, id) in order {
        let last = objects[id as usize].last_pixel(screen.width);
        let mut placed = false;
        for (ids, live) in out.iter_mut() {
            while live.peek().is_some_and(|&Reverse(l)| l < first) {
                live.pop();
            }
            if live.len() < n_ops.max(1) {
                ids.push(id);
                live.push(Reverse(last));
                placed = true;
                break;
            }
        }
        if !placed {
            out.push((vec![id], BinaryHeap::from(vec![Reverse(last)])));
        }
    }
    if out.is_empty() {
        out.push((Vec::new(), BinaryHeap::new()));
    }
    out.into_iter().map(|(ids, _)| ids).collect()
}

/// Run a frame of objects through the cycle model: `n_ops` OPs with FIFOs of `fifo_depth`, optional
/// random gaps at both ends.
pub fn run_opp(screen: Screen, objects: &[ObjectParams], n_ops: usize, fifo_depth: usize, gaps: Option<Gaps>) -> Result<OppRun, String> {
    run_opp_with_progress(screen, objects, n_ops, fifo_depth, gaps, &mut |_, _| {})
}

/// [`run_opp`], reporting `progress(pixels done, pixels)` every 4096 cycles (pixels of all passes):
/// the model steps every object processor in every cycle, so a frame costs about cycles x processors
/// (a fan of 3000 triangles around one pixel needs some 3000 processors: tens of seconds at 320x200).
pub fn run_opp_with_progress(
    screen: Screen,
    objects: &[ObjectParams],
    n_ops: usize,
    fifo_depth: usize,
    gaps: Option<Gaps>,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<OppRun, String> {
    if n_ops == 0 {
        return Err("an OPP needs at least one object processor".into());
    }
    let mut top = ModelOnly { opp: OppModel::new(n_ops, fifo_depth)?, idle: 0, cycle: 0 };
    drive_frame(&mut top, screen, objects, fifo_depth, gaps, progress)
}

/// What [`drive_frame`] drives: the cycle model alone ([`run_opp`]), or an RTL top beside it (the
/// testbenches), so that both see the same feeder, sink, gaps and passes.
pub trait OppDrive {
    /// The cycle model (its OPs' `free` drive the object loader; their last actions are counted).
    fn model(&self) -> &OppModel;
    /// One clock: the outputs before the edge.
    fn cycle(&mut self, inp: &OppIn) -> Result<OppOut, String>;
    /// After each clock: `progress` says whether anything moved; an error (a stalled frame) ends it.
    fn watch(&mut self, progress: bool, phase: &dyn Fn() -> String) -> Result<(), String>;
}

/// The cycle model alone, with its own no-progress limit.
struct ModelOnly {
    opp: OppModel,
    idle: u64,
    cycle: u64,
}

impl OppDrive for ModelOnly {
    fn model(&self) -> &OppModel {
        &self.opp
    }
    fn cycle(&mut self, inp: &OppIn) -> Result<OppOut, String> {
        self.cycle += 1;
        self.opp.step(inp)
    }
    fn watch(&mut self, progress: bool, phase: &dyn Fn() -> String) -> Result<(), String> {
        self.idle = if progress { 0 } else { self.idle + 1 };
        if self.idle > 10_000 {
            return Err(format!("the OPP made no progress for 10000 cycles at cycle {} ({})", self.cycle, phase()));
        }
        Ok(())
    }
}

/// A frame through `top`, driven by the object loader and pixel source ([`Feeder`]) and collected by
/// the [`Sink`], with optional random gaps; with fewer OPs than the frame needs, in [`passes`], each
/// pass's output stream fed back as the next pass's input through the same top.
pub fn drive_frame(
    top: &mut dyn OppDrive,
    screen: Screen,
    objects: &[ObjectParams],
    fifo_depth: usize,
    gaps: Option<Gaps>,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<OppRun, String> {
    let n_ops = top.model().ops.len();
    let batches = passes(screen, objects, n_ops);
    let mut rng = GapRng(gaps.map(|g| g.seed).unwrap_or(1));
    let mut run = OppRun { ops: n_ops, fifo_depth, pixels: screen.pixels() as u64, passes: batches.len(), ..Default::default() };
    let mut cycle = 0u64;
    let mut free: Vec<bool> = Vec::with_capacity(n_ops);
    let mut input: Option<Vec<Slot>> = None;
    for (pass, ids) in batches.iter().enumerate() {
        let more = pass + 1 < batches.len();
        let mut feeder = Feeder::pass(screen, objects, ids, input.take());
        let mut sink = if more { Sink::keeping_slots(screen) } else { Sink::new(screen) };
        while sink.lists.len() < screen.pixels() {
            if cycle % 4096 == 0 {
                progress((pass * screen.pixels() + sink.lists.len()) as u64, (batches.len() * screen.pixels()) as u64);
            }
            let go = gaps.map(|g| !rng.percent(g.source_gap_percent)).unwrap_or(true);
            let down_ready = gaps.map(|g| !rng.percent(g.sink_gap_percent)).unwrap_or(true);
            free.clear();
            free.extend(top.model().ops.iter().map(|o| o.free()));
            let f = feeder.offer(&free, go);
            let inp = OppIn { up_valid: f.valid, up_data: f.data, down_ready, load: f.load.map(|(k, id)| (k, objects[id as usize])) };
            let out = top.cycle(&inp)?;
            if !feeder.finished() && !f.valid && (go || feeder.holding) {
                run.waits_for_load += 1;
            }
            if f.valid && !out.up_ready {
                run.input_stalls += 1;
            }
            for op in &top.model().ops {
                match op.last_action {
                    Action::EmitOwnBefore | Action::EmitOwnEnd => run.insertions += 1,
                    Action::Drop => run.drops += 1,
                    _ => {}
                }
            }
            feeder.commit(&f, out.up_ready);
            let moved = f.load.is_some() || (f.valid && out.up_ready) || (out.down_valid && down_ready);
            if out.down_valid && down_ready {
                sink.take(&out.down_data)?;
            }
            cycle += 1;
            let phase = || format!("the OPP frame, pass {} of {} ({} of {} pixels' lists out)", pass + 1, batches.len(), sink.lists.len(), screen.pixels());
            top.watch(moved, &phase)?;
        }
        run.slots_out = sink.slots;
        if more {
            let stream = sink.stream.take().unwrap_or_default();
            run.feedback_slots = run.feedback_slots.max(stream.len() as u64);
            input = Some(stream);
        } else {
            run.lists = sink.lists;
        }
    }
    run.cycles = cycle;
    Ok(run)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::{WinVertex, SUBPIXEL_ONE};
    use crate::proof::render::{object_lists, ops_needed};
    use crate::proof::setup::object_setup;

    fn tri(c: [(f64, f64, u32); 3], id: u16, s: Screen) -> ObjectParams {
        let v = c.map(|(x, y, z)| WinVertex { x: (x * SUBPIXEL_ONE as f64).round() as i32, y: (y * SUBPIXEL_ONE as f64).round() as i32, z });
        object_setup(&v, [[0, 0, 16384]; 3], id, s).unwrap()
    }

    fn scene(s: Screen) -> Vec<ObjectParams> {
        let mut v = Vec::new();
        let mut k = 0u16;
        for i in 0..6 {
            let (x, y) = (2.0 + i as f64 * 4.3, 1.5 + (i % 3) as f64 * 5.1);
            v.push(tri([(x, y, 1000 * i), (x + 9.7, y + 2.2, 3000), (x + 1.3, y + 8.9, 9000 - 1000 * i)], k, s));
            k += 1;
        }
        v.push(tri([(0.0, 0.0, 50_000), (40.0, 0.0, 50_000), (0.0, 24.0, 50_000)], k, s));
        v
    }

    #[test]
    fn the_cycle_model_builds_the_algorithmic_lists_for_every_fifo_depth_with_gaps() {
        let s = Screen::new(40, 24).unwrap();
        let objs = scene(s);
        let want = object_lists(s, &objs);
        let needed = ops_needed(s, &objs) as usize;
        for depth in [1, 2, 3, 8] {
            for (seed, gi, go) in [(1, 0, 0), (7, 30, 30), (99, 60, 10), (5, 10, 70)] {
                let run = run_opp(s, &objs, needed, depth, Some(Gaps { seed, source_gap_percent: gi, sink_gap_percent: go })).unwrap();
                assert_eq!(run.lists, want, "depth {depth} seed {seed}");
            }
        }
    }

    #[test]
    fn fewer_object_processors_than_needed_take_more_passes_and_build_the_same_lists_with_gaps() {
        let s = Screen::new(40, 24).unwrap();
        let objs = scene(s);
        let want = object_lists(s, &objs);
        let needed = ops_needed(s, &objs) as usize;
        assert!(needed >= 3, "the scene should need several OPs, needs {needed}");
        let one = run_opp(s, &objs, needed, 1, None).unwrap();
        assert_eq!((one.passes, one.feedback_slots), (1, 0));
        for n in 1..needed {
            for depth in [1, 3] {
                for (seed, gi, go) in [(1, 0, 0), (7, 30, 30), (5, 10, 70)] {
                    let run = run_opp(s, &objs, n, depth, Some(Gaps { seed, source_gap_percent: gi, sink_gap_percent: go })).unwrap();
                    assert_eq!(run.lists, want, "{n} OPs, depth {depth} seed {seed}");
                    assert!(run.passes >= needed.div_ceil(n) && run.passes > 1, "{n} OPs: {} passes", run.passes);
                    assert!(run.feedback_slots >= s.pixels() as u64, "{n} OPs: {} slots stored", run.feedback_slots);
                    if gi == 0 && go == 0 {
                        assert!(run.cycles > one.cycles, "{n} OPs: {} cycles, one pass {}", run.cycles, one.cycles);
                    }
                }
            }
        }
        assert!(run_opp(s, &objs, 0, 1, None).unwrap_err().contains("at least one"));
    }

    #[test]
    fn each_pass_needs_at_most_the_opps_object_processors_and_every_object_is_in_exactly_one_pass() {
        let s = Screen::new(40, 24).unwrap();
        let objs = scene(s);
        let needed = ops_needed(s, &objs) as usize;
        for n in 1..=needed + 1 {
            let p = passes(s, &objs, n);
            let mut all: Vec<u16> = p.iter().flatten().copied().collect();
            all.sort();
            assert_eq!(all, (0..objs.len() as u16).collect::<Vec<_>>(), "{n} OPs");
            for batch in &p {
                let sub: Vec<ObjectParams> = batch.iter().map(|&i| objs[i as usize]).collect();
                assert!(ops_needed(s, &sub) as usize <= n, "{n} OPs: a pass needs {}", ops_needed(s, &sub));
            }
            assert_eq!(p.len() == 1, n >= needed, "{n} OPs: {} passes", p.len());
        }
    }
}
