//! Measures PROOF's figures for docs/proof.md, with the CLI's default camera and options
//! (`golden::proof::study::cli_options`):
//!
//! ```sh
//! cargo run --release -p tb --bin proof_figures -- fifo [WxH]                 # OPs, cycles, FIFO depths 1/2/4/8, every built-in scene (cycle model)
//! cargo run --release -p tb --bin proof_figures -- fifo-views [SIZES] [TURNS]  # FIFO depths 1/2/8 over views (turns about the vertical axis) and sizes (cycle model)
//! cargo run --release -p tb --bin proof_figures -- rtl SCENE [WxH] [DEPTHS]   # the same frame through the RTL OPP, every cycle against the model
//! cargo run --release -p tb --bin proof_figures -- synth [TOP]                # yosys synth_ice40 -dsp of opp (8 OPs), proof_shade, proof_filter, proof_filter2x2 (or only TOP)
//! ```

use golden::proof::setup::scene_setup;
use golden::proof::study::{cli_options, fifo_row, fifo_row_with, turned_view, view_options, FifoRow};
use golden::scene::builtin;
use std::time::Instant;

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn size(arg: Option<&String>) -> Result<(u32, u32), String> {
    let s = arg.map(|s| s.as_str()).unwrap_or("320x200");
    let (w, h) = s.split_once('x').ok_or_else(|| format!("size '{s}' is not WxH"))?;
    let p = |v: &str| v.parse::<u32>().map_err(|_| format!("size '{s}' is not WxH"));
    Ok((p(w)?, p(h)?))
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(|s| s.as_str()) {
        Some("fifo") => fifo(size(args.get(1))?),
        Some("fifo-views") => {
            let sizes = match args.get(1) {
                Some(l) => l.split(',').map(|s| size(Some(&s.to_string()))).collect::<Result<Vec<_>, _>>()?,
                None => vec![(320, 200), (512, 512), (640, 480)],
            };
            let turns = match args.get(2) {
                Some(l) => l.split(',').map(|t| t.parse::<f64>().map_err(|_| format!("turns '{l}': use degrees, e.g. 0,90,180"))).collect::<Result<Vec<_>, _>>()?,
                None => (0..8).map(|k| 45.0 * k as f64).collect(),
            };
            fifo_views(&sizes, &turns)
        }
        Some("rtl") => {
            let scene = args.get(1).ok_or("rtl SCENE [WxH] [DEPTHS]")?;
            let depths: Vec<usize> = match args.get(3) {
                Some(d) => d.split(',').map(|x| x.parse().map_err(|_| format!("depths '{d}': use e.g. 1,2,4,8"))).collect::<Result<_, _>>()?,
                None => vec![1, 2, 4, 8],
            };
            rtl(scene, size(args.get(2))?, &depths)
        }
        Some("synth") => synth(args.get(1).map(|s| s.as_str())),
        _ => Err("usage: proof_figures fifo [WxH] | fifo-views [SIZES] [TURNS] | rtl SCENE [WxH] [DEPTHS] | synth [TOP]".into()),
    }
}

