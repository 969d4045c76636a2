// The one handshake convention of every top (valid/ready: a beat moves in a cycle where both are high),
// as macros shared by the formal harnesses. Each expects `clock`, `past_valid` (0 in the first cycle)
// and the harness's `REACH` and `REACH_SET` parameters in scope.
//
// STREAM_IN(v, r, d):        assume an input stream keeps valid high and its data unchanged while stalled.
// STREAM_OUT(v, r, d, on):   assert the same of an output stream, where `on` holds (for example
//                            `REACH < 0`, so that a reach task checks only its reach point).
// STALL_REACH(v, r, n):      cover a stall on the stream; in task reach`n` (or with bit n of
//                            REACH_SET) assert, as `reach_n`, that it never happens, so that the task
//                            must fail and its trace shows the stall.

`define STREAM_IN(v, r, d) \
    always @(posedge clock) if (past_valid && $past((v) && !(r))) begin \
        assume (v); \
        assume ((d) == $past(d)); \
    end

`define STREAM_OUT(v, r, d, on) \
    always @(posedge clock) if (past_valid && $past((v) && !(r))) begin \
        if (on) assert (v); \
        if (on) assert ((d) == $past(d)); \
    end

`define STALL_REACH(v, r, n) \
    always @(posedge clock) if (past_valid) begin \
        cover ($past((v) && !(r)) && (v)); \
        if (REACH == (n) || REACH_SET[(n)]) reach_``n: assert (!($past((v) && !(r)) && (v))); \
    end
