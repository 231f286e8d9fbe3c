// A spec-area file that reaches up into the build area: include_layers.cmake must refuse it.
#include "build/orchestrate.h"
