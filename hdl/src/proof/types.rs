//! Payloads of the PROOF pipeline (seed 002 §4): the time slot that travels through the object
//! processors and the parameters an object processor is loaded with. Flat `LogicStruct`s (a struct
//! cannot hold `Signed<N>`, GUIDE §3): signed fields are stored as `Bits` and read with `signed_cast`.
//! Formats: `golden::proof::format` (distances 15 fraction bits in the OP, S1.14 in the slot; depth 24
//! bits; normals Q1.14; accumulators 32 bits).

use rust_hdl::prelude::*;

/// One time slot: one list entry of one pixel, or a pixel's single empty slot.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct ProofSlot {
    /// Pixel column and row.
    pub x: Bits<10>,
    pub y: Bits<10>,
    /// The pixel's final slot.
    pub last: bool,
    /// The slot holds an entry (else: the empty list of its pixel).
    pub has_entry: bool,
    /// Object id.
    pub id: Bits<16>,
    /// Depth, 0 = near.
    pub depth: Bits<24>,
    /// The object covers the pixel fully.
    pub full: bool,
    /// Interpolated normal, Q1.14 (signed).
    pub nx: Bits<16>,
    pub ny: Bits<16>,
    pub nz: Bits<16>,
    /// Distances of the pixel centre to the edges, S1.14 (signed).
    pub d0: Bits<16>,
    pub d1: Bits<16>,
    pub d2: Bits<16>,
}

/// What an object processor is loaded with (`golden::proof::format::ObjectParams`).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct ObjParams {
    pub id: Bits<16>,
    /// Bounding box, inclusive.
    pub x0: Bits<10>,
    pub x1: Bits<10>,
    pub y0: Bits<10>,
    pub y1: Bits<10>,
    /// Per edge: distance at the box's first pixel centre (27 bits, 15 fraction bits), steps per pixel
    /// (2 cos a) and per line (2 sin a) (17 bits), thresholds for "none" and "full" (18 bits, unsigned).
    pub e0_d: Bits<27>,
    pub e0_sx: Bits<17>,
    pub e0_sy: Bits<17>,
    pub e0_tn: Bits<18>,
    pub e0_tf: Bits<18>,
    pub e1_d: Bits<27>,
    pub e1_sx: Bits<17>,
    pub e1_sy: Bits<17>,
    pub e1_tn: Bits<18>,
    pub e1_tf: Bits<18>,
    pub e2_d: Bits<27>,
    pub e2_sx: Bits<17>,
    pub e2_sy: Bits<17>,
    pub e2_tn: Bits<18>,
    pub e2_tf: Bits<18>,
    /// Depth accumulator: start, step per pixel, step per line (4 fraction bits).
    pub z_v: Bits<32>,
    pub z_dx: Bits<32>,
    pub z_dy: Bits<32>,
    /// Normal accumulators (8 fraction bits on Q1.14).
    pub nx_v: Bits<32>,
    pub nx_dx: Bits<32>,
    pub nx_dy: Bits<32>,
    pub ny_v: Bits<32>,
    pub ny_dx: Bits<32>,
    pub ny_dy: Bits<32>,
    pub nz_v: Bits<32>,
    pub nz_dx: Bits<32>,
    pub nz_dy: Bits<32>,
    /// The object is opaque (issue 22): only then is its own entry full (covers the pixel and ends the
    /// list); a transparent object's entry is partial even where it covers the pixel completely.
    pub opaque: Bit,
}

