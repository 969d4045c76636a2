//! `idxrender bench --quick`: the table's structure, and its figures checked against each other and
//! against the raw counts of `bench.json` (never against remembered values, never against time);
//! frames per second at Fmax from a hand-made FPGA report; and bad arguments as one-line errors that
//! keep an earlier `bench.md`.

use serde_json::Value;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn run(args: &[&str]) -> (bool, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_idxrender")).args(args).output().expect("run idxrender");
    (o.status.success(), String::from_utf8_lossy(&o.stdout).into(), String::from_utf8_lossy(&o.stderr).into())
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("idxrender-bench-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn verilator_missing(test: &str) -> bool {
    !tb::common::require_tools(test, &["verilator"])
}

fn write(path: &Path, text: &str) -> String {
    std::fs::write(path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// The rows of the Markdown table whose header line contains `marker`, as header -> cell maps.
fn table(md: &str, marker: &str) -> Vec<HashMap<String, String>> {
    let mut lines = md.lines().skip_while(|l| !(l.starts_with("| ") && l.contains(marker)));
    let header = lines.next().unwrap_or_else(|| panic!("no table with '{marker}' in:\n{md}"));
    let cells = |l: &str| l.trim().trim_matches('|').split(" | ").map(|c| c.trim().to_string()).collect::<Vec<_>>();
    let names = cells(header);
    lines
        .skip(1)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let c = cells(l);
            assert_eq!(c.len(), names.len(), "row '{l}' has {} cells for {} columns", c.len(), names.len());
            names.iter().cloned().zip(c).collect()
        })
        .collect()
}

fn row<'a>(t: &'a [HashMap<String, String>], scene: &str, size: &str, frame: Option<&str>) -> &'a HashMap<String, String> {
    t.iter()
        .find(|r| r["scene"] == scene && r["size"] == size && frame.map_or(true, |f| r["frame"] == f))
        .unwrap_or_else(|| panic!("no row {scene} {size} {frame:?}"))
}

fn size(v: &Value) -> String {
    format!("{}x{}", v[0], v[1])
}

