//! Built-in scenes: the seeds' test models, generated in code so that no data files are needed.
//!
//! | name | what | triangles | why it is here |
//! |---|---|---|---|
//! | `polyhedron` | two big overlapping triangles, red and blue | 2 | seed 000's low-end user-interface case |
//! | `teapot` | GLUT's glutSolidTeapot at grid 14 | 12544 | the seeds' "Teapot": many small triangles, 112 of zero area |
//! | `castle` | walls and towers hiding each other | 3000 | the seeds' "Castle": high depth complexity, ~20% visible |
//! | `dolphins` | three smooth bodies leaping in an arc | 3000 | the seeds' "Dolphins": few, mostly convex, smooth bodies |
//! | `teapot-floor` | the teapot on a checkered floor, textured with [`crate::texture::checker`] | 12546 | texture mapping (issue 17): the floor's two big triangles recede, so perspective-correct and affine coordinates differ plainly and the far squares need mipmaps |
//!
//! Everything is deterministic (no random numbers), every normal has unit length and every mesh
//! passes [`Mesh::validate`].

use super::{Material, Mesh, Triangle, View, Winding};

/// Names accepted by [`scene`], in the order a user interface should list them.
pub const SCENES: &[&str] = &["polyhedron", "teapot", "castle", "dolphins"];

/// Built-in scenes with transparent materials (issue 22), for PROOF only: the index-rendering chipset
/// keeps one triangle per pixel and refuses them (render them there with `--opacity 1`).
pub const TRANSPARENT_SCENES: &[&str] = &["glass"];

/// Built-in scenes drawn with a texture (issue 17): the built-in checker unless `--texture` names one.
pub const TEXTURED_SCENES: &[&str] = &["teapot-floor"];

/// The teapot's grid as GLUT 3.7's glutSolidTeapot draws it (`teapot_glut.md`).
pub const TEAPOT_GRID: u32 = 14;

/// The built-in scene of the given name; an unknown name is an error that lists the known ones.
pub fn scene(name: &str) -> Result<Mesh, String> {
    match name {
        "polyhedron" => Ok(polyhedron()),
        "teapot" => Ok(teapot(TEAPOT_GRID)),
        "castle" => Ok(castle()),
        "dolphins" => Ok(dolphins()),
        "glass" => Ok(glass()),
        "teapot-floor" => Ok(teapot_floor()),
        _ => Err(format!(
            "unknown scene '{}'; the built-in scenes are: {}, {}, {}",
            name,
            SCENES.join(", "),
            TEXTURED_SCENES.join(", "),
            TRANSPARENT_SCENES.join(", ")
        )),
    }
}

// ---------------------------------------------------------------------------------------------
// Small vector helpers (the golden model has no linear-algebra dependency).

type V3 = [f64; 3];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn length(a: V3) -> f64 {
    dot(a, a).sqrt()
}

fn normalize(a: V3) -> V3 {
    scale(a, 1.0 / length(a))
}

// ---------------------------------------------------------------------------------------------
// polyhedron

/// Two large triangles facing +z (counter-clockwise seen from +z), the blue one 0.3 in front of the
/// red one and overlapping it, so that a view down -z shows both colours and one hidden region.
pub fn polyhedron() -> Mesh {
    let positions = vec![
        // Red, at z = 0.
        [-0.9, -0.8, 0.0],
        [0.8, -0.5, 0.0],
        [-0.3, 0.9, 0.0],
        // Blue, at z = 0.3 (nearer a viewer on +z).
        [0.9, 0.9, 0.3],
        [-0.5, 0.5, 0.3],
        [0.4, -0.9, 0.3],
    ];
    let face_normal = |i: usize| normalize(cross(sub(positions[i + 1], positions[i]), sub(positions[i + 2], positions[i])));
    let normals = vec![face_normal(0), face_normal(3)];
    let materials = vec![Material::plastic([0.9, 0.15, 0.1]), Material::plastic([0.1, 0.25, 0.9])];
    let triangles = vec![Triangle { v: [0, 1, 2], n: [0, 0, 0], material: 0 }, Triangle { v: [3, 4, 5], n: [1, 1, 1], material: 1 }];
    Mesh { name: "polyhedron".into(), positions, normals, materials, triangles, front_face: Winding::Ccw, texcoords: Vec::new(), triangle_texcoords: Vec::new(), view: None }
}

// ---------------------------------------------------------------------------------------------
// teapot (data and tessellation from /work/shared/data/teapot_glut.md)

