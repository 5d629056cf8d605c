// importSpriteFont: the font formats ContentManager loads (filled in by the SpriteFont commit).
#include "sprite_font_import.h"

#include "fxport/framework/content_manager.h"
#include "fxport/graphics/sprite_font.h"

namespace fxport {

std::unique_ptr<SpriteFont> importSpriteFont(GraphicsDevice&, const std::string& path) {
    throw ContentLoadException(path + ": font files are not read yet (the SpriteFont importer is the next commit)");
}

}  // namespace fxport
