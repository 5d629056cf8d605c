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

// How a file stores its texels: the DXGI format that holds them bit for bit (0: none does), the
// layout of a level (4x4 blocks of `blockBytes`, or `bitsPerPixel` per texel), and how they decode
// to RGBA8 (`decode`; Opaque: they do not, e.g. BC4-BC7 and float texels).
struct Format {
    enum Kind { Bc1, Bc2, Bc3, Masks, Opaque } decode = Opaque;
    std::uint32_t dxgi = 0;
    int blockBytes = 0;    // block-compressed: 8 (BC1, BC4) or 16
    int bitsPerPixel = 0;  // uncompressed
    std::uint32_t masks[4] = {0, 0, 0, 0};  // r, g, b, a (decode == Masks)
    bool luminance = false;
    bool premultiplied = false;  // DXT2, DXT4
};

// The bytes of one width x height slice; 64-bit arithmetic (16384^2 texels of 16 bytes fit).
std::uint64_t levelBytes(const Format& f, int w, int h) {
    if (f.blockBytes) return std::uint64_t((w + 3) / 4) * std::uint64_t((h + 3) / 4) * std::uint64_t(f.blockBytes);
    return std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(f.bitsPerPixel / 8);
}

int scaleChannel(std::uint32_t pixel, std::uint32_t mask) {
    if (!mask) return -1;
    const int shift = std::countr_zero(mask), bits = std::popcount(mask);
    const std::uint32_t value = (pixel & mask) >> shift, max = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1;
    return int((std::uint64_t(value) * 255 + max / 2) / max);
}

std::vector<Color> decodeLevel(const Format& f, const std::uint8_t* data, int w, int h) {
    std::vector<Color> texels(std::size_t(w) * std::size_t(h));
    if (f.decode == Format::Masks) {
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
    const std::size_t blockBytes = std::size_t(f.blockBytes);
    const int bw = (w + 3) / 4, bh = (h + 3) / 4;
    Color block[16];
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const std::uint8_t* at = data + (std::size_t(by) * std::size_t(bw) + std::size_t(bx)) * blockBytes;
            if (f.decode == Format::Bc1) decodeBc1Block(at, block);
            else if (f.decode == Format::Bc2) decodeBc2Block(at, block);
            else decodeBc3Block(at, block);
            for (int y = 0; y < 4 && by * 4 + y < h; ++y)
                for (int x = 0; x < 4 && bx * 4 + x < w; ++x) texels[std::size_t(by * 4 + y) * std::size_t(w) + std::size_t(bx * 4 + x)] = block[y * 4 + x];
        }
    return texels;
}

// Bits per texel (or bytes per 4x4 block, as a negative number) of the DXGI formats a DDS file can
// store that D3D11 samples; 0 for the others (video, packed 4:2:2, 1-bit, formats past BC7).
int dxgiLayout(std::uint32_t dxgi) {
    if (dxgi >= 1 && dxgi <= 4) return 128;
    if (dxgi >= 5 && dxgi <= 8) return 96;
    if (dxgi >= 9 && dxgi <= 22) return 64;
    if ((dxgi >= 23 && dxgi <= 47) || dxgi == 67 || (dxgi >= 87 && dxgi <= 93)) return 32;
    if ((dxgi >= 48 && dxgi <= 59) || dxgi == 85 || dxgi == 86 || dxgi == 115) return 16;
    if (dxgi >= 60 && dxgi <= 65) return 8;
    if ((dxgi >= 70 && dxgi <= 72) || (dxgi >= 79 && dxgi <= 81)) return -8;  // BC1, BC4
    if ((dxgi >= 73 && dxgi <= 78) || (dxgi >= 82 && dxgi <= 84) || (dxgi >= 94 && dxgi <= 99)) return -16;  // BC2, BC3, BC5, BC6H, BC7
    return 0;
}

