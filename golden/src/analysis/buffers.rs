//! Seed 000 §IV.C.1, Table VII and Fig. 10: the buffers of the four architecture types and their sizes.
//!
//! Naming: these are **seed 000's** Types I-IV, not seed 001's Type I/II (see [`super::cpu::CpuArch`]):
//!
//! | type | architecture (seed 000 Fig. 8) | buffers |
//! |---|---|---|
//! | I | traditional pipeline | frame buffer, Z-buffer |
//! | II | deferred shading ("direct method") | Z-buffer, pixel buffer |
//! | III | index rendering, depth regenerated from TdbV | I-buffer, TdbV, TdbS |
//! | IV | index rendering, depth in a Z-buffer | Z-buffer, I-buffer, TdbS |
//!
//! Table VII itself is garbled in the scan; the buffers per type are the text's (§IV.A.3: "Type I ...
//! equips the frame buffer and Z-buffer", "Type II ... needs Z-buffer ... and pixel buffer", "Type III
//! utilizes I-buffer and TdbV", "Type IV uses conventional Z-buffer"; TdbS is where both index-rendering
//! types keep the shading parameters, §III.B.2). Types II-IV shade at scan-out and need no frame buffer
//! (seed 001 §3.1: "frame buffer can be optional if the CS can generate pixels in screen scan-out
//! rate"); the texture buffer is left out as in the paper ("its size is user-defined").
//!
//! Sizes: a screen-size buffer has one entry per pixel; a triangle database one entry per triangle the
//! level allows in a frame ([`HardwareLevel::triangles_per_frame`]). 1 kB = 1000 bytes (the paper's
//! TdbV figures are round in decimal kB: 4000 x 60 bits = 30 kB).

use super::levels::{paper, HardwareLevel, TABLE_IV};
use crate::format::{DEPTH_BITS, PLANE_AB_BITS, PLANE_C_BITS};
use crate::shade::Shading;

/// Seed 000's architecture types.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Arch {
    /// Seed 000 Type I: traditional pipeline.
    TypeI,
    /// Seed 000 Type II: deferred shading.
    TypeII,
    /// Seed 000 Type III: index rendering, depth from TdbV + I-buffer.
    TypeIII,
    /// Seed 000 Type IV: index rendering, depth in a Z-buffer.
    TypeIV,
}

impl Arch {
    pub const ALL: [Arch; 4] = [Arch::TypeI, Arch::TypeII, Arch::TypeIII, Arch::TypeIV];

    /// The Roman numeral, as the paper labels its figures.
    pub fn numeral(self) -> &'static str {
        match self {
            Arch::TypeI => "I",
            Arch::TypeII => "II",
            Arch::TypeIII => "III",
            Arch::TypeIV => "IV",
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Arch::TypeI => "seed 000 Type I (traditional)",
            Arch::TypeII => "seed 000 Type II (deferred shading)",
            Arch::TypeIII => "seed 000 Type III (index rendering, TdbV + I-buffer)",
            Arch::TypeIV => "seed 000 Type IV (index rendering, Z-buffer + I-buffer)",
        }
    }

    /// The buffers this type equips.
    pub fn buffers(self) -> &'static [Buffer] {
        match self {
            Arch::TypeI => &[Buffer::Frame, Buffer::Z],
            Arch::TypeII => &[Buffer::Z, Buffer::Pixel],
            Arch::TypeIII => &[Buffer::I, Buffer::TdbV, Buffer::TdbS],
            Arch::TypeIV => &[Buffer::Z, Buffer::I, Buffer::TdbS],
        }
    }
}

/// The six buffers of Table VII.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Buffer {
    Frame,
    Z,
    Pixel,
    I,
    TdbS,
    TdbV,
}

impl Buffer {
    pub const ALL: [Buffer; 6] = [Buffer::Frame, Buffer::Z, Buffer::Pixel, Buffer::I, Buffer::TdbS, Buffer::TdbV];

