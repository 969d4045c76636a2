//! Combinational multipliers of any width as leaf blocks: hdl_gen's `*` exists only for 16x16
//! (GUIDE §1). In Verilog each is `p = a * b`, which yosys `synth_ice40 -dsp` maps onto SB_MAC16
//! blocks (a 24x18 product takes 3); the Rust simulation multiplies in i128 (operands up to 64 bits,
//! product truncated to P <= 128 bits).

use super::{bits_from_u128, from_i128, to_i128};
use rust_hdl::prelude::*;

/// Signed A x B -> P bits (two's complement, truncated if P is narrower than A + B).
#[derive(LogicBlock, Default)]
pub struct MulS<const A: usize, const B: usize, const P: usize> {
    pub a: Signal<In, Signed<A>>,
    pub b: Signal<In, Signed<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize> Logic for MulS<A, B, P> {
    fn update(&mut self) {
        // Inputs unchanged since the last evaluation: the product stands (the conversions to and from
        // i128 are most of the Rust simulation's cost of a wide product). Both start at 0, 0 * 0 = 0.
        if !self.a.changed && !self.b.changed {
            return;
        }
        let prod = to_i128(self.a.val()).wrapping_mul(to_i128(self.b.val()));
        self.p.next = from_i128::<P>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom("always @(*) p = a * b;".into())
    }
}

/// Signed A x B -> P bits with the low `KA` bits of `a` and the low `KB` bits of `b` multiplied in
/// logic, and only `(A - KA) x (B - KB)` on multiplier blocks: `a = ah 2^KA + al`, `b = bh 2^KB + bl`
/// (`ah`, `bh` the arithmetic high parts, `al`, `bl` unsigned), so
/// `a b = (ah bh) 2^(KA+KB) + (ah bl) 2^KA + al b`, with `ah bl` and `al b` as shifted sums
/// ([`logic_product_verilog`]'s form, signed). S11.8 coordinates (issue 15 item 3) made setup's edge
/// deltas 21 bits: a 21x21 product on MULT18X18D blocks takes four, split 3 + 3 bits it takes one and
/// two small adder trees. The Rust simulation multiplies exactly, as [`MulS`]; the Verilog is checked
/// against `*` under Icarus and on Yosys's ECP5 netlist (`tb/tests/logic_products.rs`).
#[derive(LogicBlock, Default)]
pub struct MulSplitS<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize> {
    pub a: Signal<In, Signed<A>>,
    pub b: Signal<In, Signed<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize> Logic for MulSplitS<A, B, P, KA, KB> {
    fn update(&mut self) {
        if !self.a.changed && !self.b.changed {
            return;
        }
        let prod = to_i128(self.a.val()).wrapping_mul(to_i128(self.b.val()));
        self.p.next = from_i128::<P>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(split_product_verilog(A, B, P, KA, KB))
    }
}

/// The Verilog of [`MulSplitS`]: `hh` on multiplier blocks, `hl` and `lb` as sums of shifted copies.
pub fn split_product_verilog(a: usize, b: usize, p: usize, ka: usize, kb: usize) -> String {
    assert!(ka < a && kb < b && p >= a.max(b), "split product {a}x{b} into {p} bits, {ka} + {kb} low bits in logic");
    // Each part as wide as its own product (the sums of shifted copies no wider than they need be).
    let (wh, whl, wlb) = (a - ka + b - kb, a - ka + kb, ka + b);
    let mut v = format!("wire signed [{}:0] ah = a[{}:{ka}];\nwire signed [{}:0] bh = b[{}:{kb}];\n", a - ka - 1, a - 1, b - kb - 1, b - 1);
    v += &format!("wire signed [{}:0] hh = ah * bh;\n", wh - 1);
    let sum = |x: &str, sel: &str, bits: usize, w: usize| -> String {
        if bits == 0 {
            return format!("{w}'sd0");
        }
        (0..bits).map(|i| format!("({sel}[{i}] ? ({x} <<< {i}) : {w}'sd0)")).collect::<Vec<_>>().join(" + ")
    };
    if kb > 0 {
        v += &format!("wire [{}:0] bl = b[{}:0];\nwire signed [{}:0] ahx = ah;\n", kb - 1, kb - 1, whl - 1);
    }
    if ka > 0 {
        v += &format!("wire [{}:0] al = a[{}:0];\nwire signed [{}:0] bx = b;\n", ka - 1, ka - 1, wlb - 1);
    }
    v += &format!("wire signed [{}:0] hl = {};\n", whl - 1, sum("ahx", "bl", kb, whl));
    v += &format!("wire signed [{}:0] lb = {};\n", wlb - 1, sum("bx", "al", ka, wlb));
    v += &format!("always @(*) p = (hh <<< {}) + (hl <<< {ka}) + lb;", ka + kb);
    v
}

/// Signed A x B -> P bits over one clock edge: `p` is the product of the operands `a` and `b` held at
/// the last rising edge of `clock` where `ce` was high (latency 1; with `ce` low the product stands).
/// In Verilog the partial products are registered and only their shifted sum is combinational
/// ([`pipe_product_verilog`]): as in [`MulSplitS`], the low `KA` bits of `a` times `b` and the low `KB`
/// bits of `b` times the high part of `a` in logic, and the high parts cut into 17-bit unsigned pieces
/// under one signed top piece of at most 18 bits, each pair on one MULT18X18D. Setup's products were a
/// register, the blocks and the sum of their partials in one cycle, 8-9 ns of logic and 10-12 ns of
/// routing on the ECP5 (issue 15 item 5): here the blocks' outputs end the cycle. The Rust simulation
/// registers the exact product, which the partials' sum equals modulo 2^P; the Verilog is checked
/// against `*` one edge later, and against holding when `ce` is low, under Icarus and on Yosys's ECP5
/// netlist (`tb/tests/logic_products.rs`).
#[derive(LogicBlock, Default)]
pub struct MulPipeS<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize> {
    pub clock: Signal<In, Clock>,
    /// Take the operands at this edge.
    pub ce: Signal<In, Bit>,
    pub a: Signal<In, Signed<A>>,
    pub b: Signal<In, Signed<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize, const KA: usize, const KB: usize> Logic for MulPipeS<A, B, P, KA, KB> {
    fn update(&mut self) {
        if self.clock.pos_edge() && self.ce.val() {
            let prod = to_i128(self.a.val()).wrapping_mul(to_i128(self.b.val()));
            self.p.next = from_i128::<P>(prod);
        }
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(pipe_product_verilog(A, B, P, KA, KB))
    }
}

/// The pieces [`MulPipeS`] cuts bits `lo..hi` of an operand into, lowest first: (lowest bit, width,
/// signed). 17-bit unsigned pieces (18 bits with a zero on top, one MULT18X18D operand) while more than
/// 18 bits are left, then the signed rest.
fn product_pieces(lo: usize, hi: usize) -> Vec<(usize, usize, bool)> {
    let mut v = Vec::new();
    let mut at = lo;
    while hi - at > 18 {
        v.push((at, 17, false));
        at += 17;
    }
    v.push((at, hi - at, true));
    v
}

/// The Verilog of [`MulPipeS`]: one registered 18x18 (or narrower) signed product per pair of pieces
/// of `ah = a >> ka` and `bh = b >> kb`, the rows of `al * b` and `ah * bl` as registered sums of
/// shifted copies, and `p` the shifted sum of them all (`a b = ah bh 2^(ka+kb) + ah bl 2^ka + al b`).
pub fn pipe_product_verilog(a: usize, b: usize, p: usize, ka: usize, kb: usize) -> String {
    assert!(ka < a && kb < b && p >= a.max(b) && p <= a + b, "pipelined product {a}x{b} into {p} bits, {ka} + {kb} low bits in logic");
    let (pa, pb) = (product_pieces(ka, a), product_pieces(kb, b));
    let mut v = String::new();
    let piece = |name: &str, port: &str, k: usize, (lo, w, signed): (usize, usize, bool)| -> (String, usize) {
        if signed {
            (format!("wire signed [{}:0] {name}{k} = {port}[{}:{lo}];\n", w - 1, lo + w - 1), w)
        } else {
            (format!("wire signed [{w}:0] {name}{k} = {{1'b0, {port}[{}:{lo}]}};\n", lo + w - 1), w + 1)
        }
    };
    let wa: Vec<usize> = pa.iter().enumerate().map(|(k, &x)| { let (d, w) = piece("pa", "a", k, x); v += &d; w }).collect();
    let wb: Vec<usize> = pb.iter().enumerate().map(|(k, &x)| { let (d, w) = piece("pb", "b", k, x); v += &d; w }).collect();
    let mut regs = String::new();
    let mut terms = Vec::new();
    for (i, &(la, _, _)) in pa.iter().enumerate() {
        for (j, &(lb, _, _)) in pb.iter().enumerate() {
            v += &format!("reg signed [{}:0] pp{i}_{j};\n", wa[i] + wb[j] - 1);
            regs += &format!("    pp{i}_{j} <= pa{i} * pb{j};\n");
            terms.push(format!("(pp{i}_{j} <<< {})", la + lb));
        }
    }
    // The rows in logic, in registered sums of at most three: Yosys 0.23 maps a sum of five such rows
    // into 781 LUT4, of three and two into 253 (measured on 5 x 26 bits).
    // `x` (declared by `decl`) times the bits of `sel` below `n`, as rows `w` bits wide.
    let rows = |decl: String, name: &str, x: &str, sel: &str, n: usize, w: usize, shift: usize| -> (String, String, Vec<String>) {
        let (mut d, mut r, mut t) = (decl, String::new(), Vec::new());
        for (g, lo) in (0..n).step_by(3).enumerate() {
            let sum: Vec<String> = (lo..n.min(lo + 3)).map(|i| format!("({sel}[{i}] ? ({x} <<< {i}) : {w}'sd0)")).collect();
            d += &format!("wire signed [{}:0] {name}{g} = {};\nreg signed [{}:0] {name}r{g};\n", w - 1, sum.join(" + "), w - 1);
            r += &format!("    {name}r{g} <= {name}{g};\n");
            t.push(format!("({name}r{g} <<< {shift})"));
        }
        (d, r, t)
    };
    let mut add = |(d, r, t): (String, String, Vec<String>)| {
        v += &d;
        regs += &r;
        terms.extend(t);
    };
    if kb > 0 {
        let w = a - ka + kb;
        add(rows(format!("wire signed [{}:0] ahx = $signed(a[{}:{ka}]);\n", w - 1, a - 1), "hl", "ahx", "b", kb, w, ka));
    }
    if ka > 0 {
        let w = ka + b;
        add(rows(format!("wire signed [{}:0] bx = b;\n", w - 1), "lb", "bx", "a", ka, w, 0));
    }
    v += &format!("always @(posedge clock) if (ce) begin\n{regs}end\nalways @(*) p = {};", terms.join(" + "));
    v
}

/// The Verilog of an unsigned product in logic: one sum of B partial products (`a` shifted by i where
/// bit i of `b` is set, each extended to P bits by the context), so that Yosys builds an adder tree of
/// LUTs (its `$macc` mapping) instead of a `$mul` that `synth_ecp5` would put on a MULT18X18D. The
/// same function as `a * b` truncated to P bits.
pub fn logic_product_verilog(a_bits: usize, b_bits: usize, p_bits: usize) -> String {
    assert!(p_bits >= a_bits && b_bits >= 1, "logic product {a_bits}x{b_bits} into {p_bits} bits");
    shifted_sum_verilog("a", "b", b_bits, p_bits, false)
}

/// `always @(*) p = ...`: the sum over i < `bits` of `x << i` where bit i of `sel` is set, each term P
/// bits (signed terms, zero and shift when `signed`).
fn shifted_sum_verilog(x: &str, sel: &str, bits: usize, p_bits: usize, signed: bool) -> String {
    let (zero, shl) = if signed { (format!("{p_bits}'sd0"), "<<<") } else { (format!("{p_bits}'d0"), "<<") };
    let terms: Vec<String> = (0..bits)
        .map(|i| if i == 0 { format!("({sel}[0] ? {x} : {zero})") } else { format!("({sel}[{i}] ? ({x} {shl} {i}) : {zero})") })
        .collect();
    format!("always @(*) p = {};", terms.join("\n    + "))
}

/// Unsigned A x B -> P bits: [`MulU`] (`p = a * b`, which synthesis puts on multiplier blocks) or
/// [`MulLogicU`] (the same product as a sum in logic, [`logic_product_verilog`]); `IN_LOGIC` picks the
/// Verilog, the Rust model is the same.
#[derive(LogicBlock, Default)]
pub struct MulUnsigned<const A: usize, const B: usize, const P: usize, const IN_LOGIC: bool> {
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<B>>,
    pub p: Signal<Out, Bits<P>>,
}

/// Unsigned A x B -> P bits.
pub type MulU<const A: usize, const B: usize, const P: usize> = MulUnsigned<A, B, P, false>;

/// Unsigned A x B -> P bits, in logic rather than on a DSP block ([`logic_product_verilog`]): for the
/// small products of the texture path (8-bit texels times 8- or 5-bit weights), where a MULT18X18D
/// would be mostly unused and the chip has too few of them (docs/texture.md, the budget).
pub type MulLogicU<const A: usize, const B: usize, const P: usize> = MulUnsigned<A, B, P, true>;

impl<const A: usize, const B: usize, const P: usize, const IN_LOGIC: bool> Logic for MulUnsigned<A, B, P, IN_LOGIC> {
    fn update(&mut self) {
        if !self.a.changed && !self.b.changed {
            return;
        }
        let prod = self.a.val().to_u128().wrapping_mul(self.b.val().to_u128());
        self.p.next = bits_from_u128::<P>(prod);
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        if IN_LOGIC {
            Verilog::Custom(logic_product_verilog(A, B, P))
        } else {
            Verilog::Custom("always @(*) p = a * b;".into())
        }
    }
}

/// The square of an unsigned A-bit operand -> P bits, in logic ([`square_logic_verilog`]): a square
/// needs about half the partial products of a general product (`x_i x_j` and `x_j x_i` are one term),
/// so it costs about half the LUTs of [`MulLogicU`] (488 LUT4 and 15 CCU2C for 15 bits on the ECP5
/// against 961). For the Color Shader's gloss squarers, which the 45F's 72 MULT18X18D cannot also hold
/// (issue 15 item 5).
#[derive(LogicBlock, Default)]
pub struct SquareLogicU<const A: usize, const P: usize> {
    pub a: Signal<In, Bits<A>>,
    pub p: Signal<Out, Bits<P>>,
}

impl<const A: usize, const P: usize> Logic for SquareLogicU<A, P> {
    fn update(&mut self) {
        if !self.a.changed {
            return;
        }
        let a = self.a.val().to_u128();
        self.p.next = bits_from_u128::<P>(a.wrapping_mul(a));
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(square_logic_verilog(A, P, false))
    }
}

/// [`SquareLogicU`] of a two's complement operand: the square of its magnitude (`2^(A-1)` for the
/// most negative value, which still fits A unsigned bits). For the normalizer's `n_k^2`.
#[derive(LogicBlock, Default)]
pub struct SquareLogicS<const A: usize, const P: usize> {
    pub a: Signal<In, Signed<A>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const P: usize> Logic for SquareLogicS<A, P> {
    fn update(&mut self) {
        if !self.a.changed {
            return;
        }
        let a = to_i128(self.a.val());
        self.p.next = from_i128::<P>(a.wrapping_mul(a));
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(square_logic_verilog(A, P, true))
    }
}

/// The Verilog of [`SquareLogicU`] (and, with `signed`, of [`SquareLogicS`] on the magnitude `m`):
/// `m^2 = sum_i m_i (2^(2i) + 2^(i+1) sum_(j>i) m_j 2^j)`, so row i, present when bit i is set, is
/// `{m[A-1:i+1], 2'b01} << 2i`; rows are 2A bits wide and the sum is truncated to P.
pub fn square_logic_verilog(a_bits: usize, p_bits: usize, signed: bool) -> String {
    assert!(a_bits >= 2 && p_bits >= a_bits, "logic square of {a_bits} bits into {p_bits}");
    let w = 2 * a_bits;
    let mut v = if signed {
        format!("wire [{n}:0] m = a[{n}] ? ({a_bits}'d0 - a) : a;\n", n = a_bits - 1)
    } else {
        format!("wire [{}:0] m = a;\n", a_bits - 1)
    };
    for i in 0..a_bits {
        let row = if i + 1 < a_bits {
            format!("{{{}'d0, m[{}:{}], 2'b01}} << {}", w - (a_bits - i - 1) - 2, a_bits - 1, i + 1, 2 * i)
        } else {
            format!("{w}'d1 << {}", 2 * i)
        };
        v += &format!("wire [{}:0] r{i} = m[{i}] ? ({row}) : {w}'d0;\n", w - 1);
    }
    let rows: Vec<String> = (0..a_bits).map(|i| format!("r{i}")).collect();
    v += &format!("wire [{}:0] row_sum = {};\nalways @(*) p = row_sum[{}:0];", w - 1, rows.join(" + "), p_bits.min(w) - 1);
    v
}

/// `(hi - lo) * f` -> P bits, in logic (as [`logic_product_verilog`], with the signed A + 1-bit
/// difference `hi - lo` in place of `a`): the product of a lerp `lo (2^B - f) + hi f = (lo << B) + (hi - lo) f`. The difference
/// is taken inside the leaf: Verilator reads a parent that computes a child's input and uses its output
/// in one `always` block as a combinational loop (UNOPTFLAT) when the child is a sum like this one.
#[derive(LogicBlock, Default)]
pub struct LerpDeltaLogic<const A: usize, const B: usize, const P: usize> {
    pub lo: Signal<In, Bits<A>>,
    pub hi: Signal<In, Bits<A>>,
    pub f: Signal<In, Bits<B>>,
    pub p: Signal<Out, Signed<P>>,
}

impl<const A: usize, const B: usize, const P: usize> Logic for LerpDeltaLogic<A, B, P> {
    fn update(&mut self) {
        if !self.lo.changed && !self.hi.changed && !self.f.changed {
            return;
        }
        let d = self.hi.val().to_u128() as i128 - self.lo.val().to_u128() as i128;
        self.p.next = from_i128::<P>(d.wrapping_mul(self.f.val().to_u128() as i128));
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        assert!(P > A, "lerp delta {A}x{B} into {P} bits");
        Verilog::Custom(shifted_sum_verilog("($signed({1'b0, hi}) - $signed({1'b0, lo}))", "f", B, P, true))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::{from_i64, to_i128};

    #[test]
    fn the_split_product_is_exact_in_the_rust_model() {
        let mut m = MulSplitS::<21, 21, 42, 3, 3>::default();
        m.connect_all();
        for (a, b) in [(-(1i64 << 20), -(1i64 << 20)), ((1 << 20) - 1, -(1 << 20)), (-12345, 678), (7, -1)] {
            m.a.next = from_i64::<21>(a);
            m.b.next = from_i64::<21>(b);
            assert!(simulate(&mut m, 10));
            assert_eq!(to_i128(m.p.val()), a as i128 * b as i128);
        }
    }

    #[test]
    fn the_pipelined_product_is_the_product_of_the_operands_at_the_last_edge() {
        let mut m = MulPipeS::<40, 26, 66, 5, 0>::default();
        m.connect_all();
        let pairs = [(-(1i64 << 39), -(1i64 << 25)), ((1 << 39) - 1, -(1 << 25)), (-12345, 678), (7, -1)];
        let mut last = 0i128;
        for (a, b) in pairs {
            m.a.next = from_i64::<40>(a);
            m.b.next = from_i64::<26>(b);
            m.ce.next = true;
            m.clock.next = Clock::from(false);
            assert!(simulate(&mut m, 10));
            // Before the edge: still the product of the pair before.
            assert_eq!(to_i128(m.p.val()), last);
            m.clock.next = Clock::from(true);
            assert!(simulate(&mut m, 10));
            last = a as i128 * b as i128;
            assert_eq!(to_i128(m.p.val()), last);
        }
        // With ce low an edge leaves the product.
        m.a.next = from_i64::<40>(3);
        m.ce.next = false;
        m.clock.next = Clock::from(false);
        assert!(simulate(&mut m, 10));
        m.clock.next = Clock::from(true);
        assert!(simulate(&mut m, 10));
        assert_eq!(to_i128(m.p.val()), last);
    }

    #[test]
    fn the_pipelined_product_cuts_its_operands_into_pieces_of_one_multiplier_block() {
        assert_eq!(product_pieces(5, 40), vec![(5, 17, false), (22, 18, true)]);
        assert_eq!(product_pieces(0, 26), vec![(0, 17, false), (17, 9, true)]);
        assert_eq!(product_pieces(0, 18), vec![(0, 18, true)]);
    }

    #[test]
    fn signed_wide_product_is_exact() {
        let mut m = MulS::<44, 25, 69>::default();
        m.connect_all();
        for (a, b) in [(-(1i64 << 43), (1i64 << 24) - 1), ((1 << 43) - 1, -(1 << 24)), (-12345, 678)] {
            m.a.next = from_i64::<44>(a);
            m.b.next = from_i64::<25>(b);
            assert!(simulate(&mut m, 10));
            assert_eq!(to_i128(m.p.val()), a as i128 * b as i128);
        }
    }
}
