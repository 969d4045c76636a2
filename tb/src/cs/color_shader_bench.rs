//! Every-cycle bench of the Color Shader: the RTL (`hdl::cs::color_shader::ColorShader`, RustHDL,
//! direct drive, GUIDE §5) and the cycle model (`golden::cycle::color_shader::ColorShaderModel`) get
//! the same inputs every cycle: frame starts (also while busy, where they must be ignored), random
//! back-pressure on the video stream, and the read data of the I-buffer and TdbS memory models
//! ([`CsMemories`], latency 1), which answer the ports, and the Phong constants (written while idle,
//! before the first frame). Every output port is compared every cycle; the first mismatch stops the
//! run with the cycle, the port, both values and the path of a VCD.

use crate::common::{vcd_path, vcd_wanted, Rng, Trace, Watchdog};
use crate::cs::pack::{record_of, tdata_of, BitVector};
use crate::cs::replay::{port, PortSpec, Recording};
use golden::cycle::color_shader::{ColorShaderModel, CsConfigWrite, CsInputs, CsMemories, CsOutputs, ReadPort, VideoBeat, WritePort};
use hdl::cs::{LightVectors, MaterialWord};
use golden::render::Texturing;
use golden::texbank::Footprint;
use hdl::cs::color_shader::ColorShader;
use hdl::cs::color_shader_tex::ColorShaderTex;
use rust_hdl::prelude::*;
use std::path::PathBuf;

/// One frame to scan.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct FrameSpec {
    pub width: u32,
    pub height: u32,
    pub background: [u8; 3],
    pub clear_behind: bool,
    /// Phong scan-out (the constants are the run's `config`).
    pub phong: bool,
}

/// How the environment behaves.
#[derive(Copy, Clone, Debug)]
pub struct CsDrive {
    /// Percentage of cycles in which the video consumer is not ready.
    pub stall_percent: u64,
    /// Percentage of busy cycles in which `start` is (uselessly) high.
    pub start_while_busy_percent: u64,
    /// Idle cycles between frames, at most.
    pub max_idle: u64,
    pub seed: u64,
}

impl CsDrive {
    /// Consumer always ready, frames back to back.
    pub fn ideal() -> CsDrive {
        CsDrive { stall_percent: 0, start_while_busy_percent: 0, max_idle: 0, seed: 1 }
    }
}

/// What a run produced.
#[derive(Clone, Debug, Default)]
pub struct CsRun {
    /// Per accepted frame: the beats taken, in order.
    pub frames: Vec<Vec<VideoBeat>>,
    /// Starts that were refused (`size_error`).
    pub refused: u64,
    /// Cycles of the run.
    pub cycles: u64,
    /// Per accepted frame: cycles from its first issue to its last beat taken, both included.
    pub frame_cycles: Vec<u64>,
    pub rtl_cycles_per_second: f64,
    pub recording: Option<Recording>,
    /// Words read at the texture port (bank reads), over the run.
    pub tex_words: u64,
}

/// Ports of the `cs` top in the replay's order.
pub fn replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    (
        vec![
            port("start", 1),
            port("width", 11),
            port("height", 11),
            port("background", 24),
            port("clear_behind", 1),
            port("shading_phong", 1),
            port("light_write_enable", 1),
            port("light_write_address", 2),
            port("light_write_data", 96),
            port("material_write_enable", 1),
            port("material_write_address", hdl::cs::CS_MATERIAL_BITS),
            port("material_write_slot", 3),
            port("material_write_data", 96),
            port("ibuf_read_data", 16),
            port("tdbs_read_data", hdl::cs::TDBS_RECORD_BITS),
            port("video_tready", 1),
        ],
        vec![
            port("busy", 1),
            port("size_error", 1),
            port("ibuf_read_enable", 1),
            port("ibuf_read_address", 20),
            port("tdbs_read_enable", 1),
            port("tdbs_read_address", 16),
            port("ibuf_write_enable", 1),
            port("ibuf_write_address", 20),
            port("ibuf_write_data", 16),
            port("zbuf_write_enable", 1),
            port("zbuf_write_address", 20),
            port("zbuf_write_data", 24),
            port("video_tdata", 24),
            port("video_tvalid", 1),
            port("video_tuser", 1),
            port("video_tlast", 1),
        ],
    )
}

