//! The front end of PROOF's filter stage (seed 002 §6.1), shared by both filter areas: per list entry
//! the 8x8 subpixel mask from its edge distances (the tree of multiples of sin a and cos a,
//! [`EdgeMask`]) and the entry's weight in each subpixel, front to back: 64 [`BlendCell`]s give
//! each covered subpixel `w = (T a + 8) >> 4` of the transmittance `T` the nearer entries of the pixel
//! left (an opaque entry, a = 16, takes all of it). The back ends ([`super::filter::FilterStage`],
//! 1x1; [`super::filter2x2::Filter2x2Stage`], 2x2) weight the colours by the weights' sums. Cycle
//! behaviour: `golden::proof::cycle_filter::FilterFront`.
//!
//! ```text
//!          dir_write cfg_addr dir_data (id -> cos/sin of the 3 edges, Q1.14)
//!          alpha_write        alpha_data (id -> opacity, Q1.4, 16 opaque)
//!                   │
//!             +─────┴──────────────────────────────────────────────────────────+
//!  slot    ──▶| F0 ─▶ edge masks x3 (F1 base, F2 rows, F3 mask) ─▶ F4 64 blend   |──▶ tag (F4's slot)
//!  slot_valid▶| dir,  tree of multiples in y, then in x             cells: w_i,  |──▶ wq0..wq3, weight
//!  adv     ──▶| alpha F1: a = min(alpha, 16)                        sum tree     |    (Σ w_i per quadrant, all)
//!             | tables                                              union        |──▶ union_mask = taken | mask
//!             +────────────────────────────────────────────────────────────────+
//! ```
//! Every register loads when `adv` is high (the back end's global stall). F0 takes `slot` (valid or
//! not) and the direction and opacity tables are read at the same edge with enable `adv`, so a
//! stalled F0 keeps its words. F4's entry mask is the AND of the three edges' masks, all 64 for a full
//! entry, none for an empty slot. The pixel states `taken` and the cells' `spent` change only when a
//! valid slot passes F3 and return to 0 after a pixel's last slot. Five registers from `slot` to
//! `tag`; the weights' sums are combinational from F4's cells (a tree of 63 adders: rows, quadrants,
//! the pixel).

use super::blend_cell::BlendCell;
use crate::common::AddU;
use super::edge_mask::EdgeMask;
use super::table_ram::TableRam;
use super::types::{FilterTag, ShadedSlot};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FilterFront {
    pub clock: Signal<In, Clock>,
    // From the back end's control
    /// Move every register one stage on at this edge (the stage's global stall).
    pub adv: Signal<In, Bit>,
    // From the host (decoded by the stage)
    /// Write `dir_data` (cos, sin of edge k at bits 32k, 32k + 16) to the direction table at `cfg_addr`.
    pub dir_write: Signal<In, Bit>,
    pub cfg_addr: Signal<In, Bits<16>>,
    pub dir_data: Signal<In, Bits<96>>,
    /// Write `alpha_data` (the object's opacity in sixteenths, Q1.4; above 16 counts as 16) to the
    /// opacity table at `cfg_addr`.
    pub alpha_write: Signal<In, Bit>,
    pub alpha_data: Signal<In, Bits<5>>,
    // From the shading stage
    /// The shaded slot F0 takes at the next `adv` edge.
    pub slot: Signal<In, ShadedSlot>,
    /// `slot` is a slot of the stream.
    pub slot_valid: Signal<In, Bit>,
    // To the back end (F4)
    /// F4's slot information (`valid`: F4 holds a slot).
    pub tag: Signal<Out, FilterTag>,
    /// F4's entry's weights summed over each quadrant of 4x4 subpixels (q = 2 qy + qx; 0..=4096, in
    /// 1/256 of a subpixel).
    pub wq0: Signal<Out, Bits<13>>,
    pub wq1: Signal<Out, Bits<13>>,
    pub wq2: Signal<Out, Bits<13>>,
    pub wq3: Signal<Out, Bits<13>>,
    /// F4's entry's weight in the pixel (0..=16384).
    pub weight: Signal<Out, Bits<15>>,
    /// The subpixels of F4's pixel covered so far, this entry included.
    pub union_mask: Signal<Out, Bits<64>>,

    // Registers, table and sub-blocks (pub: the benches compare them with the model).
    pub dir_table: TableRam<Bits<96>>,
    pub alpha_table: TableRam<Bits<5>>,
    pub f0: DFF<ShadedSlot>,
    pub f0_valid: DFF<Bit>,
    pub e0: EdgeMask,
    pub e1: EdgeMask,
    pub e2: EdgeMask,
    pub f1: DFF<FilterTag>,
    pub f2: DFF<FilterTag>,
    pub f3: DFF<FilterTag>,
    pub taken: DFF<Bits<64>>,
    pub f4: DFF<FilterTag>,
    pub f4_union: DFF<Bits<64>>,
    /// One per subpixel, bit order `8 j + i` (F4's weights and the pixel state `spent`).
    pub cells: Vec<BlendCell>,

    tag0: Signal<Local, FilterTag>,
    alpha: Signal<Local, Bits<5>>,
    emask: Signal<Local, Bits<64>>,
    uni: Signal<Local, Bits<64>>,
    // The sum tree of widening adders: a1 pairs in a row, a2 half rows of a quadrant, a3 two rows of
    // a quadrant, a4 quadrants, a5 halves, a6 the pixel.
    a1: Vec<AddU<9, 10>>,
    a2: Vec<AddU<10, 11>>,
    a3: Vec<AddU<11, 12>>,
    a4: Vec<AddU<12, 13>>,
    a5: Vec<AddU<13, 14>>,
    a6: AddU<14, 15>,
    all64: Constant<Bits<64>>,
    zero64: Constant<Bits<64>>,
    sixteen5: Constant<Bits<5>>,
}

