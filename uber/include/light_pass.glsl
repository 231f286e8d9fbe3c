// light_pass.glsl -- the body of the deferred global-light uber-shader, shared by its two
// forms: uber/lighting.frag (the raster pass: one fragment per pixel of each tile drawn) and
// uber/lighting.comp (the compute pass: one invocation per pixel of each tile dispatched).
// Both call shade_pixel() on the same G-buffer with the same permutation defines, so the two
// forms run the same arithmetic in the same order.
//
// Seven switches, each a raw tile property (docs/design.md, "The technique"). A permutation is
// the full shader restricted to the pixels its tile class admits, so on those pixels it
// computes the same value as the all-features shader:
//   SKY              sky pixels exist; without it every pixel is assumed to be geometry.
//   SUN_LIGHT        some pixel faces the sun; without it the sun term is exactly zero.
//   SOLID_SHADOW     every non-sky pixel is fully shadowed: shadow factor 0, no lookups.
//   SOFT_SHADOW      shadow edge: 8-tap PCF. With neither shadow define: fully lit, factor 1.
//   SHADOW_FADE      some pixel lies beyond the fade start; before it the fade is the identity.
//   LIGHT_SCATTERING some pixel lies beyond the scattering start; before it, the identity.
//   MSAA_EDGE        some pixel's samples differ: shade every sample and average; otherwise
//                    all samples are equal and sample 0 alone gives the same average.
// (Built with GBUFFER_SINGLE_SAMPLED, the G-buffer has one sample and MSAA_EDGE adds nothing.)
// Each feature is one call into the include library with the same arguments in every
// permutation, so the arithmetic that does run is identical to the full shader's.
//
// SKY and LIGHT_SCATTERING are read as expressions (`if (SKY)`), never with #ifdef, so the same
// text builds whatever kind the spec gives them (docs/spec-format.md, "Kinds"): a value-style
// define (split_second.json: `(1 == 1)` or `(0 == 1)`, folded away at compile time), a
// specialization constant (split_second_specialization.json, fixed at pipeline creation) or a
// uniform read (split_second_branch.json, taken per draw). Every other switch is a variant and
// keeps its #ifdef. The companions below are not permuted and get no feature defines, so they
// give the two expressions the value their pass needs themselves.
//
// DYNAMIC_BRANCHING builds the per-pixel baseline instead (tilelight's "dynamic" light pass):
// every feature compiled in, as in the naive pass, but each taken only where this pixel needs
// it, decided per pixel with the same tests the tile classifier applies per tile: no sun term
// and no shadow lookups where the pixel does not face the sun, every sample shaded only where
// the pixel's samples differ (it runs on the plain G-buffer, which has no classification data:
// it compares the samples' stored values). Sky, fade and scattering already branch
// per pixel inside their functions. Skipped work is exactly the identity there (the same
// contract the permutations rely on), so the result equals the naive pass.

#ifndef UBER_LIGHT_PASS_GLSL
#define UBER_LIGHT_PASS_GLSL

#include "gbuffer.glsl"
#include "sample_mean.glsl"
#include "light_scattering.glsl"
#include "shadow_fade.glsl"
#include "sun_lighting.glsl"
#include "sun_shadow.glsl"
#include "world_position.glsl"

#ifdef DYNAMIC_BRANCHING
#define SUN_LIGHT
#define SOFT_SHADOW
#define SHADOW_FADE
#define LIGHT_SCATTERING (1 == 1)
#define MSAA_EDGE
#define SKY (1 == 1)
const bool PER_PIXEL_BRANCHES = true;
#else
const bool PER_PIXEL_BRANCHES = false; // the tile's class decided: every test below folds away
#endif
#ifdef FLOOR_PASS
// The floor pass lights nothing: shade_sample() below is compiled but never called, and only
// needs the two expressions to exist.
#define LIGHT_SCATTERING (0 == 1)
#define SKY (0 == 1)
#endif

#if defined(SOLID_SHADOW) && defined(SOFT_SHADOW)
#error "SOLID_SHADOW and SOFT_SHADOW are mutually exclusive: such a tile is impossible"
#endif

