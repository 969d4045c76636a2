//! `idxrender render --arch proof`: a frame through PROOF (seed 002): object setup on the host, the
//! object-processor pipeline, the shading stage and the subpixel filter. Writes `frame.png`
//! (anti-aliased), `coverage.png` (covered subpixels per pixel, 0..64 as grey) and `stats.json`.
//!
//! `--backend golden` renders with the algorithmic model and also runs the OPP's cycle model (checked
//! against the algorithmic lists) for the cycle count; `--backend rtl` runs the frame through the
//! RustHDL simulations of the OPP, the shading stage and the filter stage (`tb::proof`), each checked
//! against its cycle model every cycle. The filter stage is the RTL of the chosen area: `--filter 1x1`
//! the 1x1 box (`FilterStage`, top `proof_filter`), `--filter 2x2` the paper's 2x2 area
//! (`Filter2x2Stage`, top `proof_filter2x2`, built for the frame's screen size, at least 2 pixels
//! wide). `--vcd` writes `frame.vcd` (OPP), `shade.vcd` (shading stage) and `filter.vcd` (filter
//! stage).

use crate::args::{BackendArg, RenderArgs};
use golden::proof::cycle_opp::run_opp_with_progress;
use golden::proof::filter::FilterArea;
use golden::proof::cycle_filter2x2::check_box_size;
use golden::proof::render::{list_stats, object_lists, ops_needed, shade_and_filter};
use golden::proof::setup::scene_setup;
use golden::render::RenderOptions;
use golden::scene::Mesh;

/// The most object processors an OPP of the RTL backends is built with.
const RTL_MAX_OPS: usize = 1024;

fn parse_filter(s: &str) -> Result<FilterArea, String> {
    match s {
        "1x1" => Ok(FilterArea::Box1),
        "2x2" => Ok(FilterArea::Box2),
        _ => Err(format!("--filter '{s}' is not a filter area: use 1x1 or 2x2")),
    }
}

