# CPU side of the tile passes: the tile grid, the per-class index buffer builder and the
# primitive encoding (triangles or points) they share with the GPU path.
target_sources(tilelight_runtime PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/tile_grid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tile_index_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tile_primitive.cpp)
