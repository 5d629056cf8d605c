// Probe parsing and comparison (see probe.h).
#include "probe.h"

#include <cinttypes>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace conformance {

namespace {

bool eat(const char*& p, const char* word) {
    while (*p == ' ' || *p == '\t') ++p;
    std::size_t n = std::strlen(word);
    if (std::strncmp(p, word, n)) return false;
    p += n;
    return true;
}

void parseTarget(const char*& p, Probe& probe) {
    char* end = nullptr;
    if (eat(p, "uav")) {
        probe.target = Probe::Target::Uav;
        probe.slot = int(std::strtoul(p, &end, 10));
        p = end;
    } else if (eat(p, "rtv")) {
        probe.target = Probe::Target::Rtv;
        probe.slot = int(std::strtoul(p, &end, 10));
        p = end;
    } else if (eat(p, "dsv")) {
        probe.target = Probe::Target::Dsv;
    }
}

void parseRect(const char*& p, Probe& probe) {
    int a = 0, b = 0, c = 0, d = 0, len = 0;
    if (std::sscanf(p, " ( %d , %d , %d , %d )%n", &a, &b, &c, &d, &len) == 4) {
        probe.left = a; probe.top = b; probe.right = c; probe.bottom = d;
    } else if (std::sscanf(p, " ( %d , %d , %d )%n", &a, &b, &c, &len) == 3) {
        probe.left = a; probe.top = b; probe.right = a + 1; probe.bottom = b + 1; probe.arrayLayer = c;
    } else if (std::sscanf(p, " ( %d , %d )%n", &a, &b, &len) == 2) {
        probe.left = a; probe.top = b; probe.right = a + 1; probe.bottom = b + 1;
    } else if (std::sscanf(p, " ( %d )%n", &a, &len) == 1) {
        probe.left = a; probe.top = 0; probe.right = a + 1; probe.bottom = 1;
    } else {
        throw std::runtime_error(std::string("malformed probe rectangle '") + p + "'");
    }
    p += len;
}

// "(v0, v1, ...) ulps" after the kind word.
void parseValues(const char*& p, Probe& probe) {
    while (*p == ' ') ++p;
    if (*p != '(') throw std::runtime_error(std::string("malformed probe values '") + p + "'");
    ++p;
    probe.components = 0;
    bool integer = probe.kind[0] == 'u' || probe.kind[0] == 'i';
    while (probe.components < 4) {
        char* end = nullptr;
        int k = probe.components;
        if (integer) {
            long long v = probe.kind[0] == 'u' ? (long long)std::strtoull(p, &end, 0) : std::strtoll(p, &end, 0);
            probe.expectedBits[std::size_t(k)] = std::uint32_t(v);
            probe.expected[std::size_t(k)] = double(v);
        } else {
            probe.expected[std::size_t(k)] = std::strtod(p, &end);
        }
        if (end == p) throw std::runtime_error(std::string("malformed probe value '") + p + "'");
        p = end;
        ++probe.components;
        while (*p == ' ') ++p;
        if (*p == ',') { ++p; continue; }
        if (*p == ')') { ++p; break; }
        throw std::runtime_error(std::string("malformed probe values at '") + p + "'");
    }
    char* end = nullptr;
    unsigned long u = std::strtoul(p, &end, 10);
    probe.ulps = end == p ? 0 : unsigned(u);
}

}  // namespace

Probe parseProbe(const std::string& rest) {
    Probe probe;
    const char* p = rest.c_str();
    parseTarget(p, probe);
    parseRect(p, probe);
    static const char* const kKinds[] = {"rgba", "f32", "f64", "u32", "i32", "u64", "i64"};
    for (const char* k : kKinds) {
        if (eat(p, k)) { probe.kind = k; break; }
    }
    if (probe.kind.empty()) throw std::runtime_error(std::string("unknown probe kind '") + p + "'");
    parseValues(p, probe);
    if (probe.kind == "rgba" && probe.components != 4) throw std::runtime_error("rgba probe without 4 values");
    return probe;
}

bool floatsMatch(float got, float expected, unsigned ulps) {
    std::int32_t x, y;
    std::memcpy(&x, &got, 4);
    std::memcpy(&y, &expected, 4);
    // Sign-magnitude to a monotonic integer line, as vkd3d's compare_float does.
    std::int64_t a = x < 0 ? std::int64_t(INT_MIN) - x : x;
    std::int64_t b = y < 0 ? std::int64_t(INT_MIN) - y : y;
    std::int64_t diff = a > b ? a - b : b - a;
    return std::uint64_t(diff) <= ulps;
}

bool texelMatches(const Probe& probe, const Texel& texel) {
    for (int k = 0; k < probe.components; ++k) {
        std::uint32_t bits = texel.bits[std::size_t(k)];
        if (probe.kind == "u32" || probe.kind == "i32") {
            if (bits != probe.expectedBits[std::size_t(k)]) return false;
            continue;
        }
        float got;
        std::memcpy(&got, &bits, 4);
        if (!floatsMatch(got, float(probe.expected[std::size_t(k)]), probe.ulps)) return false;
    }
    return true;
}

std::string describeTexel(const Probe& probe, const Texel& texel) {
    std::ostringstream out;
    out << "(";
    for (int k = 0; k < probe.components; ++k) {
        std::uint32_t bits = texel.bits[std::size_t(k)];
        float f;
        std::memcpy(&f, &bits, 4);
        if (k) out << ", ";
        if (probe.kind == "u32") out << bits;
        else if (probe.kind == "i32") out << std::int32_t(bits);
        else { char buf[48]; std::snprintf(buf, sizeof buf, "%.9g", double(f)); out << buf; }
    }
    out << ")";
    return out.str();
}

std::string describeExpected(const Probe& probe) {
    std::ostringstream out;
    out << probe.kind << "(";
    for (int k = 0; k < probe.components; ++k) {
        if (k) out << ", ";
        char buf[48];
        std::snprintf(buf, sizeof buf, "%.9g", probe.expected[std::size_t(k)]);
        out << buf;
    }
    out << ")";
    if (probe.ulps) out << " within " << probe.ulps << " ulps";
    return out.str();
}

}  // namespace conformance
