// Effect::FromShaderFiles: an effect made of loose D3D10/11 shader files by entry point and
// profile (xlate's compileShaderFiles does the compiling and merging; this only maps the options).
#include "fxport/graphics/effect.h"
#include "fxport/xlate/effect_compiler.h"

namespace fxport {

std::unique_ptr<Effect> Effect::FromShaderFiles(fxport::GraphicsDevice& device, const ShaderFile& vertexShader,
                                                const ShaderFile& pixelShader, const EffectOptions& options) {
    return FromShaderFiles(device, std::vector<ShaderFile>{vertexShader, pixelShader}, options);
}

std::unique_ptr<Effect> Effect::FromShaderFiles(fxport::GraphicsDevice& device, const std::vector<ShaderFile>& shaders,
                                                const EffectOptions& options) {
    xlate::CompileOptions o;
    o.includeDirs = options.includeDirs;
    o.includeRoot = options.includeRoot;
    o.defines = options.defines;
    o.useCache = options.useCache;
    o.cacheDir = options.cacheDir;
    std::vector<xlate::ShaderEntry> entries;
    for (const ShaderFile& s : shaders) entries.push_back({s.path, s.entryPoint, s.profile});
    return std::make_unique<Effect>(device, xlate::compileShaderFiles(entries, o));
}

}  // namespace fxport
