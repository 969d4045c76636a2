//! The RTL backend: the `hdl::chipset::Chipset` top ([`RtlChipset`]), its Type III twin
//! `hdl::chipset::chipset3::Chipset3` ([`RtlChipset3`]) or its textured twin
//! `hdl::chipset::chipset_tex::ChipsetTex` ([`RtlChipsetTex`]), simulated in RustHDL (direct drive, GUIDE §5)
//! behind `golden::render::Chipset`, so that the host program of the golden model drives the RTL
//! through seed 001's two pipelines in parallel, frames back to back. The memories behind the top's
//! ports (Z-buffer or TdbV, two I-buffer banks, two TdbS banks) are modelled here: synchronous,
//! latency 1, read-before-write. The two tops share every port but the RC's own memory
//! ([`ChipsetTop`]), and every port's words are counted per frame ([`PortTraffic`]).
//!
//! # The host loop (the Verilator harness `tb/verilator/chipset/harness.cpp` runs the same one)
//!
//! One clock loop drives every port at once:
//! * *Upper pipeline*: frame f's RC commands (frame start, triangles, end of frame) are offered one
//!   after the other once frame f-1's scan-out has been started (the start swaps the banks); frame 0
//!   and 1 after reset carry `clear` (each bank once), later frames do not.
//! * *Lower pipeline*: when a result reports a triangle visible, the host lights it at once
//!   (`LowerPipeline::visible`) and queues its colour-setup command; the queue is offered to
//!   `setup_cmd` from the next cycle, while the RC goes on with later triangles.
//! * Frame f is *drawn* when its end-of-frame result has come, its queue is empty and colour setup is
//!   idle. Its scan-out begins once it is drawn and frame f-1's scan-out has ended: Phong constants
//!   (one write per cycle), then `scan_start` until the CS takes it, then the pixels (the display is
//!   always ready).
//!
//! Per frame (`cycles.json`, [`PhaseCycles`]):
//! * `clear`: the RC's clear writes (background index on the draw side of the I-buffer);
//! * `geometry_transfer`: from the first triangle command taken to the last command taken;
//! * `rasterization`: from the frame command first offered to the end-of-frame result;
//! * `colour_setup`: from the first setup command offered until colour setup is idle after the last
//!   (it overlaps rasterization);
//! * `scan_out`: from the first Phong-constant write or scan start offered to the last pixel;
//! * `total`: from the frame command to the end of its scan-out;
//! * `frame_interval`: from the previous frame's scan start (taken) to this frame's: the time per
//!   frame of a long run, measured at the ports (none for the first frame of a run);
//! * `z_reads`: cycles in rasterization with a Z-buffer read, the fragments the RC Z-tested.
//!
//! A textured frame (`chipset_tex` only; the other tops refuse one) also has, before its scan start
//! and after the Phong constants, one level-table write per mipmap level; the host loads the texture
//! into the four banks when the frame's scan-out begins (no scan is running then), holds the
//! texture's settings on their ports and sends each colour-setup command's nine texture values
//! beside it. Its [`golden::render::TextureCounts`] are counted at the ports ([`TexTraffic`]): samples
//! = scan-side I-buffer reads of a triangle's index, bank words = the bits of `tex_rd`, texels =
//! footprints (cycles with a bank read) x 1 (nearest) or 4.

use crate::cs::pack::{command_of, record_of, rgb_of, tdata_of};
use crate::rc::pack::command_word;
use golden::cycle::colour_setup::SetupCmd;
use golden::format::{Screen, DEPTH_MAX, INDEX_BACKGROUND};
use golden::raster::{Culled, TriResult};
use golden::render::{Chipset, FrameJob, FrameOut, LowerPipeline, ScanOut};
use golden::cycle::color_shader::{phong_config, CsConfigWrite};
use golden::shade::{Shading, TdbsEntry};
use hdl::chipset::chipset3::Chipset3 as Chipset3Rtl;
use hdl::chipset::chipset_tex::ChipsetTex as ChipsetTexRtl;
use hdl::cs::texel_address::ADDR_BITS;
use hdl::cs::{TdbtRecord, TexValues};
use hdl::chipset::Chipset as ChipsetRtl;
use crate::cs::color_shader_bench::ConfigPorts;
use golden::format::Plane;
use golden::raster::RcType;
use hdl::common::{StreamIn, StreamOut};
use hdl::cs::TdbsRecord;
use hdl::rc::RcCommand;
use std::collections::VecDeque;
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
    /// From the previous frame's scan start to this one's (none for a run's first frame).
    pub frame_interval: Option<u64>,
    /// Cycles in rasterization with a draw-side I-buffer read (Type IV: with a Z-buffer read): the
    /// fragments the RC tested for visibility.
    pub z_reads: u64,
    /// Words on each memory port for this frame, counted at the top's ports.
    pub traffic: PortTraffic,
    /// Words on the texture ports (`chipset_tex`; zero on the other tops and in untextured frames).
    pub texture: TexTraffic,
}

/// Words read and written on each memory port of a chipset top for one frame: the draw side (the RC
/// and colour setup) while the frame is drawn, the scan side (the CS) while it is scanned out. Type
/// IV's top has no TdbV port, Type III's no Z-buffer port.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PortTraffic {
    pub z_reads: u64,
    pub z_writes: u64,
    /// Draw side of the I-buffer (the RC: reads with each fragment, writes of passes and clears).
    pub i_reads: u64,
    pub i_writes: u64,
    pub tdbv_reads: u64,
    pub tdbv_writes: u64,
    /// TdbS written by colour setup.
    pub tdbs_writes: u64,
    /// Scan side of the I-buffer (the CS's scan-out reads and clear-behind writes).
    pub scan_i_reads: u64,
    pub scan_i_writes: u64,
    /// TdbS read by the CS.
    pub tdbs_reads: u64,
}

/// Bytes per word of each memory (its width rounded up to whole bytes): Z 24 bits, I 16, TdbV 136
/// (A 40, B 40, C 56), TdbS 424.
pub const Z_BYTES: u64 = 3;
pub const I_BYTES: u64 = 2;
pub const TDBV_BYTES: u64 = 17;
pub const TDBS_BYTES: u64 = 53;

