//! Tests of colour setup and the Color Shader: RTL vs cycle model every cycle, images and TdbS vs the
//! algorithmic model on real frames, throughput figures, the Verilog replay, lint and synthesis.

use super::color_shader_bench::{self as csb, CsDrive, FrameSpec};
use super::colour_setup_bench::{self as setb, SetupDrive};
use super::frames::record;
use super::replay::{replay_iverilog, synth_ice40};
use super::stimulus::*;
use crate::common::{require_tools, scratch_dir, Rng};
use golden::cycle::color_shader::{phong_config, CS_PIPELINE_CYCLES};
use golden::cycle::colour_setup::{SetupCmd, SETUP_INTERVAL, SETUP_LATENCY};
use golden::format::{Plane, DEPTH_MAX};
use golden::scene::builtin;
use golden::format::CS_MATERIALS;
use golden::shade::Shading;

fn seed_for(test: &str, default: u64) -> u64 {
    let seed = Rng::new(default).seed();
    println!("{test}: seed {seed} (set SEED={seed} to replay)");
    seed
}

// ------------------------------------------------------------------------------------------------
// Colour setup

#[test]
fn colour_setup_matches_its_cycle_model_every_cycle_on_random_commands_with_gaps() {
    let seed = seed_for("colour_setup_random", 0xC0105E7);
    let mut rng = Rng::new(seed);
    let cmds = random_commands(300, &mut rng);
    let run = setb::run_rtl_vs_model("colour_setup_random", &cmds, SetupDrive { gap_percent: 30, seed }, false).unwrap();
    assert_eq!(run.writes.len(), cmds.len());
    for (c, (idx, rec)) in cmds.iter().zip(&run.writes) {
        assert_eq!((*idx, *rec), (c.index, c.record()));
    }
    println!("colour_setup: {} commands, {} cycles, RustHDL {:.0} cycles/s", cmds.len(), run.cycles, run.rtl_cycles_per_second);
}

#[test]
fn colour_setup_writes_the_golden_tdbs_of_every_builtin_scene() {
    let seed = seed_for("colour_setup_scenes", 7);
    for name in builtin::SCENES {
        for shading in [Shading::Gouraud, Shading::Phong, Shading::Flat] {
            let f = record(name, shading, 160, 100).unwrap();
            let cmds: Vec<SetupCmd> = f.chip.setups.iter().map(|c| SetupCmd::from_command(c).unwrap()).collect();
            assert!(!cmds.is_empty(), "{name}: nothing visible");
            let test = format!("colour_setup_{name}_{shading:?}").to_lowercase();
            let run = setb::run_rtl_vs_model(&test, &cmds, SetupDrive { gap_percent: 10, seed }, false).unwrap();
            for (idx, rec) in &run.writes {
                assert_eq!(*rec, f.chip.tdbs[*idx as usize], "{name} {shading:?}: record {idx}");
            }
            assert_eq!(run.writes.len(), cmds.len());
        }
    }
}

#[test]
fn colour_setup_takes_a_triangle_every_4_cycles_and_writes_it_41_cycles_later() {
    assert_eq!((SETUP_INTERVAL, SETUP_LATENCY), (4, 41), "the figures in the test's name");
    let f = record("castle", Shading::Gouraud, 160, 100).unwrap();
    let cmds: Vec<SetupCmd> = f.chip.setups.iter().take(50).map(|c| SetupCmd::from_command(c).unwrap()).collect();
    let flat: Vec<SetupCmd> = cmds.iter().map(|c| SetupCmd { flat: true, flat_rgb: [1, 2, 3], ..*c }).collect();
    for (what, cmds) in [("shaded", &cmds), ("flat", &flat)] {
        let run = setb::run_rtl_vs_model(&format!("colour_setup_throughput_{what}"), cmds, SetupDrive { gap_percent: 0, seed: 1 }, false).unwrap();
        // Commands back to back: taken every SETUP_INTERVAL cycles, the last written SETUP_LATENCY
        // cycles after it was taken; the run ends one cycle after the last write.
        let n = cmds.len() as u64;
        assert_eq!(run.cycles, SETUP_INTERVAL * (n - 1) + SETUP_LATENCY + 1);
        println!(
            "colour setup, {what}: {} cycles for {n} triangles back to back = {:.2} cycles/triangle sustained, latency {SETUP_LATENCY}",
            run.cycles - 1,
            (run.cycles - 1 - SETUP_LATENCY) as f64 / (n - 1) as f64
        );
    }
}

