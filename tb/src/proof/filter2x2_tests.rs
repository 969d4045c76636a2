//! Tests of PROOF's filter stage with the 2x2 area and of its box (run with
//! `cargo test --release -p tb proof::filter2x2`).

use super::filter2x2_bench::{box_ports, run_box, run_filter2x2};
use super::filter_bench::{filter_ports, FilterRun};
use super::filter_tests::{check_image, layered_pixels, lint_clean, random_lists, scene_cfg, scene_dirs, scene_slots, transparent_scene};
use super::shade_bench::StageGaps;
use super::stage_tests::{scene, synth_without_latches};
use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted, Rng};
use golden::proof::cycle_filter::{filter_config, filter_config_alpha, FilteredPixel};
use golden::proof::cycle_filter2x2::{box2_of_quads, random_quads, QuadPixel};
use golden::proof::cycle_opp::GapRng;
use golden::proof::cycle_shade::{CfgWrite, ShadedSlot};
use golden::proof::filter::{box2, quadrant_sums, quadrant_sums_blended, FilterArea};

/// Run the 2x2 stage bench; on a failure rerun it with a waveform and panic with the report.
#[allow(clippy::too_many_arguments)]
fn filter2x2_or_panic(name: &str, seed: u64, bits: usize, w: u32, h: u32, cfg: &[CfgWrite], slots: &[ShadedSlot], gaps: StageGaps) -> FilterRun {
    let vcd = if vcd_wanted() { Some(vcd_path("proof", name)) } else { None };
    match run_filter2x2(bits, w, h, cfg, slots, Some(gaps), vcd.as_deref(), None) {
        Ok(r) => r,
        Err(e) => {
            let p = vcd_path("proof", name);
            let _ = run_filter2x2(bits, w, h, cfg, slots, Some(gaps), Some(&p), None);
            panic!("{name} (seed {seed}, SEED=n replays): {e}; waveform {}", p.display());
        }
    }
}

/// The same for the box alone.
fn box_or_panic(name: &str, seed: u64, w: u32, h: u32, bg: [u8; 3], frames: &[Vec<QuadPixel>], gaps: StageGaps) -> Vec<Vec<FilteredPixel>> {
    let vcd = if vcd_wanted() { Some(vcd_path("proof", name)) } else { None };
    match run_box(w, h, bg, frames, gaps, vcd.as_deref(), None) {
        Ok(r) => r.0,
        Err(e) => {
            let p = vcd_path("proof", name);
            let _ = run_box(w, h, bg, frames, gaps, Some(&p), None);
            panic!("{name} {w}x{h} (seed {seed}, SEED=n replays): {e}; waveform {}", p.display());
        }
    }
}

fn check_box_frame(what: &str, w: u32, got: &[FilteredPixel], quads: &[QuadPixel], want: &[u8]) {
    assert_eq!(got.len(), quads.len(), "{what}: pixel count");
    for (p, o) in got.iter().enumerate() {
        let (x, y) = ((p as u32 % w) as u16, (p as u32 / w) as u16);
        assert_eq!((o.x, o.y), (x, y), "{what}: pixel order");
        let own: u32 = quads[p].cov.iter().map(|&c| c as u32).sum();
        assert_eq!((o.rgb.to_vec(), o.covered as u32), (want[3 * p..3 * p + 3].to_vec(), own), "{what}: pixel ({x}, {y}) vs the golden 2x2 box");
    }
}

#[test]
fn filter2x2_stage_matches_its_cycle_model_every_cycle_and_the_golden_2x2_filter_on_polyhedron_and_teapot_lists_with_random_gaps() {
    let mut rng = Rng::new(0x2b0c5);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    for (name, grid, w, h) in [("polyhedron", 0, 40, 25), ("teapot", 2, 40, 25)] {
        let sc = scene(name, grid, w, h);
        let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box2);
        let (_, rgb1, _) = scene_slots(&sc, FilterArea::Box1);
        // A 1x1 filter must not pass this test.
        let differ = (0..rgb.len()).filter(|&i| rgb[i] != rgb1[i]).count();
        assert!(differ > 100, "{name}: the 2x2 and 1x1 images should differ ({differ} bytes do)");
        let cfg = filter_config(&scene_dirs(&sc), sc.background, 10).unwrap();
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 20, sink_gap_percent: 30 };
        let t0 = std::time::Instant::now();
        let run = filter2x2_or_panic("filter2x2_every_cycle", seed, 10, w, h, &cfg, &slots, gaps);
        println!("{name} {w}x{h}: {} slots, {} pixels, {} cycles in {:?}", slots.len(), run.pixels.len(), run.cycles, t0.elapsed());
        check_image(name, w, &run, &rgb, &cov);
    }
}

