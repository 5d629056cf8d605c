// Reading, writing and checking the conformance baseline (see baseline.h).
#include "baseline.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace conformance {

Baseline baselineOf(const RunReport& report) {
    Baseline out;
    for (const FileOutcome& f : report.files) {
        BaselineRow& row = out[f.name.substr(0, f.name.rfind(".shader_test"))];
        for (const ModelResult& r : f.results) {
            SectionCounts t = r.total();
            row.compiled += t.compiled;
            row.rejected += t.rejected;
            row.probesPassed += r.probesPassed;
        }
    }
    return out;
}

Baseline readBaseline(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot read the baseline");
    Baseline out;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#' || line.rfind("file\t", 0) == 0) continue;
        std::istringstream fields(line);
        std::string name;
        BaselineRow row;
        if (!(fields >> name >> row.compiled >> row.rejected >> row.probesPassed))
            throw std::runtime_error(path + ":" + std::to_string(number) + ": want 'file compiled rejected probes_passed'");
        out[name] = row;
    }
    return out;
}

void writeBaseline(const Baseline& baseline, std::ostream& out) {
    out << "# Per file of the vkd3d-shader HLSL suite, summed over shader models 2.0-5.0: sections compiled,\n"
           "# fail sections rejected, probes passed. The ctest conformance.Vkd3dHlslSuite fails when a count\n"
           "# drops; rewrite with scripts/conformance --write-baseline after a fix raises them.\n";
    out << "file\tcompiled\trejected\tprobes_passed\n";
    for (const auto& [name, row] : baseline)
        out << name << '\t' << row.compiled << '\t' << row.rejected << '\t' << row.probesPassed << "\n";
}

int compareWithBaseline(const Baseline& current, const Baseline& baseline, std::ostream& out) {
    int drops = 0;
    auto check = [&](const std::string& name, const char* what, int now, int before) {
        if (now >= before) return;
        ++drops;
        out << "REGRESSION " << name << ": " << what << " " << now << " < baseline " << before << "\n";
    };
    for (const auto& [name, before] : baseline) {
        auto it = current.find(name);
        if (it == current.end()) {
            ++drops;
            out << "REGRESSION " << name << ": in the baseline but not run\n";
            continue;
        }
        check(name, "sections compiled", it->second.compiled, before.compiled);
        check(name, "fail sections rejected", it->second.rejected, before.rejected);
        check(name, "probes passed", it->second.probesPassed, before.probesPassed);
    }
    return drops;
}

}  // namespace conformance
