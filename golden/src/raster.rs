//! The Rasterizer Controller's semantics (seed 001 §2.3.1, §3.1), untimed: what the RC writes into the
//! Z-buffer and the I-buffer for a stream of triangles, and which triangles it flags visible.
//!
//! * Back-face culling by the sign of Pineda's determinant (seed 001 §2.3.1). Window y grows down,
//!   so a triangle that looks counter-clockwise on the screen has `det < 0`.
//! * Edge functions (seed 001 eq. 5) `E(p) = dx*(p.y - a.y) - dy*(p.x - a.x)` for each edge a->b of the
//!   triangle in the order with `det > 0`, at pixel centres `p = (256X+128, 256Y+128)` in subpixels: integers.
//! * Top-left fill rule: a centre exactly on an edge belongs to the triangle only if the edge is a top
//!   edge (`dy == 0 && dx > 0`) or a left edge (`dy < 0`). The RTL folds this into the edge constant:
//!   inside iff `E - bias >= 0` for all three edges, bias 0 on top-left edges and 1 elsewhere.
//! * Bounding box: the pixels whose centres lie within the vertices' extent,
//!   `X in [(xmin+127)>>8, (xmax-128)>>8]`, clamped to the screen.
//! * Depth: a [`Plane`] through the three vertex depths (one reciprocal per triangle), clamped to
//!   0..=2^24-1. Z-test "less": of equal depths the first drawn wins. The Z-buffer is cleared to the far
//!   value, the I-buffer to 0 (background). On a pass both are written.
//! * Two of seed 000's index-rendering architectures ([`RcType`]): Type IV keeps a Z-buffer beside the
//!   I-buffer; Type III keeps none and regenerates the old depth of a pixel from TdbV, the triangle
//!   database for visibility, which holds every drawn triangle's depth plane: the plane of the index
//!   stored at the pixel, evaluated there. The traversal steps the same plane with exact integer adds
//!   (`raw = C + A*X + B*Y`), so the regenerated depth is the depth Type IV would have stored and the
//!   two types draw the same I-buffer, bit for bit, whenever every triangle of a frame has its own index.

use crate::format::{
    reciprocal, Plane, Recip, Screen, WinVertex, DEPTH_MAX, INDEX_BACKGROUND, SUBPIXEL_BITS, SUBPIXEL_HALF, SUBPIXEL_ONE,
};

/// Seed 000's index-rendering architecture the RC implements: where the old depth of a pixel comes from.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub enum RcType {
    /// No Z-buffer: the depth plane of the triangle whose index the I-buffer holds, read from TdbV and
    /// evaluated at the pixel.
    III,
    /// A Z-buffer beside the I-buffer (the conventional Z-test).
    #[default]
    IV,
}

impl RcType {
    /// "III" or "IV", as the command line and the reports spell it.
    pub fn name(self) -> &'static str {
        match self {
            RcType::III => "III",
            RcType::IV => "IV",
        }
    }
}

/// Which faces are culled (glCullFace, with culling disabled as `None`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum CullMode {
    Back,
    Front,
    None,
}

/// Which winding is the front face (glFrontFace), as seen on the screen.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum FrontFace {
    Ccw,
    Cw,
}

/// Why a triangle produced no setup.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Culled {
    /// Zero area (det == 0): nothing to draw.
    ZeroArea,
    /// Removed by the cull mode.
    Facing,
}

/// One edge function, stepped in whole pixels: `E(X, Y) = c + step_x*X + step_y*Y`, already biased by
/// the fill rule so that "inside" is `E >= 0`.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct Edge {
    pub step_x: i64,
    pub step_y: i64,
    pub c: i64,
    pub top_left: bool,
}

impl Edge {
    /// The edge a->b.
    pub fn new(a: WinVertex, b: WinVertex) -> Edge {
        let dx = (b.x - a.x) as i64;
        let dy = (b.y - a.y) as i64;
        let top_left = dy < 0 || (dy == 0 && dx > 0);
        let h = SUBPIXEL_HALF as i64;
        let one = SUBPIXEL_ONE as i64;
        // E(256X+128, 256Y+128) = dx*(256Y + 128 - a.y) - dy*(256X + 128 - a.x)
        let c = dx * (h - a.y as i64) - dy * (h - a.x as i64) - if top_left { 0 } else { 1 };
        Edge { step_x: -one * dy, step_y: one * dx, c, top_left }
    }
    pub fn at(&self, x: i64, y: i64) -> i64 {
        self.c + self.step_x * x + self.step_y * y
    }
}

