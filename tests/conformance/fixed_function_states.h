// vkd3d's test states for D3D9's fixed-function stages (`fog ...`, `fog-colour`, `point-size`,
// `point-sprite`, `clip-plane`, `alpha test`, `shade mode`), as vkd3d's shader_runner.c reads them,
// kept as plain values; the XNA session sets them as GraphicsDevice::FixedFunction, the D3D11
// session (D3D11 has none of them) skips draws that need them.
#pragma once

#include <array>
#include <string>

namespace conformance {

struct FixedFunctionDesc {
    bool fog = false;                 // "fog disable" turns it off; every other "fog" line on
    int fogMode = 0;                  // D3DFOGMODE: 0 none (vertex fog), 1 exp, 2 exp2, 3 linear
    bool fogFromW = false;            // "non-ortho": the eye depth w, not z
    float fogStart = 0, fogEnd = 1, fogDensity = 1;
    std::array<float, 4> fogColour{};
    float pointSize = 1, pointSizeMin = 1, pointSizeMax = 64;  // D3D9's defaults
    bool pointSprite = false;
    unsigned clipPlaneMask = 0;       // "clip-plane N a b c d" sets plane N and enables it
    std::array<std::array<float, 4>, 8> clipPlanes{};
    bool alphaTest = false;
    std::string alphaFunction = "always";  // never less equal "less equal" greater "not equal" "greater equal" always
    float alphaReference = 0;
    bool flatShading = false;

    // The first state that differs from D3D9's defaults ("" when none): what a session that
    // cannot set them names in its skip.
    std::string firstSet() const;
};

// Applies one [test] directive to `desc`; false when it is not one of these states. Throws
// std::runtime_error on a malformed line.
bool parseFixedFunctionState(const std::string& directive, FixedFunctionDesc& desc);

// "fog", "point-size", "clip-planes": [require] capabilities these states provide.
bool isFixedFunctionCapability(const std::string& capability);

}  // namespace conformance
