//! # PROOF: the object-processor pipeline, shading stage and subpixel filter (seed 002)
//!
//! A second rendering architecture beside the index-rendering chipset, sharing its scenes, host
//! geometry and number-format conventions. Schneider & Claussen (1988) partition the pixel work in
//! object space: a pipeline of object processors (OPs), each holding one object, builds per pixel a
//! depth-sorted list of the objects that may contribute (§3-4); a pipeline of light-source processors
//! colours each entry (§5); a filter builds an 8x8 subpixel mask and mixes the colours (§6).
//!
//! * [`format`]: formats, the object parameters, list entries and time slots, the coverage test;
//! * [`setup`]: the host's object setup and the look-up tables between stages;
//! * [`shade`], [`filter`]: the shading and filter stages' arithmetic;
//! * [`render`]: the algorithmic renderer (what a frame is);
//! * [`cycle_shade`], [`cycle_filter`], [`cycle_filter2x2`]: cycle-accurate models of the shading
//!   stage and of the filter stage with the 1x1 and the 2x2 area (register by register);
//! * [`study`]: the per-scene figures (OPs, cycles, FIFO depths) with the CLI's default options;
//! * [`cycle_op`], [`cycle_opp`]: cycle-accurate models of the OP and of the OPP with its
//!   object loader (when each port changes), which the RTL in `hdl/src/proof/` must match.

pub mod cycle_filter;
pub mod cycle_filter2x2;
pub mod cycle_op;
pub mod cycle_opp;
pub mod cycle_shade;
pub mod filter;
pub mod format;
pub mod good_nature;
pub mod render;
pub mod setup;
pub mod shade;
pub mod study;
