#include "material_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "noise.h"
#include "rng.h"
#include "vec.h"

namespace fxport::content {

namespace {

float SmoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float Mix(float a, float b, float t) { return a + (b - a) * t; }

Rgba Mix(Rgba a, Rgba b, float t) {
    return {Mix(a.r, b.r, t), Mix(a.g, b.g, t), Mix(a.b, b.b, t), Mix(a.a, b.a, t)};
}

Rgba Scale(Rgba c, float s) { return {c.r * s, c.g * s, c.b * s, c.a}; }

// Texture coordinate of the centre of texel i in a texture of `size` texels.
float Centre(int i, int size) { return (static_cast<float>(i) + 0.5f) / static_cast<float>(size); }

// Fixed seeds, one per material, so that the materials do not share noise.
constexpr std::uint32_t kTileSeed = 0x7117e5U;
constexpr std::uint32_t kBrickSeed = 0xb41c4U;
constexpr std::uint32_t kStoneSeed = 0x5701eU;
constexpr std::uint32_t kWoodSeed = 0x3009dU;

}  // namespace

Rgba SpecularTexel(float intensity, float power) { return {intensity, power / 255.0f, 0.0f, 1.0f}; }

Image NormalMapFromHeight(const HeightField& height, float strength) {
    Image out(height.Width(), height.Height());
    for (int y = 0; y < height.Height(); ++y) {
        for (int x = 0; x < height.Width(); ++x) {
            const float dhdx = 0.5f * (height.At(x + 1, y) - height.At(x - 1, y));
            const float dhdrow = 0.5f * (height.At(x, y + 1) - height.At(x, y - 1));
            // Rows run down the image, tangent-space +Y runs up it: +Y slope = -dh/drow, and the
            // normal leans against the slope: n = (-dh/dx, -dh/dy_up, 1).
            const Vec3 n = Normalize(Vec3{-strength * dhdx, strength * dhdrow, 1.0f});
            out.Set(x, y, {n.x * 0.5f + 0.5f, n.y * 0.5f + 0.5f, n.z * 0.5f + 0.5f, 1.0f});
        }
    }
    return out;
}

MaterialTextures MakeFloorTiles(int size) {
    MaterialTextures t{Image(size, size), Image(size, size), Image(size, size)};
    HeightField height(size, size);
    const int tile = size / 2;
    const float groutHalf = 3.0f * static_cast<float>(size) / 256.0f;
    const float bevel = 5.0f * static_cast<float>(size) / 256.0f;
    const Rgba cream{0.84f, 0.80f, 0.71f, 1.0f};
    const Rgba slate{0.42f, 0.47f, 0.53f, 1.0f};
    const Rgba grout{0.33f, 0.31f, 0.29f, 1.0f};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const int tx = x / tile;
            const int ty = y / tile;
            const float lx = static_cast<float>(x % tile) + 0.5f;
            const float ly = static_cast<float>(y % tile) + 0.5f;
            const float edge = std::min({lx, static_cast<float>(tile) - lx, ly, static_cast<float>(tile) - ly});
            const float face = SmoothStep(groutHalf, groutHalf + bevel, edge);
            const float u = Centre(x, size);
            const float v = Centre(y, size);
            const float fine = TileableFbm(u, v, 16, 4, kTileSeed);
            const float cloud = TileableFbm(u, v, 4, 3, kTileSeed + 1);
            const float perTile = HashUnit(static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty), kTileSeed);
            const Rgba glaze = ((tx + ty) % 2 == 0) ? cream : slate;
            const Rgba tileColour = Scale(glaze, 0.92f + 0.10f * perTile + 0.12f * (cloud - 0.5f));
            const Rgba groutColour = Scale(grout, 0.85f + 0.3f * fine);
            t.albedo.Set(x, y, Mix(groutColour, tileColour, face));
            height.At(x, y) = face * (0.97f + 0.03f * cloud) + 0.15f * (1.0f - face) * fine;
            t.specular.Set(x, y, SpecularTexel(Mix(0.04f, 0.55f, face), Mix(4.0f, 64.0f, face)));
        }
    }
    t.normal = NormalMapFromHeight(height, 2.5f);
    return t;
}

