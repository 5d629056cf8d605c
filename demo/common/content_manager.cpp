#include "common/content_manager.h"

#include <chrono>
#include <filesystem>

namespace fxport::demo {

namespace {

// Times one load for the load log.
class LoadTimer {
public:
    double milliseconds() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

Effect* ContentManager::findLoadedEffect(const std::string& assetName) const {
    auto it = effects_.find(assetName);
    return it == effects_.end() ? nullptr : it->second.get();
}

ContentManager::~ContentManager() { Unload(); }

void ContentManager::Unload() {
    // Effects and textures may be referenced by models' parts: drop the models first.
    models_.clear();
    fonts_.clear();
    textures_.clear();
    effects_.clear();
    loadLog_.clear();
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
    LoadTimer timer;
    auto effect = std::make_unique<Effect>(device(assetName), file, effectOptions);
    effect->Name = name;
    loadLog_.push_back({assetName, "Effect", timer.milliseconds()});
    return effects_.emplace(assetName, std::move(effect)).first->second.get();
}

template <> Model* ContentManager::Load<Model>(const std::string& assetName) {
    auto it = models_.find(assetName);
    if (it != models_.end()) return it->second.get();
    LoadTimer timer;
    auto model = Model::Load(device(assetName), path(assetName, ".gltf"));
    loadLog_.push_back({assetName, "Model", timer.milliseconds()});
    return models_.emplace(assetName, std::move(model)).first->second.get();
}

template <> Texture2D* ContentManager::Load<Texture2D>(const std::string& assetName) {
    auto it = textures_.find(assetName);
    if (it != textures_.end()) return it->second.get();
    LoadTimer timer;
    auto texture = Texture2D::FromFile(device(assetName), path(assetName, ".png"));
    texture->Name = assetName;
    loadLog_.push_back({assetName, "Texture2D", timer.milliseconds()});
    return textures_.emplace(assetName, std::move(texture)).first->second.get();
}

template <> SpriteFont* ContentManager::Load<SpriteFont>(const std::string& assetName) {
    auto it = fonts_.find(assetName);
    if (it != fonts_.end()) return it->second.get();
    LoadTimer timer;
    auto font = SpriteFont::createDebugFont(device(assetName));
    loadLog_.push_back({assetName, "SpriteFont", timer.milliseconds()});
    return fonts_.emplace(assetName, std::move(font)).first->second.get();
}

}  // namespace fxport::demo
