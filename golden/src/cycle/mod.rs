//! Cycle-accurate models of the RTL blocks: plain Rust with a `step(inputs) -> outputs` interface on
//! the same ports as the block, written from the specification and the algorithmic model (not
//! translated from the RTL). Each must reproduce the algorithmic model's buffers.
pub mod rc;
pub mod colour_setup;
pub mod color_shader;
pub mod tex_setup;
pub mod texture_sampler;
