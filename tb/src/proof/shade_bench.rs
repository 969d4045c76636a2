//! Level 1 for PROOF's shading stage: the RustHDL `ShadingStage` (direct drive) beside
//! `golden::proof::cycle_shade::ShadeModel`, same inputs every cycle; compared before every rising
//! edge: `upstream.ready`, `downstream.valid`, `downstream.data` (when valid), and every pipeline
//! register's valid bit and, when valid, its arithmetic fields. The first difference stops the run
//! with the cycle, the port or register, both values and the VCD path.

use crate::common::{Trace, Watchdog};
use super::convert::{hex_of, slot_to_rtl};
use super::replay::{inp, out, Port, Recorder};
use golden::proof::cycle_opp::GapRng;
use golden::proof::cycle_shade::{CfgWrite, ShadeIn, ShadeModel, ShadeOut, ShadedSlot, Work};
use golden::proof::format::Slot;
use hdl::proof::{ShadeWork, ShadedSlot as RtlShaded, ShadingStage};
use rust_hdl::prelude::*;
use std::path::{Path, PathBuf};

fn sext16(v: u64) -> i16 {
    v as u16 as i16
}

pub fn shaded_from_rtl(s: &RtlShaded) -> ShadedSlot {
    ShadedSlot {
        x: s.x.to_u64() as u16,
        y: s.y.to_u64() as u16,
        last: s.last,
        has_entry: s.has_entry,
        id: s.id.to_u64() as u16,
        full: s.full,
        dist: [sext16(s.d0.to_u64()), sext16(s.d1.to_u64()), sext16(s.d2.to_u64())],
        rgb: [s.r.to_u64() as u8, s.g.to_u64() as u8, s.b.to_u64() as u8],
    }
}

pub fn shaded_to_rtl(s: &ShadedSlot) -> RtlShaded {
    let b16 = |v: i16| Bits::<16>::from(v as u16 as u64);
    RtlShaded {
        x: (s.x as u64).into(),
        y: (s.y as u64).into(),
        last: s.last,
        has_entry: s.has_entry,
        id: (s.id as u64).into(),
        full: s.full,
        d0: b16(s.dist[0]),
        d1: b16(s.dist[1]),
        d2: b16(s.dist[2]),
        r: (s.rgb[0] as u64).into(),
        g: (s.rgb[1] as u64).into(),
        b: (s.rgb[2] as u64).into(),
    }
}

/// The comparable part of a pipeline register: (valid, id, material, gloss, nl, x, acc).
fn key_rtl(w: &ShadeWork) -> (bool, u16, u8, u8, i64, i64, [i64; 3]) {
    (
        w.valid,
        w.id.to_u64() as u16,
        w.mat.to_u64() as u8,
        w.gloss.to_u64() as u8,
        w.nl.to_u64() as i64,
        w.sp.to_u64() as i64,
        [w.acc_r.to_u64() as i64, w.acc_g.to_u64() as i64, w.acc_b.to_u64() as i64],
    )
}
fn key_model(w: &Work) -> (bool, u16, u8, u8, i64, i64, [i64; 3]) {
    (w.valid, w.slot.entry.id, w.mat, w.gloss, w.nl, w.x, w.acc)
}

/// The shading top's ports, for the Verilog replay.
pub fn shade_ports() -> Vec<Port> {
    vec![
        inp("cfg_write", 1),
        inp("cfg_sel", 4),
        inp("cfg_addr", 16),
        inp("cfg_data", 96),
        inp("upstream$valid", 1),
        inp("upstream$data", hdl::proof::ProofSlot::BITS),
        inp("downstream$ready", 1),
        out("upstream$ready", 1, None),
        out("downstream$valid", 1, None),
        out("downstream$data", RtlShaded::BITS, Some("downstream$valid")),
    ]
}

/// One cycle of recorded vectors for the shading top, in [`shade_ports`] order: the inputs and the
/// model's outputs.
pub fn shade_vector_row(i: &ShadeIn, exp: &ShadeOut) -> Vec<String> {
    let up: Bits<{ hdl::proof::ProofSlot::BITS }> = slot_to_rtl(&i.up_data).into();
    let down: Bits<{ RtlShaded::BITS }> = shaded_to_rtl(&exp.down_data).into();
    super::convert::cfg_stage_row(i.cfg, i.up_valid, hex_of(up), i.down_ready, exp.up_ready, exp.down_valid, hex_of(down))
}

super::rusthdl_stage_top!(ShadeBench, ShadeIn, ShadeOut);

pub struct ShadeBench {
    pub uut: ShadingStage,
    pub model: ShadeModel,
    pub cycle: u64,
    trace: Trace,
    pub vectors: Option<Recorder>,
}

impl ShadeBench {
    pub fn new(n_lights: usize, obj_addr_bits: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<ShadeBench, String> {
        let mut uut = ShadingStage::new(n_lights, obj_addr_bits)?;
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("proof_shade: design check failed: {e:?}"))?;
        let trace = Trace::new(&uut, vcd)?;
        Ok(ShadeBench {
            uut,
            model: ShadeModel::new(n_lights, obj_addr_bits as u32)?,
            cycle: 0,
            trace,
            vectors: vectors.map(|p| Recorder::create(p, &shade_ports())).transpose()?,
        })
    }

    fn fail(&self, what: String) -> String {
        self.trace.fail(self.cycle, what)
    }

