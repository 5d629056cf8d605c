#include "device/dds_image.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cstring>

#include "fxport/graphics/errors.h"
#include "fxport/platform/file_reading.h"

namespace fxport::detail {

namespace {

constexpr int kMaxSide = 16384;  // D3D11's largest Texture2D
constexpr int kMaxVolumeDepth = 2048;  // D3D11's largest Texture3D (Texture3D checks width and height)

std::uint32_t u32(std::span<const std::uint8_t> b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 | std::uint32_t(b[at + 3]) << 24;
}

constexpr std::uint32_t fourCC(const char (&s)[5]) {
    return std::uint32_t(std::uint8_t(s[0])) | std::uint32_t(std::uint8_t(s[1])) << 8 | std::uint32_t(std::uint8_t(s[2])) << 16 |
           std::uint32_t(std::uint8_t(s[3])) << 24;
}

// RGB565 -> 8-bit channels by bit replication (the same as rounding c * 255 / 31 and c * 255 / 63).
void expand565(std::uint16_t c, int rgb[3]) {
    int r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
    rgb[0] = (r << 3) | (r >> 2);
    rgb[1] = (g << 2) | (g >> 4);
    rgb[2] = (b << 3) | (b >> 2);
}

// The colour half of a BC1/2/3 block; `threeColourMode` only for BC1 when c0 <= c1.
void decodeColours(const std::uint8_t* block, bool allowThreeColour, Color out[16]) {
    const std::uint16_t c0 = std::uint16_t(block[0] | block[1] << 8), c1 = std::uint16_t(block[2] | block[3] << 8);
    int p[4][4];
    expand565(c0, p[0]);
    expand565(c1, p[1]);
    const bool three = allowThreeColour && c0 <= c1;
    for (int k = 0; k < 3; ++k) {
        if (three) {
            p[2][k] = (p[0][k] + p[1][k] + 1) / 2;
            p[3][k] = 0;
        } else {
            p[2][k] = (2 * p[0][k] + p[1][k] + 1) / 3;
            p[3][k] = (p[0][k] + 2 * p[1][k] + 1) / 3;
        }
    }
    const std::uint32_t indices = std::uint32_t(block[4]) | std::uint32_t(block[5]) << 8 | std::uint32_t(block[6]) << 16 |
                                  std::uint32_t(block[7]) << 24;
    for (int i = 0; i < 16; ++i) {
        const int at = (indices >> (2 * i)) & 3;
        out[i] = Color(p[at][0], p[at][1], p[at][2], three && at == 3 ? 0 : 255);
    }
}

struct Format {
    enum Kind { Bc1, Bc2, Bc3, Masks } kind = Masks;
    int bitsPerPixel = 0;
    std::uint32_t masks[4] = {0, 0, 0, 0};  // r, g, b, a
    bool luminance = false;
};

std::size_t levelBytes(const Format& f, int w, int h) {
    if (f.kind == Format::Masks) return std::size_t(w) * std::size_t(h) * std::size_t(f.bitsPerPixel / 8);
    const std::size_t blocks = std::size_t((w + 3) / 4) * std::size_t((h + 3) / 4);
    return blocks * (f.kind == Format::Bc1 ? 8 : 16);
}

int scaleChannel(std::uint32_t pixel, std::uint32_t mask) {
    if (!mask) return -1;
    const int shift = std::countr_zero(mask), bits = std::popcount(mask);
    const std::uint32_t value = (pixel & mask) >> shift, max = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1;
    return int((std::uint64_t(value) * 255 + max / 2) / max);
}

std::vector<Color> decodeLevel(const Format& f, const std::uint8_t* data, int w, int h) {
    std::vector<Color> texels(std::size_t(w) * std::size_t(h));
    if (f.kind == Format::Masks) {
        const int bytes = f.bitsPerPixel / 8;
        for (std::size_t i = 0; i < texels.size(); ++i) {
            std::uint32_t pixel = 0;
            for (int b = 0; b < bytes; ++b) pixel |= std::uint32_t(data[i * std::size_t(bytes) + std::size_t(b)]) << (8 * b);
            const int r = scaleChannel(pixel, f.masks[0]), g = scaleChannel(pixel, f.masks[1]), b = scaleChannel(pixel, f.masks[2]),
                      a = scaleChannel(pixel, f.masks[3]);
            if (f.luminance) texels[i] = Color(std::max(r, 0), std::max(r, 0), std::max(r, 0), a < 0 ? 255 : a);
            else texels[i] = Color(std::max(r, 0), std::max(g, 0), std::max(b, 0), a < 0 ? 255 : a);
        }
        return texels;
    }
    const std::size_t blockBytes = f.kind == Format::Bc1 ? 8 : 16;
    const int bw = (w + 3) / 4, bh = (h + 3) / 4;
    Color block[16];
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const std::uint8_t* at = data + (std::size_t(by) * std::size_t(bw) + std::size_t(bx)) * blockBytes;
            if (f.kind == Format::Bc1) decodeBc1Block(at, block);
            else if (f.kind == Format::Bc2) decodeBc2Block(at, block);
            else decodeBc3Block(at, block);
            for (int y = 0; y < 4 && by * 4 + y < h; ++y)
                for (int x = 0; x < 4 && bx * 4 + x < w; ++x) texels[std::size_t(by * 4 + y) * std::size_t(w) + std::size_t(bx * 4 + x)] = block[y * 4 + x];
        }
    return texels;
}

Format formatOfDxgi(std::uint32_t dxgi, const std::string& name) {
    Format f;
    switch (dxgi) {
    case 71: case 72: f.kind = Format::Bc1; return f;
    case 74: case 75: f.kind = Format::Bc2; return f;
    case 77: case 78: f.kind = Format::Bc3; return f;
    case 28: case 29: f.bitsPerPixel = 32; f.masks[0] = 0xFF; f.masks[1] = 0xFF00; f.masks[2] = 0xFF0000; f.masks[3] = 0xFF000000u; return f;
    case 87: case 91: f.bitsPerPixel = 32; f.masks[0] = 0xFF0000; f.masks[1] = 0xFF00; f.masks[2] = 0xFF; f.masks[3] = 0xFF000000u; return f;
    case 88: case 93: f.bitsPerPixel = 32; f.masks[0] = 0xFF0000; f.masks[1] = 0xFF00; f.masks[2] = 0xFF; return f;
    default: throw ArgumentError(name + ": DXGI format " + std::to_string(dxgi) + " is not one fxport reads (R8G8B8A8, B8G8R8A8/X8, BC1-BC3)");
    }
}

Format formatOfPixelFormat(std::span<const std::uint8_t> b, const std::string& name) {
    const std::uint32_t flags = u32(b, 80), code = u32(b, 84);
    Format f;
    if (flags & 0x4) {  // DDPF_FOURCC
        if (code == fourCC("DXT1")) f.kind = Format::Bc1;
        else if (code == fourCC("DXT2") || code == fourCC("DXT3")) f.kind = Format::Bc2;
        else if (code == fourCC("DXT4") || code == fourCC("DXT5")) f.kind = Format::Bc3;
        else {
            std::string text(reinterpret_cast<const char*>(&b[84]), 4);
            throw ArgumentError(name + ": compression '" + text + "' is not one fxport reads (DXT1, DXT3, DXT5)");
        }
        return f;
    }
    f.bitsPerPixel = int(u32(b, 88));
    if (f.bitsPerPixel != 8 && f.bitsPerPixel != 16 && f.bitsPerPixel != 24 && f.bitsPerPixel != 32)
        throw ArgumentError(name + ": " + std::to_string(f.bitsPerPixel) + " bits per pixel is not a format fxport reads");
    f.luminance = (flags & 0x20000) != 0;  // DDPF_LUMINANCE: the red mask is the luminance
    if (flags & 0x40 || f.luminance) f.masks[0] = u32(b, 92), f.masks[1] = u32(b, 96), f.masks[2] = u32(b, 100);
    if (flags & 0x3) f.masks[3] = u32(b, 104);  // DDPF_ALPHAPIXELS or DDPF_ALPHA
    return f;
}

}  // namespace

