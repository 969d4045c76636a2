//! Cycle-accurate model of PROOF's filter stage with the paper's 2x2 filter area (seed 002 §6: "the
//! filter area will be 2 x 2 pixels"): the RTL top `hdl::proof::filter2x2::Filter2x2Stage` must match
//! [`Filter2x2Model`] on every port in every cycle, and its box `hdl::proof::box2x2::Box2x2` must
//! match [`BoxModel`].
//!
//! ```text
//!   cfg (0: directions, 1: background, 2: opacities)
//!     │
//!   up ─▶ FilterFront F0..F4 ─▶ Q5 ─────────▶ Q6 ──────────────▶ box: A ─▶ H ─▶ V ─▶ OUT ─▶ down
//!  (shaded  (masks, weights,   quadrant       quadrant sums          line buffer     (one pixel per
//!   slots)   union)            weights,       += w_q c (pixel        of column sums   list, raster
//!                              coverage       state), out on last                      order)
//! ```
//!
//! The box of pixel (x, y) is the 2x2-pixel area centred on its centre: quadrant columns 2x-1..2x+2
//! and rows 2y-1..2y+2 of 4x4 subpixels, clamped to the screen so that the edge quadrants repeat
//! (`filter::box2`). The sums are linear, so the background is added once per box rather than per
//! quadrant: `Σ (entries_q + (16 - cov_q) bg) = Σ entries_q + (256 - Σ cov_q) bg`.
//!
//! Back end after the front's F4 (every register loads when `adv = !(Q6 holds a last slot) ||
//! box_up_ready`, a global stall; `up_ready = adv`):
//! * Q5: per quadrant q the weight `w_q` = F4's quadrant weight, the sum of the entry's blend
//!   weights over the quadrant's 16 subpixels in 1/256 (0..=4096; 256 per owned subpixel when the
//!   entry is opaque), and the coverage `c_q` = covered subpixels in q (the popcounts of F4's union
//!   mask);
//! * Q6: `acc_qk = sum_qk + w_q c_k` per quadrant and channel and `wacc_q = wsum_q + w_q` (the
//!   pixel state `sum`, `wsum` becomes `acc`, `wacc`, or 0 after the pixel's last slot). Q6 holds the
//!   word `(acc_qk + (256 c_q - wacc_q) bg_k + 128) >> 8`: the quadrant's blended sum with the
//!   background's share in its covered subpixels (their remaining transmittance), rounded to whole
//!   units, which is `filter::quadrant_sums_blended` less the `(16 - c_q) bg_k` of its uncovered
//!   subpixels (the box adds those). For an opaque list `wacc_q = 256 c_q` and the word is the
//!   unblended `Σ owned x colour`. Q6 holding a valid last slot *is* the box's input word.
//!
//! The box (register A, H, the line buffer's read register, V, OUT; same stall rule with
//! `adv = !out_valid || down_ready`, `up_ready = adv && !flushing`):
//! * A ← the input pixel, with `lt = left_top + q0 + q1`, `lb = left_bottom + q2 + q3` (left = the
//!   left neighbour's q1/q3, which A holds; at x = 0 the pixel's own q0/q2) and its q1, q3 and own
//!   coverage. A's pixel moves to H when the next pixel enters or, at x = W-1, at once.
//! * H ← A's pixel with `t = lt + right_top`, `b = lb + right_bottom` (right = the entering pixel's
//!   q0/q2; at x = W-1 A's own q1/q3). The line buffer is read at H's new column at the same edge.
//!   After H takes the frame's last pixel (W-1, H-1), the box flushes: H takes columns 0..W-1 of
//!   the last row again (`flush`), one per `adv`, and the input waits.
//! * V ← for a pixel of row y >= 1: the box of (x, y-1) = `line.s + t`; for a flush column: the box
//!   of (x, H-1) = `line.s + line.b`; row 0 gives none. A pixel's H also writes its column:
//!   `line.b = b`, `line.s = up + t + b` with `up` = the old `line.b`, or `t` in row 0 (the clamp).
//! * OUT ← `(box_k + (256 - box_cov) bg_k + 128) >> 8`, covered = the pixel's own coverage.
//!
//! Channels are indexed r, g, b, then 3 = coverage.

use super::cycle_filter::{filter_write, FilterFront, FilterOut, FilteredPixel, Tag};
use super::cycle_opp::GapRng;

