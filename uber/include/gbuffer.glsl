// gbuffer.glsl -- the G-buffer layout (Split/Second, Table 4.1), behind accessors.
//
// Following Tabula Rasa (GPU Gems 3, Listing 19-4), this is the ONLY file that
// knows which channel of which render target holds what. Material shaders write
// through the gbuffer_encode_* functions, the lighting and classification
// shaders read through gbuffer_load()/gbuffer_decode(); the layout can change
// here without touching either side.
//
//   target  format       r         g         b         a
//   RT0     RGBA8 unorm  albedo.r  albedo.g  albedo.b  specular amount
//   RT1     RGBA16F      normal.x  normal.y  normal.z  motion byte / 255
//   RT2     RGBA16F      prelit.r  prelit.g  prelit.b  specular power
//   depth   D32 (0..1), multisampled like the colour targets; exactly 1.0 is
//           sky, geometry lies below it; the lowest mantissa bit is the
//           MSAA-edge bit, the next one the sun-facing bit
//
// Motion byte: bits 0..6 are the motion ID (0 = sky), bit 7 is unused.
//
// The depth alone classifies a sample: whether it is sky, faces the sun or
// marks an MSAA edge, and where it lies. The classifier reads nothing else
// (gbuffer_load_depth()), except the colour targets of the pixels whose samples
// carry the face bit and agree in depth (see "MSAA-edge bit" below): an RGBA16F
// RT1 texel is the costliest fetch on a CPU driver (lavapipe), and the
// classifier read one for every pixel for these two decisions, a third of its
// time (docs/results.md h).
//
// Sky: the sky pass draws at the far plane, depth 1.0 (and motion ID 0), where
// the depth was cleared; gbuffer_encode_depth() keeps every material depth
// below 1.0, so `depth == 1.0` is the sky test of every reader.
//
// Sun-facing bit: the one "faces the sun" decision of the lighting (SUN_LIGHT)
// is made once, by the material shader, on the normal exactly as RT1 stores it
// (gbuffer_stored_normal()), and kept in the depth; the lighting and the
// classifier both read the bit, so they cannot disagree. It makes the G-buffer
// depend on the direction of the one sun, which the frame knows before the
// G-buffer pass (scene_params.glsl).
//
// MSAA-edge bit: Split/Second keeps a per-sample edge bit in the motion byte;
// here it is the lowest mantissa bit of the stored depth (one unit in the last
// place, 6e-8 of the depth or less). A material shader sets it in every sample
// it writes when its fragment covers only part of the pixel
// (gbuffer_fragment_is_partial). It moved to the depth because the classifier
// reads it from every sample of every pixel: a D32 texel is half the bytes of
// an RGBA16F one and takes the cheaper fetch path on a CPU driver (lavapipe),
// and the classifier reads sample 0's depth anyway.
// The bit marks a pixel whose samples MAY differ: because each fragment stores
// one depth in all its samples (below), two fragments that both cover the whole
// pixel win the depth test on the same samples, so a pixel whose samples differ
// always keeps a sample from a partial fragment. The converse does not hold:
// the two triangles of one flat face both cover part of the pixels along their
// shared diagonal, and store equal values there (gbuffer.frag computes them
// from the face's plane). So a pixel is an MSAA edge (gbuffer_pixel_is_edge(),
// the classifier's test) only where the bit is set AND some sample differs from
// sample 0 in some target; only such pixels are read beyond their depths, and
// only pixels with the bit are compared at all.
//
// Per-pixel depth: a non-edge pixel must have bit-identical samples, because
// the lighting shades only sample 0 of it. Colour targets are written once per
// pixel, but hardware depth is interpolated per sample, so a sloped surface
// would give every sample a different depth. Scene material shaders therefore
// write `gl_FragDepth = gbuffer_encode_depth(gl_FragCoord.z, partial, faces_sun)`
// (the pixel-centre depth with its bits), which stores one depth for all covered
// samples of the pixel; the edge-bit argument above rests on it too. The sky
// pass writes no bits: it lies at depth 1.0, whose low bits are 0 (and the
// decoders ignore the bits of the sky depth).
//
// Define GBUFFER_ENCODE_ONLY before including this file in a material
// (fragment) shader: it then declares no descriptors (the lighting bindings
// would collide with the material's own), only the layout, the encode/decode
// functions and gbuffer_fragment_is_partial(), whose GBUFFER_SAMPLES is
// specialization constant 0 of the material shader.

#ifndef UBER_GBUFFER_GLSL
#define UBER_GBUFFER_GLSL

#include "precise_math.glsl"

