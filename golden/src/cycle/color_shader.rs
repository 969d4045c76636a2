//! Cycle-accurate model of the Color Shader (`hdl/src/cs/color_shader.rs`), seed 001 §3.1: the
//! scan-out engine that reads the I-buffer in raster order, fetches TdbS by index and evaluates the
//! colour planes (flat, Gouraud) or lights the interpolated normal (Phong), one pixel per clock, onto
//! an AXI4-Stream video output.
//!
//! Written from the timing specification below and the algorithmic model ([`Plane::eval_clamped`],
//! [`PhongLights::shade`], `GoldenChipset::scanout`); it looks only at the block's ports.
//!
//! ## Ports (one clock; every output is a function of registers only)
//! * control in: `start` (pulse), `width`, `height` (11 bits each, 1..=1024), `background` (RGB888),
//!   `clear_behind`; out: `busy`, `size_error`;
//! * I-buffer read port: `ibuf_read_enable`, `ibuf_read_address` (20 bits, `y*width + x`) out,
//!   `ibuf_read_data` (16-bit index) in, valid in the cycle after the address (latency 1);
//! * TdbS read port: `tdbs_read_enable`, `tdbs_read_address` (16 bits) out, `tdbs_read_data` (the
//!   record) in, latency 1;
//! * clear-behind write ports: I-buffer (`address`, data 0) and Z-buffer (`address`, data
//!   `DEPTH_MAX`), enabled when the frame was started with `clear_behind`;
//! * video out: `tdata` (RGB888), `tvalid`, `tuser` (first pixel of the frame), `tlast` (last pixel
//!   of a line); `tready` in. A beat moves at a rising edge with `tvalid && tready`.
//! * Phong constants in: `shading_phong` (latched at start); a light write (`address` 0..=3, L and H
//!   in Q1.14; addresses from [`CS_LIGHTS`] up are ignored) and a material write (`address` =
//!   material 0..[`CS_MATERIALS`], `slot` 0 = ambient R, G, B and log2 gloss, slot 1 + l = light l's
//!   diffuse R, G, B and specular R, G, B, 16 bits each; slots past the last light are ignored), both
//!   taking effect at the edge. They are meant for an idle CS: the model lights a pixel with the
//!   constants of the cycle its record arrives, the RTL reads them up to 22 cycles later.
//!
//! ## Timing
//! * `start` is taken in a cycle where `busy` is low. It latches `width`, `height`, `background` and
//!   `clear_behind`. A size outside 1..=1024 sets `size_error` and starts nothing; a good start clears
//!   it. `start` while busy is ignored.
//! * A pixel is *issued* in a cycle t where the frame is running and fewer than [`CS_FIFO_DEPTH`]
//!   pixels are pending (issued, not yet taken by the video consumer): `ibuf_read_enable` is high and
//!   `ibuf_read_address` is the pixel's address. Pixels are issued in raster order.
//! * t+1: the index arrives on `ibuf_read_data`; the clear-behind writes of that pixel's address
//!   happen in this cycle (the read has already happened at t's edge).
//! * t+2: `tdbs_read_enable`, `tdbs_read_address` = the index.
//! * t+3: the record arrives on `tdbs_read_data`; the planes are evaluated (t+3, t+4, t+5: products,
//!   sum, round; clamped to 0..255 for flat and Gouraud, saturated to 16 bits as the normal for
//!   Phong), the Phong path normalises (t+5..t+16) and lights (t+17..t+25) it, and at t+26 the beat
//!   (background where the index is 0) enters the output FIFO, in every shading mode.
//! * t+27 at the earliest: the beat is offered on the video port, in order, until taken.
//! * With `tready` always high a pixel is issued every cycle (27 pending < 32): a W x H frame takes
//!   W*H + 27 cycles from the first issue to the last beat taken. `busy` is high from the cycle after
//!   the start until the last beat is taken.
//!
//! ## Texture (issue 17; the RTL does not have it yet: this is its specification)
//! A frame started while the model holds a texture ([`ColorShaderModel::set_texturing`], the host's
//! texture settings and level table, loaded while the CS is idle) is textured:
//! * t+2: the TdbT read port (`tdbt_read_enable`, `tdbt_read_address` = the index) beside TdbS;
//!   t+3: the record ([`TexPlanes`]) arrives with the TdbS record.
//! * t+3 .. t+28: the per-pixel coordinate unit (`tex_coord`, 14 cycles; `tex_lod`, 12) beside the
//!   colour (flat, Gouraud or Phong, as untextured, then delayed to match).
//! * t+29: the pixel is offered to the texture unit ([`TextureSamplerModel`]: its bank ports are the
//!   CS's texture port, `tex_banks`); a background pixel (index 0) passes through it untextured. A
//!   trilinear pixel between two levels is taken in t+30 (the unit's `ready` is low for one cycle).
//! * The unit's colour (MODULATE of texel and colour) 8 cycles after it took the pixel enters the
//!   output FIFO: with `tready` high the beat is on the video port in t+38 ([`CS_PIPELINE_CYCLES_TEX`]),
//!   or t+39 for a pixel between two levels.
//! * The credit is [`CS_FIFO_DEPTH_TEX`] = 64 pending pixels (the output FIFO is 64 deep), so that
//!   nearest and bilinear keep one pixel per clock; a trilinear frame issues a pixel every other
//!   cycle at most (one every two clocks, the issue's floor), which leaves the unit's second cycle
//!   free without stalling the fixed pipeline in front of it.