/// What an object processor keeps of its [`ObjParams`] after the load: the id, the box, the steps, the
/// thresholds and the opacity. The start values (`e*_d`, `z_v`, `n*_v`) go straight into the
/// accumulators at the load and are never read again, so the OP does not store them (209 of the 732
/// bits).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct ObjSteps {
    pub id: Bits<16>,
    pub x0: Bits<10>,
    pub x1: Bits<10>,
    pub y0: Bits<10>,
    pub y1: Bits<10>,
    pub e0_sx: Bits<17>,
    pub e0_sy: Bits<17>,
    pub e0_tn: Bits<18>,
    pub e0_tf: Bits<18>,
    pub e1_sx: Bits<17>,
    pub e1_sy: Bits<17>,
    pub e1_tn: Bits<18>,
    pub e1_tf: Bits<18>,
    pub e2_sx: Bits<17>,
    pub e2_sy: Bits<17>,
    pub e2_tn: Bits<18>,
    pub e2_tf: Bits<18>,
    pub z_dx: Bits<32>,
    pub z_dy: Bits<32>,
    pub nx_dx: Bits<32>,
    pub nx_dy: Bits<32>,
    pub ny_dx: Bits<32>,
    pub ny_dy: Bits<32>,
    pub nz_dx: Bits<32>,
    pub nz_dy: Bits<32>,
    pub opaque: Bit,
}

/// A shaded time slot (shading stage -> filter): the slot without depth and normal, with the entry's
/// colour (0 for an empty slot).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct ShadedSlot {
    pub x: Bits<10>,
    pub y: Bits<10>,
    pub last: bool,
    pub has_entry: bool,
    pub id: Bits<16>,
    pub full: bool,
    /// Edge distances, S1.14 (signed).
    pub d0: Bits<16>,
    pub d1: Bits<16>,
    pub d2: Bits<16>,
    /// Colour of the entry.
    pub r: Bits<8>,
    pub g: Bits<8>,
    pub b: Bits<8>,
}

/// What one register of the shading pipeline holds (`golden::proof::cycle_shade::Work`).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct ShadeWork {
    /// The register holds an entry or empty slot of the stream.
    pub valid: bool,
    pub x: Bits<10>,
    pub y: Bits<10>,
    pub last: bool,
    pub has_entry: bool,
    pub id: Bits<16>,
    pub full: bool,
    pub d0: Bits<16>,
    pub d1: Bits<16>,
    pub d2: Bits<16>,
    /// Normal, Q1.14 (signed), not normalised.
    pub nx: Bits<16>,
    pub ny: Bits<16>,
    pub nz: Bits<16>,
    /// Material index and log2 of its gloss.
    pub mat: Bits<8>,
    pub gloss: Bits<3>,
    /// N.L clamped to [0, 1] (Q1.14) and the specular power (N.H)^k.
    pub nl: Bits<15>,
    pub sp: Bits<15>,
    /// Intensity sums per channel, 22 fraction bits.
    pub acc_r: Bits<40>,
    pub acc_g: Bits<40>,
    pub acc_b: Bits<40>,
}

/// What the filter stage's registers F1..F6 carry beside the arithmetic
/// (`golden::proof::cycle_filter::Tag`).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct FilterTag {
    /// The register holds a slot of the stream.
    pub valid: bool,
    pub x: Bits<10>,
    pub y: Bits<10>,
    /// The pixel's final slot.
    pub last: bool,
    pub has_entry: bool,
    pub full: bool,
    /// The entry's colour.
    pub r: Bits<8>,
    pub g: Bits<8>,
    pub b: Bits<8>,
    /// The entry's opacity, Q1.4 (0..=16), from the opacity table (from F1 on).
    pub alpha: Bits<5>,
}

/// One anti-aliased pixel leaving the filter stage (one per object list).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct FilteredPixel {
    pub x: Bits<10>,
    pub y: Bits<10>,
    pub r: Bits<8>,
    pub g: Bits<8>,
    pub b: Bits<8>,
    /// Subpixels covered by some object, 0..=64.
    pub covered: Bits<7>,
}

