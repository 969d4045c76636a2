//! The RC's cycle-accurate model (`golden::cycle::rc`) against the algorithmic model
//! (`golden::raster::Rasterizer`): the same Z-buffer, I-buffer and per-triangle flags on every built-in
//! scene, on the hand-made cases and on seeded random triangle lists, with random gaps on the command
//! port and random back-pressure on the result port.

use golden::format::Screen;
use tb::common::Rng;
use tb::rc::bench::{run_model, Drive};
use tb::rc::stimulus::{frame, hand_made, hand_made_screen, hazard_triangles, power_of_two_triangles, random_triangles, reference, scene_triangles};

fn check(name: &str, screen: Screen, cmds: &[golden::cycle::rc::RcCmd], drive: Drive) -> u64 {
    let run = run_model(screen, cmds, drive, None).unwrap_or_else(|e| panic!("{name}: {e}"));
    let r = reference(screen, cmds);
    assert_eq!(run.results, r.results, "{name}: results differ");
    assert!(run.zbuf == r.zbuf, "{name}: Z-buffer differs");
    assert!(run.ibuf == r.ibuf, "{name}: I-buffer differs");
    assert_eq!(run.z_reads, r.rast.counts.fragments, "{name}: one Z read per fragment");
    assert_eq!(run.z_passes, r.rast.counts.z_passes, "{name}: one write per pass");
    run.cycles
}

#[test]
fn cycle_model_reproduces_the_algorithmic_buffers_on_every_builtin_scene() {
    let screen = Screen::new(320, 200).unwrap();
    for name in golden::scene::builtin::SCENES {
        let cmds = frame(true, scene_triangles(name, 6, screen).unwrap());
        let drive = Drive::random(&format!("scene {name}"), 0x5ce7e);
        let cycles = check(name, screen, &cmds, drive);
        println!("{name}: {} commands, {cycles} cycles with gaps and back-pressure", cmds.len());
    }
}

#[test]
fn cycle_model_reproduces_the_hand_made_cases() {
    for (name, cmds) in hand_made() {
        check(name, hand_made_screen(), &cmds, Drive::ideal());
        check(name, hand_made_screen(), &cmds, Drive::random(name, 0xca5e));
    }
}

/// The two same-pixel cases make the traces their names and comments say: three Z reads of one pixel
/// in three consecutive cycles, and two triangles' fragments on one pixel in consecutive cycles.
#[test]
fn the_same_pixel_cases_produce_the_read_patterns_they_are_named_for() {
    let case = |n: &str| hand_made().into_iter().find(|(name, _)| *name == n).unwrap().1;
    let three = run_model(hand_made_screen(), &case("same_pixel_back_to_back"), Drive::ideal(), None).unwrap();
    assert_eq!((three.z_reads, three.same_address_reads_back_to_back), (3, 2), "three reads of one pixel, each the cycle after the one before");
    let gapless = run_model(hand_made_screen(), &case("same_pixel_across_triangles_without_gap"), Drive::ideal(), None).unwrap();
    assert_eq!(gapless.same_address_reads_back_to_back, 1, "one read of the pixel the cycle after the other triangle's");
}

/// The mutation cover's one-pixel triangle lists (`hazard_triangles`) do what they are for: the cycle model
/// draws them as the algorithmic model does, their fragments read one pixel in consecutive cycles many
/// times (the forwarding's hazard), they set the top index bit, they use the depth clamps, and in the
/// staircase lists at least half of the fragments pass.
#[test]
fn one_pixel_triangle_lists_read_their_pixel_back_to_back_with_high_indices_and_clamped_depths() {
    let mut rng = Rng::new(0x4a2a);
    let screen = hand_made_screen();
    let (mut back_to_back, mut top_index_bit, mut clamps) = (0, false, [false; 2]);
    for n in 0..4 {
        let tris = hazard_triangles(&mut rng, screen, 80, n >= 2);
        top_index_bit |= tris.iter().any(|t| t.index >= 1 << (golden::cycle::rc::INDEX_BITS - 1));
        for t in &tris {
            clamps[0] |= t.v.iter().all(|v| v.z == 0);
            clamps[1] |= t.v.iter().all(|v| v.z == golden::format::DEPTH_MAX);
        }
        let cmds = frame(true, tris);
        check(&format!("one-pixel list {n}"), screen, &cmds, Drive::random(&format!("one-pixel list {n}"), 0x4a2a + n));
        let run = run_model(screen, &cmds, Drive::ideal(), None).unwrap();
        back_to_back += run.same_address_reads_back_to_back;
        if n >= 2 {
            // The staircase: fragments mostly nearer than what the pixel holds, so they pass.
            assert!(2 * run.z_passes >= run.z_reads, "staircase list {n}: {} of {} Z reads passed", run.z_passes, run.z_reads);
        }
    }
    assert!(back_to_back >= 100, "only {back_to_back} reads of the pixel read the cycle before");
    assert!(top_index_bit, "no index with bit 15 set");
    assert_eq!(clamps, [true, true], "depth 0 and DEPTH_MAX on every vertex of some triangle");
}

#[test]
fn cycle_model_reproduces_seeded_random_triangle_lists() {
    let mut rng = Rng::new(0x7a11);
    println!("random lists: seed {} (set SEED to replay)", rng.seed());
    for n in 0..20 {
        let screen = Screen::new(16 + rng.below(48) as u32, 16 + rng.below(40) as u32).unwrap();
        let cmds = frame(true, random_triangles(&mut rng, screen, 40));
        let drive = Drive { gap_percent: 30, stall_percent: 40, seed: rng.next_u64(), garbage: true, stale_depth: false };
        check(&format!("list {n}"), screen, &cmds, drive);
    }
}

