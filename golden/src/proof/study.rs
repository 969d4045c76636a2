//! PROOF's figures: the OPs and cycles each built-in scene needs, and the FIFO-depth study (seed 002
//! §4.3: "a FIFO that can store the description of only one object is sufficient; increasing the
//! length of the FIFO will result in performance gains less than 2 %"), with the camera and options
//! that `idxrender render --arch proof` uses by default. Run by `cargo run --release -p tb --bin
//! proof_figures -- fifo` (see docs/proof.md).

use super::cycle_opp::{run_opp, OppRun};
use super::render::{object_lists, ops_needed};
use super::setup::scene_setup;
use crate::format::Screen;
use crate::render::RenderOptions;
use crate::scene::Mesh;
use crate::shade::Shading;

/// The options of `idxrender render --arch proof --scene S --size WxH` with no other flag: the
/// default view framed for the screen's aspect ratio, Gouraud normals, back-face culling, the mesh's
/// own front face, the default lighting and background. `tests/proof_cli.rs` checks that the CLI
/// reports the same figures.
pub fn cli_options(mesh: &Mesh, w: u32, h: u32) -> RenderOptions {
    RenderOptions::for_scene(mesh, Screen::new(w, h).expect("study screen size"), Shading::Gouraud)
}

/// The default view's direction (0.3, 0.45, 1) turned about the vertical axis by `turn_deg` (0: the
/// default view; the elevation, about 23 degrees, is kept).
pub fn turned_view(turn_deg: f64) -> [f64; 3] {
    let (x, z) = (0.3f64, 1.0f64);
    let (s, c) = turn_deg.to_radians().sin_cos();
    [x * c + z * s, 0.45, -x * s + z * c]
}

/// The options of [`cli_options`] with the camera framing the mesh from `direction` instead (40
/// degrees, the screen's aspect ratio, as the default view).
pub fn view_options(mesh: &Mesh, w: u32, h: u32, direction: [f64; 3]) -> RenderOptions {
    let mut o = cli_options(mesh, w, h);
    o.camera = crate::host::Camera::framing_aspect(mesh, direction, 40.0, w as f64 / h as f64);
    o
}

/// One scene's row of the FIFO table.
#[derive(Clone, Debug, serde::Serialize)]
pub struct FifoRow {
    pub scene: String,
    pub objects: usize,
    pub ops_needed: usize,
    /// Runs of the OPP cycle model, one per depth, with exactly `ops_needed` OPs and no gaps.
    pub runs: Vec<OppRun>,
}

impl FifoRow {
    /// Cycle gain from the first to the last depth, in percent of the first.
    pub fn gain_percent(&self) -> f64 {
        let (a, b) = (self.runs[0].cycles as f64, self.runs[self.runs.len() - 1].cycles as f64);
        100.0 * (a - b) / a
    }
}

/// Run `mesh` at `w`x`h` through the OPP cycle model for each FIFO depth; each run's lists are checked
/// against the algorithmic model.
pub fn fifo_row(name: &str, mesh: &Mesh, w: u32, h: u32, depths: &[usize]) -> Result<FifoRow, String> {
    fifo_row_with(name, mesh, &cli_options(mesh, w, h), depths)
}

/// [`fifo_row`] with any options (another view: [`view_options`]).
pub fn fifo_row_with(name: &str, mesh: &Mesh, opts: &RenderOptions, depths: &[usize]) -> Result<FifoRow, String> {
    let sc = scene_setup(mesh, opts)?;
    let need = (ops_needed(sc.screen, &sc.objects) as usize).max(1);
    let lists = object_lists(sc.screen, &sc.objects);
    let mut runs = Vec::new();
    for &d in depths {
        let r = run_opp(sc.screen, &sc.objects, need, d, None)?;
        if r.lists != lists {
            return Err(format!("{name} depth {d}: the OPP cycle model's lists differ from the algorithmic lists"));
        }
        runs.push(r);
    }
    Ok(FifoRow { scene: name.to_string(), objects: sc.objects.len(), ops_needed: need, runs })
}

/// One scene's row of the real-time study (seed 002's claim of 30 frames per second at 512x512):
/// the OPP cycle model with each number of physical OPs, fewer than needed taking passes.
#[derive(Clone, Debug, serde::Serialize)]
pub struct RealtimeRow {
    pub scene: String,
    pub objects: usize,
    pub ops_needed: usize,
    /// One run per OP count (FIFO depth 1, no gaps), the lists checked against the algorithmic model.
    pub runs: Vec<OppRun>,
}

/// Run `mesh` at `w`x`h` through the OPP cycle model with each of `ops` physical OPs (counts above
/// the scene's need are clamped to it: more OPs than objects alive on a line are never used).
pub fn realtime_row(name: &str, mesh: &Mesh, w: u32, h: u32, ops: &[usize]) -> Result<RealtimeRow, String> {
    let sc = scene_setup(mesh, &cli_options(mesh, w, h))?;
    let need = (ops_needed(sc.screen, &sc.objects) as usize).max(1);
    let lists = object_lists(sc.screen, &sc.objects);
    let mut counts: Vec<usize> = ops.iter().map(|&n| n.clamp(1, need)).collect();
    counts.push(need);
    counts.sort();
    counts.dedup();
    let mut runs = Vec::new();
    for n in counts {
        let r = run_opp(sc.screen, &sc.objects, n, 1, None)?;
        if r.lists != lists {
            return Err(format!("{name} with {n} OPs: the OPP cycle model's lists differ from the algorithmic lists"));
        }
        runs.push(r);
    }
    Ok(RealtimeRow { scene: name.to_string(), objects: sc.objects.len(), ops_needed: need, runs })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin;

    #[test]
    fn a_turn_of_zero_is_the_default_view_and_turns_keep_the_elevation() {
        assert_eq!(turned_view(0.0), [0.3, 0.45, 1.0]);
        let mesh = builtin::teapot(2);
        assert_eq!(format!("{:?}", view_options(&mesh, 64, 40, turned_view(0.0))), format!("{:?}", cli_options(&mesh, 64, 40)));
        for t in [45.0, 90.0, 180.0, 315.0] {
            let d = turned_view(t);
            let horizontal = (d[0] * d[0] + d[2] * d[2]).sqrt();
            assert!((horizontal - (0.09f64 + 1.0).sqrt()).abs() < 1e-12 && d[1] == 0.45, "{t}: {d:?}");
        }
        let d = turned_view(180.0);
        assert!((d[0] + 0.3).abs() < 1e-12 && (d[2] + 1.0).abs() < 1e-12, "half a turn looks from behind: {d:?}");
    }

    #[test]
    fn deeper_fifos_never_change_the_lists_and_one_slot_keeps_one_pixel_per_clock_on_a_small_frame() {
        let mesh = builtin::teapot(2);
        let row = fifo_row("teapot", &mesh, 64, 40, &[1, 2, 8]).unwrap();
        assert!(row.ops_needed > 5 && row.ops_needed < row.objects, "{row:?}");
        for r in &row.runs {
            // At least one cycle per output slot; the lists were checked in fifo_row.
            assert!(r.cycles >= r.slots_out && r.slots_out >= 64 * 40, "{r:?}");
        }
    }
}