impl PortTraffic {
    /// The counts in the order of `FIELDS` (the Verilator harness's `F` line has the same order).
    pub fn to_vec(&self) -> Vec<u64> {
        vec![self.z_reads, self.z_writes, self.i_reads, self.i_writes, self.tdbv_reads, self.tdbv_writes, self.tdbs_writes, self.scan_i_reads, self.scan_i_writes, self.tdbs_reads]
    }
    pub const FIELDS: [&'static str; 10] = ["z_reads", "z_writes", "i_reads", "i_writes", "tdbv_reads", "tdbv_writes", "tdbs_writes", "scan_i_reads", "scan_i_writes", "tdbs_reads"];
    pub fn from_slice(v: &[u64]) -> PortTraffic {
        PortTraffic { z_reads: v[0], z_writes: v[1], i_reads: v[2], i_writes: v[3], tdbv_reads: v[4], tdbv_writes: v[5], tdbs_writes: v[6], scan_i_reads: v[7], scan_i_writes: v[8], tdbs_reads: v[9] }
    }
    /// Add the RC's counts (Z, draw-side I, TdbV) of `t`.
    pub fn add_rc(&mut self, t: &PortTraffic) {
        (self.z_reads, self.z_writes, self.i_reads, self.i_writes) = (self.z_reads + t.z_reads, self.z_writes + t.z_writes, self.i_reads + t.i_reads, self.i_writes + t.i_writes);
        (self.tdbv_reads, self.tdbv_writes) = (self.tdbv_reads + t.tdbv_reads, self.tdbv_writes + t.tdbv_writes);
    }
    /// Add the scan side's counts of `t`.
    pub fn add_scan(&mut self, t: &PortTraffic) {
        (self.scan_i_reads, self.scan_i_writes, self.tdbs_reads) = (self.scan_i_reads + t.scan_i_reads, self.scan_i_writes + t.scan_i_writes, self.tdbs_reads + t.tdbs_reads);
    }
    /// Bytes the RC moves (Z, draw-side I, TdbV): read, written.
    pub fn rasterization_bytes(&self) -> (u64, u64) {
        (self.z_reads * Z_BYTES + self.i_reads * I_BYTES + self.tdbv_reads * TDBV_BYTES, self.z_writes * Z_BYTES + self.i_writes * I_BYTES + self.tdbv_writes * TDBV_BYTES)
    }
    pub fn to_json(&self) -> String {
        let f: Vec<String> = Self::FIELDS.iter().zip(self.to_vec()).map(|(k, v)| format!("\"{k}\": {v}")).collect();
        let (r, w) = self.rasterization_bytes();
        format!("{{ {}, \"rasterization_bytes_read\": {r}, \"rasterization_bytes_written\": {w} }}", f.join(", "))
    }
}

impl PhaseCycles {
    pub fn to_json(&self) -> String {
        format!(
            "{{\n  \"clear\": {},\n  \"geometry_transfer\": {},\n  \"rasterization\": {},\n  \"colour_setup\": {},\n  \"scan_out\": {},\n  \"total\": {},\n  \"frame_interval\": {},\n  \"z_reads\": {},\n  \"traffic\": {}\n}}\n",
            self.clear,
            self.geometry_transfer,
            self.rasterization,
            self.colour_setup,
            self.scan_out,
            self.total,
            self.frame_interval.map_or("null".to_string(), |v| v.to_string()),
            self.z_reads,
            self.traffic.to_json()
        )
    }
}

/// How the host loop drives the streams: as fast as the chipset takes them (the default), or with
/// random gaps before its commands (`rc_cmd`, `setup_cmd`) and random back-pressure on what it takes
/// (`rc_result`, the video stream). Both RTL backends draw the same random numbers in the same order
/// (xorshift64*, `common::Rng`), so their ports stay equal cycle for cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct HostDrive {
    pub seed: u64,
    /// Percentage of cycles in which a command that could be offered is held back.
    pub gap_percent: u64,
    /// Percentage of cycles in which `rc_result.ready` and `video_tready` are low.
    pub stall_percent: u64,
}

impl HostDrive {
    /// Random gaps and stalls from `default_seed` (the `SEED` environment variable overrides it).
    pub fn random(gap_percent: u64, stall_percent: u64, default_seed: u64) -> HostDrive {
        HostDrive { seed: crate::common::Rng::new(default_seed).seed(), gap_percent, stall_percent }
    }
}

/// Five frames of four built-in scenes in all three shadings, for runs back to back: castle Gouraud,
/// dolphins flat, the teapot (grid 4) Phong, the polyhedron Gouraud, castle Phong. A frame that read the
/// other bank, a TdbS record of the frame before (the same index is another triangle in another scene),
/// a pixel the clear-behind missed or a stale depth taken for a valid one would differ from its golden
/// frame.
pub fn mixed_frames(screen: Screen) -> Vec<(golden::scene::Mesh, golden::render::RenderOptions)> {
    use golden::scene::builtin;
    let scene = |n: &str| builtin::scene(n).expect("a built-in scene");
    [(scene("castle"), Shading::Gouraud), (scene("dolphins"), Shading::Flat), (builtin::teapot(4), Shading::Phong), (builtin::polyhedron(), Shading::Gouraud), (scene("castle"), Shading::Phong)]
        .into_iter()
        .map(|(m, s)| {
            let o = golden::render::RenderOptions::for_scene(&m, screen, s);
            (m, o)
        })
        .collect()
}

/// A progress report: phase name, done, total.
pub type Progress = Box<dyn FnMut(&str, u64, u64)>;

/// What the host loop needs of a chipset top: the ports both tops share (`host`), and the memory of
/// its RC (`chipset`: the Z-buffer; `chipset3`: TdbV), modelled by [`RcMemory`].
pub trait ChipsetTop: Block + ConfigPorts + Sized {
    /// The RC type the top builds.
    const TYPE: RcType;
    fn build(width: u32, height: u32) -> Result<Self, String>;
    /// The shared ports.
    fn host(&mut self) -> HostPorts<'_>;
    /// The shared ports, for the ports-only VCD.
    fn accept_host(&self, probe: &mut dyn Probe);
    /// The RC's own memory ports, for the ports-only VCD.
    fn accept_rc_memory(&self, probe: &mut dyn Probe);
    /// Drive the RC memory's read data (read at the last edge).
    fn drive_rc_memory(&mut self, m: &RcMemory);
    /// The RC memory's reads and writes at this edge (reads see the contents before the writes), counted.
    fn rc_memory_edge(&self, m: &mut RcMemory, t: &mut PortTraffic, cycle: u64) -> Result<(), String>;
    /// Any access on the RC memory's ports in this cycle.
    fn rc_memory_active(&self) -> bool;
    /// The texture ports (`chipset_tex`), if the top has them.
    fn texture(&mut self) -> Option<TexPorts<'_>> {
        None
    }
    /// The texture ports, for the ports-only VCD.
    fn accept_texture(&self, _probe: &mut dyn Probe) {}
}

/// The ports `chipset_tex` has beyond `chipset`'s (see `hdl::chipset::chipset_tex`).
pub struct TexPorts<'a> {
    pub setup_tex: &'a mut Signal<In, TexValues>,
    pub tt_re: &'a Signal<Out, Bit>,
    pub tt_rd_addr: &'a Signal<Out, Bits<17>>,
    pub tt_rd_data: &'a mut Signal<In, TdbtRecord>,
    pub tt_we: &'a Signal<Out, Bit>,
    pub tt_wr_addr: &'a Signal<Out, Bits<17>>,
    pub tt_wr_data: &'a Signal<Out, TdbtRecord>,
    pub scan_texture: &'a mut Signal<In, Bit>,
    pub tex_w0_log2: &'a mut Signal<In, Bits<4>>,
    pub tex_h0_log2: &'a mut Signal<In, Bits<4>>,
    pub tex_last_level: &'a mut Signal<In, Bits<4>>,
    pub tex_filter: &'a mut Signal<In, Bits<2>>,
    pub tex_clamp: &'a mut Signal<In, Bit>,
    pub tex_base_we: &'a mut Signal<In, Bit>,
    pub tex_base_sel: &'a mut Signal<In, Bits<4>>,
    pub tex_base_data: &'a mut Signal<In, Bits<ADDR_BITS>>,
    pub tex_rd: &'a Signal<Out, Bits<4>>,
    pub tex_addr: [&'a Signal<Out, Bits<ADDR_BITS>>; 4],
    pub tex_data: [&'a mut Signal<In, Bits<24>>; 4],
}

/// The ports that `chipset` and `chipset3` share, borrowed from either.
pub struct HostPorts<'a> {
    pub clock: &'a mut Signal<In, Clock>,
    pub rc_cmd: &'a mut StreamIn<RcCommand>,
    pub rc_result: &'a mut StreamOut<hdl::rc::RcResult>,
    pub setup_cmd: &'a mut StreamIn<hdl::cs::SetupCommand>,
    pub setup_busy: &'a mut Signal<Out, Bit>,
    pub scan_start: &'a mut Signal<In, Bit>,
    pub scan_background: &'a mut Signal<In, Bits<24>>,
    pub scan_clear_behind: &'a mut Signal<In, Bit>,
    pub scan_phong: &'a mut Signal<In, Bit>,
    pub scan_busy: &'a mut Signal<Out, Bit>,
    pub video_tdata: &'a mut Signal<Out, Bits<24>>,
    pub video_tvalid: &'a mut Signal<Out, Bit>,
    pub video_tready: &'a mut Signal<In, Bit>,
    pub video_tuser: &'a mut Signal<Out, Bit>,
    pub video_tlast: &'a mut Signal<Out, Bit>,
    pub id_re: &'a mut Signal<Out, Bit>,
    pub id_rd_addr: &'a mut Signal<Out, Bits<21>>,
    pub id_rd_data: &'a mut Signal<In, Bits<16>>,
    pub id_we: &'a mut Signal<Out, Bit>,
    pub id_wr_addr: &'a mut Signal<Out, Bits<21>>,
    pub id_wr_data: &'a mut Signal<Out, Bits<16>>,
    pub is_re: &'a mut Signal<Out, Bit>,
    pub is_rd_addr: &'a mut Signal<Out, Bits<21>>,
    pub is_rd_data: &'a mut Signal<In, Bits<16>>,
    pub is_we: &'a mut Signal<Out, Bit>,
    pub is_wr_addr: &'a mut Signal<Out, Bits<21>>,
    pub is_wr_data: &'a mut Signal<Out, Bits<16>>,
    pub t_re: &'a mut Signal<Out, Bit>,
    pub t_rd_addr: &'a mut Signal<Out, Bits<17>>,
    pub t_rd_data: &'a mut Signal<In, TdbsRecord>,
    pub t_we: &'a mut Signal<Out, Bit>,
    pub t_wr_addr: &'a mut Signal<Out, Bits<17>>,
    pub t_wr_data: &'a mut Signal<Out, TdbsRecord>,
    pub draw_bank: &'a mut Signal<Out, Bit>,
}

