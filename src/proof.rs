//! `idxrender render --arch proof`: a frame through PROOF (seed 002): object setup on the host, the
//! object-processor pipeline, the shading stage and the subpixel filter. Writes `frame.png`
//! (anti-aliased), `coverage.png` (covered subpixels per pixel, 0..64 as grey) and `stats.json`.
//!
//! `--backend golden` renders with the algorithmic model and also runs the OPP's cycle model (checked
//! against the algorithmic lists) for the cycle count; `--backend rtl` builds the object lists with the
//! RustHDL simulation of the OPP and colours every entry with the RustHDL shading stage (`tb::proof`),
//! both checked against their cycle models every cycle, then filters them (golden filter: the filter
//! RTL is not written yet). `--vcd` writes `frame.vcd` (OPP) and `shade.vcd` (shading stage).

use crate::cli::{BackendArg, RenderArgs};
use golden::proof::cycle_opp::run_opp;
use golden::proof::filter::FilterArea;
use golden::proof::render::{filter_lists, list_stats, object_lists, ops_needed, shade_and_filter};
use golden::proof::setup::scene_setup;
use golden::render::RenderOptions;
use golden::scene::Mesh;

fn parse_filter(s: &str) -> Result<FilterArea, String> {
    match s {
        "1x1" => Ok(FilterArea::Box1),
        "2x2" => Ok(FilterArea::Box2),
        _ => Err(format!("--filter '{s}' is not a filter area: use 1x1 or 2x2")),
    }
}

pub fn run_render(args: &RenderArgs, mesh: &Mesh, opts: &RenderOptions) -> Result<(), String> {
    let area = parse_filter(&args.filter)?;
    if !(1..=64).contains(&args.fifo_depth) {
        return Err(format!("--fifo-depth {} is not in 1..=64", args.fifo_depth));
    }
    if args.vcd && args.backend != BackendArg::Rtl {
        return Err("--vcd needs --backend rtl".into());
    }
    let t0 = std::time::Instant::now();
    let scene = scene_setup(mesh, opts)?;
    let needed = ops_needed(scene.screen, &scene.objects) as usize;
    let n_ops = args.ops.unwrap_or(needed.max(1));
    if n_ops == 0 {
        return Err("--ops 0: the OPP needs at least one object processor".into());
    }
    if n_ops < needed {
        return Err(format!(
            "the frame needs {needed} object processors with OP reuse, but --ops is {n_ops}: raise --ops or leave it out"
        ));
    }
    let (lists, cycles, backend, colours) = match args.backend {
        BackendArg::Golden => {
            let lists = object_lists(scene.screen, &scene.objects);
            let run = run_opp(scene.screen, &scene.objects, n_ops, args.fifo_depth, None)?;
            if run.lists != lists {
                return Err("internal error: the OPP cycle model's lists differ from the algorithmic model's".into());
            }
            (lists, run, "golden", None)
        }
        BackendArg::Rtl => {
            let vcd = if args.vcd {
                std::fs::create_dir_all(&args.out).map_err(|e| format!("cannot create output directory {}: {e}", args.out.display()))?;
                Some(args.out.join("frame.vcd"))
            } else {
                None
            };
            let (lists, run) = tb::proof::backend::opp_lists_rtl(&scene, n_ops, args.fifo_depth, vcd.as_deref())?;
            let shade_vcd = if args.vcd { Some(args.out.join("shade.vcd")) } else { None };
            let (colours, _) = tb::proof::backend::shade_lists_rtl(&scene, &lists, shade_vcd.as_deref())?;
            (lists, run, "rtl", Some(colours))
        }
    };
    let (rgb, covered) = match &colours {
        Some(c) => filter_lists(&scene, &lists, c, area),
        None => shade_and_filter(&scene, &lists, area),
    };
    let stats = list_stats(&scene, &lists, &covered);
    let secs = t0.elapsed().as_secs_f64();
    let (w, h) = (scene.screen.width, scene.screen.height);
    let grey: Vec<u8> = covered.iter().flat_map(|&c| {
        let g = ((c as u32 * 255 + 32) / 64) as u8;
        [g, g, g]
    }).collect();
    let json = serde_json::json!({
        "scene": mesh.name,
        "arch": "proof",
        "backend": backend,
        "size": [w, h],
        "filter": match area { FilterArea::Box1 => "1x1", FilterArea::Box2 => "2x2" },
        "shading": format!("{:?} normals, lit per list entry (unnormalised, seed 002 5.2.2)", opts.shading),
        "cull": opts.cull,
        "front_face": opts.front,
        "camera": opts.camera,
        "opp": cycles,
        "stats": stats,
    });
    std::fs::create_dir_all(&args.out).map_err(|e| format!("cannot create output directory {}: {e}", args.out.display()))?;
    let files = vec![
        crate::output::write_atomic(&args.out, "frame.png", &crate::output::png_bytes(w, h, &rgb)?)?,
        crate::output::write_atomic(&args.out, "coverage.png", &crate::output::png_bytes(w, h, &grey)?)?,
        crate::output::write_atomic(&args.out, "stats.json", serde_json::to_string_pretty(&json).unwrap().as_bytes())?,
    ];
    crate::say!(
        "{} (PROOF, {backend}): {}x{}, {} objects, {} OPs needed with reuse, OPP of {} OPs with FIFO depth {}: {} cycles for {} pixels",
        mesh.name, w, h, stats.setup.objects, stats.ops_needed, n_ops, args.fifo_depth, cycles.cycles, cycles.pixels
    );
    crate::say!(
        "  {} list entries, longest list {}, {} pixels anti-aliased; {:.3} s",
        stats.entries, stats.max_list, stats.pixels_with_partial, secs
    );
    for f in files {
        crate::say!("  wrote {}", f.display());
    }
    Ok(())
}
