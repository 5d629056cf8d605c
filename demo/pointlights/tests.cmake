# fxdemo pointlights --spot --check: the G-buffer, the light map with the chapter's exercise (the spot
# light, at a game time where its cone lights the floor, a sphere and a crate) and the final combine
# against the CPU references (reference_check.h). demo.pointlights.check (demo/CMakeLists.txt) runs
# the same check without the spot light.
add_test(NAME demo.pointlights.spot.check
         COMMAND fxdemo pointlights --size 320x240 --frames 1 --time 2.5 --spot --check
                 --out ${CMAKE_BINARY_DIR}/test-out/pointlights-spot)
list(APPEND FXDEMO_TESTS demo.pointlights.spot.check)

# Frustum culling (issue 6 part 3): from close up (--camera -10,0,6) some of the 22 point lights are
# outside the view and not drawn; the frame is byte-identical to the one with every light drawn
# (--no-cull), since a light whose sphere the frustum does not meet lights no pixel seen.
set(FXDEMO_PL_CULL_OUT ${CMAKE_BINARY_DIR}/test-out/pointlights-cull)
add_test(NAME demo.pointlights.cull.culled
         COMMAND fxdemo pointlights --size 320x240 --frames 1 --camera -10,0,6 --explain --out ${FXDEMO_PL_CULL_OUT}/culled)
set_tests_properties(demo.pointlights.cull.culled PROPERTIES FIXTURES_SETUP pointlights_cull
  PASS_REGULAR_EXPRESSION "point lights in the last frame: [0-9]+ drawn, [1-9][0-9]* culled.*"
  FAIL_REGULAR_EXPRESSION "built     SpotLight")
add_test(NAME demo.pointlights.cull.all
         COMMAND fxdemo pointlights --size 320x240 --frames 1 --camera -10,0,6 --no-cull --out ${FXDEMO_PL_CULL_OUT}/all)
set_tests_properties(demo.pointlights.cull.all PROPERTIES FIXTURES_SETUP pointlights_cull
  PASS_REGULAR_EXPRESSION ", 0 outside the view frustum not drawn")
add_test(NAME demo.pointlights.cull.same_frame
         COMMAND ${CMAKE_COMMAND} -E compare_files ${FXDEMO_PL_CULL_OUT}/culled/final.png ${FXDEMO_PL_CULL_OUT}/all/final.png)
set_tests_properties(demo.pointlights.cull.same_frame PROPERTIES FIXTURES_REQUIRED pointlights_cull)
list(APPEND FXDEMO_TESTS demo.pointlights.cull.culled demo.pointlights.cull.all)
# --gbuffer float32: the G-buffer and lightRT are float targets (5 scanned by --check-finite, the
# tutorial's formats give 1: depthRT), and no pass leaves NaN/Inf on this driver. On NVIDIA the
# cleared pixels' pow(0, 0) does (docs/stability); --define 'pow(x, y)=pow(max(x, 1e-30), y)' fixes it.
add_test(NAME demo.pointlights.float32.check-finite
         COMMAND fxdemo pointlights --size 160x120 --frames 1 --gbuffer float32 --check-finite
                 --out ${CMAKE_BINARY_DIR}/test-out/pointlights-float32)
set_tests_properties(demo.pointlights.float32.check-finite PROPERTIES
  PASS_REGULAR_EXPRESSION "--check-finite: no NaN/Inf after 4 passes \\(5 float/half targets scanned")
list(APPEND FXDEMO_TESTS demo.pointlights.float32.check-finite)
