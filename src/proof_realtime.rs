//! `idxrender bench --proof-realtime`: seed 002's real-time claim (30 frames per second at 512x512)
//! against the number of physical object processors N. Cycles per frame come from the OPP cycle
//! model (`golden::proof::study::realtime_row`; with N below the scene's need the frame takes passes,
//! each pass's lists fed back); the clock from fpga-report's JSON for the PROOF tops on the
//! LFE5U-45F. Writes a Markdown table, the same figures as JSON, and a chart of frames per second
//! against N per scene (PNG).
//!
//! The frame time is the OPP's cycles: the shading and filter stages take one slot per clock behind
//! the OPP's last pass (tens of cycles of latency), so they add no throughput limit of their own.

use crate::analyze::{draw, Bars, Chart, Group};
use golden::proof::study::{realtime_row, RealtimeRow};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Physical OP counts of the study (each scene also runs with exactly the OPs it needs).
pub const OPS: [usize; 6] = [8, 16, 24, 32, 64, 128];
const SIZE: (u32, u32) = (512, 512);
/// The PROOF stage tops whose slowest clock is the pipeline's.
const STAGE_TOPS: [&str; 3] = ["opp", "proof_shade", "proof_filter"];
const DEVICE: &str = "ecp5-45k";

/// A PROOF top on the LFE5U-45F, from fpga-report's JSON.
#[derive(Clone, Debug, serde::Serialize)]
struct TopRow {
    top: String,
    fmax_mhz: f64,
    lut4: u64,
    source: PathBuf,
}

fn read_rows(files: &[PathBuf]) -> Result<Vec<TopRow>, String> {
    let mut out: Vec<TopRow> = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).map_err(|e| format!("--proof-fpga {}: cannot read it: {e}", f.display()))?;
        let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("--proof-fpga {}: not valid JSON: {e}", f.display()))?;
        let rows = v.get("rows").and_then(|r| r.as_array()).ok_or_else(|| format!("--proof-fpga {}: no \"rows\" array (fpga-report's JSON)", f.display()))?;
        for r in rows {
            let (Some(top), Some(device)) = (r.get("top").and_then(|x| x.as_str()), r.get("device").and_then(|x| x.as_str())) else { continue };
            if device != DEVICE || !STAGE_TOPS.contains(&top) {
                continue;
            }
            let (Some(fmax), Some(lut4)) = (r.get("fmax_mhz").and_then(|x| x.as_f64()), r.get("lut4").and_then(|x| x.as_u64())) else { continue };
            out.retain(|o| o.top != top);
            out.push(TopRow { top: top.to_string(), fmax_mhz: fmax, lut4, source: f.clone() });
        }
    }
    Ok(out)
}

