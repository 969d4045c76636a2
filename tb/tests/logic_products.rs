//! The products the texture path computes in logic instead of on MULT18X18D blocks
//! (`hdl::common::MulLogicU`, `hdl::common::LerpDeltaLogic`; docs/texture.md, "The budget"): their
//! generated Verilog, and the ECP5 netlist Yosys makes of it, give Verilog's own `*` for every input,
//! and the netlist has no multiplier block. The Rust side of each leaf is checked by the texel filter's
//! and the texture unit's benches against golden.

use hdl::common::{verilog_named, LerpDeltaLogic, MulLogicU};
use rust_hdl::prelude::*;
use std::path::Path;
use std::process::Command;
use tb::common::{require_tools, workspace_target};

fn run(cmd: &mut Command, what: &str) -> String {
    let out = cmd.output().unwrap_or_else(|e| panic!("{what}: {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{what} failed:\n{text}");
    text
}

/// Exhaustive testbench: every (x, y) of the leaf's two operand ports (`lo`/`hi` at a fixed `f`
/// sweep for the lerp), against `reference`, a Verilog expression in the port names.
fn testbench(ports: &[(&str, usize)], out_bits: usize, signed_out: bool, reference: &str) -> String {
    let decls: String = ports.iter().map(|(n, w)| format!("    reg [{}:0] {n};\n", w - 1)).collect();
    let conns: Vec<String> = ports.iter().map(|(n, _)| format!(".{n}({n})")).collect();
    let total: usize = ports.iter().map(|(_, w)| w).sum();
    let assigns: String = {
        let mut at = 0;
        ports.iter().map(|(n, w)| { let s = format!("        {n} = i[{}:{}];\n", at + w - 1, at); at += w; s }).collect()
    };
    let sign = if signed_out { "signed " } else { "" };
    format!(
        "module tb;\n{decls}    wire {sign}[{o}:0] p;\n    reg {sign}[{o}:0] want;\n    integer i, bad;\n    lp uut({c}, .p(p));\n    initial begin\n      bad = 0;\n      for (i = 0; i < {n}; i = i + 1) begin\n{assigns}        #1;\n        want = {reference};\n        if (p !== want) begin\n          if (bad < 5) $display(\"mismatch at %0d: got %0d want %0d\", i, p, want);\n          bad = bad + 1;\n        end\n      end\n      $display(\"checked %0d mismatches %0d\", {n}, bad);\n      $finish;\n    end\nendmodule\n",
        o = out_bits - 1,
        c = conns.join(", "),
        n = 1usize << total,
    )
}

fn check(name: &str, verilog: &str, tbs: &[String], dir: &Path) {
    std::fs::create_dir_all(dir).unwrap();
    let src = dir.join("lp.v");
    std::fs::write(&src, verilog).unwrap();
    // Yosys's ECP5 netlist of it: no MULT18X18D.
    let net = dir.join("net.v");
    let stat = dir.join("stat.txt");
    run(
        Command::new("yosys").arg("-q").arg("-p").arg(format!(
            "read_verilog {}; synth_ecp5 -top lp; tee -q -o {} stat; write_verilog -noattr {}",
            src.display(),
            stat.display(),
            net.display()
        )),
        &format!("{name}: yosys synth_ecp5"),
    );
    let stat = std::fs::read_to_string(&stat).unwrap();
    assert!(!stat.contains("MULT18X18D"), "{name}: synth_ecp5 used a multiplier block:\n{stat}");
    assert!(stat.contains("LUT4"), "{name}: no LUT4 in the netlist:\n{stat}");
    let cells = "/usr/share/yosys/ecp5/cells_sim.v";
    for (k, tb) in tbs.iter().enumerate() {
        let tbf = dir.join(format!("tb{k}.v"));
        std::fs::write(&tbf, tb).unwrap();
        // The generated Verilog.
        let sim = dir.join(format!("sim{k}"));
        run(Command::new("iverilog").arg("-o").arg(&sim).arg(&src).arg(&tbf), &format!("{name}: iverilog"));
        let text = run(Command::new("vvp").arg("-n").arg(&sim), &format!("{name}: vvp"));
        assert!(text.contains(" mismatches 0"), "{name}: the generated Verilog is not the product ({}):\n{text}", tbf.display());
        // Yosys's netlist, simulated with Yosys's ECP5 cell models.
        let nsim = dir.join(format!("nsim{k}"));
        run(
            Command::new("iverilog").arg("-I").arg("/usr/share/yosys/ecp5").arg("-o").arg(&nsim).arg(&net).arg(cells).arg(&tbf),
            &format!("{name}: iverilog on the netlist"),
        );
        let text = run(Command::new("vvp").arg("-n").arg(&nsim), &format!("{name}: vvp on the netlist"));
        assert!(text.contains(" mismatches 0"), "{name}: Yosys's netlist is not the product ({}):\n{text}", tbf.display());
    }
    let luts = stat.lines().find(|l| l.contains("LUT4")).unwrap_or("").trim().to_string();
    println!("{name}: every input equals `*`, in the Verilog and in Yosys's ECP5 netlist ({luts}, no MULT18X18D)");
}

#[test]
fn the_logic_products_of_the_texture_path_equal_verilogs_multiply_for_every_input_and_use_no_dsp_block() {
    if !require_tools(
        "the_logic_products_of_the_texture_path_equal_verilogs_multiply_for_every_input_and_use_no_dsp_block",
        &["iverilog", "vvp", "yosys"],
    ) {
        return;
    }
    let root = workspace_target().join("hdl").join("logic_products");
    let _ = std::fs::remove_dir_all(&root);

    let mut m = MulLogicU::<8, 8, 16>::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    check("MulLogicU<8, 8, 16> (MODULATE)", &v, &[testbench(&[("a", 8), ("b", 8)], 16, false, "a * b")], &root.join("mul8x8"));

    let mut m = MulLogicU::<8, 5, 13>::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    check("MulLogicU<8, 5, 13> (trilinear blend)", &v, &[testbench(&[("a", 8), ("b", 5)], 13, false, "a * b")], &root.join("mul8x5"));

    // 2^24 inputs would take minutes under Icarus (with the cell models): lo and hi exhaustively, at f
    // = 0, 255 and the two alternating patterns (each partial product present and absent).
    let mut m = LerpDeltaLogic::<8, 8, 17>::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    let tbs: Vec<String> = [0u32, 255, 0x55, 0xaa]
        .iter()
        .map(|f| {
            testbench(&[("lo", 8), ("hi", 8)], 17, true, &format!("($signed({{1'b0, hi}}) - $signed({{1'b0, lo}})) * $signed(9'd{f})"))
                .replace("    reg [7:0] hi;\n", &format!("    reg [7:0] hi;\n    wire [7:0] f = 8'd{f};\n"))
                .replace(".hi(hi)", ".hi(hi), .f(f)")
        })
        .collect();
    check("LerpDeltaLogic<8, 8, 17> (bilinear)", &v, &tbs, &root.join("lerp"));
}
