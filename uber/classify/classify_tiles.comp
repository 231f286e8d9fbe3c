#version 450
// classify_tiles.comp -- screen-space tile classification (Split/Second, Sections 4.4-4.6).
//
// One invocation classifies one row of a block of 4x4 tiles (Fig. 4.3), tile by tile, and
// writes the row's four IDs as one uint32 (byte i = tile i of the row); tiles beyond the frame's
// partial edge blocks get 0xFF.
//
// What a tile's ID must promise (lighting.frag): SKY and SUN_LIGHT exactly where some sample is
// sky / faces the sun (the G-buffer's sun-facing bit, the lighting's own test); MSAA_EDGE,
// SHADOW_FADE and LIGHT_SCATTERING wherever a pixel needs them -- setting them anywhere else is
// harmless, because each of those features is an exact identity on the pixels that do not need
// it; and a shadow type that is right for every sun-facing sample whose shadow is not faded out
// completely: SOLID only if every tap of every such sample is occluded, none if every tap is
// lit, SOFT (full PCF, right for any sample) otherwise.
//
// Per sample the pass reads the coverage flags, which say whether the pixel's samples may differ
// (an MSAA edge, gbuffer.glsl), and per pixel sample 0's surface depth, which says whether it is
// sky, faces the sun (the lighting's own decision, made by the material) and where it lies; an
// edge pixel's other samples add their depths too. Everything that depends on position is decided per TILE, from bounds, because
// the lighting computes it with a projective map of (pixel centre, depth):
//   (x, y, d) -> h = inv_view_proj * (x, y, d, 1) -> world = h.xyz / h.w -> sun map texel P,
//   receiver depth r, view depth v,
// and each of P, r, v is a ratio of two affine functions of (x, y, d) with h.w > 0. Such a
// function is monotonic along every line, so over a convex polytope it takes its extremes at
// the vertices. The polytope is the tile's pixel-centre rectangle times its depths:
//   - view depth (fade, scattering): the rectangle x [nearest, farthest geometry depth];
//   - shadow: a thin prism, the rectangle x [plane + lowest offset, plane + highest offset],
//     where the plane is fitted to the tile's depths (a planar surface has depths affine in
//     screen space, so on one surface the prism is nearly flat).
// Every bound is widened by a rounding margin (world_error(), view_range(), prism_bounds()) that
// covers both the lighting's float arithmetic and this shader's, so a decision that the bounds settle is the
// one the lighting's own taps would make.
//
// The shadow test compares receivers with stored depths relative to a plane r = a.P + q fitted
// through the prism (for the tile's own surface, q is nearly constant): a tap of a sample at P
// reads texel t with t - P in (-2.5, 1.5] per axis (sun_shadow.glsl offsets), and is lit when
// r <= stored(t), which holds for every tap when
//     max q  <=  min over the tap rectangle of (stored(t) - a.t)  +  min over t - P of a.(t - P).
// With a = 0 this is "every receiver in front of every stored depth"; with the fitted a, a
// sloped surface that receives its own shadow map stays LIT as long as the PCF taps do. The
// mirrored test settles SOLID. Both a = 0 and the fitted a are tried.
//
// The tap rectangles are read 2x2 texels per textureGather, inside this one dispatch: for most
// tiles a rectangle holds 16-32 texels, for some (a distant tile, one spanning two surfaces)
// up to MAX_BOUNDED_TEXELS. On lavapipe, whose eight SIMD lanes loop as long as their largest
// rectangle, such tiles were once settled by a second, indirect dispatch; with four texels per
// gather that costs more than the lanes' wait (docs/results.md h).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "gbuffer.glsl"
#include "light_scattering.glsl"
#include "shadow_fade.glsl"
#include "sun_shadow.glsl"
#include "tile_classes.glsl"
#include "world_position.glsl"

layout(constant_id = 0) const uint TILE_SIZE = 4u; // pixels; 4, 8 or 16
// Samples per pixel of the G-buffer (the runtime specialises it to the targets' count). A
// constant, so that the loops over samples unroll: lavapipe runs a loop's body once more,
// masked, when its lanes leave it, which for a loop over samples 1..3 is a fourth fetch.
layout(constant_id = 8) const int GBUFFER_SAMPLES = 4;
const uint CLASSIFY_GROUP_SIZE = 64u;
layout(local_size_x = CLASSIFY_GROUP_SIZE) in;

layout(set = 1, binding = 0, std430) buffer TileIds {
    uint block_rows[]; // 4 per block
} tile_ids;

layout(push_constant) uniform ClassifyPush {
    uvec4 grid; // tiles_x, tiles_y, blocks_x, blocks_y
} push;