Format formatOfDxgi(std::uint32_t dxgi, const std::string& name) {
    Format f;
    const int layout = dxgiLayout(dxgi);
    if (!layout) throw ArgumentError(name + ": DXGI format " + std::to_string(dxgi) + " is not one fxport reads (a format D3D11 samples, BC1-BC7 included)");
    f.dxgi = dxgi;
    if (layout < 0) f.blockBytes = -layout;
    else f.bitsPerPixel = layout;
    switch (dxgi) {  // those that decode to RGBA8 (Texture2D::FromFile)
    case 71: case 72: f.decode = Format::Bc1; break;
    case 74: case 75: f.decode = Format::Bc2; break;
    case 77: case 78: f.decode = Format::Bc3; break;
    case 28: case 29: f.decode = Format::Masks; f.masks[0] = 0xFF; f.masks[1] = 0xFF00; f.masks[2] = 0xFF0000; f.masks[3] = 0xFF000000u; break;
    case 87: case 91: f.decode = Format::Masks; f.masks[0] = 0xFF0000; f.masks[1] = 0xFF00; f.masks[2] = 0xFF; f.masks[3] = 0xFF000000u; break;
    case 88: case 93: f.decode = Format::Masks; f.masks[0] = 0xFF0000; f.masks[1] = 0xFF00; f.masks[2] = 0xFF; break;
    default: break;
    }
    return f;
}

// A FourCC: DXT1-5 and BC4/BC5's names (ATI1, BC4U, BC4S, ATI2, BC5U, BC5S), or a D3DFORMAT number
// D3DX9 writes there for 16-bit and float texels (DirectXTK's DDSTextureLoader reads the same).
Format formatOfFourCC(std::span<const std::uint8_t> b, const std::string& name) {
    const std::uint32_t code = u32(b, 84);
    Format f;
    auto block = [&](std::uint32_t dxgi, Format::Kind decode) {
        f = formatOfDxgi(dxgi, name);
        f.decode = decode;
        return f;
    };
    if (code == fourCC("DXT1")) return block(71, Format::Bc1);
    if (code == fourCC("DXT2") || code == fourCC("DXT3")) return f = block(74, Format::Bc2), f.premultiplied = code == fourCC("DXT2"), f;
    if (code == fourCC("DXT4") || code == fourCC("DXT5")) return f = block(77, Format::Bc3), f.premultiplied = code == fourCC("DXT4"), f;
    if (code == fourCC("ATI1") || code == fourCC("BC4U")) return block(80, Format::Opaque);
    if (code == fourCC("BC4S")) return block(81, Format::Opaque);
    if (code == fourCC("ATI2") || code == fourCC("BC5U")) return block(83, Format::Opaque);
    if (code == fourCC("BC5S")) return block(84, Format::Opaque);
    switch (code) {
    case 36: return formatOfDxgi(11, name);   // D3DFMT_A16B16G16R16 -> R16G16B16A16_UNORM
    case 110: return formatOfDxgi(13, name);  // D3DFMT_Q16W16V16U16 -> R16G16B16A16_SNORM
    case 111: return formatOfDxgi(54, name);  // D3DFMT_R16F
    case 112: return formatOfDxgi(34, name);  // D3DFMT_G16R16F
    case 113: return formatOfDxgi(10, name);  // D3DFMT_A16B16G16R16F
    case 114: return formatOfDxgi(41, name);  // D3DFMT_R32F
    case 115: return formatOfDxgi(16, name);  // D3DFMT_G32R32F
    case 116: return formatOfDxgi(2, name);   // D3DFMT_A32B32G32R32F
    default: break;
    }
    std::string text(reinterpret_cast<const char*>(&b[84]), 4);
    for (char& c : text)
        if (c < 32 || c > 126) c = '?';
    throw ArgumentError(name + ": compression '" + text + "' is not one fxport reads (FourCC " + std::to_string(code) +
                        "; it reads DXT1-DXT5, ATI1/BC4U/BC4S, ATI2/BC5U/BC5S, D3DFMT 36 and 110-116, DX10)");
}

