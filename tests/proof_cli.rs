//! `idxrender render --arch proof` end to end: the files it writes, its errors, and that the RTL
//! backend's image equals the golden one byte for byte.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_idxrender"))
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("idxrender-proof-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(args: &[&str]) -> (bool, String, String) {
    let o = bin().args(args).output().expect("run idxrender");
    (o.status.success(), String::from_utf8_lossy(&o.stdout).into(), String::from_utf8_lossy(&o.stderr).into())
}

#[test]
fn proof_render_writes_an_antialiased_frame_a_coverage_image_and_stats() {
    let out = temp_dir("poly");
    let o = out.to_str().unwrap();
    let (ok, stdout, err) = run(&["render", "--arch", "proof", "--scene", "polyhedron", "--size", "96x60", "--out", o]);
    assert!(ok, "{err}");
    assert!(stdout.contains("OPs needed"), "{stdout}");
    let frame = image::open(out.join("frame.png")).unwrap().to_rgb8();
    let cov = image::open(out.join("coverage.png")).unwrap().to_rgb8();
    assert_eq!((frame.width(), frame.height()), (96, 60));
    // Anti-aliasing: some pixels are partially covered (grey strictly between 0 and 255).
    assert!(cov.pixels().any(|p| p[0] > 0 && p[0] < 255), "no partially covered pixel in coverage.png");
    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
    assert_eq!(stats["stats"]["ops_needed"], 2);
    assert!(stats["opp"]["cycles"].as_u64().unwrap() >= 96 * 60);
}

/// The OPP, shading and filter stages all in RTL (OPP -> shading -> filter), as RustHDL simulations
/// and as generated Verilog under Verilator, against the golden model, with both filter areas (1x1:
/// `proof_filter`; the paper's 2x2: `proof_filter2x2`): the PNG files must be identical, and
/// stats.json must say which backend ran the filter.
#[test]
fn proof_rtl_and_verilator_backend_frames_equal_the_golden_frame_byte_for_byte() {
    if !tb::common::require_tools("proof_rtl_and_verilator_backend_frames_equal_the_golden_frame_byte_for_byte", &["verilator", "g++"]) {
        return;
    }
    for (scene, extra) in [("polyhedron", vec!["--size", "64x40"]), ("teapot", vec!["--grid", "2", "--size", "48x30"])] {
        let mut frames = Vec::new();
        for (filter, top) in [("1x1", "proof_filter"), ("2x2", "proof_filter2x2")] {
            let mut files = Vec::new();
            for backend in ["golden", "rtl", "verilator"] {
                let out = temp_dir(&format!("{scene}-{filter}-{backend}"));
                let mut args = vec!["render", "--arch", "proof", "--scene", scene, "--filter", filter, "--backend", backend, "--out", out.to_str().unwrap()];
                args.extend(extra.iter());
                let (ok, stdout, err) = run(&args);
                assert!(ok, "{scene} {filter} {backend}: {err}");
                files.push((std::fs::read(out.join("frame.png")).unwrap(), std::fs::read(out.join("coverage.png")).unwrap()));
                if backend != "golden" {
                    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
                    let st = &stats["rtl_stage_cycles"];
                    assert_eq!((st["filter_backend"].as_str(), st["filter_top"].as_str()), (Some(backend), Some(top)), "{scene} {filter}: {stats}");
                    assert!(st["filter"].as_u64().unwrap() > 0, "{scene} {filter}: no filter cycles in {stats}");
                    assert!(stdout.contains(&format!("{backend}: shading stage")), "{scene} {filter}: {stdout}");
                    assert!(stdout.contains(&format!("filter stage ({top}, {filter} area)")), "{scene} {filter}: {stdout}");
                    assert!(!stdout.contains("golden"), "{scene} {filter}: the RTL run mentions the golden model: {stdout}");
                }
            }
            assert!(files[0] == files[1], "{scene} {filter}: the RTL backend's images differ from the golden model's");
            assert!(files[0] == files[2], "{scene} {filter}: the Verilator backend's images differ from the golden model's");
            frames.push(files.swap_remove(0).0);
        }
        assert!(frames[0] != frames[1], "{scene}: the 2x2 frame should differ from the 1x1 frame");
    }
}

