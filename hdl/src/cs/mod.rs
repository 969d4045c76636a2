//! `cs`: colour setup and the Color Shader (seed 001 §2.3.2 eqs. 6-7, §3.1; seed 000 §III, TdbS).
//!
//! ```text
//!             SetupCommand                          TdbsRecord
//!  host ----(valid/ready)--> [ colour_setup ] --(tdbs write port)--> TdbS memory (outside)
//!                                                                         |
//!  I-buffer (outside) --(read port, latency 1)--+                         |
//!                                               v                         v
//!                        [ color_shader ] <--(tdbs read port, latency 1)--+
//!                          |  |  clear-behind write ports --> I-buffer, Z-buffer
//!                          v
//!          AXI4-Stream video: tdata RGB888 {R,B,G}, tvalid/tready, tuser (SOF), tlast (EOL)
//! ```
//!
//! * [`colour_setup::ColourSetup`] (top `colour_setup`): a pipeline taking a command every 4 cycles;
//!   planes for R, G, B (or the normal's x, y, z) with one reciprocal, one TdbS record written at the
//!   triangle's index 41 cycles later.
//! * [`color_shader::ColorShader`] (top `cs`): scan-out, one pixel per clock, lossless back-pressure.
//! * [`video_fifo::VideoFifo`]: the CS's 32-deep output FIFO (the skid buffer).
//!
//! Colour setup has its own reciprocal: the 25 restoring steps of `golden::format::reciprocal` as a
//! chain of [`crate::common::DivStep`]s, one step per cycle, so that a new triangle can start every 4
//! cycles. The RC's [`crate::rc::fast_reciprocal::FastReciprocal`] computes the same quotient for the
//! RC's own triangles (one request per clock, 13 cycles each), so it is not shared.
//!
//! Both memories (TdbS: 2^16 records of 424 bits, and the screen-size buffers) are outside the blocks,
//! behind ports, because they do not fit FPGA block RAM; the testbenches model them.

pub mod color_shader;
pub mod color_shader_tex;
pub mod gloss_square;
pub mod light_unit;
pub mod modulate;
pub mod normalizer;
pub mod plane_mul;
pub mod plane_round;
pub mod scan_pipe;
pub mod colour_setup;
pub mod tex_coord;
pub mod tex_lod;
pub mod tex_setup;
pub mod textured_setup;
pub mod texel_address;
pub mod texel_filter;
pub mod texture_sampler;
pub mod video_fifo;

use rust_hdl::prelude::*;

/// One TdbS record (seed 000 §III-B, "triangle database for shading"): three planes
/// `v(X, Y) = (c + a*X + b*Y) / 2^16` at pixel centres, two's complement, 16 fraction bits
/// (`golden::format::Plane`), and the material (Phong). Channel 0/1/2 = R/G/B for flat and Gouraud,
/// the normal's x/y/z for Phong.
///
/// Packed layout (424 bits, field 0 in the least significant bits):
///
/// | bits | field |
/// |---|---|
/// | 39:0 | `r_a` | 
/// | 79:40 | `r_b` |
/// | 135:80 | `r_c` |
/// | 175:136 | `g_a` |
/// | 215:176 | `g_b` |
/// | 271:216 | `g_c` |
/// | 311:272 | `b_a` |
/// | 351:312 | `b_b` |
/// | 407:352 | `b_c` |
/// | 423:408 | `material` |
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct TdbsRecord {
    pub r_a: Bits<40>,
    pub r_b: Bits<40>,
    pub r_c: Bits<56>,
    pub g_a: Bits<40>,
    pub g_b: Bits<40>,
    pub g_c: Bits<56>,
    pub b_a: Bits<40>,
    pub b_b: Bits<40>,
    pub b_c: Bits<56>,
    pub material: Bits<16>,
}

/// Address bits of the Color Shader's material memory: it holds `2^CS_MATERIAL_BITS` materials (16) and
/// reads TdbS's `material` field through its low bits (`golden::format::CS_MATERIALS`).
pub const CS_MATERIAL_BITS: usize = 4;
/// Light units of the Color Shader's Phong datapath (`golden::format::CS_LIGHTS`): each lights every
/// pixel with one directional light; a light the scene does not define has zero coefficients.
pub const CS_LIGHTS: usize = 2;

/// One light's constant vectors for the Phong datapath (written through `light_write_*` while the CS
/// is idle): the direction L and the halfway vector H, unit vectors in Q1.14 (two's complement).
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct LightVectors {
    pub l_x: Bits<16>,
    pub l_y: Bits<16>,
    pub l_z: Bits<16>,
    pub h_x: Bits<16>,
    pub h_y: Bits<16>,
    pub h_z: Bits<16>,
}

/// One word of the material memory (written through `material_write_*`), six unsigned 16-bit fields of
/// colour x 255 with 8 fraction bits. Slot 0 of a material: `w0..w2` = ambient R, G, B (Ka Ia),
/// `w3` = log2 of the gloss (0..=4). Slot 1 + l: light l's `w0..w2` = diffuse (Kd Il) and `w3..w5` =
/// specular (Ks Il) R, G, B.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct MaterialWord {
    pub w0: Bits<16>,
    pub w1: Bits<16>,
    pub w2: Bits<16>,
    pub w3: Bits<16>,
    pub w4: Bits<16>,
    pub w5: Bits<16>,
}

/// Width of a packed [`TdbsRecord`].
pub const TDBS_RECORD_BITS: usize = 424;

