//! Level 1 for PROOF's filter stage with the 2x2 area: the RustHDL `Filter2x2Stage` (direct drive)
//! beside `golden::proof::cycle_filter2x2::Filter2x2Model`, and the box alone (`Box2x2` beside
//! `BoxModel`), same inputs every cycle. Compared before every rising edge: `upstream.ready`,
//! `downstream.valid`, `downstream.data` (when valid); the front end's registers (shared with the 1x1
//! bench, [`compare_front`]); Q5's weights and coverage, the quadrant sums (pixel state, always) and
//! Q6; and the box's registers: A, H, the line buffer's read word (when H is valid), the flush state
//! and V, each valid bit always and the contents when valid. The first difference stops the run with
//! the cycle, the register or port, both values and the VCD path.

use crate::common::{Trace, Watchdog};
use super::convert::hex_of;
use super::filter_bench::{check_tag, compare_front, drive_filter_inputs, filter_ports, filter_vector_row, pixel_from_rtl, pixel_to_rtl, run_filter_top, FilterRun};
use super::shade_bench::StageGaps;
use super::replay::{inp, out, Port, Recorder};
use golden::proof::cycle_filter::{FilterIn, FilterOut, FilteredPixel};
use golden::proof::cycle_filter2x2::{BoxA, BoxH, BoxIn, BoxLine, BoxModel, BoxOut, BoxV, Filter2x2Model, QuadPixel};
use golden::proof::cycle_opp::GapRng;
use golden::proof::cycle_shade::{CfgWrite, ShadedSlot};
use hdl::proof::{Box2x2, Filter2x2Stage, FilteredPixel as RtlPixel, QuadPixel as RtlQuad};
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

fn u<const N: usize>(b: Bits<N>) -> u32 {
    b.to_u64() as u32
}

pub fn quad_to_rtl(p: &QuadPixel) -> RtlQuad {
    let s = |q: usize, k: usize| Bits::<12>::from(p.sum[q][k] as u64);
    let c = |q: usize| Bits::<5>::from(p.cov[q] as u64);
    RtlQuad {
        x: (p.x as u64).into(),
        y: (p.y as u64).into(),
        r0: s(0, 0),
        r1: s(1, 0),
        r2: s(2, 0),
        r3: s(3, 0),
        g0: s(0, 1),
        g1: s(1, 1),
        g2: s(2, 1),
        g3: s(3, 1),
        b0: s(0, 2),
        b1: s(1, 2),
        b2: s(2, 2),
        b3: s(3, 2),
        c0: c(0),
        c1: c(1),
        c2: c(2),
        c3: c(3),
    }
}

fn a_from_rtl(a: &hdl::proof::BoxA) -> BoxA {
    BoxA {
        valid: a.valid,
        x: a.x.to_u64() as u16,
        y: a.y.to_u64() as u16,
        lt: [u(a.lt_r), u(a.lt_g), u(a.lt_b), u(a.lt_c)],
        lb: [u(a.lb_r), u(a.lb_g), u(a.lb_b), u(a.lb_c)],
        rt: [u(a.rt_r), u(a.rt_g), u(a.rt_b), u(a.rt_c)],
        rb: [u(a.rb_r), u(a.rb_g), u(a.rb_b), u(a.rb_c)],
        own: a.own.to_u64() as u8,
    }
}

fn h_from_rtl(h: &hdl::proof::BoxH) -> BoxH {
    BoxH {
        valid: h.valid,
        flush: h.flush,
        x: h.x.to_u64() as u16,
        y: h.y.to_u64() as u16,
        t: [u(h.t_r), u(h.t_g), u(h.t_b), u(h.t_c)],
        b: [u(h.b_r), u(h.b_g), u(h.b_b), u(h.b_c)],
        own: h.own.to_u64() as u8,
    }
}

fn line_from_rtl(l: &hdl::proof::BoxLine) -> BoxLine {
    BoxLine { b: [u(l.b_r), u(l.b_g), u(l.b_b), u(l.b_c)], s: [u(l.s_r), u(l.s_g), u(l.s_b), u(l.s_c)], own: l.own.to_u64() as u8 }
}

