#pragma once
// The tilelight app's flow, one step after another: build the scene, create the Vulkan
// context and the renderer, render the warm-up and timed frames, read them back, compare them
// and write the PNGs and report.json (or list the cameras or devices and stop).

#include "arguments.h"

#include <ostream>
#include <string>

namespace tilelight::app {

// Returns the exit code (0). Throws tilelight::Error (OptionError for a bad flag value) or
// anything the libraries throw; `stage` always says what the run is doing, for the message.
// Warnings (the loaded scene's) go to `err`, one "warning: " line each.
int render_run(const Arguments& arguments, std::ostream& out, std::ostream& err, std::string& stage);

}  // namespace tilelight::app
