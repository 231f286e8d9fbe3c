// The soak: tilelight renders 500 frames at a small size with the validation layer on. The layer
// must report nothing (tilelight fails the run on any message), and the process's peak resident
// set size must not grow with the frame count: it is compared with a 50-frame run's.
//
// The tolerance is 8 MiB over 450 extra frames, so any leak of about 18 KiB or more per frame
// fails: one read-back image at this size (128x72 RGBA32F, 144 KiB), a command buffer, a
// descriptor set or the tile index vectors left behind each frame would all be caught. Below
// that, allocator and driver noise dominates (50 vs 500 frames differ by about 3 MiB with the
// layer on, most of it the layer's own bookkeeping); smaller leaks are LeakSanitizer's job.
#include "child_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;

constexpr double kToleranceMiB = 8.0;

struct SoakRun {
  double peak_rss_mib = 0;
  bool ok = false;
};

SoakRun run_frames(unsigned frames) {
  const fs::path out = fs::path(TILELIGHT_TEST_SCRATCH) / ("frames" + std::to_string(frames));
  fs::remove_all(out);
  testsupport::Child child(TILELIGHT_EXECUTABLE, {"--width", "128", "--height", "72", "--frames",
                                                  std::to_string(frames), "--validation", "--out", out.string()});
  const testsupport::ChildOutcome r = child.wait();
  SoakRun run;
  EXPECT_EQ(r.exit_code, 0) << frames << " frames:\n" << r.err;
  EXPECT_EQ(r.err, "") << frames << " frames: nothing on stderr, validation messages included";
  std::ifstream file(out / "report.json");
  if (r.exit_code != 0 || !file) return run;
  const nlohmann::json report = nlohmann::json::parse(file);
  EXPECT_EQ(report["frames"], frames);
  run.peak_rss_mib = report["process"]["peak_rss_mib"].get<double>();
  EXPECT_GT(run.peak_rss_mib, 0.0);
  run.ok = true;
  return run;
}

TEST(Soak, FiveHundredValidatedFramesPeakAtTheSameMemoryAsFifty) {
  const SoakRun short_run = run_frames(50);
  const SoakRun long_run = run_frames(500);
  ASSERT_TRUE(short_run.ok && long_run.ok);
  std::cout << "peak RSS: 50 frames " << short_run.peak_rss_mib << " MiB, 500 frames " << long_run.peak_rss_mib
            << " MiB\n";
  RecordProperty("peak_rss_mib_50_frames", std::to_string(short_run.peak_rss_mib));
  RecordProperty("peak_rss_mib_500_frames", std::to_string(long_run.peak_rss_mib));
  EXPECT_LE(long_run.peak_rss_mib, short_run.peak_rss_mib + kToleranceMiB)
      << "peak memory grew by " << long_run.peak_rss_mib - short_run.peak_rss_mib << " MiB over 450 frames";
}

}  // namespace
