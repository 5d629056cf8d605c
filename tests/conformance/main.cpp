// shader_test_runner: runs vkd3d-shader's HLSL conformance suite (.shader_test files, read in
// place) through fxport's public compile and runtime APIs, and prints what conforms.
//
//   shader_test_runner --suite DIR [--jobs 2] [--tsv OUT.tsv] [--failures OUT.tsv] [--markdown OUT.md]
//                      [--baseline tests/conformance/baseline.tsv] [--write-baseline FILE] [--cache DIR]
//   shader_test_runner --suite DIR --file NAME      one file, each section's outcome and each failing probe
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <iostream>
#include <unistd.h>

#include "baseline.h"
#include "file_pool.h"
#include "qualifiers.h"
#include "report.h"

namespace {

using namespace conformance;

struct Args {
    std::string suite;
    std::string file;
    bool verbose = false;
    int jobs = 2;
    std::string tsv, failures, markdown, baseline, writeBaseline, cache;
    int topFailures = 30;
};

[[noreturn]] void usage(const std::string& problem) {
    std::ostream& out = problem.empty() ? std::cout : std::cerr;
    if (!problem.empty()) out << "shader_test_runner: " << problem << "\n";
    out << "usage: shader_test_runner --suite DIR [--file NAME] [--verbose] [--jobs N] [--tsv OUT] [--failures OUT]\n"
                 "                          [--markdown OUT] [--baseline FILE] [--write-baseline FILE] [--cache DIR] [--top N]\n"
                 "  --file NAME   one file (name or path), verbose: each section's outcome and diagnostic, each failing probe\n"
                 "  --tsv OUT     one row per (file, shader model); --failures OUT: every failed check with its line\n"
                 "  --baseline F  exit 1 when a file's compiled/rejected/probes-passed count drops below F\n"
                 "  --cache DIR   xlate's compile cache (default: none for effects; D3DCompile's default one)\n";
    std::exit(problem.empty() ? 0 : 2);
}

Args parseArgs(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        std::string o = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage("option '" + o + "' needs a value");
            return argv[++i];
        };
        if (o == "--help" || o == "-h") usage("");
        if (o == "--suite") a.suite = value();
        else if (o == "--file") { a.file = value(); a.verbose = true; }
        else if (o == "--verbose") a.verbose = true;
        else if (o == "--jobs") a.jobs = std::atoi(value().c_str());
        else if (o == "--tsv") a.tsv = value();
        else if (o == "--failures") a.failures = value();
        else if (o == "--markdown") a.markdown = value();
        else if (o == "--baseline") a.baseline = value();
        else if (o == "--write-baseline") a.writeBaseline = value();
        else if (o == "--cache") a.cache = value();
        else if (o == "--top") a.topFailures = std::atoi(value().c_str());
        else usage("unknown option '" + o + "'");
    }
    if (a.suite.empty() && a.file.find('/') == std::string::npos) usage("--suite DIR is required");
    if (a.jobs < 1) usage("option '--jobs' has a bad value: want a number >= 1");
    return a;
}

std::vector<std::string> suiteFiles(const Args& a) {
    if (!a.file.empty()) {
        std::string path = a.file.find('/') != std::string::npos ? a.file : a.suite + "/" + a.file;
        if (!path.ends_with(".shader_test")) path += ".shader_test";
        return {path};
    }
    std::vector<std::string> out;
    DIR* dir = ::opendir(a.suite.c_str());
    if (!dir) {
        std::cerr << "shader_test_runner: the conformance suite folder '" << a.suite
                  << "' does not exist (set FXPORT_CONFORMANCE_DIR to the folder of vkd3d's *.shader_test files, "
                     "or to an empty value to leave the suite out)\n";
        std::exit(1);
    }
    while (dirent* e = ::readdir(dir)) {
        std::string name = e->d_name;
        if (name.ends_with(".shader_test")) out.push_back(a.suite + "/" + name);
    }
    ::closedir(dir);
    std::sort(out.begin(), out.end());
    if (out.empty()) {
        std::cerr << "shader_test_runner: no *.shader_test files in '" << a.suite << "'\n";
        std::exit(1);
    }
    return out;
}

