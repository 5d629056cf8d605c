#!/bin/bash
# Session 17: issue 26's parallel cold compile measured where cores exist. scripts/bench-translate (medians of 7)
# with the fxport CLI of main 7f2e1a9 (build-dev, Release, stripped) and Debian 12's glslangValidator, spirv-opt
# and spirv-cross binaries (glslang-tools 12.0.0-2, spirv-tools 2023.1-2, spirv-cross 2021.01.15; statically linked,
# taken from the .debs with dpkg -x), once with fxport's default workers and once with FXPORT_JOBS=1.
# Bundle: .devbundle-s17/{bt/xlate/fxport,cli/*}. Run (device tool, carry .devbundle-s17): bash docs/report/device-runs/session17-bench.sh
set -u
R=$PWD
export PATH=$R/.devbundle-s17/cli:$PATH
(nproc; python3 --version; uname -m; grep -m1 "model name" /proc/cpuinfo) > $OUT/machine.txt 2>&1
FXPORT_BUILD_DIR=$R/.devbundle-s17/bt python3 scripts/bench-translate ${N:-7} > $OUT/bench-parallel.txt 2>&1
FXPORT_JOBS=1 FXPORT_BUILD_DIR=$R/.devbundle-s17/bt python3 scripts/bench-translate ${N:-7} > $OUT/bench-jobs1.txt 2>&1
cat $OUT/machine.txt $OUT/bench-parallel.txt $OUT/bench-jobs1.txt