/// One colour-setup command (`golden::render::SetupCommand` at the port widths). Coordinates are
/// S11.8 window subpixels (20 bits), values 16-bit two's complement (RGB888 or Q1.14), all stored as raw bits
/// (a `LogicStruct` cannot hold `Signed`).
///
/// Packed layout (321 bits, LSB first): `index` 15:0, `x0` 35:16, `y0` 55:36, `x1` 75:56, `y1` 95:76,
/// `x2` 115:96, `y2` 135:116, `v0r v0g v0b v1r v1g v1b v2r v2g v2b` 279:136 (16 bits each, in that
/// order), `material` 295:280, `flat` 296, `flat_r` 304:297, `flat_g` 312:305, `flat_b` 320:313.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct SetupCommand {
    pub index: Bits<16>,
    pub x0: Bits<20>,
    pub y0: Bits<20>,
    pub x1: Bits<20>,
    pub y1: Bits<20>,
    pub x2: Bits<20>,
    pub y2: Bits<20>,
    pub v0r: Bits<16>,
    pub v0g: Bits<16>,
    pub v0b: Bits<16>,
    pub v1r: Bits<16>,
    pub v1g: Bits<16>,
    pub v1b: Bits<16>,
    pub v2r: Bits<16>,
    pub v2g: Bits<16>,
    pub v2b: Bits<16>,
    pub material: Bits<16>,
    pub flat: Bit,
    pub flat_r: Bits<8>,
    pub flat_g: Bits<8>,
    pub flat_b: Bits<8>,
}

/// Width of a packed [`SetupCommand`].
pub const SETUP_COMMAND_BITS: usize = 321;

/// One TdbT record (the texture half of the triangle database, issue 17): the planes s/w, t/w and
/// 1/w of `golden::texcoord::TexPlanes`, each `a`, `b` (40 bits) and `c` (56 bits) as in
/// [`TdbsRecord`]. Packed layout (408 bits, LSB first): `s_a s_b s_c` 135:0, `t_a t_b t_c` 271:136,
/// `q_a q_b q_c` 407:272.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct TdbtRecord {
    pub s_a: Bits<40>,
    pub s_b: Bits<40>,
    pub s_c: Bits<56>,
    pub t_a: Bits<40>,
    pub t_b: Bits<40>,
    pub t_c: Bits<56>,
    pub q_a: Bits<40>,
    pub q_b: Bits<40>,
    pub q_c: Bits<56>,
}

/// Width of a packed [`TdbtRecord`].
pub const TDBT_RECORD_BITS: usize = 408;

/// The texture values of a triangle's three vertices: s/w, t/w and 1/w, 33-bit two's complement.
/// Packed layout (297 bits, LSB first): `v0s v0t v0q v1s v1t v1q v2s v2t v2q`.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct TexValues {
    pub v0s: Bits<33>,
    pub v0t: Bits<33>,
    pub v0q: Bits<33>,
    pub v1s: Bits<33>,
    pub v1t: Bits<33>,
    pub v1q: Bits<33>,
    pub v2s: Bits<33>,
    pub v2t: Bits<33>,
    pub v2q: Bits<33>,
}

/// Width of a packed [`TexValues`].
pub const TEX_VALUES_BITS: usize = 297;

/// One texture-setup command (`golden::cycle::tex_setup::TexSetupCmd`): the triangle's index and
/// window coordinates as in [`SetupCommand`], and its [`TexValues`]. Packed layout (433 bits, LSB
/// first): `index` 15:0, `x0 y0 x1 y1 x2 y2` 135:16, `values` 432:136.
#[derive(Copy, Clone, Debug, PartialEq, Default, LogicStruct)]
pub struct TexSetupCommand {
    pub index: Bits<16>,
    pub x0: Bits<20>,
    pub y0: Bits<20>,
    pub x1: Bits<20>,
    pub y1: Bits<20>,
    pub x2: Bits<20>,
    pub y2: Bits<20>,
    pub values: TexValues,
}

/// Width of a packed [`TexSetupCommand`].
pub const TEX_SETUP_COMMAND_BITS: usize = 433;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_widths_are_the_documented_ones() {
        assert_eq!(TdbsRecord::BITS, TDBS_RECORD_BITS);
        assert_eq!(SetupCommand::BITS, SETUP_COMMAND_BITS);
        assert_eq!(TdbtRecord::BITS, TDBT_RECORD_BITS);
        assert_eq!(TexSetupCommand::BITS, TEX_SETUP_COMMAND_BITS);
        assert_eq!(TexValues::BITS, TEX_VALUES_BITS);
        let r = TdbsRecord { material: 0xabcd.into(), ..Default::default() };
        let b: Bits<TDBS_RECORD_BITS> = r.into();
        assert_eq!(b.get_bits::<16>(408).to_u64(), 0xabcd);
        let c = SetupCommand { flat: true, flat_b: 0x81.into(), ..Default::default() };
        let b: Bits<SETUP_COMMAND_BITS> = c.into();
        assert!(b.get_bit(296));
        assert_eq!(b.get_bits::<8>(313).to_u64(), 0x81);
    }

    #[test]
    fn both_tops_pass_the_rust_hdl_checks_and_generate_named_verilog() {
        let v = colour_setup_verilog().unwrap();
        assert!(v.contains("module colour_setup("), "colour_setup top module name");
        let v = color_shader_verilog().unwrap();
        assert!(v.contains("module cs("), "cs top module name");
        assert!(v.contains("video_tready") && v.contains("tdbs_read_data"));
    }
}

use crate::common::verilog_named;

/// Verilog of the colour-setup top (module `colour_setup`).
pub fn colour_setup_verilog() -> Result<String, String> {
    let mut uut = colour_setup::ColourSetup::default();
    uut.connect_all();
    verilog_named(&uut, "colour_setup")
}

/// Verilog of the Color Shader top (module `cs`).
pub fn color_shader_verilog() -> Result<String, String> {
    let mut uut = color_shader::ColorShader::default();
    uut.connect_all();
    verilog_named(&uut, "cs")
}
