//! Cycle-accurate model of PROOF's shading stage (seed 002 §5, Fig. 3): the RTL top
//! `hdl::proof::shading::ShadingStage` must match [`ShadeModel`] on every port in every cycle.
//!
//! ```text
//!   cfg_write cfg_sel cfg_addr cfg_data   (host: look-up tables and light registers)
//!        │
//!   up ─▶ R0 ─▶ R1 ─▶ R2 ─▶ [ light 0: A ─▶ P1 ─▶ P2 ─▶ P3 ─▶ P4 ─▶ M ] ─▶ ... ─▶ OUT ─▶ down
//!         │obj    │mat     ambient         dots  squarings (m = 2^g)   I += Kd (N.L) + Ks (N.H)^m
//!         │table  │table   I0 = Ka Ia
//! ```
//!
//! One list entry per clock: every stage is one register and all stages move together when
//! `adv = !out_valid || down_ready` (a global stall; `up_ready = adv`, combinational). One pipeline
//! keeps the OPP's rate of one slot per clock, so the stage needs no parallel pipelines and no
//! round-robin reordering (the paper's parallel pipelines are for processors slower than one entry
//! per clock).
//!
//! Stages (the arithmetic is `super::shade`'s, split so that each register holds one step):
//! * R0: the slot; the object table (id -> material) is read at the same edge (block RAM, read enable
//!   `adv`);
//! * R1: + material index; the material table (ambient, gloss) is read;
//! * R2: the ambient processor: `I = Ka Ia << 14` (§5.2.2: "the ambient term enters first");
//! * per light, one light-source processor (the paper's diffuse and specular processor of that light,
//!   sharing one pipeline because the specular term exists only where N.L > 0):
//!   - A: `nl = clamp(round(N.L))`, `x = nl > 0 ? clamp(round(N.H)) : 0` (Q1.14, N not normalised);
//!   - P1..P4: `x = round(x^2)` while k <= log2 m (gloss up to 16: 4 squarings, §5.2.2 "m a power of
//!     two");
//!   - M: `I += Kd Il nl + Ks Il x` per channel; the light's material constants come from its own
//!     table, read when the entry enters P4;
//! * OUT: `colour = min(255, (I + 2^21) >> 22)`, 0 for an empty slot.
//!
//! Data of a register whose valid bit is 0 is don't-care (the bench compares data only when valid).

use super::format::Slot;
use super::shade::ONE_Q14;
use crate::format::round_shift;
use crate::shade::PhongLights;

/// Largest log2 of the gloss the pipeline has squaring stages for (scenes: gloss 1..=16).
pub const MAX_GLOSS_LOG2: u32 = 4;
/// Registers per light-source processor: A, P1..P4, M.
pub const LIGHT_STAGES: usize = 2 + MAX_GLOSS_LOG2 as usize;
/// Materials the tables hold (8-bit material index).
pub const MAX_MATERIALS: usize = 256;

/// Configuration targets of the `cfg` write port.
pub const CFG_OBJECT: u8 = 0;
pub const CFG_MATERIAL: u8 = 1;
pub const CFG_LIGHT_VEC: u8 = 2;
pub const CFG_LIGHT_MAT: u8 = 3;

/// One write of the host's configuration port.
/// * `CFG_OBJECT`: object table, `addr` = object id, `data[7:0]` = material index;
/// * `CFG_MATERIAL`: `addr` = material, `data` = ambient r, g, b (16 bits each, 8 fraction bits of
///   colour x 255) and log2 gloss at bit 48 (3 bits);
/// * `CFG_LIGHT_VEC`: `addr` = light, `data` = Lx, Ly, Lz, Hx, Hy, Hz (Q1.14, 16 bits each);
/// * `CFG_LIGHT_MAT`: `addr` = light << 8 | material, `data` = Kd r, g, b, Ks r, g, b (16 bits each).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct CfgWrite {
    pub sel: u8,
    pub addr: u16,
    pub data: u128,
}

