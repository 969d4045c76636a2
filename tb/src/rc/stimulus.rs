//! Command streams for the RC: built-in scenes through the host's upper pipeline, hand-made triangles
//! for the corner cases of the rules, seeded random triangle lists; and the algorithmic reference
//! (`golden::raster::Rasterizer`) for any stream.

use crate::common::Rng;
use golden::cycle::rc::{CmdKind, RcCmd, RcResult};
use golden::format::{Screen, WinVertex, DEPTH_MAX, INDEX_BACKGROUND, SUBPIXEL_HALF as HALF, SUBPIXEL_ONE as ONE, WINDOW_MAX, WINDOW_MIN};

/// Subpixels per sixteenth of a pixel: the hand-made geometry below is drawn on a 1/16-pixel grid.
const U: i32 = ONE / 16;
use golden::host::{upper_pipeline, Camera};
use golden::raster::{Culled, CullMode, FrontFace, Rasterizer};
use golden::scene::{builtin, Mesh, Winding};

/// A frame: frame start (with `clear`), the triangles, end of frame.
pub fn frame(clear: bool, tris: Vec<RcCmd>) -> Vec<RcCmd> {
    let mut v = Vec::with_capacity(tris.len() + 2);
    v.push(RcCmd::frame(clear));
    v.extend(tris);
    v.push(RcCmd::end_of_frame());
    v
}

/// The RC's command stream of a frame the host hands the chipset: [`frame`] of the job's triangles
/// with its cull mode and front face (an error names a vertex or index that does not fit the port).
pub fn job_frame(job: &golden::render::FrameJob, clear: bool) -> Result<Vec<RcCmd>, String> {
    let tris = job.tris.iter().map(|t| RcCmd::triangle(t.index, t.v, job.cull, job.front)).collect::<Result<Vec<_>, _>>()?;
    Ok(frame(clear, tris))
}

/// A built-in scene (`teapot_grid` for the teapot) as window triangles, framed as the issue says:
/// `Camera::framing(mesh, [0.3, 0.45, 1.0], 40.0)`, back faces culled, front face from the mesh.
pub fn scene_triangles(name: &str, teapot_grid: u32, screen: Screen) -> Result<Vec<RcCmd>, String> {
    let mesh: Mesh = if name == "teapot" { builtin::teapot(teapot_grid) } else { builtin::scene(name)? };
    let cam = Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0);
    let front = match mesh.front_face {
        Winding::Ccw => FrontFace::Ccw,
        Winding::Cw => FrontFace::Cw,
    };
    let geo = upper_pipeline(&mesh, &cam, screen);
    geo.hw.iter().enumerate().map(|(i, t)| RcCmd::triangle(i as u32 + 1, t.v, CullMode::Back, front)).collect()
}

fn px(x: i32, y: i32, z: u32) -> WinVertex {
    WinVertex { x, y, z }
}

fn tri(index: u32, v: [WinVertex; 3]) -> RcCmd {
    RcCmd::triangle(index, v, CullMode::None, FrontFace::Ccw).expect("hand-made triangles fit the formats")
}

