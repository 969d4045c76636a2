//! `hdl::common::MulSplit`'s Verilog: exact against the i128 product under Icarus for every shape the
//! chipset instantiates (extremes and random operands), and fewer ECP5 multiplier blocks than a plain
//! `a * b` of the same shape (yosys `synth_ecp5`), which is the reason it exists.

use hdl::common::mul_split_verilog;
use std::process::Command;
use tb::common::{require_tools, scratch_dir};

/// The shapes in use: (A, B, P, LA, LB, multiplier blocks of the plain product, of the split one).
/// The plain counts are what yosys 0.23 `synth_ecp5` gives for `a * b` (18-bit pieces per operand).
const SHAPES: &[(usize, usize, usize, usize, usize, usize, usize)] = &[
    (25, 18, 43, 7, 0, 2, 1),
    (40, 18, 58, 5, 0, 3, 2),
    (44, 26, 70, 9, 8, 6, 2),
    (26, 36, 64, 8, 0, 4, 2),
    (40, 18, 64, 5, 0, 3, 2),
    (11, 40, 51, 10, 0, 3, 0),
];

fn module(a: usize, b: usize, p: usize, la: usize, lb: usize, name: &str) -> String {
    format!(
        "module {name}(input signed [{}:0] a, input signed [{}:0] b, output reg signed [{}:0] p);\n{}\nendmodule\n",
        a - 1,
        b - 1,
        p - 1,
        mul_split_verilog(a, b, p, la, lb)
    )
}

/// Operands: both ends of each range, zero, one, minus one and a fixed pseudo-random spread.
fn operands(bits: usize, seed: u64) -> Vec<i128> {
    let min = -(1i128 << (bits - 1));
    let max = (1i128 << (bits - 1)) - 1;
    let mut v = vec![min, max, 0, 1, -1, min + 1, max - 1];
    let mut x = seed;
    for _ in 0..40 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let r = (x as i128) & ((1i128 << bits) - 1);
        v.push(if r > max { r - (1i128 << bits) } else { r });
    }
    v
}

fn hex(v: i128, bits: usize) -> String {
    format!("{bits}'h{:x}", (v as u128) & ((1u128 << bits) - 1))
}

#[test]
fn split_multipliers_equal_the_exact_product_in_verilog_for_every_shape_in_use() {
    if !require_tools("split_multipliers_equal_the_exact_product_in_verilog_for_every_shape_in_use", &["iverilog", "vvp"]) {
        return;
    }
    let dir = scratch_dir("mul_split_sim");
    for (k, &(a, b, p, la, lb, _, _)) in SHAPES.iter().enumerate() {
        let mut tb = module(a, b, p, la, lb, "uut");
        tb.push_str(&format!(
            "module bench;\nreg signed [{}:0] a; reg signed [{}:0] b; wire signed [{}:0] p;\ninteger errors = 0;\nuut u(.a(a), .b(b), .p(p));\ninitial begin\n",
            a - 1,
            b - 1,
            p - 1
        ));
        let mut n = 0;
        for &x in &operands(a, 0x9e37_79b9 + k as u64) {
            for &y in operands(b, 0x1234_5678 + k as u64).iter().take(12) {
                let want = x.wrapping_mul(y);
                tb.push_str(&format!(
                    "a = {}; b = {}; #1; if (p !== {}) begin errors = errors + 1; $display(\"MISMATCH a=%h b=%h p=%h\", a, b, p); end\n",
                    hex(x, a),
                    hex(y, b),
                    hex(want, p)
                ));
                n += 1;
            }
        }
        tb.push_str("if (errors == 0) $display(\"ALL EQUAL\"); $finish;\nend\nendmodule\n");
        let src = dir.join(format!("split_{a}x{b}_{la}_{lb}.v"));
        std::fs::write(&src, tb).unwrap();
        let bin = dir.join(format!("split_{a}x{b}_{la}_{lb}.vvp"));
        let c = Command::new("iverilog").args(["-g2012", "-o"]).arg(&bin).arg(&src).output().unwrap();
        assert!(c.status.success(), "iverilog {a}x{b}: {}", String::from_utf8_lossy(&c.stderr));
        let r = Command::new("vvp").arg(&bin).output().unwrap();
        let out = String::from_utf8_lossy(&r.stdout);
        assert!(out.contains("ALL EQUAL") && !out.contains("MISMATCH"), "{a}x{b} split {la}/{lb}, {n} products:\n{out}");
    }
}

#[test]
fn split_multipliers_take_fewer_ecp5_multiplier_blocks_than_the_plain_product() {
    if !require_tools("split_multipliers_take_fewer_ecp5_multiplier_blocks_than_the_plain_product", &["yosys"]) {
        return;
    }
    let dir = scratch_dir("mul_split_synth");
    let blocks = |src: &str, name: &str| -> usize {
        let f = dir.join(format!("{name}.v"));
        std::fs::write(&f, src).unwrap();
        let o = Command::new("yosys")
            .arg("-q")
            .arg("-p")
            .arg(format!("read_verilog {}; synth_ecp5 -top {name}; tee -o {}.stat stat", f.display(), dir.join(name).display()))
            .output()
            .unwrap();
        assert!(o.status.success(), "yosys {name}: {}", String::from_utf8_lossy(&o.stderr));
        let stat = std::fs::read_to_string(dir.join(format!("{name}.stat"))).unwrap();
        stat.lines().find(|l| l.trim_start().starts_with("MULT18X18D")).map_or(0, |l| l.split_whitespace().nth(1).unwrap().parse().unwrap())
    };
    for &(a, b, p, la, lb, plain, split) in SHAPES {
        let name = format!("plain_{a}x{b}");
        let plain_src = format!(
            "module {name}(input signed [{}:0] a, input signed [{}:0] b, output signed [{}:0] p);\nassign p = a * b;\nendmodule\n",
            a - 1,
            b - 1,
            p - 1
        );
        let got_plain = blocks(&plain_src, &name);
        let sname = format!("split_{a}x{b}_{la}_{lb}");
        let got_split = blocks(&module(a, b, p, la, lb, &sname), &sname);
        assert_eq!((got_plain, got_split), (plain, split), "{a}x{b} split {la}/{lb}: MULT18X18D plain and split");
    }
}
