// feature_reads.h - the checks that a domain's shaders read each feature the way its kind allows.
//
// Two mistakes compile without a word otherwise: a feature whose define no shader reads (a
// misspelt "define": the feature silently does nothing), and a preprocessor conditional on a
// specialization or branch feature (`#ifdef FOG` is never true: FOG is a constant or a uniform,
// not a macro, so the code it guards silently disappears), or `#ifdef`, `#ifndef` or `defined()`
// on a value-style boolean variant (defined in every permutation, so the test never changes).
#pragma once

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

// Scans the permuted shaders (the uber-shader, the program's vertex half) and their includes.
// Errors, in this order and each once per feature:
//   SPEC:LINE:COL: error: feature FOG: no source of its permutations reads its define HAS_FOGG;
//                         did you mean HAS_FOG?            (unless the feature says "unread": "allowed")
//   FILE:LINE: error: feature FOG (define FOG) is a specialization constant; #ifdef cannot test
//                     it: read it as an expression, e.g. if (FOG)
//   FILE:LINE: error: feature ALPHA (define ALPHA_TEST) is a value-style boolean, defined in every
//                     permutation as (1 == 1) or (0 == 1); #ifdef is always true: test its value,
//                     e.g. #if ALPHA_TEST or if (ALPHA_TEST)
Status check_feature_reads(const DomainSpec& spec);

}  // namespace shadergen
