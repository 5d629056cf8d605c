// Texture3D::FromFile: a volume .dds decoded by dds_image.cpp, uploaded level by level
// (texture_3d.h).
#include <algorithm>
#include <string>
#include <vector>

#include "device/dds_image.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture_3d.h"

namespace fxport {

namespace {

// The next level of a w x h x d volume: each texel the rounded mean of its 2x2x2 parents (fewer
// where a side is already 1), as GenerateMips would.
std::vector<Color> halveVolume(const std::vector<Color>& level, int w, int h, int d) {
    const int nw = std::max(1, w / 2), nh = std::max(1, h / 2), nd = std::max(1, d / 2);
    std::vector<Color> out(std::size_t(nw) * std::size_t(nh) * std::size_t(nd));
    for (int z = 0; z < nd; ++z)
        for (int y = 0; y < nh; ++y)
            for (int x = 0; x < nw; ++x) {
                int sum[4] = {0, 0, 0, 0}, n = 0;
                for (int dz = 0; dz < (d > 1 ? 2 : 1); ++dz)
                    for (int dy = 0; dy < (h > 1 ? 2 : 1); ++dy)
                        for (int dx = 0; dx < (w > 1 ? 2 : 1); ++dx) {
                            const Color& c = level[(std::size_t(2 * z + dz) * std::size_t(h) + std::size_t(2 * y + dy)) * std::size_t(w) + std::size_t(2 * x + dx)];
                            sum[0] += c.R, sum[1] += c.G, sum[2] += c.B, sum[3] += c.A, ++n;
                        }
                out[(std::size_t(z) * std::size_t(nh) + std::size_t(y)) * std::size_t(nw) + std::size_t(x)] =
                    Color(std::uint8_t((sum[0] + n / 2) / n), std::uint8_t((sum[1] + n / 2) / n), std::uint8_t((sum[2] + n / 2) / n),
                          std::uint8_t((sum[3] + n / 2) / n));
            }
    return out;
}

}  // namespace

std::unique_ptr<Texture3D> Texture3D::FromFile(fxport::GraphicsDevice& device, const std::string& path) {
    detail::DdsImage dds = detail::readDds(path);  // throws ArgumentError naming the file
    if (!dds.volume)
        throw ArgumentError("Texture3D::FromFile: '" + path + "' is not a volume texture (" +
                            (dds.cube ? "a cube map; load it as TextureCube" : "a 2D texture; load it as Texture2D") + ")");
    auto volume = std::make_unique<Texture3D>(device, dds.width, dds.height, dds.depth, dds.levelCount > 1, SurfaceFormat::Color);
    volume->Name = path;
    std::vector<Color> level;
    for (int l = 0; l < volume->LevelCount(); ++l) {
        if (l < dds.levelCount)
            level = std::move(dds.levels[std::size_t(l)]);
        else
            level = halveVolume(level, std::max(1, dds.width >> (l - 1)), std::max(1, dds.height >> (l - 1)), std::max(1, dds.depth >> (l - 1)));
        volume->SetData(l, level.data(), level.size());
    }
    return volume;
}

}  // namespace fxport