    pub fn name(self) -> &'static str {
        match self {
            Buffer::Frame => "frame buffer",
            Buffer::Z => "Z-buffer",
            Buffer::Pixel => "pixel buffer",
            Buffer::I => "I-buffer",
            Buffer::TdbS => "TdbS",
            Buffer::TdbV => "TdbV",
        }
    }

    /// Whether the buffer has one entry per pixel (else one per triangle).
    pub fn screen_size(self) -> bool {
        matches!(self, Buffer::Frame | Buffer::Z | Buffer::Pixel | Buffer::I)
    }

    /// What the size depends on (Table VII's "parameters", from §IV.C.1's text).
    pub fn depends_on(self) -> &'static str {
        match self {
            Buffer::Frame => "resolution",
            Buffer::Z => "resolution",
            Buffer::Pixel => "resolution, shading method",
            Buffer::I => "resolution, scene complexity (index width)",
            Buffer::TdbS => "scene complexity, shading method",
            Buffer::TdbV => "scene complexity",
        }
    }

    /// What one entry holds.
    pub fn entry(self) -> &'static str {
        match self {
            Buffer::Frame => "RGB colour of the pixel",
            Buffer::Z => "depth of the nearest fragment",
            Buffer::Pixel => "a copy of the parent triangle's shading parameters (direct method)",
            Buffer::I => "index of the nearest triangle",
            Buffer::TdbS => "the triangle's shading parameters (colour or normal planes)",
            Buffer::TdbV => "the triangle's depth plane",
        }
    }
}

/// Bits per entry of each buffer (fractional where derived from a size the paper states).
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Widths {
    pub colour: f64,
    pub depth: f64,
    pub index: f64,
    pub pixel: f64,
    pub tdbs: f64,
    pub tdbv: f64,
}

impl Widths {
    pub fn of(&self, b: Buffer) -> f64 {
        match b {
            Buffer::Frame => self.colour,
            Buffer::Z => self.depth,
            Buffer::Pixel => self.pixel,
            Buffer::I => self.index,
            Buffer::TdbS => self.tdbs,
            Buffer::TdbV => self.tdbv,
        }
    }
}

/// Bits of a triangle index that can name `n` triangles plus the background code 0.
pub fn index_bits_for(n: u64) -> u32 {
    64 - n.leading_zeros()
}

/// Width of one [`crate::format::Plane`] as stored (A, B, C).
pub const PLANE_BITS: u32 = 2 * PLANE_AB_BITS + PLANE_C_BITS;
/// The material number a Phong TdbS record carries (`TdbsEntry::material`).
pub const MATERIAL_BITS: u32 = 16;

/// Our chipset's widths (golden::format) at a level: colour RGB888, depth 24, index wide enough for
/// the level's triangles per frame (the RTL's index width is a parameter; its default of 16 bits holds
/// 65535 triangles, one short of the high level's 66,667), one depth plane per TdbV record, three
/// planes per TdbS record (RGB for flat and Gouraud, the normal's x, y, z for Phong, plus the material
/// number). The pixel buffer of deferred shading holds a copy of the TdbS record per pixel.
pub fn ours(level: &HardwareLevel, shading: Shading) -> Widths {
    let tdbs = 3 * PLANE_BITS + if shading == Shading::Phong { MATERIAL_BITS } else { 0 };
    Widths {
        colour: 24.0,
        depth: DEPTH_BITS as f64,
        index: index_bits_for(level.triangles_per_frame()) as f64,
        pixel: tdbs as f64,
        tdbs: tdbs as f64,
        tdbv: PLANE_BITS as f64,
    }
}

