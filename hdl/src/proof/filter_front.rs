//! The front end of PROOF's filter stage (seed 002 §6.1), shared by both filter areas: per list entry
//! the 8x8 subpixel mask from its edge distances (the tree of multiples of sin a and cos a,
//! [`EdgeMask`]) and the subpixels the entry owns, nearest first: those no earlier entry of the pixel
//! took. The back ends ([`super::filter::FilterStage`], 1x1; [`super::filter2x2::Filter2x2Stage`],
//! 2x2) weight the colours by these masks. Cycle behaviour:
//! `golden::proof::cycle_filter::FilterFront`.
//!
//! ```text
//!                dir_write dir_addr dir_data   (id -> cos/sin of the 3 edges, Q1.14)
//!                   │
//!             +─────┴───────────────────────────────────────────────────────+
//!  slot    ──▶| F0 ─▶ edge masks x3 (F1 base, F2 rows, F3 mask) ─▶ F4        |──▶ tag      (F4's slot)
//!  slot_valid▶| dir   tree of multiples in y, then in x             visible  |──▶ visible  = mask & ~taken
//!  adv     ──▶| table                                               union    |──▶ union_mask = taken | mask
//!             +─────────────────────────────────────────────────────────────+
//! ```
//! Every register loads when `adv` is high (the back end's global stall). F0 takes `slot` (valid or
//! not) and the direction table is read at the same edge with enable `adv`, so a stalled F0 keeps its
//! word. F4's entry mask is the AND of the three edges' masks, all 64 for a full entry, none for an
//! empty slot. The pixel state `taken` changes only when a valid slot passes F3 and returns to 0 after
//! a pixel's last slot. Five registers from `slot` to `tag`.

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
    /// Write `dir_data` (cos, sin of edge k at bits 32k, 32k + 16) to the direction table at `dir_addr`.
    pub dir_write: Signal<In, Bit>,
    pub dir_addr: Signal<In, Bits<16>>,
    pub dir_data: Signal<In, Bits<96>>,
    // From the shading stage
    /// The shaded slot F0 takes at the next `adv` edge.
    pub slot: Signal<In, ShadedSlot>,
    /// `slot` is a slot of the stream.
    pub slot_valid: Signal<In, Bit>,
    // To the back end (F4)
    /// F4's slot information (`valid`: F4 holds a slot).
    pub tag: Signal<Out, FilterTag>,
    /// The subpixels F4's entry owns: its mask without those nearer entries of the pixel took.
    pub visible: Signal<Out, Bits<64>>,
    /// The subpixels of F4's pixel covered so far, this entry included.
    pub union_mask: Signal<Out, Bits<64>>,

    // Registers, table and sub-blocks (pub: the benches compare them with the model).
    pub dir_table: TableRam<Bits<96>>,
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
    pub f4_visible: DFF<Bits<64>>,
    pub f4_union: DFF<Bits<64>>,

    tag0: Signal<Local, FilterTag>,
    emask: Signal<Local, Bits<64>>,
    vis: Signal<Local, Bits<64>>,
    uni: Signal<Local, Bits<64>>,
    all64: Constant<Bits<64>>,
    zero64: Constant<Bits<64>>,
}

impl FilterFront {
    /// A front end with a direction table of 2^`obj_addr_bits` entries (1..=16).
    pub fn new(obj_addr_bits: usize) -> Result<FilterFront, String> {
        Ok(FilterFront {
            clock: Default::default(),
            adv: Default::default(),
            dir_write: Default::default(),
            dir_addr: Default::default(),
            dir_data: Default::default(),
            slot: Default::default(),
            slot_valid: Default::default(),
            tag: Default::default(),
            visible: Default::default(),
            union_mask: Default::default(),
            dir_table: TableRam::new(obj_addr_bits)?,
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
            f4_visible: Default::default(),
            f4_union: Default::default(),
            tag0: Default::default(),
            emask: Default::default(),
            vis: Default::default(),
            uni: Default::default(),
            all64: Constant::new(u64::MAX.into()),
            zero64: Constant::new(0u64.into()),
        })
    }
}

impl Logic for FilterFront {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, f0, f0_valid, f1, f2, f3, taken, f4, f4_visible, f4_union);
        self.dir_table.clock.next = self.clock.val();
        self.e0.clock.next = self.clock.val();
        self.e1.clock.next = self.clock.val();
        self.e2.clock.next = self.clock.val();
        self.tag.next = self.f4.q.val();
        self.visible.next = self.f4_visible.q.val();
        self.union_mask.next = self.f4_union.q.val();

        // ---- Host writes to the direction table.
        self.dir_table.write_enable.next = self.dir_write.val();
        self.dir_table.write_address.next = self.dir_addr.val();
        self.dir_table.write_data.next = self.dir_data.val();

        // ---- F0: the slot; the direction table is read at the same edge.
        self.dir_table.read_address.next = self.slot.val().id;
        self.dir_table.read_enable.next = self.adv.val();

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

        // ---- F4: the entry's mask (all for a full entry, none for an empty slot) against the
        // subpixels nearer entries of the pixel took.
        self.emask.next = self.e0.mask.val() & self.e1.mask.val() & self.e2.mask.val();
        if self.f3.q.val().full {
            self.emask.next = self.all64.val();
        }
        if !self.f3.q.val().has_entry {
            self.emask.next = self.zero64.val();
        }
        self.vis.next = self.emask.val() & !self.taken.q.val();
        self.uni.next = self.taken.q.val() | self.emask.val();

        if self.adv.val() {
            self.f0.d.next = self.slot.val();
            self.f0_valid.d.next = self.slot_valid.val();
            self.f1.d.next = self.tag0.val();
            self.f2.d.next = self.f1.q.val();
            self.f3.d.next = self.f2.q.val();
            self.f4.d.next = self.f3.q.val();
            self.f4_visible.d.next = self.vis.val();
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
