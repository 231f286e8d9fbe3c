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
//   depth   D32 (0..1), multisampled like the colour targets; its lowest
//           mantissa bit is the MSAA-edge bit
//
// Motion byte: bits 0..6 are the motion ID (0 = sky), bit 7 is unused.
//
// MSAA-edge bit: Split/Second keeps a per-sample edge bit in the motion byte;
// here it is the lowest mantissa bit of the stored depth (one unit in the last
// place, 6e-8 of the depth or less). A material shader sets it in every sample
// it writes when its fragment covers only part of the pixel
// (gbuffer_fragment_is_partial). It moved to the depth because the classifier
// reads it from every sample of every pixel: a D32 texel is half the bytes of
// an RGBA16F one and takes the cheaper fetch path on a CPU driver (lavapipe),
// and the classifier reads sample 0's depth anyway.
// The classifier ORs the bit over a pixel's samples instead of comparing them:
// because each fragment stores one depth in all its samples (below), two
// fragments that both cover the whole pixel win the depth test on the same
// samples, so a pixel whose samples differ always keeps a sample from a partial
// fragment. The converse does not hold (two partial fragments may store equal
// values), which is safe: the MSAA_EDGE permutation's running mean of equal
// samples is exactly the colour of sample 0.
//
// Per-pixel depth: a non-edge pixel must have bit-identical samples, because
// the lighting shades only sample 0 of it. Colour targets are written once per
// pixel, but hardware depth is interpolated per sample, so a sloped surface
// would give every sample a different depth. Scene material shaders therefore
// write `gl_FragDepth = gbuffer_encode_depth(gl_FragCoord.z, partial)` (the
// pixel-centre depth with the edge bit), which stores one depth for all covered
// samples of the pixel; the edge-bit argument above rests on it too. The sky
// pass writes no edge bit: it lies at depth 1.0, whose lowest bit is 0.
//
// Define GBUFFER_ENCODE_ONLY before including this file in a material
// (fragment) shader: it then declares no descriptors (the lighting bindings
// would collide with the material's own), only the layout, the encode/decode
// functions and gbuffer_fragment_is_partial(), whose GBUFFER_SAMPLES is
// specialization constant 0 of the material shader.

#ifndef UBER_GBUFFER_GLSL
#define UBER_GBUFFER_GLSL

// Motion byte layout.
const uint GBUFFER_MOTION_ID_MASK = 0x7Fu; // motion IDs 0..127
const uint GBUFFER_SKY_MOTION_ID  = 0u;
// The MSAA-edge bit: the lowest mantissa bit of the stored depth.
const uint GBUFFER_DEPTH_EDGE_BIT = 1u;

// One decoded G-buffer sample: everything the lighting needs, and nothing about
// how it is stored.
struct GSample {
    vec3  albedo;
    float spec_amount;
    vec3  normal;      // as stored (signed, normalised by the material shader)
    uint  motion_id;   // 0..127, edge bit removed
    bool  msaa_edge;   // the depth's MSAA-edge bit (classification only)
    bool  is_sky;      // motion_id == 0: colour is prelit, no lighting at all
    vec3  prelit;
    float spec_power;
    float depth;       // depth as stored, 0..1 (edge bit included)
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

// The depth a fragment stores: `depth` (0..1) with its lowest mantissa bit
// replaced by the MSAA-edge bit. Depths below the smallest normal float are
// raised to it first, so the bit never lands in a denormal that a driver
// running with denormals-are-zero (llvmpipe) would flush.
float gbuffer_encode_depth(float depth, bool msaa_edge)
{
    uint bits = floatBitsToUint(max(depth, 1.17549435e-38));
    return uintBitsToFloat((bits & ~GBUFFER_DEPTH_EDGE_BIT) | (msaa_edge ? GBUFFER_DEPTH_EDGE_BIT : 0u));
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

GSample gbuffer_decode(vec4 rt0, vec4 rt1, vec4 rt2, float depth)
{
    GSample g;
    g.albedo      = rt0.rgb;
    g.spec_amount = rt0.a;
    g.normal      = rt1.xyz;
    g.motion_id   = gbuffer_unpack_motion_byte(rt1.a) & GBUFFER_MOTION_ID_MASK;
    g.msaa_edge   = gbuffer_decode_msaa_edge_bit(depth);
    g.is_sky      = g.motion_id == GBUFFER_SKY_MOTION_ID;
    g.prelit      = rt2.rgb;
    g.spec_power  = rt2.a;
    g.depth       = depth;
    return g;
}

// ---------------------------------------------------------------------------
// Loading from the bound multisampled G-buffer (lighting and classification).

#ifndef GBUFFER_ENCODE_ONLY

#include "lighting_params.glsl"

int gbuffer_sample_count()
{
    return textureSamples(gbuffer_normal_motion);
}

GSample gbuffer_load(ivec2 pixel, int sample_index)
{
    return gbuffer_decode(texelFetch(gbuffer_albedo_spec, pixel, sample_index),
                          texelFetch(gbuffer_normal_motion, pixel, sample_index),
                          texelFetch(gbuffer_prelit_power, pixel, sample_index),
                          texelFetch(gbuffer_depth, pixel, sample_index).r);
}

bool gbuffer_load_msaa_edge_bit(ivec2 pixel, int sample_index)
{
    return gbuffer_decode_msaa_edge_bit(texelFetch(gbuffer_depth, pixel, sample_index).r);
}

#endif // GBUFFER_ENCODE_ONLY

#endif // UBER_GBUFFER_GLSL
