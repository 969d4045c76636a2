//! Cycle-accurate model of PROOF's filter stage (seed 002 §6), 1x1 box: the RTL top
//! `hdl::proof::filter::FilterStage` must match [`FilterModel`] on every port in every cycle.
//!
//! ```text
//!   cfg_write cfg_sel cfg_addr cfg_data   (0: edge-direction table, 1: background colour, 2: opacity table)
//!        │
//!   up ─▶ F0 ─▶ F1 ─────▶ F2 ───────▶ F3 ────▶ F4 ──────────▶ F5 ──────▶ F6 ──────▶ OUT ─▶ down
//!  (shaded │dir, base,     rows: tree   masks:   weights per    W = Σ w_i  sums:      colour, covered
//!   slots) │alpha 2cos,    of multiples tree of  subpixel:      covered    Σ W c, Σ W (one per pixel)
//!          │tables 2sin,   of 2 sin     2 cos    w_i = T_i a
//!          │      alpha
//! ```
//!
//! The stage takes one list entry (time slot) per clock and gives one pixel per list: every register
//! loads when `adv = !out_valid || down_ready` (a global stall; `up_ready = adv`, combinational, as
//! in the shading stage). Latency from a pixel's last slot to its output: 8 clocks.
//!
//! Per edge k of an entry (16 times the subpixel distance, in units of 2^-14 px, exact):
//! * F0: the slot; the direction table (object id -> cos a, sin a of the three edges, Q1.14) and the
//!   opacity table (id -> opacity, Q1.4; the host writes both for every object) are read at the same
//!   edge with enable `adv`;
//! * F1: `base = 16 d - 7 cos - 7 sin` (the distance at subpixel (0, 0)), `sx = 2 cos`, `sy = 2 sin`;
//!   the entry's opacity `a` (a table value above 16 counts as 16);
//! * F2: the eight row values `base + j sy`, j = 0..7, from the paper's tree of multiples (level 2
//!   adds 4 sy on the right branch, level 1 adds 2 sy, level 0 adds sy);
//! * F3: per row the same tree in x with `sx`; a subpixel is inside the edge if its leaf is >= 0.
//!   The entry's mask is the AND of the three edges' masks (all 64 for a full entry, none for an
//!   empty slot), computed as F3 is read;
//! * F4: front-to-back blending per subpixel (`golden::proof::filter::blend_subpixels`): for each
//!   subpixel i of the mask, `w_i = (T_i a + 8) >> 4` with `T_i = 256 - spent_i`, the transmittance
//!   the nearer entries left; the pixel state `spent_i` grows by `w_i` and `taken` (the union of the
//!   masks) by the mask, both back to 0 after the pixel's last slot. An opaque entry (a = 16) takes
//!   `w_i = T_i`: all of a subpixel no nearer entry covered, nothing of one it did;
//! * F5: `W = Σ w_i` (0..=16384, per quadrant for the 2x2 area), `covered = popcount(union)`;
//! * F6: `acc = sum + W c` per channel and `wacc = wsum + W`; the pixel states `sum`, `wsum` become
//!   `acc`, `wacc`, or 0 after the last slot;
//! * OUT: for a pixel's last slot, `colour = (acc + (16384 - wacc) bg + 2^13) >> 14`, the background
//!   weighted by what is left of the 64 subpixels' transmittance.
//!
//! On lists of opaque entries every `w_i` is 0 or 256, and the output is the unblended filter's
//! (each subpixel to its nearest entry) byte for byte.
//!
//! Data of a register whose valid bit is 0 is don't-care; the pixel states change only when a valid
//! slot passes. The values never need more than 22 bits signed for any 16-bit inputs (|16 d| < 2^19,
//! |7 cos + 7 sin| < 2^19, |7 sx + 7 sy| < 2^20), so the model computes in i64 and the RTL in 22
//! bits without wrapping.

use super::cycle_shade::{CfgWrite, ShadedSlot};
use super::filter::multiples_tree;
use super::format::{ALPHA_FRAC, ALPHA_ONE};