/// `host` and `accept_host` of a chipset top (the two tops have the same names for these ports).
macro_rules! shared_ports {
    () => {
        fn host(&mut self) -> HostPorts<'_> {
            HostPorts {
                clock: &mut self.clock,
                rc_cmd: &mut self.rc_cmd,
                rc_result: &mut self.rc_result,
                setup_cmd: &mut self.setup_cmd,
                setup_busy: &mut self.setup_busy,
                scan_start: &mut self.scan_start,
                scan_background: &mut self.scan_background,
                scan_clear_behind: &mut self.scan_clear_behind,
                scan_phong: &mut self.scan_phong,
                scan_busy: &mut self.scan_busy,
                video_tdata: &mut self.video_tdata,
                video_tvalid: &mut self.video_tvalid,
                video_tready: &mut self.video_tready,
                video_tuser: &mut self.video_tuser,
                video_tlast: &mut self.video_tlast,
                id_re: &mut self.id_re,
                id_rd_addr: &mut self.id_rd_addr,
                id_rd_data: &mut self.id_rd_data,
                id_we: &mut self.id_we,
                id_wr_addr: &mut self.id_wr_addr,
                id_wr_data: &mut self.id_wr_data,
                is_re: &mut self.is_re,
                is_rd_addr: &mut self.is_rd_addr,
                is_rd_data: &mut self.is_rd_data,
                is_we: &mut self.is_we,
                is_wr_addr: &mut self.is_wr_addr,
                is_wr_data: &mut self.is_wr_data,
                t_re: &mut self.t_re,
                t_rd_addr: &mut self.t_rd_addr,
                t_rd_data: &mut self.t_rd_data,
                t_we: &mut self.t_we,
                t_wr_addr: &mut self.t_wr_addr,
                t_wr_data: &mut self.t_wr_data,
                draw_bank: &mut self.draw_bank,
            }
        }
        fn accept_host(&self, probe: &mut dyn Probe) {
            self.clock.accept("clock", probe);
            self.rc_cmd.accept("rc_cmd", probe);
            self.rc_result.accept("rc_result", probe);
            self.setup_cmd.accept("setup_cmd", probe);
            self.setup_busy.accept("setup_busy", probe);
            self.scan_start.accept("scan_start", probe);
            self.scan_background.accept("scan_background", probe);
            self.scan_clear_behind.accept("scan_clear_behind", probe);
            self.scan_phong.accept("scan_phong", probe);
            self.light_write_enable.accept("light_write_enable", probe);
            self.light_write_address.accept("light_write_address", probe);
            self.light_write_data.accept("light_write_data", probe);
            self.material_write_enable.accept("material_write_enable", probe);
            self.material_write_address.accept("material_write_address", probe);
            self.material_write_slot.accept("material_write_slot", probe);
            self.material_write_data.accept("material_write_data", probe);
            self.scan_busy.accept("scan_busy", probe);
            self.video_tdata.accept("video_tdata", probe);
            self.video_tvalid.accept("video_tvalid", probe);
            self.video_tready.accept("video_tready", probe);
            self.video_tuser.accept("video_tuser", probe);
            self.video_tlast.accept("video_tlast", probe);
            self.id_re.accept("id_re", probe);
            self.id_rd_addr.accept("id_rd_addr", probe);
            self.id_rd_data.accept("id_rd_data", probe);
            self.id_we.accept("id_we", probe);
            self.id_wr_addr.accept("id_wr_addr", probe);
            self.id_wr_data.accept("id_wr_data", probe);
            self.is_re.accept("is_re", probe);
            self.is_rd_addr.accept("is_rd_addr", probe);
            self.is_rd_data.accept("is_rd_data", probe);
            self.is_we.accept("is_we", probe);
            self.is_wr_addr.accept("is_wr_addr", probe);
            self.is_wr_data.accept("is_wr_data", probe);
            self.t_re.accept("t_re", probe);
            self.t_rd_addr.accept("t_rd_addr", probe);
            self.t_rd_data.accept("t_rd_data", probe);
            self.t_we.accept("t_we", probe);
            self.t_wr_addr.accept("t_wr_addr", probe);
            self.t_wr_data.accept("t_wr_data", probe);
            self.draw_bank.accept("draw_bank", probe);
        }
    };
}

/// The memory behind the RC's own ports: the Z-buffer (Type IV) or TdbV (Type III).
pub struct RcMemory {
    pub zbuf: Vec<u32>,
    z_rd: u32,
    pub tdbv: Vec<Plane>,
    tdbv_rd: Plane,
}

/// The Z-buffer ports' methods of `chipset` and `chipset_tex` (the same RC, the same names).
macro_rules! z_memory {
    () => {
        fn accept_rc_memory(&self, probe: &mut dyn Probe) {
            self.z_re.accept("z_re", probe);
            self.z_rd_addr.accept("z_rd_addr", probe);
            self.z_rd_data.accept("z_rd_data", probe);
            self.z_we.accept("z_we", probe);
            self.z_wr_addr.accept("z_wr_addr", probe);
            self.z_wr_data.accept("z_wr_data", probe);
        }
        fn drive_rc_memory(&mut self, m: &RcMemory) {
            self.z_rd_data.next = (m.z_rd as u64).into();
        }
        fn rc_memory_edge(&self, m: &mut RcMemory, t: &mut PortTraffic, cycle: u64) -> Result<(), String> {
            let n = m.zbuf.len();
            let bad = |what: &str, a: usize| format!("chipset: {what} address {a:#x} outside the buffer (W*H = {n} words) in cycle {cycle}");
            if self.z_re.val() {
                let a = self.z_rd_addr.val().index();
                m.z_rd = *m.zbuf.get(a).ok_or_else(|| bad("Z read", a))?;
                t.z_reads += 1;
            }
            if self.z_we.val() {
                let a = self.z_wr_addr.val().index();
                *m.zbuf.get_mut(a).ok_or_else(|| bad("Z write", a))? = self.z_wr_data.val().to_u64() as u32;
                t.z_writes += 1;
            }
            Ok(())
        }
        fn rc_memory_active(&self) -> bool {
            self.z_re.val() || self.z_we.val()
        }
    };
}

