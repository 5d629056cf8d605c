#!/bin/bash
# The GPU run every session makes (sessions 12-15 kept their own copies as the record): each *_test binary of
# the bundle, vkd3d's HLSL suite through shader_test_runner, and the two demos' final images with their md5s.
# Usage (device tool): BUNDLE=.devbundle-sNN bash docs/report/device-runs/gpu-tests.sh, carrying .gl, $BUNDLE
# (t.tar.xz = {bin/,lib/,content/}) and .vkd3d-suite.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
R=$PWD; B=$R/${BUNDLE:?BUNDLE=.devbundle-sNN}
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-dev; ln -sfn /tmp/t/content /work/main/build-dev/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/gpu.txt
cd /work/main
for t in $(ls /tmp/t/bin | grep -E '_test$'); do
  timeout 200 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?" | tee -a $OUT/tests.txt
  grep -E "^\[  (PASSED|FAILED) |Failure|^\[  FAILED" /tmp/$t.log >> $OUT/tests.txt
done
timeout 300 /tmp/t/bin/shader_test_runner --suite $R/.vkd3d-suite --jobs 12 --cache /tmp/fxcache \
  --tsv $OUT/conformance-gpu.tsv --top 15 > $OUT/conformance-gpu.txt 2>&1; echo "runner rc=$?" >> $OUT/tests.txt
cd /tmp
for d in deferred lighting2d; do
  timeout 120 /tmp/t/bin/fxdemo $d --gpu --size 1920x1080 --frames 50 --out /tmp/o/$d > $OUT/$d.log 2>&1; echo "$d rc=$?" >> $OUT/tests.txt
done
(cd /tmp/o && md5sum */final.png) > $OUT/md5.txt
cp /tmp/o/lighting2d/final.png $OUT/lighting2d-final.png; cp /tmp/o/deferred/final.png $OUT/deferred-final.png
