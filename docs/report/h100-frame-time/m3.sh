. .devbundle-perf/setup.sh
cd /tmp
L=$OUT/m3.log
S=$OUT/summary.txt
run() { # label env... -- fxdemo args
  local label=$1; shift
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  echo "=== $label: ${envs[*]} fxdemo $*" >>$L
  env "${envs[@]}" $F "$@" --bounds --out /tmp/o/$label >>$L 2>&1; echo "rc=$?" >>$L
}
R="--gpu --size 1920x1080"
OFF="FXPORT_DEFER_CLEARS=0 FXPORT_HONOUR_DISCARDS=0 FXPORT_DROP_COVERED_CLEARS=0"
MAIN="FXPORT_HONOUR_DISCARDS=0 FXPORT_DROP_COVERED_CLEARS=0"
for i in 1 2; do
 run deferred-off-$i $OFF -- deferred $R --frames 200 --no-shadow-cache
 run deferred-main-$i $MAIN -- deferred $R --frames 200
 run deferred-on-$i X=1 -- deferred $R --frames 200
 run lighting2d-off-$i $OFF -- lighting2d $R --frames 200 --no-light-scissor
 run lighting2d-main-$i $MAIN -- lighting2d $R --frames 200
 run lighting2d-on-$i X=1 -- lighting2d $R --frames 200
 run pointlights-off-$i $OFF -- pointlights $R --frames 200
 run pointlights-main-$i $MAIN -- pointlights $R --frames 200
 run pointlights-on-$i X=1 -- pointlights $R --frames 200
 run rastertek50-off-$i $OFF -- rastertek50 $R --frames 200
 run rastertek50-on-$i X=1 -- rastertek50 $R --frames 200
done
run pl10k-main $MAIN -- pointlights $R --frames 10 --light-count 10000
run pl10k-on X=1 -- pointlights $R --frames 10 --light-count 10000
cp /tmp/fxcache/gpu-limits-* $OUT/limits.txt
(cd /tmp/o && md5sum */final.png */debug.png) > $OUT/md5.txt
for d in deferred lighting2d pointlights rastertek50; do cp /tmp/o/$d-on-1/final.png $OUT/$d-final.png; done
awk '/^=== /{l=$2} /^  frame /{print l, $0} /^rc=[^0]/{print l, $0}' $L
(cd /tmp/o && md5sum */final.png) | sort | awk '{split($2,a,"-"); print $1, $2}'
