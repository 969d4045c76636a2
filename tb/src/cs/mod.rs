//! Benches of colour setup and the Color Shader (`hdl::cs`) against their cycle models
//! (`golden::cycle::{colour_setup, color_shader}`) and, through them, the algorithmic model.
//!
//! * [`colour_setup_bench`], [`color_shader_bench`]: every cycle, every port, RustHDL vs cycle model,
//!   with random gaps on the command stream and random back-pressure on the video stream; VCDs in
//!   `target/vcd/cs/<test>.vcd`;
//! * [`frames`]: real frames of the built-in scenes from the golden pipeline (setup commands recorded
//!   by a recording `Chipset`, the golden TdbS, the hardware I-buffer);
//! * [`replay`]: the generated Verilog replays recorded vectors under Icarus Verilog; lint and synthesis;
//! * [`pack`]: golden types <-> RTL port words.
//! * [`stimulus`]: random commands, records and constants; the recordings the Verilog replays.

pub mod color_shader_bench;
pub mod colour_setup_bench;
pub mod frames;
pub mod pack;
pub mod pipeline;
pub mod replay;

pub mod stimulus;
pub mod tex_coord_bench;
pub mod tex_lod_bench;
pub mod tex_setup_bench;
pub mod textured_setup_bench;
pub mod texel_address_bench;
pub mod texel_filter_bench;
pub mod texture_sampler_bench;
#[cfg(test)]
mod tests;
