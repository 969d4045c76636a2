//! PROOF's tops (OPP, shading stage, 1x1 and 2x2 filter stages) as generated Verilog under Verilator,
//! each beside its cycle model in every cycle: the backend of `render --arch proof --backend verilator`.
//! The Verilog is what `idxrender verilog` writes (`hdl::proof::verilog_*`), loaded as a shared
//! library (`crate::verilator::shared_lib`); the stimulus is the RustHDL benches' own
//! (`run_frame_top`, `run_shade_top`, `run_filter_top`: the golden object loader, pixel source and
//! sinks), so a Verilator run drives the same ports in the same cycles as a RustHDL run, and every
//! output port is compared with the cycle model before every rising edge.
//!
//! Sizes are fixed per build, as on a chip: the OPP has the `--ops` count of object processors, and
//! the shading and filter stages' object tables have [`TABLE_BITS`] address bits (every 16-bit object
//! id), so one build of each serves every scene. The 2x2 filter's line buffer is built per screen.

use super::bench::{opp_ports, opp_vector, OppTop};
use super::filter_bench::{filter_ports, filter_vector_row};
use super::replay::{Port, Recorder};
use super::shade_bench::{shade_ports, shade_vector_row};
use super::StageTop;
use crate::common::Trace;
use crate::verilator::shared_lib::{build_lib, VlTop};
use crate::verilator::Build;
use golden::proof::cycle_filter::{FilterIn, FilterModel, FilterOut};
use golden::proof::cycle_filter2x2::Filter2x2Model;
use golden::proof::cycle_opp::{OppIn, OppModel, OppOut};
use golden::proof::cycle_shade::{ShadeIn, ShadeModel, ShadeOut};
use std::path::{Path, PathBuf};

/// Address bits of the object tables in the verilated shading and filter stages: the object id's 16.
pub const TABLE_BITS: usize = 16;

/// `StageTop` for a Verilator top with a field `vl` and a method `cycle` (no RustHDL waveform: a
/// failure names the VCD itself when there is one).
macro_rules! verilated_stage_top {
    ($top:ty, $in:ty, $out:ty) => {
        impl StageTop<$in, $out> for $top {
            fn cycle(&mut self, i: &$in) -> Result<$out, String> {
                <$top>::cycle(self, i)
            }
            fn cycles(&self) -> u64 {
                self.vl.top.cycle
            }
            fn take_vectors(&mut self) -> Option<Recorder> {
                self.vl.vectors.take()
            }
            fn trace(&self) -> Option<&Trace> {
                None
            }
        }
    };
}

/// A verilated top and what a bench needs beside it.
struct Vl {
    top: VlTop,
    vectors: Option<Recorder>,
}