use crate::cycle::texture_sampler::{SamplerPixel, TextureSamplerModel};
use crate::format::{Plane, CS_GLOSS_LOG2_MAX, CS_LIGHTS, CS_MATERIALS, DEPTH_MAX, MAX_SCREEN};
use crate::render::Texturing;
use crate::shade::{PhongLights, PhongMaterial, TdbsEntry};
use crate::texbank::Footprint;
use crate::texcoord::TexPlanes;
use crate::texture::Filter;
use std::collections::VecDeque;

/// Depth of the output FIFO, and the limit of pending pixels (the credit that makes back-pressure
/// lossless against the memory latency).
pub const CS_FIFO_DEPTH: usize = 32;
/// Cycles from a pixel's issue to the first cycle its beat can be on the video port.
pub const CS_PIPELINE_CYCLES: u64 = 27;
/// The output FIFO's depth and the credit of a textured frame.
pub const CS_FIFO_DEPTH_TEX: usize = 64;
/// Cycles of the per-pixel coordinate unit, from the TdbT record (t+3) to the texture unit (t+29).
pub const CS_TEX_COORD_CYCLES: u64 = 26;
/// Textured: cycles from a pixel's issue to the first cycle its beat can be on the video port
/// (t+3, the coordinate unit, the texture unit's 8, the FIFO's 1).
pub const CS_PIPELINE_CYCLES_TEX: u64 = 3 + CS_TEX_COORD_CYCLES + 8 + 1;

/// One write to the CS's Phong constants (one cycle of `light_write_*` or `material_write_*`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum CsConfigWrite {
    Light { address: u32, l: [i64; 3], h: [i64; 3] },
    Material { address: u32, slot: u32, words: [u16; 6] },
}

/// The writes that load `lights` into the CS (host side, once per frame before the scan-out): per
/// light unit its L and H, per material its ambient and gloss word and one coefficient word per light
/// unit. A light unit the scene does not use gets zero vectors and zero coefficients, so it adds
/// nothing. Errors name the limit a scene exceeds.
pub fn phong_config(lights: &PhongLights) -> Result<Vec<CsConfigWrite>, String> {
    lights.check_rtl_limits()?;
    let q = |v: i64| v.clamp(0, u16::MAX as i64) as u16;
    let mut w = Vec::new();
    for li in 0..CS_LIGHTS {
        let (l, h) = if li < lights.l.len() { (lights.l[li], lights.h[li]) } else { ([0; 3], [0; 3]) };
        w.push(CsConfigWrite::Light { address: li as u32, l, h });
    }
    for (mi, m) in lights.materials.iter().enumerate() {
        let a = m.ambient;
        w.push(CsConfigWrite::Material { address: mi as u32, slot: 0, words: [q(a[0]), q(a[1]), q(a[2]), m.gloss_log2 as u16, 0, 0] });
        for li in 0..CS_LIGHTS {
            let words = if li < lights.l.len() {
                let (d, s) = (m.diffuse[li], m.specular[li]);
                [q(d[0]), q(d[1]), q(d[2]), q(s[0]), q(s[1]), q(s[2])]
            } else {
                [0; 6]
            };
            w.push(CsConfigWrite::Material { address: mi as u32, slot: 1 + li as u32, words });
        }
    }
    Ok(w)
}
/// Width of the I-buffer address (pixels up to 1024 x 1024).
pub const CS_ADDRESS_BITS: u32 = 20;
/// Width of the size inputs.
pub const CS_SIZE_BITS: u32 = 11;

