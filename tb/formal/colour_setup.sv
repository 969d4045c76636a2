// Formal harness of the `colour_setup` top (`idxrender verilog --block colour_setup`; RustHDL source
// hdl/src/cs/colour_setup.rs). Run by `bash scripts/formal.sh colour_setup`; see
// docs/verification.md. The planes' arithmetic is checked by the replay tests, not here: this
// harness checks the command stream and the TdbS write port.
//
// Assumed: cmd valid held until ready and data stable while stalled. Asserted: one TdbS write per
// command, in order, at the command's index (the n-th write, n solver-chosen, is at the n-th
// command's index), exactly SETUP_LATENCY = 41 cycles after the command was taken; `cmd.ready` low
// for the 3 cycles after a command is taken (SETUP_INTERVAL = 4); `busy` high while a command is in
// flight; the write data is 0 while the enable is low. Reach points: two commands taken 4 cycles
// apart and both written; a command held waiting for ready.
//
// cmd layout: index 15:0 (then the vertices and values, hdl/src/cs/mod.rs).
`include "stream.vh"

module colour_setup_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire [296:0] cmd_data,
    input wire cmd_valid
);
    wire cmd_ready;
    wire we;
    wire [15:0] waddr;
    wire [423:0] wdata;
    wire busy;
    colour_setup dut (
        .clock(clock), .cmd$data(cmd_data), .cmd$valid(cmd_valid), .cmd$ready(cmd_ready),
        .tdbs_write_enable(we), .tdbs_write_address(waddr), .tdbs_write_data(wdata), .busy(busy)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire take = cmd_valid && cmd_ready;
    `STREAM_IN(cmd_valid, cmd_ready, cmd_data)

    // Cycles since the last command was taken (saturating), and the commands in flight.
    reg [5:0] since = 6'd63;
    reg [7:0] taken = 8'd0;
    reg [7:0] written = 8'd0;
    (* anyconst *) reg [7:0] tracked;
    reg [15:0] tracked_index = 16'd0;
    reg [5:0] tracked_age = 6'd0;     // cycles since the tracked command was taken (saturating)
    reg tracked_in = 1'b0;
    always @(posedge clock) begin
        since <= take ? 6'd1 : (since == 6'd63 ? 6'd63 : since + 6'd1);
        if (take) taken <= taken + 8'd1;
        if (we) written <= written + 8'd1;
        if (take && taken == tracked) begin
            tracked_index <= cmd_data[15:0];
            tracked_in <= 1'b1;
            tracked_age <= 6'd1;
        end else if (tracked_in && tracked_age != 6'd63) begin
            tracked_age <= tracked_age + 6'd1;
        end
    end
    always @(*) begin
        if (REACH < 0) assert (written <= taken);
        if (since <= 6'd3) if (REACH < 0) assert (!cmd_ready);
        if (taken != written) if (REACH < 0) assert (busy);
        if (!we) if (REACH < 0) assert (wdata == 424'd0 && waddr == 16'd0);
        if (we && written == tracked) if (REACH < 0) assert (tracked_in && waddr == tracked_index && tracked_age == 6'd41);
        if (tracked_in && tracked_age == 6'd41) if (REACH < 0) assert (we && written == tracked);
    end

    reg two_close = 1'b0;   // two commands were taken 4 cycles apart
    always @(posedge clock) if (take && since == 6'd4) two_close <= 1'b1;
    `STALL_REACH(cmd_valid, cmd_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (two_close && we && written == 8'd1);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!(two_close && we && written == 8'd1));
    end
endmodule
