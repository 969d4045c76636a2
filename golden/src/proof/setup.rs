//! The host's object setup for PROOF (seed 002 §3.1: "the task of the geometry processor consists of all
//! calculations that are required by the following stages"): from the window triangles of
//! [`upper_pipeline`] to the parameters an object processor is loaded with, plus the look-up tables
//! between the stages (material per object for shading, edge directions per object for the filter).
//!
//! Per triangle (in the vertex order with det > 0, as the RC uses):
//! * edges a->b in normal form with the inward unit normal `(cos a, sin a) = (-dy, dx) / |ab|`, rounded
//!   to Q1.14; `p` is chosen as the floor of the smallest `v . n` over the three vertices, so that the
//!   fixed-point half-plane `d >= 0` contains the whole exact triangle (needed for a good-natured
//!   "none");
//! * `t_none = r = (|cos a| + |sin a|)/2` exactly; `t_full = r + delta + 2 LSB`, where delta bounds
//!   |fixed-point distance - true distance| over the bounding box (the rounded direction turns the line
//!   slightly; needed for a good-natured "full");
//! * the depth plane and the three normal planes from [`Plane::setup`] (one reciprocal per triangle),
//!   rescaled to the accumulators' fraction bits and evaluated at the box's first pixel.

use super::format::{alpha_q, sat, wrap, EdgeParams, ALPHA_ONE, Interp, ObjectParams, ACC_BITS, DEPTH_FRAC, EDGE_BITS, ID_BITS, NORMAL_ACC_FRAC};
use crate::format::{reciprocal, round_shift, Plane, Screen, WinVertex, PLANE_FRAC, SUBPIXEL_BITS, SUBPIXEL_ONE};
use crate::host::{eye_normals, normalize, upper_pipeline, Vec3};
use crate::raster::{canonical_order, det, is_culled, Culled};
use crate::render::RenderOptions;
use crate::scene::Mesh;
use crate::shade::{normal_q14, PhongLights, Shading};

/// Counts of the object setup.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct SetupStats {
    /// Triangles in the mesh.
    pub triangles_in: u64,
    /// Window triangles after clipping (clipping can split one into several).
    pub window_triangles: u64,
    pub culled_facing: u64,
    pub zero_area: u64,
    /// Bounding box entirely off the screen.
    pub off_screen: u64,
    /// Objects loaded into the OPP.
    pub objects: u64,
    /// Of those, objects whose opacity is below 1 (issue 22).
    pub transparent_objects: u64,
}

/// A frame's worth of objects and tables, ready for the OPP and the later stages.
#[derive(Clone, Debug)]
pub struct ProofScene {
    pub screen: Screen,
    /// Object parameters; `objects[i].id == i`.
    pub objects: Vec<ObjectParams>,
    /// Look-up table for the shading stage: the material of each object.
    pub material: Vec<u16>,
    /// The source triangle (input position) of each object.
    pub source: Vec<u32>,
    /// The lighting constants of the shading stage (project's fixed-point form).
    pub lights: PhongLights,
    pub background: [u8; 3],
    pub stats: SetupStats,
}

