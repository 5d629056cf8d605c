// Encoding of results between the file runner's processes (see results.h).
#include "results.h"

#include <sstream>
#include <stdexcept>

namespace conformance {

SectionKind sectionKindOf(Stage stage) {
    switch (stage) {
    case Stage::Pixel: return SectionKind::Pixel;
    case Stage::Vertex: return SectionKind::Vertex;
    case Stage::Effect: return SectionKind::Effect;
    case Stage::Geometry: return SectionKind::Geometry;
    default: return SectionKind::ComputeHullDomain;
    }
}

const char* sectionKindName(SectionKind kind) {
    switch (kind) {
    case SectionKind::Pixel: return "pixel";
    case SectionKind::Vertex: return "vertex";
    case SectionKind::Effect: return "effect";
    case SectionKind::Geometry: return "geometry";
    case SectionKind::ComputeHullDomain: return "compute/hull/domain";
    default: return "?";
    }
}

SectionCounts ModelResult::total() const {
    SectionCounts t;
    for (const SectionCounts& s : sections) {
        t.shouldCompile += s.shouldCompile;
        t.compiled += s.compiled;
        t.shouldFail += s.shouldFail;
        t.rejected += s.rejected;
    }
    return t;
}

namespace {

std::vector<std::string> splitTabs(const std::string& line) {
    std::vector<std::string> out;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, '\t')) out.push_back(field);
    return out;
}

std::string clean(std::string s) {
    for (char& c : s)
        if (c == '\t' || c == '\n' || c == '|') c = ' ';
    return s;
}

// "reason=count|reason=count"; reasons never hold '|', '=' or tabs (they are ours).
std::string encodeReasons(const std::map<std::string, int>& reasons) {
    std::string out;
    for (const auto& [reason, count] : reasons) out += (out.empty() ? "" : "|") + clean(reason) + "=" + std::to_string(count);
    return out.empty() ? "-" : out;
}

std::map<std::string, int> decodeReasons(const std::string& text) {
    std::map<std::string, int> out;
    if (text == "-") return out;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, '|')) {
        std::size_t eq = item.rfind('=');
        out[item.substr(0, eq)] += std::stoi(item.substr(eq + 1));
    }
    return out;
}


}  // namespace

std::string ModelResult::encode() const {
    std::ostringstream out;
    out << file << '\t' << model << '\t' << crashed << '\t' << probesRun << '\t' << probesPassed << '\t' << probesSkipped;
    for (const SectionCounts& s : sections)
        out << '\t' << s.shouldCompile << '\t' << s.compiled << '\t' << s.shouldFail << '\t' << s.rejected;
    out << '\t' << encodeReasons(skipReasons) << '\t' << encodeReasons(notCompiledReasons) << '\t' << clean(session);
    return out.str();
}

ModelResult ModelResult::decode(const std::string& line) {
    std::vector<std::string> f = splitTabs(line);
    if (f.size() != std::size_t(9 + 4 * kSectionKinds)) throw std::runtime_error("bad result line: " + line);
    ModelResult r;
    r.file = f[0];
    r.model = std::stoi(f[1]);
    r.crashed = std::stoi(f[2]);
    r.probesRun = std::stoi(f[3]);
    r.probesPassed = std::stoi(f[4]);
    r.probesSkipped = std::stoi(f[5]);
    for (int k = 0; k < kSectionKinds; ++k) {
        SectionCounts& s = r.sections[std::size_t(k)];
        s.shouldCompile = std::stoi(f[std::size_t(6 + 4 * k)]);
        s.compiled = std::stoi(f[std::size_t(7 + 4 * k)]);
        s.shouldFail = std::stoi(f[std::size_t(8 + 4 * k)]);
        s.rejected = std::stoi(f[std::size_t(9 + 4 * k)]);
    }
    r.skipReasons = decodeReasons(f[std::size_t(6 + 4 * kSectionKinds)]);
    r.notCompiledReasons = decodeReasons(f[std::size_t(7 + 4 * kSectionKinds)]);
    r.session = f[std::size_t(8 + 4 * kSectionKinds)];
    return r;
}

std::string Failure::encode() const {
    return clean(file) + '\t' + std::to_string(model) + '\t' + std::to_string(line) + '\t' + category + '\t' + clean(detail);
}

Failure Failure::decode(const std::string& line) {
    std::vector<std::string> f = splitTabs(line);
    if (f.size() < 5) throw std::runtime_error("bad failure line: " + line);
    return Failure{f[0], std::stoi(f[1]), std::stoi(f[2]), f[3], f[4]};
}

}  // namespace conformance
