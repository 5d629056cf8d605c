# Read by ctest (TEST_INCLUDE_FILES of the top directory, FXPORT_SANITIZE builds only) before it
# starts any test: the sanitizer settings every test process inherits, so that a plain `ctest` in a
# sanitizer build runs as scripts/sanitize-tests does. A setting already in the environment wins.
#  - LeakSanitizer reads tests/support/lsan.supp (leaks inside Mesa and fontconfig, each explained
#    there); print_suppressions=0 keeps its "Suppressions used" table off stderr, which CLI tests match.
#  - UBSan prints the stack and stops at the first report (the build has -fno-sanitize-recover too).
# Test binaries linking fxport_test_gl read lsan.supp also when run by hand (__lsan_default_options).
if(NOT DEFINED ENV{ASAN_OPTIONS})
  set(ENV{ASAN_OPTIONS} "detect_leaks=1")
endif()
if(NOT DEFINED ENV{LSAN_OPTIONS})
  set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
if(NOT DEFINED ENV{UBSAN_OPTIONS})
  set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
endif()
