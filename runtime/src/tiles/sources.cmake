# CPU side of the tile passes: the tile grid and the per-class index buffer builder.
target_sources(tilelight_runtime PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/tile_grid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tile_index_builder.cpp)
