//! Cycle-accurate model of one object processor (seed 002 §4.3, Fig. 2): input FIFO, primitive
//! processor (incremental distances, depth and normal, coverage) and comparator. The RTL block
//! `hdl::proof::object_processor` must match it on every port in every cycle.
//!
//! ```text
//!                 +----------------------------------------------+
//!  load ---------▶| parameter registers  ─▶ primitive processor  |
//!  load_params --▶|   (edges, depth, normals; row/cur accumulators)|
//!                 |                            │ own entry        |
//!  up_data  -----▶|  FIFO (depth D) ─▶ head ─▶ comparator ─▶ out reg|──▶ down_data
//!  up_valid -----▶|                                              |──▶ down_valid
//!  up_ready ◀-----|  (= FIFO not full, or the head leaves now)     |◀── down_ready
//!  free     ◀-----|  (no object, or the scan has passed its box)  |
//!                 +----------------------------------------------+
//! ```
//!
//! Per cycle, with `adv = !out_valid || down_ready` (the output register can take a slot), the OP
//! looks at the FIFO head H and its own entry O for H's pixel (from the `cur` accumulators):
//! * dropping the tail of a list (after a full entry in front): pop H, no output (needs no `adv`);
//! * H is a pixel's empty slot: emit O in its place if the object covers the pixel, else H; pop;
//! * O exists and is nearer than H (equal depths: lower id first): emit O without popping (a *jam*:
//!   the FIFO absorbs what arrives meanwhile); if O is full, drop the rest of the list;
//! * else emit H and pop; O is dropped if H is full; if H was the list's last slot and O is still
//!   pending, O is appended in the next cycle with `last`.
//!
//! `up_ready = fifo.len() < D || pop`: a FIFO of one slot keeps the full rate (pop-through), and the
//! ready path runs combinationally back through the chain. A pixel ends when its last slot leaves; if
//! the pixel is in the box, the accumulators then step to the next pixel of the box (dx per pixel; at
//! the box's right edge, dy to the next line's first pixel). The OP is *free* (can be loaded) before its
//! first object and once the box's last pixel has ended (OP reuse, §4.2).

use super::format::{own_entry, wrap, Entry, ObjectParams, Slot, ACC_BITS, EDGE_BITS};
use std::collections::VecDeque;

/// What the OP does in a cycle.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Action {
    Idle,
    /// Pop the head without output (tail of a list behind a full entry).
    Drop,
    /// Emit the head unchanged (or with `last` cleared) and pop it.
    EmitHead,
    /// Emit the own entry in place of an empty slot and pop it.
    EmitOwnReplace,
    /// Emit the own entry before the head; no pop.
    EmitOwnBefore,
    /// Append the own entry after the list's last slot; no pop.
    EmitOwnEnd,
}

/// Inputs of one cycle.
#[derive(Clone, Debug, Default)]
pub struct OpIn {
    pub up_valid: bool,
    pub up_data: Slot,
    pub down_ready: bool,
    /// Load a new object at this edge.
    pub load: Option<ObjectParams>,
}

/// Outputs of one cycle (before the edge).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct OpOut {
    pub up_ready: bool,
    pub down_valid: bool,
    pub down_data: Slot,
    pub free: bool,
}

/// The accumulators of the primitive processor: value at the current line's first box pixel (`row`)
/// and at the current (or next) box pixel (`cur`).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Accumulators {
    pub row_d: [i64; 3],
    pub cur_d: [i64; 3],
    pub row_z: i64,
    pub cur_z: i64,
    pub row_n: [i64; 3],
    pub cur_n: [i64; 3],
}

