#include "tilelight_testing/context_test_seam.h"

namespace tilelight {

ValidationLog& ContextTestSeam::validation_log(const Context& context) { return context.validation_log(); }

std::shared_ptr<const ValidationLog> ContextTestSeam::shared_validation_log(const Context& context) {
  return context.shared_validation_log();
}

}  // namespace tilelight