impl ChipsetTop for ChipsetRtl {
    const TYPE: RcType = RcType::IV;
    fn build(width: u32, height: u32) -> Result<Self, String> {
        ChipsetRtl::new(width, height)
    }
    shared_ports!();
    z_memory!();
}

impl ChipsetTop for ChipsetTexRtl {
    const TYPE: RcType = RcType::IV;
    fn build(width: u32, height: u32) -> Result<Self, String> {
        ChipsetTexRtl::new(width, height)
    }
    shared_ports!();
    z_memory!();
    fn texture(&mut self) -> Option<TexPorts<'_>> {
        Some(TexPorts {
            setup_tex: &mut self.setup_tex,
            tt_re: &self.tt_re,
            tt_rd_addr: &self.tt_rd_addr,
            tt_rd_data: &mut self.tt_rd_data,
            tt_we: &self.tt_we,
            tt_wr_addr: &self.tt_wr_addr,
            tt_wr_data: &self.tt_wr_data,
            scan_texture: &mut self.scan_texture,
            tex_w0_log2: &mut self.tex_w0_log2,
            tex_h0_log2: &mut self.tex_h0_log2,
            tex_last_level: &mut self.tex_last_level,
            tex_filter: &mut self.tex_filter,
            tex_clamp: &mut self.tex_clamp,
            tex_base_we: &mut self.tex_base_we,
            tex_base_sel: &mut self.tex_base_sel,
            tex_base_data: &mut self.tex_base_data,
            tex_rd: &self.tex_rd,
            tex_addr: [&self.tex_addr0, &self.tex_addr1, &self.tex_addr2, &self.tex_addr3],
            tex_data: [&mut self.tex_data0, &mut self.tex_data1, &mut self.tex_data2, &mut self.tex_data3],
        })
    }
    fn accept_texture(&self, probe: &mut dyn Probe) {
        self.setup_tex.accept("setup_tex", probe);
        self.tt_re.accept("tt_re", probe);
        self.tt_rd_addr.accept("tt_rd_addr", probe);
        self.tt_rd_data.accept("tt_rd_data", probe);
        self.tt_we.accept("tt_we", probe);
        self.tt_wr_addr.accept("tt_wr_addr", probe);
        self.tt_wr_data.accept("tt_wr_data", probe);
        self.scan_texture.accept("scan_texture", probe);
        self.tex_w0_log2.accept("tex_w0_log2", probe);
        self.tex_h0_log2.accept("tex_h0_log2", probe);
        self.tex_last_level.accept("tex_last_level", probe);
        self.tex_filter.accept("tex_filter", probe);
        self.tex_clamp.accept("tex_clamp", probe);
        self.tex_base_we.accept("tex_base_we", probe);
        self.tex_base_sel.accept("tex_base_sel", probe);
        self.tex_base_data.accept("tex_base_data", probe);
        self.tex_rd.accept("tex_rd", probe);
        self.tex_addr0.accept("tex_addr0", probe);
        self.tex_addr1.accept("tex_addr1", probe);
        self.tex_addr2.accept("tex_addr2", probe);
        self.tex_addr3.accept("tex_addr3", probe);
        self.tex_data0.accept("tex_data0", probe);
        self.tex_data1.accept("tex_data1", probe);
        self.tex_data2.accept("tex_data2", probe);
        self.tex_data3.accept("tex_data3", probe);
    }
}

impl ChipsetTop for Chipset3Rtl {
    const TYPE: RcType = RcType::III;
    fn build(width: u32, height: u32) -> Result<Self, String> {
        Chipset3Rtl::new(width, height)
    }
    shared_ports!();
    fn accept_rc_memory(&self, probe: &mut dyn Probe) {
        self.tdbv_re.accept("tdbv_re", probe);
        self.tdbv_rd_addr.accept("tdbv_rd_addr", probe);
        self.tdbv_rd_a.accept("tdbv_rd_a", probe);
        self.tdbv_rd_b.accept("tdbv_rd_b", probe);
        self.tdbv_rd_c.accept("tdbv_rd_c", probe);
        self.tdbv_we.accept("tdbv_we", probe);
        self.tdbv_wr_addr.accept("tdbv_wr_addr", probe);
        self.tdbv_wr_a.accept("tdbv_wr_a", probe);
        self.tdbv_wr_b.accept("tdbv_wr_b", probe);
        self.tdbv_wr_c.accept("tdbv_wr_c", probe);
    }
    fn drive_rc_memory(&mut self, m: &RcMemory) {
        self.tdbv_rd_a.next = hdl::common::from_i64::<40>(m.tdbv_rd.a);
        self.tdbv_rd_b.next = hdl::common::from_i64::<40>(m.tdbv_rd.b);
        self.tdbv_rd_c.next = hdl::common::from_i64::<56>(m.tdbv_rd.c);
    }
    fn rc_memory_edge(&self, m: &mut RcMemory, t: &mut PortTraffic, _cycle: u64) -> Result<(), String> {
        // 16 address bits: every address is inside TdbV's 2^16 records.
        if self.tdbv_re.val() {
            m.tdbv_rd = m.tdbv[self.tdbv_rd_addr.val().index()];
            t.tdbv_reads += 1;
        }
        if self.tdbv_we.val() {
            use hdl::common::to_i64;
            m.tdbv[self.tdbv_wr_addr.val().index()] = Plane { a: to_i64(self.tdbv_wr_a.val()), b: to_i64(self.tdbv_wr_b.val()), c: to_i64(self.tdbv_wr_c.val()) };
            t.tdbv_writes += 1;
        }
        Ok(())
    }
    fn rc_memory_active(&self) -> bool {
        self.tdbv_re.val() || self.tdbv_we.val()
    }
}

/// The RustHDL simulation of a chipset top (`chipset`, or `chipset3` for Type III) with its memories.
pub struct RtlChipsetOf<T: ChipsetTop> {
    pub screen: Screen,
    uut: Box<T>,
    rc_mem: RcMemory,
    /// Two banks of W*H words: bank b at b*W*H.
    ibuf: Vec<u32>,
    /// Two banks of 2^16 records: bank b at b*2^16.
    tdbs: Vec<TdbsRecord>,
    id_rd: u32,
    is_rd: u32,
    t_rd: TdbsRecord,
    /// Two banks of 2^16 TdbT records (a textured top's; empty otherwise).
    tdbt: Vec<TdbtRecord>,
    tt_rd: TdbtRecord,
    /// The texture the host has loaded into the four texture banks (one bank set: loaded before a
    /// textured frame's scan starts), and what the banks return (latency 1).
    tex_banks: Option<std::sync::Arc<[Vec<[u8; 3]>; 4]>>,
    tex_rd: [u64; 4],
    /// The texture ports' words at the last edge.
    edge_tex: TexTraffic,
    pub cycle: u64,
    /// Cycles per phase of the last frame.
    pub phases: PhaseCycles,
    /// Cycles per phase of every frame of the last run.
    pub frame_phases: Vec<PhaseCycles>,
    /// Frames started since reset: frames 0 and 1 clear their bank, later ones find it cleared.
    frames_started: u64,
    vcd: Option<VCDProbe<BufWriter<File>>>,
    progress: Option<Progress>,
    vcd_scope: VcdScope,
    /// How the host loop drives the streams.
    pub drive: HostDrive,
    /// Where the waveform goes, for the watchdog's message.
    vcd_path: Option<PathBuf>,
}

