// Builds a SpriteFont from a font file, by its extension: .spritefont (XNA's XML description), .fnt
// (BMFont), .ttf/.otf (stb_truetype). Throws with the file name (and line, for the text formats).
#pragma once

#include <memory>
#include <string>

namespace fxport {

class GraphicsDevice;
class SpriteFont;

std::unique_ptr<SpriteFont> importSpriteFont(GraphicsDevice& device, const std::string& path);

}  // namespace fxport
