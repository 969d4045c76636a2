//! proptest-generated triangle lists through the RC's RTL and its cycle model, every port every cycle,
//! with random command gaps and result back-pressure; the buffers must equal the algorithmic model's.
//! proptest shrinks a failing list to a minimal one (and keeps it in `proptest-regressions/`).
//! `PROPTEST_CASES` sets the number of lists (default 64: each is a short simulation).

use golden::cycle::rc::RcCmd;
use golden::format::{Screen, WinVertex, DEPTH_MAX, SUBPIXEL_HALF as H, SUBPIXEL_ONE as ONE};
use golden::raster::{CullMode, FrontFace};
use proptest::prelude::*;
use tb::rc::bench::{run_rtl, Drive};
use tb::rc::stimulus::{frame, reference};

/// A vertex in the guard band of a 24x16 screen ([-W, 2W) x [-H, 2H) pixels, in S11.8), clustered
/// around the screen so that most triangles touch it; depths anywhere, the far end often.
/// Half of the vertices sit on the half-pixel grid, so that edges run through pixel centres and the
/// fill rule decides.
fn vertex() -> impl Strategy<Value = WinVertex> {
    let z = || prop_oneof![0..=DEPTH_MAX, (DEPTH_MAX - 3)..=DEPTH_MAX, 1000u32..1004];
    prop_oneof![
        (-24 * ONE..48 * ONE, -16 * ONE..32 * ONE, z()).prop_map(|(x, y, z)| WinVertex { x, y, z }),
        (-48..96i32, -32..64i32, z()).prop_map(|(x, y, z)| WinVertex { x: H * x, y: H * y, z }),
    ]
}

/// Mostly small triangles on the screen: an anchor on the half-pixel grid plus offsets in half pixels,
/// often 0 (horizontal and vertical edges through pixel centres: where the fill rule decides); some
/// triangles anywhere in the guard band.
fn triangle() -> impl Strategy<Value = ([WinVertex; 3], u8, bool)> {
    let off = || prop_oneof![Just(0i32), -6..7i32];
    let small = (0..48i32, 0..32i32, 0..=DEPTH_MAX, off(), off(), off(), off()).prop_map(|(x, y, z, dx1, dy1, dx2, dy2)| {
        let a = WinVertex { x: H * x, y: H * y, z };
        let b = WinVertex { x: a.x + H * dx1, y: a.y + H * dy1, z: a.z };
        let c = WinVertex { x: a.x + H * dx2, y: a.y + H * dy2, z: a.z / 2 };
        [a, b, c]
    });
    let large = (vertex(), vertex(), vertex()).prop_map(|(a, b, c)| [a, b, c]);
    (prop_oneof![3 => small, 1 => large], 0u8..3, any::<bool>())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(64), ..ProptestConfig::default() })]

    #[test]
    fn rtl_equals_the_cycle_model_and_the_algorithmic_buffers_on_proptest_triangle_lists(
        tris in prop::collection::vec(triangle(), 1..24),
        gap in 0u8..50,
        stall in 0u8..50,
        seed in any::<u64>(),
    ) {
        let screen = Screen::new(24, 16).unwrap();
        let cmds: Vec<RcCmd> = tris
            .iter()
            .enumerate()
            .map(|(i, (v, cull, cw))| {
                let cull = [CullMode::Back, CullMode::Front, CullMode::None][*cull as usize];
                let front = if *cw { FrontFace::Cw } else { FrontFace::Ccw };
                RcCmd::triangle(i as u32 + 1, *v, cull, front).unwrap()
            })
            .collect();
        let cmds = frame(true, cmds);
        let drive = Drive { gap_percent: gap as u64, stall_percent: stall as u64, seed, garbage: true, stale_depth: false };
        let run = run_rtl("proptest_list", screen, &cmds, drive, None).map_err(TestCaseError::fail)?;
        let r = reference(screen, &cmds);
        prop_assert_eq!(run.results, r.results);
        prop_assert!(run.zbuf == r.zbuf, "Z-buffer differs from the algorithmic model");
        prop_assert!(run.ibuf == r.ibuf, "I-buffer differs from the algorithmic model");
    }
}