/// Clocks from a frame's first slot to its last pixel leaving the 2x2 stage when nothing stalls (the
/// frame's slots one per clock, as the 1x1 stage's `slots + 8`): after the last slot, 7 registers to
/// the box's input (F0..F4, Q5, Q6), 1 edge for the last pixel to enter A and 1 to move on to H, W
/// flush columns through H, then V and OUT, and the clock in which the last pixel is taken.
pub fn filter2x2_frame_cycles(slots: usize, width: u32) -> u64 {
    slots as u64 + width as u64 + 11
}

/// One pixel's quadrant sums: per quadrant (q = 2 qy + qx) the entries' colour sums without the
/// background, and the covered subpixels.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct QuadPixel {
    pub x: u16,
    pub y: u16,
    /// `sum[q][k]`, 0..=4080.
    pub sum: [[u16; 3]; 4],
    /// Covered subpixels per quadrant, 0..=16.
    pub cov: [u8; 4],
}

impl QuadPixel {
    /// Quadrant q's value of channel k (3: coverage).
    pub fn ch(&self, q: usize, k: usize) -> u32 {
        if k == 3 {
            self.cov[q] as u32
        } else {
            self.sum[q][k] as u32
        }
    }
    /// The golden `quadrant_sums` value (background included) of quadrant q, channel k < 3.
    pub fn with_background(&self, q: usize, k: usize, bg: [u8; 3]) -> u32 {
        self.sum[q][k] as u32 + (16 - self.cov[q] as u32) * bg[k] as u32
    }
}

/// Box register A.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct BoxA {
    pub valid: bool,
    pub x: u16,
    pub y: u16,
    pub lt: [u32; 4],
    pub lb: [u32; 4],
    pub rt: [u32; 4],
    pub rb: [u32; 4],
    pub own: u8,
}

/// Box register H.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct BoxH {
    pub valid: bool,
    pub flush: bool,
    pub x: u16,
    pub y: u16,
    pub t: [u32; 4],
    pub b: [u32; 4],
    pub own: u8,
}

/// One line-buffer word.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct BoxLine {
    pub b: [u32; 4],
    pub s: [u32; 4],
    pub own: u8,
}

/// Box register V.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct BoxV {
    pub valid: bool,
    pub x: u16,
    pub y: u16,
    pub s: [u32; 4],
    pub own: u8,
}

/// Inputs of the box in one cycle.
#[derive(Copy, Clone, Debug, Default)]
pub struct BoxIn {
    pub up_valid: bool,
    pub up_data: QuadPixel,
    pub down_ready: bool,
    pub background: [u8; 3],
}

/// Outputs of the box in one cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct BoxOut {
    pub up_ready: bool,
    pub down_valid: bool,
    pub down_data: FilteredPixel,
}

/// The screen sizes the 2x2 RTL supports (the box's line buffer needs a width of at least 2).
pub fn check_box_size(width: u32, height: u32) -> Result<(), String> {
    if !(2..=1024).contains(&width) || !(1..=1024).contains(&height) {
        return Err(format!(
            "the 2x2 filter RTL does not support a {width}x{height} screen: the width must be 2..=1024 (the line buffer's \
             read-modify-write needs a column to come round no sooner than every second pixel) and the height 1..=1024"
        ));
    }
    Ok(())
}

/// The 2x2 box, register by register.
#[derive(Clone, Debug)]
pub struct BoxModel {
    pub width: u32,
    pub height: u32,
    pub a: BoxA,
    pub h: BoxH,
    /// The line buffer (one word per column) and its read register.
    pub line: Vec<BoxLine>,
    pub rd: BoxLine,
    pub flushing: bool,
    pub fx: u16,
    pub v: BoxV,
    pub out_valid: bool,
    pub out: FilteredPixel,
}

impl BoxModel {
    pub fn new(width: u32, height: u32) -> Result<BoxModel, String> {
        check_box_size(width, height)?;
        Ok(BoxModel {
            width,
            height,
            a: BoxA::default(),
            h: BoxH::default(),
            line: vec![BoxLine::default(); width as usize],
            rd: BoxLine::default(),
            flushing: false,
            fx: 0,
            v: BoxV::default(),
            out_valid: false,
            out: FilteredPixel::default(),
        })
    }

    pub fn outputs(&self, down_ready: bool) -> BoxOut {
        let adv = !self.out_valid || down_ready;
        BoxOut { up_ready: adv && !self.flushing, down_valid: self.out_valid, down_data: self.out }
    }

