//! On closed and tiled meshes, shared edges are covered exactly once: every pixel centre inside the
//! covered region belongs to exactly one triangle (no gaps, no double hits).

use golden::format::{Screen, WinVertex, SUBPIXEL_ONE as ONE};
use golden::raster::{setup, CullMode, FrontFace};
use proptest::prelude::*;

/// Count, per pixel, how many of `tris` cover it (each triangle by its own setup).
fn hit_counts(tris: &[[WinVertex; 3]], screen: Screen, cull: CullMode, front: FrontFace) -> Vec<u32> {
    let mut hits = vec![0u32; screen.pixels()];
    for t in tris {
        if let Ok(s) = setup(t, cull, front, screen) {
            if s.bbox.is_empty() {
                continue;
            }
            for y in s.bbox.y0..=s.bbox.y1 {
                for x in s.bbox.x0..=s.bbox.x1 {
                    if s.covers(x, y) {
                        hits[(y as u32 * screen.width + x as u32) as usize] += 1;
                    }
                }
            }
        }
    }
    hits
}

/// A jittered grid of quads, each split into two triangles along an alternating diagonal, covering
/// the rectangle [x0, x1] x [y0, y1] (subpixels) exactly.
fn jittered_grid(n: usize, jitter: &[(i32, i32)], x0: i32, y0: i32, cell: i32) -> Vec<[WinVertex; 3]> {
    let idx = |i: usize, j: usize| j * (n + 1) + i;
    let p = |i: usize, j: usize| {
        let interior = i > 0 && j > 0 && i < n && j < n;
        let (dx, dy) = if interior { jitter[idx(i, j) % jitter.len()] } else { (0, 0) };
        WinVertex { x: x0 + i as i32 * cell + dx, y: y0 + j as i32 * cell + dy, z: 0 }
    };
    let mut t = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if (i + j) % 2 == 0 {
                t.push([a, b, c]);
                t.push([a, c, d]);
            } else {
                t.push([a, b, d]);
                t.push([b, c, d]);
            }
        }
    }
    t
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn shared_edge_pixels_of_a_tiled_rectangle_are_drawn_once(
        jitter in proptest::collection::vec((-20 * ONE / 16..=20 * ONE / 16, -20 * ONE / 16..=20 * ONE / 16), 49)) {
        let screen = Screen::new(64, 64).unwrap();
        // 6x6 cells of 8 px from (4,4) px: the rectangle [4, 52) px, whose edges are on pixel boundaries.
        let tris = jittered_grid(6, &jitter, 4 * ONE, 4 * ONE, 8 * ONE);
        let hits = hit_counts(&tris, screen, CullMode::None, FrontFace::Ccw);
        for y in 0..64 {
            for x in 0..64 {
                let inside = (4..52).contains(&x) && (4..52).contains(&y);
                let h = hits[y * 64 + x];
                prop_assert_eq!(h, inside as u32, "pixel ({},{})", x, y);
            }
        }
    }
}

#[test]
fn closed_sphere_front_faces_cover_its_silhouette_once_and_back_faces_once() {
    // A UV sphere projected orthographically: every pixel inside is hit once by front faces and once
    // by back faces (the mesh is closed: each edge shared by exactly two triangles).
    let screen = Screen::new(96, 96).unwrap();
    let (rings, segs) = (12, 20);
    let r = 40.0 * ONE as f64;
    let (cx, cy) = (48.0 * ONE as f64 + 3.0, 48.0 * ONE as f64 - 5.0);
    let mut pts = Vec::new();
    for i in 0..=rings {
        let th = std::f64::consts::PI * i as f64 / rings as f64;
        for j in 0..segs {
            let ph = 2.0 * std::f64::consts::PI * j as f64 / segs as f64;
            let (x, y, z) = (th.sin() * ph.cos(), th.cos(), th.sin() * ph.sin());
            pts.push(WinVertex { x: (cx + r * x).round() as i32, y: (cy - r * y).round() as i32, z: ((z + 1.0) * 1000.0) as u32 });
        }
    }
    let id = |i: usize, j: usize| i * segs + (j % segs);
    let mut tris = Vec::new();
    for i in 0..rings {
        for j in 0..segs {
            let (a, b, c, d) = (pts[id(i, j)], pts[id(i, j + 1)], pts[id(i + 1, j + 1)], pts[id(i + 1, j)]);
            if i != 0 {
                tris.push([a, b, c]);
            }
            if i != rings - 1 {
                tris.push([a, c, d]);
            }
        }
    }
    let front = hit_counts(&tris, screen, CullMode::Back, FrontFace::Ccw);
    let back = hit_counts(&tris, screen, CullMode::Front, FrontFace::Ccw);
    let mut inside = 0;
    for k in 0..screen.pixels() {
        assert!(front[k] <= 1 && back[k] <= 1, "pixel {k} hit {} / {} times", front[k], back[k]);
        assert_eq!(front[k], back[k], "pixel {k}: front and back coverage differ (a gap)");
        inside += front[k];
    }
    // The silhouette is a polygon close to a circle of radius 40 px.
    assert!(inside > 4500 && inside < 5100, "{inside}");
}