// ------------------------------------------------------------------------------------------------
// Color Shader

#[test]
fn cs_matches_its_cycle_model_every_cycle_under_random_back_pressure() {
    let seed = seed_for("cs_random", 0xC5);
    let mut rng = Rng::new(seed);
    let mut mem = random_memories(&mut rng, 64, 24, 200);
    let frames = [
        FrameSpec { width: 64, height: 24, background: [1, 2, 3], clear_behind: false, phong: false },
        FrameSpec { width: 0, height: 5, background: [0; 3], clear_behind: false, phong: false },
        FrameSpec { width: 1, height: 1, background: [9, 8, 7], clear_behind: false, phong: false },
        FrameSpec { width: 1, height: 17, background: [9, 8, 7], clear_behind: false, phong: false },
        FrameSpec { width: 1025, height: 1, background: [0; 3], clear_behind: false, phong: false },
        FrameSpec { width: 37, height: 3, background: [200, 100, 50], clear_behind: true, phong: false },
        FrameSpec { width: 64, height: 24, background: [5, 5, 5], clear_behind: false, phong: false },
    ];
    let reference = mem.clone();
    let drive = CsDrive { stall_percent: 40, start_while_busy_percent: 20, max_idle: 5, seed };
    let run = csb::run_rtl_vs_model("cs_random", &mut mem, &frames, &[], drive, false).unwrap();
    assert_eq!(run.refused, 2);
    let accepted: Vec<&FrameSpec> = frames.iter().filter(|f| (1..=1024).contains(&f.width) && (1..=1024).contains(&f.height)).collect();
    assert_eq!(run.frames.len(), accepted.len());
    // The first frame against the algorithmic evaluation, pixel by pixel.
    let img = csb::frame_image(&run.frames[0], 64, 24).unwrap();
    for (i, px) in img.chunks(3).enumerate() {
        let idx = reference.ibuf[i];
        let want = golden::cycle::color_shader::pixel_colour(idx, &reference.tdbs[idx as usize], i as u32 % 64, i as u32 / 64, [1, 2, 3]);
        assert_eq!(px, want, "pixel {i}");
    }
    for (f, beats) in accepted.iter().zip(&run.frames) {
        csb::frame_image(beats, f.width, f.height).unwrap();
    }
    // The 37x3 frame cleared the first 111 pixels behind itself: the last frame shows background there.
    let last = csb::frame_image(run.frames.last().unwrap(), 64, 24).unwrap();
    assert!(last[..111 * 3].chunks(3).all(|p| p == [5, 5, 5]));
    assert!(mem.ibuf[..111].iter().all(|&i| i == 0) && mem.ibuf[111..] == reference.ibuf[111..]);
    assert!(mem.zbuf[..111].iter().all(|&z| z == DEPTH_MAX) && mem.zbuf[111..] == reference.zbuf[111..]);
    println!("cs: {} cycles, RustHDL {:.0} cycles/s", run.cycles, run.rtl_cycles_per_second);
}