/// Hand-made cases on a 32x24 screen, each a named frame (clear = true).
pub fn hand_made() -> Vec<(&'static str, Vec<RcCmd>)> {
    let (s, u) = (ONE, U); // one pixel and one sixteenth of a pixel in subpixels
    let mut cases = vec![
        // Two triangles sharing the diagonal of a square: every centre drawn once.
        ("shared_edge", vec![tri(1, [px(2 * s, 2 * s, 100), px(10 * s, 2 * s, 100), px(10 * s, 10 * s, 100)]),
                             tri(2, [px(2 * s, 2 * s, 200), px(10 * s, 10 * s, 200), px(2 * s, 10 * s, 200)])]),
        // Pixel centres exactly on a top, a left, a bottom and a right edge (fill-rule corners):
        // a 4x4-pixel square whose edges pass through centres, split in two, both windings.
        ("fill_rule_corners", vec![tri(1, [px(4 * s + 8 * u, 4 * s + 8 * u, 10), px(8 * s + 8 * u, 4 * s + 8 * u, 10), px(8 * s + 8 * u, 8 * s + 8 * u, 10)]),
                                   tri(2, [px(4 * s + 8 * u, 4 * s + 8 * u, 10), px(4 * s + 8 * u, 8 * s + 8 * u, 10), px(8 * s + 8 * u, 8 * s + 8 * u, 10)]),
                                   tri(3, [px(12 * s + 8 * u, 4 * s + 8 * u, 10), px(12 * s + 8 * u, 8 * s + 8 * u, 10), px(16 * s + 8 * u, 4 * s + 8 * u, 10)]),
                                   tri(4, [px(16 * s + 8 * u, 8 * s + 8 * u, 10), px(12 * s + 8 * u, 8 * s + 8 * u, 10), px(16 * s + 8 * u, 4 * s + 8 * u, 10)])]),
        // Pixel centres exactly on each edge of a lone triangle, for every edge index: a right triangle
        // whose legs and diagonal pass through centres, in its three vertex rotations and both
        // windings, for each diagonal direction, each at its own place with nothing else drawn there,
        // so every tie alone decides a pixel (`fill_rule_corners` has no such tie on a top-left second
        // edge; `rc_model` checks that this case has one for every edge index and both kinds).
        ("fill_rule_every_edge_index", fill_rule_every_edge_index(s)),
        // Zero area: collinear and coincident vertices.
        ("zero_area", vec![tri(1, [px(0, 0, 5), px(5 * s, 5 * s, 5), px(10 * s, 10 * s, 5)]),
                           tri(2, [px(3 * s, 3 * s, 5); 3]),
                           tri(3, [px(s, s, 5), px(9 * s, 2 * s, 5), px(4 * s, 7 * s, 5)])]),
        // One pixel: a tiny triangle around one centre, and one covering no centre at all.
        ("one_pixel", vec![tri(1, [px(5 * s + 4 * u, 5 * s + 4 * u, 7), px(5 * s + 12 * u, 5 * s + 4 * u, 7), px(5 * s + 8 * u, 5 * s + 12 * u, 7)]),
                           tri(2, [px(9 * s + 1 * u, 9 * s + 1 * u, 7), px(9 * s + 4 * u, 9 * s + 1 * u, 7), px(9 * s + 1 * u, 9 * s + 4 * u, 7)]),
                           tri(3, [px(5 * s + 4 * u, 5 * s + 4 * u, 3), px(5 * s + 12 * u, 5 * s + 4 * u, 3), px(5 * s + 8 * u, 5 * s + 12 * u, 3)])]),
        // Fully off screen on each side: empty bounding boxes, no traversal.
        ("off_screen", vec![tri(1, [px(-20 * s, 2 * s, 1), px(-2 * s, 2 * s, 1), px(-10 * s, 9 * s, 1)]),
                            tri(2, [px(40 * s, 2 * s, 1), px(50 * s, 2 * s, 1), px(45 * s, 9 * s, 1)]),
                            tri(3, [px(2 * s, -9 * s, 1), px(9 * s, -9 * s, 1), px(5 * s, -s, 1)]),
                            tri(4, [px(2 * s, 30 * s, 1), px(9 * s, 30 * s, 1), px(5 * s, 40 * s, 1)])]),
        // Vertices in the guard band (and at the 20-bit limits): clamped boxes, big coefficients.
        ("guard_band", vec![tri(1, [px(-32 * s, -24 * s, 0), px(63 * s, 5 * s, DEPTH_MAX), px(3 * s, 47 * s, 1 << 23)]),
                            tri(2, [px(WINDOW_MIN, WINDOW_MIN, 10), px(WINDOW_MAX, WINDOW_MIN, 20), px(WINDOW_MIN, WINDOW_MAX, 30)]),
                            tri(3, [px(WINDOW_MAX, WINDOW_MAX, 5000), px(WINDOW_MIN, 100 * u, 6000), px(100 * u, WINDOW_MIN, 7000)])]),
        // Equal depths: the first drawn keeps the pixel.
        ("equal_depths", vec![tri(1, [px(s, s, 4000), px(20 * s, s, 4000), px(s, 20 * s, 4000)]),
                              tri(2, [px(s, s, 4000), px(20 * s, s, 4000), px(s, 20 * s, 4000)]),
                              tri(3, [px(20 * s, s, 4000), px(20 * s, 20 * s, 4000), px(s, 20 * s, 4000)])]),
        // A triangle that hides an earlier one completely: the earlier one stays flagged visible (it
        // passed when drawn), a later hidden one is not.
        ("hidden_completely", vec![tri(1, [px(4 * s, 4 * s, 9000), px(12 * s, 4 * s, 9000), px(8 * s, 12 * s, 9000)]),
                                   tri(2, [px(0, 0, 100), px(30 * s, 0, 200), px(0, 22 * s, 300)]),
                                   tri(3, [px(4 * s, 4 * s, 9000), px(12 * s, 4 * s, 9000), px(8 * s, 12 * s, 9000)])]),
        // Depth ramps to both clamps: a plane going below 0 and above 2^24-1 inside the triangle.
        ("depth_clamps", vec![tri(1, [px(0, 0, 0), px(31 * s, 0, DEPTH_MAX), px(0, 23 * s, 0)]),
                              tri(2, [px(31 * s, 23 * s, DEPTH_MAX), px(0, 23 * s, 0), px(31 * s, 0, DEPTH_MAX)])]),
    ];
    // Culling: both windings under each cull mode and front face.
    let cw = [px(2 * s, 2 * s, 50), px(9 * s, 2 * s, 50), px(2 * s, 9 * s, 50)];
    let ccw = [cw[0], cw[2], cw[1]];
    let mut culling = Vec::new();
    let mut index = 1;
    for cull in [CullMode::Back, CullMode::Front, CullMode::None] {
        for front in [FrontFace::Ccw, FrontFace::Cw] {
            for v in [cw, ccw] {
                culling.push(RcCmd::triangle(index, v, cull, front).unwrap());
                index += 1;
            }
        }
    }
    cases.push(("culling", culling));
    // One pixel drawn by three one-pixel triangles: their records wait in the queue while the clear
    // runs, so their fragments come in three consecutive cycles; the second (600) must see the first's
    // depth (700) through the forwarding and pass, the third (650) must see the second's and fail.
    cases.push(("same_pixel_back_to_back", vec![
        tri(1, [px(5 * s + 4 * u, 5 * s + 4 * u, 700), px(5 * s + 12 * u, 5 * s + 4 * u, 700), px(5 * s + 8 * u, 5 * s + 12 * u, 700)]),
        tri(2, [px(5 * s + 4 * u, 5 * s + 4 * u, 600), px(5 * s + 12 * u, 5 * s + 4 * u, 600), px(5 * s + 8 * u, 5 * s + 12 * u, 600)]),
        tri(3, [px(5 * s + 4 * u, 5 * s + 4 * u, 650), px(5 * s + 12 * u, 5 * s + 4 * u, 650), px(5 * s + 8 * u, 5 * s + 12 * u, 650)]),
    ]));
    // The same pixel in consecutive cycles across triangles with no gap: a large triangle's last
    // fragment (on its box's last row, so the walk ends with it), then a triangle whose first fragment
    // is that pixel, farther away, whose record was set up during the large one's walk, so it is taken
    // in the same clock and its first fragment follows at once. Its Z read cannot see the large one's
    // write yet; only the forwarding keeps it from drawing over the nearer triangle there.
    let big = [px(2 * s, 2 * s, 100), px(12 * s, 12 * s, 100), px(2 * s, 12 * s, 100)];
    let (lx, ly) = last_covered(&big, hand_made_screen());
    let behind = [px(lx * s + 4 * u, ly * s + 4 * u, 900), px(lx * s + 60 * u, ly * s + 4 * u, 900), px(lx * s + 4 * u, ly * s + 60 * u, 900)];
    cases.push(("same_pixel_across_triangles_without_gap", vec![tri(1, big), tri(2, behind)]));
    cases.into_iter().map(|(n, t)| (n, frame(true, t))).collect()
}

