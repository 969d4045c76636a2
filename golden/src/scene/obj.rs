//! Wavefront OBJ scenes through `tobj`, with the input checked first.
//!
//! tobj is lenient: it skips or zero-fills what it cannot parse. Our users need to know *where* a file
//! is wrong, so a light pre-scan checks every `v`, `vn` and `f` line and reports `path:line: problem`;
//! only a file that passes is handed to tobj (faces of more than 3 vertices are triangulated there).
//! A missing or unreadable MTL file is not fatal: the mesh gets a grey plastic material.

use super::{Material, Mesh, Triangle, Winding};
use crate::host::{cross, normalize, sub};
use std::path::Path;

/// Parse one number of a `v`/`vn` line, rejecting non-numbers and NaN/inf.
fn number(path: &Path, line: usize, word: &str) -> Result<f64, String> {
    let v: f64 = word.parse().map_err(|_| format!("{}:{line}: '{word}' is not a number", path.display()))?;
    if !v.is_finite() {
        return Err(format!("{}:{line}: non-finite coordinate '{word}'", path.display()));
    }
    Ok(v)
}

/// Resolve a 1-based (or negative, relative) OBJ index against `count` elements defined so far.
fn resolve(path: &Path, line: usize, word: &str, what: &str, count: usize) -> Result<(), String> {
    let i: i64 = word.parse().map_err(|_| format!("{}:{line}: face {what} index '{word}' is not an integer", path.display()))?;
    let ok = match i {
        0 => false,
        i if i > 0 => i as usize <= count,
        i => (-i) as usize <= count,
    };
    if !ok {
        return Err(format!("{}:{line}: face refers to {what} {i} but only {count} {what}s are defined", path.display()));
    }
    Ok(())
}

/// Check the statements the renderer uses; everything else (o, g, s, usemtl, mtllib, vt, l, ...) passes.
fn prescan(path: &Path, text: &str) -> Result<(), String> {
    let (mut nv, mut nvt, mut nvn, mut nf) = (0usize, 0usize, 0usize, 0usize);
    for (k, raw) in text.lines().enumerate() {
        let line = k + 1;
        let mut words = raw.split('#').next().unwrap_or("").split_whitespace();
        let Some(kw) = words.next() else { continue };
        let rest: Vec<&str> = words.collect();
        match kw {
            "v" => {
                if rest.len() < 3 || rest.len() > 4 {
                    return Err(format!("{}:{line}: a vertex needs 3 coordinates, found {}", path.display(), rest.len()));
                }
                for w in &rest {
                    number(path, line, w)?;
                }
                nv += 1;
            }
            "vn" => {
                if rest.len() != 3 {
                    return Err(format!("{}:{line}: a normal needs 3 components, found {}", path.display(), rest.len()));
                }
                for w in &rest {
                    number(path, line, w)?;
                }
                nvn += 1;
            }
            "vt" => nvt += 1,
            "f" => {
                if rest.len() < 3 {
                    return Err(format!("{}:{line}: a face needs at least 3 vertices, found {}", path.display(), rest.len()));
                }
                for r in &rest {
                    let parts: Vec<&str> = r.split('/').collect();
                    if parts.len() > 3 || parts[0].is_empty() {
                        return Err(format!("{}:{line}: malformed face vertex '{r}'", path.display()));
                    }
                    resolve(path, line, parts[0], "vertex", nv)?;
                    if parts.len() > 1 && !parts[1].is_empty() {
                        resolve(path, line, parts[1], "texture coordinate", nvt)?;
                    }
                    if parts.len() > 2 && !parts[2].is_empty() {
                        resolve(path, line, parts[2], "normal", nvn)?;
                    }
                }
                nf += 1;
            }
            _ => {}
        }
    }
    if nf == 0 {
        return Err(format!("{}: no faces: nothing to render", path.display()));
    }
    Ok(())
}

/// Round a Phong exponent to the nearest power of two in 1..=16.
fn gloss_from_ns(ns: f64) -> u32 {
    let mut best = 1;
    for g in [1u32, 2, 4, 8, 16] {
        if (ns - g as f64).abs() < (ns - best as f64).abs() {
            best = g;
        }
    }
    best
}

