//! Object processor (seed 002 §4.3-4.5, Fig. 2): holds one triangle, scan-converts it incrementally,
//! classifies each pixel's coverage with the grown-triangle test and inserts its own entry into the
//! pixel's depth-sorted object list. Cycle behaviour: `golden::proof::cycle_op` (the model it must
//! match on every port in every cycle).
//!
//! ```text
//!                  +-------------------------------------------------+
//!   load        ──▶| parameters ─▶ primitive processor (accumulators) |
//!   load_params ──▶|                     │ own entry, coverage        |
//!   upstream    ──▶| slot_fifo ─▶ head ─▶ comparator ─▶ output reg    |──▶ downstream
//!     .data .valid |                                                 |     .data .valid
//!     .ready    ◀──|  ready = FIFO not full, or the head leaves now    |◀──  .ready
//!   free        ◀──|  no object, or the box's last pixel has passed    |
//!                  +-------------------------------------------------+
//! ```
//!
//! * Parameters: the load puts the start values (edge distances, depth, normal) straight into the
//!   accumulators and keeps the rest ([`ObjSteps`]: id, box, steps, thresholds, opacity) in `params`.
//! * Primitive processor: per quantity a `row` accumulator (the current line's first box pixel) and a
//!   `cur` accumulator (the current box pixel). When a box pixel's list has left, `cur` steps by the
//!   per-pixel increment, or at the box's right edge `row` steps by the per-line increment and `cur`
//!   takes it. Adds only; no multiplier.
//! * Coverage: none if `d_i + t_none_i <= 0` for some edge, full if `d_i >= t_full_i` for all three
//!   and the object is `opaque` (a transparent object's entry stays partial: issue 22).
//! * Comparator: own entry before the head if (depth, id) is smaller; a full own entry ends the list
//!   (the rest is dropped, one slot per cycle, without output); a full head drops the own entry.

