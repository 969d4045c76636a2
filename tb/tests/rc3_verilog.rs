//! The Type III RC's generated Verilog (top `rc3`): Verilator `-Wall` lint with the project's named
//! waivers, and the replay of vectors recorded from cycle-model runs (inputs, memory read data and the
//! model's outputs, every cycle, with random gaps and back-pressure) on the Verilog under Icarus and
//! Verilator, checked port by port in every cycle; a fault put into the Verilog is caught.

use golden::format::Screen;
use golden::raster::RcType;
use tb::common::{require_tools, scratch_dir};
use tb::rc::bench::{run_model_of, Drive};
use tb::rc::replay::{rc3_ports, replay_rc3, Rc3Vectors, Simulator};
use tb::rc::stimulus::{frame, hand_made, hand_made_screen, scene_triangles};

/// Record the hand-made cases (all in one stream) through the Type III model.
fn hand_made_vectors(name: &str) -> (std::path::PathBuf, u64) {
    let cmds: Vec<_> = hand_made().into_iter().flat_map(|(_, c)| c).collect();
    let mut w = Rc3Vectors::create(scratch_dir("rc3_vectors").join(format!("{name}.vec"))).unwrap();
    let drive = Drive { garbage: false, ..Drive::random(name, 0x3ca5) };
    run_model_of(RcType::III, hand_made_screen(), &cmds, drive, Some(&mut w)).unwrap();
    w.0.finish().unwrap()
}

#[test]
fn rc3_verilog_passes_verilator_lint_all_with_named_waivers() {
    if !require_tools("rc3_verilog_passes_verilator_lint_all_with_named_waivers", &["verilator"]) {
        return;
    }
    let dir = scratch_dir("rc3_lint");
    let v = hdl::rc::rc3::verilog(320, 200).unwrap();
    tb::lint::lint(&v, "rc3", &dir).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn rc3_verilog_replays_the_hand_made_cases_under_icarus() {
    if !require_tools("rc3_verilog_replays_the_hand_made_cases_under_icarus", &["iverilog", "vvp"]) {
        return;
    }
    let (path, cycles) = hand_made_vectors("hand_made");
    let verdict = replay_rc3(Simulator::Icarus, hand_made_screen(), &path, cycles).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(verdict, format!("REPLAY PASSED {cycles}"));
}

#[test]
fn rc3_verilog_replays_a_type_iii_polyhedron_and_teapot_frame_under_verilator() {
    if !require_tools("rc3_verilog_replays_a_type_iii_polyhedron_and_teapot_frame_under_verilator", &["verilator"]) {
        return;
    }
    let screen = Screen::new(320, 200).unwrap();
    let mut cmds = frame(true, scene_triangles("polyhedron", 6, screen).unwrap());
    cmds.extend(frame(false, scene_triangles("teapot", 6, screen).unwrap()));
    let mut w = Rc3Vectors::create(scratch_dir("rc3_vectors").join("polyhedron_teapot.vec")).unwrap();
    let drive = Drive { garbage: false, ..Drive::random("rc3_replay_scenes", 0x3017) };
    let run = run_model_of(RcType::III, screen, &cmds, drive, Some(&mut w)).unwrap();
    assert!(run.tdbv_reads > 1000, "the teapot drawn over the polyhedron reads TdbV: {}", run.tdbv_reads);
    let (path, cycles) = w.0.finish().unwrap();
    let verdict = replay_rc3(Simulator::Verilator, screen, &path, cycles).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(verdict, format!("REPLAY PASSED {cycles}"));
}

/// The replay is not a formality: the Verilog with its newest forwarding register ignored (a fragment
/// right behind a write to its pixel then reads the stale index) fails it at the first wrong cycle.
#[test]
fn a_fault_in_the_rc3_verilog_fails_the_replay() {
    if !require_tools("a_fault_in_the_rc3_verilog_fails_the_replay", &["iverilog", "vvp"]) {
        return;
    }
    let (path, cycles) = hand_made_vectors("hand_made_fault");
    let v = hdl::rc::rc3::verilog(hand_made_screen().width, hand_made_screen().height).unwrap();
    let good = "if (h1_v$q & (h1_addr$q == f4$q[(64'h4)+:(20)])) begin";
    assert_eq!(v.matches(good).count(), 1, "the forwarding test is not in the Verilog as expected");
    let bad = v.replace(good, "if (1'b0) begin");
    let dir = scratch_dir("rc3_fault");
    let err = tb::proof::replay::replay("iverilog", &dir, "rc3", &rc3_ports(), &bad, &path, cycles).unwrap_err();
    assert!(err.contains("REPLAY FAILED at cycle"), "{err}");
}
