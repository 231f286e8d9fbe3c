// alpha_mask.glsl -- glTF's alphaMode MASK: a texel is drawn where the base colour's alpha
// (texture alpha times factor alpha) is at least the material's cutoff, and discarded where it is
// below. One function, so the G-buffer (plain and classified alike) and the sun shadow map cut
// the same holes.
#ifndef UBER_ALPHA_MASK_GLSL
#define UBER_ALPHA_MASK_GLSL

// `mask`: x the base colour factor's alpha, y the cutoff (scene.vert's out_alpha_mask).
bool alpha_mask_discards(float texture_alpha, vec2 mask)
{
    return texture_alpha * mask.x < mask.y;
}

#endif // UBER_ALPHA_MASK_GLSL