/// Fewer OPs than the frame needs (issue 19 item 2): the lists go round again in passes, through
/// every backend, and the frame is the one-pass frame; stats.json counts the passes and the memory.
#[test]
fn fewer_ops_than_needed_render_the_same_frame_in_passes_on_every_backend() {
    if !tb::common::require_tools("fewer_ops_than_needed_render_the_same_frame_in_passes_on_every_backend", &["verilator", "g++"]) {
        return;
    }
    let render = |name: &str, extra: &[&str]| -> (Vec<u8>, serde_json::Value, String) {
        let out = temp_dir(name);
        let mut a = vec!["render", "--arch", "proof", "--scene", "teapot", "--grid", "2", "--size", "40x25", "--out", out.to_str().unwrap()];
        a.extend(extra);
        let (ok, stdout, err) = run(&a);
        assert!(ok, "{a:?}: {err}");
        let stats = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
        (std::fs::read(out.join("frame.png")).unwrap(), stats, stdout)
    };
    let (one, stats, _) = render("passes-one", &[]);
    assert_eq!(stats["opp"]["passes"], 1);
    let needed = stats["stats"]["ops_needed"].as_u64().unwrap();
    assert!(needed > 8, "teapot grid 2 at 40x25 needs {needed} OPs");
    for backend in ["golden", "rtl", "verilator"] {
        let (frame, stats, stdout) = render(&format!("passes-{backend}"), &["--ops", "8", "--backend", backend]);
        assert!(frame == one, "{backend}: the frame in passes differs from the one-pass frame");
        let passes = stats["opp"]["passes"].as_u64().unwrap();
        assert!(passes >= needed.div_ceil(8), "{backend}: {passes} passes for {needed} OPs needed with 8");
        assert!(stats["feedback_bytes"].as_u64().unwrap() > 0, "{backend}: {stats}");
        assert!(stdout.contains(&format!("{passes} passes")), "{backend}: {stdout}");
    }
}