#[rustfmt::skip]
const TEAPOT_POINTS: [V3; 127] = [
    [0.2, 0.0, 2.7], [0.2, -0.112, 2.7], [0.112, -0.2, 2.7], [0.0, -0.2, 2.7],
    [1.3375, 0.0, 2.53125], [1.3375, -0.749, 2.53125], [0.749, -1.3375, 2.53125], [0.0, -1.3375, 2.53125],
    [1.4375, 0.0, 2.53125], [1.4375, -0.805, 2.53125], [0.805, -1.4375, 2.53125], [0.0, -1.4375, 2.53125],
    [1.5, 0.0, 2.4], [1.5, -0.84, 2.4], [0.84, -1.5, 2.4], [0.0, -1.5, 2.4],
    [1.75, 0.0, 1.875], [1.75, -0.98, 1.875], [0.98, -1.75, 1.875], [0.0, -1.75, 1.875],
    [2.0, 0.0, 1.35], [2.0, -1.12, 1.35], [1.12, -2.0, 1.35], [0.0, -2.0, 1.35],
    [2.0, 0.0, 0.9], [2.0, -1.12, 0.9], [1.12, -2.0, 0.9], [0.0, -2.0, 0.9],
    [-2.0, 0.0, 0.9], [2.0, 0.0, 0.45], [2.0, -1.12, 0.45], [1.12, -2.0, 0.45],
    [0.0, -2.0, 0.45], [1.5, 0.0, 0.225], [1.5, -0.84, 0.225], [0.84, -1.5, 0.225],
    [0.0, -1.5, 0.225], [1.5, 0.0, 0.15], [1.5, -0.84, 0.15], [0.84, -1.5, 0.15],
    [0.0, -1.5, 0.15], [-1.6, 0.0, 2.025], [-1.6, -0.3, 2.025], [-1.5, -0.3, 2.25],
    [-1.5, 0.0, 2.25], [-2.3, 0.0, 2.025], [-2.3, -0.3, 2.025], [-2.5, -0.3, 2.25],
    [-2.5, 0.0, 2.25], [-2.7, 0.0, 2.025], [-2.7, -0.3, 2.025], [-3.0, -0.3, 2.25],
    [-3.0, 0.0, 2.25], [-2.7, 0.0, 1.8], [-2.7, -0.3, 1.8], [-3.0, -0.3, 1.8],
    [-3.0, 0.0, 1.8], [-2.7, 0.0, 1.575], [-2.7, -0.3, 1.575], [-3.0, -0.3, 1.35],
    [-3.0, 0.0, 1.35], [-2.5, 0.0, 1.125], [-2.5, -0.3, 1.125], [-2.65, -0.3, 0.9375],
    [-2.65, 0.0, 0.9375], [-2.0, -0.3, 0.9], [-1.9, -0.3, 0.6], [-1.9, 0.0, 0.6],
    [1.7, 0.0, 1.425], [1.7, -0.66, 1.425], [1.7, -0.66, 0.6], [1.7, 0.0, 0.6],
    [2.6, 0.0, 1.425], [2.6, -0.66, 1.425], [3.1, -0.66, 0.825], [3.1, 0.0, 0.825],
    [2.3, 0.0, 2.1], [2.3, -0.25, 2.1], [2.4, -0.25, 2.025], [2.4, 0.0, 2.025],
    [2.7, 0.0, 2.4], [2.7, -0.25, 2.4], [3.3, -0.25, 2.4], [3.3, 0.0, 2.4],
    [2.8, 0.0, 2.475], [2.8, -0.25, 2.475], [3.525, -0.25, 2.49375], [3.525, 0.0, 2.49375],
    [2.9, 0.0, 2.475], [2.9, -0.15, 2.475], [3.45, -0.15, 2.5125], [3.45, 0.0, 2.5125],
    [2.8, 0.0, 2.4], [2.8, -0.15, 2.4], [3.2, -0.15, 2.4], [3.2, 0.0, 2.4],
    [0.0, 0.0, 3.15], [0.8, 0.0, 3.15], [0.8, -0.45, 3.15], [0.45, -0.8, 3.15],
    [0.0, -0.8, 3.15], [0.0, 0.0, 2.85], [1.4, 0.0, 2.4], [1.4, -0.784, 2.4],
    [0.784, -1.4, 2.4], [0.0, -1.4, 2.4], [0.4, 0.0, 2.55], [0.4, -0.224, 2.55],
    [0.224, -0.4, 2.55], [0.0, -0.4, 2.55], [1.3, 0.0, 2.55], [1.3, -0.728, 2.55],
    [0.728, -1.3, 2.55], [0.0, -1.3, 2.55], [1.3, 0.0, 2.4], [1.3, -0.728, 2.4],
    [0.728, -1.3, 2.4], [0.0, -1.3, 2.4], [0.0, 0.0, 0.0], [1.425, -0.798, 0.0],
    [1.5, 0.0, 0.075], [1.425, 0.0, 0.0], [0.798, -1.425, 0.0], [0.0, -1.5, 0.075],
    [0.0, -1.425, 0.0], [1.5, -0.84, 0.075], [0.84, -1.5, 0.075],
];

/// The 10 patches, 16 control-point numbers each, row-major (4 rows j of 4 columns k).
#[rustfmt::skip]
const TEAPOT_PATCHES: [[usize; 16]; 10] = [
    // rim
    [102, 103, 104, 105, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15],
    // body
    [12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27],
    [24, 25, 26, 27, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40],
    // lid
    [96, 96, 96, 96, 97, 98, 99, 100, 101, 101, 101, 101, 0, 1, 2, 3],
    [0, 1, 2, 3, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117],
    // bottom
    [118, 118, 118, 118, 124, 122, 119, 121, 123, 126, 125, 120, 40, 39, 38, 37],
    // handle
    [41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56],
    [53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 28, 65, 66, 67],
    // spout
    [68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83],
    [80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95],
];

/// Cubic Bernstein weights B0..B3 at t.
fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

/// Derivatives dB0/dt..dB3/dt at t.
fn bernstein_derivative(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t]
}

/// A bicubic Bezier patch, `p[j][k]`: u runs along k, v along j (glMap2's convention as GLUT uses it).
type Patch = [[V3; 4]; 4];

/// Point, dP/du and dP/dv of a patch at (u, v).
fn patch_eval(p: &Patch, u: f64, v: f64) -> (V3, V3, V3) {
    let (bu, bv, du, dv) = (bernstein(u), bernstein(v), bernstein_derivative(u), bernstein_derivative(v));
    let mut point = [0.0; 3];
    let mut pu = [0.0; 3];
    let mut pv = [0.0; 3];
    for j in 0..4 {
        // A row whose four control points coincide is that point exactly: without this shortcut the
        // weights, which sum to 1 only up to rounding, would scatter the lid's and the bottom's centre
        // by an ulp and the 112 zero-area triangles of the data file would get a tiny area instead.
        let row =
            if p[j].iter().all(|c| *c == p[j][0]) { p[j][0] } else { (0..4).fold([0.0; 3], |acc, k| add(acc, scale(p[j][k], bu[k]))) };
        let row_du = (0..4).fold([0.0; 3], |acc, k| add(acc, scale(p[j][k], du[k])));
        point = add(point, scale(row, bv[j]));
        pu = add(pu, scale(row_du, bv[j]));
        pv = add(pv, scale(row, dv[j]));
    }
    (point, pu, pv)
}

/// The outward normal of a patch at (u, v), in the patch's (GLUT's pre-rotation) frame.
///
/// GL_AUTO_NORMAL's cross(dP/du, dP/dv) points out of the pot for GLUT's patches (the triangles
/// are clockwise from outside, and strip order makes the counter-clockwise normal cross(dP/dv, dP/du)).
/// At the lid's and the bottom's centre dP/du vanishes; there the limit normal is taken by
/// evaluating a hair's breadth towards the patch centre.
fn patch_normal(p: &Patch, u: f64, v: f64) -> V3 {
    let (_, pu, pv) = patch_eval(p, u, v);
    let n = cross(pu, pv);
    if length(n) > 1e-9 {
        return normalize(n);
    }
    let nudge = 1e-5;
    let (_, pu, pv) = patch_eval(p, u + (0.5 - u) * nudge, v + (0.5 - v) * nudge);
    normalize(cross(pu, pv))
}

/// GLUT's glRotatef(270, 1, 0, 0) then glScalef(s) then glTranslatef(0, 0, -1.5): the teapot
/// stands upright along +y.
fn teapot_transform(p: V3, s: f64) -> V3 {
    [s * p[0], s * (p[2] - 1.5), -s * p[1]]
}

/// The rotation part of [`teapot_transform`], for normals.
fn teapot_rotate(n: V3) -> V3 {
    [n[0], n[2], -n[1]]
}