/// Configuration targets of the filter's `cfg` write port.
pub const CFG_DIRS: u8 = 0;
pub const CFG_BACKGROUND: u8 = 1;
/// The opacity table: object id -> opacity in sixteenths, Q1.4 (5 bits; 16 is opaque, a value above
/// 16 counts as 16). The host writes it for every object, as the direction table.
pub const CFG_ALPHA: u8 = 2;

/// A subpixel's whole weight, 1.0 in Q1.8 (the transmittance of an uncovered subpixel).
pub const W_ONE: u32 = super::filter::T_ONE;

/// Registers from a pixel's last slot at the input to its pixel at the output.
pub const FILTER_LATENCY: usize = 8;

/// One pixel of the filter's output.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct FilteredPixel {
    pub x: u16,
    pub y: u16,
    pub rgb: [u8; 3],
    /// Subpixels covered by some object (0..=64).
    pub covered: u8,
}

/// The configuration writes that load the edge-direction table (`dirs[id]` = (cos, sin) of the three
/// edges, Q1.14) and the opacity table of opaque objects, and the background colour.
/// [`filter_config_alpha`] gives the opacities.
pub fn filter_config(dirs: &[[(i16, i16); 3]], background: [u8; 3], obj_addr_bits: u32) -> Result<Vec<CfgWrite>, String> {
    filter_config_alpha(dirs, &[], background, obj_addr_bits)
}

/// [`filter_config`] with the opacity `alphas[id]` (Q1.4, `format::alpha_q`) of each object;
/// objects past the end of `alphas` are opaque.
pub fn filter_config_alpha(dirs: &[[(i16, i16); 3]], alphas: &[u16], background: [u8; 3], obj_addr_bits: u32) -> Result<Vec<CfgWrite>, String> {
    check_filter_params(obj_addr_bits)?;
    if dirs.len() > 1usize << obj_addr_bits {
        return Err(format!("{} objects do not fit the filter's direction table of {} entries", dirs.len(), 1u64 << obj_addr_bits));
    }
    let mut w = Vec::with_capacity(2 * dirs.len() + 1);
    for (id, d) in dirs.iter().enumerate() {
        let mut data = 0u128;
        for k in 0..3 {
            data |= (d[k].0 as u16 as u128) << (32 * k);
            data |= (d[k].1 as u16 as u128) << (32 * k + 16);
        }
        w.push(CfgWrite { sel: CFG_DIRS, addr: id as u16, data });
        let a = alphas.get(id).copied().unwrap_or(ALPHA_ONE).min(ALPHA_ONE);
        w.push(CfgWrite { sel: CFG_ALPHA, addr: id as u16, data: a as u128 });
    }
    let bg = background[0] as u128 | (background[1] as u128) << 8 | (background[2] as u128) << 16;
    w.push(CfgWrite { sel: CFG_BACKGROUND, addr: 0, data: bg });
    Ok(w)
}

/// A scene's filter configuration: every object's edge directions and opacity, and the background
/// ([`filter_config_alpha`] of the scene's objects).
pub fn scene_filter_config(scene: &super::setup::ProofScene, obj_addr_bits: u32) -> Result<Vec<CfgWrite>, String> {
    let dirs: Vec<_> = (0..scene.objects.len()).map(|i| super::render::dirs_of(scene, i as u16)).collect();
    let alphas: Vec<u16> = scene.objects.iter().map(|o| o.alpha).collect();
    filter_config_alpha(&dirs, &alphas, scene.background, obj_addr_bits)
}

/// The constructor parameter both the model and the RTL accept.
pub fn check_filter_params(obj_addr_bits: u32) -> Result<(), String> {
    if !(1..=16).contains(&obj_addr_bits) {
        return Err(format!("direction table of 2^{obj_addr_bits} entries: the id is 16 bits, use 1..=16 address bits"));
    }
    Ok(())
}

/// Inputs of the filter stage in one cycle.
#[derive(Copy, Clone, Debug, Default)]
pub struct FilterIn {
    pub up_valid: bool,
    pub up_data: ShadedSlot,
    pub down_ready: bool,
    pub cfg: Option<CfgWrite>,
}

/// Outputs of the filter stage in one cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct FilterOut {
    pub up_ready: bool,
    pub down_valid: bool,
    pub down_data: FilteredPixel,
}

