# Pieces every fxdemo program shares that are not listed in demo/CMakeLists.txt (paths relative to demo/).
list(APPEND FXDEMO_SOURCES
  common/build_report.cpp
  common/finite_check.cpp
  common/pass_bound.cpp
  common/pass_estimate.cpp
  common/tile_sheet.cpp)
