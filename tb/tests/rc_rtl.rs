//! The RC's RTL (RustHDL simulation, direct drive) against its cycle-accurate model, every output port
//! in every cycle, with random gaps on the command port and random back-pressure on the result port;
//! and the buffers of whole frames against the algorithmic model. `VCD=1` leaves
//! `target/vcd/rc/<test>.vcd`; a mismatch always leaves one and names it.

use golden::format::Screen;
use tb::common::Rng;
use tb::rc::bench::{run_rtl, Drive, Run};
use tb::rc::stimulus::{depth_rounding_edge_triangles, frame, hand_made, hand_made_screen, power_of_two_triangles, random_triangles, reference, scene_triangles, sliver_depth_rounding_edge_triangles};

fn check_against_reference(name: &str, screen: Screen, cmds: &[golden::cycle::rc::RcCmd], run: &Run) {
    let r = reference(screen, cmds);
    assert_eq!(run.results, r.results, "{name}: results differ from the algorithmic model");
    assert!(run.zbuf == r.zbuf, "{name}: Z-buffer differs from the algorithmic model");
    assert!(run.ibuf == r.ibuf, "{name}: I-buffer differs from the algorithmic model");
}

#[test]
fn rtl_matches_cycle_model_every_cycle_on_hand_made_cases() {
    for (name, cmds) in hand_made() {
        let test = format!("hand_made_{name}");
        let drive = Drive::random(&test, 0x4a4d);
        let run = run_rtl(&test, hand_made_screen(), &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
        check_against_reference(name, hand_made_screen(), &cmds, &run);
    }
}

#[test]
fn rtl_matches_cycle_model_every_cycle_on_seeded_random_triangle_lists() {
    let mut rng = Rng::new(0xbead);
    println!("random lists: seed {} (set SEED to replay)", rng.seed());
    for n in 0..6 {
        let screen = Screen::new(8 + rng.below(40) as u32, 8 + rng.below(32) as u32).unwrap();
        let cmds = frame(true, random_triangles(&mut rng, screen, 30));
        let drive = Drive { gap_percent: 30, stall_percent: 40, seed: rng.next_u64(), garbage: true, stale_depth: false };
        let test = format!("random_list_{n}");
        let run = run_rtl(&test, screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
        check_against_reference(&test, screen, &cmds, &run);
    }
}

/// Determinants of plus or minus a power of two: the reciprocal's first step (station 0 takes it from
/// the leading one without a subtraction, `fast_reciprocal.rs`) sets the quotient's top bit only for
/// these, which random lists almost never give.
#[test]
fn rtl_matches_cycle_model_every_cycle_on_power_of_two_determinants() {
    let mut rng = Rng::new(0x2_0002);
    let screen = hand_made_screen();
    let cmds = frame(true, power_of_two_triangles(&mut rng, screen, 80));
    let test = "power_of_two_list";
    let run = run_rtl(test, screen, &cmds, Drive::random(test, 0x2_0002), None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference(test, screen, &cmds, &run);
}

/// Triangles with a fragment whose raw depth is within 2 units of 2^-16 of a rounding edge, wide ones
/// and slivers under 1/8 pixel (the mutation cover's lists, `tb::mutation`): an error of one unit in
/// setup's depth plane (its C's rounding, the gradients' low bits) changes a depth here, where random
/// lists almost never show it. Broken on purpose (2026-12-07): C's rounding constant (the 128 of
/// `round(acc >> 8)` in S7, `acc_round`) left out passed every other test of this file and failed this
/// one (`z_wr_data` 0x468592 for 0x468593 at cycle 917).
#[test]
fn rtl_matches_cycle_model_every_cycle_on_triangles_at_a_depth_rounding_edge() {
    let mut rng = Rng::new(0xde9_7e);
    let screen = hand_made_screen();
    let lists = [("depth_rounding_edge", depth_rounding_edge_triangles(&mut rng, screen, 40, 2)), ("sliver_rounding_edge", sliver_depth_rounding_edge_triangles(&mut rng, screen, 40, 2))];
    for (test, tris) in lists {
        assert_eq!(tris.len(), 40, "{test}: the stimulus found too few triangles");
        let cmds = frame(true, tris);
        let run = run_rtl(test, screen, &cmds, Drive::random(test, 0xde9_7e), None).unwrap_or_else(|e| panic!("{e}"));
        check_against_reference(test, screen, &cmds, &run);
    }
}

/// Frames without clear over a Z-buffer of random words and an I-buffer of background indices (what
/// the chipset's RC finds after the Color Shader cleared the I-buffer behind its scan-out): every depth
/// under a background index counts as far, so the frame equals a frame on cleared buffers.
#[test]
fn a_frame_without_clear_over_stale_depths_draws_as_on_a_cleared_z_buffer() {
    let mut rng = Rng::new(0x57a1e);
    println!("stale depths: seed {} (set SEED to replay)", rng.seed());
    for n in 0..4 {
        let screen = Screen::new(8 + rng.below(40) as u32, 8 + rng.below(32) as u32).unwrap();
        let cmds = frame(false, random_triangles(&mut rng, screen, 30));
        let drive = Drive { gap_percent: 30, stall_percent: 40, seed: rng.next_u64(), garbage: false, stale_depth: true };
        let test = format!("stale_depth_{n}");
        let run = run_rtl(&test, screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
        let r = reference(screen, &cmds);
        assert_eq!(run.results, r.results, "{test}: results differ from the algorithmic model on cleared buffers");
        assert!(run.ibuf == r.ibuf, "{test}: I-buffer differs from the algorithmic model on cleared buffers");
        let z: Vec<u32> = run.ibuf.iter().zip(&run.zbuf).map(|(&i, &z)| if i == golden::format::INDEX_BACKGROUND { golden::format::DEPTH_MAX } else { z }).collect();
        assert!(z == r.zbuf, "{test}: depths under triangle indices differ from the algorithmic model");
    }
}

#[test]
fn rtl_draws_the_polyhedron_frame_like_the_algorithmic_model() {
    let screen = Screen::new(320, 200).unwrap();
    let cmds = frame(true, scene_triangles("polyhedron", 6, screen).unwrap());
    let drive = Drive::random("polyhedron", 0x9017);
    let run = run_rtl("polyhedron_320x200", screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference("polyhedron", screen, &cmds, &run);
    println!("polyhedron: {} cycles, {:.0} RTL cycles/s", run.cycles, run.rtl_cycles_per_second);
}

#[test]
fn rtl_draws_the_teapot_frame_like_the_algorithmic_model() {
    let screen = Screen::new(320, 200).unwrap();
    let cmds = frame(true, scene_triangles("teapot", 6, screen).unwrap());
    let drive = Drive::random("teapot", 0x7ea);
    let run = run_rtl("teapot_grid6_320x200", screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference("teapot", screen, &cmds, &run);
    println!("teapot: {} commands, {} cycles, {:.0} RTL cycles/s", cmds.len(), run.cycles, run.rtl_cycles_per_second);
}

/// The Z-test's read-after-write forwarding (issue 15 item 6): with no gap on the command port, a
/// triangle set up during a large one's walk has its first fragment at the large one's last pixel, in
/// the next clock. The test checks that the hazard happens (two Z reads of one address in consecutive
/// cycles) and that the buffers are right: without the forwarding the farther triangle's index would
/// be written over the nearer one's at that pixel.
#[test]
fn back_to_back_fragments_of_two_triangles_on_one_pixel_see_the_first_ones_depth() {
    let (name, cmds) = hand_made().into_iter().find(|(n, _)| *n == "same_pixel_across_triangles_without_gap").unwrap();
    let screen = hand_made_screen();
    let run = run_rtl(name, screen, &cmds, Drive::ideal(), None).unwrap_or_else(|e| panic!("{e}"));
    assert!(run.same_address_reads_back_to_back > 0, "the stimulus did not produce the hazard");
    check_against_reference(name, screen, &cmds, &run);
}

/// Issue 15's queues: a screen-size triangle keeps the traversal busy while small drawn and culled
/// triangles pile up behind it, so the record queue fills and S6 waits on it (and S5 behind it, and the
/// reciprocal's result behind S5); the result port is ready in one cycle of four, so the result queue
/// fills and the traversal waits for it. The RTL equals the model in every cycle and the results come
/// out in command order (the algorithmic model's list). The model's counters show that every one of
/// those paths was taken.
#[test]
fn full_record_and_result_queues_and_a_waiting_reciprocal_keep_every_result_in_order() {
    let (screen, cmds) = tb::rc::stimulus::queue_filling_triangles();
    let drive = Drive { gap_percent: 0, stall_percent: 75, seed: 0x51ab, garbage: false, stale_depth: false };
    let run = run_rtl("full_queues", screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference("full_queues", screen, &cmds, &run);
    assert!(run.record_queue_full_cycles > 0, "the record queue never filled");
    assert!(run.result_queue_full_cycles > 0, "the result queue never filled");
    assert!(run.recip_stall_cycles > 0, "the reciprocal's result never waited");
    eprintln!("record queue full {} cycles, result queue full {}, reciprocal waiting {}", run.record_queue_full_cycles, run.result_queue_full_cycles, run.recip_stall_cycles);
}
