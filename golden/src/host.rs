//! The host side of seed 001's dual pipeline: what the embedded CPU does before and after the chipset.
//!
//! Upper pipeline (every triangle): viewing transform and perspective of the vertices, clipping in
//! homogeneous space against the near and far planes (and the guard band), viewport to S11.8 window
//! coordinates. Lower pipeline (only triangles the RC flagged visible: *enhanced deferred lighting*,
//! seed 001 §3.2): viewing transform of the normals and Phong lighting per vertex.
//!
//! The CPU works in f64; the operation counts follow seed 001 Fig. 9 per operation: a viewing transform
//! is 12 MUL + 9 ADD per vertex (or normal), a perspective transform 5 MUL + 1 ADD per vertex, and one
//! lighting operation 34 MUL + 19 ADD + 3 reciprocal square roots per vertex and light.

use crate::format::{Screen, WinVertex, DEPTH_MAX, SUBPIXEL_ONE};
use crate::scene::{Material, Mesh, Triangle};

pub type Vec3 = [f64; 3];

pub fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
pub fn normalize(a: Vec3) -> Vec3 {
    let l = dot(a, a).sqrt();
    if l > 0.0 {
        [a[0] / l, a[1] / l, a[2] / l]
    } else {
        a
    }
}

/// Camera in the sense of gluLookAt + gluPerspective.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Camera {
    pub eye: Vec3,
    pub center: Vec3,
    pub up: Vec3,
    pub fovy_deg: f64,
    pub near: f64,
    pub far: f64,
}

impl Camera {
    /// A camera that frames the whole mesh: looks from `direction` at the centre of the mesh's bounding
    /// box, at the smallest distance where every vertex projects inside 90% of the viewport (of the given
    /// aspect ratio, width / height); near and far enclose the bounding sphere.
    pub fn framing_aspect(mesh: &Mesh, direction: Vec3, fovy_deg: f64, aspect: f64) -> Camera {
        let (c, r) = mesh.bounding_sphere();
        let d = normalize(direction);
        let up = [0.0, 1.0, 0.0];
        // Camera axes: s right, u up, d towards the eye.
        let s = normalize(cross(up, d));
        let u = cross(d, s);
        let ty = (fovy_deg.to_radians() / 2.0).tan() * 0.9;
        let tx = ty * aspect;
        // A vertex at offset q from the centre projects inside if |q.s| <= tx (dist - q.d), |q.u| <= ty (dist - q.d).
        let dist = mesh
            .positions
            .iter()
            .map(|p| {
                let q = sub(*p, c);
                let along = dot(q, d);
                (along + dot(q, s).abs() / tx).max(along + dot(q, u).abs() / ty)
            })
            .fold(r * 0.01, f64::max)
            .max(r * 1.001);
        let eye = [c[0] + d[0] * dist, c[1] + d[1] * dist, c[2] + d[2] * dist];
        let far = dist + r;
        Camera { eye, center: c, up, fovy_deg, near: (dist - r).max(far * 0.001), far }
    }

    /// [`Camera::framing_aspect`] for a square viewport (fits any aspect ratio of at least 1).
    pub fn framing(mesh: &Mesh, direction: Vec3, fovy_deg: f64) -> Camera {
        Camera::framing_aspect(mesh, direction, fovy_deg, 1.0)
    }

    /// The default view of the `render` command: from direction (0.3, 0.45, 1), 40 degrees, framed for
    /// the screen's aspect ratio.
    pub fn default_view(mesh: &Mesh, screen: Screen) -> Camera {
        Camera::for_mesh(mesh, 40.0, screen.width as f64 / screen.height as f64)
    }

    /// The mesh's own view ([`Mesh::view`]) if it has one, else the whole mesh framed from the usual
    /// direction; near and far enclose the bounding sphere.
    pub fn for_mesh(mesh: &Mesh, fovy_deg: f64, aspect: f64) -> Camera {
        let mut c = Camera::framing_aspect(mesh, [0.3, 0.45, 1.0], fovy_deg, aspect);
        if let Some(v) = mesh.view {
            (c.eye, c.center) = (v.eye, v.center);
            (c.near, c.far) = Camera::near_far_for(mesh, v.eye);
        }
        c
    }

