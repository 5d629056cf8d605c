# fxdemo deferred (issue 4): "Deferred Rendering in XNA 4" (seed 000), the final chapter's Game1.
list(APPEND FXDEMO_SOURCES
  deferred/Cameras/base_camera.cpp
  deferred/Cameras/free_camera.cpp
  deferred/Lights/directional_light.cpp
  deferred/Lights/light_manager.cpp
  deferred/Lights/point_light.cpp
  deferred/Lights/shadow_map_key.cpp
  deferred/Lights/spot_light.cpp
  deferred/build_report.cpp
  deferred/debug_sheet.cpp
  deferred/deferred_renderer.cpp
  deferred/game1.cpp
  deferred/run_deferred.cpp
  deferred/ssao.cpp)
