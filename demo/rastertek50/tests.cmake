# fxdemo rastertek50 --explain (issue 6): both effects, created by the shader classes, compiled (+);
# the G-buffer's two Vector4 targets with their bytes (64 x 48 x 16, the first plus its 4-byte
# depth-stencil texels: 61440 and 49152); both passes; and nothing left out (the seed's pipeline has
# no optional part, so the run is its all-features configuration).
add_test(NAME demo.rastertek50.explain
         COMMAND fxdemo rastertek50 --size 64x48 --frames 1 --explain
                 --out ${CMAKE_BINARY_DIR}/test-out/rastertek50-explain)
set_tests_properties(demo.rastertek50.explain PROPERTIES
  PASS_REGULAR_EXPRESSION "built +rastertek/deferred\\.fx +DeferredTechnique\\(1\\)\\+ .*built +rastertek/light\\.fx +LightTechnique\\(1\\)\\+ .*effects: 2 built.*built +colorTexture +64x48 Vector4\\+Depth24Stencil8 +61440 B.*built +normalTexture +64x48 Vector4 +49152 B.*targets: 2 built, 110592 B.*passes run: Deferred Light\npasses left out: none"
  FAIL_REGULAR_EXPRESSION "left out  ")
list(APPEND FXDEMO_TESTS demo.rastertek50.explain)
# The port draws through fxport's D3D10 front end, whose swap chain is headless: --window is
# refused with the reason (D3DClass), not opened on a back buffer nothing draws to.
add_test(NAME demo.rastertek50.window_refused COMMAND fxdemo rastertek50 --window --frames 1)
set_tests_properties(demo.rastertek50.window_refused PROPERTIES
  PASS_REGULAR_EXPRESSION "platform 'glfw': the D3D10 port renders headless only \\(osmesa, egl\\).*Could not initialize Direct3D")
list(APPEND FXDEMO_TESTS demo.rastertek50.window_refused)
