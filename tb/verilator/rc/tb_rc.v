// Self-checking replay of recorded RC vectors (tb/src/rc/replay.rs writes them; one line per cycle):
//   cmd_valid cmd_data res_ready | cmd_ready res_valid res_data z_re z_rd_addr z_we z_wr_addr z_wr_data
//   i_we i_wr_addr i_wr_data            (14 hex fields, the last 11 are the cycle model's outputs)
// Drives the generated `rc` with the recorded inputs, answers its memory ports with models of the same
// semantics as tb/src/rc/memory.rs (read data one cycle later, old contents on a same-edge write;
// Z starts at 2^24-1, I at 0; the I-buffer is read with z_re/z_rd_addr into i_rd_data), and compares every output with `!==` in every cycle. The first mismatch
// prints "TESTBENCH FAILED" with the cycle and port; the end prints "TESTBENCH PASSED <cycles>".
// Runs under Icarus (iverilog -g2012) and Verilator (--binary --timing).
`timescale 1ns/1ps
module tb_rc;
  parameter WORDS = 1 << 20;
  reg clock = 1'b0;
  reg cmd_valid = 1'b0;
  reg [213:0] cmd_data = 214'h0;
  reg res_ready = 1'b0;
  reg [23:0] z_rd_data = 24'h0;
  reg [15:0] i_rd_data = 16'h0;
  wire cmd_ready, res_valid, z_re, z_we, i_we;
  wire [19:0] res_data, z_rd_addr, z_wr_addr, i_wr_addr;
  wire [23:0] z_wr_data;
  wire [15:0] i_wr_data;
  reg [23:0] zmem [0:WORDS-1];
  reg [15:0] imem [0:WORDS-1];

  rc dut(.clock(clock), .cmd$data(cmd_data), .cmd$valid(cmd_valid), .cmd$ready(cmd_ready),
         .result$data(res_data), .result$valid(res_valid), .result$ready(res_ready),
         .z_re(z_re), .z_rd_addr(z_rd_addr), .z_we(z_we), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data),
         .z_rd_data(z_rd_data), .i_we(i_we), .i_wr_addr(i_wr_addr), .i_wr_data(i_wr_data),
         .i_rd_data(i_rd_data));

`ifdef DUMP_VCD
  // With -DDUMP_VCD and +vcd=FILE: the ports and top-level nets of the rc instance, for `idxrender vcd-diff`.
  reg [8*1024-1:0] vcd_path;
  initial if ($value$plusargs("vcd=%s", vcd_path)) begin
    $dumpfile(vcd_path);
    $dumpvars(1, dut);
  end
`endif

  always @(posedge clock) begin
    if (z_re) z_rd_data <= zmem[z_rd_addr];
    if (z_re) i_rd_data <= imem[z_rd_addr];
    if (z_we) zmem[z_wr_addr] <= z_wr_data;
    if (i_we) imem[i_wr_addr] <= i_wr_data;
  end

  integer fd, n, cyc, i;
  reg [8*1024-1:0] path;
  reg [3:0] v, r, e_cr, e_rv, e_zre, e_zwe, e_iwe;
  reg [223:0] d;
  reg [19:0] e_res, e_zra, e_zwa, e_iwa;
  reg [23:0] e_zwd;
  reg [15:0] e_iwd;

  task check(input [8*16-1:0] name, input [31:0] actual, input [31:0] expected);
    if (actual !== expected) begin
      $display("TESTBENCH FAILED: cycle %0d port %0s expected %h actual %h", cyc, name, expected, actual);
      $finish;
    end
  endtask

  initial begin
    if (!$value$plusargs("vectors=%s", path)) begin
      $display("TESTBENCH FAILED: no +vectors=FILE");
      $finish;
    end
    fd = $fopen(path, "r");
    if (fd == 0) begin
      $display("TESTBENCH FAILED: cannot open %0s", path);
      $finish;
    end
    for (i = 0; i < WORDS; i = i + 1) begin
      zmem[i] = 24'hffffff;
      imem[i] = 16'h0;
    end
    cyc = 0;
    n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h\n",
                v, d, r, e_cr, e_rv, e_res, e_zre, e_zra, e_zwe, e_zwa, e_zwd, e_iwe, e_iwa, e_iwd);
    while (n == 14) begin
      cmd_valid = v[0];
      cmd_data = d[213:0];
      res_ready = r[0];
      #4;
      check("cmd_ready", {31'h0, cmd_ready}, {28'h0, e_cr});
      check("res_valid", {31'h0, res_valid}, {28'h0, e_rv});
      check("res_data", {12'h0, res_data}, {12'h0, e_res});
      check("z_re", {31'h0, z_re}, {28'h0, e_zre});
      check("z_rd_addr", {12'h0, z_rd_addr}, {12'h0, e_zra});
      check("z_we", {31'h0, z_we}, {28'h0, e_zwe});
      check("z_wr_addr", {12'h0, z_wr_addr}, {12'h0, e_zwa});
      check("z_wr_data", {8'h0, z_wr_data}, {8'h0, e_zwd});
      check("i_we", {31'h0, i_we}, {28'h0, e_iwe});
      check("i_wr_addr", {12'h0, i_wr_addr}, {12'h0, e_iwa});
      check("i_wr_data", {16'h0, i_wr_data}, {16'h0, e_iwd});
      clock = 1'b1;
      #5;
      clock = 1'b0;
      #1;
      cyc = cyc + 1;
      n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h\n",
                  v, d, r, e_cr, e_rv, e_res, e_zre, e_zra, e_zwe, e_zwa, e_zwd, e_iwe, e_iwa, e_iwd);
    end
    $display("TESTBENCH PASSED %0d", cyc);
    $finish;
  end
endmodule
