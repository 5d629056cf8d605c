#!/bin/bash
# Session 9 (m11, run as m12 on the final main): the per-pass bounds with colour clears and a compute pass's writes added
# (fill = max(write once, clears + max(draws' writes once, fragments))), final main; one run each.
# Bundle: .devbundle-m11/t.tar.xz = {bin/,lib/,content/} (scripts/make-device-bundle build-cc demo/fxdemo).
# Run (device tool, carry .devbundle-m11): bash .devbundle-m11/m11.sh
set -u
R=$PWD; B=$R/.devbundle-m11
mkdir -p /tmp/t && tar xJf "$B/t.tar.xz" -C /tmp/t
[ -e /work/main/hlsl ] || { mkdir -p /work; ln -sfn "$R" /work/main; }
mkdir -p /work/main/build-cc; ln -sfn /tmp/t/content /work/main/build-cc/content
export LD_LIBRARY_PATH=/tmp/t/lib FXPORT_PLATFORM=egl FXPORT_CACHE_DIR=/tmp/fxcache
L=$OUT/m11.log
cd /tmp
run() { local label=$1; shift; echo "=== $label: fxdemo $*" >>$L; /tmp/t/bin/fxdemo "$@" --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L; }
for d in deferred lighting2d pointlights rastertek50; do run $d $d --gpu --size 1920x1080 --frames 200 --bounds; done
run pl10k pointlights --gpu --size 1920x1080 --frames 10 --bounds --light-count 10000
(cd /tmp/o && md5sum */final.png) > $OUT/md5.txt
grep -E "^=== |ms " $L; cat $OUT/md5.txt
