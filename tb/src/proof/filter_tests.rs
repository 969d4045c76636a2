//! Tests of PROOF's filter stage (run with `cargo test --release -p tb proof::filter`).

use super::filter_bench::{filter_ports, run_filter, FilterRun};
use super::shade_bench::StageGaps;
use super::stage_tests::{scene, synth_without_latches};
use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted, Rng};
use golden::proof::cycle_filter::{filter_config, filter_config_alpha, scene_filter_config, shaded_slots};
use golden::proof::cycle_shade::{CfgWrite, ShadedSlot};
use golden::proof::filter::{blend_subpixels, combine, combine_blended, visible_masks, FilterArea};
use golden::proof::format::{Entry, ALPHA_ONE};
use golden::proof::render::{dirs_of, filter_lists, object_lists};
use golden::proof::setup::ProofScene;
use golden::proof::shade::shade_entry;

/// Run the filter bench; on a failure rerun it with a waveform and panic with the report.
fn filter_or_panic(name: &str, seed: u64, bits: usize, cfg: &[CfgWrite], slots: &[ShadedSlot], gaps: StageGaps) -> FilterRun {
    let vcd = if vcd_wanted() { Some(vcd_path("proof", name)) } else { None };
    match run_filter(bits, cfg, slots, Some(gaps), vcd.as_deref(), None) {
        Ok(r) => r,
        Err(e) => {
            let p = vcd_path("proof", name);
            let _ = run_filter(bits, cfg, slots, Some(gaps), Some(&p), None);
            panic!("{name} (seed {seed}, SEED=n replays): {e}; waveform {}", p.display());
        }
    }
}

/// A scene's lists shaded by the golden shading: the filter's input slots, and the golden filter's
/// image (filter area `area`) and coverage.
pub(super) fn scene_slots(sc: &ProofScene, area: FilterArea) -> (Vec<ShadedSlot>, Vec<u8>, Vec<u8>) {
    let lists = object_lists(sc.screen, &sc.objects);
    let colours: Vec<Vec<[u8; 3]>> =
        lists.iter().map(|l| l.iter().map(|e| shade_entry(&sc.lights, e.normal, sc.material[e.id as usize])).collect()).collect();
    let (rgb, cov) = filter_lists(sc, &lists, &colours, area);
    (shaded_slots(sc.screen.width, &lists, &colours), rgb, cov)
}

pub(super) fn scene_dirs(sc: &ProofScene) -> Vec<[(i16, i16); 3]> {
    (0..sc.objects.len()).map(|i| dirs_of(sc, i as u16)).collect()
}

/// A scene's filter configuration: directions, opacities and background.
pub(super) fn scene_cfg(sc: &ProofScene, bits: u32) -> Vec<CfgWrite> {
    scene_filter_config(sc, bits).unwrap()
}

/// `glass` (panes of several opacities over each other) or the teapot with every material at
/// opacity 0.5, set up as the CLI does.
pub(super) fn transparent_scene(name: &str, w: u32, h: u32) -> ProofScene {
    let mut mesh = if name == "teapot" { golden::scene::builtin::teapot(2) } else { golden::scene::builtin::scene(name).unwrap() };
    if name == "teapot" {
        for m in mesh.materials.iter_mut() {
            m.opacity = 0.5;
        }
    }
    let opts = golden::proof::study::cli_options(&mesh, w, h);
    let sc = golden::proof::setup::scene_setup(&mesh, &opts).unwrap();
    assert!(sc.objects.iter().any(|o| o.alpha < ALPHA_ONE), "{name}: should have transparent objects");
    sc
}

/// Pixels of `sc` whose list holds two transparent entries or more (the stimulus must have many).
pub(super) fn layered_pixels(sc: &ProofScene) -> usize {
    let lists = object_lists(sc.screen, &sc.objects);
    lists.iter().filter(|l| l.iter().filter(|e| sc.objects[e.id as usize].alpha < ALPHA_ONE).count() >= 2).count()
}