// A tile whose tap rectangle holds more texels than this is SOFT without reading it.
const int MAX_BOUNDED_TEXELS = 256;

// Unit roundoff of float32 (2^-24). Every rounding margin below is a first-order error bound of
// the arithmetic involved times a safety factor, MARGIN_ULPS units of roundoff per operation
// chain; see world_error().
const float ROUNDOFF = 5.9604645e-8;
const float MARGIN_ULPS = 16.0;

// Where t - P of a tap can lie, per axis: base = floor(P - 0.5) and offsets -1 .. 2.
const float TAP_DELTA_MIN = float(SUN_SHADOW_TAP_MIN_OFFSET.x) - 1.5 - 1e-3;
const float TAP_DELTA_MAX = float(SUN_SHADOW_TAP_MAX_OFFSET.x) - 0.5 + 1e-3;

// ---------------------------------------------------------------------------------------------
// Per-tile facts from the samples.

// A depth plane over the tile: depth(first_pixel + (i, j)) ~ origin + dot(gradient, (i, j)).
struct DepthPlane {
    float origin;
    vec2  gradient;
};

struct TileSamples {
    uint  flags;           // TILE_FLAG_SKY / SUN / EDGE
    float geometry_min;    // depth range of the non-sky samples
    float geometry_max;
    float sun_offset_min;  // depth - plane of the sun-facing samples
    float sun_offset_max;
};

// Fitted through the depths of the corner pixels (sample 0), skipping corners at depth 1.0 --
// sky, which the sky pass leaves at the far plane -- so that a tile on a silhouette against the
// sky keeps its surface's plane. Any plane is sound: a poor fit (several surfaces) only widens
// the offsets, and with them the prism.
// d00, d10, d01, d11: sample 0's depths at first_pixel, (last.x, first.y), (first.x, last.y),
// last_pixel.
DepthPlane depth_plane_from_corners(float d00, float d10, float d01, float d11, ivec2 first_pixel,
                                    ivec2 last_pixel)
{
    bool s00 = d00 < 1.0, s10 = d10 < 1.0, s01 = d01 < 1.0, s11 = d11 < 1.0;
    vec2 span = vec2(max(last_pixel - first_pixel, ivec2(1)));
    vec2 gradient;
    gradient.x = s00 && s10 ? (d10 - d00) / span.x : s01 && s11 ? (d11 - d01) / span.x : 0.0;
    gradient.y = s00 && s01 ? (d01 - d00) / span.y : s10 && s11 ? (d11 - d10) / span.y : 0.0;
    float origin = s00 ? d00
                 : s10 ? d10 - gradient.x * span.x
                 : s01 ? d01 - gradient.y * span.y
                 : d11 - gradient.x * span.x - gradient.y * span.y;
    return DepthPlane(origin, gradient);
}

DepthPlane fit_depth_plane(ivec2 first_pixel, ivec2 last_pixel)
{
    return depth_plane_from_corners(gbuffer_load_depth(first_pixel, 0).depth,
                                    gbuffer_load_depth(ivec2(last_pixel.x, first_pixel.y), 0).depth,
                                    gbuffer_load_depth(ivec2(first_pixel.x, last_pixel.y), 0).depth,
                                    gbuffer_load_depth(last_pixel, 0).depth, first_pixel, last_pixel);
}

float plane_offset(DepthPlane plane, ivec2 step, float depth)
{
    return (depth - plane.origin) - dot(plane.gradient, vec2(step));
}

void add_sun_offset(inout TileSamples tile, DepthPlane plane, ivec2 step, float depth)
{
    float offset = plane_offset(plane, step, depth);
    tile.sun_offset_min = min(tile.sun_offset_min, offset);
    tile.sun_offset_max = max(tile.sun_offset_max, offset);
}

// Adds everything but the sun-facing sample's plane offset; returns whether it needs one.
bool add_sample_flags(inout TileSamples tile, GDepthSample g)
{
    if (g.is_sky) {
        tile.flags |= TILE_FLAG_SKY;
        return false;
    }
    tile.geometry_min = min(tile.geometry_min, g.depth);
    tile.geometry_max = max(tile.geometry_max, g.depth);
    if (g.faces_sun) {
        tile.flags |= TILE_FLAG_SUN;
    }
    return g.faces_sun;
}

void add_sample(inout TileSamples tile, DepthPlane plane, ivec2 step, GDepthSample g)
{
    if (add_sample_flags(tile, g)) {
        add_sun_offset(tile, plane, step, g.depth);
    }
}