#[test]
fn cs_scans_out_the_golden_image_of_every_builtin_scene_under_back_pressure() {
    let seed = seed_for("cs_scenes", 11);
    let phong = builtin::SCENES.iter().map(|n| (*n, Shading::Phong));
    for (name, shading) in builtin::SCENES.iter().map(|n| (*n, Shading::Gouraud)).chain([("dolphins", Shading::Flat)]).chain(phong) {
        let f = record(name, shading, 96, 60).unwrap();
        let mut mem = f.memories();
        let is_phong = shading == Shading::Phong;
        let config = if is_phong { phong_config(&f.lights).unwrap() } else { Vec::new() };
        let spec = FrameSpec { width: 96, height: 60, background: f.background, clear_behind: true, phong: is_phong };
        let drive = CsDrive { stall_percent: 30, start_while_busy_percent: 10, max_idle: 0, seed };
        let test = format!("cs_{name}_{shading:?}").to_lowercase();
        let run = csb::run_rtl_vs_model(&test, &mut mem, &[spec], &config, drive, false).unwrap();
        let img = csb::frame_image(&run.frames[0], 96, 60).unwrap();
        assert!(img == f.frame.rgb, "{name} {shading:?}: the RTL's image differs from the golden one");
        assert!(mem.ibuf.iter().all(|&i| i == 0) && mem.zbuf.iter().all(|&z| z == DEPTH_MAX), "{name}: clear-behind");
    }
}

#[test]
fn cs_streams_one_pixel_per_clock_on_a_320x200_frame_in_gouraud_and_in_phong() {
    for shading in [Shading::Gouraud, Shading::Phong] {
        let f = record("teapot", shading, 320, 200).unwrap();
        let mut mem = f.memories();
        let is_phong = shading == Shading::Phong;
        let config = if is_phong { phong_config(&f.lights).unwrap() } else { Vec::new() };
        let spec = FrameSpec { width: 320, height: 200, background: f.background, clear_behind: false, phong: is_phong };
        let test = format!("cs_320x200_{shading:?}").to_lowercase();
        let run = csb::run_rtl_vs_model(&test, &mut mem, &[spec], &config, CsDrive::ideal(), false).unwrap();
        let img = csb::frame_image(&run.frames[0], 320, 200).unwrap();
        assert!(img == f.frame.rgb, "teapot 320x200 {shading:?}: image differs");
        let cycles = run.frame_cycles[0];
        assert_eq!(cycles, 64000 + CS_PIPELINE_CYCLES);
        println!(
            "cs 320x200 {shading:?}: {cycles} cycles from the first I-buffer read to the last beat for 64000 pixels = {:.4} pixels/clock; RustHDL {:.0} cycles/s",
            64000.0 / cycles as f64,
            run.rtl_cycles_per_second
        );
    }
}

#[test]
fn the_normalizers_seed_rom_holds_the_golden_models_table_and_its_squares() {
    // hdl computes its ROM itself (it does not depend on golden); this ties the two together.
    for i in 0..256u64 {
        let y0 = golden::format::rsqrt_seed(i as u32) as u64;
        let word = hdl::cs::normalizer::seed_rom_word(i);
        assert_eq!(word & 0xffff, y0, "seed {i}");
        assert_eq!(word >> 16, (y0 * y0 + (1 << 13)) >> 14, "square of seed {i}");
    }
}

