//! Seed 000's Type III RC (`hdl::rc::rc3`: no Z-buffer, the old depth regenerated from TdbV) against
//! its cycle-accurate model (`golden::cycle::rc` with `RcType::III`) on every output port in every
//! cycle, with random gaps on the command port and random back-pressure on the result port; the
//! model's and the RTL's buffers against the algorithmic Type III model, and those against Type IV's.
//! `VCD=1` leaves `target/vcd/rc/<test>.vcd`; a mismatch always leaves one and names it.

use golden::cycle::rc::RcCmd;
use golden::format::Screen;
use golden::raster::RcType;
use tb::common::Rng;
use tb::rc::bench::{run_model_of, run_rtl_of, Drive, Run};
use tb::rc::stimulus::{frame, hand_made, hand_made_screen, random_triangles, reference_of, scene_triangles};

const III: RcType = RcType::III;

/// The run's buffers and results equal the algorithmic Type III model's, and Type IV's too (each
/// triangle of these streams has its own index).
fn check_against_reference(name: &str, screen: Screen, cmds: &[RcCmd], run: &Run) {
    let r = reference_of(III, screen, cmds);
    if let Some(k) = (0..run.results.len().max(r.results.len())).find(|&k| run.results.get(k) != r.results.get(k)) {
        panic!("{name}: result {k} differs from the algorithmic Type III model: {:?} against {:?}", run.results.get(k), r.results.get(k));
    }
    assert!(run.ibuf == r.ibuf, "{name}: I-buffer differs from the algorithmic Type III model");
    assert!(run.zbuf == r.zbuf, "{name}: regenerated depths differ from the algorithmic Type III model");
    let iv = reference_of(RcType::IV, screen, cmds);
    assert!(r.ibuf == iv.ibuf && r.zbuf == iv.zbuf && r.results == iv.results, "{name}: Type III differs from Type IV");
    assert_eq!(run.i_reads, r.rast.counts.traffic.i_reads, "{name}: one I-buffer read per fragment");
    assert_eq!(run.i_writes, r.rast.counts.traffic.i_writes, "{name}: one I-buffer write per pass");
    assert_eq!(run.tdbv_writes, r.rast.counts.traffic.tdbv_writes, "{name}: one TdbV write per walked triangle");
    // A fragment reads TdbV where its I-buffer read saw an index. A read the forwarding overrides may
    // still see the background (the write is in flight), so the port can read less than the untimed
    // model counts, never more than one read per fragment.
    assert!(run.tdbv_reads <= run.i_reads, "{name}: more TdbV reads than fragments");
    assert_eq!(run.z_reads, run.i_reads);
}

