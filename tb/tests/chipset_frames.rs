//! Whole frames through the RustHDL simulation of the `chipset` top (RC + colour setup + CS), driven by
//! the golden model's host program (seed 001's dual pipeline), equal the algorithmic golden model's
//! frames: image, I-buffer, Z-buffer, per-triangle results and every statistic. The host lights exactly
//! the triangles the RTL flagged visible (3 vertex lightings each for Gouraud).

use golden::render::{render, render_frames_with, render_with, Frame, RenderOptions};
use golden::scene::{builtin, Mesh};
use golden::format::Screen;
use golden::shade::Shading;
use golden::raster::RcType;
use tb::chipset::{mixed_frames, ChipsetTop, PhaseCycles, RtlChipset, RtlChipset3, RtlChipsetOf};

/// The screen of the single RustHDL frames. The same scenes at 320x200 and 640x480, Gouraud and Phong,
/// go through the generated Verilog under Verilator (`verilator_frames.rs`, every built-in scene) with
/// the same checks; here the RustHDL simulation of the same RTL draws them on a quarter of 320x200's
/// pixels (each scene is fitted to the screen), for about a quarter of the test's time in CI.
const RUSTHDL_FRAME: (u32, u32) = (160, 100);

fn first_difference(what: &str, a: &[u32], b: &[u32], w: u32) -> Option<String> {
    let i = (0..a.len()).find(|&i| a[i] != b[i])?;
    Some(format!("{what} at ({}, {}): golden {:#x}, RTL {:#x}", i as u32 % w, i as u32 / w, a[i], b[i]))
}

fn assert_rtl_frame_equals_golden(mesh: &Mesh, shading: Shading) {
    assert_frame_of_type_equals_golden::<hdl::chipset::Chipset>(mesh, shading)
}

/// The words the RTL's memory ports moved for the frame equal the algorithmic RC's count of the same
/// type, once the clear writes (on the I-buffer, and Type IV's Z-buffer) are taken off.
fn assert_traffic_equals_the_models(name: &str, p: &PhaseCycles, golden: &Frame, ty: RcType) {
    let (t, g) = (&p.traffic, &golden.stats.rc.traffic);
    let z_clear = if ty == RcType::IV { p.clear } else { 0 };
    let rtl = [t.z_reads, t.z_writes - z_clear, t.i_reads, t.i_writes - p.clear, t.tdbv_reads, t.tdbv_writes];
    let model = [g.z_reads, g.z_writes, g.i_reads, g.i_writes, g.tdbv_reads, g.tdbv_writes];
    assert_eq!(rtl, model, "{name}: RC port words (Z r/w, I r/w, TdbV r/w) at the RTL's ports vs the model's");
    assert_eq!(t.tdbs_writes, golden.stats.tdbs_writes, "{name}: TdbS writes");
    let n = golden.hw_index.len() as u64;
    assert_eq!((t.scan_i_reads, t.scan_i_writes), (n, n), "{name}: the scan-out reads and clears every pixel once");
}