/// A shaded time slot: the slot without depth and normal, with the entry's colour.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ShadedSlot {
    pub x: u16,
    pub y: u16,
    pub last: bool,
    pub has_entry: bool,
    pub id: u16,
    pub full: bool,
    pub dist: [i16; 3],
    pub rgb: [u8; 3],
}

/// The configuration writes that load `lights` and the object -> material table.
pub fn shade_config(lights: &PhongLights, material: &[u16], n_lights: usize, obj_addr_bits: u32) -> Result<Vec<CfgWrite>, String> {
    if lights.l.len() != n_lights {
        return Err(format!("the scene has {} lights, the shading stage has {n_lights} light-source processors", lights.l.len()));
    }
    if material.len() > 1usize << obj_addr_bits {
        return Err(format!("{} objects do not fit the shading stage's object table of {} entries", material.len(), 1u64 << obj_addr_bits));
    }
    if lights.materials.len() > MAX_MATERIALS {
        return Err(format!("{} materials: the shading stage holds at most {MAX_MATERIALS}", lights.materials.len()));
    }
    let u16_of = |v: i64, what: &str| -> Result<u128, String> {
        if (0..=0xffff).contains(&v) {
            Ok(v as u128)
        } else {
            Err(format!("{what} {v} does not fit the shading stage's 16-bit constants"))
        }
    };
    let mut w = Vec::new();
    for (id, &m) in material.iter().enumerate() {
        w.push(CfgWrite { sel: CFG_OBJECT, addr: id as u16, data: m as u128 });
    }
    for (mi, m) in lights.materials.iter().enumerate() {
        if m.gloss_log2 > MAX_GLOSS_LOG2 {
            return Err(format!("material {mi}: gloss 2^{} is above the stage's 2^{MAX_GLOSS_LOG2}", m.gloss_log2));
        }
        let mut d = (m.gloss_log2 as u128) << 48;
        for k in 0..3 {
            d |= u16_of(m.ambient[k], "ambient term")? << (16 * k);
        }
        w.push(CfgWrite { sel: CFG_MATERIAL, addr: mi as u16, data: d });
        for li in 0..n_lights {
            let mut d = 0u128;
            for k in 0..3 {
                d |= u16_of(m.diffuse[li][k], "diffuse term")? << (16 * k);
                d |= u16_of(m.specular[li][k], "specular term")? << (16 * (k + 3));
            }
            w.push(CfgWrite { sel: CFG_LIGHT_MAT, addr: ((li as u16) << 8) | mi as u16, data: d });
        }
    }
    for li in 0..n_lights {
        let mut d = 0u128;
        for k in 0..3 {
            d |= (lights.l[li][k] as u16 as u128) << (16 * k);
            d |= (lights.h[li][k] as u16 as u128) << (16 * (k + 3));
        }
        w.push(CfgWrite { sel: CFG_LIGHT_VEC, addr: li as u16, data: d });
    }
    Ok(w)
}

/// What one pipeline register holds.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Work {
    pub valid: bool,
    pub slot: Slot,
    pub mat: u8,
    pub gloss: u8,
    /// N.L clamped (Q1.14), and the specular base / power.
    pub nl: i64,
    pub x: i64,
    /// Intensity sums, 22 fraction bits.
    pub acc: [i64; 3],
}

#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct LightRegs {
    pub l: [i16; 3],
    pub h: [i16; 3],
}

/// Inputs of the shading stage in one cycle.
#[derive(Copy, Clone, Debug, Default)]
pub struct ShadeIn {
    pub up_valid: bool,
    pub up_data: Slot,
    pub down_ready: bool,
    pub cfg: Option<CfgWrite>,
}

/// Outputs of the shading stage in one cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct ShadeOut {
    pub up_ready: bool,
    pub down_valid: bool,
    pub down_data: ShadedSlot,
}

