// The [test] directives of a model run that touch the GPU: draws, uniforms, clears and probes
// (see model_run.h).
#include <functional>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "fxport/xlate/compiled_effect.h"
#include "fxport/xlate/diagnostics.h"
#include "model_run.h"
#include "probe.h"
#include "qualifiers.h"

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
        if (in >> instances) call.instances = instances;
        return call;
    }
    throw Unsupported("primitive topology '" + a + "'");
}

std::string firstError(const fxport::xlate::CompileError& e) {
    for (const auto& d : e.diagnostics())
        if (d.severity == fxport::xlate::Severity::Error) return d.id + ": " + d.message;
    return e.what();
}

}  // namespace

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

StageSource ModelRun::stageSource(Stage stage) const {
    const Block& block = *shaders_.at(stage).block;
    if (block.hexBytecode) throw Unsupported("precompiled bytecode section (no HLSL to compile)");
    if (crashedBefore(block.line))
        throw std::runtime_error("the compile of the section at line " + std::to_string(block.line) + " crashed the process");
    return StageSource{stage, block.source(), block.line};
}

ShaderSet ModelRun::drawStages(const DrawCall& call) {
    const bool patches = call.topology == "patch list";
    if (patches && !(shaders_.count(Stage::Hull) && shaders_.count(Stage::Domain)))
        throw Unsupported("patch list without hull and domain shaders (D3D11 draws patches only through them)");
    if (!patches && (shaders_.count(Stage::Hull) || shaders_.count(Stage::Domain)))
        throw Unsupported("hull/domain shaders in a draw of " + call.topology + " (they take patch lists)");
    if (!shaders_.count(Stage::Pixel)) throw Unsupported("draw without a pixel shader");
    ShaderSet set;
    set.require = require_;
    // Files without a vertex shader take vkd3d's pass-through one.
    set.stages.push_back(shaders_.count(Stage::Vertex) ? stageSource(Stage::Vertex) : StageSource{Stage::Vertex, kQuadVertexShader, 0});
    if (patches) {
        set.stages.push_back(stageSource(Stage::Hull));
        set.stages.push_back(stageSource(Stage::Domain));
    }
    if (shaders_.count(Stage::Geometry)) set.stages.push_back(stageSource(Stage::Geometry));
    set.stages.push_back(stageSource(Stage::Pixel));
    return set;
}

void ModelRun::doDraw(const std::string& args, int line) {
    gpuStep(line, [&] {
        DrawCall call = parseDrawCall(args);
        if (!stickyStates_.empty())
            throw Unsupported("test state '" + stickyStates_.begin()->second + "' (not settable through the runtime API)");
        ShaderSet stages = drawStages(call);
        if (crashedBefore(line)) throw std::runtime_error("the draw crashed the process");
        mark(line);
        gpu().setFixedFunction(fixedFunction_);
        layoutGuess_ = gpu().draw(stages, uniforms_, call);
    });
}

void ModelRun::doDispatch(const std::string& args, int line) {
    gpuStep(line, [&] {
        int x = 1, y = 1, z = 1;
        std::istringstream(args) >> x >> y >> z;
        if (!shaders_.count(Stage::Compute)) throw Unsupported("dispatch without a compute shader");
        ShaderSet set;
        set.require = require_;
        set.stages.push_back(stageSource(Stage::Compute));
        if (crashedBefore(line)) throw std::runtime_error("the dispatch crashed the process");
        mark(line);
        layoutGuess_ = gpu().dispatch(set, uniforms_, x, y, z);
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

// `copy rtv 0 srv 0`: from the first resource into the second. A session that cannot copy leaves
// the line as a state the following draws skip on, naming it.
void ModelRun::doCopy(const std::string& args) {
    std::istringstream in(args);
    std::string fromKind, toKind;
    int fromSlot = 0, toSlot = 0;
    if (!(in >> fromKind >> fromSlot >> toKind >> toSlot)) throw std::runtime_error("malformed copy line 'copy " + args + "'");
    try {
        gpu().copyResource(fromKind, fromSlot, toKind, toSlot);
    } catch (const Unsupported&) {
        stickyStates_["copy"] = "copy " + fromKind;
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
