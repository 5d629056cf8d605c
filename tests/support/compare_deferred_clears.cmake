# Issue 16: every demo renders the same PNGs with deferred clears and honoured DiscardContents (the
# defaults) and with every clear executed at once (FXPORT_DEFER_CLEARS=0 FXPORT_HONOUR_DISCARDS=0
# FXPORT_DROP_COVERED_CLEARS=0), every depth/stencil buffer made with its target (FXPORT_LAZY_DEPTH=0).
# Run by ctest: cmake -DFXDEMO=... -DOUT=... -P this file.
foreach(demo deferred pointlights lighting2d rastertek50)
  foreach(mode on off)
    set(defer 1)
    if(mode STREQUAL "off")
      set(defer 0)
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E env FXPORT_DEFER_CLEARS=${defer} FXPORT_HONOUR_DISCARDS=${defer}
                            FXPORT_DROP_COVERED_CLEARS=${defer} FXPORT_LAZY_DEPTH=${defer}
                            ${FXDEMO} ${demo} --size 160x100 --frames 2 --out ${OUT}/${mode}/${demo}
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "fxdemo ${demo} (FXPORT_DEFER_CLEARS=${defer}) failed: ${rc}\n${err}")
    endif()
  endforeach()
  file(GLOB_RECURSE images RELATIVE ${OUT}/on/${demo} ${OUT}/on/${demo}/*.png)
  list(LENGTH images count)
  if(count EQUAL 0)
    message(FATAL_ERROR "fxdemo ${demo} wrote no PNG")
  endif()
  foreach(image ${images})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/on/${demo}/${image} ${OUT}/off/${demo}/${image}
                    RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      message(FATAL_ERROR "${demo}/${image} differs between deferred and immediate clears")
    endif()
  endforeach()
  message(STATUS "${demo}: ${count} images identical")
endforeach()
