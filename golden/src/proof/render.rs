//! The algorithmic PROOF renderer: what a frame is, untimed.
//!
//! 1. Object setup on the host ([`scene_setup`]).
//! 2. OPP: for every pixel, the list of objects that may contribute, sorted nearest first (equal depths:
//!    lower id first) and cut after the first object that covers the pixel fully (seed 002 §3.2). That
//!    the OPP builds it by one insertion per object processor, in any order of the processors, gives
//!    the same list: dropping behind a full entry commutes with inserting.
//! 3. Shading stage: one colour per list entry ([`shade_entry`]).
//! 4. Filter stage: subpixel masks and weighted colours ([`super::filter`]).

use super::filter::{blend_subpixels, box2, combine, combine_blended, quadrant_sums, quadrant_sums_blended, visible_masks, FilterArea};
use super::format::{Entry, ObjectParams, ALPHA_ONE};
use super::setup::{scene_setup, ProofScene, SetupStats};
use super::shade::shade_entry;
use crate::format::Screen;
use crate::render::RenderOptions;
use crate::scene::Mesh;

/// Per-frame statistics of the PROOF pipeline.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct ProofStats {
    pub setup: SetupStats,
    /// Object processors needed with reuse (seed 002 §4.2): the most objects whose raster-order span
    /// (first to last pixel of the box) contains one pixel.
    pub ops_needed: u64,
    /// Object processors needed without reuse: one per object.
    pub ops_without_reuse: u64,
    /// List entries leaving the OPP (time slots of non-empty lists).
    pub entries: u64,
    /// Time slots leaving the OPP: entries plus one per empty pixel.
    pub slots: u64,
    pub max_list: u64,
    /// Pixels with a non-empty list.
    pub pixels_listed: u64,
    /// Pixels whose list has a partial entry (the ones the filter anti-aliases).
    pub pixels_with_partial: u64,
    /// Subpixels covered by some object, over the frame.
    pub subpixels_covered: u64,
}

/// A rendered PROOF frame.
#[derive(Clone, Debug)]
pub struct ProofFrame {
    pub screen: Screen,
    /// Anti-aliased RGB888, raster order.
    pub rgb: Vec<u8>,
    /// Covered subpixels per pixel (0..=64).
    pub covered: Vec<u8>,
    pub lists: Vec<Vec<Entry>>,
    pub stats: ProofStats,
}

/// The OPP's result, algorithmically: the object list of every pixel, raster order. A list ends at its
/// first full entry; a transparent object's entry is never full ([`super::format::own_entry`]), so it
/// keeps what lies behind it (issue 22).
pub fn object_lists(screen: Screen, objects: &[ObjectParams]) -> Vec<Vec<Entry>> {
    let w = screen.width as usize;
    let mut lists: Vec<Vec<Entry>> = vec![Vec::new(); screen.pixels()];
    for o in objects {
        for y in o.y0..=o.y1 {
            // Only the part of the row the edges allow (a thin triangle's box is mostly empty).
            let Some((x0, x1)) = o.row_span(y) else { continue };
            for x in x0..=x1 {
                if let Some(e) = o.entry_at(x, y) {
                    lists[y as usize * w + x as usize].push(e);
                }
            }
        }
    }
    for l in lists.iter_mut() {
        l.sort_by_key(|e| (e.depth, e.id));
        if let Some(p) = l.iter().position(|e| e.full) {
            l.truncate(p + 1);
        }
    }
    lists
}

/// Object processors needed with reuse: the largest number of raster-order spans over one pixel.
pub fn ops_needed(screen: Screen, objects: &[ObjectParams]) -> u64 {
    let mut ev: Vec<(u64, i64)> = Vec::with_capacity(objects.len() * 2);
    for o in objects {
        ev.push((o.first_pixel(screen.width), 1));
        ev.push((o.last_pixel(screen.width) + 1, -1));
    }
    ev.sort();
    let (mut cur, mut max) = (0i64, 0i64);
    for (_, d) in ev {
        cur += d;
        max = max.max(cur);
    }
    max as u64
}