/// The Type IV chipset (`chipset`: Z-buffer and I-buffer).
pub type RtlChipset = RtlChipsetOf<ChipsetRtl>;
/// The Type III chipset (`chipset3`: I-buffer and TdbV, no Z-buffer).
pub type RtlChipset3 = RtlChipsetOf<Chipset3Rtl>;
/// The textured chipset (`chipset_tex`: `chipset` with TdbT and four texture banks).
pub type RtlChipsetTex = RtlChipsetOf<ChipsetTexRtl>;

/// Words on a textured top's own ports in one cycle or one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexTraffic {
    pub tdbt_reads: u64,
    pub tdbt_writes: u64,
    /// Words read from the four texture banks (the bits of `tex_rd`).
    pub bank_words: u64,
    /// Cycles with a texture-bank read: one level's footprint each (a trilinear pixel between two
    /// levels reads two).
    pub footprints: u64,
    /// Scan-side I-buffer reads of a triangle's index (not the background): the pixels the CS textures.
    pub covered_reads: u64,
}

impl TexTraffic {
    /// Field names and values, for `cycles.json`.
    pub fn fields(&self) -> [(&'static str, u64); 5] {
        [("tdbt_reads", self.tdbt_reads), ("tdbt_writes", self.tdbt_writes), ("texture_bank_words", self.bank_words), ("texture_footprints", self.footprints), ("covered_scan_reads", self.covered_reads)]
    }
    fn add(&mut self, t: &TexTraffic) {
        self.tdbt_reads += t.tdbt_reads;
        self.tdbt_writes += t.tdbt_writes;
        self.bank_words += t.bank_words;
        self.footprints += t.footprints;
        self.covered_reads += t.covered_reads;
    }
}

/// Cycles without any activity at the ports (a command or result taken, a memory read or write, a
/// pixel, a Phong constant written) after which a run is stopped as hung: more than any one triangle can
/// need (a setup, then a bounding box of the whole screen with no covered pixel).
pub fn watchdog_cycles(screen: Screen) -> u64 {
    screen.pixels() as u64 + 1024
}

/// What a VCD of the chipset holds.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum VcdScope {
    /// The top-level ports (as Verilator's `--trace-depth 1` would show them): a frame in tens of MB.
    Ports,
    /// Every signal of every block: hundreds of MB per 320x200 frame.
    Full,
}


/// A chipset top seen through its ports only: a block that rust-hdl's VCD writer walks instead of
/// the whole hierarchy (same scope `uut` and names as a full dump).
struct Ports<'a, T: ChipsetTop>(&'a T);

impl<T: ChipsetTop> Logic for Ports<'_, T> {
    fn update(&mut self) {}
}

impl<T: ChipsetTop> Block for Ports<'_, T> {
    fn connect_all(&mut self) {}
    fn update_all(&mut self) {}
    fn has_changed(&self) -> bool {
        false
    }
    fn accept(&self, name: &str, probe: &mut dyn Probe) {
        probe.visit_start_scope(name, self);
        self.0.accept_host(probe);
        self.0.accept_rc_memory(probe);
        self.0.accept_texture(probe);
        probe.visit_end_scope(name, self);
    }
}

impl<T: ChipsetTop> RtlChipsetOf<T> {
    /// A chipset for `screen`; with `vcd`, the top-level ports at every settle are written there.
    pub fn new(screen: Screen, vcd: Option<PathBuf>) -> Result<RtlChipsetOf<T>, String> {
        Self::with_vcd_scope(screen, vcd, VcdScope::Ports)
    }

    /// As [`RtlChipset::new`], choosing what the VCD holds.
    pub fn with_vcd_scope(screen: Screen, vcd: Option<PathBuf>, scope: VcdScope) -> Result<RtlChipsetOf<T>, String> {
        let mut uut = Box::new(T::build(screen.width, screen.height)?);
        uut.connect_all();
        let textured = uut.texture().is_some();
        check_all(uut.as_ref()).map_err(|e| format!("chipset: rust-hdl check failed: {e:?}"))?;
        let vcd_path = vcd.clone();
        let vcd = match vcd {
            Some(p) => {
                let f = File::create(&p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
                let v = match scope {
                    VcdScope::Ports => write_vcd_dump(write_vcd_header(BufWriter::new(f), &Ports(uut.as_ref())), &Ports(uut.as_ref())),
                    VcdScope::Full => write_vcd_dump(write_vcd_header(BufWriter::new(f), uut.as_ref()), uut.as_ref()),
                };
                Some(v)
            }
            None => None,
        };
        // After reset the memories hold garbage; the first frame's clear puts them in order.
        let n = screen.pixels();
        // The RC's memory: Type IV's Z-buffer, or Type III's TdbV, whose garbage is a plane whose depth
        // would win over most fragments, were it ever read.
        let (zbuf, tdbv) = match T::TYPE {
            RcType::IV => ((0..n).map(|i| (i as u32).wrapping_mul(2654435761) & DEPTH_MAX).collect(), Vec::new()),
            RcType::III => (Vec::new(), vec![Plane { a: 0, b: 0, c: -1 << 40 }; 1 << 16]),
        };
        Ok(RtlChipsetOf {
            screen,
            uut,
            rc_mem: RcMemory { zbuf, z_rd: 0, tdbv, tdbv_rd: Plane::default() },
            ibuf: (0..2 * n).map(|i| (i as u32).wrapping_mul(40503) & 0xffff).collect(),
            tdbs: vec![TdbsRecord::default(); 2 << 16],
            id_rd: 0,
            is_rd: 0,
            t_rd: TdbsRecord::default(),
            tdbt: if textured { vec![TdbtRecord::default(); 2 << 16] } else { Vec::new() },
            tt_rd: TdbtRecord::default(),
            tex_banks: None,
            tex_rd: [0; 4],
            edge_tex: TexTraffic::default(),
            cycle: 0,
            phases: PhaseCycles::default(),
            frame_phases: Vec::new(),
            frames_started: 0,
            vcd,
            progress: None,
            vcd_scope: scope,
            drive: HostDrive::default(),
            vcd_path,
        })
    }

    /// Close the VCD (flushing it); it is also closed when the simulation is dropped.
    pub fn finish_vcd(&mut self) {
        self.vcd = None;
    }

    /// Drive the streams with random gaps and back-pressure.
    pub fn with_drive(mut self, d: HostDrive) -> RtlChipsetOf<T> {
        self.drive = d;
        self
    }

    /// Report progress through `f(phase, done, total)`.
    pub fn with_progress(mut self, f: Progress) -> RtlChipsetOf<T> {
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
            v.timestamp(self.cycle * 10 + if self.uut.host().clock.val().clk { 5 } else { 0 }).map_err(|e| format!("VCD: {e}"))?;
            self.vcd = Some(match self.vcd_scope {
                VcdScope::Ports => write_vcd_change(v, &Ports(self.uut.as_ref())),
                VcdScope::Full => write_vcd_change(v, self.uut.as_ref()),
            });
        }
        Ok(())
    }

    /// One clock: inputs (already set by the caller) settle with the clock low; the memories take
    /// their reads and writes at the edge; then the rising edge. Returns nothing: the caller samples
    /// the handshakes between [`RtlChipset::low`] and [`RtlChipset::high`].
    fn low(&mut self) -> Result<(), String> {
        self.uut.drive_rc_memory(&self.rc_mem);
        let u = self.uut.host();
        u.id_rd_data.next = (self.id_rd as u64).into();
        u.is_rd_data.next = (self.is_rd as u64).into();
        u.t_rd_data.next = self.t_rd;
        u.clock.next = false.into();
        let (tt_rd, tex_rd) = (self.tt_rd, self.tex_rd);
        if let Some(x) = self.uut.texture() {
            x.tt_rd_data.next = tt_rd;
            for (d, v) in x.tex_data.into_iter().zip(tex_rd) {
                d.next = v.into();
            }
        }
        self.settle()
    }

