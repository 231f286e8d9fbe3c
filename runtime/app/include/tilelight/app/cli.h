#pragma once
// The `tilelight` command line, as a library so tests can run it in-process.

#include <ostream>

namespace tilelight::app {

// Parses the arguments, renders, writes DIR/frame_classified.png, DIR/frame_naive.png,
// DIR/frame_dynamic.png and DIR/frame_floor.png (for the baselines that ran),
// DIR/tile_classes.png and DIR/report.json
// (see output_files.h for how they replace earlier results) and prints the timing table.
// Returns 0 on success, 1 on a runtime error (message on `err`), 2 on a usage error.
int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace tilelight::app
