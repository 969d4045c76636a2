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
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
) (
    input wire clock,
    input wire [320:0] cmd_data,
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
    // Counters modulo 256: the checks hold for streams of any length (at most 11 commands are in
    // flight), which is what lets the `prove` task's induction close.
    wire [7:0] in_flight = taken - written;
    always @(*) begin
        if (REACH < 0) assert (in_flight <= 8'd11);
        if (since <= 6'd3) if (REACH < 0) assert (!cmd_ready);
        if (taken != written) if (REACH < 0) assert (busy);
        if (!we) if (REACH < 0) assert (wdata == 424'd0 && waddr == 16'd0);
        if (we && written == tracked) if (REACH < 0) assert (tracked_in && waddr == tracked_index && tracked_age == 6'd41);
        if (tracked_in && tracked_age == 6'd41) if (REACH < 0) assert (we && written == tracked);
    end

    // Strengthening invariants (the `prove` task's k-induction), on registers probed by their names in
    // the generated Verilog (the .sby's `connect` lines, after `flatten`): `tok` has one bit per
    // command in flight, bit o-1 in the command's cycle o, bits at least 4 apart, the lowest at
    // `since`, as many as `taken - written`. `num` shifts beside `tok` with each command's number:
    // the command at bit p is the one after the nearest above it (`written` when none is), and where
    // it is `tracked`, the tracked command, of age p + 1, whose index is in the station of cycle p + 1
    // (cmd1 in cycle 1, c_index[0] in cycles 2-4, c_index[k] in cycles 4k+1 .. 4k+4). (The numbers
    // are kept in `num` rather than counted from `tok`'s bits: z3 could not relate the bit counts
    // before and after a shift, and the induction did not finish in 5 minutes.)
    wire [40:0] p_tok;
    wire [320:0] p_cmd1;
    wire [15:0] p_ci0, p_ci1, p_ci2, p_ci3, p_ci4, p_ci5, p_ci6, p_ci7, p_ci8, p_ci9, p_ci10;
    wire [175:0] ci = {p_ci10, p_ci9, p_ci8, p_ci7, p_ci6, p_ci5, p_ci4, p_ci3, p_ci2, p_ci1, p_ci0};
    reg [327:0] num = 328'd0;    // at 8 p +: 8, the number of the command at tok's bit p
    always @(posedge clock) num <= {num[319:0], taken};
    wire [327:0] above;  // at 8 p +: 8, the bits of tok above p
    wire [327:0] nxt;    // at 8 p +: 8, the number a command at bit p must have
    assign above[327:320] = 8'd0;
    assign nxt[327:320] = written;
    genvar p;
    generate
        for (p = 0; p < 41; p = p + 1) begin : order
            if (p < 40) begin : chain
                assign above[8 * p +: 8] = above[8 * (p + 1) +: 8] + {7'd0, p_tok[p + 1]};
                assign nxt[8 * p +: 8] = p_tok[p + 1] ? num[8 * (p + 1) +: 8] + 8'd1 : nxt[8 * (p + 1) +: 8];
            end
            if (INDUCT) begin : invariants
                always @(*) if (REACH < 0) begin
                    if (p < 40 && p_tok[p]) assert (!p_tok[p + 1]);
                    if (p < 39 && p_tok[p]) assert (!p_tok[p + 2]);
                    if (p < 38 && p_tok[p]) assert (!p_tok[p + 3]);
                    if (p + 1 < since) assert (!p_tok[p]);
                    if (since == p + 1) assert (p_tok[p]);
                    if (p_tok[p]) assert (num[8 * p +: 8] == nxt[8 * p +: 8]);
                    if (p_tok[p] && num[8 * p +: 8] == tracked)
                        assert (tracked_in && tracked_age == p + 1
                                && (p == 0 ? p_cmd1[15:0] : ci[16 * (p / 4) +: 16]) == tracked_index);
                    if (tracked_in && tracked_age == p + 1) assert (p_tok[p] && num[8 * p +: 8] == tracked);
                end
            end
        end
        if (INDUCT) begin : count
            always @(*) if (REACH < 0) begin
                assert (in_flight == above[7:0] + {7'd0, p_tok[0]});
                assert (taken == (p_tok[0] ? num[7:0] + 8'd1 : nxt[7:0]));
                assert (tracked_in == (tracked_age != 6'd0) && since != 6'd0);
            end
        end
    endgenerate

    reg two_close = 1'b0;   // two commands were taken 4 cycles apart
    always @(posedge clock) if (take && since == 6'd4) two_close <= 1'b1;
    `STALL_REACH(cmd_valid, cmd_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (two_close && we && written == 8'd1);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!(two_close && we && written == 8'd1));
    end
endmodule
