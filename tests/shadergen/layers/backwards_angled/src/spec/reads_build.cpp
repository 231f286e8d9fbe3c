// A spec-area file that includes the driver's public header in angle brackets:
// include_layers.cmake must refuse it too.
#include <shadergen/build.h>
