// The [test] directives of a model run that touch the GPU: draws, uniforms, clears and probes
// (see model_run.h).
#include <cstdio>
#include <cstring>
#include <sstream>

#include "fxport/graphics.h"
#include "fxport/xlate/compiled_effect.h"
#include "fxport/xlate/diagnostics.h"
#include "model_run.h"
#include "probe.h"
#include "qualifiers.h"
#include "uniform_layout.h"

namespace conformance {

namespace {

const char* const kQuadVertexShader =
    "float4 main(float4 pos : position) : sv_position\n"
    "{\n"
    "    return pos;\n"
    "}\n";

DrawCall parseDrawCall(const std::string& args) {
    DrawCall call;
    std::string a = args;
    a.erase(0, a.find_first_not_of(' '));
    if (a.rfind("quad", 0) == 0) { call.quad = true; return call; }
    for (const char* topology : {"triangle list", "triangle strip", "point list"}) {
        if (a.rfind(topology, 0) != 0) continue;
        call.topology = topology;
        std::istringstream in(a.substr(std::strlen(topology)));
        int instances = 1;
        in >> call.vertexCount;
        if (in >> instances && instances != 1) throw Unsupported("instanced draw");
        return call;
    }
    throw Unsupported("primitive topology '" + a + "'");
}

std::string firstError(const fxport::xlate::CompileError& e) {
    for (const auto& d : e.diagnostics())
        if (d.severity == fxport::xlate::Severity::Error) return d.id + ": " + d.message;
    return e.what();
}

// The value of one parameter scalar from vkd3d's uniform words. SM4+ constant buffers hold ints as
// ints; D3D9's float registers hold every numeric constant as a float.
double scalarValue(const fxport::xlate::Parameter& p, std::uint32_t word, int model) {
    float f;
    std::memcpy(&f, &word, 4);
    if (p.type == fxport::xlate::ParameterType::Float) return double(f);
    if (model < 40) return p.type == fxport::xlate::ParameterType::Bool ? (f != 0.0f ? 1.0 : 0.0) : double(int(f));
    if (p.type == fxport::xlate::ParameterType::Bool) return word != 0 ? 1.0 : 0.0;
    if (p.type == fxport::xlate::ParameterType::UInt) return double(word);
    return double(std::int32_t(word));
}

}  // namespace

fxport::Effect& ModelRun::effectFor(const std::string& vs, const std::string& ps) {
    std::string key = require_.matrixPacking + "\x01" + vs + "\x01" + ps;
    auto known = effects_.find(key);
    if (known != effects_.end()) return *known->second;
    const Block* vsBlock = shaders_.count(Stage::Vertex) ? shaders_[Stage::Vertex].block : nullptr;
    const Block* psBlock = shaders_[Stage::Pixel].block;
    std::string vsPath = compiler_.writeSource(vs, vsBlock ? vsBlock->line : 0, require_, ".hlsl");
    std::string psPath = compiler_.writeSource(ps, psBlock->line, require_, ".hlsl");
    fxport::EffectOptions options;
    options.cacheDir = options_.cacheDir;
    options.useCache = !options_.cacheDir.empty();
    std::unique_ptr<fxport::Effect> effect = fxport::Effect::FromShaderFiles(
        gpu().device(), {vsPath, "main", shaderProfile(Stage::Vertex, model_)},
        {psPath, "main", shaderProfile(Stage::Pixel, model_)}, options);
    effect->Precompile();
    return *(effects_[key] = std::move(effect));
}

std::string ModelRun::applyUniforms(fxport::Effect& effect, const std::string& source) {
    const fxport::xlate::CompiledEffect& compiled = effect.compiled();
    std::string uncovered = uncoveredUniformRead(compiled);
    if (!uncovered.empty()) throw Unsupported(uncovered);
    UniformLayout layout = computeUniformLayout(compiled, source, model_);
    for (const ParameterPlacement& placement : layout.placements) {
        const fxport::xlate::Parameter& p = compiled.parameters[std::size_t(placement.parameter)];
        if (!placement.settable) throw Unsupported(placement.why);
        if (p.offset < 0) continue;  // no shader reads it
        // D3D reads 0 past the end of the constant data bound (and ignores HLSL initializers of
        // loose shaders' globals), so every parameter is written, unset ones as 0.
        std::vector<float> floats;
        std::vector<int> ints;
        for (int off : placement.scalarOffsets) {
            std::uint32_t word = std::size_t(off) < uniforms_.size() ? uniforms_[std::size_t(off)] : 0u;
            double v = scalarValue(p, word, model_);
            if (p.type == fxport::xlate::ParameterType::Float) floats.push_back(float(v));
            else ints.push_back(int(std::int64_t(v)));
        }
        fxport::EffectParameter& parameter = effect.Parameters[p.name];
        if (p.type == fxport::xlate::ParameterType::Float) parameter.SetValue(std::span<const float>(floats));
        else parameter.SetValue(std::span<const int>(ints));
    }
    return layout.guess;
}

void ModelRun::doDraw(const std::string& args, int line) {
    drawState_ = DrawState::Skipped;
    drawNote_.clear();
    layoutGuess_.clear();
    try {
        DrawCall call = parseDrawCall(args);
        if (!stickyStates_.empty())
            throw Unsupported("test state '" + stickyStates_.begin()->second + "' (not settable through the runtime API)");
        for (Stage s : {Stage::Geometry, Stage::Hull, Stage::Domain})
            if (shaders_.count(s))
                throw Unsupported(std::string(stageName(s)) + " shader in a draw (Effect::FromShaderFiles takes vertex and pixel shaders)");
        if (!shaders_.count(Stage::Pixel)) throw Unsupported("draw without a pixel shader");
        std::string vs = shaders_.count(Stage::Vertex) ? shaders_[Stage::Vertex].block->source() : kQuadVertexShader;
        if (call.quad && !shaders_.count(Stage::Vertex)) vs = kQuadVertexShader;
        std::string ps = shaders_[Stage::Pixel].block->source();
        if (crashedBefore(line)) throw std::runtime_error("the draw crashed the process");
        for (Stage s : {Stage::Vertex, Stage::Pixel})
            if (shaders_.count(s) && crashedBefore(shaders_[s].block->line))
                throw std::runtime_error("the compile of the section at line " + std::to_string(shaders_[s].block->line) +
                                         " crashed the process");
        mark(line);
        fxport::Effect& effect = effectFor(vs, ps);
        layoutGuess_ = applyUniforms(effect, vs + ps);
        gpu().draw(effect, vs + ps, model_, call);
        drawState_ = DrawState::Drawn;
    } catch (const Unsupported& e) {
        drawNote_ = e.what();
    } catch (const fxport::xlate::CompileError& e) {
        drawState_ = DrawState::Failed;
        drawNote_ = firstError(e);
    } catch (const std::exception& e) {
        drawState_ = DrawState::Failed;
        drawNote_ = e.what();
    }
    if (drawState_ == DrawState::Failed) {
        failures_.push_back({file_.name, model_, line, "draw", drawNote_});
        log("L" + std::to_string(line) + " draw FAILED: " + drawNote_);
    } else if (drawState_ == DrawState::Skipped) {
        log("L" + std::to_string(line) + " draw skipped: " + drawNote_);
    }
}

void ModelRun::doClear(const std::string& args) {
    std::istringstream in(args);
    int slot = 0;
    float rgba[4] = {0, 0, 0, 0};
    in >> slot >> rgba[0] >> rgba[1] >> rgba[2] >> rgba[3];
    try {
        gpu().clearTarget(slot, rgba);
    } catch (const Unsupported&) {
        // A probe of that target reports why.
    }
}

void ModelRun::doProbe(const std::string& args, int line) {
    Probe probe = parseProbe(args);
    if (probe.kind == "f64" || probe.kind == "u64" || probe.kind == "i64") return skipProbe("64-bit probe (double/int64 targets)");
    if (probe.target == Probe::Target::Uav) return skipProbe("UAV probe (fxport has no UAVs yet)");
    if (probe.target == Probe::Target::Dsv) return skipProbe("depth-stencil probe (no depth readback)");
    if (drawState_ == DrawState::Skipped) return skipProbe(drawNote_);
    if (drawState_ == DrawState::Failed) return failProbe(line, "draw failed: " + drawNote_);
    try {
        for (int y = probe.top; y < probe.bottom; ++y) {
            for (int x = probe.left; x < probe.right; ++x) {
                Texel texel = gpu().readTexel(probe.slot, x, y);
                if (texelMatches(probe, texel)) continue;
                return failProbe(line, "expected " + describeExpected(probe) + ", got " + describeTexel(probe, texel) +
                                           " at (" + std::to_string(x) + ", " + std::to_string(y) + ")" +
                                           (layoutGuess_.empty() ? "" : " [uniforms placed by a guess: " + layoutGuess_ + "]"));
            }
        }
    } catch (const Unsupported& e) {
        return skipProbe(e.what());
    }
    ++result_.probesRun;
    ++result_.probesPassed;
}

}  // namespace conformance
