//! PROOF's number formats (seed 002 §4.4-§6): the one source of truth that `hdl/src/proof/` implements.
//!
//! | quantity | format | bits | why |
//! |---|---|---|---|
//! | edge direction cos a, sin a | signed Q1.14 | 16 | the edge's inward unit normal (seed 002 eq. 1), one 16-bit operand, the same format as the project's normals |
//! | edge distance d | signed, [`EDGE_FRAC`] = 15 fraction bits, pixels | [`EDGE_BITS`] = 27 | `(X+1/2) cos a` is exact with 15 fraction bits when cos a has 14, so the distance at a pixel centre is exact; inside the object's bounding box (at most 1024x1024) \|d\| < 1449 px < 2^11 |
//! | coverage thresholds r, r + delta | unsigned, 15 fraction bits | 18 | r = (\|cos a\| + \|sin a\|)/2 is the largest change of d from the pixel centre to a corner: exact in 15 fraction bits |
//! | depth accumulator | signed, [`DEPTH_FRAC`] = 4 fraction bits | 32 | 24-bit depth (the project's [`DEPTH_BITS`](crate::format::DEPTH_BITS)) with 3 guard bits for extrapolation outside thin objects |
//! | normal accumulator | signed, [`NORMAL_ACC_FRAC`] = 8 fraction bits | 32 | Q1.14 components with room for the extrapolation at partially covered pixels of slivers |
//! | list entry depth | unsigned | 24 | the accumulator's integer part clamped to 0..=2^24-1 |
//! | list entry normal | signed Q1.14 | 16 | saturated; not normalised (seed 002 §5.2.2 and appendix: normalisation omitted) |
//! | list entry distance | signed S1.14 | 16 | d rounded down to 14 fraction bits, saturated to [-2, 2): the filter only needs it within 1 px of the edge |
//! | object id | unsigned | [`ID_BITS`] = 16 | index into the look-up tables between the stages (seed 002 §3.1) |
//! | pixel x, y | unsigned | 10 | screens up to 1024x1024 |
//!
//! All interpolation is incremental in the object processor (seed 002 §4.4: "the distance d can be
//! easily computed incrementally"): a quantity v has a value v0 at the first pixel of the object's
//! bounding box (X0, Y0), a step per pixel `dx` and a step per line `dy`, and the accumulators wrap
//! (two's complement) at their width. Because of the wrap, incremental stepping and the direct
//! evaluation [`Interp::at`] give the same bits, which is what lets the algorithmic model and the RTL
//! agree exactly.

use crate::format::DEPTH_MAX;

/// Fraction bits of an edge distance (pixels).
pub const EDGE_FRAC: u32 = 15;
/// Width of the edge-distance accumulator.
pub const EDGE_BITS: u32 = 27;
/// Fraction bits of cos a and sin a (Q1.14).
pub const DIR_FRAC: u32 = 14;
/// Width of the coverage thresholds.
pub const THRESH_BITS: u32 = 18;
/// Fraction bits of the depth accumulator.
pub const DEPTH_FRAC: u32 = 4;
/// Fraction bits of the normal accumulators.
pub const NORMAL_ACC_FRAC: u32 = 8;
/// Width of the depth and normal accumulators and of their steps.
pub const ACC_BITS: u32 = 32;
/// Object-id width.
pub const ID_BITS: u32 = 16;
/// Pixel-coordinate width.
pub const COORD_BITS: u32 = 10;
/// Subpixels per pixel side in the filter (seed 002 §6: 8x8).
pub const SUBPIXELS: u32 = 8;
/// Opacity (issue 22): fraction bits of the object's opacity `alpha`, Q1.4 in 0..=[`ALPHA_ONE`] (5-bit
/// field): sixteenths, so that the filter's per-subpixel weight `T a` is a 9x5-bit product (a few
/// shifted adds) instead of a 9x9 multiplier per subpixel; the error this costs is measured in
/// docs/proof.md (eighths cost three times as much on `glass`).
pub const ALPHA_FRAC: u32 = 4;
/// The opacity of an opaque object (1.0 in Q1.4).
pub const ALPHA_ONE: u16 = 1 << ALPHA_FRAC;

