//! PROOF at full scale through its generated Verilog (issue 19 item 1): every built-in scene at
//! 320x200 and 512x512 through the OPP, the shading stage and both filter stages under Verilator
//! (`tb::proof::verilated`), each compared with its cycle model on every port in every cycle, and the
//! frame and coverage equal to the golden model's algorithmic render byte for byte. The RustHDL
//! simulation and the Verilog drive the same ports in the same cycles: their recorded port traces
//! of a small frame are compared line by line. A fault put into the OPP's Verilog must be caught.
//!
//! One OPP of [`OPS`] object processors serves every scene (the castle at 512x512 needs 226); its
//! first build takes minutes and is cached in `target/verilator/proof_opp_*`.

use golden::proof::filter::FilterArea;
use golden::proof::render::{object_lists, ops_needed, shade_and_filter};
use golden::proof::setup::{scene_setup, ProofScene};
use golden::proof::study::cli_options;
use tb::common::require_tools;
use tb::proof::backend::{filter_verilator, opp_lists_verilator, shade_slots_verilator};

/// The physical OPs of the OPP these tests build (at most the scene's objects).
const OPS: usize = 256;

fn scene(name: &str, w: u32, h: u32) -> ProofScene {
    let mesh = golden::scene::builtin::scene(name).unwrap();
    scene_setup(&mesh, &cli_options(&mesh, w, h)).unwrap()
}

/// One scene at both sizes and both filter areas: the lists, the shaded stream and the images.
fn scene_through_the_verilog_equals_golden(name: &str) {
    if !require_tools(&format!("proof_verilator {name}"), &["verilator", "g++"]) {
        return;
    }
    for (w, h) in [(320, 200), (512, 512)] {
        let s = scene(name, w, h);
        let needed = ops_needed(s.screen, &s.objects) as usize;
        let n_ops = OPS.min(s.objects.len()).max(needed);
        assert!(needed <= n_ops, "{name} {w}x{h}: needs {needed} OPs");
        let lists = object_lists(s.screen, &s.objects);
        let (vl_lists, run) = opp_lists_verilator(&s, n_ops, 1, None).unwrap_or_else(|e| panic!("{name} {w}x{h} OPP: {e}"));
        assert!(vl_lists == lists, "{name} {w}x{h}: the Verilog OPP's lists differ from the golden lists");
        assert!(run.cycles >= s.screen.pixels() as u64, "{name} {w}x{h}: {} cycles", run.cycles);
        let (shaded, _) = shade_slots_verilator(&s, &lists, None).unwrap_or_else(|e| panic!("{name} {w}x{h} shading: {e}"));
        for (area, box2) in [(FilterArea::Box1, false), (FilterArea::Box2, true)] {
            let (rgb, covered) = shade_and_filter(&s, &lists, area);
            let (vl_rgb, vl_covered, _) = filter_verilator(&s, &shaded, box2, None).unwrap_or_else(|e| panic!("{name} {w}x{h} {area:?}: {e}"));
            assert!(vl_rgb == rgb, "{name} {w}x{h} {area:?}: the Verilog frame differs from golden");
            assert!(vl_covered == covered, "{name} {w}x{h} {area:?}: the Verilog coverage differs from golden");
        }
        println!("{name} {w}x{h}: {n_ops} OPs, {} OPP cycles, frames equal golden (1x1 and 2x2)", run.cycles);
    }
}

#[test]
fn the_polyhedron_through_proofs_verilog_equals_golden_at_320x200_and_512x512() {
    scene_through_the_verilog_equals_golden("polyhedron");
}

#[test]
fn the_teapot_through_proofs_verilog_equals_golden_at_320x200_and_512x512() {
    scene_through_the_verilog_equals_golden("teapot");
}

#[test]
fn the_castle_through_proofs_verilog_equals_golden_at_320x200_and_512x512() {
    scene_through_the_verilog_equals_golden("castle");
}

#[test]
fn the_dolphins_through_proofs_verilog_equals_golden_at_320x200_and_512x512() {
    scene_through_the_verilog_equals_golden("dolphins");
}

