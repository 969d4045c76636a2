//! The RTL backend: the `hdl::chipset::Chipset` top simulated in RustHDL (direct drive, GUIDE §5)
//! behind `golden::render::Chipset`, so that the host program of the golden model drives the RTL
//! through seed 001's dual pipeline unchanged. The memories behind the top's ports (Z-buffer, I-buffer,
//! TdbS) are modelled here: synchronous, latency 1, read-before-write.
//!
//! Phases, as the host sequences them, and the cycles each takes (`cycles.json`):
//! * `clear`: cycles in which the RC writes the clear values (counted on the I-buffer port; W x H on
//!   the first frame after reset, 0 on later frames, which the CS cleared behind the previous scan-out);
//! * `geometry_transfer`: from the first triangle command offered to the last command taken: the time
//!   the host spends sending geometry (it overlaps rasterization);
//! * `rasterization`: from the frame command to the end-of-frame result (includes `clear`);
//! * `colour_setup`: from the first setup command offered until colour setup is idle after the last;
//! * `scan_out`: from the scan start to the last pixel taken (the consumer is always ready);
//! * `total`: from the frame command to the end of scan-out (rasterization + colour setup + scan-out).
//!
//! Beside the cycles, one count of work seen at the ports: `z_reads`, the cycles in rasterization with
//! a Z-buffer read (`z_re`). The RC reads Z once for every covered candidate (fragment) it Z-tests, so
//! this is the RC's fragment count as the hardware did it, for fragments per clock against the limit of
//! one read per clock on the Z port.

use crate::cs::pack::{command_of, record_of, rgb_of, tdata_of};
use crate::rc::bench::command_word;
use golden::cycle::colour_setup::SetupCmd;
use golden::cycle::rc::RcCmd;
use golden::format::{Screen, DEPTH_MAX};
use golden::raster::{Culled, CullMode, FrontFace, TriResult};
use golden::render::{Chipset, RcCommand, ScanOut, SetupCommand};
use golden::cycle::color_shader::phong_config;
use golden::shade::{PhongLights, Shading, TdbsEntry};
use hdl::chipset::Chipset as ChipsetRtl;
use hdl::cs::TdbsRecord;
use rust_hdl::core::vcd_probe::VCDProbe;
use rust_hdl::prelude::*;
use std::fs::File;
use std::io::BufWriter;
use std::path::PathBuf;

/// Cycles per phase of one frame.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PhaseCycles {
    pub clear: u64,
    pub geometry_transfer: u64,
    pub rasterization: u64,
    pub colour_setup: u64,
    pub scan_out: u64,
    pub total: u64,
    /// Cycles in rasterization with a Z-buffer read: the fragments the RC Z-tested.
    pub z_reads: u64,
}

impl PhaseCycles {
    pub fn to_json(&self) -> String {
        format!(
            "{{\n  \"clear\": {},\n  \"geometry_transfer\": {},\n  \"rasterization\": {},\n  \"colour_setup\": {},\n  \"scan_out\": {},\n  \"total\": {},\n  \"z_reads\": {}\n}}\n",
            self.clear, self.geometry_transfer, self.rasterization, self.colour_setup, self.scan_out, self.total, self.z_reads
        )
    }
}

/// A progress report: phase name, done, total.
pub type Progress = Box<dyn FnMut(&str, u64, u64)>;

/// The RustHDL simulation of the chipset with its memories.
pub struct RtlChipset {
    pub screen: Screen,
    uut: Box<ChipsetRtl>,
    zbuf: Vec<u32>,
    ibuf: Vec<u32>,
    tdbs: Vec<TdbsRecord>,
    z_rd: u32,
    i_rd: u32,
    t_rd: TdbsRecord,
    pub cycle: u64,
    pub phases: PhaseCycles,
    /// I-buffer writes of the background index (the RC's clear) since the last frame command.
    clear_writes: u64,
    /// The cycle of this frame's frame command.
    frame_start: u64,
    /// The buffers hold the previous frame's clear-behind (false after reset: memory contents unknown).
    cleared: bool,
    ibuf_after_raster: Vec<u32>,
    zbuf_after_raster: Vec<u32>,
    vcd: Option<VCDProbe<BufWriter<File>>>,
    progress: Option<Progress>,
    vcd_scope: VcdScope,
}

