//! Seed 000 Table IV: the three hardware levels of the analysis, and the few numbers the paper states
//! about them in its text.
//!
//! The scan lost Table IV's cells. What the text of seed 000 §IV.A.1 fixes, and what is reconstructed:
//!
//! | level | triangles/s | frames/s | resolutions |
//! |---|---|---|---|
//! | high-performance | 2M (text) | 30 (text) | 1024x768 (**reconstructed**), 800x600 (text) |
//! | middle-performance | 480K (text) | 30 (text) | 800x600 (text), 640x480 (**reconstructed**: the models' native size, §IV.A.2) |
//! | low-end | 96K (text) | 24 (text) | 320x200 (text: the example of §IV.A.2, and seed 001's only size), 160x100 (**reconstructed**) |
//!
//! "Resolution 800x600 appears both on high-performance and middle-performance levels" is the only
//! statement about the pairs. The reconstructed sizes continue the ladder downwards from 800x600 with
//! the common sizes of the time. Our [`Screen`](crate::format::Screen) (10-bit pixel counters) ends at
//! 1024x1024, so a larger high-end size (e.g. 1280x1024) could not be rendered: 1024x768 is the largest
//! common size it holds. Everything downstream takes the level table as data, so another
//! reconstruction is a one-line change here.

/// One hardware level of seed 000 Table IV.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct HardwareLevel {
    pub name: &'static str,
    /// Triangle rate the level is specified for.
    pub triangles_per_second: u64,
    pub frames_per_second: u32,
    /// The two screen sizes analysed at this level, larger first.
    pub resolutions: [(u32, u32); 2],
    /// Which of the above is reconstructed rather than read from the text.
    pub reconstructed: &'static str,
}

impl HardwareLevel {
    /// The largest number of triangles in one frame: the size of the triangle databases and the range
    /// of the index (seed 000 §IV.C.1: "the length of index equals log2(maximal visible polygon
    /// number)"). Rounded up.
    pub fn triangles_per_frame(&self) -> u64 {
        self.triangles_per_second.div_ceil(self.frames_per_second as u64)
    }
}

/// Seed 000 Table IV as read from the text, with the missing resolutions reconstructed (see the module
/// documentation).
pub const TABLE_IV: [HardwareLevel; 3] = [
    HardwareLevel {
        name: "high",
        triangles_per_second: 2_000_000,
        frames_per_second: 30,
        resolutions: [(1024, 768), (800, 600)],
        reconstructed: "1024x768 (the scan lost Table IV; the largest common size our 1024x1024 screen holds)",
    },
    HardwareLevel {
        name: "middle",
        triangles_per_second: 480_000,
        frames_per_second: 30,
        resolutions: [(800, 600), (640, 480)],
        reconstructed: "640x480 (the models' native resolution in seed 000 §IV.A.2)",
    },
    HardwareLevel {
        name: "low",
        triangles_per_second: 96_000,
        frames_per_second: 24,
        resolutions: [(320, 200), (160, 100)],
        reconstructed: "160x100 (half of the stated 320x200 in each direction)",
    },
];

/// The level of the given name ("high", "middle", "low").
pub fn level(name: &str) -> Result<&'static HardwareLevel, String> {
    TABLE_IV.iter().find(|l| l.name == name).ok_or_else(|| {
        format!("unknown hardware level '{name}': the levels of seed 000 Table IV are high, middle, low")
    })
}

/// Numbers seed 000 states in its text (shown beside ours, labelled as the paper's, never as ours).
pub mod paper {
    /// §IV.C.2: "The size of TdbV is about 720 kB in high-performance, 168 kB in middle-performance, or
    /// 30 kB in low-end system", in the order of [`super::TABLE_IV`].
    pub const TDBV_KB: [f64; 3] = [720.0, 168.0, 30.0];
    /// §V: index rendering in the low-end system: "buffer size 130 kB-224 kB".
    pub const LOW_END_BUFFER_KB: (f64, f64) = (130.0, 224.0);
    /// §V: "bandwidth 15 MB/s-81 MB/s" (low-end, index rendering).
    pub const LOW_END_BANDWIDTH_MBS: (f64, f64) = (15.0, 81.0);
    /// §II.D: "16-32 bits are required to store a pixel in frame buffer".
    pub const FRAME_BUFFER_BITS: (u32, u32) = (16, 32);
    /// §III.A: "only 10-20 bits are required for each pixel" of the I-buffer.
    pub const INDEX_BITS: (u32, u32) = (10, 20);
    /// §II.D: "shading and texture parameters often over 100-200 [bits] for one pixel".
    pub const PIXEL_PARAMETER_BITS: (u32, u32) = (100, 200);
    /// Abstract and §V: lighting operations saved by index rendering, flat and Gouraud (percent).
    pub const LIGHTING_SAVED_FLAT_GOURAUD: (f64, f64) = (10.0, 70.0);
    /// Abstract and §V: lighting operations saved, Phong (percent).
    pub const LIGHTING_SAVED_PHONG: (f64, f64) = (30.0, 95.0);
    /// Abstract and §V: buffer size saved against deferred shading (percent).
    pub const BUFFER_SAVED: f64 = 70.0;
    /// Abstract and §V: bandwidth saved against deferred shading (percent).
    pub const BANDWIDTH_SAVED: (f64, f64) = (50.0, 70.0);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangles_per_frame_follow_from_rate_and_frame_rate() {
        assert_eq!(TABLE_IV[0].triangles_per_frame(), 66_667);
        assert_eq!(TABLE_IV[1].triangles_per_frame(), 16_000);
        assert_eq!(TABLE_IV[2].triangles_per_frame(), 4_000);
    }

    #[test]
    fn every_resolution_fits_the_screen_format_and_800x600_is_shared() {
        for l in &TABLE_IV {
            for (w, h) in l.resolutions {
                assert!(crate::format::Screen::new(w, h).is_ok(), "{w}x{h}");
            }
        }
        assert!(TABLE_IV[0].resolutions.contains(&(800, 600)) && TABLE_IV[1].resolutions.contains(&(800, 600)));
    }

    #[test]
    fn unknown_level_names_the_known_ones() {
        assert!(level("mid").unwrap_err().contains("high, middle, low"));
        assert_eq!(level("low").unwrap().frames_per_second, 24);
    }
}