/// Load an OBJ file as one mesh (all its objects), wound counter-clockwise as OBJ files are.
pub fn load_obj(path: &Path) -> Result<Mesh, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read OBJ file: {e}", path.display()))?;
    prescan(path, &text)?;
    let opts = tobj::LoadOptions { triangulate: true, single_index: false, ignore_points: true, ignore_lines: true };
    let (models, mats) = tobj::load_obj(path, &opts).map_err(|e| format!("{}: {e}", path.display()))?;
    let mats = mats.unwrap_or_default();
    let mut materials: Vec<Material> = mats
        .iter()
        .map(|m| {
            let kd = m.diffuse.map(|d| d.map(|c| c as f64)).unwrap_or([0.7, 0.7, 0.7]);
            let ka = m.ambient.map(|a| a.map(|c| c as f64)).filter(|a| a.iter().any(|&c| c > 0.0)).unwrap_or(kd);
            let ks = m.specular.map(|s| s.map(|c| c as f64)).unwrap_or([0.3, 0.3, 0.3]);
            Material { ambient: ka, diffuse: kd, specular: ks, gloss: gloss_from_ns(m.shininess.map(|s| s as f64).unwrap_or(16.0)) }
        })
        .collect();
    let default_material = materials.len() as u32;
    materials.push(Material::plastic([0.7, 0.7, 0.7]));

    let mut mesh = Mesh {
        name: path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "obj".into()),
        positions: Vec::new(),
        normals: Vec::new(),
        materials,
        triangles: Vec::new(),
        front_face: Winding::Ccw,
    };
    for m in &models {
        let me = &m.mesh;
        let pbase = mesh.positions.len() as u32;
        mesh.positions.extend(me.positions.chunks(3).map(|p| [p[0] as f64, p[1] as f64, p[2] as f64]));
        let nbase = mesh.normals.len() as u32;
        mesh.normals.extend(me.normals.chunks(3).map(|n| normalize([n[0] as f64, n[1] as f64, n[2] as f64])));
        let material = me.material_id.filter(|&i| i < default_material as usize).map(|i| i as u32).unwrap_or(default_material);
        for (t, tri) in me.indices.chunks(3).enumerate() {
            if tri.len() < 3 {
                continue;
            }
            let v = [pbase + tri[0], pbase + tri[1], pbase + tri[2]];
            let [a, b, c] = v.map(|i| mesh.positions[i as usize]);
            let face = cross(sub(b, a), sub(c, a));
            let face = if face.iter().all(|&x| x == 0.0) { [0.0, 0.0, 1.0] } else { normalize(face) };
            let file_normals = me.normal_indices.len() >= 3 * (t + 1);
            let n = if file_normals {
                [0, 1, 2].map(|k| {
                    let ni = nbase + me.normal_indices[3 * t + k];
                    let nv = mesh.normals[ni as usize];
                    if nv.iter().all(|&x| x == 0.0) || nv.iter().any(|x| !x.is_finite()) {
                        mesh.normals.push(face);
                        mesh.normals.len() as u32 - 1
                    } else {
                        ni
                    }
                })
            } else {
                mesh.normals.push(face);
                [mesh.normals.len() as u32 - 1; 3]
            };
            mesh.triangles.push(Triangle { v, n, material });
        }
    }
    if mesh.triangles.is_empty() {
        return Err(format!("{}: no faces: nothing to render", path.display()));
    }
    mesh.validate().map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn file(name: &str, text: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("golden-obj-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    #[test]
    fn a_quad_face_becomes_two_triangles() {
        let m = load_obj(&file("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")).unwrap();
        assert_eq!(m.triangles.len(), 2);
        assert_eq!(m.front_face, Winding::Ccw);
        // Flat normals from counter-clockwise winding point along +z.
        assert!(m.triangles.iter().all(|t| m.normals[t.n[0] as usize][2] > 0.99));
    }

    #[test]
    fn negative_indices_count_back_from_the_last_vertex() {
        let m = load_obj(&file("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n")).unwrap();
        assert_eq!(m.triangles[0].v, [0, 1, 2]);
    }

    #[test]
    fn errors_name_the_file_and_line() {
        let cases = [
            ("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", "nan.obj:2"),
            ("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", "inf.obj:3"),
            ("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n", "range.obj:5"),
            ("few.obj", "v 0 0\n", "few.obj:1"),
            ("word.obj", "v 0 0 x\n", "word.obj:1"),
            ("face.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "face.obj:3"),
            ("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "zero.obj:4"),
            ("normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", "normal.obj:4"),
            ("empty.obj", "# nothing here\n", "empty.obj"),
        ];
        for (name, text, want) in cases {
            let e = load_obj(&file(name, text)).unwrap_err();
            assert!(e.contains(want), "{name}: {e}");
        }
        let e = load_obj(Path::new("/nonexistent/missing.obj")).unwrap_err();
        assert!(e.contains("missing.obj") && e.contains("cannot read"), "{e}");
    }

    #[test]
    fn a_missing_material_library_falls_back_to_grey() {
        let m = load_obj(&file("mtl.obj", "mtllib nowhere.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).unwrap();
        assert_eq!(m.triangles.len(), 1);
        assert_eq!(m.materials[m.triangles[0].material as usize].diffuse, [0.7, 0.7, 0.7]);
    }

    #[test]
    fn materials_and_file_normals_are_used() {
        let d = file("lib.mtl", "newmtl red\nKd 0.9 0.1 0.1\nKs 0.5 0.5 0.5\nNs 10\n");
        let _ = d;
        let m = load_obj(&file("withmtl.obj", "mtllib lib.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n")).unwrap();
        let mat = &m.materials[m.triangles[0].material as usize];
        assert_eq!(mat.diffuse, [0.9f32 as f64, 0.1f32 as f64, 0.1f32 as f64]);
        assert_eq!(mat.gloss, 8);
        assert_eq!(m.normals[m.triangles[0].n[0] as usize], [0.0, 0.0, 1.0]);
    }
}
