#include "common/tile_sheet.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/sprite_font.h"

namespace fxport::demo {

void WriteTileSheet(GraphicsDevice& device, const std::vector<std::vector<SheetTile>>& rows, const std::string& path) {
    const int gap = 8, labelH = 12;
    int sheetW = gap, sheetH = gap;
    for (const auto& row : rows) {
        int rowW = gap, rowH = 0;
        for (const SheetTile& t : row) {
            rowW += t.width + gap;
            rowH = std::max(rowH, t.height);
        }
        sheetW = std::max(sheetW, rowW);
        sheetH += labelH + rowH + gap;
    }

    RenderTarget2D sheet(device, sheetW, sheetH, false, SurfaceFormat::Color, DepthFormat::None);
    const std::vector<RenderTargetBinding> previous = device.GetRenderTargets();
    device.SetRenderTarget(&sheet);
    device.Clear(Color(40, 40, 40));
    SpriteBatch spriteBatch(device);
    const std::unique_ptr<SpriteFont> font = SpriteFont::createDebugFont(device);
    std::vector<std::unique_ptr<Texture2D>> textures;  // alive until the batch is drawn
    std::vector<std::pair<std::string, Vector2>> labels;
    spriteBatch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
    int y = gap;
    for (const auto& row : rows) {
        int x = gap, rowH = 0;
        for (const SheetTile& t : row) {
            auto texture = std::make_unique<Texture2D>(device, t.width, t.height, false, SurfaceFormat::Color);
            texture->SetData(t.pixels);
            spriteBatch.Draw(*texture, Rectangle(x, y + labelH, t.width, t.height), Color::White);
            textures.push_back(std::move(texture));
            labels.emplace_back(t.label, Vector2(float(x), float(y + 2)));
            x += t.width + gap;
            rowH = std::max(rowH, t.height);
        }
        y += labelH + rowH + gap;
    }
    spriteBatch.End();
    spriteBatch.Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend);
    for (const auto& [text, position] : labels) spriteBatch.DrawString(*font, text, position, Color::White);
    spriteBatch.End();
    device.SetRenderTargets(previous);
    sheet.SaveAsPng(path);
}

}  // namespace fxport::demo