#[test]
fn cs_matches_its_cycle_model_every_cycle_in_phong_with_random_constants_records_and_back_pressure() {
    let seed = seed_for("cs_phong_random", 0x9409);
    let mut rng = Rng::new(seed);
    let mut mem = random_memories(&mut rng, 48, 20, 300);
    // Normals of every length, most of them near unit length as real frames have them.
    for e in mem.tdbs.iter_mut() {
        if rng.chance(70) {
            for k in 0..3 {
                e.planes[k] = Plane { a: rng.below(1 << 17) as i64 - (1 << 16), b: rng.below(1 << 17) as i64 - (1 << 16), c: (rng.below(1 << 15) as i64 - (1 << 14)) << 16 };
            }
        }
    }
    let lights = random_lights(&mut rng);
    let mut config = ignored_writes(&mut rng);
    config.extend(phong_config(&lights).unwrap());
    let frames = [
        FrameSpec { width: 48, height: 20, background: [1, 2, 3], clear_behind: false, phong: true },
        FrameSpec { width: 48, height: 20, background: [1, 2, 3], clear_behind: false, phong: false },
        FrameSpec { width: 5, height: 3, background: [9, 8, 7], clear_behind: false, phong: true },
        FrameSpec { width: 48, height: 20, background: [7, 7, 7], clear_behind: false, phong: true },
    ];
    let reference = mem.clone();
    let drive = CsDrive { stall_percent: 35, start_while_busy_percent: 20, max_idle: 4, seed };
    let run = csb::run_rtl_vs_model("cs_phong_random", &mut mem, &frames, &config, drive, false).unwrap();
    assert_eq!(run.frames.len(), frames.len());
    // The first frame against the algorithmic model, pixel by pixel.
    let img = csb::frame_image(&run.frames[0], 48, 20).unwrap();
    let mut lit = 0;
    for (i, px) in img.chunks(3).enumerate() {
        let idx = reference.ibuf[i];
        let (x, y) = (i as u32 % 48, i as u32 / 48);
        let want = if idx == 0 {
            [1, 2, 3]
        } else {
            let e = &reference.tdbs[idx as usize];
            lit += 1;
            lights.shade([0, 1, 2].map(|k| e.planes[k].eval(x, y)), e.material % CS_MATERIALS as u16)
        };
        assert_eq!(px, want, "pixel ({x}, {y})");
    }
    assert!(lit > 500, "too few lit pixels ({lit})");
    println!("cs phong: {} cycles, RustHDL {:.0} cycles/s", run.cycles, run.rtl_cycles_per_second);
}

// ------------------------------------------------------------------------------------------------
// Generated Verilog