void decodeBc1Block(const std::uint8_t* block, Color out[16]) { decodeColours(block, true, out); }

void decodeBc2Block(const std::uint8_t* block, Color out[16]) {
    decodeColours(block + 8, false, out);
    for (int i = 0; i < 16; ++i) out[i].A = std::uint8_t(((block[i / 2] >> (4 * (i % 2))) & 15) * 17);
}

void decodeBc3Block(const std::uint8_t* block, Color out[16]) {
    decodeColours(block + 8, false, out);
    int a[8] = {block[0], block[1]};
    if (a[0] > a[1]) {
        for (int i = 1; i < 7; ++i) a[i + 1] = ((7 - i) * a[0] + i * a[1] + 3) / 7;
    } else {
        for (int i = 1; i < 5; ++i) a[i + 1] = ((5 - i) * a[0] + i * a[1] + 2) / 5;
        a[6] = 0;
        a[7] = 255;
    }
    std::uint64_t bits = 0;
    for (int k = 0; k < 6; ++k) bits |= std::uint64_t(block[2 + k]) << (8 * k);
    for (int i = 0; i < 16; ++i) out[i].A = std::uint8_t(a[(bits >> (3 * i)) & 7]);
}

DdsImage decodeDds(std::span<const std::uint8_t> b, const std::string& name) {
    if (b.size() < 128 || std::memcmp(b.data(), "DDS ", 4) != 0 || u32(b, 4) != 124)
        throw ArgumentError(name + ": not a DDS file (no 'DDS ' magic and 124-byte header)");
    DdsImage image;
    image.height = int(std::min<std::uint32_t>(u32(b, 12), INT_MAX));
    image.width = int(std::min<std::uint32_t>(u32(b, 16), INT_MAX));
    if (image.width < 1 || image.height < 1 || image.width > kMaxSide || image.height > kMaxSide)
        throw ArgumentError(name + ": " + std::to_string(u32(b, 16)) + "x" + std::to_string(u32(b, 12)) + " is not a size fxport loads (1.." +
                            std::to_string(kMaxSide) + ")");
    const std::uint32_t caps2 = u32(b, 112);
    image.volume = (caps2 & 0x200000) != 0;  // DDSCAPS2_VOLUME
    image.cube = (caps2 & 0x200) != 0;
    std::size_t offset = 128;
    Format format;
    if ((u32(b, 80) & 0x4) && u32(b, 84) == fourCC("DX10")) {
        if (b.size() < 148) throw ArgumentError(name + ": truncated DX10 header");
        format = formatOfDxgi(u32(b, 128), name);
        image.cube = image.cube || (u32(b, 136) & 0x4);
        image.volume = image.volume || u32(b, 132) == 4;  // D3D10_RESOURCE_DIMENSION_TEXTURE3D
        if (u32(b, 140) > 1) throw ArgumentError(name + ": a texture array of " + std::to_string(u32(b, 140)) + "; fxport loads one texture");
        offset = 148;
    } else {
        format = formatOfPixelFormat(b, name);
    }
    if (image.volume) {
        image.depth = int(std::min<std::uint32_t>(u32(b, 24), INT_MAX));
        if (image.cube || image.depth < 1 || image.depth > kMaxVolumeDepth)
            throw ArgumentError(name + ": a volume texture " + (image.cube ? std::string("that is also a cube map") : "of depth " + std::to_string(u32(b, 24))) +
                                " is not one fxport loads (depth 1.." + std::to_string(kMaxVolumeDepth) + ")");
    }
    const int fullChain = int(std::bit_width(unsigned(std::max({image.width, image.height, image.depth}))));  // levels down to 1x1x1
    const std::uint32_t stored = (u32(b, 8) & 0x20000) ? u32(b, 28) : 1;  // DDSD_MIPMAPCOUNT
    image.levelCount = int(std::clamp<std::uint32_t>(stored, 1, std::uint32_t(fullChain)));
    for (int face = 0; face < (image.cube ? 6 : 1); ++face)
        for (int level = 0; level < image.levelCount; ++level) {
            const int w = std::max(1, image.width >> level), h = std::max(1, image.height >> level);
            const std::size_t bytes = levelBytes(format, w, h);  // of one slice; a volume's slices follow each other
            std::vector<Color> texels;
            for (int slice = 0; slice < std::max(1, image.depth >> level); ++slice) {
                if (offset > b.size() || b.size() - offset < bytes)
                    throw ArgumentError(name + ": truncated: level " + std::to_string(level) + (image.cube ? " of face " + std::to_string(face) : "") +
                                        (image.volume ? " slice " + std::to_string(slice) : "") + " needs " + std::to_string(bytes) +
                                        " bytes at offset " + std::to_string(offset) + ", the file has " + std::to_string(b.size()));
                std::vector<Color> one = decodeLevel(format, b.data() + offset, w, h);
                texels.insert(texels.end(), one.begin(), one.end());
                offset += bytes;
            }
            image.levels.push_back(std::move(texels));
        }
    return image;
}

DdsImage readDds(const std::string& path) {
    platform::FileBytes file = platform::readUntrustedFile(path);
    if (!file.ok()) throw ArgumentError("Texture2D::FromFile: " + file.error);
    return decodeDds(file.bytes, path);
}

}  // namespace fxport::detail