    /// Whether a pixel is inside the box or still to be emitted.
    pub fn busy(&self) -> bool {
        self.a.valid || self.h.valid || self.flushing || self.v.valid || self.out_valid
    }

    /// One clock; returns the outputs before the edge.
    pub fn step(&mut self, inp: &BoxIn) -> BoxOut {
        let out = self.outputs(inp.down_ready);
        let adv = !self.out_valid || inp.down_ready;
        if !adv {
            return out;
        }
        let (w1, h1) = ((self.width - 1) as u16, (self.height - 1) as u16);
        let take = inp.up_valid && out.up_ready;
        let a_end = self.a.x == w1;
        let a_moves = self.a.valid && (take || (a_end && !self.flushing));
        let p = &inp.up_data;

        // OUT.
        let v = self.v;
        self.out_valid = v.valid;
        let bgw = 256 - v.s[3];
        self.out = FilteredPixel {
            x: v.x,
            y: v.y,
            rgb: [0, 1, 2].map(|k| ((v.s[k] + bgw * inp.background[k] as u32 + 128) >> 8) as u8),
            covered: v.own,
        };

        // V and the column's write (the line buffer's read register holds H's column).
        let (h, rd) = (self.h, self.rd);
        self.v = BoxV {
            valid: h.valid && (h.flush || h.y != 0),
            x: h.x,
            // 10-bit row as in the RTL (row 0's don't-care wraps to 1023).
            y: if h.flush { h.y } else { h.y.wrapping_sub(1) & 0x3ff },
            s: [0, 1, 2, 3].map(|k| rd.s[k] + if h.flush { rd.b[k] } else { h.t[k] }),
            own: rd.own,
        };
        // The read at this edge returns the word before this edge's write.
        let read_at = if self.flushing { self.fx } else { self.a.x } as usize;
        let new_rd = self.line[read_at];
        if h.valid && !h.flush {
            let up = if h.y == 0 { h.t } else { rd.b };
            self.line[h.x as usize] = BoxLine { b: h.b, s: [0, 1, 2, 3].map(|k| up[k] + h.t[k] + h.b[k]), own: h.own };
        }
        self.rd = new_rd;

        // H: a flush column, A's pixel, or nothing.
        let a = self.a;
        if self.flushing {
            self.h = BoxH { valid: true, flush: true, x: self.fx, y: h1, ..self.h };
            if self.fx == w1 {
                self.flushing = false;
            }
            self.fx = (self.fx + 1) & 0x3ff;
        } else if a_moves {
            let right = |k: usize, q: usize| if a_end { if q == 0 { a.rt[k] } else { a.rb[k] } } else { p.ch(2 * q, k) };
            self.h = BoxH {
                valid: true,
                flush: false,
                x: a.x,
                y: a.y,
                t: [0, 1, 2, 3].map(|k| a.lt[k] + right(k, 0)),
                b: [0, 1, 2, 3].map(|k| a.lb[k] + right(k, 1)),
                own: a.own,
            };
            if a_end && a.y == h1 {
                self.flushing = true;
                self.fx = 0;
            }
        } else {
            self.h.valid = false;
        }

        // A: the entering pixel; its left neighbour's right quadrants (its own left ones at x = 0).
        if take {
            let left = |k: usize, q: usize| if p.x == 0 { p.ch(2 * q, k) } else if q == 0 { a.rt[k] } else { a.rb[k] };
            self.a = BoxA {
                valid: true,
                x: p.x,
                y: p.y,
                lt: [0, 1, 2, 3].map(|k| left(k, 0) + p.ch(0, k) + p.ch(1, k)),
                lb: [0, 1, 2, 3].map(|k| left(k, 1) + p.ch(2, k) + p.ch(3, k)),
                rt: [0, 1, 2, 3].map(|k| p.ch(1, k)),
                rb: [0, 1, 2, 3].map(|k| p.ch(3, k)),
                own: p.cov.iter().sum(),
            };
        } else if a_moves {
            self.a.valid = false;
        }
        out
    }
}

/// Q5: per quadrant the entry's weight (1/256 subpixels) and the covered subpixels.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct QuadWeightReg {
    pub tag: Tag,
    pub w: [u16; 4],
    pub cov: [u8; 4],
}

/// Q6: the pixel's quadrant words including this entry (module doc).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct QuadSumReg {
    pub tag: Tag,
    pub acc: [[u16; 3]; 4],
    pub cov: [u8; 4],
}