    fn compare(&self, exp: &ShadeOut) -> Result<(), String> {
        let u = &self.uut;
        if u.upstream.ready.val() != exp.up_ready {
            return Err(self.fail(format!("upstream.ready rtl {} model {}", u.upstream.ready.val(), exp.up_ready)));
        }
        if u.downstream.valid.val() != exp.down_valid {
            return Err(self.fail(format!("downstream.valid rtl {} model {}", u.downstream.valid.val(), exp.down_valid)));
        }
        let got = shaded_from_rtl(&u.downstream.data.val());
        if exp.down_valid && got != exp.down_data {
            return Err(self.fail(format!("downstream.data rtl {got:?} model {:?}", exp.down_data)));
        }
        let m = &self.model;
        let mut regs: Vec<(String, ShadeWork, &Work)> =
            vec![("r0".into(), u.r0.q.val(), &m.r0), ("r1".into(), u.r1.q.val(), &m.r1), ("r2".into(), u.r2.q.val(), &m.r2)];
        for (li, lp) in u.lights.iter().enumerate() {
            let r = [lp.a.q.val(), lp.p1.q.val(), lp.p2.q.val(), lp.p3.q.val(), lp.p4.q.val(), lp.m.q.val()];
            for (k, name) in ["A", "P1", "P2", "P3", "P4", "M"].iter().enumerate() {
                regs.push((format!("light {li} {name}"), r[k], &m.lights[li][k]));
            }
        }
        for (name, r, w) in regs {
            let (kr, km) = (key_rtl(&r), key_model(w));
            // r0 has no material yet and r0/r1 no sums: compare what each register holds.
            let same = if w.valid { kr == km || (name == "r0" && (kr.0, kr.1) == (km.0, km.1)) } else { kr.0 == km.0 };
            if !same {
                return Err(self.fail(format!("register {name} rtl {kr:?} model {km:?} (valid, id, mat, gloss, nl, x, acc)")));
            }
        }
        Ok(())
    }

    /// One clock on both sides; returns the model's outputs before the edge.
    pub fn cycle(&mut self, i: &ShadeIn) -> Result<ShadeOut, String> {
        let c = i.cfg.unwrap_or_default();
        let u = &mut self.uut;
        u.cfg_write.next = i.cfg.is_some();
        u.cfg_sel.next = (c.sel as u64).into();
        u.cfg_addr.next = (c.addr as u64).into();
        u.cfg_data.next = super::convert::bits96(c.data);
        u.upstream.valid.next = i.up_valid;
        u.upstream.data.next = slot_to_rtl(&i.up_data);
        u.downstream.ready.next = i.down_ready;
        u.clock.next = false.into();
        if !simulate(u, 10_000) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle)?;
        let exp = self.model.outputs(i.down_ready);
        self.compare(&exp)?;
        if let Some(w) = self.vectors.as_mut() {
            w.cycle(&shade_vector_row(i, &exp))?;
        }
        self.model.step(i)?;
        let u = &mut self.uut;
        u.clock.next = true.into();
        if !simulate(u, 10_000) {
            return Err(self.fail("the RTL did not settle".into()));
        }
        self.trace.dump(&self.uut, 10 * self.cycle + 5)?;
        self.cycle += 1;
        Ok(exp)
    }
}

/// Percentages of idle input and refused output cycles.
#[derive(Copy, Clone, Debug)]
pub struct StageGaps {
    pub seed: u64,
    pub source_gap_percent: u64,
    pub sink_gap_percent: u64,
}

/// Configure, then stream `slots` through the RTL shading stage beside its model; returns the shaded
/// slots and the cycles. `vectors` records every cycle for the Verilog replay.
pub fn run_shade(
    n_lights: usize,
    obj_addr_bits: usize,
    cfg: &[CfgWrite],
    slots: &[Slot],
    gaps: Option<StageGaps>,
    vcd: Option<&Path>,
    vectors: Option<PathBuf>,
) -> Result<(Vec<ShadedSlot>, u64, Option<(PathBuf, u64)>), String> {
    let mut b = ShadeBench::new(n_lights, obj_addr_bits, vcd, vectors)?;
    run_shade_top(&mut b, cfg, slots, gaps)
}

/// Configure a shading top, then stream `slots` through it with optional random gaps at the input
/// and back-pressure at the output: the shaded slots, the cycles and the recorded vectors.
pub fn run_shade_top<B: super::StageTop<ShadeIn, ShadeOut>>(
    b: &mut B,
    cfg: &[CfgWrite],
    slots: &[Slot],
    gaps: Option<StageGaps>,
) -> Result<(Vec<ShadedSlot>, u64, Option<(PathBuf, u64)>), String> {
    let mut rng = GapRng(gaps.map(|g| g.seed).unwrap_or(1));
    for c in cfg {
        b.cycle(&ShadeIn { cfg: Some(*c), down_ready: true, ..Default::default() })?;
    }
    let mut i = 0usize;
    let mut watchdog = Watchdog::from_cycle(super::bench::PROGRESS_LIMIT, b.cycles());
    let mut outs = Vec::with_capacity(slots.len());
    while outs.len() < slots.len() {
        let go = i < slots.len() && gaps.map(|g| !rng.percent(g.source_gap_percent)).unwrap_or(true);
        let ready = gaps.map(|g| !rng.percent(g.sink_gap_percent)).unwrap_or(true);
        let inp = ShadeIn { up_valid: go, up_data: slots.get(i).copied().unwrap_or_default(), down_ready: ready, cfg: None };
        let o = b.cycle(&inp)?;
        if go && o.up_ready {
            i += 1;
        }
        let progress = o.down_valid && ready;
        if progress {
            outs.push(o.down_data);
        }
        let phase = || format!("the shading stage ({} of {} slots out)", outs.len(), slots.len());
        watchdog.check(b.cycles(), progress, phase, b.trace())?;
    }
    let cycles = b.cycles();
    let rec = match b.take_vectors() {
        Some(w) => Some(w.finish()?),
        None => None,
    };
    Ok((outs, cycles, rec))
}
