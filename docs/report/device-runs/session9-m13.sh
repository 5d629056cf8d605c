#!/bin/bash
# Session 9 (m13, main after the review refactor: typed compute-pass cache keys): texel-copy reductions (8x32 workgroups), blends onto a zero clear as
# writes, clears in the bounds; the four demos both ways, the default, 10 000 lights, GPU tests.
# Bundle: .devbundle-m13/t.tar.xz = {bin/,lib/,content/} of main at the measured commit
# (scripts/make-device-bundle build-cc demo/fxdemo tests/runtime/runtime_texel_copies_test
#  tests/runtime/runtime_compute_pass_test tests/runtime/runtime_deferred_clear_test).
# Run (device tool, carry .devbundle-m13): bash .devbundle-m13/m13.sh
set -u
R=$PWD; B=$R/.devbundle-m13
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/gpu.txt
cd /work/main
for t in runtime_texel_copies_test runtime_compute_pass_test runtime_deferred_clear_test; do
  timeout 240 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?" | tee -a $OUT/tests.txt
  grep -E "^\[  (PASSED|FAILED) |Failure" /tmp/$t.log >> $OUT/tests.txt
done
L=$OUT/m13.log
cd /tmp
run() { # label env... -- fxdemo args
  local label=$1; shift
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  echo "=== $label: ${envs[*]} fxdemo $*" >>$L
  env ${envs[@]+"${envs[@]}"} /tmp/t/bin/fxdemo "$@" --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L
}
G="--gpu --size 1920x1080 --frames 200 --bounds"
for d in deferred lighting2d pointlights rastertek50; do
  for i in 1; do
    run $d-fragment-$i FXPORT_COMPUTE_PASSES=0 -- $d $G
    run $d-default-$i -- $d $G
  done
done
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
for d in deferred lighting2d pointlights rastertek50; do
  for f in final debug; do python3 $B/pngdiff.py /tmp/o/$d-fragment-1/$f.png /tmp/o/$d-default-1/$f.png >> $OUT/pngdiff.txt 2>&1; done
  for f in /tmp/o/$d-fragment-1/targets/*.png; do [ -e "$f" ] || continue; cmp -s $f /tmp/o/$d-default-1/targets/$(basename $f) && echo "same $d/$(basename $f)" || echo "DIFF $d/$(basename $f)"; done >> $OUT/pngdiff.txt
done
cp /tmp/o/lighting2d-default-1/final.png $OUT/lighting2d-default-final.png
cp /tmp/o/pointlights-default-1/final.png $OUT/pointlights-default-final.png
awk '/^=== /{l=$2} /^  frame /{print l, $0} /^rc=[^0]/{print l, $0}' $L
grep -E "FAIL" $L | head; grep -c "occlusion vs GPU unwrap.*max 0 " $L
grep "rc=" $OUT/tests.txt
grep -c "^same" $OUT/pngdiff.txt; grep -v "^same" $OUT/pngdiff.txt | head; grep final $OUT/md5.txt