/// The edge directions of object `id` (the filter stage's look-up table).
pub fn dirs_of(scene: &ProofScene, id: u16) -> [(i16, i16); 3] {
    scene.objects[id as usize].edges.map(|e| (e.cos, e.sin))
}

/// Shading and filter stages over given object lists (from the algorithmic OPP, its cycle model or the
/// RTL): the anti-aliased image and the covered subpixels per pixel.
pub fn shade_and_filter(scene: &ProofScene, lists: &[Vec<Entry>], area: FilterArea) -> (Vec<u8>, Vec<u8>) {
    let colours: Vec<Vec<[u8; 3]>> =
        lists.iter().map(|l| l.iter().map(|e| shade_entry(&scene.lights, e.normal, scene.material[e.id as usize])).collect()).collect();
    filter_lists(scene, lists, &colours, area)
}

/// The filter stage over object lists whose entries are already shaded (`colours[p][k]` is the colour
/// of entry k of pixel p, from the golden shading or the RTL shading stage).
pub fn filter_lists(scene: &ProofScene, lists: &[Vec<Entry>], colours: &[Vec<[u8; 3]>], area: FilterArea) -> (Vec<u8>, Vec<u8>) {
    filter_lists_as(scene, lists, colours, area, scene.objects.iter().any(|o| o.alpha < ALPHA_ONE))
}

/// [`filter_lists`] with every object taken as opaque (each subpixel to its nearest entry).
pub fn filter_lists_opaque(scene: &ProofScene, lists: &[Vec<Entry>], colours: &[Vec<[u8; 3]>], area: FilterArea) -> (Vec<u8>, Vec<u8>) {
    filter_lists_as(scene, lists, colours, area, false)
}

/// [`filter_lists`] with front-to-back blending per subpixel ([`blend_subpixels`]): the frame's form
/// when it has a transparent object (on opaque lists it gives the same bytes as the unblended form).
pub fn filter_lists_blended(scene: &ProofScene, lists: &[Vec<Entry>], colours: &[Vec<[u8; 3]>], area: FilterArea) -> (Vec<u8>, Vec<u8>) {
    filter_lists_as(scene, lists, colours, area, true)
}

/// The filter stage, unblended (subpixels to their nearest entry) or blended; the 2x2 area's blended
/// quadrant sums are rounded to whole units ([`quadrant_sums_blended`]).
fn filter_lists_as(scene: &ProofScene, lists: &[Vec<Entry>], colours: &[Vec<[u8; 3]>], area: FilterArea, blended: bool) -> (Vec<u8>, Vec<u8>) {
    let s = scene.screen;
    let dirs = |id: u16| dirs_of(scene, id);
    let alpha = |id: u16| scene.objects[id as usize].alpha;
    let mut rgb = Vec::with_capacity(s.pixels() * 3);
    let mut quads = Vec::new();
    let mut covered = Vec::with_capacity(s.pixels());
    for (l, colours) in lists.iter().zip(colours) {
        let bg = scene.background;
        let taken = if blended {
            let (acc, taken) = blend_subpixels(l, &dirs, &alpha, colours, bg);
            match area {
                FilterArea::Box1 => rgb.extend_from_slice(&combine_blended(&acc)),
                FilterArea::Box2 => quads.push(quadrant_sums_blended(&acc)),
            }
            taken
        } else {
            let (owners, taken) = visible_masks(l, &dirs);
            match area {
                FilterArea::Box1 => rgb.extend_from_slice(&combine(&owners, colours, taken, bg)),
                FilterArea::Box2 => quads.push(quadrant_sums(&owners, colours, taken, bg)),
            }
            taken
        };
        covered.push(taken.count_ones() as u8);
    }
    if area == FilterArea::Box2 {
        rgb = box2(s.width, s.height, &quads);
    }
    (rgb, covered)
}

/// Statistics of a set of lists.
pub fn list_stats(scene: &ProofScene, lists: &[Vec<Entry>], covered: &[u8]) -> ProofStats {
    let entries: u64 = lists.iter().map(|l| l.len() as u64).sum();
    ProofStats {
        setup: scene.stats,
        ops_needed: ops_needed(scene.screen, &scene.objects),
        ops_without_reuse: scene.objects.len() as u64,
        entries,
        slots: lists.iter().map(|l| l.len().max(1) as u64).sum(),
        max_list: lists.iter().map(|l| l.len() as u64).max().unwrap_or(0),
        pixels_listed: lists.iter().filter(|l| !l.is_empty()).count() as u64,
        pixels_with_partial: lists.iter().filter(|l| l.iter().any(|e| !e.full)).count() as u64,
        subpixels_covered: covered.iter().map(|&c| c as u64).sum(),
    }
}

