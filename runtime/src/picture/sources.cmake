# Picture output (tile-class visualisation and its bitmap font): pure CPU, no Vulkan.
target_sources(tilelight_runtime PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/bitmap_font.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tile_class_image.cpp)
