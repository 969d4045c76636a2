//! Whole frames through the RustHDL simulation of the `chipset` top (RC + colour setup + CS), driven by
//! the golden model's host program (seed 001's dual pipeline), equal the algorithmic golden model's
//! frames: image, I-buffer, Z-buffer, per-triangle results and every statistic. The host lights exactly
//! the triangles the RTL flagged visible (3 vertex lightings each for Gouraud).

use golden::render::{render, render_with, Frame, RenderOptions};
use golden::scene::{builtin, Mesh};
use golden::format::Screen;
use golden::shade::Shading;
use tb::chipset::RtlChipset;

fn first_difference(what: &str, a: &[u32], b: &[u32], w: u32) -> Option<String> {
    let i = (0..a.len()).find(|&i| a[i] != b[i])?;
    Some(format!("{what} at ({}, {}): golden {:#x}, RTL {:#x}", i as u32 % w, i as u32 / w, a[i], b[i]))
}

fn assert_rtl_frame_equals_golden(mesh: &Mesh, shading: Shading) {
    let screen = Screen::new(320, 200).unwrap();
    let opts = RenderOptions::for_scene(mesh, screen, shading);
    let golden: Frame = render(mesh, &opts).unwrap();
    let mut chip = RtlChipset::new(screen, None).unwrap();
    let rtl = render_with(mesh, &opts, &mut chip).unwrap_or_else(|e| panic!("{}: RTL run failed: {e}", mesh.name));
    for (what, a, b) in [("I-buffer", &golden.hw_index, &rtl.hw_index), ("Z-buffer", &golden.zbuf, &rtl.zbuf), ("index", &golden.index, &rtl.index)] {
        if let Some(d) = first_difference(what, a, b, screen.width) {
            panic!("{}: {d}", mesh.name);
        }
    }
    let px = |f: &Frame, i: usize| [f.rgb[3 * i], f.rgb[3 * i + 1], f.rgb[3 * i + 2]];
    if let Some(i) = (0..screen.pixels()).find(|&i| px(&golden, i) != px(&rtl, i)) {
        panic!("{}: colour at ({}, {}): golden {:?}, RTL {:?}", mesh.name, i % 320, i / 320, px(&golden, i), px(&rtl, i));
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
    assert_eq!(p.total, p.rasterization + p.colour_setup + p.scan_out);
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

#[test]
fn a_second_frame_uses_the_buffers_the_color_shader_cleared_behind_the_first() {
    // Frame 1 of the castle, then frame 2 of the dolphins on the same chipset: no RC clear, and
    // frame 2 must still equal the golden frame (any pixel the clear-behind missed would show).
    let screen = Screen::new(160, 100).unwrap();
    let mut chip = RtlChipset::new(screen, None).unwrap();
    let castle = builtin::scene("castle").unwrap();
    render_with(&castle, &RenderOptions::for_scene(&castle, screen, Shading::Gouraud), &mut chip).unwrap();
    let dolphins = builtin::scene("dolphins").unwrap();
    let opts = RenderOptions::for_scene(&dolphins, screen, Shading::Gouraud);
    let rtl = render_with(&dolphins, &opts, &mut chip).unwrap();
    assert_eq!(chip.phases.clear, 0, "the second frame needs no clear");
    let golden = render(&dolphins, &opts).unwrap();
    assert!(golden.hw_index == rtl.hw_index, "second frame: I-buffer differs");
    assert!(golden.zbuf == rtl.zbuf, "second frame: Z-buffer differs");
    assert!(golden.rgb == rtl.rgb, "second frame: image differs");
}
