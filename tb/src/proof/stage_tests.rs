//! Tests of PROOF's shading and filter stages (run with `cargo test --release -p tb proof`).

use super::shade_bench::{run_shade, StageGaps};
use crate::common::{require_tools, scratch_dir, vcd_path, vcd_wanted, Rng};
use golden::proof::cycle_shade::{shade_config, slots_of_lists, ShadedSlot};
use golden::proof::format::{Entry, Slot};
use golden::proof::render::object_lists;
use golden::proof::setup::{scene_setup, ProofScene};
use golden::proof::shade::shade_entry;
use golden::shade::PhongLights;

pub fn scene(name: &str, grid: u32, w: u32, h: u32) -> ProofScene {
    use golden::raster::{CullMode, FrontFace};
    let mesh = if name == "teapot" { golden::scene::builtin::teapot(grid) } else { golden::scene::builtin::scene(name).unwrap() };
    let opts = golden::render::RenderOptions {
        screen: golden::format::Screen::new(w, h).unwrap(),
        camera: golden::host::Camera::framing(&mesh, [0.3, 0.45, 1.0], 40.0),
        shading: golden::shade::Shading::Gouraud,
        cull: CullMode::Back,
        front: if mesh.front_face == golden::scene::Winding::Cw { FrontFace::Cw } else { FrontFace::Ccw },
        lighting: golden::host::Lighting::default(),
        index_bits: 16,
        rc_type: golden::raster::RcType::IV,
        texturing: None,
        background: [24, 24, 40],
    };
    scene_setup(&mesh, &opts).unwrap()
}

/// Run the shading bench; on a failure rerun it with a waveform and panic with the report.
fn shade_or_panic(name: &str, seed: u64, n_lights: usize, bits: usize, cfg: &[golden::proof::cycle_shade::CfgWrite], slots: &[Slot], gaps: StageGaps) -> (Vec<ShadedSlot>, u64) {
    let vcd = if vcd_wanted() { Some(vcd_path("proof", name)) } else { None };
    match run_shade(n_lights, bits, cfg, slots, Some(gaps), vcd.as_deref(), None) {
        Ok((o, c, _)) => (o, c),
        Err(e) => {
            let p = vcd_path("proof", name);
            let _ = run_shade(n_lights, bits, cfg, slots, Some(gaps), Some(&p), None);
            panic!("{name} (seed {seed}, SEED=n replays): {e}; waveform {}", p.display());
        }
    }
}

fn check_colours(what: &str, lights: &PhongLights, material: &[u16], slots: &[Slot], out: &[ShadedSlot]) {
    assert_eq!(out.len(), slots.len(), "{what}: slot count");
    for (s, o) in slots.iter().zip(out) {
        assert_eq!((o.x, o.y, o.last, o.has_entry, o.id, o.full, o.dist), (s.x, s.y, s.last, s.has_entry, s.entry.id, s.entry.full, s.entry.dist), "{what}");
        let want = if s.has_entry { shade_entry(lights, s.entry.normal, material[s.entry.id as usize]) } else { [0; 3] };
        assert_eq!(o.rgb, want, "{what}: pixel ({}, {}) id {} normal {:?}", s.x, s.y, s.entry.id, s.entry.normal);
    }
}

#[test]
fn shading_stage_matches_its_cycle_model_every_cycle_on_polyhedron_and_teapot_lists_with_random_gaps() {
    let mut rng = Rng::new(0x5ade);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    for (name, grid, w, h) in [("polyhedron", 0, 40, 25), ("teapot", 2, 40, 25)] {
        let sc = scene(name, grid, w, h);
        let lists = object_lists(sc.screen, &sc.objects);
        let slots = slots_of_lists(w, &lists);
        let cfg = shade_config(&sc.lights, &sc.material, 1, 10).unwrap();
        let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 20, sink_gap_percent: 30 };
        let t0 = std::time::Instant::now();
        let (out, cycles) = shade_or_panic("shade_every_cycle", seed, 1, 10, &cfg, &slots, gaps);
        println!("{name} {w}x{h}: {} slots, {cycles} cycles in {:?}", slots.len(), t0.elapsed());
        check_colours(name, &sc.lights, &sc.material, &slots, &out);
    }
}

