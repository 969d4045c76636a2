//! PROOF's 2x2 filter area (seed 002 §6: "the filter area will be 2 x 2 pixels"), streaming: a box of
//! 2x2 pixels centred on each pixel's centre, i.e. the pixel's own four quadrants of 4x4 subpixels,
//! the two nearest quadrants of each edge neighbour and the nearest quadrant of each corner
//! neighbour: 16 quadrants, 256 subpixels. Beyond the screen edge the edge quadrants repeat
//! (`golden::proof::filter::box2` clamps quadrant coordinates). Input: one pixel's quadrant sums per
//! transfer, a whole frame in raster order; output: one filtered pixel per input pixel, raster order.
//! Cycle behaviour: `golden::proof::cycle_filter2x2::BoxModel`, which the benches compare every cycle.
//!
//! ```text
//!                          background
//!                              │
//!            +─────────────────┴──────────────────────────────────────────────+
//! upstream ─▶| A ─────────▶ H ────────────▶ V ───────────────▶ OUT             |─▶ downstream
//! (QuadPixel)| left+own    T, B: + right    box = S + T        (box + (256 -   |   (FilteredPixel)
//!  .valid    | quadrants   quadrants        (flush: S + B)      cov) bg + 128)  |   .valid
//!  .ready  ◀─|             │ read  line[x]  │ write line[x] =   >> 8            |◀─ .ready
//!            |             └──────▶ (W x 112 bits) ◀ B, S=B'+T+B                 |
//!            +────────────────────────────────────────────────────────────────+
//! ```
//!
//! The box of pixel (x, y) spans quadrant columns 2x-1..2x+2 and rows 2y-1..2y+2. It is summed
//! horizontally first, then vertically, so one line buffer of per-column partial sums suffices:
//! * **A** holds the newest pixel with `L = left + q0 + q1` (top half) and `left + q2 + q3`
//!   (bottom), where `left` is the left neighbour's right quadrant (the pixel's own left one at x = 0).
//! * **H**: when the next pixel enters A, A's pixel moves to H with `T = L_top + right` and
//!   `B = L_bottom + right`, `right` being the next pixel's left quadrant; at the row's end (x = W-1)
//!   it moves on without waiting, with its own right quadrant (the clamp). The line buffer is read at
//!   this edge at the column of the pixel entering H.
//! * **V** (read-modify-write of line[x]): for a pixel of row y >= 1, the box of (x, y-1) is
//!   `S(x, y-1) + T(x, y)`; line[x] becomes `B(x, y)` and `S(x, y) = B(x, y-1) + T(x, y) + B(x, y)`
//!   (at y = 0 the top clamp: `T + T + B`). Row 0 gives no output.
//! * After the frame's last pixel (W-1, H-1) has entered H, the box **flushes**: for x = 0..W-1, H
//!   takes column x again and V emits the last row's box `S(x, H-1) + B(x, H-1)` (the bottom clamp).
//!   `upstream.ready` is low for these W cycles.
//! * **OUT**: the background fills the subpixels no entry covers: `colour = (box + (256 - covered)
//!   bg + 128) >> 8`; `covered` of the output is the pixel's own covered subpixels (stored with the
//!   column).
//!
//! Every register loads when `adv = !out_valid | downstream.ready` (a global stall);
//! `upstream.ready = adv & !flushing`, combinational as in the rest of the filter stage. One pixel per
//! clock in and out during a frame, plus W clocks of flush per frame. Without stalls, pixel (x, y) is
//! on `downstream` from the second edge after pixel (x+1, y+1) entered A (the third at the row's end,
//! x = W-1, where A's pixel moves on one edge after it entered); the last row comes out in the flush.
//! The line buffer is written one edge after the column's read, and a column is read again no sooner
//! than W-1 >= 1 edges after that, so no read sees a stale word; this is why the width must be at
//! least 2. Line buffer: 2^ceil(log2 W) words of 112 bits (the widths of `BoxLine`).