/// F1: per edge, the distance at subpixel (0, 0) and the steps.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeF1 {
    pub base: i64,
    pub sx: i64,
    pub sy: i64,
}

/// F2: per edge, the row values and the x step.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeF2 {
    pub rows: [i64; 8],
    pub sx: i64,
}

/// The slot information that travels beside the arithmetic (F0..F3).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Tag {
    pub valid: bool,
    pub slot: ShadedSlot,
    /// The entry's opacity, Q1.4 (0..=16), from the opacity table (set from F1 on).
    pub alpha: u8,
}

/// F4: the entry's weight in each subpixel (in 1/256 of a subpixel, bit order `8 j + i`) and the
/// pixel's union of masks so far.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct VisReg {
    pub tag: Tag,
    pub w: [u16; 64],
    pub union: u64,
}

impl Default for VisReg {
    fn default() -> VisReg {
        VisReg { tag: Tag::default(), w: [0; 64], union: 0 }
    }
}

impl VisReg {
    /// The weights summed per quadrant of 4x4 subpixels (q = 2 qy + qx; 0..=4096 each).
    pub fn quadrant_weights(&self) -> [u32; 4] {
        let mut q = [0u32; 4];
        for (i, &w) in self.w.iter().enumerate() {
            q[super::filter::quadrant_of(i)] += w as u32;
        }
        q
    }

    /// The entry's whole weight in the pixel (0..=16384: 256 per subpixel).
    pub fn weight(&self) -> u32 {
        self.quadrant_weights().iter().sum()
    }
}

/// F5: the entry's weight (0..=16384) and the pixel's covered subpixels so far.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct WeightReg {
    pub tag: Tag,
    pub w: u16,
    pub covered: u8,
}

/// F6: the pixel's colour sums and weight sum including this entry.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct SumReg {
    pub tag: Tag,
    pub acc: [u32; 3],
    pub wacc: u32,
    pub covered: u8,
}

/// The front end of the filter stage, F0..F4 (seed 002 §6.1: the subpixel mask and which entry owns
/// each subpixel), shared by the 1x1 back end ([`FilterModel`]) and the 2x2 back end
/// (`cycle_filter2x2::Filter2x2Model`): everything up to F4's visible and union masks.
#[derive(Clone, Debug)]
pub struct FilterFront {
    pub obj_addr_bits: u32,
    /// Direction table: (cos, sin) of the three edges per object, and its output register.
    pub dir_table: Vec<[i16; 6]>,
    pub dir_q: [i16; 6],
    /// Opacity table ([`CFG_ALPHA`]), read with the direction table, and its output register.
    pub alpha_table: Vec<u8>,
    pub alpha_q: u8,
    pub f0: Tag,
    pub f1: (Tag, [EdgeF1; 3]),
    pub f2: (Tag, [EdgeF2; 3]),
    /// F3: each edge's half-plane mask.
    pub f3: (Tag, [u64; 3]),
    /// Pixel state: subpixels covered by nearer entries.
    pub taken: u64,
    /// Pixel state: per subpixel (bit order), the part of its 256 that nearer entries took
    /// (256 - transmittance; 0..=256).
    pub spent: [u16; 64],
    pub f4: VisReg,
}

/// The filter stage with the 1x1 box, register by register: [`FilterFront`] then F5, F6, OUT.
#[derive(Clone, Debug)]
pub struct FilterModel {
    pub front: FilterFront,
    pub background: [u8; 3],
    pub f5: WeightReg,
    /// Pixel state: colour sums of the entries so far (weights in 1/256 of a subpixel).
    pub sum: [u32; 3],
    /// Pixel state: the weights of the entries so far (0..=16384).
    pub wsum: u32,
    pub f6: SumReg,
    pub out_valid: bool,
    pub out: FilteredPixel,
}

/// F1's arithmetic for one edge: distance d (S1.14) and direction (cos, sin) (Q1.14).
pub fn edge_f1(d: i16, cos: i16, sin: i16) -> EdgeF1 {
    let (d, c, s) = (d as i64, cos as i64, sin as i64);
    EdgeF1 { base: 16 * d - 7 * c - 7 * s, sx: 2 * c, sy: 2 * s }
}