impl QuadSumReg {
    /// The box's input word when Q6 holds a pixel's last slot.
    pub fn word(&self) -> QuadPixel {
        QuadPixel { x: self.tag.slot.x, y: self.tag.slot.y, sum: self.acc, cov: self.cov }
    }
}

/// The mask of quadrant q (4x4 subpixels; bit 8 j + i).
pub fn quadrant_mask(q: usize) -> u64 {
    let (qx, qy) = (q % 2, q / 2);
    (0..4).fold(0u64, |m, j| m | 0xfu64 << (8 * (4 * qy + j) + 4 * qx))
}

/// Inputs of the 2x2 stage in one cycle (the same ports as the 1x1 stage).
pub use super::cycle_filter::FilterIn;

/// The filter stage with the 2x2 area, register by register.
#[derive(Clone, Debug)]
pub struct Filter2x2Model {
    pub front: FilterFront,
    pub background: [u8; 3],
    pub q5: QuadWeightReg,
    /// Pixel state: quadrant sums of the entries so far (weight x colour, 1/256) and their weights.
    pub qsum: [[u32; 3]; 4],
    pub wsum: [u16; 4],
    pub q6: QuadSumReg,
    pub boxm: BoxModel,
}

impl Filter2x2Model {
    /// A stage with a direction table of 2^`obj_addr_bits` entries for a `width` x `height` screen.
    pub fn new(obj_addr_bits: u32, width: u32, height: u32) -> Result<Filter2x2Model, String> {
        Ok(Filter2x2Model {
            front: FilterFront::new(obj_addr_bits)?,
            background: [0; 3],
            q5: QuadWeightReg::default(),
            qsum: [[0; 3]; 4],
            wsum: [0; 4],
            q6: QuadSumReg::default(),
            boxm: BoxModel::new(width, height)?,
        })
    }

    /// Q6 offers the box a word.
    pub fn q6_out(&self) -> bool {
        self.q6.tag.valid && self.q6.tag.slot.last
    }

    pub fn outputs(&self, down_ready: bool) -> FilterOut {
        let b = self.boxm.outputs(down_ready);
        FilterOut { up_ready: !self.q6_out() || b.up_ready, down_valid: b.down_valid, down_data: b.down_data }
    }

    pub fn busy(&self) -> bool {
        self.front.busy() || self.q5.tag.valid || self.q6.tag.valid || self.boxm.busy()
    }

    /// One clock; returns the outputs before the edge.
    pub fn step(&mut self, inp: &FilterIn) -> Result<FilterOut, String> {
        let out = self.outputs(inp.down_ready);
        // The box first: it reads Q6 as it is before this edge.
        self.boxm.step(&BoxIn { up_valid: self.q6_out(), up_data: self.q6.word(), down_ready: inp.down_ready, background: self.background });
        if out.up_ready {
            // Q6: multiply-add into the pixel's quadrant sums.
            let q5 = self.q5;
            let c = q5.tag.slot.rgb;
            let acc = [0, 1, 2, 3].map(|q| [0, 1, 2].map(|k| self.qsum[q][k] + q5.w[q] as u32 * c[k] as u32));
            let wacc = [0, 1, 2, 3].map(|q| self.wsum[q] + q5.w[q]);
            // The background's weight in the covered subpixels (13 bits as in the RTL; never
            // negative: each covered subpixel's weights sum to at most 256).
            let rem = [0, 1, 2, 3].map(|q| ((q5.cov[q] as u32) << 8).wrapping_sub(wacc[q] as u32) & 0x1fff);
            let bg = self.background;
            let word = [0, 1, 2, 3].map(|q| [0, 1, 2].map(|k| (((acc[q][k] + rem[q] * bg[k] as u32 + 128) >> 8) & 0xfff) as u16));
            self.q6 = QuadSumReg { tag: q5.tag, acc: word, cov: q5.cov };
            if q5.tag.valid {
                (self.qsum, self.wsum) = if q5.tag.slot.last { ([[0; 3]; 4], [0; 4]) } else { (acc, wacc) };
            }
            // Q5: F4's quadrant weights (1/256 subpixels) and the quadrant popcounts of its union mask.
            let f4 = self.front.f4;
            let ones = |m: u64| [0, 1, 2, 3].map(|q| (m & quadrant_mask(q)).count_ones() as u8);
            let wq = f4.quadrant_weights().map(|w| w as u16);
            self.q5 = QuadWeightReg { tag: f4.tag, w: wq, cov: ones(f4.union) };
            self.front.advance(inp.up_valid, &inp.up_data);
        }
        if let Some(c) = inp.cfg {
            filter_write(&mut self.front, &mut self.background, &c)?;
        }
        Ok(out)
    }
}