impl FilterFront {
    /// A front end with a direction table of 2^`obj_addr_bits` entries (1..=16).
    pub fn new(obj_addr_bits: usize) -> Result<FilterFront, String> {
        Ok(FilterFront {
            clock: Default::default(),
            adv: Default::default(),
            dir_write: Default::default(),
            cfg_addr: Default::default(),
            dir_data: Default::default(),
            alpha_write: Default::default(),
            alpha_data: Default::default(),
            slot: Default::default(),
            slot_valid: Default::default(),
            tag: Default::default(),
            wq0: Default::default(),
            wq1: Default::default(),
            wq2: Default::default(),
            wq3: Default::default(),
            weight: Default::default(),
            union_mask: Default::default(),
            dir_table: TableRam::new(obj_addr_bits)?,
            alpha_table: TableRam::new(obj_addr_bits)?,
            f0: Default::default(),
            f0_valid: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            e2: Default::default(),
            f1: Default::default(),
            f2: Default::default(),
            f3: Default::default(),
            taken: Default::default(),
            f4: Default::default(),
            f4_union: Default::default(),
            cells: (0..64).map(|_| BlendCell::default()).collect(),
            tag0: Default::default(),
            alpha: Default::default(),
            emask: Default::default(),
            uni: Default::default(),
            a1: (0..32).map(|_| Default::default()).collect(),
            a2: (0..16).map(|_| Default::default()).collect(),
            a3: (0..8).map(|_| Default::default()).collect(),
            a4: (0..4).map(|_| Default::default()).collect(),
            a5: (0..2).map(|_| Default::default()).collect(),
            a6: Default::default(),
            all64: Constant::new(u64::MAX.into()),
            zero64: Constant::new(0u64.into()),
            sixteen5: Constant::new(16u64.into()),
        })
    }
}

