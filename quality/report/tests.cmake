# fxdemo report --quick: every demo's sweep at a tiny size, 1 timed frame; --check asserts what must
# hold on any machine (see checkReport in run_report.cpp).
add_test(NAME demo.report.quick
         COMMAND fxdemo report --quick --check --out ${CMAKE_BINARY_DIR}/test-out/report)
list(APPEND FXDEMO_QUALITY_TESTS demo.report.quick)

# Issue 16: with --bounds each pass's time in report.md has its bound's two terms (fill, texture
# fetches), the bound and the ratio beside it.
add_test(NAME demo.report.bounds
         COMMAND fxdemo report --quick --bounds --demos rastertek50 --out ${CMAKE_BINARY_DIR}/test-out/report-bounds)
set_tests_properties(demo.report.bounds PROPERTIES
                     PASS_REGULAR_EXPRESSION "Deferred [0-9.]+ \\(fill [0-9.]+ fetch [0-9.]+ bound [0-9.]+ x[0-9.]+\\)")
list(APPEND FXDEMO_QUALITY_TESTS demo.report.bounds)
