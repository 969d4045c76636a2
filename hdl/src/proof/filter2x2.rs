//! PROOF's filter stage (seed 002 §6) with the paper's filter area of 2x2 pixels ("The filter area
//! will be 2 X 2 pixels"): the front end of the 1x1 stage ([`FilterFront`]: 8x8 masks by the tree of
//! multiples, the subpixels each entry owns, nearest first), then per pixel the colour sums of its
//! four quadrants of 4x4 subpixels, then a streaming 2x2 box over the quadrants with a line buffer
//! ([`Box2x2`]). Same ports as the 1x1 top [`super::filter::FilterStage`]; one list entry per clock in,
//! one pixel per list out, raster order. Cycle behaviour:
//! `golden::proof::cycle_filter2x2::Filter2x2Model`, which the bench compares every cycle.
//!
//! ```text
//!          cfg_write cfg_sel cfg_addr cfg_data   (0: direction table, 1: background, 2: opacity table)
//!              │
//!            +─┴──────────────────────────────────────────────────────────────────────+
//! upstream ─▶| F0..F4 (FilterFront) ─▶ Q5 quadrant ─▶ Q6 quadrant sums ─▶ Box2x2        |─▶ downstream
//!  .data     |  masks, visible,        popcounts:     += w_q c (pixel     A, H, line    |   .data (FilteredPixel)
//! (ShadedSlot)|  union                  w_q, c_q       state); word on     buffer, V,    |   .valid
//!  .valid    |                                        a pixel's last slot OUT          |
//!  .ready  ◀─|  ready = adv = !(Q6 holds a last slot) | box.upstream.ready             |◀─ .ready
//!            +────────────────────────────────────────────────────────────────────────+
//! ```
//!
//! * **Q5**: per quadrant q the weight `w_q` (the front's quadrant weight: the entry's blend weights
//!   over the quadrant's 16 subpixels, in 1/256, 0..=4096; 256 per owned subpixel for an opaque
//!   entry) and `c_q` (subpixels of q covered so far, from F4's union mask through a
//!   [`QuadrantPopcount`]).
//! * **Q6**: `acc_qk = sum_qk + w_q c_k` (12 multipliers of 13x8 bits) and `wacc_q = wsum_q + w_q`;
//!   the pixel state `sum`, `wsum` becomes `acc`, `wacc`, or 0 after the pixel's last slot. The Q6
//!   register holds the word `(acc_qk + (256 c_q - wacc_q) bg_k + 128) >> 8` (12 more 13x8
//!   multipliers): the quadrant's blended colour sum with the background's share in its covered
//!   subpixels (their remaining transmittance), rounded to whole units, 12 bits as for opaque lists
//!   (`golden::proof::filter::quadrant_sums_blended`). For an opaque list `wacc_q = 256 c_q` and the
//!   word is exactly the unblended `Σ owned x colour`. When Q6 holds a pixel's last slot, it is the
//!   box's input word: the box adds the background of the uncovered subpixels once per box,
//!   `(256 - covered) bg`, instead of per pixel.
//!
//! Cycle behaviour: the front, Q5 and Q6 load when `adv = !(Q6 valid and last) | box.upstream.ready`
//! (a global stall, `upstream.ready = adv`, combinational as in the 1x1 stage); the box has its own
//! stall from `downstream.ready`. A pixel's quadrant word reaches the box 7 clocks after its last slot
//! entered; the pixel leaves the box 3 clocks after its lower-right neighbour's word entered it (see
//! [`Box2x2`]): the output lags by about one row and one pixel, and after a frame's last pixel the box
//! flushes the last row (W clocks, input held off).
//!
//! **Why a separate top and not a mode port.** The 2x2 area costs a line buffer of W words of 112
//! bits and 24 quadrant multipliers that a 1x1 build does not need, and the line buffer's size fixes
//! the screen width at synthesis; so the area is chosen when the FPGA is built, as the screen size is
//! for the `rc` top: `proof_filter` is the 1x1 stage, `proof_filter2x2` this one for 320x200.

