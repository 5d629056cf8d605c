#!/bin/bash
# Session 16: issue 26's million executions of the loose-shader and cache-entry harnesses on the GPU machine's
# 16 idle cores. Bundle: .devbundle-s16/fz.tar.xz = bin/{fuzz_shader_files,fuzz_cache_entry} (scripts/fuzz's
# build-fuzz/ of main ea87180: clang 14, -fsanitize=fuzzer,address,undefined, glslang/SPIRV-Cross linked
# statically; strip -g) and corpus/{shader_files,cache_entry} (tests/fuzz/make-corpus seeds).
# Run (device tool, carry .devbundle-s16): bash docs/report/device-runs/session16-fuzz.sh
set -u
T=${T:-470}
# Second run (BUNDLE=fz2.tar.xz: the first run's grown corpora; KF=0 leaves fuzz_cache_entry out).
R=$PWD; mkdir -p /tmp/fz && tar xJf .devbundle-s16/${BUNDLE:-fz.tar.xz} -C /tmp/fz
cd /tmp/fz && mkdir -p runs/s runs/k
(nproc; python3 --version; uname -m) > $OUT/machine.txt 2>&1
timeout $((T+40)) bin/fuzz_shader_files -dict=$R/tests/fuzz/hlsl.dict -fork=${SF:-13} -ignore_crashes=1 -ignore_timeouts=1 \
  -ignore_ooms=1 -max_total_time=$T -timeout=30 -rss_limit_mb=4096 -max_len=65536 -artifact_prefix=runs/s/ \
  corpus/shader_files > $OUT/shader_files.log 2>&1 &
[ "${KF:-3}" = 0 ] || timeout $((T+40)) bin/fuzz_cache_entry -fork=${KF:-3} -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_total_time=$T -timeout=30 -rss_limit_mb=2048 -max_len=262144 -artifact_prefix=runs/k/ \
  corpus/cache_entry > $OUT/cache_entry.log 2>&1 &
wait
# Every input of the grown corpora replayed once, in process, with a 2 s limit: no answer may take longer.
timeout 60 bin/fuzz_cache_entry -runs=0 -timeout=2 corpus/cache_entry > $OUT/cache_entry-replay.log 2>&1; echo "cache replay rc=$?" >> $OUT/summary.txt
(cd corpus/shader_files && ls | timeout 70 xargs -P 16 -n 40 ../../bin/fuzz_shader_files -timeout=2 > $OUT/shader_files-replay.log 2>&1; echo "shader replay rc=$?" >> $OUT/summary.txt)
ls runs/s runs/k > $OUT/findings.txt 2>&1
tar cf - runs | xz > $OUT/findings.tar.xz
for h in shader_files cache_entry; do echo "$h corpus $(ls corpus/$h | wc -l)" >> $OUT/summary.txt; grep -E "^#[0-9]+: cov" $OUT/$h.log | tail -1 >> $OUT/summary.txt; grep -E "INFO: (fuzzed|exiting)|crash|timeout|oom" $OUT/$h.log | tail -5 >> $OUT/summary.txt; done
tar cf - corpus | xz > $OUT/corpus.tar.xz