fn assert_frame_of_type_equals_golden<T: ChipsetTop>(mesh: &Mesh, shading: Shading) {
    let screen = Screen::new(RUSTHDL_FRAME.0, RUSTHDL_FRAME.1).unwrap();
    let mut opts = RenderOptions::for_scene(mesh, screen, shading);
    opts.rc_type = T::TYPE;
    let golden: Frame = render(mesh, &opts).unwrap();
    let mut chip = RtlChipsetOf::<T>::new(screen, None).unwrap();
    let rtl = render_with(mesh, &opts, &mut chip).unwrap_or_else(|e| panic!("{}: RTL run failed: {e}", mesh.name));
    for (what, a, b) in [("I-buffer", &golden.hw_index, &rtl.hw_index), ("Z-buffer", &golden.zbuf, &rtl.zbuf), ("index", &golden.index, &rtl.index)] {
        if let Some(d) = first_difference(what, a, b, screen.width) {
            panic!("{}: {d}", mesh.name);
        }
    }
    let px = |f: &Frame, i: usize| [f.rgb[3 * i], f.rgb[3 * i + 1], f.rgb[3 * i + 2]];
    if let Some(i) = (0..screen.pixels()).find(|&i| px(&golden, i) != px(&rtl, i)) {
        panic!("{}: colour at ({}, {}): golden {:?}, RTL {:?}", mesh.name, i as u32 % screen.width, i as u32 / screen.width, px(&golden, i), px(&rtl, i));
    }
    assert_eq!(golden.results, rtl.results, "{}: per-triangle results", mesh.name);
    assert_eq!(golden.stats, rtl.stats, "{}: statistics", mesh.name);
    // Deferred lighting: the host lit the triangles the RTL flagged, and only those.
    let s = &rtl.stats;
    // Phong: the host lights no vertex; the CS lights every covered pixel once per light.
    let per_triangle = match shading {
        Shading::Flat => 1,
        Shading::Gouraud => 3,
        Shading::Phong => 0,
    };
    assert!(s.flagged_visible > 0, "{}: nothing flagged visible", mesh.name);
    assert_eq!(s.host.lighting, per_triangle * s.flagged_visible, "{}: vertex lightings vs flagged triangles", mesh.name);
    if shading == Shading::Phong {
        assert_eq!(s.cs_lightings, s.covered_pixels * opts.lighting.lights.len() as u64, "{}: per-pixel lightings", mesh.name);
    }
    let flagged_hw = rtl.results.iter().filter(|r| r.visible).count() as u64;
    assert_eq!(s.tdbs_writes, flagged_hw, "{}: colour setup ran for other than the flagged triangles", mesh.name);
    let p = &chip.phases;
    assert_eq!(p.clear, screen.pixels() as u64, "{}: the first frame clears every pixel once", mesh.name);
    // The two pipelines in parallel: colour setup ran beside rasterization, so the frame took less
    // than the three phases one after the other.
    assert!(p.total >= p.rasterization + p.scan_out && p.total < p.rasterization + p.colour_setup + p.scan_out, "{}: {p:?}", mesh.name);
    assert_traffic_equals_the_models(&mesh.name, p, &golden, T::TYPE);
    eprintln!("{}: {:?}", mesh.name, p);
}

#[test]
fn polyhedron_through_the_rtl_chipset_equals_the_golden_frame() {
    assert_rtl_frame_equals_golden(&builtin::polyhedron(), Shading::Gouraud);
}

#[test]
fn dolphins_through_the_rtl_chipset_equal_the_golden_frame() {
    assert_rtl_frame_equals_golden(&builtin::scene("dolphins").unwrap(), Shading::Gouraud);
}

#[test]
fn castle_through_the_rtl_chipset_equals_the_golden_frame() {
    assert_rtl_frame_equals_golden(&builtin::scene("castle").unwrap(), Shading::Gouraud);
}

#[test]
fn teapot_through_the_rtl_chipset_equals_the_golden_frame() {
    assert_rtl_frame_equals_golden(&builtin::teapot(builtin::TEAPOT_GRID), Shading::Gouraud);
}

#[test]
fn phong_frames_through_the_rtl_chipset_equal_the_golden_frames() {
    // The polyhedron, and the teapot at a coarse grid, where per-pixel lighting differs most from
    // Gouraud (the full teapot is in the Verilator frame tests).
    assert_rtl_frame_equals_golden(&builtin::polyhedron(), Shading::Phong);
    assert_rtl_frame_equals_golden(&builtin::teapot(4), Shading::Phong);
}

#[test]
fn a_flat_shaded_frame_through_the_rtl_chipset_equals_the_golden_frame() {
    assert_rtl_frame_equals_golden(&builtin::teapot(4), Shading::Flat);
}

