// Parsing the resource-like blocks of a .shader_test (see resource_desc.h).
#include "resource_desc.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "qualifiers.h"

namespace conformance {

namespace {

std::string where(const Block& block, const Line& line) {
    return "line " + std::to_string(line.number) + " of [" + block.header + "]";
}

bool eat(const char*& p, const char* word) {
    while (*p == ' ' || *p == '\t') ++p;
    std::size_t n = std::strlen(word);
    if (std::strncmp(p, word, n)) return false;
    p += n;
    while (*p == ' ' || *p == '\t') ++p;
    return true;
}

}  // namespace

Format parseFormat(const std::string& text, std::string* rest) {
    static const struct { const char* name; int components; char type; bool shadow; } kFormats[] = {
        {"r32g32b32a32-float", 4, 'f', false}, {"r32g32b32a32-sint", 4, 's', false}, {"r32g32b32a32-uint", 4, 'u', false},
        {"r32g32-float", 2, 'f', false},       {"r32g32-sint", 2, 's', false},       {"r32g32-uint", 2, 'u', false},
        {"r32-float-shadow", 1, 'f', true},    {"r32-float", 1, 'f', false},         {"r32-sint", 1, 's', false},
        {"r32-uint", 1, 'u', false},           {"r32-typeless", 1, 't', false},      {"unknown", 0, 't', false},
    };
    const char* p = text.c_str();
    while (*p == ' ') ++p;
    for (const auto& f : kFormats) {
        if (std::strncmp(p, f.name, std::strlen(f.name))) continue;
        if (rest) *rest = p + std::strlen(f.name);
        return Format{f.name, f.components, f.type, f.shadow};
    }
    throw std::runtime_error("unknown format '" + text + "'");
}

namespace {

void parseSize(const char* p, ResourceDesc& r) {
    char kind[32] = {0};
    int a = 0, b = 0, c = 0;
    int n = std::sscanf(p, " ( %31[a-z_0-9] , %d , %d , %d )", kind, &a, &b, &c);
    if (n < 2) throw std::runtime_error(std::string("malformed size '") + p + "'");
    r.dimension = kind;
    r.sizeGiven = true;
    r.width = a;
    if (r.dimension == "2d" || r.dimension == "2darray" || r.dimension == "3d") r.height = b;
    if (r.dimension == "2darray" || r.dimension == "3d") r.depth = c;
    if (r.dimension == "2dms") { r.samples = a; r.width = b; r.height = c; }
    if (r.dimension == "cube") { r.height = a; r.depth = 6; }
}

// A data line: numbers as vkd3d reads them -- strtoul (base 0), or strtof when a '.' follows the
// integer part -- stored as raw 32-bit words.
void parseDataWords(const char* p, std::vector<std::uint32_t>& out) {
    for (;;) {
        char* end = nullptr;
        std::uint32_t word = std::uint32_t(std::strtoul(p, &end, 0));
        if (end && *end == '.') {
            float f = std::strtof(p, &end);
            std::memcpy(&word, &f, 4);
        }
        if (end == p) return;
        out.push_back(word);
        p = end;
    }
}

}  // namespace

ResourceDesc parseResource(const Block& block) {
    ResourceDesc r;
    r.kind = block.kind;
    r.slot = block.slot;
    if (block.kind == BlockKind::Dsv) r.format = Format{"d32-float", 1, 'f', true};
    for (const Line& line : block.lines) {
        const char* p = line.text.c_str();
        try {
            if (eat(p, "format")) r.format = parseFormat(p);
            else if (eat(p, "stride")) { r.stride = std::atoi(p); r.format = Format{"structured", 0, 't', false}; }
            else if (eat(p, "size")) parseSize(p, r);
            else if (eat(p, "levels")) r.levels = std::atoi(p);
            else parseDataWords(p, r.data);
        } catch (const std::exception& e) {
            throw std::runtime_error(where(block, line) + ": " + e.what());
        }
    }
    return r;
}

namespace {

Address parseAddress(const char*& p) {
    static const struct { const char* name; Address a; } kModes[] = {
        {"border", Address::Border}, {"clamp", Address::Clamp}, {"mirror_once", Address::MirrorOnce},
        {"mirror", Address::Mirror}, {"wrap", Address::Wrap},
    };
    for (const auto& m : kModes)
        if (eat(p, m.name)) return m.a;
    throw std::runtime_error(std::string("unknown address mode '") + p + "'");
}

Filter parseFilter(const char*& p) {
    if (eat(p, "point")) return Filter::Point;
    if (eat(p, "linear")) return Filter::Linear;
    throw std::runtime_error(std::string("unknown filter '") + p + "'");
}

}  // namespace

SamplerDesc parseSampler(const Block& block) {
    SamplerDesc s;
    s.slot = block.slot;
    for (const Line& line : block.lines) {
        const char* p = line.text.c_str();
        try {
            if (eat(p, "address")) { s.u = parseAddress(p); s.v = parseAddress(p); s.w = parseAddress(p); }
            else if (eat(p, "filter")) { s.min = parseFilter(p); s.mag = parseFilter(p); s.mip = parseFilter(p); }
            else if (eat(p, "comparison")) { s.comparison = true; s.comparisonFunc = p; }
            else throw std::runtime_error("unknown sampler directive");
        } catch (const std::exception& e) {
            throw std::runtime_error(where(block, line) + ": " + e.what());
        }
    }
    return s;
}

std::vector<InputElement> parseInputLayout(const Block& block) {
    std::vector<InputElement> out;
    for (const Line& line : block.lines) {
        InputElement e;
        char* end = nullptr;
        e.slot = int(std::strtoul(line.text.c_str(), &end, 10));
        std::string rest;
        e.format = parseFormat(end, &rest);
        char name[128] = {0};
        int index = 0;
        int n = std::sscanf(rest.c_str(), " %127s %d", name, &index);
        if (n < 1) throw std::runtime_error(where(block, line) + ": malformed input layout element");
        e.semantic = name;
        e.index = n >= 2 ? index : 0;
        out.push_back(e);
    }
    return out;
}

RequireDesc parseRequire(const Block& block) {
    RequireDesc r;
    for (const Line& line : block.lines) {
        const char* p = line.text.c_str();
        if (eat(p, "shader model >=")) {
            int m = parseShaderModel(p);
            if (m < 0) throw std::runtime_error(where(block, line) + ": unknown shader model");
            r.minModel = std::max(r.minModel, m);
        } else if (eat(p, "shader model <")) {
            int m = parseShaderModel(p);
            if (m < 0) throw std::runtime_error(where(block, line) + ": unknown shader model");
            r.maxModel = std::min(r.maxModel, m - 1);  // models are discrete: "< 4.0" allows up to 3.x
        } else if (eat(p, "options:")) {
            if (std::strstr(p, "row-major")) r.matrixPacking = "row-major";
            if (std::strstr(p, "column-major")) r.matrixPacking = "column-major";
            r.backcompat = std::strstr(p, "backcompat") != nullptr;
        } else {
            r.capabilities.push_back(line.text);
        }
    }
    return r;
}

}  // namespace conformance