#[test]
fn type_iii_cycle_model_draws_every_builtin_scene_like_the_algorithmic_model() {
    let screen = Screen::new(320, 200).unwrap();
    for name in golden::scene::builtin::SCENES {
        let cmds = frame(true, scene_triangles(name, 6, screen).unwrap());
        let drive = Drive::random(&format!("type III scene {name}"), 0x3ce7e);
        let run = run_model_of(III, screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{name}: {e}"));
        check_against_reference(name, screen, &cmds, &run);
        let r = reference_of(III, screen, &cmds);
        println!(
            "{name}: {} cycles; TdbV reads {} at the port, {} in the untimed model; TdbV writes {}",
            run.cycles, run.tdbv_reads, r.rast.counts.traffic.tdbv_reads, run.tdbv_writes
        );
    }
}

#[test]
fn type_iii_rtl_matches_its_cycle_model_every_cycle_on_hand_made_cases() {
    for (name, cmds) in hand_made() {
        let test = format!("rc3_hand_made_{name}");
        for drive in [Drive::ideal(), Drive::random(&test, 0x3a4d)] {
            let run = run_rtl_of(III, &test, hand_made_screen(), &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
            check_against_reference(name, hand_made_screen(), &cmds, &run);
        }
    }
}

#[test]
fn type_iii_rtl_matches_its_cycle_model_every_cycle_on_seeded_random_triangle_lists() {
    let mut rng = Rng::new(0x3bead);
    println!("random lists: seed {} (set SEED to replay)", rng.seed());
    for n in 0..6 {
        let screen = Screen::new(8 + rng.below(40) as u32, 8 + rng.below(32) as u32).unwrap();
        let cmds = frame(true, random_triangles(&mut rng, screen, 30));
        let drive = Drive { gap_percent: 30, stall_percent: 40, seed: rng.next_u64(), garbage: true, stale_depth: false };
        let test = format!("rc3_random_list_{n}");
        let run = run_rtl_of(III, &test, screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
        check_against_reference(&test, screen, &cmds, &run);
    }
}

#[test]
fn type_iii_rtl_draws_the_teapot_frame_like_the_algorithmic_model() {
    let screen = Screen::new(160, 100).unwrap();
    let cmds = frame(true, scene_triangles("teapot", 6, screen).unwrap());
    let drive = Drive::random("rc3 teapot", 0x37ea);
    let run = run_rtl_of(III, "rc3_teapot_grid6_160x100", screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference("teapot", screen, &cmds, &run);
    println!("teapot: {} commands, {} cycles, {:.0} RTL cycles/s", cmds.len(), run.cycles, run.rtl_cycles_per_second);
}

/// The pixel hazard: a fragment's I-buffer read cannot see the writes of the four fragments ahead of
/// it, so F4 forwards the newest of those to the same pixel. The stimulus: pairs of a larger triangle
/// and a farther small one drawn right after it (its record waits in the queue during the larger
/// one's walk, so its first fragments follow with no gap), kept when the small one's fragments read a
/// pixel the larger one wrote 1, 2, 3 or 4 cycles before (found by the cycle model, counted at the port).
/// Without the forwarding the farther triangle would see the background's far depth there and win.
/// Each of the four forwarding registers is needed: with any one of them ignored, this test fails.
#[test]
fn fragments_one_to_four_cycles_behind_a_write_to_their_pixel_see_its_depth() {
    use golden::format::WinVertex;
    use golden::raster::{CullMode, FrontFace};
    let screen = Screen::new(16, 12).unwrap();
    let mut rng = Rng::new(0x3f0d);
    let mut kept: Vec<(Vec<RcCmd>, usize)> = Vec::new();
    let mut found = [0usize; 4];
    let mut tries = 0;
    while found.iter().any(|&f| f < 3) {
        tries += 1;
        assert!(tries < 20_000, "no stimulus found for every distance: {found:?}");
        let mut p = |lo: i64, span: i64, z: u32| WinVertex { x: (lo + rng.below(span as u64) as i64) as i32, y: (lo + rng.below(span as u64) as i64) as i32, z };
        let (one, u) = (golden::format::SUBPIXEL_ONE as i64, golden::format::SUBPIXEL_ONE / 16);
        let big = [p(0, one * 12, 100), p(0, one * 12, 100), p(0, one * 12, 100)];
        let c = p(one, one * 9, 200);
        let small = [c, WinVertex { x: c.x + 40 * u, ..c }, WinVertex { y: c.y + 20 * u, ..c }];
        let Ok(a) = RcCmd::triangle(1, big, CullMode::None, FrontFace::Ccw) else { continue };
        let Ok(b) = RcCmd::triangle(2, small, CullMode::None, FrontFace::Ccw) else { continue };
        let cmds = frame(true, vec![a, b]);
        let run = run_model_of(III, screen, &cmds, Drive::ideal(), None).unwrap();
        if let Some(k) = (0..4).find(|&k| run.same_address_reads_within[k] > 0 && found[k] < 3) {
            found[k] += 1;
            kept.push((cmds, k + 1));
        }
    }
    for (n, (cmds, distance)) in kept.iter().enumerate() {
        let test = format!("rc3_same_pixel_{n}_distance_{distance}");
        let run = run_rtl_of(III, &test, screen, cmds, Drive::ideal(), None).unwrap_or_else(|e| panic!("{e}"));
        assert!(run.same_address_reads_within[distance - 1] > 0, "{test}: the hazard did not happen in the RTL run");
        check_against_reference(&test, screen, cmds, &run);
    }
    println!("{} pairs, hazards at distances 1, 2, 3, 4: {found:?} ({tries} tried)", kept.len());
}

/// Queues: a long walk while drawn and culled triangles pile up behind it with the result port ready
/// one cycle in four: the record queue and the six-deep result queue fill, and results leave in
/// command order.
#[test]
fn type_iii_full_record_and_result_queues_keep_every_result_in_order() {
    let (screen, cmds) = tb::rc::stimulus::queue_filling_triangles();
    let drive = Drive { gap_percent: 0, stall_percent: 75, seed: 0x351ab, garbage: false, stale_depth: false };
    let run = run_rtl_of(III, "rc3_full_queues", screen, &cmds, drive, None).unwrap_or_else(|e| panic!("{e}"));
    check_against_reference("full_queues", screen, &cmds, &run);
    assert!(run.record_queue_full_cycles > 0, "the record queue never filled");
    assert!(run.result_queue_full_cycles > 0, "the result queue never filled");
}
