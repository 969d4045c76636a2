//! The products the texture path computes in logic instead of on MULT18X18D blocks
//! (`hdl::common::MulLogicU`, `hdl::common::LerpDeltaLogic`; docs/texture.md, "The budget"): their
//! generated Verilog, and the ECP5 netlist Yosys makes of it, give Verilog's own `*` for every input,
//! and the netlist has no multiplier block. The Rust side of each leaf is checked by the texel filter's
//! and the texture unit's benches against golden.
//! The RC reciprocal's two-steps-in-one leaf (`hdl::common::DivStep2x45`) is checked the same way against
//! two chained restoring steps.

use hdl::common::{verilog_named, LerpDeltaLogic, MulLogicU, MulPipeS, MulSplitS, SquareLogicS, SquareLogicU};
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
    check_blocks(name, verilog, tbs, dir, 0);
}

/// [`check`] for a product that keeps `blocks` MULT18X18D (its high parts) and the rest in logic.
fn check_blocks(name: &str, verilog: &str, tbs: &[String], dir: &Path, blocks: usize) {
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
    let used: usize = stat.lines().find(|l| l.contains("MULT18X18D")).and_then(|l| l.split_whitespace().last()?.parse().ok()).unwrap_or(0);
    assert_eq!(used, blocks, "{name}: synth_ecp5 used {used} multiplier blocks, not {blocks}:\n{stat}");
    assert!(stat.contains("LUT4"), "{name}: no LUT4 in the netlist:\n{stat}");
    let cells = "/usr/share/yosys/ecp5/cells_sim.v";
    // Yosys 0.23's ECP5 simulation models have no MULT18X18D: the netlist of a product that keeps
    // blocks is simulated with `mult18x18d_model()`, which models them as synth_ecp5 uses them here
    // (no parameters: combinational).
    let netlist = std::fs::read_to_string(&net).unwrap();
    assert!(!netlist.contains("MULT18X18D #("), "{name}: a multiplier block with parameters (registers?), which the model does not cover");
    let model = dir.join("mult18x18d_model.v");
    std::fs::write(&model, if blocks > 0 { mult18x18d_model() } else { String::new() }).unwrap();
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
            Command::new("iverilog").arg("-I").arg("/usr/share/yosys/ecp5").arg("-o").arg(&nsim).arg(&net).arg(cells).arg(&model).arg(&tbf),
            &format!("{name}: iverilog on the netlist"),
        );
        let text = run(Command::new("vvp").arg("-n").arg(&nsim), &format!("{name}: vvp on the netlist"));
        assert!(text.contains(" mismatches 0"), "{name}: Yosys's netlist is not the product ({}):\n{text}", tbf.display());
    }
    let luts = stat.lines().find(|l| l.contains("LUT4")).unwrap_or("").trim().to_string();
    println!("{name}: every input gives the reference (Verilog's `*`, or two chained steps), in the Verilog and in Yosys's ECP5 netlist ({luts}, {blocks} MULT18X18D)");
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

/// ECP5's MULT18X18D as a combinational product: `P = A * B`, each operand signed or unsigned by
/// SIGNEDA / SIGNEDB (SOURCEA/B and the C port unused), for the netlist simulations.
fn mult18x18d_model() -> String {
    let ports = |p: &str, n: usize| (0..n).map(|i| format!("{p}{i}")).collect::<Vec<_>>();
    let cat = |p: &str, n: usize| format!("{{{}}}", ports(p, n).into_iter().rev().collect::<Vec<_>>().join(", "));
    format!(
        "module MULT18X18D(input {a}, {b}, {c}, SIGNEDA, SIGNEDB, SOURCEA, SOURCEB, output {p});\n  wire [17:0] av = {ca};\n  wire [17:0] bv = {cb};\n  wire signed [35:0] ax = SIGNEDA ? {{{{18{{av[17]}}}}, av}} : {{18'b0, av}};\n  wire signed [35:0] bx = SIGNEDB ? {{{{18{{bv[17]}}}}, bv}} : {{18'b0, bv}};\n  wire [35:0] pv = ax * bx;\n  assign {cp} = pv;\nendmodule\n",
        a = ports("A", 18).join(", "),
        b = ports("B", 18).join(", "),
        c = ports("C", 18).join(", "),
        p = ports("P", 36).join(", "),
        ca = cat("A", 18),
        cb = cat("B", 18),
        cp = cat("P", 36),
    )
}