    /// Near and far from the bounding sphere for a given eye (the CLI's default when only the eye is given).
    pub fn near_far_for(mesh: &Mesh, eye: Vec3) -> (f64, f64) {
        let (c, r) = mesh.bounding_sphere();
        let dist = dot(sub(eye, c), sub(eye, c)).sqrt();
        let far = dist + r;
        ((dist - r).max(far * 0.001), far)
    }

    /// Reject cameras that make no image (the CLI reports these as argument errors).
    /// Positions beyond [`CAMERA_RANGE`] are refused: their squared distances overflow f64.
    pub fn validate(&self) -> Result<(), String> {
        let all = [self.eye, self.center, self.up].concat();
        if all.iter().any(|v| !v.is_finite()) || !self.near.is_finite() || !self.far.is_finite() || !self.fovy_deg.is_finite() {
            return Err("camera: eye, center, up, near, far and fovy must be finite numbers".into());
        }
        if !(self.fovy_deg > 0.0 && self.fovy_deg < 180.0) {
            return Err(format!("camera: fovy {} is not in (0, 180) degrees", self.fovy_deg));
        }
        for (what, p) in [("eye", self.eye), ("center", self.center)] {
            if p.iter().any(|v| v.abs() > CAMERA_RANGE) {
                return Err(format!(
                    "camera: {what} ({}, {}, {}) is outside +-{CAMERA_RANGE:e}: f64 cannot resolve the view from there",
                    p[0], p[1], p[2]
                ));
            }
        }
        let f = sub(self.center, self.eye);
        if dot(f, f) == 0.0 {
            return Err("camera: eye and center are the same point".into());
        }
        let s = cross(normalize(f), normalize(self.up));
        if dot(self.up, self.up) == 0.0 || dot(s, s) < 1e-12 {
            return Err("camera: up is zero or parallel to the viewing direction".into());
        }
        if !(self.near > 0.0 && self.far > self.near) {
            return Err(format!("camera: need 0 < near < far, got near {} far {}", self.near, self.far));
        }
        Ok(())
    }

    /// The 3x4 viewing matrix of gluLookAt (rows s, u, -f with translation).
    pub fn view_matrix(&self) -> [[f64; 4]; 3] {
        let f = normalize(sub(self.center, self.eye));
        let s = normalize(cross(f, self.up));
        let u = cross(s, f);
        [
            [s[0], s[1], s[2], -dot(s, self.eye)],
            [u[0], u[1], u[2], -dot(u, self.eye)],
            [-f[0], -f[1], -f[2], dot(f, self.eye)],
        ]
    }
}

/// The largest camera coordinate accepted (`Camera::validate`): squares of differences stay far below
/// f64's range, and a scene of ordinary size is still resolved from that far.
pub const CAMERA_RANGE: f64 = 1e15;

/// One directional light, its direction given in eye space (towards the light) and its intensity.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Light {
    pub direction: Vec3,
    pub intensity: [f64; 3],
}

/// The lighting environment: ambient intensity Ia and one or more directional lights; the viewer is at
/// infinity along +z of eye space (OpenGL's default, non-local viewer), so H is constant per light.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Lighting {
    pub ambient: [f64; 3],
    pub lights: Vec<Light>,
}

impl Default for Lighting {
    fn default() -> Self {
        Lighting {
            ambient: [0.2, 0.2, 0.2],
            lights: vec![Light { direction: normalize([-0.4, 0.6, 0.7]), intensity: [0.85, 0.85, 0.85] }],
        }
    }
}

impl Lighting {
    /// Seed 001 eq. 4 for one eye-space normal, in f64 (the CPU's arithmetic): returns RGB in 0..1.
    pub fn shade(&self, m: &Material, n: Vec3) -> [f64; 3] {
        let n = normalize(n);
        let mut c = [0.0; 3];
        for k in 0..3 {
            c[k] = self.ambient[k] * m.ambient[k];
        }
        for l in &self.lights {
            let ld = normalize(l.direction);
            let h = normalize([ld[0], ld[1], ld[2] + 1.0]);
            let nl = dot(n, ld).max(0.0);
            let nh = dot(n, h).max(0.0);
            let spec = if nl > 0.0 { nh.powi(m.gloss as i32) } else { 0.0 };
            for k in 0..3 {
                c[k] += l.intensity[k] * (m.diffuse[k] * nl + m.specular[k] * spec);
            }
        }
        c
    }
}

