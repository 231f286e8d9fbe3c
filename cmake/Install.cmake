# `cmake --install`: the CLI, the registry header (and shadergen/vulkan.h, for consumers that
# want Vulkan create-infos), the CMake function and the package config,
# so another project's find_package(shadergen CONFIG REQUIRED) gets all three.
#
# shadergen::vulkan (the target of shadergen/vulkan.h, which links Vulkan::Headers) has an
# export set and file of its own, shadergenVulkanTargets.cmake, which the package config loads
# only for find_package(shadergen ... COMPONENTS vulkan), after it has found Vulkan: a consumer
# that does not ask for the component never needs Vulkan. Both are installed whether or not this
# build found Vulkan, since the header needs nothing of the machine that built shadergen.
include(CMakePackageConfigHelpers)

set(SHADERGEN_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadergen)
install(TARGETS shadergen shadergen_registry EXPORT shadergenTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS shadergen_vulkan EXPORT shadergenVulkanTargets)
install(FILES ${PROJECT_SOURCE_DIR}/shadergen/include/shadergen/registry.h
  ${PROJECT_SOURCE_DIR}/shadergen/include/shadergen/vulkan.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadergen)
install(EXPORT shadergenTargets NAMESPACE shadergen:: DESTINATION ${SHADERGEN_CMAKE_DIR})
install(EXPORT shadergenVulkanTargets NAMESPACE shadergen:: DESTINATION ${SHADERGEN_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shadergenConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shadergenConfig.cmake
  INSTALL_DESTINATION ${SHADERGEN_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shadergenConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/shadergenConfig.cmake
  ${PROJECT_BINARY_DIR}/shadergenConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/ShadergenFunctions.cmake
  DESTINATION ${SHADERGEN_CMAKE_DIR})
