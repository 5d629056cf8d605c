// The ratchet: tests/conformance/baseline.tsv holds, per file, the sections compiled, the fail
// sections rejected and the probes passed (summed over the shader models run). A run fails when a
// count of any file drops below it; a fix raises the counts and the baseline is rewritten.
#pragma once

#include <map>
#include <ostream>
#include <string>

#include "report.h"

namespace conformance {

struct BaselineRow {
    int compiled = 0;
    int rejected = 0;
    int probesPassed = 0;
};
using Baseline = std::map<std::string, BaselineRow>;

Baseline baselineOf(const RunReport& report);
Baseline readBaseline(const std::string& path);  // throws std::runtime_error naming path:line
void writeBaseline(const Baseline& baseline, std::ostream& out);
// Prints every drop ("file: compiled 12 < baseline 14") and returns how many there were.
int compareWithBaseline(const Baseline& current, const Baseline& baseline, std::ostream& out);

}  // namespace conformance
