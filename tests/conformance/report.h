// What a whole run says: the per-(file, model) TSV, the summary tables (per shader model, per
// section kind, skip reasons), the most frequent failure kinds, and the Markdown tables of
// docs/conformance.md.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "file_pool.h"

namespace conformance {

struct RunReport {
    std::vector<FileOutcome> files;  // sorted by name before printing
    double seconds = 0;
};

void writeTsv(const RunReport& report, std::ostream& out);
void writeFailures(const RunReport& report, std::ostream& out);
void printSummary(const RunReport& report, std::ostream& out);
// The most frequent failures, grouped by category and diagnostic (quoted names and numbers folded).
void printFailureKinds(const RunReport& report, std::ostream& out, int limit);
void writeMarkdownTables(const RunReport& report, std::ostream& out);

}  // namespace conformance