/// Twelve 4x4-pixel right triangles with every edge through pixel centres (see `hand_made`).
fn fill_rule_every_edge_index(s: i32) -> Vec<RcCmd> {
    let u = s / 16;
    let mut tris = Vec::new();
    for (row, diagonal_down) in [(0, true), (1, false)] {
        for k in 0..6 {
            let (x0, y0) = ((1 + 5 * k) * s + 8 * u, (2 + 6 * row) * s + 8 * u);
            let (a, b, c) = if diagonal_down {
                (px(x0, y0, 30), px(x0 + 4 * s, y0, 30), px(x0 + 4 * s, y0 + 4 * s, 30))
            } else {
                (px(x0, y0 + 4 * s, 30), px(x0 + 4 * s, y0, 30), px(x0 + 4 * s, y0 + 4 * s, 30))
            };
            let ccw = [[a, b, c], [b, c, a], [c, a, b]][k as usize % 3];
            let v = if k < 3 { ccw } else { [ccw[0], ccw[2], ccw[1]] };
            tris.push(tri(tris.len() as u32 + 1, v));
        }
    }
    tris
}

/// The last covered pixel of a triangle in raster order (where its walk's last fragment is).
fn last_covered(v: &[WinVertex; 3], screen: Screen) -> (i32, i32) {
    let st = golden::raster::setup(v, CullMode::None, FrontFace::Ccw, screen).expect("a drawn triangle");
    covered_pixels(&st).last().expect("covers a pixel")
}

/// The pixels of `st`'s box whose centres it covers, in raster order.
fn covered_pixels(st: &golden::raster::Setup) -> impl Iterator<Item = (i32, i32)> + '_ {
    let b = st.bbox;
    (b.y0..=b.y1).flat_map(move |y| (b.x0..=b.x1).map(move |x| (x, y))).filter(|&(x, y)| st.covers(x, y))
}

