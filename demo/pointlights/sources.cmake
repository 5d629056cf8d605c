# fxdemo pointlights (issue 5, item 1): Catalin Zima's point lights (seed 001).
list(APPEND FXDEMO_SOURCES
  pointlights/build_report.cpp
  pointlights/camera.cpp
  pointlights/debug_sheet.cpp
  pointlights/deferred_renderer.cpp
  pointlights/game1.cpp
  pointlights/quad_renderer.cpp
  pointlights/reference_check.cpp
  pointlights/run_pointlights.cpp
  pointlights/scene.cpp)