/// What a VCD of the chipset holds.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum VcdScope {
    /// The top-level ports (as Verilator's `--trace-depth 1` would show them): a frame in tens of MB.
    Ports,
    /// Every signal of every block: hundreds of MB per 320x200 frame.
    Full,
}

/// The `chipset` top seen through its ports only: a block that rust-hdl's VCD writer walks instead of
/// the whole hierarchy (same scope `uut` and names as a full dump).
struct Ports<'a>(&'a ChipsetRtl);

impl Logic for Ports<'_> {
    fn update(&mut self) {}
}

impl Block for Ports<'_> {
    fn connect_all(&mut self) {}
    fn update_all(&mut self) {}
    fn has_changed(&self) -> bool {
        false
    }
    fn accept(&self, name: &str, probe: &mut dyn Probe) {
        let u = self.0;
        probe.visit_start_scope(name, self);
        u.clock.accept("clock", probe);
        u.rc_cmd.accept("rc_cmd", probe);
        u.rc_result.accept("rc_result", probe);
        u.setup_cmd.accept("setup_cmd", probe);
        u.setup_busy.accept("setup_busy", probe);
        u.scan_start.accept("scan_start", probe);
        u.scan_background.accept("scan_background", probe);
        u.scan_clear_behind.accept("scan_clear_behind", probe);
        u.scan_phong.accept("scan_phong", probe);
        u.light_write_enable.accept("light_write_enable", probe);
        u.light_write_address.accept("light_write_address", probe);
        u.light_write_data.accept("light_write_data", probe);
        u.material_write_enable.accept("material_write_enable", probe);
        u.material_write_address.accept("material_write_address", probe);
        u.material_write_slot.accept("material_write_slot", probe);
        u.material_write_data.accept("material_write_data", probe);
        u.scan_busy.accept("scan_busy", probe);
        u.video_tdata.accept("video_tdata", probe);
        u.video_tvalid.accept("video_tvalid", probe);
        u.video_tready.accept("video_tready", probe);
        u.video_tuser.accept("video_tuser", probe);
        u.video_tlast.accept("video_tlast", probe);
        u.z_re.accept("z_re", probe);
        u.z_rd_addr.accept("z_rd_addr", probe);
        u.z_rd_data.accept("z_rd_data", probe);
        u.z_we.accept("z_we", probe);
        u.z_wr_addr.accept("z_wr_addr", probe);
        u.z_wr_data.accept("z_wr_data", probe);
        u.i_re.accept("i_re", probe);
        u.i_rd_addr.accept("i_rd_addr", probe);
        u.i_rd_data.accept("i_rd_data", probe);
        u.i_we.accept("i_we", probe);
        u.i_wr_addr.accept("i_wr_addr", probe);
        u.i_wr_data.accept("i_wr_data", probe);
        u.t_re.accept("t_re", probe);
        u.t_rd_addr.accept("t_rd_addr", probe);
        u.t_rd_data.accept("t_rd_data", probe);
        u.t_we.accept("t_we", probe);
        u.t_wr_addr.accept("t_wr_addr", probe);
        u.t_wr_data.accept("t_wr_data", probe);
        probe.visit_end_scope(name, self);
    }
}

impl RtlChipset {
    /// A chipset for `screen`; with `vcd`, the top-level ports at every settle are written there.
    pub fn new(screen: Screen, vcd: Option<PathBuf>) -> Result<RtlChipset, String> {
        Self::with_vcd_scope(screen, vcd, VcdScope::Ports)
    }

