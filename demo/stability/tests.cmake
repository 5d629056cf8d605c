# The stability suite at a small size: the checker must report the known float32 overflow of the
# exponential shadow map and normalize(0) in GBuffer.fx as written, the known breakages (near/far
# 1e7, a light sphere past the far plane, the spot's cos(FOV) test) must show, every opt-in fix
# must leave no NaN/Inf within its bound, and the unwrap's zero-sin/cos rays must match.
add_test(NAME demo.stability.assert
         COMMAND fxdemo stability --size 8 --no-largest --assert --out ${CMAKE_BINARY_DIR}/test-out/stability)
# --check-finite on a demo: a clean run says so (the demo's passes were scanned).
add_test(NAME demo.rastertek50.check-finite
         COMMAND fxdemo rastertek50 --size 64x48 --frames 1 --check-finite --out ${CMAKE_BINARY_DIR}/test-out/rastertek50-finite)
set_tests_properties(demo.rastertek50.check-finite PROPERTIES PASS_REGULAR_EXPRESSION "--check-finite: no NaN/Inf after [1-9]")
list(APPEND FXDEMO_TESTS demo.stability.assert demo.rastertek50.check-finite)