/// A video beat.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct VideoBeat {
    pub rgb: [u8; 3],
    /// Start of frame (AXI4-Stream video `tuser`).
    pub sof: bool,
    /// End of line (`tlast`).
    pub eol: bool,
}

/// The block's inputs in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct CsInputs {
    pub start: bool,
    pub width: u32,
    pub height: u32,
    pub background: [u8; 3],
    pub clear_behind: bool,
    pub ibuf_read_data: u16,
    pub tdbs_read_data: TdbsEntry,
    /// The TdbT record (textured frames).
    pub tdbt_read_data: TexPlanes,
    pub video_tready: bool,
    pub shading_phong: bool,
    pub config: Option<CsConfigWrite>,
}

/// A memory read port in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct ReadPort {
    pub enable: bool,
    pub address: u32,
}

/// A memory write port in one cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct WritePort {
    pub enable: bool,
    pub address: u32,
    pub data: u32,
}

/// The block's outputs in one cycle (before its rising edge). Payloads are meaningful only when
/// their enable / valid is high; the model sets them to 0 otherwise and a bench compares them only then.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct CsOutputs {
    pub busy: bool,
    pub size_error: bool,
    pub ibuf_read: ReadPort,
    pub tdbs_read: ReadPort,
    /// Textured frames: the TdbT read, in the cycle of the TdbS read.
    pub tdbt_read: ReadPort,
    /// Textured frames: the texture banks' read port (the texture unit's).
    pub tex_banks: Footprint,
    pub ibuf_write: WritePort,
    pub zbuf_write: WritePort,
    pub video_tvalid: bool,
    pub video: VideoBeat,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
struct Pixel {
    x: u32,
    y: u32,
    address: u32,
    sof: bool,
    eol: bool,
}

/// The cycle-accurate model.
#[derive(Clone, Debug, Default)]
pub struct ColorShaderModel {
    running: bool,
    size_error: bool,
    width: u32,
    height: u32,
    background: [u8; 3],
    clear: bool,
    x: u32,
    y: u32,
    address: u32,
    pending: usize,
    /// Issued last cycle: waiting for the I-buffer data.
    s1: Option<Pixel>,
    /// Index known: TdbS read this cycle.
    s2: Option<(Pixel, u16)>,
    /// Waiting for the TdbS data.
    s3: Option<(Pixel, u16)>,
    /// Evaluated: the beats of stages t+4 .. t+26, the oldest first (entering the FIFO next).
    post: VecDeque<Option<VideoBeat>>,
    fifo: VecDeque<VideoBeat>,
    phong: bool,
    /// The Phong constants: per light unit L and H; per material its slot words.
    light_regs: [([i64; 3], [i64; 3]); CS_LIGHTS],
    material_words: [[[u16; 6]; 1 + CS_LIGHTS]; CS_MATERIALS],
    /// Beats taken by the consumer since construction.
    pub beats: u64,
    /// The texture the next frame is started with.
    texturing: Option<Texturing>,
    /// This frame's texture unit (a textured frame).
    sampler: Option<TextureSamplerModel>,
    /// This frame's level-0 size, log2.
    tex_size_log2: (u32, u32),
    /// Trilinear: the cycle after an issue issues nothing.
    trilinear: bool,
    issued_last: bool,
    /// Textured: the pixels in the coordinate unit, the oldest first, then the one offered to the
    /// texture unit and the (sof, eol) of those it has taken.
    tex_line: VecDeque<Option<(SamplerPixel, (bool, bool))>>,
    offer: Option<(SamplerPixel, (bool, bool))>,
    in_sampler: VecDeque<(bool, bool)>,
}