/// F2's tree in y.
pub fn edge_f2(e: &EdgeF1) -> EdgeF2 {
    EdgeF2 { rows: multiples_tree(e.sy).map(|m| e.base + m), sx: e.sx }
}

/// F3's tree in x: bit 8 j + i set when subpixel (i, j) is inside the edge.
pub fn edge_f3(e: &EdgeF2) -> u64 {
    let mx = multiples_tree(e.sx);
    let mut m = 0u64;
    for j in 0..8 {
        for i in 0..8 {
            if e.rows[j] + mx[i] >= 0 {
                m |= 1 << (8 * j + i);
            }
        }
    }
    m
}

impl FilterFront {
    /// A front end with a direction table of 2^`obj_addr_bits` entries.
    pub fn new(obj_addr_bits: u32) -> Result<FilterFront, String> {
        check_filter_params(obj_addr_bits)?;
        Ok(FilterFront {
            obj_addr_bits,
            dir_table: vec![[0; 6]; 1 << obj_addr_bits],
            dir_q: [0; 6],
            alpha_table: vec![0; 1 << obj_addr_bits],
            alpha_q: 0,
            f0: Tag::default(),
            f1: Default::default(),
            f2: Default::default(),
            f3: Default::default(),
            taken: 0,
            spent: [0; 64],
            f4: VisReg::default(),
        })
    }

    /// Whether any register of F0..F4 holds a slot.
    pub fn busy(&self) -> bool {
        self.f0.valid || self.f1.0.valid || self.f2.0.valid || self.f3.0.valid || self.f4.tag.valid
    }

    /// The entry mask F3 holds: AND of the edges, all for a full entry, none for an empty slot.
    pub fn entry_mask(&self) -> u64 {
        let (t, m) = &self.f3;
        if !t.slot.has_entry {
            0
        } else if t.slot.full {
            u64::MAX
        } else {
            m[0] & m[1] & m[2]
        }
    }

    /// One edge with the global stall open: F4 ← F3 ← F2 ← F1 ← F0 ← the input slot. The back end
    /// must read F4 before calling this.
    pub fn advance(&mut self, up_valid: bool, up_data: &ShadedSlot) {
        // F4: per covered subpixel, the weight w = (T a + 8) >> 4 of what the nearer entries left,
        // T = 256 - spent (an opaque entry, a = 16, takes all of it).
        let mask = self.entry_mask();
        let t3 = self.f3.0;
        let a = t3.alpha as u32;
        let mut w = [0u16; 64];
        for (i, wi) in w.iter_mut().enumerate() {
            if mask >> i & 1 == 1 {
                let t = W_ONE - self.spent[i] as u32;
                *wi = ((t * a + (1 << (ALPHA_FRAC - 1))) >> ALPHA_FRAC) as u16;
            }
        }
        self.f4 = VisReg { tag: t3, w, union: self.taken | mask };
        if t3.valid {
            if t3.slot.last {
                self.taken = 0;
                self.spent = [0; 64];
            } else {
                self.taken |= mask;
                for i in 0..64 {
                    self.spent[i] += w[i];
                }
            }
        }
        // F3, F2, F1: the trees.
        self.f3 = (self.f2.0, self.f2.1.map(|e| edge_f3(&e)));
        self.f2 = (self.f1.0, self.f1.1.map(|e| edge_f2(&e)));
        let (s, q) = (self.f0.slot, self.dir_q);
        let alpha = self.alpha_q.min(ALPHA_ONE as u8);
        self.f1 = (Tag { alpha, ..self.f0 }, [0, 1, 2].map(|k| edge_f1(s.dist[k], q[2 * k], q[2 * k + 1])));
        // F0: the slot; read the direction and opacity tables.
        self.f0 = Tag { valid: up_valid, slot: *up_data, alpha: 0 };
        let id = up_data.id as usize & ((1usize << self.obj_addr_bits) - 1);
        self.dir_q = self.dir_table[id];
        self.alpha_q = self.alpha_table[id];
    }