/// The paper's widths, where it states them, and a reconstruction where it does not (Table VII's
/// width column is unreadable):
/// * index: the stated rule, log2 of the level's triangles per frame (rounded up); 12-17 bits,
///   within the stated "10-20 bits";
/// * TdbV: derived from the stated sizes (720 kB, 168 kB, 30 kB): 86.4, 84 and 60 bits per record;
/// * colour: 24 bits (**reconstructed**: the text says 16-32);
/// * depth: 24 bits at the high and middle levels, 16 at the low end (**reconstructed**: not stated;
///   the TdbV sizes fit three depth-plane coefficients of depth + 4 bits: 3 x 20 = 60, 3 x 28 = 84);
/// * pixel buffer and TdbS: 100 bits for Gouraud, 200 for Phong (**reconstructed** from "over 100-200"
///   bits of shading parameters per pixel; a TdbS record holds the same parameters once per triangle).
pub fn paper_widths(level: &HardwareLevel, shading: Shading) -> Widths {
    let li = TABLE_IV.iter().position(|l| l.name == level.name).unwrap_or(0);
    let n = level.triangles_per_frame() as f64;
    let params = if shading == Shading::Phong { paper::PIXEL_PARAMETER_BITS.1 } else { paper::PIXEL_PARAMETER_BITS.0 } as f64;
    Widths {
        colour: 24.0,
        depth: if level.name == "low" { 16.0 } else { 24.0 },
        index: index_bits_for(level.triangles_per_frame()) as f64,
        pixel: params,
        tdbs: params,
        tdbv: paper::TDBV_KB[li] * 1000.0 * 8.0 / n,
    }
}

/// Entries of a buffer: pixels for screen-size buffers, triangles per frame for the databases.
pub fn entries(b: Buffer, pixels: u64, triangles: u64) -> u64 {
    if b.screen_size() {
        pixels
    } else {
        triangles
    }
}

/// One buffer's size in bytes.
pub fn size_bytes(b: Buffer, w: &Widths, pixels: u64, triangles: u64) -> f64 {
    entries(b, pixels, triangles) as f64 * w.of(b) / 8.0
}

/// One type's buffers and their sizes (bytes), in the order of [`Arch::buffers`].
pub fn arch_sizes(arch: Arch, w: &Widths, pixels: u64, triangles: u64) -> Vec<(Buffer, f64)> {
    arch.buffers().iter().map(|&b| (b, size_bytes(b, w, pixels, triangles))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_width_holds_the_triangles_and_the_background_code() {
        assert_eq!(index_bits_for(65_535), 16);
        assert_eq!(index_bits_for(65_536), 17);
        assert_eq!(index_bits_for(66_667), 17);
        assert_eq!(index_bits_for(16_000), 14);
        assert_eq!(index_bits_for(4_000), 12);
    }

    #[test]
    fn paper_widths_reproduce_the_stated_tdbv_sizes() {
        for (l, kb) in TABLE_IV.iter().zip(paper::TDBV_KB) {
            let w = paper_widths(l, Shading::Gouraud);
            let got = size_bytes(Buffer::TdbV, &w, 1, l.triangles_per_frame()) / 1000.0;
            assert!((got - kb).abs() < 1e-6, "{}: {got} kB vs the paper's {kb}", l.name);
        }
        assert_eq!(paper_widths(&TABLE_IV[2], Shading::Gouraud).tdbv, 60.0);
        assert_eq!(paper_widths(&TABLE_IV[1], Shading::Gouraud).tdbv, 84.0);
    }

    #[test]
    fn our_records_are_the_golden_formats() {
        let w = ours(&TABLE_IV[2], Shading::Gouraud);
        assert_eq!(w.tdbv, 136.0);
        assert_eq!(w.tdbs, 408.0);
        assert_eq!(ours(&TABLE_IV[2], Shading::Phong).tdbs, 424.0);
        assert_eq!(w.depth, 24.0);
        assert_eq!(w.index, 12.0);
    }

    #[test]
    fn sizes_count_pixels_for_screen_buffers_and_triangles_for_databases() {
        let w = Widths { colour: 24.0, depth: 16.0, index: 12.0, pixel: 100.0, tdbs: 100.0, tdbv: 60.0 };
        let s = arch_sizes(Arch::TypeIII, &w, 64_000, 4_000);
        assert_eq!(s, vec![(Buffer::I, 96_000.0), (Buffer::TdbV, 30_000.0), (Buffer::TdbS, 50_000.0)]);
        let t1: f64 = arch_sizes(Arch::TypeI, &w, 64_000, 4_000).iter().map(|x| x.1).sum();
        assert_eq!(t1, 64_000.0 * 5.0);
    }
}
