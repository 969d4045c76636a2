//! The RC's generated Verilog: top module `rc`, Verilator `-Wall` lint (waivers named below with their
//! reasons), yosys `synth_ice40 -dsp` without latches, and the replay of recorded vectors (inputs and
//! the cycle model's outputs, every cycle, recorded from a model run with random gaps and
//! back-pressure) on the Verilog under Icarus and Verilator: the Verilog is checked against the same
//! model as the RustHDL simulation, independently of it.

use golden::format::Screen;
use std::process::Command;
use tb::common::{require_tools, scratch_dir};
use tb::rc::bench::{run_model, Drive};
use tb::rc::replay::{replay, write_rc_verilog, Simulator, VectorWriter};
use tb::rc::stimulus::{frame, hand_made, hand_made_screen, scene_triangles};

#[test]
fn rc_verilog_has_the_top_module_rc() {
    let v = hdl::verilog_top("rc").unwrap();
    assert!(v.contains("\nmodule rc(clock,cmd$data,"), "top module is not `rc`");
    assert!(!v.contains("module top"), "a module is still named top");
    assert!(hdl::verilog_top("rcx").unwrap_err().contains("rc"));
}

#[test]
fn rc_verilog_passes_verilator_lint_all_with_named_waivers() {
    if !require_tools("rc_verilog_passes_verilator_lint_all_with_named_waivers", &["verilator"]) {
        return;
    }
    let dir = scratch_dir("rc_lint");
    let v = write_rc_verilog(Screen::new(320, 200).unwrap(), &dir).unwrap();
    let text = std::fs::read_to_string(&v).unwrap();
    tb::lint::lint(&text, "rc", &dir).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn rc_synthesizes_for_ice40_with_dsp_and_no_latches() {
    if !require_tools("rc_synthesizes_for_ice40_with_dsp_and_no_latches", &["yosys"]) {
        return;
    }
    let dir = scratch_dir("rc_synth");
    let v = write_rc_verilog(Screen::new(320, 200).unwrap(), &dir).unwrap();
    let log = dir.join("yosys.log");
    let o = Command::new("yosys")
        .arg("-q")
        .arg("-l")
        .arg(&log)
        .arg("-p")
        .arg(format!("read_verilog {}; synth_ice40 -dsp -top rc; stat", v.display()))
        .output()
        .unwrap();
    let text = std::fs::read_to_string(&log).unwrap_or_default();
    assert!(o.status.success(), "yosys failed:\n{}{}", String::from_utf8_lossy(&o.stderr), text);
    // `proc` reports "Latch inferred for signal ..." for every latch (and "No latch inferred" otherwise).
    let latches: Vec<&str> = text.lines().filter(|l| l.trim_start().starts_with("Latch inferred")).collect();
    assert!(latches.is_empty(), "yosys inferred latches:\n{}", latches.join("\n"));
    let stat = text.rsplit("Printing statistics.").next().unwrap();
    assert!(!stat.to_uppercase().contains("LATCH"), "latch cells in the netlist:\n{stat}");
    let count = |cell: &str| -> u64 {
        stat.lines().filter_map(|l| l.trim().strip_prefix(cell).and_then(|r| r.trim().parse::<u64>().ok())).sum()
    };
    let lut = count("SB_LUT4");
    let ff: u64 = ["SB_DFF ", "SB_DFFE ", "SB_DFFSR ", "SB_DFFR ", "SB_DFFS ", "SB_DFFESR ", "SB_DFFER ", "SB_DFFES ", "SB_DFFSS ", "SB_DFFESS "]
        .iter()
        .map(|c| count(c))
        .sum();
    println!("ice40: {lut} LUT4, {ff} FF, {} CARRY, {} RAM40_4K, {} MAC16", count("SB_CARRY"), count("SB_RAM40_4K"), count("SB_MAC16"));
    assert!(lut > 0 && ff > 0, "no logic in the netlist:\n{stat}");
}

#[test]
fn generated_verilog_replays_the_hand_made_cases_under_icarus() {
    if !require_tools("generated_verilog_replays_the_hand_made_cases_under_icarus", &["iverilog", "vvp"]) {
        return;
    }
    // All hand-made frames in one stream (each starts with a clearing frame start).
    let cmds: Vec<_> = hand_made().into_iter().flat_map(|(_, c)| c).collect();
    let path = scratch_dir("rc_vectors").join("hand_made.vec");
    let mut w = VectorWriter::create(path).unwrap();
    let drive = Drive { garbage: false, ..Drive::random("replay_hand_made", 0x1ca5) };
    run_model(hand_made_screen(), &cmds, drive, Some(&mut w)).unwrap();
    let (path, cycles) = w.finish().unwrap();
    let checked = replay(Simulator::Icarus, hand_made_screen(), &path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(checked, cycles, "the replay stopped early");
}

#[test]
fn generated_verilog_replays_a_polyhedron_frame_under_verilator() {
    if !require_tools("generated_verilog_replays_a_polyhedron_frame_under_verilator", &["verilator"]) {
        return;
    }
    let screen = Screen::new(320, 200).unwrap();
    let cmds = frame(true, scene_triangles("polyhedron", 6, screen).unwrap());
    let path = scratch_dir("rc_vectors").join("polyhedron.vec");
    let mut w = VectorWriter::create(path).unwrap();
    let drive = Drive { garbage: false, ..Drive::random("replay_polyhedron", 0x9017) };
    run_model(screen, &cmds, drive, Some(&mut w)).unwrap();
    let (path, cycles) = w.finish().unwrap();
    let checked = replay(Simulator::Verilator, screen, &path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(checked, cycles, "the replay stopped early");
}

/// Triangles with the longest edges the formats allow, on a 1024x1024 screen: vertices at both ends of
/// the 20-bit S11.8 range (a guard band of one screen on each side), so edge deltas reach 2^20
/// subpixels and the steps 2^28; each triangle overlaps the screen in a small box, to keep the replay
/// short. With them, the polyhedron triangle at 640x480 that exposed a width bug in the generated
/// Verilog (the RustHDL simulation drew its 51 812 pixels, the Verilog 2: the edge steps were shifted
/// in 17 bits; found by `render --backend verilator --size 640x480 --scene polyhedron`). Every 320x200
/// scene stays below 256-pixel edges, which is why the other replays never showed it.
#[test]
fn generated_verilog_draws_triangles_with_the_longest_edges_the_formats_allow_under_icarus() {
    if !require_tools("generated_verilog_draws_triangles_with_the_longest_edges_the_formats_allow_under_icarus", &["iverilog", "vvp"]) {
        return;
    }
    use golden::cycle::rc::RcCmd;
    use golden::format::{WinVertex, DEPTH_MAX};
    use golden::raster::{CullMode, FrontFace};
    let screen = Screen::new(1024, 1024).unwrap();
    let s = golden::format::SUBPIXEL_ONE; // one pixel in subpixels
    let (lo, hi) = (golden::format::WINDOW_MIN, golden::format::WINDOW_MAX);
    let v = |x, y, z| WinVertex { x, y, z };
    let tris = [
        // The 640x480 polyhedron triangle, as it reached the RC.
        [v(2741 * s / 16, 5511 * s / 16, 14991021), v(7906 * s / 16, 5538 * s / 16, 12643651), v(4200 * s / 16, 384 * s / 16, 11227834)],
        // The bottom-right corner, with two vertices at the format's positive end.
        [v(1020 * s, 1020 * s, 0), v(hi, 1023 * s + s / 2, DEPTH_MAX - 1), v(1023 * s + s / 2, hi, 1 << 23)],
        // The top-left corner, with two vertices at the negative end.
        [v(lo, 4 * s, 77), v(4 * s, lo, DEPTH_MAX - 1), v(4 * s, 4 * s, 5)],
        // A band across the whole x range (dx = 2^20 - 1) and one across the whole y range.
        [v(lo, 1000 * s, 1000), v(hi, 1010 * s, 2_000_000), v(1000 * s, 1030 * s, 9_000_000)],
        [v(1000 * s, lo, 1000), v(1010 * s, hi, 2_000_000), v(1030 * s, 1000 * s, 9_000_000)],
    ];
    let cmds = frame(
        false,
        tris.iter().enumerate().map(|(i, t)| RcCmd::triangle(i as u32 + 1, *t, CullMode::None, FrontFace::Ccw).unwrap()).collect(),
    );
    let path = scratch_dir("rc_vectors").join("longest_edges.vec");
    let mut w = VectorWriter::create(path).unwrap();
    let run = run_model(screen, &cmds, Drive::ideal(), Some(&mut w)).unwrap();
    let (path, cycles) = w.finish().unwrap();
    // The replay compares every port in every cycle with the cycle model; first make sure the frame it
    // compares is the algorithmic model's, and that every triangle put pixels into it.
    let r = tb::rc::stimulus::reference(screen, &cmds);
    assert_eq!(run.ibuf, r.ibuf, "the cycle model's I-buffer differs from the algorithmic model's");
    for i in 1..=tris.len() as u32 {
        assert!(r.ibuf.iter().any(|&x| x == i), "triangle {i} draws no pixel: the case tests nothing");
    }
    let checked = replay(Simulator::Icarus, screen, &path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(checked, cycles, "the replay stopped early");
}