// Rows of a tile gathered at a time: as many as one 32-bit edge mask holds (all 4 rows of a 4x4
// tile; 4 of 8, 2 of 16).
const uint GATHER_ROWS = 32u / TILE_SIZE < TILE_SIZE ? 32u / TILE_SIZE : TILE_SIZE;
const uint GATHER_PIXELS = GATHER_ROWS * TILE_SIZE;

// An edge pixel adds all its samples; any other pixel sample 0 alone, which speaks for its
// equal siblings exactly as the lighting shades only sample 0 of such a pixel.
//
// Gathers rows [rows, rows + GATHER_ROWS) of the tile. With `whole_tile` (GATHER_ROWS ==
// TILE_SIZE, rows == 0) it first fits `plane` to the corner depths it has just read (the
// pixels are clamped to the frame, so its corner entries are the tile's corner pixels), which
// spares the four reads of fit_depth_plane(); otherwise `plane` is the caller's.
//
// The code is shaped for lavapipe, which runs eight neighbouring invocations as one SIMD
// program: a branch's body is executed (masked) for all eight whenever it is reached, and a
// loop runs as long as its busiest lane plus one masked pass. So
//   - the pixels of GATHER_ROWS rows are unrolled, with constant bounds (coordinates clamped to
//     the frame: a repeated pixel adds nothing new), and no per-pixel loop runs out;
//   - every sample's coverage flags (one R8UI fetch) are read without a branch per sample;
//   - the other samples of the edge pixels are added afterwards, in a loop over a bit mask of
//     them, instead of a branch per pixel that paid their fetches for every pixel; the loop
//     runs once per edge pixel of the busiest of the eight tiles (a few % of pixels are edge
//     pixels).
void gather_rows(inout TileSamples tile, ivec2 first_pixel, ivec2 last_pixel, inout DepthPlane plane,
                 uint rows, bool whole_tile)
{
    float depth[GATHER_PIXELS];  // sample 0: corners fit the plane, sun-facing ones get offsets
    uint needs_offset = 0u;      // bit k: pixel k = j * TILE_SIZE + i, that is (i, rows + j)
    uint edge_pixels = 0u;    // bit k: some sample of pixel k has the partial flag
    uint shared_pixels = 0u;  // ... the shared flag (partial fragments with shared values)
    [[unroll]] for (uint k = 0u; k < GATHER_PIXELS; ++k) {
        ivec2 pixel = min(first_pixel + ivec2(k % TILE_SIZE, rows + k / TILE_SIZE), last_pixel);
        GDepthSample first = gbuffer_load_depth(pixel, 0);
        uint edge = 0u;
        uint shared_face = 0u;
#ifndef GBUFFER_SINGLE_SAMPLED
        uint flags = 0u;
        [[unroll]] for (int s = 0; s < GBUFFER_SAMPLES; ++s) {
            flags |= gbuffer_load_flags(pixel, s);
        }
        edge = uint(gbuffer_flags_partial(flags));
        shared_face = uint(gbuffer_flags_shared(flags));
#endif
        depth[k] = first.depth;
        needs_offset |= uint(add_sample_flags(tile, first)) << k;
        edge_pixels |= edge << k;
        shared_pixels |= shared_face << k;
    }
    if (whole_tile) {
        plane = depth_plane_from_corners(depth[0], depth[TILE_SIZE - 1], depth[GATHER_PIXELS - TILE_SIZE],
                                         depth[GATHER_PIXELS - 1], first_pixel, last_pixel);
    }
    [[unroll]] for (uint k = 0u; k < GATHER_PIXELS; ++k) {
        if ((needs_offset & (1u << k)) != 0u) {
            ivec2 pixel = min(first_pixel + ivec2(k % TILE_SIZE, rows + k / TILE_SIZE), last_pixel);
            add_sun_offset(tile, plane, pixel - first_pixel, depth[k]);
        }
    }
    // Samples 1.. of the pixels with a partial or shared flag (the G-buffer always has 2 or
    // more), one (pixel, sample) pair per pass, so that the pass the loop always runs once more
    // (masked) costs one sample's fetches, not a pixel's. The tile is an MSAA edge tile where
    // some pixel's samples may differ: a pixel with the partial flag; or one with the shared
    // flag whose samples differ from sample 0 in their surface depth, which this loop
    // reads anyway, or, where every depth agrees (a flat face's inner diagonal, which is no
    // edge), in a colour target, which the loop after it checks, only in tiles without an edge
    // so far and only until one pixel's values differ.
    uint pending = edge_pixels | shared_pixels;
    bool depths_differ = false;
    int s = 1;
    while (pending != 0u) {
        uint k = uint(findLSB(pending));
        ivec2 pixel = min(first_pixel + ivec2(k % TILE_SIZE, rows + k / TILE_SIZE), last_pixel);
        GDepthSample g = gbuffer_load_depth(pixel, s);
        add_sample(tile, plane, pixel - first_pixel, g);
        // Sample 0's depth is fetched again rather than indexed out of depth[]: a dynamic index
        // would move that array to memory for every access above (lavapipe: ~3 ms at 720p).
        depths_differ = depths_differ || floatBitsToUint(g.depth) != floatBitsToUint(gbuffer_load_depth(pixel, 0).depth);
        bool pixel_done = s >= GBUFFER_SAMPLES - 1;
        pending = pixel_done ? pending & (pending - 1u) : pending;
        s = pixel_done ? 1 : s + 1;
    }
    bool samples_differ = edge_pixels != 0u || depths_differ;
    uint values_pending = samples_differ ? 0u : shared_pixels;
    while (values_pending != 0u) {
        uint k = uint(findLSB(values_pending));
        ivec2 pixel = min(first_pixel + ivec2(k % TILE_SIZE, rows + k / TILE_SIZE), last_pixel);
        samples_differ = !gbuffer_samples_equal(pixel, GBUFFER_SAMPLES);
        values_pending = samples_differ ? 0u : values_pending & (values_pending - 1u);
    }
    if (samples_differ) {
        tile.flags |= TILE_FLAG_EDGE;
    }
}

