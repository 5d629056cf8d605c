# fxdemo pointlights --spot --check: the G-buffer, the light map with the chapter's exercise (the spot
# light, at a game time where its cone lights the floor, a sphere and a crate) and the final combine
# against the CPU references (reference_check.h). demo.pointlights.check (demo/CMakeLists.txt) runs
# the same check without the spot light.
add_test(NAME demo.pointlights.spot.check
         COMMAND fxdemo pointlights --size 320x240 --frames 1 --time 2.5 --spot --check
                 --out ${CMAKE_BINARY_DIR}/test-out/pointlights-spot)
list(APPEND FXDEMO_TESTS demo.pointlights.spot.check)