use super::background_share::BackgroundShare;
use super::box2x2::Box2x2;
use super::filter_front::FilterFront;
use super::quadrant_popcount::QuadrantPopcount;
use super::types::{FilterTag, FilteredPixel, ShadedSlot};
use crate::common::{MulU, StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Filter2x2Stage {
    pub clock: Signal<In, Clock>,
    // From the host
    /// Write `cfg_data` to target `cfg_sel` at `cfg_addr` at this edge (layouts:
    /// `golden::proof::cycle_filter::filter_config`).
    pub cfg_write: Signal<In, Bit>,
    pub cfg_sel: Signal<In, Bits<4>>,
    pub cfg_addr: Signal<In, Bits<16>>,
    pub cfg_data: Signal<In, Bits<96>>,
    // From the shading stage
    /// The shaded list entries, one slot per entry (one empty slot for an empty list), a whole frame
    /// in raster order.
    pub upstream: StreamIn<ShadedSlot>,
    // To the frame buffer
    /// One 2x2-filtered pixel per list, raster order.
    pub downstream: StreamOut<FilteredPixel>,

    // Registers and sub-blocks (pub: the bench compares them with the model).
    pub front: FilterFront,
    pub background: DFF<Bits<24>>,
    pub pc_union: QuadrantPopcount,
    pub q5: DFF<FilterTag>,
    /// Per quadrant q: weight (1/256 subpixels) and coverage (Q5).
    pub q5_w: Vec<DFF<Bits<13>>>,
    pub q5_c: Vec<DFF<Bits<5>>>,
    /// Pixel state: per quadrant q and channel k, index 3 q + k, the entries' weight x colour sums
    /// so far (1/256), and per quadrant their weights.
    pub qsum: Vec<DFF<Bits<20>>>,
    pub wsum: Vec<DFF<Bits<13>>>,
    pub q6: DFF<FilterTag>,
    /// Q6: the words including this entry (index 3 q + k) and the coverage per quadrant.
    pub q6_acc: Vec<DFF<Bits<12>>>,
    pub q6_c: Vec<DFF<Bits<5>>>,
    pub box2: Box2x2,
    // Weights times colours, and the background's weights times the background, index 3 q + k.
    wc: Vec<MulU<13, 8, 20>>,
    bgm: Vec<BackgroundShare>,

    adv: Signal<Local, Bit>,
    col: Vec<Signal<Local, Bits<8>>>,
    bgc: Vec<Signal<Local, Bits<8>>>,
    acc: Vec<Signal<Local, Bits<20>>>,
    wacc: Vec<Signal<Local, Bits<13>>>,
    word20: Vec<Signal<Local, Bits<20>>>,
    word_sh: Vec<Signal<Local, Bits<20>>>,
    zero20: Constant<Bits<20>>,
    zero13: Constant<Bits<13>>,
    half20: Constant<Bits<20>>,
    sel_dirs: Constant<Bits<4>>,
    sel_bg: Constant<Bits<4>>,
    sel_alpha: Constant<Bits<4>>,
}

impl Filter2x2Stage {
    /// A 2x2 filter stage with a direction table of 2^`obj_addr_bits` entries (1..=16) for a
    /// `width` x `height` screen (width 2..=1024, height 1..=1024).
    pub fn new(obj_addr_bits: usize, width: u32, height: u32) -> Result<Filter2x2Stage, String> {
        fn regs<T: Synth>(n: usize) -> Vec<DFF<T>> {
            (0..n).map(|_| DFF::default()).collect()
        }
        Ok(Filter2x2Stage {
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
            q5: Default::default(),
            q5_w: regs(4),
            q5_c: regs(4),
            qsum: regs(12),
            wsum: regs(4),
            q6: Default::default(),
            q6_acc: regs(12),
            q6_c: regs(4),
            box2: Box2x2::new(width, height)?,
            wc: (0..12).map(|_| MulU::default()).collect(),
            bgm: (0..12).map(|_| BackgroundShare::default()).collect(),
            adv: Default::default(),
            col: (0..3).map(|_| Signal::default()).collect(),
            bgc: (0..3).map(|_| Signal::default()).collect(),
            acc: (0..12).map(|_| Signal::default()).collect(),
            wacc: (0..4).map(|_| Signal::default()).collect(),
            word20: (0..12).map(|_| Signal::default()).collect(),
            word_sh: (0..12).map(|_| Signal::default()).collect(),
            zero20: Constant::new(0u64.into()),
            zero13: Constant::new(0u64.into()),
            half20: Constant::new(128u64.into()),
            sel_dirs: Constant::new(0u64.into()),
            sel_bg: Constant::new(1u64.into()),
            sel_alpha: Constant::new(2u64.into()),
        })
    }
}

impl Logic for Filter2x2Stage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, background, q5, q6);
        for q in 0..4 {
            self.q5_w[q].clock.next = self.clock.val();
            self.q5_w[q].d.next = self.q5_w[q].q.val();
            self.q5_c[q].clock.next = self.clock.val();
            self.q5_c[q].d.next = self.q5_c[q].q.val();
            self.q6_c[q].clock.next = self.clock.val();
            self.q6_c[q].d.next = self.q6_c[q].q.val();
            self.wsum[q].clock.next = self.clock.val();
            self.wsum[q].d.next = self.wsum[q].q.val();
        }
        for i in 0..12 {
            self.qsum[i].clock.next = self.clock.val();
            self.qsum[i].d.next = self.qsum[i].q.val();
            self.q6_acc[i].clock.next = self.clock.val();
            self.q6_acc[i].d.next = self.q6_acc[i].q.val();
        }
        self.front.clock.next = self.clock.val();
        self.box2.clock.next = self.clock.val();
        // Q6 offers the box a word when it holds a pixel's last slot. Written out twice rather than
        // through a shared Local: with a shared temporary Verilator cannot split this always block,
        // and the box's `valid -> ready` inside its own block then looks like a combinational loop
        // (UNOPTFLAT) although `upstream.ready` does not depend on `upstream.valid`.
        self.adv.next = !(self.q6.q.val().valid & self.q6.q.val().last) | self.box2.upstream.ready.val();
        self.upstream.ready.next = self.adv.val();

        // ---- Host writes: the direction table and the background colour.
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

        // ---- Q5: quadrant weights (1/256 subpixels) and coverage.
        self.pc_union.x.next = self.front.union_mask.val();

        // ---- Q6: quadrant sums += w_q c, weights += w_q; the word adds the background's share in
        // the covered subpixels, (256 c_q - wacc_q) bg, and rounds to whole units.
        self.col[0].next = self.q5.q.val().r;
        self.col[1].next = self.q5.q.val().g;
        self.col[2].next = self.q5.q.val().b;
        self.bgc[0].next = self.background.q.val().get_bits::<8>(0);
        self.bgc[1].next = self.background.q.val().get_bits::<8>(8);
        self.bgc[2].next = self.background.q.val().get_bits::<8>(16);
        for q in 0..4 {
            self.wacc[q].next = self.wsum[q].q.val() + self.q5_w[q].q.val();
            for k in 0..3 {
                self.wc[3 * q + k].a.next = self.q5_w[q].q.val();
                self.wc[3 * q + k].b.next = self.col[k].val();
                self.acc[3 * q + k].next = self.qsum[3 * q + k].q.val() + self.wc[3 * q + k].p.val();
                self.bgm[3 * q + k].cov.next = self.q5_c[q].q.val();
                self.bgm[3 * q + k].wsum.next = self.wsum[q].q.val();
                self.bgm[3 * q + k].w.next = self.q5_w[q].q.val();
                self.bgm[3 * q + k].bg.next = self.bgc[k].val();
                self.word20[3 * q + k].next = self.acc[3 * q + k].val() + self.bgm[3 * q + k].p.val() + self.half20.val();
                self.word_sh[3 * q + k].next = self.word20[3 * q + k].val() >> 8;
            }
        }

        // ---- The box: Q6 holding a pixel's last slot is its input word.
        self.box2.background.next = self.background.q.val();
        self.box2.upstream.valid.next = self.q6.q.val().valid & self.q6.q.val().last;
        self.box2.upstream.data.next.x = self.q6.q.val().x;
        self.box2.upstream.data.next.y = self.q6.q.val().y;
        self.box2.upstream.data.next.r0 = self.q6_acc[0].q.val();
        self.box2.upstream.data.next.g0 = self.q6_acc[1].q.val();
        self.box2.upstream.data.next.b0 = self.q6_acc[2].q.val();
        self.box2.upstream.data.next.r1 = self.q6_acc[3].q.val();
        self.box2.upstream.data.next.g1 = self.q6_acc[4].q.val();
        self.box2.upstream.data.next.b1 = self.q6_acc[5].q.val();
        self.box2.upstream.data.next.r2 = self.q6_acc[6].q.val();
        self.box2.upstream.data.next.g2 = self.q6_acc[7].q.val();
        self.box2.upstream.data.next.b2 = self.q6_acc[8].q.val();
        self.box2.upstream.data.next.r3 = self.q6_acc[9].q.val();
        self.box2.upstream.data.next.g3 = self.q6_acc[10].q.val();
        self.box2.upstream.data.next.b3 = self.q6_acc[11].q.val();
        self.box2.upstream.data.next.c0 = self.q6_c[0].q.val();
        self.box2.upstream.data.next.c1 = self.q6_c[1].q.val();
        self.box2.upstream.data.next.c2 = self.q6_c[2].q.val();
        self.box2.upstream.data.next.c3 = self.q6_c[3].q.val();
        StreamOut::<FilteredPixel>::link(&mut self.downstream, &mut self.box2.downstream);

        if self.adv.val() {
            self.q5.d.next = self.front.tag.val();
            self.q5_w[0].d.next = self.front.wq0.val();
            self.q5_w[1].d.next = self.front.wq1.val();
            self.q5_w[2].d.next = self.front.wq2.val();
            self.q5_w[3].d.next = self.front.wq3.val();
            self.q5_c[0].d.next = self.pc_union.q0.val();
            self.q5_c[1].d.next = self.pc_union.q1.val();
            self.q5_c[2].d.next = self.pc_union.q2.val();
            self.q5_c[3].d.next = self.pc_union.q3.val();
            self.q6.d.next = self.q5.q.val();
            for q in 0..4 {
                self.q6_c[q].d.next = self.q5_c[q].q.val();
                if self.q5.q.val().valid {
                    self.wsum[q].d.next = self.wacc[q].val();
                    if self.q5.q.val().last {
                        self.wsum[q].d.next = self.zero13.val();
                    }
                }
            }
            for i in 0..12 {
                self.q6_acc[i].d.next = self.word_sh[i].val().get_bits::<12>(0);
                if self.q5.q.val().valid {
                    self.qsum[i].d.next = self.acc[i].val();
                    if self.q5.q.val().last {
                        self.qsum[i].d.next = self.zero20.val();
                    }
                }
            }
        }
    }
}

/// The Verilog of a 2x2 filter stage with a direction table of 2^`obj_addr_bits` entries for a
/// `width` x `height` screen, top module named `name`.
pub fn verilog_filter2x2(name: &str, obj_addr_bits: usize, width: u32, height: u32) -> Result<String, String> {
    let mut uut = Filter2x2Stage::new(obj_addr_bits, width, height)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(super::rename_top(&generate_verilog(&uut), name))
}