/// Inclusive pixel rectangle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub struct BBox {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

impl BBox {
    pub fn is_empty(&self) -> bool {
        self.x0 > self.x1 || self.y0 > self.y1
    }
    pub fn pixels(&self) -> u64 {
        if self.is_empty() {
            0
        } else {
            ((self.x1 - self.x0 + 1) as u64) * ((self.y1 - self.y0 + 1) as u64)
        }
    }
}

/// Twice the signed area in subpixel^2, window coordinates (y down): > 0 when clockwise on the screen.
pub fn det(v: &[WinVertex; 3]) -> i64 {
    (v[1].x - v[0].x) as i64 * (v[2].y - v[0].y) as i64 - (v[2].x - v[0].x) as i64 * (v[1].y - v[0].y) as i64
}

/// Put a triangle in the vertex order with `det > 0` (swap vertices 1 and 2 if needed).
/// Returns the order used, as indices into the input.
pub fn canonical_order(v: &[WinVertex; 3]) -> [usize; 3] {
    if det(v) < 0 {
        [0, 2, 1]
    } else {
        [0, 1, 2]
    }
}

/// Everything the RC's setup stage computes for one triangle.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Setup {
    /// The vertices in the order with det > 0.
    pub v: [WinVertex; 3],
    pub det: i64,
    pub recip: Recip,
    pub edges: [Edge; 3],
    pub bbox: BBox,
    pub depth: Plane,
}

/// Decide whether a triangle is culled, given the cull mode and front face.
pub fn is_culled(d: i64, cull: CullMode, front: FrontFace) -> Option<Culled> {
    if d == 0 {
        return Some(Culled::ZeroArea);
    }
    // On the screen, det > 0 is clockwise.
    let cw = d > 0;
    let is_front = match front {
        FrontFace::Cw => cw,
        FrontFace::Ccw => !cw,
    };
    match cull {
        CullMode::None => None,
        CullMode::Back if !is_front => Some(Culled::Facing),
        CullMode::Front if is_front => Some(Culled::Facing),
        _ => None,
    }
}

/// The RC's triangle setup.
pub fn setup(tri: &[WinVertex; 3], cull: CullMode, front: FrontFace, screen: Screen) -> Result<Setup, Culled> {
    let d = det(tri);
    if let Some(c) = is_culled(d, cull, front) {
        return Err(c);
    }
    let o = canonical_order(tri);
    let v = [tri[o[0]], tri[o[1]], tri[o[2]]];
    let det = d.abs();
    let recip = reciprocal(det);
    let edges = [Edge::new(v[0], v[1]), Edge::new(v[1], v[2]), Edge::new(v[2], v[0])];
    let xmin = v.iter().map(|p| p.x).min().unwrap();
    let xmax = v.iter().map(|p| p.x).max().unwrap();
    let ymin = v.iter().map(|p| p.y).min().unwrap();
    let ymax = v.iter().map(|p| p.y).max().unwrap();
    let bbox = BBox {
        x0: ((xmin + SUBPIXEL_HALF - 1) >> SUBPIXEL_BITS).max(0),
        y0: ((ymin + SUBPIXEL_HALF - 1) >> SUBPIXEL_BITS).max(0),
        x1: ((xmax - SUBPIXEL_HALF) >> SUBPIXEL_BITS).min(screen.width as i32 - 1),
        y1: ((ymax - SUBPIXEL_HALF) >> SUBPIXEL_BITS).min(screen.height as i32 - 1),
    };
    let depth = Plane::setup(&v, [v[0].z as i64, v[1].z as i64, v[2].z as i64], det, recip);
    Ok(Setup { v, det, recip, edges, bbox, depth })
}

impl Setup {
    /// Whether pixel (X, Y)'s centre is inside (fill rule included).
    pub fn covers(&self, x: i32, y: i32) -> bool {
        self.edges.iter().all(|e| e.at(x as i64, y as i64) >= 0)
    }
    /// The fragment's depth at pixel (X, Y).
    pub fn depth_at(&self, x: i32, y: i32) -> u32 {
        self.depth.eval_clamped(x as u32, y as u32, DEPTH_MAX as i64) as u32
    }
}

/// The RC's result for one triangle.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct TriResult {
    pub index: u32,
    pub culled: Option<Culled>,
    /// Some fragment passed the Z-test when it was drawn.
    pub visible: bool,
}