MaterialTextures MakeWallBricks(int size) {
    MaterialTextures t{Image(size, size), Image(size, size), Image(size, size)};
    HeightField height(size, size);
    const int brickW = size / 4;
    const int brickH = size / 8;
    const float mortarHalf = 2.0f * static_cast<float>(size) / 256.0f;
    const float bevel = 3.0f * static_cast<float>(size) / 256.0f;
    const Rgba brickRed{0.58f, 0.27f, 0.19f, 1.0f};
    const Rgba brickDark{0.42f, 0.21f, 0.16f, 1.0f};
    const Rgba brickOrange{0.66f, 0.38f, 0.22f, 1.0f};
    const Rgba mortar{0.68f, 0.66f, 0.62f, 1.0f};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const int row = y / brickH;
            const int shifted = (x + (row % 2) * (brickW / 2)) % size;
            const int column = shifted / brickW;
            const float lx = static_cast<float>(shifted % brickW) + 0.5f;
            const float ly = static_cast<float>(y % brickH) + 0.5f;
            const float edge = std::min({lx, static_cast<float>(brickW) - lx, ly, static_cast<float>(brickH) - ly});
            const float face = SmoothStep(mortarHalf, mortarHalf + bevel, edge);
            const float u = Centre(x, size);
            const float v = Centre(y, size);
            const float fine = TileableFbm(u, v, 32, 3, kBrickSeed);
            const float pits = TileableValueNoise(u, v, 64, kBrickSeed + 2);
            const float hue = HashUnit(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row), kBrickSeed);
            const float shade = HashUnit(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row), kBrickSeed + 1);
            Rgba brick = hue < 0.5f ? Mix(brickDark, brickRed, hue * 2.0f) : Mix(brickRed, brickOrange, hue * 2.0f - 1.0f);
            brick = Scale(brick, 0.85f + 0.25f * shade + 0.25f * (fine - 0.5f));
            const Rgba mortarColour = Scale(mortar, 0.85f + 0.3f * fine);
            t.albedo.Set(x, y, Mix(mortarColour, brick, face));
            const float pit = pits > 0.8f ? (pits - 0.8f) * 2.0f : 0.0f;
            height.At(x, y) = face * (0.9f + 0.1f * fine - pit) + (1.0f - face) * 0.1f * fine;
            t.specular.Set(x, y, SpecularTexel(Mix(0.03f, 0.12f, face), Mix(4.0f, 12.0f, face)));
        }
    }
    t.normal = NormalMapFromHeight(height, 2.5f);
    return t;
}

MaterialTextures MakeStone(int size) {
    MaterialTextures t{Image(size, size), Image(size, size), Image(size, size)};
    HeightField height(size, size);
    const Rgba base{0.74f, 0.72f, 0.68f, 1.0f};
    const Rgba vein{0.36f, 0.36f, 0.40f, 1.0f};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = Centre(x, size);
            const float v = Centre(y, size);
            const float warp = TileableFbm(u, v, 4, 5, kStoneSeed);
            const float cloud = TileableFbm(u, v, 8, 4, kStoneSeed + 1);
            // Integer frequencies in u and v keep the veins periodic over the texture.
            const float phase = 2.0f * kPi * (2.0f * u + 1.0f * v + 2.5f * warp);
            const float veinAmount = std::pow(1.0f - std::fabs(std::sin(phase)), 8.0f);
            const Rgba stone = Scale(base, 0.85f + 0.3f * (cloud - 0.5f) + 0.1f);
            t.albedo.Set(x, y, Mix(stone, vein, 0.75f * veinAmount));
            height.At(x, y) = 0.5f * cloud - 0.3f * veinAmount;
            t.specular.Set(x, y, SpecularTexel(Mix(0.45f, 0.2f, veinAmount), Mix(40.0f, 16.0f, veinAmount)));
        }
    }
    t.normal = NormalMapFromHeight(height, 1.5f);
    return t;
}

