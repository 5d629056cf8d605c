#!/bin/bash
# Session 9 (m9): texel-copy reductions (lighting2d's occlusion map as one dispatch) on the H100.
# Bundle: .devbundle-m9/t.tar.xz = {bin/,lib/,content/} of main at the measured commit
# (scripts/make-device-bundle build-cc demo/fxdemo tests/runtime/runtime_texel_copies_test tests/runtime/runtime_compute_pass_test).
# Run (device tool, carry .devbundle-m9): bash .devbundle-m9/m9.sh
set -u
R=$PWD; B=$R/.devbundle-m9
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
L=$OUT/m9.log
cd /tmp
run() { # label env... -- fxdemo args
  local label=$1; shift
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  echo "=== $label: ${envs[*]} fxdemo $*" >>$L
  env ${envs[@]+"${envs[@]}"} /tmp/t/bin/fxdemo "$@" --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L
}
G="--gpu --size 1920x1080 --frames 200 --bounds"
for i in 1 2; do
  run lighting2d-fragment-$i FXPORT_COMPUTE_PASSES=0 -- lighting2d $G
  run lighting2d-default-$i -- lighting2d $G
done
for d in deferred pointlights rastertek50; do run $d-default -- $d $G; run $d-fragment FXPORT_COMPUTE_PASSES=0 -- $d $G; done
run lighting2d-check-compute FXPORT_COMPUTE_PASSES=1 -- lighting2d --gpu --size 1920x1080 --frames 1 --check
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
for f in final debug; do python3 $B/pngdiff.py /tmp/o/lighting2d-fragment-1/$f.png /tmp/o/lighting2d-default-1/$f.png >> $OUT/pngdiff.txt 2>&1; done
for t in occlusionMap; do ls /tmp/o/lighting2d-default-1/targets/ | head -40 > $OUT/targets.txt; done
for f in /tmp/o/lighting2d-fragment-1/targets/*.png; do cmp -s $f /tmp/o/lighting2d-default-1/targets/$(basename $f) && echo "same $(basename $f)" || echo "DIFF $(basename $f)"; done >> $OUT/pngdiff.txt
cp /tmp/o/lighting2d-default-1/final.png $OUT/lighting2d-default-final.png
awk '/^=== /{l=$2} /^  frame /{print l, $0} /^rc=[^0]/{print l, $0}' $L
grep -E "occlusion|FAIL|ok$" $L | sort | uniq -c | head -20
grep "rc=" $OUT/tests.txt
cat $OUT/pngdiff.txt | sort | uniq -c | head; grep final $OUT/md5.txt