/// Ports of the `cs_tex` top in the replay's order: `cs`'s, then the texture's.
pub fn tex_replay_ports() -> (Vec<PortSpec>, Vec<PortSpec>) {
    let (mut i, mut o) = replay_ports();
    i.extend([
        port("tdbt_read_data", hdl::cs::TDBT_RECORD_BITS),
        port("texture_enable", 1),
        port("tex_w0_log2", 4),
        port("tex_h0_log2", 4),
        port("tex_last_level", 4),
        port("tex_filter", 2),
        port("tex_clamp", 1),
        port("tex_base_we", 1),
        port("tex_base_sel", 4),
        port("tex_base_data", 20),
        port("tex_data0", 24),
        port("tex_data1", 24),
        port("tex_data2", 24),
        port("tex_data3", 24),
    ]);
    let names = tex_port_values(&CsOutputs::default());
    o.extend(names.iter().map(|(n, _, w)| port(n, *w)));
    (i, o)
}

fn tex_in_vector(i: &CsInputs, t: &TexInputs) -> BitVector {
    let mut v = in_vector(i);
    v.push_tex_planes(&i.tdbt_read_data);
    v.push(t.enable as u128, 1);
    v.push(t.w0_log2 as u128, 4);
    v.push(t.h0_log2 as u128, 4);
    v.push(t.last_level as u128, 4);
    v.push(t.filter as u128, 2);
    v.push(t.clamp as u128, 1);
    let (sel, base) = t.base.unwrap_or((0, 0));
    v.push(t.base.is_some() as u128, 1);
    v.push(sel as u128, 4);
    v.push(base as u128, 20);
    for d in t.data {
        v.push(d as u128, 24);
    }
    v
}

fn tex_out_vector(o: &CsOutputs) -> BitVector {
    let mut v = out_vector(o);
    for (_, val, w) in tex_port_values(o) {
        v.push(val as u128, w);
    }
    v
}

/// Six 16-bit fields packed as a `LogicStruct` (field 0 in the least significant bits).
fn pack6(f: [u64; 6]) -> u128 {
    f.iter().enumerate().fold(0u128, |acc, (k, &x)| acc | (((x & 0xffff) as u128) << (16 * k)))
}

/// The config write of a cycle as the ports carry it: (light enable, address, data), (material
/// enable, address, slot, data); the data are the six 16-bit fields packed as the `LogicStruct`.
pub fn config_ports(c: Option<CsConfigWrite>) -> ((bool, u64, u128), (bool, u64, u64, u128)) {
    let q = |v: i64| v as u16 as u64;
    match c {
        Some(CsConfigWrite::Light { address, l, h }) => {
            ((true, address as u64 & 3, pack6([q(l[0]), q(l[1]), q(l[2]), q(h[0]), q(h[1]), q(h[2])])), (false, 0, 0, 0))
        }
        Some(CsConfigWrite::Material { address, slot, words }) => {
            let mask = (1u64 << hdl::cs::CS_MATERIAL_BITS) - 1;
            ((false, 0, 0), (true, address as u64 & mask, slot as u64 & 7, pack6(words.map(|w| w as u64))))
        }
        None => ((false, 0, 0), (false, 0, 0, 0)),
    }
}

/// The CS's Phong-constant write ports of a block (the `cs` and `chipset` tops name them alike).
pub struct ConfigPortRefs<'a> {
    pub light_enable: &'a mut Signal<In, Bit>,
    pub light_address: &'a mut Signal<In, Bits<2>>,
    pub light_data: &'a mut Signal<In, LightVectors>,
    pub material_enable: &'a mut Signal<In, Bit>,
    pub material_address: &'a mut Signal<In, Bits<{ hdl::cs::CS_MATERIAL_BITS }>>,
    pub material_slot: &'a mut Signal<In, Bits<3>>,
    pub material_data: &'a mut Signal<In, MaterialWord>,
}

/// A block with the CS's Phong-constant write ports.
pub trait ConfigPorts {
    fn config_ports(&mut self) -> ConfigPortRefs<'_>;
}

