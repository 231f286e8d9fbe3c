#include "compile/program_check.h"

#include <algorithm>

namespace shadergen {

std::vector<InterfaceProblem> interface_problems(const std::vector<VariableInfo>& vertex_outputs,
                                                 const std::vector<VariableInfo>& fragment_inputs) {
  std::vector<InterfaceProblem> errors;
  for (const VariableInfo& input : fragment_inputs) {
    auto output = std::find_if(vertex_outputs.begin(), vertex_outputs.end(),
                               [&](const VariableInfo& v) { return v.location == input.location; });
    std::string what = "the fragment shader reads location " + std::to_string(input.location) + " (\"" + input.name +
                       "\", " + std::to_string(input.components) + " components)";
    if (output == vertex_outputs.end())
      errors.push_back({what + ", which the vertex shader does not write", input.name});
    else if (output->components < input.components)
      errors.push_back({what + ", which the vertex shader writes with " + std::to_string(output->components) + " (\"" +
                            output->name + "\")",
                        input.name});
  }
  return errors;
}

}  // namespace shadergen