std::string makeTempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/fxport-conformance-XXXXXX";
    if (!::mkdtemp(tmpl.data())) {
        std::cerr << "shader_test_runner: cannot make a temporary folder under " << tmpl << "\n";
        std::exit(1);
    }
    return tmpl;
}

template <class Write>
void writeFile(const std::string& path, Write write) {
    if (path.empty()) return;
    std::ofstream out(path);
    if (!out) {
        std::cerr << "shader_test_runner: cannot write '" << path << "'\n";
        std::exit(1);
    }
    write(out);
}

int finish(const Args& a, RunReport& report) {
    std::sort(report.files.begin(), report.files.end(), [](const FileOutcome& x, const FileOutcome& y) { return x.name < y.name; });
    for (FileOutcome& f : report.files)
        std::sort(f.results.begin(), f.results.end(), [](const ModelResult& x, const ModelResult& y) { return x.model < y.model; });
    writeFile(a.tsv, [&](std::ostream& o) { writeTsv(report, o); });
    writeFile(a.failures, [&](std::ostream& o) { writeFailures(report, o); });
    writeFile(a.markdown, [&](std::ostream& o) { writeMarkdownTables(report, o); });
    Baseline current = baselineOf(report);
    // Read before writing: --baseline and --write-baseline may name one file (docs/conformance.md's
    // command does), and a drop must be judged against the counts as they were.
    const Baseline previous = a.baseline.empty() ? Baseline{} : readBaseline(a.baseline);
    writeFile(a.writeBaseline, [&](std::ostream& o) { writeBaseline(current, o); });
    printSummary(report, std::cout);
    if (a.topFailures > 0) printFailureKinds(report, std::cout, a.topFailures);
    if (a.baseline.empty()) return 0;
    int drops = compareWithBaseline(current, previous, std::cout);
    std::cout << (drops ? "\nFAILED: " + std::to_string(drops) + " count(s) below the baseline " + a.baseline + "\n"
                        : "\nOK: no count below the baseline " + a.baseline + "\n");
    return drops ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    Args a = parseArgs(argc, argv);
    std::vector<std::string> files = suiteFiles(a);
    RunOptions run;
    run.tempDir = makeTempDir();
    run.cacheDir = a.cache;
    // D3DCompile (the D3D11 session's compiles) has no cache option: it takes $FXPORT_CACHE_DIR.
    if (!a.cache.empty()) ::setenv("FXPORT_CACHE_DIR", a.cache.c_str(), 1);
    if (a.verbose) run.verbose = &std::cout;
    PoolOptions pool;
    pool.jobs = a.file.empty() ? a.jobs : 1;  // one file: its models in order
    RunReport report;
    if (!a.file.empty()) std::cout << "== " << files.front() << " ==\n";
    auto started = std::chrono::steady_clock::now();
    runFiles(files, run, pool, [&](const FileOutcome& f) {
        if (!f.error.empty()) std::cout << f.name << ": " << f.error << "\n";
        if (a.verbose)
            for (const Failure& x : f.failures)
                if (x.category == "crash")
                    std::cout << "  sm" << shaderModelName(x.model) << " L" << x.line << " crash: " << x.detail << "\n";
        report.files.push_back(f);
    });
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::string rm = "rm -rf '" + run.tempDir + "'";
    if (std::system(rm.c_str()) != 0) std::cerr << "shader_test_runner: could not remove " << run.tempDir << "\n";
    try {
        return finish(a, report);
    } catch (const std::exception& e) {
        std::cerr << "shader_test_runner: " << e.what() << "\n";
        return 1;
    }
}