MaterialTextures MakeWoodCrate(int size) {
    MaterialTextures t{Image(size, size), Image(size, size), Image(size, size)};
    HeightField height(size, size);
    const float s = static_cast<float>(size) / 256.0f;
    const float frame = 28.0f * s;
    const float inner = static_cast<float>(size) - 2.0f * frame;
    const float plank = inner / 4.0f;
    const float braceHalf = 13.0f * s;
    const float nailRadius = 4.0f * s;
    const Rgba light{0.71f, 0.53f, 0.32f, 1.0f};
    const Rgba dark{0.49f, 0.33f, 0.18f, 1.0f};
    const Rgba metal{0.58f, 0.58f, 0.60f, 1.0f};
    const float fs = static_cast<float>(size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            const float py = static_cast<float>(y) + 0.5f;
            const float u = Centre(x, size);
            const float v = Centre(y, size);
            const float warp = TileableFbm(u, v, 4, 4, kWoodSeed);
            const float fine = TileableFbm(u, v, 32, 2, kWoodSeed + 1);
            const float toOuter = std::min({px, fs - px, py, fs - py});
            const bool inFrame = toOuter < frame;
            const bool vertical = std::min(px, fs - px) < frame && std::min(py, fs - py) >= std::min(px, fs - px);
            // Distance to the brace's centre line, which runs from the bottom-left to the top-right
            // inner corner (x + y = size).
            const float braceDistance = std::fabs(px + py - fs) / std::sqrt(2.0f);
            const bool inBrace = !inFrame && braceDistance < braceHalf;

            float grainPhase;
            float h;
            float plankShade;
            if (inFrame) {
                grainPhase = vertical ? 24.0f * u : 24.0f * v;
                h = 1.0f - 0.15f * (1.0f - SmoothStep(0.0f, 3.0f * s, toOuter)) -
                    0.25f * (1.0f - SmoothStep(0.0f, 3.0f * s, frame - toOuter));
                plankShade = 0.82f;
            } else if (inBrace) {
                grainPhase = 12.0f * (u - v);
                h = 0.9f - 0.25f * (1.0f - SmoothStep(0.0f, 3.0f * s, braceHalf - braceDistance));
                plankShade = 0.95f;
            } else {
                const float inPlank = std::fmod(py - frame, plank);
                const float toGroove = std::min(inPlank, plank - inPlank);
                const int index = static_cast<int>((py - frame) / plank);
                grainPhase = 24.0f * v + HashUnit(static_cast<std::uint32_t>(index), 0U, kWoodSeed);
                h = 0.55f * SmoothStep(1.0f * s, 4.0f * s, toGroove) + 0.05f;
                plankShade = 0.9f + 0.15f * HashUnit(static_cast<std::uint32_t>(index), 1U, kWoodSeed);
            }
            const float grain = 0.5f + 0.5f * std::sin(2.0f * kPi * (grainPhase + 2.0f * warp));
            Rgba colour = Scale(Mix(dark, light, grain * 0.7f + 0.3f * fine), plankShade);
            float specIntensity = 0.12f;
            float specPower = 10.0f;
            h += 0.04f * grain;

            // Nails at the frame's corners and the middle of each side.
            const float c0 = frame * 0.5f;
            const float c1 = fs * 0.5f;
            const float c2 = fs - frame * 0.5f;
            const float centres[3] = {c0, c1, c2};
            for (float cy : centres) {
                for (float cx : centres) {
                    if (cx == c1 && cy == c1) continue;
                    const float d = std::hypot(px - cx, py - cy);
                    if (d < nailRadius) {
                        const float dome = std::sqrt(1.0f - (d / nailRadius) * (d / nailRadius));
                        colour = Scale(metal, 0.8f + 0.2f * dome);
                        h = 1.0f + 0.4f * dome;
                        specIntensity = 0.8f;
                        specPower = 90.0f;
                    }
                }
            }
            t.albedo.Set(x, y, colour);
            height.At(x, y) = h;
            t.specular.Set(x, y, SpecularTexel(specIntensity, specPower));
        }
    }
    t.normal = NormalMapFromHeight(height, 2.0f);
    return t;
}

}  // namespace fxport::content
