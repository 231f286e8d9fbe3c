// tile_classes.glsl -- per-pixel classification flags and their reduction to a raw tile ID.
//
// The classifier ORs these flags over every pixel (every sample of an MSAA-edge pixel) of a
// tile, then turns the result into the 7-bit raw ID. The raw bit values are specialization
// constants set by the runtime from the generated registry (split_second::raw_bit), so the
// bit layout lives in exactly one place: permutations/split_second.json.

#ifndef UBER_TILE_CLASSES_GLSL
#define UBER_TILE_CLASSES_GLSL

layout(constant_id = 1) const uint RAW_BIT_SHADOW_SOLID = 1u;
layout(constant_id = 2) const uint RAW_BIT_SHADOW_SOFT = 2u;
layout(constant_id = 3) const uint RAW_BIT_SHADOW_FADE = 4u;
layout(constant_id = 4) const uint RAW_BIT_LIGHT_SCATTERING = 8u;
layout(constant_id = 5) const uint RAW_BIT_MSAA_EDGE = 16u;
layout(constant_id = 6) const uint RAW_BIT_SKY = 32u;
layout(constant_id = 7) const uint RAW_BIT_SUN_LIGHT = 64u;

const uint TILE_FLAG_FADE       = 0x01u; // a geometry sample beyond the shadow-fade start
const uint TILE_FLAG_SCATTERING = 0x02u; // a geometry sample beyond the scattering start
const uint TILE_FLAG_EDGE       = 0x04u; // a pixel whose samples differ
const uint TILE_FLAG_SKY        = 0x08u; // a sky sample
const uint TILE_FLAG_SUN        = 0x10u; // a geometry sample facing the sun
const uint TILE_FLAG_SHADOWED   = 0x20u; // a sun-facing sample with 0 of 8 taps lit
const uint TILE_FLAG_LIT        = 0x40u; // a sun-facing sample with 8 of 8 taps lit
const uint TILE_FLAG_PARTIAL    = 0x80u; // a sun-facing sample with 1..7 taps lit

// Shadow type over the sun-facing samples only: sky and samples facing away from the sun have
// a sun term of exactly zero in every permutation, so their shadow does not matter.
uint raw_id_from_tile_flags(uint flags)
{
    bool shadowed = (flags & TILE_FLAG_SHADOWED) != 0u;
    bool lit = (flags & TILE_FLAG_LIT) != 0u;
    bool partial = (flags & TILE_FLAG_PARTIAL) != 0u;
    uint raw = 0u;
    if (shadowed && !lit && !partial) raw |= RAW_BIT_SHADOW_SOLID;
    if (partial || (shadowed && lit)) raw |= RAW_BIT_SHADOW_SOFT;
    if ((flags & TILE_FLAG_FADE) != 0u) raw |= RAW_BIT_SHADOW_FADE;
    if ((flags & TILE_FLAG_SCATTERING) != 0u) raw |= RAW_BIT_LIGHT_SCATTERING;
    if ((flags & TILE_FLAG_EDGE) != 0u) raw |= RAW_BIT_MSAA_EDGE;
    if ((flags & TILE_FLAG_SKY) != 0u) raw |= RAW_BIT_SKY;
    if ((flags & TILE_FLAG_SUN) != 0u) raw |= RAW_BIT_SUN_LIGHT;
    return raw;
}

#endif // UBER_TILE_CLASSES_GLSL
