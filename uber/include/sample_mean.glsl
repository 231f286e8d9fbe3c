// sample_mean.glsl -- the running mean of a pixel's samples, shared by every pass that averages
// samples (the global light pass, the local-light passes) so that they all round alike.

#ifndef UBER_SAMPLE_MEAN_GLSL
#define UBER_SAMPLE_MEAN_GLSL

// One step of the running mean of a pixel's samples: `mean` of samples 0 .. s - 1, and sample
// s's colour. A component equal to the mean so far is kept as it is (a select, no arithmetic),
// so a pixel whose samples all shade alike averages to exactly its sample-0 colour for any
// sample count, Inf included; a plain sum would not (v + v + v rounds, Inf - Inf is NaN). That
// is what lets a pixel whose samples are equal shade sample 0 alone. Every pass that averages
// samples goes through here, in sample order, so they round alike.
vec3 add_sample_to_mean(vec3 mean, vec3 colour, int s)
{
    return mix(mean + (colour - mean) / float(s + 1), mean, equal(colour, mean));
}

#endif // UBER_SAMPLE_MEAN_GLSL
