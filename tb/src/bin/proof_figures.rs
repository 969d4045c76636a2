//! Measures PROOF's figures for docs/proof.md, with the CLI's default camera and options
//! (`golden::proof::study::cli_options`):
//!
//! ```sh
//! cargo run --release -p tb --bin proof_figures -- fifo [WxH]                 # OPs, cycles, FIFO depths 1/2/4/8, every built-in scene (cycle model)
//! cargo run --release -p tb --bin proof_figures -- rtl SCENE [WxH] [DEPTHS]   # the same frame through the RTL OPP, every cycle against the model
//! cargo run --release -p tb --bin proof_figures -- synth [TOP]                # yosys synth_ice40 -dsp of opp (8 OPs), proof_shade, proof_filter, proof_filter2x2 (or only TOP)
//! ```

use golden::proof::setup::scene_setup;
use golden::proof::study::{cli_options, fifo_row};
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
        Some("rtl") => {
            let scene = args.get(1).ok_or("rtl SCENE [WxH] [DEPTHS]")?;
            let depths: Vec<usize> = match args.get(3) {
                Some(d) => d.split(',').map(|x| x.parse().map_err(|_| format!("depths '{d}': use e.g. 1,2,4,8"))).collect::<Result<_, _>>()?,
                None => vec![1, 2, 4, 8],
            };
            rtl(scene, size(args.get(2))?, &depths)
        }
        Some("synth") => synth(args.get(1).map(|s| s.as_str())),
        _ => Err("usage: proof_figures fifo [WxH] | rtl SCENE [WxH] [DEPTHS] | synth [TOP]".into()),
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