/// Set up the edges of a triangle in canonical order; `bbox` = (X0, X1, Y0, Y1).
pub fn edge_setup(v: &[WinVertex; 3], bbox: (i32, i32, i32, i32)) -> [EdgeParams; 3] {
    let (x0, x1, y0, y1) = bbox;
    [0, 1, 2].map(|k| {
        let (a, b) = (v[k], v[(k + 1) % 3]);
        let (dx, dy) = ((b.x - a.x) as f64, (b.y - a.y) as f64);
        let len = (dx * dx + dy * dy).sqrt();
        let (cf, sf) = (-dy / len, dx / len);
        let q = |f: f64| (f * 16384.0).round() as i64;
        let (c, s) = (q(cf), q(sf));
        // p' = floor(min v . n') in 15 fraction bits: v (8 fraction bits) * n' (14) has 22.
        let pmin = v.iter().map(|w| w.x as i64 * c + w.y as i64 * s).min().unwrap();
        let p = pmin >> (SUBPIXEL_BITS + 14 - 15);
        let d0 = (2 * x0 as i64 + 1) * c + (2 * y0 as i64 + 1) * s - p;
        let r = c.abs() + s.abs();
        // delta: |f' - f| over the box [x0, x1+1] x [y0, y1+1] (pixels); linear, so at the corners.
        let (ax, ay) = (a.x as f64 / SUBPIXEL_ONE as f64, a.y as f64 / SUBPIXEL_ONE as f64);
        let mut delta: f64 = 0.0;
        for (px, py) in [(x0, y0), (x1 + 1, y0), (x0, y1 + 1), (x1 + 1, y1 + 1)] {
            let (px, py) = (px as f64, py as f64);
            let fixed = (px * c as f64 + py * s as f64) / 16384.0 - p as f64 / 32768.0;
            let exact = cf * (px - ax) + sf * (py - ay);
            delta = delta.max((fixed - exact).abs());
        }
        let t_full = r + (delta * 32768.0).ceil() as i64 + 2;
        EdgeParams { cos: c as i16, sin: s as i16, d0: wrap(d0, EDGE_BITS) as i32, t_none: r as u32, t_full: t_full as u32 }
    })
}

/// Rescale a plane (16 fraction bits) to an accumulator with `frac` fraction bits, starting at (X0, Y0).
fn plane_interp(p: &Plane, x0: i32, y0: i32, frac: u32) -> Interp {
    let sh = PLANE_FRAC - frac;
    Interp {
        v0: sat(round_shift(p.raw(x0 as u32, y0 as u32) as i128, sh) as i64, ACC_BITS),
        dx: sat(round_shift(p.a as i128, sh) as i64, ACC_BITS),
        dy: sat(round_shift(p.b as i128, sh) as i64, ACC_BITS),
    }
}

/// The bounding box of the pixels whose square meets the vertex extent, clamped to the screen:
/// (X0, X1, Y0, Y1), possibly empty.
pub fn pixel_box(v: &[WinVertex; 3], screen: Screen) -> (i32, i32, i32, i32) {
    let xmin = v.iter().map(|p| p.x).min().unwrap();
    let xmax = v.iter().map(|p| p.x).max().unwrap();
    let ymin = v.iter().map(|p| p.y).min().unwrap();
    let ymax = v.iter().map(|p| p.y).max().unwrap();
    (
        (xmin >> SUBPIXEL_BITS).max(0),
        ((xmax - 1) >> SUBPIXEL_BITS).min(screen.width as i32 - 1),
        (ymin >> SUBPIXEL_BITS).max(0),
        ((ymax - 1) >> SUBPIXEL_BITS).min(screen.height as i32 - 1),
    )
}

/// One object from a window triangle (any order), its vertex normals (Q1.14) and an id; `None` if the
/// triangle has no area or its box is off the screen.
pub fn object_setup(tri: &[WinVertex; 3], normals: [[i64; 3]; 3], id: u16, screen: Screen) -> Option<ObjectParams> {
    let d = det(tri);
    if d == 0 {
        return None;
    }
    let o = canonical_order(tri);
    let v = [tri[o[0]], tri[o[1]], tri[o[2]]];
    let nv = [normals[o[0]], normals[o[1]], normals[o[2]]];
    let bbox = pixel_box(&v, screen);
    let (x0, x1, y0, y1) = bbox;
    if x0 > x1 || y0 > y1 {
        return None;
    }
    let det = d.abs();
    let r = reciprocal(det);
    let zp = Plane::setup(&v, [v[0].z as i64, v[1].z as i64, v[2].z as i64], det, r);
    let n = [0, 1, 2].map(|k| {
        let p = Plane::setup(&v, [nv[0][k], nv[1][k], nv[2][k]], det, r);
        plane_interp(&p, x0, y0, NORMAL_ACC_FRAC)
    });
    Some(ObjectParams {
        id,
        x0: x0 as u16,
        x1: x1 as u16,
        y0: y0 as u16,
        y1: y1 as u16,
        edges: edge_setup(&v, bbox),
        z: plane_interp(&zp, x0, y0, DEPTH_FRAC),
        n,
        alpha: ALPHA_ONE,
    })
}