/// Issue 22: the `glass` scene's transparent objects through PROOF's Verilog at 320x200: the OPP's
/// lists keep what lies behind transparent entries, as golden's do (the OP's `opaque` bit), and
/// differ from the lists of the same objects made opaque; the 1x1 and the 2x2 filter blend them, and
/// the frames and coverage equal golden's byte for byte.
#[test]
fn the_glass_scene_through_proofs_verilog_blends_as_golden_at_320x200() {
    if !require_tools("the_glass_scene_through_proofs_verilog_blends_as_golden_at_320x200", &["verilator", "g++"]) {
        return;
    }
    let s = scene("glass", 320, 200);
    assert!(s.stats.transparent_objects > 0);
    let lists = object_lists(s.screen, &s.objects);
    let mut opaque = s.objects.clone();
    for o in &mut opaque {
        o.alpha = golden::proof::format::ALPHA_ONE;
    }
    assert!(object_lists(s.screen, &opaque) != lists, "the transparent lists must differ from the opaque ones");
    let n_ops = OPS.min(s.objects.len()).max(ops_needed(s.screen, &s.objects) as usize);
    let (vl_lists, run) = opp_lists_verilator(&s, n_ops, 1, None).unwrap_or_else(|e| panic!("glass OPP: {e}"));
    assert!(vl_lists == lists, "glass 320x200: the Verilog OPP's lists differ from the golden lists");
    let (shaded, _) = shade_slots_verilator(&s, &lists, None).unwrap_or_else(|e| panic!("glass shading: {e}"));
    println!("glass 320x200: {n_ops} OPs, {} OPP cycles, transparent lists equal golden; {} shaded slots", run.cycles, shaded.len());
    for (area, box2) in [(FilterArea::Box1, false), (FilterArea::Box2, true)] {
        let (rgb, covered) = shade_and_filter(&s, &lists, area);
        let (vl_rgb, vl_covered, cycles) = filter_verilator(&s, &shaded, box2, None).unwrap_or_else(|e| panic!("glass filter {area:?}: {e}"));
        assert!(vl_rgb == rgb, "glass 320x200 {area:?}: the Verilog frame differs from golden");
        assert!(vl_covered == covered, "glass 320x200 {area:?}: the Verilog coverage differs from golden");
        println!("glass 320x200 {area:?}: {cycles} filter cycles, blended frame equals golden");
    }
}

/// Two recorded port traces (the replay's format, one line per cycle) agree: every column in every
/// line, except an output whose guard (its valid bit) is 0 in both, which is don't-care.
fn assert_same_trace(what: &str, ports: &[tb::proof::replay::Port], a: &std::path::Path, b: &std::path::Path) {
    let (ta, tb_) = (std::fs::read_to_string(a).unwrap(), std::fs::read_to_string(b).unwrap());
    let (la, lb): (Vec<&str>, Vec<&str>) = (ta.lines().collect(), tb_.lines().collect());
    assert_eq!(la.len(), lb.len(), "{what}: {} cycles in the RustHDL trace, {} in the Verilog's", la.len(), lb.len());
    assert!(la.len() > 100, "{what}: only {} cycles", la.len());
    for (c, (x, y)) in la.iter().zip(&lb).enumerate() {
        let (cx, cy): (Vec<&str>, Vec<&str>) = (x.split(' ').collect(), y.split(' ').collect());
        for (k, p) in ports.iter().enumerate() {
            let guard_off = p.guard.is_some_and(|g| {
                let gi = ports.iter().position(|q| q.name == g).unwrap();
                cx[gi] == "0" && cy[gi] == "0"
            });
            assert!(guard_off || cx[k] == cy[k], "{what}: cycle {c}, port {}: RustHDL {} Verilog {}", p.name, cx[k], cy[k]);
        }
    }
}

