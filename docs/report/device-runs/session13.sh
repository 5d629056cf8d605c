#!/bin/bash
# Session 13: after the seam2 merge (every GL call of device/ and effect/ behind the backend): the D3D11 and
# runtime tests that use the moved code, and the demos' md5 against session 12's. See session13.log.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
R=$PWD; B=$R/.devbundle-s13
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-dev; ln -sfn /tmp/t/content /work/main/build-dev/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd /work/main
for t in $(ls /tmp/t/bin | grep -E '_test$'); do
  timeout 150 /tmp/t/bin/$t > /tmp/$t.log 2>&1; echo "$t rc=$?"; grep -E "^\[  (PASSED|FAILED) |^\[  FAILED" /tmp/$t.log | head -8
done
cd /tmp
for d in deferred lighting2d; do timeout 100 /tmp/t/bin/fxdemo $d --gpu --size 1920x1080 --frames 50 --out /tmp/o/$d > /tmp/$d.log 2>&1; echo "$d rc=$?"; done
(cd /tmp/o && md5sum */final.png)