/// Whether some covered pixel of `st` has its raw depth within `band` of a rounding edge.
fn depth_near_rounding_edge(st: &golden::raster::Setup, band: i64) -> bool {
    covered_pixels(st).any(|(x, y)| near_rounding_edge(st.depth.raw(x as u32, y as u32), band))
}

/// The screen of the hand-made cases.
pub fn hand_made_screen() -> Screen {
    Screen::new(32, 24).unwrap()
}

/// `n` random triangles over a screen: vertices anywhere in the guard band, some tiny, some large,
/// random depths, cull modes and front faces.
pub fn random_triangles(rng: &mut Rng, screen: Screen, n: usize) -> Vec<RcCmd> {
    (0..n).map(|i| random_triangle(rng, screen, i as u32 + 1)).collect()
}

/// One triangle of [`random_triangles`], with index `index`.
fn random_triangle(rng: &mut Rng, screen: Screen, index: u32) -> RcCmd {
    let (gx0, gx1) = screen.guard_x();
    let (gy0, gy1) = screen.guard_y();
    let big = rng.chance(20);
    let (cx, cy) = (rng.below((gx1 - gx0) as u64) as i32 + gx0, rng.below((gy1 - gy0) as u64) as i32 + gy0);
    let (cx, cy) = if big { (cx, cy) } else { (rng.below(screen.width as u64 * ONE as u64) as i32, rng.below(screen.height as u64 * ONE as u64) as i32) };
    let r = if big { (gx1 - gx0) as u64 } else { 1 + rng.below(6 * ONE as u64) };
    let mut p = [WinVertex::default(); 3];
    for q in &mut p {
        let dx = rng.below(2 * r + 1) as i32 - r as i32;
        let dy = rng.below(2 * r + 1) as i32 - r as i32;
        *q = WinVertex {
            x: (cx + dx).clamp(gx0, gx1 - 1),
            y: (cy + dy).clamp(gy0, gy1 - 1),
            z: if rng.chance(10) { DEPTH_MAX - rng.below(4) as u32 } else { rng.below(DEPTH_MAX as u64 + 1) as u32 },
        };
    }
    let cull = [CullMode::Back, CullMode::Front, CullMode::None][rng.below(3) as usize];
    let front = if rng.chance(50) { FrontFace::Ccw } else { FrontFace::Cw };
    RcCmd::triangle(index, p, cull, front).expect("guard-band vertices fit the formats")
}

/// `n` triangles on one pixel, for the Z-test's forwarding: groups of a triangle of about 8x8 pixels
/// around a random pixel, then six one-pixel triangles on that pixel whose records queue up while the
/// larger one is walked, so that their fragments follow each other in consecutive cycles. Depths: with
/// `staircase`, most triangles step 0 to 7 units nearer than the one before (consecutive fragments
/// pass and the forwarded depth's low bits decide the next test), some lie behind (they fail), some at
/// `DEPTH_MAX`, and the last at 0; without, random, near a base depth of the list, or at the clamps
/// (the first 0 ends every later pass on the pixel). Indices are random over the whole 16-bit range, culling random (a fifth of the
/// one-pixel triangles is culled): the forwarding's compare sees every depth bit and the I-buffer every
/// index bit.
pub fn hazard_triangles(rng: &mut Rng, screen: Screen, n: usize, staircase: bool) -> Vec<RcCmd> {
    let (cx, cy) = ((4 + rng.below(screen.width as u64 - 8) as i32) * ONE + HALF, (4 + rng.below(screen.height as u64 - 8) as i32) * ONE + HALF);
    // Depths, one of two ways. A staircase: most triangles come a few units nearer than the one before
    // (or at the same depth), so that consecutive fragments on the pixel pass and the next one's test
    // against the forwarded depth is decided by its low bits. Otherwise: random over the whole range
    // (four tenths), within 8 of a base depth (four tenths), or at a clamp.
    let base = rng.below(DEPTH_MAX as u64 + 1) as i64;
    let mut run = if staircase { (DEPTH_MAX / 2 + rng.below(DEPTH_MAX as u64 / 2) as u32) as i64 } else { 0 };
    (0..n)
        .map(|i| {
            let z = if !staircase {
                match rng.below(10) {
                    0 => 0,
                    1 => DEPTH_MAX,
                    2..=5 => rng.below(DEPTH_MAX as u64 + 1) as u32,
                    _ => (base + rng.below(16) as i64 - 8).clamp(0, DEPTH_MAX as i64) as u32,
                }
            } else if i + 1 == n {
                0
            } else {
                match rng.below(20) {
                    0 => DEPTH_MAX,
                    // Behind the staircase: fails against the forwarded or the stored depth.
                    1..=3 => (run + 1 + rng.below((DEPTH_MAX as i64 - run) as u64) as i64) as u32,
                    _ => {
                        run = (run - rng.below(8) as i64).max(1);
                        run as u32
                    }
                }
            };
            let index = 1 + rng.below((1 << golden::cycle::rc::INDEX_BITS) - 1) as u32;
            let cull_tiny = rng.chance(20);
            let mut j = || rng.below(3) as i32 * U;
            let (p, cull) = if i % 7 == 0 {
                let r = 64 * U + j() * 8;
                ([(cx - r, cy - r), (cx + r, cy - r / 2), (cx - r / 2, cy + r)], CullMode::None)
            } else {
                let cull = if cull_tiny { CullMode::Back } else { CullMode::None };
                ([(cx - 4 * U - j(), cy - 4 * U - j()), (cx + 4 * U + j(), cy - 4 * U - j()), (cx, cy + 4 * U + j())], cull)
            };
            let clamp = staircase && (z == 0 || z == DEPTH_MAX);
            let v = p.map(|(x, y)| WinVertex { x, y, z: if !clamp && rng.chance(30) { (z + rng.below(4) as u32).min(DEPTH_MAX) } else { z } });
            let front = if rng.chance(50) { FrontFace::Ccw } else { FrontFace::Cw };
            RcCmd::triangle(index, v, cull, front).expect("on-screen vertices fit the formats")
        })
        .collect()
}

