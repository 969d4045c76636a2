//! Seed 000's Type III (no Z-buffer, the old depth regenerated from TdbV) draws what Type IV (Z-buffer)
//! draws: the same I-buffer, image, per-triangle results and depths, on the built-in scenes and on
//! random triangles that interpenetrate, share planes or repeat each other exactly. Where the two can
//! differ (one index used by two triangles of a frame) the difference is shown.

use golden::format::{Screen, WinVertex, DEPTH_MAX, SUBPIXEL_ONE as ONE};
use golden::raster::{CullMode, FrontFace, RcType, Rasterizer};
use golden::render::{render, RenderOptions};
use golden::scene::builtin;
use golden::shade::Shading;
use proptest::prelude::*;

fn draw_both(tris: &[(u32, [WinVertex; 3])], screen: Screen, cull: CullMode) -> (Rasterizer, Rasterizer, Vec<bool>, Vec<bool>) {
    let mut iv = Rasterizer::of_type(screen, RcType::IV);
    let mut iii = Rasterizer::of_type(screen, RcType::III);
    let a: Vec<bool> = tris.iter().map(|(i, t)| iv.draw(*i, t, cull, FrontFace::Ccw).visible).collect();
    let b: Vec<bool> = tris.iter().map(|(i, t)| iii.draw(*i, t, cull, FrontFace::Ccw).visible).collect();
    (iv, iii, a, b)
}

#[test]
fn type_iii_frames_equal_type_iv_frames_on_every_built_in_scene_at_two_sizes() {
    for name in builtin::SCENES {
        let mesh = builtin::scene(name).unwrap();
        for (w, h) in [(320, 200), (640, 480)] {
            let screen = Screen::new(w, h).unwrap();
            let iv_opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
            let iii_opts = RenderOptions { rc_type: RcType::III, ..iv_opts.clone() };
            let iv = render(&mesh, &iv_opts).unwrap();
            let iii = render(&mesh, &iii_opts).unwrap();
            let at = format!("{name} at {w}x{h}");
            assert!(iv.stats.rc.fragments > 0, "{at}: nothing drawn");
            assert_eq!(iii.hw_index, iv.hw_index, "{at}: I-buffer");
            assert_eq!(iii.rgb, iv.rgb, "{at}: image");
            assert_eq!(iii.results, iv.results, "{at}: per-triangle results");
            assert_eq!(iii.zbuf, iv.zbuf, "{at}: regenerated depth against the Z-buffer");
            let (a, b) = (iv.stats.rc.traffic, iii.stats.rc.traffic);
            assert_eq!((b.z_reads, b.z_writes), (0, 0), "{at}: Type III touched a Z-buffer");
            assert_eq!((a.tdbv_reads, a.tdbv_writes), (0, 0), "{at}: Type IV touched TdbV");
            assert_eq!((a.i_reads, a.i_writes), (b.i_reads, b.i_writes), "{at}: I-buffer traffic");
            // TdbV is read once per fragment that lands on a pixel some triangle already owns: every
            // fragment but the first on each covered pixel (no scene has a fragment at the far depth).
            assert_eq!(b.tdbv_reads, iv.stats.rc.fragments - iv.stats.covered_pixels, "{at}: TdbV reads");
            // One TdbV record per walked triangle: at most every triangle set up, at least every one
            // that owns a pixel of the final I-buffer.
            let set_up = iv.stats.rc.triangles - iv.stats.rc.culled_facing - iv.stats.rc.culled_zero_area;
            let owners = iv.hw_index.iter().filter(|&&i| i != 0).collect::<std::collections::HashSet<_>>().len() as u64;
            assert!(b.tdbv_writes <= set_up && b.tdbv_writes >= owners, "{at}: {} TdbV writes, {set_up} set up, {owners} owners", b.tdbv_writes);
        }
    }
}

