#include "deferred/debug_sheet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/tile_sheet.h"
#include "deferred/game1.h"

namespace TheCansinDeferredRenderer {

namespace {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;
    Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h)) {}
    Color& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Shown where a float target holds its "nothing here" value (cleared depth, empty shadow map).
const Color kEmpty(20, 30, 70);

Color grey(float v) { return Color(v, v, v, 1.0f); }

Image fromColor(const Texture2D& texture, bool alphaAsGrey) {
    Image image(texture.Width(), texture.Height());
    std::vector<Color> data = texture.GetData<Color>();
    for (std::size_t i = 0; i < data.size(); ++i) {
        Color c = data[i];
        image.pixels[i] = alphaAsGrey ? Color(int(c.A), int(c.A), int(c.A)) : Color(int(c.R), int(c.G), int(c.B));
    }
    return image;
}

// A G-buffer target's texels as RGBA floats, in any of the formats DemoSettings::gbufferFormats
// chooses (Rgba64 and Color: unorm to [0,1]; Single, Vector2, Vector4: as stored, absent channels 0).
std::vector<Vector4> texelsOf(const Texture2D& texture) {
    const std::size_t n = std::size_t(texture.Width()) * std::size_t(texture.Height());
    std::vector<Vector4> out(n, Vector4(0, 0, 0, 0));
    switch (texture.Format()) {
    case SurfaceFormat::Rgba64: {
        std::vector<std::uint16_t> data = texture.GetData<std::uint16_t>();
        for (std::size_t i = 0; i < n; ++i)
            out[i] = Vector4(data[4 * i] / 65535.0f, data[4 * i + 1] / 65535.0f, data[4 * i + 2] / 65535.0f,
                             data[4 * i + 3] / 65535.0f);
        break;
    }
    case SurfaceFormat::Color: {
        std::vector<Color> data = texture.GetData<Color>();
        for (std::size_t i = 0; i < n; ++i) out[i] = data[i].ToVector4();
        break;
    }
    case SurfaceFormat::Single: {
        std::vector<float> data = texture.GetData<float>();
        for (std::size_t i = 0; i < n; ++i) out[i].X = data[i];
        break;
    }
    case SurfaceFormat::Vector2: {
        std::vector<Vector2> data = texture.GetData<Vector2>();
        for (std::size_t i = 0; i < n; ++i) out[i] = Vector4(data[i].X, data[i].Y, 0, 0);
        break;
    }
    case SurfaceFormat::Vector4:
        out = texture.GetData<Vector4>();
        break;
    default:
        throw ArgumentError(std::string("WriteDebugSheet: G-buffer target '") + texture.Name + "' has format " +
                            surfaceFormatName(texture.Format()) + ", which the sheet does not read");
    }
    return out;
}

// A G-buffer colour target: rgb, or alpha as grey.
Image fromGBuffer(const Texture2D& texture, bool alphaAsGrey) {
    Image image(texture.Width(), texture.Height());
    std::vector<Vector4> data = texelsOf(texture);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const Vector4& t = data[i];
        image.pixels[i] = alphaAsGrey ? grey(t.W) : Color(t.X, t.Y, t.Z);
    }
    return image;
}

// Values stretched so that the smallest shown becomes white and the largest black (near = bright);
// `empty` marks texels to show as kEmpty. Returns the range in `range`.
Image stretched(int width, int height, const std::vector<float>& values, const std::vector<bool>& empty,
                std::array<float, 2>& range) {
    Image image(width, height);
    float lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (empty[i]) continue;
        lo = std::min(lo, values[i]);
        hi = std::max(hi, values[i]);
    }
    range = {lo, hi};
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (empty[i]) {
            image.pixels[i] = kEmpty;
        } else {
            float t = hi > lo ? (values[i] - lo) / (hi - lo) : 0.0f;
            image.pixels[i] = grey(1.0f - t);
        }
    }
    return image;
}