// Also returns the tile's depth plane (fit_depth_plane()'s).
TileSamples gather_tile(ivec2 first_pixel, ivec2 last_pixel, out DepthPlane plane)
{
    TileSamples tile = TileSamples(0u, 1.0 / 0.0, -1.0 / 0.0, 1.0 / 0.0, -1.0 / 0.0);
    if (GATHER_ROWS == TILE_SIZE) {
        gather_rows(tile, first_pixel, last_pixel, plane, 0u, true); // the whole tile, without a loop
    } else {
        plane = fit_depth_plane(first_pixel, last_pixel);
        for (uint rows = 0u; rows < TILE_SIZE; rows += GATHER_ROWS) {
            gather_rows(tile, first_pixel, last_pixel, plane, rows, false);
        }
    }
    return tile;
}

// ---------------------------------------------------------------------------------------------
// The projective map, per tile.

// Rows of the map from homogeneous camera clip coordinates (x, y, d, 1), composed once per
// invocation: h.w, the view depth's numerator, and the sun clip position's numerators.
struct ClipMaps {
    mat3x4 world_rows; // h.x, h.y, h.z
    vec4 w_row;       // h.w
    vec4 view_row;    // dot(h.xyz, camera_forward)
    mat4 sun;         // sun_view_proj * inv_view_proj (rows used: x, y, z)
    vec4 w_row_abs;   // |entries|, for the margins
    float world_abs;  // max over rows x, y, z of the sum of |inv_view_proj| entries
};

vec4 matrix_row(mat4 m, int row)
{
    return vec4(m[0][row], m[1][row], m[2][row], m[3][row]);
}

ClipMaps clip_maps()
{
    mat4 inv = params.inv_view_proj;
    ClipMaps maps;
    maps.world_rows = mat3x4(matrix_row(inv, 0), matrix_row(inv, 1), matrix_row(inv, 2));
    maps.w_row = matrix_row(inv, 3);
    maps.view_row = maps.world_rows * params.camera_forward.xyz;
    maps.sun = params.sun_view_proj * inv;
    maps.w_row_abs = abs(maps.w_row);
    maps.world_abs = max(max(dot(abs(maps.world_rows[0]), vec4(1.0)), dot(abs(maps.world_rows[1]), vec4(1.0))),
                         dot(abs(maps.world_rows[2]), vec4(1.0)));
    return maps;
}

// First-order bound on the error of a world position computed by world_position_from_depth()
// (4-term dot products, one division), for vertices with |x|, |y| <= 1, |d| <= depth_abs,
// h.w >= w_min and |world| <= world_abs. h.w is a small difference of large terms for distant
// points, which is what makes them imprecise. MARGIN_ULPS covers the lighting's rounding and
// this shader's (composed matrices) together.
float world_error(ClipMaps maps, float depth_abs, float w_min, float world_abs)
{
    vec4 v_abs = vec4(1.0, 1.0, max(depth_abs, 1.0), 1.0);
    float terms = maps.world_abs * max(depth_abs, 1.0);
    float w_terms = dot(maps.w_row_abs, v_abs);
    return MARGIN_ULPS * ROUNDOFF * ((terms + world_abs * w_terms) / w_min + world_abs);
}