    /// As [`RtlChipset::new`], choosing what the VCD holds.
    pub fn with_vcd_scope(screen: Screen, vcd: Option<PathBuf>, scope: VcdScope) -> Result<RtlChipset, String> {
        let mut uut = Box::new(ChipsetRtl::new(screen.width, screen.height)?);
        uut.connect_all();
        check_all(uut.as_ref()).map_err(|e| format!("chipset: rust-hdl check failed: {e:?}"))?;
        let vcd = match vcd {
            Some(p) => {
                let f = File::create(&p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
                let v = match scope {
                    VcdScope::Ports => write_vcd_dump(write_vcd_header(BufWriter::new(f), &Ports(&uut)), &Ports(&uut)),
                    VcdScope::Full => write_vcd_dump(write_vcd_header(BufWriter::new(f), uut.as_ref()), uut.as_ref()),
                };
                Some(v)
            }
            None => None,
        };
        // After reset the memories hold garbage; the first frame's clear puts them in order.
        let n = screen.pixels();
        Ok(RtlChipset {
            screen,
            uut,
            zbuf: (0..n).map(|i| (i as u32).wrapping_mul(2654435761) & DEPTH_MAX).collect(),
            ibuf: (0..n).map(|i| (i as u32).wrapping_mul(40503) & 0xffff).collect(),
            tdbs: vec![TdbsRecord::default(); 1 << 16],
            z_rd: 0,
            i_rd: 0,
            t_rd: TdbsRecord::default(),
            cycle: 0,
            phases: PhaseCycles::default(),
            clear_writes: 0,
            frame_start: 0,
            cleared: false,
            ibuf_after_raster: Vec::new(),
            zbuf_after_raster: Vec::new(),
            vcd,
            progress: None,
            vcd_scope: scope,
        })
    }

    /// Close the VCD (flushing it); it is also closed when the simulation is dropped.
    pub fn finish_vcd(&mut self) {
        self.vcd = None;
    }

    /// Report progress through `f(phase, done, total)`.
    pub fn with_progress(mut self, f: Progress) -> RtlChipset {
        self.progress = Some(f);
        self
    }

    fn report(&mut self, phase: &str, done: u64, total: u64) {
        if let Some(p) = self.progress.as_mut() {
            p(phase, done, total);
        }
    }

    fn settle(&mut self) -> Result<(), String> {
        if !simulate(self.uut.as_mut(), 1000) {
            return Err(format!("chipset: the simulation did not settle in cycle {}", self.cycle));
        }
        if let Some(v) = self.vcd.take() {
            let mut v = v;
            v.timestamp(self.cycle * 10 + if self.uut.clock.val().clk { 5 } else { 0 }).map_err(|e| format!("VCD: {e}"))?;
            self.vcd = Some(match self.vcd_scope {
                VcdScope::Ports => write_vcd_change(v, &Ports(&self.uut)),
                VcdScope::Full => write_vcd_change(v, self.uut.as_ref()),
            });
        }
        Ok(())
    }

    /// One clock: inputs (already set by the caller) settle with the clock low; the memories take
    /// their reads and writes at the edge; then the rising edge. Returns nothing: the caller samples
    /// the handshakes between [`RtlChipset::low`] and [`RtlChipset::high`].
    fn low(&mut self) -> Result<(), String> {
        let u = &mut self.uut;
        u.z_rd_data.next = (self.z_rd as u64).into();
        u.i_rd_data.next = (self.i_rd as u64).into();
        u.t_rd_data.next = self.t_rd;
        u.clock.next = false.into();
        self.settle()
    }

    fn high(&mut self) -> Result<(), String> {
        let n = self.zbuf.len();
        let bad = |what: &str, a: usize| format!("chipset: {what} address {a} outside the {n}-word buffer in cycle {}", self.cycle);
        let u = &self.uut;
        // Reads see the contents before this edge's writes.
        if u.z_re.val() {
            let a = u.z_rd_addr.val().index();
            self.z_rd = *self.zbuf.get(a).ok_or_else(|| bad("Z read", a))?;
        }
        if u.i_re.val() {
            let a = u.i_rd_addr.val().index();
            self.i_rd = *self.ibuf.get(a).ok_or_else(|| bad("I read", a))?;
        }
        if u.t_re.val() {
            self.t_rd = self.tdbs[u.t_rd_addr.val().index()];
        }
        if u.z_we.val() {
            let a = u.z_wr_addr.val().index();
            *self.zbuf.get_mut(a).ok_or_else(|| bad("Z write", a))? = u.z_wr_data.val().to_u64() as u32;
        }
        if u.i_we.val() {
            let a = u.i_wr_addr.val().index();
            let d = u.i_wr_data.val().to_u64() as u32;
            *self.ibuf.get_mut(a).ok_or_else(|| bad("I write", a))? = d;
            if d == 0 {
                self.clear_writes += 1;
            }
        }
        if u.t_we.val() {
            let a = u.t_wr_addr.val().index();
            self.tdbs[a] = u.t_wr_data.val();
        }
        self.uut.clock.next = true.into();
        self.settle()?;
        self.cycle += 1;
        Ok(())
    }

    fn idle_inputs(&mut self) {
        let u = &mut self.uut;
        u.rc_cmd.valid.next = false;
        u.rc_result.ready.next = true;
        u.setup_cmd.valid.next = false;
        u.scan_start.next = false;
        u.video_tready.next = true;
        // Phong-constant writes: none, and payloads 0.
        crate::cs::color_shader_bench::drive_config(&mut **u, None);
    }

    /// The buffers as the RC left them at the end of the last rasterization.
    pub fn buffers_after_raster(&self) -> (&[u32], &[u32]) {
        (&self.ibuf_after_raster, &self.zbuf_after_raster)
    }

    /// A cycle budget that no correct frame reaches: a hang is an error, not an endless loop.
    fn budget(&self, work: u64) -> u64 {
        1_000_000 + 64 * work
    }
}

impl Chipset for RtlChipset {
    fn rasterize(&mut self, tris: &[RcCommand], cull: CullMode, front: FrontFace) -> Result<Vec<TriResult>, String> {
        let mut cmds = vec![RcCmd::frame(!self.cleared)];
        for t in tris {
            cmds.push(RcCmd::triangle(t.index, t.v, cull, front)?);
        }
        cmds.push(RcCmd::end_of_frame());
        let words: Vec<_> = cmds.iter().map(command_word).collect();
        let mut results = Vec::with_capacity(tris.len());
        let (mut next, start) = (0usize, self.cycle);
        self.clear_writes = 0;
        self.frame_start = start;
        let (mut first_tri_taken, mut last_cmd_taken) = (None, start);
        let mut z_reads = 0u64;
        let limit = self.cycle + self.budget(self.screen.pixels() as u64 + 64 * tris.len() as u64);
        loop {
            self.idle_inputs();
            if next < words.len() {
                self.uut.rc_cmd.valid.next = true;
                self.uut.rc_cmd.data.next = words[next];
            }
            self.low()?;
            let u = &self.uut;
            let taken = next < words.len() && u.rc_cmd.ready.val();
            z_reads += u.z_re.val() as u64;
            let mut eof = false;
            if u.rc_result.valid.val() {
                let r = u.rc_result.data.val();
                if r.eof {
                    eof = true;
                } else {
                    let culled = if r.zero_area {
                        Some(Culled::ZeroArea)
                    } else if r.culled {
                        Some(Culled::Facing)
                    } else {
                        None
                    };
                    results.push(TriResult { index: r.index.to_u64() as u32, culled, visible: r.visible });
                }
            }
            self.high()?;
            if taken {
                if next == 1 {
                    first_tri_taken = Some(self.cycle - 1);
                }
                next += 1;
                last_cmd_taken = self.cycle;
            }
            if self.cycle % 4096 == 0 {
                let phase = if first_tri_taken.is_none() { "clear" } else { "rasterization" };
                self.report(phase, results.len() as u64, tris.len() as u64);
            }
            if eof {
                break;
            }
            if self.cycle > limit {
                return Err(format!("chipset: no end-of-frame result after {} cycles", self.cycle - start));
            }
        }
        if results.len() != tris.len() {
            return Err(format!("chipset: {} results for {} triangles", results.len(), tris.len()));
        }
        let t0 = first_tri_taken.unwrap_or(last_cmd_taken);
        self.phases.clear = self.clear_writes;
        self.phases.geometry_transfer = last_cmd_taken - t0;
        self.phases.rasterization = self.cycle - start;
        self.phases.z_reads = z_reads;
        self.ibuf_after_raster = self.ibuf.clone();
        self.zbuf_after_raster = self.zbuf.clone();
        Ok(results)
    }