use super::table_ram::TableRam;
use super::types::{BoxA, BoxH, BoxLine, BoxV, FilteredPixel, QuadPixel};
use crate::common::{MulU, StreamIn, StreamOut};
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Box2x2 {
    pub clock: Signal<In, Clock>,
    // From the stage's configuration register
    /// Background colour (R bits 0-7, G 8-15, B 16-23) of the subpixels no entry covers.
    pub background: Signal<In, Bits<24>>,
    // From the quadrant sums
    /// One pixel's quadrant sums per transfer, a whole frame in raster order.
    pub upstream: StreamIn<QuadPixel>,
    // To the frame buffer
    /// The 2x2-filtered pixels, raster order.
    pub downstream: StreamOut<FilteredPixel>,

    // Registers and the line buffer (pub: the benches compare them with the model).
    pub a: DFF<BoxA>,
    pub h: DFF<BoxH>,
    pub line: TableRam<BoxLine>,
    pub flushing: DFF<Bit>,
    pub fx: DFF<Bits<10>>,
    pub v: DFF<BoxV>,
    pub out_valid: DFF<Bit>,
    pub out_data: DFF<FilteredPixel>,
    // Background weight times colour.
    bgm_r: MulU<9, 8, 17>,
    bgm_g: MulU<9, 8, 17>,
    bgm_b: MulU<9, 8, 17>,

    adv: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    a_end: Signal<Local, Bit>,
    a_moves: Signal<Local, Bit>,
    first: Signal<Local, Bit>,
    // A: the left quadrants, top and bottom (the pixel's own at x = 0).
    lt_r: Signal<Local, Bits<12>>,
    lt_g: Signal<Local, Bits<12>>,
    lt_b: Signal<Local, Bits<12>>,
    lt_c: Signal<Local, Bits<5>>,
    lb_r: Signal<Local, Bits<12>>,
    lb_g: Signal<Local, Bits<12>>,
    lb_b: Signal<Local, Bits<12>>,
    lb_c: Signal<Local, Bits<5>>,
    // H: the right quadrants, top and bottom (A's own at the row's end).
    rt_r: Signal<Local, Bits<12>>,
    rt_g: Signal<Local, Bits<12>>,
    rt_b: Signal<Local, Bits<12>>,
    rt_c: Signal<Local, Bits<5>>,
    rb_r: Signal<Local, Bits<12>>,
    rb_g: Signal<Local, Bits<12>>,
    rb_b: Signal<Local, Bits<12>>,
    rb_c: Signal<Local, Bits<5>>,
    // V: the fourth half-row (T of the next row, or B again in the flush), the first term of the
    // new S (B of the row above, or T again in row 0), the output row and the line word written.
    v4_r: Signal<Local, Bits<14>>,
    v4_g: Signal<Local, Bits<14>>,
    v4_b: Signal<Local, Bits<14>>,
    v4_c: Signal<Local, Bits<7>>,
    up_r: Signal<Local, Bits<14>>,
    up_g: Signal<Local, Bits<14>>,
    up_b: Signal<Local, Bits<14>>,
    up_c: Signal<Local, Bits<7>>,
    vy: Signal<Local, Bits<10>>,
    wr: Signal<Local, BoxLine>,
    // OUT.
    bgw: Signal<Local, Bits<9>>,
    t_r: Signal<Local, Bits<17>>,
    t_g: Signal<Local, Bits<17>>,
    t_b: Signal<Local, Bits<17>>,
    c_r: Signal<Local, Bits<17>>,
    c_g: Signal<Local, Bits<17>>,
    c_b: Signal<Local, Bits<17>>,
    wm1: Constant<Bits<10>>,
    hm1: Constant<Bits<10>>,
    zero10: Constant<Bits<10>>,
    one10: Constant<Bits<10>>,
    n256: Constant<Bits<9>>,
    half17: Constant<Bits<17>>,
}

/// Address bits of the line buffer for a screen `width` pixels wide.
pub fn line_bits(width: u32) -> usize {
    (u32::BITS - (width.max(2) - 1).leading_zeros()) as usize
}