pub(super) fn check_image(what: &str, w: u32, run: &FilterRun, rgb: &[u8], cov: &[u8]) {
    assert_eq!(run.pixels.len(), cov.len(), "{what}: pixel count");
    for (p, o) in run.pixels.iter().enumerate() {
        let (x, y) = ((p as u32 % w) as u16, (p as u32 / w) as u16);
        assert_eq!((o.x, o.y), (x, y), "{what}: pixel order");
        assert_eq!((o.rgb.to_vec(), o.covered), (rgb[3 * p..3 * p + 3].to_vec(), cov[p]), "{what}: pixel ({x}, {y}) vs the golden filter");
    }
}

#[test]
fn filter_stage_matches_its_cycle_model_every_cycle_and_the_golden_filter_on_polyhedron_and_teapot_lists_with_random_gaps() {
    let mut rng = Rng::new(0xf11_7e5);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    for (name, grid, w, h) in [("polyhedron", 0, 40, 25), ("teapot", 2, 40, 25)] {
        let sc = scene(name, grid, w, h);
        let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box1);
        let cfg = filter_config(&scene_dirs(&sc), sc.background, 10).unwrap();
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 20, sink_gap_percent: 30 };
        let t0 = std::time::Instant::now();
        let run = filter_or_panic("filter_every_cycle", seed, 10, &cfg, &slots, gaps);
        let partial = cov.iter().filter(|&&c| c > 0 && c < 64).count();
        println!("{name} {w}x{h}: {} slots, {} pixels ({partial} partially covered), {} cycles in {:?}", slots.len(), run.pixels.len(), run.cycles, t0.elapsed());
        assert!(partial > 20, "{name}: the stimulus should anti-alias edges");
        check_image(name, w, &run, &rgb, &cov);
    }
}

/// Transparent objects: `glass` and the teapot at opacity 0.5 through the RTL with random gaps, every
/// cycle against the model (the 64 subpixel weights and transmittances included), the pixels against
/// the golden blend; the same lists taken as opaque give other pixels (the blend is exercised).
#[test]
fn filter_stage_blends_glass_and_a_half_transparent_teapot_as_its_model_and_the_golden_filter_with_random_gaps() {
    let mut rng = Rng::new(0x61a55);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    for (name, w, h) in [("glass", 40, 25), ("teapot", 40, 25)] {
        let sc = transparent_scene(name, w, h);
        let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box1);
        let layered = layered_pixels(&sc);
        assert!(layered > 20, "{name}: pixels with two transparent entries or more: {layered}");
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 20, sink_gap_percent: 30 };
        let run = filter_or_panic("filter_blend_every_cycle", seed, 11, &scene_cfg(&sc, 11), &slots, gaps);
        println!("{name} {w}x{h}: {} slots, {} pixels, {layered} with two transparent entries or more, {} cycles", slots.len(), run.pixels.len(), run.cycles);
        check_image(name, w, &run, &rgb, &cov);
        let opaque = filter_or_panic("filter_blend_as_opaque", seed, 11, &filter_config(&scene_dirs(&sc), sc.background, 11).unwrap(), &slots, gaps);
        assert!(opaque.pixels.iter().zip(&run.pixels).any(|(a, b)| a.rgb != b.rgb), "{name}: opacities should change the picture");
    }
}

/// The configuration writes are not a stall: a table load longer than the watchdog's limit (two
/// writes per object since the opacity table, so 5876 objects, the teapot's, already exceed it) is
/// followed by the frame. Failed before the watchdog counted from the first slot: "no progress for
/// 10000 cycles in the filter stage (0 of 1 pixels out ...)".
#[test]
fn a_filter_table_load_longer_than_the_watchdog_limit_is_not_a_stall() {
    let n = super::bench::PROGRESS_LIMIT as usize / 2 + 100;
    let dirs = vec![[(16384i16, 0i16); 3]; n];
    let cfg = filter_config(&dirs, [1, 2, 3], 14).unwrap();
    assert!(cfg.len() as u64 > super::bench::PROGRESS_LIMIT);
    let slots = vec![ShadedSlot { x: 0, y: 0, last: true, has_entry: true, id: (n - 1) as u16, full: true, rgb: [200, 100, 50], ..Default::default() }];
    let run = run_filter(14, &cfg, &slots, None, None, None).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(run.pixels.len(), 1);
    assert_eq!(run.pixels[0].rgb, [200, 100, 50]);
}