    /// The edge; returns the words on each port in this cycle.
    fn high(&mut self) -> Result<PortTraffic, String> {
        let n = self.screen.pixels();
        let cycle = self.cycle;
        let bad = |what: &str, a: usize| format!("chipset: {what} address {a:#x} outside the buffer (W*H = {n} words per bank) in cycle {cycle}");
        // I-buffer address: bit 20 the bank, bits 19:0 the pixel.
        let ia = |what: &str, a: usize| if a & 0xfffff < n { Ok((a >> 20) * n + (a & 0xfffff)) } else { Err(bad(what, a)) };
        let mut t = PortTraffic::default();
        self.uut.rc_memory_edge(&mut self.rc_mem, &mut t, cycle)?;
        let u = self.uut.host();
        // Reads see the contents before this edge's writes.
        if u.id_re.val() {
            self.id_rd = self.ibuf[ia("I read (draw side)", u.id_rd_addr.val().index())?];
            t.i_reads += 1;
        }
        if u.is_re.val() {
            self.is_rd = self.ibuf[ia("I read (scan side)", u.is_rd_addr.val().index())?];
            t.scan_i_reads += 1;
        }
        if u.t_re.val() {
            self.t_rd = self.tdbs[u.t_rd_addr.val().index()];
            t.tdbs_reads += 1;
        }
        let (dw, sw) = (u.id_we.val(), u.is_we.val());
        let (da, sa) = (u.id_wr_addr.val().index(), u.is_wr_addr.val().index());
        if dw && sw && da == sa {
            return Err(format!("chipset: both I-buffer write ports write address {da:#x} in cycle {cycle}"));
        }
        if dw {
            self.ibuf[ia("I write (draw side)", da)?] = u.id_wr_data.val().to_u64() as u32;
            t.i_writes += 1;
        }
        if sw {
            self.ibuf[ia("I write (scan side)", sa)?] = u.is_wr_data.val().to_u64() as u32;
            t.scan_i_writes += 1;
        }
        if u.t_we.val() {
            let a = u.t_wr_addr.val().index();
            self.tdbs[a] = u.t_wr_data.val();
            t.tdbs_writes += 1;
        }
        let covered = u.is_re.val() && self.is_rd != INDEX_BACKGROUND;
        let mut x = TexTraffic::default();
        if let Some(p) = self.uut.texture() {
            x.covered_reads = covered as u64;
            if p.tt_re.val() {
                self.tt_rd = self.tdbt[p.tt_rd_addr.val().index()];
                x.tdbt_reads += 1;
            }
            if p.tt_we.val() {
                self.tdbt[p.tt_wr_addr.val().index()] = p.tt_wr_data.val();
                x.tdbt_writes += 1;
            }
            let rd = p.tex_rd.val().to_u64();
            if rd != 0 {
                let banks = self.tex_banks.as_ref().ok_or_else(|| format!("chipset: a texture read in cycle {cycle} with no texture loaded"))?;
                for k in 0..4 {
                    if rd >> k & 1 == 1 {
                        let a = p.tex_addr[k].val().index();
                        let w = banks[k].get(a).ok_or_else(|| format!("chipset: texture bank {k} read at {a:#x}, outside its {} words, in cycle {cycle}", banks[k].len()))?;
                        self.tex_rd[k] = tdata_of(*w) as u64;
                        x.bank_words += 1;
                    }
                }
                x.footprints += 1;
            }
        }
        self.edge_tex = x;
        let u = self.uut.host();
        u.clock.next = true.into();
        self.settle()?;
        self.cycle += 1;
        Ok(t)
    }

    fn idle_inputs(&mut self) {
        let u = self.uut.host();
        u.rc_cmd.valid.next = false;
        u.rc_result.ready.next = true;
        u.setup_cmd.valid.next = false;
        u.scan_start.next = false;
        u.video_tready.next = true;
        // Phong-constant writes: none, and payloads 0.
        crate::cs::color_shader_bench::drive_config(&mut *self.uut, None);
        if let Some(x) = self.uut.texture() {
            x.tex_base_we.next = false;
        }
    }

    /// A cycle budget that no correct frame reaches: a hang is an error, not an endless loop.
    fn budget(&self, work: u64) -> u64 {
        1_000_000 + 64 * work
    }

    /// I-buffer bank `b` and the depths as the RC sees them: Type IV's Z-buffer (a stale depth under
    /// the background index counts as 2^24-1), Type III's planes regenerated from TdbV.
    fn snapshot(&self, b: usize) -> (Vec<u32>, Vec<u32>) {
        let n = self.screen.pixels();
        let ib = self.ibuf[b * n..(b + 1) * n].to_vec();
        let zb = match T::TYPE {
            RcType::IV => depths_as_seen(&ib, &self.rc_mem.zbuf),
            RcType::III => crate::rc::bench::regenerated_depths(self.screen, &ib, &self.rc_mem.tdbv),
        };
        (ib, zb)
    }
}

/// The Z-buffer as the RC sees it: 2^24-1 where the I-buffer holds the background index (a stale depth
/// of an earlier frame), the stored depth elsewhere. What the frame is compared with golden on.
pub fn depths_as_seen(ibuf: &[u32], zbuf: &[u32]) -> Vec<u32> {
    ibuf.iter().zip(zbuf).map(|(&i, &z)| if i == INDEX_BACKGROUND { DEPTH_MAX } else { z }).collect()
}

/// One frame's work in the host loop, with the cycles at which things happened.
pub(crate) struct FrameRun {
    pub words: Vec<RcCommand>,
    pub tris: Vec<u32>,
    pub config: Vec<CsConfigWrite>,
    pub phong: bool,
    pub background: u32,
    pub results: Vec<TriResult>,
    pub start: Option<u64>,
    pub first_tri_taken: Option<u64>,
    pub last_cmd_taken: u64,
    pub eof: Option<u64>,
    pub clear_writes: u64,
    pub z_reads: u64,
    /// Words on each memory port for this frame.
    pub traffic: PortTraffic,
    pub setup_first: Option<u64>,
    pub drawn: Option<u64>,
    pub scan_begin: Option<u64>,
    pub scan_taken: Option<u64>,
    pub scan_done: Option<u64>,
    /// The frame's texture, when it is textured.
    pub tex: Option<crate::cs::color_shader_bench::FrameTexture>,
    /// The texture ports' words while the frame was drawn (TdbT writes) and scanned out.
    pub tex_traffic: TexTraffic,
}

/// Why the RTL chipsets refuse a textured frame (the CLI says it before it simulates anything).
pub fn texturing_unsupported(t: &golden::render::Texturing) -> String {
    format!(
        "texture mapping ({}): this top has no texture port; the textured chipset is `chipset_tex` (RtlChipsetTex, VerilatorChipset::textured, which `render` picks for a textured scene), or use --no-texture to draw the scene untextured",
        t.source
    )
}

impl FrameRun {
    /// The RC words and scan parameters of `job`; `clear`: the frame clears its bank itself.
    pub(crate) fn new(job: &FrameJob, clear: bool, textured_top: bool) -> Result<FrameRun, String> {
        if let (Some(t), false) = (&job.texturing, textured_top) {
            return Err(texturing_unsupported(t));
        }
        let cmds = crate::rc::stimulus::job_frame(job, clear)?;
        let phong = job.shading == Shading::Phong;
        Ok(FrameRun {
            words: cmds.iter().map(command_word).collect(),
            tris: job.tris.iter().map(|t| t.index).collect(),
            config: if phong { phong_config(&job.lights)? } else { Vec::new() },
            phong,
            background: tdata_of(job.background),
            results: Vec::with_capacity(job.tris.len()),
            start: None,
            first_tri_taken: None,
            last_cmd_taken: 0,
            eof: None,
            clear_writes: 0,
            z_reads: 0,
            traffic: PortTraffic::default(),
            setup_first: None,
            drawn: None,
            scan_begin: None,
            scan_taken: None,
            scan_done: None,
            tex: job.texturing.as_ref().map(crate::cs::color_shader_bench::FrameTexture::of),
            tex_traffic: TexTraffic::default(),
        })
    }

