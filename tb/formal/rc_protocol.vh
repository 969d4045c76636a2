// The RC's command and result streams, shared by rc.sv and rc3.sv (included inside the harness module,
// after `stream.vh`, with `RC_ORDER` defined as the condition under which the order assertions hold).
// Assumed: commands of kind 0 (frame start, never clearing: a clear takes width x height cycles),
// 1 (triangle, index not 0, the background) or 2 (end of frame), held while stalled. Asserted: results leave in command order, one per triangle or end of
// frame (checked for one solver-chosen position, `tracked`), and held while stalled. Reach points 0-2:
// a stalled result; a result with `visible` set; an end-of-frame result.
    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire take = cmd_valid && cmd_ready;
    wire [1:0] kind = cmd_data[1:0];
    always @(*) if (cmd_valid) begin
        assume (kind != 2'd3);
        if (kind == 2'd0) assume (!cmd_data[2]);
        if (kind == 2'd1) assume (cmd_data[18:3] != 16'd0);
    end
    `STREAM_IN(cmd_valid, cmd_ready, cmd_data)

    wire pop = result_valid && result_ready;
    wire counts = take && kind != 2'd0;
    reg [7:0] pushed = 8'd0;
    reg [7:0] popped = 8'd0;
    (* anyconst *) reg [7:0] tracked;
    reg [16:0] tracked_key = 17'd0;   // {index, eof} of the tracked command
    always @(posedge clock) begin
        if (counts) pushed <= pushed + 8'd1;
        if (pop) popped <= popped + 8'd1;
        if (counts && pushed == tracked) tracked_key <= kind == 2'd2 ? 17'd1 : {cmd_data[18:3], 1'b0};
    end
    always @(*) begin
        if (`RC_ORDER) assert (popped <= pushed);
        // An end-of-frame result carries eof (its index field is the command's, unspecified here).
        if (pop && popped == tracked) if (`RC_ORDER) assert (tracked < pushed && result_data[0] == tracked_key[0]
            && (tracked_key[0] || result_data[16:1] == tracked_key[16:1]));
        if (!result_valid) if (`RC_ORDER) assert (result_data == 20'd0);
    end
    `STREAM_OUT(result_valid, result_ready, result_data, `RC_ORDER)

    `STALL_REACH(result_valid, result_ready, 0)
    always @(posedge clock) if (past_valid) begin
        cover (pop && result_data[19]);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(pop && result_data[19]));
        cover (pop && result_data[0]);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(pop && result_data[0]));
    end
