#!/bin/bash
# Session 8 (m8, the final main after review): exact compute passes (replayed interpolants) and bounds with fetches on the H100.
# Bundle: .devbundle-m6/t.tar.xz = {bin/,lib/,fxdemo,content/} of main at the measured commit
# (scripts/make-device-bundle build-cc demo/fxdemo tests/runtime/runtime_compute_pass_test).
# Run (device tool, carry .devbundle-m6): bash .devbundle-m6/m6.sh
set -u
R=$PWD; B=$R/.devbundle-m6
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/gpu.txt
# GPU tests, compute passes as the default leaves them (the rule: on here), then forced off for the render test.
cd /work/main
for t in runtime_compute_pass_test runtime_gpu_limits_test render_deferred_test; do
  timeout 240 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?" | tee -a $OUT/tests.txt
  grep -E "^\[  (PASSED|FAILED) |Failure|compute vs" /tmp/$t.log >> $OUT/tests.txt
done
FXPORT_COMPUTE_PASSES=0 timeout 240 /tmp/t/bin/render_deferred_test > /tmp/rd-off.log 2>&1; echo "render_deferred_test (FXPORT_COMPUTE_PASSES=0) rc=$?" | tee -a $OUT/tests.txt
L=$OUT/m8.log
cd /tmp
run() { # label env... -- fxdemo args
  local label=$1; shift
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  echo "=== $label: ${envs[*]} fxdemo $*" >>$L
  env ${envs[@]+"${envs[@]}"} /tmp/t/bin/fxdemo "$@" --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L
}
G="--gpu --size 1920x1080 --frames 200 --bounds"
for d in deferred lighting2d pointlights rastertek50; do
  run $d-fragment-1 FXPORT_COMPUTE_PASSES=0 -- $d $G
  run $d-compute-1 FXPORT_COMPUTE_PASSES=1 -- $d $G
done
for d in deferred lighting2d; do run $d-default -- $d $G; done
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
for d in deferred lighting2d pointlights rastertek50; do
  for f in final debug; do python3 $B/pngdiff.py /tmp/o/$d-fragment-1/$f.png /tmp/o/$d-compute-1/$f.png >> $OUT/pngdiff.txt 2>&1; done
done
awk '/^=== /{l=$2} /^  frame /{print l, $0} /^rc=[^0]/{print l, $0}' $L
grep "rc=" $OUT/tests.txt
cat $OUT/pngdiff.txt; cat $OUT/md5.txt | grep final
