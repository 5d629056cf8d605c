#!/bin/bash
# Session 17: issue 26's million executions of the loose-shader harness in ONE run, on the two-GPU machine's
# 32 cores (only the CPUs are used). Bundle: .devbundle-s17/fz.tar.xz = bin/fuzz_shader_files (scripts/fuzz's
# build-fuzz/ of main (7f2e1a9 for the first run, 13c5552 for the second): clang 14, -fsanitize=fuzzer,address,undefined, glslang/SPIRV-Cross linked
# statically; strip -g) and corpus/shader_files (session 16's grown corpus: 3 265 inputs grown from tests/fuzz/make-corpus
# seeds; the second run adds the first run's two crash inputs). fuzz_cache_entry already ran 1.85 M executions in one run (session16-fuzz.sh).
# Run (device tool, kind nvidia-h100-x2, carry .devbundle-s17): bash docs/report/device-runs/session17-fuzz.sh
set -u
T=${T:-450}
R=$PWD; mkdir -p /tmp/fz && tar xJf .devbundle-s17/fz.tar.xz -C /tmp/fz
cd /tmp/fz && mkdir -p runs/s
(nproc; python3 --version; uname -m) > $OUT/machine.txt 2>&1
J=${SF:-$(( $(nproc) - 1 ))}
timeout $((T+30)) bin/fuzz_shader_files -dict=$R/tests/fuzz/hlsl.dict -fork=$J -ignore_crashes=1 -ignore_timeouts=1 \
  -ignore_ooms=1 -max_total_time=$T -timeout=30 -rss_limit_mb=3072 -max_len=65536 -artifact_prefix=runs/s/ \
  corpus/shader_files > $OUT/shader_files.log 2>&1
echo "fuzz rc=$? workers=$J" >> $OUT/summary.txt
ls runs/s > $OUT/findings.txt 2>&1
echo "shader_files corpus $(ls corpus/shader_files | wc -l)" >> $OUT/summary.txt
grep -E "^#[0-9]+: cov" $OUT/shader_files.log | tail -1 >> $OUT/summary.txt
grep -E "INFO: (fuzzed|exiting)|crash|timeout|oom" $OUT/shader_files.log | tail -5 >> $OUT/summary.txt
# Every input of the grown corpus replayed once, in process, with a 2 s limit: no answer may take longer.
(cd corpus/shader_files && ls | timeout 50 xargs -P $(nproc) -n 40 ../../bin/fuzz_shader_files -timeout=2 > $OUT/shader_files-replay.log 2>&1; echo "shader replay rc=$?" >> $OUT/summary.txt)
# Inputs the replay found over the limit come back (the first run's slow input was lost with its corpus).
mkdir -p runs/slow && grep -B4 "timeout after" $OUT/shader_files-replay.log | sed -n 's/^Running: //p' | while read n; do cp corpus/shader_files/$n runs/slow/; done
tar cf - runs | xz -T0 > $OUT/findings.tar.xz
cat $OUT/summary.txt