/// `n` right triangles whose determinant is a power of two: legs of 2^a and 2^b subpixels (a, b in
/// 0..=12) along the axes, at random places on the screen, in a random vertex order (so either
/// winding; drawn with no culling), random depths and indices. The reciprocal's divisor is then 2^s,
/// the one case in which the restoring division's remainder becomes 0 after its first step and every
/// later step takes the "does not fit" branch.
pub fn power_of_two_triangles(rng: &mut Rng, screen: Screen, n: usize) -> Vec<RcCmd> {
    (0..n)
        .map(|_| {
            let (a, b) = (rng.below(13) as i32, rng.below(13) as i32);
            let (lx, ly) = (1 << a, 1 << b);
            let x0 = rng.below((screen.width as i32 * ONE - lx) as u64) as i32;
            let y0 = rng.below((screen.height as i32 * ONE - ly) as u64) as i32;
            let mut z = || rng.below(DEPTH_MAX as u64 + 1) as u32;
            let mut v = [WinVertex { x: x0, y: y0, z: z() }, WinVertex { x: x0 + lx, y: y0, z: z() }, WinVertex { x: x0, y: y0 + ly, z: z() }];
            if rng.chance(50) {
                v.swap(1, 2);
            }
            let index = 1 + rng.below((1 << golden::cycle::rc::INDEX_BITS) - 1) as u32;
            let front = if rng.chance(50) { FrontFace::Ccw } else { FrontFace::Cw };
            RcCmd::triangle(index, v, CullMode::None, front).expect("on-screen vertices fit the formats")
        })
        .collect()
}

/// The stream that fills the RC's queues (on a 40x24 screen): a screen-size triangle keeps the
/// traversal busy while 40 small drawn and back-facing triangles pile up behind it.
pub fn queue_filling_triangles() -> (Screen, Vec<RcCmd>) {
    let screen = Screen::new(40, 24).expect("a valid size");
    (screen, queue_filling_triangles_on(screen))
}

/// Index 1 at depth `z`, covering every pixel with x + y < 60 (all of 32x24, most of 40x24): the long
/// walk the queues fill behind.
fn screen_size_triangle(z: u32) -> RcCmd {
    let v = |x: i32, y: i32| WinVertex { x: x * ONE, y: y * ONE, z };
    RcCmd::triangle(1, [v(-20, -20), v(80, -20), v(-20, 60)], CullMode::None, FrontFace::Ccw).expect("fits")
}

/// [`queue_filling_triangles_on`] with `n` of [`random_triangles`] behind the screen-size triangle
/// (indices 2 to n + 1): the queues fill with records of every kind (drawn, culled, zero-area; any
/// edge steps). The screen-size triangle lies at depth 900, in front of most of them.
pub fn queue_filling_random_triangles(rng: &mut Rng, screen: Screen, n: usize) -> Vec<RcCmd> {
    let mut tris = vec![screen_size_triangle(900)];
    tris.extend((0..n).map(|i| random_triangle(rng, screen, i as u32 + 2)));
    frame(false, tris)
}

/// [`queue_filling_random_triangles`] in a cleared frame with the screen-size triangle at the far
/// end (`DEPTH_MAX - 8`): the queued records' triangles lie in front of it, so their fragments pass
/// and a record changed while it waits in a queue shows in the depths and indices written.
pub fn queue_filling_random_triangles_in_front(rng: &mut Rng, screen: Screen, n: usize) -> Vec<RcCmd> {
    let mut tris = vec![screen_size_triangle(DEPTH_MAX - 8)];
    tris.extend((0..n).map(|i| random_triangle(rng, screen, i as u32 + 2)));
    frame(true, tris)
}