fn v_from_rtl(v: &hdl::proof::BoxV) -> BoxV {
    BoxV { valid: v.valid, x: v.x.to_u64() as u16, y: v.y.to_u64() as u16, s: [u(v.s_r), u(v.s_g), u(v.s_b), u(v.s_c)], own: v.own.to_u64() as u8 }
}

/// The box's registers against the model's: each valid bit always, the contents when valid (for a
/// flush column of H: its column and row; the line buffer's read word when H is valid).
pub fn compare_box(u: &Box2x2, m: &BoxModel) -> Result<(), String> {
    let a = a_from_rtl(&u.a.q.val());
    if a.valid != m.a.valid || (m.a.valid && a != m.a) {
        return Err(format!("register box A rtl {a:?} model {:?}", m.a));
    }
    let h = h_from_rtl(&u.h.q.val());
    let key = |h: &BoxH| if h.flush { (h.valid, h.flush, h.x, h.y, [0; 4], [0; 4], 0) } else { (h.valid, h.flush, h.x, h.y, h.t, h.b, h.own) };
    if h.valid != m.h.valid || (m.h.valid && key(&h) != key(&m.h)) {
        return Err(format!("register box H rtl {h:?} model {:?}", m.h));
    }
    if m.h.valid {
        let rd = line_from_rtl(&u.line.read_data.val());
        if rd != m.rd {
            return Err(format!("box line buffer word of column {} rtl {rd:?} model {:?}", m.h.x, m.rd));
        }
    }
    let (fl, fx) = (u.flushing.q.val(), u.fx.q.val().to_u64() as u16);
    if fl != m.flushing || (m.flushing && fx != m.fx) {
        return Err(format!("box flush state rtl ({fl}, column {fx}) model ({}, column {})", m.flushing, m.fx));
    }
    let v = v_from_rtl(&u.v.q.val());
    if v.valid != m.v.valid || (m.v.valid && v != m.v) {
        return Err(format!("register box V rtl {v:?} model {:?}", m.v));
    }
    Ok(())
}

/// The ports shared by both tops' comparisons.
fn compare_ports(up_ready: bool, down_valid: bool, down: &RtlPixel, exp_up_ready: bool, exp_down_valid: bool, exp_down: &FilteredPixel) -> Result<(), String> {
    if up_ready != exp_up_ready {
        return Err(format!("upstream.ready rtl {up_ready} model {exp_up_ready}"));
    }
    if down_valid != exp_down_valid {
        return Err(format!("downstream.valid rtl {down_valid} model {exp_down_valid}"));
    }
    let got = pixel_from_rtl(down);
    if exp_down_valid && got != *exp_down {
        return Err(format!("downstream.data rtl {got:?} model {exp_down:?}"));
    }
    Ok(())
}

pub struct Filter2x2Bench {
    pub uut: Filter2x2Stage,
    pub model: Filter2x2Model,
    pub cycle: u64,
    trace: Trace,
    pub vectors: Option<Recorder>,
}

impl Filter2x2Bench {
    pub fn new(obj_addr_bits: usize, width: u32, height: u32, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<Filter2x2Bench, String> {
        let model = Filter2x2Model::new(obj_addr_bits as u32, width, height)?;
        let mut uut = Filter2x2Stage::new(obj_addr_bits, width, height)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("proof_filter2x2: design check failed: {e:?}"))?;
        let trace = Trace::new(&uut, vcd)?;
        Ok(Filter2x2Bench { uut, model, cycle: 0, trace, vectors: vectors.map(|p| Recorder::create(p, &filter_ports())).transpose()? })
    }

