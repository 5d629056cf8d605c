// Tables of a run (see report.h).
#include "report.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <regex>
#include <set>

#include "qualifiers.h"

namespace conformance {

namespace {

struct Totals {
    SectionCounts sections;
    std::array<SectionCounts, kSectionKinds> kinds{};
    int probesRun = 0, probesPassed = 0, probesSkipped = 0, crashedRows = 0;
    std::set<std::string> crashedFiles;
    std::map<std::string, int> skipReasons, notCompiled;

    void add(const ModelResult& r) {
        SectionCounts t = r.total();
        sections.shouldCompile += t.shouldCompile;
        sections.compiled += t.compiled;
        sections.shouldFail += t.shouldFail;
        sections.rejected += t.rejected;
        for (int k = 0; k < kSectionKinds; ++k) {
            kinds[std::size_t(k)].shouldCompile += r.sections[std::size_t(k)].shouldCompile;
            kinds[std::size_t(k)].compiled += r.sections[std::size_t(k)].compiled;
            kinds[std::size_t(k)].shouldFail += r.sections[std::size_t(k)].shouldFail;
            kinds[std::size_t(k)].rejected += r.sections[std::size_t(k)].rejected;
        }
        probesRun += r.probesRun;
        probesPassed += r.probesPassed;
        probesSkipped += r.probesSkipped;
        if (r.crashed) { crashedRows += r.crashed; crashedFiles.insert(r.file); }
        for (const auto& [why, n] : r.skipReasons) skipReasons[why] += n;
        for (const auto& [why, n] : r.notCompiledReasons) notCompiled[why] += n;
    }
};

std::string ratio(int part, int whole) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%d / %d (%.1f %%)", part, whole, whole ? 100.0 * part / whole : 0.0);
    return buf;
}

Totals totalsFor(const RunReport& report, int model) {
    Totals t;
    for (const FileOutcome& f : report.files)
        for (const ModelResult& r : f.results)
            if (model == 0 || r.model == model) t.add(r);
    return t;
}

void printModelTable(const RunReport& report, std::ostream& out) {
    out << "model | sections that should compile, compiled | fail sections rejected | probes passed / run | probes skipped | crashes\n";
    for (int model : {20, 30, 40, 50, 0}) {
        Totals t = totalsFor(report, model);
        out << (model ? shaderModelName(model) : std::string("all")) << " | " << ratio(t.sections.compiled, t.sections.shouldCompile)
            << " | " << ratio(t.sections.rejected, t.sections.shouldFail) << " | " << ratio(t.probesPassed, t.probesRun)
            << " | " << t.probesSkipped << " | " << t.crashedRows << "\n";
    }
}

void printKindTable(const Totals& t, std::ostream& out) {
    out << "section kind | should compile, compiled | fail sections rejected\n";
    for (int k = 0; k < kSectionKinds; ++k) {
        const SectionCounts& s = t.kinds[std::size_t(k)];
        out << sectionKindName(SectionKind(k)) << " | " << ratio(s.compiled, s.shouldCompile) << " | "
            << ratio(s.rejected, s.shouldFail) << "\n";
    }
}

void printReasons(const std::map<std::string, int>& reasons, std::ostream& out) {
    std::vector<std::pair<int, std::string>> sorted;
    for (const auto& [why, n] : reasons) sorted.push_back({n, why});
    std::sort(sorted.rbegin(), sorted.rend());
    for (const auto& [n, why] : sorted) out << "  " << n << "  " << why << "\n";
}

std::vector<std::string> outOfScope(const RunReport& report) {
    std::vector<std::string> out;
    for (const FileOutcome& f : report.files)
        if (f.outOfScope) out.push_back(f.name);
    return out;
}

// A diagnostic with the particulars folded, so that one cause groups together; "" for failures
// that only repeat another (a probe after a draw that failed is listed under the draw).
std::string groupKey(const Failure& f) {
    if (f.category == "probe") {
        if (f.detail.rfind("draw failed: ", 0) == 0) return "";
        bool guessed = f.detail.find("[uniforms placed by a guess") != std::string::npos;
        return std::string("probe: wrong value") + (guessed ? " (D3D9 uniform registers guessed)" : "");
    }
    std::string d = f.detail;
    d = std::regex_replace(d, std::regex("'[^']*'"), "'_'");
    d = std::regex_replace(d, std::regex("\"[^\"]*\""), "\"_\"");
    d = std::regex_replace(d, std::regex("\\b[0-9]+\\b"), "N");
    if (d.size() > 160) d = d.substr(0, 160) + "...";
    return f.category + ": " + d;
}

}  // namespace

void writeTsv(const RunReport& report, std::ostream& out) {
    out << "file\tmodel\tcompile_ok\tcompile_expected\trejected\tfail_expected\tprobes_passed\tprobes_run\tprobes_skipped\tcrashed\tskip_reasons\tsession\n";
    for (const FileOutcome& f : report.files) {
        for (const ModelResult& r : f.results) {
            SectionCounts t = r.total();
            std::string reasons;
            for (const auto& [why, n] : r.skipReasons) reasons += (reasons.empty() ? "" : "; ") + std::to_string(n) + "x " + why;
            out << r.file << '\t' << shaderModelName(r.model) << '\t' << t.compiled << '\t' << t.shouldCompile << '\t'
                << t.rejected << '\t' << t.shouldFail << '\t' << r.probesPassed << '\t' << r.probesRun << '\t'
                << r.probesSkipped << '\t' << r.crashed << '\t' << (reasons.empty() ? "-" : reasons) << '\t' << r.session << "\n";
        }
        if (f.outOfScope) out << f.name << "\tout-of-scope\t0\t0\t0\t0\t0\t0\t0\t0\tonly SM 5.1/6.x sections\t-\n";
    }
}