fn f64_of(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn quick_bench_writes_a_table_whose_figures_agree_with_its_raw_counts_and_the_fpga_report() {
    if verilator_missing("quick bench") {
        return;
    }
    let d = temp_dir("quick");
    let out = d.join("bench.md");
    // A hand-made report: one device where the chipset has an Fmax, one where it does not fit, and
    // another top's Fmax that must not be taken for the chipset's.
    let fpga = write(
        &d.join("fpga.json"),
        r#"{"rows": [
            {"top": "chipset", "device": "ecp5-85k", "fmax_mhz": 41.3, "fits": true},
            {"top": "chipset", "device": "up5k", "fmax_mhz": null, "fits": false},
            {"top": "colour_setup", "device": "hx8k", "fmax_mhz": 18.22, "fits": true}
        ]}"#,
    );
    let (ok, stdout, err) = run(&["bench", "--quick", "--out", out.to_str().unwrap(), "--fpga-report", &fpga]);
    assert!(ok, "bench --quick failed: {err}");
    assert!(stdout.contains("wrote"), "{stdout}");
    let md = std::fs::read_to_string(&out).unwrap();
    let json: Value = serde_json::from_str(&std::fs::read_to_string(d.join("bench.json")).expect("bench.json beside bench.md")).unwrap();
    for heading in ["## Golden model: frames per second", "## Simulation speed", "## Hardware efficiency", "## Frames per second at Fmax"] {
        assert!(md.contains(heading), "bench.md lacks '{heading}'");
    }
    let m = &json["machine"];
    assert!(md.contains("Machine: ") && md.contains(m["cpu"].as_str().unwrap()) && md.contains(m["verilator"].as_str().unwrap()), "machine line");
    assert!(m["logical_cpus"].as_u64().unwrap() >= 1);
    // The bench names the index-rendering type it measured.
    assert_eq!(json["rc_type"], "IV");
    assert!(md.contains("Chipset measured: seed 000 Type IV") && stdout.contains("chipset: seed 000 Type IV"), "type line");

    // Golden: every scene at both sizes, fps = frames / seconds, as printed.
    let golden = json["golden"].as_array().unwrap();
    let gt = table(&md, "frames timed");
    assert_eq!(golden.len(), 8, "4 scenes x 2 sizes");
    for g in golden {
        let fps = f64_of(&g["frames_per_second"]);
        assert!(fps > 0.0 && g["frames"].as_u64().unwrap() >= 1);
        assert!(close(fps, g["frames"].as_u64().unwrap() as f64 / f64_of(&g["seconds"])));
        assert_eq!(row(&gt, g["scene"].as_str().unwrap(), &size(&g["size"]), None)["frames/s"], format!("{fps:.1}"));
    }

    // Simulators: a RustHDL frame and every Verilated frame, each with an equals-golden verdict.
    let sims = json["simulators"].as_array().unwrap();
    let st = table(&md, "cycles/s");
    assert!(st[0].contains_key("equals golden"), "no equals-golden column");
    assert!(sims.iter().any(|s| s["simulator"] == "RustHDL" && s["cycles"].as_u64().is_some()));
    assert_eq!(sims.iter().filter(|s| s["simulator"] == "Verilator").count(), 8, "4 scenes x 2 sizes, one run of 3 frames each");
    assert!(sims.iter().filter(|s| s["simulator"] == "Verilator").all(|s| s["frames"] == 3));
    for (s, r) in sims.iter().zip(&st) {
        let equal = s["equals_golden"]["equal"].as_bool().unwrap();
        assert_eq!(r["equals golden"] == "yes", equal, "{r:?}");
        if let Some(c) = s["cycles"].as_u64() {
            assert!(close(f64_of(&s["cycles_per_second"]), c as f64 / f64_of(&s["seconds"])));
        }
    }

    // Efficiency: rates recomputed from the raw counts, within their limits, and as printed.
    let rt = table(&md, "CS px/clk");
    let frames = json["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 24, "4 scenes x 2 sizes x 3 frames");
    for f in frames {
        let (scene, sz, frame) = (f["scene"].as_str().unwrap(), size(&f["size"]), f["frame"].to_string());
        let p = &f["phases"];
        let c = |k: &str| p[k].as_u64().unwrap_or_else(|| panic!("{scene} {sz} frame {frame}: no {k}"));
        let pixels = f["pixels"].as_u64().unwrap();
        // Colour setup runs beside rasterization; a frame's scan-out follows its rasterization.
        assert!(c("total") >= c("rasterization") + c("scan_out"), "{scene} {sz} frame {frame}: {p}");
        assert_eq!(c("clear"), if frame != "3" { pixels } else { 0 }, "frames 1 and 2 clear their bank, frame 3 nothing");
        // Frames back to back: the interval is at least the frame's rasterization and one scan-out (one
        // pixel per clock at best), and shorter than the frame's own span, which overlaps its neighbours;
        // the first frame of a run has none.
        if frame == "1" {
            assert!(p["frame_interval"].is_null());
        } else {
            let i = c("frame_interval");
            assert!(i >= c("rasterization").max(pixels) && i < c("total"), "{scene} {sz} frame {frame}: {p}");
        }
        let q = &f["rates"];
        let px = pixels as f64 / c("scan_out") as f64;
        assert!(close(f64_of(&q["cs_pixels_per_clock"]), px) && px <= 1.0, "{scene} {sz}: CS {px} px/clk");
        let frag = c("z_reads") as f64 / c("rasterization") as f64;
        assert!(close(f64_of(&q["fragments_per_clock"]), frag) && frag <= 1.0);
        let cand = f["candidates"].as_u64().unwrap() as f64 / c("rasterization") as f64;
        // The traversal looks at up to WALK_LONG_SKIP candidates of the box per clock.
        assert!(close(f64_of(&q["candidates_per_clock"]), cand) && cand <= golden::cycle::rc::WALK_LONG_SKIP as f64);
        let r = row(&rt, scene, &sz, Some(&frame));
        assert_eq!(r["CS px/clk"], format!("{px:.4}"));
        assert!(r["RC fragments/clk"].starts_with(&format!("{frag:.3}")), "{r:?}");
        assert_eq!(r["RC candidates/clk"], format!("{cand:.3}"));
        if f["equals_golden"]["equal"].as_bool().unwrap() {
            // The chipset's Z reads are the algorithmic RC's fragments when the frame is right.
            assert_eq!(c("z_reads"), f["fragments_model"].as_u64().unwrap(), "{scene} {sz} frame {frame}");
        }
    }
    // The traversal's walk: one row per scene and size; every clock that delivers a fragment delivers
    // exactly one (so those clocks are the model's Z reads), the model's Z reads are the algorithmic RC's
    // fragments and the Verilated chipset's, and the share is recomputed and printed.
    let tt = table(&md, "clocks with a fragment");
    let trav = json["traversal"].as_array().unwrap();
    assert_eq!(trav.len(), 8, "4 scenes x 2 sizes");
    for t in trav {
        let (scene, sz) = (t["scene"].as_str().unwrap(), size(&t["size"]));
        let (walk, frag) = (t["walk_clocks"].as_u64().unwrap(), t["fragment_clocks"].as_u64().unwrap());
        assert!(frag > 0 && frag <= walk, "{t}");
        assert_eq!(frag, t["z_reads"].as_u64().unwrap(), "{scene} {sz}: one fragment per delivering clock");
        let steady = frames.iter().find(|f| f["scene"] == t["scene"] && f["size"] == t["size"] && f["frame"] == 3).unwrap();
        assert_eq!(t["z_reads"], steady["fragments_model"], "{scene} {sz}: the model's Z reads are the algorithmic RC's fragments");
        assert_eq!(t["z_reads_equal_verilators"], true, "{scene} {sz}");
        assert!(close(f64_of(&t["share"]), frag as f64 / walk as f64));
        let r = row(&tt, scene, &sz, None);
        assert_eq!(r["share"], format!("{:.1}%", 100.0 * frag as f64 / walk as f64));
        assert_eq!(r["walk clocks"], walk.to_string());
    }
    // Back-to-back RC setup: both simulators count the same, and a drawn triangle costs more than a culled one.
    let setup = json["setup"].as_array().unwrap();
    assert_eq!(setup.len(), 2);
    for s in setup {
        assert_eq!(s["rusthdl_cycles_per_triangle"], s["verilator_cycles_per_triangle"], "{s}");
        assert!(f64_of(&s["verilator_cycles_per_triangle"]) > 0.0);
    }
    assert!(f64_of(&setup[0]["verilator_cycles_per_triangle"]) > f64_of(&setup[1]["verilator_cycles_per_triangle"]));

    // Fmax: the chipset's ecp5-85k row only; fps = Fmax * 1e6 / the steady-state frame's cycles.
    let fm = &json["fmax"];
    assert!(fm["no_fmax"].is_null(), "{}", fm["no_fmax"]);
    let rows = fm["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 8, "one row per scene and size, for the one device with an Fmax");
    let ft = table(&md, "frames/s at Fmax");
    for r in rows {
        assert_eq!(r["device"], "ecp5-85k");
        let steady = frames.iter().find(|f| f["scene"] == r["scene"] && f["size"] == r["size"] && f["frame"] == 3).unwrap();
        let cycles = steady["phases"]["frame_interval"].as_u64().unwrap();
        let fps = 41.3e6 / cycles as f64;
        assert!(close(f64_of(&r["frames_per_second"]), fps), "{r}");
        assert_eq!(row(&ft, r["scene"].as_str().unwrap(), &size(&r["size"]), None)["frames/s at Fmax"], format!("{fps:.1}"));
    }
    assert!(md.contains("up5k: does not fit"), "the chipset row that does not fit is named");
    let devices: Vec<&str> = fm["devices"].as_array().unwrap().iter().map(|x| x["device"].as_str().unwrap()).collect();
    assert_eq!(devices, ["ecp5-85k", "up5k"], "only the chipset's rows: another top's Fmax is not the chipset's");
    assert!(md.contains("reconstructed"), "Table IV's reconstructed size is marked");
}

#[test]
fn without_a_chipset_fmax_the_table_says_why_and_gives_no_frame_rate() {
    if verilator_missing("no Fmax") {
        return;
    }
    let d = temp_dir("nofmax");
    let out = d.join("bench.md");
    let fpga = write(&d.join("fpga.json"), r#"{"rows": [{"top": "chipset", "device": "hx8k", "fmax_mhz": null, "fits": false}]}"#);
    let (ok, _, err) = run(&["bench", "--quick", "--scenes", "polyhedron", "--out", out.to_str().unwrap(), "--fpga-report", &fpga]);
    assert!(ok, "{err}");
    let md = std::fs::read_to_string(&out).unwrap();
    let json: Value = serde_json::from_str(&std::fs::read_to_string(d.join("bench.json")).unwrap()).unwrap();
    assert!(json["fmax"]["rows"].as_array().unwrap().is_empty());
    assert!(md.contains("No `chipset` row of") && md.contains("hx8k: does not fit"), "{md}");
    assert!(!md.contains("frames/s at Fmax"), "no frame-rate table without an Fmax");
    assert_eq!(json["golden"].as_array().unwrap().len(), 2, "--scenes polyhedron: one scene at two sizes");
}

/// Runs that must fail with one line naming the problem, without a panic, leaving `bench.md` as it was.
#[test]
fn bad_arguments_are_one_line_errors_that_keep_the_earlier_table() {
    let d = temp_dir("errors");
    let out = d.join("bench.md");
    std::fs::write(&out, "an earlier table\n").unwrap();
    let o = out.to_str().unwrap();
    let bad_json = write(&d.join("bad.json"), "{\"rows\": [");
    let bad_field = write(&d.join("field.json"), r#"{"rows": [{"top": "chipset", "device": "up5k", "fmax_mhz": "fast"}]}"#);
    let no_rows = write(&d.join("norows.json"), r#"{"tops": []}"#);
    let missing = d.join("missing.json");
    let file = write(&d.join("a-file"), "");
    let under_file = format!("{file}/bench.md");
    let dir = d.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--scenes", "teapot,nosuch", "--out", o], "unknown scene 'nosuch'"),
        (vec!["--fpga-report", &bad_json, "--out", o], "not valid JSON"),
        (vec!["--fpga-report", &bad_field, "--out", o], "fmax_mhz"),
        (vec!["--fpga-report", &no_rows, "--out", o], "no \"rows\" array"),
        (vec!["--fpga-report", missing.to_str().unwrap(), "--out", o], "cannot read"),
        (vec!["--out", &under_file], "--out"),
        (vec!["--out", dir], "is a directory"),
    ];
    for (args, needle) in cases {
        let all = [&["bench", "--quick"][..], &args[..]].concat();
        let (ok, _, err) = run(&all);
        assert!(!ok, "{all:?} should fail");
        assert!(!err.contains("panicked"), "{all:?} panicked: {err}");
        assert!(err.contains(needle), "{all:?}: the error does not say '{needle}': {err}");
        assert_eq!(err.trim().lines().count(), 1, "{all:?}: not one line: {err}");
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "an earlier table\n", "{all:?} touched bench.md");
        assert!(!d.join("bench.json").exists(), "{all:?} wrote bench.json");
    }
}

/// `bench --proof-realtime`: the PROOF real-time study writes its table, JSON and chart; the frame
/// rates are the clock over the cycles of the cycle model, fewer OPs take more passes, and the clock is
/// the slowest of the stage tops in the given fpga-report JSON.
#[test]
fn bench_proof_realtime_gives_frames_per_second_against_ops_from_the_cycle_model_and_the_slowest_stage() {
    let dir = temp_dir("proof-realtime");
    let fpga = dir.join("fpga.json");
    let rows = r#"{"rows": [
        {"top": "opp", "device": "ecp5-45k", "fmax_mhz": 40.0, "lut4": 12000},
        {"top": "proof_shade", "device": "ecp5-45k", "fmax_mhz": 50.0, "lut4": 600},
        {"top": "proof_filter", "device": "ecp5-45k", "fmax_mhz": 35.0, "lut4": 1500},
        {"top": "opp", "device": "up5k", "fmax_mhz": 10.0, "lut4": 15000}]}"#;
    write(&fpga, rows);
    let out = dir.join("rt.md");
    let (ok, _, err) = run(&["bench", "--proof-realtime", "--scenes", "dolphins", "--proof-fpga", fpga.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    let md = std::fs::read_to_string(&out).unwrap();
    assert!(md.contains("Clock: 35.00 MHz"), "{md}");
    assert!(image::open(dir.join("rt.png")).is_ok(), "no chart");
    let j: Value = serde_json::from_slice(&std::fs::read(dir.join("rt.json")).unwrap()).unwrap();
    let runs = j["rows"][0]["runs"].as_array().unwrap();
    let needed = j["rows"][0]["ops_needed"].as_u64().unwrap();
    let mut last_passes = u64::MAX;
    for r in runs {
        let (n, passes, cycles) = (r["ops"].as_u64().unwrap(), r["passes"].as_u64().unwrap(), r["cycles"].as_u64().unwrap());
        assert!(passes <= last_passes, "more OPs, more passes: {r}");
        last_passes = passes;
        assert_eq!(passes == 1, n >= needed, "{r}");
        assert!(cycles >= passes * 512 * 512, "{r}");
        let fps = format!("{:.1}", 35.0e6 / cycles as f64);
        assert!(md.contains(&format!("| {cycles} |")) && md.contains(&fps), "{fps} for {cycles} cycles not in the table:\n{md}");
    }
    // A report without the stage tops gives no clock, and the table says so.
    write(&fpga, r#"{"rows": [{"top": "rc", "device": "ecp5-45k", "fmax_mhz": 40.0, "lut4": 1}]}"#);
    let (ok, _, err) = run(&["bench", "--proof-realtime", "--scenes", "polyhedron", "--proof-fpga", fpga.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(std::fs::read_to_string(&out).unwrap().contains("No Fmax"));
    let (ok, _, err) = run(&["bench", "--proof-fpga", fpga.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(!ok && err.contains("--proof-fpga applies to --proof-realtime"), "{err}");
}
