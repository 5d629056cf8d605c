# fxdemo stability (issue 6): stiff and extreme inputs through the real effects, FiniteCheck and CPU references.
list(APPEND FXDEMO_SOURCES
  stability/run_stability.cpp
  stability/stability_cases.cpp
  stability/case_support.cpp
  stability/gbuffer_pass.cpp
  stability/depth_range_cases.cpp
  stability/normal_cases.cpp
  stability/point_light_cases.cpp
  stability/spot_cone_cases.cpp
  stability/unwrap_cases.cpp
  stability/zima_light_cases.cpp)
