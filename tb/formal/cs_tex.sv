// Formal harness of the `cs_tex` top (the textured Color Shader, `idxrender verilog --block cs_tex`;
// RustHDL source hdl/src/cs/color_shader_tex.rs). Run by `bash scripts/formal.sh cs_tex`; see
// docs/verification.md. The colours are the replay tests' job; this harness checks the video
// stream's protocol and framing, textured or not, as cs.sv does for `cs`, and that an untextured frame
// leaves the texture ports idle.
//
// Assumed: one frame, started while not busy, of width 1..3 and height 1..2 (so that the whole
// frame, 38 cycles of latency plus its pixels, two clocks each when trilinear, fits the bmc depth);
// the width and height held while busy; light, material and level-table writes only while not busy;
// the texture's settings those the host can give (filter 0-2, sizes to 1024, the last level at most
// the larger size's log2); the memories' read data (I-buffer, TdbS, TdbT, the four banks) arbitrary.
// Asserted: video_tvalid held until video_tready and tdata, tuser and tlast stable while stalled;
// no beat before the frame starts or after its width x height beats; tuser on the first beat only,
// tlast on the last beat of each line only; `busy` high while beats of the frame are still to come
// and none is on the port; no size error; no TdbT or texture-bank read in an untextured frame. Reach
// points: a stalled beat, the last beat of a 3x2 frame taken, a read of all four texture banks in one
// cycle (a bilinear footprint).
`include "stream.vh"

module cs_tex_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire start,
    input wire [10:0] width,
    input wire [10:0] height,
    input wire [23:0] background,
    input wire clear_behind,
    input wire shading_phong,
    input wire light_write_enable,
    input wire [1:0] light_write_address,
    input wire [95:0] light_write_data,
    input wire material_write_enable,
    input wire [3:0] material_write_address,
    input wire [2:0] material_write_slot,
    input wire [95:0] material_write_data,
    input wire [15:0] ibuf_read_data,
    input wire [423:0] tdbs_read_data,
    input wire [407:0] tdbt_read_data,
    input wire texture_enable,
    input wire [3:0] tex_w0_log2,
    input wire [3:0] tex_h0_log2,
    input wire [3:0] tex_last_level,
    input wire [1:0] tex_filter,
    input wire tex_clamp,
    input wire tex_base_we,
    input wire [3:0] tex_base_sel,
    input wire [19:0] tex_base_data,
    input wire [23:0] tex_data0,
    input wire [23:0] tex_data1,
    input wire [23:0] tex_data2,
    input wire [23:0] tex_data3,
    input wire video_tready
);
    wire busy, size_error;
    wire ibuf_read_enable, tdbs_read_enable, ibuf_write_enable, zbuf_write_enable;
    wire [19:0] ibuf_read_address, ibuf_write_address, zbuf_write_address;
    wire [15:0] tdbs_read_address, ibuf_write_data;
    wire [23:0] zbuf_write_data, video_tdata;
    wire video_tvalid, video_tuser, video_tlast;
    wire tdbt_read_enable;
    wire [15:0] tdbt_read_address;
    wire [3:0] tex_rd;
    wire [19:0] tex_addr0, tex_addr1, tex_addr2, tex_addr3;
    cs_tex dut (
        .clock(clock), .start(start), .width(width), .height(height), .background(background),
        .clear_behind(clear_behind), .shading_phong(shading_phong),
        .light_write_enable(light_write_enable), .light_write_address(light_write_address),
        .light_write_data(light_write_data), .material_write_enable(material_write_enable),
        .material_write_address(material_write_address), .material_write_slot(material_write_slot),
        .material_write_data(material_write_data), .busy(busy), .size_error(size_error),
        .ibuf_read_enable(ibuf_read_enable), .ibuf_read_address(ibuf_read_address),
        .ibuf_read_data(ibuf_read_data), .tdbs_read_enable(tdbs_read_enable),
        .tdbs_read_address(tdbs_read_address), .tdbs_read_data(tdbs_read_data),
        .ibuf_write_enable(ibuf_write_enable), .ibuf_write_address(ibuf_write_address),
        .ibuf_write_data(ibuf_write_data), .zbuf_write_enable(zbuf_write_enable),
        .zbuf_write_address(zbuf_write_address), .zbuf_write_data(zbuf_write_data),
        .video_tdata(video_tdata), .video_tvalid(video_tvalid), .video_tready(video_tready),
        .video_tuser(video_tuser), .video_tlast(video_tlast),
        .tdbt_read_enable(tdbt_read_enable), .tdbt_read_address(tdbt_read_address),
        .tdbt_read_data(tdbt_read_data), .texture_enable(texture_enable), .tex_w0_log2(tex_w0_log2),
        .tex_h0_log2(tex_h0_log2), .tex_last_level(tex_last_level), .tex_filter(tex_filter),
        .tex_clamp(tex_clamp), .tex_base_we(tex_base_we), .tex_base_sel(tex_base_sel),
        .tex_base_data(tex_base_data), .tex_rd(tex_rd), .tex_addr0(tex_addr0), .tex_addr1(tex_addr1),
        .tex_addr2(tex_addr2), .tex_addr3(tex_addr3), .tex_data0(tex_data0), .tex_data1(tex_data1),
        .tex_data2(tex_data2), .tex_data3(tex_data3)
    );

    `include "cs_frame.vh"

    // ---- The texture: the host's side, and the texture ports idle in an untextured frame.
    reg textured = 1'b0;
    always @(posedge clock) if (begin_frame) textured <= texture_enable;
    always @(*) begin
        if (busy || begin_frame) assume (!tex_base_we);
        assume (tex_filter != 2'd3 && tex_w0_log2 <= 4'd10 && tex_h0_log2 <= 4'd10);
        assume (tex_last_level <= tex_w0_log2 || tex_last_level <= tex_h0_log2);
        if (!textured) if (REACH < 0) assert (tex_rd == 4'd0 && !tdbt_read_enable);
    end
    always @(posedge clock) if (past_valid) begin
        cover (tex_rd == 4'hf);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (tex_rd != 4'hf);
    end
endmodule