impl Vl {
    fn open(build: &Build, name: &str, ports: &[Port], vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<Vl, String> {
        let mut top = VlTop::open(build, name, ports, vcd)?;
        top.keep_rows = vectors.is_some();
        Ok(Vl { top, vectors: vectors.map(|p| Recorder::create(p, ports)).transpose()? })
    }
    /// One clock of `row`; records what the Verilog gave.
    fn cycle(&mut self, row: &[String]) -> Result<(), String> {
        let got = self.top.cycle(row)?;
        if let Some(r) = self.vectors.as_mut() {
            r.cycle(&got)?;
        }
        Ok(())
    }
}

/// The OPP of `n_ops` OPs (FIFO depth `fifo_depth`) under Verilator beside its cycle model.
pub struct VlOpp {
    vl: Vl,
    pub model: OppModel,
}

impl VlOpp {
    /// Build (or reuse) the library; `vcd` writes every signal, `vectors` records the ports as the
    /// Verilog drove them (the replay's format).
    pub fn new(n_ops: usize, fifo_depth: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<VlOpp, String> {
        let verilog = hdl::proof::verilog_opp("opp", n_ops, fifo_depth)?;
        VlOpp::from_verilog(&format!("proof_opp_{n_ops}ops_depth{fifo_depth}"), &verilog, n_ops, fifo_depth, vcd, vectors)
    }

    /// [`VlOpp::new`] on the given Verilog of an OPP (top `opp`) of `n_ops` OPs, cached as `cache`:
    /// for tests that put a fault into the text.
    pub fn from_verilog(cache: &str, verilog: &str, n_ops: usize, fifo_depth: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<VlOpp, String> {
        let build = build_lib(cache, "opp", verilog, &opp_ports(), vcd.is_some())?;
        Ok(VlOpp { vl: Vl::open(&build, "opp", &opp_ports(), vcd, vectors)?, model: OppModel::new(n_ops, fifo_depth)? })
    }
}

impl VlOpp {
    fn cycle(&mut self, inp: &OppIn) -> Result<OppOut, String> {
        let exp = self.model.outputs(inp.down_ready);
        self.vl.cycle(&opp_vector(inp, &exp))?;
        self.model.step(inp)?;
        Ok(exp)
    }
}

verilated_stage_top!(VlOpp, OppIn, OppOut);

impl OppTop for VlOpp {
    fn model(&self) -> &OppModel {
        &self.model
    }
}

/// The shading stage with `n_lights` light-source processors under Verilator beside its cycle model.
pub struct VlShade {
    vl: Vl,
    pub model: ShadeModel,
}

impl VlShade {
    pub fn new(n_lights: usize, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<VlShade, String> {
        let verilog = hdl::proof::verilog_shading("proof_shade", n_lights, TABLE_BITS)?;
        let build = build_lib(&format!("proof_shade_{n_lights}lights"), "proof_shade", &verilog, &shade_ports(), vcd.is_some())?;
        Ok(VlShade { vl: Vl::open(&build, "proof_shade", &shade_ports(), vcd, vectors)?, model: ShadeModel::new(n_lights, TABLE_BITS as u32)? })
    }
}

impl VlShade {
    fn cycle(&mut self, i: &ShadeIn) -> Result<ShadeOut, String> {
        let exp = self.model.outputs(i.down_ready);
        self.vl.cycle(&shade_vector_row(i, &exp))?;
        self.model.step(i)?;
        Ok(exp)
    }
}

verilated_stage_top!(VlShade, ShadeIn, ShadeOut);

/// The filter stage's cycle model: the 1x1 box or the 2x2 area.
enum FilterKind {
    Box1(FilterModel),
    Box2(Box<Filter2x2Model>),
}

/// A filter stage under Verilator beside its cycle model.
pub struct VlFilter {
    vl: Vl,
    model: FilterKind,
}

impl VlFilter {
    /// The 1x1 stage (`proof_filter`).
    pub fn box1(vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<VlFilter, String> {
        let verilog = hdl::proof::verilog_filter("proof_filter", TABLE_BITS)?;
        let build = build_lib("proof_filter", "proof_filter", &verilog, &filter_ports(), vcd.is_some())?;
        Ok(VlFilter { vl: Vl::open(&build, "proof_filter", &filter_ports(), vcd, vectors)?, model: FilterKind::Box1(FilterModel::new(TABLE_BITS as u32)?) })
    }
    /// The 2x2 stage (`proof_filter2x2`) with its line buffer for `width` x `height` frames.
    pub fn box2(width: u32, height: u32, vcd: Option<&Path>, vectors: Option<PathBuf>) -> Result<VlFilter, String> {
        let model = Filter2x2Model::new(TABLE_BITS as u32, width, height)?;
        let verilog = hdl::proof::verilog_filter2x2("proof_filter2x2", TABLE_BITS, width, height)?;
        let build = build_lib(&format!("proof_filter2x2_{width}x{height}"), "proof_filter2x2", &verilog, &filter_ports(), vcd.is_some())?;
        Ok(VlFilter { vl: Vl::open(&build, "proof_filter2x2", &filter_ports(), vcd, vectors)?, model: FilterKind::Box2(Box::new(model)) })
    }
}

impl VlFilter {
    fn cycle(&mut self, i: &FilterIn) -> Result<FilterOut, String> {
        let exp = match &self.model {
            FilterKind::Box1(m) => m.outputs(i.down_ready),
            FilterKind::Box2(m) => m.outputs(i.down_ready),
        };
        self.vl.cycle(&filter_vector_row(i, &exp))?;
        match &mut self.model {
            FilterKind::Box1(m) => m.step(i)?,
            FilterKind::Box2(m) => m.step(i)?,
        };
        Ok(exp)
    }
}

verilated_stage_top!(VlFilter, FilterIn, FilterOut);