    /// A host write to the direction table (cfg target [`CFG_DIRS`]).
    pub fn write_dirs(&mut self, c: &CfgWrite) {
        let a = c.addr as usize & ((1usize << self.obj_addr_bits) - 1);
        self.dir_table[a] = [0, 1, 2, 3, 4, 5].map(|k| ((c.data >> (16 * k)) & 0xffff) as u16 as i16);
    }

    /// A host write to the opacity table (cfg target [`CFG_ALPHA`]): the low 5 bits.
    pub fn write_alpha(&mut self, c: &CfgWrite) {
        let a = c.addr as usize & ((1usize << self.obj_addr_bits) - 1);
        self.alpha_table[a] = (c.data & 0x1f) as u8;
    }
}

/// A host write to a filter stage (either area): the direction table or the background colour.
pub fn filter_write(front: &mut FilterFront, background: &mut [u8; 3], c: &CfgWrite) -> Result<(), String> {
    match c.sel {
        CFG_DIRS => front.write_dirs(c),
        CFG_BACKGROUND => *background = [0, 1, 2].map(|k| ((c.data >> (8 * k)) & 0xff) as u8),
        CFG_ALPHA => front.write_alpha(c),
        s => return Err(format!("cfg_sel {s} is not a filter-stage target (0: directions, 1: background, 2: opacities)")),
    }
    Ok(())
}

impl FilterModel {
    /// A stage with a direction table of 2^`obj_addr_bits` entries.
    pub fn new(obj_addr_bits: u32) -> Result<FilterModel, String> {
        Ok(FilterModel {
            front: FilterFront::new(obj_addr_bits)?,
            background: [0; 3],
            f5: WeightReg::default(),
            sum: [0; 3],
            wsum: 0,
            f6: SumReg::default(),
            out_valid: false,
            out: FilteredPixel::default(),
        })
    }

    pub fn outputs(&self, down_ready: bool) -> FilterOut {
        FilterOut { up_ready: !self.out_valid || down_ready, down_valid: self.out_valid, down_data: self.out }
    }

    /// Whether any register holds a slot or a pixel is half done.
    pub fn busy(&self) -> bool {
        self.front.busy() || self.f5.tag.valid || self.f6.tag.valid || self.out_valid
    }

    /// One clock; returns the outputs before the edge.
    pub fn step(&mut self, inp: &FilterIn) -> Result<FilterOut, String> {
        let out = self.outputs(inp.down_ready);
        if out.up_ready {
            self.advance(inp);
        }
        if let Some(c) = inp.cfg {
            filter_write(&mut self.front, &mut self.background, &c)?;
        }
        Ok(out)
    }

    fn advance(&mut self, inp: &FilterIn) {
        // OUT: one pixel per list.
        let f6 = self.f6;
        self.out_valid = f6.tag.valid && f6.tag.slot.last;
        let wbg = 64 * W_ONE - f6.wacc;
        self.out = FilteredPixel {
            x: f6.tag.slot.x,
            y: f6.tag.slot.y,
            rgb: [0, 1, 2].map(|k| ((f6.acc[k] + wbg * self.background[k] as u32 + (1 << 13)) >> 14) as u8),
            covered: f6.covered,
        };
        // F6: multiply-add into the pixel's sums.
        let f5 = self.f5;
        let acc = [0, 1, 2].map(|k| self.sum[k] + f5.w as u32 * f5.tag.slot.rgb[k] as u32);
        let wacc = self.wsum + f5.w as u32;
        self.f6 = SumReg { tag: f5.tag, acc, wacc, covered: f5.covered };
        if f5.tag.valid {
            if f5.tag.slot.last {
                self.sum = [0; 3];
                self.wsum = 0;
            } else {
                self.sum = acc;
                self.wsum = wacc;
            }
        }
        // F5: weights.
        let f4 = self.front.f4;
        self.f5 = WeightReg { tag: f4.tag, w: f4.weight() as u16, covered: f4.union.count_ones() as u8 };
        // F4..F0.
        self.front.advance(inp.up_valid, &inp.up_data);
    }
}

/// A filter stage's cycle model: the 1x1 area ([`FilterModel`]) or the 2x2 one
/// (`cycle_filter2x2::Filter2x2Model`), on the same ports.
pub trait FilterStageModel {
    fn step(&mut self, inp: &FilterIn) -> Result<FilterOut, String>;
}