/// A material's opacity (0..=1) in the object's Q1.4 form: `round(opacity x 16)`, except that only an
/// opacity of 1 (or more, or a NaN, which [`crate::scene::Mesh::validate`] refuses before this) is
/// opaque: anything below 1 stays transparent, at most 15/16, so the lists keep what lies behind it.
pub fn alpha_q(opacity: f64) -> u16 {
    if opacity.is_nan() || opacity >= 1.0 {
        return ALPHA_ONE;
    }
    ((opacity.max(0.0) * ALPHA_ONE as f64).round() as u16).min(ALPHA_ONE - 1)
}

/// Wrap to a signed two's-complement value of `bits` bits.
pub fn wrap(v: i64, bits: u32) -> i64 {
    let s = 64 - bits;
    (v << s) >> s
}

/// Saturate to a signed range of `bits` bits.
pub fn sat(v: i64, bits: u32) -> i64 {
    let max = (1i64 << (bits - 1)) - 1;
    v.clamp(-max - 1, max)
}

/// A linearly interpolated quantity in an object processor: value `v0` at the bounding box's first
/// pixel (X0, Y0), steps `dx` per pixel and `dy` per line, all wrapping at `bits`.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Interp {
    pub v0: i64,
    pub dx: i64,
    pub dy: i64,
}

impl Interp {
    /// The value at pixel (x0 + i, y0 + j): what `j` line steps and `i` pixel steps give.
    pub fn at(&self, i: i64, j: i64, bits: u32) -> i64 {
        wrap(self.v0.wrapping_add(self.dx.wrapping_mul(i)).wrapping_add(self.dy.wrapping_mul(j)), bits)
    }
}

/// One edge of an object in normal form `d = x cos a + y sin a - p` (seed 002 eq. 1), d > 0 inside.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct EdgeParams {
    /// cos a, Q1.14.
    pub cos: i16,
    /// sin a, Q1.14.
    pub sin: i16,
    /// d at the centre of pixel (X0, Y0), 15 fraction bits.
    pub d0: i32,
    /// "None" if d <= -t_none at the pixel centre: r = (|cos a| + |sin a|) / 2, 15 fraction bits.
    pub t_none: u32,
    /// "Full" needs d >= t_full at the pixel centre: r plus the bound of the fixed-point line's
    /// deviation from the true edge over the bounding box.
    pub t_full: u32,
}

impl EdgeParams {
    /// The distance-accumulator view: steps 2 cos a per pixel and 2 sin a per line (Q1.14 -> 15 bits).
    pub fn interp(&self) -> Interp {
        Interp { v0: self.d0 as i64, dx: 2 * self.cos as i64, dy: 2 * self.sin as i64 }
    }
}

/// Everything an object processor is loaded with (seed 002 §4.3: "registers which store the
/// parameters which describe the stored object").
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct ObjectParams {
    pub id: u16,
    /// Bounding box: the pixels whose square meets the object's vertex extent (clamped to the screen).
    pub x0: u16,
    pub x1: u16,
    pub y0: u16,
    pub y1: u16,
    pub edges: [EdgeParams; 3],
    /// Depth accumulator ([`DEPTH_FRAC`] fraction bits, [`ACC_BITS`] wide).
    pub z: Interp,
    /// Eye-space normal components ([`NORMAL_ACC_FRAC`] fraction bits on Q1.14, [`ACC_BITS`] wide).
    pub n: [Interp; 3],
    /// Opacity, Q1.4 ([`ALPHA_ONE`] = opaque). Only an opaque full entry ends a pixel's list; the filter
    /// blends the others (golden model only so far: the RTL backends refuse transparent objects).
    pub alpha: u16,
}

impl Default for ObjectParams {
    /// An empty, opaque object (what an unloaded OP holds).
    fn default() -> Self {
        ObjectParams { id: 0, x0: 0, x1: 0, y0: 0, y1: 0, edges: Default::default(), z: Default::default(), n: Default::default(), alpha: ALPHA_ONE }
    }
}

/// Coverage of a pixel by an object (seed 002 §4.5), ternary.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Coverage {
    None,
    Partial,
    Full,
}