pub fn run_render(args: &RenderArgs, mesh: &Mesh, opts: &RenderOptions) -> Result<(), String> {
    let area = parse_filter(args.filter.as_deref().unwrap_or("1x1"))?;
    let fifo_depth = args.fifo_depth.unwrap_or(1);
    if !(1..=64).contains(&fifo_depth) {
        return Err(format!("--fifo-depth {fifo_depth} is not in 1..=64"));
    }
    if args.vcd && args.backend == BackendArg::Golden {
        return Err("--vcd needs --backend rtl or --backend verilator".into());
    }
    if args.backend != BackendArg::Golden && area == FilterArea::Box2 {
        // Before any simulation: the 2x2 RTL's line buffer fixes what screens it can filter.
        check_box_size(opts.screen.width, opts.screen.height)?;
    }
    let t0 = std::time::Instant::now();
    let scene = scene_setup(mesh, opts)?;
    let od = crate::output::OutputDir::begin(&args.out)?;
    let needed = ops_needed(scene.screen, &scene.objects) as usize;
    let n_ops = args.ops.unwrap_or(needed.max(1));
    if n_ops == 0 {
        return Err("--ops 0: the OPP needs at least one object processor".into());
    }
    // Each object processor holds one object: more than the frame's objects are never used, and a
    // huge count would only allocate (checked before any work).
    let most = scene.objects.len().max(1);
    if n_ops > most {
        return Err(format!("--ops {n_ops}: the frame has {} objects, so at most {most} object processors can be used", scene.objects.len()));
    }
    // The RTL backends build an OPP of exactly n_ops OPs: the Verilator build of 256 takes minutes
    // and grows with N, a RustHDL OPP of thousands would not finish; refused before any work.
    if args.backend != BackendArg::Golden && n_ops > RTL_MAX_OPS {
        return Err(format!(
            "--ops {n_ops}: the RTL backends build an OPP of that many object processors; at most {RTL_MAX_OPS} (the frame needs {needed}; fewer take passes)"
        ));
    }
    // Fewer OPs than the frame needs: the frame takes several passes, each pass's output lists
    // going round again with the next batch of objects (seed 002 4.2; golden::proof::cycle_opp::passes).
    let (lists, cycles, backend, image, stage_cycles) = match args.backend {
        BackendArg::Golden => {
            let lists = object_lists(scene.screen, &scene.objects);
            // The OPP's cycle model steps every processor in every cycle: show how far it is.
            let bar = indicatif::ProgressBar::new(scene.screen.pixels() as u64);
            bar.set_style(
                indicatif::ProgressStyle::with_template("  OPP cycle model ({msg}) [{bar:40}] {pos}/{len} pixels ({elapsed})")
                    .map_err(|e| format!("progress bar: {e}"))?
                    .progress_chars("=> "),
            );
            bar.set_message(format!("{n_ops} OPs"));
            let run = run_opp_with_progress(scene.screen, &scene.objects, n_ops, fifo_depth, None, &mut |done, total| {
                bar.set_length(total);
                bar.set_position(done)
            });
            bar.finish_and_clear();
            let run = run?;
            if run.lists != lists {
                return Err("internal error: the OPP cycle model's lists differ from the algorithmic model's".into());
            }
            let image = shade_and_filter(&scene, &lists, area);
            (lists, run, "golden", image, None)
        }
        BackendArg::Rtl => {
            let vcd_of = |name: &str| -> Result<Option<std::path::PathBuf>, String> {
                if !args.vcd {
                    return Ok(None);
                }
                Ok(Some(od.dir().join(name)))
            };
            let (lists, run) = tb::proof::backend::opp_lists_rtl(&scene, n_ops, fifo_depth, vcd_of("frame.vcd")?.as_deref())?;
            let (shaded, shade_cycles) = tb::proof::backend::shade_slots_rtl(&scene, &lists, vcd_of("shade.vcd")?.as_deref())?;
            let filter_vcd = vcd_of("filter.vcd")?;
            let (rgb, covered, filter_cycles) = match area {
                FilterArea::Box1 => tb::proof::backend::filter_rtl(&scene, &shaded, filter_vcd.as_deref())?,
                FilterArea::Box2 => tb::proof::backend::filter2x2_rtl(&scene, &shaded, filter_vcd.as_deref())?,
            };
            let image = (rgb, covered);
            (lists, run, "rtl", image, Some((shade_cycles, filter_cycles)))
        }
        BackendArg::Verilator => {
            let vcd_of = |name: &str| if args.vcd { Some(od.dir().join(name)) } else { None };
            crate::say!("  building or loading the Verilator libraries (cached in target/verilator/proof_*), then the frame");
            let (lists, run) = tb::proof::backend::opp_lists_verilator(&scene, n_ops, fifo_depth, vcd_of("frame.vcd").as_deref())?;
            let (shaded, shade_cycles) = tb::proof::backend::shade_slots_verilator(&scene, &lists, vcd_of("shade.vcd").as_deref())?;
            let (rgb, covered, filter_cycles) = tb::proof::backend::filter_verilator(&scene, &shaded, area == FilterArea::Box2, vcd_of("filter.vcd").as_deref())?;
            (lists, run, "verilator", (rgb, covered), Some((shade_cycles, filter_cycles)))
        }
    };
    let (rgb, covered) = image;
    let filter_top = match area {
        FilterArea::Box1 => "proof_filter",
        FilterArea::Box2 => "proof_filter2x2",
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
        "feedback_bytes": cycles.feedback_bytes(),
        "rtl_stage_cycles": stage_cycles.map(|(s, f)| serde_json::json!({ "shading": s, "filter": f, "filter_backend": backend, "filter_top": filter_top })),
        "stats": stats,
    });
    let staged = vec![
        crate::output::write_atomic(od.dir(), "frame.png", &crate::output::png_bytes(w, h, &rgb)?)?,
        crate::output::write_atomic(od.dir(), "coverage.png", &crate::output::png_bytes(w, h, &grey)?)?,
        crate::output::write_atomic(od.dir(), "stats.json", serde_json::to_string_pretty(&json).unwrap().as_bytes())?,
    ];
    let files: Vec<std::path::PathBuf> = staged.iter().map(|f| od.final_path(f)).collect();
    od.commit()?;
    crate::say!(
        "{} (PROOF, {backend}): {}x{}, {} objects, {} OPs needed with reuse, OPP of {} OPs with FIFO depth {}: {} cycles for {} pixels",
        mesh.name, w, h, stats.setup.objects, stats.ops_needed, n_ops, fifo_depth, cycles.cycles, cycles.pixels
    );
    if cycles.passes > 1 {
        crate::say!(
            "  {} passes (fewer OPs than the {needed} needed): the lists went round again, at most {} slots ({} bytes) stored between passes",
            cycles.passes, cycles.feedback_slots, cycles.feedback_bytes()
        );
    }
    crate::say!(
        "  {} list entries, longest list {}, {} pixels anti-aliased; {:.3} s",
        stats.entries, stats.max_list, stats.pixels_with_partial, secs
    );
    if let Some((s, f)) = stage_cycles {
        crate::say!("  {backend}: shading stage {s} cycles; filter stage ({filter_top}, {} area) {f} cycles", json["filter"].as_str().unwrap_or(""));
    }
    for f in files {
        crate::say!("  wrote {}", f.display());
    }
    Ok(())
}
