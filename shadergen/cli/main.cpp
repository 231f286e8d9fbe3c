// The shadergen executable: everything lives in the library so that tests can drive the CLI.
#include "shadergen/cli.h"

int main(int argc, char** argv) { return shadergen::run_cli(argc, argv); }