// Sun visibility at a surface point, 0 (shadowed) .. 1 (lit), after the distance fade.
float sun_visibility(vec3 world_pos, float view_depth)
{
#if defined(SOLID_SHADOW)
    float shadow = 0.0;
#elif defined(SOFT_SHADOW)
    float shadow = sun_shadow_pcf(world_pos);
#else
    float shadow = 1.0;
#endif
#ifdef SHADOW_FADE
    shadow = shadow_fade_apply(shadow, view_depth);
#endif
    return shadow;
}

vec3 shade_geometry(GSample g, ivec2 pixel)
{
    vec3 world_pos = world_position_from_depth(pixel, g.depth);
    float view_depth = linear_view_depth(world_pos);
    vec3 colour = g.prelit;
#ifdef SUN_LIGHT
    if (!PER_PIXEL_BRANCHES || g.faces_sun) {
        vec3 sun = sun_surface_radiance(g.albedo, g.faces_sun, g.normal, world_pos, g.spec_amount, g.spec_power);
        colour += sun * sun_visibility(world_pos, view_depth);
    }
#endif
    if (LIGHT_SCATTERING) {
        colour = light_scattering_apply(colour, view_depth);
    }
    return colour;
}

vec3 shade_sample(ivec2 pixel, int sample_index)
{
    GSample g = gbuffer_load(pixel, sample_index);
    // The scene wrote the sky's final colour (atmosphere included): no sun, no scattering, so
    // nothing here depends on the sky's depth and its distance bits are harmless.
    if (SKY && g.is_sky) {
        return g.prelit;
    }
    return shade_geometry(g, pixel);
}

// Whether the bound G-buffer is the classified path's, with coverage flags (RT4): the tile passes
// set it (specialization constant 2); the baselines run on the plain G-buffer, which has none.
layout(constant_id = 2) const bool TAGGED_GBUFFER = false;

// The average of every sample, given sample 0's colour. (With one sample per pixel there is
// nothing to add: the loop runs no pass.)
vec3 add_other_samples(ivec2 pixel, vec3 sample0_colour)
{
    int samples = gbuffer_sample_count();
    vec3 mean = sample0_colour;
    for (int s = 1; s < samples; ++s) {
        mean = add_sample_to_mean(mean, shade_sample(pixel, s), s);
    }
    return mean;
}

// Whether `pixel` needs its other samples shaded (MSAA_EDGE): the dynamic pass compares the
// samples' stored values (the plain G-buffer has no flags); a tile pass asks the coverage
// flags, which say "equal" only for samples of one fragment; the naive pass shades every sample of
// every pixel. Skipping equal samples changes nothing (add_sample_to_mean()).
bool pixel_needs_other_samples(ivec2 pixel)
{
    if (PER_PIXEL_BRANCHES) {
        return gbuffer_pixel_samples_differ(pixel);
    }
#ifndef GBUFFER_SINGLE_SAMPLED
    if (TAGGED_GBUFFER) {
        return gbuffer_flags_say_samples_may_differ(pixel);
    }
#endif
    return true;
}

#ifdef FLOOR_PASS
// FLOOR_PASS builds tilelight's "floor" baseline instead: what any full-frame light pass costs
// at least. It reads what the naive pass reads (every sample of every pixel, every target,
// through gbuffer_load()) and lights nothing: the pixel is the mean of its samples' prelit
// colours. Every other field feeds a select that no stored G-buffer takes (depths lie in 0..1),
// so the compiler cannot prove it dead and must keep each fetch, as the naive pass does.
vec3 floor_sample(GSample g)
{
    bool impossible = g.depth > 2.0;
    vec3 rest = g.albedo + g.normal + vec3(g.spec_amount + g.spec_power + float(g.motion_id));
    return impossible ? rest : g.prelit;
}

vec3 shade_pixel(ivec2 pixel)
{
    int samples = gbuffer_sample_count();
    vec3 sum = vec3(0.0);
    for (int s = 0; s < samples; ++s) {
        sum += floor_sample(gbuffer_load(pixel, s));
    }
    return sum / float(samples);
}
#else
// The lit colour of `pixel`: sample 0 shaded, and with MSAA_EDGE every other sample averaged in
// where the pixel's samples may differ.
vec3 shade_pixel(ivec2 pixel)
{
    vec3 colour = shade_sample(pixel, 0);
#ifdef MSAA_EDGE
    if (pixel_needs_other_samples(pixel)) {
        colour = add_other_samples(pixel, colour);
    }
#endif
    return colour;
}
#endif // FLOOR_PASS

#endif // UBER_LIGHT_PASS_GLSL