/// The same small frame through the RustHDL simulation and through the generated Verilog of each
/// PROOF top: the port traces (inputs as driven, outputs as each simulator gave them) are the same.
#[test]
fn rusthdl_and_the_verilog_give_the_same_port_traces_on_a_small_frame() {
    use tb::proof::bench::{opp_ports, run_frame, run_frame_top};
    use tb::proof::filter_bench::{filter_ports, run_filter, run_filter_top};
    use tb::proof::filter2x2_bench::run_filter2x2;
    use tb::proof::shade_bench::{run_shade, run_shade_top, shade_ports};
    use tb::proof::verilated::{VlFilter, VlOpp, VlShade, TABLE_BITS};
    if !require_tools("rusthdl_and_the_verilog_give_the_same_port_traces_on_a_small_frame", &["verilator", "g++"]) {
        return;
    }
    let dir = tb::common::scratch_dir("proof_verilator_traces");
    // GLUT's teapot at grid 2 (117 objects): a RustHDL OPP of the 6178-object teapot's OPs would take hours.
    let mesh = golden::scene::builtin::teapot(2);
    let s = scene_setup(&mesh, &cli_options(&mesh, 24, 16)).unwrap();
    let n_ops = ops_needed(s.screen, &s.objects) as usize;
    let (rh, vl) = (dir.join("rusthdl.txt"), dir.join("verilog.txt"));
    let gaps = Some(golden::proof::cycle_opp::Gaps { seed: 7, source_gap_percent: 20, sink_gap_percent: 20 });
    run_frame(s.screen, &s.objects, n_ops, 1, gaps, None, Some(rh.clone())).unwrap();
    let mut top = VlOpp::new(n_ops, 1, None, Some(vl.clone())).unwrap();
    let (run, _) = run_frame_top(&mut top, s.screen, &s.objects, 1, gaps).unwrap();
    assert_same_trace("opp", &opp_ports(), &rh, &vl);

    let lists = run.lists;
    let n_lights = s.lights.l.len();
    let cfg = golden::proof::cycle_shade::shade_config(&s.lights, &s.material, n_lights, TABLE_BITS as u32).unwrap();
    let slots = golden::proof::cycle_shade::slots_of_lists(s.screen.width, &lists);
    let sg = Some(tb::proof::shade_bench::StageGaps { seed: 3, source_gap_percent: 15, sink_gap_percent: 25 });
    let (shaded, _, _) = run_shade(n_lights, TABLE_BITS, &cfg, &slots, sg, None, Some(rh.clone())).unwrap();
    let mut top = VlShade::new(n_lights, None, Some(vl.clone())).unwrap();
    run_shade_top(&mut top, &cfg, &slots, sg).unwrap();
    assert_same_trace("proof_shade", &shade_ports(), &rh, &vl);

    let dirs: Vec<_> = (0..s.objects.len()).map(|i| golden::proof::render::dirs_of(&s, i as u16)).collect();
    let fcfg = golden::proof::cycle_filter::filter_config(&dirs, s.background, TABLE_BITS as u32).unwrap();
    run_filter(TABLE_BITS, &fcfg, &shaded, sg, None, Some(rh.clone())).unwrap();
    let mut top = VlFilter::box1(None, Some(vl.clone())).unwrap();
    run_filter_top(&mut top, &fcfg, &shaded, sg).unwrap();
    assert_same_trace("proof_filter", &filter_ports(), &rh, &vl);

    run_filter2x2(TABLE_BITS, 24, 16, &fcfg, &shaded, sg, None, Some(rh.clone())).unwrap();
    let mut top = VlFilter::box2(24, 16, None, Some(vl.clone())).unwrap();
    run_filter_top(&mut top, &fcfg, &shaded, sg).unwrap();
    assert_same_trace("proof_filter2x2", &filter_ports(), &rh, &vl);
}

/// The comparison catches a wrong Verilog: OP 0 of a two-OP OPP also loads when OP 1 is addressed.
#[test]
fn a_fault_in_the_opps_verilog_is_caught_by_the_cycle_comparison() {
    use tb::proof::verilated::VlOpp;
    if !require_tools("a_fault_in_the_opps_verilog_is_caught_by_the_cycle_comparison", &["verilator", "g++"]) {
        return;
    }
    let s = scene("polyhedron", 32, 20);
    let good = hdl::proof::verilog_opp("opp", 2, 1).unwrap();
    let line = "ops$0$load = load & (load_op == op_ids$0);";
    assert!(good.contains(line), "the OPP Verilog no longer has the line this test changes");
    let bad = good.replace(line, "ops$0$load = load & (load_op == op_ids$1);");
    let mut top = VlOpp::from_verilog("proof_opp_fault_test", &bad, 2, 1, None, None).unwrap();
    let err = tb::proof::bench::run_frame_top(&mut top, s.screen, &s.objects, 1, None).err();
    let err = err.expect("the faulty OPP Verilog went unnoticed");
    assert!(err.contains("opp (Verilator) at cycle"), "{err}");
    // The same run on the good text passes.
    let mut top = VlOpp::new(2, 1, None, None).unwrap();
    tb::proof::bench::run_frame_top(&mut top, s.screen, &s.objects, 1, None).unwrap();
}

/// Issue 19 item 2 at full scale: the castle at 512x512 needs 226 OPs; through the Verilog of a
/// 32-OP OPP it takes passes, its lists fed back each time, and builds the golden lists.
#[test]
fn the_castle_at_512x512_through_a_32_op_verilog_opp_in_passes_builds_the_golden_lists() {
    if !require_tools("the_castle_at_512x512_through_a_32_op_verilog_opp_in_passes_builds_the_golden_lists", &["verilator", "g++"]) {
        return;
    }
    let s = scene("castle", 512, 512);
    let lists = object_lists(s.screen, &s.objects);
    let (vl_lists, run) = opp_lists_verilator(&s, 32, 1, None).unwrap();
    let model = golden::proof::cycle_opp::run_opp(s.screen, &s.objects, 32, 1, None).unwrap();
    assert!(vl_lists == lists, "the lists after {} passes differ from the golden lists", run.passes);
    assert_eq!((run.passes, run.cycles, run.feedback_slots), (model.passes, model.cycles, model.feedback_slots));
    assert!(run.passes >= 226usize.div_ceil(32), "{} passes", run.passes);
    println!("castle 512x512, 32 OPs: {} passes, {} cycles, {} slots fed back at most", run.passes, run.cycles, run.feedback_slots);
}