macro_rules! config_ports_of {
    ($t:ty) => {
        impl ConfigPorts for $t {
            fn config_ports(&mut self) -> ConfigPortRefs<'_> {
                ConfigPortRefs {
                    light_enable: &mut self.light_write_enable,
                    light_address: &mut self.light_write_address,
                    light_data: &mut self.light_write_data,
                    material_enable: &mut self.material_write_enable,
                    material_address: &mut self.material_write_address,
                    material_slot: &mut self.material_write_slot,
                    material_data: &mut self.material_write_data,
                }
            }
        }
    };
}
config_ports_of!(ColorShader);
config_ports_of!(ColorShaderTex);
config_ports_of!(hdl::chipset::Chipset);
config_ports_of!(hdl::chipset::chipset3::Chipset3);
config_ports_of!(hdl::chipset::chipset_tex::ChipsetTex);

/// Drive one cycle's Phong-constant write (or none) onto a block's write ports.
pub fn drive_config(u: &mut impl ConfigPorts, c: Option<CsConfigWrite>) {
    let ((le, la, ld), (me, ma, ms, md)) = config_ports(c);
    let f = |d: u128, k: usize| -> Bits<16> { (((d >> (16 * k)) & 0xffff) as u64).into() };
    let p = u.config_ports();
    p.light_enable.next = le;
    p.light_address.next = la.into();
    p.light_data.next = LightVectors { l_x: f(ld, 0), l_y: f(ld, 1), l_z: f(ld, 2), h_x: f(ld, 3), h_y: f(ld, 4), h_z: f(ld, 5) };
    p.material_enable.next = me;
    p.material_address.next = ma.into();
    p.material_slot.next = ms.into();
    p.material_data.next = MaterialWord { w0: f(md, 0), w1: f(md, 1), w2: f(md, 2), w3: f(md, 3), w4: f(md, 4), w5: f(md, 5) };
}

fn in_vector(i: &CsInputs) -> BitVector {
    let mut v = BitVector::default();
    v.push(i.start as u128, 1);
    v.push(i.width as u128, 11);
    v.push(i.height as u128, 11);
    v.push(tdata_of(i.background) as u128, 24);
    v.push(i.clear_behind as u128, 1);
    v.push(i.shading_phong as u128, 1);
    let ((le, la, ld), (me, ma, ms, md)) = config_ports(i.config);
    v.push(le as u128, 1);
    v.push(la as u128, 2);
    v.push(ld, 96);
    v.push(me as u128, 1);
    v.push(ma as u128, hdl::cs::CS_MATERIAL_BITS);
    v.push(ms as u128, 3);
    v.push(md, 96);
    v.push(i.ibuf_read_data as u128, 16);
    v.push_record(&i.tdbs_read_data);
    v.push(i.video_tready as u128, 1);
    v
}

