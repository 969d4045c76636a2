//! Building blocks shared by every unit: the valid/ready stream interface, wide multipliers, a
//! block-RAM model that yosys maps without read-during-write glue, and width-safe casts.
//!
//! The casts follow `shared/rusthdl/GUIDE.md` §1: rust-hdl 0.46's `signed_bit_cast` overflows the stack
//! on the most negative value, so [`signed_bit_cast_safe`] replaces it; hdl_gen matches cast functions
//! by name prefix, so it still emits `$signed(x)` in Verilog.

pub mod add;
pub mod div_step;
pub mod div_step2;
pub mod fast_ram;
pub mod leading_one;
pub mod merge_modules;
pub mod mul;
pub mod normalize;
pub mod stream;

pub use add::AddU;
pub use div_step::{DivStep, DivStep45, DivStepN};
pub use div_step2::DivStep2x45;
pub use fast_ram::FastRAM;
pub use leading_one::{LeadingOne, LeadingOne36, LeadingOne44};
pub use merge_modules::merge_identical_modules;
pub use mul::{pipe_product_verilog, split_product_verilog, square_logic_verilog, LerpDeltaLogic, MulLogicU, MulPipeS, MulS, MulSplitS, MulU, SquareLogicS, SquareLogicU};
pub use normalize::{LeftAlign, Normalize18};
pub use stream::{StreamIn, StreamOut};

use rust_hdl::prelude::*;

/// The Verilog of a block with its top module named `name` (submodules are `name$child`). Runs
/// rust-hdl's structural checks first, so a failed check is an `Err` rather than a panic.
pub fn verilog_named<U: Block>(uut: &U, name: &str) -> Result<String, String> {
    check_all(uut).map_err(|e| format!("{name}: rust-hdl check failed: {e:?}"))?;
    let mut defines = ModuleDefines::default();
    uut.accept(name, &mut defines);
    Ok(sized_localparams(&defines.defines()))
}

/// Give every signed `localparam` an explicit range. rust-hdl writes a signed constant as
/// `localparam signed k7_17 = 17'b111;`: IEEE 1364 makes it a signed 17-bit parameter (Icarus and
/// Verilator agree), but Yosys 0.23 keeps it unsigned, so `$signed(x) + k7_17` zero-extends a
/// negative `x` in the synthesized netlist and not in simulation. Found by the mutation cover, whose
/// replay of Yosys's unmutated netlist of `rc` failed: bounding boxes of triangles left of the screen.
/// With `localparam signed [16:0] k7_17 = 17'b111;` every tool reads the same value.
pub fn sized_localparams(v: &str) -> String {
    let mut out = String::with_capacity(v.len() + v.len() / 50);
    for line in v.lines() {
        let t = line.trim_start();
        let sized = t.strip_prefix("localparam signed ").and_then(|rest| {
            let (name, value) = rest.split_once(" = ")?;
            let width: usize = value.trim_start_matches('-').split_once('\'')?.0.parse().ok()?;
            (!name.contains('[')).then(|| format!("{}localparam signed [{}:0] {name} = {value}", &line[..line.len() - t.len()], width - 1))
        });
        out.push_str(sized.as_deref().unwrap_or(line));
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod sized_localparams_tests {
    #[test]
    fn signed_localparams_get_the_range_of_their_literal_and_the_rest_is_untouched() {
        let v = "module m;\n    localparam signed k7_17 = 17'b111;\n    localparam  k0_2 = 2'b0;\n    localparam signed [3:0] k = 4'h1;\nendmodule\n";
        let want = "module m;\n    localparam signed [16:0] k7_17 = 17'b111;\n    localparam  k0_2 = 2'b0;\n    localparam signed [3:0] k = 4'h1;\nendmodule\n";
        assert_eq!(super::sized_localparams(v), want);
    }
}

/// rust-hdl names the top module `top` and its children `top$...`: give them the top's own name
/// (and its signed constants their ranges, [`sized_localparams`]).
pub fn rename_top(v: &str, name: &str) -> String {
    let v = sized_localparams(v);
    let mut out = String::with_capacity(v.len());
    for line in v.lines() {
        let indent = &line[..line.len() - line.trim_start().len()];
        let t = line.trim_start();
        let renamed = ["module top", "endmodule // top", "top$"].iter().find(|p| t.starts_with(*p)).map(|p| {
            let at = p.find("top").unwrap();
            format!("{indent}{}{name}{}", &t[..at], &t[at + 3..])
        });
        out.push_str(renamed.as_deref().unwrap_or(line));
        out.push('\n');
    }
    out
}

/// `signed_bit_cast` without the stack overflow: sign-extends (M > N) or truncates (M < N); N, M <= 64.
pub fn signed_bit_cast_safe<const M: usize, const N: usize>(x: Signed<N>) -> Signed<M> {
    from_i64::<M>(to_i64(x))
}

/// The value of a `Signed<N>` (N <= 64) as an i64.
pub fn to_i64<const N: usize>(x: Signed<N>) -> i64 {
    let raw = unsigned_cast(x).to_u64();
    if N >= 64 {
        raw as i64
    } else {
        ((raw << (64 - N)) as i64) >> (64 - N)
    }
}

/// Wrap an i64 into a `Signed<N>` (two's-complement truncation; never panics).
pub fn from_i64<const N: usize>(v: i64) -> Signed<N> {
    from_i128::<N>(v as i128)
}

/// Wrap an i128 into a `Signed<N>` of any width up to 128 (two's-complement truncation).
pub fn from_i128<const N: usize>(v: i128) -> Signed<N> {
    let masked = if N >= 128 { v as u128 } else { (v as u128) & ((1u128 << N) - 1) };
    signed_cast(bits_from_u128::<N>(masked))
}

/// The value of a `Signed<N>` (N <= 128) as an i128.
pub fn to_i128<const N: usize>(x: Signed<N>) -> i128 {
    let raw = unsigned_cast(x).to_u128();
    if N >= 128 {
        raw as i128
    } else {
        ((raw << (128 - N)) as i128) >> (128 - N)
    }
}

/// A `Bits<N>` from a u128 (truncated to N bits); goes through BigUint above 64 bits.
pub fn bits_from_u128<const N: usize>(v: u128) -> Bits<N> {
    let v = if N >= 128 { v } else { v & ((1u128 << N) - 1) };
    if N <= 64 {
        Bits::<N>::from(v as u64)
    } else {
        Bits::<N>::from(num_bigint::BigUint::from(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn casts_round_trip_including_the_most_negative_value() {
        assert_eq!(to_i64(signed_bit_cast_safe::<32, 16>(from_i64::<16>(-32768))), -32768);
        assert_eq!(to_i64(signed_bit_cast_safe::<8, 16>(from_i64::<16>(0x1ff))), -1);
        assert_eq!(to_i128(from_i128::<80>(-(1i128 << 70) + 5)), -(1i128 << 70) + 5);
        assert_eq!(to_i128(from_i128::<80>(1i128 << 78)), 1i128 << 78);
    }
}
