//! The one list of Verilator warnings waived on the generated Verilog, each with its reason and the
//! tops that need it, and the `verilator --lint-only -Wall` run every top's test uses. The waivers are
//! about what rust-hdl 0.46's code generator emits (GUIDE §4), not about the designs.

use std::path::Path;
use std::process::Command;

/// A waived Verilator warning: its name, why, and the tops it is waived for (empty: every top).
pub struct Waiver {
    pub warning: &'static str,
    pub why: &'static str,
    pub tops: &'static [&'static str],
}

/// Every waiver of `-Wall` on the project's tops.
pub const LINT_WAIVERS: &[Waiver] = &[
    Waiver {
        warning: "WIDTH",
        why: "rust-hdl emits `bit_cast` as `x & N'hmask` (wider than x), 32- and 64-bit literals for enum values and struct-field offsets, and 32-bit `index() == i` compares, whatever the operand widths",
        tops: &[],
    },
    Waiver { warning: "DECLFILENAME", why: "rust-hdl writes every module of a top's hierarchy into one file", tops: &[] },
    Waiver {
        warning: "UNUSEDSIGNAL",
        why: "slices drop bits on purpose, and rust-hdl cannot slice a cast, so each slice reads a whole-width local: the RC's 4 subpixel bits of >> 4, product bits above a proven width, clamped box values' high bits, the divider's unused handshake; the CS's unread material field (Phong only) and debug overflow flag, colour setup's rounding remainders; PROOF's start values read only at load and the fraction bits a stage drops",
        tops: &[],
    },
    Waiver {
        warning: "UNUSEDPARAM",
        why: "rust-hdl copies each block's localparams (enum states, constants) into every child DFF module",
        tops: &["rc", "rc3", "colour_setup", "cs", "cs_tex", "chipset", "chipset3", "chipset_tex", "textured_setup"],
    },
    Waiver {
        warning: "UNOPTFLAT",
        why: "rust-hdl emits a block's combinational logic as one always @(*), so a block that drives a child's inputs (a multiplier, a division step) and reads its outputs is one vertex on a cycle for Verilator's scheduler, though no signal depends on itself (check_all finds no loop, Icarus settles every cycle; on `cs_tex` slowly, about 2 cycles/s, so its replay runs under Verilator)",
        tops: &["rc", "rc3", "colour_setup", "cs", "cs_tex", "chipset", "chipset3", "chipset_tex", "tex_coord", "tex_lod", "tex_setup", "textured_setup"],
    },
];

/// The `-Wno-...` flags for `top`.
pub fn waiver_flags(top: &str) -> Vec<String> {
    LINT_WAIVERS.iter().filter(|w| w.tops.is_empty() || w.tops.contains(&top)).map(|w| format!("-Wno-{}", w.warning)).collect()
}

/// `verilator --lint-only -Wall` on `verilog` (written to `dir/<top>.v`) with `top`'s waivers: Ok, or
/// the log with every warning and error.
pub fn lint(verilog: &str, top: &str, dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    let file = dir.join(format!("{top}.v"));
    std::fs::write(&file, verilog).map_err(|e| e.to_string())?;
    let out = Command::new("verilator")
        .args(["--lint-only", "-Wall", "--top-module", top])
        .args(waiver_flags(top))
        .arg(&file)
        .output()
        .map_err(|e| format!("cannot run verilator: {e}"))?;
    let text = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() || text.contains("%Warning") || text.contains("%Error") {
        return Err(format!("verilator --lint-only -Wall on {top} (waived: {}):\n{text}", waiver_flags(top).join(" ")));
    }
    Ok(())
}
