# Which tier each test is in, by its ctest name (docs/ci.md, "Tiers"). Read when CMake
# configures (tests added with add_test) and by ctest (GoogleTest cases, known only after the
# build): plain CMake language, no commands but set, list, foreach, if and function.
#
#   default    what the README's test command runs: every test not in `long`
#   long       sweeps and repeated frame configurations; scripts/run-tests.sh --all and CI
#   sanitizer  the default-tier cases the ASan/UBSan build runs; its product-code line coverage
#              must stay >= 95 % of the whole suite's (scripts/coverage.sh measures both)
#   quick      the edit loop, scripts/run-tests.sh --quick: the default tier less its slowest
#
# A pattern is a regular expression over the whole name; keep each list sorted by area, and
# say why a case is where it is. A test in several lists takes the first that applies.

# Sweeps and repeated frame configurations: the same frame again at another camera, MSAA mode,
# path or light pass, where one configuration of each kind stays in the default tier.
set(TESTS_LONG_PATTERNS
  # A second configure, build and install of shadergen without Vulkan (177 s cold); the default
  # tier keeps shadergen.outside_consumer, the same install with Vulkan.
  "^shadergen\\.outside_consumer_without_vulkan$"
  # A one-node Slurm cluster, 4 shards and a merge on two domains (44 s).
  "^shadergen\\.slurm_shards$"
  # 500 validated frames against 100 (65 s).
  "^Soak\\."
  # Every design choice of the sweep side by side, and the same for a glTF scene (29 s + 5 s);
  # the other benchmarks' smoke runs stay in the default tier.
  "^tilelight\\.sweep(_scene)?_smoke$"
  # Classified == naive per pixel: the default tier keeps the default camera, 1x, raw IDs,
  # triangle pairs and an odd size, each on both paths and both light passes; the other
  # cameras, tile sizes and the uncoalesced index build are the sweep.
  "^Frames/Equivalence\\.ClassifiedEqualsNaivePerPixel/(cpu|gpu)_(low|shadow|sky|street|telephoto|closeup|tile8|tile16_[a-z_]+|uncoalesced|1x_low|1x_raw|1x_triangles|triangles_odd_size)_(compute|raster)( |$)"
  # The three light kinds on every camera; KindsFramesUnderValidation keeps the default camera.
  "^EveryCamera/"
  # Compute == raster bit for bit on further configurations; the equivalence cases above
  # compare both passes with naive already.
  "^Frames/ComputeMatchesRaster\\."
)