// The largest |world coordinate| at a vertex whose h.w is w.
float world_abs_at(ClipMaps maps, vec4 clip, float w)
{
    vec3 world = abs((clip * maps.world_rows) / w);
    return max(world.x, max(world.y, world.z));
}

// View-depth range of the rectangle x [depth_min, depth_max].
struct ViewRange {
    float lo;
    float hi;
};

ViewRange view_range(ClipMaps maps, vec2 ndc_min, vec2 ndc_max, float depth_min, float depth_max)
{
    float lo = 1.0 / 0.0;
    float hi = -1.0 / 0.0;
    float w_min = 1.0 / 0.0;
    float world_abs = 0.0;
    [[unroll]] for (int i = 0; i < 8; ++i) {
        vec4 clip = vec4((i & 1) != 0 ? ndc_max.x : ndc_min.x, (i & 2) != 0 ? ndc_max.y : ndc_min.y,
                         (i & 4) != 0 ? depth_max : depth_min, 1.0);
        float w = dot(maps.w_row, clip);
        float v = dot(maps.view_row, clip) / w;
        lo = min(lo, v);
        hi = max(hi, v);
        w_min = min(w_min, w);
        world_abs = max(world_abs, world_abs_at(maps, clip, w));
    }
    float camera = dot(params.camera_pos.xyz, params.camera_forward.xyz);
    vec3 forward_abs = abs(params.camera_forward.xyz);
    float world = world_error(maps, max(abs(depth_min), abs(depth_max)), w_min, world_abs);
    float margin = (forward_abs.x + forward_abs.y + forward_abs.z)
                       * (world + MARGIN_ULPS * ROUNDOFF * (world_abs + abs(camera)))
                   + MARGIN_ULPS * ROUNDOFF * max(abs(lo), abs(hi));
    if (!(w_min > 0.0 && lo <= hi)) {
        return ViewRange(-1.0 / 0.0, 1.0 / 0.0); // no bound: every distance feature, shadow kept
    }
    return ViewRange(lo - camera - margin, hi - camera + margin);
}

// ---------------------------------------------------------------------------------------------
// Shadow type from the prism.

// Where the prism's samples land in the sun's map, in the lighting's float arithmetic.
struct PrismBounds {
    bool  valid;        // false: no usable bound (degenerate or non-finite), the tile is SOFT
    vec2  p_min;        // texel position range (lookup point, continuous texel coordinates)
    vec2  p_max;
    float r_min;        // receiver depth range (biased)
    float r_max;
    vec2  slope;        // a: receiver depth per texel of the fitted surface, or 0
    float q_min[2];     // range of r - a.P, for a = 0 ([0]) and the fitted a ([1])
    float q_max[2];
};

// Sun clip numerators (x, y, z) and h.w at a vertex.
vec4 sun_clip_at(ClipMaps maps, vec4 clip)
{
    vec4 s = maps.sun * clip;
    return vec4(s.xyz, dot(maps.w_row, clip));
}

void texel_and_receiver(vec4 sun_clip, out vec2 texel, out float receiver)
{
    vec3 ndc = sun_clip.xyz / sun_clip.w;
    texel = (ndc.xy * 0.5 + 0.5) * params.shadow_map_size.xy;
    receiver = ndc.z - params.distances.w;
}

// The slope of r over P through three vertices on the plane; 0 where they are (nearly)
// collinear in the map.
vec2 fitted_slope(vec2 p0, float r0, vec2 p1, float r1, vec2 p2, float r2)
{
    vec2 e1 = p1 - p0;
    vec2 e2 = p2 - p0;
    float det = e1.x * e2.y - e1.y * e2.x;
    if (!(abs(det) > 1e-6 * (dot(e1, e1) + dot(e2, e2)) && abs(det) > 1e-12)) {
        return vec2(0.0);
    }
    vec2 a = vec2((r1 - r0) * e2.y - (r2 - r0) * e1.y, e1.x * (r2 - r0) - e2.x * (r1 - r0)) / det;
    return all(lessThan(abs(a), vec2(1.0))) ? a : vec2(0.0);
}