/// Two triangles that pierce each other along a line: the visible one changes across it, and the
/// regenerated depth decides exactly where, as the stored depth does.
#[test]
fn interpenetrating_triangles_split_the_same_pixels_in_both_types() {
    let s = Screen::new(64, 48).unwrap();
    let v = |x: i32, y: i32, z: u32| WinVertex { x: x * ONE + 3, y: y * ONE + 5, z };
    // One leans from near (left) to far (right), the other the other way.
    let a = [v(2, 2, 1_000), v(60, 4, 9_000_000), v(4, 44, 1_000)];
    let b = [v(60, 2, 1_000), v(58, 44, 1_000), v(2, 20, 9_000_000)];
    let (iv, iii, ra, rb) = draw_both(&[(1, a), (2, b)], s, CullMode::None);
    let owners = |r: &Rasterizer, i: u32| r.ibuf.iter().filter(|&&x| x == i).count();
    assert!(owners(&iv, 1) > 100 && owners(&iv, 2) > 100, "both triangles own part of the overlap");
    assert_eq!(iii.ibuf, iv.ibuf);
    assert_eq!(iii.depths(), iv.zbuf);
    assert_eq!(ra, rb);
}

fn vertex(w: i32, h: i32) -> impl Strategy<Value = WinVertex> {
    // Depths from a small set make equal and coplanar depths common; some vertices off the screen.
    (-w * ONE / 4..w * ONE * 5 / 4, -h * ONE / 4..h * ONE * 5 / 4, prop::sample::select(vec![0u32, 7, 500_000, 500_001, DEPTH_MAX / 2, DEPTH_MAX]))
        .prop_map(|(x, y, z)| WinVertex { x, y, z })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Random overlapping triangles, some repeated exactly and some sharing a plane (same depths at
    /// different vertices of one plane), each with its own index.
    #[test]
    fn random_triangles_with_their_own_indices_draw_the_same_in_both_types(
        tris in prop::collection::vec(prop::array::uniform3(vertex(24, 16)), 1..24),
        repeats in prop::collection::vec(any::<prop::sample::Index>(), 0..6),
        cull_none in any::<bool>(),
    ) {
        let s = Screen::new(24, 16).unwrap();
        let mut all: Vec<[WinVertex; 3]> = tris.clone();
        for r in &repeats {
            let t = tris[r.index(tris.len())];
            all.push(t); // exactly the same triangle: equal depths everywhere, the first drawn keeps the pixel
            all.push([t[1], t[2], t[0]]); // the same plane with its vertices rotated
        }
        let indexed: Vec<(u32, [WinVertex; 3])> = all.into_iter().enumerate().map(|(i, t)| (i as u32 + 1, t)).collect();
        let cull = if cull_none { CullMode::None } else { CullMode::Back };
        let (iv, iii, ra, rb) = draw_both(&indexed, s, cull);
        prop_assert_eq!(&iii.ibuf, &iv.ibuf);
        prop_assert_eq!(iii.depths(), iv.zbuf.clone());
        prop_assert_eq!(ra, rb);
        prop_assert_eq!(iii.counts.z_passes, iv.counts.z_passes);
    }
}

/// Type III reads the depth plane of the index the pixel holds, so an index given to two triangles of
/// one frame regenerates the later triangle's plane under the earlier one's pixels: the one case the
/// types differ. The chipset's host numbers a frame's triangles 1, 2, 3, ... so it never happens there.
#[test]
fn an_index_reused_within_a_frame_is_where_type_iii_differs() {
    let s = Screen::new(16, 16).unwrap();
    let v = |x: i32, y: i32, z: u32| WinVertex { x: x * ONE, y: y * ONE, z };
    let near_left = [v(0, 0, 100), v(8, 0, 100), v(0, 16, 100)];
    let far_big = [v(0, 0, 9_000), v(16, 0, 9_000), v(0, 16, 9_000)];
    let mid = [v(0, 0, 5_000), v(16, 0, 5_000), v(0, 16, 5_000)];
    // Index 1 twice: the near triangle's pixels regenerate the far plane's depth in Type III.
    let (iv, iii, _, _) = draw_both(&[(1, near_left), (1, far_big), (2, mid)], s, CullMode::None);
    assert_ne!(iii.ibuf, iv.ibuf, "the reused index changes Type III's picture");
    // With its own index each, they agree.
    let (iv, iii, _, _) = draw_both(&[(1, near_left), (3, far_big), (2, mid)], s, CullMode::None);
    assert_eq!(iii.ibuf, iv.ibuf);
}
