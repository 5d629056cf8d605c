# Device machine only (it points /work/wt/perf at the unpacked bundle): never run it on a workstation.
# sourced on the device: unpack the bundle where the binary's compiled-in paths point
set -e
mkdir -p /tmp/b && tar xJf .devbundle-perf/b.tar.xz -C /tmp/b
mkdir -p /work/wt && ln -sfn /tmp/b /work/wt/perf
export LD_LIBRARY_PATH=/tmp/b/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
F=/tmp/b/bin/fxdemo
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv
set +e
