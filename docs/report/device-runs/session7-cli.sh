#!/bin/bash
# Copied from .devbundle-final/ (a device-tool bundle; see docs/fuzzing.md and docs/report/compute-passes.md).
# One CLI fuzzing run of about 1 M mutants (issue 15): N instances of tests/fuzz/fuzz-cli in batch mode.
set -u
R=$PWD; B=$R/.devbundle-final
mkdir -p /tmp/fz && cd /tmp/fz && tar xJf "$B/fz.tar.xz" && ln -sfn "$R/hlsl" hlsl && ln -sfn "$R/tests/fixtures" tests/fixtures
mkdir -p runs/cli
T=${T:-550}; N=${N:-16}
for i in $(seq $N); do FUZZ_WORKER_SECONDS=2 timeout $T python3 -u tests/fuzz/fuzz-cli bin/fxport runs/cli/$i 1000000 $((900+i)) 200 > runs/cli/$i.log 2>&1 & done
wait
for i in $(seq $N); do tail -n 1 runs/cli/$i.log; done
python3 - <<'PY'
import re,glob
tot=0; find=0
for f in glob.glob('runs/cli/*.log'):
    last=[l for l in open(f) if 'executions' in l]
    if last:
        m=re.match(r'(\d+) executions', last[-1]); tot+=int(m.group(1))
        find+=int(re.search(r"'finding': (\d+)", last[-1]).group(1))
print('TOTAL', tot, 'findings', find)
PY
ls runs/cli | grep -v log | head
rm -rf runs/cli/*/work
tar cJf $OUT/cli-runs.tar.xz runs
