// A labelled contact sheet of images written as one PNG (the demos' debug.png): rows of tiles, a
// 12-pixel label line above each, on a dark grey ground, drawn through SpriteBatch into a Color
// render target. The sheet is as wide as its widest row and as tall as its rows.
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics.h"

namespace fxport::demo {

struct SheetTile {
    std::string label;
    int width = 0, height = 0;  // size on the sheet
    std::vector<Color> pixels;  // width x height, rows from the top
};

// Restores the device's render targets afterwards.
void WriteTileSheet(GraphicsDevice& device, const std::vector<std::vector<SheetTile>>& rows, const std::string& path);

}  // namespace fxport::demo
