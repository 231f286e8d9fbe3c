// Checks that the generated registry links and holds what the manifest promises.
#include <consumer_shaders.h>

#include <cstdio>

int main() {
  const shadergen::Registry& registry = game::shaders::registry();
  if (registry.raw.size() != game::shaders::kRawCount) return 1;
  if (registry.optimised.size() != game::shaders::kOptimisedCount) return 2;
  for (const shadergen::Permutation& p : registry.raw) {
    if (p.pruned != game::shaders::kRawPruned[p.id]) return 3;
    if (!p.pruned && (p.spirv.empty() || p.spirv[0] != 0x07230203u)) return 4;
    if (registry.raw_to_optimised[p.id] != game::shaders::kRawToOptimised[p.id]) return 5;
  }
  std::printf("consumer: %s: %zu raw, %zu optimised permutations\n", registry.name.data(), registry.raw.size(),
              registry.optimised.size());
  return 0;
}
