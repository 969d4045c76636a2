//! `idxrender render --arch index`: a frame through seed 001's dual pipeline (host geometry, RC,
//! deferred lighting of the flagged triangles, colour setup, CS scan-out).
//!
//! `--backend golden` runs the algorithmic model. `--backend rtl` runs the RustHDL simulation of the
//! `chipset` top (`tb::chipset::RtlChipset`: RC + colour setup + CS with modelled Z/I/TdbS memories)
//! under the same host program, then compares its frame with the golden model's (image, I-buffer,
//! Z-buffer, per-triangle results) and fails, after writing its outputs, if they differ. It also
//! writes `cycles.json` (cycles per phase, words on each memory port), `chipset.v` (the Verilog of the
//! simulated top, for this screen size; `chipset3.v` for `--type III`, the top without a Z-buffer;
//! `chipset_tex.v` for a textured scene, the top with TdbT and the texture banks) and, with `--vcd`,
//! `frame.vcd` (the top's ports; `--vcd-full`: every signal).

use crate::args::{BackendArg, RenderArgs};
use golden::render::{render, render_frames_with, Frame, RenderOptions};
use golden::scene::Mesh;
use golden::shade::{PhongLights, Shading};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;

/// The RTL's triangle index is this wide (`hdl::rc`).
const RTL_INDEX_BITS: u32 = 16;

