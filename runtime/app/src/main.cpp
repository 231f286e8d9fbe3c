// tilelight: thin entry point; the command line lives in the tilelight_app library.
#include "tilelight/app/cli.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>

namespace {

// run() reports every exception itself; this is for the ones it cannot see (one escaping a
// destructor or a noexcept function, or a driver thread), so nothing ends without a word.
[[noreturn]] void on_terminate() {
  std::fputs("tilelight: fatal error: std::terminate was called (an exception escaped where none may)\n", stderr);
  std::abort();
}

}  // namespace

int main(int argc, char** argv) {
  std::set_terminate(on_terminate);
  return tilelight::app::run(argc, argv, std::cout, std::cerr);
}