/// Run the study and write `<out>` (Markdown), `<out>.json` and `<out stem>.png`.
pub fn run(out: &Path, fpga: &[PathBuf], scenes: &[String]) -> Result<(), String> {
    let tops = read_rows(fpga)?;
    let clock = if STAGE_TOPS.iter().all(|t| tops.iter().any(|r| r.top == *t)) {
        tops.iter().map(|r| r.fmax_mhz).fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    let opp = tops.iter().find(|r| r.top == "opp");
    let (w, h) = SIZE;
    let mut rows: Vec<RealtimeRow> = Vec::new();
    for name in scenes {
        let mesh = golden::scene::builtin::scene(name)?;
        crate::say!("  {name} {w}x{h}: OPP cycle model with N = {:?} and the N it needs ...", OPS);
        rows.push(realtime_row(name, &mesh, w, h, &OPS)?);
    }
    let fps = |cycles: u64| if clock > 0.0 { clock * 1e6 / cycles as f64 } else { 0.0 };
    let mut md = String::new();
    let _ = writeln!(md, "# PROOF in real time? Frames per second against the number of object processors (512x512)\n");
    let _ = writeln!(md, "Command: `idxrender bench --proof-realtime --proof-fpga {}`.\n", fpga.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(","));
    let _ = writeln!(
        md,
        "Cycles per frame: the OPP cycle model (FIFO depth 1, no gaps), the lists checked against the algorithmic model; \
         with fewer OPs than the scene needs the frame takes passes, each pass's output stream stored and fed back \
         (`feedback` = the largest stored stream, {} bits per slot; hardware reading one pass while writing the next needs two such buffers). \
         Shading and filter stream behind the OPP's last pass at one slot per clock and add only their latency.\n",
        golden::proof::format::SLOT_BITS
    );
    if clock > 0.0 {
        let _ = writeln!(md, "Clock: {clock:.2} MHz, the slowest of the PROOF stage tops on the LFE5U-45F in the fpga-report JSON:\n");
        let _ = writeln!(md, "| top | Fmax (MHz) | LUT4 | from |\n|---|---|---|---|");
        for t in &tops {
            let _ = writeln!(md, "| `{}` | {:.2} | {} | {} |", t.top, t.fmax_mhz, t.lut4, t.source.display());
        }
        if let Some(o) = opp {
            let per_op = o.lut4 as f64 / 8.0;
            let others: u64 = tops.iter().filter(|t| t.top != "opp").map(|t| t.lut4).sum();
            let fit = ((43_848.0 - others as f64) / per_op).floor();
            let _ = writeln!(
                md,
                "\nLUT4 per OP: {per_op:.0} (the 8-OP `opp` top's LUT4 / 8). With the shading and 1x1 filter stages ({others} LUT4) \
                 the 43 848 LUT4 of the LFE5U-45F hold at most about {fit:.0} OPs by LUT count alone (routing and the \
                 wrapper not counted). The Fmax was measured on 8 OPs only: the OPP's ready path runs combinationally \
                 through every OP, so a longer chain clocks slower, and the frame rates for N > 8 are upper bounds.\n"
            );
        }
    } else {
        let _ = writeln!(md, "No Fmax: give fpga-report JSON files with the rows of {} on {DEVICE} (`--proof-fpga`), for frames per second.\n", STAGE_TOPS.join(", "));
    }
    let _ = writeln!(md, "| scene | objects | OPs needed | N | passes | cycles per frame | feedback (slots / KiB) | frames/s | 30 frames/s |\n|---|---|---|---|---|---|---|---|---|");
    for r in &rows {
        for run in &r.runs {
            let f = fps(run.cycles);
            let _ = writeln!(
                md,
                "| {} | {} | {} | {}{} | {} | {} | {} / {:.0} | {} | {} |",
                r.scene,
                r.objects,
                r.ops_needed,
                run.ops,
                if run.ops == r.ops_needed { " (all)" } else { "" },
                run.passes,
                run.cycles,
                run.feedback_slots,
                run.feedback_bytes() as f64 / 1024.0,
                if clock > 0.0 { format!("{f:.1}") } else { "-".into() },
                if clock > 0.0 { if f >= 30.0 { "yes" } else { "no" } } else { "-" }
            );
        }
    }
    if clock > 0.0 {
        let _ = writeln!(md, "\nFewest OPs reaching 30 frames per second at {clock:.2} MHz (cycles per frame at most {:.0}):\n", clock * 1e6 / 30.0);
        for r in &rows {
            let best = r.runs.iter().find(|run| fps(run.cycles) >= 30.0);
            let _ = writeln!(
                md,
                "* {}: {}",
                r.scene,
                match best {
                    Some(run) => format!("N = {} of the counts tried ({} pass{}, {:.1} frames/s)", run.ops, run.passes, if run.passes == 1 { "" } else { "es" }, fps(run.cycles)),
                    None => "not reached with any N tried".into(),
                }
            );
        }
    }
    let chart = Chart {
        title: format!("PROOF at 512x512: frames per second against OPs ({})", if clock > 0.0 { format!("{clock:.2} MHz") } else { "no Fmax: cycles".into() }),
        y_label: if clock > 0.0 { "frames per second".into() } else { "million cycles per frame".into() },
        series: vec![if clock > 0.0 { "frames/s".into() } else { "Mcycles/frame".into() }],
        groups: rows
            .iter()
            .map(|r| Group {
                name: r.scene.clone(),
                bars: r
                    .runs
                    .iter()
                    .map(|run| Bars { label: format!("N={}", run.ops), values: vec![if clock > 0.0 { fps(run.cycles) } else { run.cycles as f64 / 1e6 }] })
                    .collect(),
            })
            .collect(),
        stacked: false,
        reference: if clock > 0.0 { Some(30.0) } else { None },
    };
    let png = draw(&chart)?;
    let stem = out.file_stem().and_then(|s| s.to_str()).unwrap_or("proof-realtime");
    let dir = out.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let png_path = dir.join(format!("{stem}.png"));
    let _ = writeln!(md, "\n![frames per second against N]({stem}.png)");
    let json = serde_json::json!({ "clock_mhz": clock, "tops": tops, "rows": rows });
    std::fs::write(&png_path, png).map_err(|e| format!("cannot write {}: {e}", png_path.display()))?;
    std::fs::write(dir.join(format!("{stem}.json")), serde_json::to_string_pretty(&json).unwrap()).map_err(|e| format!("cannot write {stem}.json: {e}"))?;
    std::fs::write(out, &md).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
    crate::say!("wrote {}, {stem}.json and {}", out.display(), png_path.display());
    Ok(())
}