// The DXGI format whose bits are those of a legacy channel-mask format (DirectXTK's table; A2B10G10R10
// files written by D3DX have their red and blue masks swapped, read as D3DX meant them); 0 when none.
std::uint32_t dxgiOfMasks(std::uint32_t flags, int bits, const std::uint32_t m[4]) {
    auto is = [&](std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a) { return m[0] == r && m[1] == g && m[2] == b && m[3] == a; };
    if (flags & 0x40) {  // DDPF_RGB
        if (bits == 32 && is(0xFF, 0xFF00, 0xFF0000, 0xFF000000u)) return 28;         // R8G8B8A8_UNORM
        if (bits == 32 && is(0xFF0000, 0xFF00, 0xFF, 0xFF000000u)) return 87;         // B8G8R8A8_UNORM
        if (bits == 32 && is(0xFF0000, 0xFF00, 0xFF, 0)) return 88;                   // B8G8R8X8_UNORM
        if (bits == 32 && is(0x3FF00000, 0xFFC00, 0x3FF, 0xC0000000u)) return 24;     // R10G10B10A2_UNORM
        if (bits == 32 && is(0xFFFF, 0xFFFF0000u, 0, 0)) return 35;                   // R16G16_UNORM
        if (bits == 32 && is(0xFFFFFFFFu, 0, 0, 0)) return 41;                        // R32_FLOAT
        if (bits == 16 && is(0x7C00, 0x3E0, 0x1F, 0x8000)) return 86;                 // B5G5R5A1_UNORM
        if (bits == 16 && is(0xF800, 0x7E0, 0x1F, 0)) return 85;                      // B5G6R5_UNORM
        if (bits == 16 && is(0xF00, 0xF0, 0xF, 0xF000)) return 115;                   // B4G4R4A4_UNORM
        if (bits == 16 && is(0xFF, 0, 0, 0xFF00)) return 49;                          // R8G8_UNORM
        if (bits == 16 && is(0xFFFF, 0, 0, 0)) return 56;                             // R16_UNORM
        if (bits == 8 && is(0xFF, 0, 0, 0)) return 61;                                // R8_UNORM
    } else if (flags & 0x20000) {  // DDPF_LUMINANCE
        if (bits == 16 && is(0xFFFF, 0, 0, 0)) return 56;
        if ((bits == 16 || bits == 8) && is(0xFF, 0, 0, 0xFF00)) return 49;
        if (bits == 8 && is(0xFF, 0, 0, 0)) return 61;
    } else if ((flags & 0x2) && bits == 8) {  // DDPF_ALPHA
        return 65;                           // A8_UNORM
    } else if (flags & 0x80000) {            // DDPF_BUMPDUDV: signed texels
        if (bits == 32 && is(0xFF, 0xFF00, 0xFF0000, 0xFF000000u)) return 31;  // R8G8B8A8_SNORM
        if (bits == 32 && is(0xFFFF, 0xFFFF0000u, 0, 0)) return 37;            // R16G16_SNORM
        if (bits == 16 && is(0xFF, 0xFF00, 0, 0)) return 51;                   // R8G8_SNORM
    }
    return 0;
}

