// .dds files whose BC1/BC2/BC3 blocks are kept compressed: TextureProcessor's NoChange and
// DxtCompressed outputs (XNA's TextureProcessorOutputFormat) upload a DXT1/3/5 file's blocks as
// SurfaceFormat::Dxt1/Dxt3/Dxt5, level by level as stored. Other files load decoded, as
// Texture2D::FromFile and TextureCube::FromFile do (texture.cpp, texture_cube_file.cpp).
#include <algorithm>
#include <string>
#include <vector>

#include "device/dds_image.h"
#include "device/dxt_encoder.h"
#include "device/image_io.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"

namespace fxport::detail {

namespace {

// The XNA format holding a DXGI format's blocks bit for bit; Color when none does. The _SRGB
// variants (72, 75, 78) hold the same bits; XNA's Dxt formats have no sRGB reading, nor does
// the decoded path.
SurfaceFormat dxtFormatOf(std::uint32_t dxgi) {
    if (dxgi == 71 || dxgi == 72) return SurfaceFormat::Dxt1;
    if (dxgi == 74 || dxgi == 75) return SurfaceFormat::Dxt3;
    if (dxgi == 77 || dxgi == 78) return SurfaceFormat::Dxt5;
    return SurfaceFormat::Color;
}

std::vector<Color> decodeBlocks(SurfaceFormat format, const std::vector<std::uint8_t>& bytes, int w, int h) {
    std::vector<Color> texels(std::size_t(w) * std::size_t(h));
    const std::size_t blockBytes = format == SurfaceFormat::Dxt1 ? 8 : 16;
    const int bw = (w + 3) / 4;
    Color block[16];
    for (int by = 0; by < (h + 3) / 4; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const std::uint8_t* at = bytes.data() + (std::size_t(by) * std::size_t(bw) + std::size_t(bx)) * blockBytes;
            if (format == SurfaceFormat::Dxt1) decodeBc1Block(at, block);
            else if (format == SurfaceFormat::Dxt3) decodeBc2Block(at, block);
            else decodeBc3Block(at, block);
            for (int y = 0; y < 4 && by * 4 + y < h; ++y)
                for (int x = 0; x < 4 && bx * 4 + x < w; ++x) texels[std::size_t(by * 4 + y) * std::size_t(w) + std::size_t(bx * 4 + x)] = block[y * 4 + x];
        }
    return texels;
}

// Level `l` of one face: stored blocks while the file has them; past a partial chain, the level
// above decoded, its 2x2 averages (as GenerateMips would) encoded again.
struct BlockChain {
    SurfaceFormat format;
    int side0w, side0h;
    std::vector<std::uint8_t> previous;
    const std::vector<std::uint8_t>& level(const DdsImage& dds, std::size_t first, int l) {
        if (l < dds.levelCount) return previous = dds.stored[first + std::size_t(l)];
        const int w = std::max(1, side0w >> (l - 1)), h = std::max(1, side0h >> (l - 1));
        const std::vector<Color> half = halve(decodeBlocks(format, previous, w, h), w, h);
        return previous = encodeDxt(format, half, std::max(1, w / 2), std::max(1, h / 2));
    }
};

}  // namespace

std::unique_ptr<Texture2D> texture2DFromDdsAsStored(GraphicsDevice& device, const std::string& path) {
    const DdsImage dds = readDds(path, DdsContent::Stored);
    const SurfaceFormat format = dxtFormatOf(dds.dxgiFormat);
    if (format == SurfaceFormat::Color || dds.cube || dds.volume || dds.arraySize > 1 || dds.oneDimensional)
        return texture2DFromDds(device, path);  // decoded, or refused by name as Texture2D::FromFile does
    auto texture = std::make_unique<Texture2D>(device, dds.width, dds.height, dds.levelCount > 1, format);
    texture->Name = path;
    BlockChain chain{format, dds.width, dds.height, {}};
    for (int l = 0; l < texture->LevelCount(); ++l) {
        const std::vector<std::uint8_t>& blocks = chain.level(dds, 0, l);
        texture->SetData(l, nullptr, blocks.data(), blocks.size());
    }
    return texture;
}

std::unique_ptr<TextureCube> textureCubeFromDdsAsStored(GraphicsDevice& device, const std::string& path) {
    const DdsImage dds = readDds(path, DdsContent::Stored);
    const SurfaceFormat format = dxtFormatOf(dds.dxgiFormat);
    if (format == SurfaceFormat::Color || !dds.cube || dds.width != dds.height || dds.arraySize > 1)
        return TextureCube::FromFile(device, path);  // decoded, or refused by name
    auto cube = std::make_unique<TextureCube>(device, dds.width, dds.levelCount > 1, format);
    cube->Name = path;
    for (int face = 0; face < 6; ++face) {
        BlockChain chain{format, dds.width, dds.height, {}};
        for (int l = 0; l < cube->LevelCount(); ++l) {
            const std::vector<std::uint8_t>& blocks = chain.level(dds, std::size_t(face * dds.levelCount), l);
            cube->SetData(CubeMapFace(face), l, blocks.data(), blocks.size());
        }
    }
    return cube;
}

}  // namespace fxport::detail
