//! PROOF's shading stage (seed 002 §5, Fig. 3): colours every list entry leaving the object-processor
//! pipeline with a pipeline of light-source processors: the ambient term enters first, then per light
//! the diffuse and specular terms `I(i+1) = M (N.B)^m + I(i)` with m a power of two. One entry per
//! clock, so one pipeline keeps the OPP's rate (no parallel pipelines needed). Cycle behaviour:
//! `golden::proof::cycle_shade::ShadeModel`, which the bench compares every cycle.
//!
//! ```text
//!         cfg_write cfg_sel cfg_addr cfg_data
//!              │ (0: object table, 1: material table, 2: light L/H, 3: light material table)
//!            +─┴─────────────────────────────────────────────────────────────────+
//! upstream ─▶| R0 ─▶ R1 ─▶ R2 (ambient) ─▶ light 0 ─▶ ... ─▶ light L-1 ─▶ OUT     |─▶ downstream
//!  .data     | obj    mat                 (A, P1..P4, M: 6 registers each)         |   .data (ShadedSlot)
//!  .valid    | table  table                                                         |   .valid
//!  .ready  ◀─|  ready = adv = !out_valid | downstream.ready (global stall)          |◀─ .ready
//!            +-------------------------------------------------------------------+
//! ```
//! Latency through an empty stage: 4 + 6 L registers. The tables are block RAMs read with enable
//! `adv`, so a stalled pipeline keeps each register's table word.

