//! # golden: the behavioural model of the chipset
//!
//! Plain Rust, no rust-hdl dependency (Cargo enforces it): this crate defines what every RTL block in
//! `hdl/` must do, bit for bit. Two levels:
//! * untimed, algorithmic: [`raster`] (the Rasterizer Controller's buffers and flags), [`shade`] (colour
//!   setup and the Color Shader), [`render`] (a frame through seed 001's dual pipeline);
//! * cycle-accurate models of the blocks (`step(inputs) -> outputs`), added with the RTL they specify.
//!
//! [`format`] is the one source of truth for number formats; [`host`] is the CPU side (geometry,
//! lighting, operation counts); [`scene`] holds the built-in scenes and the OBJ loader.

pub mod analysis;
pub mod cycle;
pub mod format;
pub mod host;
pub mod proof;
pub mod raster;
pub mod render;
pub mod scene;
pub mod shade;
pub mod texbank;
pub mod texcoord;
pub mod texture;
