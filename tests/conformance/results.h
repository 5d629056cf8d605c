// Counts of one (file, shader model) run, how they travel from the child process that ran the file
// to the parent (one text line each), and the failures worth a look (for --verbose and the report).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "shader_test_file.h"

namespace conformance {

// Section kinds as the report groups them: compute, hull and domain share one row.
enum class SectionKind { Pixel, Vertex, Effect, Geometry, ComputeHullDomain, Count };
SectionKind sectionKindOf(Stage stage);
const char* sectionKindName(SectionKind kind);
constexpr int kSectionKinds = int(SectionKind::Count);

struct SectionCounts {
    int shouldCompile = 0;
    int compiled = 0;
    int shouldFail = 0;
    int rejected = 0;
};

struct ModelResult {
    std::string file;
    int model = 0;
    std::array<SectionCounts, kSectionKinds> sections{};
    int probesRun = 0;
    int probesPassed = 0;
    int probesSkipped = 0;
    int crashed = 0;  // compiles or draws that took the process down (each rerun past)
    std::map<std::string, int> skipReasons;         // probes skipped, by reason
    std::map<std::string, int> notCompiledReasons;  // sections that should compile and were not even tried
    // The public API whose session ran it (gpu_backend.h): "xna", "d3d11", or "xna-kept" where the
    // D3D11 session passed fewer probes (session_choice.h).
    std::string session = "xna";

    SectionCounts total() const;
    std::string encode() const;  // one tab-separated line
    static ModelResult decode(const std::string& line);
};

// A check that did not hold, with what fxport said (for grouping by diagnostic).
struct Failure {
    std::string file;
    int model = 0;
    int line = 0;
    std::string category;  // "refused" (valid HLSL), "accepted" (invalid HLSL), "probe", "draw"
    std::string detail;    // the diagnostic or the expected/got values
    std::string encode() const;
    static Failure decode(const std::string& line);
};

}  // namespace conformance
