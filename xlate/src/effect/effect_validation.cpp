// The consistency checks of a loaded CompiledEffect (see effect_validation.h).
#include "effect/effect_validation.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "fx/input_limits.h"

namespace fxport::xlate {

namespace {

constexpr int kMaxBlockBytes = 1 << 20;  // far above D3D's 64 KiB constant buffers
constexpr int kMaxBinding = 64;
constexpr int kMaxUnit = 32;
constexpr int kMaxLocation = 32;

bool within(long long v, long long lo, long long hi) { return v >= lo && v <= hi; }

std::optional<std::string> checkChoice(const ShaderChoice& c, const CompiledEffect& e, const std::string& where, bool passValid) {
    for (int s : c.shaders)
        if (!within(s, -1, static_cast<long long>(e.shaders.size()) - 1)) return where + " names shader #" + std::to_string(s) + ", which does not exist";
    // -1 is a NULL element of a shader array (chosen at Apply by index) or a shader that failed
    // in a pass marked invalid; a valid pass's one shader must exist.
    if (passValid && c.selector.empty())
        for (int s : c.shaders)
            if (s < 0) return where + " names shader #" + std::to_string(s) + " and no shader array to choose from";
    for (const auto& op : c.selector)
        if (op.kind != SelectorOp::Kind::PushConstant && !within(op.value, 0, static_cast<long long>(e.parameters.size()) - 1))
            return where + " selects by parameter #" + std::to_string(op.value) + ", which does not exist";
    return std::nullopt;
}

std::optional<std::string> checkParameter(const Parameter& p, const CompiledEffect& e, bool member) {
    const std::string what = "parameter '" + p.name + "'";
    if (!within(p.rows, 1, 4) || !within(p.columns, 1, 4)) return what + " has " + std::to_string(p.rows) + "x" + std::to_string(p.columns) + " components";
    if (!within(p.elements, 0, limits::kMaxArrayElements)) return what + " has " + std::to_string(p.elements) + " elements";
    if (p.size < 0 || p.matrixStride < 0 || p.arrayStride < 0) return what + " has a negative size or stride";
    if (!member) {
        if (!within(p.block, 0, static_cast<long long>(e.uniformBlocks.size()) - 1) && !(p.block == 0 && e.uniformBlocks.empty()))
            return what + " is in constant buffer #" + std::to_string(p.block) + ", which does not exist";
        if (p.offset != -1) {
            long long blockSize = e.uniformBlocks.empty() ? 0 : e.uniformBlocks[static_cast<size_t>(p.block)].size;
            if (p.offset < 0 || static_cast<long long>(p.offset) + p.size > blockSize)
                return what + " lies at bytes " + std::to_string(p.offset) + "+" + std::to_string(p.size) + ", outside its constant buffer of " +
                       std::to_string(blockSize) + " bytes";
        }
    }
    long long values = static_cast<long long>(p.rows) * p.columns * std::max(1, p.elements);
    if (static_cast<long long>(p.defaultValue.size()) > values) return what + " has more default values than components";
    for (const auto& m : p.members)
        if (auto problem = checkParameter(m, e, true)) return problem;
    return std::nullopt;
}

// A stored declaration must be one the compiler could have resolved against the shader's outputs,
// naming only variables the shader has (the runtime links a GL program with them).
std::optional<std::string> checkStreamOutput(const CompiledShader& s) {
    for (const ShaderOutput& o : s.outputs)
        if (!within(o.components, 1, 4) || o.glslName.empty()) return " has output '" + o.semantic + "' of " + std::to_string(o.components) + " components";
    if (!within(s.outputPrimitiveVertices, 0, 3)) return " emits primitives of " + std::to_string(s.outputPrimitiveVertices) + " vertices";
    if (s.streamOutput.empty()) return std::nullopt;
    if (s.profile.stage != ShaderStage::Vertex && s.profile.stage != ShaderStage::Geometry) return " streams output from a stage that cannot";
    if (s.glsl.empty()) {  // an outline (CompileOptions::skipShaders): parsed, never resolved
        for (const auto& e : s.streamOutput.entries)
            if (!e.varying.empty()) return "'s stream output names variables of a shader that was not compiled";
        return std::nullopt;
    }
    StreamOutput again = s.streamOutput;
    for (auto& e : again.entries) e.varying.clear();
    std::string why;
    if (!resolveStreamOutput(s.outputs, again, why)) return "'s stream output is inconsistent: " + why;
    if (again.entries != s.streamOutput.entries) return "'s stream output captures variables its outputs do not name";
    return std::nullopt;
}

}  // namespace

std::optional<std::string> findEffectInconsistency(const CompiledEffect& e) {
    for (const auto& b : e.uniformBlocks)
        if (!within(b.size, 0, kMaxBlockBytes) || !within(b.binding, 0, kMaxBinding))
            return "constant buffer '" + b.name + "' has size " + std::to_string(b.size) + " and binding " + std::to_string(b.binding);
    if (e.uniformBufferSize != (e.uniformBlocks.empty() ? e.uniformBufferSize : e.uniformBlocks[0].size) || e.uniformBufferSize < 0 ||
        e.uniformBufferSize > kMaxBlockBytes)
        return "the $Global size " + std::to_string(e.uniformBufferSize) + " does not match its constant buffer";
    for (const auto& p : e.parameters)
        if (auto problem = checkParameter(p, e, false)) return problem;
    for (size_t i = 0; i < e.shaders.size(); ++i) {
        const CompiledShader& s = e.shaders[i];
        const std::string what = "shader #" + std::to_string(i) + " (" + s.entryPoint + ")";
        for (const auto& in : s.inputs)
            if (!within(in.location, 0, kMaxLocation - 1) || !within(in.components, 1, 4)) return what + " has input '" + in.semantic + "' out of range";
        const long long lastParameter = static_cast<long long>(e.parameters.size()) - 1;
        for (const auto& b : s.samplers) {
            if (!within(b.unit, 0, kMaxUnit - 1)) return what + " binds a sampler to unit " + std::to_string(b.unit);
            if (!within(b.elements, 1, kMaxUnit - b.unit) || !within(b.textureRegister, -1, 127) || !within(b.samplerRegister, -1, 15))
                return what + " binds a sampler of " + std::to_string(b.elements) + " elements at unit " + std::to_string(b.unit) +
                       " (registers t" + std::to_string(b.textureRegister) + ", s" + std::to_string(b.samplerRegister) + ")";
            for (const auto& sp : b.stateParameters) {
                if (!within(sp.parameter, 0, lastParameter)) return what + " reads a sampler state from parameter #" + std::to_string(sp.parameter);
                for (const auto& op : sp.element)
                    if (op.kind != SelectorOp::Kind::PushConstant && !within(op.value, 0, lastParameter))
                        return what + " indexes a sampler state's parameter by parameter #" + std::to_string(op.value) + ", which does not exist";
            }
        }
        for (int p : s.parametersRead)
            if (!within(p, 0, static_cast<long long>(e.parameters.size()) - 1)) return what + " reads parameter #" + std::to_string(p);
        for (const auto* ranges : {&s.uniformRangesRead, &s.uniformRangesLive})
            for (const auto& r : *ranges) {
                if (!within(r.block, 0, static_cast<long long>(e.uniformBlocks.size()) - 1)) return what + " reads constant buffer #" + std::to_string(r.block);
                if (r.offset < 0 || r.size < 0 || static_cast<long long>(r.offset) + r.size > e.uniformBlocks[static_cast<size_t>(r.block)].size)
                    return what + " reads bytes " + std::to_string(r.offset) + "+" + std::to_string(r.size) + " outside its constant buffer";
            }
        if (!within(s.outputTargets, 0, 8)) return what + " writes " + std::to_string(s.outputTargets) + " render targets";
        for (const auto& b : s.storage)
            if (!within(b.slot, 0, 127) || !within(b.binding, 0, kSrvBufferBindingBase + 127) || !within(b.stride, 0, 2048))
                return what + " binds '" + b.name + "' at register " + std::to_string(b.slot) + ", binding " + std::to_string(b.binding) +
                       ", stride " + std::to_string(b.stride);
        if (auto problem = checkStreamOutput(s)) return what + *problem;
        for (int n : s.threadGroupSize)
            if (!within(n, 0, 1024)) return what + " has a thread-group size of " + std::to_string(n);
    }
    for (const auto& t : e.techniques)
        for (const auto& p : t.passes) {
            const std::string where = "pass '" + t.name + "/" + p.name + "'";
            for (const ShaderChoice* c : {&p.vertexShader, &p.pixelShader, &p.geometryShader, &p.hullShader, &p.domainShader, &p.computeShader})
                if (auto problem = checkChoice(*c, e, where, p.valid)) return problem;
            for (const auto& st : p.states) {
                if (!within(st.index, 0, 7)) return where + " sets a state of render target " + std::to_string(st.index);
                if (!within(st.parameter, -1, static_cast<long long>(e.parameters.size()) - 1))
                    return where + " sets a state from parameter #" + std::to_string(st.parameter);
                for (const auto& op : st.element)
                    if (op.kind != SelectorOp::Kind::PushConstant && !within(op.value, 0, static_cast<long long>(e.parameters.size()) - 1))
                        return where + " indexes a state's parameter by parameter #" + std::to_string(op.value) + ", which does not exist";
                // Enum values were read by name; numbers must be numbers.
                bool finite = true;
                if (const float* f = std::get_if<float>(&st.value)) finite = std::isfinite(*f);
                if (const auto* v = std::get_if<std::array<float, 4>>(&st.value))
                    for (float x : *v) finite = finite && std::isfinite(x);
                if (!finite) return where + " sets a state to a value that is not a number";
            }
            for (const TextureStage& ts : p.textureStages) {
                if (!within(ts.stage, 0, 15)) return where + " sets texture stage " + std::to_string(ts.stage);
                const bool known = ts.textureParameter.empty() ||
                                   std::any_of(e.parameters.begin(), e.parameters.end(), [&](const Parameter& x) { return x.name == ts.textureParameter; });
                if (!known) return where + " sets texture stage " + std::to_string(ts.stage) + " from '" + ts.textureParameter + "', which is no parameter";
            }
        }
    return std::nullopt;
}

}  // namespace fxport::xlate
