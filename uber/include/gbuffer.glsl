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
//   RT3     R32F         surface depth (0..1): exactly 1.0 is sky, geometry lies
//                        below it; its lowest mantissa bit is the sun-facing bit
//   RT4     R8UI         coverage flags (classified G-buffer, 2+ samples only)
//   depth   D32          the hardware depth test's own, interpolated per sample;
//                        no shader reads it
//
// RT0..RT3 are what lighting reads; the baselines' "plain" G-buffer writes them
// and nothing else, bit for bit as the classified G-buffer does (one material
// shader, compiled with and without GBUFFER_COVERAGE_FLAGS). RT4 is the classified
// path's only extra: classification reads it to find the pixels whose samples
// may differ. Motion byte: bits 0..6 are the motion ID (0 = sky), bit 7 unused.
//
// Surface depth (RT3): colour targets are written once per fragment (per pixel,
// not per sample), so every sample a fragment covers stores the same RT3 value,
// the fragment's depth at the pixel centre; a pixel covered by one fragment has
// bit-identical samples in every target lighting reads, which is what lets the
// lighting shade sample 0 alone there. The hardware depth stays interpolated per
// sample and no shader writes gl_FragDepth, so early and hierarchical depth
// testing stay on. A mesh with flat faces (gbuffer.frag) stores the depth of its
// face's plane, whose coefficients both triangles of the face receive from data
// they share exactly, so the two store equal values along their shared diagonal.
//
// Sky: the sky pass draws at the far plane and stores surface depth 1.0 (and
// motion ID 0); gbuffer_encode_depth() keeps every material depth below 1.0, so
// `depth == 1.0` is the sky test of every reader.
//
// Sun-facing bit: the one "faces the sun" decision of the lighting (SUN_LIGHT)
// is made once, by the material shader, on the normal exactly as RT1 stores it
// (gbuffer_stored_normal()), and kept in the surface depth; the lighting and
// the classifier both read the bit, so they cannot disagree. It makes the
// G-buffer depend on the direction of the one sun, which the frame knows before
// the G-buffer pass (scene_params.glsl).
//
// Coverage flags (RT4, one byte a sample): what the fragment that wrote the sample knew about
// its coverage AFTER the depth test (post-depth coverage: gl_SampleMaskIn holds only the samples
// that passed, with early fragment tests). GBUFFER_FLAG_PARTIAL: it won only some of its
// pixel's samples. A pixel whose samples come from two or more fragments always holds a sample
// of a partial one: the last fragment written among them did not win every sample, or it would
// hold them all. So a pixel with no flag on any sample has bit-identical samples, exactly, and
// intersecting surfaces, which interleave by depth inside a pixel, are found too.
// GBUFFER_FLAG_SHARED replaces PARTIAL where the partial fragment's values come from data its
// neighbours share exactly: a flat face (both triangles of a face store the same values along
// their diagonal, gbuffer.frag) and the sky (whose values depend on the pixel centre alone, and
// whose full-screen triangle a driver may split); such a pixel differs only where a comparison
// of its stored values says so (gbuffer_samples_equal()).
//
// The plain G-buffer has no flags: a reader that needs the decision there (the
// dynamic baseline) compares every sample's stored values instead
// (gbuffer_pixel_samples_differ()), which is exact and costs more.
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
// The sun-facing bit: the lowest mantissa bit of the surface depth.
const uint GBUFFER_DEPTH_SUN_BIT = 1u;
// The depth of the sky (the far plane), and the largest a material stores.
const float GBUFFER_SKY_DEPTH = 1.0;
const float GBUFFER_MAX_GEOMETRY_DEPTH = 0.99999994; // the float below 1.0
// Coverage flags (RT4).
const uint GBUFFER_FLAG_PARTIAL = 1u; // the writing fragment won only some samples: they differ
const uint GBUFFER_FLAG_SHARED = 2u;  // ... and its values are shared data: compare them

// One decoded G-buffer sample: everything the lighting needs, and nothing about
// how it is stored.
struct GSample {
    vec3  albedo;
    float spec_amount;
    vec3  normal;      // as stored (signed, normalised by the material shader)
    uint  motion_id;   // 0..127
    bool  faces_sun;   // the surface depth's sun-facing bit
    bool  is_sky;      // depth 1.0: colour is prelit, no lighting at all
    vec3  prelit;
    float spec_power;
    float depth;       // surface depth as stored, 0..1 (its bit included)
};