pub fn run_render(args: &RenderArgs, mesh: &Mesh, opts: &RenderOptions) -> Result<(), String> {
    if args.vcd && args.backend == BackendArg::Golden {
        return Err("--vcd needs --backend rtl or --backend verilator".into());
    }
    if args.backend != BackendArg::Golden {
        if let (Some(_), golden::raster::RcType::III) = (&opts.texturing, opts.rc_type) {
            return Err("texture mapping through the RTL: the textured chipset (`chipset_tex`) has the Type IV RC; drop --type III, or use --backend golden".into());
        }
        if opts.index_bits > RTL_INDEX_BITS {
            return Err(format!(
                "--index-bits {}: the RTL's triangle index is {RTL_INDEX_BITS} bits; use --backend golden for wider indices",
                opts.index_bits
            ));
        }
        if opts.shading == Shading::Phong {
            // Before any simulation: a scene whose lights or materials the CS cannot hold.
            PhongLights::new(&opts.lighting, &mesh.materials)
                .check_rtl_limits()
                .map_err(|e| format!("--shading phong through the RTL: {e}; use --backend golden"))?;
        }
    }
    // The run's files are staged and moved into --out together at the end (crate::output::OutputDir).
    let od = crate::output::OutputDir::begin(&args.out)?;
    let t0 = std::time::Instant::now();
    let golden_frame = render(mesh, opts)?;
    if args.backend == BackendArg::Golden {
        // The algorithmic model draws frames one after the other; the later ones are the same frame.
        for _ in 1..args.frames {
            render(mesh, opts)?;
        }
    }
    let golden_secs = t0.elapsed().as_secs_f64();
    let (frame, rtl) = match args.backend {
        BackendArg::Golden => (golden_frame, None),
        BackendArg::Rtl | BackendArg::Verilator => {
            let run = run_rtl(args, mesh, opts, od.dir())?;
            // Every frame of the run against the golden frame (the scene is the same each time).
            let diff = run.frames.iter().enumerate().find_map(|(k, f)| compare(&golden_frame, f).map(|d| if run.frames.len() > 1 { format!("frame {} of {}: {d}", k + 1, run.frames.len()) } else { d }));
            (run.frame, Some((run.phases, run.cycles, run.secs, run.vcd, diff)))
        }
    };
    let mut stats = serde_json::json!({
        "scene": mesh.name,
        "size": [opts.screen.width, opts.screen.height],
        "shading": opts.shading,
        "cull": opts.cull,
        "front_face": opts.front,
        "camera": opts.camera,
        "index_bits": opts.index_bits,
        "type": opts.rc_type.name(),
        "texturing": opts.texturing,
        "backend": match args.backend { BackendArg::Golden => "golden", BackendArg::Rtl => "rtl", BackendArg::Verilator => "verilator" },
        "stats": frame.stats,
    });
    let mut files = crate::output::write_frame(od.dir(), &frame, &stats)?;
    let s = &frame.stats;
    crate::say!(
        "{}: {}x{} {:?}, Type {}, {} triangles in (a), {} after culling (b), {} flagged visible, {} visible in the image (c)",
        mesh.name, opts.screen.width, opts.screen.height, opts.shading, opts.rc_type.name(), s.triangles_in, s.after_culling, s.flagged_visible, s.visible_final
    );
    crate::say!(
        "  {} fragments, {} Z passes, {} covered pixels, depth complexity {:.2}; host cost {} (Type I {}, Type II {})",
        s.rc.fragments,
        s.rc.z_passes,
        s.covered_pixels,
        s.depth_complexity,
        s.host_ops.cost(),
        s.host_type_i.ops().cost(),
        s.host_type_ii.ops().cost()
    );
    if let (Some(t), Some(ts)) = (&opts.texturing, &s.texture) {
        let (w, h) = t.texture.size();
        crate::say!(
            "  texture {} ({w}x{h}, {} levels), {:?} {:?} {:?}: {} samples, {} texels read ({:.2} per sample), {} bank words ({:.2} per sample); a traditional pipeline samples {} times with early Z ({:.1}% of those), {} without",
            t.source,
            t.texture.levels.len(),
            t.filter,
            t.coords,
            t.wrap,
            ts.samples,
            ts.texels_read,
            ts.texels_per_sample,
            ts.bank_words_read,
            ts.bank_words_per_sample,
            ts.traditional_samples_early_z,
            ts.percent_of_early_z,
            ts.traditional_samples
        );
    }
    let Some((phases, run_cycles, secs, vcd, diff)) = rtl else {
        crate::say!("  golden model: {golden_secs:.3} s");
        let files: Vec<PathBuf> = files.iter().map(|f| od.final_path(f)).collect();
        od.commit()?;
        for f in files {
            crate::say!("  wrote {}", f.display());
        }
        return Ok(());
    };
    let pixels = (opts.screen.width * opts.screen.height) as f64;
    let cycles = serde_json::json!({
        "clear": phases.clear,
        "geometry_transfer": phases.geometry_transfer,
        "rasterization": phases.rasterization,
        "colour_setup": phases.colour_setup,
        "scan_out": phases.scan_out,
        "total": phases.total,
        "frames": args.frames,
        "frame_interval": phases.frame_interval,
        "scan_out_pixels_per_clock": pixels / phases.scan_out.max(1) as f64,
        "simulation_seconds": secs,
        "simulated_cycles_per_second": run_cycles as f64 / secs.max(1e-9),
        "equal_to_golden": diff.is_none(),
        "type": opts.rc_type.name(),
        // Words on each memory port of the top in the (last) frame, counted at the ports.
        "memory_words": tb::chipset::PortTraffic::FIELDS.iter().zip(phases.traffic.to_vec()).map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect::<serde_json::Map<String, serde_json::Value>>(),
        "rasterization_bytes_read": phases.traffic.rasterization_bytes().0,
        "rasterization_bytes_written": phases.traffic.rasterization_bytes().1,
        // A textured frame's words on the texture ports (TdbT, the four texture banks), counted there.
        "texture_words": opts.texturing.as_ref().map(|_| phases.texture.fields().iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect::<serde_json::Map<String, serde_json::Value>>()),
    });
    stats["cycles"] = cycles.clone();
    // stats.json again, now with the cycle counts.
    crate::output::write_atomic(od.dir(), "stats.json", serde_json::to_string_pretty(&stats).unwrap().as_bytes())?;
    files.push(crate::output::write_atomic(od.dir(), "cycles.json", serde_json::to_string_pretty(&cycles).unwrap().as_bytes())?);
    let (v, vname) = match opts.rc_type {
        golden::raster::RcType::IV if opts.texturing.is_some() => (hdl::chipset::chipset_tex::verilog(opts.screen.width, opts.screen.height)?, "chipset_tex.v"),
        golden::raster::RcType::IV => (hdl::chipset::verilog(opts.screen.width, opts.screen.height)?, "chipset.v"),
        golden::raster::RcType::III => (hdl::chipset::chipset3::verilog(opts.screen.width, opts.screen.height)?, "chipset3.v"),
    };
    files.push(crate::output::write_atomic(od.dir(), vname, v.as_bytes())?);
    if let Some(p) = vcd {
        files.push(p);
    }
    crate::say!(
        "  RTL{}: {} cycles (clear {}, geometry transfer {}, rasterization {}, colour setup {}, scan-out {} = {:.4} px/clk{}); \
         {:.1} s simulated, {:.0} cycles/s",
        if args.frames > 1 { format!(", last of {} frames", args.frames) } else { String::new() },
        phases.total,
        phases.clear,
        phases.geometry_transfer,
        phases.rasterization,
        phases.colour_setup,
        phases.scan_out,
        pixels / phases.scan_out.max(1) as f64,
        phases.frame_interval.map(|i| format!("; frame interval {i}")).unwrap_or_default(),
        secs,
        run_cycles as f64 / secs.max(1e-9)
    );
    let files: Vec<PathBuf> = files.iter().map(|f| od.final_path(f)).collect();
    od.commit()?;
    for f in files {
        crate::say!("  wrote {}", f.display());
    }
    match diff {
        None => {
            crate::say!("  RTL frame equals the golden model's (image, I-buffer, Z-buffer, per-triangle results)");
            Ok(())
        }
        Some(d) => Err(format!("the RTL frame differs from the golden model's: {d} (outputs above are the RTL's)")),
    }
}

