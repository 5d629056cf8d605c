#!/bin/bash
# Session 11: after the merges of the compute/hull/domain, D3D11 and fxc-rejection branches and the
# stock-effect / vertex-input fixes: the GPU tests that touch the backend (D3D11 front end, compute and
# tessellation, stock effects, vertex inputs), vkd3d's HLSL suite on the H100 (EGL), two demos' images.
# Bundle: .devbundle-s11/t.tar.xz = {bin/,lib/,content/} of main at the measured commit
# (scripts/make-device-bundle build-dev tests/d3d11/d3d11_test tests/runtime/runtime_d3d11_stages_test
#  tests/runtime/runtime_stock_effects_test tests/runtime/runtime_vertex_input_binding_test
#  tests/runtime/runtime_conventions_test tests/runtime/runtime_hlsl_semantics_test
#  tests/runtime/runtime_compute_pass_test tests/conformance/shader_test_runner demo/fxdemo, plus
#  build-dev/content), the suite's files copied to .vkd3d-suite/.
# Run (device tool, carry .gl .devbundle-s11 .vkd3d-suite): bash docs/report/device-runs/session11.sh
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
R=$PWD; B=$R/.devbundle-s11
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-dev; ln -sfn /tmp/t/content /work/main/build-dev/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/gpu.txt
cd /work/main
for t in d3d11_test runtime_d3d11_stages_test runtime_stock_effects_test runtime_vertex_input_binding_test runtime_compute_pass_test runtime_conventions_test runtime_hlsl_semantics_test; do
  timeout 240 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?" | tee -a $OUT/tests.txt
  grep -E "^\[  (PASSED|FAILED) |Failure" /tmp/$t.log >> $OUT/tests.txt
done
timeout 400 /tmp/t/bin/shader_test_runner --suite $R/.vkd3d-suite --jobs 12 --cache /tmp/fxcache \
  --tsv $OUT/conformance-h100.tsv --top 15 > $OUT/conformance-h100.txt 2>&1; echo "runner rc=$?" >> $OUT/tests.txt
cd /tmp
for d in deferred lighting2d; do
  timeout 120 /tmp/t/bin/fxdemo $d --gpu --size 1920x1080 --frames 50 --out /tmp/o/$d > $OUT/$d.log 2>&1; echo "$d rc=$?" >> $OUT/tests.txt
done
(cd /tmp/o && md5sum */final.png) > $OUT/md5.txt
cp /tmp/o/lighting2d/final.png $OUT/lighting2d-final.png; cp /tmp/o/deferred/final.png $OUT/deferred-final.png