/// One pixel's quadrant sums (filter stage -> 2x2 box, seed 002 §6 "the filter area will be 2 x 2
/// pixels"): quadrant `q = 2 qy + qx` of 4x4 subpixels, q0 top left, q1 top right, q2 bottom left,
/// q3 bottom right (`golden::proof::filter::quadrant_sums` without the background term).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct QuadPixel {
    pub x: Bits<10>,
    pub y: Bits<10>,
    /// Per quadrant: the sum over the pixel's entries of (subpixels owned in the quadrant) x colour,
    /// 0..=4080 (the background is added by the box).
    pub r0: Bits<12>,
    pub r1: Bits<12>,
    pub r2: Bits<12>,
    pub r3: Bits<12>,
    pub g0: Bits<12>,
    pub g1: Bits<12>,
    pub g2: Bits<12>,
    pub g3: Bits<12>,
    pub b0: Bits<12>,
    pub b1: Bits<12>,
    pub b2: Bits<12>,
    pub b3: Bits<12>,
    /// Per quadrant: the subpixels some entry covers, 0..=16.
    pub c0: Bits<5>,
    pub c1: Bits<5>,
    pub c2: Bits<5>,
    pub c3: Bits<5>,
}

/// The 2x2 box's register A (`golden::proof::cycle_filter2x2::BoxA`): the newest pixel, with the
/// horizontal sums of its 3 own and left quadrant columns and its right quadrants.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct BoxA {
    pub valid: bool,
    pub x: Bits<10>,
    pub y: Bits<10>,
    /// Top half: left neighbour's right quadrant + own left + own right (colours, coverage).
    pub lt_r: Bits<14>,
    pub lt_g: Bits<14>,
    pub lt_b: Bits<14>,
    pub lt_c: Bits<6>,
    /// Bottom half, the same.
    pub lb_r: Bits<14>,
    pub lb_g: Bits<14>,
    pub lb_b: Bits<14>,
    pub lb_c: Bits<6>,
    /// Own right quadrants, top (q1) and bottom (q3): the next pixel's left neighbours.
    pub rt_r: Bits<12>,
    pub rt_g: Bits<12>,
    pub rt_b: Bits<12>,
    pub rt_c: Bits<5>,
    pub rb_r: Bits<12>,
    pub rb_g: Bits<12>,
    pub rb_b: Bits<12>,
    pub rb_c: Bits<5>,
    /// The pixel's own covered subpixels, 0..=64.
    pub own: Bits<7>,
}

/// The 2x2 box's register H: a column's horizontal sums over the box's 4 quadrant columns, top and
/// bottom half of one pixel row; or (`flush`) a column of the frame's last row to emit.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct BoxH {
    pub valid: bool,
    pub flush: bool,
    pub x: Bits<10>,
    pub y: Bits<10>,
    pub t_r: Bits<14>,
    pub t_g: Bits<14>,
    pub t_b: Bits<14>,
    pub t_c: Bits<7>,
    pub b_r: Bits<14>,
    pub b_g: Bits<14>,
    pub b_b: Bits<14>,
    pub b_c: Bits<7>,
    pub own: Bits<7>,
}

/// The 2x2 box's register V: the whole box's sums for one output pixel.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct BoxV {
    pub valid: bool,
    pub x: Bits<10>,
    pub y: Bits<10>,
    /// Colour sums of the 16 quadrants, 0..=65280.
    pub s_r: Bits<16>,
    pub s_g: Bits<16>,
    pub s_b: Bits<16>,
    /// Covered subpixels of the 16 quadrants, 0..=256.
    pub s_c: Bits<9>,
    /// The output pixel's own covered subpixels.
    pub own: Bits<7>,
}

/// One word of the 2x2 box's line buffer (one per screen column): what the next pixel row needs of
/// this column's box sums.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct BoxLine {
    /// The last row's bottom-half horizontal sums (B).
    pub b_r: Bits<14>,
    pub b_g: Bits<14>,
    pub b_b: Bits<14>,
    pub b_c: Bits<7>,
    /// The partial vertical sums S = B(row - 1) + T(row) + B(row): three of the box's four
    /// half-rows.
    pub s_r: Bits<16>,
    pub s_g: Bits<16>,
    pub s_b: Bits<16>,
    pub s_c: Bits<8>,
    /// The last row's pixel's own covered subpixels.
    pub own: Bits<7>,
}