#[test]
fn several_frames_in_one_stream_without_clear_keep_the_earlier_contents() {
    // clear = false trusts the buffers to be clear (the chipset clears behind the scan-out); a second
    // frame without clear must therefore draw over the first, exactly as the algorithmic model does.
    let screen = hand_made_screen();
    let cases = hand_made();
    let mut cmds = Vec::new();
    for (_, c) in cases.iter().take(3) {
        let mut c = c.clone();
        c[0] = golden::cycle::rc::RcCmd::frame(false);
        cmds.extend(c);
    }
    let run = run_model(screen, &cmds, Drive::ideal(), None).unwrap();
    let r = reference(screen, &cmds);
    assert_eq!(run.results, r.results);
    assert!(run.zbuf == r.zbuf && run.ibuf == r.ibuf);
}

/// Issue 18: a bench that stops making progress ends within one watchdog period (W*H + 1024 cycles
/// without a command or result taken or a memory access) with an error saying so, not after the
/// cycle budget. Here the result consumer is never ready, so the RC stalls on its first result.
#[test]
fn a_bench_that_stops_making_progress_ends_at_once_with_a_clear_error() {
    let screen = Screen::new(32, 20).unwrap();
    let cmds = frame(true, scene_triangles("polyhedron", 6, screen).unwrap());
    let drive = Drive { gap_percent: 0, stall_percent: 100, seed: 1, garbage: false, stale_depth: false };
    let t0 = std::time::Instant::now();
    let e = run_model(screen, &cmds, drive, None).unwrap_err();
    assert!(e.contains("no progress for 1664 cycles") && e.contains("results"), "{e}");
    eprintln!("stopped in {:.3} s: {e}", t0.elapsed().as_secs_f64());
}

/// `fill_rule_every_edge_index` is what its name says: for each of the three edges of the set-up
/// triangle (vertex order with det > 0), and for top-left and other edges alike, some triangle has a
/// pixel centre exactly on that edge, covered by its other two edges and on no other triangle of the
/// case, so the tie alone decides what the I-buffer holds there. (`fill_rule_corners` has ties on
/// every edge index too, but those on the third edge all lie on an edge shared at equal depth.)
#[test]
fn the_fill_rule_case_puts_lone_pixel_centres_on_every_edge_index_of_both_kinds() {
    use golden::raster::{setup, CullMode, FrontFace};
    let (_, cmds) = hand_made().into_iter().find(|(n, _)| *n == "fill_rule_every_edge_index").unwrap();
    let tris: Vec<_> = cmds
        .iter()
        .filter(|c| c.kind == golden::cycle::rc::CmdKind::Triangle)
        .map(|c| setup(&c.v, CullMode::None, FrontFace::Ccw, hand_made_screen()).expect("drawn"))
        .collect();
    let mut seen = [[false; 2]; 3];
    for (i, st) in tris.iter().enumerate() {
        let b = st.bbox;
        for (y, x) in (b.y0..=b.y1).flat_map(|y| (b.x0..=b.x1).map(move |x| (y, x))) {
            // No other triangle has the centre inside or on its edges.
            let touches = |o: &golden::raster::Setup| o.edges.iter().all(|e| e.at(x as i64, y as i64) + if e.top_left { 0 } else { 1 } >= 0);
            let lone = tris.iter().enumerate().all(|(j, o)| j == i || !touches(o));
            for k in 0..3 {
                let e = &st.edges[k];
                let on_edge = e.at(x as i64, y as i64) + if e.top_left { 0 } else { 1 } == 0;
                let others_cover = (0..3).filter(|&j| j != k).all(|j| st.edges[j].at(x as i64, y as i64) >= 0);
                if on_edge && others_cover && lone {
                    seen[k][e.top_left as usize] = true;
                }
            }
        }
    }
    assert_eq!(seen, [[true; 2]; 3], "[edge][top-left] with a lone centre on the edge");
}

/// The mutation cover's power-of-two lists (`power_of_two_triangles`) do what they are for: every
/// determinant is plus or minus a power of two (the reciprocal's divisor 2^s), both signs and exponents
/// from 0 to 16 occur, and the cycle model draws them as the algorithmic model does.
#[test]
fn power_of_two_triangle_lists_give_the_reciprocal_power_of_two_divisors_and_draw_as_the_reference() {
    let mut rng = Rng::new(0x2_0002);
    let screen = hand_made_screen();
    let tris = power_of_two_triangles(&mut rng, screen, 80);
    let (mut signs, mut exps) = ([false; 2], std::collections::BTreeSet::new());
    for t in &tris {
        let d = golden::raster::det(&t.v);
        assert!(d != 0 && d.unsigned_abs().is_power_of_two(), "triangle {} has determinant {d}", t.index);
        signs[(d > 0) as usize] = true;
        exps.insert(d.unsigned_abs().trailing_zeros());
    }
    assert_eq!(signs, [true, true], "both windings");
    assert!(exps.contains(&0) && exps.contains(&16) && exps.len() >= 12, "exponents {exps:?}");
    let cmds = frame(true, tris);
    check("power-of-two list", screen, &cmds, Drive::random("power-of-two list", 0x2_0002));
}
