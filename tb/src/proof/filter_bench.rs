//! Level 1 for PROOF's filter stage: the RustHDL `FilterStage` (direct drive) beside
//! `golden::proof::cycle_filter::FilterModel`, same inputs every cycle; compared before every rising
//! edge: `upstream.ready`, `downstream.valid`, `downstream.data` (when valid), the pixel states
//! (`taken`, each subpixel's `spent`, the colour and weight sums), and every pipeline register's
//! valid bit and, when valid, its contents (F0's slot, the tables' outputs, each edge's base/steps,
//! tree rows and mask, the opacity, the 64 subpixel weights and the union mask, the entry's weight,
//! the sums). The first difference stops the run with the cycle, the port or register, both values
//! and the VCD path.

use crate::common::{Trace, Watchdog};
use super::convert::hex_of;
use super::shade_bench::{shaded_to_rtl, StageGaps};
use super::replay::{inp, out, Port, Recorder};
use golden::proof::cycle_filter::{EdgeF1, EdgeF2, FilterFront as FrontModel, FilterIn, FilterModel, FilterOut, FilteredPixel, Tag};
use golden::proof::cycle_opp::GapRng;
use golden::proof::cycle_shade::{CfgWrite, ShadedSlot};
use hdl::proof::edge_mask::EdgeMask;
use hdl::proof::{FilterFront, FilterStage, FilterTag, FilteredPixel as RtlPixel, ShadedSlot as RtlShaded};
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

fn sext(v: u64, bits: u32) -> i64 {
    ((v << (64 - bits)) as i64) >> (64 - bits)
}

pub fn pixel_from_rtl(p: &RtlPixel) -> FilteredPixel {
    FilteredPixel {
        x: p.x.to_u64() as u16,
        y: p.y.to_u64() as u16,
        rgb: [p.r.to_u64() as u8, p.g.to_u64() as u8, p.b.to_u64() as u8],
        covered: p.covered.to_u64() as u8,
    }
}

pub fn pixel_to_rtl(p: &FilteredPixel) -> RtlPixel {
    RtlPixel {
        x: (p.x as u64).into(),
        y: (p.y as u64).into(),
        r: (p.rgb[0] as u64).into(),
        g: (p.rgb[1] as u64).into(),
        b: (p.rgb[2] as u64).into(),
        covered: (p.covered as u64).into(),
    }
}

/// (valid, x, y, last, has_entry, full, rgb, alpha) of a register's tag.
type TagKey = (bool, u16, u16, bool, bool, bool, [u8; 3], u8);

fn tag_rtl(t: &FilterTag) -> TagKey {
    (
        t.valid,
        t.x.to_u64() as u16,
        t.y.to_u64() as u16,
        t.last,
        t.has_entry,
        t.full,
        [t.r.to_u64() as u8, t.g.to_u64() as u8, t.b.to_u64() as u8],
        t.alpha.to_u64() as u8,
    )
}
fn tag_model(t: &Tag) -> TagKey {
    let s = &t.slot;
    (t.valid, s.x, s.y, s.last, s.has_entry, s.full, s.rgb, t.alpha)
}

fn f1_rtl(e: &EdgeMask) -> EdgeF1 {
    EdgeF1 { base: sext(e.base.q.val().to_u64(), 22), sx: sext(e.sx.q.val().to_u64(), 22), sy: sext(e.sy.q.val().to_u64(), 22) }
}
fn f2_rtl(e: &EdgeMask) -> EdgeF2 {
    let mut rows = [0i64; 8];
    for (j, r) in rows.iter_mut().enumerate() {
        *r = sext(e.rows[j].q.val().to_u64(), 22);
    }
    EdgeF2 { rows, sx: sext(e.sx2.q.val().to_u64(), 22) }
}

