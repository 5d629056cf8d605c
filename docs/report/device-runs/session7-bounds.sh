#!/bin/bash
# Copied from .devbundle-bb/ (a device-tool bundle: fxdemo and runtime_compute_pass_test of main, see docs/report/compute-passes.md).
# Compute passes with dispatches clipped to the triangles' bounds: the GPU test and deferred/lighting2d both ways.
set -u
R=$PWD; B=$R/.devbundle-bb
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
(cd /work/main && /tmp/t/bin/runtime_compute_pass_test --gtest_brief=1 2>&1 | grep -E "compute vs|PASSED|FAILED|Failure" > $OUT/test.log; echo "rc=${PIPESTATUS[0]}" >> $OUT/test.log)
cat $OUT/test.log
L=$OUT/m5.log
cd /tmp
for d in deferred lighting2d; do
  for m in 0 1; do
    echo "=== $d-$m: FXPORT_COMPUTE_PASSES=$m fxdemo $d --gpu --size 1920x1080 --frames 200 --bounds" >> $L
    FXPORT_COMPUTE_PASSES=$m /tmp/t/fxdemo $d --gpu --size 1920x1080 --frames 200 --bounds --out /tmp/o/$d-$m >> $L 2>&1; echo "rc=$?" >> $L
  done
  for f in final debug; do python3 $B/pngdiff.py /tmp/o/$d-0/$f.png /tmp/o/$d-1/$f.png >> $OUT/pngdiff.txt 2>&1; done
done
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
grep -E "^===|^  [A-Z]|rc=" $L | grep -v "fill GB\|clear " 
cat $OUT/pngdiff.txt $OUT/md5.txt