/// Whether raw depth `raw` (16 fraction bits) lies within `band` of a rounding edge: an error of up
/// to `band` one way or the other changes its rounded value.
fn near_rounding_edge(raw: i64, band: i64) -> bool {
    // It rounds up from 2^15: band lower ones reach 2^15 - band, and band more reach 2^15 + band - 1.
    let f = raw.rem_euclid(1 << 16) - (1 << 15);
    -band <= f && f < band
}

/// `n` small drawn triangles (no culling, random depths, indices 1 to n), each with a covered pixel
/// whose raw depth lies within `band` units of 2^-16 of a rounding edge (`raw mod 2^16` near 2^15), so
/// that an error of `band` or less in the depth plane or its stepping changes that fragment's depth:
/// random triangles are drawn (at most `5000 n`) and those kept.
pub fn depth_rounding_edge_triangles(rng: &mut Rng, screen: Screen, n: usize, band: i64) -> Vec<RcCmd> {
    let mut tris = Vec::new();
    for _ in 0..5000 * n {
        if tris.len() == n {
            break;
        }
        let (cx, cy) = (rng.below(screen.width as u64 * ONE as u64) as i32, rng.below(screen.height as u64 * ONE as u64) as i32);
        let r = ONE + rng.below(9 * ONE as u64) as i32;
        let v = [0, 1, 2].map(|_| WinVertex {
            x: cx + rng.below(2 * r as u64 + 1) as i32 - r,
            y: cy + rng.below(2 * r as u64 + 1) as i32 - r,
            z: rng.below(DEPTH_MAX as u64 + 1) as u32,
        });
        let Ok(st) = golden::raster::setup(&v, CullMode::None, FrontFace::Ccw, screen) else { continue };
        if depth_near_rounding_edge(&st, band) {
            tris.push(RcCmd::triangle(tris.len() as u32 + 1, v, CullMode::None, FrontFace::Ccw).expect("on-screen vertices fit the formats"));
        }
    }
    tris
}

/// `n` slivers (no culling, indices 1 to n): triangles under 1/8 pixel in area (0 < |det| < 64 U^2, in
/// units of 1/65536 square pixel) around a pixel centre, each covering a pixel whose raw depth lies
/// within `band` units of 2^-16 of a rounding edge. Only a determinant this small lets the low bits
/// of the depth gradient's product reach the gradient (the reciprocal's shift is then at most 13), and
/// a sliver covers only pixels within a pixel or two of its vertices, where an error in the gradient
/// moves the depth by a few units: such a fault shows only at a sliver's pixel near a rounding edge.
/// Geometries are drawn (at most `20000 n`), and for each sliver that covers a pixel, depths (at
/// most 4096 times) until one meets the edge.
pub fn sliver_depth_rounding_edge_triangles(rng: &mut Rng, screen: Screen, n: usize, band: i64) -> Vec<RcCmd> {
    let mut tris = Vec::new();
    for _ in 0..20_000 * n {
        if tris.len() == n {
            break;
        }
        let (cx, cy) = (rng.below(screen.width as u64) as i32 * ONE + HALF, rng.below(screen.height as u64) as i32 * ONE + HALF);
        let xy = [0, 1, 2].map(|_| (cx + rng.below(48 * U as u64 + 1) as i32 - 24 * U, cy + rng.below(48 * U as u64 + 1) as i32 - 24 * U));
        // The determinant, from the geometry alone (it does not depend on the depths; zero area is an error).
        let flat = xy.map(|(x, y)| WinVertex { x, y, z: 0 });
        match golden::raster::setup(&flat, CullMode::None, FrontFace::Ccw, screen) {
            Ok(st) if st.det.abs() < 64 * (U * U) as i64 => {}
            _ => continue,
        }
        for _ in 0..4096 {
            let v = xy.map(|(x, y)| WinVertex { x, y, z: rng.below(DEPTH_MAX as u64 + 1) as u32 });
            let Ok(st) = golden::raster::setup(&v, CullMode::None, FrontFace::Ccw, screen) else { break };
            if covered_pixels(&st).next().is_none() {
                break;
            }
            if depth_near_rounding_edge(&st, band) {
                tris.push(RcCmd::triangle(tris.len() as u32 + 1, v, CullMode::None, FrontFace::Ccw).expect("on-screen vertices fit the formats"));
                break;
            }
        }
    }
    tris
}

