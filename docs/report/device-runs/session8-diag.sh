#!/bin/bash
# Session 8 diagnostic: GPU tests' exit codes, and each deferred candidate draw's outcome on the GPU.
set -u
R=$PWD; B=$R/.devbundle-m6
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
cd /work/main
for t in runtime_compute_pass_test runtime_gpu_limits_test render_deferred_test; do
  timeout 240 /tmp/t/bin/$t > $OUT/$t.log 2>&1; echo "$t rc=$?"; grep -E "^\[  (PASSED|FAILED) |Failure" $OUT/$t.log | head -5
done
FXPORT_COMPUTE_PASSES=0 timeout 240 /tmp/t/bin/render_deferred_test > /dev/null 2>&1; echo "render_deferred_test (FXPORT_COMPUTE_PASSES=0) rc=$?"
cd /tmp
echo "=== outcomes, deferred 3 frames (FXPORT_COMPUTE_PASSES_DEBUG=1)"
FXPORT_COMPUTE_PASSES=1 FXPORT_COMPUTE_PASSES_DEBUG=1 /tmp/t/bin/fxdemo deferred --gpu --size 1920x1080 --frames 3 --out /tmp/o/dbg 2>&1 | grep "compute pass" | sed 's/[0-9.]* MiB/N MiB/' | sort | uniq -c | sort -rn | head -30
for h in 1 0; do
  echo "=== deferred compute, FXPORT_HONOUR_DISCARDS=$h"
  FXPORT_COMPUTE_PASSES=1 FXPORT_HONOUR_DISCARDS=$h /tmp/t/bin/fxdemo deferred --gpu --size 1920x1080 --frames 100 --bounds --out /tmp/o/h$h 2>&1 | grep -E "^  (ClearGBuffer|SSAO|frame)"
done
