// INTERNAL: an Effect's GL side.
//
// An effect loads as an outline (xlate's CompileOptions::skipShaders: techniques, passes,
// parameters, no shader code); a technique's shaders are cross-compiled and linked the first time
// one of its passes is applied (or by Precompile()). Each compile yields a Code: its own
// CompiledEffect (filtered to the techniques it was asked for), a separable program per shader and,
// per program, the byte ranges of each uniform block the shader reads.
//
// Constants live in one CPU shadow per uniform block with a dirty byte range (ConstantBlock). Until a compiled
// shader declares a block, its layout is unknown; the shadow then uses a provisional packed layout
// (each parameter row-major, tightly packed) so that SetValue/GetValue work before any Apply. When a
// Code brings the real layout, adoptLayouts() moves every value to its real place and creates the
// GL buffer. Apply() uploads, for each shader it binds, only the dirty bytes that shader reads; the
// rest stays dirty for a later pass.
#pragma once

#include <climits>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "effect/constant_block.h"
#include "effect/effect_notices.h"
#include "device/backend.h"
#include "device/impl_access.h"
#include "device/shader_program.h"
#include "fxport/graphics/effect.h"
#include "fxport/xlate/compiled_effect.h"
#include "effect/pass_states.h"

namespace fxport {

struct Effect::Impl {
    // The outline: techniques, passes and parameters; parameter offsets are the block layouts known
    // so far (provisional for a block no compiled shader declared yet).
    xlate::CompiledEffect outline;
    std::string displayName;  // file name for messages: "GBuffer.fx"
    // Whether a draw with one of its SRGBWriteEnable passes into a target GL does not encode was
    // reported (once per effect; set while drawing, hence mutable).
    mutable bool reportedUnencodedSrgbWrite = false;

    // Where technique compiles come from: the effect's source (kept from load, so a technique
    // compiled later matches the outline even if the file changes), or nothing when the effect
    // was built from an already compiled effect.
    bool fromSource = false;
    std::string source;
    std::string sourcePath;
    EffectOptions options;

    struct Block {
        BackendObject buffer = 0;  // 0 while the layout is provisional
        int binding = 0;
        bool provisional = true;
        ConstantBlock constants;  // the CPU shadow and its dirty range
    };
    std::vector<Block> blocks;
    std::vector<Texture*> textures;  // per parameter (objects only)
    // Per parameter that no shader reads (no block storage): its scalars as set, row by row,
    // element by element; empty until set (the default applies). D3D's effect parameters keep a
    // value all the same: pass states (`ZWriteEnable = <ZWrites[Mode]>`) and shader selectors read it.
    std::vector<std::vector<double>> unread;
    std::unordered_map<std::string, int> parameterIndex;

    // Byte ranges [begin, end) of one block that a shader reads, sorted, merged.
    struct BlockReads {
        int block = 0;
        std::vector<std::pair<int, int>> ranges;
    };
    struct Code {
        std::shared_ptr<const xlate::CompiledEffect> effect;
        std::vector<ShaderProgram> programs;               // per effect->shaders
        std::vector<std::vector<BlockReads>> reads;        // per effect->shaders
        std::vector<std::vector<SamplerSlot>> samplers;    // per effect->shaders, decoded once
        std::vector<std::vector<PassStates>> passStates;   // per effect->techniques, per pass, decoded once
    };
    std::vector<std::unique_ptr<Code>> codes;  // stable addresses: the device points at programs
    struct TechniqueCode {
        Code* code = nullptr;  // nullptr until compiled
        int index = -1;        // the technique's index in code->effect->techniques
    };
    std::vector<TechniqueCode> techniqueCode;  // per outline technique
    const Code* whole = nullptr;  // a Code holding every technique (Precompile/compiled())

    // Introspection (Effect::statistics()).
    double loadMilliseconds = 0;
    double compileMilliseconds = 0;
    double linkMilliseconds = 0;
    std::uint64_t constantBytesUploaded = 0;
    std::uint64_t constantUploads = 0;

    void forgetTexture(const Texture* texture) {
        for (Texture*& t : textures)
            if (t == texture) t = nullptr;
    }
    // Scalar `k` (row by row, element by element) of parameter `index`; for a parameter no shader
    // reads, its value as set or else its default; 0 past the end.
    double parameterScalar(int index, int k) const {
        const xlate::Parameter& p = outline.parameters[std::size_t(index)];
        if (p.offset >= 0) return blocks[std::size_t(p.block)].constants.load(p, k);
        const std::vector<double>& set = unread[std::size_t(index)];
        const std::vector<double>& values = set.empty() ? p.defaultValue : set;
        return k >= 0 && std::size_t(k) < values.size() ? values[std::size_t(k)] : 0.0;
    }
    // The first scalar of element `element` of parameter `index` (parameter-driven states and
    // shader selectors).
    double parameterNumber(int index, int element) const {
        const xlate::Parameter& p = outline.parameters[std::size_t(index)];
        return parameterScalar(index, element * p.rows * p.columns);
    }
    // Runs a selector program (`VSIndices[ShaderIndex]`, `ZWrites[Mode]`) over the current
    // parameter values: the number it leaves (0 for an empty program). An index outside its array
    // is an InvalidOperation naming the parameter.
    double evaluateSelector(const std::vector<xlate::SelectorOp>& ops) const;
    // Uploads the dirty bytes of each block that `reads` covers; what it does not cover stays dirty
    // (as one range: the hull of what is left, so some bytes may be sent twice, never too few).
    void uploadRead(const std::vector<BlockReads>& reads, Backend& backend);
    // What a program of this effect reads; nullptr for another effect's program.
    const std::vector<BlockReads>* readsOf(const ShaderProgram* program) const {
        for (const auto& code : codes)
            for (std::size_t i = 0; i < code->programs.size(); ++i)
                if (&code->programs[i] == program) return &code->reads[i];
        return nullptr;
    }

    // Block layouts: start provisional, then take the real ones from a compiled effect.
    void layOutProvisionally();
    void adoptLayouts(const xlate::CompiledEffect& code, GraphicsDevice& device);
    // Moves the value of parameter `index` from its provisional block place to `unread` (a compiled
    // technique says no shader reads it).
    void keepUnreadValue(int index);

    // Compiles (if needed) the technique `technique` of the outline and returns its code.
    const TechniqueCode& ensureCompiled(int technique, GraphicsDevice& device);
    // Compiles every technique not compiled yet, in one xlate call.
    void compileAll(GraphicsDevice& device);
    // Makes programs and read ranges for a compiled effect and adopts its layouts.
    Code& addCode(std::shared_ptr<const xlate::CompiledEffect> effect, GraphicsDevice& device);
    void releasePrograms(GraphicsDevice& device);

    // "float4x4", "float3[8]", "texture2D", for messages.
    static std::string hlslTypeName(const xlate::Parameter& p);
};

}  // namespace fxport
