#!/bin/bash
# Session 25: issue 26's fuzzing of the rewrites added since the last long runs (sessions 23-25: static
# initializer scopes, gathers with offsets, attribute case, qualified casts, struct samplers, semantic
# widths, ...) on the GPU machine's 16 idle cores: fuzz_compile (whole effects, front end in process) and
# fuzz_shader_files (loose shaders, entry points named in each file), 7 forks each.
# Bundle: .devbundle-s25/fz.tar.xz = bin/{fuzz_compile,fuzz_shader_files} (scripts/fuzz's build-fuzz/ of
# main at the commit in the log: clang 14, -O1, -fsanitize=fuzzer,address,undefined), lib/ (make-device-bundle)
# and corpus/{compile,shader_files} (tests/fuzz/make-corpus seeds, tests/fuzz/seeds included).
# Run (device tool, carry .devbundle-s25): bash docs/report/device-runs/session25-fuzz.sh
set -u
T=${T:-450}
R=$PWD; mkdir -p /tmp/fz && tar xJf .devbundle-s25/fz.tar.xz -C /tmp/fz
cd /tmp/fz && mkdir -p runs/c runs/s
export LD_LIBRARY_PATH=/tmp/fz/lib
(nproc; uname -m) > $OUT/machine.txt 2>&1
timeout $((T+60)) bin/fuzz_compile -dict=$R/tests/fuzz/hlsl.dict -fork=7 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_total_time=$T -timeout=30 -rss_limit_mb=4096 -max_len=65536 -artifact_prefix=runs/c/ corpus/compile > $OUT/compile.log 2>&1 &
timeout $((T+60)) bin/fuzz_shader_files -dict=$R/tests/fuzz/hlsl.dict -fork=7 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_total_time=$T -timeout=30 -rss_limit_mb=4096 -max_len=65536 -artifact_prefix=runs/s/ corpus/shader_files > $OUT/shader_files.log 2>&1 &
wait
# Each crash replayed in process: its innermost frame says whose it is (glslang's are contained by fxport's worker).
for f in runs/c/* runs/s/*; do [ -f "$f" ] || continue; case $f in runs/c/*) b=bin/fuzz_compile;; *) b=bin/fuzz_shader_files;; esac
  echo "== $f" >> $OUT/replays.txt; timeout 60 $b -timeout=30 "$f" 2>&1 | grep -E "^ +#[0-3] |ERROR|SUMMARY" | head -8 >> $OUT/replays.txt; done
for h in compile shader_files; do echo "$h corpus $(ls corpus/$h | wc -l)" >> $OUT/summary.txt
  grep -E "^#[0-9]+: cov" $OUT/$h.log | tail -1 >> $OUT/summary.txt; grep -cE "crash|deadly" $OUT/$h.log >> $OUT/summary.txt; done
ls runs/c runs/s > $OUT/findings.txt 2>&1
tar cf - runs | xz > $OUT/findings.tar.xz