struct RtlRun {
    frame: Frame,
    /// Every frame of the run (`frame` is the last, once compared).
    frames: Vec<Frame>,
    phases: tb::chipset::PhaseCycles,
    /// Cycles of the whole run.
    cycles: u64,
    secs: f64,
    vcd: Option<PathBuf>,
}

fn run_rtl(args: &RenderArgs, mesh: &Mesh, opts: &RenderOptions, dir: &std::path::Path) -> Result<RtlRun, String> {
    // The waveform streams into the staged output folder (moved into --out only with the rest).
    let vcd_path = dir.join("frame.vcd");
    let bar = ProgressBar::new(1);
    bar.set_style(
        ProgressStyle::with_template("{msg:>14} [{bar:40}] {pos}/{len} ({elapsed})")
            .map_err(|e| format!("progress bar: {e}"))?
            .progress_chars("=> "),
    );
    let b = bar.clone();
    let scope = if args.vcd_full { tb::chipset::VcdScope::Full } else { tb::chipset::VcdScope::Ports };
    let progress: tb::chipset::Progress = Box::new(move |phase: &str, done: u64, total: u64| {
        if b.message() != phase {
            b.set_message(phase.to_string());
        }
        b.set_length(total.max(1));
        b.set_position(done);
    });
    let vcd_file = args.vcd.then(|| vcd_path.clone());
    // --backend verilator: the same host program and memories around the generated Verilog (built
    // once per screen size into target/verilator/, see tb::verilator).
    let mut chip: Box<dyn tb::backend::CycleChipset> = match args.backend {
        BackendArg::Verilator if opts.texturing.is_some() => Box::new(tb::verilator::VerilatorChipset::textured(opts.screen, vcd_file, scope)?.with_progress(progress)),
        BackendArg::Verilator => Box::new(tb::verilator::VerilatorChipset::of_type(opts.rc_type, opts.screen, vcd_file, scope)?.with_progress(progress)),
        _ => match opts.rc_type {
            golden::raster::RcType::IV if opts.texturing.is_some() => Box::new(tb::chipset::RtlChipsetTex::with_vcd_scope(opts.screen, vcd_file, scope)?.with_progress(progress)),
            golden::raster::RcType::IV => Box::new(tb::chipset::RtlChipset::with_vcd_scope(opts.screen, vcd_file, scope)?.with_progress(progress)),
            golden::raster::RcType::III => Box::new(tb::chipset::RtlChipset3::with_vcd_scope(opts.screen, vcd_file, scope)?.with_progress(progress)),
        },
    };
    // Simulation time, not the Verilator build (or the cache lookup) in the constructor.
    let t0 = std::time::Instant::now();
    let jobs: Vec<(&Mesh, &RenderOptions)> = (0..args.frames).map(|_| (mesh, opts)).collect();
    let result = render_frames_with(&jobs, chip.as_mut());
    chip.finish_vcd();
    bar.finish_and_clear();
    let secs = t0.elapsed().as_secs_f64();
    let frames = result.map_err(|e| format!("RTL simulation: {e}"))?;
    let vcd = args.vcd.then_some(vcd_path);
    let cycles = chip.cycles();
    Ok(RtlRun { frame: frames.last().cloned().ok_or("no frame")?, frames, phases: chip.phases(), cycles, secs, vcd })
}

/// The first difference between two frames of the same scene, if any.
pub(crate) fn compare(golden: &Frame, rtl: &Frame) -> Option<String> {
    let w = golden.screen.width as usize;
    let at = |i: usize| format!("pixel ({}, {})", i % w, i / w);
    if let Some(i) = (0..golden.hw_index.len()).find(|&i| golden.hw_index[i] != rtl.hw_index[i]) {
        return Some(format!("I-buffer at {}: golden {}, RTL {}", at(i), golden.hw_index[i], rtl.hw_index[i]));
    }
    if let Some(i) = (0..golden.zbuf.len()).find(|&i| golden.zbuf[i] != rtl.zbuf[i]) {
        return Some(format!("Z-buffer at {}: golden {:#x}, RTL {:#x}", at(i), golden.zbuf[i], rtl.zbuf[i]));
    }
    if let Some(i) = (0..golden.rgb.len() / 3).find(|&i| golden.rgb[3 * i..3 * i + 3] != rtl.rgb[3 * i..3 * i + 3]) {
        return Some(format!("colour at {}: golden {:?}, RTL {:?}", at(i), &golden.rgb[3 * i..3 * i + 3], &rtl.rgb[3 * i..3 * i + 3]));
    }
    if golden.results != rtl.results {
        let k = golden.results.iter().zip(&rtl.results).position(|(a, b)| a != b).unwrap_or(golden.results.len().min(rtl.results.len()));
        return Some(format!("per-triangle result {k}: golden {:?}, RTL {:?}", golden.results.get(k), rtl.results.get(k)));
    }
    None
}
