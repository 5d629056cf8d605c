// XNA's texture-processor steps on decoded images (see texture_processor.h).
#include "fxport/graphics/texture_processor.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "device/dds_image.h"
#include "device/dxt_encoder.h"
#include "device/image_io.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"

namespace fxport {

namespace {

int nextPowerOfTwo(int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
}

void keyOut(std::vector<Color>& pixels, Color key) {
    for (Color& c : pixels)
        if (c == key) c = Color(0, 0, 0, 0);
}

void premultiply(std::vector<Color>& pixels) {
    // round(v * a / 255): v * a / 255 is never exactly k + 1/2 (255 is odd), so integer rounding is exact.
    auto mul = [](int v, int a) { return (2 * v * a + 255) / 510; };
    for (Color& c : pixels) c = Color(mul(c.R, c.A), mul(c.G, c.A), mul(c.B, c.A), c.A);
}

// Bilinear resampling with texel centres aligned (destination centre (x + 0.5) maps to
// source (x + 0.5) * w / W), edges clamped.
std::vector<Color> resize(const std::vector<Color>& src, int w, int h, int W, int H) {
    std::vector<Color> out(std::size_t(W) * std::size_t(H));
    auto at = [&](int x, int y) -> const Color& {
        return src[std::size_t(std::clamp(y, 0, h - 1)) * std::size_t(w) + std::size_t(std::clamp(x, 0, w - 1))];
    };
    for (int y = 0; y < H; ++y) {
        const double sy = (y + 0.5) * h / H - 0.5;
        const int y0 = int(std::floor(sy));
        const double fy = sy - y0;
        for (int x = 0; x < W; ++x) {
            const double sx = (x + 0.5) * w / W - 0.5;
            const int x0 = int(std::floor(sx));
            const double fx = sx - x0;
            const Color &a = at(x0, y0), &b = at(x0 + 1, y0), &c = at(x0, y0 + 1), &d = at(x0 + 1, y0 + 1);
            auto mix = [&](int ca, int cb, int cc, int cd) {
                const double top = ca + (cb - ca) * fx, bottom = cc + (cd - cc) * fx;
                return int(std::lround(top + (bottom - top) * fy));
            };
            out[std::size_t(y) * std::size_t(W) + std::size_t(x)] =
                Color(mix(a.R, b.R, c.R, d.R), mix(a.G, b.G, c.G, d.G), mix(a.B, b.B, c.B, d.B), mix(a.A, b.A, c.A, d.A));
        }
    }
    return out;
}

// XNA's DxtCompressed rule: Dxt5 for fractional alpha (strictly between 0 and 255), else Dxt1.
SurfaceFormat dxtFormatFor(const std::vector<std::vector<Color>>& levels) {
    for (const std::vector<Color>& level : levels)
        for (const Color& c : level)
            if (c.A != 0 && c.A != 255) return SurfaceFormat::Dxt5;
    return SurfaceFormat::Dxt1;
}

// `levels` (width x height, then its mip chain) block-compressed into a new texture.
std::unique_ptr<Texture2D> compressed(GraphicsDevice& device, const std::string& path, const std::vector<std::vector<Color>>& levels,
                                      int width, int height) {
    if (width % 4 != 0 || height % 4 != 0)
        throw ArgumentError(path + ": TextureFormat DxtCompressed needs a width and height that are multiples of 4 (block-compressed "
                                   "textures are made of 4x4 blocks); the image is " +
                            std::to_string(width) + "x" + std::to_string(height) +
                            " (resize it, set ResizeToPowerOfTwo, or use TextureFormat Color)");
    const SurfaceFormat format = dxtFormatFor(levels);
    auto texture = std::make_unique<Texture2D>(device, width, height, levels.size() > 1, format);
    texture->Name = path;
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const int w = std::max(1, width >> l), h = std::max(1, height >> l);
        const std::vector<std::uint8_t> blocks = detail::encodeDxt(format, levels[l], w, h);
        texture->SetData(int(l), nullptr, blocks.data(), blocks.size());
    }
    return texture;
}

// A .dds as authored, in `format`'s SurfaceFormat (an uncompressed file's decoded levels are read
// back exactly, SurfaceFormat::Color, to be compressed).
std::unique_ptr<Texture2D> loadDds(GraphicsDevice& device, const std::string& path, TextureProcessorOutputFormat format) {
    if (format == TextureProcessorOutputFormat::Color) return detail::texture2DFromDds(device, path);
    std::unique_ptr<Texture2D> texture = detail::texture2DFromDdsAsStored(device, path);
    if (format == TextureProcessorOutputFormat::NoChange || texture->Format() != SurfaceFormat::Color) return texture;
    std::vector<std::vector<Color>> levels;
    for (int l = 0; l < texture->LevelCount(); ++l) {
        levels.emplace_back(std::size_t(std::max(1, texture->Width() >> l)) * std::size_t(std::max(1, texture->Height() >> l)));
        texture->getData(l, levels.back().data(), levels.back().size() * sizeof(Color));
    }
    return compressed(device, path, levels, texture->Width(), texture->Height());
}

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

}  // namespace

TextureProcessor::Output TextureProcessor::Process(std::vector<Color> pixels, int width, int height) const {
    if (width <= 0 || height <= 0 || pixels.size() != std::size_t(width) * std::size_t(height))
        throw ArgumentError("TextureProcessor::Process: " + std::to_string(pixels.size()) + " pixels for a " +
                            std::to_string(width) + "x" + std::to_string(height) + " image");
    if (ColorKeyEnabled) keyOut(pixels, ColorKeyColor);
    int W = ResizeToPowerOfTwo ? nextPowerOfTwo(width) : width;
    int H = ResizeToPowerOfTwo ? nextPowerOfTwo(height) : height;
    if (MakeSquare) W = H = std::max(W, H);
    if (W != width || H != height) pixels = resize(pixels, width, height, W, H);
    if (PremultiplyAlpha) premultiply(pixels);
    Output out{W, H, {std::move(pixels)}};
    for (int w = W, h = H; GenerateMipmaps && (w > 1 || h > 1); w = std::max(1, w / 2), h = std::max(1, h / 2))
        out.levels.push_back(detail::halve(out.levels.back(), w, h));
    return out;
}

std::unique_ptr<Texture2D> TextureProcessor::Load(GraphicsDevice& device, const std::string& path) const {
    if (lowerExtension(path) == ".dds") return loadDds(device, path, TextureFormat);
    detail::Image image = detail::loadImage(path);  // throws ArgumentError naming the file
    Output processed = Process(std::move(image.pixels), image.width, image.height);
    if (TextureFormat == TextureProcessorOutputFormat::DxtCompressed)
        return compressed(device, path, processed.levels, processed.width, processed.height);
    auto texture = std::make_unique<Texture2D>(device, processed.width, processed.height, processed.levels.size() > 1,
                                               SurfaceFormat::Color);
    texture->Name = path;
    for (std::size_t l = 0; l < processed.levels.size(); ++l)
        texture->SetData(int(l), nullptr, processed.levels[l].data(), processed.levels[l].size());
    return texture;
}

std::unique_ptr<TextureCube> TextureProcessor::LoadCube(GraphicsDevice& device, const std::string& path) const {
    if (TextureFormat == TextureProcessorOutputFormat::Color) return TextureCube::FromFile(device, path);
    return detail::textureCubeFromDdsAsStored(device, path);
}

}  // namespace fxport