/// The 32 patches in GLUT's drawing order: for each of the 10 patches p, then its mirror q in y, and
/// for the first six (rim, body, lid, bottom) also r (mirror in x) and s (mirror in x and y).
fn teapot_patches() -> Vec<Patch> {
    let mut out = Vec::with_capacity(32);
    for (i, numbers) in TEAPOT_PATCHES.iter().enumerate() {
        let at = |j: usize, k: usize| TEAPOT_POINTS[numbers[4 * j + k]];
        let make = |f: &dyn Fn(usize, usize) -> V3| -> Patch {
            let mut p = [[[0.0; 3]; 4]; 4];
            for (j, row) in p.iter_mut().enumerate() {
                for (k, c) in row.iter_mut().enumerate() {
                    *c = f(j, k);
                }
            }
            p
        };
        out.push(make(&|j, k| at(j, k)));
        out.push(make(&|j, k| {
            let c = at(j, 3 - k);
            [c[0], -c[1], c[2]]
        }));
        if i < 6 {
            out.push(make(&|j, k| {
                let c = at(j, 3 - k);
                [-c[0], c[1], c[2]]
            }));
            out.push(make(&|j, k| {
                let c = at(j, k);
                [-c[0], -c[1], c[2]]
            }));
        }
    }
    out
}

/// glutSolidTeapot(1.0) tessellated on a `grid` x `grid` mesh per patch: 2 * grid^2 * 32 triangles in
/// glEvalMesh2's triangle-strip order, zero-area ones included, wound clockwise from outside, with
/// GLUT's texture coordinates (each patch spans the texture once).
///
/// Panics if `grid` is 0 (there would be no triangles).
pub fn teapot(grid: u32) -> Mesh {
    assert!(grid >= 1, "teapot grid must be at least 1");
    let g = grid as usize;
    let size = 1.0;
    let s = 0.5 * size;
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut texcoords = Vec::new();
    let mut triangles = Vec::with_capacity(2 * g * g * 32);
    for patch in teapot_patches() {
        // Grid vertex (i along u, j along v) has index base + j * (g + 1) + i; normals share the index.
        let base = positions.len() as u32;
        for j in 0..=g {
            let v = j as f64 / g as f64;
            for i in 0..=g {
                let u = i as f64 / g as f64;
                let (point, _, _) = patch_eval(&patch, u, v);
                positions.push(teapot_transform(point, s));
                normals.push(teapot_rotate(patch_normal(&patch, u, v)));
                // GLUT maps GL_MAP2_TEXTURE_COORD_2 with the corners (0,0), (1,0), (0,1), (1,1)
                // over every patch: texture coordinates (s, t) = (u, v).
                texcoords.push([u, v]);
            }
        }
        let index = |i: usize, j: usize| base + (j * (g + 1) + i) as u32;
        for j in 0..g {
            // glEvalMesh2(GL_FILL) draws one strip per row: (u0, v), (u0, v+1), (u1, v), (u1, v+1), ...
            let strip: Vec<u32> = (0..=g).flat_map(|i| [index(i, j), index(i, j + 1)]).collect();
            for n in 0..2 * g {
                // GL_TRIANGLE_STRIP flips every odd triangle to keep the winding.
                let v = if n % 2 == 0 { [strip[n], strip[n + 1], strip[n + 2]] } else { [strip[n + 1], strip[n], strip[n + 2]] };
                triangles.push(Triangle { v, n: v, material: 0 });
            }
        }
    }
    // Glazed: a white specular strong enough that per-pixel (Phong) highlights show plainly.
    let teapot_colour = Material { ambient: [0.75, 0.5, 0.22], diffuse: [0.75, 0.5, 0.22], specular: [0.9, 0.9, 0.9], gloss: 16, opacity: 1.0, texture: None };
    // Texture coordinates are per grid vertex, as positions and normals are.
    let triangle_texcoords = triangles.iter().map(|t| t.v).collect();
    Mesh { name: "teapot".into(), positions, normals, materials: vec![teapot_colour], triangles, front_face: Winding::Cw, texcoords, triangle_texcoords, view: None }
}

/// The floor of [`teapot_floor`]: y just below the teapot's base (-0.75), x in +-FLOOR_HALF, z from
/// -FLOOR_BACK (away from the default view) to +FLOOR_HALF, the texture repeated once per
/// FLOOR_TILE units.
pub const FLOOR_Y: f64 = -0.7505;
pub const FLOOR_HALF: f64 = 3.0;
pub const FLOOR_BACK: f64 = 12.0;
pub const FLOOR_TILE: f64 = 2.0;

/// The teapot (grid 14, GLUT's texture coordinates) standing near the front of a long floor of two
/// triangles that goes into the distance, its texture repeated every [`FLOOR_TILE`] units. Both are textured by the same texture
/// (one texture per frame, as the chipset holds one).
pub fn teapot_floor() -> Mesh {
    let mut m = teapot(TEAPOT_GRID);
    m.name = "teapot-floor".into();
    // Low over the front of the floor, looking along it past the teapot.
    m.view = Some(View { eye: [1.2, 1.3, 5.0], center: [0.0, -0.4, -3.0] });
    let base = m.positions.len() as u32;
    let (h, y, back) = (FLOOR_HALF, FLOOR_Y, FLOOR_BACK);
    // Corners a (-x, -z), b (+x, -z), c (+x, +z), d (-x, +z): (a, b, c) and (a, c, d) are clockwise
    // seen from above, the teapot's front-face winding.
    for p in [[-h, y, -back], [h, y, -back], [h, y, h], [-h, y, h]] {
        m.positions.push(p);
        m.texcoords.push([(p[0] + h) / FLOOR_TILE, (p[2] + back) / FLOOR_TILE]);
    }
    let n = m.normals.len() as u32;
    m.normals.push([0.0, 1.0, 0.0]);
    m.materials.push(material([0.85, 0.85, 0.85], 0.2, 8));
    for v in [[base, base + 1, base + 2], [base, base + 2, base + 3]] {
        m.triangles.push(Triangle { v, n: [n; 3], material: 1 });
        m.triangle_texcoords.push(v);
    }
    m
}

// ---------------------------------------------------------------------------------------------
// Building closed solids for castle and dolphins.

/// A closed solid (or an open sheet) under construction: positions and triangles, with normals
/// computed when it is added to the mesh.
///
/// Normals are the area-weighted average of the faces around each vertex, so sharpness is chosen by
/// vertex sharing: a crease (box edge, cylinder rim) gets separate vertices on each side.
#[derive(Default)]
struct Part {
    positions: Vec<V3>,
    triangles: Vec<[usize; 3]>,
}

/// How a [`Part::tube`] is closed at one end.
enum Cap {
    /// A flat polygon with its own vertices, so the rim stays a sharp edge.
    Flat,
    /// A fan to a single point (a nose, a tail, a cone's apex).
    Point(V3),
}

impl Part {
    fn vertex(&mut self, p: V3) -> usize {
        self.positions.push(p);
        self.positions.len() - 1
    }