PrismBounds prism_bounds(ClipMaps maps, vec2 ndc_min, vec2 ndc_max, DepthPlane plane, vec2 plane_span,
                         float offset_min, float offset_max)
{
    // Outward rounding of the vertex depths (a few ulps of 1.0: the offsets themselves are
    // differences of nearby depths and nearly exact).
    const float depth_slack = 8.0 * ROUNDOFF * 2.0;
    vec2 p[8];
    float r[8];
    float w_min = 1.0 / 0.0;
    float depth_abs = 0.0;
    float world_abs = 0.0;
    [[unroll]] for (int i = 0; i < 8; ++i) {
        vec2 corner = vec2((i & 1) != 0 ? 1.0 : 0.0, (i & 2) != 0 ? 1.0 : 0.0);
        float depth = plane.origin + dot(plane.gradient, corner * plane_span)
                      + ((i & 4) != 0 ? offset_max + depth_slack : offset_min - depth_slack);
        vec4 clip = vec4(mix(ndc_min, ndc_max, corner), depth, 1.0);
        vec4 sun_clip = sun_clip_at(maps, clip);
        w_min = min(w_min, sun_clip.w);
        depth_abs = max(depth_abs, abs(depth));
        world_abs = max(world_abs, world_abs_at(maps, clip, sun_clip.w));
        texel_and_receiver(sun_clip, p[i], r[i]);
    }
    PrismBounds b;
    b.valid = w_min > 0.0;
    b.p_min = vec2(1.0 / 0.0);
    b.p_max = vec2(-1.0 / 0.0);
    b.r_min = 1.0 / 0.0;
    b.r_max = -1.0 / 0.0;
    b.slope = fitted_slope(p[0], r[0], p[1], r[1], p[2], r[2]);
    b.q_min[0] = b.q_min[1] = 1.0 / 0.0;
    b.q_max[0] = b.q_max[1] = -1.0 / 0.0;
    [[unroll]] for (int i = 0; i < 8; ++i) {
        b.p_min = min(b.p_min, p[i]);
        b.p_max = max(b.p_max, p[i]);
        b.r_min = min(b.r_min, r[i]);
        b.r_max = max(b.r_max, r[i]);
        float q = r[i] - dot(b.slope, p[i]);
        b.q_min[1] = min(b.q_min[1], q);
        b.q_max[1] = max(b.q_max[1], q);
    }
    b.q_min[0] = b.r_min;
    b.q_max[0] = b.r_max;
    b.valid = b.valid && all(lessThan(abs(vec4(b.p_min, b.p_max)), vec4(1e7)))
              && abs(b.r_min) < 1e7 && abs(b.r_max) < 1e7 && abs(b.q_min[1]) < 1e7 && abs(b.q_max[1]) < 1e7;
    if (!b.valid) {
        return b;
    }

    // Margins: the world position's error carried through the sun's affine map, plus that
    // map's own rounding, for the lighting and for this shader alike.
    float world = world_error(maps, depth_abs, w_min, world_abs);
    mat4 sun = params.sun_view_proj;
    vec3 row_abs = vec3(dot(abs(matrix_row(sun, 0).xyz), vec3(1.0)), dot(abs(matrix_row(sun, 1).xyz), vec3(1.0)),
                        dot(abs(matrix_row(sun, 2).xyz), vec3(1.0)));
    vec3 shift_abs = abs(matrix_row(sun, 3).xyz) + abs(vec3(sun[3][0], sun[3][1], sun[3][2]));
    vec3 clip_error = row_abs * world + MARGIN_ULPS * ROUNDOFF * (row_abs * world_abs + shift_abs + 1.0);
    vec2 map_size = params.shadow_map_size.xy;
    float p_abs = max(max(abs(b.p_min.x), abs(b.p_max.x)), max(abs(b.p_min.y), abs(b.p_max.y)));
    vec2 p_error = 0.5 * map_size * clip_error.xy + MARGIN_ULPS * ROUNDOFF * (p_abs + map_size);
    float r_error = clip_error.z + MARGIN_ULPS * ROUNDOFF * (1.0 + abs(params.distances.w));
    b.p_min -= p_error;
    b.p_max += p_error;
    b.r_min -= r_error;
    b.r_max += r_error;
    float slope_abs = abs(b.slope.x) + abs(b.slope.y);
    float q_error[2];
    q_error[0] = r_error;
    q_error[1] = r_error + dot(abs(b.slope), p_error) + MARGIN_ULPS * ROUNDOFF * (1.0 + slope_abs * p_abs);
    [[unroll]] for (int k = 0; k < 2; ++k) {
        b.q_min[k] -= q_error[k];
        b.q_max[k] += q_error[k];
    }
    return b;
}

// The smallest / largest a.(t - P) over the tap box.
float slope_delta_min(vec2 a)
{
    return min(a.x * TAP_DELTA_MIN, a.x * TAP_DELTA_MAX) + min(a.y * TAP_DELTA_MIN, a.y * TAP_DELTA_MAX);
}

float slope_delta_max(vec2 a)
{
    return max(a.x * TAP_DELTA_MIN, a.x * TAP_DELTA_MAX) + max(a.y * TAP_DELTA_MIN, a.y * TAP_DELTA_MAX);
}