impl FilterStageModel for FilterModel {
    fn step(&mut self, inp: &FilterIn) -> Result<FilterOut, String> {
        FilterModel::step(self, inp)
    }
}

/// Filter a frame's stream of shaded slots through a filter model with no gaps: configure, then return
/// the pixels in order and the cycles until the last one left. `idle_limit` cycles without a pixel is an
/// error (a list without a last slot, or not a whole frame); the 2x2 area needs more than a row of them.
pub fn filter_slots<M: FilterStageModel>(model: &mut M, cfg: &[CfgWrite], slots: &[ShadedSlot], idle_limit: u32) -> Result<(Vec<FilteredPixel>, u64), String> {
    for c in cfg {
        model.step(&FilterIn { cfg: Some(*c), down_ready: true, ..Default::default() })?;
    }
    let pixels = slots.iter().filter(|s| s.last).count();
    let mut out = Vec::with_capacity(pixels);
    let (mut i, mut idle, mut cycles) = (0usize, 0u32, 0u64);
    while out.len() < pixels {
        let inp = FilterIn { up_valid: i < slots.len(), up_data: slots.get(i).copied().unwrap_or_default(), down_ready: true, cfg: None };
        let o = model.step(&inp)?;
        cycles += 1;
        if inp.up_valid && o.up_ready {
            i += 1;
        }
        if o.down_valid {
            out.push(o.down_data);
            idle = 0;
        } else {
            idle += 1;
            if idle > idle_limit {
                return Err(format!("the filter model produced no pixel for {idle_limit} cycles (a list without a last slot, or not a whole frame?)"));
            }
        }
    }
    Ok((out, cycles))
}

/// Shaded slots of a frame from its lists and per-entry colours (what the shading stage sends).
pub fn shaded_slots(width: u32, lists: &[Vec<super::format::Entry>], colours: &[Vec<[u8; 3]>]) -> Vec<ShadedSlot> {
    let mut v = Vec::new();
    for (p, (l, c)) in lists.iter().zip(colours).enumerate() {
        let (x, y) = ((p as u32 % width) as u16, (p as u32 / width) as u16);
        if l.is_empty() {
            v.push(ShadedSlot { x, y, last: true, ..Default::default() });
        }
        for (k, e) in l.iter().enumerate() {
            v.push(ShadedSlot { x, y, last: k + 1 == l.len(), has_entry: true, id: e.id, full: e.full, dist: e.dist, rgb: c[k] });
        }
    }
    v
}

/// Test fixtures shared by the 1x1 and 2x2 filter models' tests: a real scene's lists as a slot
/// stream, and a run of any filter model with random gaps on both sides.
#[cfg(test)]
pub(crate) mod fixtures {
    use super::*;
    use crate::proof::cycle_opp::GapRng;
    use crate::proof::format::Entry;
    use crate::proof::render::object_lists;
    use crate::proof::setup::{scene_setup, ProofScene};
    use crate::proof::shade::shade_entry;
    use crate::scene::Mesh;

    /// The fixtures' object-address bits (`glass` has over 1024 objects).
    pub const FIXTURE_BITS: u32 = 11;

    /// A scene at w x h with the CLI's options: its object lists, their shaded colours, the slot stream
    /// and the filter's configuration writes ([`FIXTURE_BITS`] object-address bits).
    pub struct RealFrame {
        pub sc: ProofScene,
        pub lists: Vec<Vec<Entry>>,
        pub colours: Vec<Vec<[u8; 3]>>,
        pub slots: Vec<ShadedSlot>,
        pub cfg: Vec<CfgWrite>,
    }

    pub fn real_frame(mesh: &Mesh, w: u32, h: u32) -> RealFrame {
        let opts = crate::proof::study::cli_options(mesh, w, h);
        let sc = scene_setup(mesh, &opts).unwrap();
        let lists = object_lists(sc.screen, &sc.objects);
        let colours: Vec<Vec<[u8; 3]>> =
            lists.iter().map(|l| l.iter().map(|e| shade_entry(&sc.lights, e.normal, sc.material[e.id as usize])).collect()).collect();
        let slots = shaded_slots(w, &lists, &colours);
        let cfg = scene_filter_config(&sc, FIXTURE_BITS).unwrap();
        RealFrame { sc, lists, colours, slots, cfg }
    }

