# The stability suite at a small size: the checker must report the known float32 overflow of the
# exponential shadow map and normalize(0) in GBuffer.fx as written, the known breakages (near/far
# 1e7, a light sphere past the far plane, the spot's cos(FOV) test) must show, every opt-in fix
# must leave no NaN/Inf within its bound, and the unwrap's zero-sin/cos rays must match.
add_test(NAME demo.stability.assert
         COMMAND fxdemo stability --size 8 --no-largest --assert --out ${CMAKE_BINARY_DIR}/test-out/stability)
list(APPEND FXDEMO_QUALITY_TESTS demo.stability.assert)
