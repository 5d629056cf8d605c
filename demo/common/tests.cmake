# Tests of what every fxdemo program shares (common/run_options.h: --check-finite, --define).
# --check-finite on a demo: a clean run says so (the demo's passes were scanned).
add_test(NAME demo.rastertek50.check-finite
         COMMAND fxdemo rastertek50 --size 64x48 --frames 1 --check-finite --out ${CMAKE_BINARY_DIR}/test-out/rastertek50-finite)
set_tests_properties(demo.rastertek50.check-finite PROPERTIES PASS_REGULAR_EXPRESSION "--check-finite: no NaN/Inf after [1-9]")
list(APPEND FXDEMO_TESTS demo.rastertek50.check-finite)

# --define NAME=VALUE (common/run_options.h) is how a user applies the suite's opt-in fixes to a
# demo. A define that breaks every effect ('float' -> '(') must surface as a compile error in that
# demo's own effect folder (so it reached the compiler), and a malformed one must be refused.
foreach(pair "deferred;xna-deferred" "pointlights;zima-lights" "lighting2d;lighting2d" "rastertek50;rastertek")
  list(GET pair 0 program)
  list(GET pair 1 folder)
  add_test(NAME demo.${program}.define_reaches_effects
           COMMAND fxdemo ${program} --size 64x48 --frames 1 --define "float=("
                   --out ${CMAKE_BINARY_DIR}/test-out/define-${program})
  set_tests_properties(demo.${program}.define_reaches_effects PROPERTIES
    PASS_REGULAR_EXPRESSION "hlsl/${folder}/[A-Za-z]+\\.fx\\([0-9]+,[0-9]+\\): error")
  list(APPEND FXDEMO_TESTS demo.${program}.define_reaches_effects)
endforeach()
add_test(NAME demo.define_malformed COMMAND fxdemo pointlights --define "pow(x, y)")
set_tests_properties(demo.define_malformed PROPERTIES PASS_REGULAR_EXPRESSION "--define wants NAME=VALUE, not 'pow\\(x, y\\)'")
list(APPEND FXDEMO_TESTS demo.define_malformed)