/// The whole frame's object setup: upper pipeline, culling, lower pipeline (normals only: lighting is
/// the shading stage's job), object parameters (with each material's opacity, Q1.4) and tables.
pub fn scene_setup(mesh: &Mesh, opts: &RenderOptions) -> Result<ProofScene, String> {
    mesh.validate()?;
    opts.camera.validate()?;
    let geo = upper_pipeline(mesh, &opts.camera, opts.screen);
    let mut stats = SetupStats { triangles_in: mesh.triangles.len() as u64, window_triangles: geo.hw.len() as u64, ..Default::default() };
    let mut objects = Vec::new();
    let mut material = Vec::new();
    let mut source = Vec::new();
    let mut normal_cache: Vec<Option<[Vec3; 3]>> = vec![None; mesh.triangles.len()];
    for t in &geo.hw {
        match is_culled(det(&t.v), opts.cull, opts.front) {
            Some(Culled::ZeroArea) => {
                stats.zero_area += 1;
                continue;
            }
            Some(Culled::Facing) => {
                stats.culled_facing += 1;
                continue;
            }
            None => {}
        }
        let s = t.source as usize;
        let tri = &mesh.triangles[s];
        let en = *normal_cache[s].get_or_insert_with(|| eye_normals(mesh, &opts.camera, tri));
        let normals: [[i64; 3]; 3] = match opts.shading {
            Shading::Flat => {
                let f = normal_q14(normalize([0, 1, 2].map(|k| en[0][k] + en[1][k] + en[2][k])));
                [f; 3]
            }
            _ => t.bary.map(|b| normal_q14([0, 1, 2].map(|k| b[0] * en[0][k] + b[1] * en[1][k] + b[2] * en[2][k]))),
        };
        if objects.len() >= 1 << ID_BITS {
            return Err(format!(
                "more than {} objects after culling: PROOF's object ids are {ID_BITS} bits; use a smaller scene",
                1u64 << ID_BITS
            ));
        }
        match object_setup(&t.v, normals, objects.len() as u16, opts.screen) {
            Some(mut p) => {
                p.alpha = alpha_q(mesh.materials[tri.material as usize].opacity);
                stats.transparent_objects += (p.alpha < ALPHA_ONE) as u64;
                objects.push(p);
                material.push(tri.material as u16);
                source.push(t.source);
            }
            None => stats.off_screen += 1,
        }
    }
    stats.objects = objects.len() as u64;
    Ok(ProofScene {
        screen: opts.screen,
        objects,
        material,
        source,
        lights: PhongLights::new(&opts.lighting, &mesh.materials),
        background: opts.background,
        stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proof::format::{Coverage, EDGE_FRAC};

    fn v(x: f64, y: f64, z: u32) -> WinVertex {
        WinVertex { x: (x * SUBPIXEL_ONE as f64) as i32, y: (y * SUBPIXEL_ONE as f64) as i32, z }
    }

    #[test]
    fn distances_are_in_pixels_and_positive_inside() {
        let s = Screen::new(64, 64).unwrap();
        // Right triangle with a vertical left edge at x = 10 and a horizontal top edge at y = 10.
        let p = object_setup(&[v(10.0, 10.0, 0), v(40.0, 10.0, 0), v(10.0, 40.0, 0)], [[0, 0, 16384]; 3], 0, s).unwrap();
        let (d, _, _) = p.accumulators_at(20, 12);
        // Centre (20.5, 12.5): 2.5 px below the top edge, 10.5 px right of the left edge.
        let px = |v: i64| v as f64 / (1 << EDGE_FRAC) as f64;
        let ds: Vec<f64> = d.iter().map(|&x| px(x)).collect();
        assert!(ds.iter().any(|&x| (x - 2.5).abs() < 1e-3), "{ds:?}");
        assert!(ds.iter().any(|&x| (x - 10.5).abs() < 1e-3), "{ds:?}");
        assert_eq!(p.coverage_at(20, 12), Coverage::Full);
        assert_eq!(p.coverage_at(10, 20), Coverage::Partial);
        assert_eq!(p.coverage_at(9, 20), Coverage::None);
        assert_eq!(p.coverage_at(45, 45), Coverage::None);
    }
}