/// The colour of one pixel: background where the index is 0, else the three planes evaluated at the
/// pixel centre and clamped to 0..=255 (flat and Gouraud; `GoldenChipset::scanout`); for Phong see
/// [`ColorShaderModel`]'s use of [`PhongLights::shade`].
pub fn pixel_colour(index: u16, record: &TdbsEntry, x: u32, y: u32, background: [u8; 3]) -> [u8; 3] {
    if index == 0 {
        background
    } else {
        let p: &[Plane; 3] = &record.planes;
        [0, 1, 2].map(|k| p[k].eval_clamped(x, y, 255) as u8)
    }
}

impl ColorShaderModel {
    pub fn new() -> ColorShaderModel {
        ColorShaderModel { post: vec![None; CS_PIPELINE_CYCLES as usize - 4].into(), ..Default::default() }
    }

    /// Load (or with `None` remove) the texture for the frames started from now on (host side: the
    /// texture's settings and level table; its texels are in the banks behind `tex_banks`).
    pub fn set_texturing(&mut self, texturing: Option<Texturing>) {
        self.texturing = texturing;
    }

    fn credit(&self) -> usize {
        if self.sampler.is_some() {
            CS_FIFO_DEPTH_TEX
        } else {
            CS_FIFO_DEPTH
        }
    }

    /// The Phong constants as the hardware holds them, in the golden model's form. A log2 gloss
    /// above [`CS_GLOSS_LOG2_MAX`] squares that many times (the number of squaring stages).
    fn phong_lights(&self) -> PhongLights {
        let l = self.light_regs.iter().map(|r| r.0).collect();
        let h = self.light_regs.iter().map(|r| r.1).collect();
        let materials = self
            .material_words
            .iter()
            .map(|w| PhongMaterial {
                ambient: [0, 1, 2].map(|k| w[0][k] as i64),
                diffuse: (0..CS_LIGHTS).map(|li| [0, 1, 2].map(|k| w[1 + li][k] as i64)).collect(),
                specular: (0..CS_LIGHTS).map(|li| [3, 4, 5].map(|k| w[1 + li][k] as i64)).collect(),
                gloss_log2: ((w[0][3] & 7) as u32).min(CS_GLOSS_LOG2_MAX),
            })
            .collect();
        PhongLights { l, h, materials }
    }

    fn busy(&self) -> bool {
        self.running || self.pending > 0
    }

    fn issuing(&self) -> bool {
        self.running && self.pending < self.credit() && !(self.trilinear && self.issued_last)
    }

    /// The outputs in the current cycle.
    pub fn outputs(&self) -> CsOutputs {
        let mut o = CsOutputs { busy: self.busy(), size_error: self.size_error, ..Default::default() };
        if self.issuing() {
            o.ibuf_read = ReadPort { enable: true, address: self.address };
        }
        if let Some(p) = self.s1 {
            if self.clear {
                o.ibuf_write = WritePort { enable: true, address: p.address, data: 0 };
                o.zbuf_write = WritePort { enable: true, address: p.address, data: DEPTH_MAX };
            }
        }
        if let Some((_, idx)) = self.s2 {
            o.tdbs_read = ReadPort { enable: true, address: idx as u32 };
            if self.sampler.is_some() {
                o.tdbt_read = o.tdbs_read;
            }
        }
        if let Some(b) = self.fifo.front() {
            o.video_tvalid = true;
            o.video = *b;
        }
        o
    }

