#include "fxport/graphics/finite_check.h"

#include <cmath>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/render_target.h"
#include "device/surface_formats.h"

namespace fxport {

namespace {

std::string valueText(float v) {
    if (std::isnan(v)) return "NaN";
    return v > 0 ? "+Inf" : "-Inf";
}

std::string targetLabel(const Texture& t) {
    if (!t.Name.empty()) return t.Name;
    std::string size = t.kind() == Texture::Kind::TextureCube
                           ? std::to_string(static_cast<const TextureCube&>(t).Size()) + "^2 cube"
                           : std::to_string(static_cast<const Texture2D&>(t).Width()) + "x" +
                                 std::to_string(static_cast<const Texture2D&>(t).Height());
    return std::string("unnamed ") + (t.kind() == Texture::Kind::TextureCube ? "RenderTargetCube" : "RenderTarget2D") +
           " (" + size + " " + surfaceFormatName(t.Format()) + ")";
}

}  // namespace

std::string NonFiniteTarget::describe() const {
    static const char* kChannels = "rgba";
    std::string where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    if (face >= 0) where += " of cube face " + std::to_string(face);
    return "pass '" + pass + "' wrote " + valueText(value) + " into '" + target + "' at " + where + " channel " +
           kChannels[channel & 3] + " (" + std::to_string(count) + " texels non-finite)";
}

bool findNonFinite(const float* rgba, int width, int height, int channels, NonFiniteTarget& found) {
    std::int64_t count = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* texel = rgba + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
            bool bad = false;
            for (int c = 0; c < channels; ++c) {
                if (std::isfinite(texel[c])) continue;
                if (count == 0 && !bad) found.x = x, found.y = y, found.channel = c, found.value = texel[c];
                bad = true;
            }
            count += bad ? 1 : 0;
        }
    }
    found.count = count;
    return count > 0;
}

void FiniteCheck::beginPass(const std::string& name) {
    pass_ = name;
    device_.markBoundTargets();
}

std::vector<NonFiniteTarget> FiniteCheck::endPass() {
    std::vector<NonFiniteTarget> found;
    ++passes_;
    for (const RenderTargetBinding& b : device_.targetsBoundSinceMark()) {
        const Texture& t = *b.RenderTarget;
        if (t.IsDisposed()) continue;
        if (!isFloatFormat(t.Format())) {
            ++skipped_;
            continue;
        }
        ++scanned_;
        const bool cube = t.kind() == Texture::Kind::TextureCube;
        std::vector<Vector4> texels;
        int width = 0, height = 0;
        if (cube) {
            const auto& c = static_cast<const RenderTargetCube&>(t);
            texels = c.GetDataAsVector4(b.CubeMapFace);
            width = height = c.Size();
        } else {
            const auto& r = static_cast<const RenderTarget2D&>(t);
            texels = r.GetDataAsVector4();
            width = r.Width(), height = r.Height();
        }
        static_assert(sizeof(Vector4) == 4 * sizeof(float), "Vector4 is four packed floats");
        NonFiniteTarget result;
        if (!findNonFinite(&texels[0].X, width, height, channelCount(t.Format()), result)) continue;
        result.pass = pass_;
        result.target = targetLabel(t);
        result.face = cube ? int(b.CubeMapFace) : -1;
        found.push_back(result);
    }
    findings_.insert(findings_.end(), found.begin(), found.end());
    return found;
}

}  // namespace fxport
