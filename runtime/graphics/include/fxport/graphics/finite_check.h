// FiniteCheck: finds the first pass that wrote NaN or Inf into a render target.
//
//   FiniteCheck check(device);
//   check.beginPass("LightMap");  ... draws ...  check.endPass();   // scans what the pass bound
//   if (!check.findings().empty()) std::puts(check.findings()[0].describe().c_str());
//
// endPass() reads back every target bound since beginPass() (GraphicsDevice::markBoundTargets:
// each cube face bound separately, the back buffer included) and scans level 0 texel by texel.
// Only float and half formats can hold NaN/Inf; unorm/snorm targets cannot (GL stores a NaN
// written to them as 0), so they are counted as skipped, not scanned: a NaN the shader wrote into
// such a target is invisible to any read-back and has to be found in the float target it came from.
// Costs one read-back per scanned target per pass: a debugging aid, off unless asked for.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fxport {

class GraphicsDevice;

// One target (one cube face) that holds non-finite texels after a pass.
struct NonFiniteTarget {
    std::string pass;      // the name given to beginPass
    std::string target;    // the target's Name ("GBuffer2"), or "RenderTarget2D #7 (64x64 HalfVector4)" if unnamed
    int face = -1;         // cube face 0..5 (XNA CubeMapFace order), -1 for a 2D target
    int x = 0, y = 0;      // the first non-finite texel in row-major order, top row first
    int channel = 0;       // 0..3 = r, g, b, a
    float value = 0;       // NaN, +Inf or -Inf
    std::int64_t count = 0;  // texels of this target (face) with at least one non-finite channel
    // "pass 'LightMap' wrote NaN into 'LightMap' at pixel (12, 7) channel r (3 of 4096 texels non-finite)"
    std::string describe() const;
};

class FiniteCheck {
public:
    explicit FiniteCheck(GraphicsDevice& device) : device_(device) {}

    void beginPass(const std::string& name);
    // Scans the targets bound since beginPass; returns what this pass left non-finite (also added
    // to findings()). Targets already reported by an earlier pass are scanned again: a later pass
    // that leaves them non-finite is reported too, so findings()[0] is the pass that broke first.
    std::vector<NonFiniteTarget> endPass();

    const std::vector<NonFiniteTarget>& findings() const { return findings_; }
    int passesChecked() const { return passes_; }
    int targetsScanned() const { return scanned_; }
    int targetsSkipped() const { return skipped_; }  // formats that cannot hold NaN/Inf
    void clear() { findings_.clear(), passes_ = scanned_ = skipped_ = 0; }

private:
    GraphicsDevice& device_;
    std::string pass_;
    std::vector<NonFiniteTarget> findings_;
    int passes_ = 0, scanned_ = 0, skipped_ = 0;
};

// Scans RGBA float texels (width x height, top row first) for NaN/Inf. `channels`: how many of the
// four the format has (the rest GL fills with 0/1). Returns false if all are finite; otherwise fills
// the first texel's x, y, channel, value and the count. The CPU part of FiniteCheck, for tests and
// for scanning data that did not come from a target.
bool findNonFinite(const float* rgba, int width, int height, int channels, NonFiniteTarget& found);

}  // namespace fxport
