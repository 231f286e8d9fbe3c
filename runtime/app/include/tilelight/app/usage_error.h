#pragma once
// A command line whose flags parse but do not fit together or with the scene (--camera street
// with --scene, --eye equal to --target, gltf:7 in a file of two cameras): exit 2 like a parse
// error, in CLI11's words ("--flag: message", then "Run with --help for more information.").

#include "tilelight/base/error.h"

namespace tilelight::app {

class UsageError : public OptionError {
 public:
  using OptionError::OptionError;
};

}  // namespace tilelight::app