/// A testbench of `n` operand pairs of a signed `wa` x `wb` -> `wp` product against Verilog's `*`: the
/// first 64 pairs from the extremes and small values of each operand (every combination), the rest
/// random (`$random` words, as wide as the operand).
fn random_testbench(wa: usize, wb: usize, wp: usize, n: usize) -> String {
    operand_testbench(wa, wb, wp, n, false)
}

/// [`random_testbench`] for a product with a clock and an enable (`clocked`, [`MulPipeS`]): before each
/// rising edge `p` must still be the product of the pair before, after it the product of the new pair,
/// or of the pair before when `ce` was low at the edge (every seventh).
fn operand_testbench(wa: usize, wb: usize, wp: usize, n: usize, clocked: bool) -> String {
    let word = |w: usize| format!("{{{}}}", vec!["$random"; w.div_ceil(32)].join(", "));
    let corner = |w: usize, name: &str| {
        format!(
            "case (k) 0: {name} = {{1'b1, {{{m}{{1'b0}}}}}}; 1: {name} = {{1'b0, {{{m}{{1'b1}}}}}}; 2: {name} = -1; 3: {name} = 0; 4: {name} = 1; 5: {name} = {{{w}{{1'b1}}}} << {h}; 6: {name} = ({w}'d1 << {h}) - 1; default: {name} = {r}; endcase",
            m = w - 1,
            h = w / 2,
            r = word(w)
        )
    };
    format!(
        "module tb;\n    reg signed [{a}:0] a;\n    reg signed [{b}:0] b;\n    wire signed [{o}:0] p;\n    reg signed [{o}:0] want;\n    integer i, k, bad;\n    {inst}\n    initial begin\n      bad = 0;\n      {init}\n      for (i = 0; i < {n}; i = i + 1) begin\n        if (i < 64) begin\n          k = i % 8; {ca}\n          k = i / 8; {cb}\n        end else begin\n          a = {ra};\n          b = {rb};\n        end\n        #1;\n        {before}want = a * b;\n        if (p !== want) begin\n          if (bad < 5) $display(\"mismatch at %0d: %0d * %0d got %0d want %0d\", i, a, b, p, want);\n          bad = bad + 1;\n        end\n      end\n      $display(\"checked %0d mismatches %0d\", {n}, bad);\n      $finish;\n    end\nendmodule\n",
        a = wa - 1,
        b = wb - 1,
        o = wp - 1,
        ca = corner(wa, "a"),
        cb = corner(wb, "b"),
        ra = word(wa),
        rb = word(wb),
        inst = if clocked { "reg clock, ce;\n    lp uut(.clock(clock), .ce(ce), .a(a), .b(b), .p(p));" } else { "lp uut(.a(a), .b(b), .p(p));" },
        init = if clocked { "clock = 0; ce = 1; a = 0; b = 0; #1 clock = 1; #1 clock = 0; want = 0;" } else { "" },
        // Every seventh edge with ce low: the product of the pair before must stand.
        before = if clocked {
            "if (p !== want) begin if (bad < 5) $display(\"changed before the edge at %0d: got %0d want %0d\", i, p, want); bad = bad + 1; end\n        ce = (i % 7 != 3); #1 clock = 1; #1 clock = 0;\n        if (ce) "
        } else {
            ""
        },
    )
}