    /// One clock: returns this cycle's outputs, then takes the rising edge with `inp`.
    pub fn step(&mut self, inp: &CsInputs) -> CsOutputs {
        let mut out = self.outputs();
        let size_mask = (1u32 << CS_SIZE_BITS) - 1;
        // Video: the head beat leaves.
        if out.video_tvalid && inp.video_tready {
            self.fifo.pop_front();
            self.pending -= 1;
            self.beats += 1;
        }
        // Pipeline, from the end backwards.
        if let Some(b) = self.post.pop_front().flatten() {
            assert!(self.fifo.len() < CS_FIFO_DEPTH, "CS model: output FIFO overflow (credit accounting broken)");
            self.fifo.push_back(b);
        }
        if let Some(sampler) = self.sampler.as_mut() {
            let so = sampler.step(self.offer.as_ref().map(|o| &o.0));
            out.tex_banks = so.banks;
            if so.ready {
                if let Some((_, meta)) = self.offer.take() {
                    self.in_sampler.push_back(meta);
                }
            }
            if let Some(rgb) = so.rgb {
                let (sof, eol) = self.in_sampler.pop_front().expect("CS model: a texture unit colour with no pixel");
                assert!(self.fifo.len() < CS_FIFO_DEPTH_TEX, "CS model: output FIFO overflow (credit accounting broken)");
                self.fifo.push_back(VideoBeat { rgb, sof, eol });
            }
            if let Some(next) = self.tex_line.pop_front().flatten() {
                assert!(self.offer.is_none(), "CS model: a pixel reached the texture unit while the last waits");
                self.offer = Some(next);
            }
        }
        let (w_log2, h_log2) = self.tex_size_log2;
        let textured = self.sampler.is_some();
        let beat = self.s3.take().map(|(p, idx)| {
            let rec = &inp.tdbs_read_data;
            let rgb = if self.phong && idx != 0 {
                let n = [0, 1, 2].map(|k| rec.planes[k].eval(p.x, p.y));
                self.phong_lights().shade(n, rec.material % CS_MATERIALS as u16)
            } else {
                pixel_colour(idx, rec, p.x, p.y, self.background)
            };
            let planes = inp.tdbt_read_data;
            let tex = (textured && idx != 0).then(|| planes.eval(p.x, p.y, w_log2, h_log2));
            let sample = SamplerPixel { s: tex.map_or(0, |c| c.s), t: tex.map_or(0, |c| c.t), lod: tex.map_or(0, |c| c.lod), colour: rgb, textured: tex.is_some() };
            (VideoBeat { rgb, sof: p.sof, eol: p.eol }, sample)
        });
        if textured {
            self.tex_line.push_back(beat.map(|(b, sample)| (sample, (b.sof, b.eol))));
            self.post.push_back(None);
        } else {
            self.post.push_back(beat.map(|b| b.0));
        }
        self.s3 = self.s2.take();
        self.s2 = self.s1.take().map(|p| (p, inp.ibuf_read_data));
        // Issue.
        self.issued_last = out.ibuf_read.enable;
        if out.ibuf_read.enable {
            let eol = self.x + 1 == self.width;
            self.s1 = Some(Pixel { x: self.x, y: self.y, address: self.address, sof: self.x == 0 && self.y == 0, eol });
            self.pending += 1;
            self.address += 1;
            if eol {
                self.x = 0;
                if self.y + 1 == self.height {
                    self.running = false;
                } else {
                    self.y += 1;
                }
            } else {
                self.x += 1;
            }
        }
        // Phong constants.
        match inp.config {
            Some(CsConfigWrite::Light { address, l, h }) if (address as usize) < CS_LIGHTS => {
                self.light_regs[address as usize] = (l.map(|c| c as i16 as i64), h.map(|c| c as i16 as i64));
            }
            Some(CsConfigWrite::Material { address, slot, words }) if (slot as usize) <= CS_LIGHTS => {
                let words = if slot == 0 { [words[0], words[1], words[2], words[3] & 7, 0, 0] } else { words };
                self.material_words[address as usize % CS_MATERIALS][slot as usize] = words;
            }
            _ => {}
        }
        // Frame start.
        if inp.start && !out.busy {
            let (w, h) = (inp.width & size_mask, inp.height & size_mask);
            if (1..=MAX_SCREEN).contains(&w) && (1..=MAX_SCREEN).contains(&h) {
                self.size_error = false;
                self.running = true;
                self.width = w;
                self.height = h;
                self.background = inp.background;
                self.clear = inp.clear_behind;
                self.phong = inp.shading_phong;
                self.x = 0;
                self.y = 0;
                self.address = 0;
                self.sampler = self.texturing.as_ref().map(|tx| TextureSamplerModel::new((*tx.texture).clone(), tx.filter, tx.wrap));
                self.tex_size_log2 = self.texturing.as_ref().map_or((0, 0), |tx| (tx.texture.levels[0].w_log2, tx.texture.levels[0].h_log2));
                self.trilinear = self.texturing.as_ref().is_some_and(|tx| tx.filter == Filter::Trilinear);
                self.issued_last = false;
                self.tex_line = vec![None; CS_TEX_COORD_CYCLES as usize - 1].into();
                self.offer = None;
                self.in_sampler.clear();
            } else {
                self.size_error = true;
            }
        }
        out
    }
}

