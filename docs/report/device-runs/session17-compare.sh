#!/bin/bash
# Session 17: the two tests that failed in session17.sh on the H200, with this session's binaries (s17g) and with
# ea87180's (s17old: a CI clone's build, before the viewport change), to tell what the change did from what
# the GPU always did. Run (device tool, carry .gl .devbundle-s17g .devbundle-s17old): bash docs/report/device-runs/session17-compare.sh
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
R=$PWD
for v in ${VERSIONS:-s17g s17old}; do
  mkdir -p /tmp/$v && tar xJf .devbundle-$v/t.tar.xz -C /tmp/$v
  [ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
  mkdir -p /work/main/build-dev; ln -sfn /tmp/$v/content /work/main/build-dev/content
  # the old build (a CI clone of ea87180 in /tmp/ci18) looks for its sources and content there
  mkdir -p /tmp/ci18/build; ln -sfn "$R/hlsl" /tmp/ci18/hlsl; ln -sfn /tmp/$v/content /tmp/ci18/build/content
  cd /work/main
  echo "=== $v"
  LD_LIBRARY_PATH=/tmp/$v/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxc-$v timeout 200 /tmp/$v/bin/render_deferred_test --gtest_filter='*WholeFrame*' 2>&1 | grep -vE "^\[ +(RUN|OK) " | tail -25
  LD_LIBRARY_PATH=/tmp/$v/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxc-$v timeout 200 /tmp/$v/bin/runtime_texture_filtering_test 2>&1 | grep -E "Failure|FAILED|PASSED|Expected|Which|actual" | head -8
  rm -f /work/main/build-dev/content; cd $R
done