    /// A planar convex face of a convex solid whose interior contains `inside`: fanned into triangles
    /// and wound counter-clockwise as seen from outside, whichever order the corners come in.
    fn convex_face(&mut self, corners: &[V3], inside: V3) {
        let centre = scale(corners.iter().fold([0.0; 3], |a, &c| add(a, c)), 1.0 / corners.len() as f64);
        let n = cross(sub(corners[1], corners[0]), sub(corners[2], corners[0]));
        let flip = dot(n, sub(centre, inside)) < 0.0;
        let ids: Vec<usize> = corners.iter().map(|&c| self.vertex(c)).collect();
        for k in 1..ids.len() - 1 {
            if flip {
                self.triangles.push([ids[0], ids[k + 1], ids[k]]);
            } else {
                self.triangles.push([ids[0], ids[k], ids[k + 1]]);
            }
        }
    }

    /// An axis-aligned box, each face with its own four vertices (flat shading).
    fn cuboid(&mut self, lo: V3, hi: V3) {
        let inside = scale(add(lo, hi), 0.5);
        let c = |x: usize, y: usize, z: usize| [[lo[0], hi[0]][x], [lo[1], hi[1]][y], [lo[2], hi[2]][z]];
        for axis in 0..3 {
            for side in 0..2 {
                let mut corners = Vec::new();
                for (a, b) in [(0, 0), (1, 0), (1, 1), (0, 1)] {
                    corners.push(match axis {
                        0 => c(side, a, b),
                        1 => c(a, side, b),
                        _ => c(a, b, side),
                    });
                }
                self.convex_face(&corners, inside);
            }
        }
    }

    /// A tube through `rings` (each ring's points going the same way round), closed at both ends.
    /// Consecutive rings are joined by quads whose vertices are shared (smooth normals). The winding
    /// is made consistent here and outward by [`Part::orient_outward`].
    fn tube(&mut self, rings: &[Vec<V3>], start: Cap, end: Cap) {
        let m = rings[0].len();
        let ids: Vec<Vec<usize>> = rings.iter().map(|r| r.iter().map(|&p| self.vertex(p)).collect()).collect();
        for w in ids.windows(2) {
            let (a, b) = (&w[0], &w[1]);
            for j in 0..m {
                let k = (j + 1) % m;
                self.triangles.push([a[j], a[k], b[k]]);
                self.triangles.push([a[j], b[k], b[j]]);
            }
        }
        // The side quads use a ring's edges as j -> j+1 on the first ring and j+1 -> j on the last,
        // so the caps take each edge the other way round.
        let first = &ids[0];
        let last = &ids[ids.len() - 1];
        match start {
            Cap::Point(p) => {
                let tip = self.vertex(p);
                for j in 0..m {
                    self.triangles.push([tip, first[(j + 1) % m], first[j]]);
                }
            }
            Cap::Flat => {
                let own: Vec<usize> = rings[0].iter().map(|&p| self.vertex(p)).collect();
                for j in 1..m - 1 {
                    self.triangles.push([own[0], own[j + 1], own[j]]);
                }
            }
        }
        match end {
            Cap::Point(p) => {
                let tip = self.vertex(p);
                for j in 0..m {
                    self.triangles.push([tip, last[j], last[(j + 1) % m]]);
                }
            }
            Cap::Flat => {
                let own: Vec<usize> = rings[rings.len() - 1].iter().map(|&p| self.vertex(p)).collect();
                for j in 1..m - 1 {
                    self.triangles.push([own[0], own[j], own[j + 1]]);
                }
            }
        }
    }

    /// Flip every triangle if the consistently wound solid encloses a negative volume, i.e. if its
    /// counter-clockwise normals point inwards.
    fn orient_outward(&mut self) {
        let volume: f64 = self.triangles.iter().map(|t| dot(self.positions[t[0]], cross(self.positions[t[1]], self.positions[t[2]]))).sum();
        if volume < 0.0 {
            for t in &mut self.triangles {
                t.swap(1, 2);
            }
        }
    }
}

/// A vertical ring of `segments` points of radius `r` around (cx, y, cz), counter-clockwise from +y.
fn ring_y(c: V3, r: f64, segments: usize) -> Vec<V3> {
    (0..segments)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / segments as f64;
            [c[0] + r * a.cos(), c[1], c[2] - r * a.sin()]
        })
        .collect()
}

/// Accumulates parts into one mesh.
struct MeshBuilder {
    mesh: Mesh,
}

impl MeshBuilder {
    fn new(name: &str, materials: Vec<Material>) -> MeshBuilder {
        MeshBuilder {
            mesh: Mesh {
                name: name.into(),
                positions: Vec::new(),
                normals: Vec::new(),
                materials,
                triangles: Vec::new(),
                front_face: Winding::Ccw,
                texcoords: Vec::new(),
                triangle_texcoords: Vec::new(),
                view: None,
            },
        }
    }

    /// Add a part with smooth (vertex-averaged) normals; `closed` parts are first wound outward.
    fn add(&mut self, mut part: Part, material: u32, closed: bool) {
        if closed {
            part.orient_outward();
        }
        let mut acc = vec![[0.0; 3]; part.positions.len()];
        for t in &part.triangles {
            let [a, b, c] = t.map(|i| part.positions[i]);
            // Twice the area times the unit normal: larger faces weigh more.
            let n = cross(sub(b, a), sub(c, a));
            for &i in t {
                acc[i] = add(acc[i], n);
            }
        }
        let base = self.mesh.positions.len() as u32;
        self.mesh.positions.extend_from_slice(&part.positions);
        // A vertex no triangle uses keeps a harmless +y so that every normal has unit length.
        self.mesh.normals.extend(acc.iter().map(|&n| if length(n) > 0.0 { normalize(n) } else { [0.0, 1.0, 0.0] }));
        for t in &part.triangles {
            let v = t.map(|i| base + i as u32);
            self.mesh.triangles.push(Triangle { v, n: v, material });
        }
    }

    /// Move the mesh so that its bounding box is centred on the origin.
    fn centred(mut self) -> Mesh {
        let (c, _) = self.mesh.bounding_sphere();
        for p in &mut self.mesh.positions {
            *p = sub(*p, c);
        }
        self.mesh
    }
}

/// A material with its own specular level and gloss (ambient = diffuse, as [`Material::plastic`]).
fn material(diffuse: V3, specular: f64, gloss: u32) -> Material {
    Material { ambient: diffuse, diffuse, specular: [specular; 3], gloss, opacity: 1.0, texture: None }
}

// ---------------------------------------------------------------------------------------------
// castle

const STONE: u32 = 0;
const ROOF_RED: u32 = 1;
const ROOF_BLUE: u32 = 2;
const GROUND: u32 = 3;
const TIMBER: u32 = 4;