/// The registers of one object processor.
#[derive(Clone, Debug)]
pub struct OpModel {
    pub depth: usize,
    pub fifo: VecDeque<Slot>,
    pub out_valid: bool,
    pub out_data: Slot,
    /// Inside a pixel's list (its first slot has been handled).
    pub mid: bool,
    /// The own entry of the current pixel is still to be inserted.
    pub own_pending: bool,
    /// The list has ended; the own entry is appended next.
    pub tail: bool,
    /// Dropping the rest of the current list.
    pub dropping: bool,
    /// The current pixel and whether it is in the box.
    pub px: u16,
    pub py: u16,
    pub pix_act: bool,
    pub loaded: bool,
    pub done: bool,
    pub params: ObjectParams,
    pub acc: Accumulators,
    /// Action of the last step (for statistics and debugging).
    pub last_action: Action,
}

/// The combinational decisions of a cycle (what [`OpModel::outputs`] presents and [`OpModel::step`]
/// then does; the OPP model computes them once per cycle with [`OpModel::decide_outputs`]).
#[derive(Copy, Clone, Debug)]
pub struct Decision {
    action: Action,
    emit: Option<Slot>,
    pop: bool,
    starting: bool,
    act: bool,
    own: bool,
    end_pixel: bool,
    /// Coordinates of the pixel being handled.
    x: u16,
    y: u16,
}

impl OpModel {
    pub fn new(depth: usize) -> Result<OpModel, String> {
        if depth == 0 || depth > 64 {
            return Err(format!("FIFO depth {depth} is not supported: 1..=64 slots"));
        }
        Ok(OpModel {
            depth,
            fifo: VecDeque::with_capacity(depth),
            out_valid: false,
            out_data: Slot::default(),
            mid: false,
            own_pending: false,
            tail: false,
            dropping: false,
            px: 0,
            py: 0,
            pix_act: false,
            loaded: false,
            done: false,
            params: ObjectParams::default(),
            acc: Accumulators::default(),
            last_action: Action::Idle,
        })
    }

    /// Free for a new object (registered).
    pub fn free(&self) -> bool {
        !self.loaded || self.done
    }

    /// The own entry from the `cur` accumulators.
    pub fn own(&self) -> Option<Entry> {
        own_entry(&self.params, self.acc.cur_d, self.acc.cur_z, self.acc.cur_n)
    }

    fn decide(&self, down_ready: bool) -> Decision {
        let adv = !self.out_valid || down_ready;
        let mut d = Decision {
            action: Action::Idle,
            emit: None,
            pop: false,
            starting: false,
            act: self.pix_act,
            own: self.own_pending,
            end_pixel: false,
            x: self.px,
            y: self.py,
        };
        if self.mid && self.tail {
            if adv {
                let o = self.own().unwrap_or_default();
                d.action = Action::EmitOwnEnd;
                d.emit = Some(Slot { x: self.px, y: self.py, last: true, has_entry: true, entry: o });
                d.end_pixel = true;
            }
            return d;
        }
        let h = match self.fifo.front() {
            Some(h) => *h,
            None => return d,
        };
        d.starting = !self.mid;
        d.x = h.x;
        d.y = h.y;
        let o = self.own();
        if d.starting {
            d.act = self.loaded && !self.done && self.params.in_box(h.x, h.y);
            d.own = d.act && o.is_some();
        }
        let o = o.unwrap_or_default();
        if self.mid && self.dropping {
            d.action = Action::Drop;
            d.pop = true;
            d.end_pixel = h.last;
            return d;
        }
        if !adv {
            return d;
        }
        if !h.has_entry {
            d.pop = true;
            d.end_pixel = h.last;
            if d.own {
                d.action = Action::EmitOwnReplace;
                d.emit = Some(Slot { x: h.x, y: h.y, last: h.last, has_entry: true, entry: o });
            } else {
                d.action = Action::EmitHead;
                d.emit = Some(h);
            }
        } else if d.own && o.before(&h.entry) {
            d.action = Action::EmitOwnBefore;
            d.emit = Some(Slot { x: h.x, y: h.y, last: o.full, has_entry: true, entry: o });
        } else {
            d.action = Action::EmitHead;
            d.pop = true;
            let append = d.own && !h.entry.full;
            d.emit = Some(Slot { last: h.last && !append, ..h });
            d.end_pixel = h.last && !append;
        }
        d
    }

