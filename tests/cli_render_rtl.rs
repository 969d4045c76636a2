//! `render --backend rtl`: the RustHDL simulation of the `chipset` top behind the same host program.
//! Its files are byte-identical to `--backend golden`'s, it adds `cycles.json`, `chipset.v` and (with
//! `--vcd`) `frame.vcd`, and bad input still gives clean errors that leave earlier outputs untouched.
//! Small screens keep the simulations short; the full 320x200 frames are in `tb/tests/chipset_frames.rs`.

use std::path::{Path, PathBuf};
use std::process::Command;

fn run(args: &[&str]) -> (bool, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).args(args).output().expect("run idxrender");
    (o.status.success(), String::from_utf8_lossy(&o.stdout).into(), String::from_utf8_lossy(&o.stderr).into())
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("idxrender-rtl-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn assert_clean_error(args: &[&str], needle: &str) {
    let (ok, _, err) = run(args);
    assert!(!ok, "{args:?} should fail");
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    assert!(err.to_lowercase().contains(&needle.to_lowercase()), "{args:?}: error does not mention '{needle}': {err}");
}

fn read(dir: &Path, f: &str) -> Vec<u8> {
    std::fs::read(dir.join(f)).unwrap_or_else(|e| panic!("{}: {e}", dir.join(f).display()))
}

