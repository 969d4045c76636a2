//! The golden rasterizer against a naive f64 oracle: per pixel, over the triangle's whole float extent,
//! a point-in-triangle test with the same top-left fill rule, written without edge stepping, biasing or
//! bounding-box arithmetic. Coverage must be identical.

use golden::format::{Screen, WinVertex, SUBPIXEL_ONE as ONE};
use golden::host::Camera;
use golden::raster::{det, setup, CullMode, FrontFace};
use golden::render::{render, RenderOptions};
use golden::scene::{builtin, Winding};
use golden::shade::Shading;
use proptest::prelude::*;

/// Inside test in floating point: vertices in pixels, centre (X+0.5, Y+0.5), edges of the clockwise
/// (on screen, y down) order; a centre on an edge counts only for top or left edges.
fn oracle_inside(v: &[WinVertex; 3], x: i32, y: i32) -> bool {
    let p: Vec<(f64, f64)> = v.iter().map(|q| (q.x as f64 / ONE as f64, q.y as f64 / ONE as f64)).collect();
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    if area == 0.0 {
        return false;
    }
    let order = if area > 0.0 { [0, 1, 2] } else { [0, 2, 1] };
    let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
    (0..3).all(|k| {
        let a = p[order[k]];
        let b = p[order[(k + 1) % 3]];
        let e = (b.0 - a.0) * (cy - a.1) - (b.1 - a.1) * (cx - a.0);
        let top = b.1 == a.1 && b.0 > a.0;
        let left = b.1 < a.1;
        e > 0.0 || (e == 0.0 && (top || left))
    })
}

/// Compare coverage of one triangle over its float extent (plus a margin) clipped to the screen.
fn check_triangle(v: &[WinVertex; 3], screen: Screen) -> Result<(), String> {
    let s = setup(v, CullMode::None, FrontFace::Ccw, screen);
    let lo_x = (v.iter().map(|q| q.x).min().unwrap() / ONE - 2).max(0);
    let hi_x = (v.iter().map(|q| q.x).max().unwrap() / ONE + 2).min(screen.width as i32 - 1);
    let lo_y = (v.iter().map(|q| q.y).min().unwrap() / ONE - 2).max(0);
    let hi_y = (v.iter().map(|q| q.y).max().unwrap() / ONE + 2).min(screen.height as i32 - 1);
    for y in lo_y..=hi_y {
        for x in lo_x..=hi_x {
            let want = oracle_inside(v, x, y);
            let got = match &s {
                Ok(st) => !st.bbox.is_empty() && x >= st.bbox.x0 && x <= st.bbox.x1 && y >= st.bbox.y0 && y <= st.bbox.y1 && st.covers(x, y),
                Err(_) => false,
            };
            if want != got {
                return Err(format!("triangle {v:?}: pixel ({x},{y}) oracle {want} model {got}"));
            }
        }
    }
    Ok(())
}

fn vertex(screen: Screen) -> impl Strategy<Value = WinVertex> {
    let (x0, x1) = screen.guard_x();
    let (y0, y1) = screen.guard_y();
    // Mostly near the screen (so triangles cover pixels), sometimes anywhere in the guard band.
    prop_oneof![
        3 => (-2 * ONE..(screen.width as i32 + 2) * ONE, -2 * ONE..(screen.height as i32 + 2) * ONE, 0u32..1 << 24)
            .prop_map(|(x, y, z)| WinVertex { x, y, z }),
        1 => (x0..x1, y0..y1, 0u32..1 << 24).prop_map(|(x, y, z)| WinVertex { x, y, z }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn random_triangles_cover_exactly_the_oracle_pixels(a in vertex(Screen { width: 64, height: 48 }),
                                                        b in vertex(Screen { width: 64, height: 48 }),
                                                        c in vertex(Screen { width: 64, height: 48 })) {
        let screen = Screen::new(64, 48).unwrap();
        prop_assert!(check_triangle(&[a, b, c], screen).is_ok(), "{}", check_triangle(&[a, b, c], screen).unwrap_err());
    }

    #[test]
    fn small_triangles_on_the_pixel_grid_cover_exactly_the_oracle_pixels(
        p in proptest::collection::vec((0i32..8 * ONE, 0i32..8 * ONE), 3)) {
        // Vertices on a quarter-pixel grid near few pixels: many centres fall exactly on edges and corners.
        let screen = Screen::new(8, 8).unwrap();
        let v = [0, 1, 2].map(|k| WinVertex { x: p[k].0 / (ONE / 4) * (ONE / 4), y: p[k].1 / (ONE / 4) * (ONE / 4), z: 0 });
        prop_assert!(check_triangle(&v, screen).is_ok(), "{}", check_triangle(&v, screen).unwrap_err());
    }
}

#[test]
fn every_builtin_scene_rasterizes_exactly_as_the_oracle() {
    for name in builtin::SCENES {
        let mesh = builtin::scene(name).unwrap();
        let screen = Screen::new(160, 100).unwrap();
        let front = if mesh.front_face == Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw };
        let opts = RenderOptions {
            screen,
            camera: Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0),
            shading: Shading::Gouraud,
            cull: CullMode::Back,
            front,
            lighting: Default::default(),
            index_bits: 16,
            rc_type: golden::raster::RcType::IV,
            texturing: None,
            background: [0, 0, 0],
        };
        let geo = golden::host::upper_pipeline(&mesh, &opts.camera, screen);
        let mut tested = 0;
        for t in &geo.hw {
            if det(&t.v) != 0 {
                check_triangle(&t.v, screen).unwrap_or_else(|e| panic!("scene {name}: {e}"));
                tested += 1;
            }
        }
        assert!(tested > 0, "{name}");
        // And the whole frame renders.
        let f = render(&mesh, &opts).unwrap();
        assert!(f.stats.visible_final > 0, "{name} shows nothing");
    }
}
