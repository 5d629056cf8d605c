# Issue 16 item 4: every demo renders the same PNGs, byte for byte, with compute passes on
# (FXPORT_COMPUTE_PASSES=1) and off. Two frames, so the second frame's dispatches replay the
# interpolants the first one stored; --explain must show dispatches and replays.
# Run by ctest: cmake -DFXDEMO=... -DOUT=... -P this file. rastertek50 is not among them: it draws
# through the D3D10 front end, whose device core keeps the compute-pass rewrite off (each D3D draw is
# exactly what was asked: runtime/d3d11/src/device.cpp), so it has no dispatches to compare.
set(line_regex "run as compute +([0-9]+) +\\(([0-9]+) from the replay store")
foreach(demo deferred pointlights lighting2d)
  foreach(mode 0 1)
    file(REMOVE_RECURSE ${OUT}/${mode}/${demo})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env FXPORT_COMPUTE_PASSES=${mode}
                            ${FXDEMO} ${demo} --size 160x100 --frames 2 --explain --out ${OUT}/${mode}/${demo}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "fxdemo ${demo} (FXPORT_COMPUTE_PASSES=${mode}) failed: ${rc}\n${out}\n${err}")
    endif()
  endforeach()
  if(NOT out MATCHES "${line_regex}")
    message(FATAL_ERROR "fxdemo ${demo} --explain with compute passes prints no dispatch counts:\n${out}")
  endif()
  if(CMAKE_MATCH_1 EQUAL 0 OR CMAKE_MATCH_2 EQUAL 0)
    message(FATAL_ERROR "fxdemo ${demo}: ${CMAKE_MATCH_1} draws run as compute, ${CMAKE_MATCH_2} replayed; expected some of each")
  endif()
  message(STATUS "${demo}: ${CMAKE_MATCH_1} draws run as compute, ${CMAKE_MATCH_2} from the replay store")
  file(GLOB_RECURSE images RELATIVE ${OUT}/0/${demo} ${OUT}/0/${demo}/*.png)
  list(LENGTH images count)
  if(count EQUAL 0)
    message(FATAL_ERROR "fxdemo ${demo} wrote no PNG")
  endif()
  foreach(image ${images})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/0/${demo}/${image} ${OUT}/1/${demo}/${image}
                    RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      message(FATAL_ERROR "${demo}/${image} differs between compute passes on and off")
    endif()
  endforeach()
  message(STATUS "${demo}: ${count} images identical with compute passes on and off")
endforeach()
