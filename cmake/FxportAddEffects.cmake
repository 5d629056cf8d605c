# fxport_add_effects(): compile .fx effects at build time with the fxport CLI, as MonoGame's content
# pipeline does, so the game loads them with Effect::FromCompiledFile (no glslang at run time).
#
#   fxport_add_effects(TARGET mygame
#                      EFFECTS shaders/Bloom.fx shaders/Scene.fx
#                      [INCLUDE_DIRS shaders/common ...]     # fxport compile -I
#                      [DEFINES QUALITY=2 USE_FOG ...]       # fxport compile -D
#                      [OUTPUT_DIR dir]                      # default: ${CMAKE_CURRENT_BINARY_DIR}/effects
#                      [OUTPUTS_VAR var])                    # receives the list of compiled files
#
# Each EFFECT becomes OUTPUT_DIR/<name>.fxeffect, built before TARGET. The compile re-runs when the
# effect, any file it #includes (a depfile written by `fxport compile --depfile`), or the fxport CLI
# changes. A broken effect fails the build with its own `file(line,col): error FXnnnn: ...` lines.
# Works from find_package(fxport) and from add_subdirectory(fxport) alike.
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "fxport_add_effects needs CMake 3.20 or newer (DEPFILE with Makefiles, cmake_path); this is ${CMAKE_VERSION}")
endif()
# Depfile paths are read relative to the calling directory's build folder, in the caller's project
# whatever its cmake_minimum_required says (a function keeps the policies of its definition).
cmake_policy(SET CMP0116 NEW)

function(fxport_add_effects)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;OUTPUT_DIR;OUTPUTS_VAR" "EFFECTS;INCLUDE_DIRS;DEFINES")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "fxport_add_effects: unknown argument(s) ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT TARGET ${arg_TARGET})
    message(FATAL_ERROR "fxport_add_effects: TARGET '${arg_TARGET}' is not a target")
  endif()
  if(NOT arg_EFFECTS)
    message(FATAL_ERROR "fxport_add_effects: no EFFECTS given for ${arg_TARGET}")
  endif()
  if(NOT arg_OUTPUT_DIR)
    set(arg_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/effects)
  endif()
  cmake_path(ABSOLUTE_PATH arg_OUTPUT_DIR BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} NORMALIZE)
  # The folder is made now and again before each compile: Unix Makefiles, unlike Ninja, does not
  # create an output's folder, and a clean may have removed it.
  file(MAKE_DIRECTORY ${arg_OUTPUT_DIR})

  set(options "")
  foreach(dir IN LISTS arg_INCLUDE_DIRS)
    cmake_path(ABSOLUTE_PATH dir BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE)
    list(APPEND options -I ${dir})
  endforeach()
  foreach(define IN LISTS arg_DEFINES)
    list(APPEND options -D ${define})
  endforeach()

  set(outputs "")
  foreach(effect IN LISTS arg_EFFECTS)
    # Absolute input paths: diagnostics then name a file an IDE can open.
    cmake_path(ABSOLUTE_PATH effect BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE)
    cmake_path(GET effect STEM name)
    set(output ${arg_OUTPUT_DIR}/${name}.fxeffect)
    if(output IN_LIST outputs)
      message(FATAL_ERROR "fxport_add_effects: two effects named '${name}' would both write ${output}")
    endif()
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${arg_OUTPUT_DIR}
      COMMAND fxport::fxport compile ${effect} -o ${output} --depfile ${output}.d ${options}
      DEPENDS ${effect} fxport::fxport
      DEPFILE ${output}.d
      COMMENT "fxport: compiling effect ${name}.fx"
      VERBATIM COMMAND_EXPAND_LISTS)
    list(APPEND outputs ${output})
  endforeach()
  # Generated files listed as sources are built before the target (they have no language to compile).
  target_sources(${arg_TARGET} PRIVATE ${outputs})
  if(arg_OUTPUTS_VAR)
    set(${arg_OUTPUTS_VAR} ${outputs} PARENT_SCOPE)
  endif()
endfunction()
