// tilelight_make_hall: writes the generated interior of bench/scenes/hall_scene.h as a .glb, for
// measuring a big scene from inside (docs/results.md, section m). Prints the triangle count and
// a camera placed inside, as tilelight options.
//
//   tilelight_make_hall --out hall.glb [--bays 24] [--column-segments 96] [--column-rings 128]

#include "scenes/hall_glb.h"
#include "scenes/hall_scene.h"

#include "tilelight/base/atomic_write.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

namespace {

int run(int argc, char** argv) {
  using namespace tilelight;
  CLI::App app{
      "tilelight_make_hall: writes a generated stone hall (columns, arches, walls with windows, a\n"
      "skylight, benches; one mesh per part of each bay) as a binary glTF file, for measuring big\n"
      "scenes from inside with tilelight --scene FILE --eye ... --target ..."};
  std::string out;
  bench::HallOptions options;
  app.add_option("--out", out, "the .glb file to write")->required();
  app.add_option("--bays", options.bays, "bays of 5 m along the nave, two columns each")
      ->capture_default_str()
      ->check(CLI::Range(1u, 400u));
  app.add_option("--column-segments", options.column_segments, "quads around each column")
      ->capture_default_str()
      ->check(CLI::Range(8u, 4096u));
  app.add_option("--column-rings", options.column_rings, "quads up each column")
      ->capture_default_str()
      ->check(CLI::Range(4u, 4096u));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  const bench::HallScene hall = bench::make_hall(options);
  const std::vector<std::uint8_t> glb = bench::encode_hall_glb(hall);
  write_file_atomically(out, glb);
  const auto v = [](glm::vec3 p) { return fmt::format("{:g},{:g},{:g}", p.x, p.y, p.z); };
  std::cout << fmt::format("{}: {} triangles in {} meshes, {:.1f} MB\n", out, hall.triangle_count(), hall.meshes.size(),
                           static_cast<double>(glb.size()) / 1e6)
            << fmt::format("a view from inside: --eye {} --target {}\n", v(hall.suggested_eye),
                           v(hall.suggested_target));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "tilelight_make_hall: error: " << e.what() << '\n';
    return 1;
  }
}
