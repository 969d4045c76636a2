//! A look-up table between PROOF's stages (seed 002 §3.1: "look-up tables" hold what the later stages
//! need per object): a synchronous block RAM of 2^A words (A a constructor parameter, 1..=16) with a
//! read enable, so that a stalled pipeline keeps the word of the entry it holds. Leaf block: Verilog
//! written by hand (one `always` with `(* no_rw_check *)`, as `common::FastRAM`), simulation in Rust;
//! the generated Verilog is checked against the simulation by the stage benches' Verilog replay.
//! A read of the word being written returns the old word. Addresses use their low A bits.
//!
//! ```text
//!                  +-----------------+
//!  read_address ──▶|                 |
//!  read_enable  ──▶|  table_ram (2^A)|──▶ read_data (registered)
//!  write_*      ──▶|                 |
//!                  +-----------------+
//! ```

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct TableRam<D: Synth> {
    pub clock: Signal<In, Clock>,
    // From the stage that reads
    /// Word to read at this edge (low A bits).
    pub read_address: Signal<In, Bits<16>>,
    /// Update `read_data` at this edge (else it holds).
    pub read_enable: Signal<In, Bit>,
    // To the stage that reads
    /// The word read at the last enabled edge.
    pub read_data: Signal<Out, D>,
    // From the host
    /// Write `write_data` to `write_address` at this edge.
    pub write_enable: Signal<In, Bit>,
    pub write_address: Signal<In, Bits<16>>,
    pub write_data: Signal<In, D>,
    /// Simulation contents (back-door readable).
    pub _mem: Vec<D>,
    _mask: usize,
    _addr_bits: usize,
}

impl<D: Synth> TableRam<D> {
    pub fn new(addr_bits: usize) -> Result<TableRam<D>, String> {
        if !(1..=16).contains(&addr_bits) {
            return Err(format!("a table of 2^{addr_bits} words is not supported: 1..=16 address bits"));
        }
        Ok(TableRam {
            clock: Default::default(),
            read_address: Default::default(),
            read_enable: Default::default(),
            read_data: Default::default(),
            write_enable: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            _mem: vec![D::default(); 1 << addr_bits],
            _mask: (1 << addr_bits) - 1,
            _addr_bits: addr_bits,
        })
    }
}

impl<D: Synth> Logic for TableRam<D> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            if self.read_enable.val() {
                self.read_data.next = self._mem[self.read_address.val().index() & self._mask];
            }
            if self.write_enable.val() {
                let a = self.write_address.val().index() & self._mask;
                self._mem[a] = self.write_data.val();
            }
        }
    }
    fn connect(&mut self) {
        self.read_data.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "(* no_rw_check *) reg [{d}:0] mem [0:{n}];
always @(posedge clock) begin
  if (read_enable) read_data <= mem[read_address[{a}:0]];
  if (write_enable) mem[write_address[{a}:0]] <= write_data;
end",
            d = D::BITS - 1,
            n = (1usize << self._addr_bits) - 1,
            a = self._addr_bits - 1
        ))
    }
    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "table_ram".into(),
            clock: "clock".into(),
            inputs: vec!["read_address".into(), "read_enable".into(), "write_enable".into(), "write_address".into(), "write_data".into()],
            outputs: vec!["read_data".into()],
        }]
    }
}