/// Every output port of a cycle as (name, value), in the replay's order.
fn port_values(o: &CsOutputs) -> [(&'static str, u64, usize); 16] {
    [
        ("busy", o.busy as u64, 1),
        ("size_error", o.size_error as u64, 1),
        ("ibuf_read_enable", o.ibuf_read.enable as u64, 1),
        ("ibuf_read_address", o.ibuf_read.address as u64, 20),
        ("tdbs_read_enable", o.tdbs_read.enable as u64, 1),
        ("tdbs_read_address", o.tdbs_read.address as u64, 16),
        ("ibuf_write_enable", o.ibuf_write.enable as u64, 1),
        ("ibuf_write_address", o.ibuf_write.address as u64, 20),
        ("ibuf_write_data", o.ibuf_write.data as u64, 16),
        ("zbuf_write_enable", o.zbuf_write.enable as u64, 1),
        ("zbuf_write_address", o.zbuf_write.address as u64, 20),
        ("zbuf_write_data", o.zbuf_write.data as u64, 24),
        ("video_tdata", tdata_of(o.video.rgb) as u64, 24),
        ("video_tvalid", o.video_tvalid as u64, 1),
        ("video_tuser", o.video.sof as u64, 1),
        ("video_tlast", o.video.eol as u64, 1),
    ]
}

fn out_vector(o: &CsOutputs) -> BitVector {
    let mut v = BitVector::default();
    for (_, val, w) in port_values(o) {
        v.push(val as u128, w);
    }
    v
}

/// The output ports both CS tops share.
macro_rules! cs_outputs {
    ($u:expr) => {{
        let u = $u;
        let t = u.video_tdata.val().to_u64() as u32;
        CsOutputs {
            busy: u.busy.val(),
            size_error: u.size_error.val(),
            ibuf_read: ReadPort { enable: u.ibuf_read_enable.val(), address: u.ibuf_read_address.val().to_u64() as u32 },
            tdbs_read: ReadPort { enable: u.tdbs_read_enable.val(), address: u.tdbs_read_address.val().to_u64() as u32 },
            ibuf_write: WritePort {
                enable: u.ibuf_write_enable.val(),
                address: u.ibuf_write_address.val().to_u64() as u32,
                data: u.ibuf_write_data.val().to_u64() as u32,
            },
            zbuf_write: WritePort {
                enable: u.zbuf_write_enable.val(),
                address: u.zbuf_write_address.val().to_u64() as u32,
                data: u.zbuf_write_data.val().to_u64() as u32,
            },
            video_tvalid: u.video_tvalid.val(),
            video: VideoBeat { rgb: crate::cs::pack::rgb_of(t), sof: u.video_tuser.val(), eol: u.video_tlast.val() },
            tdbt_read: Default::default(),
            tex_banks: Default::default(),
        }
    }};
}

/// The input ports both CS tops share.
macro_rules! drive_cs_inputs {
    ($u:expr, $i:expr) => {{
        let (u, i) = ($u, $i);
        u.start.next = i.start;
        u.width.next = (i.width as u64 & 0x7ff).into();
        u.height.next = (i.height as u64 & 0x7ff).into();
        u.background.next = (tdata_of(i.background) as u64).into();
        u.clear_behind.next = i.clear_behind;
        u.shading_phong.next = i.shading_phong;
        drive_config(u, i.config);
        u.ibuf_read_data.next = (i.ibuf_read_data as u64).into();
        u.tdbs_read_data.next = record_of(&i.tdbs_read_data);
        u.video_tready.next = i.video_tready;
    }};
}

/// What a textured CS's texture ports get in a cycle (besides [`CsInputs`]).
#[derive(Clone, Debug, Default)]
pub struct TexInputs {
    pub enable: bool,
    pub w0_log2: u32,
    pub h0_log2: u32,
    pub last_level: u32,
    /// 0 nearest, 1 bilinear, 2 trilinear.
    pub filter: u64,
    pub clamp: bool,
    /// A level-table write: (level, its first word).
    pub base: Option<(u32, u32)>,
    /// The four banks' read data (latency 1).
    pub data: [u64; 4],
}

/// A frame's texture as a host loads it into a textured CS (this bench, and the chipset's host loop in
/// `crate::chipset`): the CS's settings, its level table and the four banks' contents (`golden::texbank`).
pub struct FrameTexture {
    pub w0_log2: u32,
    pub h0_log2: u32,
    pub last_level: u32,
    /// 0 nearest, 1 bilinear, 2 trilinear.
    pub filter: u64,
    pub clamp: bool,
    /// Each level's first word in the banks.
    pub bases: Vec<u32>,
    pub banks: std::sync::Arc<[Vec<[u8; 3]>; 4]>,
    /// Texels per footprint: 1 nearest, 4 bilinear and trilinear.
    pub texels_per_footprint: u64,
}

impl FrameTexture {
    pub fn of(t: &golden::render::Texturing) -> FrameTexture {
        let geoms = golden::texbank::layout(&t.texture);
        FrameTexture {
            w0_log2: geoms[0].w_log2,
            h0_log2: geoms[0].h_log2,
            last_level: geoms.len() as u32 - 1,
            filter: crate::cs::texture_sampler_bench::filter_code(t.filter),
            clamp: t.wrap == golden::texture::Wrap::ClampToEdge,
            bases: geoms.iter().map(|g| g.base).collect(),
            banks: std::sync::Arc::new(golden::texbank::banks(&t.texture)),
            texels_per_footprint: if t.filter == golden::texture::Filter::Nearest { 1 } else { 4 },
        }
    }
}

/// A CS top the bench can drive: `cs` or `cs_tex`.
pub trait CsUut: Block + Default {
    /// The top's name (the VCD directory, messages).
    const NAME: &'static str;
    fn drive(&mut self, i: &CsInputs, tex: &TexInputs);
    fn outputs(&self) -> CsOutputs;
    fn set_clock(&mut self, c: bool);
}

impl CsUut for ColorShader {
    const NAME: &'static str = "cs";
    fn drive(&mut self, i: &CsInputs, _tex: &TexInputs) {
        drive_cs_inputs!(self, i);
    }
    fn outputs(&self) -> CsOutputs {
        // No TdbT or texture port: the model leaves them idle in untextured frames, the only ones a
        // `cs` run has.
        cs_outputs!(self)
    }
    fn set_clock(&mut self, c: bool) {
        self.clock.next = c.into();
    }
}

impl CsUut for ColorShaderTex {
    const NAME: &'static str = "cs_tex";
    fn drive(&mut self, i: &CsInputs, tex: &TexInputs) {
        drive_cs_inputs!(&mut *self, i);
        self.tdbt_read_data.next = crate::cs::pack::tdbt_record_of(&i.tdbt_read_data);
        self.texture_enable.next = tex.enable;
        self.tex_w0_log2.next = (tex.w0_log2 as u64).into();
        self.tex_h0_log2.next = (tex.h0_log2 as u64).into();
        self.tex_last_level.next = (tex.last_level as u64).into();
        self.tex_filter.next = tex.filter.into();
        self.tex_clamp.next = tex.clamp;
        let (sel, base) = tex.base.unwrap_or((0, 0));
        self.tex_base_we.next = tex.base.is_some();
        self.tex_base_sel.next = (sel as u64).into();
        self.tex_base_data.next = (base as u64).into();
        self.tex_data0.next = tex.data[0].into();
        self.tex_data1.next = tex.data[1].into();
        self.tex_data2.next = tex.data[2].into();
        self.tex_data3.next = tex.data[3].into();
    }
    fn outputs(&self) -> CsOutputs {
        let mut o = cs_outputs!(self);
        o.tdbt_read = ReadPort { enable: self.tdbt_read_enable.val(), address: self.tdbt_read_address.val().to_u64() as u32 };
        let rd = self.tex_rd.val().to_u64();
        o.tex_banks.read = [0, 1, 2, 3].map(|k| rd >> k & 1 == 1);
        o.tex_banks.addr = [&self.tex_addr0, &self.tex_addr1, &self.tex_addr2, &self.tex_addr3].map(|a| a.val().to_u64() as u32);
        o
    }
    fn set_clock(&mut self, c: bool) {
        self.clock.next = c.into();
    }
}

/// Cycles in which the CS may do nothing at its ports (no memory access, no beat) before the bench
/// stops it: its pipeline is a few stages deep, and a 95 % stalled video port still takes a beat
/// within 1024 cycles with probability 1 - 1e-22.
const PROGRESS_LIMIT: u64 = 1024;

struct Rtl<U: CsUut> {
    uut: U,
    trace: Trace,
}

impl<U: CsUut> Rtl<U> {
    fn new(vcd: Option<&PathBuf>) -> Result<Rtl<U>, String> {
        let mut uut = U::default();
        uut.connect_all();
        check_all(&uut).map_err(|e| format!("{} design check: {e:?}", U::NAME))?;
        let trace = Trace::new(&uut, vcd.map(PathBuf::as_path))?;
        Ok(Rtl { uut, trace })
    }
    fn settle(&mut self, t: u64) -> Result<(), String> {
        if !simulate(&mut self.uut, 200) {
            return Err(format!("{} did not settle at time {t}", U::NAME));
        }
        self.trace.dump(&self.uut, t)
    }
    fn cycle(&mut self, cycle: u64, i: &CsInputs, tex: &TexInputs) -> Result<CsOutputs, String> {
        self.uut.drive(i, tex);
        self.uut.set_clock(false);
        self.settle(cycle * 10)?;
        Ok(self.uut.outputs())
    }
    fn rising_edge(&mut self, cycle: u64) -> Result<(), String> {
        self.uut.set_clock(true);
        self.settle(cycle * 10 + 5)
    }
}

/// A textured run: the texture, and per frame whether it is textured.
#[derive(Clone, Debug)]
pub struct TexRun {
    pub texturing: Texturing,
    pub textured: Vec<bool>,
}

/// The texture ports that are not in [`port_values`]: (name, value, width).
fn tex_port_values(o: &CsOutputs) -> [(&'static str, u64, usize); 7] {
    let rd = (0..4).map(|k| (o.tex_banks.read[k] as u64) << k).sum::<u64>();
    let a = |k: usize| o.tex_banks.addr[k] as u64;
    [
        ("tdbt_read_enable", o.tdbt_read.enable as u64, 1),
        ("tdbt_read_address", o.tdbt_read.address as u64, 16),
        ("tex_rd", rd, 4),
        ("tex_addr0", a(0), 20),
        ("tex_addr1", a(1), 20),
        ("tex_addr2", a(2), 20),
        ("tex_addr3", a(3), 20),
    ]
}

enum Stop {
    Mismatch(u64, &'static str, u64, u64),
    Error(String),
}

#[allow(clippy::too_many_arguments)]
fn run_inner<U: CsUut>(
    mem: &mut CsMemories,
    frames: &[FrameSpec],
    config: &[CsConfigWrite],
    tex: Option<&TexRun>,
    drive: CsDrive,
    with_rtl: bool,
    vcd: Option<&PathBuf>,
    record: bool,
) -> Result<CsRun, Stop> {
    let mut rng = Rng::new(drive.seed);
    let mut noise = Rng::new(drive.seed ^ 0x7E47);
    let mut model = ColorShaderModel::new();
    let mut rtl = if with_rtl { Some(Rtl::<U>::new(vcd).map_err(Stop::Error)?) } else { None };
    // The texture: its level table (written in the first cycles, beside the constants), its banks
    // and settings; the banks answer the last cycle's footprint.
    let loaded = tex.map(|t| FrameTexture::of(&t.texturing));
    let mut footprint = Footprint::default();
    let settings = |on: bool| -> TexInputs {
        match &loaded {
            Some(t) => TexInputs { enable: on, w0_log2: t.w0_log2, h0_log2: t.h0_log2, last_level: t.last_level, filter: t.filter, clamp: t.clamp, ..Default::default() },
            None => TexInputs::default(),
        }
    };
    let mut rec = if record {
        let (i, o) = if tex.is_some() { tex_replay_ports() } else { replay_ports() };
        Some(Recording::new(i, o))
    } else {
        None
    };
    let mut run = CsRun::default();
    let total_px: u64 = frames.iter().map(|f| f.width as u64 * f.height as u64).sum();
    let limit = 1000 + (total_px + 100 * frames.len() as u64) * (2 + 100 / (100 - drive.stall_percent.min(95)));
    let (mut next, mut idle) = (0usize, 0u64);
    let (mut first_issue, mut last_beat) = (None::<u64>, 0u64);
    let mut was_busy = false;
    let t0 = std::time::Instant::now();
    let mut cycle = 0u64;
    let mut watchdog = Watchdog::new(PROGRESS_LIMIT);
    loop {
        let busy = model.outputs().busy;
        if was_busy && !busy {
            // The frame in flight has finished.
            run.frame_cycles.push(last_beat + 1 - first_issue.unwrap_or(last_beat + 1));
            first_issue = None;
            idle = if drive.max_idle > 0 { rng.below(drive.max_idle + 1) } else { 0 };
        }
        was_busy = busy;
        let spec = frames.get(next).copied();
        // The Phong constants go in first, one write per cycle, while the CS is idle.
        let cfg = config.get(cycle as usize).copied();
        let base = loaded.as_ref().and_then(|t| t.bases.get(cycle as usize)).map(|&base| (cycle as u32, base));
        let textured = tex.is_some_and(|t| t.textured.get(next).copied().unwrap_or(false));
        let start = match spec {
            _ if cfg.is_some() || base.is_some() => false,
            Some(_) if !busy => idle == 0,
            _ => busy && drive.start_while_busy_percent > 0 && rng.chance(drive.start_while_busy_percent),
        };
        let s = spec.or(frames.last().copied()).unwrap_or(FrameSpec { width: 1, height: 1, background: [0; 3], clear_behind: false, phong: false });
        let (ibuf_read_data, tdbs_read_data) = mem.read_data();
        let inp = CsInputs {
            start,
            width: if busy { rng.below(2048) as u32 } else { s.width },
            height: if busy { rng.below(2048) as u32 } else { s.height },
            background: if busy { [rng.below(256) as u8, 0, 7] } else { s.background },
            clear_behind: if busy { rng.chance(50) } else { s.clear_behind },
            ibuf_read_data,
            tdbs_read_data,
            tdbt_read_data: mem.tdbt_data(),
            video_tready: !rng.chance(drive.stall_percent),
            shading_phong: if busy { rng.chance(50) } else { s.phong },
            config: cfg,
        };
        // The model takes the texture with the start of a textured frame; the RTL its settings, held
        // (random while busy: they are latched at start).
        if !busy {
            model.set_texturing(tex.filter(|_| textured).map(|t| t.texturing.clone()));
        }
        // (The random draws only in a textured run: a `cs` run's stimulus is what it was before `cs_tex`.)
        let mut tin = settings(if busy { tex.is_some() && rng.chance(50) } else { textured });
        tin.base = base;
        if let Some(b) = loaded.as_ref().map(|t| &t.banks) {
            for (k, d) in tin.data.iter_mut().enumerate() {
                *d = if footprint.read[k] { tdata_of(b[k][footprint.addr[k] as usize]) as u64 } else { noise.next_u64() & 0xff_ffff };
            }
        }
        let expected = model.step(&inp);
        footprint = expected.tex_banks;
        run.tex_words += expected.tex_banks.reads() as u64;
        if let Some(r) = rtl.as_mut() {
            let actual = r.cycle(cycle, &inp, &tin).map_err(Stop::Error)?;
            let (e_all, a_all) = (port_values(&expected).into_iter().chain(tex_port_values(&expected)), port_values(&actual).into_iter().chain(tex_port_values(&actual)));
            for ((p, e, _), (_, a, _)) in e_all.zip(a_all) {
                if e != a {
                    return Err(Stop::Mismatch(cycle, p, e, a));
                }
            }
            r.rising_edge(cycle).map_err(Stop::Error)?;
        }
        if let Some(rc) = rec.as_mut() {
            if tex.is_some() {
                rc.push(tex_in_vector(&inp, &tin), tex_out_vector(&expected));
            } else {
                rc.push(in_vector(&inp), out_vector(&expected));
            }
        }
        if start && !busy {
            next += 1;
            if model.outputs().size_error {
                run.refused += 1;
            } else {
                run.frames.push(Vec::new());
            }
        }
        if !busy && idle > 0 && cfg.is_none() {
            idle -= 1;
        }
        if expected.ibuf_read.enable && first_issue.is_none() {
            first_issue = Some(cycle);
        }
        if expected.video_tvalid && inp.video_tready {
            match run.frames.last_mut() {
                Some(f) => f.push(expected.video),
                None => return Err(Stop::Error(format!("cycle {cycle}: a video beat before any frame was started"))),
            }
            last_beat = cycle;
        }
        // Progress: a frame started, a constant written, a memory access or a video beat taken, or
        // the driver itself waiting between frames.
        let progress = (start && !busy)
            || cfg.is_some()
            || base.is_some()
            || expected.ibuf_read.enable
            || expected.tdbs_read.enable
            || expected.ibuf_write.enable
            || expected.zbuf_write.enable
            || (expected.video_tvalid && inp.video_tready)
            || (!busy && idle > 0);
        let phase = || format!("the CS (frame {} of {}, {} beats out)", run.frames.len(), frames.len(), run.frames.last().map_or(0, Vec::len));
        watchdog.check(cycle, progress, phase, rtl.as_ref().map(|r| &r.trace)).map_err(Stop::Error)?;
        mem.edge(&expected);
        cycle += 1;
        if next == frames.len() && !model.outputs().busy {
            if was_busy {
                run.frame_cycles.push(last_beat + 1 - first_issue.unwrap_or(last_beat + 1));
            }
            break;
        }
        if cycle > limit {
            return Err(Stop::Error(format!("the CS did not finish {} frame(s) in {limit} cycles", frames.len())));
        }
    }
    let dt = t0.elapsed().as_secs_f64();
    run.cycles = cycle;
    run.rtl_cycles_per_second = if with_rtl && dt > 0.0 { cycle as f64 / dt } else { 0.0 };
    run.recording = rec;
    Ok(run)
}

/// The cycle model alone (no RTL, so no mismatch can stop it).
fn model_only(r: Result<CsRun, Stop>) -> Result<CsRun, String> {
    r.map_err(|s| match s {
        Stop::Error(e) => e,
        Stop::Mismatch(..) => unreachable!(),
    })
}

/// The cycle model alone.
pub fn run_model(mem: &mut CsMemories, frames: &[FrameSpec], config: &[CsConfigWrite], drive: CsDrive) -> Result<CsRun, String> {
    model_only(run_inner::<ColorShader>(mem, frames, config, None, drive, false, None, false))
}

/// The cycle model alone, recording every port of every cycle for a replay of the `cs` Verilog (the
/// memories answer the model's reads, as they would the RTL's if it is equal): for frames too large
/// for the RustHDL simulation to record in reasonable time.
pub fn record_model(mem: &mut CsMemories, frames: &[FrameSpec], config: &[CsConfigWrite], drive: CsDrive) -> Result<CsRun, String> {
    model_only(run_inner::<ColorShader>(mem, frames, config, None, drive, false, None, true))
}

/// The cycle model alone on a textured run, recording every port of every cycle for a replay of the
/// `cs_tex` Verilog (the memories answer the model's reads, as they would the RTL's if it is equal).
pub fn record_tex_model(mem: &mut CsMemories, frames: &[FrameSpec], config: &[CsConfigWrite], tex: &TexRun, drive: CsDrive) -> Result<CsRun, String> {
    model_only(run_inner::<ColorShaderTex>(mem, frames, config, Some(tex), drive, false, None, true))
}

/// The RTL against the model, every port every cycle; `mem` is updated by the run's writes; `config`
/// is written before the first frame. `test` names the VCD (`target/vcd/cs/<test>.vcd`): written
/// with `VCD=1`, and always for a failing run.
pub fn run_rtl_vs_model(
    test: &str,
    mem: &mut CsMemories,
    frames: &[FrameSpec],
    config: &[CsConfigWrite],
    drive: CsDrive,
    record: bool,
) -> Result<CsRun, String> {
    run_top::<ColorShader>(test, mem, frames, config, None, drive, record)
}

/// [`run_rtl_vs_model`] for the textured CS (`cs_tex`): `tex` gives the texture and which frames use
/// it (`mem` holds their TdbT); its level table is written before the first frame.
pub fn run_tex_rtl_vs_model(
    test: &str,
    mem: &mut CsMemories,
    frames: &[FrameSpec],
    config: &[CsConfigWrite],
    tex: &TexRun,
    drive: CsDrive,
    record: bool,
) -> Result<CsRun, String> {
    run_top::<ColorShaderTex>(test, mem, frames, config, Some(tex), drive, record)
}

fn run_top<U: CsUut>(
    test: &str,
    mem: &mut CsMemories,
    frames: &[FrameSpec],
    config: &[CsConfigWrite],
    tex: Option<&TexRun>,
    drive: CsDrive,
    record: bool,
) -> Result<CsRun, String> {
    let path = vcd_path(U::NAME, test);
    let vcd = if vcd_wanted() { Some(&path) } else { None };
    let start_mem = mem.clone();
    match run_inner::<U>(mem, frames, config, tex, drive, true, vcd, record) {
        Ok(r) => Ok(r),
        Err(Stop::Error(e)) => Err(e),
        Err(Stop::Mismatch(cycle, port, e, a)) => {
            let mut again = start_mem;
            let _ = run_inner::<U>(&mut again, frames, config, tex, drive, true, Some(&path), false);
            Err(format!(
                "{} differs from its cycle model in cycle {cycle} (seed {}), port {port}: expected {e:#x}, actual {a:#x}\n  VCD: {}",
                U::NAME,
                drive.seed,
                path.display()
            ))
        }
    }
}

/// Check a frame's beats: W*H beats, `tuser` on the first only, `tlast` exactly at line ends; returns
/// the RGB888 image.
pub fn frame_image(beats: &[VideoBeat], width: u32, height: u32) -> Result<Vec<u8>, String> {
    if beats.len() != (width * height) as usize {
        return Err(format!("{} beats for a {width}x{height} frame", beats.len()));
    }
    let mut rgb = Vec::with_capacity(beats.len() * 3);
    for (i, b) in beats.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        if b.sof != (i == 0) {
            return Err(format!("tuser is {} at pixel ({x}, {y})", b.sof));
        }
        if b.eol != (x == width - 1) {
            return Err(format!("tlast is {} at pixel ({x}, {y})", b.eol));
        }
        rgb.extend_from_slice(&b.rgb);
    }
    Ok(rgb)
}