// Motion byte layout.
const uint GBUFFER_MOTION_ID_MASK = 0x7Fu; // motion IDs 0..127
const uint GBUFFER_SKY_MOTION_ID  = 0u;
// The MSAA-edge bit: the lowest mantissa bit of the stored depth.
const uint GBUFFER_DEPTH_EDGE_BIT = 1u;
// The sun-facing bit: the next mantissa bit.
const uint GBUFFER_DEPTH_SUN_BIT = 2u;
// The face bit: the third, set instead of the MSAA-edge bit by a partial fragment that stored
// its flat face's canonical values (gbuffer.frag).
const uint GBUFFER_DEPTH_FACE_BIT = 4u;
const uint GBUFFER_DEPTH_BITS = GBUFFER_DEPTH_EDGE_BIT | GBUFFER_DEPTH_SUN_BIT | GBUFFER_DEPTH_FACE_BIT;
// The depth of the sky (the far plane), and the largest a material stores.
const float GBUFFER_SKY_DEPTH = 1.0;
const float GBUFFER_MAX_GEOMETRY_DEPTH = 0.99999994; // the float below 1.0

// One decoded G-buffer sample: everything the lighting needs, and nothing about
// how it is stored.
struct GSample {
    vec3  albedo;
    float spec_amount;
    vec3  normal;      // as stored (signed, normalised by the material shader)
    uint  motion_id;   // 0..127
    bool  msaa_edge;   // the depth's MSAA-edge bit (classification only)
    bool  face_edge;   // the depth's face bit (classification only)
    bool  faces_sun;   // the depth's sun-facing bit
    bool  is_sky;      // depth 1.0: colour is prelit, no lighting at all
    vec3  prelit;
    float spec_power;
    float depth;       // depth as stored, 0..1 (its bits included)
};

// What the depth alone says about a sample (gbuffer_decode_depth()).
struct GDepthSample {
    float depth;       // as stored, bits included
    bool  is_sky;
    bool  faces_sun;
    bool  msaa_edge;
    bool  face_edge;
};

// ---------------------------------------------------------------------------
// Encoding (material shaders).

// The motion byte is stored as byte/255 in a 16F channel: half precision keeps
// 11 significant bits, so byte/255 * 255 is within 0.125 of the byte and the
// rounding in gbuffer_unpack_motion_byte() recovers it exactly.
float gbuffer_pack_motion_byte(uint motion_id)
{
    return float(motion_id & GBUFFER_MOTION_ID_MASK) / 255.0;
}

// The depth a material fragment stores: `depth` (0..1) kept below the sky's
// 1.0, with its three lowest mantissa bits replaced by the MSAA-edge,
// sun-facing and face bits. Depths below the smallest normal float are raised
// to it first, so the bits never land in a denormal that a driver running with
// denormals-are-zero (llvmpipe) would flush.
float gbuffer_encode_depth(float depth, bool msaa_edge, bool faces_sun, bool face_edge)
{
    uint bits = floatBitsToUint(clamp(depth, 1.17549435e-38, GBUFFER_MAX_GEOMETRY_DEPTH));
    bits &= ~GBUFFER_DEPTH_BITS;
    return uintBitsToFloat(bits | (msaa_edge ? GBUFFER_DEPTH_EDGE_BIT : 0u) | (faces_sun ? GBUFFER_DEPTH_SUN_BIT : 0u) |
                           (face_edge ? GBUFFER_DEPTH_FACE_BIT : 0u));
}

// The normal as RT1 (16F) stores it: rounded to half precision here, so that
// the attachment stores this exact value and the sun-facing bit is decided on
// what the lighting shades with.
vec3 gbuffer_stored_normal(vec3 normal)
{
    vec2 xy = unpackHalf2x16(packHalf2x16(normal.xy));
    float z = unpackHalf2x16(packHalf2x16(vec2(normal.z, 0.0))).x;
    return vec3(xy, z);
}

// The sun-facing bit of a stored normal: N.L > 0 towards the sun (false for a
// zero or NaN normal), written out in a fixed order (precise_dot()) so that
// every shader that recomputes it from the same values (the test upload) gets
// the same bit.
bool gbuffer_faces_sun(vec3 stored_normal, vec3 towards_sun)
{
    return precise_dot(stored_normal, towards_sun) > 0.0;
}

// RT0: the target is unorm, so the clamp only makes explicit what the hardware
// would do on write.
vec4 gbuffer_encode_rt0(vec3 albedo, float spec_amount)
{
    return vec4(clamp(albedo, 0.0, 1.0), clamp(spec_amount, 0.0, 1.0));
}

vec4 gbuffer_encode_rt1(vec3 normal, uint motion_id)
{
    return vec4(normal, gbuffer_pack_motion_byte(motion_id));
}

// Sky: prelit carries the final sky colour; motion ID 0 marks it.
vec4 gbuffer_encode_sky_rt1()
{
    return gbuffer_encode_rt1(vec3(0.0), GBUFFER_SKY_MOTION_ID);
}

vec4 gbuffer_encode_rt2(vec3 prelit, float spec_power)
{
    return vec4(prelit, spec_power);
}

#ifdef GBUFFER_ENCODE_ONLY
// Samples per pixel of the G-buffer being written; the runtime specialises it.
layout(constant_id = 0) const uint GBUFFER_SAMPLES = 1u;

// True when this fragment covers only some of its pixel's samples: the value of
// the MSAA-edge bit for every sample it writes. Fragment stage only.
bool gbuffer_fragment_is_partial()
{
    uint all_samples = (1u << GBUFFER_SAMPLES) - 1u;
    return (uint(gl_SampleMaskIn[0]) & all_samples) != all_samples;
}
#endif

