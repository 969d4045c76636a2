//! Wavefront OBJ loading (with its MTL materials) into a [`Mesh`].
//!
//! tobj does the grouping and the MTL parsing (with its `use_f64` feature: coordinates stay f64, so a
//! small model far from the origin keeps its shape), but it is lenient (it silently accepts NaN, and its
//! errors name neither file nor line), while a user who points the program at a broken file must be
//! told where it is broken. So the text is first checked line by line here, and tobj only ever sees
//! lines that passed: any error names the file and the line, and no input makes the loader panic.
//! Polygons are triangulated here by ear clipping (tobj's fan is wrong for concave polygons), a UTF-8
//! byte-order mark is skipped, and a material library that cannot be read is a warning, not silence.

use std::path::Path;

use super::{Material, Mesh, Triangle, Winding};

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn length(a: V3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// `a` scaled to unit length, or `None` if it has no usable direction.
fn unit(a: V3) -> Option<V3> {
    let l = length(a);
    (l > 0.0 && l.is_finite()).then(|| [a[0] / l, a[1] / l, a[2] / l])
}

/// The unit normal of a counter-clockwise triangle; a zero-area triangle gets +z.
fn face_normal(a: V3, b: V3, c: V3) -> V3 {
    unit(cross(sub(b, a), sub(c, a))).unwrap_or([0.0, 0.0, 1.0])
}

/// The largest |coordinate| accepted in an OBJ file (the camera's range, `host::CAMERA_RANGE`).
pub const OBJ_COORDINATE_RANGE: f64 = crate::host::CAMERA_RANGE;

/// Load an OBJ file (and the MTL files it names) as one mesh named after the file stem.
///
/// Polygons are split into triangles by ear clipping. File normals are used when every face gives
/// them (and made unit length); otherwise each triangle gets its flat counter-clockwise face normal. A
/// missing or broken MTL file is not fatal: the faces get a grey plastic instead (see
/// [`load_obj_with_warnings`] for the warning).
pub fn load_obj(path: &Path) -> Result<Mesh, String> {
    load_obj_with_warnings(path).map(|(m, _)| m)
}

/// [`load_obj`], with what the loader had to work around (an MTL file it could not read, a polygon
/// it could not clip and fanned instead), one line each naming the file and line.
pub fn load_obj_with_warnings(path: &Path) -> Result<(Mesh, Vec<String>), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read OBJ file: {}", path.display(), e))?;
    // A UTF-8 byte-order mark is not part of the first statement.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let checked = prescan(path, text)?;
    let mut warnings = checked.warnings.clone();
    if checked.faces == 0 {
        return Err(format!("{}: OBJ file has no faces", path.display()));
    }

    // The update fills the options that tobj's optional features (merging, reordering) add.
    #[allow(clippy::needless_update)]
    let options =
        tobj::LoadOptions { triangulate: true, single_index: false, ignore_points: true, ignore_lines: true, ..Default::default() };
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mtl_problems = std::cell::RefCell::new(Vec::new());
    let (models, materials) = tobj::load_obj_buf(&mut checked.text.as_bytes(), &options, |mtl| {
        // The library is checked line by line first: tobj panics on a colour with fewer than three
        // numbers (found by the loader's fuzzing, golden/tests/obj_fuzz.rs).
        let file = dir.join(mtl);
        let r = check_mtl(&file).map_err(|e| (e, tobj::LoadError::MaterialParseError)).and_then(|text| {
            tobj::load_mtl_buf(&mut text.as_bytes()).map_err(|e| (e.to_string(), e))
        });
        match r {
            Ok(m) => Ok(m),
            Err((why, e)) => {
                mtl_problems.borrow_mut().push(format!("{}: material library {} cannot be used ({why}): its faces are grey plastic", path.display(), file.display()));
                Err(e)
            }
        }
    })
    .map_err(|e| format!("{}: {}", path.display(), e))?;
    warnings.extend(mtl_problems.into_inner());
    // A missing MTL file leaves the faces without a material; they get the default below.
    let file_materials: Vec<Material> = materials.unwrap_or_default().iter().map(|m| convert_material(&dir, m)).collect();

    let mut mesh = Mesh {
        name: path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "obj".into()),
        positions: Vec::new(),
        normals: Vec::new(),
        materials: file_materials,
        triangles: Vec::new(),
        front_face: Winding::Ccw,
        texcoords: Vec::new(),
        triangle_texcoords: Vec::new(),
        view: None,
    };
    let mut default_material = None;
    for model in &models {
        let m = &model.mesh;
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(m.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
        let material = match m.material_id {
            Some(i) if i < mesh.materials.len() => i as u32,
            _ => *default_material.get_or_insert_with(|| {
                mesh.materials.push(Material::plastic([0.7, 0.7, 0.7]));
                (mesh.materials.len() - 1) as u32
            }),
        };
        // tobj invents normals for faces without them, so file normals are only trusted when the
        // prescan saw them on every face. Zero-length ones are marked None and replaced per corner.
        let use_file_normals = checked.all_faces_have_normals && m.normal_indices.len() == m.indices.len();
        let normal_base = mesh.normals.len() as u32;
        let file_normals: Vec<Option<V3>> = if use_file_normals {
            m.normals.chunks_exact(3).map(|n| unit([n[0], n[1], n[2]])).collect()
        } else {
            Vec::new()
        };
        if use_file_normals {
            mesh.normals.extend(file_normals.iter().map(|n| n.unwrap_or([0.0, 0.0, 1.0])));
        }
        for (corner, idx) in m.indices.chunks_exact(3).enumerate() {
            let v = [base + idx[0], base + idx[1], base + idx[2]];
            let [a, b, c] = v.map(|i| mesh.positions[i as usize]);
            let mut face = None;
            let mut face_index = |normals: &mut Vec<V3>| {
                *face.get_or_insert_with(|| {
                    normals.push(face_normal(a, b, c));
                    (normals.len() - 1) as u32
                })
            };
            let n: [u32; 3] = std::array::from_fn(|k| {
                if use_file_normals {
                    let ni = m.normal_indices[3 * corner + k];
                    match file_normals.get(ni as usize) {
                        Some(Some(_)) => normal_base + ni,
                        _ => face_index(&mut mesh.normals),
                    }
                } else {
                    face_index(&mut mesh.normals)
                }
            });
            mesh.triangles.push(Triangle { v, n, material });
        }
    }
    if mesh.triangles.is_empty() {
        return Err(format!("{}: OBJ file has no faces", path.display()));
    }
    attach_texcoords(path, &mut mesh, checked.texcoords, &checked.triangle_texcoords, &mut warnings)?;
    mesh.validate().map_err(|e| format!("{}: {}", path.display(), e))?;
    Ok((mesh, warnings))
}

