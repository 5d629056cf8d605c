// Every family of fxc's rejections that fxport checks before glslang sees the effect, run in one
// place (runFxcChecks, called by the compiler after parsing). Each family is one file with its own
// header comment naming the rule, fxc's error number and the conformance file that pins it; adding
// a family is one line in fxc_checks.cpp. fxc_rejections.h holds the first, token-pattern family.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "fx/shader_profile.h"
#include "fx/source_map.h"

namespace fxport::xlate {

// All errors of all families, in source order, one per token.
std::vector<Diagnostic> runFxcChecks(const EffectSyntax& syntax, const SourceMap& map);

// What the families share: the tokens, a located report, bracket matching and the shaders the
// effect compiles.
class FxcCheck {
public:
    FxcCheck(const EffectSyntax& syntax, const SourceMap& map) : syntax_(syntax), t_(syntax.tokens), map_(map) {}
    std::vector<std::pair<size_t, Diagnostic>> takeFound() { return std::move(found_); }

protected:
    // `compile ps_4_0 main()` in a pass or a shader variable: the profile and the entry function.
    struct CompiledEntry {
        ShaderProfile profile;
        const FxFunction* function = nullptr;
    };

    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    const SourceMap& map_;

    const Token& tok(size_t i) const { return t_[std::min(i, t_.size() - 1)]; }
    void report(const std::string& message, size_t token);  // FX2001, as glslang's refusals
    void report(const char* id, const std::string& message, size_t token);
    size_t closing(size_t open) const;  // the bracket closing the one at `open` (or the end token)
    bool inFunction(size_t at) const;
    const FxFunction* functionAt(size_t at) const;
    std::vector<CompiledEntry> compiledEntries() const;
    // The functions `entry` calls, directly or not, itself included.
    std::vector<const FxFunction*> reachableFrom(const FxFunction& entry) const;
    // Whether `name` is mentioned in the body of one of `functions` (a use, as far as tokens tell).
    bool mentionedIn(const std::vector<const FxFunction*>& functions, const std::string& name) const;

private:
    std::vector<std::pair<size_t, Diagnostic>> found_;
};

// The families (one file each).
std::vector<std::pair<size_t, Diagnostic>> findRegisterReservationErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findConstantBufferSlotErrors(const EffectSyntax& syntax, const SourceMap& map);  // constant_buffer_slots.cpp
std::vector<std::pair<size_t, Diagnostic>> findGeometryEntryErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findGeometryInputErrors(const EffectSyntax& syntax, const SourceMap& map);  // geometry_input_rules.cpp
std::vector<std::pair<size_t, Diagnostic>> findLocalDeclarationErrors(const EffectSyntax& syntax, const SourceMap& map);  // local_declaration_rules.cpp
std::vector<std::pair<size_t, Diagnostic>> findImplicitSizeArrayErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findEntrySemanticErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findMajorityModifierErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findStateBlockErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findFunctionAttributeErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findStaticSamplerErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findFunctionSignatureErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findComputeOnlyIntrinsicErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findTextureShaderIntrinsicErrors(const EffectSyntax& syntax, const SourceMap& map);  // texture_shader_intrinsics.cpp
std::vector<std::pair<size_t, Diagnostic>> findSm4ObjectMethodErrors(const EffectSyntax& syntax, const SourceMap& map);  // sm4_object_methods.cpp
std::vector<std::pair<size_t, Diagnostic>> findMatrixShapeConversionErrors(const EffectSyntax& syntax, const SourceMap& map);
std::vector<std::pair<size_t, Diagnostic>> findLvalueCastErrors(const EffectSyntax& syntax, const SourceMap& map);  // lvalue_casts.cpp
std::vector<std::pair<size_t, Diagnostic>> findEffectKeywordErrors(const EffectSyntax& syntax, const SourceMap& map);  // effect_keywords.cpp
std::vector<std::pair<size_t, Diagnostic>> findPatchObjectErrors(const EffectSyntax& syntax, const SourceMap& map);  // patch_objects.cpp
std::vector<std::pair<size_t, Diagnostic>> findOverloadAmbiguityErrors(const EffectSyntax& syntax, const SourceMap& map);  // overload_ambiguity.cpp
std::vector<std::pair<size_t, Diagnostic>> findTernaryShapeErrors(const EffectSyntax& syntax, const SourceMap& map);  // ternary_shapes.cpp
std::vector<std::pair<size_t, Diagnostic>> findUniformInitializerErrors(const EffectSyntax& syntax, const SourceMap& map);  // uniform_initializers.cpp
std::vector<std::pair<size_t, Diagnostic>> findUavRuleErrors(const EffectSyntax& syntax, const SourceMap& map);  // uav_rules.cpp
std::vector<std::pair<size_t, Diagnostic>> findEffectObjectValueErrors(const EffectSyntax& syntax, const SourceMap& map);  // effect_object_values.cpp
std::vector<std::pair<size_t, Diagnostic>> findCbufferReservationErrors(const EffectSyntax& syntax, const SourceMap& map);  // cbuffer_reservations.cpp
std::vector<std::pair<size_t, Diagnostic>> findResourceArrayIndexingErrors(const EffectSyntax& syntax, const SourceMap& map);  // resource_array_indexing.cpp
std::vector<std::pair<size_t, Diagnostic>> findIndexTypeErrors(const EffectSyntax& syntax, const SourceMap& map);  // index_types.cpp
std::vector<std::pair<size_t, Diagnostic>> findLengthPropertyErrors(const EffectSyntax& syntax, const SourceMap& map);  // length_property.cpp
std::vector<std::pair<size_t, Diagnostic>> findSwitchSelectorErrors(const EffectSyntax& syntax, const SourceMap& map);  // switch_labels.cpp
std::vector<std::pair<size_t, Diagnostic>> findOperandTypeErrors(const EffectSyntax& syntax, const SourceMap& map);  // operand_type_rules.cpp
std::vector<std::pair<size_t, Diagnostic>> findMatrixSubscriptErrors(const EffectSyntax& syntax, const SourceMap& map);  // matrix_subscripts.cpp
std::vector<std::pair<size_t, Diagnostic>> findOutArgumentShapeErrors(const EffectSyntax& syntax, const SourceMap& map);  // out_argument_shapes.cpp
std::vector<std::pair<size_t, Diagnostic>> findDeclarationLimitErrors(const EffectSyntax& syntax, const SourceMap& map);  // declaration_limits.cpp
std::vector<std::pair<size_t, Diagnostic>> findOverloadTieErrors(const EffectSyntax& syntax, const SourceMap& map);  // overload_ties.cpp
std::vector<std::pair<size_t, Diagnostic>> findDeclarationFormErrors(const EffectSyntax& syntax, const SourceMap& map);  // declaration_forms.cpp
std::vector<std::pair<size_t, Diagnostic>> findVectorElementWriteErrors(const EffectSyntax& syntax, const SourceMap& map);  // vector_element_writes.cpp
std::vector<std::pair<size_t, Diagnostic>> findNegativeUintConstantErrors(const EffectSyntax& syntax, const SourceMap& map);  // negative_uint_constants.cpp
std::vector<std::pair<size_t, Diagnostic>> findTexelOffsetErrors(const EffectSyntax& syntax, const SourceMap& map);  // texel_offsets.cpp
std::vector<std::pair<size_t, Diagnostic>> findTextureSubscriptErrors(const EffectSyntax& syntax, const SourceMap& map);  // texture_subscripts.cpp
std::vector<std::pair<size_t, Diagnostic>> findGroupSharedCs4Errors(const EffectSyntax& syntax, const SourceMap& map);  // group_shared_cs4.cpp
std::vector<std::pair<size_t, Diagnostic>> findStaticMixedStructErrors(const EffectSyntax& syntax, const SourceMap& map);  // static_mixed_structs.cpp

}  // namespace fxport::xlate
