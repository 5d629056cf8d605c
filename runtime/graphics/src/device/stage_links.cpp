// Stages compiled apart, linked by semantic at draw time (device_impl.h, xlate/varying_links.h):
// an effect's own stages share one numbering and never need this; a D3D11 vertex shader and a
// pixel shader from two D3DCompile calls (or SpriteBatch's vertex shader and a pixel-only
// effect) may number the same user semantic differently, and GL links by number.
#include "device/device_impl.h"
#include "fxport/xlate/varying_links.h"

namespace fxport {

namespace {

// Whether some semantic both share sits at two locations.
bool locationsDiffer(const xlate::CompiledShader& reader, const xlate::CompiledShader& writer) {
    for (const xlate::Varying& in : reader.varyingInputs)
        for (const xlate::Varying& out : writer.varyingOutputs)
            if (in.semantic == out.semantic && in.location != out.location) return true;
    return false;
}

}  // namespace

// The reader's variant with its inputs at `writer`'s locations; null when the reader needs none.
const ShaderProgram* GraphicsDevice::Impl::makeLinkedReader(const ShaderProgram& reader, const ShaderProgram& writer) {
    if (!locationsDiffer(*reader.shader, *writer.shader)) return nullptr;
    std::string outputs;
    for (const xlate::Varying& v : writer.shader->varyingOutputs) outputs += v.semantic + "=" + std::to_string(v.location) + ";";
    auto key = std::make_pair(reader.program, outputs);
    auto it = linkedReaders.find(key);
    if (it != linkedReaders.end()) return &it->second->program;
    std::optional<xlate::CompiledShader> moved = xlate::inputsLinkedTo(*reader.shader, writer.shader->varyingOutputs);
    if (!moved) return nullptr;
    auto linked = std::make_unique<LinkedReader>();
    linked->shader = std::move(*moved);
    linked->program = ShaderProgram{};
    linked->program.stage = reader.stage;
    linked->program.shader = &linked->shader;
    linked->program.label = reader.label + " [inputs linked to " + writer.label + "]";
    linked->program.mayDiscard = reader.mayDiscard;
    linked->program.program =
        createProgram(reader.stage, linked->shader, linked->shader.glsl, linked->program.label);
    return &linkedReaders.emplace(key, std::move(linked)).first->second->program;
}

// Decided once per pair of programs: a draw only looks the pair up.
const ShaderProgram& GraphicsDevice::Impl::linkedReader(const ShaderProgram& reader, const ShaderProgram& writer) {
    const auto pair = std::make_pair(reader.program, writer.program);
    auto known = readerForWriter.find(pair);
    if (known == readerForWriter.end()) known = readerForWriter.emplace(pair, makeLinkedReader(reader, writer)).first;
    return known->second ? *known->second : reader;
}

void GraphicsDevice::Impl::dropLinkedReadersOf(BackendObject readerProgram) {
    for (auto it = readerForWriter.begin(); it != readerForWriter.end();)  // its id may be made again
        it = it->first.first == readerProgram || it->first.second == readerProgram ? readerForWriter.erase(it) : std::next(it);
    std::vector<std::unique_ptr<LinkedReader>> dropped;
    for (auto it = linkedReaders.begin(); it != linkedReaders.end();) {
        if (it->first.first != readerProgram) {
            ++it;
            continue;
        }
        dropped.push_back(std::move(it->second));
        it = linkedReaders.erase(it);
    }
    for (auto& l : dropped) {
        releaseFixedFunctionVariants(l->program);
        deleteProgram(l->program.program);
    }
}

}  // namespace fxport