/// A random frame for the filter benches: per pixel a list of up to 4 entries with distances and
/// directions over the whole 16-bit range (saturated distances, non-unit directions), full entries,
/// empty pixels, random colours, on a random background; every pixel of the screen's border too.
pub(super) struct RandomLists {
    pub dirs: Vec<[(i16, i16); 3]>,
    /// Per object, its opacity (Q1.4): all 16 (opaque) unless asked for transparency.
    pub alphas: Vec<u16>,
    /// Per pixel (raster order): the list and its colours.
    pub lists: Vec<(Vec<Entry>, Vec<[u8; 3]>)>,
    pub bg: [u8; 3],
    pub slots: Vec<ShadedSlot>,
    /// Per pixel (raster order): the entries' owned subpixel masks and colours, and the union.
    pub owners: Vec<(Vec<u64>, Vec<[u8; 3]>, u64)>,
}

impl RandomLists {
    /// Per pixel (raster order): the golden blend's 64 composited subpixels and the covered mask.
    pub fn blended(&self) -> Vec<([[u32; 3]; 64], u64)> {
        let dirs = |id: u16| self.dirs[id as usize];
        let alpha = |id: u16| self.alphas[id as usize];
        self.lists.iter().map(|(l, c)| blend_subpixels(l, &dirs, &alpha, c, self.bg)).collect()
    }
}

pub(super) fn random_lists(rng: &mut Rng, w: u32, h: u32, transparent: bool) -> RandomLists {
    let extremes = [i16::MIN, i16::MAX, 0, 16384, -16384, 11585, -11585, 1, -1];
    let r16 = |rng: &mut Rng| if rng.chance(15) { extremes[rng.below(extremes.len() as u64) as usize] } else { rng.next_u64() as u16 as i16 };
    let n_obj = 50usize;
    let dirs: Vec<[(i16, i16); 3]> = (0..n_obj).map(|_| [0; 3].map(|_: i32| (r16(rng), r16(rng)))).collect();
    // With transparency: a third opaque, the rest any opacity 0..=15 (0 and 15 often).
    let alphas: Vec<u16> = (0..n_obj)
        .map(|_| match (transparent, rng.below(6)) {
            (false, _) | (true, 0 | 1) => ALPHA_ONE,
            (true, 2) => 0,
            (true, 3) => ALPHA_ONE - 1,
            _ => rng.below(ALPHA_ONE as u64) as u16,
        })
        .collect();
    let bg = [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8];
    let mut slots = Vec::new();
    let mut owners = Vec::new();
    let mut lists = Vec::new();
    for p in 0..w * h {
        let (x, y) = ((p % w) as u16, (p / w) as u16);
        let n = rng.below(5) as usize;
        let list: Vec<Entry> = (0..n)
            .map(|_| {
                // Mostly small distances (edges through the pixel), sometimes anything.
                let d = |rng: &mut Rng| if rng.chance(60) { (rng.below(40000) as i64 - 20000) as i16 } else { r16(rng) };
                Entry { id: rng.below(n_obj as u64) as u16, full: rng.chance(15), dist: [d(rng), d(rng), d(rng)], ..Default::default() }
            })
            .collect();
        let colours: Vec<[u8; 3]> = list.iter().map(|_| [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8]).collect();
        let (own, taken) = visible_masks(&list, &|id| dirs[id as usize]);
        slots.extend(shaded_slots(1, &[list.clone()], &[colours.clone()]).into_iter().map(|s| ShadedSlot { x, y, ..s }));
        owners.push((own, colours.clone(), taken));
        lists.push((list, colours));
    }
    RandomLists { dirs, alphas, lists, bg, slots, owners }
}