/// The shading stage, register by register.
#[derive(Clone, Debug)]
pub struct ShadeModel {
    pub obj_addr_bits: u32,
    // Tables and light registers.
    pub obj_table: Vec<u8>,
    pub mat_table: Vec<u64>,
    pub light_regs: Vec<LightRegs>,
    pub light_mat: Vec<Vec<[u16; 6]>>,
    // Block-RAM output registers.
    pub obj_q: u8,
    pub mat_q: u64,
    pub light_q: Vec<[u16; 6]>,
    // Pipeline registers.
    pub r0: Work,
    pub r1: Work,
    pub r2: Work,
    /// Per light: A, P1..P4, M.
    pub lights: Vec<[Work; LIGHT_STAGES]>,
    pub out_valid: bool,
    pub out: ShadedSlot,
}

/// Clamped, rounded dot product of a (not unit) normal with a Q1.14 vector: Q1.14 in [0, 1].
pub fn dot_stage(n: [i16; 3], b: [i16; 3]) -> i64 {
    let s: i64 = (0..3).map(|k| n[k] as i64 * b[k] as i64).sum();
    round_shift(s as i128, 14).clamp(0, ONE_Q14 as i128) as i64
}

/// One squaring stage.
pub fn square_stage(x: i64) -> i64 {
    round_shift((x * x) as i128, 14) as i64
}

/// The output stage's colour from the intensity sum.
pub fn colour_of(acc: i64) -> u8 {
    round_shift(acc as i128, 22).clamp(0, 255) as u8
}

impl ShadeModel {
    /// A stage with `n_lights` light-source processors and an object table of 2^`obj_addr_bits` entries.
    pub fn new(n_lights: usize, obj_addr_bits: u32) -> Result<ShadeModel, String> {
        check_shade_params(n_lights, obj_addr_bits)?;
        Ok(ShadeModel {
            obj_addr_bits,
            obj_table: vec![0; 1 << obj_addr_bits],
            mat_table: vec![0; MAX_MATERIALS],
            light_regs: vec![LightRegs::default(); n_lights],
            light_mat: vec![vec![[0; 6]; MAX_MATERIALS]; n_lights],
            obj_q: 0,
            mat_q: 0,
            light_q: vec![[0; 6]; n_lights],
            r0: Work::default(),
            r1: Work::default(),
            r2: Work::default(),
            lights: vec![[Work::default(); LIGHT_STAGES]; n_lights],
            out_valid: false,
            out: ShadedSlot::default(),
        })
    }

    /// Registers from input to output (the latency in cycles of an entry through an empty stage).
    pub fn depth(&self) -> usize {
        4 + LIGHT_STAGES * self.lights.len()
    }

    pub fn outputs(&self, down_ready: bool) -> ShadeOut {
        ShadeOut { up_ready: !self.out_valid || down_ready, down_valid: self.out_valid, down_data: self.out }
    }

    /// Whether any register holds an entry.
    pub fn busy(&self) -> bool {
        self.r0.valid || self.r1.valid || self.r2.valid || self.out_valid || self.lights.iter().any(|l| l.iter().any(|w| w.valid))
    }

    /// One clock; returns the outputs before the edge.
    pub fn step(&mut self, inp: &ShadeIn) -> Result<ShadeOut, String> {
        let out = self.outputs(inp.down_ready);
        if out.up_ready {
            self.advance(inp);
        }
        if let Some(c) = inp.cfg {
            self.write(&c)?;
        }
        Ok(out)
    }