impl Box2x2 {
    /// A box for a `width` x `height` screen: width 2..=1024, height 1..=1024.
    pub fn new(width: u32, height: u32) -> Result<Box2x2, String> {
        if !(2..=1024).contains(&width) || !(1..=1024).contains(&height) {
            return Err(format!(
                "the 2x2 filter RTL does not support a {width}x{height} screen: the width must be 2..=1024 (the line buffer's \
                 read-modify-write needs a column to come round no sooner than every second pixel) and the height 1..=1024"
            ));
        }
        Ok(Box2x2 {
            clock: Default::default(),
            background: Default::default(),
            upstream: Default::default(),
            downstream: Default::default(),
            a: Default::default(),
            h: Default::default(),
            line: TableRam::new(line_bits(width))?,
            flushing: Default::default(),
            fx: Default::default(),
            v: Default::default(),
            out_valid: Default::default(),
            out_data: Default::default(),
            bgm_r: Default::default(),
            bgm_g: Default::default(),
            bgm_b: Default::default(),
            adv: Default::default(),
            take: Default::default(),
            a_end: Default::default(),
            a_moves: Default::default(),
            first: Default::default(),
            lt_r: Default::default(),
            lt_g: Default::default(),
            lt_b: Default::default(),
            lt_c: Default::default(),
            lb_r: Default::default(),
            lb_g: Default::default(),
            lb_b: Default::default(),
            lb_c: Default::default(),
            rt_r: Default::default(),
            rt_g: Default::default(),
            rt_b: Default::default(),
            rt_c: Default::default(),
            rb_r: Default::default(),
            rb_g: Default::default(),
            rb_b: Default::default(),
            rb_c: Default::default(),
            v4_r: Default::default(),
            v4_g: Default::default(),
            v4_b: Default::default(),
            v4_c: Default::default(),
            up_r: Default::default(),
            up_g: Default::default(),
            up_b: Default::default(),
            up_c: Default::default(),
            vy: Default::default(),
            wr: Default::default(),
            bgw: Default::default(),
            t_r: Default::default(),
            t_g: Default::default(),
            t_b: Default::default(),
            c_r: Default::default(),
            c_g: Default::default(),
            c_b: Default::default(),
            wm1: Constant::new(((width - 1) as u64).into()),
            hm1: Constant::new(((height - 1) as u64).into()),
            zero10: Constant::new(0u64.into()),
            one10: Constant::new(1u64.into()),
            n256: Constant::new(256u64.into()),
            half17: Constant::new(128u64.into()),
        })
    }
}

