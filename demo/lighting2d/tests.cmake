# fxdemo lighting2d --check over three frames at an odd size: every light's steps, the accumulated
# light map and the back buffer of the last frame against the CPU references (reference_check.h).
# Three frames: the accumulation's reference starts from black, so light from an earlier frame left
# in lightMap (PreserveContents) would fail it. demo.lighting2d.check (demo/CMakeLists.txt) runs one
# frame at 320x192.
add_test(NAME demo.lighting2d.check.frames
         COMMAND fxdemo lighting2d --size 200x120 --frames 3 --check --out ${CMAKE_BINARY_DIR}/test-out/lighting2d-frames)
list(APPEND FXDEMO_TESTS demo.lighting2d.check.frames)

# fxdemo lighting2d --explain (issue 6): a scene of point lights only loads neither spot effect and
# allocates no spot debug copies; the all-features scene (3 spot, 3 point lights) built in the same
# run has them, so they are listed as left out (the spot unwrap copy: 96 x 96 x 4 bytes). And the
# other way round for spot lights only.
add_test(NAME demo.lighting2d.explain.point_only
         COMMAND fxdemo lighting2d --size 96x64 --frames 1 --lights p --explain
                 --out ${CMAKE_BINARY_DIR}/test-out/lighting2d-explain-p)
set_tests_properties(demo.lighting2d.explain.point_only PROPERTIES
  PASS_REGULAR_EXPRESSION "built +Effects/Unwrap .*built +Effects/PointLight .*left out +Effects/UnwrapSpotlight .*left out +Effects/SpotLight .*effects: 5 built.*all-features 7.*left out +debug\\.spotUnwrap +96x96 Color +36864 B.*lights drawn: 0 spot, 3 point \\(all-features: 3 spot, 3 point\\)"
  FAIL_REGULAR_EXPRESSION "built +Effects/(UnwrapSpotlight|SpotLight) ")
add_test(NAME demo.lighting2d.explain.spot_only
         COMMAND fxdemo lighting2d --size 96x64 --frames 1 --lights s --explain
                 --out ${CMAKE_BINARY_DIR}/test-out/lighting2d-explain-s)
set_tests_properties(demo.lighting2d.explain.spot_only PROPERTIES
  PASS_REGULAR_EXPRESSION "built +Effects/UnwrapSpotlight .*built +Effects/SpotLight .*left out +Effects/Unwrap .*left out +Effects/PointLight .*effects: 5 built.*all-features 7.*left out +debug\\.pointUnwrap .*lights drawn: 3 spot, 0 point"
  FAIL_REGULAR_EXPRESSION "built +Effects/(Unwrap|PointLight) ")
list(APPEND FXDEMO_TESTS demo.lighting2d.explain.point_only demo.lighting2d.explain.spot_only)