    /// The outputs of this cycle, given the downstream ready (Mealy: `up_ready` depends on it).
    pub fn outputs(&self, down_ready: bool) -> OpOut {
        let d = self.decide(down_ready);
        OpOut { up_ready: self.fifo.len() < self.depth || d.pop, down_valid: self.out_valid, down_data: self.out_data, free: self.free() }
    }

    /// This cycle's decisions and outputs, for [`OpModel::step_decided`].
    pub fn decide_outputs(&self, down_ready: bool) -> (Decision, OpOut) {
        let d = self.decide(down_ready);
        (d, OpOut { up_ready: self.fifo.len() < self.depth || d.pop, down_valid: self.out_valid, down_data: self.out_data, free: self.free() })
    }

    /// One clock: returns the outputs that were presented before the edge.
    pub fn step(&mut self, inp: &OpIn) -> OpOut {
        let (d, out) = self.decide_outputs(inp.down_ready);
        self.step_decided(inp, d);
        out
    }

    /// One clock with the decisions `decide_outputs(inp.down_ready)` already made this cycle.
    pub fn step_decided(&mut self, inp: &OpIn, d: Decision) {
        let up_ready = self.fifo.len() < self.depth || d.pop;
        self.last_action = d.action;
        // Output register.
        if let Some(s) = d.emit {
            self.out_valid = true;
            self.out_data = s;
        } else if inp.down_ready {
            self.out_valid = false;
        }
        // List state.
        match d.action {
            Action::Idle => {}
            _ => {
                if d.starting {
                    self.px = d.x;
                    self.py = d.y;
                    self.pix_act = d.act;
                }
                if d.end_pixel {
                    self.mid = false;
                    self.own_pending = false;
                    self.tail = false;
                    self.dropping = false;
                    if d.act {
                        self.step_accumulators(d.x, d.y);
                    }
                } else {
                    self.mid = true;
                    match d.action {
                        Action::EmitOwnBefore => {
                            self.own_pending = false;
                            self.dropping = self.own().map(|o| o.full).unwrap_or(false);
                        }
                        Action::EmitHead => {
                            let h = self.fifo.front().unwrap();
                            self.own_pending = d.own && !h.entry.full;
                            self.tail = h.last && self.own_pending;
                        }
                        Action::EmitOwnReplace => self.own_pending = false,
                        _ => {}
                    }
                }
            }
        }
        if d.pop {
            self.fifo.pop_front();
        }
        if inp.up_valid && up_ready {
            self.fifo.push_back(inp.up_data);
        }
        if let Some(p) = inp.load {
            self.params = p;
            self.loaded = true;
            self.done = false;
            let d = p.edges.map(|e| e.d0 as i64);
            let n = p.n.map(|n| n.v0);
            self.acc = Accumulators { row_d: d, cur_d: d, row_z: p.z.v0, cur_z: p.z.v0, row_n: n, cur_n: n };
        }
    }

    /// After the box pixel (x, y): step to the next box pixel.
    fn step_accumulators(&mut self, x: u16, y: u16) {
        let p = self.params;
        let a = &mut self.acc;
        if x == p.x1 {
            for k in 0..3 {
                a.row_d[k] = wrap(a.row_d[k] + 2 * p.edges[k].sin as i64, EDGE_BITS);
                a.cur_d[k] = a.row_d[k];
                a.row_n[k] = wrap(a.row_n[k] + p.n[k].dy, ACC_BITS);
                a.cur_n[k] = a.row_n[k];
            }
            a.row_z = wrap(a.row_z + p.z.dy, ACC_BITS);
            a.cur_z = a.row_z;
            if y == p.y1 {
                self.done = true;
            }
        } else {
            for k in 0..3 {
                a.cur_d[k] = wrap(a.cur_d[k] + 2 * p.edges[k].cos as i64, EDGE_BITS);
                a.cur_n[k] = wrap(a.cur_n[k] + p.n[k].dx, ACC_BITS);
            }
            a.cur_z = wrap(a.cur_z + p.z.dx, ACC_BITS);
        }
    }
}
