//! The `render` command end to end: every built-in scene produces its four files, and every kind of
//! bad input gives an error that names the problem, exits non-zero, never panics, and leaves the files
//! of an earlier run untouched.

use std::path::{Path, PathBuf};
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_idxrender"))
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("idxrender-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Run and return (success, stdout, stderr).
fn run(args: &[&str]) -> (bool, String, String) {
    let o = bin().args(args).output().expect("run idxrender");
    (o.status.success(), String::from_utf8_lossy(&o.stdout).into(), String::from_utf8_lossy(&o.stderr).into())
}

fn assert_clean_error(args: &[&str], needle: &str) {
    let (ok, _, err) = run(args);
    assert!(!ok, "{args:?} should fail");
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    assert!(err.to_lowercase().contains(&needle.to_lowercase()), "{args:?}: error does not mention '{needle}': {err}");
}

fn png_size(path: &Path) -> (u32, u32) {
    let img = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (img.width(), img.height())
}

#[test]
fn every_builtin_scene_writes_frame_index_and_stats() {
    for scene in ["polyhedron", "teapot", "castle", "dolphins"] {
        let out = temp_dir(scene);
        let (ok, stdout, err) = run(&["render", "--scene", scene, "--out", out.to_str().unwrap()]);
        assert!(ok, "{scene}: {err}");
        assert!(stdout.contains("triangles in (a)"), "{stdout}");
        assert_eq!(png_size(&out.join("frame.png")), (320, 200));
        assert_eq!(png_size(&out.join("index.png")), (320, 200));
        let index = std::fs::read(out.join("index.bin")).unwrap();
        assert_eq!(index.len(), 320 * 200 * 4);
        let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
        let s = &stats["stats"];
        let a = s["triangles_in"].as_u64().unwrap();
        let c = s["visible_final"].as_u64().unwrap();
        assert!(c > 0 && c <= s["flagged_visible"].as_u64().unwrap() && c <= a, "{scene}: {s}");
        // Every index in index.bin names an input triangle.
        let max = index.chunks(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).max().unwrap();
        assert!(max as u64 <= a && max > 0, "{scene}: max index {max} of {a}");
    }
}

#[test]
fn shading_modes_and_cull_options_render() {
    let out = temp_dir("modes");
    for args in [
        vec!["--shading", "flat"],
        vec!["--shading", "phong"],
        vec!["--cull", "none"],
        vec!["--cull", "front", "--front-face", "cw"],
        vec!["--size", "64x48", "--eye", "0,0,5", "--center", "0,0,0", "--fovy", "60"],
    ] {
        let mut a = vec!["render", "--scene", "polyhedron", "--out", out.to_str().unwrap()];
        a.extend(args.iter());
        let (ok, _, err) = run(&a);
        assert!(ok, "{a:?}: {err}");
    }
}

#[test]
fn bad_arguments_give_errors_naming_the_problem() {
    let o = temp_dir("bad");
    let o = o.to_str().unwrap();
    assert_clean_error(&["render", "--scene", "nope", "--out", o], "nope");
    assert_clean_error(&["render", "--out", o], "--scene");
    assert_clean_error(&["render", "--scene", "teapot", "--size", "320", "--out", o], "WxH");
    assert_clean_error(&["render", "--scene", "teapot", "--size", "2000x10", "--out", o], "2000x10");
    assert_clean_error(&["render", "--scene", "teapot", "--size", "0x10", "--out", o], "0x10");
    assert_clean_error(&["render", "--scene", "teapot", "--eye", "1,2", "--out", o], "--eye");
    assert_clean_error(&["render", "--scene", "teapot", "--eye", "1,nan,2", "--out", o], "finite");
    assert_clean_error(&["render", "--scene", "teapot", "--eye", "0,0,0", "--center", "0,0,0", "--out", o], "same point");
    assert_clean_error(&["render", "--scene", "teapot", "--fovy", "200", "--out", o], "fovy");
    assert_clean_error(&["render", "--scene", "teapot", "--near", "-1", "--out", o], "near");
    assert_clean_error(&["render", "--scene", "teapot", "--near", "5", "--far", "2", "--out", o], "near");
    assert_clean_error(&["render", "--scene", "teapot", "--up", "0,0,0", "--out", o], "up");
    assert_clean_error(&["render", "--scene", "teapot", "--shading", "toon", "--out", o], "toon");
    assert_clean_error(&["render", "--scene", "teapot", "--grid", "0", "--out", o], "grid");
    assert_clean_error(&["render", "--scene", "teapot", "--bogus"], "bogus");
}

/// Camera values that used to be reported as something else (issue 18): a zero or vanishing field of
/// view, and positions whose squares overflow f64.
#[test]
fn camera_errors_name_the_argument_at_fault() {
    let o = temp_dir("camera");
    let o = o.to_str().unwrap();
    // Was "must be finite numbers" (the default view divided by tan(0)).
    assert_clean_error(&["render", "--scene", "teapot", "--fovy", "0", "--out", o], "--fovy 0.0: the vertical field of view must be in (0, 180)");
    // Was "up is zero or parallel to the viewing direction".
    assert_clean_error(&["render", "--scene", "teapot", "--fovy", "1e-300", "--out", o], "--fovy 1e-300: the default view would put the eye");
    // Was "must be finite numbers" (the far plane overflowed).
    assert_clean_error(&["render", "--scene", "teapot", "--eye", "1e200,0,0", "--out", o], "--eye 1e200,0.0,0.0: 1e200 is outside +-1e15");
    assert_clean_error(&["render", "--scene", "teapot", "--center", "0,-2e16,0", "--out", o], "--center");
}

/// Options that do not apply to what is rendered are errors, not ignored in silence (issue 18).
#[test]
fn options_that_do_not_apply_are_errors() {
    let o = temp_dir("apply");
    let o = o.to_str().unwrap();
    assert_clean_error(&["render", "--scene", "castle", "--grid", "3", "--out", o], "--grid applies to --scene teapot only");
    assert_clean_error(&["render", "--scene", "polyhedron", "--ops", "4", "--out", o], "--ops applies to --arch proof only");
    assert_clean_error(&["render", "--scene", "polyhedron", "--fifo-depth", "2", "--filter", "2x2", "--out", o], "--fifo-depth, --filter applies to --arch proof only");
    assert_clean_error(&["render", "--scene", "polyhedron", "--arch", "proof", "--index-bits", "12", "--out", o], "--index-bits applies to --arch index only");
    // The defaults still apply where the option belongs.
    let (ok, _, err) = run(&["render", "--scene", "teapot", "--grid", "2", "--size", "32x20", "--out", o]);
    assert!(ok, "{err}");
}

#[test]
fn more_triangles_than_the_index_width_allows_is_an_error() {
    let o = temp_dir("index");
    // 12544 teapot triangles do not fit 8-bit indices (255 usable).
    assert_clean_error(&["render", "--scene", "teapot", "--index-bits", "8", "--out", o.to_str().unwrap()], "8-bit triangle index");
    assert_clean_error(&["render", "--scene", "teapot", "--index-bits", "40", "--out", o.to_str().unwrap()], "index width");
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn bad_obj_files_give_errors_naming_file_and_line() {
    let d = temp_dir("obj");
    let o = d.join("out");
    let o = o.to_str().unwrap();
    let missing = d.join("missing.obj");
    assert_clean_error(&["render", "--obj", missing.to_str().unwrap(), "--out", o], "missing.obj");
    let nan = write(&d, "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n");
    assert_clean_error(&["render", "--obj", nan.to_str().unwrap(), "--out", o], "nan.obj:3");
    let inf = write(&d, "inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
    assert_clean_error(&["render", "--obj", inf.to_str().unwrap(), "--out", o], "inf.obj:3");
    let range = write(&d, "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    assert_clean_error(&["render", "--obj", range.to_str().unwrap(), "--out", o], "range.obj:4");
    let malformed = write(&d, "bad.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
    assert_clean_error(&["render", "--obj", malformed.to_str().unwrap(), "--out", o], "bad.obj:2");
    let empty = write(&d, "empty.obj", "# nothing\n");
    assert_clean_error(&["render", "--obj", empty.to_str().unwrap(), "--out", o], "empty.obj");
}

#[test]
fn obj_files_with_quads_and_degenerate_or_off_screen_triangles_render() {
    let d = temp_dir("objok");
    // A quad (triangulated), a zero-area triangle, and a triangle far off to the side.
    let f = write(
        &d,
        "ok.obj",
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 0\nv 0 0 0\nv 50 0 0\nv 51 0 0\nv 50 1 0\nf 1 2 3 4\nf 5 6 5\nf 7 8 9\n",
    );
    let out = d.join("out");
    let (ok, _, err) = run(&["render", "--obj", f.to_str().unwrap(), "--eye", "0,0,4", "--center", "0,0,0", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
    assert_eq!(stats["stats"]["triangles_in"], 4);
    assert_eq!(stats["stats"]["visible_final"], 2);
}

#[test]
fn a_failed_run_leaves_the_previous_outputs_untouched() {
    let out = temp_dir("keep");
    let o = out.to_str().unwrap();
    let (ok, _, err) = run(&["render", "--scene", "polyhedron", "--out", o]);
    assert!(ok, "{err}");
    let before: Vec<Vec<u8>> = ["frame.png", "index.bin", "index.png", "stats.json"].iter().map(|f| std::fs::read(out.join(f)).unwrap()).collect();
    assert_clean_error(&["render", "--scene", "teapot", "--index-bits", "4", "--out", o], "index");
    let after: Vec<Vec<u8>> = ["frame.png", "index.bin", "index.png", "stats.json"].iter().map(|f| std::fs::read(out.join(f)).unwrap()).collect();
    assert!(before == after, "outputs changed by a failed run");
}

/// Every file of a folder, name and bytes, sorted.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .map(|e| (e.file_name().to_string_lossy().into_owned(), std::fs::read(e.path()).unwrap()))
        .collect();
    v.sort();
    v
}

/// The folder holding `out`, without the staging folders of a run (`.NAME.new-PID`, `.NAME.old-PID`).
fn leftovers(out: &Path) -> Vec<String> {
    let parent = out.parent().unwrap();
    std::fs::read_dir(parent).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).filter(|n| n.contains(".new-") || n.contains(".old-")).collect()
}

/// Issue 18: a run's files are one unit. A golden run into a folder that held an RTL run leaves no
/// `cycles.json` or `chipset.v` of the RTL run behind.
#[test]
fn a_run_replaces_the_whole_output_folder_so_no_file_of_another_run_stays() {
    let out = temp_dir("unit").join("out");
    let o = out.to_str().unwrap();
    let (ok, _, err) = run(&["render", "--scene", "polyhedron", "--size", "32x20", "--backend", "rtl", "--out", o]);
    assert!(ok, "{err}");
    assert!(out.join("cycles.json").exists());
    let (ok, _, err) = run(&["render", "--scene", "castle", "--size", "32x20", "--out", o]);
    assert!(ok, "{err}");
    let names: Vec<String> = snapshot(&out).into_iter().map(|f| f.0).collect();
    assert_eq!(names, ["frame.png", "index.bin", "index.png", "stats.json"], "stale files of the RTL run");
    assert!(leftovers(&out).is_empty(), "{:?}", leftovers(&out));
}

/// Issue 18: faults in the middle of writing (a file-size limit, a write that stops halfway) leave the
/// previous result whole and nothing half-written beside it.
#[test]
fn a_write_that_fails_halfway_keeps_the_previous_result_whole() {
    let out = temp_dir("faults").join("out");
    let o = out.to_str().unwrap();
    let (ok, _, err) = run(&["render", "--scene", "polyhedron", "--size", "32x20", "--out", o]);
    assert!(ok, "{err}");
    let before = snapshot(&out);
    // A file-size limit of 8 KiB: the 640x480 frame.png cannot be written.
    let bin = env!("CARGO_BIN_EXE_idxrender");
    let o2 = Command::new("sh").arg("-c").arg(format!("ulimit -f 8; exec '{bin}' render --scene teapot --size 640x480 --out '{o}'")).output().unwrap();
    let err = String::from_utf8_lossy(&o2.stderr);
    assert!(!o2.status.success() && err.contains("File too large") && !err.contains("panicked"), "{err}");
    assert!(snapshot(&out) == before, "the previous result changed under a file-size limit");
    assert!(leftovers(&out).is_empty(), "{:?}", leftovers(&out));
    // The third file of the run stops halfway (as a full disk would).
    let o3 = bin_with_fault(2).args(["render", "--scene", "castle", "--size", "32x20", "--out", o]).output().unwrap();
    let err = String::from_utf8_lossy(&o3.stderr);
    assert!(!o3.status.success() && err.contains("injected fault"), "{err}");
    assert!(snapshot(&out) == before, "the previous result changed after a write failed halfway");
    assert!(leftovers(&out).is_empty(), "{:?}", leftovers(&out));
}

fn bin_with_fault(after: usize) -> Command {
    let mut c = bin();
    c.env("IDXRENDER_FAIL_AFTER_WRITES", after.to_string());
    c
}

/// A folder with files this program does not write is not replaced: its files could be the user's.
#[test]
fn a_folder_with_other_files_is_refused_and_left_as_it_was() {
    let out = temp_dir("foreign");
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    assert_clean_error(&["render", "--scene", "polyhedron", "--size", "32x20", "--out", out.to_str().unwrap()], "notes.txt");
    assert_eq!(std::fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
    assert_eq!(snapshot(&out).len(), 1);
}

#[test]
fn type_iii_writes_the_same_frame_and_index_buffer_as_type_iv_and_says_which_it_drew() {
    let (a, b) = (temp_dir("type-iii"), temp_dir("type-iv"));
    for (t, out) in [("III", &a), ("IV", &b)] {
        let (ok, stdout, err) = run(&["render", "--scene", "castle", "--size", "96x64", "--type", t, "--out", out.to_str().unwrap()]);
        assert!(ok, "--type {t}: {err}");
        assert!(stdout.contains(&format!("Type {t},")), "--type {t}: {stdout}");
        let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
        assert_eq!(stats["type"], t);
    }
    for f in ["frame.png", "index.bin"] {
        assert_eq!(std::fs::read(a.join(f)).unwrap(), std::fs::read(b.join(f)).unwrap(), "{f}");
    }
    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(a.join("stats.json")).unwrap()).unwrap();
    let t = &stats["stats"]["rc"]["traffic"];
    assert_eq!((t["z_reads"].as_u64(), t["z_writes"].as_u64()), (Some(0), Some(0)), "Type III has no Z-buffer: {t}");
    assert!(t["tdbv_reads"].as_u64().unwrap() > 0 && t["tdbv_writes"].as_u64().unwrap() > 0, "{t}");
    assert_clean_error(&["render", "--scene", "castle", "--type", "V"], "--type");
    assert_clean_error(&["render", "--arch", "proof", "--scene", "castle", "--type", "III"], "--type applies to --arch index only");
}

/// stats.json of a run.
fn stats_of(out: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap()
}

#[test]
fn the_textured_scene_renders_with_every_filter_and_both_coordinate_modes_and_counts_its_texels() {
    let mut images = Vec::new();
    for (filter, coords) in [("nearest", "perspective"), ("bilinear", "perspective"), ("trilinear", "perspective"), ("bilinear", "affine")] {
        let out = temp_dir(&format!("tex-{filter}-{coords}"));
        let (ok, stdout, err) = run(&["render", "--scene", "teapot-floor", "--texture-filter", filter, "--texture-coords", coords, "--out", out.to_str().unwrap()]);
        assert!(ok, "{filter} {coords}: {err}");
        assert!(stdout.contains("texture built-in checker"), "{stdout}");
        let stats = stats_of(&out);
        assert_eq!(stats["texturing"]["filter"], filter);
        assert_eq!(stats["texturing"]["coords"], coords);
        let s = &stats["stats"];
        let t = &s["texture"];
        let samples = t["samples"].as_u64().unwrap();
        assert_eq!(samples, s["covered_pixels"].as_u64().unwrap(), "the CS samples each covered pixel once");
        assert_eq!(t["traditional_samples_early_z"], s["rc"]["z_passes"]);
        let texels = t["texels_read"].as_u64().unwrap();
        match filter {
            "nearest" => assert_eq!(texels, samples),
            "bilinear" => assert_eq!(texels, 4 * samples),
            _ => assert!(texels > 4 * samples && texels <= 8 * samples, "trilinear read {texels} texels for {samples} samples"),
        }
        // The texture port reads a texel repeated in a footprint once, so never more words than texels.
        let words = t["bank_words_read"].as_u64().unwrap();
        assert!(words >= samples && words <= texels, "{filter}: {words} bank words for {texels} texels");
        images.push(std::fs::read(out.join("frame.png")).unwrap());
    }
    for i in 0..images.len() {
        for j in i + 1..images.len() {
            assert_ne!(images[i], images[j], "runs {i} and {j} drew the same image");
        }
    }
}

#[test]
fn a_texture_file_textures_the_teapot_and_bad_texture_input_is_an_error_naming_it() {
    let dir = temp_dir("texfiles");
    let good = dir.join("good.png");
    image::RgbImage::from_fn(8, 4, |x, y| image::Rgb([(x * 30) as u8, (y * 60) as u8, 200])).save(&good).unwrap();
    let odd = dir.join("odd.png");
    image::RgbImage::from_fn(6, 4, |_, _| image::Rgb([1, 2, 3])).save(&odd).unwrap();
    let junk = write(&dir, "junk.png", "not an image");
    let out = dir.join("out");
    let o = out.to_str().unwrap();
    let (ok, stdout, err) = run(&["render", "--scene", "teapot", "--texture", good.to_str().unwrap(), "--out", o]);
    assert!(ok, "{err}");
    assert!(stdout.contains("good.png (8x4, 4 levels)"), "{stdout}");
    let before = snapshot(&out);
    assert_clean_error(&["render", "--scene", "teapot", "--texture", dir.join("missing.png").to_str().unwrap(), "--out", o], "missing.png");
    assert_clean_error(&["render", "--scene", "teapot", "--texture", odd.to_str().unwrap(), "--out", o], "powers of two");
    assert_clean_error(&["render", "--scene", "teapot", "--texture", junk.to_str().unwrap(), "--out", o], "junk.png");
    assert_clean_error(&["render", "--scene", "polyhedron", "--texture", good.to_str().unwrap(), "--out", o], "no texture coordinates");
    assert_clean_error(&["render", "--scene", "polyhedron", "--texture-filter", "nearest", "--out", o], "--texture-filter needs a texture");
    assert_clean_error(&["render", "--scene", "teapot-floor", "--texture-filter", "cubic", "--out", o], "cubic");
    assert_clean_error(&["render", "--scene", "teapot-floor", "--backend", "rtl", "--type", "III", "--out", o], "--type III");
    assert_clean_error(&["render", "--scene", "teapot", "--texture", good.to_str().unwrap(), "--arch", "proof", "--out", o], "--arch index");
    assert_clean_error(&["render", "--scene", "teapot-floor", "--no-texture", "--texture-filter", "nearest", "--out", o], "--no-texture");
    assert_eq!(snapshot(&out), before, "a failed run must leave the previous outputs as they were");
    // A scene's own texture: PROOF draws the scene without it and says so; --no-texture leaves it out.
    let (ok, _, err) = run(&["render", "--scene", "teapot-floor", "--arch", "proof", "--size", "64x48", "--out", o]);
    assert!(ok, "{err}");
    assert!(err.contains("drawn without its texture"), "{err}");
    let (ok, stdout, err) = run(&["render", "--scene", "teapot-floor", "--no-texture", "--out", o]);
    assert!(ok, "{err}");
    assert!(!stdout.contains("texture built-in checker"), "{stdout}");
    assert!(stats_of(&out)["texturing"].is_null());
}

#[test]
fn an_obj_with_a_diffuse_map_is_textured_by_it_and_a_second_map_is_a_warning() {
    let d = temp_dir("objtex");
    // A quad mapped once with a 2x2 texture, red at the top left (t = 0 is the first row).
    image::RgbImage::from_fn(2, 2, |x, y| if (x + y) % 2 == 0 { image::Rgb([255, 0, 0]) } else { image::Rgb([0, 0, 255]) }).save(d.join("red.png")).unwrap();
    image::RgbImage::from_fn(2, 2, |_, _| image::Rgb([0, 255, 0])).save(d.join("green.png")).unwrap();
    write(&d, "quad.mtl", "newmtl a\nKd 1 1 1\nKa 1 1 1\nmap_Kd red.png\nnewmtl b\nKd 1 1 1\nmap_Kd green.png\n");
    let quad = "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 1\nvt 1 1\nvt 1 0\nvt 0 0\nvn 0 0 1\nusemtl a\nf 1/1/1 2/2/1 3/3/1 4/4/1\n";
    let f = write(&d, "quad.obj", quad);
    let out = d.join("out");
    let view = ["--eye", "0,0,3", "--center", "0,0,0", "--size", "64x64", "--texture-filter", "nearest"];
    let mut args = vec!["render", "--obj", f.to_str().unwrap(), "--out", out.to_str().unwrap()];
    args.extend(view);
    let (ok, stdout, err) = run(&args);
    assert!(ok, "{err}");
    assert!(stdout.contains("red.png (2x2"), "{stdout}");
    let img = image::open(out.join("frame.png")).unwrap().to_rgb8();
    // The quad covers the middle; its top-left quarter shows the red texel, its top-right the blue.
    let (tl, tr) = (img.get_pixel(26, 26).0, img.get_pixel(38, 26).0);
    assert!(tl[0] > 100 && tl[1] == 0 && tl[2] == 0, "top left {tl:?}");
    assert!(tr[2] > 100 && tr[0] == 0 && tr[1] == 0, "top right {tr:?}");
    // A second material with another map: drawn with the first, and said so.
    let two = format!("{quad}v 2 -1 0\nv 3 -1 0\nv 3 0 0\nusemtl b\nf 5/1/1 6/2/1 7/3/1\n");
    let f2 = write(&d, "two.obj", &two);
    let mut args = vec!["render", "--obj", f2.to_str().unwrap(), "--out", out.to_str().unwrap()];
    args.extend(view);
    let (ok, _, err) = run(&args);
    assert!(ok, "{err}");
    assert!(err.contains("names 2 textures") && err.contains("red.png"), "{err}");
    // PROOF draws it untextured (as before textures were read), with a warning.
    let (ok, _, err) = run(&["render", "--obj", f.to_str().unwrap(), "--arch", "proof", "--eye", "0,0,3", "--center", "0,0,0", "--size", "64x64", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(err.contains("drawn without its texture"), "{err}");
}