# Default-tier cases the sanitizer build leaves out: each adds little coverage of product code
# over the cases kept (docs/ci.md lists them with their times).
set(TESTS_NOT_SANITIZER_PATTERNS
  # Build-system tests: a second CMake project built against an install, and docs/adopting.md's
  # example project. They test CMake files, and under the sanitizers they would build their
  # projects again with ASan for no new coverage of product code.
  "^shadergen\\.outside_consumer$"
  "^docs\\.adopting$"
  # The style checks: clang-format and the lint cache's own test run no product code.
  "^style\\."
  # The benchmarks and their tests: the sanitize preset builds no benchmarks
  # (SHADERGEN_BUILD_BENCH=OFF); what they run is product code the other cases reach.
  "^bench\\."
  "_bench_smoke$"
  "^shadergen\\.scale_chart_smoke$"
  "^tilelight\\.make_hall_smoke$"
  # The real domain built again per case: 42 to 144 s each under ASan, about 600 s of the sanitizer
  # suite's test time in the cold run of ccc5169 (docs/ci.md). One case keeps the whole real
  # build under the sanitizers; the others check properties of the same output.
  "^SplitSecondBuild\\.(Deterministic|EveryBlob|WarmRebuild|GeneratedCpp|RawEntries|AllPermutations|IdenticalBlobs)"
  # A 16-feature domain built to check its dedupe (23 s under ASan): the same build code as
  # every other shadergen case, at a larger scale.
  "^Scaling\\.SixteenFeaturesBuildToFourDistinctSources$"
  # The same frame again at another MSAA mode, light shape, baseline or camera: each family
  # keeps the cases whose host code differs (one MSAA mode of each light shape, the camera
  # inside a volume and beyond the far plane, raw IDs, triangle pairs, an odd size, 1x), and
  # the default tier runs them all. Under ASan a frame costs 2 to 3 times what it does in the
  # test build: these cases were about 230 s of the sanitizer suite's 848 s of test time.
  "^Lights/LocalLight(Volumes\\.EqualTheFullScreenReferencePerPixel|Frame\\.LightsItsRangeOnlyAndEveryTargetAlike)/(point_msaa1|point_globe_msaa[14]|point_around_camera_msaa4|spot_msaa[14]|spot_globe_msaa4|box_msaa[14]|box_back_colour_msaa[14]|box_back_colour_globe_msaa4|point_beyond_far_plane_msaa4)( |$)"
  "^Lights/LocalLightShadowVolumes\\.EqualTheFullScreenReferencePerPixel/(point_msaa1|spot_msaa4|box_msaa4|point_camera_inside_msaa4)( |$)"
  "^Frames/Equivalence\\.ClassifiedEqualsNaivePerPixel/(cpu_default_compute|gpu_default_raster|cpu_odd_size_raster|gpu_odd_size_(raster|compute)|cpu_raw_(raster|compute)|gpu_raw_compute|cpu_triangles_compute|cpu_1x_raster|gpu_1x_odd_size_compute)( |$)"
  "^Baselines/WholeFrame\\.ClassifiedEqualsEveryBaselineOnThePlainGBuffer/(naive|dynamic)_"
  "^Baselines/FrameTimingsAddUp\\.PerFrame/(naive_gpu|dynamic_cpu)( |$)"
  "^Modes/ForwardPassFrame\\.[A-Za-z]+/msaa4_compute( |$)"
  "^Cameras/PlainGBuffer\\.[A-Za-z]+/(closeup_msaa|street_msaa|low_1x)( |$)"
  "^Scenes/GltfFrames\\.ClassifiedEqualsNaivePerPixel/engine_glb_gpu_no_msaa( |$)"
  "^Views/EyeViews\\.[A-Za-z]+/procedural_(low_wide|street)( |$)"
)

# Default-tier cases the quick loop leaves out: the slowest.
set(TESTS_NOT_QUICK_PATTERNS
  # Each of these takes 3 s or more (the slowest list of scripts/run-tests.sh).
  "^shadergen\\.outside_consumer$"
  "^docs\\.adopting$"
  "^SplitSecondBuild\\."
  "^Frames/Equivalence\\."
  "^KindsFramesUnderValidation\\."
  "^TilelightLightKinds\\."
  "^TilelightCli\\."
  "^FrameFailure\\."
  "^ShardedBuild\\."
  "^Scaling\\."
  "^RemoteCacheHostile\\."
  "^IndexPaths\\.Gpu"
  "^Classification\\."
  "^WholeFrameReportFiles\\."
  "^Lights/"
  "^LocalLightCli\\."
  "^TypedApi\\.AVulkanDriver"
  "_bench_smoke$"
)

# tests_tier_labels(<name> <out>): the tier labels of the test called <name>.
function(tests_tier_labels name out)
  foreach(pattern IN LISTS TESTS_LONG_PATTERNS)
    if(name MATCHES "${pattern}")
      set(${out} long PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(tiers default)
  set(sanitizer TRUE)
  foreach(pattern IN LISTS TESTS_NOT_SANITIZER_PATTERNS)
    if(name MATCHES "${pattern}")
      set(sanitizer FALSE)
      break()
    endif()
  endforeach()
  if(sanitizer)
    list(APPEND tiers sanitizer)
  endif()
  set(quick TRUE)
  foreach(pattern IN LISTS TESTS_NOT_QUICK_PATTERNS)
    if(name MATCHES "${pattern}")
      set(quick FALSE)
      break()
    endif()
  endforeach()
  if(quick)
    list(APPEND tiers quick)
  endif()
  set(${out} "${tiers}" PARENT_SCOPE)
endfunction()