    /// Writes before the scan starts: the Phong constants, then the level table.
    pub(crate) fn config_writes(&self) -> usize {
        self.config.len() + self.tex.as_ref().map_or(0, |t| t.bases.len())
    }

    /// What the CS's texture path did in this frame, counted at the ports.
    pub(crate) fn texture_counts(&self) -> Option<golden::render::TextureCounts> {
        self.tex.as_ref().map(|t| golden::render::TextureCounts {
            samples: self.tex_traffic.covered_reads,
            texels_read: self.tex_traffic.footprints * t.texels_per_footprint,
            bank_words: self.tex_traffic.bank_words,
        })
    }

    /// A result for this frame: the next triangle's. Returns whether the host must light it.
    pub(crate) fn result(&mut self, r: TriResult) -> Result<bool, String> {
        let k = self.results.len();
        match self.tris.get(k) {
            Some(&i) if i == r.index => {}
            Some(&i) => return Err(format!("chipset: result for triangle index {} where {i} was next", r.index)),
            None => return Err(format!("chipset: more results than the {} triangles sent", self.tris.len())),
        }
        self.results.push(r);
        Ok(r.visible)
    }

    pub(crate) fn phases(&self, prev_scan_taken: Option<u64>) -> PhaseCycles {
        let start = self.start.unwrap_or(0);
        let eof = self.eof.unwrap_or(start);
        let done = self.scan_done.unwrap_or(eof);
        PhaseCycles {
            clear: self.clear_writes,
            geometry_transfer: self.last_cmd_taken - self.first_tri_taken.unwrap_or(self.last_cmd_taken),
            rasterization: eof - start,
            colour_setup: self.setup_first.map_or(0, |f| self.drawn.unwrap_or(f) - f),
            scan_out: done - self.scan_begin.unwrap_or(done),
            total: done - start,
            frame_interval: prev_scan_taken.zip(self.scan_taken).map(|(a, b)| b - a),
            z_reads: self.z_reads,
            traffic: self.traffic.clone(),
            texture: self.tex_traffic,
        }
    }
}

/// An RC result word as the host reads it.
pub fn tri_result(r: &hdl::rc::RcResult) -> TriResult {
    let culled = if r.zero_area {
        Some(Culled::ZeroArea)
    } else if r.culled {
        Some(Culled::Facing)
    } else {
        None
    };
    TriResult { index: r.index.to_u64() as u32, culled, visible: r.visible }
}

/// Where the scan-out of the next frame stands.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum ScanState {
    /// Waiting for the frame to be drawn and the previous scan-out to end.
    Wait,
    /// Writing Phong constant k.
    Config(usize),
    /// Offering `scan_start`.
    Start,
    /// Taking pixels.
    Running,
}