/// [`queue_filling_triangles`] on any screen of at least 8x6 pixels: the small triangles spread over
/// it the same way (at 40x24 the same stream).
pub fn queue_filling_triangles_on(screen: Screen) -> Vec<RcCmd> {
    let (xs, ys) = (screen.width as i32 - 6, screen.height as i32 - 4);
    let v = |x: i32, y: i32, z: u32| WinVertex { x: x * ONE, y: y * ONE, z };
    let mut tris = vec![screen_size_triangle(900)];
    for i in 0..40u32 {
        let (x, y) = (2 + (i as i32 * 3) % xs, 2 + (i as i32 * 5) % ys);
        let t = if i % 3 == 2 {
            // back-facing under Back culling: a result without traversal
            RcCmd::triangle(i + 2, [v(x, y, 100), v(x, y + 2, 100), v(x + 2, y, 100)], CullMode::Back, FrontFace::Cw)
        } else {
            RcCmd::triangle(i + 2, [v(x, y, 100 + i), v(x + 2, y, 100 + i), v(x, y + 2, 100 + i)], CullMode::None, FrontFace::Ccw)
        };
        tris.push(t.expect("fits"));
    }
    frame(false, tris)
}

/// What the algorithmic model makes of a command stream, starting from cleared buffers.
pub struct Reference {
    pub zbuf: Vec<u32>,
    pub ibuf: Vec<u32>,
    pub results: Vec<RcResult>,
    pub rast: Rasterizer,
}

pub fn reference(screen: Screen, cmds: &[RcCmd]) -> Reference {
    reference_of(golden::raster::RcType::IV, screen, cmds)
}

/// [`reference`] for the RC of type `ty`; its `zbuf` is the depth of every pixel (Type III: regenerated
/// from TdbV).
pub fn reference_of(ty: golden::raster::RcType, screen: Screen, cmds: &[RcCmd]) -> Reference {
    let mut r = Rasterizer::of_type(screen, ty);
    let mut results = Vec::new();
    for c in cmds {
        match c.kind {
            CmdKind::Frame => {
                if c.clear {
                    r.clear();
                }
            }
            CmdKind::Triangle => {
                let t = r.draw(c.index, &c.v, c.cull, c.front);
                results.push(RcResult {
                    eof: false,
                    index: t.index,
                    culled: t.culled.is_some(),
                    zero_area: t.culled == Some(Culled::ZeroArea),
                    visible: t.visible,
                });
            }
            CmdKind::EndOfFrame => results.push(RcResult { eof: true, ..RcResult::default() }),
        }
    }
    Reference { zbuf: r.depths(), ibuf: r.ibuf.clone(), results, rast: r }
}

/// Cleared buffers, as the reference starts.
pub fn cleared(screen: Screen) -> (Vec<u32>, Vec<u32>) {
    (vec![DEPTH_MAX; screen.pixels()], vec![INDEX_BACKGROUND; screen.pixels()])
}

/// Whether the walk of `st` makes a long-skip test (no candidate of the window covered, an edge
/// negative at x) where an edge's value at x + 15, that edge's or another's, is negative by at most
/// `band`: a value there off by `band` or less can change whether the walk skips 16 candidates or 4.
/// (Requiring the same edge at x and x + 15 gives other triangles, which kill `rc3` #28 no longer.)
fn has_marginal_long_skip(st: &golden::raster::Setup, band: i64) -> bool {
    use golden::cycle::rc::{walk_step, WALK_LONG_SKIP};
    // An empty box has no walk (its rows would never reach y1).
    if st.bbox.is_empty() {
        return false;
    }
    let (mut x, mut y) = (st.bbox.x0, st.bbox.y0);
    loop {
        let step = walk_step(st, x, y);
        let far = x as i64 + WALK_LONG_SKIP as i64 - 1;
        if step.frag.is_none() && st.edges.iter().any(|e| e.at(x as i64, y as i64) < 0) && st.edges.iter().any(|e| (-band..0).contains(&e.at(far, y as i64))) {
            return true;
        }
        if step.end {
            return false;
        }
        (x, y) = (step.next_x, step.next_y);
    }
}

/// `n` drawn triangles (no culling, random depths, indices 1 to n) with wide boxes whose walk makes a
/// long-skip test with an edge's value at x + 15 negative by at most `band` (its edge crosses the
/// row just past the 16 candidates): an error of up to `band` in the edge value there, or in the step
/// multiple that forms it, changes the walk's timing. Random triangles over the whole screen are drawn
/// (at most `5000 n`) and those kept.
pub fn long_skip_edge_triangles(rng: &mut Rng, screen: Screen, n: usize, band: i64) -> Vec<RcCmd> {
    let mut tris = Vec::new();
    for _ in 0..5000 * n {
        if tris.len() == n {
            break;
        }
        let v = [0, 1, 2].map(|_| WinVertex {
            x: rng.below(screen.width as u64 * ONE as u64) as i32,
            y: rng.below(screen.height as u64 * ONE as u64) as i32,
            z: rng.below(DEPTH_MAX as u64 + 1) as u32,
        });
        let Ok(st) = golden::raster::setup(&v, CullMode::None, FrontFace::Ccw, screen) else { continue };
        if st.bbox.x1 - st.bbox.x0 >= 16 && has_marginal_long_skip(&st, band) {
            tris.push(RcCmd::triangle(tris.len() as u32 + 1, v, CullMode::None, FrontFace::Ccw).expect("on-screen vertices fit the formats"));
        }
    }
    tris
}