// Exponential shadow map texels exp(distance / 2) (DepthWriter.fx) back to distances.
std::vector<float> shadowDistances(const std::vector<float>& texels, std::vector<bool>& empty) {
    std::vector<float> distances(texels.size());
    empty.assign(texels.size(), false);
    for (std::size_t i = 0; i < texels.size(); ++i) {
        if (texels[i] <= 0.0f) empty[i] = true;
        else distances[i] = 2.0f * std::log(texels[i]);
    }
    return distances;
}

// Area-averaged downscale (or nearest upscale) to w x h.
Image resized(const Image& source, int w, int h) {
    Image out(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int x0 = x * source.width / w, x1 = std::max(x0 + 1, (x + 1) * source.width / w);
            int y0 = y * source.height / h, y1 = std::max(y0 + 1, (y + 1) * source.height / h);
            float sum[3] = {0, 0, 0};
            int n = 0;
            for (int sy = y0; sy < y1; ++sy) {
                for (int sx = x0; sx < x1; ++sx) {
                    const Color& c = source.pixels[std::size_t(sy) * std::size_t(source.width) + std::size_t(sx)];
                    sum[0] += c.R;
                    sum[1] += c.G;
                    sum[2] += c.B;
                    ++n;
                }
            }
            out.at(x, y) = Color(int(sum[0] / float(n) + 0.5f), int(sum[1] / float(n) + 0.5f), int(sum[2] / float(n) + 0.5f));
        }
    }
    return out;
}

// The label's value range; "empty" when no texel had a value.
std::string format(const char* pattern, double a, double b) {
    if (!(a <= b)) return " empty";
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

struct Tile {
    std::string label;
    std::string file;  // full-size file name
    Image image;
    int width;   // size on the sheet
    int height;
};

}  // namespace

