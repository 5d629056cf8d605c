# The graphics runtime's inner boundaries (issue 22; docs/DESIGN.md, "What a draw does"), checked on
# the sources of runtime/graphics, runtime/d3d11 and runtime/framework:
#   1. no GL call (gl[A-Z]...( ) outside runtime/graphics/src/gl/;
#   2. the device core's and the effect runtime's private headers (device/device_impl.h,
#      effect/effect_impl.h) and the GL backend's headers (gl/...) included only from their folder;
#   3. public headers (runtime/*/include) free of GL: no GL headers, types or constants, and no
#      internal header;
#   4. the GL-free internal headers (the backend seam, the state shadow, vertex-input matching,
#      the front-end core) stay GL-free;
#   5. the optimisation passes are removable: every source under a passes/ folder is added by
#      runtime/graphics/CMakeLists.txt only inside its if(FXPORT_PASS_<NAME>), no file outside a
#      passes/ folder includes a header from one, and only device/optimization_passes.h reads the
#      FXPORT_PASS_ macros (the core reaches a pass under `if constexpr` on its flag there).
# Both hold everywhere: the folders meet through small GL-free headers instead (device/effect_programs.h,
# device/compute_passes.h, effect/effect_notices.h; docs/DESIGN.md). The lists of files excepted
# below are empty and may only stay so: a listed file that no longer breaks its rule fails the test too.
# Usage: cmake -DSOURCE_DIR=<repo> -P check_graphics_seam.cmake
set(src runtime/graphics/src)
set(glCallsLeft)  # rule 1: none left
set(deviceImplLeft)  # rule 2: none left (effects: device/effect_programs.h; GL passes: device/compute_passes.h)
set(effectImplLeft)  # rule 2: none left (the device tells effects through effect/effect_notices.h)
set(glHeadersLeft)  # rule 2: none left (the core calls the compute passes through device/compute_passes.h)
set(passesNotRemovable)  # rule 5: pass sources always built: none left
set(glFreeInternal  # rule 4
  ${src}/device/backend.h ${src}/device/state_shadow.h ${src}/device/vertex_input.h ${src}/device/vertex_format.h ${src}/device/front_end_core.h
  ${src}/device/device_impl.h ${src}/device/impl_access.h ${src}/device/surface_formats.h ${src}/device/draw_hints.h
  ${src}/diagnostics/fragment_tally.h ${src}/device/gpu_query.h ${src}/device/device_probes.h
  ${src}/device/shader_program.h ${src}/device/pass_emulation.h ${src}/effect/effect_notices.h ${src}/device/compute_passes.h ${src}/device/effect_programs.h
  ${src}/device/optimization_passes.h)

set(problems "")
set(stillListed "")
# Checks `where` against one rule: `broken` says whether it breaks it, `exceptions` the list.
macro(judge where broken exceptions what)
  list(FIND ${exceptions} "${where}" listed)
  if(${broken} AND listed EQUAL -1)
    string(APPEND problems "${where}: ${what}\n")
  elseif(NOT ${broken} AND NOT listed EQUAL -1)
    string(APPEND problems "${where}: listed in ${exceptions} (check_graphics_seam.cmake) but no longer ${what}: take it off the list\n")
  endif()
endmacro()