// The map texels any tap of the prism's samples can read: [rect_min, rect_max], and its part
// inside the map, [lo, hi] (empty when lo > hi in some axis).
struct TapRectangle {
    ivec2 rect_min;
    ivec2 rect_max;
    ivec2 lo;
    ivec2 hi;
};

// Precondition: b.valid.
TapRectangle tap_rectangle(PrismBounds b)
{
    // The lighting clamps P to the map +- SUN_SHADOW_TAP_REACH: samples clamped there have no
    // tap inside the map, so clamping the range here keeps every in-map tap and int() defined.
    vec2 map_size = params.shadow_map_size.xy;
    vec2 lo_pos = clamp(b.p_min, vec2(-2.0 * SUN_SHADOW_TAP_REACH), map_size + 2.0 * SUN_SHADOW_TAP_REACH);
    vec2 hi_pos = clamp(b.p_max, vec2(-2.0 * SUN_SHADOW_TAP_REACH), map_size + 2.0 * SUN_SHADOW_TAP_REACH);
    TapRectangle rect;
    rect.rect_min = ivec2(floor(lo_pos - 0.5)) + SUN_SHADOW_TAP_MIN_OFFSET;
    rect.rect_max = ivec2(floor(hi_pos - 0.5)) + SUN_SHADOW_TAP_MAX_OFFSET;
    rect.lo = max(rect.rect_min, ivec2(0));
    rect.hi = min(rect.rect_max, ivec2(map_size) - 1);
    return rect;
}

// The stored depths of the 2x2 texels from `texel` (inside the map), read with one
// textureGather: four texels for one coordinate computation, one bounds check and one pass of
// the caller's loop, where lavapipe pays each of those per texelFetch (docs/results.md h). A
// texel beyond `hi` (the rectangle's last column or row) is replaced by `texel` itself, which
// the rectangle holds and whose second reading changes no minimum or maximum, so the bounds are
// exactly the rectangle's.
struct ShadowTexels {
    ivec2 texel[4];
    float stored[4];
};

ShadowTexels sun_shadow_stored_quad(ivec2 texel, ivec2 hi)
{
    // The gather's footprint for a point on the corner between the four texels is exactly
    // them: (i0, j1), (i1, j1), (i1, j0), (i0, j0) in x, y, z, w.
    vec4 g = textureGather(shadow_map, vec2(texel + 1) * params.shadow_map_size.zw);
    bool right = texel.x + 1 <= hi.x;
    bool below = texel.y + 1 <= hi.y;
    ShadowTexels q;
    q.texel[0] = texel;
    q.stored[0] = g.w;
    q.texel[1] = right ? texel + ivec2(1, 0) : texel;
    q.stored[1] = right ? g.z : g.w;
    q.texel[2] = below ? texel + ivec2(0, 1) : texel;
    q.stored[2] = below ? g.x : g.w;
    q.texel[3] = right && below ? texel + ivec2(1, 1) : texel;
    q.stored[3] = right && below ? g.y : g.w;
    return q;
}

// Texels of the rectangle inside the map (0 when none).
int tap_rectangle_texels(TapRectangle rect)
{
    ivec2 extent = max(rect.hi - rect.lo + 1, ivec2(0));
    return extent.x * extent.y;
}