/// Per-frame counters of the RC.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct RcCounts {
    pub triangles: u64,
    pub culled_zero_area: u64,
    pub culled_facing: u64,
    /// Pixels in the clamped bounding boxes: what a one-pixel-per-clock traversal visits.
    pub candidates: u64,
    /// Pixels whose centre is inside a triangle: fragments.
    pub fragments: u64,
    pub z_passes: u64,
    pub flagged_visible: u64,
    /// The visibility test's memory words, clears not included: Type IV reads the Z-buffer and the
    /// I-buffer word for every fragment and writes both on a pass; Type III reads the I-buffer word,
    /// then TdbV where the pixel is owned by a triangle, writes the I-buffer on a pass, and writes one
    /// TdbV record per triangle it walks.
    pub traffic: RcTraffic,
}

/// Words moved on each of the RC's memories (reads and writes), clears not included.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct RcTraffic {
    pub z_reads: u64,
    pub z_writes: u64,
    pub i_reads: u64,
    pub i_writes: u64,
    pub tdbv_reads: u64,
    pub tdbv_writes: u64,
}

/// The RC's buffers, one entry per pixel, row 0 at the top: the I-buffer, and the Z-buffer (Type IV)
/// or TdbV (Type III, one depth plane per triangle index).
#[derive(Clone, Debug)]
pub struct Rasterizer {
    pub screen: Screen,
    pub ty: RcType,
    /// Type IV's Z-buffer; unused (left at the far value) in Type III.
    pub zbuf: Vec<u32>,
    pub ibuf: Vec<u32>,
    /// Type III's TdbV, indexed by triangle index (entry 0, the background, is never read).
    pub tdbv: Vec<Plane>,
    pub counts: RcCounts,
}

impl Rasterizer {
    /// A Type IV RC (Z-buffer).
    pub fn new(screen: Screen) -> Rasterizer {
        Rasterizer::of_type(screen, RcType::IV)
    }

    pub fn of_type(screen: Screen, ty: RcType) -> Rasterizer {
        Rasterizer {
            screen,
            ty,
            zbuf: vec![DEPTH_MAX; screen.pixels()],
            ibuf: vec![INDEX_BACKGROUND; screen.pixels()],
            tdbv: Vec::new(),
            counts: RcCounts::default(),
        }
    }

    /// Frame start: clear the buffers (TdbV needs none: only indices in the I-buffer are read).
    pub fn clear(&mut self) {
        self.zbuf.fill(DEPTH_MAX);
        self.ibuf.fill(INDEX_BACKGROUND);
        self.counts = RcCounts::default();
    }

    /// The depth a pixel holds: Type IV's Z-buffer word; Type III's regenerated from TdbV (the far value
    /// where the I-buffer holds the background).
    pub fn depth(&self, x: i32, y: i32) -> u32 {
        let a = y as usize * self.screen.width as usize + x as usize;
        match self.ty {
            RcType::IV => self.zbuf[a],
            RcType::III => match self.ibuf[a] {
                INDEX_BACKGROUND => DEPTH_MAX,
                i => self.tdbv[i as usize].eval_clamped(x as u32, y as u32, DEPTH_MAX as i64) as u32,
            },
        }
    }

    /// The depth of every pixel (see [`Rasterizer::depth`]): what the Z-buffer holds in Type IV.
    pub fn depths(&self) -> Vec<u32> {
        let (w, h) = (self.screen.width as i32, self.screen.height as i32);
        (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| self.depth(x, y)).collect()
    }

