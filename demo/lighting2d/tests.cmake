# fxdemo lighting2d --check over three frames at an odd size: every light's steps, the accumulated
# light map and the back buffer of the last frame against the CPU references (reference_check.h).
# Three frames: the accumulation's reference starts from black, so light from an earlier frame left
# in lightMap (PreserveContents) would fail it. demo.lighting2d.check (demo/CMakeLists.txt) runs one
# frame at 320x192.
add_test(NAME demo.lighting2d.check.frames
         COMMAND fxdemo lighting2d --size 200x120 --frames 3 --check --out ${CMAKE_BINARY_DIR}/test-out/lighting2d-frames)
list(APPEND FXDEMO_TESTS demo.lighting2d.check.frames)
