// ContentManager: XNA's Content.Load<T>("name"), for the ported demos. XNA loads assets that the
// content pipeline built; fxport loads them from their sources:
//   Effect      "Effects/Clear"  -> <EffectDirectory>/Clear.fx, compiled by xlate (cached)
//   Model       "Scene"          -> <RootDirectory>/Scene.gltf (Model::Load)
//   Texture2D   "SpotCookie"     -> <RootDirectory>/SpotCookie.png (Texture2D::FromFile)
//   SpriteFont  any name         -> SpriteFont::createDebugFont (fxport has no font pipeline yet)
// As in XNA, the manager owns what it loads and hands out the same object for the same name; the
// objects live until the manager is destroyed (Unload()).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "fxport/graphics/model.h"
#include "fxport/graphics/sprite_font.h"

namespace fxport::demo {

class ContentManager {
public:
    // Folder of the generated content (glTF models, PNG textures): XNA's Content.RootDirectory.
    std::string RootDirectory;
    // fxport: folder of the .fx files that "Effects/<name>" refers to.
    std::string EffectDirectory;

    ContentManager() = default;
    ~ContentManager();
    ContentManager(const ContentManager&) = delete;
    ContentManager& operator=(const ContentManager&) = delete;

    // fxport: XNA's ContentManager gets the device from the Game's services; here it is set once
    // the device exists.
    void setGraphicsDevice(GraphicsDevice* device) { device_ = device; }

    // T is Effect, Model, Texture2D or SpriteFont. Throws ArgumentError naming the asset and the file
    // when it cannot be loaded.
    template <class T> T* Load(const std::string& assetName);

    // fxport: the options every effect is compiled with (e.g. useCache = false, so that a load's
    // time is xlate's whole compile and not a cache hit).
    EffectOptions effectOptions;
    // fxport: every asset loaded, in order, with the time its load took (an effect's includes xlate's
    // compile or cache lookup). What a program actually built: fxdemo --explain and tests read it.
    struct LoadRecord {
        std::string assetName;
        std::string type;  // "Effect", "Model", "Texture2D", "SpriteFont"
        double milliseconds = 0;
    };
    const std::vector<LoadRecord>& loadLog() const { return loadLog_; }
    // The loaded effect of that asset name, or nullptr when it was never loaded (Load would load it).
    Effect* findLoadedEffect(const std::string& assetName) const;

    // Frees everything loaded.
    void Unload();

private:
    GraphicsDevice& device(const std::string& assetName) const;
    std::string path(const std::string& assetName, const char* extension) const;

    GraphicsDevice* device_ = nullptr;
    std::map<std::string, std::unique_ptr<Effect>> effects_;
    std::map<std::string, std::unique_ptr<Model>> models_;
    std::map<std::string, std::unique_ptr<Texture2D>> textures_;
    std::map<std::string, std::unique_ptr<SpriteFont>> fonts_;
    std::vector<LoadRecord> loadLog_;
};

template <> Effect* ContentManager::Load<Effect>(const std::string& assetName);
template <> Model* ContentManager::Load<Model>(const std::string& assetName);
template <> Texture2D* ContentManager::Load<Texture2D>(const std::string& assetName);
template <> SpriteFont* ContentManager::Load<SpriteFont>(const std::string& assetName);

}  // namespace fxport::demo
