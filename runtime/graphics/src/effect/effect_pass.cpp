// EffectPass::Apply: what the D3D effect framework does at BeginPass/CommitChanges.
#include <algorithm>

#include "device/effect_programs.h"
#include "effect/effect_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/texture.h"

namespace fxport {

namespace {

// Evaluates `VertexShader = (VSArray[VSIndices[ShaderIndex]])` style selectors.
int chooseShader(const Effect::Impl& e, const xlate::ShaderChoice& choice, const std::string& technique, const std::string& pass) {
    if (choice.selector.empty()) return choice.shaders[0];
    int pick = int(e.evaluateSelector(choice.selector));
    if (pick < 0 || pick >= int(choice.shaders.size()))
        throw InvalidOperation(e.displayName + " technique '" + technique + "' pass '" + pass + "': the shader-array index evaluates to " + std::to_string(pick) +
                               ", outside 0.." + std::to_string(choice.shaders.size() - 1));
    return choice.shaders[std::size_t(pick)];
}

}  // namespace

double Effect::Impl::evaluateSelector(const std::vector<xlate::SelectorOp>& ops) const {
    std::vector<double> stack;
    for (const xlate::SelectorOp& op : ops) {
        switch (op.kind) {
        case xlate::SelectorOp::Kind::PushConstant: stack.push_back(op.value); break;
        case xlate::SelectorOp::Kind::PushParameter: stack.push_back(parameterNumber(op.value, 0)); break;
        case xlate::SelectorOp::Kind::IndexParameter: {
            int index = stack.empty() ? 0 : int(stack.back());
            if (!stack.empty()) stack.pop_back();
            const xlate::Parameter& array = outline.parameters[std::size_t(op.value)];
            if (index < 0 || index >= std::max(1, array.elements))
                throw InvalidOperation("Effect '" + displayName + "': index " + std::to_string(index) + " of parameter '" + array.name +
                                       "' is outside 0.." + std::to_string(std::max(1, array.elements) - 1));
            stack.push_back(parameterNumber(op.value, index));
            break;
        }
        }
    }
    return stack.empty() ? 0 : stack.back();
}

void Effect::Impl::uploadRead(const std::vector<BlockReads>& reads, Backend& backend) {
    for (const BlockReads& r : reads) {
        Block& block = blocks[std::size_t(r.block)];
        ConstantBlock& b = block.constants;
        if (b.dirtyEnd <= b.dirtyBegin || !block.buffer) continue;
        // Walk the dirty range: send what a read range covers, remember the hull of the rest.
        int leftBegin = INT_MAX, leftEnd = 0, cursor = b.dirtyBegin;
        for (const auto& [begin, end] : r.ranges) {
            int lo = std::max(begin, cursor), hi = std::min(end, b.dirtyEnd);
            if (lo >= hi) continue;
            if (lo > cursor) leftBegin = std::min(leftBegin, cursor), leftEnd = lo;
            backend.writeBuffer(block.buffer, std::size_t(lo), std::size_t(hi - lo), b.bytes.data() + lo);
            constantBytesUploaded += std::uint64_t(hi - lo);
            ++constantUploads;
            cursor = hi;
        }
        if (cursor < b.dirtyEnd) leftBegin = std::min(leftBegin, cursor), leftEnd = b.dirtyEnd;
        b.dirtyBegin = leftBegin;
        b.dirtyEnd = leftEnd;
    }
}

void EffectPass::Apply() {
    if (effect_->IsDisposed()) throw InvalidOperation("EffectPass '" + name_ + "'.Apply(): the effect was disposed");
    // A derived effect (BasicEffect ...) may redirect to the pass of the permutation it needs.
    effect_->OnApply(*this).applyThis();
}

void EffectPass::applyThis() {
    if (effect_->IsDisposed()) throw InvalidOperation("EffectPass '" + name_ + "'.Apply(): the effect was disposed");
    Effect::Impl& e = effectImpl(*effect_);
    GraphicsDevice& device = effect_->device();
    // The first Apply of a technique compiles it (xlate, cached) and links its programs.
    const Effect::Impl::TechniqueCode& code = e.ensureCompiled(technique_, device);
    const xlate::CompiledEffect& compiled = *code.code->effect;
    const xlate::Technique& technique = compiled.techniques[std::size_t(code.index)];
    const xlate::Pass& pass = technique.passes[std::size_t(pass_)];
    if (!pass.valid) {
        std::string where = e.displayName + " technique '" + technique.name + "' pass '" + pass.name + "'";
        std::string why;
        for (const xlate::Diagnostic& diag : compiled.diagnostics) why += "\n  " + diag.format();
        throw InvalidOperation(where + " cannot run: the compiler rejected it" + why);
    }

    // The draw stages, then compute (dispatched alone: DispatchCompute).
    const xlate::ShaderChoice* choices[kUniformStages] = {&pass.vertexShader, &pass.pixelShader, &pass.geometryShader,
                                                          &pass.hullShader, &pass.domainShader, &pass.computeShader};
    for (int stage = 0; stage < kUniformStages; ++stage) {
        const xlate::ShaderChoice& choice = *choices[stage];
        if (choice.shaders.empty()) {
            // D3D: a stage the pass does not assign keeps its shader -- except the geometry, hull
            // and domain stages, which a pass with a vertex shader and none of its own runs without.
            if (stage >= 2 && stage < kStageCount && !pass.vertexShader.shaders.empty()) effects::bindShader(device, stage, nullptr);
            if (stage == 1 && pass.nullPixelShader) effects::bindShader(device, 1, nullptr);  // Effects 10/11's SetPixelShader(NULL): a front end supplies none
            continue;
        }
        int chosen = chooseShader(e, choice, technique.name, pass.name);
        if (chosen < 0 || std::size_t(chosen) >= code.code->programs.size())  // a NULL element of a shader array
            throw InvalidOperation(e.displayName + " technique '" + technique.name + "' pass '" + pass.name + "': the shader chosen for stage " +
                                   std::to_string(stage) + " is NULL (#" + std::to_string(chosen) + "); fxport has no fixed-function pipeline to draw with");
        std::size_t shader = std::size_t(chosen);
        const ShaderProgram& program = code.code->programs[shader];
        effects::bindShader(device, stage, &program);
        // Only the blocks this shader reads, and of those only the bytes it reads; changes to
        // other constants stay dirty until a shader that reads them is applied.
        const std::vector<Effect::Impl::BlockReads>& reads = code.code->reads[shader];
        e.uploadRead(reads, effects::backend(device));
        for (const Effect::Impl::BlockReads& r : reads) {
            const Effect::Impl::Block& block = e.blocks[std::size_t(r.block)];
            if (block.buffer) effects::wantUniformBuffer(device, uniformBindingFor(stage, block.binding), block.buffer);
        }
        for (const SamplerSlot& slot : code.code->samplers[shader]) {
            // A texture parameter left unset does not clear the slot: hosts that feed
            // Textures[n] directly (as the tutorials do) keep working. An SM 1-3 vertex shader's
            // sampler is XNA's vertex texture of its s#.
            const bool vertex = slot.vertexRegister >= 0 && slot.vertexRegister < kMaxTextureSlots;
            TextureCollection& textures = vertex ? device.VertexTextures : device.Textures;
            SamplerStateCollection& states = vertex ? device.VertexSamplerStates : device.SamplerStates;
            const int index = vertex ? slot.vertexRegister : slot.unit;
            if (slot.textureParameter >= 0 && e.textures[std::size_t(slot.textureParameter)])
                textures[index] = e.textures[std::size_t(slot.textureParameter)];
            states[index] = samplerStateOver(slot, e, states[index]);
        }
    }
    // A stage the pass leaves alone keeps its shader (D3D9). When that is one of this effect's (an
    // earlier pass's vertex shader under a pixel-shader-only pass), it reads this effect's
    // constants too: send what changed of those.
    for (int stage = 0; stage < kStageCount; ++stage)  // (a compute shader is another pass's own)
        if (choices[stage]->shaders.empty())
            if (const ShaderProgram* kept = effects::boundShader(device, stage))
                if (const auto* reads = e.readsOf(kept)) e.uploadRead(*reads, effects::backend(device));
    applyPassStates(code.code->passStates[std::size_t(code.index)][std::size_t(pass_)], e, device);
    effects::passApplied(device);
}

}  // namespace fxport
