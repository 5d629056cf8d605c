# What each folder may include (docs/DESIGN.md, "Layers and what each folder may include"), checked
# on the sources' #include lines:
#   reference/  "reference/..." and the standard library only: no runtime, no GL, no demo, no tests
#   demo/       its own ports and common/, fxport/ (the runtime), reference/; never tests/ or quality/
#   quality/    its own report/ and stability/, the ports, fxport/, reference/; never tests/
#   xlate/, runtime/  nothing of reference/, demo/, quality/ or tests/
# Usage: cmake -DSOURCE_DIR=<repo> -P check_includes.cmake
set(ports "common|deferred|pointlights|lighting2d|rastertek50")
set(rules
  "reference|^(reference/)|^(GL|GLES[0-9]*|EGL|GLFW|epoxy|glad|glbinding|gtest)/"
  "demo|^(${ports}|fxport|reference)/|^(GL|EGL|GLFW)/"
  "quality|^(report|stability|${ports}|fxport|reference)/|^(GL|EGL|GLFW)/"
  "xlate|^|^(reference|common|report|stability)/"
  "runtime|^|^(reference|common|report|stability)/")
set(problems "")
foreach(rule ${rules})
  string(REPLACE "|^" ";^" parts "${rule}")
  list(GET parts 0 folder)
  list(GET parts 1 allowedQuoted)
  list(GET parts 2 forbiddenAngled)
  file(GLOB_RECURSE sources ${SOURCE_DIR}/${folder}/*.h ${SOURCE_DIR}/${folder}/*.cpp ${SOURCE_DIR}/${folder}/*.hpp)
  foreach(source ${sources})
    file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    get_filename_component(dir ${source} DIRECTORY)
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*" "" target "${line}")
      string(SUBSTRING "${target}" 0 1 kind)
      string(REGEX REPLACE "^[\"<]([^\">]*)[\">].*" "\\1" path "${target}")
      file(RELATIVE_PATH where ${SOURCE_DIR} ${source})
      if(kind STREQUAL "\"")
        # A quoted include must name an allowed folder, or (xlate/runtime) a file beside the source.
        if(folder MATCHES "^(xlate|runtime)$")
          if(path MATCHES "${forbiddenAngled}" OR path MATCHES "(render_harness|runtime_test_support)\\.h$")
            string(APPEND problems "${where}: ${line}\n")
          endif()
        elseif(NOT path MATCHES "${allowedQuoted}" AND NOT EXISTS ${dir}/${path})
          string(APPEND problems "${where}: ${line}\n")
        elseif(NOT path MATCHES "${allowedQuoted}")
          string(APPEND problems "${where}: ${line} (a file beside it: include it by its folder)\n")
        endif()
      elseif(path MATCHES "${forbiddenAngled}")
        string(APPEND problems "${where}: ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
# runtime/d3d11 is a front end over the device core: no GL, and none of the core's GL-bearing
# internal headers (it reaches the core through front_end_core.h).
file(GLOB_RECURSE d3d11_sources ${SOURCE_DIR}/runtime/d3d11/*.h ${SOURCE_DIR}/runtime/d3d11/*.cpp)
foreach(source ${d3d11_sources})
  file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line ${includes})
    if(line MATCHES "(GL|EGL|GLFW)/|platform/gl\\.h|device_impl\\.h|effect_impl\\.h|gl_formats\\.h|draw_call\\.h")
      file(RELATIVE_PATH where ${SOURCE_DIR} ${source})
      string(APPEND problems "${where}: ${line} (the D3D11 front end reaches GL only through the device core)\n")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "includes across the layers (docs/DESIGN.md):\n${problems}")
endif()
message(STATUS "includes follow the layers")