/// Give the mesh the file's texture coordinates when any face has them. tobj sees the faces in the
/// prescan's order, one triangle each, so the n-th triangle is the prescan's n-th. Faces without
/// texture coordinates in a file where others have them get (0, 0), with a warning.
fn attach_texcoords(
    path: &Path,
    mesh: &mut Mesh,
    texcoords: Vec<[f64; 2]>,
    triangle_texcoords: &[Option<[u32; 3]>],
    warnings: &mut Vec<String>,
) -> Result<(), String> {
    if triangle_texcoords.iter().all(Option::is_none) {
        return Ok(());
    }
    if triangle_texcoords.len() != mesh.triangles.len() {
        return Err(format!(
            "{}: the OBJ reader returned {} triangles where the file has {}: texture coordinates cannot be matched",
            path.display(),
            mesh.triangles.len(),
            triangle_texcoords.len()
        ));
    }
    mesh.texcoords = texcoords;
    let missing = triangle_texcoords.iter().filter(|t| t.is_none()).count();
    if missing > 0 {
        warnings.push(format!("{}: {} triangles have no texture coordinates where others have them: they get (0, 0)", path.display(), missing));
        mesh.texcoords.push([0.0, 0.0]);
    }
    let origin = (mesh.texcoords.len() - 1) as u32;
    mesh.triangle_texcoords = triangle_texcoords.iter().map(|t| t.unwrap_or([origin; 3])).collect();
    Ok(())
}

/// The text of an MTL library whose colour and number statements tobj can parse, or why not (with
/// the line).
fn check_mtl(path: &Path) -> Result<String, String> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text).to_string();
    for (number, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        let mut words = line.split_whitespace();
        let keyword = words.next().unwrap_or("");
        let args: Vec<&str> = words.collect();
        let numbers_ok = |n: usize| args.len() >= n && args[..n].iter().all(|w| w.parse::<f64>().is_ok());
        let ok = match keyword {
            "Ka" | "Kd" | "Ks" | "Ke" => numbers_ok(3),
            "Ns" | "Ni" => numbers_ok(1),
            // Opacity: a number in 0..=1 (a NaN or 1.5 would otherwise reach the blend as garbage).
            "d" | "Tr" => numbers_ok(1) && args[0].parse::<f64>().is_ok_and(|v| (0.0..=1.0).contains(&v)),
            _ => true,
        };
        if !ok {
            if keyword == "d" || keyword == "Tr" {
                return Err(format!("line {}: `{keyword}` needs one number in 0..=1 (the opacity d, or Tr = 1 - d)", number + 1));
            }
            return Err(format!("line {}: `{keyword}` needs {} numbers", number + 1, if keyword.starts_with('K') { 3 } else { 1 }));
        }
    }
    Ok(text)
}

