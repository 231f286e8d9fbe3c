// A spec-area file that reaches up into the output area: include_layers.cmake must refuse it.
#include "output/manifest_writer.h"
