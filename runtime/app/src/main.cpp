// tilelight: thin entry point; the command line lives in the tilelight_app library.
#include "tilelight_app/cli.h"

#include <iostream>

int main(int argc, char** argv) { return tilelight::app::run(argc, argv, std::cout, std::cerr); }
