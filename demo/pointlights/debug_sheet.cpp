#include "pointlights/debug_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/tile_sheet.h"
#include "pointlights/game1.h"

namespace DeferredLighting {

namespace {

using Tile = fxport::demo::SheetTile;

std::vector<Color> rgbOf(const std::vector<Color>& data) {
    std::vector<Color> out(data.size());
    for (std::size_t i = 0; i < data.size(); ++i) out[i] = Color(int(data[i].R), int(data[i].G), int(data[i].B));
    return out;
}

std::vector<Color> alphaOf(const std::vector<Color>& data) {
    std::vector<Color> out(data.size());
    for (std::size_t i = 0; i < data.size(); ++i) out[i] = Color(int(data[i].A), int(data[i].A), int(data[i].A));
    return out;
}

// Area-averaged downscale to w x h.
std::vector<Color> resized(const std::vector<Color>& source, int sw, int sh, int w, int h) {
    std::vector<Color> out(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int x0 = x * sw / w, x1 = std::max(x0 + 1, (x + 1) * sw / w);
            int y0 = y * sh / h, y1 = std::max(y0 + 1, (y + 1) * sh / h);
            float sum[3] = {0, 0, 0};
            int n = 0;
            for (int sy = y0; sy < y1; ++sy) {
                for (int sx = x0; sx < x1; ++sx) {
                    const Color& c = source[std::size_t(sy) * std::size_t(sw) + std::size_t(sx)];
                    sum[0] += c.R;
                    sum[1] += c.G;
                    sum[2] += c.B;
                    ++n;
                }
            }
            out[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
                Color(int(sum[0] / float(n) + 0.5f), int(sum[1] / float(n) + 0.5f), int(sum[2] / float(n) + 0.5f));
        }
    }
    return out;
}

}  // namespace

void WriteDebugSheet(Game1& game, const std::string& path) {
    GraphicsDevice& device = *game.GraphicsDevice;
    DeferredRenderer& renderer = game.getRenderer();
    const int W = renderer.getColorRT().Width(), H = renderer.getColorRT().Height();
    const int tileW = 256, tileH = std::max(1, tileW * H / W);

    std::vector<std::vector<Tile>> rows(2);
    auto add = [&](int row, std::string label, const std::vector<Color>& full) {
        rows[std::size_t(row)].push_back(Tile{std::move(label), tileW, tileH, resized(full, W, H, tileW, tileH)});
    };

    std::vector<Color> color = renderer.getColorRT().GetData<Color>();
    std::vector<Color> normal = renderer.getNormalRT().GetData<Color>();
    std::vector<Color> light = renderer.getLightRT().GetData<Color>();
    add(0, "colorRT.rgb diffuse", rgbOf(color));
    add(0, "colorRT.a spec intensity", alphaOf(color));
    add(0, "normalRT world normal xyz as rgb", rgbOf(normal));
    add(0, "normalRT.a spec power/255", alphaOf(normal));
    {
        // depthRT (z/w) stretched over the values written: near = white; cleared (1.0) dark blue.
        std::vector<float> depth = renderer.getDepthRT().GetData<float>();
        float lo = INFINITY, hi = -INFINITY;
        for (float d : depth)
            if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
        std::vector<Color> image(depth.size());
        for (std::size_t i = 0; i < depth.size(); ++i) {
            if (depth[i] >= 1.0f) image[i] = Color(20, 30, 70);
            else {
                float t = hi > lo ? (depth[i] - lo) / (hi - lo) : 0.0f;
                image[i] = Color(1.0f - t, 1.0f - t, 1.0f - t, 1.0f);
            }
        }
        char label[96];
        std::snprintf(label, sizeof label, "depthRT z/w %.4f-%.4f", double(lo), double(hi));
        add(1, label, image);
    }
    add(1, "lightRT.rgb diffuse light", rgbOf(light));
    add(1, "lightRT.a specular", alphaOf(light));
    add(1, "back buffer (final.png)", device.GetBackBufferData());

    fxport::demo::WriteTileSheet(device, rows, path);
}

}  // namespace DeferredLighting
