//! Seed 000's Type III against Type IV at the RC, measured at the RTL's memory ports (RustHDL runs of
//! `rc` and `rc3`, each checked against its cycle model in every cycle): words and bytes read and
//! written per frame on every buffer, cycles, and the buffers' sizes, beside the analysis model's
//! prediction for the same accesses (`golden::analysis::bandwidth`: F fragments, Zp passes, T
//! triangles, Rv fragments on an owned pixel, from the untimed model). For docs/rc.md:
//! `cargo run --release -p tb --bin rc3_figures`.
//!
//! Steady state: each frame is drawn without the RC's clear (the chipset clears the I-buffer behind
//! the scan-out), so clears and scan-out reads are not in these counts.
//!
//! `--chipset`: the whole chipset (`chipset` and `chipset3`, their generated Verilog under Verilator),
//! every memory port of the top counted by the backend in the third of three frames back to back (the
//! first two clear their I-buffer bank after reset; the third finds its bank cleared behind the
//! scan-out), beside the analysis model's accesses
//! for the same buffers (`golden::analysis::bandwidth::accesses`, seed 000 Figs. 11-12).

use golden::format::Screen;
use golden::raster::RcType;
use tb::rc::bench::{run_rtl_of, Drive};
use tb::rc::stimulus::{frame, reference_of, scene_triangles};

// Bytes per entry (Z 3, I 2, a TdbV record 17, a TdbS record 53): the backends' own, `tb::chipset`.
use tb::chipset::{I_BYTES, TDBS_BYTES, TDBV_BYTES, Z_BYTES};

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    if std::env::args().any(|a| a == "--chipset") {
        return chipset();
    }
    let screen = Screen::new(320, 200)?;
    let px = screen.pixels() as u64;
    println!("| scene | type | cycles | Z read | Z write | I read | I write | TdbV read | TdbV write | bytes per frame | predicted (analysis) | buffers (bytes) |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    for name in golden::scene::builtin::SCENES {
        let tris = scene_triangles(name, golden::scene::builtin::TEAPOT_GRID, screen)?;
        let cmds = frame(false, tris.clone());
        for ty in [RcType::IV, RcType::III] {
            let run = run_rtl_of(ty, &format!("rc3_figures_{name}_{}", ty.name()), screen, &cmds, Drive::ideal(), None)?;
            let r = reference_of(ty, screen, &cmds);
            if run.ibuf != r.ibuf {
                return Err(format!("{name}: Type {} RTL frame differs from the algorithmic model", ty.name()));
            }
            let c = r.rast.counts;
            // Words at the ports.
            let (zr, zw) = match ty {
                RcType::IV => (run.z_reads, run.z_passes),
                RcType::III => (0, 0),
            };
            let (ir, iw, vr, vw) = (run.i_reads, run.i_writes, run.tdbv_reads, run.tdbv_writes);
            let bytes = (zr + zw) * Z_BYTES + (ir + iw) * I_BYTES + (vr + vw) * TDBV_BYTES;
            // The analysis model's rasterization accesses (bandwidth.rs, without clear and scan-out):
            // IV: Z read F + write Zp, I write Zp (its entry beside Z, no read); III: I read F + write
            // Zp, TdbV write T + read Rv.
            let set_up = c.triangles - c.culled_facing - c.culled_zero_area;
            let predicted = match ty {
                RcType::IV => (c.fragments + c.z_passes) * Z_BYTES + c.z_passes * I_BYTES,
                RcType::III => (c.fragments + c.z_passes) * I_BYTES + (set_up + c.traffic.tdbv_reads) * TDBV_BYTES,
            };
            let sizes = match ty {
                RcType::IV => format!("Z {} + I {}", px * Z_BYTES, px * I_BYTES),
                RcType::III => format!("I {} + TdbV {} ({} records)", px * I_BYTES, tris.len() as u64 * TDBV_BYTES, tris.len()),
            };
            println!(
                "| {name} | {} | {} | {zr} | {zw} | {ir} | {iw} | {vr} (untimed {}) | {vw} | {bytes} | {predicted} | {sizes} |",
                ty.name(),
                run.cycles,
                c.traffic.tdbv_reads
            );
        }
    }
    Ok(())
}

/// Words and bytes per frame on every memory port of the two chipset tops, Gouraud shading, 320x200.
fn chipset() -> Result<(), String> {
    use golden::analysis::bandwidth::accesses;
    use golden::analysis::buffers::{Arch, Buffer};
    use golden::render::{render, render_frames_with, RenderOptions};
    use tb::verilator::VerilatorChipset;
    let screen = Screen::new(320, 200)?;
    println!("| scene | type | Z r / w (words) | I draw r / w | I scan r / w | TdbV r / w | TdbS w / r | bytes: RC / whole frame | analysis: accesses (bytes, whole frame) |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for name in golden::scene::builtin::SCENES {
        let mesh = golden::scene::builtin::scene(name)?;
        for ty in [RcType::IV, RcType::III] {
            let mut opts = RenderOptions::for_scene(&mesh, screen, golden::shade::Shading::Gouraud);
            opts.rc_type = ty;
            let mut chip = VerilatorChipset::of_type(ty, screen, None, tb::chipset::VcdScope::Ports)?;
            let frames = render_frames_with(&[(&mesh, &opts), (&mesh, &opts), (&mesh, &opts)], &mut chip)?;
            let golden = render(&mesh, &opts)?;
            if frames.iter().any(|f| f.rgb != golden.rgb || f.hw_index != golden.hw_index) {
                return Err(format!("{name}: a Type {} chipset frame differs from golden", ty.name()));
            }
            let t = &chip.frame_phases[2].traffic;
            let (rr, rw) = t.rasterization_bytes();
            let bytes = rr + rw + (t.scan_i_reads + t.scan_i_writes) * I_BYTES + (t.tdbs_writes + t.tdbs_reads) * TDBS_BYTES;
            let m = golden::analysis::measure::measure(&mesh, &RenderOptions { rc_type: RcType::IV, ..opts.clone() })?;
            let tr = golden::analysis::traffic(&m, false);
            let arch = if ty == RcType::IV { Arch::TypeIV } else { Arch::TypeIII };
            let bufs: &[(Buffer, u64)] = match ty {
                RcType::IV => &[(Buffer::Z, Z_BYTES), (Buffer::I, I_BYTES), (Buffer::TdbS, TDBS_BYTES)],
                RcType::III => &[(Buffer::I, I_BYTES), (Buffer::TdbV, TDBV_BYTES), (Buffer::TdbS, TDBS_BYTES)],
            };
            let predicted: Vec<String> = bufs.iter().map(|&(b, _)| format!("{} {:.0}", b.name(), accesses(arch, b, &tr))).collect();
            let predicted_bytes: f64 = bufs.iter().map(|&(b, w)| accesses(arch, b, &tr) * w as f64).sum();
            println!(
                "| {name} | {} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {bytes} | {} ({predicted_bytes:.0}) |",
                ty.name(),
                t.z_reads,
                t.z_writes,
                t.i_reads,
                t.i_writes,
                t.scan_i_reads,
                t.scan_i_writes,
                t.tdbv_reads,
                t.tdbv_writes,
                t.tdbs_writes,
                t.tdbs_reads,
                rr + rw,
                predicted.join(", ")
            );
        }
    }
    Ok(())
}
