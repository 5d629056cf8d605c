# Compute passes on the H100 (issue 16 item 4): each demo at 1920x1080, 200 frames, --bounds,
# with FXPORT_COMPUTE_PASSES=0 and =1, twice each; the frame lines, the MD5s of final.png and
# debug.png, and the compute-vs-fragment pixel comparison (pngdiff.py) go to $OUT.
#
# Bundle (on the build machine, from the perf worktree at the commit to measure):
#   scripts/build build && scripts/make-device-bundle build demo/fxdemo
#   mkdir -p .devbundle-perf && cp docs/report/h100-frame-time/{setup.sh,m4.sh,pngdiff.py} .devbundle-perf/
#   rm -rf /tmp/m4b && mkdir -p /tmp/m4b/build && cp -r .devbundle/bin .devbundle/lib hlsl /tmp/m4b/ &&
#     cp -rL build/content /tmp/m4b/build/ && tar cJf .devbundle-perf/b.tar.xz -C /tmp/m4b .
# (the layout of m3's bundle: setup.sh unpacks it to /tmp/b and points /work/wt/perf there, where
# fxdemo's compiled-in hlsl/ and build/content/ paths lead).
# Run (device tool, carry .devbundle-perf): bash .devbundle-perf/m4.sh   (about 16 runs of ~10-15 s)
. .devbundle-perf/setup.sh
P=$PWD/.devbundle-perf/pngdiff.py
cd /tmp
L=$OUT/m4.log
run() { # label env... -- fxdemo args
  local label=$1; shift
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  echo "=== $label: ${envs[*]} fxdemo $*" >>$L
  env "${envs[@]}" $F "$@" --bounds --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L
}
R="--gpu --size 1920x1080 --frames 200"
for i in 1 2; do
  for d in deferred lighting2d pointlights rastertek50; do
    run $d-fragment-$i FXPORT_COMPUTE_PASSES=0 -- $d $R
    run $d-compute-$i FXPORT_COMPUTE_PASSES=1 -- $d $R
  done
done
# One --explain run per demo with compute passes on: how many draws ran as compute, why others fell back.
for d in deferred lighting2d pointlights rastertek50; do
  run $d-explain FXPORT_COMPUTE_PASSES=1 -- $d --gpu --size 1920x1080 --frames 2 --explain
done
cp /tmp/fxcache/gpu-limits-* $OUT/limits.txt
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
for d in deferred lighting2d pointlights rastertek50; do
  for f in final debug; do
    python3 $P /tmp/o/$d-fragment-1/$f.png /tmp/o/$d-compute-1/$f.png >> $OUT/pngdiff.txt 2>&1
  done
  cp /tmp/o/$d-compute-1/final.png $OUT/$d-compute-final.png
done
awk '/^=== /{l=$2} /^  frame /{print l, $0} /^rc=[^0]/{print l, $0}' $L
awk '/^=== /{l=$2} /run as compute|fell back/{print l, $0}' $L
cat $OUT/pngdiff.txt