/// One entry of a pixel's object list: what the later stages need (seed 002 §4.1).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Entry {
    pub id: u16,
    /// Depth, 24 bits, 0 = near.
    pub depth: u32,
    /// The object covers the pixel completely (else partially).
    pub full: bool,
    /// Interpolated normal, Q1.14, not normalised.
    pub normal: [i16; 3],
    /// Distances of the pixel centre to the three edges, S1.14 saturated.
    pub dist: [i16; 3],
}

impl Entry {
    /// List order: nearer first; of equal depths the lower object id first.
    pub fn before(&self, other: &Entry) -> bool {
        (self.depth, self.id) < (other.depth, other.id)
    }
}

/// Bits of one time slot in the RTL (`hdl::proof::ProofSlot::BITS`, checked by a tb test): the width
/// of the feedback memory that stores a pass's output stream.
pub const SLOT_BITS: u64 = 159;

/// One time slot of the pixel stream through the OPP: one list entry of one pixel, or the single
/// empty slot of a pixel whose list is empty. `last` marks a pixel's final slot.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Slot {
    pub x: u16,
    pub y: u16,
    pub last: bool,
    pub has_entry: bool,
    pub entry: Entry,
}

impl Slot {
    /// The slot the geometry processor pushes for a pixel: an empty list.
    pub fn empty(x: u16, y: u16) -> Slot {
        Slot { x, y, last: true, has_entry: false, entry: Entry::default() }
    }
}

/// The object's own entry at pixel (x, y) given its accumulator values there: `d` (edge distances,
/// 15 fraction bits), `z` and `n` (accumulators). This is the object processor's combinational output
/// (primitive processor, seed 002 Fig. 2); `None` when the object does not cover the pixel at all.
pub fn own_entry(p: &ObjectParams, d: [i64; 3], z: i64, n: [i64; 3]) -> Option<Entry> {
    let cov = classify(p, d);
    if cov == Coverage::None {
        return None;
    }
    Some(Entry {
        id: p.id,
        depth: (z >> DEPTH_FRAC).clamp(0, DEPTH_MAX as i64) as u32,
        full: cov == Coverage::Full && p.alpha >= ALPHA_ONE,
        normal: n.map(|v| sat(v >> NORMAL_ACC_FRAC, 16) as i16),
        dist: d.map(|v| sat(v >> (EDGE_FRAC - DIR_FRAC), 16) as i16),
    })
}

/// The grown-triangle test (seed 002 §4.5), good-natured: none if the centre is at least r outside one
/// edge, full if it is at least r + delta inside all three, else partial.
pub fn classify(p: &ObjectParams, d: [i64; 3]) -> Coverage {
    if (0..3).any(|i| d[i] <= -(p.edges[i].t_none as i64)) {
        Coverage::None
    } else if (0..3).all(|i| d[i] >= p.edges[i].t_full as i64) {
        Coverage::Full
    } else {
        Coverage::Partial
    }
}

impl ObjectParams {
    /// Whether pixel (x, y) is in the bounding box.
    pub fn in_box(&self, x: u16, y: u16) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    /// The pixels of row `y` of the bounding box that may have an entry: those where no edge says
    /// "none" (`d <= -t_none` at the centre), from each edge's distance, which is affine along the row
    /// (`d0 + 2 cos a * i + 2 sin a * j`, exact integers inside the box). A superset, never fewer: the
    /// caller still asks [`ObjectParams::entry_at`]. `None`: no pixel of the row. Where a distance
    /// would wrap in its register along the row (it does not inside a box, see the formats table),
    /// the whole row is returned.
    pub fn row_span(&self, y: u16) -> Option<(u16, u16)> {
        if y < self.y0 || y > self.y1 {
            return None;
        }
        let (j, w) = (y as i64 - self.y0 as i64, self.x1 as i64 - self.x0 as i64);
        let (mut lo, mut hi) = (0i64, w);
        for e in &self.edges {
            let f = e.interp();
            let row = f.v0 + f.dy * j;
            if [row, row + f.dx * w].iter().any(|&v| wrap(v, EDGE_BITS) != v) {
                return Some((self.x0, self.x1));
            }
            // Possibly covered where row + dx * i > -t, i.e. dx * i > k.
            let k = -(e.t_none as i64) - row;
            if f.dx > 0 {
                lo = lo.max(k.div_euclid(f.dx));
            } else if f.dx < 0 {
                hi = hi.min((-k).div_euclid(-f.dx) + 1);
            } else if row <= -(e.t_none as i64) {
                return None;
            }
        }
        (lo <= hi).then(|| (self.x0 + lo as u16, self.x0 + hi as u16))
    }