/// Random lists (see [`random_lists`]): the RTL against the model every cycle, the pixels against the
/// golden masks and combination.
#[test]
fn filter_stage_on_random_lists_with_extreme_distances_and_directions_matches_its_model_and_the_golden_filter() {
    let mut rng = Rng::new(0xed9e);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let (w, h) = (24u32, 12u32);
    let r = random_lists(&mut rng, w, h, false);
    let rgb: Vec<u8> = r.owners.iter().flat_map(|(o, c, t)| combine(o, c, *t, r.bg)).collect();
    let cov: Vec<u8> = r.owners.iter().map(|(_, _, t)| t.count_ones() as u8).collect();
    let cfg = filter_config(&r.dirs, r.bg, 6).unwrap();
    let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
    let run = filter_or_panic("filter_random_lists_every_cycle", seed, 6, &cfg, &r.slots, gaps);
    check_image("random lists", w, &run, &rgb, &cov);
    let partial = cov.iter().filter(|&&c| c > 0 && c < 64).count();
    let multi_owner = run.pixels.len();
    assert!(partial > 50 && cov.contains(&64) && cov.contains(&0), "the stimulus should give partial, full and empty pixels ({partial} partial of {multi_owner})");
}

/// Random lists with random opacities (0, 15/16 and 1 often): the RTL against the model every cycle,
/// the pixels against the golden blend.
#[test]
fn filter_stage_on_random_lists_with_random_opacities_matches_its_model_and_the_golden_blend() {
    let mut rng = Rng::new(0xa1fa);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let (w, h) = (24u32, 12u32);
    let r = random_lists(&mut rng, w, h, true);
    let blended = r.blended();
    let rgb: Vec<u8> = blended.iter().flat_map(|(acc, _)| combine_blended(acc)).collect();
    let cov: Vec<u8> = blended.iter().map(|(_, taken)| taken.count_ones() as u8).collect();
    let cfg = filter_config_alpha(&r.dirs, &r.alphas, r.bg, 6).unwrap();
    let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
    let run = filter_or_panic("filter_random_opacities_every_cycle", seed, 6, &cfg, &r.slots, gaps);
    check_image("random lists, random opacities", w, &run, &rgb, &cov);
}

#[test]
fn filter_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches() {
    if !require_tools("filter_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches", &["iverilog", "verilator", "yosys"]) {
        return;
    }
    // The teapot at opacity 0.5: transparent entries over each other and over opaque ones' edges.
    let sc = transparent_scene("teapot", 24, 16);
    let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box1);
    let cfg = scene_cfg(&sc, 8);
    let dir = scratch_dir("proof_filter_replay");
    let gaps = StageGaps { seed: 78, source_gap_percent: 25, sink_gap_percent: 25 };
    let run = run_filter(8, &cfg, &slots, Some(gaps), None, Some(dir.join("filter_vectors.txt"))).unwrap();
    check_image("replay stimulus", 24, &run, &rgb, &cov);
    let (vp, cycles) = run.vectors.clone().unwrap();
    let v = hdl::proof::verilog_filter("proof_filter8", 8).unwrap();
    for sim in ["iverilog", "verilator"] {
        let d = scratch_dir(&format!("proof_filter_replay_{sim}"));
        let verdict = super::replay::replay(sim, &d, "proof_filter8", &filter_ports(), &v, &vp, cycles).unwrap_or_else(|e| panic!("{sim}: {e}"));
        println!("{sim}: {verdict}");
        assert!(verdict.contains(&cycles.to_string()));
    }
    // Lint the top that `idxrender verilog --block proof_filter` writes.
    lint_clean(&dir, "proof_filter", &hdl::verilog_top("proof_filter").unwrap());
    synth_without_latches(&dir, "proof_filter8", &v);
}

/// `verilator --lint-only -Wall` of a filter top, clean with the project's waivers (`crate::lint`).
pub(super) fn lint_clean(dir: &std::path::Path, top: &str, v: &str) {
    crate::lint::lint(v, top, dir).unwrap_or_else(|e| panic!("{e}"));
}