#[test]
fn rtl_backend_writes_the_golden_files_byte_for_byte_plus_cycles_verilog_and_vcd() {
    let d = temp_dir("poly");
    let (g, r) = (d.join("golden"), d.join("rtl"));
    let common = ["render", "--scene", "polyhedron", "--size", "48x32"];
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let (ok, out, err) = run(&[&common[..], &["--backend", "rtl", "--vcd", "--out", r.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals the golden model's"), "{out}");
    for f in ["frame.png", "index.bin", "index.png"] {
        assert!(read(&g, f) == read(&r, f), "{f} differs between --backend golden and --backend rtl");
    }
    let cycles: serde_json::Value = serde_json::from_slice(&read(&r, "cycles.json")).unwrap();
    for k in ["clear", "geometry_transfer", "rasterization", "colour_setup", "scan_out", "total"] {
        assert!(cycles[k].is_u64(), "cycles.json lacks {k}: {cycles}");
    }
    // The first frame after reset clears every pixel once; scan-out reads every pixel once.
    assert_eq!(cycles["clear"], 48 * 32);
    assert!(cycles["scan_out"].as_u64().unwrap() >= 48 * 32);
    let total = cycles["total"].as_u64().unwrap();
    let c = |k: &str| cycles[k].as_u64().unwrap();
    // Colour setup runs beside rasterization (seed 001's two pipelines in parallel); the scan-out follows.
    assert!(total >= c("rasterization") + c("scan_out") && total < c("rasterization") + c("colour_setup") + c("scan_out"), "{cycles}");
    assert!(cycles["frame_interval"].is_null() && cycles["frames"] == 1, "one frame has no interval: {cycles}");
    let v = String::from_utf8(read(&r, "chipset.v")).unwrap();
    assert!(v.contains("module chipset("), "chipset.v has no top module named chipset");
    // A waveform of the whole run: a header declaring the top's clock, then value changes (the
    // `vcd-diff` tests parse such files with the `vcd` crate).
    let vcd = String::from_utf8(read(&r, "frame.vcd")).unwrap();
    let (header, body) = vcd.split_once("$enddefinitions").expect("frame.vcd has a VCD header");
    assert!(header.contains(" clock $end"), "frame.vcd declares no clock");
    assert!(body.matches("\n#").count() as u64 >= 2 * total, "frame.vcd has fewer timestamps than half-cycles");
    assert!(!r.join(".frame.vcd.tmp").exists());
}

#[test]
fn frames_back_to_back_report_their_interval_and_bad_counts_are_clear_errors() {
    let d = temp_dir("frames");
    let common = ["render", "--scene", "castle", "--size", "40x30", "--frames", "3"];
    for backend in ["rtl", "verilator"] {
        let out_dir = d.join(backend);
        let (ok, out, err) = run(&[&common[..], &["--backend", backend, "--out", out_dir.to_str().unwrap()]].concat());
        assert!(ok, "{backend}: {err}");
        assert!(out.contains("last of 3 frames") && out.contains("frame interval"), "{backend}: {out}");
        let cycles: serde_json::Value = serde_json::from_slice(&read(&out_dir, "cycles.json")).unwrap();
        let c = |k: &str| cycles[k].as_u64().unwrap_or_else(|| panic!("{backend}: no {k} in {cycles}"));
        // Frame 3 clears nothing (frames 1 and 2 cleared the two banks); the RC drew it while frame 2
        // was scanned out, so the interval is shorter than the frame's own span.
        assert_eq!((c("frames"), c("clear")), (3, 0), "{backend}: {cycles}");
        assert!(c("frame_interval") >= c("rasterization").max(40 * 30) && c("frame_interval") < c("total"), "{backend}: {cycles}");
    }
    let (a, b) = (read(&d.join("rtl"), "cycles.json"), read(&d.join("verilator"), "cycles.json"));
    let (a, b): (serde_json::Value, serde_json::Value) = (serde_json::from_slice(&a).unwrap(), serde_json::from_slice(&b).unwrap());
    for k in ["clear", "rasterization", "colour_setup", "scan_out", "total", "frame_interval"] {
        assert_eq!(a[k], b[k], "{k}: RustHDL vs Verilator");
    }
    assert_clean_error(&["render", "--scene", "castle", "--frames", "0"], "--frames");
    assert_clean_error(&["render", "--scene", "castle", "--frames", "65"], "1..=64");
    assert_clean_error(&["render", "--scene", "castle", "--arch", "proof", "--frames", "2"], "--frames applies to --arch index");
}

#[test]
fn phong_through_the_rtl_backend_writes_the_golden_files_byte_for_byte() {
    let d = temp_dir("phong");
    let (g, r) = (d.join("golden"), d.join("rtl"));
    let common = ["render", "--scene", "teapot", "--grid", "3", "--shading", "phong", "--size", "64x40"];
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let (ok, out, err) = run(&[&common[..], &["--backend", "rtl", "--out", r.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals the golden model's"), "{out}");
    for f in ["frame.png", "index.bin", "index.png"] {
        assert!(read(&g, f) == read(&r, f), "{f} differs between --backend golden and --backend rtl (Phong)");
    }
}

#[test]
fn a_textured_scene_through_both_rtl_backends_writes_the_golden_files_byte_for_byte_and_chipset_tex_v() {
    // teapot-floor with its checker, trilinear: the `chipset_tex` top (RC, textured setup, cs_tex).
    let d = temp_dir("tex");
    let (g, r) = (d.join("golden"), d.join("rtl"));
    let common = ["render", "--scene", "teapot-floor", "--size", "48x32", "--shading", "phong", "--texture-filter", "trilinear"];
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let (ok, out, err) = run(&[&common[..], &["--backend", "rtl", "--out", r.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals the golden model's"), "{out}");
    for f in ["frame.png", "index.bin", "index.png"] {
        assert!(read(&g, f) == read(&r, f), "{f} differs between --backend golden and --backend rtl");
    }
    // The texture counts, which the RTL backend counts at the top's ports, are the golden model's.
    let stats = |dir: &Path| serde_json::from_slice::<serde_json::Value>(&read(dir, "stats.json")).unwrap()["stats"]["texture"].clone();
    assert!(stats(&r)["bank_words_read"].as_u64().is_some_and(|w| w > 0), "{}", stats(&r));
    assert_eq!(stats(&g), stats(&r), "texture counts");
    let v = String::from_utf8(read(&r, "chipset_tex.v")).unwrap();
    assert!(v.contains("module chipset_tex("), "chipset_tex.v has no top module named chipset_tex");
    assert!(!r.join("chipset.v").exists(), "a textured run writes the textured top's Verilog, not chipset.v");
    // The same run on the generated Verilog: the same files, the same cycles as the RustHDL run.
    if !tb::common::require_tools("a_textured_scene_through_both_rtl_backends_writes_the_golden_files_byte_for_byte_and_chipset_tex_v", &["verilator"]) {
        return;
    }
    let vr = d.join("verilator");
    let (ok, out, err) = run(&[&common[..], &["--backend", "verilator", "--out", vr.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals the golden model's"), "{out}");
    for f in ["frame.png", "index.bin", "index.png", "chipset_tex.v"] {
        assert!(read(&r, f) == read(&vr, f), "{f} differs between --backend rtl and --backend verilator");
    }
    let cycles = |dir: &Path| serde_json::from_slice::<serde_json::Value>(&read(dir, "cycles.json")).unwrap();
    assert!(cycles(&r)["texture_words"]["texture_bank_words"].as_u64().is_some_and(|w| w > 0), "{}", cycles(&r));
    for k in ["clear", "rasterization", "colour_setup", "scan_out", "total", "memory_words", "texture_words"] {
        assert_eq!(cycles(&r)[k], cycles(&vr)[k], "cycles.json's {k}: --backend rtl vs verilator");
    }
    assert_eq!(stats(&g), stats(&vr), "texture counts (Verilator)");
}

#[test]
fn bad_input_through_the_rtl_backend_gives_clean_errors_and_keeps_earlier_outputs() {
    let d = temp_dir("bad");
    let o = d.join("out");
    let os = o.to_str().unwrap();
    let (ok, _, err) = run(&["render", "--scene", "polyhedron", "--size", "32x24", "--backend", "rtl", "--out", os]);
    assert!(ok, "{err}");
    let files = ["frame.png", "index.bin", "index.png", "stats.json", "cycles.json", "chipset.v"];
    let before: Vec<Vec<u8>> = files.iter().map(|f| read(&o, f)).collect();

    let nan = d.join("nan.obj");
    std::fs::write(&nan, "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n").unwrap();
    assert_clean_error(&["render", "--obj", nan.to_str().unwrap(), "--backend", "rtl", "--out", os], "nan.obj:3");
    assert_clean_error(&["render", "--scene", "teapot", "--grid", "4", "--index-bits", "4", "--backend", "rtl", "--out", os], "4-bit triangle index");
    assert_clean_error(&["render", "--scene", "polyhedron", "--index-bits", "20", "--backend", "rtl", "--out", os], "16 bits");
    // Phong through the RTL: 17 materials are one more than the CS's material memory holds.
    let many = d.join("many.obj");
    let mut mtl = String::new();
    let mut obj = String::from("mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n");
    for i in 0..17 {
        mtl.push_str(&format!("newmtl m{i}\nKd 0.{i:02} 0.5 0.5\n"));
        obj.push_str(&format!("usemtl m{i}\nf 1//1 2//1 3//1\n"));
    }
    std::fs::write(d.join("many.mtl"), mtl).unwrap();
    std::fs::write(&many, obj).unwrap();
    assert_clean_error(&["render", "--obj", many.to_str().unwrap(), "--shading", "phong", "--backend", "rtl", "--out", os], "17 materials");
    assert_clean_error(&["render", "--obj", many.to_str().unwrap(), "--shading", "phong", "--backend", "verilator", "--out", os], "at most 16");
    assert_clean_error(&["render", "--scene", "polyhedron", "--vcd", "--out", os], "--vcd needs --backend rtl");
    assert_clean_error(&["render", "--scene", "polyhedron", "--backend", "fpga", "--out", os], "fpga");

    let after: Vec<Vec<u8>> = files.iter().map(|f| read(&o, f)).collect();
    assert!(before == after, "a failed run changed earlier outputs");
}

#[test]
fn degenerate_and_off_screen_triangles_go_through_the_rtl_like_the_golden_model() {
    let d = temp_dir("objok");
    let f = d.join("mixed.obj");
    // A quad, a zero-area triangle, a triangle off to the side, one crossing the near plane.
    std::fs::write(
        &f,
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 0\nv 0 0 0\nv 50 0 0\nv 51 0 0\nv 50 1 0\n\
         v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0 0 6\nf 1 2 3 4\nf 5 6 5\nf 7 8 9\nf 10 11 12\n",
    )
    .unwrap();
    let (g, r) = (d.join("golden"), d.join("rtl"));
    let common = ["render", "--obj", f.to_str().unwrap(), "--eye", "0,0,4", "--center", "0,0,0", "--cull", "none", "--size", "40x30"];
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let (ok, out, err) = run(&[&common[..], &["--backend", "rtl", "--out", r.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals"), "{out}");
    assert!(read(&g, "frame.png") == read(&r, "frame.png"));
    assert!(read(&g, "index.bin") == read(&r, "index.bin"));
}

/// The Verilator backend through the program, at the size where triangles get edges over 256 pixels:
/// the generated Verilog's files equal the golden backend's byte for byte.
#[test]
fn verilator_backend_writes_the_golden_files_byte_for_byte_at_640x480() {
    if !tb::common::require_tools("verilator_backend_writes_the_golden_files_byte_for_byte_at_640x480", &["verilator"]) {
        return;
    }
    let d = temp_dir("verilator");
    let (g, v) = (d.join("golden"), d.join("verilator"));
    let common = ["render", "--scene", "polyhedron", "--size", "640x480"];
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let (ok, out, err) = run(&[&common[..], &["--backend", "verilator", "--out", v.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    assert!(out.contains("RTL frame equals the golden model's"), "{out}");
    for f in ["frame.png", "index.bin", "index.png"] {
        assert!(read(&g, f) == read(&v, f), "{f} differs between --backend golden and --backend verilator");
    }
    let cycles: serde_json::Value = serde_json::from_slice(&read(&v, "cycles.json")).unwrap();
    assert_eq!(cycles["clear"], 640 * 480, "the first frame after reset clears every pixel once: {cycles}");
    assert_eq!(cycles["equal_to_golden"], true);
}

/// `--type III` through both RTL backends: the files equal Type IV's golden files byte for byte (Type
/// III is exact), the top written is `chipset3` (no Z-buffer port), and `cycles.json` counts the words
/// on its ports: TdbV read and written, the Z-buffer never.
#[test]
fn type_iii_through_both_rtl_backends_writes_the_type_iv_golden_files_and_counts_tdbv_words() {
    if !tb::common::require_tools("type_iii_through_both_rtl_backends_writes_the_type_iv_golden_files_and_counts_tdbv_words", &["verilator"]) {
        return;
    }
    let d = temp_dir("type-iii");
    // 96x64: the Verilator harness built for the back-to-back tests (tb/tests/verilator_frames.rs) is
    // reused; the VCD is the RustHDL run's (the Verilator VCD is compared port by port there).
    let common = ["render", "--scene", "castle", "--size", "96x64"];
    let g = d.join("golden-iv");
    let (ok, _, err) = run(&[&common[..], &["--out", g.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let mut words = Vec::new();
    for backend in ["rtl", "verilator"] {
        let r = d.join(backend);
        let vcd: &[&str] = if backend == "rtl" { &["--vcd"] } else { &[] };
        let (ok, out, err) = run(&[&common[..], &["--type", "III", "--backend", backend], vcd, &["--out", r.to_str().unwrap()]].concat());
        assert!(ok, "--backend {backend}: {err}");
        assert!(out.contains("RTL frame equals the golden model's"), "{out}");
        for f in ["frame.png", "index.bin", "index.png"] {
            assert!(read(&g, f) == read(&r, f), "{f} differs between Type IV golden and Type III --backend {backend}");
        }
        let v = String::from_utf8(read(&r, "chipset3.v")).unwrap();
        assert!(v.contains("module chipset3(") && !v.contains("z_rd_addr"), "chipset3.v: no chipset3 top, or a Z-buffer port");
        if backend == "rtl" {
            let vcd = String::from_utf8(read(&r, "frame.vcd")).unwrap();
            assert!(vcd.contains(" tdbv_rd_addr ") && !vcd.contains(" z_rd_addr "), "frame.vcd's ports are not chipset3's");
        }
        let cycles: serde_json::Value = serde_json::from_slice(&read(&r, "cycles.json")).unwrap();
        assert_eq!(cycles["type"], "III");
        let m = &cycles["memory_words"];
        assert_eq!((m["z_reads"].as_u64(), m["z_writes"].as_u64()), (Some(0), Some(0)), "{m}");
        assert!(m["tdbv_reads"].as_u64().unwrap() > 0 && m["tdbv_writes"].as_u64().unwrap() > 0, "{m}");
        words.push(m.clone());
    }
    assert_eq!(words[0], words[1], "port words: RustHDL vs Verilator");
    // TdbV holds one record per index (2^16): a frame with more triangles is refused before simulation.
    assert_clean_error(&["render", "--scene", "teapot", "--grid", "60", "--size", "48x32", "--type", "III", "--backend", "rtl", "--out", d.join("big").to_str().unwrap()], "16-bit triangle index allows only 65535");
    assert!(!d.join("big").exists(), "a refused run wrote its output folder");
}