/// A straight, axis-aligned wall on the ground from `from` to `to` (x, z of its centre line), with
/// merlons of width `merlon` separated by gaps of the same width along its outer edge; `outward` is
/// the unit (x, z) direction the outside of the wall faces.
fn crenellated_wall(b: &mut MeshBuilder, from: [f64; 2], to: [f64; 2], thickness: f64, height: f64, merlon: f64, outward: [f64; 2]) {
    // Axis 0 (x) or 2 (z) that the wall runs along, the other one across it, and the matching
    // index into the (x, z) pairs.
    let (along, across, a2, c2) = if from[1] == to[1] { (0, 2, 0, 1) } else { (2, 0, 1, 0) };
    let (start, stop) = (from[a2].min(to[a2]), from[a2].max(to[a2]));
    let (centre, h) = (from[c2], thickness / 2.0);
    let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
    (lo[along], hi[along]) = (start, stop);
    (lo[1], hi[1]) = (0.0, height);
    (lo[across], hi[across]) = (centre - h, centre + h);
    let mut wall = Part::default();
    wall.cuboid(lo, hi);
    b.add(wall, STONE, true);
    merlons(b, from, to, thickness, height, merlon, outward);
}

/// The merlons on top (at `height`) of a wall as [`crenellated_wall`] describes it.
fn merlons(b: &mut MeshBuilder, from: [f64; 2], to: [f64; 2], thickness: f64, height: f64, merlon: f64, outward: [f64; 2]) {
    let (along, across, a2, c2) = if from[1] == to[1] { (0, 2, 0, 1) } else { (2, 0, 1, 0) };
    let (start, stop) = (from[a2].min(to[a2]), from[a2].max(to[a2]));
    let (centre, out) = (from[c2], outward[c2]);
    let h = thickness / 2.0;
    // As many merlon-gap pairs as fit, centred along the wall.
    let count = ((stop - start + merlon) / (2.0 * merlon)).floor() as usize;
    let slack = (stop - start) - (2 * count - 1) as f64 * merlon;
    // Merlons cover the outer 45% of the wall's thickness, leaving a wall-walk behind them.
    let (e0, e1) = (centre + out * h, centre + out * (h - 0.45 * thickness));
    for i in 0..count {
        let a = start + slack / 2.0 + 2.0 * merlon * i as f64;
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        (lo[along], hi[along]) = (a, a + merlon);
        (lo[1], hi[1]) = (height, height + merlon);
        (lo[across], hi[across]) = (e0.min(e1), e0.max(e1));
        let mut m = Part::default();
        m.cuboid(lo, hi);
        b.add(m, STONE, true);
    }
}

/// A round tower standing on the ground at (x, z): a closed cylinder with a conical roof.
#[allow(clippy::too_many_arguments)]
fn tower(b: &mut MeshBuilder, x: f64, z: f64, radius: f64, height: f64, roof_height: f64, segments: usize, roof: u32) {
    let mut body = Part::default();
    body.tube(&[ring_y([x, 0.0, z], radius, segments), ring_y([x, height, z], radius, segments)], Cap::Flat, Cap::Flat);
    b.add(body, STONE, true);
    let mut cone = Part::default();
    // The roof overhangs the wall by a fifth of the radius.
    cone.tube(&[ring_y([x, height, z], 1.2 * radius, segments)], Cap::Flat, Cap::Point([x, height + roof_height, z]));
    b.add(cone, roof, true);
}

/// A house of the courtyard: a box with a gabled roof whose ridge runs along x.
fn house(b: &mut MeshBuilder, x: f64, z: f64, width: f64, depth: f64, height: f64) {
    let (hw, hd) = (width / 2.0, depth / 2.0);
    let mut walls = Part::default();
    walls.cuboid([x - hw, 0.0, z - hd], [x + hw, height, z + hd]);
    b.add(walls, TIMBER, true);
    let ridge = height + 0.6 * depth;
    let (e, r) = (0.1, height);
    let c = [
        [x - hw - e, r, z - hd - e],
        [x + hw + e, r, z - hd - e],
        [x + hw + e, r, z + hd + e],
        [x - hw - e, r, z + hd + e],
        [x - hw - e, ridge, z],
        [x + hw + e, ridge, z],
    ];
    let inside = [x, (r + ridge) / 2.0 - 0.1, z];
    let mut roof = Part::default();
    roof.convex_face(&[c[0], c[1], c[2], c[3]], inside);
    roof.convex_face(&[c[0], c[1], c[5], c[4]], inside);
    roof.convex_face(&[c[3], c[2], c[5], c[4]], inside);
    roof.convex_face(&[c[0], c[3], c[4]], inside);
    roof.convex_face(&[c[1], c[2], c[5]], inside);
    b.add(roof, ROOF_RED, true);
}

