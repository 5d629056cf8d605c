// importSpriteFont: ContentManager's font loader, choosing the importer by the file's extension.
#include "font_file_loader.h"

#include <filesystem>

#include "fxport/framework/sprite_font_import.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/sprite_font.h"

namespace fxport {

std::unique_ptr<SpriteFont> importSpriteFont(GraphicsDevice& device, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".spritefont") {
        const FontDescription description = ReadFontDescription(path);
        return BuildSpriteFont(device, FindFontFile(description, path), description);
    }
    if (extension == ".fnt") return LoadBMFont(device, path);
    if (extension == ".ttf" || extension == ".otf") return BuildSpriteFont(device, path, FontDescription{});
    throw ArgumentError("SpriteFont: '" + path + "' is not a .spritefont, .fnt, .ttf or .otf file");
}

}  // namespace fxport
