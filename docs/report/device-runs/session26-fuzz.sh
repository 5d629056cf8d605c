#!/bin/bash
# Session 26: issue 26's proof, 1 M executions in one run of the loose-shader harness (fuzz_shader_files)
# and of the cache-entry harness (fuzz_cache_entry), with fuzz_compile beside them, on the two-GPU machine's
# 32 cores. New since session 25: -entropic=0 (scripts/fuzz says why: 5-6x the executions a second).
# Bundle: .devbundle-s26/fz.tar.xz = bin/{fuzz_shader_files,fuzz_cache_entry,fuzz_compile} (scripts/fuzz's
# build-fuzz/ of main at the commit in the log: clang 14, -O1, -fsanitize=fuzzer,address,undefined; stripped),
# lib/ (scripts/make-device-bundle) and corpus/{shader_files,cache_entry,compile} (build-fuzz/runs/*/corpus).
# Run (device tool, kind nvidia-h200-x2, carry .devbundle-s26): bash docs/report/device-runs/session26-fuzz.sh
# Run 1: the defaults (T=380, forks 21/4/6). Run 2: T=470 S=30 K=0 C=0 REPLAY=80 (every core for the loose-shader
# harness). Run 3: T=540 S=31 K=0 C=0 REPLAY=0 (no replay: the whole call for executions).
set -u
T=${T:-380} S=${S:-21} K=${K:-4} C=${C:-6} REPLAY=${REPLAY:-120}
R=$PWD; mkdir -p /tmp/fz && tar xJf .devbundle-s26/fz.tar.xz -C /tmp/fz
cd /tmp/fz && mkdir -p runs/s runs/k runs/c
export LD_LIBRARY_PATH=/tmp/fz/lib
(nproc; uname -m; date -u) > $OUT/machine.txt 2>&1
common=(-entropic=0 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -max_total_time=$T -timeout=30)
[ $S = 0 ] || timeout $((T+60)) bin/fuzz_shader_files -dict=$R/tests/fuzz/hlsl.dict -fork=$S "${common[@]}" -rss_limit_mb=4096 \
  -max_len=65536 -artifact_prefix=runs/s/ corpus/shader_files > $OUT/shader_files.log 2>&1 &
[ $K = 0 ] || timeout $((T+60)) bin/fuzz_cache_entry -fork=$K "${common[@]}" -rss_limit_mb=2048 -max_len=262144 \
  -artifact_prefix=runs/k/ corpus/cache_entry > $OUT/cache_entry.log 2>&1 &
[ $C = 0 ] || timeout $((T+60)) bin/fuzz_compile -dict=$R/tests/fuzz/hlsl.dict -fork=$C "${common[@]}" -rss_limit_mb=4096 \
  -max_len=65536 -artifact_prefix=runs/c/ corpus/compile > $OUT/compile.log 2>&1 &
wait
# "No answer over 2 s": every input of each grown corpus once more, in process, with a 2 s limit (16 at a time).
run=(); [ $S = 0 ] || run+=(shader_files); [ $K = 0 ] || run+=(cache_entry); [ $C = 0 ] || run+=(compile)
replayed=(); [ $REPLAY = 0 ] || replayed=("${run[@]}")
for h in "${replayed[@]}"; do
  ls corpus/$h | wc -l > $OUT/$h.corpus-size
  ls corpus/$h | split -n r/16 - /tmp/part.$h.
  for p in /tmp/part.$h.*; do (cd corpus/$h && timeout $REPLAY ../../bin/fuzz_$h -entropic=0 -runs=0 -timeout=2 -rss_limit_mb=4096 \
      -artifact_prefix=../../runs/replay-$h- $(cat $p) > $p.log 2>&1; echo "$p rc=$?" >> $OUT/$h.replay-rc) & done; wait
  grep -hE "ERROR|timeout|SUMMARY" /tmp/part.$h.*.log | head -20 > $OUT/$h.replay-findings
done
for h in "${run[@]}"; do echo "$h: $(grep -E "^#[0-9]+: cov" $OUT/$h.log | tail -1)"; done > $OUT/summary.txt
ls -la runs/* > /tmp/findings.txt 2>&1
# The device tool brings back only a few files: one archive of the logs, the summaries and the findings.
cp /tmp/findings.txt /tmp/part.*.log $OUT/ 2>/dev/null; mkdir -p /tmp/res && mv $OUT/* /tmp/res/ && cp -r runs /tmp/res/
tar cJf $OUT/results.tar.xz -C /tmp/res . && cat /tmp/res/summary.txt /tmp/res/*.corpus-size /tmp/res/*.replay-findings
