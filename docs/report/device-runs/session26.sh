#!/bin/bash
# Session 26: after the d3d11 (Texture2DMSArray, stencil SRVs, typeless family views, sRGB targets, sampled 1D
# depth, XNA vertex textures), conformance (clip distances in hull/domain shaders, struct casts of calls, uniform
# structs holding objects) and rw27 (reversed smoothstep/clamp bounds, round half to even, int sign) merges.
# The device budget left after the fuzz runs allowed one short call: the changed test binaries first, then the
# demos' images, then vkd3d's suite (gpu-tests.sh's steps, in that order).
# Bundle: .devbundle-s26/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s26 .vkd3d-suite): bash docs/report/device-runs/session26.sh
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
R=$PWD; B=$R/.devbundle-s26
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-dev; ln -sfn /tmp/t/content /work/main/build-dev/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/gpu.txt
cd /work/main
for t in $(ls /tmp/t/bin | grep -E '_test$'); do
  timeout 60 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?" | tee -a $OUT/tests.txt
  grep -E "^\[  (PASSED|FAILED) |Failure|^\[  FAILED" /tmp/$t.log | tee -a $OUT/tests.txt
done
cd /tmp
for d in deferred lighting2d; do
  timeout 40 /tmp/t/bin/fxdemo $d --gpu --size 1920x1080 --frames 50 --out /tmp/o/$d > /dev/null 2>&1; echo "$d rc=$?" | tee -a $OUT/tests.txt
done
(cd /tmp/o && md5sum */final.png) | tee $OUT/md5.txt
cp /tmp/o/deferred/final.png $OUT/deferred-final.png
timeout 100 /tmp/t/bin/shader_test_runner --suite $R/.vkd3d-suite --jobs 14 --cache /tmp/fxcache \
  --tsv $OUT/conformance-gpu.tsv --top 10 > $OUT/conformance-gpu.txt 2>&1; echo "runner rc=$?" | tee -a $OUT/tests.txt
awk -F'\t' 'NR>1{c+=$3;r+=$5;p+=$7} END{print "suite on GPU: compiled",c,"rejected",r,"probes",p}' $OUT/conformance-gpu.tsv | tee -a $OUT/tests.txt