/// Memories as the bench provides them: synchronous read ports with latency 1 (the data of the
/// address presented in cycle t appears in cycle t+1; with the enable low the data holds) and
/// write ports that take effect at the edge. A read of an address being written returns the old data.
#[derive(Clone, Debug)]
pub struct CsMemories {
    pub ibuf: Vec<u16>,
    pub zbuf: Vec<u32>,
    pub tdbs: Vec<TdbsEntry>,
    /// TdbT (textured frames; empty otherwise).
    pub tdbt: Vec<TexPlanes>,
    ibuf_data: u16,
    tdbs_data: TdbsEntry,
    tdbt_data: TexPlanes,
}

impl CsMemories {
    pub fn new(ibuf: Vec<u16>, zbuf: Vec<u32>, tdbs: Vec<TdbsEntry>) -> CsMemories {
        CsMemories { ibuf, zbuf, tdbs, tdbt: Vec::new(), ibuf_data: 0, tdbs_data: TdbsEntry::default(), tdbt_data: TexPlanes::default() }
    }
    /// The same with a TdbT.
    pub fn with_tdbt(self, tdbt: Vec<TexPlanes>) -> CsMemories {
        CsMemories { tdbt, ..self }
    }
    /// The TdbT read data in the current cycle.
    pub fn tdbt_data(&self) -> TexPlanes {
        self.tdbt_data
    }
    /// The read data the memories show in the current cycle.
    pub fn read_data(&self) -> (u16, TdbsEntry) {
        (self.ibuf_data, self.tdbs_data)
    }
    /// The rising edge, given the block's outputs in this cycle. Out-of-range addresses read 0 and
    /// ignore writes (the bench reports them as mismatches through the compare).
    pub fn edge(&mut self, o: &CsOutputs) {
        if o.ibuf_read.enable {
            self.ibuf_data = self.ibuf.get(o.ibuf_read.address as usize).copied().unwrap_or(0);
        }
        if o.tdbs_read.enable {
            self.tdbs_data = self.tdbs.get(o.tdbs_read.address as usize).copied().unwrap_or_default();
        }
        if o.tdbt_read.enable {
            self.tdbt_data = self.tdbt.get(o.tdbt_read.address as usize).copied().unwrap_or_default();
        }
        if o.ibuf_write.enable {
            if let Some(v) = self.ibuf.get_mut(o.ibuf_write.address as usize) {
                *v = o.ibuf_write.data as u16;
            }
        }
        if o.zbuf_write.enable {
            if let Some(v) = self.zbuf.get_mut(o.zbuf_write.address as usize) {
                *v = o.zbuf_write.data;
            }
        }
    }
}

/// Run one frame through the model with the given back-pressure pattern (`tready(cycle)`), and
/// return the RGB888 image in raster order and the number of cycles from the first pixel's issue to
/// the last beat taken, both included.
///
/// For Phong (`phong` is `Some`), the constants are written first, one per cycle, and the frame
/// starts in the cycle after the last write.
pub fn scan_frame(
    mem: &mut CsMemories,
    width: u32,
    height: u32,
    background: [u8; 3],
    clear_behind: bool,
    phong: Option<&[CsConfigWrite]>,
    tready: impl FnMut(u64) -> bool,
) -> Result<(Vec<u8>, u64), String> {
    scan(mem, width, height, background, clear_behind, phong, None, tready).map(|s| (s.rgb, s.cycles))
}

/// What [`scan_textured_frame`] measured.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Scan {
    /// RGB888 in raster order.
    pub rgb: Vec<u8>,
    /// Cycles from the first pixel's issue to the last beat taken, both included.
    pub cycles: u64,
    /// Words read at the texture port.
    pub bank_words: u64,
}

/// [`scan_frame`] of a textured frame (`mem` holds its TdbT): also the words read at the texture
/// port.
pub fn scan_textured_frame(
    mem: &mut CsMemories,
    width: u32,
    height: u32,
    background: [u8; 3],
    phong: Option<&[CsConfigWrite]>,
    texturing: &Texturing,
    tready: impl FnMut(u64) -> bool,
) -> Result<Scan, String> {
    scan(mem, width, height, background, false, phong, Some(texturing), tready)
}