    /// The accumulator values at pixel (x, y) of the bounding box, by direct evaluation.
    pub fn accumulators_at(&self, x: u16, y: u16) -> ([i64; 3], i64, [i64; 3]) {
        let (i, j) = (x as i64 - self.x0 as i64, y as i64 - self.y0 as i64);
        (
            self.edges.map(|e| e.interp().at(i, j, EDGE_BITS)),
            self.z.at(i, j, ACC_BITS),
            self.n.map(|n| n.at(i, j, ACC_BITS)),
        )
    }

    /// The object's entry at pixel (x, y), or `None` outside the box or when not covered.
    pub fn entry_at(&self, x: u16, y: u16) -> Option<Entry> {
        if !self.in_box(x, y) {
            return None;
        }
        let (d, z, n) = self.accumulators_at(x, y);
        own_entry(self, d, z, n)
    }

    /// The coverage at pixel (x, y) (none outside the box).
    pub fn coverage_at(&self, x: u16, y: u16) -> Coverage {
        if !self.in_box(x, y) {
            return Coverage::None;
        }
        classify(self, self.accumulators_at(x, y).0)
    }

    /// Raster position of the first and last pixel of the box (for loading order and OP reuse).
    pub fn first_pixel(&self, width: u32) -> u64 {
        self.y0 as u64 * width as u64 + self.x0 as u64
    }
    pub fn last_pixel(&self, width: u32) -> u64 {
        self.y1 as u64 * width as u64 + self.x1 as u64
    }
}

/// Insert an object's own entry into a sorted, truncated list (the comparator's rule, seed 002 §4.3):
/// at its place by depth; if an entry before it covers the pixel fully it is dropped; if it covers the
/// pixel fully, everything behind it is dropped.
pub fn insert(list: &mut Vec<Entry>, own: Entry) {
    let pos = list.iter().position(|e| own.before(e)).unwrap_or(list.len());
    if list[..pos].iter().any(|e| e.full) {
        return;
    }
    list.insert(pos, own);
    if own.full {
        list.truncate(pos + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_and_sat_behave_like_twos_complement_registers() {
        assert_eq!(wrap(1 << 26, 27), -(1 << 26));
        assert_eq!(wrap(-(1 << 26) - 1, 27), (1 << 26) - 1);
        assert_eq!(sat(40000, 16), 32767);
        assert_eq!(sat(-40000, 16), -32768);
    }

    #[test]
    fn incremental_stepping_equals_direct_evaluation_even_when_wrapping() {
        let ip = Interp { v0: (1 << 30) - 5, dx: 123_456_789, dy: -987_654_321 };
        let mut row = ip.v0;
        for j in 0..40 {
            let mut v = row;
            for i in 0..50 {
                assert_eq!(v, ip.at(i, j, 32), "({i},{j})");
                v = wrap(v + ip.dx, 32);
            }
            row = wrap(row + ip.dy, 32);
        }
    }

    #[test]
    fn a_full_entry_drops_everything_behind_it_and_hides_what_follows() {
        let e = |id: u16, depth: u32, full: bool| Entry { id, depth, full, ..Default::default() };
        let mut l = vec![e(1, 10, false), e(2, 20, false), e(3, 30, true)];
        insert(&mut l, e(4, 15, true));
        assert_eq!(l.iter().map(|x| x.id).collect::<Vec<_>>(), vec![1, 4]);
        insert(&mut l, e(5, 16, false));
        assert_eq!(l.iter().map(|x| x.id).collect::<Vec<_>>(), vec![1, 4]);
        insert(&mut l, e(0, 15, false));
        assert_eq!(l.iter().map(|x| x.id).collect::<Vec<_>>(), vec![1, 0, 4], "equal depth: lower id first");
    }
}
