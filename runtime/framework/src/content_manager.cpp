// ContentManager: asset name -> file (the mapping in content_manager.h), loading, caching by name,
// the load log.
#include "fxport/framework/content_manager.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/model.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/texture.h"
#include "font_file_loader.h"

namespace fxport {

namespace {

namespace fs = std::filesystem;

// Times one load for the load log.
class LoadTimer {
public:
    double milliseconds() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string quoted(const std::string& assetName) { return "\"" + assetName + "\""; }

// XNA content names come from Windows: `Textures\\Wall` separates folders with a backslash. Names
// are cached by this spelling, so `Textures\\Wall` and `Textures/Wall` are one asset (as MonoGame).
std::string portableName(std::string name) {
    for (char& c : name)
        if (c == '\\') c = '/';
    return name;
}

bool sameIgnoringCase(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

// The regular files whose path equals `path` ignoring case below its deepest existing folder (a
// Windows game's content names its files in any case; Linux file names are case-sensitive).
std::vector<fs::path> filesIgnoringCase(const fs::path& path) {
    std::error_code error;
    fs::path base = path.parent_path();
    while (!base.empty() && !fs::is_directory(base, error)) base = base.parent_path();
    std::vector<fs::path> found{base.empty() ? fs::path(".") : base};
    for (const fs::path& part : path.lexically_relative(found[0])) {
        std::vector<fs::path> next;
        for (const fs::path& folder : found)
            for (const auto& entry : fs::directory_iterator(folder, error))
                if (sameIgnoringCase(entry.path().filename().native(), part.native())) next.push_back(entry.path());
        found = std::move(next);
    }
    std::vector<fs::path> files;
    for (const fs::path& f : found)
        if (fs::is_regular_file(f, error)) files.push_back(f);
    return files;
}

std::string lowerExtension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

// Runs a loader; its error gets the asset's name in front (the loader names the file).
template <class F> auto loadNamed(const std::string& type, const std::string& assetName, F&& load) {
    try {
        return load();
    } catch (const ContentLoadException&) {
        throw;
    } catch (const std::exception& e) {
        throw ContentLoadException("ContentManager.Load<" + type + ">(" + quoted(assetName) + "): " + e.what());
    }
}

}  // namespace

ContentManager::ContentManager(GraphicsDevice& device, std::string rootDirectory)
    : RootDirectory(std::move(rootDirectory)), device_(&device) {}

ContentManager::~ContentManager() { Unload(); }

void ContentManager::Unload() {
    // Models' parts may reference effects and textures: drop the models first.
    models_.clear();
    fonts_.clear();
    textures_.clear();
    cubes_.clear();
    effects_.clear();
    loadLog_.clear();
}

Effect* ContentManager::findLoadedEffect(const std::string& assetName) const {
    auto it = effects_.find(portableName(assetName));
    return it == effects_.end() ? nullptr : it->second.get();
}

GraphicsDevice& ContentManager::device(const std::string& assetName, const char* type) const {
    if (!device_)
        throw InvalidOperation(std::string("ContentManager.Load<") + type + ">(" + quoted(assetName) +
                               "): no GraphicsDevice yet (a Game sets it in Run/Start; else construct the "
                               "ContentManager with the device)");
    return *device_;
}

std::vector<std::string> ContentManager::candidates(const std::string& folder, const std::string& name,
                                                    std::initializer_list<const char*> extensions) const {
    std::vector<std::string> paths;
    for (const fs::path& base : searchFolders(folder))
        for (const char* extension : extensions) paths.push_back((base / (portableName(name) + extension)).string());
    return paths;
}

std::vector<fs::path> ContentManager::searchFolders(const std::string& folder) {
    // XNA's TitleContainer reads content beside the game's executable, wherever it is started
    // from; a relative folder is also tried from the working directory (where fxport looked before).
    const fs::path given(folder);
    if (given.is_absolute()) return {given};
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    std::vector<fs::path> folders;
    if (!error) folders.push_back(executable.parent_path() / given);
    const fs::path fromWorkingDirectory = fs::absolute(given, error);
    bool same = !folders.empty() && fs::equivalent(folders[0], fromWorkingDirectory, error);
    if (!same) folders.push_back(given);
    return folders;
}

std::string ContentManager::locate(const std::string& assetName, const char* type,
                                   const std::vector<std::string>& paths) const {
    if (assetName.empty()) throw ArgumentError(std::string("ContentManager.Load<") + type + ">: empty asset name");
    // Asset names stay inside RootDirectory, as #include stays inside the include root: a name
    // that is absolute or climbs out with `..` would load any file the process can read.
    const fs::path name(portableName(assetName));
    const fs::path normal = name.lexically_normal();
    if (name.has_root_path() || (!normal.empty() && *normal.begin() == ".."))
        throw ContentLoadException(std::string("ContentManager.Load<") + type + ">(" + quoted(assetName) +
                                   "): the asset name leaves the RootDirectory '" + RootDirectory +
                                   "'; name assets relative to it, without '..' above it");
    for (const std::string& path : paths) {
        std::error_code error;
        if (fs::is_regular_file(path, error)) return path;
    }
    // No exact name: the one file that matches ignoring case, as on Windows; several are an error.
    std::vector<fs::path> matches;
    for (const std::string& path : paths)
        for (const fs::path& f : filesIgnoringCase(path))
            if (std::find(matches.begin(), matches.end(), f) == matches.end()) matches.push_back(f);
    if (matches.size() == 1) return matches[0].string();
    if (matches.size() > 1) {
        std::string list;
        for (const fs::path& f : matches) list += "\n  " + f.string();
        throw ContentLoadException(std::string("ContentManager.Load<") + type + ">(" + quoted(assetName) +
                                   "): several files match the name when case is ignored (as Windows would); rename all but one:" + list);
    }
    std::string tried;
    for (const std::string& path : paths) tried += "\n  " + path;
    throw ContentLoadException(std::string("ContentManager.Load<") + type + ">(" + quoted(assetName) +
                               "): no file for the asset; tried:" + tried);
}

template <> Effect* ContentManager::Load<Effect>(const std::string& assetName) {
    if (auto it = effects_.find(portableName(assetName)); it != effects_.end()) return it->second.get();
    std::vector<std::string> paths;
    if (!EffectDirectory.empty())
        paths = candidates(EffectDirectory, fs::path(portableName(assetName)).filename().string(), {".fx", ".fxeffect"});
    for (const std::string& path : candidates(RootDirectory, assetName, {".fx", ".fxeffect"})) paths.push_back(path);
    const std::string file = locate(assetName, "Effect", paths);
    GraphicsDevice& graphicsDevice = device(assetName, "Effect");
    LoadTimer timer;
    std::unique_ptr<Effect> effect = loadNamed("Effect", assetName, [&] {
        return lowerExtension(file) == ".fxeffect" ? Effect::FromCompiledFile(graphicsDevice, file)
                                                   : std::make_unique<Effect>(graphicsDevice, file, effectOptions);
    });
    effect->Name = fs::path(assetName).filename().string();
    loadLog_.push_back({assetName, "Effect", file, timer.milliseconds()});
    return effects_.emplace(portableName(assetName), std::move(effect)).first->second.get();
}

template <> Texture2D* ContentManager::Load<Texture2D>(const std::string& assetName) {
    if (auto it = textures_.find(portableName(assetName)); it != textures_.end()) return it->second.get();
    const std::string file =
        locate(assetName, "Texture2D", candidates(RootDirectory, assetName, {".png", ".jpg", ".jpeg", ".bmp", ".tga", ".dds"}));
    GraphicsDevice& graphicsDevice = device(assetName, "Texture2D");
    LoadTimer timer;
    const TextureProcessor& processing = processorFor(assetName);
    auto texture = loadNamed("Texture2D", assetName, [&] { return processing.Load(graphicsDevice, file); });
    texture->Name = assetName;
    loadLog_.push_back({assetName, "Texture2D", file, timer.milliseconds()});
    return textures_.emplace(portableName(assetName), std::move(texture)).first->second.get();
}

const TextureProcessor& ContentManager::processorFor(const std::string& assetName) const {
    auto processor = textureProcessors_.find(portableName(assetName));
    return processor != textureProcessors_.end() ? processor->second : textureProcessor;
}

// Cube maps come from .dds files as authored (XNA's TextureProcessor makes them only from .dds too);
// of the asset's processor only TextureFormat applies (a DXT cube kept compressed under NoChange).
template <> TextureCube* ContentManager::Load<TextureCube>(const std::string& assetName) {
    if (auto it = cubes_.find(portableName(assetName)); it != cubes_.end()) return it->second.get();
    const std::string file = locate(assetName, "TextureCube", candidates(RootDirectory, assetName, {".dds"}));
    GraphicsDevice& graphicsDevice = device(assetName, "TextureCube");
    LoadTimer timer;
    const TextureProcessor& processing = processorFor(assetName);
    auto cube = loadNamed("TextureCube", assetName, [&] { return processing.LoadCube(graphicsDevice, file); });
    cube->Name = assetName;
    loadLog_.push_back({assetName, "TextureCube", file, timer.milliseconds()});
    return cubes_.emplace(portableName(assetName), std::move(cube)).first->second.get();
}

void ContentManager::SetTextureProcessor(const std::string& assetName, const TextureProcessor& processor) {
    if (textures_.count(portableName(assetName)) || cubes_.count(portableName(assetName)))
        throw InvalidOperation("ContentManager::SetTextureProcessor(" + quoted(assetName) +
                               "): the texture is already loaded; set its processing before the first Load");
    textureProcessors_[portableName(assetName)] = processor;
}

template <> Model* ContentManager::Load<Model>(const std::string& assetName) {
    if (auto it = models_.find(portableName(assetName)); it != models_.end()) return it->second.get();
    const std::string file = locate(assetName, "Model", candidates(RootDirectory, assetName, {".gltf", ".glb", ".fbx", ".x", ".obj", ".dae"}));
    GraphicsDevice& graphicsDevice = device(assetName, "Model");
    LoadTimer timer;
    auto model = loadNamed("Model", assetName, [&] { return Model::Load(graphicsDevice, file); });
    loadLog_.push_back({assetName, "Model", file, timer.milliseconds()});
    return models_.emplace(portableName(assetName), std::move(model)).first->second.get();
}

template <> SpriteFont* ContentManager::Load<SpriteFont>(const std::string& assetName) {
    if (auto it = fonts_.find(portableName(assetName)); it != fonts_.end()) return it->second.get();
    const std::string file = locate(assetName, "SpriteFont",
                                    candidates(RootDirectory, assetName, {".spritefont", ".fnt", ".ttf", ".otf"}));
    GraphicsDevice& graphicsDevice = device(assetName, "SpriteFont");
    LoadTimer timer;
    auto font = loadNamed("SpriteFont", assetName, [&] { return importSpriteFont(graphicsDevice, file); });
    loadLog_.push_back({assetName, "SpriteFont", file, timer.milliseconds()});
    return fonts_.emplace(portableName(assetName), std::move(font)).first->second.get();
}

}  // namespace fxport
