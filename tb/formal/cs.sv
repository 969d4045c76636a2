// Formal harness of the `cs` top (the Color Shader, `idxrender verilog --block cs`; RustHDL source
// hdl/src/cs/color_shader.rs). Run by `bash scripts/formal.sh cs`; see docs/verification.md. The
// colours are the replay tests' job; this harness checks the video stream's protocol and framing.
//
// Assumed: one frame, started while not busy, of width 1..3 and height 1..2 (so that the whole
// frame, 27 cycles of latency plus its pixels, fits the bmc depth); the width and height held while
// busy; light and material writes only while not busy; the memories' read data arbitrary.
// Asserted: video_tvalid held until video_tready and tdata, tuser and tlast stable while stalled;
// no beat before the frame starts or after its width x height beats; tuser on the first beat only,
// tlast on the last beat of each line only; `busy` high while beats of the frame are still to come
// and none is on the port; no size error. Reach points: a stalled beat, the last beat of a 3x2
// frame taken.
`include "stream.vh"

module cs_formal #(
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
    input wire video_tready
);
    wire busy, size_error;
    wire ibuf_read_enable, tdbs_read_enable, ibuf_write_enable, zbuf_write_enable;
    wire [19:0] ibuf_read_address, ibuf_write_address, zbuf_write_address;
    wire [15:0] tdbs_read_address, ibuf_write_data;
    wire [23:0] zbuf_write_data, video_tdata;
    wire video_tvalid, video_tuser, video_tlast;
    cs dut (
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
        .video_tuser(video_tuser), .video_tlast(video_tlast)
    );

    `include "cs_frame.vh"
endmodule