#[allow(clippy::too_many_arguments)]
fn scan(
    mem: &mut CsMemories,
    width: u32,
    height: u32,
    background: [u8; 3],
    clear_behind: bool,
    phong: Option<&[CsConfigWrite]>,
    texturing: Option<&Texturing>,
    mut tready: impl FnMut(u64) -> bool,
) -> Result<Scan, String> {
    let mut m = ColorShaderModel::new();
    m.set_texturing(texturing.cloned());
    let mut bank_words = 0u64;
    let config = phong.unwrap_or(&[]);
    let start = config.len() as u64;
    let mut rgb = Vec::with_capacity((width * height * 3) as usize);
    let mut cycle = 0u64;
    let (mut first_issue, mut last_beat) = (None, 0u64);
    let limit = start + 64 + 64 * (width as u64 * height as u64 + 64);
    loop {
        let (ibuf_read_data, tdbs_read_data) = mem.read_data();
        let ready = tready(cycle);
        let inp = CsInputs {
            start: cycle == start,
            width,
            height,
            background,
            clear_behind,
            ibuf_read_data,
            tdbs_read_data,
            tdbt_read_data: mem.tdbt_data(),
            video_tready: ready,
            shading_phong: phong.is_some(),
            config: config.get(cycle as usize).copied(),
        };
        let o = m.step(&inp);
        bank_words += o.tex_banks.reads() as u64;
        if o.ibuf_read.enable && first_issue.is_none() {
            first_issue = Some(cycle);
        }
        if o.video_tvalid && ready {
            rgb.extend_from_slice(&o.video.rgb);
            last_beat = cycle;
        }
        mem.edge(&o);
        if cycle > start && !o.busy {
            if o.size_error {
                return Err(format!("the CS refused the screen size {width}x{height} (1..={MAX_SCREEN} each)"));
            }
            return Ok(Scan { rgb, cycles: last_beat + 1 - first_issue.unwrap_or(last_beat + 1), bank_words });
        }
        cycle += 1;
        if cycle > limit {
            return Err(format!("the CS model did not finish a {width}x{height} frame in {limit} cycles"));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::Screen;
    use crate::host::Camera;
    use crate::raster::{CullMode, FrontFace};
    use crate::render::{render_with, GoldenChipset, RenderOptions};
    use crate::scene::{builtin, Winding};
    use crate::shade::Shading;

    fn frame(name: &str, shading: Shading, w: u32, h: u32) -> (GoldenChipset, crate::render::Frame, [u8; 3], PhongLights) {
        let mesh = if name == "teapot" { builtin::teapot(6) } else { builtin::scene(name).unwrap() };
        let screen = Screen::new(w, h).unwrap();
        let bg = [24, 24, 40];
        let opts = RenderOptions {
            screen,
            camera: Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0),
            shading,
            cull: CullMode::Back,
            front: if mesh.front_face == Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw },
            lighting: Default::default(),
            index_bits: 16,
            rc_type: crate::raster::RcType::IV,
            texturing: None,
            background: bg,
        };
        let mut chip = GoldenChipset::new(screen);
        let f = render_with(&mesh, &opts, &mut chip).unwrap();
        (chip, f, bg, PhongLights::new(&opts.lighting, &mesh.materials))
    }

    fn memories(chip: &GoldenChipset, f: &crate::render::Frame) -> CsMemories {
        let ibuf = f.hw_index.iter().map(|&i| i as u16).collect();
        CsMemories::new(ibuf, f.zbuf.clone(), chip.tdbs.clone())
    }

    #[test]
    fn color_shader_model_scans_out_the_golden_image_of_every_scene() {
        for name in builtin::SCENES {
            for shading in [Shading::Gouraud, Shading::Flat, Shading::Phong] {
                let (chip, f, bg, lights) = frame(name, shading, 160, 100);
                let mut mem = memories(&chip, &f);
                let config = phong_config(&lights).unwrap();
                let phong = (shading == Shading::Phong).then_some(&config[..]);
                let (rgb, cycles) = scan_frame(&mut mem, 160, 100, bg, false, phong, |_| true).unwrap();
                assert!(rgb == f.rgb, "{name} {shading:?}: the model's image differs from the golden one");
                assert_eq!(cycles, 160 * 100 + CS_PIPELINE_CYCLES, "{name}: one pixel per clock");
            }
        }
    }

    #[test]
    fn back_pressure_loses_and_repeats_no_pixel_and_clear_behind_clears_both_buffers() {
        let (chip, f, bg, _) = frame("castle", Shading::Gouraud, 96, 64);
        let mut mem = memories(&chip, &f);
        let mut x = 0x9e3779b97f4a7c15u64;
        let (rgb, cycles) = scan_frame(&mut mem, 96, 64, bg, true, None, |_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x % 3 != 0
        })
        .unwrap();
        assert!(rgb == f.rgb, "image under back-pressure differs");
        assert!(cycles > 96 * 64 * 4 / 3, "back-pressure had no effect ({cycles} cycles)");
        assert!(mem.ibuf.iter().all(|&i| i == 0), "I-buffer not cleared behind the scan");
        assert!(mem.zbuf.iter().all(|&z| z == DEPTH_MAX), "Z-buffer not cleared behind the scan");
    }

    const BG: [u8; 3] = [24, 24, 40];

    /// teapot-floor at 320x200, Gouraud, textured with the built-in checker (`filter`, perspective),
    /// its golden frame and chipset, and the memories the CS scans.
    fn textured(filter: Filter) -> (crate::render::Frame, Texturing, CsMemories) {
        let mesh = builtin::teapot_floor();
        let screen = Screen::new(320, 200).unwrap();
        let texturing = Texturing { texture: std::sync::Arc::new(crate::texture::checker()), source: "test".into(), filter, coords: crate::texcoord::Coords::Perspective, wrap: crate::texture::Wrap::Repeat };
        let opts = RenderOptions { texturing: Some(texturing.clone()), background: BG, ..RenderOptions::for_scene(&mesh, screen, Shading::Gouraud) };
        let mut chip = GoldenChipset::new(screen);
        let f = render_with(&mesh, &opts, &mut chip).unwrap();
        let tdbt = chip.tdbt.iter().map(|t| t.unwrap_or_default()).collect();
        let mem = memories(&chip, &f).with_tdbt(tdbt);
        (f, texturing, mem)
    }

    #[test]
    fn the_textured_color_shader_model_scans_out_golden_textured_frames_at_the_stated_rates() {
        for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
            let (f, tx, mut mem) = textured(filter);
            let counts = f.stats.texture.clone().expect("a textured frame counts its texels");
            let scan = scan_textured_frame(&mut mem, 320, 200, BG, None, &tx, |_| true).unwrap();
            assert!(scan.rgb == f.rgb, "{filter:?}: the model's image differs from the golden one");
            assert_eq!(scan.bank_words, counts.bank_words_read, "{filter:?}: words read at the texture port");
            println!("{filter:?}: {} cycles, {} words at the texture port", scan.cycles, scan.bank_words);
            let n = 320 * 200;
            match filter {
                // One pixel per clock; the last beat CS_PIPELINE_CYCLES_TEX after the last issue.
                Filter::Nearest | Filter::Bilinear => assert_eq!(scan.cycles, n + CS_PIPELINE_CYCLES_TEX, "{filter:?}"),
                // One pixel every two clocks; a last pixel between two levels one cycle later.
                Filter::Trilinear => assert!((2 * n - 1 + CS_PIPELINE_CYCLES_TEX..=2 * n + CS_PIPELINE_CYCLES_TEX).contains(&scan.cycles), "{} cycles", scan.cycles),
            }
        }
    }

    #[test]
    fn a_textured_frame_under_back_pressure_loses_and_repeats_no_pixel() {
        for filter in [Filter::Bilinear, Filter::Trilinear] {
            let (f, tx, mut mem) = textured(filter);
            let mut x = 0x9e3779b97f4a7c15u64;
            let scan = scan_textured_frame(&mut mem, 320, 200, BG, None, &tx, |_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x % 4 != 0
            })
            .unwrap();
            assert!(scan.rgb == f.rgb, "{filter:?}: image under back-pressure differs");
            assert!(scan.cycles > 320 * 200 * 5 / 4, "{filter:?}: back-pressure had no effect ({} cycles)", scan.cycles);
        }
    }

    #[test]
    fn bad_screen_sizes_set_size_error_and_start_nothing() {
        for (w, h) in [(0, 10), (10, 0), (1025, 4), (4, 2047)] {
            let mut mem = CsMemories::new(vec![0; 16], vec![0; 16], vec![TdbsEntry::default()]);
            let e = scan_frame(&mut mem, w, h, [0; 3], false, None, |_| true).unwrap_err();
            assert!(e.contains(&format!("{w}x{h}")), "{e}");
        }
    }
}