/// The whole 2x2 stage on random lists (the 1x1 bench's stimulus: extreme distances and directions,
/// full entries, empty pixels) on every pixel, the screen's border included, which the scenes above
/// leave empty: the RTL against the model every cycle, the pixels against golden `quadrant_sums` and
/// `box2`.
#[test]
fn filter2x2_stage_on_random_lists_with_entries_on_the_screen_border_matches_its_model_and_the_golden_2x2_filter() {
    let mut rng = Rng::new(0x2ed9e);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let (w, h) = (24u32, 12u32);
    let r = random_lists(&mut rng, w, h, false);
    let quads: Vec<[[u32; 3]; 4]> = r.owners.iter().map(|(o, c, t)| quadrant_sums(o, c, *t, r.bg)).collect();
    let rgb = box2(w, h, &quads);
    let cov: Vec<u8> = r.owners.iter().map(|(_, _, t)| t.count_ones() as u8).collect();
    let cfg = filter_config(&r.dirs, r.bg, 6).unwrap();
    let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
    let run = filter2x2_or_panic("filter2x2_random_lists_every_cycle", seed, 6, w, h, &cfg, &r.slots, gaps);
    check_image("random lists, 2x2", w, &run, &rgb, &cov);
    let border_covered = (0..w * h).filter(|&p| (p % w == 0 || p % w == w - 1 || p / w == 0 || p / w == h - 1) && cov[p as usize] > 0).count();
    assert!(border_covered > 20, "the stimulus should cover the border ({border_covered} border pixels covered)");
}

/// Transparency through the 2x2 area: `glass` and the teapot at opacity 0.5, the RTL against the model
/// in every cycle (the 13-bit quadrant weights, the 20-bit pixel sums and the background's share in
/// the word included), the pixels against the golden blended 2x2 filter; the same lists taken as
/// opaque give other pixels (the blend is exercised).
#[test]
fn filter2x2_stage_blends_glass_and_a_half_transparent_teapot_as_its_model_and_the_golden_2x2_filter_with_random_gaps() {
    let mut rng = Rng::new(0x2a1fa);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    for (name, w, h) in [("glass", 40, 25), ("teapot", 40, 25)] {
        let sc = transparent_scene(name, w, h);
        let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box2);
        let layered = layered_pixels(&sc);
        assert!(layered > 20, "{name}: pixels with two transparent entries or more: {layered}");
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 20, sink_gap_percent: 30 };
        let run = filter2x2_or_panic("filter2x2_blend_every_cycle", seed, 11, w, h, &scene_cfg(&sc, 11), &slots, gaps);
        println!("{name} {w}x{h}: {} slots, {} pixels, {layered} with two transparent entries or more, {} cycles", slots.len(), run.pixels.len(), run.cycles);
        check_image(name, w, &run, &rgb, &cov);
        let opaque = filter2x2_or_panic("filter2x2_blend_as_opaque", seed, 11, w, h, &filter_config(&scene_dirs(&sc), sc.background, 11).unwrap(), &slots, gaps);
        assert!(opaque.pixels.iter().zip(&run.pixels).any(|(a, b)| a.rgb != b.rgb), "{name}: opacities should change the picture");
    }
}

/// Random lists with random opacities (0 and 15/16 often) on every pixel, the border included: the
/// RTL against the model every cycle, the pixels against golden `blend_subpixels`,
/// `quadrant_sums_blended` and `box2`.
#[test]
fn filter2x2_stage_on_random_lists_with_random_opacities_matches_its_model_and_the_golden_blend() {
    let mut rng = Rng::new(0x2a1fb);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let (w, h) = (24u32, 12u32);
    let r = random_lists(&mut rng, w, h, true);
    let blended = r.blended();
    let quads: Vec<[[u32; 3]; 4]> = blended.iter().map(|(acc, _)| quadrant_sums_blended(acc)).collect();
    let cov: Vec<u8> = blended.iter().map(|(_, taken)| taken.count_ones() as u8).collect();
    let rgb = box2(w, h, &quads);
    let cfg = filter_config_alpha(&r.dirs, &r.alphas, r.bg, 6).unwrap();
    let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
    let run = filter2x2_or_panic("filter2x2_random_opacities_every_cycle", seed, 6, w, h, &cfg, &r.slots, gaps);
    check_image("random lists, random opacities, 2x2", w, &run, &rgb, &cov);
}