/// Five frames of four scenes back to back in one run on one chipset (`tb::chipset::mixed_frames`): the
/// RC draws each frame into one I-buffer and TdbS bank while the CS scans the previous frame out of the
/// other.
#[test]
fn five_frames_of_four_scenes_back_to_back_each_equal_their_golden_frame() {
    let screen = Screen::new(96, 64).unwrap();
    let jobs = mixed_frames(screen);
    let refs: Vec<(&Mesh, &RenderOptions)> = jobs.iter().map(|(m, o)| (m, o)).collect();
    let mut chip = RtlChipset::new(screen, None).unwrap();
    let frames = render_frames_with(&refs, &mut chip).unwrap();
    for (k, ((mesh, opts), rtl)) in jobs.iter().zip(&frames).enumerate() {
        let golden = render(mesh, opts).unwrap();
        let name = format!("frame {} ({} {:?})", k + 1, mesh.name, opts.shading);
        for (what, a, b) in [("I-buffer", &golden.hw_index, &rtl.hw_index), ("Z-buffer", &golden.zbuf, &rtl.zbuf)] {
            if let Some(d) = first_difference(what, a, b, screen.width) {
                panic!("{name}: {d}");
            }
        }
        assert!(golden.rgb == rtl.rgb, "{name}: image differs");
        assert_eq!(golden.results, rtl.results, "{name}: per-triangle results");
        assert_eq!(golden.stats, rtl.stats, "{name}: statistics");
    }
    let p = &chip.frame_phases;
    for (k, q) in p.iter().enumerate() {
        // Frames 1 and 2 clear their bank (its first use after reset); later ones find it cleared.
        assert_eq!(q.clear, if k < 2 { screen.pixels() as u64 } else { 0 }, "frame {}: {q:?}", k + 1);
        // Back to back: a frame starts drawing while the previous one is scanned out.
        if k > 0 {
            let i = q.frame_interval.expect("an interval after the first frame");
            assert!(i < q.total && i >= q.rasterization, "frame {}: interval {i}, {q:?}", k + 1);
        }
    }
    eprintln!("{p:#?}");
}

#[test]
fn the_polyhedron_through_the_type_iii_rtl_chipset_equals_the_golden_frame() {
    assert_frame_of_type_equals_golden::<hdl::chipset::chipset3::Chipset3>(&builtin::polyhedron(), Shading::Gouraud);
}

/// Type III back to back (the mixed frames include Phong and flat shading): TdbV has one bank, and each frame's I-buffer bank was cleared behind the
/// scan-out, so a stale plane of an earlier frame (the same index is another triangle in another scene)
/// would show as a wrong depth or a wrong index here.
#[test]
fn five_frames_back_to_back_through_the_type_iii_chipset_each_equal_their_golden_frame() {
    let screen = Screen::new(96, 64).unwrap();
    let mut jobs = mixed_frames(screen);
    for (_, o) in jobs.iter_mut() {
        o.rc_type = RcType::III;
    }
    let refs: Vec<(&Mesh, &RenderOptions)> = jobs.iter().map(|(m, o)| (m, o)).collect();
    let mut chip = RtlChipset3::new(screen, None).unwrap();
    let frames = render_frames_with(&refs, &mut chip).unwrap();
    for (k, ((mesh, opts), rtl)) in jobs.iter().zip(&frames).enumerate() {
        let golden = render(mesh, opts).unwrap();
        let name = format!("frame {} ({} {:?})", k + 1, mesh.name, opts.shading);
        for (what, a, b) in [("I-buffer", &golden.hw_index, &rtl.hw_index), ("depth", &golden.zbuf, &rtl.zbuf)] {
            if let Some(d) = first_difference(what, a, b, screen.width) {
                panic!("{name}: {d}");
            }
        }
        assert!(golden.rgb == rtl.rgb, "{name}: image differs");
        assert_eq!(golden.results, rtl.results, "{name}: per-triangle results");
        assert_eq!(golden.stats, rtl.stats, "{name}: statistics");
        assert_traffic_equals_the_models(&name, &chip.frame_phases[k], &golden, RcType::III);
    }
}
