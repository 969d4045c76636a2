//! # hdl: the chipset's RustHDL blocks
//!
//! Synthesizable RTL only; it does not depend on the golden model (Cargo enforces the separation,
//! `tb/` joins the two). One block per file, a folder per unit:
//! * [`common`]: the valid/ready stream interface, wide multipliers, block RAM, safe casts;
//! * `rc/`: the Rasterizer Controller (seed 001 §3): setup, traversal, Z-test, I-buffer writes; and
//!   its Type III form (seed 000), `rc3`, whose visibility test regenerates depth from TdbV;
//! * `cs/`: colour setup and the Color Shader (seed 001 §2.3.2, §3.1);
//! * `proof/`: PROOF's object processors, shading and filter stages (seed 002).
//!
//! [`verilog_top`] generates the Verilog of a top by name (what `idxrender verilog --block` writes).

pub mod chipset;
pub mod common;
pub mod cs;
pub mod proof;
pub mod rc;

/// The tops that can be generated, and what each is.
pub const TOPS: &[(&str, &str)] = &[
    ("opp", "PROOF object-processor pipeline: 8 object processors, FIFO depth 1 (seed 002 section 4)"),
    ("proof_shade", "PROOF shading stage: 1 light-source processor, 1024-entry object table, one entry per clock (seed 002 section 5)"),
    ("proof_filter", "PROOF filter stage: 8x8 subpixel masks by the tree of multiples, 1x1 box, 1024-entry direction table, one entry per clock (seed 002 section 6)"),
    ("proof_filter2x2", "PROOF filter stage with the paper's 2x2-pixel filter area for a 320x200 screen: the same masks, quadrant sums, a streaming box with a 320-column line buffer, 1024-entry direction table, one entry per clock (seed 002 section 6)"),
    ("rc", "Rasterizer Controller for a 320x200 screen: setup, traversal, Z-test, Z/I-buffer ports"),
    ("rc3", "Type III Rasterizer Controller for a 320x200 screen (seed 000): no Z-buffer, depth regenerated from TdbV; I-buffer and TdbV ports"),
    ("colour_setup", "Colour setup: 3 planes with one reciprocal per triangle, TdbS write port (seed 001 eqs. 6-7)"),
    ("chipset", "The raster chipset for 320x200: RC + colour setup + CS around Z/I-buffer and TdbS memory ports"),
    ("chipset3", "The Type III raster chipset for 320x200 (seed 000): rc3 + colour setup + CS around I-buffer, TdbV and TdbS memory ports, no Z-buffer"),
    ("cs", "Color Shader: I-buffer + TdbS scan-out, 1 pixel/clock, AXI4-Stream video, clear-behind ports"),
    ("cs_tex", "Textured Color Shader: the cs with TdbT and four texture-bank read ports, per-pixel perspective-correct coordinates, nearest/bilinear at 1 pixel/clock, trilinear at 1 pixel per 2 clocks, MODULATE"),
    ("chipset_tex", "The textured raster chipset for 320x200: RC + textured setup (colour and texture planes) + cs_tex around Z/I-buffer, TdbS, TdbT and texture-bank memory ports"),
];

/// The screen the screen-sized tops are generated for unless another is asked for.
pub const DEFAULT_SCREEN: (u32, u32) = (320, 200);

/// The tops whose RTL depends on the screen size (address widths, the 2x2 filter's line buffer):
/// `idxrender verilog --size WxH` applies to these and leaves the others as they are.
pub const SCREEN_TOPS: &[&str] = &["proof_filter2x2", "rc", "rc3", "chipset", "chipset3", "chipset_tex"];

/// A text written for [`DEFAULT_SCREEN`] ("320x200", "320-column") said of a `screen` of width x
/// height pixels instead.
pub fn for_screen(text: &str, screen: (u32, u32)) -> String {
    let (w, h) = screen;
    let (dw, dh) = DEFAULT_SCREEN;
    text.replace(&format!("{dw}x{dh}"), &format!("{w}x{h}")).replace(&format!("{dw}-column"), &format!("{w}-column"))
}

/// The description of top `block` (from [`TOPS`]) for a `screen` of width x height pixels.
pub fn top_description(block: &str, screen: (u32, u32)) -> Option<String> {
    TOPS.iter().find(|t| t.0 == block).map(|t| for_screen(t.1, screen))
}

/// Generate the Verilog of the top named `block` (module name = `block`) for [`DEFAULT_SCREEN`].
pub fn verilog_top(block: &str) -> Result<String, String> {
    verilog_top_for(block, DEFAULT_SCREEN)
}

/// Generate the Verilog of the top named `block` (module name = `block`); the tops of
/// [`SCREEN_TOPS`] are sized for `screen` (width, height), the others do not depend on it.
pub fn verilog_top_for(block: &str, screen: (u32, u32)) -> Result<String, String> {
    let (w, h) = screen;
    match block {
        "opp" => proof::verilog_opp("opp", 8, 1),
        "proof_shade" => proof::verilog_shading("proof_shade", 1, 10),
        "proof_filter" => proof::verilog_filter("proof_filter", 10),
        "proof_filter2x2" => proof::verilog_filter2x2("proof_filter2x2", 10, w, h),
        "rc" => rc::verilog(w, h),
        "rc3" => rc::rc3::verilog(w, h),
        "colour_setup" => cs::colour_setup_verilog(),
        "cs" => cs::color_shader_verilog(),
        "chipset" => chipset::verilog(w, h),
        "chipset3" => chipset::chipset3::verilog(w, h),
        "cs_tex" => cs::color_shader_tex::verilog(),
        "chipset_tex" => chipset::chipset_tex::verilog(w, h),
        _ => Err(format!(
            "unknown block '{block}': known blocks are {}",
            TOPS.iter().map(|t| t.0).collect::<Vec<_>>().join(", ")
        )),
    }
}
