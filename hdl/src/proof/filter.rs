//! PROOF's filter stage (seed 002 §6), 1x1 box: per list entry the 8x8 subpixel mask from its edge
//! distances and its weight in each subpixel ([`FilterFront`], F0..F4: the tree of multiples of
//! sin a and cos a, then front-to-back blending per subpixel, nearest entry first), and per pixel the
//! colours combined with those weights, the background taking the transmittance left. Opaque entries
//! take whole subpixels (the seed's filter); transparent ones a share of each (issue 22). One list
//! entry per clock in, one pixel per list out. Cycle behaviour:
//! `golden::proof::cycle_filter::FilterModel`, which the bench compares every cycle.
//!
//! ```text
//!            cfg_write cfg_sel cfg_addr cfg_data  (0: direction table, id -> cos/sin of 3 edges;
//!              │                                   1: background; 2: opacity table, id -> Q1.4)
//!            +─┴────────────────────────────────────────────────────────────────────────────+
//! upstream ─▶| F0 ─▶ edge masks x3 (F1 base, F2 rows, F3 mask) ─▶ F4 w_i per  ─▶ F5 W = Σ w_i  |─▶ downstream
//!  .data     | dir,           tree of multiples                  subpixel      covered        |   .data (FilteredPixel)
//! (ShadedSlot)| alpha tables                                                                  |   .valid
//!  .valid    |  ─▶ F6 sums += W c, Σ W ─▶ OUT (last slot): (sum + (16384 - Σ W) bg + 2^13) >> 14 |
//!  .ready  ◀─|  ready = adv = !out_valid | downstream.ready (global stall)                    |◀─ .ready
//!            +──────────────────────────────────────────────────────────────────────────────+
//! ```
//! Latency from a pixel's last slot to its pixel: 8 clocks. The tables are block RAMs read with
//! enable `adv` at the edge where F0 loads, so a stalled F0 keeps its words (as in the shading stage).
//! The pixel states (`taken` and the cells' `spent` at F4, `sum` and `wsum` at F6) change only when a
//! valid slot passes, and return to 0 after a pixel's last slot. Weights are in 1/256 of a subpixel:
//! a pixel's weights and the background's sum to 16384.
//!
//! The paper's 2x2 filter area (`golden::proof::filter::box2`) is the other top,
//! [`super::filter2x2::Filter2x2Stage`]: the same front end, quadrant sums and line buffers.