// What the surface depth alone says about a sample (gbuffer_decode_depth()).
struct GDepthSample {
    float depth;       // as stored, bit included
    bool  is_sky;
    bool  faces_sun;
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

// The surface depth a material fragment stores: `depth` (0..1) kept below the
// sky's 1.0, with its lowest mantissa bit replaced by the sun-facing bit.
// Depths below the smallest normal float are raised to it first, so the bit
// never lands in a denormal that a driver running with denormals-are-zero
// (llvmpipe) would flush.
float gbuffer_encode_depth(float depth, bool faces_sun)
{
    uint bits = floatBitsToUint(clamp(depth, 1.17549435e-38, GBUFFER_MAX_GEOMETRY_DEPTH));
    bits &= ~GBUFFER_DEPTH_SUN_BIT;
    return uintBitsToFloat(bits | (faces_sun ? GBUFFER_DEPTH_SUN_BIT : 0u));
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

// The coverage flags of a fragment: `partial` (post-depth), and whether its values are shared
// data (a flat face, the sky).
uint gbuffer_encode_flags(bool partial, bool shared_values)
{
    return partial ? (shared_values ? GBUFFER_FLAG_SHARED : GBUFFER_FLAG_PARTIAL) : 0u;
}

// The coverage flags of an alpha-masked fragment. It runs without early fragment tests (a
// discard must also discard its depth), so `partial_before_depth` is its rasterised coverage, not
// the samples it won: covering every sample, it may still lose some to the depth test and leave
// its pixel holding two surfaces, with no partial fragment written last. So a masked fragment
// never writes "no flag": where its coverage is partial it flags as an opaque one would (a
// partial fragment's post-depth coverage is partial too); where it covers every sample it writes
// SHARED, "compare the stored values", which readers resolve exactly (classification compares,
// the light pass shades every sample). The argument of the coverage flags above then holds again:
// of the fragments a mixed pixel holds, the one written last is flagged, masked or not. A masked
// fragment that wins every sample costs a comparison, never a wrong answer.
uint gbuffer_encode_masked_flags(bool partial_before_depth, bool shared_values)
{
    return partial_before_depth ? gbuffer_encode_flags(true, shared_values) : GBUFFER_FLAG_SHARED;
}

#ifdef GBUFFER_ENCODE_ONLY
// Samples per pixel of the G-buffer being written; the runtime specialises it.
layout(constant_id = 0) const uint GBUFFER_SAMPLES = 1u;

// True when this fragment covers only some of its pixel's samples (after the depth test where
// the shader declares post_depth_coverage). Fragment stage only.
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

GDepthSample gbuffer_decode_depth(float depth)
{
    GDepthSample d;
    d.depth = depth;
    d.is_sky = depth == GBUFFER_SKY_DEPTH;
    d.faces_sun = !d.is_sky && (floatBitsToUint(depth) & GBUFFER_DEPTH_SUN_BIT) != 0u;
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
    g.faces_sun   = d.faces_sun;
    g.is_sky      = d.is_sky;
    g.prelit      = rt2.rgb;
    g.spec_power  = rt2.a;
    g.depth       = depth;
    return g;
}

// Whether a sample's flags make its pixel an edge, and whether they ask for a comparison.
bool gbuffer_flags_partial(uint flags)
{
    return (flags & GBUFFER_FLAG_PARTIAL) != 0u;
}

bool gbuffer_flags_shared(uint flags)
{
    return (flags & GBUFFER_FLAG_SHARED) != 0u;
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
                          gbuffer_fetch(gbuffer_surface_depth, pixel, sample_index).r);
}

// The surface depth alone (classification).
GDepthSample gbuffer_load_depth(ivec2 pixel, int sample_index)
{
    return gbuffer_decode_depth(gbuffer_fetch(gbuffer_surface_depth, pixel, sample_index).r);
}

// True when samples 1 .. samples - 1 of `pixel` store what its sample 0 stores, bit for bit, in
// every target lighting reads: sample 0's texels are read once. `samples` is the G-buffer's
// count (a constant where the caller has one, so that the loop unrolls).
bool gbuffer_samples_equal(ivec2 pixel, int samples)
{
    uvec4 rt0 = floatBitsToUint(gbuffer_fetch(gbuffer_albedo_spec, pixel, 0));
    uvec4 rt1 = floatBitsToUint(gbuffer_fetch(gbuffer_normal_motion, pixel, 0));
    uvec4 rt2 = floatBitsToUint(gbuffer_fetch(gbuffer_prelit_power, pixel, 0));
    uint rt3 = floatBitsToUint(gbuffer_fetch(gbuffer_surface_depth, pixel, 0).r);
    bool equal_all = true;
    for (int s = 1; s < samples; ++s) {
        equal_all = equal_all && floatBitsToUint(gbuffer_fetch(gbuffer_surface_depth, pixel, s).r) == rt3 &&
                    all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_albedo_spec, pixel, s)), rt0)) &&
                    all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_normal_motion, pixel, s)), rt1)) &&
                    all(equal(floatBitsToUint(gbuffer_fetch(gbuffer_prelit_power, pixel, s)), rt2));
    }
    return equal_all;
}

// True when the samples of `pixel` differ in some target lighting reads: the plain G-buffer's
// test (it has no flags), exact. False means the samples are bit-identical, so sample 0 alone
// shades the pixel.
bool gbuffer_pixel_samples_differ(ivec2 pixel)
{
    return !gbuffer_samples_equal(pixel, gbuffer_sample_count());
}

#ifndef GBUFFER_SINGLE_SAMPLED
uint gbuffer_load_flags(ivec2 pixel, int sample_index)
{
    return gbuffer_fetch(gbuffer_coverage_flags, pixel, sample_index).r;
}

// False only when no sample of `pixel` carries a flag: then every sample comes from one fragment
// and they are bit-identical. The classified G-buffer's cheap test (one R8UI texel a sample).
bool gbuffer_flags_say_samples_may_differ(ivec2 pixel)
{
    uint flags = 0u;
    for (int s = 0; s < gbuffer_sample_count(); ++s) {
        flags |= gbuffer_load_flags(pixel, s);
    }
    return flags != 0u;
}
#endif

#endif // GBUFFER_ENCODE_ONLY

#endif // UBER_GBUFFER_GLSL