use super::slot_fifo::SlotFifo;
use super::types::{ObjParams, ObjSteps, ProofSlot};
use crate::common::{signed_bit_cast_safe, StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct ObjectProcessor {
    pub clock: Signal<In, Clock>,
    // From the object loader (geometry processor)
    /// Load `load_params` at this edge (only while `free`).
    pub load: Signal<In, Bit>,
    /// The object.
    pub load_params: Signal<In, ObjParams>,
    // From the previous object processor (or the pixel source)
    /// Slots of the pixels' object lists, raster order.
    pub upstream: StreamIn<ProofSlot>,
    // To the next object processor (or the shading stage)
    /// The lists with this OP's object inserted.
    pub downstream: StreamOut<ProofSlot>,
    // To the object loader
    /// No object, or the scan has passed the object's last box pixel.
    pub free: Signal<Out, Bit>,

    // Registers (pub so that the testbench can compare them with the model).
    /// The loaded object's id, box, steps, thresholds and opacity (not its start values).
    pub params: DFF<ObjSteps>,
    pub row_d0: DFF<Signed<27>>,
    pub row_d1: DFF<Signed<27>>,
    pub row_d2: DFF<Signed<27>>,
    pub cur_d0: DFF<Signed<27>>,
    pub cur_d1: DFF<Signed<27>>,
    pub cur_d2: DFF<Signed<27>>,
    pub row_z: DFF<Signed<32>>,
    pub cur_z: DFF<Signed<32>>,
    pub row_nx: DFF<Signed<32>>,
    pub row_ny: DFF<Signed<32>>,
    pub row_nz: DFF<Signed<32>>,
    pub cur_nx: DFF<Signed<32>>,
    pub cur_ny: DFF<Signed<32>>,
    pub cur_nz: DFF<Signed<32>>,
    pub mid: DFF<Bit>,
    pub own_pending: DFF<Bit>,
    pub tail: DFF<Bit>,
    pub dropping: DFF<Bit>,
    pub px: DFF<Bits<10>>,
    pub py: DFF<Bits<10>>,
    pub pix_act: DFF<Bit>,
    pub loaded: DFF<Bit>,
    pub done: DFF<Bit>,
    pub out_valid: DFF<Bit>,
    pub out_data: DFF<ProofSlot>,
    pub fifo: SlotFifo,

    // Combinational temporaries.
    p: Signal<Local, ObjSteps>,
    h: Signal<Local, ProofSlot>,
    own_slot: Signal<Local, ProofSlot>,
    emit_slot: Signal<Local, ProofSlot>,
    // primitive processor
    sx0: Signal<Local, Signed<27>>,
    sx1: Signal<Local, Signed<27>>,
    sx2: Signal<Local, Signed<27>>,
    sy0: Signal<Local, Signed<27>>,
    sy1: Signal<Local, Signed<27>>,
    sy2: Signal<Local, Signed<27>>,
    tn0: Signal<Local, Signed<27>>,
    tn1: Signal<Local, Signed<27>>,
    tn2: Signal<Local, Signed<27>>,
    tf0: Signal<Local, Signed<27>>,
    tf1: Signal<Local, Signed<27>>,
    tf2: Signal<Local, Signed<27>>,
    m0: Signal<Local, Signed<27>>,
    m1: Signal<Local, Signed<27>>,
    m2: Signal<Local, Signed<27>>,
    nrow_d0: Signal<Local, Signed<27>>,
    nrow_d1: Signal<Local, Signed<27>>,
    nrow_d2: Signal<Local, Signed<27>>,
    nrow_z: Signal<Local, Signed<32>>,
    nrow_nx: Signal<Local, Signed<32>>,
    nrow_ny: Signal<Local, Signed<32>>,
    nrow_nz: Signal<Local, Signed<32>>,
    zb: Signal<Local, Bits<32>>,
    nxb: Signal<Local, Bits<32>>,
    nyb: Signal<Local, Bits<32>>,
    nzb: Signal<Local, Bits<32>>,
    db0: Signal<Local, Bits<27>>,
    db1: Signal<Local, Bits<27>>,
    db2: Signal<Local, Bits<27>>,
    cov_none: Signal<Local, Bit>,
    cov_full: Signal<Local, Bit>,
    // comparator
    adv: Signal<Local, Bit>,
    h_valid: Signal<Local, Bit>,
    in_box: Signal<Local, Bit>,
    start_act: Signal<Local, Bit>,
    act: Signal<Local, Bit>,
    own: Signal<Local, Bit>,
    nearer: Signal<Local, Bit>,
    append: Signal<Local, Bit>,
    emit: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    end_pixel: Signal<Local, Bit>,
    any_action: Signal<Local, Bit>,
    a_head: Signal<Local, Bit>,
    a_before: Signal<Local, Bit>,
    a_replace: Signal<Local, Bit>,
    cx: Signal<Local, Bits<10>>,
    cy: Signal<Local, Bits<10>>,
    // constants
    zero27: Constant<Signed<27>>,
    dmax16: Constant<Bits<16>>,
    dmin16: Constant<Bits<16>>,
    zmax24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
    ones11: Constant<Bits<11>>,
    ones9: Constant<Bits<9>>,
    zero11: Constant<Bits<11>>,
    zero9: Constant<Bits<9>>,
}

impl ObjectProcessor {
    /// An object processor with an input FIFO of `fifo_depth` slots (1..=8).
    pub fn new(fifo_depth: usize) -> Result<ObjectProcessor, String> {
        Ok(ObjectProcessor {
            clock: Default::default(),
            load: Default::default(),
            load_params: Default::default(),
            upstream: Default::default(),
            downstream: Default::default(),
            free: Default::default(),
            params: Default::default(),
            row_d0: Default::default(),
            row_d1: Default::default(),
            row_d2: Default::default(),
            cur_d0: Default::default(),
            cur_d1: Default::default(),
            cur_d2: Default::default(),
            row_z: Default::default(),
            cur_z: Default::default(),
            row_nx: Default::default(),
            row_ny: Default::default(),
            row_nz: Default::default(),
            cur_nx: Default::default(),
            cur_ny: Default::default(),
            cur_nz: Default::default(),
            mid: Default::default(),
            own_pending: Default::default(),
            tail: Default::default(),
            dropping: Default::default(),
            px: Default::default(),
            py: Default::default(),
            pix_act: Default::default(),
            loaded: Default::default(),
            done: Default::default(),
            out_valid: Default::default(),
            out_data: Default::default(),
            fifo: SlotFifo::new(fifo_depth)?,
            p: Default::default(),
            h: Default::default(),
            own_slot: Default::default(),
            emit_slot: Default::default(),
            sx0: Default::default(),
            sx1: Default::default(),
            sx2: Default::default(),
            sy0: Default::default(),
            sy1: Default::default(),
            sy2: Default::default(),
            tn0: Default::default(),
            tn1: Default::default(),
            tn2: Default::default(),
            tf0: Default::default(),
            tf1: Default::default(),
            tf2: Default::default(),
            m0: Default::default(),
            m1: Default::default(),
            m2: Default::default(),
            nrow_d0: Default::default(),
            nrow_d1: Default::default(),
            nrow_d2: Default::default(),
            nrow_z: Default::default(),
            nrow_nx: Default::default(),
            nrow_ny: Default::default(),
            nrow_nz: Default::default(),
            zb: Default::default(),
            nxb: Default::default(),
            nyb: Default::default(),
            nzb: Default::default(),
            db0: Default::default(),
            db1: Default::default(),
            db2: Default::default(),
            cov_none: Default::default(),
            cov_full: Default::default(),
            adv: Default::default(),
            h_valid: Default::default(),
            in_box: Default::default(),
            start_act: Default::default(),
            act: Default::default(),
            own: Default::default(),
            nearer: Default::default(),
            append: Default::default(),
            emit: Default::default(),
            pop: Default::default(),
            end_pixel: Default::default(),
            any_action: Default::default(),
            a_head: Default::default(),
            a_before: Default::default(),
            a_replace: Default::default(),
            cx: Default::default(),
            cy: Default::default(),
            zero27: Constant::new(Signed::<27>::default()),
            dmax16: Constant::new(0x7fff.into()),
            dmin16: Constant::new(0x8000.into()),
            zmax24: Constant::new(0xff_ffff.into()),
            zero24: Constant::new(0.into()),
            ones11: Constant::new(0x7ff.into()),
            ones9: Constant::new(0x1ff.into()),
            zero11: Constant::new(0.into()),
            zero9: Constant::new(0.into()),
        })
    }
}

impl Logic for ObjectProcessor {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, params, row_d0, row_d1, row_d2, cur_d0, cur_d1, cur_d2, row_z, cur_z, row_nx, row_ny, row_nz, cur_nx,
            cur_ny, cur_nz, mid, own_pending, tail, dropping, px, py, pix_act, loaded, done, out_valid, out_data
        );
        clock!(self, clock, fifo);
        self.p.next = self.params.q.val();
        self.h.next = self.fifo.data_out.val();

        // ---- Primitive processor: steps and thresholds, sign-extended to the accumulator width.
        self.sx0.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e0_sx));
        self.sx1.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e1_sx));
        self.sx2.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e2_sx));
        self.sy0.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e0_sy));
        self.sy1.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e1_sy));
        self.sy2.next = signed_bit_cast_safe::<27, 17>(signed_cast(self.p.val().e2_sy));
        self.tn0.next = signed_cast(bit_cast::<27, 18>(self.p.val().e0_tn));
        self.tn1.next = signed_cast(bit_cast::<27, 18>(self.p.val().e1_tn));
        self.tn2.next = signed_cast(bit_cast::<27, 18>(self.p.val().e2_tn));
        self.tf0.next = signed_cast(bit_cast::<27, 18>(self.p.val().e0_tf));
        self.tf1.next = signed_cast(bit_cast::<27, 18>(self.p.val().e1_tf));
        self.tf2.next = signed_cast(bit_cast::<27, 18>(self.p.val().e2_tf));
        // Coverage (seed 002 §4.5): none if d + r <= 0 for an edge, full if d >= r + delta for all and
        // the object is opaque (a transparent object's entry never ends the list: issue 22).
        self.m0.next = self.cur_d0.q.val() + self.tn0.val();
        self.m1.next = self.cur_d1.q.val() + self.tn1.val();
        self.m2.next = self.cur_d2.q.val() + self.tn2.val();
        self.cov_none.next =
            (self.m0.val() <= self.zero27.val()) | (self.m1.val() <= self.zero27.val()) | (self.m2.val() <= self.zero27.val());
        self.cov_full.next =
            (self.tf0.val() <= self.cur_d0.q.val()) & (self.tf1.val() <= self.cur_d1.q.val()) & (self.tf2.val() <= self.cur_d2.q.val()) & self.p.val().opaque;
        // Own entry: depth clamped to 24 bits, normals and distances saturated to 16 bits.
        self.zb.next = unsigned_cast(self.cur_z.q.val());
        self.nxb.next = unsigned_cast(self.cur_nx.q.val());
        self.nyb.next = unsigned_cast(self.cur_ny.q.val());
        self.nzb.next = unsigned_cast(self.cur_nz.q.val());
        self.db0.next = unsigned_cast(self.cur_d0.q.val());
        self.db1.next = unsigned_cast(self.cur_d1.q.val());
        self.db2.next = unsigned_cast(self.cur_d2.q.val());
        self.own_slot.next = self.h.val();
        self.own_slot.next.has_entry = true;
        self.own_slot.next.id = self.p.val().id;
        self.own_slot.next.full = self.cov_full.val();
        self.own_slot.next.depth = self.zb.val().get_bits::<24>(4);
        if self.zb.val().get_bits::<4>(28).any() {
            self.own_slot.next.depth = self.zmax24.val();
        }
        if self.zb.val().get_bit(31) {
            self.own_slot.next.depth = self.zero24.val();
        }
        self.own_slot.next.nx = self.nxb.val().get_bits::<16>(8);
        if (self.nxb.val().get_bits::<9>(23) != self.zero9.val()) & (self.nxb.val().get_bits::<9>(23) != self.ones9.val()) {
            self.own_slot.next.nx = self.dmax16.val();
            if self.nxb.val().get_bit(31) {
                self.own_slot.next.nx = self.dmin16.val();
            }
        }
        self.own_slot.next.ny = self.nyb.val().get_bits::<16>(8);
        if (self.nyb.val().get_bits::<9>(23) != self.zero9.val()) & (self.nyb.val().get_bits::<9>(23) != self.ones9.val()) {
            self.own_slot.next.ny = self.dmax16.val();
            if self.nyb.val().get_bit(31) {
                self.own_slot.next.ny = self.dmin16.val();
            }
        }
        self.own_slot.next.nz = self.nzb.val().get_bits::<16>(8);
        if (self.nzb.val().get_bits::<9>(23) != self.zero9.val()) & (self.nzb.val().get_bits::<9>(23) != self.ones9.val()) {
            self.own_slot.next.nz = self.dmax16.val();
            if self.nzb.val().get_bit(31) {
                self.own_slot.next.nz = self.dmin16.val();
            }
        }
        self.own_slot.next.d0 = self.db0.val().get_bits::<16>(1);
        if (self.db0.val().get_bits::<11>(16) != self.zero11.val()) & (self.db0.val().get_bits::<11>(16) != self.ones11.val()) {
            self.own_slot.next.d0 = self.dmax16.val();
            if self.db0.val().get_bit(26) {
                self.own_slot.next.d0 = self.dmin16.val();
            }
        }
        self.own_slot.next.d1 = self.db1.val().get_bits::<16>(1);
        if (self.db1.val().get_bits::<11>(16) != self.zero11.val()) & (self.db1.val().get_bits::<11>(16) != self.ones11.val()) {
            self.own_slot.next.d1 = self.dmax16.val();
            if self.db1.val().get_bit(26) {
                self.own_slot.next.d1 = self.dmin16.val();
            }
        }
        self.own_slot.next.d2 = self.db2.val().get_bits::<16>(1);
        if (self.db2.val().get_bits::<11>(16) != self.zero11.val()) & (self.db2.val().get_bits::<11>(16) != self.ones11.val()) {
            self.own_slot.next.d2 = self.dmax16.val();
            if self.db2.val().get_bit(26) {
                self.own_slot.next.d2 = self.dmin16.val();
            }
        }

        // ---- Comparator and list control.
        self.adv.next = !self.out_valid.q.val() | self.downstream.ready.val();
        self.h_valid.next = !self.fifo.empty.val();
        self.in_box.next = (self.h.val().x >= self.p.val().x0)
            & (self.h.val().x <= self.p.val().x1)
            & (self.h.val().y >= self.p.val().y0)
            & (self.h.val().y <= self.p.val().y1);
        self.start_act.next = self.loaded.q.val() & !self.done.q.val() & self.in_box.val();
        self.act.next = self.pix_act.q.val();
        self.own.next = self.own_pending.q.val();
        self.cx.next = self.px.q.val();
        self.cy.next = self.py.q.val();
        if !self.mid.q.val() {
            self.act.next = self.start_act.val();
            self.own.next = self.start_act.val() & !self.cov_none.val();
            self.cx.next = self.h.val().x;
            self.cy.next = self.h.val().y;
        }
        self.nearer.next = (self.own_slot.val().depth < self.h.val().depth)
            | ((self.own_slot.val().depth == self.h.val().depth) & (self.own_slot.val().id < self.h.val().id));
        self.append.next = self.own.val() & !self.h.val().full;
        self.emit.next = false;
        self.pop.next = false;
        self.end_pixel.next = false;
        self.any_action.next = false;
        self.a_head.next = false;
        self.a_before.next = false;
        self.a_replace.next = false;
        self.emit_slot.next = self.h.val();
        if self.mid.q.val() & self.tail.q.val() {
            // Append the own entry after the list's last slot.
            if self.adv.val() {
                self.emit.next = true;
                self.any_action.next = true;
                self.end_pixel.next = true;
                self.emit_slot.next = self.own_slot.val();
                self.emit_slot.next.x = self.px.q.val();
                self.emit_slot.next.y = self.py.q.val();
                self.emit_slot.next.last = true;
            }
        } else if self.h_valid.val() {
            if self.mid.q.val() & self.dropping.q.val() {
                // Behind a full entry: drop, one slot per cycle, no output needed.
                self.pop.next = true;
                self.any_action.next = true;
                self.end_pixel.next = self.h.val().last;
            } else if self.adv.val() {
                self.any_action.next = true;
                self.emit.next = true;
                if !self.h.val().has_entry {
                    self.pop.next = true;
                    self.end_pixel.next = self.h.val().last;
                    if self.own.val() {
                        self.a_replace.next = true;
                        self.emit_slot.next = self.own_slot.val();
                    } else {
                        self.a_head.next = true;
                    }
                } else if self.own.val() & self.nearer.val() {
                    self.a_before.next = true;
                    self.emit_slot.next = self.own_slot.val();
                    self.emit_slot.next.last = self.cov_full.val();
                } else {
                    self.a_head.next = true;
                    self.pop.next = true;
                    self.emit_slot.next.last = self.h.val().last & !self.append.val();
                    self.end_pixel.next = self.h.val().last & !self.append.val();
                }
            }
        }

        // ---- List state.
        if self.any_action.val() {
            if !self.mid.q.val() {
                self.px.d.next = self.h.val().x;
                self.py.d.next = self.h.val().y;
                self.pix_act.d.next = self.start_act.val();
            }
            if self.end_pixel.val() {
                self.mid.d.next = false;
                self.own_pending.d.next = false;
                self.tail.d.next = false;
                self.dropping.d.next = false;
            } else {
                self.mid.d.next = true;
                if self.a_before.val() {
                    self.own_pending.d.next = false;
                    self.dropping.d.next = self.cov_full.val();
                }
                if self.a_head.val() {
                    self.own_pending.d.next = self.append.val();
                    self.tail.d.next = self.h.val().last & self.append.val();
                }
                if self.a_replace.val() {
                    self.own_pending.d.next = false;
                }
            }
        }

        // ---- Accumulators: step after a box pixel's list has left.
        self.nrow_d0.next = self.row_d0.q.val() + self.sy0.val();
        self.nrow_d1.next = self.row_d1.q.val() + self.sy1.val();
        self.nrow_d2.next = self.row_d2.q.val() + self.sy2.val();
        self.nrow_z.next = self.row_z.q.val() + signed_cast(self.p.val().z_dy);
        self.nrow_nx.next = self.row_nx.q.val() + signed_cast(self.p.val().nx_dy);
        self.nrow_ny.next = self.row_ny.q.val() + signed_cast(self.p.val().ny_dy);
        self.nrow_nz.next = self.row_nz.q.val() + signed_cast(self.p.val().nz_dy);
        if self.end_pixel.val() & self.act.val() {
            if self.cx.val() == self.p.val().x1 {
                self.row_d0.d.next = self.nrow_d0.val();
                self.row_d1.d.next = self.nrow_d1.val();
                self.row_d2.d.next = self.nrow_d2.val();
                self.row_z.d.next = self.nrow_z.val();
                self.row_nx.d.next = self.nrow_nx.val();
                self.row_ny.d.next = self.nrow_ny.val();
                self.row_nz.d.next = self.nrow_nz.val();
                self.cur_d0.d.next = self.nrow_d0.val();
                self.cur_d1.d.next = self.nrow_d1.val();
                self.cur_d2.d.next = self.nrow_d2.val();
                self.cur_z.d.next = self.nrow_z.val();
                self.cur_nx.d.next = self.nrow_nx.val();
                self.cur_ny.d.next = self.nrow_ny.val();
                self.cur_nz.d.next = self.nrow_nz.val();
                if self.cy.val() == self.p.val().y1 {
                    self.done.d.next = true;
                }
            } else {
                self.cur_d0.d.next = self.cur_d0.q.val() + self.sx0.val();
                self.cur_d1.d.next = self.cur_d1.q.val() + self.sx1.val();
                self.cur_d2.d.next = self.cur_d2.q.val() + self.sx2.val();
                self.cur_z.d.next = self.cur_z.q.val() + signed_cast(self.p.val().z_dx);
                self.cur_nx.d.next = self.cur_nx.q.val() + signed_cast(self.p.val().nx_dx);
                self.cur_ny.d.next = self.cur_ny.q.val() + signed_cast(self.p.val().ny_dx);
                self.cur_nz.d.next = self.cur_nz.q.val() + signed_cast(self.p.val().nz_dx);
            }
        }

        // ---- Loading (only while free; overrides the step).
        if self.load.val() {
            self.params.d.next.id = self.load_params.val().id;
            self.params.d.next.x0 = self.load_params.val().x0;
            self.params.d.next.x1 = self.load_params.val().x1;
            self.params.d.next.y0 = self.load_params.val().y0;
            self.params.d.next.y1 = self.load_params.val().y1;
            self.params.d.next.e0_sx = self.load_params.val().e0_sx;
            self.params.d.next.e0_sy = self.load_params.val().e0_sy;
            self.params.d.next.e0_tn = self.load_params.val().e0_tn;
            self.params.d.next.e0_tf = self.load_params.val().e0_tf;
            self.params.d.next.e1_sx = self.load_params.val().e1_sx;
            self.params.d.next.e1_sy = self.load_params.val().e1_sy;
            self.params.d.next.e1_tn = self.load_params.val().e1_tn;
            self.params.d.next.e1_tf = self.load_params.val().e1_tf;
            self.params.d.next.e2_sx = self.load_params.val().e2_sx;
            self.params.d.next.e2_sy = self.load_params.val().e2_sy;
            self.params.d.next.e2_tn = self.load_params.val().e2_tn;
            self.params.d.next.e2_tf = self.load_params.val().e2_tf;
            self.params.d.next.z_dx = self.load_params.val().z_dx;
            self.params.d.next.z_dy = self.load_params.val().z_dy;
            self.params.d.next.nx_dx = self.load_params.val().nx_dx;
            self.params.d.next.nx_dy = self.load_params.val().nx_dy;
            self.params.d.next.ny_dx = self.load_params.val().ny_dx;
            self.params.d.next.ny_dy = self.load_params.val().ny_dy;
            self.params.d.next.nz_dx = self.load_params.val().nz_dx;
            self.params.d.next.nz_dy = self.load_params.val().nz_dy;
            self.params.d.next.opaque = self.load_params.val().opaque;
            self.loaded.d.next = true;
            self.done.d.next = false;
            self.row_d0.d.next = signed_cast(self.load_params.val().e0_d);
            self.row_d1.d.next = signed_cast(self.load_params.val().e1_d);
            self.row_d2.d.next = signed_cast(self.load_params.val().e2_d);
            self.cur_d0.d.next = signed_cast(self.load_params.val().e0_d);
            self.cur_d1.d.next = signed_cast(self.load_params.val().e1_d);
            self.cur_d2.d.next = signed_cast(self.load_params.val().e2_d);
            self.row_z.d.next = signed_cast(self.load_params.val().z_v);
            self.cur_z.d.next = signed_cast(self.load_params.val().z_v);
            self.row_nx.d.next = signed_cast(self.load_params.val().nx_v);
            self.row_ny.d.next = signed_cast(self.load_params.val().ny_v);
            self.row_nz.d.next = signed_cast(self.load_params.val().nz_v);
            self.cur_nx.d.next = signed_cast(self.load_params.val().nx_v);
            self.cur_ny.d.next = signed_cast(self.load_params.val().ny_v);
            self.cur_nz.d.next = signed_cast(self.load_params.val().nz_v);
        }

        // ---- Output register, FIFO, handshakes.
        if self.emit.val() {
            self.out_valid.d.next = true;
            self.out_data.d.next = self.emit_slot.val();
        } else if self.downstream.ready.val() {
            self.out_valid.d.next = false;
        }
        self.fifo.read.next = self.pop.val();
        self.upstream.ready.next = !self.fifo.full.val() | self.pop.val();
        self.fifo.write.next = self.upstream.valid.val() & !self.fifo.full.val() | self.upstream.valid.val() & self.pop.val();
        self.fifo.data_in.next = self.upstream.data.val();
        self.downstream.valid.next = self.out_valid.q.val();
        self.downstream.data.next = self.out_data.q.val();
        self.free.next = !self.loaded.q.val() | self.done.q.val();
    }
}