Format formatOfPixelFormat(std::span<const std::uint8_t> b, const std::string& name) {
    const std::uint32_t flags = u32(b, 80);
    if (flags & 0x4) return formatOfFourCC(b, name);  // DDPF_FOURCC
    Format f;
    f.bitsPerPixel = int(std::min<std::uint32_t>(u32(b, 88), 1024));
    if (f.bitsPerPixel != 8 && f.bitsPerPixel != 16 && f.bitsPerPixel != 24 && f.bitsPerPixel != 32)
        throw ArgumentError(name + ": " + std::to_string(u32(b, 88)) + " bits per pixel is not a format fxport reads");
    f.luminance = (flags & 0x20000) != 0;  // DDPF_LUMINANCE: the red mask is the luminance
    f.masks[0] = u32(b, 92), f.masks[1] = u32(b, 96), f.masks[2] = u32(b, 100), f.masks[3] = u32(b, 104);
    f.dxgi = dxgiOfMasks(flags, f.bitsPerPixel, f.masks);
    if (f.dxgi == 24) std::swap(f.masks[0], f.masks[2]);  // D3DX's swapped A2B10G10R10 masks (see dxgiOfMasks)
    if (!(flags & 0x40) && !f.luminance) f.masks[0] = f.masks[1] = f.masks[2] = 0;
    if (!(flags & 0x3)) f.masks[3] = 0;  // neither DDPF_ALPHAPIXELS nor DDPF_ALPHA
    f.decode = (flags & 0x80000) ? Format::Opaque : Format::Masks;  // signed bump-map texels do not decode to colours
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

namespace {

constexpr int kMaxArraySize = 2048;  // D3D11's largest Texture2DArray

// The DX10 header's resource dimension, array size and cube flag (DirectXTK's rules: a 3D one needs
// DDSD_DEPTH, is no array; a 1D one has height 1).
void readDx10Header(std::span<const std::uint8_t> b, const std::string& name, DdsImage& image) {
    const std::uint32_t dimension = u32(b, 132), arraySize = u32(b, 140);
    if (arraySize == 0 || arraySize > std::uint32_t(kMaxArraySize))
        throw ArgumentError(name + ": DX10 header's array size " + std::to_string(arraySize) + " (1.." + std::to_string(kMaxArraySize) + ")");
    image.arraySize = int(arraySize);
    if (dimension == 2) {  // D3D10_RESOURCE_DIMENSION_TEXTURE1D
        if (image.height != 1) throw ArgumentError(name + ": a 1D texture of height " + std::to_string(image.height));
        image.oneDimensional = true;
    } else if (dimension == 3) {
        image.cube = (u32(b, 136) & 0x4) != 0;  // D3D11_RESOURCE_MISC_TEXTURECUBE
        image.volume = false;
    } else if (dimension == 4) {
        image.volume = true;
        image.cube = false;
        if (arraySize > 1) throw ArgumentError(name + ": a volume texture with array size " + std::to_string(arraySize) + " (volumes are not arrays)");
    } else {
        throw ArgumentError(name + ": DX10 header's resource dimension " + std::to_string(dimension) + " is not a texture's (2, 3 or 4)");
    }
    const std::uint32_t alpha = u32(b, 144) & 0x7;  // DDS_MISC_FLAGS2_ALPHA_MODE_MASK
    image.alphaMode = alpha <= 4 ? int(alpha) : 0;
}

// The header's size, kind (2D, cube, volume, array) and level count; the texels start at `offset`.
Format readHeader(std::span<const std::uint8_t> b, const std::string& name, DdsImage& image, std::size_t& offset) {
    if (b.size() < 128 || std::memcmp(b.data(), "DDS ", 4) != 0 || u32(b, 4) != 124)
        throw ArgumentError(name + ": not a DDS file (no 'DDS ' magic and 124-byte header)");
    image.height = int(std::min<std::uint32_t>(u32(b, 12), INT_MAX));
    image.width = int(std::min<std::uint32_t>(u32(b, 16), INT_MAX));
    if (image.width < 1 || image.height < 1 || image.width > kMaxSide || image.height > kMaxSide)
        throw ArgumentError(name + ": " + std::to_string(u32(b, 16)) + "x" + std::to_string(u32(b, 12)) + " is not a size fxport loads (1.." +
                            std::to_string(kMaxSide) + ")");
    const std::uint32_t caps2 = u32(b, 112);
    image.volume = (caps2 & 0x200000) != 0;  // DDSCAPS2_VOLUME
    image.cube = (caps2 & 0x200) != 0;
    offset = 128;
    Format format;
    if ((u32(b, 80) & 0x4) && u32(b, 84) == fourCC("DX10")) {
        if (b.size() < 148) throw ArgumentError(name + ": truncated DX10 header");
        format = formatOfDxgi(u32(b, 128), name);
        readDx10Header(b, name, image);
        offset = 148;
    } else {
        format = formatOfPixelFormat(b, name);
        image.volume = image.volume || (u32(b, 8) & 0x800000);  // DDSD_DEPTH
        if (image.cube && (caps2 & 0xFC00) != 0xFC00)
            throw ArgumentError(name + ": a cube map without all six faces (DDSCAPS2 " + std::to_string(caps2) + "); D3D has no partial cubes");
        image.alphaMode = format.premultiplied ? 2 : 0;
    }
    if (image.volume) {
        image.depth = int(std::min<std::uint32_t>(u32(b, 24), INT_MAX));
        if (image.cube || image.depth < 1 || image.depth > kMaxVolumeDepth || image.width > kMaxVolumeDepth || image.height > kMaxVolumeDepth)
            throw ArgumentError(name + ": a volume texture " + (image.cube ? std::string("that is also a cube map") : "of " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + "x" + std::to_string(u32(b, 24))) + " is not one fxport loads (1.." + std::to_string(kMaxVolumeDepth) + " each)");
    }
    image.dxgiFormat = format.dxgi;
    image.decodable = format.decode != Format::Opaque;
    const int fullChain = int(std::bit_width(unsigned(std::max({image.width, image.height, image.depth}))));  // levels down to 1x1x1
    const std::uint32_t stored = u32(b, 28);  // mipMapCount; 0 is one level (DirectXTK reads it whatever DDSD_MIPMAPCOUNT says)
    image.levelCount = int(std::clamp<std::uint32_t>(stored, 1, std::uint32_t(fullChain)));
    return format;
}

// Each subresource's bytes in the file's order (array item, face, level; a volume level's slices
// together), checked against the file's length before anything is copied.
void readLevels(std::span<const std::uint8_t> b, const std::string& name, const Format& format, bool decode, std::size_t offset, DdsImage& image) {
    const int faces = image.cube ? 6 : 1;
    for (int item = 0; item < image.arraySize; ++item)
        for (int face = 0; face < faces; ++face)
            for (int level = 0; level < image.levelCount; ++level) {
                const int w = std::max(1, image.width >> level), h = std::max(1, image.height >> level), slices = std::max(1, image.depth >> level);
                const std::uint64_t slice = levelBytes(format, w, h), bytes = slice * std::uint64_t(slices);
                if (offset > b.size() || b.size() - offset < bytes) {
                    const std::uint64_t whole = offset > b.size() ? 0 : (b.size() - offset) / slice;  // a volume's slices present
                    throw ArgumentError(name + ": truncated: level " + std::to_string(level) + (image.arraySize > 1 ? " of array item " + std::to_string(item) : "") +
                                        (image.cube ? " of face " + std::to_string(face) : "") + (image.volume ? " slice " + std::to_string(whole) : "") +
                                        " needs " + std::to_string(image.volume ? slice : bytes) + " bytes at offset " +
                                        std::to_string(offset + whole * slice * (image.volume ? 1 : 0)) + ", the file has " + std::to_string(b.size()));
                }
                const std::uint8_t* at = b.data() + offset;
                if (decode) {
                    std::vector<Color> texels;
                    for (int z = 0; z < slices; ++z) {
                        std::vector<Color> one = decodeLevel(format, at + std::size_t(slice) * std::size_t(z), w, h);
                        texels.insert(texels.end(), one.begin(), one.end());
                    }
                    image.levels.push_back(std::move(texels));
                } else {
                    image.stored.emplace_back(at, at + bytes);
                }
                offset += std::size_t(bytes);
            }
}

}  // namespace

DdsImage decodeDds(std::span<const std::uint8_t> b, const std::string& name, DdsContent content) {
    DdsImage image;
    std::size_t offset = 0;
    const Format format = readHeader(b, name, image, offset);
    const bool decode = content == DdsContent::Decoded;
    if (decode && format.decode == Format::Opaque)
        throw ArgumentError(name + ": DXGI format " + std::to_string(format.dxgi) +
                            " does not decode to 8-bit RGBA here (fxport decodes DXT1-DXT5, 8-bit RGBA/BGRA and channel-mask formats; "
                            "D3DX11CreateShaderResourceViewFromFile keeps the rest as stored)");
    if (decode && (image.arraySize > 1 || image.oneDimensional))
        throw ArgumentError(name + ": a " + (image.oneDimensional ? std::string("1D texture") : "texture array of " + std::to_string(image.arraySize)) +
                            "; fxport loads one 2D, cube or volume texture here");
    if (!decode && image.dxgiFormat == 0 && format.decode == Format::Opaque)
        throw ArgumentError(name + ": signed (bump-map) texels of a layout no DXGI format holds");
    if (!decode && image.dxgiFormat == 0) {
        readLevels(b, name, format, true, offset, image);  // no DXGI format holds these texels: 8-bit RGBA instead
        return image;
    }
    readLevels(b, name, format, decode, offset, image);
    return image;
}

DdsImage readDds(const std::string& path, DdsContent content) {
    platform::FileBytes file = platform::readUntrustedFile(path);
    if (!file.ok()) throw ArgumentError((content == DdsContent::Decoded ? "Texture2D::FromFile: " : "") + file.error);
    return decodeDds(file.bytes, path, content);
}

}  // namespace fxport::detail
