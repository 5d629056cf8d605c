// `probe ...` lines of a [test] block and vkd3d's comparison rules (tests/utils.h compare_float:
// floats compared as sign-magnitude integers, at most `ulps` apart; default 0).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace conformance {

struct Probe {
    enum class Target { Rtv, Uav, Dsv } target = Target::Rtv;
    int slot = 0;
    int left = 0, top = 0, right = 1, bottom = 1;  // the rectangle probed (right/bottom exclusive)
    int arrayLayer = 0;
    std::string kind;               // rgba, f32, u32, i32, f64, u64, i64
    int components = 4;             // values given
    std::array<double, 4> expected{};
    std::array<std::uint32_t, 4> expectedBits{};  // u32/i32 as written
    unsigned ulps = 0;
};

// Parses what follows "probe". Throws std::runtime_error on a malformed line.
Probe parseProbe(const std::string& rest);

// True when two floats are within `ulps` units in the last place (vkd3d's compare_float).
bool floatsMatch(float got, float expected, unsigned ulps);

// One pixel read back as 32-bit words (a float target: the floats' bits).
struct Texel {
    std::array<std::uint32_t, 4> bits{};
};

// Whether one texel satisfies the probe.
bool texelMatches(const Probe& probe, const Texel& texel);
std::string describeTexel(const Probe& probe, const Texel& texel);
std::string describeExpected(const Probe& probe);

}  // namespace conformance
