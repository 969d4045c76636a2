//! A synchronous block RAM with one read and one write port, port-compatible with rust-hdl's `RAM`,
//! that stores its simulation contents in a Vec (fast, with back-door access through `_mem`) and
//! emits `(* no_rw_check *)` so yosys maps it to block RAM without read-during-write bypass logic
//! (GUIDE §2). A read of the address being written returns the old data, in simulation and Verilog.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FastRAM<D: Synth, const N: usize> {
    /// Read port: data appears one clock after the address.
    pub read_address: Signal<In, Bits<N>>,
    pub read_clock: Signal<In, Clock>,
    pub read_data: Signal<Out, D>,
    /// Write port.
    pub write_address: Signal<In, Bits<N>>,
    pub write_clock: Signal<In, Clock>,
    pub write_data: Signal<In, D>,
    pub write_enable: Signal<In, bool>,
    /// Simulation contents (ignored by the derives: leading underscore).
    pub _mem: Vec<D>,
}

impl<D: Synth, const N: usize> Default for FastRAM<D, N> {
    fn default() -> Self {
        Self {
            read_address: Default::default(),
            read_clock: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_clock: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _mem: vec![D::default(); 1 << N],
        }
    }
}

impl<D: Synth, const N: usize> Logic for FastRAM<D, N> {
    fn update(&mut self) {
        if self.read_clock.pos_edge() {
            self.read_data.next = self._mem[self.read_address.val().index()];
        }
        if self.write_clock.pos_edge() && self.write_enable.val() {
            let a = self.write_address.val().index();
            self._mem[a] = self.write_data.val();
        }
    }
    fn connect(&mut self) {
        self.read_data.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "(* no_rw_check *) reg [{d}:0] mem [0:{a}];
always @(posedge read_clock) read_data <= mem[read_address];
always @(posedge write_clock) if (write_enable) mem[write_address] <= write_data;",
            d = D::BITS - 1,
            a = (1usize << N) - 1
        ))
    }
    fn timing(&self) -> Vec<TimingInfo> {
        vec![
            TimingInfo { name: "ram_read".into(), clock: "read_clock".into(), inputs: vec!["read_address".into()], outputs: vec!["read_data".into()] },
            TimingInfo {
                name: "ram_write".into(),
                clock: "write_clock".into(),
                inputs: vec!["write_address".into(), "write_data".into(), "write_enable".into()],
                outputs: vec![],
            },
        ]
    }
}