/// The front end's registers (F0..F4, `taken`, `spent`, the tables' outputs) against the model's:
/// every valid bit and, when valid, the contents. Shared by the 1x1 and 2x2 benches.
pub fn compare_front(u: &FilterFront, m: &FrontModel) -> Result<(), String> {
    let diff = |what: &str, r: String, e: String| -> Result<(), String> {
        if r != e {
            Err(format!("register {what} rtl {r} model {e}"))
        } else {
            Ok(())
        }
    };
    // F0 and the direction table's output.
    diff("F0 valid", format!("{}", u.f0_valid.q.val()), format!("{}", m.f0.valid))?;
    if m.f0.valid {
        let f0 = super::shade_bench::shaded_from_rtl(&u.f0.q.val());
        diff("F0 slot", format!("{f0:?}"), format!("{:?}", m.f0.slot))?;
        let q = u.dir_table.read_data.val();
        let dq: [i16; 6] = [0, 1, 2, 3, 4, 5].map(|k| sext(q.get_bits::<16>(16 * k).to_u64(), 16) as i16);
        diff("direction table output", format!("{dq:?}"), format!("{:?}", m.dir_q))?;
        diff("opacity table output", format!("{}", u.alpha_table.read_data.val().to_u64()), format!("{}", m.alpha_q))?;
    }
    let edges = [&u.e0, &u.e1, &u.e2];
    let tags = [(&u.f1, &m.f1.0, "F1"), (&u.f2, &m.f2.0, "F2"), (&u.f3, &m.f3.0, "F3"), (&u.f4, &m.f4.tag, "F4")];
    for (r, t, name) in tags {
        check_tag(name, &r.q.val(), t)?;
    }
    for k in 0..3 {
        if m.f1.0.valid {
            diff(&format!("F1 edge {k}"), format!("{:?}", f1_rtl(edges[k])), format!("{:?}", m.f1.1[k]))?;
        }
        if m.f2.0.valid {
            diff(&format!("F2 edge {k}"), format!("{:?}", f2_rtl(edges[k])), format!("{:?}", m.f2.1[k]))?;
        }
        if m.f3.0.valid {
            diff(&format!("F3 edge {k} mask"), format!("{:#018x}", edges[k].m.q.val().to_u64()), format!("{:#018x}", m.f3.1[k]))?;
        }
    }
    diff("taken", format!("{:#018x}", u.taken.q.val().to_u64()), format!("{:#018x}", m.taken))?;
    let spent: Vec<u16> = u.cells.iter().map(|c| c.spent.q.val().to_u64() as u16).collect();
    diff("spent", format!("{spent:?}"), format!("{:?}", m.spent))?;
    if m.f4.tag.valid {
        let w: Vec<u16> = u.cells.iter().map(|c| c.f4_w.q.val().to_u64() as u16).collect();
        diff("F4 weights", format!("{w:?}"), format!("{:?}", m.f4.w))?;
        diff("F4 union", format!("{:#018x}", u.f4_union.q.val().to_u64()), format!("{:#018x}", m.f4.union))?;
    }
    Ok(())
}

/// A register's tag: the valid bit always, the contents when valid.
pub fn check_tag(name: &str, r: &FilterTag, m: &Tag) -> Result<(), String> {
    let (kr, km) = (tag_rtl(r), tag_model(m));
    if kr.0 != km.0 || (km.0 && kr != km) {
        return Err(format!("register {name} tag rtl {kr:?} model {km:?} (valid, x, y, last, has_entry, full, rgb, alpha)"));
    }
    Ok(())
}

/// The filter top's ports, for the Verilog replay (the 1x1 and the 2x2 top have the same).
pub fn filter_ports() -> Vec<Port> {
    vec![
        inp("cfg_write", 1),
        inp("cfg_sel", 4),
        inp("cfg_addr", 16),
        inp("cfg_data", 96),
        inp("upstream$valid", 1),
        inp("upstream$data", RtlShaded::BITS),
        inp("downstream$ready", 1),
        out("upstream$ready", 1, None),
        out("downstream$valid", 1, None),
        out("downstream$data", RtlPixel::BITS, Some("downstream$valid")),
    ]
}

pub struct FilterBench {
    pub uut: FilterStage,
    pub model: FilterModel,
    pub cycle: u64,
    trace: Trace,
    pub vectors: Option<Recorder>,
}

pub use super::convert::bits96;