void writeFailures(const RunReport& report, std::ostream& out) {
    out << "file\tmodel\tline\tcategory\tdetail\n";
    for (const FileOutcome& f : report.files)
        for (const Failure& x : f.failures) out << x.encode() << "\n";
}

namespace {

// SM 4/5 runs whose D3D11 session passed fewer probes than the XNA one (session_choice.h): the
// D3D11 front end's gaps, listed so they stay visible.
void printKeptOnXna(const RunReport& report, std::ostream& out) {
    std::string list;
    int n = 0;
    for (const FileOutcome& f : report.files)
        for (const ModelResult& r : f.results)
            if (r.session == "xna-kept") {
                ++n;
                list += " " + r.file + "@" + shaderModelName(r.model);
            }
    out << "SM 4/5 runs kept on the XNA session (the D3D11 one passed fewer probes): " << n << list << "\n";
}

}  // namespace

void printSummary(const RunReport& report, std::ostream& out) {
    Totals all = totalsFor(report, 0);
    out << "\n== vkd3d-shader HLSL suite through fxport: " << report.files.size() << " files, "
        << static_cast<int>(report.seconds + 0.5) << " s ==\n\nPer shader model:\n";
    printModelTable(report, out);
    out << "\nPer section kind (all models):\n";
    printKindTable(all, out);
    out << "\nProbes skipped, by reason (" << all.probesSkipped << " of "
        << all.probesSkipped + all.probesRun << " probes):\n";
    printReasons(all.skipReasons, out);
    out << "\nSections counted but not compiled or checked, by reason:\n";
    printReasons(all.notCompiled, out);
    std::vector<std::string> scope = outOfScope(report);
    out << "\nOut of scope (only SM 5.1 / 6.x sections): " << scope.size() << " files\n";
    out << "Compiles or draws that crashed the process: " << all.crashedRows << " in " << all.crashedFiles.size() << " files";
    for (const std::string& f : all.crashedFiles) out << " " << f;
    out << "\n";
    printKeptOnXna(report, out);
}

void printFailureKinds(const RunReport& report, std::ostream& out, int limit) {
    struct Group { int count = 0; std::map<std::string, int> files; };
    std::map<std::string, Group> groups;
    for (const FileOutcome& f : report.files) {
        for (const Failure& x : f.failures) {
            std::string key = groupKey(x);
            if (key.empty()) continue;
            Group& g = groups[key];
            ++g.count;
            ++g.files[x.file];
        }
    }
    std::vector<std::pair<int, std::string>> sorted;
    for (const auto& [key, g] : groups) sorted.push_back({g.count, key});
    std::sort(sorted.rbegin(), sorted.rend());
    out << "\nMost frequent failure kinds (count, files, the files with most):\n";
    for (int i = 0; i < std::min(limit, int(sorted.size())); ++i) {
        const Group& g = groups[sorted[std::size_t(i)].second];
        out << "  " << g.count << " in " << g.files.size() << " files  " << sorted[std::size_t(i)].second << "\n     e.g.";
        std::vector<std::pair<int, std::string>> files;
        for (const auto& [file, n] : g.files) files.push_back({n, file});
        std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
        for (std::size_t k = 0; k < std::min<std::size_t>(8, files.size()); ++k) out << " " << files[k].second << "(" << files[k].first << ")";
        out << "\n";
    }
}

void writeMarkdownTables(const RunReport& report, std::ostream& out) {
    out << "| shader model | sections that should compile, compiled | `fail` sections rejected | probes passed / run | probes skipped | crashes |\n";
    out << "|---|---|---|---|---|---|\n";
    for (int model : {20, 30, 40, 50, 0}) {
        Totals t = totalsFor(report, model);
        out << "| " << (model ? shaderModelName(model) : std::string("**all**")) << " | "
            << ratio(t.sections.compiled, t.sections.shouldCompile) << " | " << ratio(t.sections.rejected, t.sections.shouldFail)
            << " | " << ratio(t.probesPassed, t.probesRun) << " | " << t.probesSkipped << " | " << t.crashedRows << " |\n";
    }
    Totals all = totalsFor(report, 0);
    out << "\n| section kind (all models) | should compile, compiled | `fail` sections rejected |\n|---|---|---|\n";
    for (int k = 0; k < kSectionKinds; ++k) {
        const SectionCounts& s = all.kinds[std::size_t(k)];
        out << "| " << sectionKindName(SectionKind(k)) << " | " << ratio(s.compiled, s.shouldCompile) << " | "
            << ratio(s.rejected, s.shouldFail) << " |\n";
    }
    out << "\n| probes skipped | reason |\n|---|---|\n";
    std::vector<std::pair<int, std::string>> sorted;
    for (const auto& [why, n] : all.skipReasons) sorted.push_back({n, why});
    std::sort(sorted.rbegin(), sorted.rend());
    for (const auto& [n, why] : sorted) out << "| " << n << " | " << why << " |\n";
    out << "\n| sections not compiled or not checked | reason |\n|---|---|\n";
    for (const auto& [why, n] : all.notCompiled) out << "| " << n << " | " << why << " |\n";
    out << "\nOut of scope (only SM 5.1 / 6.x sections): " << outOfScope(report).size() << " files.\n";
}

}  // namespace conformance
