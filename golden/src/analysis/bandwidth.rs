//! Seed 000 §IV.C.2-3, Figs. 11-12: buffer bandwidth of the four types (seed 000's Types I-IV), worst
//! case and simulated.
//!
//! The paper gives no access model in readable form, so this one is written down here and used for
//! both figures. Per frame, with P the screen's pixels (clear and scan-out touch every one), F the
//! fragments (pixel rate), Zp the fragments that pass the depth test (reduced pixel rate), S the pixels
//! covered in the final image, T the triangles set up by the rasterizer, Tv the triangles flagged
//! visible (TdbS records written) and Rv the fragments that land on a pixel some triangle already owns
//! (Type III must fetch that triangle's depth plane from TdbV to compare), and Rs the TdbS records
//! fetched at scan-out (S when every covered pixel fetches; fewer with a one-record cache in the shader,
//! which refetches only when the index changes along the scan):
//!
//! | buffer | types | entry accesses per frame |
//! |---|---|---|
//! | Z-buffer | I, IV | clear P + read F + write Zp |
//! | Z-buffer | II | clear P + read F + write Zp + read P at scan-out (tells background from shaded pixels) |
//! | frame buffer | I | clear P + write Zp + read P at scan-out |
//! | pixel buffer | II | write Zp + read S at scan-out |
//! | I-buffer | III | clear P + read F (which TdbV record to fetch) + write Zp + read P at scan-out |
//! | I-buffer | IV | clear P + write Zp + read P at scan-out (its entry sits beside the Z entry, §III.B.3) |
//! | TdbV | III | write T + read Rv |
//! | TdbS | III, IV | write Tv + read Rs at scan-out |
//!
//! Bytes = accesses x bits per entry / 8; MB/s = bytes per frame x frames/s / 10^6. Texture traffic is
//! left out as the paper leaves the texture buffer out; the per-pixel texture-operation counts are in
//! [`super::lighting`].
//!
//! The worst case (Fig. 11) is the paper's "maximal allowed polygon number ... where all polygons are
//! visible in each frame": T = Tv = the level's triangles per frame, every pixel covered (S = P), and,
//! since all are visible, fragments arriving back to front so that every one passes (Zp = F), and no
//! locality for a TdbS cache (Rs = S). The
//! paper's pixel rate for that case is in the lost Table IV; here it is F = D x P with an assumed depth
//! complexity D (a parameter, reported with the results), and Rv = F - P.

use super::buffers::{Arch, Buffer, Widths};

/// Per-frame counts that drive the buffer traffic (f64: the worst case scales by a depth complexity).
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Traffic {
    pub pixels: f64,
    pub fragments: f64,
    pub z_passes: f64,
    pub covered: f64,
    pub triangles: f64,
    pub visible_triangles: f64,
    pub tdbv_reads: f64,
    pub tdbs_reads: f64,
}

impl Traffic {
    /// The worst case of Fig. 11: `triangles` all visible, depth complexity `depth` on every pixel.
    pub fn worst_case(pixels: u64, triangles: u64, depth: f64) -> Traffic {
        let p = pixels as f64;
        let f = depth * p;
        Traffic {
            pixels: p,
            fragments: f,
            z_passes: f,
            covered: p,
            triangles: triangles as f64,
            visible_triangles: triangles as f64,
            tdbv_reads: (f - p).max(0.0),
            tdbs_reads: p,
        }
    }
}

/// Entry accesses per frame of one buffer in one type (the table in the module documentation).
pub fn accesses(arch: Arch, b: Buffer, t: &Traffic) -> f64 {
    match (b, arch) {
        (Buffer::Z, Arch::TypeII) => t.pixels + t.fragments + t.z_passes + t.pixels,
        (Buffer::Z, _) => t.pixels + t.fragments + t.z_passes,
        (Buffer::Frame, _) => t.pixels + t.z_passes + t.pixels,
        (Buffer::Pixel, _) => t.z_passes + t.covered,
        (Buffer::I, Arch::TypeIII) => t.pixels + t.fragments + t.z_passes + t.pixels,
        (Buffer::I, _) => t.pixels + t.z_passes + t.pixels,
        (Buffer::TdbV, _) => t.triangles + t.tdbv_reads,
        (Buffer::TdbS, _) => t.visible_triangles + t.tdbs_reads,
    }
}

/// Bytes per frame of each of a type's buffers, in the order of [`Arch::buffers`].
pub fn bytes_per_frame(arch: Arch, w: &Widths, t: &Traffic) -> Vec<(Buffer, f64)> {
    arch.buffers().iter().map(|&b| (b, accesses(arch, b, t) * w.of(b) / 8.0)).collect()
}

/// MB/s (10^6 bytes per second) of a per-frame byte count at `fps`.
pub fn mb_per_s(bytes_per_frame: f64, fps: u32) -> f64 {
    bytes_per_frame * fps as f64 / 1e6
}

#[cfg(test)]
mod tests {
    use super::*;

    fn w() -> Widths {
        Widths { colour: 24.0, depth: 24.0, index: 16.0, pixel: 400.0, tdbs: 400.0, tdbv: 136.0 }
    }

    #[test]
    fn worst_case_counts_every_fragment_as_a_pass_and_every_pixel_as_covered() {
        let t = Traffic::worst_case(100, 10, 3.0);
        assert_eq!((t.fragments, t.z_passes, t.covered, t.tdbv_reads), (300.0, 300.0, 100.0, 200.0));
        assert_eq!((t.triangles, t.visible_triangles, t.tdbs_reads), (10.0, 10.0, 100.0));
    }

    #[test]
    fn traditional_traffic_is_clear_test_write_and_scanout() {
        // 10 pixels, 8 fragments, 5 passes: Z 10+8+5 entries of 3 bytes; frame 10+5+10 of 3 bytes.
        let t = Traffic { pixels: 10.0, fragments: 8.0, z_passes: 5.0, covered: 4.0, triangles: 3.0, visible_triangles: 2.0, tdbv_reads: 1.0, tdbs_reads: 4.0 };
        let b = bytes_per_frame(Arch::TypeI, &w(), &t);
        assert_eq!(b, vec![(Buffer::Frame, 75.0), (Buffer::Z, 69.0)]);
        let b3 = bytes_per_frame(Arch::TypeIII, &w(), &t);
        assert_eq!(b3, vec![(Buffer::I, 2.0 * 33.0), (Buffer::TdbV, 4.0 * 17.0), (Buffer::TdbS, 6.0 * 50.0)]);
        assert_eq!(mb_per_s(1e6, 30), 30.0);
    }

    #[test]
    fn deferred_shading_moves_pixel_traffic_into_the_wide_pixel_buffer() {
        let t = Traffic::worst_case(1000, 100, 2.0);
        let sum = |a| bytes_per_frame(a, &w(), &t).iter().map(|x| x.1).sum::<f64>();
        assert!(sum(Arch::TypeII) > sum(Arch::TypeIV) && sum(Arch::TypeIV) > sum(Arch::TypeI));
    }
}
