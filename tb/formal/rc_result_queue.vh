// The result queue behind the RC's visibility tests, shared by the module harnesses rc_z_test.sv
// (`rc$z_test`) and rc3_tdbv_test.sv (`rc3$vis`). Expects `clock`, `REACH`, `result_valid`,
// `result_ready`, `result_data` and `stream.vh`'s macros in scope.
//
// RC_RESULT_QUEUE(tok, pass, depth): `tok` is the token in the stage that decides (its RcToken),
// `pass` its fragment's Z-test outcome. A result is pushed by a result token or a fragment marked
// last. Asserted (when REACH < 0): valid held until ready and data stable while stalled, never more
// than `depth` results held, and the n-th result (n solver-chosen, `tracked`) is the n-th pushed
// token's index and flags, with `visible` the OR of the passes of that triangle's fragments.
// Declares `pushed` and `popped` (8-bit counters, modulo 256) for the harness's reach points.
// RcResult: eof 0, index 16:1, culled 17, zero_area 18, visible 19.
`define RC_RESULT_QUEUE(tok, pass, depth) \
    wire rq_frag = (tok[1:0]) == 2'd2; \
    wire rq_pushes = (tok[1:0]) == 2'd3 || (rq_frag && (tok[3])); \
    reg rq_vis = 1'b0; \
    always @(posedge clock) if (rq_frag) rq_vis <= (tok[3]) ? 1'b0 : (rq_vis | (pass)); \
    wire [19:0] rq_expected = rq_frag \
        ? {rq_vis | (pass), 2'b00, tok[83:68], 1'b0} \
        : {1'b0, tok[86], tok[85], tok[83:68], tok[84]}; \
    reg [7:0] pushed = 8'd0; \
    reg [7:0] popped = 8'd0; \
    (* anyconst *) reg [7:0] tracked; \
    reg [19:0] tracked_result = 20'd0; \
    wire pop = result_valid && result_ready; \
    always @(posedge clock) begin \
        if (rq_pushes) pushed <= pushed + 8'd1; \
        if (pop) popped <= popped + 8'd1; \
        if (rq_pushes && pushed == tracked) tracked_result <= rq_expected; \
    end \
    always @(*) begin \
        if (REACH < 0) assert (pushed - popped <= (depth)); \
        if (REACH < 0) assert (result_valid == (pushed != popped)); \
        if (pop && popped == tracked) if (REACH < 0) assert (result_data == tracked_result); \
    end \
    `STREAM_OUT(result_valid, result_ready, result_data, REACH < 0)