    /// Draw one triangle with hardware index `index` (1..).
    pub fn draw(&mut self, index: u32, tri: &[WinVertex; 3], cull: CullMode, front: FrontFace) -> TriResult {
        self.counts.triangles += 1;
        let s = match setup(tri, cull, front, self.screen) {
            Err(c) => {
                match c {
                    Culled::ZeroArea => self.counts.culled_zero_area += 1,
                    Culled::Facing => self.counts.culled_facing += 1,
                }
                return TriResult { index, culled: Some(c), visible: false };
            }
            Ok(s) => s,
        };
        let mut visible = false;
        let w = self.screen.width as usize;
        if !s.bbox.is_empty() {
            self.counts.candidates += s.bbox.pixels();
            if self.ty == RcType::III {
                // The traversal writes the triangle's depth plane into TdbV when it starts the walk.
                if self.tdbv.len() <= index as usize {
                    self.tdbv.resize(index as usize + 1, Plane::default());
                }
                self.tdbv[index as usize] = s.depth;
                self.counts.traffic.tdbv_writes += 1;
            }
            for y in s.bbox.y0..=s.bbox.y1 {
                for x in s.bbox.x0..=s.bbox.x1 {
                    if !s.covers(x, y) {
                        continue;
                    }
                    self.counts.fragments += 1;
                    let z = s.depth_at(x, y);
                    let a = y as usize * w + x as usize;
                    let t = &mut self.counts.traffic;
                    t.i_reads += 1;
                    let old = match self.ty {
                        RcType::IV => {
                            t.z_reads += 1;
                            // The I-buffer word read with the depth: a background index marks it stale.
                            if self.ibuf[a] == INDEX_BACKGROUND { DEPTH_MAX } else { self.zbuf[a] }
                        }
                        RcType::III => match self.ibuf[a] {
                            INDEX_BACKGROUND => DEPTH_MAX,
                            i => {
                                t.tdbv_reads += 1;
                                self.tdbv[i as usize].eval_clamped(x as u32, y as u32, DEPTH_MAX as i64) as u32
                            }
                        },
                    };
                    if z < old {
                        if self.ty == RcType::IV {
                            self.zbuf[a] = z;
                            t.z_writes += 1;
                        }
                        self.ibuf[a] = index;
                        t.i_writes += 1;
                        self.counts.z_passes += 1;
                        visible = true;
                    }
                }
            }
        }
        if visible {
            self.counts.flagged_visible += 1;
        }
        TriResult { index, culled: None, visible }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: i32, y: i32, z: u32) -> WinVertex {
        WinVertex { x: x * SUBPIXEL_ONE, y: y * SUBPIXEL_ONE, z }
    }

    #[test]
    fn clockwise_on_screen_has_positive_det() {
        // (0,0) -> (1,0) -> (0,1) with y down turns clockwise on the screen.
        assert!(det(&[v(0, 0, 0), v(1, 0, 0), v(0, 1, 0)]) > 0);
        assert_eq!(is_culled(1, CullMode::Back, FrontFace::Ccw), Some(Culled::Facing));
        assert_eq!(is_culled(-1, CullMode::Back, FrontFace::Ccw), None);
        assert_eq!(is_culled(1, CullMode::Front, FrontFace::Ccw), None);
        assert_eq!(is_culled(1, CullMode::None, FrontFace::Ccw), None);
        assert_eq!(is_culled(0, CullMode::None, FrontFace::Ccw), Some(Culled::ZeroArea));
    }

    #[test]
    fn two_triangles_sharing_a_diagonal_cover_a_square_exactly_once() {
        let s = Screen::new(16, 16).unwrap();
        let mut r = Rasterizer::new(s);
        let a = [v(2, 2, 10), v(10, 2, 10), v(10, 10, 10)];
        let b = [v(2, 2, 10), v(10, 10, 10), v(2, 10, 10)];
        let mut hits = vec![0u32; 256];
        for (i, t) in [a, b].iter().enumerate() {
            let st = setup(t, CullMode::None, FrontFace::Ccw, s).unwrap();
            for y in 0..16 {
                for x in 0..16 {
                    if st.covers(x, y) {
                        hits[(y * 16 + x) as usize] += 1;
                    }
                }
            }
            r.draw(i as u32 + 1, t, CullMode::None, FrontFace::Ccw);
        }
        // The square [2,10)x[2,10) has 64 pixel centres; each is hit once.
        assert_eq!(hits.iter().filter(|&&h| h == 1).count(), 64);
        assert!(hits.iter().all(|&h| h <= 1));
    }

    #[test]
    fn z_test_keeps_first_of_equal_depths() {
        let s = Screen::new(8, 8).unwrap();
        let mut r = Rasterizer::new(s);
        let t = [v(0, 0, 100), v(8, 0, 100), v(0, 8, 100)];
        assert!(r.draw(1, &t, CullMode::None, FrontFace::Ccw).visible);
        assert!(!r.draw(2, &t, CullMode::None, FrontFace::Ccw).visible);
        assert!(r.ibuf.iter().all(|&i| i == 0 || i == 1));
    }

    #[test]
    fn off_screen_triangle_has_an_empty_bounding_box() {
        let s = Screen::new(8, 8).unwrap();
        let st = setup(&[v(-5, -5, 0), v(-1, -5, 0), v(-5, -1, 0)], CullMode::None, FrontFace::Ccw, s).unwrap();
        assert!(st.bbox.is_empty());
    }
}