/// An MTL material in our Phong model: Kd, Ka (Kd when missing or black, since a black ambient
/// would leave unlit sides invisible), Ks, Ns rounded to a power of two in 1..=16, and the opacity:
/// `d`, else 1 - `Tr` (tobj keeps `Tr` among its unknown parameters), else 1 (opaque).
fn convert_material(dir: &Path, m: &tobj::Material) -> Material {
    let colour = |c: Option<[f64; 3]>| -> Option<V3> { c.filter(|c| c.iter().all(|x| x.is_finite())).map(|c| c.map(|x| x.clamp(0.0, 1.0))) };
    let diffuse = colour(m.diffuse).unwrap_or([0.7, 0.7, 0.7]);
    let ambient = colour(m.ambient).filter(|a| a.iter().any(|&x| x > 0.0)).unwrap_or(diffuse);
    let specular = colour(m.specular).unwrap_or([0.0; 3]);
    let gloss = match m.shininess {
        Some(ns) if ns.is_finite() => gloss_from_ns(ns),
        _ => 16,
    };
    let tr = m.unknown_param.get("Tr").and_then(|t| t.trim().parse::<f64>().ok()).map(|t| 1.0 - t);
    let opacity = m.dissolve.or(tr).filter(|d| d.is_finite()).unwrap_or(1.0).clamp(0.0, 1.0);
    let texture = m.diffuse_texture.as_ref().map(|t| dir.join(t.trim()));
    Material { ambient, diffuse, specular, gloss, opacity, texture }
}

/// The power of two in 1..=16 nearest to Ns on a log scale (MTL's Ns runs 0..1000; the chip's
/// gloss is 1..=16, seed 001 eq. 4).
fn gloss_from_ns(ns: f64) -> u32 {
    if ns <= 1.0 {
        return 1;
    }
    1 << (ns.log2().round().clamp(0.0, 4.0) as u32)
}

/// What the prescan learned: the text tobj is given, the number of faces, and whether all faces
/// carry normal references.
struct Checked {
    text: String,
    faces: usize,
    all_faces_have_normals: bool,
    warnings: Vec<String>,
    /// The file's `vt` (u, v; v = 0 where a line gives only u), and per triangle passed to tobj, in
    /// order, its corners' 0-based indices into them (None for a face without any).
    texcoords: Vec<[f64; 2]>,
    triangle_texcoords: Vec<Option<[u32; 3]>>,
}

/// Check every line of an OBJ file; return the text reduced to the statements tobj needs.
///
/// Statements the mesh does not use (o, g, s, l, p, ...) are accepted. Texture coordinates (`vt`
/// and the faces' references to them) are kept here, not passed to tobj. Comments are cut off
/// before tobj sees the line (tobj would read `v 1 2 3 # note` as a fourth coordinate).
fn prescan(path: &Path, text: &str) -> Result<Checked, String> {
    let (mut nv, mut nvt, mut nvn) = (0i64, 0i64, 0i64);
    let mut out = String::with_capacity(text.len());
    let mut faces = 0usize;
    let mut all_faces_have_normals = true;
    let mut positions: Vec<V3> = Vec::new();
    let mut warnings = Vec::new();
    let mut texcoords: Vec<[f64; 2]> = Vec::new();
    let mut triangle_texcoords: Vec<Option<[u32; 3]>> = Vec::new();
    for (number, raw) in text.lines().enumerate() {
        let err = |msg: String| format!("{}:{}: {}", path.display(), number + 1, msg);
        let line = raw.split('#').next().unwrap_or("").trim();
        let mut words = line.split_whitespace();
        let keyword = words.next().unwrap_or("");
        let args: Vec<&str> = words.collect();
        let numbers = |what: &str| -> Result<Vec<f64>, String> {
            args.iter()
                .map(|w| match w.parse::<f64>() {
                    Ok(x) if x.is_finite() && x.abs() <= OBJ_COORDINATE_RANGE => Ok(x),
                    Ok(x) if x.is_finite() => Err(err(format!("{} '{}' is outside +-{:e}, the range of coordinates", what, w, OBJ_COORDINATE_RANGE))),
                    Ok(_) => Err(err(format!("non-finite coordinate '{}'", w))),
                    Err(_) => Err(err(format!("malformed {}: '{}' is not a number", what, w))),
                })
                .collect()
        };
        // Statements tobj needs are passed on; everything else becomes an empty line.
        let keep = match keyword {
            "v" => {
                let c = numbers("vertex")?;
                match c.len() {
                    3 | 6 => {}
                    4 if c[3] == 0.0 => return Err(err("vertex has weight w = 0".into())),
                    4 => {}
                    n => return Err(err(format!("vertex needs 3 coordinates (and an optional w or r g b), found {} numbers", n))),
                }
                let w = if c.len() == 4 { c[3] } else { 1.0 };
                positions.push([c[0] / w, c[1] / w, c[2] / w]);
                nv += 1;
                true
            }
            "vn" => {
                let c = numbers("normal")?;
                if c.len() != 3 {
                    return Err(err(format!("normal needs 3 components, found {}", c.len())));
                }
                nvn += 1;
                true
            }
            "vt" => {
                let c = numbers("texture coordinate")?;
                if !(1..=3).contains(&c.len()) {
                    return Err(err(format!("texture coordinate needs 1 to 3 numbers, found {}", c.len())));
                }
                nvt += 1;
                texcoords.push([c[0], c.get(1).copied().unwrap_or(0.0)]);
                // tobj is not given them (it would reject `vt u`): the prescan keeps them.
                false
            }
            "f" => {
                if args.len() < 3 {
                    return Err(err(format!("face needs at least 3 vertices, found {}", args.len())));
                }
                let mut refs = Vec::with_capacity(args.len());
                let mut face_texcoords = Vec::with_capacity(args.len());
                for word in &args {
                    let (v, vt, vn) =
                        parse_ref(word).ok_or_else(|| err(format!("malformed face vertex '{}' (expected i, i/j, i//k or i/j/k)", word)))?;
                    let v = resolve(v, nv, "vertex", "vertices").map_err(&err)?;
                    if let Some(t) = vt {
                        face_texcoords.push(resolve(t, nvt, "texture coordinate", "texture coordinates").map_err(&err)? as u32 - 1);
                    }
                    let vn = match vn {
                        Some(n) => Some(resolve(n, nvn, "normal", "normals").map_err(&err)?),
                        None => None,
                    };
                    refs.push((v, vn));
                }
                if !face_texcoords.is_empty() && face_texcoords.len() != refs.len() {
                    return Err(err(format!(
                        "face gives texture coordinates for {} of its {} vertices: give them for all or none",
                        face_texcoords.len(),
                        refs.len()
                    )));
                }
                all_faces_have_normals &= refs.iter().all(|r| r.1.is_some());
                faces += 1;
                // Rewritten as triangles (ear clipping), with absolute indices and without texture
                // coordinates: tobj then sees exactly what was checked.
                let corners: Vec<V3> = refs.iter().map(|r| positions[r.0 as usize - 1]).collect();
                let tris = match ear_clip(&corners) {
                    Some(t) => t,
                    None => {
                        warnings.push(err(format!("the {}-gon is not a simple polygon: fanned from its first vertex", refs.len())));
                        (1..refs.len() - 1).map(|k| [0, k, k + 1]).collect()
                    }
                };
                for t in tris {
                    triangle_texcoords.push((!face_texcoords.is_empty()).then(|| t.map(|k| face_texcoords[k])));
                    out.push('f');
                    for k in t {
                        match refs[k] {
                            (v, Some(n)) => out.push_str(&format!(" {}//{}", v, n)),
                            (v, None) => out.push_str(&format!(" {}", v)),
                        }
                    }
                    out.push('\n');
                }
                continue;
            }
            "usemtl" | "mtllib" => {
                if args.is_empty() {
                    return Err(err(format!("{} needs a name", keyword)));
                }
                true
            }
            "o" | "g" => true,
            _ => false,
        };
        if keep {
            out.push_str(line);
        }
        out.push('\n');
    }
    Ok(Checked { text: out, faces, all_faces_have_normals, warnings, texcoords, triangle_texcoords })
}