/// The seeds' "Castle": an outer curtain wall with corner and gate towers, an inner ward with its
/// own walls and towers, a keep with turrets, houses in the bailey and a ground plane. Seen from
/// outside most of it hides behind the walls (the paper reports only ~20% of Castle's triangles
/// visible), which is what the index buffer's depth complexity is tested with.
pub fn castle() -> Mesh {
    let materials = vec![
        material([0.62, 0.6, 0.56], 0.15, 2), // stone
        material([0.7, 0.18, 0.12], 0.4, 8),  // red roofs
        material([0.18, 0.28, 0.7], 0.4, 8),  // blue roofs
        material([0.3, 0.55, 0.22], 0.05, 1), // ground
        material([0.78, 0.66, 0.45], 0.1, 4), // timber houses
    ];
    let mut b = MeshBuilder::new("castle", materials);

    // Ground: a 14 x 14 quad grid facing +y (an open sheet, wound counter-clockwise from above).
    let mut ground = Part::default();
    let (half, cells) = (13.0, 8usize);
    let step = 2.0 * half / cells as f64;
    for i in 0..cells {
        for j in 0..cells {
            let (x0, z0) = (-half + step * i as f64, -half + step * j as f64);
            let a = ground.vertex([x0, 0.0, z0]);
            let bb = ground.vertex([x0, 0.0, z0 + step]);
            let c = ground.vertex([x0 + step, 0.0, z0 + step]);
            let d = ground.vertex([x0 + step, 0.0, z0]);
            ground.triangles.push([a, bb, c]);
            ground.triangles.push([a, c, d]);
        }
    }
    b.add(ground, GROUND, false);

    // Outer curtain wall, 16 x 16, with a gate in the south (+z) side between two gate towers.
    let r = 8.0;
    let (t, h, merlon) = (0.8, 4.0, 0.55);
    crenellated_wall(&mut b, [-r, -r], [r, -r], t, h, merlon, [0.0, -1.0]);
    crenellated_wall(&mut b, [-r, -r], [-r, r], t, h, merlon, [-1.0, 0.0]);
    crenellated_wall(&mut b, [r, -r], [r, r], t, h, merlon, [1.0, 0.0]);
    crenellated_wall(&mut b, [-r, r], [-1.8, r], t, h, merlon, [0.0, 1.0]);
    crenellated_wall(&mut b, [1.8, r], [r, r], t, h, merlon, [0.0, 1.0]);
    let mut lintel = Part::default();
    lintel.cuboid([-1.8, 2.8, r - t / 2.0], [1.8, h, r + t / 2.0]);
    b.add(lintel, STONE, true);
    for (x, z) in [(-r, -r), (r, -r), (-r, r), (r, r)] {
        tower(&mut b, x, z, 1.5, 6.0, 3.0, 20, ROOF_RED);
    }
    for x in [-2.4, 2.4] {
        tower(&mut b, x, r + 0.3, 1.0, 5.5, 2.2, 16, ROOF_BLUE);
    }

    // Houses in the bailey, between the two rings of walls.
    for (x, z) in [(-6.0, -6.2), (-3.0, -6.3), (0.5, -6.2), (3.6, -6.3), (-6.2, 5.8), (5.8, 6.0)] {
        house(&mut b, x, z, 2.0, 1.6, 1.6);
    }

    // Inner ward, 9 x 9, higher walls, gate in the south side.
    let q = 4.5;
    let (t2, h2, merlon2) = (0.7, 6.0, 0.5);
    crenellated_wall(&mut b, [-q, -q], [q, -q], t2, h2, merlon2, [0.0, -1.0]);
    crenellated_wall(&mut b, [-q, -q], [-q, q], t2, h2, merlon2, [-1.0, 0.0]);
    crenellated_wall(&mut b, [q, -q], [q, q], t2, h2, merlon2, [1.0, 0.0]);
    crenellated_wall(&mut b, [-q, q], [-1.2, q], t2, h2, merlon2, [0.0, 1.0]);
    crenellated_wall(&mut b, [1.2, q], [q, q], t2, h2, merlon2, [0.0, 1.0]);
    for (x, z) in [(-q, -q), (q, -q), (-q, q), (q, q)] {
        tower(&mut b, x, z, 1.0, 8.0, 2.5, 16, ROOF_BLUE);
    }

    // The keep: a tall block with merlons all round and a turret on each corner.
    let (k, kh) = (1.8, 10.0);
    let mut keep = Part::default();
    keep.cuboid([-k, 0.0, -k], [k, kh, k]);
    b.add(keep, STONE, true);
    // Merlons on the keep's parapet: a virtual 0.8-thick wall whose outer face is the keep's.
    for (from, to, out) in [
        ([-k, -k + 0.4], [k, -k + 0.4], [0.0, -1.0]),
        ([-k, k - 0.4], [k, k - 0.4], [0.0, 1.0]),
        ([-k + 0.4, -k], [-k + 0.4, k], [-1.0, 0.0]),
        ([k - 0.4, -k], [k - 0.4, k], [1.0, 0.0]),
    ] {
        merlons(&mut b, from, to, 0.8, kh, 0.5, out);
    }
    for (x, z) in [(-k, -k), (k, -k), (-k, k), (k, k)] {
        let mut turret = Part::default();
        turret.tube(&[ring_y([x, kh - 1.5, z], 0.6, 16), ring_y([x, kh + 1.5, z], 0.6, 16)], Cap::Flat, Cap::Flat);
        b.add(turret, STONE, true);
        let mut cone = Part::default();
        cone.tube(&[ring_y([x, kh + 1.5, z], 0.75, 16)], Cap::Flat, Cap::Point([x, kh + 3.2, z]));
        b.add(cone, ROOF_RED, true);
    }
    b.centred()
}

// ---------------------------------------------------------------------------------------------
// dolphins

/// Radius of the dolphin's body at t in [0, 1] (nose to tail), for a body of length 1: a rounded
/// sqrt rise at the beak, a bulging melon, the widest point a third of the way back and a long
/// taper into the tail stock.
fn dolphin_radius(t: f64) -> f64 {
    let smooth = |a: f64, b: f64, x: f64| {
        let s = ((x - a) / (b - a)).clamp(0.0, 1.0);
        s * s * (3.0 - 2.0 * s)
    };
    // The beak is thinner than the head behind it.
    let beak = 0.45 + 0.55 * smooth(0.03, 0.16, t);
    0.3 * t.sqrt() * (1.0 - t).powf(1.3) * beak
}

/// A fin as a swept, tapering blade with a diamond cross-section: `root` (buried in the body),
/// `span` direction, `chord` direction (towards the leading edge), lengths, and the sweep of the tip
/// backwards along -chord.
#[allow(clippy::too_many_arguments)]
fn fin(root: V3, span: V3, chord: V3, length: f64, root_chord: f64, tip_chord: f64, sweep: f64, thickness: f64) -> Part {
    let d = normalize(span);
    let c = normalize(sub(chord, scale(d, dot(chord, d))));
    let n = cross(d, c);
    let stations = 5;
    let centre = |s: f64| add(add(root, scale(d, s * length)), scale(c, -sweep * s * s));
    let rings: Vec<Vec<V3>> = (0..stations)
        .map(|i| {
            let s = i as f64 / stations as f64;
            let ch = root_chord + (tip_chord - root_chord) * s;
            let o = centre(s);
            // The thickest point is a third of the chord behind the leading edge.
            let lead = add(o, scale(c, 0.6 * ch));
            let trail = add(o, scale(c, -0.4 * ch));
            let mid = add(o, scale(c, 0.2 * ch));
            vec![lead, add(mid, scale(n, thickness * ch)), trail, add(mid, scale(n, -thickness * ch))]
        })
        .collect();
    let mut part = Part::default();
    part.tube(&rings, Cap::Flat, Cap::Point(centre(1.0)));
    part
}

