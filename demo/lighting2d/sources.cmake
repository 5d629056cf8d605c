# fxdemo lighting2d (issue 5 item 2): Rabid Lion Games' 2D lighting system (seed 002).
list(APPEND FXDEMO_SOURCES
  lighting2d/build_report.cpp
  lighting2d/light_renderer.cpp
  lighting2d/reference_check.cpp
  lighting2d/run_lighting2d.cpp
  lighting2d/scene_sprites.cpp)
