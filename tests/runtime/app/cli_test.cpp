// The tilelight command line, run in-process: its files, its report and its errors.
#include "tilelight/app/cli.h"
#include "frame_support.h"
#include "tilelight_testing/test_support.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight::test {
namespace {

namespace fs = std::filesystem;

const char* const kOutputs[] = {"frame_classified.png", "frame_naive.png", "frame_dynamic.png", "tile_classes.png",
                                "report.json"};

nlohmann::json read_report(const fs::path& out) {
  std::ifstream file(out / "report.json");
  return nlohmann::json::parse(file);
}

TEST(TilelightCli, WritesTheFiveFilesAndTheReportFields) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli({"--width", "200", "--height", "120", "--frames", "2", "--light-pass", "raster",
                               "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : kOutputs) EXPECT_TRUE(fs::exists(out / name)) << name;
  EXPECT_NE(r.out.find("global light"), std::string::npos) << r.out;

  std::ifstream file(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(file);
  EXPECT_EQ(report["width"], 200);
  EXPECT_EQ(report["height"], 120);
  EXPECT_EQ(report["msaa_samples"], 4);  // lavapipe offers 1x and 4x only
  EXPECT_EQ(report["tiles"], 50 * 30);
  for (const char* p :
       {"SKY", "SUN_LIGHT", "SOLID_SHADOW", "SOFT_SHADOW", "SHADOW_FADE", "LIGHT_SCATTERING", "MSAA_EDGE"}) {
    ASSERT_TRUE(report["raw_property_tiles"].contains(p)) << p;
    // At 200x120 no tile lies wholly inside one shadow (Classification.DefaultCameraHasAllSevenProperties).
    if (std::string_view(p) != "SOLID_SHADOW") {
      EXPECT_GT(report["raw_property_tiles"][p].get<int>(), 0) << p;
    }
  }
  ASSERT_EQ(report["optimised_tiles"].size(), 32u);
  int sum = 0;
  for (const auto& n : report["optimised_tiles"]) sum += n.get<int>();
  EXPECT_EQ(sum, 50 * 30);
  EXPECT_EQ(report["primitives"]["uncoalesced"], 50 * 30);
  EXPECT_LT(report["primitives"]["coalesced"].get<int>(), 50 * 30);
  // auto is points on lavapipe: a non-square rectangle is drawn as a point per tile.
  EXPECT_EQ(report["primitive"], "points");
  const int coalesced = report["primitives"]["coalesced"].get<int>();
  const int rectangles = report["primitives"]["rectangles"].get<int>();
  EXPECT_GE(coalesced, rectangles);
  EXPECT_NE(r.out.find(fmt::format("tiles 1500, points 1500 -> {} coalesced ({} rectangles);", coalesced, rectangles)),
            std::string::npos)
      << r.out;
  for (const char* t :
       {"gbuffer", "shadow_map", "classification", "index_build_cpu", "tiled_light", "naive_light", "dynamic_light"}) {
    ASSERT_TRUE(report["timings_ms"].contains(t)) << t;
    EXPECT_GE(report["timings_ms"][t].get<double>(), 0.0) << t;
    // One figure per timed frame; with two frames the median is their mean.
    const auto& frames = report["frame_timings_ms"][t];
    ASSERT_EQ(frames.size(), 2u) << t;
    EXPECT_NEAR(report["timings_ms"][t].get<double>(), (frames[0].get<double>() + frames[1].get<double>()) / 2, 0.002)
        << t;
  }
  EXPECT_GT(report["timings_ms"]["dynamic_light"].get<double>(), 0.0);
  EXPECT_EQ(report["baselines"], "both");
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
  EXPECT_EQ(report["equivalence"]["reference"], "naive");
  EXPECT_EQ(report["dynamic_equivalence"]["pixels_different"], 0);
  for (const char* column : {"naive", "dynamic", "classified"}) {
    EXPECT_NE(r.out.find(column), std::string::npos) << r.out;
  }
  for (const char* line :
       {"whole frame vs dynamic (per-pixel branching): ", "whole frame vs naive (every feature on every sample): ",
        "light path vs dynamic (per-pixel branching): ", "light path vs naive (every feature on every sample): ",
        "G-buffer, plain (baselines)", "G-buffer, classified"}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " in\n" << r.out;
  }
  // The table leads with the whole frame, then its stages.
  EXPECT_LT(r.out.find("\nwhole frame "), r.out.find("\nshadow map ")) << r.out;
  EXPECT_NE(r.out.find("; dynamic vs naive: 0 differ (max 0)"), std::string::npos) << r.out;
  // Nothing temporary left beside the results.
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

// No MSAA: a single-sampled G-buffer read by the split_second_1x shaders, validation clean, the
// same frame from every method and no tile with the MSAA_EDGE property.
TEST(TilelightCli, NoMsaaRendersSingleSampledAndEqual) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli(
      {"--width", "200", "--height", "120", "--msaa", "1", "--path", "gpu", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["msaa_samples"], 1);
  EXPECT_EQ(report["raw_property_tiles"]["MSAA_EDGE"], 0);
  EXPECT_GT(report["raw_property_tiles"]["SUN_LIGHT"].get<int>(), 0);
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
  EXPECT_EQ(report["dynamic_equivalence"]["pixels_different"], 0);
  EXPECT_NE(r.out.find("200x120, 1x MSAA"), std::string::npos) << r.out;
}

// --baseline chooses the full-screen passes: one alone writes only its own frame and times only
// its own column; the classified frame is compared with whichever ran.
TEST(TilelightCli, BaselineChoosesThePassesTimed) {
  const fs::path naive_out = scratch_dir() / "naive";
  const CliResult naive =
      run_cli({"--width", "96", "--height", "64", "--baseline", "naive", "--out", naive_out.string()});
  ASSERT_EQ(naive.exit_code, 0) << naive.err;
  const nlohmann::json naive_report = read_report(naive_out);
  EXPECT_EQ(naive_report["baselines"], "naive");
  EXPECT_EQ(naive_report["timings_ms"]["dynamic_light"], 0.0);
  EXPECT_GT(naive_report["timings_ms"]["naive_light"].get<double>(), 0.0);
  EXPECT_TRUE(naive_report["dynamic_equivalence"].is_null());
  EXPECT_EQ(naive_report["equivalence"]["reference"], "naive");
  EXPECT_TRUE(fs::exists(naive_out / "frame_naive.png"));
  EXPECT_FALSE(fs::exists(naive_out / "frame_dynamic.png"));
  EXPECT_EQ(naive.out.find("vs dynamic"), std::string::npos) << naive.out;

  const fs::path dynamic_out = scratch_dir() / "dynamic";
  const CliResult dynamic =
      run_cli({"--width", "96", "--height", "64", "--baseline", "dynamic", "--out", dynamic_out.string()});
  ASSERT_EQ(dynamic.exit_code, 0) << dynamic.err;
  const nlohmann::json dynamic_report = read_report(dynamic_out);
  EXPECT_EQ(dynamic_report["timings_ms"]["naive_light"], 0.0);
  EXPECT_GT(dynamic_report["timings_ms"]["dynamic_light"].get<double>(), 0.0);
  EXPECT_EQ(dynamic_report["equivalence"]["reference"], "dynamic");
  EXPECT_EQ(dynamic_report["equivalence"]["pixels_different"], 0);
  EXPECT_FALSE(fs::exists(dynamic_out / "frame_naive.png"));
  EXPECT_TRUE(fs::exists(dynamic_out / "frame_dynamic.png"));
  EXPECT_NE(dynamic.out.find("classified vs dynamic: 0 pixels differ"), std::string::npos) << dynamic.out;

  // Into the folder of the naive run: its frame_naive.png, from another run, goes.
  ASSERT_EQ(
      run_cli({"--width", "96", "--height", "64", "--baseline", "dynamic", "--out", naive_out.string()}).exit_code, 0);
  EXPECT_FALSE(fs::exists(naive_out / "frame_naive.png"));
  EXPECT_TRUE(fs::exists(naive_out / "frame_dynamic.png"));

  EXPECT_EQ(run_cli({"--baseline", "fastest", "--out", (scratch_dir() / "bad").string()}).exit_code, 2);
}

// Forced triangles: each rectangle is one primitive (a pair of triangles), so the report's
// primitive count is its rectangle count.
TEST(TilelightCli, TrianglesReportOnePrimitivePerRectangle) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r = run_cli({"--width", "200", "--height", "120", "--light-pass", "raster", "--primitive",
                               "triangles", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream file(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(file);
  EXPECT_EQ(report["primitive"], "triangles");
  const int coalesced = report["primitives"]["coalesced"].get<int>();
  const int rectangles = report["primitives"]["rectangles"].get<int>();
  EXPECT_EQ(coalesced, rectangles);
  EXPECT_LT(rectangles, 50 * 30) << "nothing was coalesced";
  EXPECT_NE(
      r.out.find(fmt::format("tiles 1500, triangles 1500 -> {} coalesced ({} rectangles);", coalesced, rectangles)),
      std::string::npos)
      << r.out;
}

// The README's contract: 2 on any usage error, whatever kind of parse error CLI11 raised; --help
// is not an error.
// --light-pass compute (the default): the tile pass dispatches each class over its tile list,
// the baselines are full-frame dispatches; the report and the console say so, and the frames
// still agree.
TEST(TilelightCli, ComputeLightPassReportsItsKindAndAgrees) {
  const fs::path out = scratch_dir() / "out";
  const CliResult r =
      run_cli({"--width", "200", "--height", "120", "--path", "gpu", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["light_pass"], "compute");
  EXPECT_EQ(report["primitive"], "workgroups");
  EXPECT_EQ(report["primitives"]["uncoalesced"], 50 * 30);
  EXPECT_EQ(report["primitives"]["rectangles"], 0);
  EXPECT_EQ(report["equivalence"]["pixels_different"], 0);
  EXPECT_EQ(report["dynamic_equivalence"]["pixels_different"], 0);
  EXPECT_NE(r.out.find("compute light pass, path gpu"), std::string::npos) << r.out;
  EXPECT_NE(
      r.out.find(fmt::format("tiles 1500, dispatched in {} workgroups", report["primitives"]["coalesced"].get<int>())),
      std::string::npos)
      << r.out;
  ASSERT_EQ(run_cli({"--width", "64", "--height", "48", "--light-pass", "raster", "--out", out.string()}).exit_code, 0);
  EXPECT_EQ(read_report(out)["light_pass"], "raster");
}

TEST(TilelightCli, UsageErrorsExitTwoAndHelpExitsZero) {
  const fs::path out = scratch_dir() / "out";
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{{"--no-such-option"},
                                                                                    {"--frames", "abc"},
                                                                                    {"--frames", "0"},
                                                                                    {"--width"},
                                                                                    {"--path", "fpga"},
                                                                                    {"--msaa", "3"},
                                                                                    {"--baseline", "x"},
                                                                                    {"--light-pass", "mesh"},
                                                                                    {"--permutations", "all"}}) {
    std::vector<std::string> with_out = args;
    with_out.insert(with_out.end(), {"--out", out.string()});
    const CliResult r = run_cli(with_out);
    EXPECT_EQ(r.exit_code, 2) << args.front() << ": " << r.err;
    EXPECT_NE(r.err.find("Run with --help for more information."), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
  const CliResult help = run_cli({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--primitive"), std::string::npos) << help.out;
}

// Like --path, --primitive takes one of a fixed set: anything else is a usage error, reported
// before anything is rendered.
TEST(TilelightCli, UnknownPrimitiveIsAUsageError) {
  const fs::path out = scratch_dir() / "out";
  const CliResult primitive = run_cli({"--primitive", "bogus", "--out", out.string()});
  const CliResult path = run_cli({"--path", "fpga", "--out", out.string()});
  EXPECT_EQ(primitive.exit_code, 2);  // README: 2 on a usage error
  EXPECT_EQ(path.exit_code, 2);
  EXPECT_EQ(primitive.err,
            "--primitive: bogus not in {auto,points,triangles}\nRun with --help for more information.\n");
  EXPECT_EQ(primitive.out, "");
  EXPECT_FALSE(fs::exists(out));
}

// The flags parsed to the renderer's values say which value was refused, in the words
// CLI::IsMember uses for the others, before anything is rendered.
TEST(TilelightCli, UnknownChoiceNamesTheFlagAndTheChoices) {
  const fs::path out = scratch_dir() / "out";
  const std::pair<std::vector<std::string>, const char*> cases[] = {
      {{"--baseline", "x"}, "--baseline: x not in {none,naive,dynamic,both,floor,all}"},
      {{"--light-pass", "mesh"}, "--light-pass: mesh not in {raster,compute}"},
      {{"--path", "fpga"}, "--path: fpga not in {cpu,gpu}"},
      {{"--permutations", "all"}, "--permutations: all not in {optimised,raw}"},
      {{"--msaa", "3"}, "--msaa: 3 not in {auto,1,2,4,8,16}"}};
  for (const auto& [args, message] : cases) {
    std::vector<std::string> with_out = args;
    with_out.insert(with_out.end(), {"--out", out.string()});
    const CliResult r = run_cli(with_out);
    EXPECT_EQ(r.exit_code, 2) << message;
    EXPECT_EQ(r.err, std::string(message) + "\nRun with --help for more information.\n");
  }
  EXPECT_FALSE(fs::exists(out));
}

struct BadInput {
  const char* name;
  std::vector<std::string> args;
  const char* message;
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

class TilelightBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(TilelightBadInput, FailsWithAClearMessageAndWritesNothing) {
  const fs::path out = scratch_dir() / "out";
  std::vector<std::string> args = GetParam().args;
  args.push_back("--out");
  args.push_back(out.string());
  const CliResult r = run_cli(args);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(GetParam().message), std::string::npos) << r.err;
  if (fs::exists(out)) {
    EXPECT_TRUE(fs::is_empty(out)) << "partial output left in " << out;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TilelightBadInput,
    ::testing::Values(
        BadInput{"zero_width", {"--width", "0"}, "--width 0: the frame must be at least 1 pixel"},
        BadInput{"huge_height", {"--height", "999999"}, "--height 999999: exceeds the maximum"},
        BadInput{"msaa_lavapipe_lacks",
                 {"--msaa", "2"},
                 "--msaa 2: MSAA 2x is not supported by this device (supported for the G-buffer: 1x, 4x)"},
        BadInput{"msaa_not_a_count", {"--msaa", "3"}, "--msaa: 3 not in {auto,1,2,4,8,16}"},
        BadInput{"unknown_device", {"--device", "no-such-gpu"}, "no-such-gpu"},
        BadInput{"unknown_camera", {"--camera", "moon"}, "--camera moon: unknown camera (known: default, sky"},
        BadInput{"bad_path", {"--path", "fpga"}, "--path"},
        BadInput{"bad_primitive", {"--primitive", "bogus"}, "--primitive: bogus not in {auto,points,triangles}"},
        BadInput{"bad_tile_size", {"--tile-size", "5"}, "--tile-size: 5 not in {4,8,16}"},
        BadInput{"bad_light_pass", {"--light-pass", "mesh"}, "--light-pass: mesh not in {raster,compute}"},
        BadInput{"bad_permutations", {"--permutations", "all"}, "--permutations: all not in {optimised,raw}"},
        BadInput{"bad_baseline", {"--baseline", "x"}, "--baseline: x not in {none,naive,dynamic,both,floor,all}"}),
    [](const ::testing::TestParamInfo<BadInput>& param_info) { return std::string(param_info.param.name); });

TEST(TilelightCli, UnwritableOutFolderIsNamed) {
  const fs::path blocker = scratch_dir() / "a-file";
  std::ofstream(blocker) << "not a folder";
  const CliResult r = run_cli({"--width", "16", "--height", "16", "--out", (blocker / "out").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--out " + (blocker / "out").string()), std::string::npos) << r.err;
}

TEST(TilelightCli, FailedRunKeepsEarlierResults) {
  const fs::path out = scratch_dir() / "out";
  ASSERT_EQ(run_cli({"--width", "64", "--height", "48", "--out", out.string()}).exit_code, 0);
  std::ifstream before_file(out / "report.json");
  const std::string before((std::istreambuf_iterator<char>(before_file)), {});
  EXPECT_NE(run_cli({"--width", "64", "--height", "48", "--camera", "moon", "--out", out.string()}).exit_code, 0);
  std::ifstream after_file(out / "report.json");
  const std::string after((std::istreambuf_iterator<char>(after_file)), {});
  EXPECT_EQ(before, after);
}

}  // namespace
}  // namespace tilelight::test