impl FilterBench {
    pub fn new(obj_addr_bits: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<FilterBench, String> {
        let model = FilterModel::new(obj_addr_bits as u32)?;
        let mut uut = FilterStage::new(obj_addr_bits)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("proof_filter: design check failed: {e:?}"))?;
        let trace = Trace::new(&uut, vcd)?;
        Ok(FilterBench {
            uut,
            model,
            cycle: 0,
            trace,
            vectors: vectors.map(|p| Recorder::create(p, &filter_ports())).transpose()?,
        })
    }

    fn fail(&self, what: String) -> String {
        self.trace.fail(self.cycle, what)
    }

    fn compare(&self, exp: &FilterOut) -> Result<(), String> {
        let u = &self.uut;
        let m = &self.model;
        if u.upstream.ready.val() != exp.up_ready {
            return Err(self.fail(format!("upstream.ready rtl {} model {}", u.upstream.ready.val(), exp.up_ready)));
        }
        if u.downstream.valid.val() != exp.down_valid {
            return Err(self.fail(format!("downstream.valid rtl {} model {}", u.downstream.valid.val(), exp.down_valid)));
        }
        let got = pixel_from_rtl(&u.downstream.data.val());
        if exp.down_valid && got != exp.down_data {
            return Err(self.fail(format!("downstream.data rtl {got:?} model {:?}", exp.down_data)));
        }
        compare_front(&u.front, &m.front).map_err(|e| self.fail(e))?;
        let diff = |what: &str, r: String, e: String| -> Result<(), String> {
            if r != e {
                Err(self.fail(format!("register {what} rtl {r} model {e}")))
            } else {
                Ok(())
            }
        };
        check_tag("F5", &u.f5.q.val(), &m.f5.tag).map_err(|e| self.fail(e))?;
        if m.f5.tag.valid {
            diff(
                "F5 weight/covered",
                format!("{}/{}", u.f5_w.q.val().to_u64(), u.f5_covered.q.val().to_u64()),
                format!("{}/{}", m.f5.w, m.f5.covered),
            )?;
        }
        let sums = [u.sum_r.q.val().to_u64() as u32, u.sum_g.q.val().to_u64() as u32, u.sum_b.q.val().to_u64() as u32];
        diff("sum/wsum", format!("{sums:?}/{}", u.wsum.q.val().to_u64()), format!("{:?}/{}", m.sum, m.wsum))?;
        check_tag("F6", &u.f6.q.val(), &m.f6.tag).map_err(|e| self.fail(e))?;
        if m.f6.tag.valid {
            let acc = [u.f6_r.q.val().to_u64() as u32, u.f6_g.q.val().to_u64() as u32, u.f6_b.q.val().to_u64() as u32];
            diff(
                "F6 sums/weight/covered",
                format!("{acc:?}/{}/{}", u.f6_w.q.val().to_u64(), u.f6_covered.q.val().to_u64()),
                format!("{:?}/{}/{}", m.f6.acc, m.f6.wacc, m.f6.covered),
            )?;
        }
        Ok(())
    }

    /// One clock on both sides; returns the model's outputs before the edge.
    pub fn cycle(&mut self, i: &FilterIn) -> Result<FilterOut, String> {
        drive_filter_inputs!(self.uut, i);
        self.uut.clock.next = false.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle)?;
        let exp = self.model.outputs(i.down_ready);
        self.compare(&exp)?;
        if let Some(w) = self.vectors.as_mut() {
            w.cycle(&filter_vector_row(i, &exp))?;
        }
        self.model.step(i)?;
        self.uut.clock.next = true.into();
        if !simulate(&mut self.uut, 10_000) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle + 5)?;
        self.cycle += 1;
        Ok(exp)
    }
}

super::rusthdl_stage_top!(FilterBench, FilterIn, FilterOut);

