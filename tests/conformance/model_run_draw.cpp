// The [test] directives of a model run that touch the GPU: draws, uniforms, clears and probes
// (see model_run.h).
#include <functional>
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
    // "3 control point patch list 3": patches of 3 control points, 3 vertices in all.
    {
        int points = 0, vertices = 0, used = 0;
        if (std::sscanf(a.c_str(), "%d control point patch list %d%n", &points, &vertices, &used) == 2) {
            call.topology = "patch list";
            call.controlPoints = points;
            call.vertexCount = vertices;
            if (points <= 0 || vertices % points) throw std::runtime_error("patch list of " + std::to_string(vertices) + " vertices in patches of " + std::to_string(points));
            return call;
        }
    }
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
    return effectOf({{Stage::Vertex, vs}, {Stage::Pixel, ps}});
}

fxport::Effect& ModelRun::effectOf(const std::vector<std::pair<Stage, std::string>>& stages) {
    std::string key = require_.matrixPacking;
    for (const auto& [stage, source] : stages) key += "\x01" + std::to_string(int(stage)) + "\x01" + source;
    auto known = effects_.find(key);
    if (known != effects_.end()) return *known->second;
    std::vector<fxport::Effect::ShaderFile> files;
    for (const auto& [stage, source] : stages) {
        const Block* block = shaders_.count(stage) ? shaders_[stage].block : nullptr;
        files.push_back({compiler_.writeSource(source, block ? block->line : 0, require_, ".hlsl"), "main", shaderProfile(stage, model_)});
    }
    fxport::EffectOptions options;
    options.cacheDir = options_.cacheDir;
    options.useCache = !options_.cacheDir.empty();
    std::unique_ptr<fxport::Effect> effect = fxport::Effect::FromShaderFiles(gpu().device(), files, options);
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

// A draw or dispatch: Drawn when `step` returns; Skipped with the reason when it throws
// Unsupported; Failed with the error otherwise. Then the outcome is noted for the line.
void ModelRun::gpuStep(int line, const std::function<void()>& step) {
    drawState_ = DrawState::Skipped;
    drawNote_.clear();
    layoutGuess_.clear();
    try {
        step();
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
    noteDrawOutcome(line);
}

void ModelRun::doDraw(const std::string& args, int line) {
    gpuStep(line, [&] {
        DrawCall call = parseDrawCall(args);
        if (!stickyStates_.empty())
            throw Unsupported("test state '" + stickyStates_.begin()->second + "' (not settable through the runtime API)");
        const bool patches = call.topology == "patch list";
        if (patches && !(shaders_.count(Stage::Hull) && shaders_.count(Stage::Domain)))
            throw Unsupported("patch list without hull and domain shaders (D3D11 draws patches only through them)");
        if (!patches && (shaders_.count(Stage::Hull) || shaders_.count(Stage::Domain)))
            throw Unsupported("hull/domain shaders in a draw of " + call.topology + " (they take patch lists)");
        if (!shaders_.count(Stage::Pixel)) throw Unsupported("draw without a pixel shader");
        std::string vs = shaders_.count(Stage::Vertex) ? shaders_[Stage::Vertex].block->source() : kQuadVertexShader;
        if (call.quad && !shaders_.count(Stage::Vertex)) vs = kQuadVertexShader;
        std::vector<std::pair<Stage, std::string>> stages = {{Stage::Vertex, vs}};
        if (patches) {
            stages.push_back({Stage::Hull, shaders_[Stage::Hull].block->source()});
            stages.push_back({Stage::Domain, shaders_[Stage::Domain].block->source()});
        }
        if (shaders_.count(Stage::Geometry)) stages.push_back({Stage::Geometry, shaders_[Stage::Geometry].block->source()});
        stages.push_back({Stage::Pixel, shaders_[Stage::Pixel].block->source()});
        if (crashedBefore(line)) throw std::runtime_error("the draw crashed the process");
        std::string all;
        for (const auto& [stage, source] : stages) {
            if (shaders_.count(stage) && shaders_[stage].block->hexBytecode)
                throw Unsupported("precompiled bytecode section (no HLSL to compile)");
            if (shaders_.count(stage) && crashedBefore(shaders_[stage].block->line))
                throw std::runtime_error("the compile of the section at line " + std::to_string(shaders_[stage].block->line) +
                                         " crashed the process");
            all += source;
        }
        mark(line);
        fxport::Effect& effect = effectOf(stages);
        layoutGuess_ = applyUniforms(effect, all);
        gpu().draw(effect, all, model_, call);
    });
}

void ModelRun::doDispatch(const std::string& args, int line) {
    gpuStep(line, [&] {
        int x = 1, y = 1, z = 1;
        std::istringstream(args) >> x >> y >> z;
        if (!shaders_.count(Stage::Compute)) throw Unsupported("dispatch without a compute shader");
        const Block& cs = *shaders_[Stage::Compute].block;
        if (cs.hexBytecode) throw Unsupported("precompiled bytecode section (no HLSL to compile)");
        if (crashedBefore(line)) throw std::runtime_error("the dispatch crashed the process");
        if (crashedBefore(cs.line)) throw std::runtime_error("the compile of the section at line " + std::to_string(cs.line) + " crashed the process");
        mark(line);
        std::string source = cs.source();
        fxport::Effect& effect = effectOf({{Stage::Compute, source}});
        layoutGuess_ = applyUniforms(effect, source);
        gpu().dispatch(effect, source, model_, x, y, z);
    });
}

void ModelRun::noteDrawOutcome(int line) {
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
    if (probe.target == Probe::Target::Dsv) return skipProbe("depth-stencil probe (no depth readback)");
    if (drawState_ == DrawState::Skipped) return skipProbe(drawNote_);
    if (drawState_ == DrawState::Failed) return failProbe(line, "draw failed: " + drawNote_);
    try {
        for (int y = probe.top; y < probe.bottom; ++y) {
            for (int x = probe.left; x < probe.right; ++x) {
                Texel texel = probe.target == Probe::Target::Uav ? gpu().readUav(probe.slot, x, y) : gpu().readTexel(probe.slot, x, y);
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
