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

# Tools that explain themselves (issue 12 item 4). `fxdemo --help` lists every program; each answers
# --help with its options (exit 0); a bad option is ONE line on stderr naming the option and the
# value, "fxdemo <program>: <option> wants <what>, not '<value>'", exit 2 (common/run_options.h).

set(FXDEMO_PROGRAM_NAMES deferred pointlights lighting2d rastertek50 report stability)
set(FXDEMO_SORTED_NAMES ${FXDEMO_PROGRAM_NAMES})
list(SORT FXDEMO_SORTED_NAMES)  # fxdemo --help lists them by name
string(JOIN ".*" FXDEMO_PROGRAM_LIST ${FXDEMO_SORTED_NAMES})
add_test(NAME demo.cli.help
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>|--help" -DEXIT=0 "-DSTDOUT=programs:.*${FXDEMO_PROGRAM_LIST}"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
add_test(NAME demo.cli.no_program
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>" -DEXIT=2 "-DSTDERR=usage: fxdemo <program>"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
add_test(NAME demo.cli.unknown_program
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>|nosuchdemo" -DEXIT=2 "-DSTDERR=^fxdemo: unknown program 'nosuchdemo'"
                 -DONE_LINE=ON -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
list(APPEND FXDEMO_TESTS demo.cli.help demo.cli.no_program demo.cli.unknown_program)
foreach(program ${FXDEMO_PROGRAM_NAMES})
  add_test(NAME demo.cli.${program}.help
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>|${program}|--help" -DEXIT=0
                   "-DSTDOUT=^usage: fxdemo ${program} .*--out DIR" -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
  list(APPEND FXDEMO_TESTS demo.cli.${program}.help)
endforeach()

# The table: program | arguments | what the one line must say (regex). Every row: exit 2, one line
# on stderr starting "fxdemo <program>: ", nothing on stdout, no exception's bare name.
set(FXDEMO_BAD_OPTIONS
  "size_zero|--size|0x0|--size wants WxH.*, not '0x0'$"
  "size_negative|--size|-5x10|--size wants WxH.*, not '-5x10'$"
  "size_text|--size|big|--size wants WxH.*, not 'big'$"
  "size_missing|--size|--size wants WxH.*, not '' \\(no value given\\)$"
  "size_above_driver|--size|99999x99999|--size wants W and H from 1 to [0-9]+ \\(the driver's GL_MAX_TEXTURE_SIZE\\), not '99999x99999'$"
  "frames_zero|--frames|0|--frames wants a positive number, not '0'$"
  "frames_text|--frames|many|--frames wants a positive number, not 'many'$"
  "unknown|--no-such-option|unknown option '--no-such-option' \\(fxdemo [a-z0-9]+ --help lists the options\\)$")
foreach(program ${FXDEMO_PROGRAM_NAMES})
  foreach(row ${FXDEMO_BAD_OPTIONS})
    string(REPLACE "|" ";" fields "${row}")
    list(POP_FRONT fields case)
    list(POP_BACK fields expected)
    string(JOIN "|" arguments ${fields})
    if(program STREQUAL "stability" AND case MATCHES "^size_(above_driver|text)$")
      # The suite's --size is N (or NxN) in 1..4096.
      string(REGEX REPLACE "--size wants .*, not" "--size wants N \\\\(or NxN\\\\) in 1..4096, not" expected "${expected}")
    endif()
    add_test(NAME demo.cli.${program}.bad.${case}
             COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>|${program}|${arguments}" -DEXIT=2
                     "-DSTDERR=^fxdemo ${program}: ${expected}" -DONE_LINE=ON -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
    list(APPEND FXDEMO_TESTS demo.cli.${program}.bad.${case})
  endforeach()
endforeach()
# Each program's own options, one bad value each.
set(FXDEMO_BAD_OWN_OPTIONS
  "deferred|gbuffer|--gbuffer|rgb565|--gbuffer wants tutorial, color8 or float32, not 'rgb565'$"
  "deferred|spot_shadow|--spot-shadow|100|--spot-shadow wants a size in 256..4096, not '100'$"
  "deferred|camera|--camera|1,2,3|--camera wants PX,PY,PZ,TX,TY,TZ, not '1,2,3'$"
  "pointlights|time|--time|soon|--time wants seconds, not 'soon'$"
  "pointlights|gbuffer|--gbuffer|rgb565|--gbuffer wants tutorial, half16 or float32, not 'rgb565'$"
  "lighting2d|lights|--lights|x|--lights wants the letters s \\(spot\\) and p \\(point\\), not 'x'$"
  "rastertek50|hlsl_missing|--hlsl|--hlsl wants a folder, not '' \\(no value given\\)$"
  "report|demos|--demos|tetris|--demos wants a comma-separated list of rastertek50, lighting2d, pointlights, deferred, not 'tetris'$"
  "stability|size_zero_n|--size|0|--size wants N \\(or NxN\\) in 1..4096, not '0'$"
  "pointlights|define|--define|pow(x, y)|--define wants NAME=VALUE, not 'pow\\(x, y\\)'$")
foreach(row ${FXDEMO_BAD_OWN_OPTIONS})
  string(REPLACE "|" ";" fields "${row}")
  list(POP_FRONT fields program case)
  list(POP_BACK fields expected)
  string(JOIN "|" arguments ${fields})
  add_test(NAME demo.cli.${program}.bad.${case}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:fxdemo>|${program}|${arguments}" -DEXIT=2
                   "-DSTDERR=^fxdemo ${program}: ${expected}" -DONE_LINE=ON -P ${CMAKE_CURRENT_SOURCE_DIR}/common/expect_run.cmake)
  list(APPEND FXDEMO_TESTS demo.cli.${program}.bad.${case})
endforeach()