/// The split products of the setup blocks (`MulSplitS`, issue 15 item 3's 21-bit edge deltas): each
/// shape setup uses equals Verilog's `*` on extreme and random operands, in the generated Verilog and
/// in Yosys's ECP5 netlist, and keeps only its high parts' MULT18X18D: the count the S11.4 design's
/// narrower products had (a 21x21 product with 3 + 3 low bits in logic: one block, where `*` takes four).
#[test]
fn the_split_products_of_setup_equal_verilogs_multiply_and_keep_the_blocks_of_their_high_parts() {
    if !require_tools("the_split_products_of_setup_equal_verilogs_multiply_and_keep_the_blocks_of_their_high_parts", &["iverilog", "vvp", "yosys"]) {
        return;
    }
    let root = workspace_target().join("hdl").join("split_products");
    let _ = std::fs::remove_dir_all(&root);
    fn one<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize>(root: &Path, what: &str, blocks: usize) {
        let mut m = MulSplitS::<A, B, P, KA, KB>::default();
        m.connect_all();
        let v = verilog_named(&m, "lp").unwrap();
        let name = format!("MulSplitS<{A}, {B}, {P}, {KA}, {KB}> ({what})");
        check_blocks(&name, &v, &[random_testbench(A, B, P, 1000)], &root.join(format!("s{A}x{B}_{KA}_{KB}")), blocks);
    }
    one::<21, 21, 42, 3, 3>(&root, "det and edge operands", 1);
    one::<25, 21, 46, 7, 3>(&root, "the RC's dot units", 1);
    one::<40, 21, 61, 0, 3>(&root, "plane C of texture setup", 3);
    one::<40, 21, 64, 5, 3>(&root, "colour setup's plane C", 2);
    one::<40, 26, 64, 4, 0>(&root, "colour setup's A and B", 4);
    one::<34, 21, 55, 0, 3>(&root, "texture setup's numerators", 2);
    one::<55, 26, 80, 3, 0>(&root, "texture setup's A and B", 6);
}

/// The Color Shader's plane product (`PlaneMul`, 40x11: two multiplier blocks and five LUT rows, also
/// the texture units' `tex_coord`) equals Verilog's `*` on extreme and random operands, in its
/// hand-written Verilog and in Yosys's ECP5 netlist, and keeps exactly two MULT18X18D. (Until now only
/// the CS's Verilog replays checked that Verilog, on the operands a few frames happen to produce.)
#[test]
fn the_plane_product_of_the_colour_shader_equals_verilogs_multiply_on_two_multiplier_blocks() {
    if !require_tools("the_plane_product_of_the_colour_shader_equals_verilogs_multiply_on_two_multiplier_blocks", &["iverilog", "vvp", "yosys"]) {
        return;
    }
    let root = workspace_target().join("hdl").join("plane_product");
    let _ = std::fs::remove_dir_all(&root);
    let mut m = hdl::cs::plane_mul::PlaneMul::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    check_blocks("PlaneMul (40x11)", &v, &[random_testbench(40, 11, 51, 2000)], &root, 2);
}

/// The pipelined products (`MulPipeS`: partial products registered, their sum in the next cycle; issue
/// 15 item 5): each shape equals Verilog's `*` of the operands at the last rising edge (and not before
/// it), on extreme and random operands, in the generated Verilog and in Yosys's ECP5 netlist, on as
/// many MULT18X18D as pairs of pieces.
#[test]
fn the_pipelined_products_equal_verilogs_multiply_one_edge_later_on_one_block_per_pair_of_pieces() {
    if !require_tools("the_pipelined_products_equal_verilogs_multiply_one_edge_later_on_one_block_per_pair_of_pieces", &["iverilog", "vvp", "yosys"]) {
        return;
    }
    let root = workspace_target().join("hdl").join("pipe_products");
    let _ = std::fs::remove_dir_all(&root);
    fn one<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize>(root: &Path, what: &str, blocks: usize) {
        let mut m = MulPipeS::<A, B, P, KA, KB>::default();
        m.connect_all();
        let v = verilog_named(&m, "lp").unwrap();
        let name = format!("MulPipeS<{A}, {B}, {P}, {KA}, {KB}> ({what})");
        check_blocks(&name, &v, &[operand_testbench(A, B, P, 1000, true)], &root.join(format!("p{A}x{B}_{KA}_{KB}")), blocks);
    }
    one::<40, 26, 64, 5, 8>(&root, "colour setup's A and B", 2);
    one::<21, 21, 42, 3, 3>(&root, "the RC's det", 1);
    one::<25, 21, 46, 7, 3>(&root, "the RC's dot units", 1);
    one::<40, 21, 61, 5, 3>(&root, "the RC's plane C", 2);
}