fn fifo((w, h): (u32, u32)) -> Result<(), String> {
    let depths = [1, 2, 4, 8];
    println!("PROOF at {w}x{h}, CLI default camera, back-face culling, OPP cycle model with exactly the OPs needed, no gaps");
    println!();
    println!("| scene | objects | OPs needed | slots out | depth 1 | depth 2 | depth 4 | depth 8 | gain 1->8 | best vs depth 1 |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut details = Vec::new();
    for name in builtin::SCENES {
        let t0 = Instant::now();
        let mesh = builtin::scene(name)?;
        let row = fifo_row(name, &mesh, w, h, &depths)?;
        let c: Vec<u64> = row.runs.iter().map(|r| r.cycles).collect();
        let best = *c.iter().min().unwrap();
        println!(
            "| {name} | {} | {} | {} | {} | {} | {} | {} | {:.2} % | {:.2} % |",
            row.objects,
            row.ops_needed,
            row.runs[0].slots_out,
            c[0],
            c[1],
            c[2],
            c[3],
            row.gain_percent(),
            100.0 * (c[0] - best) as f64 / c[0] as f64
        );
        for r in &row.runs {
            details.push(format!(
                "{name} depth {}: {} cycles, {} slots out, {} input stalls, {} waits for a load, {} insertions, {} drops",
                r.fifo_depth, r.cycles, r.slots_out, r.input_stalls, r.waits_for_load, r.insertions, r.drops
            ));
        }
        details.push(format!("{name}: {:.1} s", t0.elapsed().as_secs_f64()));
    }
    println!();
    for d in details {
        println!("{d}");
    }
    Ok(())
}

/// Pearson's correlation of two equally long series (0 when either is constant).
fn correlation(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let cov: f64 = a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum();
    let (va, vb): (f64, f64) = (a.iter().map(|x| (x - ma).powi(2)).sum(), b.iter().map(|y| (y - mb).powi(2)).sum());
    if va == 0.0 || vb == 0.0 {
        0.0
    } else {
        cov / (va * vb).sqrt()
    }
}

/// The FIFO study over views and sizes: every built-in scene, each size, the default view turned
/// about the vertical axis by each of `turns` degrees, FIFO depths 1, 2 and 8 on the cycle model with
/// exactly the OPs needed (each run's lists checked against the algorithmic model). Two workers.
fn fifo_views(sizes: &[(u32, u32)], turns: &[f64]) -> Result<(), String> {
    let depths = [1usize, 2, 8];
    let mut jobs = Vec::new();
    for name in builtin::SCENES {
        for &s in sizes {
            for &t in turns {
                jobs.push((name.to_string(), s, t));
            }
        }
    }
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results: std::sync::Mutex<Vec<(usize, FifoRow)>> = std::sync::Mutex::new(Vec::new());
    let t0 = Instant::now();
    let errors: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|sc| {
        for _ in 0..2 {
            sc.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                let Some((name, (w, h), t)) = jobs.get(k) else { break };
                let run = builtin::scene(name).and_then(|mesh| fifo_row_with(name, &mesh, &view_options(&mesh, *w, *h, turned_view(*t)), &depths));
                match run {
                    Ok(row) => {
                        eprintln!("{name} {w}x{h} turn {t}: done ({:.0} s)", t0.elapsed().as_secs_f64());
                        results.lock().unwrap().push((k, row));
                    }
                    Err(e) => errors.lock().unwrap().push(format!("{name} {w}x{h} turn {t}: {e}")),
                }
            });
        }
    });
    if let Some(e) = errors.into_inner().unwrap().first() {
        return Err(e.clone());
    }
    let mut rows = results.into_inner().unwrap();
    rows.sort_by_key(|r| r.0);
    println!("PROOF FIFO depth over views and sizes: the CLI's options with the default view turned about the vertical axis; OPP cycle model, exactly the OPs needed, no gaps");
    println!();
    println!("| scene | size | turn | objects | OPs | slots out | depth 1 | depth 2 | depth 8 | gain 1->2 | gain 1->8 | drops / 1000 slots | input stalls d1 / 1000 slots | waits for a load d1, d8 |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let (mut gains, mut drops, mut stalls, mut over) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (k, row) in &rows {
        let (_, (w, h), t) = &jobs[*k];
        let c: Vec<u64> = row.runs.iter().map(|r| r.cycles).collect();
        let slots = row.runs[0].slots_out as f64;
        let g2 = 100.0 * (c[0] as f64 - c[1] as f64) / c[0] as f64;
        let g8 = row.gain_percent();
        let d = 1000.0 * row.runs[0].drops as f64 / slots;
        let st = 1000.0 * row.runs[0].input_stalls as f64 / slots;
        println!(
            "| {} | {w}x{h} | {t:.0} | {} | {} | {} | {} | {} | {} | {g2:.2} % | {g8:.2} % | {d:.1} | {st:.1} | {}, {} |",
            row.scene, row.objects, row.ops_needed, row.runs[0].slots_out, c[0], c[1], c[2], row.runs[0].waits_for_load, row.runs[2].waits_for_load
        );
        gains.push(g8);
        drops.push(d);
        stalls.push(st);
        over.push(100.0 * (c[0] as f64 - slots) / slots);
    }
    println!();
    println!("Per scene and size, gain 1->8 over the views: min / median / max, views above 2 %:");
    println!();
    println!("| scene | size | min | median | max | views > 2 % |");
    println!("|---|---|---|---|---|---|");
    for name in builtin::SCENES {
        for &(w, h) in sizes {
            let mut g: Vec<f64> = rows.iter().filter(|(k, _)| jobs[*k].0 == *name && jobs[*k].1 == (w, h)).map(|(_, r)| r.gain_percent()).collect();
            if g.is_empty() {
                continue;
            }
            g.sort_by(|a, b| a.partial_cmp(b).unwrap());
            let above = g.iter().filter(|&&x| x > 2.0).count();
            println!("| {name} | {w}x{h} | {:.2} % | {:.2} % | {:.2} % | {above} of {} |", g[0], g[g.len() / 2], g[g.len() - 1], g.len());
        }
    }
    let above = gains.iter().filter(|&&x| x > 2.0).count();
    println!();
    println!(
        "{} runs of 3 depths; gain 1->8 above 2 % in {above} ({:.1} %), largest {:.2} %; correlation of the gain with drops per slot {:.2}, with input stalls at depth 1 per slot {:.2}, with depth 1's cycles over slots {:.2}; {:.0} s",
        gains.len(),
        100.0 * above as f64 / gains.len() as f64,
        gains.iter().cloned().fold(f64::MIN, f64::max),
        correlation(&gains, &drops),
        correlation(&gains, &stalls),
        correlation(&gains, &over),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

fn rtl(name: &str, (w, h): (u32, u32), depths: &[usize]) -> Result<(), String> {
    let mesh = if name == "teapot" { builtin::teapot(builtin::TEAPOT_GRID) } else { builtin::scene(name)? };
    let sc = scene_setup(&mesh, &cli_options(&mesh, w, h))?;
    let row = fifo_row(name, &mesh, w, h, depths)?;
    for (k, &d) in depths.iter().enumerate() {
        let t0 = Instant::now();
        let (run, _) = tb::proof::bench::run_frame(sc.screen, &sc.objects, row.ops_needed, d, None, None, None)?;
        if run.lists != row.runs[k].lists {
            return Err(format!("{name} depth {d}: the RTL's lists differ from the cycle model's"));
        }
        println!(
            "{name} {w}x{h} depth {d}: RTL {} cycles, cycle model {} cycles ({} OPs, every port every cycle equal; {:.1} s)",
            run.cycles,
            row.runs[k].cycles,
            row.ops_needed,
            t0.elapsed().as_secs_f64()
        );
        if run.cycles != row.runs[k].cycles {
            return Err(format!("{name} depth {d}: RTL {} cycles, model {}", run.cycles, row.runs[k].cycles));
        }
    }
    Ok(())
}

fn synth(only: Option<&str>) -> Result<(), String> {
    const TOPS: [(&str, u64); 4] = [("opp", 8), ("proof_shade", 1), ("proof_filter", 1), ("proof_filter2x2", 1)];
    if let Some(t) = only {
        if !TOPS.iter().any(|x| x.0 == t) {
            return Err(format!("synth {t}: the PROOF tops are {}", TOPS.map(|x| x.0).join(", ")));
        }
    }
    let dir = tb::common::scratch_dir("proof_figures_synth");
    for (top, per) in TOPS.into_iter().filter(|x| only.is_none_or(|t| t == x.0)) {
        let v = hdl::verilog_top(top)?;
        std::fs::write(dir.join(format!("{top}.v")), &v).map_err(|e| e.to_string())?;
        let t0 = Instant::now();
        let o = std::process::Command::new("yosys")
            .current_dir(&dir)
            .env("TMPDIR", &dir)
            .args(["-q", "-p", &format!("read_verilog {top}.v; synth_ice40 -dsp -top {top}; tee -o {top}_stat.txt stat")])
            .output()
            .map_err(|e| format!("cannot run yosys: {e}"))?;
        if !o.status.success() {
            return Err(format!("yosys on {top}: {}", String::from_utf8_lossy(&o.stderr)));
        }
        let stat = std::fs::read_to_string(dir.join(format!("{top}_stat.txt"))).map_err(|e| e.to_string())?;
        let count = |cell: &str| -> u64 {
            stat.lines().filter(|l| l.trim_start().starts_with(cell)).filter_map(|l| l.split_whitespace().last()?.parse::<u64>().ok()).sum()
        };
        let (lut, carry, ff, dsp, bram) = (count("SB_LUT4"), count("SB_CARRY"), count("SB_DFF"), count("SB_MAC16"), count("SB_RAM40_4K"));
        let latches = stat.contains("LATCH") || stat.contains("$dlatch");
        println!(
            "{top}: {lut} SB_LUT4, {carry} SB_CARRY, {ff} FF, {dsp} SB_MAC16, {bram} SB_RAM40_4K, latches: {latches}; yosys {:.1} s",
            t0.elapsed().as_secs_f64()
        );
        if per > 1 {
            println!("  per OP (total / {per}): {} SB_LUT4, {} SB_CARRY, {} FF, {} SB_MAC16", lut / per, carry / per, ff / per, dsp / per);
        }
    }
    Ok(())
}
