//! The RC's testbench: memory models for its Z/I ports ([`memory`]), command streams and the
//! algorithmic reference ([`stimulus`]), the command port words ([`pack`]), the every-cycle RTL-vs-model
//! bench with VCDs ([`bench`]) and the replay of recorded vectors on the generated Verilog ([`replay`]).

pub mod bench;
pub mod memory;
pub mod pack;
pub mod replay;
pub mod stimulus;