/// Render a frame of `mesh` through the algorithmic PROOF model.
pub fn render_proof(mesh: &Mesh, opts: &RenderOptions, area: FilterArea) -> Result<ProofFrame, String> {
    let scene = scene_setup(mesh, opts)?;
    Ok(render_scene(&scene, area))
}

/// Render a set-up scene.
pub fn render_scene(scene: &ProofScene, area: FilterArea) -> ProofFrame {
    let lists = object_lists(scene.screen, &scene.objects);
    let (rgb, covered) = shade_and_filter(scene, &lists, area);
    let stats = list_stats(scene, &lists, &covered);
    ProofFrame { screen: scene.screen, rgb, covered, lists, stats }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::Screen;
    use crate::proof::setup::scene_setup;
    use crate::render::RenderOptions;
    use crate::scene::{builtin, Material, Mesh, Triangle, Winding};
    use crate::shade::Shading;

    /// A fan of `n` thin triangles around the screen's middle: the case whose bounding boxes are
    /// mostly empty (issue 18: a 3 000-gon took 47 s when every box pixel was tested).
    fn fan(n: usize) -> Mesh {
        let mut positions = vec![[0.0, 0.0, 0.0]];
        for k in 0..n {
            let a = k as f64 * std::f64::consts::TAU / n as f64;
            positions.push([a.cos(), a.sin(), 0.0]);
        }
        let triangles = (0..n).map(|k| Triangle { v: [0, 1 + k as u32, 1 + ((k + 1) % n) as u32], n: [0; 3], material: 0 }).collect();
        Mesh { name: "fan".into(), positions, normals: vec![[0.0, 0.0, 1.0]], materials: vec![Material::plastic([0.7, 0.7, 0.7])], triangles, front_face: Winding::Ccw, texcoords: Vec::new(), triangle_texcoords: Vec::new(), view: None }
    }

    /// Every pixel of a box outside an object's row span has no entry, so the lists built from the
    /// spans equal those built from every box pixel: on every built-in scene and on a fan.
    #[test]
    fn row_spans_leave_out_only_pixels_without_an_entry() {
        let screen = Screen::new(160, 100).unwrap();
        let mut meshes: Vec<Mesh> = builtin::SCENES.iter().map(|n| builtin::scene(n).unwrap()).collect();
        meshes.push(fan(300));
        for mesh in &meshes {
            let opts = RenderOptions::for_scene(mesh, screen, Shading::Gouraud);
            let scene = scene_setup(mesh, &opts).unwrap();
            let (mut inside, mut skipped) = (0u64, 0u64);
            for o in &scene.objects {
                for y in o.y0..=o.y1 {
                    let span = o.row_span(y);
                    for x in o.x0..=o.x1 {
                        let in_span = span.is_some_and(|(a, b)| x >= a && x <= b);
                        if in_span {
                            inside += 1;
                        } else {
                            skipped += 1;
                            assert!(o.entry_at(x, y).is_none(), "{}: object {} has an entry at ({x}, {y}) outside its row span {span:?}", mesh.name, o.id);
                        }
                    }
                }
            }
            eprintln!("{}: {inside} box pixels tested, {skipped} skipped", mesh.name);
        }
    }

    #[test]
    fn a_fan_of_3000_triangles_builds_its_lists_quickly() {
        let screen = Screen::new(320, 200).unwrap();
        let mesh = fan(3000);
        let opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
        let scene = scene_setup(&mesh, &opts).unwrap();
        let t0 = std::time::Instant::now();
        let lists = object_lists(scene.screen, &scene.objects);
        assert!(lists.iter().any(|l| !l.is_empty()));
        eprintln!("3000-triangle fan at 320x200: lists in {:.2} s", t0.elapsed().as_secs_f64());
    }
}