impl Logic for Box2x2 {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, a, h, flushing, fx, v, out_valid, out_data);
        self.line.clock.next = self.clock.val();
        self.adv.next = !self.out_valid.q.val() | self.downstream.ready.val();
        self.upstream.ready.next = self.adv.val() & !self.flushing.q.val();
        self.take.next = self.upstream.valid.val() & self.adv.val() & !self.flushing.q.val();
        self.a_end.next = self.a.q.val().x == self.wm1.val();
        // A's pixel moves to H when the next pixel arrives, or at once at the row's end.
        self.a_moves.next = self.a.q.val().valid & (self.take.val() | (self.a_end.val() & !self.flushing.q.val()));
        self.first.next = self.upstream.data.val().x == self.zero10.val();
        self.downstream.valid.next = self.out_valid.q.val();
        self.downstream.data.next = self.out_data.q.val();

        // ---- A: the left neighbour's right quadrants, or at x = 0 the pixel's own left ones.
        self.lt_r.next = self.a.q.val().rt_r;
        self.lt_g.next = self.a.q.val().rt_g;
        self.lt_b.next = self.a.q.val().rt_b;
        self.lt_c.next = self.a.q.val().rt_c;
        self.lb_r.next = self.a.q.val().rb_r;
        self.lb_g.next = self.a.q.val().rb_g;
        self.lb_b.next = self.a.q.val().rb_b;
        self.lb_c.next = self.a.q.val().rb_c;
        if self.first.val() {
            self.lt_r.next = self.upstream.data.val().r0;
            self.lt_g.next = self.upstream.data.val().g0;
            self.lt_b.next = self.upstream.data.val().b0;
            self.lt_c.next = self.upstream.data.val().c0;
            self.lb_r.next = self.upstream.data.val().r2;
            self.lb_g.next = self.upstream.data.val().g2;
            self.lb_b.next = self.upstream.data.val().b2;
            self.lb_c.next = self.upstream.data.val().c2;
        }

        // ---- H: the next pixel's left quadrants, or at the row's end A's own right ones.
        self.rt_r.next = self.upstream.data.val().r0;
        self.rt_g.next = self.upstream.data.val().g0;
        self.rt_b.next = self.upstream.data.val().b0;
        self.rt_c.next = self.upstream.data.val().c0;
        self.rb_r.next = self.upstream.data.val().r2;
        self.rb_g.next = self.upstream.data.val().g2;
        self.rb_b.next = self.upstream.data.val().b2;
        self.rb_c.next = self.upstream.data.val().c2;
        if self.a_end.val() {
            self.rt_r.next = self.a.q.val().rt_r;
            self.rt_g.next = self.a.q.val().rt_g;
            self.rt_b.next = self.a.q.val().rt_b;
            self.rt_c.next = self.a.q.val().rt_c;
            self.rb_r.next = self.a.q.val().rb_r;
            self.rb_g.next = self.a.q.val().rb_g;
            self.rb_b.next = self.a.q.val().rb_b;
            self.rb_c.next = self.a.q.val().rb_c;
        }
        // The line buffer is read at the edge where H loads, at H's new column.
        self.line.read_enable.next = self.adv.val();
        self.line.read_address.next = bit_cast::<16, 10>(self.a.q.val().x);
        if self.flushing.q.val() {
            self.line.read_address.next = bit_cast::<16, 10>(self.fx.q.val());
        }

        // ---- V: the box is three half-rows from the line buffer plus a fourth.
        self.v4_r.next = self.h.q.val().t_r;
        self.v4_g.next = self.h.q.val().t_g;
        self.v4_b.next = self.h.q.val().t_b;
        self.v4_c.next = self.h.q.val().t_c;
        self.vy.next = self.h.q.val().y - self.one10.val();
        if self.h.q.val().flush {
            self.v4_r.next = self.line.read_data.val().b_r;
            self.v4_g.next = self.line.read_data.val().b_g;
            self.v4_b.next = self.line.read_data.val().b_b;
            self.v4_c.next = self.line.read_data.val().b_c;
            self.vy.next = self.h.q.val().y;
        }
        // The column's new word: at y = 0 the row above is the clamp (T again).
        self.up_r.next = self.line.read_data.val().b_r;
        self.up_g.next = self.line.read_data.val().b_g;
        self.up_b.next = self.line.read_data.val().b_b;
        self.up_c.next = self.line.read_data.val().b_c;
        if self.h.q.val().y == self.zero10.val() {
            self.up_r.next = self.h.q.val().t_r;
            self.up_g.next = self.h.q.val().t_g;
            self.up_b.next = self.h.q.val().t_b;
            self.up_c.next = self.h.q.val().t_c;
        }
        self.wr.next = self.line.read_data.val();
        self.wr.next.b_r = self.h.q.val().b_r;
        self.wr.next.b_g = self.h.q.val().b_g;
        self.wr.next.b_b = self.h.q.val().b_b;
        self.wr.next.b_c = self.h.q.val().b_c;
        self.wr.next.s_r = bit_cast::<16, 14>(self.up_r.val()) + bit_cast::<16, 14>(self.h.q.val().t_r) + bit_cast::<16, 14>(self.h.q.val().b_r);
        self.wr.next.s_g = bit_cast::<16, 14>(self.up_g.val()) + bit_cast::<16, 14>(self.h.q.val().t_g) + bit_cast::<16, 14>(self.h.q.val().b_g);
        self.wr.next.s_b = bit_cast::<16, 14>(self.up_b.val()) + bit_cast::<16, 14>(self.h.q.val().t_b) + bit_cast::<16, 14>(self.h.q.val().b_b);
        self.wr.next.s_c = bit_cast::<8, 7>(self.up_c.val()) + bit_cast::<8, 7>(self.h.q.val().t_c) + bit_cast::<8, 7>(self.h.q.val().b_c);
        self.wr.next.own = self.h.q.val().own;
        self.line.write_enable.next = self.adv.val() & self.h.q.val().valid & !self.h.q.val().flush;
        self.line.write_address.next = bit_cast::<16, 10>(self.h.q.val().x);
        self.line.write_data.next = self.wr.val();

        // ---- OUT: the background fills the uncovered subpixels of the 256; round and divide.
        self.bgw.next = self.n256.val() - self.v.q.val().s_c;
        self.bgm_r.a.next = self.bgw.val();
        self.bgm_g.a.next = self.bgw.val();
        self.bgm_b.a.next = self.bgw.val();
        self.bgm_r.b.next = self.background.val().get_bits::<8>(0);
        self.bgm_g.b.next = self.background.val().get_bits::<8>(8);
        self.bgm_b.b.next = self.background.val().get_bits::<8>(16);
        self.t_r.next = bit_cast::<17, 16>(self.v.q.val().s_r) + self.bgm_r.p.val();
        self.t_g.next = bit_cast::<17, 16>(self.v.q.val().s_g) + self.bgm_g.p.val();
        self.t_b.next = bit_cast::<17, 16>(self.v.q.val().s_b) + self.bgm_b.p.val();
        self.c_r.next = self.t_r.val() + self.half17.val();
        self.c_g.next = self.t_g.val() + self.half17.val();
        self.c_b.next = self.t_b.val() + self.half17.val();

        if self.adv.val() {
            // A.
            if self.take.val() {
                self.a.d.next.valid = true;
                self.a.d.next.x = self.upstream.data.val().x;
                self.a.d.next.y = self.upstream.data.val().y;
                self.a.d.next.lt_r = bit_cast::<14, 12>(self.lt_r.val()) + bit_cast::<14, 12>(self.upstream.data.val().r0) + bit_cast::<14, 12>(self.upstream.data.val().r1);
                self.a.d.next.lt_g = bit_cast::<14, 12>(self.lt_g.val()) + bit_cast::<14, 12>(self.upstream.data.val().g0) + bit_cast::<14, 12>(self.upstream.data.val().g1);
                self.a.d.next.lt_b = bit_cast::<14, 12>(self.lt_b.val()) + bit_cast::<14, 12>(self.upstream.data.val().b0) + bit_cast::<14, 12>(self.upstream.data.val().b1);
                self.a.d.next.lt_c = bit_cast::<6, 5>(self.lt_c.val()) + bit_cast::<6, 5>(self.upstream.data.val().c0) + bit_cast::<6, 5>(self.upstream.data.val().c1);
                self.a.d.next.lb_r = bit_cast::<14, 12>(self.lb_r.val()) + bit_cast::<14, 12>(self.upstream.data.val().r2) + bit_cast::<14, 12>(self.upstream.data.val().r3);
                self.a.d.next.lb_g = bit_cast::<14, 12>(self.lb_g.val()) + bit_cast::<14, 12>(self.upstream.data.val().g2) + bit_cast::<14, 12>(self.upstream.data.val().g3);
                self.a.d.next.lb_b = bit_cast::<14, 12>(self.lb_b.val()) + bit_cast::<14, 12>(self.upstream.data.val().b2) + bit_cast::<14, 12>(self.upstream.data.val().b3);
                self.a.d.next.lb_c = bit_cast::<6, 5>(self.lb_c.val()) + bit_cast::<6, 5>(self.upstream.data.val().c2) + bit_cast::<6, 5>(self.upstream.data.val().c3);
                self.a.d.next.rt_r = self.upstream.data.val().r1;
                self.a.d.next.rt_g = self.upstream.data.val().g1;
                self.a.d.next.rt_b = self.upstream.data.val().b1;
                self.a.d.next.rt_c = self.upstream.data.val().c1;
                self.a.d.next.rb_r = self.upstream.data.val().r3;
                self.a.d.next.rb_g = self.upstream.data.val().g3;
                self.a.d.next.rb_b = self.upstream.data.val().b3;
                self.a.d.next.rb_c = self.upstream.data.val().c3;
                self.a.d.next.own = bit_cast::<7, 5>(self.upstream.data.val().c0)
                    + bit_cast::<7, 5>(self.upstream.data.val().c1)
                    + bit_cast::<7, 5>(self.upstream.data.val().c2)
                    + bit_cast::<7, 5>(self.upstream.data.val().c3);
            } else if self.a_moves.val() {
                self.a.d.next.valid = false;
            }
            // H: a flush column, A's pixel, or nothing.
            if self.flushing.q.val() {
                self.h.d.next.valid = true;
                self.h.d.next.flush = true;
                self.h.d.next.x = self.fx.q.val();
                self.h.d.next.y = self.hm1.val();
                self.fx.d.next = self.fx.q.val() + self.one10.val();
                if self.fx.q.val() == self.wm1.val() {
                    self.flushing.d.next = false;
                }
            } else if self.a_moves.val() {
                self.h.d.next.valid = true;
                self.h.d.next.flush = false;
                self.h.d.next.x = self.a.q.val().x;
                self.h.d.next.y = self.a.q.val().y;
                self.h.d.next.t_r = self.a.q.val().lt_r + bit_cast::<14, 12>(self.rt_r.val());
                self.h.d.next.t_g = self.a.q.val().lt_g + bit_cast::<14, 12>(self.rt_g.val());
                self.h.d.next.t_b = self.a.q.val().lt_b + bit_cast::<14, 12>(self.rt_b.val());
                self.h.d.next.t_c = bit_cast::<7, 6>(self.a.q.val().lt_c) + bit_cast::<7, 5>(self.rt_c.val());
                self.h.d.next.b_r = self.a.q.val().lb_r + bit_cast::<14, 12>(self.rb_r.val());
                self.h.d.next.b_g = self.a.q.val().lb_g + bit_cast::<14, 12>(self.rb_g.val());
                self.h.d.next.b_b = self.a.q.val().lb_b + bit_cast::<14, 12>(self.rb_b.val());
                self.h.d.next.b_c = bit_cast::<7, 6>(self.a.q.val().lb_c) + bit_cast::<7, 5>(self.rb_c.val());
                self.h.d.next.own = self.a.q.val().own;
                if self.a_end.val() & (self.a.q.val().y == self.hm1.val()) {
                    self.flushing.d.next = true;
                    self.fx.d.next = self.zero10.val();
                }
            } else {
                self.h.d.next.valid = false;
            }
            // V.
            self.v.d.next.valid = self.h.q.val().valid & (self.h.q.val().flush | !(self.h.q.val().y == self.zero10.val()));
            self.v.d.next.x = self.h.q.val().x;
            self.v.d.next.y = self.vy.val();
            self.v.d.next.s_r = self.line.read_data.val().s_r + bit_cast::<16, 14>(self.v4_r.val());
            self.v.d.next.s_g = self.line.read_data.val().s_g + bit_cast::<16, 14>(self.v4_g.val());
            self.v.d.next.s_b = self.line.read_data.val().s_b + bit_cast::<16, 14>(self.v4_b.val());
            self.v.d.next.s_c = bit_cast::<9, 8>(self.line.read_data.val().s_c) + bit_cast::<9, 7>(self.v4_c.val());
            self.v.d.next.own = self.line.read_data.val().own;
            // OUT.
            self.out_valid.d.next = self.v.q.val().valid;
            self.out_data.d.next.x = self.v.q.val().x;
            self.out_data.d.next.y = self.v.q.val().y;
            self.out_data.d.next.r = self.c_r.val().get_bits::<8>(8);
            self.out_data.d.next.g = self.c_g.val().get_bits::<8>(8);
            self.out_data.d.next.b = self.c_b.val().get_bits::<8>(8);
            self.out_data.d.next.covered = self.v.q.val().own;
        }
    }
}

/// The Verilog of a 2x2 box for a `width` x `height` screen, top module named `name` (the box alone:
/// its bench replays random quadrant sums on it).
pub fn verilog_box2x2(name: &str, width: u32, height: u32) -> Result<String, String> {
    let mut uut = Box2x2::new(width, height)?;
    uut.connect_all();
    check_all(&uut).map_err(|e| format!("{name}: design check failed: {e:?}"))?;
    Ok(super::rename_top(&generate_verilog(&uut), name))
}