impl<T: ChipsetTop> Chipset for RtlChipsetOf<T> {
    fn run(&mut self, jobs: &[FrameJob], host: &mut dyn LowerPipeline) -> Result<Vec<FrameOut>, String> {
        let mut frames = Vec::with_capacity(jobs.len());
        for job in jobs {
            frames.push(FrameRun::new(job, self.frames_started < 2, self.uut.texture().is_some())?);
            self.frames_started += 1;
        }
        let nf = frames.len();
        let (w, h) = (self.screen.width as usize, self.screen.height as usize);
        let mut outs: Vec<Option<FrameOut>> = vec![None; nf];
        let mut rgb: Vec<u8> = Vec::with_capacity(w * h * 3);
        let (mut rc_f, mut rc_next, mut res_f, mut draw_f, mut scan_f) = (0usize, 0usize, 0usize, 0usize, 0usize);
        let mut queue: VecDeque<(usize, hdl::cs::SetupCommand, TexValues)> = VecDeque::new();
        let mut scan = ScanState::Wait;
        let mut pixels = 0usize;
        let work: u64 = jobs.iter().map(|j| self.screen.pixels() as u64 + 128 * j.tris.len() as u64).sum();
        let (start, limit) = (self.cycle, self.cycle + self.budget(work) * (1 + self.drive.gap_percent.max(self.drive.stall_percent) / 10));
        let d = self.drive;
        let mut rng = crate::common::Rng::new(d.seed);
        let (mut rc_presenting, mut setup_presenting) = (false, false);
        let (watchdog, mut last_activity) = (watchdog_cycles(self.screen), self.cycle);
        while scan_f < nf {
            self.idle_inputs();
            // Random gaps and stalls, drawn in this order every cycle (the Verilator harness does the same).
            let rc_can = rc_f < nf && rc_next < frames[rc_f].words.len() && (rc_f == 0 || frames[rc_f - 1].scan_taken.is_some());
            if rc_can && !rc_presenting {
                rc_presenting = !(d.gap_percent > 0 && rng.chance(d.gap_percent));
            }
            if !queue.is_empty() && !setup_presenting {
                setup_presenting = !(d.gap_percent > 0 && rng.chance(d.gap_percent));
            }
            let res_ready = !(d.stall_percent > 0 && rng.chance(d.stall_percent));
            let video_ready = !(d.stall_percent > 0 && rng.chance(d.stall_percent));
            self.uut.host().rc_result.ready.next = res_ready;
            self.uut.host().video_tready.next = video_ready;
            // Upper pipeline: frame rc_f's commands, once the previous frame's scan-out has started.
            let rc_offer = rc_can && rc_presenting;
            if rc_offer {
                let u = self.uut.host();
                u.rc_cmd.valid.next = true;
                u.rc_cmd.data.next = frames[rc_f].words[rc_next];
                frames[rc_f].start.get_or_insert(self.cycle);
            }
            // Lower pipeline: the queued colour-setup commands.
            let setup_offer = !queue.is_empty() && setup_presenting;
            if let (true, Some((f, c, tv))) = (setup_offer, queue.front()) {
                let u = self.uut.host();
                u.setup_cmd.valid.next = true;
                u.setup_cmd.data.next = *c;
                if let Some(x) = self.uut.texture() {
                    x.setup_tex.next = *tv;
                }
                frames[*f].setup_first.get_or_insert(self.cycle);
            }
            // Scan-out of frame scan_f.
            if scan == ScanState::Wait && frames[scan_f].drawn.is_some() && (scan_f == 0 || frames[scan_f - 1].scan_done.is_some()) {
                frames[scan_f].scan_begin = Some(self.cycle);
                scan = if frames[scan_f].config_writes() == 0 { ScanState::Start } else { ScanState::Config(0) };
                // No scan runs: the host loads the frame's texture into the banks.
                if let Some(t) = &frames[scan_f].tex {
                    self.tex_banks = Some(t.banks.clone());
                }
            }
            let sf = &frames[scan_f];
            let u = self.uut.host();
            u.scan_background.next = (sf.background as u64).into();
            u.scan_clear_behind.next = true;
            u.scan_phong.next = sf.phong;
            if let Some(x) = self.uut.texture() {
                x.scan_texture.next = sf.tex.is_some();
                if let Some(t) = &sf.tex {
                    x.tex_w0_log2.next = (t.w0_log2 as u64).into();
                    x.tex_h0_log2.next = (t.h0_log2 as u64).into();
                    x.tex_last_level.next = (t.last_level as u64).into();
                    x.tex_filter.next = t.filter.into();
                    x.tex_clamp.next = t.clamp;
                }
            }
            match scan {
                ScanState::Config(k) if k < sf.config.len() => crate::cs::color_shader_bench::drive_config(&mut *self.uut, Some(sf.config[k])),
                ScanState::Config(k) => {
                    let level = k - sf.config.len();
                    let base = sf.tex.as_ref().map_or(0, |t| t.bases[level]);
                    if let Some(x) = self.uut.texture() {
                        x.tex_base_we.next = true;
                        x.tex_base_sel.next = (level as u64).into();
                        x.tex_base_data.next = (base as u64).into();
                    }
                }
                ScanState::Start => self.uut.host().scan_start.next = true,
                _ => {}
            }
            self.low()?;
            let rc_mem_active = self.uut.rc_memory_active();
            let u = self.uut.host();
            let rc_taken = rc_offer && u.rc_cmd.ready.val();
            let setup_taken = setup_offer && u.setup_cmd.ready.val();
            let setup_busy = u.setup_busy.val() || u.t_we.val();
            let start_taken = scan == ScanState::Start && !u.scan_busy.val();
            let scan_busy = u.scan_busy.val();
            if res_f < nf {
                frames[res_f].z_reads += u.id_re.val() as u64;
                frames[res_f].clear_writes += (u.id_we.val() && u.id_wr_data.val().to_u64() == 0) as u64;
            }
            let result = (u.rc_result.valid.val() && res_ready).then(|| u.rc_result.data.val());
            let beat = if u.video_tvalid.val() && video_ready {
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
            let draw_bank = u.draw_bank.val() as usize;
            let active = rc_taken
                || setup_taken
                || start_taken
                || (u.rc_result.valid.val() && res_ready)
                || (u.video_tvalid.val() && video_ready)
                || rc_mem_active
                || u.id_re.val()
                || u.id_we.val()
                || u.is_we.val()
                || u.t_we.val()
                || matches!(scan, ScanState::Config(_));
            // The host answers a visible result at once (its command is offered from the next cycle).
            let mut eof = false;
            if let Some(r) = result {
                if res_f >= nf {
                    return Err(format!("chipset: a result after the last frame's end of frame in cycle {}", self.cycle));
                }
                if r.eof {
                    eof = true;
                } else if frames[res_f].result(tri_result(&r))? {
                    let position = frames[res_f].results.len() - 1;
                    let c = host.visible(res_f, position)?;
                    let tv = crate::cs::pack::tex_values_of(&c.tex.unwrap_or_default());
                    queue.push_back((res_f, command_of(&SetupCmd::from_command(&c)?), tv));
                }
            }
            let words = self.high()?;
            // The draw side's words go to the frame being drawn: the RC's to frame res_f (its end of
            // frame result ends them), colour setup's to frame draw_f; the scan side's to frame scan_f.
            if let Some(fr) = frames.get_mut(res_f) {
                fr.traffic.add_rc(&words);
            }
            let tex_words = self.edge_tex;
            if let Some(fr) = frames.get_mut(draw_f) {
                fr.traffic.tdbs_writes += words.tdbs_writes;
                fr.tex_traffic.tdbt_writes += tex_words.tdbt_writes;
            }
            if let Some(fr) = frames.get_mut(scan_f) {
                fr.traffic.add_scan(&words);
                fr.tex_traffic.add(&TexTraffic { tdbt_writes: 0, ..tex_words });
            }
            let now = self.cycle;
            if rc_taken {
                rc_presenting = false;
                let fr = &mut frames[rc_f];
                if rc_next == 1 {
                    fr.first_tri_taken = Some(now - 1);
                }
                fr.last_cmd_taken = now;
                rc_next += 1;
                if rc_next == fr.words.len() {
                    (rc_f, rc_next) = (rc_f + 1, 0);
                }
            }
            if setup_taken {
                queue.pop_front();
                setup_presenting = false;
            }
            if eof {
                let fr = &mut frames[res_f];
                if fr.results.len() != fr.tris.len() {
                    return Err(format!("chipset: {} results for {} triangles", fr.results.len(), fr.tris.len()));
                }
                fr.eof = Some(now);
                let (ibuf, zbuf) = self.snapshot(draw_bank);
                outs[res_f] = Some(FrameOut {
                    results: std::mem::take(&mut fr.results),
                    scan: ScanOut { rgb: Vec::new(), ibuf, zbuf },
                    rc_counts: None,
                    texture_counts: None,
                });
                res_f += 1;
            }
            if draw_f < nf && frames[draw_f].eof.is_some() && queue.is_empty() && !setup_taken && !setup_busy {
                frames[draw_f].drawn = Some(now);
                draw_f += 1;
            }
            match scan {
                ScanState::Config(k) => scan = if k + 1 == frames[scan_f].config_writes() { ScanState::Start } else { ScanState::Config(k + 1) },
                ScanState::Start if start_taken => {
                    frames[scan_f].scan_taken = Some(now - 1);
                    scan = ScanState::Running;
                }
                _ => {}
            }
            if let Some(p) = beat {
                if scan != ScanState::Running || pixels == w * h {
                    return Err(format!("chipset: a pixel no scan-out asked for in cycle {}", now - 1));
                }
                rgb.extend_from_slice(&p);
                pixels += 1;
                if pixels % 4096 == 0 {
                    self.report("scan-out", pixels as u64, (w * h) as u64);
                }
            }
            if scan == ScanState::Running && pixels == w * h && !scan_busy {
                frames[scan_f].scan_done = Some(now);
                let out = outs[scan_f].as_mut().ok_or("chipset: a frame scanned out before its end of frame")?;
                out.scan.rgb = std::mem::replace(&mut rgb, Vec::with_capacity(w * h * 3));
                out.texture_counts = frames[scan_f].texture_counts();
                (scan, pixels) = (ScanState::Wait, 0);
                scan_f += 1;
            }
            if now % 4096 == 0 && res_f < nf {
                let phase = if frames[res_f].first_tri_taken.is_none() { "clear" } else { "rasterization" };
                self.report(phase, frames[res_f].results.len() as u64, frames[res_f].tris.len() as u64);
            }
            if active {
                last_activity = now;
            }
            if now - last_activity > watchdog {
                let phase = if res_f < nf { format!("frame {}'s rasterization", res_f + 1) } else { format!("frame {}'s scan-out", scan_f + 1) };
                let wave = match &self.vcd_path {
                    Some(p) => format!("the waveform is {}", p.display()),
                    None => "run again with a VCD (render --vcd) to see why".to_string(),
                };
                return Err(format!(
                    "chipset: no progress for {watchdog} cycles in {phase}, at cycle {now}: no command or result taken, no memory access, no pixel; {wave}"
                ));
            }
            if now > limit {
                return Err(format!(
                    "chipset: {nf} frames not done after {} cycles ({res_f} drawn by the RC, {scan_f} scanned out)",
                    now - start
                ));
            }
        }
        self.frame_phases = (0..nf).map(|f| frames[f].phases(if f > 0 { frames[f - 1].scan_taken } else { None })).collect();
        self.phases = self.frame_phases.last().cloned().unwrap_or_default();
        outs.into_iter().map(|o| o.ok_or_else(|| "chipset: a frame without output".to_string())).collect()
    }
}

/// TdbS bank `bank` as the RTL left it, in the golden model's terms (for checks).
pub fn tdbs_entries<T: ChipsetTop>(c: &RtlChipsetOf<T>, bank: usize, indices: &[u32]) -> Vec<TdbsEntry> {
    indices.iter().map(|&i| crate::cs::pack::entry_of(&c.tdbs[(bank << 16) + i as usize])).collect()
}

/// Whether a golden TdbS entry and the RTL's record agree.
pub fn record_matches(e: &TdbsEntry, r: &TdbsRecord) -> bool {
    record_of(e) == *r
}