impl Logic for FilterFront {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, f0, f0_valid, f1, f2, f3, taken, f4, f4_union);
        self.dir_table.clock.next = self.clock.val();
        self.alpha_table.clock.next = self.clock.val();
        self.e0.clock.next = self.clock.val();
        self.e1.clock.next = self.clock.val();
        self.e2.clock.next = self.clock.val();
        self.tag.next = self.f4.q.val();
        self.union_mask.next = self.f4_union.q.val();

        // ---- Host writes to the direction and opacity tables.
        self.dir_table.write_enable.next = self.dir_write.val();
        self.dir_table.write_address.next = self.cfg_addr.val();
        self.dir_table.write_data.next = self.dir_data.val();
        self.alpha_table.write_enable.next = self.alpha_write.val();
        self.alpha_table.write_address.next = self.cfg_addr.val();
        self.alpha_table.write_data.next = self.alpha_data.val();

        // ---- F0: the slot; the tables are read at the same edge.
        self.dir_table.read_address.next = self.slot.val().id;
        self.dir_table.read_enable.next = self.adv.val();
        self.alpha_table.read_address.next = self.slot.val().id;
        self.alpha_table.read_enable.next = self.adv.val();

        // ---- F1..F3: the three edges' masks (cos at bit 32k, sin at 32k + 16 of the table word).
        self.e0.adv.next = self.adv.val();
        self.e1.adv.next = self.adv.val();
        self.e2.adv.next = self.adv.val();
        self.e0.d.next = self.f0.q.val().d0;
        self.e1.d.next = self.f0.q.val().d1;
        self.e2.d.next = self.f0.q.val().d2;
        self.e0.cs.next = self.dir_table.read_data.val().get_bits::<16>(0);
        self.e0.sn.next = self.dir_table.read_data.val().get_bits::<16>(16);
        self.e1.cs.next = self.dir_table.read_data.val().get_bits::<16>(32);
        self.e1.sn.next = self.dir_table.read_data.val().get_bits::<16>(48);
        self.e2.cs.next = self.dir_table.read_data.val().get_bits::<16>(64);
        self.e2.sn.next = self.dir_table.read_data.val().get_bits::<16>(80);
        self.tag0.next = self.f1.q.val();
        self.tag0.next.valid = self.f0_valid.q.val();
        self.tag0.next.x = self.f0.q.val().x;
        self.tag0.next.y = self.f0.q.val().y;
        self.tag0.next.last = self.f0.q.val().last;
        self.tag0.next.has_entry = self.f0.q.val().has_entry;
        self.tag0.next.full = self.f0.q.val().full;
        self.tag0.next.r = self.f0.q.val().r;
        self.tag0.next.g = self.f0.q.val().g;
        self.tag0.next.b = self.f0.q.val().b;
        // The opacity, at most 16.
        self.alpha.next = self.alpha_table.read_data.val();
        if self.alpha_table.read_data.val() > self.sixteen5.val() {
            self.alpha.next = self.sixteen5.val();
        }
        self.tag0.next.alpha = self.alpha.val();

        // ---- F4: the entry's mask (all for a full entry, none for an empty slot) against the
        // subpixels nearer entries of the pixel took.
        self.emask.next = self.e0.mask.val() & self.e1.mask.val() & self.e2.mask.val();
        if self.f3.q.val().full {
            self.emask.next = self.all64.val();
        }
        if !self.f3.q.val().has_entry {
            self.emask.next = self.zero64.val();
        }
        self.uni.next = self.taken.q.val() | self.emask.val();
        for i in 0..64 {
            self.cells[i].clock.next = self.clock.val();
            self.cells[i].adv.next = self.adv.val();
            self.cells[i].hit.next = self.emask.val().get_bit(i);
            self.cells[i].valid.next = self.f3.q.val().valid;
            self.cells[i].last.next = self.f3.q.val().last;
            self.cells[i].a.next = self.f3.q.val().alpha;
        }

        // ---- The sum tree over F4's cells. a1: subpixel pairs (row j = k / 4); a2: half rows of a
        // quadrant (m = 2 j + qx); a3: two rows of a quadrant (n = 2 r + qx, rows 2r and 2r + 1);
        // a4: quadrants (q = 2 qy + qx, a3's r = 2 qy and 2 qy + 1); a5: top and bottom half.
        for k in 0..32 {
            self.a1[k].a.next = self.cells[2 * k].w.val();
            self.a1[k].b.next = self.cells[2 * k + 1].w.val();
        }
        for m in 0..16 {
            self.a2[m].a.next = self.a1[2 * m].s.val();
            self.a2[m].b.next = self.a1[2 * m + 1].s.val();
        }
        for r in 0..4 {
            for qx in 0..2 {
                self.a3[2 * r + qx].a.next = self.a2[4 * r + qx].s.val();
                self.a3[2 * r + qx].b.next = self.a2[4 * r + qx + 2].s.val();
            }
        }
        for qy in 0..2 {
            for qx in 0..2 {
                self.a4[2 * qy + qx].a.next = self.a3[4 * qy + qx].s.val();
                self.a4[2 * qy + qx].b.next = self.a3[4 * qy + qx + 2].s.val();
            }
        }
        for h in 0..2 {
            self.a5[h].a.next = self.a4[2 * h].s.val();
            self.a5[h].b.next = self.a4[2 * h + 1].s.val();
        }
        self.a6.a.next = self.a5[0].s.val();
        self.a6.b.next = self.a5[1].s.val();
        self.wq0.next = self.a4[0].s.val();
        self.wq1.next = self.a4[1].s.val();
        self.wq2.next = self.a4[2].s.val();
        self.wq3.next = self.a4[3].s.val();
        self.weight.next = self.a6.s.val();

        if self.adv.val() {
            self.f0.d.next = self.slot.val();
            self.f0_valid.d.next = self.slot_valid.val();
            self.f1.d.next = self.tag0.val();
            self.f2.d.next = self.f1.q.val();
            self.f3.d.next = self.f2.q.val();
            self.f4.d.next = self.f3.q.val();
            self.f4_union.d.next = self.uni.val();
            if self.f3.q.val().valid {
                self.taken.d.next = self.uni.val();
                if self.f3.q.val().last {
                    self.taken.d.next = self.zero64.val();
                }
            }
        }
    }
}
