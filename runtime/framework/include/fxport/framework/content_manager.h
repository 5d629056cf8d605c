// ContentManager: XNA's Content.Load<T>("name"). XNA loads .xnb files its content pipeline built;
// fxport loads the sources. An asset name has no extension, '/' separates folders, and each type
// tries these files, in order, under each search folder:
//
//   Effect      <name>.fx (compiled by xlate, cached), <name>.fxeffect (precompiled: fxport compile)
//   Texture2D   <name>.png, <name>.jpg, <name>.jpeg, <name>.bmp, <name>.tga (processed as XNA's
//               content pipeline did: magenta keyed out, alpha premultiplied — textureProcessor,
//               texture_processor.h), <name>.dds (as authored: its mip levels; BC1-BC3 decoded to
//               Color, see dds_image.h)
//   TextureCube <name>.dds (a cube map, its six faces and mip levels as authored; TextureCube::FromFile)
//   Model       <name>.gltf, <name>.glb, <name>.fbx, <name>.x, <name>.obj, <name>.dae (Assimp)
//   SpriteFont  <name>.spritefont (XNA's XML font description: FontName, Size, Spacing, UseKerning,
//               Style, DefaultCharacter, CharacterRegions; the font found by fontconfig, or a .ttf
//               named like FontName beside it), <name>.fnt (BMFont, text format, with its page
//               PNGs), <name>.ttf / <name>.otf (XNA's new-SpriteFont template: Size 14 points,
//               characters 32..126, Spacing 0, no DefaultCharacter); metrics in sprite_font_import.h
//
// Search folders: RootDirectory (a relative one is looked for beside the executable first, as
// XNA's TitleContainer does, then from the working directory), and for
// effects first EffectDirectory when set, where the asset's last path component is used
// ("Effects/Clear" -> <EffectDirectory>/Clear.fx), so .fx sources can stay where they are.
// A missing asset throws ContentLoadException naming the asset, the type and every path tried.
//
// As in XNA, the manager owns what it loads, returns the same object for the same name (cached per
// type and name), and frees everything at Unload() or destruction.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fxport/graphics/effect.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/model.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_processor.h"

namespace fxport {

class GraphicsDevice;

// XNA's ContentLoadException: the asset could not be found or read.
class ContentLoadException : public std::runtime_error {
public:
    explicit ContentLoadException(const std::string& what) : std::runtime_error(what) {}
};

class ContentManager {
public:
    ContentManager() = default;
    // fxport: XNA's ContentManager(IServiceProvider, rootDirectory); the service it needs is the device.
    explicit ContentManager(GraphicsDevice& device, std::string rootDirectory = {});
    ~ContentManager();
    ContentManager(const ContentManager&) = delete;
    ContentManager& operator=(const ContentManager&) = delete;

    // The folder asset names are relative to (XNA's Content.RootDirectory).
    std::string RootDirectory;
    // fxport: a folder searched first for effects, by the asset's last path component (see above).
    std::string EffectDirectory;
    // fxport: the options every effect is compiled with (include folders, defines, cache).
    EffectOptions effectOptions;
    // fxport: the processing every image texture gets, XNA's TextureProcessor defaults unless changed
    // (a game whose .contentproj changed them says so here, or per asset below;
    // TextureProcessor::None() loads images as the files have them). Its TextureFormat (XNA's
    // Color, DxtCompressed, NoChange) is the loaded texture's SurfaceFormat; TextureCube loads take
    // only TextureFormat from it (texture_processor.h).
    TextureProcessor textureProcessor;
    // fxport: the processing of one asset (its name as Load is given it), instead of textureProcessor;
    // XNA's per-asset ProcessorParameters, TextureFormat included (e.g. NoChange to keep a .dds's
    // DXT blocks). Throws InvalidOperation when the asset is already loaded.
    void SetTextureProcessor(const std::string& assetName, const TextureProcessor& processor);

    // fxport: a Game sets its device here when it makes it; a standalone manager takes it in the
    // constructor.
    void setGraphicsDevice(GraphicsDevice* device) { device_ = device; }

    // T is Effect, Texture2D, TextureCube (a .dds cube map), Model or SpriteFont (other types do not link). Throws
    // ContentLoadException naming the asset and the paths tried when no file exists, and the
    // loader's error (ArgumentError, xlate::CompileError ...) prefixed with the asset name when the
    // file cannot be read.
    template <class T> T* Load(const std::string& assetName);

    // Frees everything loaded (models first: their parts reference effects and textures).
    void Unload();

    // fxport: every asset loaded, in order, with the time its load took (an effect's includes
    // xlate's compile or cache lookup): what a program actually built (fxdemo --explain reads it).
    struct LoadRecord {
        std::string assetName;
        std::string type;  // "Effect", "Texture2D", "TextureCube", "Model", "SpriteFont"
        std::string path;  // the file loaded
        double milliseconds = 0;
    };
    const std::vector<LoadRecord>& loadLog() const { return loadLog_; }
    // fxport: the loaded effect of that asset name, or nullptr when it was never loaded.
    Effect* findLoadedEffect(const std::string& assetName) const;

private:
    GraphicsDevice& device(const std::string& assetName, const char* type) const;
    // The first existing file among the candidates; throws ContentLoadException listing them all.
    std::string locate(const std::string& assetName, const char* type, const std::vector<std::string>& candidates) const;
    std::vector<std::string> candidates(const std::string& folder, const std::string& name,
                                        std::initializer_list<const char*> extensions) const;
    // `folder` as the places it names: itself when absolute; else beside the executable, then from
    // the working directory (once when both are the same folder).
    static std::vector<std::filesystem::path> searchFolders(const std::string& folder);
    // The asset's SetTextureProcessor processor, else textureProcessor.
    const TextureProcessor& processorFor(const std::string& assetName) const;

    GraphicsDevice* device_ = nullptr;
    std::map<std::string, std::unique_ptr<Effect>> effects_;
    std::map<std::string, std::unique_ptr<Model>> models_;
    std::map<std::string, std::unique_ptr<Texture2D>> textures_;
    std::map<std::string, std::unique_ptr<TextureCube>> cubes_;
    std::map<std::string, TextureProcessor> textureProcessors_;  // by portable asset name
    std::map<std::string, std::unique_ptr<SpriteFont>> fonts_;
    std::vector<LoadRecord> loadLog_;
};

template <> Effect* ContentManager::Load<Effect>(const std::string& assetName);
template <> Texture2D* ContentManager::Load<Texture2D>(const std::string& assetName);
template <> TextureCube* ContentManager::Load<TextureCube>(const std::string& assetName);
template <> Model* ContentManager::Load<Model>(const std::string& assetName);
template <> SpriteFont* ContentManager::Load<SpriteFont>(const std::string& assetName);

}  // namespace fxport