    /// Configure, then feed the slots with `gin`% input gaps and `gout`% output stalls (seeded) until a
    /// pixel per list has left.
    pub fn run_with_gaps<M: FilterStageModel>(m: &mut M, cfg: &[CfgWrite], slots: &[ShadedSlot], seed: u64, gin: u64, gout: u64) -> Vec<FilteredPixel> {
        for c in cfg {
            m.step(&FilterIn { cfg: Some(*c), down_ready: true, ..Default::default() }).unwrap();
        }
        let mut rng = GapRng(seed);
        let pixels = slots.iter().filter(|s| s.last).count();
        let (mut i, mut out) = (0, Vec::new());
        while out.len() < pixels {
            let go = i < slots.len() && !rng.percent(gin);
            let ready = !rng.percent(gout);
            let inp = FilterIn { up_valid: go, up_data: slots.get(i).copied().unwrap_or_default(), down_ready: ready, cfg: None };
            let o = m.step(&inp).unwrap();
            if go && o.up_ready {
                i += 1;
            }
            if o.down_valid && ready {
                out.push(o.down_data);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::fixtures::{real_frame, run_with_gaps, RealFrame, FIXTURE_BITS};
    use super::*;
    use crate::proof::cycle_opp::GapRng;
    use crate::proof::filter::{subpixel_mask, FilterArea};
    use crate::proof::format::Entry;
    use crate::proof::render::filter_lists;
    use crate::scene::builtin;


    #[test]
    fn the_filter_cycle_model_equals_the_algorithmic_filter_on_real_lists_with_gaps() {
        for (mesh, w, h) in [(builtin::polyhedron(), 64, 40), (builtin::teapot(2), 48, 30)] {
            let RealFrame { sc, lists, colours, slots, cfg } = real_frame(&mesh, w, h);
            let (want_rgb, want_cov) = filter_lists(&sc, &lists, &colours, FilterArea::Box1);
            for (seed, gin, gout) in [(1, 0, 0), (3, 30, 30), (17, 5, 60)] {
                let mut m = FilterModel::new(FIXTURE_BITS).unwrap();
                let out = run_with_gaps(&mut m, &cfg, &slots, seed, gin, gout);
                assert_eq!(out.len(), (w * h) as usize);
                for (p, o) in out.iter().enumerate() {
                    let (x, y) = ((p as u32 % w) as u16, (p as u32 / w) as u16);
                    assert_eq!((o.x, o.y), (x, y), "{} pixel order", mesh.name);
                    assert_eq!(o.rgb[..], want_rgb[3 * p..3 * p + 3], "{} pixel ({x}, {y}) seed {seed}", mesh.name);
                    assert_eq!(o.covered, want_cov[p], "{} pixel ({x}, {y}) covered", mesh.name);
                }
            }
            let partial = want_cov.iter().filter(|&&c| c > 0 && c < 64).count();
            let multi = lists.iter().filter(|l| l.len() > 1).count();
            assert!(partial > 20 && multi > 10, "{}: the lists should exercise the filter ({partial} partial, {multi} multi)", mesh.name);
        }
    }

    #[test]
    fn the_filter_cycle_model_blends_transparent_lists_as_the_algorithmic_filter_with_gaps() {
        let mut half = builtin::teapot(2);
        for m in half.materials.iter_mut() {
            m.opacity = 0.5;
        }
        for (mesh, w, h) in [(builtin::glass(), 64, 40), (half, 48, 30)] {
            let RealFrame { sc, lists, colours, slots, cfg } = real_frame(&mesh, w, h);
            assert!(cfg.iter().any(|c| c.sel == CFG_ALPHA && c.data < ALPHA_ONE as u128), "{}: the frame should have transparent objects", mesh.name);
            let (want_rgb, want_cov) = filter_lists(&sc, &lists, &colours, FilterArea::Box1);
            // The same lists with every object taken as opaque differ: the blend is exercised.
            let (opaque_rgb, _) = crate::proof::render::filter_lists_opaque(&sc, &lists, &colours, FilterArea::Box1);
            assert_ne!(want_rgb, opaque_rgb, "{}", mesh.name);
            for (seed, gin, gout) in [(2, 0, 0), (5, 30, 30)] {
                let mut m = FilterModel::new(FIXTURE_BITS).unwrap();
                let out = run_with_gaps(&mut m, &cfg, &slots, seed, gin, gout);
                for (p, o) in out.iter().enumerate() {
                    assert_eq!(o.rgb[..], want_rgb[3 * p..3 * p + 3], "{} pixel {p} seed {seed}", mesh.name);
                    assert_eq!(o.covered, want_cov[p], "{} pixel {p} covered", mesh.name);
                }
            }
        }
    }

    #[test]
    fn three_full_entries_of_opacity_nine_sixteenths_take_144_63_and_28_of_each_subpixel() {
        // By hand: 256 x 9/16 = 144 leaves 112; 112 x 9/16 = 63 leaves 49; 49 x 9/16 = 27.56, rounded
        // to 28, leaves 21 for the background.
        let mut f = FilterFront::new(2).unwrap();
        f.write_alpha(&CfgWrite { sel: CFG_ALPHA, addr: 1, data: 9 });
        let slot = |last| ShadedSlot { x: 3, y: 4, last, has_entry: true, id: 1, full: true, ..Default::default() };
        let mut seen = Vec::new();
        for n in 0..10 {
            if f.f4.tag.valid {
                seen.push((f.f4.tag.alpha, f.f4.weight(), f.f4.quadrant_weights()));
            }
            f.advance(n < 3, &slot(n == 2));
        }
        assert_eq!(seen, [(9, 144 * 64, [144 * 16; 4]), (9, 63 * 64, [63 * 16; 4]), (9, 28 * 64, [28 * 16; 4])]);
        assert_eq!((f.taken, f.spent), (0, [0; 64]), "the pixel state returns to 0 after the last slot");
    }

    #[test]
    fn the_staged_trees_give_the_golden_subpixel_mask_for_extreme_distances_and_directions() {
        let mut rng = GapRng(0xf117);
        let r16 = |rng: &mut GapRng| {
            let mut v = 0i64;
            for _ in 0..16 {
                v = 2 * v + rng.percent(50) as i64;
            }
            (v - 32768) as i16
        };
        let extremes = [i16::MIN, i16::MAX, 0, 16384, -16384, 11585, -11585];
        for n in 0..4000 {
            let mut e = Entry::default();
            let mut dirs = [(0i16, 0i16); 3];
            for k in 0..3 {
                let pick = |rng: &mut GapRng, r: i16| if rng.percent(20) { extremes[n % extremes.len()] } else { r };
                let (a, b, c) = (r16(&mut rng), r16(&mut rng), r16(&mut rng));
                e.dist[k] = pick(&mut rng, a);
                dirs[k] = (pick(&mut rng, b) / 2, pick(&mut rng, c) / 2);
            }
            let staged = (0..3).map(|k| edge_f3(&edge_f2(&edge_f1(e.dist[k], dirs[k].0, dirs[k].1)))).fold(u64::MAX, |a, m| a & m);
            assert_eq!(staged, subpixel_mask(&e, &dirs), "case {n}: {e:?} {dirs:?}");
            // The 22-bit claim of the RTL: every intermediate fits.
            for k in 0..3 {
                let f2 = edge_f2(&edge_f1(e.dist[k], dirs[k].0, dirs[k].1));
                for r in f2.rows {
                    for m in multiples_tree(f2.sx) {
                        assert!((r + m).abs() < 1 << 21);
                    }
                }
            }
        }
    }

    #[test]
    fn an_unknown_configuration_target_is_an_error() {
        let mut m = FilterModel::new(4).unwrap();
        let e = m.step(&FilterIn { cfg: Some(CfgWrite { sel: 7, addr: 0, data: 0 }), ..Default::default() }).unwrap_err();
        assert!(e.contains("cfg_sel 7"), "{e}");
        assert!(FilterModel::new(0).is_err());
        assert!(filter_config(&[[(0, 0); 3]; 5], [0; 3], 2).unwrap_err().contains("do not fit"));
    }
}
