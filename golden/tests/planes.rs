//! Colour planes evaluated in fixed point stay within 1 LSB of exact (f64) evaluation of the plane
//! through the three vertex colours, for triangles inside 640x480 (format.rs states the bound).

use golden::format::{WinVertex, SUBPIXEL_ONE as ONE};
use golden::raster::{setup, CullMode, FrontFace};
use golden::shade::colour_setup;
use golden::format::Screen;
use proptest::prelude::*;

fn exact(v: &[WinVertex; 3], c: [f64; 3], x: f64, y: f64) -> f64 {
    let p: Vec<(f64, f64)> = v.iter().map(|q| (q.x as f64 / ONE as f64, q.y as f64 / ONE as f64)).collect();
    let d = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    // Barycentric weights of (x, y).
    let w1 = ((x - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (y - p[0].1)) / d;
    let w2 = ((p[1].0 - p[0].0) * (y - p[0].1) - (x - p[0].0) * (p[1].1 - p[0].1)) / d;
    c[0] + w1 * (c[1] - c[0]) + w2 * (c[2] - c[0])
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn colour_planes_are_within_one_lsb_of_exact_evaluation(
        p in proptest::collection::vec((0i32..640 * ONE, 0i32..480 * ONE), 3),
        col in proptest::collection::vec((0i64..256, 0i64..256, 0i64..256), 3)) {
        let screen = Screen::new(640, 480).unwrap();
        let v = [0, 1, 2].map(|k| WinVertex { x: p[k].0, y: p[k].1, z: 0 });
        let s = match setup(&v, CullMode::None, FrontFace::Ccw, screen) { Ok(s) => s, Err(_) => return Ok(()) };
        let vals = [0, 1, 2].map(|k| [col[k].0, col[k].1, col[k].2]);
        let e = colour_setup(&v, vals, 0);
        // Skip slivers whose gradient exceeds the stated bound (2^12 LSB/pixel).
        if e.planes.iter().any(|pl| pl.a.abs() > 4096 << 16 || pl.b.abs() > 4096 << 16) { return Ok(()); }
        // Sample up to ~400 covered pixels.
        let step = ((s.bbox.pixels() / 400).max(1) as f64).sqrt().ceil() as i32;
        let mut y = s.bbox.y0;
        while y <= s.bbox.y1 {
            let mut x = s.bbox.x0;
            while x <= s.bbox.x1 {
                if s.covers(x, y) {
                    for ch in 0..3 {
                        let want = exact(&v, [vals[0][ch] as f64, vals[1][ch] as f64, vals[2][ch] as f64], x as f64 + 0.5, y as f64 + 0.5);
                        let got = e.planes[ch].eval(x as u32, y as u32) as f64;
                        prop_assert!((got - want).abs() <= 1.0, "pixel ({},{}) channel {}: fixed {} exact {}", x, y, ch, got, want);
                    }
                }
                x += step;
            }
            y += step;
        }
    }
}

#[test]
fn a_full_screen_gradient_triangle_is_exact_to_one_lsb_everywhere() {
    let screen = Screen::new(640, 480).unwrap();
    let v = [WinVertex { x: 0, y: 0, z: 0 }, WinVertex { x: 640 * ONE, y: 0, z: 0 }, WinVertex { x: 0, y: 480 * ONE, z: 0 }];
    let vals = [[0, 255, 17], [255, 0, 200], [128, 3, 255]];
    let e = colour_setup(&v, vals, 0);
    let s = setup(&v, CullMode::None, FrontFace::Ccw, screen).unwrap();
    let mut n = 0;
    for y in 0..480 {
        for x in 0..640 {
            if s.covers(x, y) {
                n += 1;
                for ch in 0..3 {
                    let want = exact(&v, [vals[0][ch] as f64, vals[1][ch] as f64, vals[2][ch] as f64], x as f64 + 0.5, y as f64 + 0.5);
                    let got = e.planes[ch].eval(x as u32, y as u32) as f64;
                    assert!((got - want).abs() <= 1.0, "({x},{y}) ch {ch}: {got} vs {want}");
                }
            }
        }
    }
    assert!(n > 150_000);
}