#[cfg(test)]
mod construction_tests {
    use super::*;

    #[test]
    fn a_long_skip_edge_triangle_makes_a_long_skip_test_within_its_band_and_random_ones_rarely_do() {
        let screen = hand_made_screen();
        // 128 square sixteenths of a pixel, in the edge values' unit (subpixel^2): 128 U^2.
        let band = 128 * (U * U) as i64;
        let tris = long_skip_edge_triangles(&mut Rng::new(0x5c1b), screen, 40, band);
        assert_eq!(tris.len(), 40);
        let marginal = |t: &RcCmd| golden::raster::setup(&t.v, t.cull, t.front, screen).is_ok_and(|st| has_marginal_long_skip(&st, band));
        assert!(tris.iter().all(marginal));
        let plain = random_triangles(&mut Rng::new(0x5c1b), screen, 40).iter().filter(|t| marginal(t)).count();
        assert!(plain < 10, "{plain} of 40 random triangles");
    }

    #[test]
    fn random_triangles_queued_behind_a_far_screen_size_one_are_visible_four_times_as_often() {
        let screen = hand_made_screen();
        // Visible random triangles (not the screen-size one, index 1) behind each kind of screen-size triangle.
        let visible = |cmds: &[RcCmd]| reference(screen, cmds).results.iter().filter(|r| !r.eof && r.index != 1 && r.visible).count();
        let in_front = visible(&queue_filling_random_triangles_in_front(&mut Rng::new(0xfa7), screen, 40));
        let behind = visible(&queue_filling_random_triangles(&mut Rng::new(0xfa7), screen, 40));
        assert!(in_front >= 10 && behind * 4 <= in_front, "visible: {in_front} in front of the far one, {behind} with it at depth 900");
    }

    /// Whether the depth plane moved by `band` units of 2^-16, up or down, changes some covered pixel's depth.
    fn plane_moved_by_band_changes_a_depth(st: &golden::raster::Setup, band: i64) -> bool {
        [band, -band].iter().any(|&d| {
            let mut moved = st.depth;
            moved.c += d;
            covered_pixels(st).any(|(x, y)| moved.eval(x as u32, y as u32) != st.depth.eval(x as u32, y as u32))
        })
    }

    #[test]
    fn a_sliver_rounding_edge_triangle_is_under_an_eighth_pixel_and_changes_a_fragments_depth_with_an_error_within_its_band() {
        let screen = hand_made_screen();
        for band in [2, 8] {
            let tris = sliver_depth_rounding_edge_triangles(&mut Rng::new(0x511e7), screen, 40, band);
            assert_eq!(tris.len(), 40, "band {band}");
            for t in &tris {
                let st = golden::raster::setup(&t.v, t.cull, t.front, screen).expect("drawn");
                assert!(st.det.abs() < 64 * (U * U) as i64, "triangle {}: det {}", t.index, st.det);
                assert!(plane_moved_by_band_changes_a_depth(&st, band), "band {band}: triangle {} does not sit on a rounding edge", t.index);
            }
        }
    }

    #[test]
    fn a_depth_rounding_edge_triangle_changes_a_fragments_depth_with_an_error_within_its_band() {
        let screen = hand_made_screen();
        for band in [2, 32] {
            let tris = depth_rounding_edge_triangles(&mut Rng::new(0xde9_7e), screen, 40, band);
            assert_eq!(tris.len(), 40, "band {band}");
            for t in &tris {
                let st = golden::raster::setup(&t.v, t.cull, t.front, screen).expect("drawn");
                assert!(plane_moved_by_band_changes_a_depth(&st, band), "band {band}: triangle {} does not sit on a rounding edge", t.index);
            }
            // Random triangles meet a rounding edge this closely far less often.
            let plain = random_triangles(&mut Rng::new(0xde9_7e), screen, 40);
            let on_edge = plain
                .iter()
                .filter_map(|t| golden::raster::setup(&t.v, t.cull, t.front, screen).ok())
                .filter(|st| depth_near_rounding_edge(st, band))
                .count();
            assert!(on_edge < 20, "band {band}: {on_edge} of 40 random triangles");
        }
    }
}
