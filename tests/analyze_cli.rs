//! The `analyze` command end to end: the report, the charts and the JSON come out of one run, the JSON
//! agrees with seed 001's formula applied to the measured triangle counts and with the `render`
//! command's statistics for the same scene, and bad input gives an error naming the problem.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_idxrender"))
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("idxrender-analyze-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

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

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = run(args);
    assert!(ok, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: stdout is not JSON ({e}): {out}"))
}

/// Seed 001's equivalent cost (ADD 1, MUL 2, rsqrt 16) of Table 2 with one light, written out again
/// here from the paper's text rather than taken from the code under test.
fn seed001_cost(a: u64, b: u64, c: u64) -> [u64; 3] {
    let (view, persp, light) = (12 * 2 + 9, 5 * 2 + 1, 34 * 2 + 19 + 3 * 16);
    let geometry = 3 * a * (view + persp);
    [geometry + 3 * a * view + 3 * b * light, geometry + 3 * a * view + 3 * a * light, geometry + 3 * c * view + 3 * c * light]
}

#[test]
fn low_end_analysis_writes_the_report_and_every_chart() {
    let out = temp_dir("report");
    let (ok, stdout, err) = run(&["analyze", "--scene", "castle", "--scene", "polyhedron", "--level", "low", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(stdout.contains("lighting operations saved"), "{stdout}");
    let md = std::fs::read_to_string(out.join("analysis.md")).unwrap();
    for section in ["Seed 001 Tables 1-3", "Fig. 9", "Texture operations", "Table VII", "Fig. 11", "Fig. 12", "Against the papers' claims"] {
        assert!(md.contains(section), "analysis.md lacks '{section}'");
    }
    assert!(md.contains("| castle | 320x200 |") && md.contains("| polyhedron | 160x100 |"), "{md}");
    let charts = [
        "seed001_cpu_cost.png",
        "fig9_phong.png",
        "fig9_gouraud.png",
        "fig9_flat.png",
        "fig10_phong_ours.png",
        "fig10_phong_paper.png",
        "fig10_gouraud_ours.png",
        "fig10_gouraud_paper.png",
        "fig11_phong_ours.png",
        "fig11_gouraud_ours.png",
        "fig12_phong_ours.png",
        "fig12_gouraud_ours.png",
    ];
    for c in charts {
        assert!(md.contains(&format!("]({c})")), "analysis.md does not show {c}");
        let img = image::open(out.join(c)).unwrap_or_else(|e| panic!("{c}: {e}")).to_rgb8();
        assert!(img.width() >= 900 && img.height() >= 500, "{c}: {}x{}", img.width(), img.height());
        // Not blank: bars in the palette's colours and dark text pixels both present.
        let coloured = img.pixels().filter(|p| p.0 != [255, 255, 255] && (p.0[0] as i32 - p.0[2] as i32).abs() > 60).count();
        let dark = img.pixels().filter(|p| p.0.iter().all(|&c| c < 80)).count();
        assert!(coloured > 500 && dark > 500, "{c}: {coloured} coloured, {dark} dark pixels");
    }
}

#[test]
fn json_cpu_table_follows_seed_001_from_the_measured_counts() {
    let v = json(&["analyze", "--scene", "dolphins", "--level", "low", "--json"]);
    let cpu = &v["analysis"]["cpu"][0];
    assert_eq!(cpu["scene"], "dolphins");
    let n = |x: &serde_json::Value| x.as_u64().unwrap();
    let (a, b, c, flagged) = (n(&cpu["counts"]["a"]), n(&cpu["counts"]["b"]), n(&cpu["counts"]["c"]), n(&cpu["flagged"]));
    assert!(c <= flagged && flagged <= b && b <= a, "{cpu}");
    let want = seed001_cost(a, b, c);
    for (k, row) in cpu["table3"].as_array().unwrap().iter().enumerate() {
        assert_eq!(n(&row["cost"]), want[k], "row {k}: {row}");
    }
    // As built, the host lights the flagged triangles.
    assert_eq!(n(&cpu["as_built"]["cost"]), seed001_cost(a, b, flagged)[2]);
}

#[test]
fn json_counts_agree_with_the_render_command() {
    let v = json(&["analyze", "--scene", "castle", "--level", "low", "--json"]);
    let m = v["analysis"]["measured"].as_array().unwrap().iter().find(|m| m["width"] == 320 && m["height"] == 200).expect("castle at 320x200").clone();
    let out = temp_dir("render");
    let (ok, _, err) = run(&["render", "--scene", "castle", "--size", "320x200", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    let stats: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("stats.json")).unwrap()).unwrap();
    let s = &stats["stats"];
    assert_eq!(m["a"], s["triangles_in"]);
    assert_eq!(m["b"], s["after_culling"]);
    assert_eq!(m["flagged"], s["flagged_visible"]);
    assert_eq!(m["c"], s["visible_final"]);
    assert_eq!(m["rc"]["fragments"], s["rc"]["fragments"]);
    assert_eq!(m["covered_pixels"], s["covered_pixels"]);
    // Fig. 9 (Phong): Type I lights the Z passes, index rendering the covered pixels.
    let l = v["analysis"]["lighting"].as_array().unwrap().iter().find(|l| l["width"] == 320).unwrap();
    assert_eq!(l["phong"]["type_i"], s["rc"]["z_passes"]);
    assert_eq!(l["phong"]["type_iii_iv"], s["covered_pixels"]);
}

#[test]
fn bad_arguments_give_errors_naming_the_problem() {
    assert_clean_error(&["analyze", "--scene", "nope", "--level", "low"], "nope");
    assert_clean_error(&["analyze", "--level", "ultra"], "ultra");
    assert_clean_error(&["analyze", "--worst-depth", "0.5", "--level", "low"], "--worst-depth");
    assert_clean_error(&["analyze", "--worst-depth", "nan", "--level", "low"], "--worst-depth");
    assert_clean_error(&["analyze", "--obj", "/nonexistent/x.obj", "--level", "low"], "x.obj");
    let file = temp_dir("notadir").join("file");
    std::fs::write(&file, b"x").unwrap();
    assert_clean_error(&["analyze", "--scene", "polyhedron", "--level", "low", "--out", file.to_str().unwrap()], "not a folder");
}

/// `analyze --out` is one unit like `render --out` (issue 18): a folder holding a file that analyze
/// does not write is refused before any work, and left as it was.
#[test]
fn analyze_refuses_an_out_folder_with_foreign_files_before_the_work() {
    let dir = temp_dir("foreign");
    std::fs::write(dir.join("notes.txt"), b"mine").unwrap();
    let t0 = std::time::Instant::now();
    assert_clean_error(&["analyze", "--scene", "polyhedron", "--level", "low", "--out", dir.to_str().unwrap()], "notes.txt");
    assert!(t0.elapsed().as_secs_f64() < 5.0, "refused only after the analysis");
    assert_eq!(std::fs::read(dir.join("notes.txt")).unwrap(), b"mine");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
}

/// A failed write to standard output is an error (issue 18: `analyze --json > /dev/full` exited 0); a
/// reader that stops early (`| head`) is not.
#[test]
fn a_full_disk_behind_standard_output_is_an_error_and_a_closed_pipe_is_not() {
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").expect("/dev/full (Linux)");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_idxrender"))
        .args(["analyze", "--scene", "polyhedron", "--json"])
        .stdout(full)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "exit 0 although nothing could be written");
    assert!(err.contains("cannot write to standard output") && !err.contains("panicked"), "{err}");
    // The reader closes the pipe after the first bytes: the command still succeeds.
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_idxrender"))
        .args(["analyze", "--scene", "polyhedron", "--json"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 1];
    std::io::Read::read_exact(child.stdout.as_mut().unwrap(), &mut first).unwrap();
    drop(child.stdout.take());
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success(), "a closed pipe made the command fail: {}", String::from_utf8_lossy(&o.stderr));
}
