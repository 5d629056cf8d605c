# Issue 16: every demo renders the same PNGs with depth/stencil buffers made at the first draw that
# needs one (the default), with every buffer made with its target (FXPORT_LAZY_DEPTH=0), and with
# lazy buffers under immediate clears (FXPORT_DEFER_CLEARS=0: each clear of a buffer not made yet
# waits on its target instead of in the device's pending clear). Prints each demo's --explain counts
# of depth/stencil buffers; the eager run must allocate every buffer asked for, the lazy one no more.
# Run by ctest: cmake -DFXDEMO=... -DOUT=... -P this file.
set(line_regex "this scene +asked for +([0-9]+) \\(([0-9]+) B\\) +allocated +([0-9]+) \\(([0-9]+) B\\) +never allocated +([0-9]+) \\(([0-9]+) B saved\\) +invalidated +([0-9]+)")
foreach(demo deferred pointlights lighting2d rastertek50)
  foreach(mode lazy eager immediate)
    set(env FXPORT_LAZY_DEPTH=1 FXPORT_DEFER_CLEARS=1)
    if(mode STREQUAL "eager")
      set(env FXPORT_LAZY_DEPTH=0 FXPORT_DEFER_CLEARS=1)
    elseif(mode STREQUAL "immediate")
      set(env FXPORT_LAZY_DEPTH=1 FXPORT_DEFER_CLEARS=0)
    endif()
    file(REMOVE_RECURSE ${OUT}/${mode}/${demo})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env}
                            ${FXDEMO} ${demo} --size 160x100 --frames 2 --explain --out ${OUT}/${mode}/${demo}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "fxdemo ${demo} (${env}) failed: ${rc}\n${out}\n${err}")
    endif()
    if(NOT out MATCHES "${line_regex}")
      message(FATAL_ERROR "fxdemo ${demo} --explain (${env}) prints no depth/stencil counts:\n${out}")
    endif()
    set(asked ${CMAKE_MATCH_1})
    set(allocated_${mode} ${CMAKE_MATCH_3})
    message(STATUS "${demo} ${mode}: depth/stencil buffers asked for ${asked} (${CMAKE_MATCH_2} B), allocated "
                   "${CMAKE_MATCH_3} (${CMAKE_MATCH_4} B), never allocated ${CMAKE_MATCH_5} (${CMAKE_MATCH_6} B saved), "
                   "invalidated ${CMAKE_MATCH_7}")
    if(mode STREQUAL "eager" AND NOT CMAKE_MATCH_3 EQUAL asked)
      message(FATAL_ERROR "${demo}: with FXPORT_LAZY_DEPTH=0, ${CMAKE_MATCH_3} of ${asked} depth buffers were made")
    endif()
  endforeach()
  if(allocated_lazy GREATER allocated_eager OR NOT allocated_lazy EQUAL allocated_immediate)
    message(FATAL_ERROR "${demo}: depth buffers made: ${allocated_lazy} lazy, ${allocated_eager} eager, "
                        "${allocated_immediate} lazy with immediate clears")
  endif()
  file(GLOB_RECURSE images RELATIVE ${OUT}/lazy/${demo} ${OUT}/lazy/${demo}/*.png)
  list(LENGTH images count)
  if(count EQUAL 0)
    message(FATAL_ERROR "fxdemo ${demo} wrote no PNG")
  endif()
  foreach(image ${images})
    foreach(other eager immediate)
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/lazy/${demo}/${image} ${OUT}/${other}/${demo}/${image}
                      RESULT_VARIABLE same)
      if(NOT same EQUAL 0)
        message(FATAL_ERROR "${demo}/${image} differs between lazy depth buffers and ${other}")
      endif()
    endforeach()
  endforeach()
  message(STATUS "${demo}: ${count} images identical lazy, eager and lazy with immediate clears")
endforeach()