/// One dolphin in its own frame: length 2 along x with the nose at +x, back towards +y.
fn dolphin_parts() -> Vec<Part> {
    let length = 2.0;
    let (rings, segments) = (20usize, 20usize);
    let x_at = |t: f64| length * (0.5 - t);
    // Rings crowd towards nose and tail, where the profile bends fastest.
    let ring_t = |i: usize| (1.0 - (std::f64::consts::PI * i as f64 / (rings + 1) as f64).cos()) / 2.0;
    let body_rings: Vec<Vec<V3>> = (1..=rings)
        .map(|i| {
            let t = ring_t(i);
            let r = length * dolphin_radius(t);
            (0..segments)
                .map(|j| {
                    let a = std::f64::consts::TAU * j as f64 / segments as f64;
                    // Slightly taller than wide.
                    [x_at(t), 1.08 * r * a.cos(), 0.88 * r * a.sin()]
                })
                .collect()
        })
        .collect();
    let mut body = Part::default();
    body.tube(&body_rings, Cap::Point([x_at(0.0), 0.0, 0.0]), Cap::Point([x_at(1.0), 0.0, 0.0]));

    let r_at = |t: f64| length * dolphin_radius(t);
    let dorsal = fin([x_at(0.5), 0.85 * r_at(0.5), 0.0], [-0.45, 1.0, 0.0], [1.0, 0.0, 0.0], 0.32, 0.38, 0.06, 0.22, 0.14);
    let mut parts = vec![body, dorsal];
    for side in [-1.0, 1.0] {
        parts.push(fin(
            [x_at(0.3), -0.45 * r_at(0.3), side * 0.6 * r_at(0.3)],
            [-0.3, -0.55, side],
            [1.0, 0.0, 0.0],
            0.3,
            0.2,
            0.05,
            0.12,
            0.15,
        ));
        parts.push(fin([x_at(0.93), 0.0, side * 0.01], [-0.45, 0.0, side], [1.0, 0.0, 0.0], 0.36, 0.26, 0.07, 0.16, 0.12));
    }
    parts
}