file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/runtime/graphics/*.h ${SOURCE_DIR}/runtime/graphics/*.cpp ${SOURCE_DIR}/runtime/graphics/*.inc
     ${SOURCE_DIR}/runtime/d3d11/*.h ${SOURCE_DIR}/runtime/d3d11/*.cpp
     ${SOURCE_DIR}/runtime/framework/*.h ${SOURCE_DIR}/runtime/framework/*.cpp)
foreach(where ${sources})
  file(READ ${SOURCE_DIR}/${where} text)
  string(REGEX REPLACE "//[^\n]*" "" code "${text}")     # comments may name GL calls
  set(code " ${code}")
  string(REGEX MATCHALL "\n[ \t]*#[ \t]*include[ \t]*[\"<][^\">]*[\">]" includes "${code}")
  get_filename_component(folder ${where} DIRECTORY)

  # 1. GL calls
  if(NOT where MATCHES "^${src}/gl/")
    set(broken FALSE)
    if(code MATCHES "[^A-Za-z0-9_]gl[A-Z][A-Za-z0-9]*[ ]*\\(")
      set(broken TRUE)
    endif()
    judge(${where} broken glCallsLeft "calls GL (every gl* call belongs under ${src}/gl/)")
  endif()

  # 2. private headers
  foreach(rule "device/device_impl\\.h|^${src}/device/|deviceImplLeft"
               "effect/effect_impl\\.h|^${src}/effect/|effectImplLeft"
               "\"gl/|^${src}/gl/|glHeadersLeft")
    string(REPLACE "|" ";" parts "${rule}")
    list(GET parts 0 header)
    list(GET parts 1 home)
    list(GET parts 2 exceptions)
    if(NOT where MATCHES "${home}")
      set(broken FALSE)
      if(includes MATCHES "${header}")
        set(broken TRUE)
      endif()
      judge(${where} broken ${exceptions} "includes a private header of another folder (${header})")
    endif()
  endforeach()

  # 3. public headers, 4. GL-free internal headers
  list(FIND glFreeInternal "${where}" glFree)
  if(where MATCHES "^runtime/[a-z0-9]+/include/" OR NOT glFree EQUAL -1)
    if(includes MATCHES "(GL|EGL|GLFW|epoxy)/|platform/gl\\.h")
      string(APPEND problems "${where}: a public or GL-free header includes GL\n")
    endif()
    # Internal headers: none in a public header; only GL-free ones in a GL-free header.
    string(REGEX MATCHALL "\"(device|effect|gl|helpers|diagnostics)/[^\"]*\"" internal "${includes}")
    foreach(header ${internal})
      string(REPLACE "\"" "" header "${header}")
      list(FIND glFreeInternal "${src}/${header}" ok)
      if(where MATCHES "^runtime/[a-z0-9]+/include/" OR ok EQUAL -1)
        string(APPEND problems "${where}: a public or GL-free header includes ${header}\n")
      endif()
    endforeach()
    if(code MATCHES "[^A-Za-z0-9_](GL[a-z]+|GL_[A-Z0-9_]+)[^A-Za-z0-9_]")
      string(APPEND problems "${where}: a public or GL-free header names a GL type or constant (${CMAKE_MATCH_1})\n")
    endif()
  endif()
endforeach()

# 5. removable passes: the sources each if(FXPORT_PASS_<NAME>) ... endif() of the library adds
file(READ ${SOURCE_DIR}/runtime/graphics/CMakeLists.txt graphicsLists)
string(REGEX MATCHALL "\nif\\(FXPORT_PASS_[A-Z_]+\\)[^\n]*\n([^e][^\n]*\n)*endif" passBlocks "${graphicsLists}")
set(removable "")
foreach(block ${passBlocks})
  string(REGEX MATCHALL "src/[a-z_/]+\\.cpp" added "${block}")
  list(APPEND removable ${added})
endforeach()
foreach(where ${sources})
  if(where MATCHES "^${src}/[a-z]+/passes/.*\\.cpp$")
    string(REPLACE "runtime/graphics/" "" inLists "${where}")
    list(FIND removable "${inLists}" found)
    set(broken FALSE)
    if(found EQUAL -1)
      set(broken TRUE)
    endif()
    judge(${where} broken passesNotRemovable "added to the library outside an if(FXPORT_PASS_<NAME>) (a pass must be removable by its build option)")
  endif()
  file(READ ${SOURCE_DIR}/${where} text)
  string(REGEX REPLACE "//[^\n]*" "" code "${text}")
  if(NOT where MATCHES "^${src}/[a-z]+/passes/" AND code MATCHES "#[ \t]*include[ \t]*\"[a-z]+/passes/")
    string(APPEND problems "${where}: includes a pass's header (the core reaches a pass through its interface: device/compute_passes.h, device_impl.h)\n")
  endif()
  if(NOT where STREQUAL "${src}/device/optimization_passes.h" AND code MATCHES "FXPORT_PASS_")
    string(APPEND problems "${where}: reads an FXPORT_PASS_ macro (only device/optimization_passes.h does; use its k...Built flags)\n")
  endif()
endforeach()

if(problems)
  message(FATAL_ERROR "the graphics runtime's boundaries (tests/layering/check_graphics_seam.cmake):\n${problems}")
endif()
message(STATUS "the graphics runtime keeps its boundaries")
