# fxdemo report --quick: every demo's sweep at a tiny size, 1 timed frame; --check asserts what must
# hold on any machine (see checkReport in run_report.cpp).
add_test(NAME demo.report.quick
         COMMAND fxdemo report --quick --check --out ${CMAKE_BINARY_DIR}/test-out/report)
list(APPEND FXDEMO_QUALITY_TESTS demo.report.quick)