/// The seeds' "Dolphins": three smooth dolphins leaping one after another along an arc, each a body
/// of revolution with a dorsal fin, two flippers and two tail flukes.
pub fn dolphins() -> Mesh {
    let mut b = MeshBuilder::new("dolphins", vec![material([0.45, 0.52, 0.62], 0.5, 16)]);
    let arc = 2.2;
    // (angle on the arc in degrees, depth offset, scale): rising, at the top, diving.
    for (angle, z, size) in [(140.0f64, -0.9, 1.0), (90.0, 0.0, 0.85), (40.0, 0.9, 0.95)] {
        let phi = angle.to_radians();
        // The frame: forward along the arc (left to right), back pointing away from the arc's centre.
        let forward = [phi.sin(), -phi.cos(), 0.0];
        let up = [phi.cos(), phi.sin(), 0.0];
        let side = cross(forward, up);
        let origin = [arc * phi.cos(), arc * phi.sin() - 1.0, z];
        for mut part in dolphin_parts() {
            for p in &mut part.positions {
                let l = scale(*p, size);
                *p = add(origin, add(add(scale(forward, l[0]), scale(up, l[1])), scale(side, l[2])));
            }
            b.add(part, 0, true);
        }
    }
    b.centred()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_teapot_has_glut_texture_coordinates_each_patch_corner_at_its_control_point() {
        let g = 4;
        let m = teapot(g);
        m.validate().unwrap();
        assert_eq!(m.triangle_texcoords.len(), m.triangles.len());
        // The first patch is the rim P (its points by row j, column k); u runs along k, v along j,
        // and a Bezier patch passes through its four corner points. So (s, t) = (1, 0) is P[0][3]
        // and (0, 1) is P[3][0], both in the first (g + 1)^2 vertices.
        let p = |j: usize, k: usize| teapot_transform(TEAPOT_POINTS[TEAPOT_PATCHES[0][4 * j + k]], 0.5);
        let at = |st: [f64; 2]| m.texcoords[..(g as usize + 1).pow(2)].iter().position(|&c| c == st).unwrap();
        for (st, point) in [([0.0, 0.0], p(0, 0)), ([1.0, 0.0], p(0, 3)), ([0.0, 1.0], p(3, 0)), ([1.0, 1.0], p(3, 3))] {
            let q = m.positions[at(st)];
            assert!((0..3).all(|c| (q[c] - point[c]).abs() < 1e-12), "{st:?}: {q:?} vs {point:?}");
        }
        // Neighbouring corners of a triangle are one grid step apart in s and t.
        for tc in &m.triangle_texcoords {
            for a in 0..3 {
                for b in 0..3 {
                    let (ca, cb) = (m.texcoords[tc[a] as usize], m.texcoords[tc[b] as usize]);
                    assert!((ca[0] - cb[0]).abs() <= 1.0 / g as f64 + 1e-12 && (ca[1] - cb[1]).abs() <= 1.0 / g as f64 + 1e-12);
                }
            }
        }
    }

    fn corners(m: &Mesh, t: &Triangle) -> [V3; 3] {
        t.v.map(|i| m.positions[i as usize])
    }

    /// Twice the triangle's area times its counter-clockwise unit normal.
    fn ccw_normal(m: &Mesh, t: &Triangle) -> V3 {
        let [a, b, c] = corners(m, t);
        cross(sub(b, a), sub(c, a))
    }

    fn area(m: &Mesh, t: &Triangle) -> f64 {
        length(ccw_normal(m, t)) / 2.0
    }

    fn mean_normal(m: &Mesh, t: &Triangle) -> V3 {
        t.n.iter().fold([0.0; 3], |a, &i| add(a, m.normals[i as usize]))
    }

    /// Fraction of the non-degenerate triangles whose geometric normal for the mesh's front-face
    /// winding points the same way as the mean of their corner normals.
    fn winding_agreement(m: &Mesh) -> f64 {
        let sign = if m.front_face == Winding::Ccw { 1.0 } else { -1.0 };
        let (mut agree, mut total) = (0usize, 0usize);
        for t in &m.triangles {
            if area(m, t) <= 1e-12 {
                continue;
            }
            total += 1;
            if sign * dot(ccw_normal(m, t), mean_normal(m, t)) > 0.0 {
                agree += 1;
            }
        }
        agree as f64 / total as f64
    }

    fn all_normals_unit(m: &Mesh) -> bool {
        m.normals.iter().all(|n| (length(*n) - 1.0).abs() < 1e-9)
    }

    #[test]
    fn teapot_has_glut_triangle_counts_at_grid_14_and_7() {
        assert_eq!(teapot(14).triangles.len(), 12544);
        assert_eq!(teapot(7).triangles.len(), 3136);
    }

    #[test]
    fn teapot_has_112_zero_area_triangles_at_grid_14() {
        let m = teapot(14);
        let zero = m.triangles.iter().filter(|t| area(&m, t) <= 1e-12).count();
        assert_eq!(zero, 112);
    }

    #[test]
    fn teapot_normals_are_unit_and_front_face_is_clockwise() {
        let m = teapot(14);
        assert!(all_normals_unit(&m));
        assert_eq!(m.front_face, Winding::Cw);
        m.validate().unwrap();
    }

    #[test]
    fn teapot_clockwise_winding_agrees_with_outward_vertex_normals() {
        for grid in [14, 7] {
            let m = teapot(grid);
            let agreement = winding_agreement(&m);
            assert!(agreement >= 0.99, "grid {grid}: only {:.2}% agree", 100.0 * agreement);
        }
    }

    #[test]
    fn teapot_normals_point_away_from_the_pots_axis_on_the_body() {
        // The winding test alone would pass with normals and winding both inward; the body's
        // normals must also point away from the y axis.
        let m = teapot(14);
        let body = 4 * 2 * 14 * 14..3 * 4 * 2 * 14 * 14; // patches 4..12: the two body patches and mirrors
        for t in &m.triangles[body] {
            for (&v, &n) in t.v.iter().zip(&t.n) {
                let (p, n) = (m.positions[v as usize], m.normals[n as usize]);
                assert!(p[0] * n[0] + p[2] * n[2] > 0.0, "normal {n:?} at {p:?} points inward");
            }
        }
    }

    #[test]
    fn teapot_stands_upright_and_unit_size_like_glut() {
        let m = teapot(14);
        let lo_y = m.positions.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        let hi_y = m.positions.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
        // Bottom at z = 0 and lid knob at z = 3.15 in the data, scaled by 0.5 and shifted by -1.5.
        assert!((lo_y + 0.75).abs() < 1e-12, "{lo_y}");
        assert!((hi_y - 0.825).abs() < 1e-12, "{hi_y}");
    }

    #[test]
    fn every_built_in_scene_validates_with_a_triangle_count_in_range() {
        let ranges = [("polyhedron", 2..=2), ("teapot", 12544..=12544), ("castle", 2000..=5000), ("dolphins", 2700..=3300)];
        assert_eq!(SCENES, ranges.clone().map(|(n, _)| n));
        for (name, range) in ranges {
            let m = scene(name).unwrap();
            m.validate().unwrap();
            assert_eq!(m.name, name);
            assert!(range.contains(&m.triangles.len()), "{name}: {} triangles", m.triangles.len());
            assert!(all_normals_unit(&m), "{name} has a normal that is not unit length");
            for mat in &m.materials {
                assert!(mat.gloss.is_power_of_two() && (1..=16).contains(&mat.gloss), "{name}: gloss {}", mat.gloss);
            }
        }
    }

    #[test]
    fn unknown_scene_is_an_error_naming_the_known_scenes() {
        let e = scene("nope").unwrap_err();
        assert!(e.contains("nope"), "{e}");
        for name in SCENES {
            assert!(e.contains(name), "{e}");
        }
    }

    #[test]
    fn scenes_are_deterministic() {
        for name in SCENES {
            assert_eq!(scene(name).unwrap(), scene(name).unwrap(), "{name}");
        }
    }

    #[test]
    fn counter_clockwise_scenes_are_wound_outward() {
        for name in ["polyhedron", "castle", "dolphins"] {
            let m = scene(name).unwrap();
            assert_eq!(m.front_face, Winding::Ccw);
            let agreement = winding_agreement(&m);
            assert!(agreement >= 0.95, "{name}: only {:.2}% agree", 100.0 * agreement);
        }
    }

    #[test]
    fn polyhedron_faces_plus_z_with_two_colours_at_two_depths() {
        let m = polyhedron();
        for t in &m.triangles {
            assert!(ccw_normal(&m, t)[2] > 0.0);
            assert_eq!(m.normals[t.n[0] as usize], [0.0, 0.0, 1.0]);
        }
        assert_ne!(m.materials[0], m.materials[1]);
        assert_ne!(m.positions[0][2], m.positions[3][2]);
    }

    #[test]
    fn castle_and_dolphins_are_centred_and_closed_parts_have_no_degenerate_triangles() {
        for name in ["castle", "dolphins"] {
            let m = scene(name).unwrap();
            let (c, r) = m.bounding_sphere();
            assert!(length(c) < 1e-9 * r, "{name}: centre {c:?}");
            let degenerate = m.triangles.iter().filter(|t| area(&m, t) <= 1e-9 * r * r).count();
            assert_eq!(degenerate, 0, "{name}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// glass (issue 22: PROOF's transparency)

/// Three tinted panes of glass crossing each other in a star on the left, and a translucent teapot
/// in front of an opaque block on the right, on an opaque floor. Opacities (MTL `d`): red pane 0.5,
/// green 0.4, blue 0.6, teapot 0.45; floor and block 1. Panes are thin closed boxes, so from any side
/// one face of each is drawn; the teapot is GLUT's at grid 6, its back faces culled as everywhere.
pub fn glass() -> Mesh {
    let tinted = |c: V3, d: f64| Material { opacity: d, ..material(c, 0.6, 16) };
    let materials = vec![
        material([0.55, 0.55, 0.58], 0.05, 1), // floor
        material([0.85, 0.62, 0.12], 0.3, 8),  // block behind the teapot
        tinted([0.9, 0.15, 0.12], 0.5),        // red pane
        tinted([0.15, 0.8, 0.2], 0.4),         // green pane
        tinted([0.15, 0.3, 0.95], 0.6),        // blue pane
        tinted([0.6, 0.85, 0.9], 0.45),        // glass teapot
    ];
    let mut b = MeshBuilder::new("glass", materials);
    let mut floor = Part::default();
    floor.cuboid([-2.5, -0.1, -1.9], [2.6, 0.0, 1.0]);
    b.add(floor, 0, true);
    let mut block = Part::default();
    block.cuboid([0.5, 0.0, -1.85], [1.9, 1.3, -1.3]);
    b.add(block, 1, true);
    // The panes: 1.9 wide, 1.5 high, 0.04 thick, about a vertical axis through (-1.3, _, -0.4),
    // turned by -25, 20 and 65 degrees.
    for (k, turn) in [-25.0f64, 20.0, 65.0].iter().enumerate() {
        let mut pane = Part::default();
        pane.cuboid([-0.95, 0.0, -0.02], [0.95, 1.5, 0.02]);
        let (c, s) = (turn.to_radians().cos(), turn.to_radians().sin());
        for p in &mut pane.positions {
            *p = [-1.3 + c * p[0] + s * p[2], p[1], -0.4 - s * p[0] + c * p[2]];
        }
        b.add(pane, 2 + k as u32, true);
    }
    // The teapot (wound clockwise as GLUT draws it: flipped to the builder's counter-clockwise), its
    // base on the floor in front of the block, with its own normals.
    let pot = teapot(6);
    let lowest = pot.positions.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    let (base, nbase) = (b.mesh.positions.len() as u32, b.mesh.normals.len() as u32);
    b.mesh.positions.extend(pot.positions.iter().map(|p| [1.3 + p[0], p[1] - lowest, -0.2 + p[2]]));
    b.mesh.normals.extend_from_slice(&pot.normals);
    for t in &pot.triangles {
        b.mesh.triangles.push(Triangle { v: [t.v[0], t.v[2], t.v[1]].map(|i| base + i), n: [t.n[0], t.n[2], t.n[1]].map(|i| nbase + i), material: 5 });
    }
    b.centred()
}