    fn compare(&self, exp: &FilterOut) -> Result<(), String> {
        let (u, m) = (&self.uut, &self.model);
        compare_ports(u.upstream.ready.val(), u.downstream.valid.val(), &u.downstream.data.val(), exp.up_ready, exp.down_valid, &exp.down_data)?;
        compare_front(&u.front, &m.front)?;
        check_tag("Q5", &u.q5.q.val(), &m.q5.tag)?;
        if m.q5.tag.valid {
            let w = [0, 1, 2, 3].map(|q| u.q5_w[q].q.val().to_u64() as u16);
            let c = [0, 1, 2, 3].map(|q| u.q5_c[q].q.val().to_u64() as u8);
            if (w, c) != (m.q5.w, m.q5.cov) {
                return Err(format!("register Q5 weights/coverage rtl {w:?}/{c:?} model {:?}/{:?}", m.q5.w, m.q5.cov));
            }
        }
        let state = [0, 1, 2, 3].map(|q| [0, 1, 2].map(|k| u.qsum[3 * q + k].q.val().to_u64() as u32));
        let wstate = [0, 1, 2, 3].map(|q| u.wsum[q].q.val().to_u64() as u16);
        if (state, wstate) != (m.qsum, m.wsum) {
            return Err(format!("quadrant sums/weights (pixel state) rtl {state:?}/{wstate:?} model {:?}/{:?}", m.qsum, m.wsum));
        }
        let sums = |v: &Vec<DFF<Bits<12>>>| [0, 1, 2, 3].map(|q| [0, 1, 2].map(|k| v[3 * q + k].q.val().to_u64() as u16));
        check_tag("Q6", &u.q6.q.val(), &m.q6.tag)?;
        if m.q6.tag.valid {
            let c = [0, 1, 2, 3].map(|q| u.q6_c[q].q.val().to_u64() as u8);
            if (sums(&u.q6_acc), c) != (m.q6.acc, m.q6.cov) {
                return Err(format!("register Q6 words/coverage rtl {:?}/{c:?} model {:?}/{:?}", sums(&u.q6_acc), m.q6.acc, m.q6.cov));
            }
        }
        compare_box(&u.box2, &m.boxm)
    }

