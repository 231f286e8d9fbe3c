// A base-area file that reaches up into the cache area through an angle-bracket include:
// include_layers.cmake must refuse it. Another library's header (<vector>, <curl/curl.h>) is not
// checked.
#include <curl/curl.h>
#include <vector>

#include <cache/entry_writer.h>
