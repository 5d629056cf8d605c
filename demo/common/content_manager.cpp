#include "common/content_manager.h"

#include <filesystem>

namespace fxport::demo {

ContentManager::~ContentManager() { Unload(); }

void ContentManager::Unload() {
    // Effects and textures may be referenced by models' parts: drop the models first.
    models_.clear();
    fonts_.clear();
    textures_.clear();
    effects_.clear();
}

GraphicsDevice& ContentManager::device(const std::string& assetName) const {
    if (!device_) throw InvalidOperation("ContentManager.Load(\"" + assetName + "\"): no GraphicsDevice set");
    return *device_;
}

std::string ContentManager::path(const std::string& assetName, const char* extension) const {
    return (std::filesystem::path(RootDirectory) / (assetName + extension)).string();
}

template <> Effect* ContentManager::Load<Effect>(const std::string& assetName) {
    auto it = effects_.find(assetName);
    if (it != effects_.end()) return it->second.get();
    // "Effects/Clear" -> <EffectDirectory>/Clear.fx
    std::string name = assetName;
    const std::string prefix = "Effects/";
    if (name.rfind(prefix, 0) == 0) name = name.substr(prefix.size());
    const std::string file = (std::filesystem::path(EffectDirectory) / (name + ".fx")).string();
    if (!std::filesystem::exists(file))
        throw ArgumentError("ContentManager.Load<Effect>(\"" + assetName + "\"): " + file + " does not exist");
    auto effect = std::make_unique<Effect>(device(assetName), file);
    effect->Name = name;
    return effects_.emplace(assetName, std::move(effect)).first->second.get();
}

template <> Model* ContentManager::Load<Model>(const std::string& assetName) {
    auto it = models_.find(assetName);
    if (it != models_.end()) return it->second.get();
    return models_.emplace(assetName, Model::Load(device(assetName), path(assetName, ".gltf"))).first->second.get();
}

template <> Texture2D* ContentManager::Load<Texture2D>(const std::string& assetName) {
    auto it = textures_.find(assetName);
    if (it != textures_.end()) return it->second.get();
    auto texture = Texture2D::FromFile(device(assetName), path(assetName, ".png"));
    texture->Name = assetName;
    return textures_.emplace(assetName, std::move(texture)).first->second.get();
}

template <> SpriteFont* ContentManager::Load<SpriteFont>(const std::string& assetName) {
    auto it = fonts_.find(assetName);
    if (it != fonts_.end()) return it->second.get();
    return fonts_.emplace(assetName, SpriteFont::createDebugFont(device(assetName))).first->second.get();
}

}  // namespace fxport::demo