/// The squares in logic (`SquareLogicU`, `SquareLogicS`: half the partial products of a general
/// product; issue 15 item 5, the 45F's multiplier count): the Color Shader's gloss squarer (15 bits
/// unsigned) and the normalizer's `n_k^2` (16 bits signed, the most negative value included) equal
/// Verilog's `a * a` for every input, in the generated Verilog and in Yosys's ECP5 netlist, which has no
/// multiplier block.
#[test]
fn the_squares_in_logic_equal_verilogs_multiply_for_every_input_and_use_no_dsp_block() {
    if !require_tools("the_squares_in_logic_equal_verilogs_multiply_for_every_input_and_use_no_dsp_block", &["iverilog", "vvp", "yosys"]) {
        return;
    }
    let root = workspace_target().join("hdl").join("logic_squares");
    let _ = std::fs::remove_dir_all(&root);
    let mut m = SquareLogicU::<15, 30>::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    check("SquareLogicU<15, 30> (gloss squarer)", &v, &[testbench(&[("a", 15)], 30, false, "a * a")], &root.join("u15"));
    let mut m = SquareLogicS::<16, 32>::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    check("SquareLogicS<16, 32> (normalizer)", &v, &[testbench(&[("a", 16)], 32, true, "$signed(a) * $signed(a)")], &root.join("s16"));
}

/// The RC reciprocal's two-steps-in-one leaf (`DivStep2x45`, issue 15 item 5): its generated Verilog
/// and Yosys's ECP5 netlist of it equal two chained restoring steps (`DivStep45`'s Verilog, written
/// out here) on random divisors of every width and remainders below twice the divisor, the edges
/// (den - 1, den, 2 den - 1) included.
#[test]
fn the_reciprocals_two_steps_in_one_equal_two_chained_steps_in_verilog_and_in_the_netlist() {
    if !require_tools("the_reciprocals_two_steps_in_one_equal_two_chained_steps_in_verilog_and_in_the_netlist", &["iverilog", "vvp", "yosys"]) {
        return;
    }
    let mut m = hdl::common::DivStep2x45::default();
    m.connect_all();
    let v = verilog_named(&m, "lp").unwrap();
    let tb = "module tb;
    reg [44:0] rem, den, r1, r2;
    reg [46:0] den3;
    reg [24:0] quo, q1, q2;
    reg [63:0] a, b;
    wire [44:0] rem_next;
    wire [24:0] quo_next;
    integer i, bad;
    lp uut(.rem(rem), .den(den), .den3(den3), .quo(quo), .rem_next(rem_next), .quo_next(quo_next));
    initial begin
      bad = 0;
      for (i = 0; i < 5000; i = i + 1) begin
        a = {$random, $random};
        b = {$random, $random};
        den = (a[43:0] >> (i % 44)) | 45'd1;
        case (i % 4)
          0: rem = b % (2 * den);
          1: rem = den - 45'd1;
          2: rem = 2 * den - 45'd1;
          default: rem = den;
        endcase
        den3 = 3 * den;
        quo = b[60:36];
        if (rem >= den) begin r1 = (rem - den) << 1; q1 = (quo << 1) | 25'd1; end else begin r1 = rem << 1; q1 = quo << 1; end
        if (r1 >= den) begin r2 = (r1 - den) << 1; q2 = (q1 << 1) | 25'd1; end else begin r2 = r1 << 1; q2 = q1 << 1; end
        #1;
        if (rem_next !== r2 || quo_next !== q2) begin
          if (bad < 5) $display(\"mismatch at %0d: rem %0d den %0d: got %0d %0d want %0d %0d\", i, rem, den, rem_next, quo_next, r2, q2);
          bad = bad + 1;
        end
      end
      $display(\"checked 5000 mismatches %0d\", bad);
      $finish;
    end
endmodule
"
    .to_string();
    check("DivStep2x45", &v, &[tb], &workspace_target().join("hdl").join("div_step2"));
}
