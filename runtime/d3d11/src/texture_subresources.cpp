// One subresource of a 2D texture or array texture, wherever its texels live: the device core's
// Texture2D or Texture2DArray, or CPU memory for USAGE_STAGING (one vector per subresource, in
// D3D's order level + slice * MipLevels). The context's copies and updates go through these.
#include <cstring>

#include "d3d11_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::d3d11 {

bool splitSubresource(const Texture& t, UINT index, Subresource& out) {
    if (index >= UINT(t.subresources())) return false;
    out.level = int(index % UINT(t.levels));
    out.slice = int(index / UINT(t.levels));
    return true;
}

std::vector<std::uint8_t> readSubresource(Texture& t, Subresource s) {
    std::vector<std::uint8_t> texels;
    readSubresourceInto(t, s, texels);
    return texels;
}

void readSubresourceInto(Texture& t, Subresource s, std::vector<std::uint8_t>& texels) {
    if (!t.staging.empty()) {
        texels = t.staging[std::size_t(s.slice * t.levels + s.level)];
        return;
    }
    texels.resize(t.levelBytes(s.level));
    if (t.array) t.array->getData(s.level, s.slice, texels.data(), texels.size());
    else if (t.colour) t.colour->getData(s.level, texels.data(), texels.size());
    else throw InvalidOperation("the texture's texels cannot be read (a depth-stencil or cube texture)");
}

void writeSubresource(Texture& t, Subresource s, const Rectangle* area, const std::vector<std::uint8_t>& packed) {
    if (t.array) return t.array->setData(s.level, s.slice, area, packed.data(), packed.size());
    if (t.colour) return t.colour->setData(s.level, area, packed.data(), packed.size());
    if (t.staging.empty()) throw InvalidOperation("the texture's texels cannot be written (a depth-stencil or cube texture)");
    // Staging: `area` of the level's tightly packed rows.
    std::vector<std::uint8_t>& level = t.staging[std::size_t(s.slice * t.levels + s.level)];
    if (!area) {
        level = packed;
        return;
    }
    // In units of 4x4 blocks for BC formats (an area on the block grid).
    const std::size_t texel = std::size_t(bytesPerPixel(t.format)), row = rowBytes(t.format, area->Width);
    const std::size_t levelRow = rowBytes(t.format, t.levelWidth(s.level)), block = isCompressedFormat(t.format) ? 4 : 1;
    for (int y = 0; y < rowCount(t.format, area->Height); ++y)
        std::memcpy(&level[(std::size_t(area->Y) / block + std::size_t(y)) * levelRow + std::size_t(area->X) / block * texel], &packed[std::size_t(y) * row], row);
}

}  // namespace fxport::d3d11