impl super::cycle_filter::FilterStageModel for Filter2x2Model {
    fn step(&mut self, inp: &FilterIn) -> Result<FilterOut, String> {
        Filter2x2Model::step(self, inp)
    }
}

/// Random but consistent quadrant sums for the box's tests: coverage 0..=16 with the extremes often,
/// colour sums up to 255 per covered subpixel and often exactly that (the most the front can produce;
/// the box's widths rely on it).
pub fn random_quads(w: u32, h: u32, rng: &mut GapRng) -> Vec<QuadPixel> {
    let mut r = |n: u32| -> u32 {
        let mut v = 0u32;
        for _ in 0..16 {
            v = 2 * v + rng.percent(50) as u32;
        }
        v % n
    };
    (0..w * h)
        .map(|p| {
            let mut qp = QuadPixel { x: (p % w) as u16, y: (p / w) as u16, ..Default::default() };
            for q in 0..4 {
                let c = match r(4) {
                    0 => 0,
                    1 => 16,
                    _ => r(17),
                };
                qp.cov[q] = c as u8;
                for k in 0..3 {
                    let max = 255 * c;
                    qp.sum[q][k] = if r(5) == 0 { max } else { r(max + 1) } as u16;
                }
            }
            qp
        })
        .collect()
}


/// The golden 2x2 filter (`filter::box2`) of a frame of quadrant sums on a background.
pub fn box2_of_quads(width: u32, height: u32, quads: &[QuadPixel], background: [u8; 3]) -> Vec<u8> {
    let q: Vec<[[u32; 3]; 4]> = quads.iter().map(|p| [0, 1, 2, 3].map(|q| [0, 1, 2].map(|k| p.with_background(q, k, background)))).collect();
    super::filter::box2(width, height, &q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proof::cycle_filter::fixtures::{real_frame, run_with_gaps, RealFrame, FIXTURE_BITS};
    use crate::proof::filter::FilterArea;
    use crate::proof::render::filter_lists;
    use crate::scene::builtin;

    fn run_box(m: &mut BoxModel, quads: &[QuadPixel], bg: [u8; 3], seed: u64, gin: u64, gout: u64) -> Vec<FilteredPixel> {
        let mut rng = GapRng(seed);
        let (mut i, mut out, mut idle) = (0, Vec::new(), 0);
        while out.len() < quads.len() {
            let go = i < quads.len() && !rng.percent(gin);
            let ready = !rng.percent(gout);
            let o = m.step(&BoxIn { up_valid: go, up_data: quads.get(i).copied().unwrap_or_default(), down_ready: ready, background: bg });
            if go && o.up_ready {
                i += 1;
            }
            if o.down_valid && ready {
                out.push(o.down_data);
                idle = 0;
            }
            idle += 1;
            assert!(idle < 10_000, "the box model hangs after {} pixels", out.len());
        }
        out
    }

    #[test]
    fn the_box_model_equals_the_golden_2x2_box_on_random_quadrant_sums_of_every_small_size_with_gaps() {
        let mut rng = GapRng(0xb0c5);
        for (w, h) in [(2, 1), (2, 2), (3, 1), (2, 5), (5, 2), (7, 4), (16, 3), (9, 9)] {
            for (frame, (seed, gin, gout)) in [(1, 0, 0), (5, 30, 30), (9, 60, 10), (13, 10, 70)].into_iter().enumerate() {
                let bg = [rng.percent(50) as u8 * 255, (seed * 37) as u8, 200];
                let quads = random_quads(w, h, &mut rng);
                let want = box2_of_quads(w, h, &quads, bg);
                // Two frames back to back through one model: the flush must leave it ready.
                let mut m = BoxModel::new(w, h).unwrap();
                for f in 0..2 {
                    let got = run_box(&mut m, &quads, bg, seed + f, gin, gout);
                    for (p, o) in got.iter().enumerate() {
                        let (x, y) = ((p as u32 % w) as u16, (p as u32 / w) as u16);
                        assert_eq!((o.x, o.y), (x, y), "{w}x{h} frame {frame}.{f}: order");
                        assert_eq!(o.rgb[..], want[3 * p..3 * p + 3], "{w}x{h} frame {frame}.{f}: pixel ({x}, {y})");
                        assert_eq!(o.covered as u32, quads[p].cov.iter().map(|&c| c as u32).sum::<u32>(), "{w}x{h}: covered");
                    }
                }
                assert!(!m.busy(), "{w}x{h}: the box should be empty after the flush");
            }
        }
    }

    #[test]
    fn the_2x2_cycle_model_equals_the_algorithmic_2x2_filter_on_real_lists_with_gaps() {
        for (mesh, w, h) in [(builtin::polyhedron(), 64, 40), (builtin::teapot(2), 48, 30)] {
            let RealFrame { sc, lists, colours, slots, cfg } = real_frame(&mesh, w, h);
            let (want_rgb, want_cov) = filter_lists(&sc, &lists, &colours, FilterArea::Box2);
            let (rgb1, _) = filter_lists(&sc, &lists, &colours, FilterArea::Box1);
            assert_ne!(want_rgb, rgb1, "{}: the 2x2 image should differ from the 1x1 one", mesh.name);
            for (seed, gin, gout) in [(1u64, 0u64, 0u64), (3, 30, 30), (17, 5, 60)] {
                let mut m = Filter2x2Model::new(FIXTURE_BITS, w, h).unwrap();
                let out = run_with_gaps(&mut m, &cfg, &slots, seed, gin, gout);
                assert_eq!(out.len(), (w * h) as usize);
                for (p, o) in out.iter().enumerate() {
                    let (x, y) = ((p as u32 % w) as u16, (p as u32 / w) as u16);
                    assert_eq!((o.x, o.y), (x, y), "{} pixel order", mesh.name);
                    assert_eq!(o.rgb[..], want_rgb[3 * p..3 * p + 3], "{} pixel ({x}, {y}) seed {seed}", mesh.name);
                    assert_eq!(o.covered, want_cov[p], "{} pixel ({x}, {y}) covered", mesh.name);
                }
            }
            // Without gaps: the frame takes its slots, the front's and Q's registers, the row of
            // lag and the flush.
            let mut m = Filter2x2Model::new(FIXTURE_BITS, w, h).unwrap();
            let (px, cycles) = super::super::cycle_filter::filter_slots(&mut m, &cfg, &slots, 4000).unwrap();
            assert_eq!(px.len(), (w * h) as usize);
            assert_eq!(cycles, filter2x2_frame_cycles(slots.len(), w), "{}: {} slots", mesh.name, slots.len());
        }
    }

    #[test]
    fn the_2x2_cycle_model_blends_transparent_lists_as_the_algorithmic_2x2_filter_with_gaps() {
        let mut half = builtin::teapot(2);
        for m in half.materials.iter_mut() {
            m.opacity = 0.5;
        }
        for (mesh, w, h) in [(builtin::glass(), 64, 40), (half, 48, 30)] {
            let RealFrame { sc, lists, colours, slots, cfg } = real_frame(&mesh, w, h);
            assert!(sc.objects.iter().any(|o| o.alpha < crate::proof::format::ALPHA_ONE), "{}: the frame should have transparent objects", mesh.name);
            let (want_rgb, want_cov) = filter_lists(&sc, &lists, &colours, FilterArea::Box2);
            // The same lists taken as opaque give another image: the blend is exercised.
            let (opaque_rgb, _) = crate::proof::render::filter_lists_opaque(&sc, &lists, &colours, FilterArea::Box2);
            assert_ne!(want_rgb, opaque_rgb, "{}", mesh.name);
            for (seed, gin, gout) in [(2u64, 0u64, 0u64), (5, 30, 30)] {
                let mut m = Filter2x2Model::new(FIXTURE_BITS, w, h).unwrap();
                let out = run_with_gaps(&mut m, &cfg, &slots, seed, gin, gout);
                assert_eq!(out.len(), (w * h) as usize);
                for (p, o) in out.iter().enumerate() {
                    assert_eq!(o.rgb[..], want_rgb[3 * p..3 * p + 3], "{} pixel {p} seed {seed}", mesh.name);
                    assert_eq!(o.covered, want_cov[p], "{} pixel {p} covered", mesh.name);
                }
            }
        }
    }

    #[test]
    fn a_screen_narrower_than_two_pixels_is_refused_with_the_reason() {
        let e = BoxModel::new(1, 10).unwrap_err();
        assert!(e.contains("1x10") && e.contains("width must be 2..=1024"), "{e}");
        assert!(Filter2x2Model::new(4, 1025, 10).is_err());
        assert!(Filter2x2Model::new(4, 2, 1).is_ok());
    }
}