/// Quantise a 0..1 colour to RGB888 (round to nearest, saturate).
pub fn to_rgb8(c: [f64; 3]) -> [u8; 3] {
    c.map(|v| (v * 255.0).round().clamp(0.0, 255.0) as u8)
}

/// Operation counts of one pipeline stage.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Ops {
    pub mul: u64,
    pub add: u64,
    pub rsqrt: u64,
}

impl Ops {
    pub const VIEW: Ops = Ops { mul: 12, add: 9, rsqrt: 0 };
    pub const PERSPECTIVE: Ops = Ops { mul: 5, add: 1, rsqrt: 0 };
    pub const LIGHTING: Ops = Ops { mul: 34, add: 19, rsqrt: 3 };

    pub fn times(self, n: u64) -> Ops {
        Ops { mul: self.mul * n, add: self.add * n, rsqrt: self.rsqrt * n }
    }
    pub fn plus(self, o: Ops) -> Ops {
        Ops { mul: self.mul + o.mul, add: self.add + o.add, rsqrt: self.rsqrt + o.rsqrt }
    }
    /// Seed 001's equivalent CPU cost: ADD = 1, MUL = 2, reciprocal square root = 16.
    pub fn cost(&self) -> u64 {
        self.add + 2 * self.mul + 16 * self.rsqrt
    }
}

/// The host's operation counts per stage (seed 001 Table 2's rows), counted as the host does them.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct HostOps {
    /// Viewing transforms of vertex coordinates (one per triangle corner: strips are not used, as in the seed).
    pub view_vertices: u64,
    /// Perspective transforms of vertex coordinates.
    pub perspective: u64,
    /// Viewing transforms of normal vectors.
    pub view_normals: u64,
    /// Lighting operations (one per vertex and light; per triangle and light for flat shading).
    pub lighting: u64,
}

impl HostOps {
    pub fn ops(&self) -> Ops {
        Ops::VIEW
            .times(self.view_vertices)
            .plus(Ops::PERSPECTIVE.times(self.perspective))
            .plus(Ops::VIEW.times(self.view_normals))
            .plus(Ops::LIGHTING.times(self.lighting))
    }
}

/// A triangle as the host sends it to the RC: window vertices plus, per vertex, its barycentric weights
/// in the source triangle (clipping makes new vertices), so that lighting can be done later on the
/// source triangle's three vertices only.
#[derive(Clone, Debug, PartialEq)]
pub struct HwTriangle {
    /// Position of the source triangle in the input order (0-based).
    pub source: u32,
    pub v: [WinVertex; 3],
    pub bary: [[f64; 3]; 3],
    /// Each vertex's clip-space w (the eye-space depth, > 0 after clipping), for perspective-correct
    /// texture coordinates.
    pub w: [f64; 3],
}

/// Counts of the upper pipeline.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ClipStats {
    /// Source triangles entirely outside a clip plane (dropped: nothing of them is on screen).
    pub clipped_away: u64,
    /// Source triangles that crossed a plane and were split.
    pub split: u64,
    /// Triangles sent to the RC.
    pub sent: u64,
}

/// The guard band in NDC: the viewport maps [-1, 1] onto the screen and the window formats hold one
/// screen beyond each edge, i.e. NDC [-3, 3). Clipping at 2.9 keeps rounding inside the band.
const GUARD_NDC: f64 = 2.9;

/// A clip-space vertex with its barycentric weights in the source triangle.
#[derive(Copy, Clone, Debug)]
struct ClipVertex {
    p: [f64; 4],
    bary: [f64; 3],
}

/// Distances to the clip planes (>= 0 inside): near z >= -w, far z <= w, then the guard band in x and y.
fn plane_distances(p: &[f64; 4]) -> [f64; 6] {
    let [x, y, z, w] = *p;
    [z + w, w - z, GUARD_NDC * w + x, GUARD_NDC * w - x, GUARD_NDC * w + y, GUARD_NDC * w - y]
}

/// Sutherland-Hodgman clipping of a convex polygon against one plane in homogeneous space.
fn clip_polygon(poly: &[ClipVertex], plane: usize) -> Vec<ClipVertex> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for i in 0..poly.len() {
        let a = poly[i];
        let b = poly[(i + 1) % poly.len()];
        let da = plane_distances(&a.p)[plane];
        let db = plane_distances(&b.p)[plane];
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            let lerp = |u: f64, v: f64| u + (v - u) * t;
            out.push(ClipVertex {
                p: [lerp(a.p[0], b.p[0]), lerp(a.p[1], b.p[1]), lerp(a.p[2], b.p[2]), lerp(a.p[3], b.p[3])],
                bary: [lerp(a.bary[0], b.bary[0]), lerp(a.bary[1], b.bary[1]), lerp(a.bary[2], b.bary[2])],
            });
        }
    }
    out
}