/// Drive a filter top's inputs for one cycle (the 1x1 and the 2x2 top have the same ports).
macro_rules! drive_filter_inputs {
    ($u:expr, $i:expr) => {{
        let i: &golden::proof::cycle_filter::FilterIn = $i;
        let c = i.cfg.unwrap_or_default();
        $u.cfg_write.next = i.cfg.is_some();
        $u.cfg_sel.next = (c.sel as u64).into();
        $u.cfg_addr.next = (c.addr as u64).into();
        $u.cfg_data.next = $crate::proof::filter_bench::bits96(c.data);
        $u.upstream.valid.next = i.up_valid;
        $u.upstream.data.next = $crate::proof::shade_bench::shaded_to_rtl(&i.up_data);
        $u.downstream.ready.next = i.down_ready;
    }};
}
pub(crate) use drive_filter_inputs;

/// One cycle of recorded vectors for a filter top, in [`filter_ports`] order: the inputs and the
/// model's outputs.
pub fn filter_vector_row(i: &FilterIn, exp: &FilterOut) -> Vec<String> {
    let up: Bits<{ RtlShaded::BITS }> = shaded_to_rtl(&i.up_data).into();
    let down: Bits<{ RtlPixel::BITS }> = pixel_to_rtl(&exp.down_data).into();
    super::convert::cfg_stage_row(i.cfg, i.up_valid, hex_of(up), i.down_ready, exp.up_ready, exp.down_valid, hex_of(down))
}

/// The outcome of a run of the filter bench.
pub struct FilterRun {
    pub pixels: Vec<FilteredPixel>,
    /// Cycles after the configuration writes until the last pixel left.
    pub cycles: u64,
    /// The recorded vectors (path, cycles) when asked for.
    pub vectors: Option<(PathBuf, u64)>,
}

/// Configure, then stream `slots` through the RTL filter stage beside its model, with optional random
/// gaps at the input and back-pressure at the output; returns the pixels in order.
pub fn run_filter(
    obj_addr_bits: usize,
    cfg: &[CfgWrite],
    slots: &[ShadedSlot],
    gaps: Option<StageGaps>,
    vcd: Option<&Path>,
    vectors: Option<PathBuf>,
) -> Result<FilterRun, String> {
    let mut b = FilterBench::new(obj_addr_bits, vcd, vectors)?;
    run_filter_top(&mut b, cfg, slots, gaps)
}

/// Configure a filter top, then stream `slots` through it with optional random gaps at the input and
/// back-pressure at the output until every list's pixel has left; returns the pixels in order.
pub fn run_filter_top<B: super::StageTop<FilterIn, FilterOut>>(b: &mut B, cfg: &[CfgWrite], slots: &[ShadedSlot], gaps: Option<StageGaps>) -> Result<FilterRun, String> {
    let mut rng = GapRng(gaps.map(|g| g.seed).unwrap_or(1));
    for c in cfg {
        b.cycle(&FilterIn { cfg: Some(*c), down_ready: true, ..Default::default() })?;
    }
    let start = b.cycles();
    let pixels = slots.iter().filter(|s| s.last).count();
    let mut i = 0usize;
    let mut watchdog = Watchdog::from_cycle(super::bench::PROGRESS_LIMIT, start);
    let mut outs = Vec::with_capacity(pixels);
    while outs.len() < pixels {
        let go = i < slots.len() && gaps.map(|g| !rng.percent(g.source_gap_percent)).unwrap_or(true);
        let ready = gaps.map(|g| !rng.percent(g.sink_gap_percent)).unwrap_or(true);
        let inp = FilterIn { up_valid: go, up_data: slots.get(i).copied().unwrap_or_default(), down_ready: ready, cfg: None };
        let o = b.cycle(&inp)?;
        if go && o.up_ready {
            i += 1;
        }
        let progress = o.down_valid && ready;
        if progress {
            outs.push(o.down_data);
        }
        let phase = || format!("the filter stage ({} of {pixels} pixels out; a list without a last slot?)", outs.len());
        watchdog.check(b.cycles(), progress, phase, b.trace())?;
    }
    let cycles = b.cycles() - start;
    let rec = match b.take_vectors() {
        Some(w) => Some(w.finish()?),
        None => None,
    };
    Ok(FilterRun { pixels: outs, cycles, vectors: rec })
}