#[test]
fn colour_setup_verilog_replays_the_recorded_vectors() {
    if !require_tools("colour_setup_verilog_replays_the_recorded_vectors", &["iverilog"]) {
        return;
    }
    let rec = colour_setup_replay_recording(seed_for("colour_setup_replay", 0xC0105E7), 60).unwrap();
    let v = hdl::verilog_top("colour_setup").unwrap();
    let r = replay_iverilog(&v, "colour_setup", &rec, &scratch_dir("cs/colour_setup_replay")).unwrap();
    println!("colour_setup Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
}

#[test]
fn cs_verilog_replays_the_recorded_vectors() {
    if !require_tools("cs_verilog_replays_the_recorded_vectors", &["iverilog"]) {
        return;
    }
    let rec = cs_replay_recording(seed_for("cs_replay", 0xC5)).unwrap();
    let v = hdl::verilog_top("cs").unwrap();
    let r = replay_iverilog(&v, "cs", &rec, &scratch_dir("cs/cs_replay")).unwrap();
    println!("cs Verilog (iverilog): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
}

#[test]
fn the_verilog_replay_catches_a_changed_constant() {
    if !require_tools("the_verilog_replay_catches_a_changed_constant", &["iverilog"]) {
        return;
    }
    let mut rng = Rng::new(3);
    let mut mem = random_memories(&mut rng, 8, 4, 10);
    let frames = [FrameSpec { width: 8, height: 4, background: [1, 2, 3], clear_behind: true, phong: false }];
    let run = csb::run_rtl_vs_model("cs_replay_broken", &mut mem, &frames, &[], CsDrive::ideal(), true).unwrap();
    let v = hdl::verilog_top("cs").unwrap();
    let far = "24'hffffff";
    assert!(v.contains(far), "the far depth constant is not in the Verilog");
    let broken = v.replacen(far, "24'hfffffe", 1);
    let e = replay_iverilog(&broken, "cs", run.recording.as_ref().unwrap(), &scratch_dir("cs/cs_replay_broken")).unwrap_err();
    assert!(e.contains("port zbuf_write_data expected ffffff actual fffffe"), "{e}");
}

#[test]
fn the_verilog_replay_catches_a_changed_phong_rounding_constant() {
    if !require_tools("the_verilog_replay_catches_a_changed_phong_rounding_constant", &["iverilog"]) {
        return;
    }
    let f = record("polyhedron", Shading::Phong, 24, 16).unwrap();
    let mut mem = f.memories();
    let config = phong_config(&f.lights).unwrap();
    let frames = [FrameSpec { width: 24, height: 16, background: f.background, clear_behind: false, phong: true }];
    let run = csb::run_rtl_vs_model("cs_replay_phong_broken", &mut mem, &frames, &config, CsDrive::ideal(), true).unwrap();
    let v = hdl::verilog_top("cs").unwrap();
    // The rounding half of the final >> 22 of the Phong sum.
    let half = "localparam  khalf_34 = 34'h200000;";
    assert!(v.contains(half), "the Phong rounding constant is not in the Verilog");
    let broken = v.replacen(half, "localparam  khalf_34 = 34'h0;", 1);
    let e = replay_iverilog(&broken, "cs", run.recording.as_ref().unwrap(), &scratch_dir("cs/cs_replay_phong_broken")).unwrap_err();
    assert!(e.contains("port video_tdata expected"), "{e}");
    println!("broken Phong rounding: {}", e.lines().next().unwrap_or(""));
}

#[test]
fn colour_setup_and_cs_pass_verilator_lint() {
    if !require_tools("colour_setup_and_cs_pass_verilator_lint", &["verilator"]) {
        return;
    }
    for top in ["colour_setup", "cs"] {
        let v = hdl::verilog_top(top).unwrap();
        crate::lint::lint(&v, top, &scratch_dir(&format!("cs/lint_{top}"))).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn colour_setup_and_cs_synthesize_for_ice40_without_latches() {
    if !require_tools("colour_setup_and_cs_synthesize_for_ice40_without_latches", &["yosys"]) {
        return;
    }
    for top in ["colour_setup", "cs"] {
        let v = hdl::verilog_top(top).unwrap();
        let f = synth_ice40(&v, top, &scratch_dir(&format!("cs/synth_{top}"))).unwrap();
        println!("{top}: yosys synth_ice40 -dsp: {} SB_LUT4, {} SB_CARRY, {} FF, {} SB_RAM40_4K, {} SB_MAC16, 0 latches", f.lut4, f.carry, f.ff, f.bram, f.dsp);
        assert!(f.lut4 > 0 && f.ff > 0);
    }
}

/// Issue 18: a CS whose video consumer is never ready stops at the port; the bench ends one watchdog
/// period later (1024 cycles with no memory access and no beat) with the phase and the waveform,
/// instead of running to its cycle budget.
#[test]
fn a_cs_run_that_stops_making_progress_ends_at_once_naming_the_phase_and_the_waveform() {
    let mut rng = Rng::new(0x57a11);
    let mut mem = random_memories(&mut rng, 16, 8, 20);
    let frames = [FrameSpec { width: 16, height: 8, background: [1, 2, 3], clear_behind: false, phong: false }];
    let drive = CsDrive { stall_percent: 100, start_while_busy_percent: 0, max_idle: 0, seed: 1 };
    let e = csb::run_rtl_vs_model("cs_never_ready", &mut mem, &frames, &[], drive, false).unwrap_err();
    assert!(e.contains("no progress for 1024 cycles in the CS (frame 1 of 1, 0 beats out)"), "{e}");
    assert!(e.contains("cycle 10"), "stopped late: {e}");
    assert!(e.contains("waveform"), "{e}");
}

#[test]
fn cs_tex_matches_its_cycle_model_every_cycle_on_textured_and_untextured_frames_under_back_pressure() {
    use golden::texture::{Filter, Wrap};
    let seed = seed_for("cs_tex", 17);
    let (w, h) = (64, 40);
    for (filter, wrap, shading) in [
        (Filter::Nearest, Wrap::ClampToEdge, Shading::Gouraud),
        (Filter::Bilinear, Wrap::Repeat, Shading::Phong),
        (Filter::Trilinear, Wrap::Repeat, Shading::Gouraud),
    ] {
        let tx = checker_texturing(filter, wrap);
        let f = super::frames::record_textured(shading, &tx, w, h).unwrap();
        let mut mem = f.textured_memories();
        let reference = mem.clone();
        let is_phong = shading == Shading::Phong;
        let config = if is_phong { phong_config(&f.lights).unwrap() } else { Vec::new() };
        let spec = FrameSpec { width: w, height: h, background: f.background, clear_behind: false, phong: is_phong };
        // Textured, untextured (the same memories, scanned as `cs` would), textured again.
        let tex = csb::TexRun { texturing: tx, textured: vec![true, false, true] };
        let drive = CsDrive { stall_percent: 30, start_while_busy_percent: 10, max_idle: 3, seed };
        let test = format!("cs_tex_{filter:?}_{shading:?}").to_lowercase();
        let run = csb::run_tex_rtl_vs_model(&test, &mut mem, &[spec; 3], &config, &tex, drive, false).unwrap();
        assert_eq!(run.frames.len(), 3);
        for k in [0, 2] {
            let img = csb::frame_image(&run.frames[k], w, h).unwrap();
            assert!(img == f.frame.rgb, "{filter:?} {shading:?}: textured frame {k} differs from golden");
        }
        if !is_phong {
            let img = csb::frame_image(&run.frames[1], w, h).unwrap();
            for (i, px) in img.chunks(3).enumerate() {
                let idx = reference.ibuf[i];
                let want = golden::cycle::color_shader::pixel_colour(idx, &reference.tdbs[idx as usize], i as u32 % w, i as u32 / w, f.background);
                assert_eq!(px, want, "{filter:?}: untextured frame, pixel {i}");
            }
        }
        println!("cs_tex {filter:?} {wrap:?} {shading:?}: {} cycles, RustHDL {:.0} cycles/s", run.cycles, run.rtl_cycles_per_second);
    }
}

#[test]
fn the_cs_tex_verilog_replays_the_recorded_vectors_and_a_changed_blend_is_caught() {
    if !require_tools("the_cs_tex_verilog_replays_the_recorded_vectors_and_a_changed_blend_is_caught", &["verilator"]) {
        return;
    }
    let rec = cs_tex_replay_recording().unwrap();
    let v = hdl::cs::color_shader_tex::verilog().unwrap();
    let r = super::replay::replay_verilator(&v, "cs_tex", &rec, &scratch_dir("cs/cs_tex_replay")).unwrap();
    println!("cs_tex Verilog (Verilator): {} cycles replayed in {:.2} s, 0 mismatches", r.cycles, r.seconds);
    // The trilinear blend's rounding constant removed: the video stream must differ.
    let eight = "localparam  k8_13 = 13'b1000;";
    assert!(v.contains(eight), "the blend's rounding constant is not in the Verilog");
    let e = super::replay::replay_verilator(&v.replacen(eight, "localparam  k8_13 = 13'b0;", 1), "cs_tex", &rec, &scratch_dir("cs/cs_tex_replay_broken")).unwrap_err();
    assert!(e.contains("video_tdata"), "{e}");
}

#[test]
fn cs_tex_passes_verilator_lint() {
    if !require_tools("cs_tex_passes_verilator_lint", &["verilator"]) {
        return;
    }
    let v = hdl::cs::color_shader_tex::verilog().unwrap();
    crate::lint::lint(&v, "cs_tex", &scratch_dir("cs/lint_cs_tex")).unwrap_or_else(|e| panic!("{e}"));
}

/// Issue 17 item 4 in RTL: a bilinear textured 320x200 frame streams one pixel per clock (the last
/// beat `CS_PIPELINE_CYCLES_TEX` after the last issue), its image is golden's and the words read at
/// the texture port are golden's count.
#[test]
fn cs_tex_streams_a_bilinear_320x200_frame_at_one_pixel_per_clock() {
    use golden::cycle::color_shader::CS_PIPELINE_CYCLES_TEX;
    use golden::texture::{Filter, Wrap};
    let tx = checker_texturing(Filter::Bilinear, Wrap::Repeat);
    let f = super::frames::record_textured(Shading::Gouraud, &tx, 320, 200).unwrap();
    let mut mem = f.textured_memories();
    let spec = FrameSpec { width: 320, height: 200, background: f.background, clear_behind: false, phong: false };
    let tex = csb::TexRun { texturing: tx, textured: vec![true] };
    let run = csb::run_tex_rtl_vs_model("cs_tex_320x200_bilinear", &mut mem, &[spec], &[], &tex, CsDrive::ideal(), false).unwrap();
    assert!(csb::frame_image(&run.frames[0], 320, 200).unwrap() == f.frame.rgb, "the RTL's textured frame differs from golden");
    let counts = f.frame.stats.texture.clone().expect("a textured frame counts its texels");
    assert_eq!(run.tex_words, counts.bank_words_read, "words read at the texture port");
    assert_eq!(run.frame_cycles[0], 64000 + CS_PIPELINE_CYCLES_TEX);
    println!(
        "cs_tex 320x200 bilinear: {} cycles for 64000 pixels = {:.4} pixels/clock, {} words at the texture port; RustHDL {:.0} cycles/s",
        run.frame_cycles[0],
        64000.0 / run.frame_cycles[0] as f64,
        run.tex_words,
        run.rtl_cycles_per_second
    );
}

/// Issue 17 item 5 for the CS: whole textured frames of teapot-floor, every filter at 320x200 and
/// bilinear at 640x480, recorded from the cycle model (with back-pressure) and replayed on the
/// `cs_tex` Verilog under Verilator, every port in every cycle; each frame's image is golden's.
#[test]
fn the_cs_tex_verilog_equals_the_cycle_model_on_whole_textured_frames_under_verilator() {
    use golden::texture::{Filter, Wrap};
    if !require_tools("the_cs_tex_verilog_equals_the_cycle_model_on_whole_textured_frames_under_verilator", &["verilator"]) {
        return;
    }
    let v = hdl::cs::color_shader_tex::verilog().unwrap();
    let (mut recs, mut names) = (Vec::new(), Vec::new());
    for (filter, wrap, shading, (w, h)) in [
        (Filter::Nearest, Wrap::Repeat, Shading::Gouraud, (320, 200)),
        (Filter::Bilinear, Wrap::ClampToEdge, Shading::Phong, (320, 200)),
        (Filter::Trilinear, Wrap::Repeat, Shading::Gouraud, (320, 200)),
        (Filter::Bilinear, Wrap::Repeat, Shading::Gouraud, (640, 480)),
    ] {
        let tx = checker_texturing(filter, wrap);
        let f = super::frames::record_textured(shading, &tx, w, h).unwrap();
        let mut mem = f.textured_memories();
        let is_phong = shading == Shading::Phong;
        let config = if is_phong { phong_config(&f.lights).unwrap() } else { Vec::new() };
        let spec = FrameSpec { width: w, height: h, background: f.background, clear_behind: false, phong: is_phong };
        let tex = csb::TexRun { texturing: tx, textured: vec![true] };
        let drive = CsDrive { stall_percent: 10, start_while_busy_percent: 5, max_idle: 0, seed: 0xF4A3 };
        let run = csb::record_tex_model(&mut mem, &[spec], &config, &tex, drive).unwrap();
        assert!(csb::frame_image(&run.frames[0], w, h).unwrap() == f.frame.rgb, "{filter:?} {w}x{h}: the model's frame differs from golden");
        names.push(format!("teapot-floor {w}x{h} {filter:?} {wrap:?} {shading:?}"));
        recs.push(run.recording.unwrap());
    }
    // One Verilator build replays the four recordings, each from the initial state.
    let dir = scratch_dir("cs/cs_tex_frames");
    let reports = super::replay::replay_verilator_all(&v, "cs_tex", &recs, &dir).unwrap_or_else(|e| panic!("{e}"));
    let _ = std::fs::remove_file(dir.join("in.hex"));
    let _ = std::fs::remove_file(dir.join("out.hex"));
    assert_eq!(reports.len(), recs.len());
    for (name, r) in names.iter().zip(&reports) {
        println!("cs_tex Verilog (Verilator), {name}: {} cycles replayed in {:.2} s, 0 mismatches, image = golden", r.cycles, r.seconds);
    }
}