use super::light_processor::LightProcessor;
use super::table_ram::TableRam;
use super::types::{ProofSlot, ShadeWork, ShadedSlot};
use crate::common::{StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ShadingStage {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Write `cfg_data` to table `cfg_sel` at `cfg_addr` at this edge (layouts: `golden::proof::cycle_shade::CfgWrite`).
    pub cfg_write: Signal<In, Bit>,
    pub cfg_sel: Signal<In, Bits<4>>,
    pub cfg_addr: Signal<In, Bits<16>>,
    pub cfg_data: Signal<In, Bits<96>>,
    // From the object-processor pipeline
    /// The object lists, one slot per entry.
    pub upstream: StreamIn<ProofSlot>,
    // To the filter
    /// The same slots with each entry's colour.
    pub downstream: StreamOut<ShadedSlot>,

    // Registers and tables (pub: the bench compares them with the model).
    pub obj_table: TableRam<Bits<8>>,
    pub mat_table: TableRam<Bits<51>>,
    pub r0: DFF<ShadeWork>,
    pub r1: DFF<ShadeWork>,
    pub r2: DFF<ShadeWork>,
    pub lights: Vec<LightProcessor>,
    pub out_valid: DFF<Bit>,
    pub out_data: DFF<ShadedSlot>,

    adv: Signal<Local, Bit>,
    fin: Signal<Local, ShadeWork>,
    w_in: Signal<Local, ShadeWork>,
    amb_r: Signal<Local, Bits<40>>,
    amb_g: Signal<Local, Bits<40>>,
    amb_b: Signal<Local, Bits<40>>,
    c_r: Signal<Local, Bits<40>>,
    c_g: Signal<Local, Bits<40>>,
    c_b: Signal<Local, Bits<40>>,
    round40: Constant<Bits<40>>,
    max18: Constant<Bits<18>>,
    ff8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
    sel_obj: Constant<Bits<4>>,
    sel_mat: Constant<Bits<4>>,
    sel_vec: Constant<Bits<4>>,
    sel_lmat: Constant<Bits<4>>,
    light_ids: Vec<Constant<Bits<16>>>,
    light_ids8: Vec<Constant<Bits<8>>>,
    _last: usize,
}

impl ShadingStage {
    /// A shading stage with `n_lights` light-source processors (1..=8) and an object table of
    /// 2^`obj_addr_bits` entries (1..=16).
    pub fn new(n_lights: usize, obj_addr_bits: usize) -> Result<ShadingStage, String> {
        if !(1..=8).contains(&n_lights) {
            return Err(format!("{n_lights} light-source processors: the shading stage supports 1..=8"));
        }
        Ok(ShadingStage {
            clock: Default::default(),
            cfg_write: Default::default(),
            cfg_sel: Default::default(),
            cfg_addr: Default::default(),
            cfg_data: Default::default(),
            upstream: Default::default(),
            downstream: Default::default(),
            obj_table: TableRam::new(obj_addr_bits)?,
            mat_table: TableRam::new(8)?,
            r0: Default::default(),
            r1: Default::default(),
            r2: Default::default(),
            lights: (0..n_lights).map(|_| LightProcessor::new()).collect(),
            out_valid: Default::default(),
            out_data: Default::default(),
            adv: Default::default(),
            fin: Default::default(),
            w_in: Default::default(),
            amb_r: Default::default(),
            amb_g: Default::default(),
            amb_b: Default::default(),
            c_r: Default::default(),
            c_g: Default::default(),
            c_b: Default::default(),
            round40: Constant::new((1u64 << 21).into()),
            max18: Constant::new(255.into()),
            ff8: Constant::new(255.into()),
            zero8: Constant::new(0.into()),
            sel_obj: Constant::new(0.into()),
            sel_mat: Constant::new(1.into()),
            sel_vec: Constant::new(2.into()),
            sel_lmat: Constant::new(3.into()),
            light_ids: (0..n_lights).map(|i| Constant::new((i as u64).into())).collect(),
            light_ids8: (0..n_lights).map(|i| Constant::new((i as u64).into())).collect(),
            _last: n_lights - 1,
        })
    }
}

impl Logic for ShadingStage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r0, r1, r2, out_valid, out_data);
        self.obj_table.clock.next = self.clock.val();
        self.mat_table.clock.next = self.clock.val();
        self.adv.next = !self.out_valid.q.val() | self.downstream.ready.val();
        self.upstream.ready.next = self.adv.val();
        self.downstream.valid.next = self.out_valid.q.val();
        self.downstream.data.next = self.out_data.q.val();

        // ---- Host writes.
        self.obj_table.write_enable.next = self.cfg_write.val() & (self.cfg_sel.val() == self.sel_obj.val());
        self.obj_table.write_address.next = self.cfg_addr.val();
        self.obj_table.write_data.next = self.cfg_data.val().get_bits::<8>(0);
        self.mat_table.write_enable.next = self.cfg_write.val() & (self.cfg_sel.val() == self.sel_mat.val());
        self.mat_table.write_address.next = bit_cast::<16, 8>(self.cfg_addr.val().get_bits::<8>(0));
        self.mat_table.write_data.next = self.cfg_data.val().get_bits::<51>(0);
        for i in 0..self.lights.len() {
            self.lights[i].clock.next = self.clock.val();
            self.lights[i].adv.next = self.adv.val();
            self.lights[i].vec_write.next =
                self.cfg_write.val() & (self.cfg_sel.val() == self.sel_vec.val()) & (self.cfg_addr.val() == self.light_ids[i].val());
            self.lights[i].mat_write.next = self.cfg_write.val()
                & (self.cfg_sel.val() == self.sel_lmat.val())
                & (self.cfg_addr.val().get_bits::<8>(8) == self.light_ids8[i].val());
            self.lights[i].cfg_addr.next = self.cfg_addr.val().get_bits::<8>(0);
            self.lights[i].cfg_data.next = self.cfg_data.val();
        }

        // ---- R0, R1: the slot, then its material index; the tables are read with enable adv.
        self.w_in.next = self.r0.q.val();
        self.w_in.next.valid = self.upstream.valid.val();
        self.w_in.next.x = self.upstream.data.val().x;
        self.w_in.next.y = self.upstream.data.val().y;
        self.w_in.next.last = self.upstream.data.val().last;
        self.w_in.next.has_entry = self.upstream.data.val().has_entry;
        self.w_in.next.id = self.upstream.data.val().id;
        self.w_in.next.full = self.upstream.data.val().full;
        self.w_in.next.d0 = self.upstream.data.val().d0;
        self.w_in.next.d1 = self.upstream.data.val().d1;
        self.w_in.next.d2 = self.upstream.data.val().d2;
        self.w_in.next.nx = self.upstream.data.val().nx;
        self.w_in.next.ny = self.upstream.data.val().ny;
        self.w_in.next.nz = self.upstream.data.val().nz;
        self.obj_table.read_address.next = self.upstream.data.val().id;
        self.obj_table.read_enable.next = self.adv.val();
        self.mat_table.read_address.next = bit_cast::<16, 8>(self.obj_table.read_data.val());
        self.mat_table.read_enable.next = self.adv.val();
        // ---- R2: the ambient processor, I = Ka Ia << 14.
        self.amb_r.next = bit_cast::<40, 16>(self.mat_table.read_data.val().get_bits::<16>(0));
        self.amb_g.next = bit_cast::<40, 16>(self.mat_table.read_data.val().get_bits::<16>(16));
        self.amb_b.next = bit_cast::<40, 16>(self.mat_table.read_data.val().get_bits::<16>(32));

        // ---- The light-source processors in a chain.
        self.lights[0].prev.next = self.r2.q.val();
        for i in 1..self.lights.len() {
            self.lights[i].prev.next = self.lights[i - 1].work.val();
        }
        self.fin.next = self.r2.q.val();
        for i in self._last..self.lights.len() {
            self.fin.next = self.lights[i].work.val();
        }
        // ---- OUT: colour = min(255, (I + 2^21) >> 22).
        self.c_r.next = self.fin.val().acc_r + self.round40.val();
        self.c_g.next = self.fin.val().acc_g + self.round40.val();
        self.c_b.next = self.fin.val().acc_b + self.round40.val();

        if self.adv.val() {
            self.r0.d.next = self.w_in.val();
            self.r1.d.next = self.r0.q.val();
            self.r1.d.next.mat = self.obj_table.read_data.val();
            self.r2.d.next = self.r1.q.val();
            self.r2.d.next.gloss = self.mat_table.read_data.val().get_bits::<3>(48);
            self.r2.d.next.acc_r = self.amb_r.val() << 14;
            self.r2.d.next.acc_g = self.amb_g.val() << 14;
            self.r2.d.next.acc_b = self.amb_b.val() << 14;
            self.out_valid.d.next = self.fin.val().valid;
            self.out_data.d.next.x = self.fin.val().x;
            self.out_data.d.next.y = self.fin.val().y;
            self.out_data.d.next.last = self.fin.val().last;
            self.out_data.d.next.has_entry = self.fin.val().has_entry;
            self.out_data.d.next.id = self.fin.val().id;
            self.out_data.d.next.full = self.fin.val().full;
            self.out_data.d.next.d0 = self.fin.val().d0;
            self.out_data.d.next.d1 = self.fin.val().d1;
            self.out_data.d.next.d2 = self.fin.val().d2;
            self.out_data.d.next.r = self.c_r.val().get_bits::<8>(22);
            if self.c_r.val().get_bits::<18>(22) > self.max18.val() {
                self.out_data.d.next.r = self.ff8.val();
            }
            self.out_data.d.next.g = self.c_g.val().get_bits::<8>(22);
            if self.c_g.val().get_bits::<18>(22) > self.max18.val() {
                self.out_data.d.next.g = self.ff8.val();
            }
            self.out_data.d.next.b = self.c_b.val().get_bits::<8>(22);
            if self.c_b.val().get_bits::<18>(22) > self.max18.val() {
                self.out_data.d.next.b = self.ff8.val();
            }
            if !self.fin.val().has_entry {
                self.out_data.d.next.r = self.zero8.val();
                self.out_data.d.next.g = self.zero8.val();
                self.out_data.d.next.b = self.zero8.val();
            }
        }
    }
}

/// The Verilog of a shading stage, top module named `name`.
pub fn verilog_shading(name: &str, n_lights: usize, obj_addr_bits: usize) -> Result<String, String> {
    let mut uut = ShadingStage::new(n_lights, obj_addr_bits)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(super::rename_top(&generate_verilog(&uut), name))
}