    fn advance(&mut self, inp: &ShadeIn) {
        let mask = (1usize << self.obj_addr_bits) - 1;
        // The output register.
        let last = if self.lights.is_empty() { self.r2 } else { self.lights[self.lights.len() - 1][LIGHT_STAGES - 1] };
        self.out_valid = last.valid;
        let s = &last.slot;
        let e = &s.entry;
        self.out = ShadedSlot {
            x: s.x,
            y: s.y,
            last: s.last,
            has_entry: s.has_entry,
            id: e.id,
            full: e.full,
            dist: e.dist,
            rgb: if s.has_entry { last.acc.map(colour_of) } else { [0; 3] },
        };
        // Light-source processors, from the last back (each reads its predecessor's old value).
        for li in (0..self.lights.len()).rev() {
            let prev = if li == 0 { self.r2 } else { self.lights[li - 1][LIGHT_STAGES - 1] };
            let st = &mut self.lights[li];
            // M: multiply-add with the constants read when the entry entered P4.
            let mut m = st[LIGHT_STAGES - 2];
            let q = self.light_q[li];
            for k in 0..3 {
                m.acc[k] += q[k] as i64 * m.nl + q[k + 3] as i64 * m.x;
            }
            st[LIGHT_STAGES - 1] = m;
            self.light_q[li] = self.light_mat[li][st[LIGHT_STAGES - 3].mat as usize];
            // P4..P1: squarings.
            for k in (1..=MAX_GLOSS_LOG2 as usize).rev() {
                let mut w = st[k - 1];
                if k as u8 <= w.gloss {
                    w.x = square_stage(w.x);
                }
                st[k] = w;
            }
            // A: the dot products.
            let mut a = prev;
            let n = a.slot.entry.normal;
            let lr = self.light_regs[li];
            a.nl = dot_stage(n, lr.l);
            a.x = if a.nl > 0 { dot_stage(n, lr.h) } else { 0 };
            st[0] = a;
        }
        // R2: the ambient processor, with the material table's output.
        let mut r2 = self.r1;
        for k in 0..3 {
            r2.acc[k] = (((self.mat_q >> (16 * k)) & 0xffff) as i64) << 14;
        }
        r2.gloss = ((self.mat_q >> 48) & 7) as u8;
        self.r2 = r2;
        // R1: the material index from the object table; read the material table.
        let mut r1 = self.r0;
        r1.mat = self.obj_q;
        self.r1 = r1;
        self.mat_q = self.mat_table[self.obj_q as usize];
        // R0: the incoming slot; read the object table.
        self.r0 = Work { valid: inp.up_valid, slot: inp.up_data, ..Default::default() };
        self.obj_q = self.obj_table[inp.up_data.entry.id as usize & mask];
    }

    fn write(&mut self, c: &CfgWrite) -> Result<(), String> {
        let h16 = |k: usize| ((c.data >> (16 * k)) & 0xffff) as u16;
        match c.sel {
            CFG_OBJECT => {
                let mask = (1usize << self.obj_addr_bits) - 1;
                self.obj_table[c.addr as usize & mask] = (c.data & 0xff) as u8;
            }
            CFG_MATERIAL => self.mat_table[(c.addr & 0xff) as usize] = (c.data & ((1 << 51) - 1)) as u64,
            CFG_LIGHT_VEC => {
                let li = c.addr as usize;
                if li < self.light_regs.len() {
                    self.light_regs[li] = LightRegs { l: [0, 1, 2].map(|k| h16(k) as i16), h: [3, 4, 5].map(|k| h16(k) as i16) };
                }
            }
            CFG_LIGHT_MAT => {
                let li = (c.addr >> 8) as usize;
                if li < self.light_mat.len() {
                    self.light_mat[li][(c.addr & 0xff) as usize] = [0, 1, 2, 3, 4, 5].map(h16);
                }
            }
            s => return Err(format!("cfg_sel {s} is not a shading-stage table (0..=3)")),
        }
        Ok(())
    }
}

/// The constructor parameters both the model and the RTL accept.
pub fn check_shade_params(n_lights: usize, obj_addr_bits: u32) -> Result<(), String> {
    if !(1..=8).contains(&n_lights) {
        return Err(format!("{n_lights} light-source processors: the shading stage supports 1..=8"));
    }
    if !(1..=16).contains(&obj_addr_bits) {
        return Err(format!("object table of 2^{obj_addr_bits} entries: the id is 16 bits, use 1..=16 address bits"));
    }
    Ok(())
}

