#pragma once
// The tests' way to a Context's validation log, which is private: Context befriends this class
// and only the test-support library defines it. The product itself only asks
// Context::require_no_validation_messages().

#include "tilelight/vulkan/context.h"

#include <memory>

namespace tilelight {

class ContextTestSeam {
 public:
  // Every warning and error the layer reported (always empty when validation is off).
  static ValidationLog& validation_log(const Context& context);
  // The same log, kept alive past the context: messages emitted while it is destroyed (leaked
  // objects) can still be checked.
  static std::shared_ptr<const ValidationLog> shared_validation_log(const Context& context);
};

}  // namespace tilelight