/// The upper pipeline on the CPU: transforms every triangle's vertices, clips, maps to window
/// coordinates. Returns the triangles to send to the RC in order, and counts.
pub struct Geometry {
    pub hw: Vec<HwTriangle>,
    pub clip: ClipStats,
    pub ops: HostOps,
}

pub fn upper_pipeline(mesh: &Mesh, cam: &Camera, screen: Screen) -> Geometry {
    let v = cam.view_matrix();
    let aspect = screen.width as f64 / screen.height as f64;
    let f = 1.0 / (cam.fovy_deg.to_radians() / 2.0).tan();
    let (n, fa) = (cam.near, cam.far);
    // gluPerspective: x' = f/aspect x, y' = f y, z' = (f+n)/(n-f) z + 2fn/(n-f), w' = -z.
    let (pa, pb) = ((fa + n) / (n - fa), 2.0 * fa * n / (n - fa));
    let mut ops = HostOps::default();
    let mut clip = ClipStats::default();
    let mut hw = Vec::with_capacity(mesh.triangles.len());
    let to_clip = |p: [f64; 3]| -> [f64; 4] {
        let e = [0, 1, 2].map(|r| v[r][0] * p[0] + v[r][1] * p[1] + v[r][2] * p[2] + v[r][3]);
        [f / aspect * e[0], f * e[1], pa * e[2] + pb, -e[2]]
    };
    let to_window = |p: &[f64; 4]| -> WinVertex {
        let (x, y, z) = (p[0] / p[3], p[1] / p[3], p[2] / p[3]);
        let xw = (x + 1.0) * 0.5 * screen.width as f64;
        let yw = (1.0 - y) * 0.5 * screen.height as f64;
        let zw = ((z + 1.0) * 0.5 * DEPTH_MAX as f64).round().clamp(0.0, DEPTH_MAX as f64);
        WinVertex { x: (xw * SUBPIXEL_ONE as f64).round() as i32, y: (yw * SUBPIXEL_ONE as f64).round() as i32, z: zw as u32 }
    };
    for (ti, t) in mesh.triangles.iter().enumerate() {
        ops.view_vertices += 3;
        ops.perspective += 3;
        let poly: Vec<ClipVertex> = (0..3)
            .map(|k| {
                let mut bary = [0.0; 3];
                bary[k] = 1.0;
                ClipVertex { p: to_clip(mesh.positions[t.v[k] as usize]), bary }
            })
            .collect();
        let inside_all = poly.iter().all(|c| plane_distances(&c.p).iter().all(|&d| d >= 0.0));
        let pieces = if inside_all {
            poly
        } else {
            let mut p = poly;
            for plane in 0..6 {
                p = clip_polygon(&p, plane);
                if p.len() < 3 {
                    break;
                }
            }
            if p.len() < 3 {
                clip.clipped_away += 1;
                continue;
            }
            clip.split += 1;
            p
        };
        let win: Vec<WinVertex> = pieces.iter().map(|c| to_window(&c.p)).collect();
        for k in 1..pieces.len() - 1 {
            hw.push(HwTriangle {
                source: ti as u32,
                v: [win[0], win[k], win[k + 1]],
                bary: [pieces[0].bary, pieces[k].bary, pieces[k + 1].bary],
                w: [pieces[0].p[3], pieces[k].p[3], pieces[k + 1].p[3]],
            });
        }
    }
    clip.sent = hw.len() as u64;
    Geometry { hw, clip, ops }
}

/// Lower pipeline, per source triangle: transform the corner normals to eye space (the inverse transpose
/// of the view matrix's rotation is the rotation itself, since gluLookAt is orthonormal).
pub fn eye_normals(mesh: &Mesh, cam: &Camera, t: &Triangle) -> [Vec3; 3] {
    let v = cam.view_matrix();
    t.n.map(|ni| {
        let n = mesh.normals[ni as usize];
        normalize([0, 1, 2].map(|r| v[r][0] * n[0] + v[r][1] * n[1] + v[r][2] * n[2]))
    })
}
