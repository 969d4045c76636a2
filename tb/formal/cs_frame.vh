// The Color Shader's frame and video-stream properties shared by cs.sv and cs_tex.sv (`include`d
// inside each harness module after the top's instance; REACH is the module's parameter). See cs.sv's
// header for what is assumed and asserted; reach points 0 (a stalled beat) and 1 (the last beat of a
// 3x2 frame taken).
    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;

    reg started = 1'b0;
    reg [10:0] w = 11'd0;
    reg [10:0] h = 11'd0;
    wire begin_frame = start && !busy;
    always @(*) begin
        if (start) assume (!started && !busy && width >= 11'd1 && width <= 11'd3 && height >= 11'd1 && height <= 11'd2);
        if (started && busy) assume (width == w && height == h);
        if (busy || begin_frame) assume (!light_write_enable && !material_write_enable);
    end

    // ---- The video stream.
    wire beat = video_tvalid && video_tready;
    reg [10:0] bx = 11'd0;
    reg [10:0] by = 11'd0;
    reg frame_done = 1'b0;
    always @(posedge clock) begin
        if (begin_frame) begin
            started <= 1'b1;
            w <= width;
            h <= height;
        end
        if (beat) begin
            if (bx + 11'd1 == w) begin
                bx <= 11'd0;
                by <= by + 11'd1;
                if (by + 11'd1 == h) frame_done <= 1'b1;
            end else begin
                bx <= bx + 11'd1;
            end
        end
    end
    `STREAM_OUT(video_tvalid, video_tready, {video_tdata, video_tuser, video_tlast}, REACH < 0)
    always @(*) begin
        if (video_tvalid) begin
            if (REACH < 0) assert (started && !frame_done);
            if (REACH < 0) assert (video_tuser == (bx == 11'd0 && by == 11'd0));
            if (REACH < 0) assert (video_tlast == (bx + 11'd1 == w));
        end
        if (REACH < 0) assert (!size_error);
        if (started && !frame_done && !video_tvalid) if (REACH < 0) assert (busy);
    end

    `STALL_REACH(video_tvalid, video_tready, 0)
    always @(posedge clock) if (past_valid) begin
        cover (beat && video_tlast && by + 11'd1 == h && h == 11'd2 && w == 11'd3);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(beat && video_tlast && by + 11'd1 == h && h == 11'd2 && w == 11'd3));
    end