// ---------------------------------------------------------------------------
// Decoding (pure: usable on values from any source, e.g. in round-trip tests).

uint gbuffer_unpack_motion_byte(float stored)
{
    return uint(clamp(round(stored * 255.0), 0.0, 255.0));
}

bool gbuffer_decode_msaa_edge_bit(float depth)
{
    return (floatBitsToUint(depth) & GBUFFER_DEPTH_EDGE_BIT) != 0u;
}

GDepthSample gbuffer_decode_depth(float depth)
{
    GDepthSample d;
    d.depth = depth;
    d.is_sky = depth == GBUFFER_SKY_DEPTH;
    d.faces_sun = !d.is_sky && (floatBitsToUint(depth) & GBUFFER_DEPTH_SUN_BIT) != 0u;
    d.msaa_edge = !d.is_sky && gbuffer_decode_msaa_edge_bit(depth);
    d.face_edge = !d.is_sky && (floatBitsToUint(depth) & GBUFFER_DEPTH_FACE_BIT) != 0u;
    return d;
}

GSample gbuffer_decode(vec4 rt0, vec4 rt1, vec4 rt2, float depth)
{
    GSample g;
    g.albedo      = rt0.rgb;
    g.spec_amount = rt0.a;
    g.normal      = rt1.xyz;
    g.motion_id   = gbuffer_unpack_motion_byte(rt1.a) & GBUFFER_MOTION_ID_MASK;
    GDepthSample d = gbuffer_decode_depth(depth);
    g.msaa_edge   = d.msaa_edge;
    g.face_edge   = d.face_edge;
    g.faces_sun   = d.faces_sun;
    g.is_sky      = d.is_sky;
    g.prelit      = rt2.rgb;
    g.spec_power  = rt2.a;
    g.depth       = depth;
    return g;
}

// ---------------------------------------------------------------------------
// Loading from the bound G-buffer (lighting and classification).

#ifndef GBUFFER_ENCODE_ONLY

#include "lighting_params.glsl"

int gbuffer_sample_count()
{
    return gbuffer_samples();
}

GSample gbuffer_load(ivec2 pixel, int sample_index)
{
    return gbuffer_decode(gbuffer_fetch(gbuffer_albedo_spec, pixel, sample_index),
                          gbuffer_fetch(gbuffer_normal_motion, pixel, sample_index),
                          gbuffer_fetch(gbuffer_prelit_power, pixel, sample_index),
                          gbuffer_fetch(gbuffer_depth, pixel, sample_index).r);
}

// The depth target alone (classification).
GDepthSample gbuffer_load_depth(ivec2 pixel, int sample_index)
{
    return gbuffer_decode_depth(gbuffer_fetch(gbuffer_depth, pixel, sample_index).r);
}

// True when samples 1 .. samples - 1 of `pixel` store what its sample 0 stores, bit for bit, in
// every colour target: sample 0's three texels are read once. `samples` is the G-buffer's count
// (a constant where the caller has one, so that the loop unrolls).
bool gbuffer_colours_all_equal(ivec2 pixel, int samples)
{
    uvec4 rt0 = floatBitsToUint(gbuffer_fetch(gbuffer_albedo_spec, pixel, 0));
    uvec4 rt1 = floatBitsToUint(gbuffer_fetch(gbuffer_normal_motion, pixel, 0));
    uvec4 rt2 = floatBitsToUint(gbuffer_fetch(gbuffer_prelit_power, pixel, 0));
    bool equal_all = true;
    for (int s = 1; s < samples; ++s) {
        equal_all = equal_all && all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_albedo_spec, pixel, s)), rt0)) &&
                    all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_normal_motion, pixel, s)), rt1)) &&
                    all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_prelit_power, pixel, s)), rt2));
    }
    return equal_all;
}

// True when the samples of `pixel` may differ: some sample carries the MSAA-edge bit, or some
// carries the face bit and some sample differs from sample 0 in some target (two triangles of
// one flat face store equal values, gbuffer.frag: their inner diagonal is no edge). False means
// the samples are bit-identical, so sample 0 alone shades the pixel (see above).
bool gbuffer_pixel_is_edge(ivec2 pixel)
{
    bool partial = false, face = false;
    for (int s = 0; s < gbuffer_sample_count(); ++s) {
        GDepthSample d = gbuffer_load_depth(pixel, s);
        partial = partial || d.msaa_edge;
        face = face || d.face_edge;
    }
    if (partial || !face) {
        return partial;
    }
    uint first_depth = floatBitsToUint(gbuffer_fetch(gbuffer_depth, pixel, 0).r);
    for (int s = 1; s < gbuffer_sample_count(); ++s) {
        if (floatBitsToUint(gbuffer_fetch(gbuffer_depth, pixel, s).r) != first_depth) {
            return true;
        }
    }
    return !gbuffer_colours_all_equal(pixel, gbuffer_sample_count());
}


#endif // GBUFFER_ENCODE_ONLY

#endif // UBER_GBUFFER_GLSL