uint shadow_type_from_prism(PrismBounds b)
{
    if (!b.valid) {
        return TILE_FLAG_PARTIAL;
    }
    TapRectangle rect = tap_rectangle(b);
    ivec2 lo = rect.lo;
    ivec2 hi = rect.hi;
    if (any(greaterThan(lo, hi))) {
        return TILE_FLAG_LIT; // every tap outside the map, where nothing was rendered
    }
    if (tap_rectangle_texels(rect) > MAX_BOUNDED_TEXELS) {
        return TILE_FLAG_PARTIAL;
    }
    // c = stored - a.t over the rectangle, for a = 0 and the fitted a.
    float c_min[2] = float[2](1.0 / 0.0, 1.0 / 0.0);
    float c_max[2] = float[2](-1.0 / 0.0, -1.0 / 0.0);
    // The rectangle's 2x2 quads row by row in one loop, not a loop per row: lavapipe runs each
    // loop once more (masked) than its busiest lane needs.
    int quads = ((hi.x - lo.x + 2) / 2) * ((hi.y - lo.y + 2) / 2);
    ivec2 quad_origin = lo;
    for (int q = 0; q < quads; ++q) {
        ShadowTexels quad = sun_shadow_stored_quad(quad_origin, hi);
        [[unroll]] for (int i = 0; i < 4; ++i) {
            float stored = quad.stored[i];
            float c = stored - dot(b.slope, vec2(quad.texel[i]));
            c_min[0] = min(c_min[0], stored);
            c_max[0] = max(c_max[0], stored);
            c_min[1] = min(c_min[1], c);
            c_max[1] = max(c_max[1], c);
        }
        bool row_done = quad_origin.x + 2 > hi.x;
        quad_origin = row_done ? ivec2(lo.x, quad_origin.y + 2) : quad_origin + ivec2(2, 0);
    }
    float c_error = MARGIN_ULPS * ROUNDOFF * (1.0 + dot(abs(b.slope), params.shadow_map_size.xy));
    vec2 slopes[2] = vec2[2](vec2(0.0), b.slope);
    // Taps outside the map are lit, so they never stop LIT.
    [[unroll]] for (int k = 0; k < 2; ++k) {
        if (b.q_max[k] <= c_min[k] - c_error + slope_delta_min(slopes[k])) {
            return TILE_FLAG_LIT;
        }
    }
    // SHADOWED needs every tap inside the map and every sample inside the sun's depth range
    // (outside it, sun_shadow_lookup() counts all taps lit).
    bool inside_map = all(equal(lo, rect.rect_min)) && all(equal(hi, rect.rect_max));
    float bias = params.distances.w;
    bool in_volume = b.r_min + bias >= 0.0 && b.r_max + bias <= 1.0;
    if (inside_map && in_volume) {
        [[unroll]] for (int k = 0; k < 2; ++k) {
            if (b.q_min[k] > c_max[k] + c_error + slope_delta_max(slopes[k])) {
                return TILE_FLAG_SHADOWED;
            }
        }
    }
    return TILE_FLAG_PARTIAL;
}

// ---------------------------------------------------------------------------------------------

// The raw ID of `tile`, which lies inside the grid.
uint classify_tile(ClipMaps maps, uvec2 tile, ivec2 size)
{
    ivec2 first_pixel = ivec2(tile * TILE_SIZE);
    ivec2 last_pixel = min(first_pixel + int(TILE_SIZE), size) - 1;
    DepthPlane plane;
    TileSamples samples_seen = gather_tile(first_pixel, last_pixel, plane);
    uint flags = samples_seen.flags;
    if (samples_seen.geometry_min > samples_seen.geometry_max) {
        return raw_id_from_tile_flags(flags); // sky only: no depth, no shadow
    }
    // The lighting's own pixel-centre NDC of the corner pixels: float arithmetic is monotonic,
    // so every pixel of the tile lies between them.
    vec2 ndc_min = pixel_centre_ndc(first_pixel);
    vec2 ndc_max = pixel_centre_ndc(last_pixel);
    ViewRange view = view_range(maps, ndc_min, ndc_max, samples_seen.geometry_min, samples_seen.geometry_max);
    // The lighting's own threshold tests at the range's ends: float subtraction, multiplication
    // by a positive constant and clamp are monotonic, so a sample's test lies between them.
    if (shadow_fade_active(view.hi)) flags |= TILE_FLAG_FADE;
    if (light_scattering_active(view.hi)) flags |= TILE_FLAG_SCATTERING;
    if ((flags & TILE_FLAG_SUN) == 0u) {
        return raw_id_from_tile_flags(flags);
    }
    // A shadow faded out completely gives every shadow type the same colour (shadow_fade.glsl).
    if (shadow_fade_complete(view.lo)) {
        return raw_id_from_tile_flags(flags);
    }
    PrismBounds prism = prism_bounds(maps, ndc_min, ndc_max, plane, vec2(last_pixel - first_pixel),
                                     samples_seen.sun_offset_min, samples_seen.sun_offset_max);
    flags |= shadow_type_from_prism(prism);
    return raw_id_from_tile_flags(flags);
}

void classify_block_row()
{
    uint block = gl_GlobalInvocationID.x / 4u;
    if (block >= push.grid.z * push.grid.w) {
        return;
    }
    uint row = gl_GlobalInvocationID.x % 4u;
    uvec2 first_tile = uvec2(block % push.grid.z, block / push.grid.z) * 4u + uvec2(0u, row);
    ivec2 size = ivec2(params.viewport.xy);
    ClipMaps maps = clip_maps();
    uint packed_row = 0u;
    for (uint i = 0u; i < 4u; ++i) {
        uvec2 tile = first_tile + uvec2(i, 0u);
        uint id = all(lessThan(tile, push.grid.xy)) ? classify_tile(maps, tile, size) : 0xFFu;
        packed_row |= id << (8u * i);
    }
    tile_ids.block_rows[block * 4u + row] = packed_row;
}

void main()
{
    classify_block_row();
}
