#version 450
// tile_prefix.comp -- GPU-driven index build, pass 2: an exclusive prefix sum over the per-class
// primitive counts (32 optimised IDs, or 128 raw IDs) gives each ID its range of the one index buffer; the indirect
// records and the fill cursors follow from it. At most 128 values: one invocation does it serially.
#extension GL_GOOGLE_include_directive : require
#include "tile_rects.glsl"

layout(local_size_x = 1) in;

void main()
{
    uint first_primitive = 0u;
    for (uint id = 0u; id < push.classes.x; ++id) {
        uint count = counters.primitives[id];
        counters.cursor[id] = first_primitive;
        draw_records.draws[id].index_count = count * indices_per_primitive();
        draw_records.draws[id].instance_count = 1u;
        draw_records.draws[id].first_index = first_primitive * indices_per_primitive();
        draw_records.draws[id].vertex_offset = 0;
        draw_records.draws[id].first_instance = 0u;
        first_primitive += count;
    }
}
