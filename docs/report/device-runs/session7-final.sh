#!/bin/bash
# Copied from .devbundle-final/ (a device-tool bundle; see docs/fuzzing.md and docs/report/compute-passes.md).
# Session 7 final device call: fuzzers in the background (nice 19) on 14 cores; GPU tests through EGL
# (with and without FXPORT_COMPUTE_PASSES); the compute-pass timing run (m4.sh).
set -u
R=$PWD
FINAL_OUT=$OUT
B=$R/.devbundle-final
# 1. fuzzers
mkdir -p /tmp/fz && cd /tmp/fz && tar xJf "$B/fz.tar.xz" && ln -sfn "$R/hlsl" hlsl && ln -sfn "$R/tests/fixtures" tests/fixtures
mkdir -p runs/c runs/cli
T=${T:-500}
nice -n 19 timeout $((T+30)) bin/fuzz_compile -dict=tests/fuzz/hlsl.dict -fork=${CF:-14} -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -max_total_time=$T -timeout=30 -rss_limit_mb=4096 -max_len=65536 -artifact_prefix=runs/c/ corpus/compile > runs/compile.log 2>&1 &
for i in 1; do FUZZ_WORKER_SECONDS=2 nice -n 19 timeout $T python3 -u tests/fuzz/fuzz-cli bin/fxport runs/cli/$i 1000000 $((700+i)) 200 > runs/cli/$i.log 2>&1 & done
# 2. unpack the GPU bundle (compiled-in paths point at /work/main)
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
mkdir -p /usr/share/fonts/truetype/dejavu && cp /tmp/t/fonts/* /usr/share/fonts/truetype/dejavu/ 2>/dev/null
# 3. perf (m4)
cd "$R"; mkdir -p /tmp/perfout
OUT=/tmp/perfout bash $B/m4.sh
cd /tmp/perfout && tar cf $FINAL_OUT/perf.tar .
# 4. GPU tests, with and without compute passes
G=$FINAL_OUT/gpu-tests.log
nvidia-smi --query-gpu=name,driver_version --format=csv > $G
for t in $(ls /tmp/t/bin); do
  cp=1; [ $t = runtime_compute_pass_test ] && cp=
  echo "=== $t FXPORT_COMPUTE_PASSES=$cp" >> $G
  (cd /work/main && env ${cp:+FXPORT_COMPUTE_PASSES=$cp} LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/tcache timeout 90 /tmp/t/bin/$t --gtest_brief=1 >> $G 2>&1; echo "rc=$?" >> $G)
done
grep -E "^===|PASSED|FAILED|rc=" $G
# 5. fuzz results
wait
cd /tmp/fz
grep -E "^#[0-9]+" runs/compile.log | tail -1
for i in 1; do tail -n 1 runs/cli/$i.log; done
n=0; for c in runs/c/crash-* runs/c/timeout-* runs/c/oom-*; do [ -e "$c" ] || continue; n=$((n+1)); [ $n -gt 10 ] && break; timeout 30 bin/fuzz_compile -timeout=20 "$c" > "$c.replay" 2>&1; done
ls runs/c
rm -rf runs/cli/*/work
tar cJf $FINAL_OUT/runs.tar.xz runs
tar cJf $FINAL_OUT/corpus.tar.xz corpus