void WriteDebugSheet(Game1& game, const std::string& path, const std::string& fullSizeDir) {
    GraphicsDevice& device = *game.GraphicsDevice;
    DeferredRenderer& renderer = game.getDeferredRenderer();
    const auto& gbuffer = renderer.getGBuffer();
    auto& gbuffer0 = *static_cast<Texture2D*>(gbuffer[0].RenderTarget);
    auto& gbuffer1 = *static_cast<Texture2D*>(gbuffer[1].RenderTarget);
    auto& gbuffer2 = *static_cast<Texture2D*>(gbuffer[2].RenderTarget);
    const int W = gbuffer0.Width(), H = gbuffer0.Height();
    const int tileW = 256, tileH = std::max(1, tileW * H / W);

    std::vector<std::vector<Tile>> rows(4);
    auto add = [&](int row, std::string label, std::string file, Image image, int w, int h) {
        rows[std::size_t(row)].push_back(Tile{std::move(label), std::move(file), std::move(image), w, h});
    };

    // Row 0: G-buffer targets 0 and 1.
    add(0, "GBuffer0.rgb albedo", "gbuffer0_albedo.png", fromGBuffer(gbuffer0, false), tileW, tileH);
    add(0, "GBuffer0.a spec intensity", "gbuffer0_alpha.png", fromGBuffer(gbuffer0, true), tileW, tileH);
    add(0, "GBuffer1 normals: xyz as rgb", "gbuffer1_normals.png", fromGBuffer(gbuffer1, false), tileW, tileH);
    add(0, "GBuffer1.a spec power/255", "gbuffer1_alpha.png", fromGBuffer(gbuffer1, true), tileW, tileH);

    // Row 1: G-buffer depth (z/w and view z) and the light map.
    {
        std::vector<Vector4> depth = texelsOf(gbuffer2);
        std::vector<float> zw(depth.size()), viewDepth(depth.size());
        std::vector<bool> empty(depth.size());
        for (std::size_t i = 0; i < depth.size(); ++i) {
            empty[i] = depth[i].X >= 1.0f;  // Clear.fx writes 1
            zw[i] = depth[i].X;
            viewDepth[i] = -depth[i].Y;
        }
        std::array<float, 2> range{};
        Image zwImage = stretched(W, H, zw, empty, range);
        add(1, "GBuffer2.r z/w" + format(" %.4f-%.4f", range[0], range[1]), "gbuffer2_zw.png", zwImage, tileW, tileH);
        Image viewImage = stretched(W, H, viewDepth, empty, range);
        add(1, "GBuffer2.g -viewZ" + format(" %.1f-%.1f", range[0], range[1]), "gbuffer2_viewz.png", viewImage, tileW, tileH);
    }
    add(1, "LightMap.rgb diffuse", "lightmap_rgb.png", fromColor(renderer.getLightMap(), false), tileW, tileH);
    add(1, "LightMap.a specular", "lightmap_alpha.png", fromColor(renderer.getLightMap(), true), tileW, tileH);

    // Row 2: shadow maps as distances from the light (near = bright).
    const int shadowTile = tileH, faceTile = std::min(128, (4 * tileW - shadowTile) / 6 - 8);
    for (auto& light : game.getLightManager().getSpotLights()) {
        if (!light->getShadowMap()) continue;  // fxport: made only when drawn (SpotLight::MakeShadowMap)
        RenderTarget2D& map = *light->getShadowMap();
        std::vector<bool> empty;
        std::vector<float> distances = shadowDistances(map.GetData<float>(), empty);
        std::array<float, 2> range{};
        Image image = stretched(map.Width(), map.Height(), distances, empty, range);
        add(2, "Spot shadow" + format(" %.1f-%.1f", range[0], range[1]), "spot_shadow.png", std::move(image), shadowTile,
            shadowTile);
        break;  // one is enough
    }
    for (auto& light : game.getLightManager().getPointLights()) {
        if (!light->getShadowMap()) continue;  // fxport: made only when drawn (PointLight::MakeShadowMap)
        RenderTargetCube& map = *light->getShadowMap();
        const char* names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
        const char* files[6] = {"point_shadow_px.png", "point_shadow_nx.png", "point_shadow_py.png",
                                "point_shadow_ny.png", "point_shadow_pz.png", "point_shadow_nz.png"};
        for (int face = 0; face < 6; ++face) {
            std::vector<float> texels(std::size_t(map.Size()) * std::size_t(map.Size()));
            map.GetData(CubeMapFace(face), texels.data(), texels.size());
            std::vector<bool> empty;
            std::vector<float> distances = shadowDistances(texels, empty);
            std::array<float, 2> range{};
            Image image = stretched(map.Size(), map.Size(), distances, empty, range);
            add(2, std::string("Pt") + names[face] + format(" %.0f-%.0f", range[0], range[1]), files[face],
                std::move(image), faceTile, faceTile);
        }
        break;
    }

    // Row 3: the scene before SSAO, SSAO raw and blurred, the final back buffer.
    if (game.hasSSAO()) {  // fxport: DemoSettings::ssao off makes neither the Scene target nor SSAO's
        add(3, "Scene (before SSAO)", "scene.png", fromColor(game.getScene(), false), tileW, tileH);
        add(3, "SSAOTarget", "ssao.png", fromColor(game.getSSAO().getSSAOTarget(), false), tileW, tileH);
        add(3, "BlurTarget", "ssao_blur.png", fromColor(game.getSSAO().getBlurTarget(), false), tileW, tileH);
    }
    {
        Image backBuffer(W, H);
        backBuffer.pixels = device.GetBackBufferData();
        add(3, "Back buffer (final.png)", "final.png", std::move(backBuffer), tileW, tileH);
    }

    std::vector<std::vector<fxport::demo::SheetTile>> sheet;
    for (const auto& row : rows) {
        sheet.emplace_back();
        for (const Tile& t : row) sheet.back().push_back({t.label, t.width, t.height, resized(t.image, t.width, t.height).pixels});
    }
    fxport::demo::WriteTileSheet(device, sheet, path);

    if (!fullSizeDir.empty()) {
        std::filesystem::create_directories(fullSizeDir);
        for (auto& row : rows) {
            for (Tile& t : row) {
                Texture2D full(device, t.image.width, t.image.height, false, SurfaceFormat::Color);
                full.SetData(t.image.pixels);
                full.SaveAsPng((std::filesystem::path(fullSizeDir) / t.file).string());
            }
        }
    }
}

}  // namespace TheCansinDeferredRenderer