/// Random entries (normals up to the saturated extremes) under two lights and five materials with
/// gloss 1, 2, 4, 8, 16, so that every squaring stage is used and skipped.
#[test]
fn two_light_shading_stage_with_every_gloss_matches_its_cycle_model_and_the_golden_shading() {
    let mut rng = Rng::new(0x2_119);
    let seed = rng.seed();
    println!("seed {seed} (SEED=n replays)");
    let lighting = golden::host::Lighting {
        ambient: [0.2, 0.1, 0.3],
        lights: vec![
            golden::host::Light { direction: golden::host::normalize([-0.4, 0.6, 0.7]), intensity: [0.85, 0.7, 0.6] },
            golden::host::Light { direction: golden::host::normalize([0.5, -0.2, 0.8]), intensity: [0.3, 0.4, 0.5] },
        ],
    };
    let mats: Vec<golden::scene::Material> = [1, 2, 4, 8, 16]
        .iter()
        .enumerate()
        .map(|(k, &g)| golden::scene::Material { ambient: [0.3, 0.5, 0.9], diffuse: [0.9, 0.4 + 0.1 * k as f64, 0.2], specular: [0.6, 0.6, 0.6], gloss: g, opacity: 1.0, texture: None })
        .collect();
    let lights = PhongLights::new(&lighting, &mats);
    let material: Vec<u16> = (0..40).map(|i| (i % 5) as u16).collect();
    let mut slots = Vec::new();
    for p in 0..300u32 {
        let n = 1 + rng.below(3) as usize;
        for k in 0..n {
            let comp = |r: &mut Rng| if r.chance(10) { [-32768i64, 32767, 0, 16384][r.below(4) as usize] as i16 } else { (r.below(40000) as i64 - 20000) as i16 };
            let e = Entry { id: rng.below(40) as u16, depth: 0, full: rng.chance(30), normal: [comp(&mut rng), comp(&mut rng), comp(&mut rng)], dist: [1, -2, 3] };
            let empty = rng.chance(10);
            slots.push(Slot { x: (p % 32) as u16, y: (p / 32) as u16, last: empty || k + 1 == n, has_entry: !empty, entry: e });
            if empty {
                break;
            }
        }
    }
    let cfg = shade_config(&lights, &material, 2, 6).unwrap();
    let gaps = StageGaps { seed: rng.next_u64(), source_gap_percent: 30, sink_gap_percent: 40 };
    let (out, _) = shade_or_panic("shade_two_lights_every_cycle", seed, 2, 6, &cfg, &slots, gaps);
    check_colours("two lights", &lights, &material, &slots, &out);
    assert!(out.iter().any(|o| o.rgb.iter().any(|&c| c == 255)), "the stimulus should saturate a colour");
}

#[test]
fn shading_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches() {
    if !require_tools("shading_verilog_replays_the_recorded_vectors_lints_clean_and_synthesizes_without_latches", &["iverilog", "verilator", "yosys"]) {
        return;
    }
    let sc = scene("teapot", 2, 24, 16);
    let lists = object_lists(sc.screen, &sc.objects);
    let slots = slots_of_lists(24, &lists);
    let cfg = shade_config(&sc.lights, &sc.material, 1, 8).unwrap();
    let dir = scratch_dir("proof_shade_replay");
    let gaps = StageGaps { seed: 77, source_gap_percent: 25, sink_gap_percent: 25 };
    let (out, _, rec) = run_shade(1, 8, &cfg, &slots, Some(gaps), None, Some(dir.join("shade_vectors.txt"))).unwrap();
    check_colours("replay stimulus", &sc.lights, &sc.material, &slots, &out);
    let (vp, cycles) = rec.unwrap();
    let v = hdl::proof::verilog_shading("proof_shade8", 1, 8).unwrap();
    for sim in ["iverilog", "verilator"] {
        let d = scratch_dir(&format!("proof_shade_replay_{sim}"));
        let verdict = super::replay::replay(sim, &d, "proof_shade8", &super::shade_bench::shade_ports(), &v, &vp, cycles)
            .unwrap_or_else(|e| panic!("{sim}: {e}"));
        println!("{sim}: {verdict}");
        assert!(verdict.contains(&cycles.to_string()));
    }
    // Lint the top that `idxrender verilog --block proof_shade` writes, with the project's waivers.
    let top = hdl::verilog_top("proof_shade").unwrap();
    crate::lint::lint(&top, "proof_shade", &dir).unwrap_or_else(|e| panic!("{e}"));
    synth_without_latches(&dir, "proof_shade8", &v);
}

/// `synth_ice40 -dsp`; asserts no latches and a plausible netlist; returns the stat text.
pub fn synth_without_latches(dir: &std::path::Path, top: &str, v: &str) -> String {
    use std::process::Command;
    std::fs::write(dir.join(format!("{top}.v")), v).unwrap();
    let o = Command::new("yosys")
        .current_dir(dir)
        .args(["-q", "-p", &format!("read_verilog {top}.v; synth_ice40 -dsp -top {top}; tee -o {top}_stat.txt stat")])
        .output()
        .unwrap();
    assert!(o.status.success(), "yosys: {}", String::from_utf8_lossy(&o.stderr));
    let stat = std::fs::read_to_string(dir.join(format!("{top}_stat.txt"))).unwrap();
    println!("{stat}");
    assert!(!stat.contains("LATCH") && !stat.contains("$dlatch"), "latches in the netlist:\n{stat}");
    let count = |cell: &str| -> u64 {
        stat.lines().filter(|l| l.trim_start().starts_with(cell)).filter_map(|l| l.split_whitespace().last()?.parse::<u64>().ok()).sum()
    };
    assert!(count("SB_LUT4") > 50 && count("SB_DFF") > 50, "implausible netlist:\n{stat}");
    stat
}