    fn colour_setup(&mut self, cmds: &[SetupCommand]) -> Result<(), String> {
        let words = cmds.iter().map(|c| SetupCmd::from_command(c).map(|s| command_of(&s))).collect::<Result<Vec<_>, _>>()?;
        let (start, limit) = (self.cycle, self.cycle + self.budget(64 * cmds.len() as u64));
        let mut next = 0;
        loop {
            self.idle_inputs();
            if next < words.len() {
                self.uut.setup_cmd.valid.next = true;
                self.uut.setup_cmd.data.next = words[next];
            }
            self.low()?;
            let taken = next < words.len() && self.uut.setup_cmd.ready.val();
            let busy = self.uut.setup_busy.val() || self.uut.t_we.val();
            self.high()?;
            if taken {
                next += 1;
                if next % 256 == 0 {
                    self.report("colour setup", next as u64, words.len() as u64);
                }
            }
            if next == words.len() && !taken && !busy {
                break;
            }
            if self.cycle > limit {
                return Err(format!("chipset: colour setup did not finish in {} cycles", self.cycle - start));
            }
        }
        self.phases.colour_setup = self.cycle - start;
        Ok(())
    }

    fn scanout(&mut self, shading: Shading, lights: &PhongLights, background: [u8; 3]) -> Result<ScanOut, String> {
        let phong = shading == Shading::Phong;
        let config = if phong { phong_config(lights)? } else { Vec::new() };
        let (w, h) = (self.screen.width as usize, self.screen.height as usize);
        let mut rgb = Vec::with_capacity(w * h * 3);
        let (start, limit) = (self.cycle, self.cycle + self.budget(w as u64 * h as u64));
        // Phong: the constants first, one write per cycle, while the CS is idle.
        for c in &config {
            self.idle_inputs();
            crate::cs::color_shader_bench::drive_config(&mut *self.uut, Some(*c));
            self.low()?;
            self.high()?;
        }
        let mut started = false;
        let mut pixels = 0usize;
        loop {
            self.idle_inputs();
            self.uut.scan_background.next = (tdata_of(background) as u64).into();
            self.uut.scan_clear_behind.next = true;
            self.uut.scan_phong.next = phong;
            self.uut.scan_start.next = !started;
            self.low()?;
            let u = &self.uut;
            let start_taken = !started && !u.scan_busy.val();
            let beat = if u.video_tvalid.val() {
                let (x, y) = (pixels % w, pixels / w);
                if u.video_tuser.val() != (pixels == 0) {
                    return Err(format!("chipset: tuser is {} on pixel ({x},{y})", u.video_tuser.val()));
                }
                if u.video_tlast.val() != (x == w - 1) {
                    return Err(format!("chipset: tlast is {} on pixel ({x},{y})", u.video_tlast.val()));
                }
                Some(rgb_of(u.video_tdata.val().to_u64() as u32))
            } else {
                None
            };
            let busy = u.scan_busy.val();
            self.high()?;
            started |= start_taken;
            if let Some(p) = beat {
                if pixels == w * h {
                    return Err("chipset: more pixels than the screen has".into());
                }
                rgb.extend_from_slice(&p);
                pixels += 1;
                if pixels % 4096 == 0 {
                    self.report("scan-out", pixels as u64, (w * h) as u64);
                }
            }
            if started && pixels == w * h && !busy {
                break;
            }
            if self.cycle > limit {
                return Err(format!("chipset: scan-out produced {pixels} of {} pixels in {} cycles", w * h, self.cycle - start));
            }
        }
        self.phases.scan_out = self.cycle - start;
        self.phases.total = self.cycle - self.frame_start;
        self.cleared = true;
        Ok(ScanOut { rgb, ibuf: self.ibuf_after_raster.clone(), zbuf: self.zbuf_after_raster.clone() })
    }
}

/// TdbS as the RTL left it, in the golden model's terms (for checks).
pub fn tdbs_entries(c: &RtlChipset, indices: &[u32]) -> Vec<TdbsEntry> {
    indices.iter().map(|&i| crate::cs::pack::entry_of(&c.tdbs[i as usize])).collect()
}

/// Whether a golden TdbS entry and the RTL's record agree.
pub fn record_matches(e: &TdbsEntry, r: &TdbsRecord) -> bool {
    record_of(e) == *r
}
