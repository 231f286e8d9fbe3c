// The tile pass is submitted before the host signals it. A failure in between must not leave
// the queue blocked: the renderer empties the draws, signals, waits, then reports the error.
#include "tilelight/base/error.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/error.h"
#include "tilelight_testing/context_test_seam.h"
#include "tilelight_testing/renderer_test_seam.h"
#include "tilelight_testing/test_support.h"

namespace tilelight::test {
namespace {

class FrameFailure : public VulkanTest {};

TEST_F(FrameFailure, ErrorBeforeTheHostSignalStillReleasesTheGpu) {
  const Scene scene = make_demo_scene();
  RendererOptions options;
  options.light_pass = LightPass::raster;
  options.width = 96;
  options.height = 64;
  options.timeout = Seconds(20);
  TileRenderer renderer(context(), scene, options);
  TileRendererTestSeam::set_before_host_signal(renderer, [] { throw Error("injected failure in the index build"); });
  try {
    renderer.render_frame();
    FAIL() << "render_frame() did not report the injected failure";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "injected failure in the index build");
  }
  // The queue is free again: this would time out if the tile pass were still waiting.
  EXPECT_NO_THROW(context().wait_idle("after the injected failure", Seconds(20)));
  // And the renderer still works.
  TileRendererTestSeam::set_before_host_signal(renderer, {});
  EXPECT_NO_THROW(renderer.render_frame());
}

// The fault: a GPU slower than the renderer's timeout, so the host's wait for classification
// itself times out while submit A's signal is still pending. Releasing the tile pass must first
// let that signal land (a host signal below a pending one is invalid: the validation layer
// checks it, and VulkanTest fails on any message), then signal, then drain.
TEST_F(FrameFailure, ATimedOutClassificationWaitStillReleasesTheGpuValidly) {
  const Scene scene = make_demo_scene();
  for (const LightPass pass : {LightPass::raster, LightPass::compute}) {
    RendererOptions options;
    options.width = 640;
    options.height = 360;
    options.light_pass = pass;
    options.timeout = Seconds(1e-9);  // no lavapipe frame is this fast
    TileRenderer renderer(context(), scene, options);
    try {
      renderer.render_frame();
      FAIL() << "render_frame() did not time out";
    } catch (const TimeoutError& e) {
      EXPECT_NE(std::string(e.what()).find("classification"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(context().wait_idle("after the timed-out frame", Seconds(20)));
    EXPECT_EQ(ContextTestSeam::validation_log(context()).count(), 0u) << to_string(pass);
  }
}

TEST_F(FrameFailure, BadSizesAreRejectedWithTheValue) {
  const Scene scene = make_demo_scene();
  RendererOptions options;
  options.width = 0;
  try {
    TileRenderer renderer(context(), scene, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("width 0"), std::string::npos) << e.what();
  }
  options.width = 64;
  options.height = 1u << 20;
  try {
    TileRenderer renderer(context(), scene, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("1048576"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tilelight::test
