// program_check.h - the interface between the two halves of a "program" permutation: what
// the fragment shader reads must be what the vertex shader writes.
#pragma once

#include <string>
#include <vector>

#include "compile/reflection.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

// One problem per fragment input that no vertex output at its location feeds with at least as
// many components (Vulkan lets an output carry more than the input reads), each naming the
// location, the variable and both widths; the caller says which permutations have it.
struct InterfaceProblem {
  std::string message;
  std::string input;  // the fragment input's name, to find its declaration
};
std::vector<InterfaceProblem> interface_problems(const std::vector<VariableInfo>& vertex_outputs,
                                                 const std::vector<VariableInfo>& fragment_inputs);

}  // namespace shadergen
