#include "program_check.h"

#include <algorithm>

namespace shadergen {

Diagnostics check_interface(const std::string& label, const std::vector<VariableInfo>& vertex_outputs,
                            const std::vector<VariableInfo>& fragment_inputs) {
  Diagnostics errors;
  for (const VariableInfo& input : fragment_inputs) {
    auto output = std::find_if(vertex_outputs.begin(), vertex_outputs.end(),
                               [&](const VariableInfo& v) { return v.location == input.location; });
    std::string what = label + ": the fragment shader reads location " + std::to_string(input.location) + " (\"" +
                       input.name + "\", " + std::to_string(input.components) + " components)";
    if (output == vertex_outputs.end())
      errors.push_back(make_error(what + ", which the vertex shader does not write"));
    else if (output->components < input.components)
      errors.push_back(make_error(what + ", which the vertex shader writes with " + std::to_string(output->components) +
                                  " (\"" + output->name + "\")"));
  }
  return errors;
}

}  // namespace shadergen