/// Shade a stream of slots through the model with no gaps (for tests and the golden side of the RTL
/// backend): returns the shaded slots in order.
pub fn shade_slots(model: &mut ShadeModel, cfg: &[CfgWrite], slots: &[Slot]) -> Result<Vec<ShadedSlot>, String> {
    for c in cfg {
        model.step(&ShadeIn { cfg: Some(*c), down_ready: true, ..Default::default() })?;
    }
    let mut out = Vec::with_capacity(slots.len());
    let mut i = 0;
    let mut idle = 0;
    while out.len() < slots.len() {
        let inp = ShadeIn { up_valid: i < slots.len(), up_data: slots.get(i).copied().unwrap_or_default(), down_ready: true, cfg: None };
        let o = model.step(&inp)?;
        if inp.up_valid && o.up_ready {
            i += 1;
        }
        if o.down_valid {
            out.push(o.down_data);
            idle = 0;
        } else {
            idle += 1;
            if idle > 1000 {
                return Err("the shading model produced no output for 1000 cycles".into());
            }
        }
    }
    Ok(out)
}

/// The time slots of a frame's object lists, raster order: one per entry, one for an empty list.
pub fn slots_of_lists(width: u32, lists: &[Vec<super::format::Entry>]) -> Vec<Slot> {
    let mut v = Vec::new();
    for (p, l) in lists.iter().enumerate() {
        let (x, y) = ((p as u32 % width) as u16, (p as u32 / width) as u16);
        if l.is_empty() {
            v.push(Slot::empty(x, y));
        }
        for (k, e) in l.iter().enumerate() {
            v.push(Slot { x, y, last: k + 1 == l.len(), has_entry: true, entry: *e });
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proof::render::object_lists;
    use crate::proof::setup::scene_setup;
    use crate::proof::shade::shade_entry;
    use crate::render::RenderOptions;
    use crate::scene::builtin;

    /// The options the PROOF tests use (Gouraud normals, back-face culling).
    pub fn test_options(mesh: &crate::scene::Mesh, w: u32, h: u32) -> RenderOptions {
        use crate::raster::{CullMode, FrontFace};
        RenderOptions {
            screen: crate::format::Screen::new(w, h).unwrap(),
            camera: crate::host::Camera::framing(mesh, [0.3, 0.45, 1.0], 40.0),
            shading: crate::shade::Shading::Gouraud,
            cull: CullMode::Back,
            front: if mesh.front_face == crate::scene::Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw },
            lighting: crate::host::Lighting::default(),
            index_bits: 16,
            rc_type: crate::raster::RcType::IV,
            texturing: None,
            background: [24, 24, 40],
        }
    }

    #[test]
    fn the_staged_shading_model_equals_the_algorithmic_shading_on_real_lists() {
        for (mesh, w, h) in [(builtin::polyhedron(), 64, 40), (builtin::teapot(2), 48, 30)] {
            let opts = test_options(&mesh, w, h);
            let sc = scene_setup(&mesh, &opts).unwrap();
            let lists = object_lists(sc.screen, &sc.objects);
            let slots = slots_of_lists(w, &lists);
            let mut m = ShadeModel::new(sc.lights.l.len(), 12).unwrap();
            let cfg = shade_config(&sc.lights, &sc.material, sc.lights.l.len(), 12).unwrap();
            let out = shade_slots(&mut m, &cfg, &slots).unwrap();
            let mut entries = 0;
            for (s, o) in slots.iter().zip(&out) {
                assert_eq!((o.x, o.y, o.last, o.has_entry, o.id, o.dist), (s.x, s.y, s.last, s.has_entry, s.entry.id, s.entry.dist));
                if s.has_entry {
                    entries += 1;
                    let want = shade_entry(&sc.lights, s.entry.normal, sc.material[s.entry.id as usize]);
                    assert_eq!(o.rgb, want, "{} pixel ({}, {}) id {}", mesh.name, s.x, s.y, s.entry.id);
                }
            }
            assert!(entries > 100, "{}: only {entries} entries", mesh.name);
        }
    }
}
