// BC1/BC2/BC3 block encoding over stb_dxt (see dxt_encoder.h).
#include "device/dxt_encoder.h"

#include <algorithm>
#include <array>

#include <cstring>  // stb_dxt.h uses memcpy without including it

#define STB_DXT_IMPLEMENTATION
#include <stb/stb_dxt.h>

namespace fxport::detail {

namespace {

using Block = std::array<Color, 16>;

// The RGB565 endpoint `c` widened by bit replication, as decoders do.
std::array<int, 3> widen565(unsigned c) {
    const unsigned r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    return {int(r << 3 | r >> 2), int(g << 2 | g >> 4), int(b << 3 | b >> 2)};
}

// An opaque block's colour half (8 bytes, four-colour mode) from stb_dxt.
void encodeOpaqueColours(const Block& block, std::uint8_t out[8]) {
    unsigned char rgba[64];
    for (int i = 0; i < 16; ++i) {
        const Color& c = block[std::size_t(i)];
        rgba[4 * i] = c.R, rgba[4 * i + 1] = c.G, rgba[4 * i + 2] = c.B, rgba[4 * i + 3] = 255;
    }
    stb_compress_dxt_block(out, rgba, 0, STB_DXT_HIGHQUAL);
}

// BC1 with transparent texels: the three-colour mode (c0 <= c1; c2 = (c0 + c1) / 2, index 3
// transparent black). The endpoints are those stb_dxt picks for the opaque texels alone.
void encodeBc1WithTransparency(const Block& block, std::uint8_t out[8]) {
    Block opaque = block;
    const auto firstOpaque = std::find_if(block.begin(), block.end(), [](const Color& c) { return c.A >= 128; });
    if (firstOpaque == block.end()) {  // all transparent: c0 = c1 = 0, every index 3
        const std::uint8_t clear[8] = {0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF};
        std::copy(clear, clear + 8, out);
        return;
    }
    for (Color& c : opaque)
        if (c.A < 128) c = *firstOpaque;  // transparent texels must not pull the endpoints
    encodeOpaqueColours(opaque, out);
    unsigned c0 = unsigned(out[0] | out[1] << 8), c1 = unsigned(out[2] | out[3] << 8);
    if (c0 > c1) std::swap(c0, c1);
    out[0] = std::uint8_t(c0), out[1] = std::uint8_t(c0 >> 8), out[2] = std::uint8_t(c1), out[3] = std::uint8_t(c1 >> 8);
    const auto a = widen565(c0), b = widen565(c1);
    const std::array<int, 3> palette[3] = {a, b, {(a[0] + b[0] + 1) / 2, (a[1] + b[1] + 1) / 2, (a[2] + b[2] + 1) / 2}};
    std::uint32_t indices = 0;
    for (int i = 0; i < 16; ++i) {
        const Color& c = block[std::size_t(i)];
        int best = 3;
        if (c.A >= 128) {
            int bestError = 1 << 30;
            for (int k = 0; k < 3; ++k) {
                const int dr = c.R - palette[k][0], dg = c.G - palette[k][1], db = c.B - palette[k][2];
                const int error = dr * dr + dg * dg + db * db;
                if (error < bestError) bestError = error, best = k;
            }
        }
        indices |= std::uint32_t(best) << (2 * i);
    }
    for (int k = 0; k < 4; ++k) out[4 + k] = std::uint8_t(indices >> (8 * k));
}

void encodeBlock(SurfaceFormat format, const Block& block, std::uint8_t* out) {
    if (format == SurfaceFormat::Dxt1) {
        const bool transparent = std::any_of(block.begin(), block.end(), [](const Color& c) { return c.A < 128; });
        if (transparent) encodeBc1WithTransparency(block, out);
        else encodeOpaqueColours(block, out);
        return;
    }
    if (format == SurfaceFormat::Dxt3) {  // explicit 4-bit alpha, rounded, two texels a byte
        for (int i = 0; i < 8; ++i) {
            const int lo = (block[std::size_t(2 * i)].A * 15 + 127) / 255, hi = (block[std::size_t(2 * i + 1)].A * 15 + 127) / 255;
            out[i] = std::uint8_t(lo | hi << 4);
        }
        encodeOpaqueColours(block, out + 8);
        return;
    }
    unsigned char rgba[64];
    for (int i = 0; i < 16; ++i) {
        const Color& c = block[std::size_t(i)];
        rgba[4 * i] = c.R, rgba[4 * i + 1] = c.G, rgba[4 * i + 2] = c.B, rgba[4 * i + 3] = c.A;
    }
    stb_compress_dxt_block(out, rgba, 1, STB_DXT_HIGHQUAL);  // BC3: alpha block, then colours
}

}  // namespace

std::vector<std::uint8_t> encodeDxt(SurfaceFormat format, const std::vector<Color>& texels, int width, int height) {
    const std::size_t blockBytes = format == SurfaceFormat::Dxt1 ? 8 : 16;
    const int bw = (width + 3) / 4, bh = (height + 3) / 4;
    std::vector<std::uint8_t> out(std::size_t(bw) * std::size_t(bh) * blockBytes);
    Block block;
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            for (int i = 0; i < 16; ++i) {
                const int x = std::min(bx * 4 + i % 4, width - 1), y = std::min(by * 4 + i / 4, height - 1);
                block[std::size_t(i)] = texels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            }
            encodeBlock(format, block, out.data() + (std::size_t(by) * std::size_t(bw) + std::size_t(bx)) * blockBytes);
        }
    return out;
}

}  // namespace fxport::detail