/// The box alone on random quadrant sums with the extremes (empty and fully covered quadrants, 255 per
/// covered subpixel, black and white backgrounds), on screens down to 2x1 where every pixel is at an
/// edge, two frames back to back so that the flush must leave the box ready for the next frame.
#[test]
fn the_2x2_box_matches_its_model_every_cycle_and_the_golden_box_on_extreme_quadrant_sums_of_small_screens() {
    let mut rng = Rng::new(0xb0c52);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let mut gap = GapRng(rng.next_u64());
    for (n, (w, h)) in [(2, 1), (2, 2), (3, 1), (2, 5), (5, 3), (8, 4), (13, 2), (4, 9)].into_iter().enumerate() {
        let bg = match n % 3 {
            0 => [255, 255, 255],
            1 => [0, 0, 0],
            _ => [rng.below(256) as u8, rng.below(256) as u8, rng.below(256) as u8],
        };
        let frames: Vec<Vec<QuadPixel>> = (0..2).map(|_| random_quads(w, h, &mut gap)).collect();
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
        let got = box_or_panic("box2x2_every_cycle", seed, w, h, bg, &frames, gaps);
        for (f, quads) in frames.iter().enumerate() {
            check_box_frame(&format!("{w}x{h} frame {f}"), w, &got[f], quads, &box2_of_quads(w, h, quads, bg));
        }
    }
}

#[test]
fn filter2x2_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches() {
    if !require_tools("filter2x2_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches", &["iverilog", "verilator", "yosys"]) {
        return;
    }
    let dir = scratch_dir("proof_filter2x2_replay");
    // The whole stage on a real frame with transparency (the teapot at opacity 0.5).
    let (w, h) = (24, 16);
    let sc = transparent_scene("teapot", w, h);
    let (slots, rgb, cov) = scene_slots(&sc, FilterArea::Box2);
    let cfg = scene_cfg(&sc, 8);
    let gaps = StageGaps { seed: 79, source_gap_percent: 25, sink_gap_percent: 25 };
    let run = run_filter2x2(8, w, h, &cfg, &slots, Some(gaps), None, Some(dir.join("filter2x2_vectors.txt"))).unwrap();
    check_image("replay stimulus", w, &run, &rgb, &cov);
    let (vp, cycles) = run.vectors.clone().unwrap();
    let v = hdl::proof::verilog_filter2x2("proof_filter2x2_8", 8, w, h).unwrap();
    // The box alone on extreme sums, two frames (the flush and the next frame's first row).
    let (bw, bh, bg) = (7, 4, [255, 0, 37]);
    let frames: Vec<Vec<QuadPixel>> = {
        let mut g = GapRng(0x5eed);
        (0..2).map(|_| random_quads(bw, bh, &mut g)).collect()
    };
    let bgaps = StageGaps { seed: 80, source_gap_percent: 30, sink_gap_percent: 30 };
    let (bframes, brec) = run_box(bw, bh, bg, &frames, bgaps, None, Some(dir.join("box_vectors.txt"))).unwrap();
    for (f, quads) in frames.iter().enumerate() {
        check_box_frame("box replay stimulus", bw, &bframes[f], quads, &box2_of_quads(bw, bh, quads, bg));
    }
    let (bvp, bcycles) = brec.unwrap();
    let bv = hdl::proof::verilog_box2x2("box2x2_7x4", bw, bh).unwrap();
    for sim in ["iverilog", "verilator"] {
        let d = scratch_dir(&format!("proof_filter2x2_replay_{sim}"));
        let verdict = super::replay::replay(sim, &d, "proof_filter2x2_8", &filter_ports(), &v, &vp, cycles).unwrap_or_else(|e| panic!("{sim}: {e}"));
        println!("{sim} stage: {verdict}");
        assert!(verdict.contains(&cycles.to_string()));
        let d = scratch_dir(&format!("proof_box2x2_replay_{sim}"));
        let verdict = super::replay::replay(sim, &d, "box2x2_7x4", &box_ports(), &bv, &bvp, bcycles).unwrap_or_else(|e| panic!("{sim}: {e}"));
        println!("{sim} box: {verdict}");
        assert!(verdict.contains(&bcycles.to_string()));
    }
    // The top that `idxrender verilog --block proof_filter2x2` writes.
    lint_clean(&dir, "proof_filter2x2", &hdl::verilog_top("proof_filter2x2").unwrap());
    synth_without_latches(&dir, "proof_filter2x2_8", &v);
}

#[test]
fn a_2x2_filter_rtl_narrower_than_two_pixels_is_refused_with_the_reason() {
    let e = hdl::proof::Filter2x2Stage::new(8, 1, 30).err().expect("a 1-pixel-wide 2x2 stage should be refused");
    assert!(e.contains("1x30") && e.contains("width must be 2..=1024"), "{e}");
    assert!(hdl::proof::Box2x2::new(1025, 4).is_err());
}
