# fxdemo report (issue 6, part 1): error against GPU time for each demo's quality knobs.
list(APPEND FXDEMO_SOURCES
  report/deferred_light_map_reference.cpp
  report/deferred_sweep.cpp
  report/lighting2d_reference.cpp
  report/lighting2d_sweep.cpp
  report/measurement.cpp
  report/pointlights_sweep.cpp
  report/rastertek50_sweep.cpp
  report/report_files.cpp
  report/report_plot.cpp
  report/run_report.cpp
  report/sweep.cpp
  report/triangle_bvh.cpp)

# fxport_reference: the double-precision CPU references of the deferred demo's passes (written from
# hlsl/xna-deferred, D3D9 sampling and rasterisation rules; sources in tests/render, which tests them
# against the GPU), as a library that the render tests and `fxdemo report` (the deferred demo's
# exact light map) both link. Plain C++: no GL, no fxport runtime.
add_library(fxport_reference STATIC
  ${PROJECT_SOURCE_DIR}/tests/render/d3d9_sampling.cpp
  ${PROJECT_SOURCE_DIR}/tests/render/deferred_reference.cpp
  ${PROJECT_SOURCE_DIR}/tests/render/reference_eval.cpp
  ${PROJECT_SOURCE_DIR}/tests/render/scene_geometry.cpp)
target_include_directories(fxport_reference PUBLIC ${PROJECT_SOURCE_DIR}/tests/render)
target_link_libraries(fxport_reference PRIVATE fxport_warnings)
list(APPEND FXDEMO_LIBRARIES fxport_reference)