/// The 2x2 RTL's line buffer needs a screen at least 2 pixels wide: said before any simulation.
#[test]
fn proof_rtl_2x2_filter_on_a_one_pixel_wide_screen_is_a_clear_error() {
    let out = temp_dir("narrow");
    let a = ["render", "--arch", "proof", "--scene", "polyhedron", "--size", "1x20", "--filter", "2x2", "--backend", "rtl", "--out", out.to_str().unwrap()];
    let (ok, _, err) = run(&a);
    assert!(!ok && !err.contains("panicked") && err.contains("1x20") && err.contains("width must be 2..=1024"), "{err}");
    // The golden model filters any screen.
    let (ok, _, err) = run(&["render", "--arch", "proof", "--scene", "polyhedron", "--size", "1x20", "--filter", "2x2", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
}

#[test]
fn proof_bad_options_are_clear_errors() {
    for (args, needle) in [
        (vec!["--filter", "3x3"], "filter"),
        (vec!["--fifo-depth", "0"], "fifo-depth"),
        (vec!["--ops", "0"], "at least one object processor"),
        // The RTL backends build an OPP of N OPs: refused above 1024 before any work.
        (vec!["--scene", "teapot", "--ops", "1025", "--backend", "verilator"], "at most 1024"),
        (vec!["--scene", "teapot", "--ops", "2000", "--backend", "rtl"], "at most 1024"),
        // Issue 18: this count used to be allocated until the process was killed.
        (vec!["--ops", "100000000"], "at most 2 object processors"),
        (vec!["--vcd"], "--vcd needs --backend rtl or --backend verilator"),
    ] {
        let out = temp_dir("bad");
        let mut a = vec!["render", "--arch", "proof", "--size", "32x20", "--out", out.to_str().unwrap()];
        if !args.contains(&"--scene") {
            a.extend(["--scene", "polyhedron"]);
        }
        a.extend(args.iter());
        let (ok, _, err) = run(&a);
        assert!(!ok && !err.contains("panicked") && err.contains(needle), "{a:?}: {err}");
    }
}

/// The figures in docs/proof.md come from `golden::proof::study` (`proof_figures`): it must set the
/// scene up exactly as the CLI does by default, so the OPs needed and the OPP cycles agree.
#[test]
fn the_proof_study_uses_the_clis_default_camera_and_options() {
    for scene in ["castle", "dolphins"] {
        let out = temp_dir(&format!("study-{scene}"));
        let (ok, _, err) = run(&["render", "--arch", "proof", "--scene", scene, "--size", "80x50", "--out", out.to_str().unwrap()]);
        assert!(ok, "{scene}: {err}");
        let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
        let mesh = golden::scene::builtin::scene(scene).unwrap();
        let row = golden::proof::study::fifo_row(scene, &mesh, 80, 50, &[1]).unwrap();
        assert_eq!(stats["stats"]["ops_needed"].as_u64().unwrap() as usize, row.ops_needed, "{scene}: OPs needed");
        assert_eq!(stats["opp"]["cycles"].as_u64().unwrap(), row.runs[0].cycles, "{scene}: OPP cycles");
        assert_eq!(stats["stats"]["setup"]["objects"].as_u64().unwrap() as usize, row.objects, "{scene}: objects");
    }
}

/// Issue 22: the glass scene (transparent panes and teapot) renders through PROOF's golden model
/// (whose OPP cycle model must build the same lists), and stats.json counts its transparent objects;
/// `--opacity` applies to any scene; the chipset refuses transparency by name, before writing anything.
#[test]
fn the_glass_scene_renders_transparent_through_proof_and_is_refused_where_nothing_blends() {
    let out = temp_dir("glass");
    let o = out.to_str().unwrap();
    let (ok, _, err) = run(&["render", "--arch", "proof", "--scene", "glass", "--size", "96x60", "--out", o]);
    assert!(ok, "{err}");
    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
    let transparent = stats["stats"]["setup"]["transparent_objects"].as_u64().unwrap();
    let objects = stats["stats"]["setup"]["objects"].as_u64().unwrap();
    assert!(transparent > 0 && transparent < objects, "{transparent} of {objects}");

    // --opacity 1 makes it opaque: fewer entries (lists end at the panes and the teapot).
    let opaque = temp_dir("glass-opaque");
    let (ok, _, err) = run(&["render", "--arch", "proof", "--scene", "glass", "--opacity", "1", "--size", "96x60", "--out", opaque.to_str().unwrap()]);
    assert!(ok, "{err}");
    let stats1: serde_json::Value = serde_json::from_slice(&std::fs::read(opaque.join("stats.json")).unwrap()).unwrap();
    assert_eq!(stats1["stats"]["setup"]["transparent_objects"], 0);
    assert!(stats1["stats"]["entries"].as_u64() < stats["stats"]["entries"].as_u64());

    for (args, says) in [
        (vec!["render", "--scene", "glass"], "index-rendering chipset keeps one triangle per pixel"),
        (vec!["render", "--scene", "teapot", "--opacity", "0.5"], "--arch proof"),
        (vec!["render", "--arch", "proof", "--scene", "teapot", "--opacity", "1.5"], "--opacity 1.5 is not in 0..=1"),
        (vec!["render", "--arch", "proof", "--scene", "teapot", "--opacity", "NaN"], "is not in 0..=1"),
    ] {
        let d = temp_dir("refused");
        let mut a = args.clone();
        a.extend(["--size", "32x20", "--out", d.to_str().unwrap()]);
        let (ok, _, err) = run(&a);
        assert!(!ok && err.contains(says), "{args:?}: {err}");
        assert!(!d.join("frame.png").exists(), "{args:?} wrote a frame");
    }
}

/// Issue 22: transparent frames through PROOF's RTL (OPP -> shading -> the blending filter) as
/// RustHDL simulations and as Verilog under Verilator equal the golden frame byte for byte: the
/// teapot at opacity 0.5 through the 1x1 and the 2x2 filter, and `glass` (with 8 OPs, so its lists
/// take passes, which keeps the RustHDL OPP small).
#[test]
fn transparent_frames_through_the_rtl_and_verilator_backends_equal_the_golden_frame_byte_for_byte() {
    if !tb::common::require_tools("transparent_frames_through_the_rtl_and_verilator_backends_equal_the_golden_frame_byte_for_byte", &["verilator", "g++"]) {
        return;
    }
    for (scene, extra) in [
        ("teapot", vec!["--grid", "2", "--opacity", "0.5", "--size", "48x30"]),
        ("teapot", vec!["--grid", "2", "--opacity", "0.5", "--size", "48x30", "--filter", "2x2"]),
        ("glass", vec!["--ops", "8", "--size", "40x25"]),
    ] {
        let mut files = Vec::new();
        for backend in ["golden", "rtl", "verilator"] {
            let out = temp_dir(&format!("transparent-{scene}-{}-{backend}", extra.len()));
            let mut args = vec!["render", "--arch", "proof", "--scene", scene, "--backend", backend, "--out", out.to_str().unwrap()];
            args.extend(extra.iter());
            let (ok, _, err) = run(&args);
            assert!(ok, "{scene} {backend}: {err}");
            let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
            assert!(stats["stats"]["setup"]["transparent_objects"].as_u64().unwrap() > 0, "{scene}: {stats}");
            files.push((std::fs::read(out.join("frame.png")).unwrap(), std::fs::read(out.join("coverage.png")).unwrap()));
        }
        assert!(files[0] == files[1], "{scene} {extra:?}: the RTL backend's images differ from the golden model's");
        assert!(files[0] == files[2], "{scene} {extra:?}: the Verilator backend's images differ from the golden model's");
    }
}

/// MTL opacity: `d`, else 1 - `Tr`; a value outside 0..=1 makes the library unusable, as any bad MTL
/// line does: a warning naming the line and the fallback (grey plastic, opaque), on the CLI too.
#[test]
fn mtl_dissolve_and_tr_set_the_opacity_and_bad_values_name_their_line() {
    let dir = temp_dir("mtl");
    let obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl half\nf 1 2 3\nusemtl tr\nf 2 4 3\n";
    std::fs::write(dir.join("a.obj"), obj).unwrap();
    std::fs::write(dir.join("m.mtl"), "newmtl half\nKd 1 0 0\nd 0.5\nnewmtl tr\nKd 0 1 0\nTr 0.25\n").unwrap();
    let (mesh, _) = golden::scene::obj::load_obj_with_warnings(&dir.join("a.obj")).unwrap();
    let mut opacities: Vec<f64> = mesh.materials.iter().map(|m| m.opacity).collect();
    opacities.sort_by(f64::total_cmp);
    assert_eq!(opacities, vec![0.5, 0.75]);
    std::fs::write(dir.join("m.mtl"), "newmtl half\nKd 1 0 0\n\nd NaN\n").unwrap();
    let (mesh, warnings) = golden::scene::obj::load_obj_with_warnings(&dir.join("a.obj")).unwrap();
    assert!(warnings.iter().any(|w| w.contains("line 4") && w.contains("`d` needs one number in 0..=1")), "{warnings:?}");
    assert!(mesh.materials.iter().all(|m| m.opacity == 1.0));
    let out = temp_dir("mtl-out");
    let (ok, _, err) = run(&["render", "--arch", "proof", "--obj", dir.join("a.obj").to_str().unwrap(), "--size", "32x20", "--out", out.to_str().unwrap()]);
    assert!(ok && err.contains("line 4") && err.contains("grey plastic"), "{err}");
}