    /// One clock on both sides; returns the model's outputs before the edge.
    pub fn cycle(&mut self, i: &FilterIn) -> Result<FilterOut, String> {
        drive_filter_inputs!(self.uut, i);
        self.uut.clock.next = false.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.trace.fail(self.cycle, "the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle)?;
        let exp = self.model.outputs(i.down_ready);
        self.compare(&exp).map_err(|e| self.trace.fail(self.cycle, e))?;
        if let Some(w) = self.vectors.as_mut() {
            w.cycle(&filter_vector_row(i, &exp))?;
        }
        self.model.step(i)?;
        self.uut.clock.next = true.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.trace.fail(self.cycle, "the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle + 5)?;
        self.cycle += 1;
        Ok(exp)
    }
}

super::rusthdl_stage_top!(Filter2x2Bench, FilterIn, FilterOut);

/// Configure, then stream a frame's `slots` through the RTL 2x2 filter stage for a `width` x `height`
/// screen beside its model, with optional random gaps at the input and back-pressure at the output;
/// returns the pixels in order and the cycles after the configuration writes.
pub fn run_filter2x2(
    obj_addr_bits: usize,
    width: u32,
    height: u32,
    cfg: &[CfgWrite],
    slots: &[ShadedSlot],
    gaps: Option<StageGaps>,
    vcd: Option<&Path>,
    vectors: Option<PathBuf>,
) -> Result<FilterRun, String> {
    let mut b = Filter2x2Bench::new(obj_addr_bits, width, height, vcd, vectors)?;
    run_filter_top(&mut b, cfg, slots, gaps)
}

/// The box's ports, for the Verilog replay.
pub fn box_ports() -> Vec<Port> {
    vec![
        inp("background", 24),
        inp("upstream$valid", 1),
        inp("upstream$data", RtlQuad::BITS),
        inp("downstream$ready", 1),
        out("upstream$ready", 1, None),
        out("downstream$valid", 1, None),
        out("downstream$data", RtlPixel::BITS, Some("downstream$valid")),
    ]
}

pub struct BoxBench {
    pub uut: Box2x2,
    pub model: BoxModel,
    pub cycle: u64,
    trace: Trace,
    pub vectors: Option<Recorder>,
}

impl BoxBench {
    pub fn new(width: u32, height: u32, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<BoxBench, String> {
        let model = BoxModel::new(width, height)?;
        let mut uut = Box2x2::new(width, height)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("box2x2: design check failed: {e:?}"))?;
        let trace = Trace::new(&uut, vcd)?;
        Ok(BoxBench { uut, model, cycle: 0, trace, vectors: vectors.map(|p| Recorder::create(p, &box_ports())).transpose()? })
    }

    /// One clock on both sides; returns the model's outputs before the edge.
    pub fn cycle(&mut self, i: &BoxIn) -> Result<BoxOut, String> {
        let bg = i.background[0] as u64 | (i.background[1] as u64) << 8 | (i.background[2] as u64) << 16;
        self.uut.background.next = bg.into();
        self.uut.upstream.valid.next = i.up_valid;
        self.uut.upstream.data.next = quad_to_rtl(&i.up_data);
        self.uut.downstream.ready.next = i.down_ready;
        self.uut.clock.next = false.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.trace.fail(self.cycle, "the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle)?;
        let exp = self.model.outputs(i.down_ready);
        let u = &self.uut;
        compare_ports(u.upstream.ready.val(), u.downstream.valid.val(), &u.downstream.data.val(), exp.up_ready, exp.down_valid, &exp.down_data)
            .and_then(|_| compare_box(u, &self.model))
            .map_err(|e| self.trace.fail(self.cycle, e))?;
        if let Some(w) = self.vectors.as_mut() {
            let up: Bits<{ RtlQuad::BITS }> = quad_to_rtl(&i.up_data).into();
            let down: Bits<{ RtlPixel::BITS }> = pixel_to_rtl(&exp.down_data).into();
            w.cycle(&[
                format!("{bg:x}"),
                format!("{}", i.up_valid as u8),
                hex_of(up),
                format!("{}", i.down_ready as u8),
                format!("{}", exp.up_ready as u8),
                format!("{}", exp.down_valid as u8),
                hex_of(down),
            ])?;
        }
        self.model.step(i);
        self.uut.clock.next = true.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.trace.fail(self.cycle, "the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle + 5)?;
        self.cycle += 1;
        Ok(exp)
    }
}

/// Stream `frames` through the RTL box beside its model, frame after frame with no pause, with
/// random gaps and back-pressure; returns each frame's pixels and the recorded vectors if asked for.
pub fn run_box(
    width: u32,
    height: u32,
    background: [u8; 3],
    frames: &[Vec<QuadPixel>],
    gaps: StageGaps,
    vcd: Option<&Path>,
    vectors: Option<PathBuf>,
) -> Result<(Vec<Vec<FilteredPixel>>, Option<(PathBuf, u64)>), String> {
    let mut b = BoxBench::new(width, height, vcd, vectors)?;
    let mut rng = GapRng(gaps.seed);
    let all: Vec<QuadPixel> = frames.iter().flatten().copied().collect();
    let mut i = 0usize;
    let mut watchdog = Watchdog::new(super::bench::PROGRESS_LIMIT);
    let mut outs = Vec::with_capacity(all.len());
    while outs.len() < all.len() {
        let go = i < all.len() && !rng.percent(gaps.source_gap_percent);
        let ready = !rng.percent(gaps.sink_gap_percent);
        let o = b.cycle(&BoxIn { up_valid: go, up_data: all.get(i).copied().unwrap_or_default(), down_ready: ready, background })?;
        if go && o.up_ready {
            i += 1;
        }
        let progress = o.down_valid && ready;
        if progress {
            outs.push(o.down_data);
        }
        let phase = || format!("the 2x2 box ({} of {} pixels out)", outs.len(), all.len());
        watchdog.check(b.cycle, progress, phase, Some(&b.trace))?;
    }
    let rec = match b.vectors.take() {
        Some(w) => Some(w.finish()?),
        None => None,
    };
    let per = (width * height) as usize;
    Ok((outs.chunks(per).map(|c| c.to_vec()).collect(), rec))
}