/// Split a polygon (corners in order) into triangles by ear clipping, in the plane that its Newell
/// normal is most perpendicular to; the triangles keep the polygon's winding. A triangle is itself.
/// `None` when the polygon is not simple (no ear is left, e.g. it crosses itself) or has no area.
fn ear_clip(p: &[V3]) -> Option<Vec<[usize; 3]>> {
    let n = p.len();
    if n == 3 {
        return Some(vec![[0, 1, 2]]);
    }
    // Newell's normal, and the two axes of the plane to project on.
    let mut nn = [0.0f64; 3];
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        nn[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nn[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nn[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    let k = (0..3).max_by(|&i, &j| nn[i].abs().total_cmp(&nn[j].abs()))?;
    if !(nn[k].abs() > 0.0) {
        return None;
    }
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let sign = nn[k].signum();
    let q: Vec<[f64; 2]> = p.iter().map(|c| [c[u], c[v]]).collect();
    // Twice the signed area of (a, b, c) in the projection, positive for the polygon's winding.
    let area = |a: usize, b: usize, c: usize| sign * ((q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[c][0] - q[a][0]) * (q[b][1] - q[a][1]));
    let inside = |x: usize, a: usize, b: usize, c: usize| area(a, b, x) >= 0.0 && area(b, c, x) >= 0.0 && area(c, a, x) >= 0.0;
    // A convex polygon (no corner turns the other way) is its own fan: linear time for the large
    // polygons of scanned models, where clipping ears one by one would be quadratic or worse.
    if (0..n).all(|i| area((i + n - 1) % n, i, (i + 1) % n) >= 0.0) {
        return Some((1..n - 1).map(|k| [0, k, k + 1]).collect());
    }
    let mut left: Vec<usize> = (0..n).collect();
    let mut tris = Vec::with_capacity(n - 2);
    while left.len() > 3 {
        let m = left.len();
        let ear = (0..m).find(|&i| {
            let (a, b, c) = (left[(i + m - 1) % m], left[i], left[(i + 1) % m]);
            area(a, b, c) > 0.0 && !left.iter().any(|&x| x != a && x != b && x != c && q[x] != q[a] && q[x] != q[b] && q[x] != q[c] && inside(x, a, b, c))
        })?;
        tris.push([left[(ear + m - 1) % m], left[ear], left[(ear + 1) % m]]);
        left.remove(ear);
    }
    tris.push([left[0], left[1], left[2]]);
    Some(tris)
}

/// A face vertex `i`, `i/j`, `i//k` or `i/j/k` as (i, j, k); `None` if it is none of these.
fn parse_ref(word: &str) -> Option<(i64, Option<i64>, Option<i64>)> {
    let parts: Vec<&str> = word.split('/').collect();
    let int = |s: &str| s.parse::<i64>().ok();
    match parts.as_slice() {
        [v] => Some((int(v)?, None, None)),
        [v, t] => Some((int(v)?, Some(int(t)?), None)),
        [v, t, n] => Some((int(v)?, if t.is_empty() { None } else { Some(int(t)?) }, Some(int(n)?))),
        _ => None,
    }
}

/// An OBJ index (1-based, or negative = counted back from the last one defined so far) as a
/// 1-based absolute index, checked against the `count` defined so far.
fn resolve(index: i64, count: i64, what: &str, plural: &str) -> Result<i64, String> {
    let absolute = if index < 0 { count + 1 + index } else { index };
    if index == 0 {
        Err(format!("face refers to {} 0, but OBJ indices start at 1", what))
    } else if absolute < 1 || absolute > count {
        Err(format!("face refers to {} {} but only {} {} are defined", what, index, count, plural))
    } else {
        Ok(absolute)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// A fresh directory under the system temp dir, unique per test and process.
    fn temp_dir(tag: &str) -> PathBuf {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("golden-obj-{}-{}-{}", std::process::id(), tag, n));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Write `text` to `<fresh dir>/<name>` and load it.
    fn load_text(name: &str, text: &str) -> (PathBuf, Result<Mesh, String>) {
        let dir = temp_dir(name);
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        let result = load_obj(&path);
        // Only the path's text is needed afterwards.
        std::fs::remove_dir_all(&dir).unwrap();
        (path, result)
    }

    const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    #[test]
    fn a_quad_face_becomes_two_triangles_with_ccw_face_normals() {
        let (_, m) = load_text("quad.obj", &format!("{SQUARE}f 1 2 3 4\n"));
        let m = m.unwrap();
        assert_eq!(m.name, "quad");
        assert_eq!(m.front_face, Winding::Ccw);
        assert_eq!(m.triangles.len(), 2);
        for t in &m.triangles {
            for &n in &t.n {
                assert_eq!(m.normals[n as usize], [0.0, 0.0, 1.0]);
            }
        }
        m.validate().unwrap();
    }

    #[test]
    fn a_pentagon_is_split_into_three_triangles() {
        let (_, m) = load_text("penta.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n");
        assert_eq!(m.unwrap().triangles.len(), 3);
    }

    /// Twice the signed area of a triangle in the z = 0 plane.
    fn area2(m: &Mesh, t: &Triangle) -> f64 {
        let [a, b, c] = t.v.map(|i| m.positions[i as usize]);
        (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    }

    /// Issue 18: tobj's fan turned concave polygons into wrong shapes. An L-shaped hexagon (area 3)
    /// whose fan from its first vertex would cover the notch: the triangles must tile exactly its area, all
    /// counter-clockwise, and none may have its centroid in the notch.
    #[test]
    fn a_concave_polygon_is_split_by_ear_clipping_into_triangles_inside_it() {
        // (0,0) (2,0) (2,1) (1,1) (1,2) (0,2): the notch is the square (1..2, 1..2). Listed from
        // (2,1), whose fan's first triangle (2,1) (1,1) (1,2) lies in the notch.
        let text = "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n";
        let (_, m) = load_text("ell.obj", text);
        let m = m.unwrap();
        assert_eq!(m.triangles.len(), 4);
        let total: f64 = m.triangles.iter().map(|t| area2(&m, t)).sum();
        assert!((total - 6.0).abs() < 1e-12, "twice the area {total}, expected 6");
        for t in &m.triangles {
            assert!(area2(&m, t) > 0.0, "a triangle turned clockwise: {t:?}");
            let c = t.v.map(|i| m.positions[i as usize]);
            let (x, y) = ((c[0][0] + c[1][0] + c[2][0]) / 3.0, (c[0][1] + c[1][1] + c[2][1]) / 3.0);
            assert!(!(x > 1.0 && y > 1.0), "triangle {t:?} lies in the notch");
        }
    }

    #[test]
    fn a_self_crossing_polygon_is_fanned_with_a_warning_naming_the_line() {
        let dir = temp_dir("bowtie");
        let path = dir.join("bowtie.obj");
        std::fs::write(&path, "v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 2 0\nf 1 2 3 4\n").unwrap();
        let (m, w) = load_obj_with_warnings(&path).unwrap();
        assert_eq!(m.triangles.len(), 2);
        assert!(w.iter().any(|w| w.contains("bowtie.obj:5") && w.contains("not a simple polygon")), "{w:?}");
    }

    /// Issue 18: coordinates were rounded to f32, so a unit square at x = 1e8 collapsed.
    #[test]
    fn coordinates_keep_f64_precision_far_from_the_origin() {
        let (_, m) = load_text("far.obj", "v 100000000 0 0\nv 100000001 0 0\nv 100000001 1 0\nv 100000000 1 0\nf 1 2 3 4\n");
        let m = m.unwrap();
        let xs = m.positions.iter().map(|p| p[0]);
        let (lo, hi) = (xs.clone().fold(f64::MAX, f64::min), xs.fold(f64::MIN, f64::max));
        assert_eq!(hi - lo, 1.0, "{:?}", m.positions);
        assert!(m.triangles.iter().all(|t| area2(&m, t) > 0.0));
    }

    /// Issue 18: 1e39 became inf in f32 and was reported without its line.
    #[test]
    fn a_coordinate_beyond_the_range_is_an_error_naming_the_line() {
        let (_, m) = load_text("huge.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n");
        let e = m.unwrap_err();
        assert!(e.contains("huge.obj:2") && e.contains("1e39") && e.contains("outside"), "{e}");
    }

    /// Issue 18: a UTF-8 byte-order mark made the first line vanish.
    #[test]
    fn a_byte_order_mark_does_not_hide_the_first_line() {
        let (_, m) = load_text("bom.obj", "\u{feff}v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert_eq!(m.unwrap().triangles.len(), 1);
    }

    /// A large convex polygon takes the fan's linear path: a 20 000-gon loads at once.
    #[test]
    fn a_large_convex_polygon_is_fanned_in_linear_time() {
        let n = 20_000;
        let mut text = String::new();
        for k in 0..n {
            let a = k as f64 * std::f64::consts::TAU / n as f64;
            text.push_str(&format!("v {} {} 0\n", a.cos(), a.sin()));
        }
        text.push('f');
        for k in 1..=n {
            text.push_str(&format!(" {k}"));
        }
        text.push('\n');
        let t0 = std::time::Instant::now();
        let (_, m) = load_text("circle.obj", &text);
        assert_eq!(m.unwrap().triangles.len(), n - 2);
        eprintln!("20 000-gon loaded in {:.2} s", t0.elapsed().as_secs_f64());
    }

    /// Found by the fuzzing harness: a colour with one number made tobj panic.
    #[test]
    fn a_material_colour_with_too_few_numbers_is_a_warning_naming_the_line() {
        let dir = temp_dir("shortkd");
        std::fs::write(dir.join("m.mtl"), "newmtl red\nKd 1\n").unwrap();
        let path = dir.join("short.obj");
        std::fs::write(&path, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n").unwrap();
        let (m, w) = load_obj_with_warnings(&path).unwrap();
        assert_eq!(m.triangles.len(), 1);
        assert!(w.iter().any(|w| w.contains("line 2") && w.contains("`Kd` needs 3 numbers")), "{w:?}");
    }

    /// The texture coordinate of every triangle corner, looked up by the corner's position.
    fn corner_uvs(m: &Mesh) -> Vec<([f64; 3], [f64; 2])> {
        m.triangles
            .iter()
            .zip(&m.triangle_texcoords)
            .flat_map(|(t, tc)| (0..3).map(move |k| (t.v[k], tc[k])))
            .map(|(v, c)| (m.positions[v as usize], m.texcoords[c as usize]))
            .collect()
    }

    #[test]
    fn texture_coordinates_follow_their_corners_through_triangulation_groups_and_materials() {
        // Two quads in two groups with two materials; the uv of a corner is (x / 2, y / 2 + 0.25),
        // given in a scrambled vt order so that an index mix-up shows.
        let text = "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n\
                    vt 0.5 0.75\nvt 0 0.25\nvt 0.5 0.25\nvt 0 0.75\nvt 1 0.25\nvt 1 0.75\n\
                    g left\nusemtl a\nf 1/2 2/3 3/1 4/4\ng right\nusemtl b\nf 2/3 5/5 6/6 3/1\n";
        let (_, m) = load_text("uv.obj", text);
        let m = m.unwrap();
        assert_eq!(m.triangles.len(), 4);
        assert_eq!(m.triangle_texcoords.len(), 4);
        for (p, uv) in corner_uvs(&m) {
            assert_eq!(uv, [p[0] / 2.0, p[1] / 2.0 + 0.25], "corner {p:?}");
        }
    }

    #[test]
    fn a_texture_coordinate_with_only_u_has_v_zero_and_a_mesh_without_any_has_none() {
        let (_, m) = load_text("u.obj", &format!("{SQUARE}vt 0.5\nf 1/1 2/1 3/1\n"));
        assert_eq!(m.unwrap().texcoords, vec![[0.5, 0.0]]);
        let (_, m) = load_text("none.obj", &format!("{SQUARE}vt 0.5 0.5\nf 1 2 3\n"));
        let m = m.unwrap();
        assert!(m.triangle_texcoords.is_empty() && m.texcoords.is_empty());
    }

    #[test]
    fn texture_coordinates_on_some_corners_of_a_face_or_out_of_range_are_errors_naming_the_line() {
        let (path, m) = load_text("mixed.obj", &format!("{SQUARE}vt 0 0\nf 1/1 2/1 3/1\nf 1/1 3 4/1\n"));
        let e = m.unwrap_err();
        assert!(e.contains(&format!("{}:7:", path.display())) && e.contains("2 of its 3 vertices"), "{e}");
        let (path, m) = load_text("range.obj", &format!("{SQUARE}vt 0 0\nf 1/1 2/2 3/1\n"));
        let e = m.unwrap_err();
        assert!(e.contains(&format!("{}:6:", path.display())) && e.contains("texture coordinate 2"), "{e}");
    }

    #[test]
    fn faces_without_texture_coordinates_beside_faces_with_them_get_the_origin_with_a_warning() {
        let dir = temp_dir("someuv");
        let path = dir.join("someuv.obj");
        std::fs::write(&path, format!("{SQUARE}vt 1 1\nf 1/1 2/1 3/1\nf 1 3 4\n")).unwrap();
        let (m, w) = load_obj_with_warnings(&path).unwrap();
        assert_eq!(m.texcoords[m.triangle_texcoords[0][0] as usize], [1.0, 1.0]);
        assert_eq!(m.texcoords[m.triangle_texcoords[1][2] as usize], [0.0, 0.0]);
        assert!(w.iter().any(|w| w.contains("1 triangles have no texture coordinates")), "{w:?}");
    }

    #[test]
    fn a_material_diffuse_map_is_kept_as_a_path_beside_the_obj() {
        let dir = temp_dir("mapkd");
        std::fs::write(dir.join("m.mtl"), "newmtl wood\nKd 1 1 1\nmap_Kd tex/wood.png\n").unwrap();
        let path = dir.join("mapkd.obj");
        std::fs::write(&path, format!("mtllib m.mtl\n{SQUARE}usemtl wood\nf 1 2 3\n")).unwrap();
        let m = load_obj(&path).unwrap();
        assert_eq!(m.materials[0].texture, Some(dir.join("tex/wood.png")));
    }

    /// Issue 18: a missing material library gave no word.
    #[test]
    fn a_missing_material_library_is_a_warning() {
        let dir = temp_dir("nomtl");
        let path = dir.join("nomtl.obj");
        std::fs::write(&path, "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n").unwrap();
        let (m, w) = load_obj_with_warnings(&path).unwrap();
        assert_eq!(m.triangles.len(), 1);
        assert!(w.iter().any(|w| w.contains("gone.mtl") && w.contains("grey")), "{w:?}");
    }

    #[test]
    fn a_missing_file_error_names_the_path() {
        let dir = temp_dir("missing");
        let path = dir.join("does-not-exist.obj");
        let e = load_obj(&path).unwrap_err();
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(e.starts_with(&format!("{}: cannot read OBJ file:", path.display())), "{e}");
    }

    #[test]
    fn a_nan_coordinate_is_an_error_naming_file_and_line() {
        let (path, m) = load_text("nan.obj", "# a comment\nv 1 nan 0\nv 0 0 0\nv 1 1 1\nf 1 2 3\n");
        assert_eq!(m.unwrap_err(), format!("{}:2: non-finite coordinate 'nan'", path.display()));
    }

    #[test]
    fn an_infinite_normal_is_an_error_naming_file_and_line() {
        let (path, m) = load_text("inf.obj", &format!("{SQUARE}vn 0 inf 1\nf 1 2 3\n"));
        assert_eq!(m.unwrap_err(), format!("{}:5: non-finite coordinate 'inf'", path.display()));
    }

    #[test]
    fn a_face_index_out_of_range_is_an_error_naming_the_line() {
        let (path, m) = load_text("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        assert_eq!(m.unwrap_err(), format!("{}:4: face refers to vertex 9 but only 3 vertices are defined", path.display()));
    }

    #[test]
    fn a_face_may_only_refer_to_vertices_defined_before_it() {
        let (path, m) = load_text("order.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n");
        assert_eq!(m.unwrap_err(), format!("{}:3: face refers to vertex 3 but only 2 vertices are defined", path.display()));
    }

    #[test]
    fn index_zero_and_bad_normal_references_are_errors_naming_the_line() {
        let (path, m) = load_text("zero.obj", &format!("{SQUARE}f 0 1 2\n"));
        assert!(m.unwrap_err().starts_with(&format!("{}:5: face refers to vertex 0", path.display())));
        let (path, m) = load_text("badvn.obj", &format!("{SQUARE}vn 0 0 1\nf 1//1 2//1 3//2\n"));
        assert_eq!(m.unwrap_err(), format!("{}:6: face refers to normal 2 but only 1 normals are defined", path.display()));
    }

    #[test]
    fn a_vertex_with_too_few_numbers_is_an_error_naming_the_line() {
        let (path, m) = load_text("short.obj", "v 0 0 0\nv 1 2\nv 0 1 0\nf 1 2 3\n");
        let e = m.unwrap_err();
        assert!(e.starts_with(&format!("{}:2: vertex needs 3 coordinates", path.display())), "{e}");
    }

    #[test]
    fn malformed_lines_are_errors_naming_the_line() {
        for (text, line) in [
            ("v 0 0 0\nv 1 x 0\n", 2),
            (&format!("{SQUARE}f 1 2\n") as &str, 5),
            (&format!("{SQUARE}f 1 2 3/4/5/6\n"), 5),
            (&format!("{SQUARE}f 1 2 a\n"), 5),
            (&format!("{SQUARE}usemtl\nf 1 2 3\n"), 5),
            ("v 1 1 1 0\n", 1),
        ] {
            let (path, m) = load_text("bad.obj", text);
            let e = m.unwrap_err();
            assert!(e.starts_with(&format!("{}:{}: ", path.display(), line)), "{text:?} gave {e}");
        }
    }

    #[test]
    fn negative_indices_count_back_from_the_last_vertex() {
        let (_, m) = load_text("neg.obj", "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nvn 0 0 2\nf 2//-1 3//-1 4//1\n");
        let m = m.unwrap();
        assert_eq!(m.triangles.len(), 2);
        for t in &m.triangles {
            let p: Vec<V3> = t.v.iter().map(|&i| m.positions[i as usize]).collect();
            assert_eq!(p, vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
        }
    }

    #[test]
    fn file_normals_are_used_and_made_unit_length() {
        let (_, m) = load_text("normals.obj", &format!("{SQUARE}vn 0 0 2\nvn 0 0 0\nf 1//1 2//1 3//2\n"));
        let m = m.unwrap();
        let t = m.triangles[0];
        assert_eq!(m.normals[t.n[0] as usize], [0.0, 0.0, 1.0]);
        // The zero-length file normal is replaced by the face normal.
        assert_eq!(m.normals[t.n[2] as usize], [0.0, 0.0, 1.0]);
        assert!(m.normals.iter().all(|n| (length(*n) - 1.0).abs() < 1e-12));
    }

    #[test]
    fn a_zero_area_face_gets_normal_plus_z() {
        let (_, m) = load_text("flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n");
        let m = m.unwrap();
        assert_eq!(m.normals[m.triangles[0].n[0] as usize], [0.0, 0.0, 1.0]);
    }

    #[test]
    fn a_missing_mtl_file_still_loads_with_the_default_material() {
        let (_, m) = load_text("nomtl.obj", &format!("mtllib nowhere.mtl\nusemtl red\n{SQUARE}f 1 2 3\n"));
        let m = m.unwrap();
        assert_eq!(m.materials, vec![Material::plastic([0.7, 0.7, 0.7])]);
        assert_eq!(m.triangles[0].material, 0);
    }

    #[test]
    fn mtl_materials_are_converted_with_gloss_a_power_of_two() {
        let dir = temp_dir("mtl");
        std::fs::write(
            dir.join("m.mtl"),
            "newmtl red\nKd 0.8 0.1 0.1\nKa 0 0 0\nKs 0.5 0.5 0.5\nNs 96\nnewmtl dull\nKd 0.2 0.3 0.4\nNs 3\n",
        )
        .unwrap();
        let path = dir.join("two.obj");
        std::fs::write(&path, format!("mtllib m.mtl\n{SQUARE}usemtl dull\nf 1 2 3\nusemtl red\nf 1 3 4\n")).unwrap();
        let m = load_obj(&path).unwrap();
        let red = &m.materials[m.triangles[1].material as usize];
        // tobj (use_f64) reads MTL numbers as f64.
        assert_eq!(red.diffuse, [0.8, 0.1, 0.1]);
        assert_eq!(red.ambient, red.diffuse, "black Ka falls back to Kd");
        assert_eq!(red.gloss, 16);
        let dull = &m.materials[m.triangles[0].material as usize];
        assert_eq!(dull.gloss, 4);
        assert_eq!(dull.specular, [0.0; 3]);
        m.validate().unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn gloss_is_the_nearest_power_of_two_clamped_to_1_to_16() {
        assert_eq!([0.0, 1.0, 1.4, 1.5, 3.0, 5.0, 6.0, 12.0, 1000.0].map(gloss_from_ns), [1, 1, 1, 2, 4, 4, 8, 16, 16]);
    }

    #[test]
    fn an_empty_file_is_an_error_not_a_panic() {
        let (path, m) = load_text("empty.obj", "");
        let e = m.unwrap_err();
        assert!(e.contains(&path.display().to_string()) && e.contains("no faces"), "{e}");
        let (_, m) = load_text("points.obj", &format!("{SQUARE}l 1 2\np 3\n"));
        assert!(m.unwrap_err().contains("no faces"));
    }

    #[test]
    fn groups_objects_comments_and_unknown_statements_are_accepted() {
        let text = format!("# header\nmtllib none.mtl\no thing\ng part\ns 1\nvt 0.5\n{SQUARE}usemtl x\nf 1/1 2/1 3/1 # trailing comment\ng other\nf 1 3 4\nl 1 2\n");
        let (_, m) = load_text("misc.obj", &text);
        assert_eq!(m.unwrap().triangles.len(), 2);
    }
}