use super::filter_front::FilterFront;
use super::popcount::Popcount64;
use super::types::{FilterTag, FilteredPixel, ShadedSlot};
use crate::common::{MulU, StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FilterStage {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Write `cfg_data` to target `cfg_sel` at `cfg_addr` at this edge (layouts:
    /// `golden::proof::cycle_filter::filter_config`).
    pub cfg_write: Signal<In, Bit>,
    pub cfg_sel: Signal<In, Bits<4>>,
    pub cfg_addr: Signal<In, Bits<16>>,
    pub cfg_data: Signal<In, Bits<96>>,
    // From the shading stage
    /// The shaded list entries, one slot per entry (one empty slot for an empty list).
    pub upstream: StreamIn<ShadedSlot>,
    // To the frame buffer
    /// One anti-aliased pixel per list, raster order.
    pub downstream: StreamOut<FilteredPixel>,

    // Registers, tables and sub-blocks (pub: the bench compares them with the model).
    pub front: FilterFront,
    pub background: DFF<Bits<24>>,
    pub pc_union: Popcount64,
    pub f5: DFF<FilterTag>,
    pub f5_w: DFF<Bits<15>>,
    pub f5_covered: DFF<Bits<7>>,
    pub sum_r: DFF<Bits<24>>,
    pub sum_g: DFF<Bits<24>>,
    pub sum_b: DFF<Bits<24>>,
    pub wsum: DFF<Bits<15>>,
    pub f6: DFF<FilterTag>,
    pub f6_r: DFF<Bits<24>>,
    pub f6_g: DFF<Bits<24>>,
    pub f6_b: DFF<Bits<24>>,
    pub f6_w: DFF<Bits<15>>,
    pub f6_covered: DFF<Bits<7>>,
    pub out_valid: DFF<Bit>,
    pub out_data: DFF<FilteredPixel>,
    // Weights times colours.
    wc_r: MulU<15, 8, 23>,
    wc_g: MulU<15, 8, 23>,
    wc_b: MulU<15, 8, 23>,
    bg_r: MulU<15, 8, 23>,
    bg_g: MulU<15, 8, 23>,
    bg_b: MulU<15, 8, 23>,

    adv: Signal<Local, Bit>,
    acc_r: Signal<Local, Bits<24>>,
    acc_g: Signal<Local, Bits<24>>,
    acc_b: Signal<Local, Bits<24>>,
    wacc: Signal<Local, Bits<15>>,
    wbg: Signal<Local, Bits<15>>,
    t_r: Signal<Local, Bits<24>>,
    t_g: Signal<Local, Bits<24>>,
    t_b: Signal<Local, Bits<24>>,
    c_r: Signal<Local, Bits<24>>,
    c_g: Signal<Local, Bits<24>>,
    c_b: Signal<Local, Bits<24>>,
    zero24: Constant<Bits<24>>,
    zero15: Constant<Bits<15>>,
    whole: Constant<Bits<15>>,
    half24: Constant<Bits<24>>,
    sel_dirs: Constant<Bits<4>>,
    sel_bg: Constant<Bits<4>>,
    sel_alpha: Constant<Bits<4>>,
}

impl FilterStage {
    /// A filter stage with a direction table of 2^`obj_addr_bits` entries (1..=16).
    pub fn new(obj_addr_bits: usize) -> Result<FilterStage, String> {
        Ok(FilterStage {
            clock: Default::default(),
            cfg_write: Default::default(),
            cfg_sel: Default::default(),
            cfg_addr: Default::default(),
            cfg_data: Default::default(),
            upstream: Default::default(),
            downstream: Default::default(),
            front: FilterFront::new(obj_addr_bits)?,
            background: Default::default(),
            pc_union: Default::default(),
            f5: Default::default(),
            f5_w: Default::default(),
            f5_covered: Default::default(),
            sum_r: Default::default(),
            sum_g: Default::default(),
            sum_b: Default::default(),
            wsum: Default::default(),
            f6: Default::default(),
            f6_r: Default::default(),
            f6_g: Default::default(),
            f6_b: Default::default(),
            f6_w: Default::default(),
            f6_covered: Default::default(),
            out_valid: Default::default(),
            out_data: Default::default(),
            wc_r: Default::default(),
            wc_g: Default::default(),
            wc_b: Default::default(),
            bg_r: Default::default(),
            bg_g: Default::default(),
            bg_b: Default::default(),
            adv: Default::default(),
            acc_r: Default::default(),
            acc_g: Default::default(),
            acc_b: Default::default(),
            wacc: Default::default(),
            wbg: Default::default(),
            t_r: Default::default(),
            t_g: Default::default(),
            t_b: Default::default(),
            c_r: Default::default(),
            c_g: Default::default(),
            c_b: Default::default(),
            zero24: Constant::new(0u64.into()),
            zero15: Constant::new(0u64.into()),
            whole: Constant::new(16384u64.into()),
            half24: Constant::new(8192u64.into()),
            sel_dirs: Constant::new(0u64.into()),
            sel_bg: Constant::new(1u64.into()),
            sel_alpha: Constant::new(2u64.into()),
        })
    }
}

impl Logic for FilterStage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, background, f5, f5_w, f5_covered, sum_r, sum_g, sum_b, wsum, f6, f6_r, f6_g, f6_b, f6_w, f6_covered, out_valid,
            out_data
        );
        self.front.clock.next = self.clock.val();
        self.adv.next = !self.out_valid.q.val() | self.downstream.ready.val();
        self.upstream.ready.next = self.adv.val();
        self.downstream.valid.next = self.out_valid.q.val();
        self.downstream.data.next = self.out_data.q.val();

        // ---- Host writes: the direction and opacity tables and the background colour.
        self.front.dir_write.next = self.cfg_write.val() & (self.cfg_sel.val() == self.sel_dirs.val());
        self.front.cfg_addr.next = self.cfg_addr.val();
        self.front.dir_data.next = self.cfg_data.val();
        self.front.alpha_write.next = self.cfg_write.val() & (self.cfg_sel.val() == self.sel_alpha.val());
        self.front.alpha_data.next = self.cfg_data.val().get_bits::<5>(0);
        if self.cfg_write.val() & (self.cfg_sel.val() == self.sel_bg.val()) {
            self.background.d.next = self.cfg_data.val().get_bits::<24>(0);
        }

        // ---- F0..F4: masks and ownership.
        self.front.adv.next = self.adv.val();
        self.front.slot.next = self.upstream.data.val();
        self.front.slot_valid.next = self.upstream.valid.val();

        // ---- F5: the entry's weight (the front's sum tree) and the coverage.
        self.pc_union.x.next = self.front.union_mask.val();

        // ---- F6: sums += W c, wsum += W.
        self.wc_r.a.next = self.f5_w.q.val();
        self.wc_g.a.next = self.f5_w.q.val();
        self.wc_b.a.next = self.f5_w.q.val();
        self.wc_r.b.next = self.f5.q.val().r;
        self.wc_g.b.next = self.f5.q.val().g;
        self.wc_b.b.next = self.f5.q.val().b;
        self.acc_r.next = self.sum_r.q.val() + bit_cast::<24, 23>(self.wc_r.p.val());
        self.acc_g.next = self.sum_g.q.val() + bit_cast::<24, 23>(self.wc_g.p.val());
        self.acc_b.next = self.sum_b.q.val() + bit_cast::<24, 23>(self.wc_b.p.val());
        self.wacc.next = self.wsum.q.val() + self.f5_w.q.val();

        // ---- OUT: the background takes the transmittance left; round and divide by 16384.
        self.wbg.next = self.whole.val() - self.f6_w.q.val();
        self.bg_r.a.next = self.wbg.val();
        self.bg_g.a.next = self.wbg.val();
        self.bg_b.a.next = self.wbg.val();
        self.bg_r.b.next = self.background.q.val().get_bits::<8>(0);
        self.bg_g.b.next = self.background.q.val().get_bits::<8>(8);
        self.bg_b.b.next = self.background.q.val().get_bits::<8>(16);
        self.t_r.next = self.f6_r.q.val() + bit_cast::<24, 23>(self.bg_r.p.val());
        self.t_g.next = self.f6_g.q.val() + bit_cast::<24, 23>(self.bg_g.p.val());
        self.t_b.next = self.f6_b.q.val() + bit_cast::<24, 23>(self.bg_b.p.val());
        self.c_r.next = self.t_r.val() + self.half24.val();
        self.c_g.next = self.t_g.val() + self.half24.val();
        self.c_b.next = self.t_b.val() + self.half24.val();

        if self.adv.val() {
            self.f5.d.next = self.front.tag.val();
            self.f5_w.d.next = self.front.weight.val();
            self.f5_covered.d.next = self.pc_union.count.val();
            self.f6.d.next = self.f5.q.val();
            self.f6_r.d.next = self.acc_r.val();
            self.f6_g.d.next = self.acc_g.val();
            self.f6_b.d.next = self.acc_b.val();
            self.f6_w.d.next = self.wacc.val();
            self.f6_covered.d.next = self.f5_covered.q.val();
            if self.f5.q.val().valid {
                self.sum_r.d.next = self.acc_r.val();
                self.sum_g.d.next = self.acc_g.val();
                self.sum_b.d.next = self.acc_b.val();
                self.wsum.d.next = self.wacc.val();
                if self.f5.q.val().last {
                    self.sum_r.d.next = self.zero24.val();
                    self.sum_g.d.next = self.zero24.val();
                    self.sum_b.d.next = self.zero24.val();
                    self.wsum.d.next = self.zero15.val();
                }
            }
            self.out_valid.d.next = self.f6.q.val().valid & self.f6.q.val().last;
            self.out_data.d.next.x = self.f6.q.val().x;
            self.out_data.d.next.y = self.f6.q.val().y;
            self.out_data.d.next.r = self.c_r.val().get_bits::<8>(14);
            self.out_data.d.next.g = self.c_g.val().get_bits::<8>(14);
            self.out_data.d.next.b = self.c_b.val().get_bits::<8>(14);
            self.out_data.d.next.covered = self.f6_covered.q.val();
        }
    }
}

/// The Verilog of a filter stage with a direction table of 2^`obj_addr_bits` entries, top module
/// named `name`.
pub fn verilog_filter(name: &str, obj_addr_bits: usize) -> Result<String, String> {
    let mut uut = FilterStage::new(obj_addr_bits)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(super::rename_top(&generate_verilog(&uut), name))
}
