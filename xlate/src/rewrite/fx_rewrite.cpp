#include "rewrite/fx_rewrite.h"

#include "rewrite/geometry_clip_inputs.h"
#include "rewrite/uniform_object_structs.h"
#include "rewrite/out_of_range_indices.h"
#include "rewrite/local_object_arrays.h"
#include "rewrite/object_array_dimensions.h"
#include "rewrite/geometry_output_stream.h"

#include "rewrite/aggregate_conversions.h"
#include "rewrite/array_sizes.h"
#include "rewrite/numthreads_sizes.h"
#include "rewrite/static_initializer_calls.h"
#include "rewrite/initializer_lists.h"
#include "rewrite/index_evaluation_order.h"
#include "rewrite/out_argument_casts.h"
#include "rewrite/length_property.h"
#include "rewrite/unused_uavs.h"
#include "rewrite/pow2_partitioning.h"
#include "rewrite/int_literal_folding.h"
#include "rewrite/refract_eta.h"
#include "rewrite/tess_factor_intrinsics.h"
#include "rewrite/compare_store.h"
#include "rewrite/byte_address_stores.h"
#include "rewrite/interlocked_values.h"
#include "rewrite/mixed_dimension_outputs.h"
#include "rewrite/switch_labels.h"
#include "rewrite/local_state_blocks.h"
#include "rewrite/negated_bool_literals.h"
#include "rewrite/unroll_limits.h"
#include "rewrite/buffer_load_locations.h"
#include "rewrite/sample_indexers.h"
#include "rewrite/qualified_casts.h"
#include "rewrite/keyword_identifiers.h"
#include "rewrite/matrix_constructor_arguments.h"
#include "rewrite/matrix_rows_intrinsics.h"
#include "rewrite/static_object_aliases.h"
#include "rewrite/static_object_structs.h"
#include "rewrite/shader_valued_defaults.h"
#include "rewrite/fxc_intrinsics.h"
#include "rewrite/matrix_majority.h"
#include "rewrite/matrix_swizzle.h"
#include "rewrite/one_component_types.h"
#include "rewrite/degenerate_matrices.h"
#include "rewrite/lvalue_casts.h"
#include "rewrite/componentwise_casts.h"
#include "rewrite/mixed_shapes.h"
#include "rewrite/array_arguments.h"
#include "rewrite/overload_choices.h"
#include "rewrite/intrinsic_overrides.h"
#include "rewrite/scalar_intrinsics.h"
#include "rewrite/ldexp_calls.h"
#include "rewrite/sign_results.h"
#include "rewrite/min_precision_types.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <set>

#include "rewrite/fxc_statements.h"
#include "rewrite/matrix_swizzle.h"
#include "fx/render_states.h"
#include "fx/source_map.h"
#include "fx/text_util.h"
#include "rewrite/intrinsic_spellings.h"
#include "rewrite/texture_registers.h"
#include "rewrite/one_row_textures.h"

namespace fxport::xlate {

TextureKind textureKindOfType(const std::string& type) {
    std::string t = toLower(type);
    if (t.find("cube") != std::string::npos) return TextureKind::TextureCube;
    if (t.find("3d") != std::string::npos) return TextureKind::Texture3D;
    if (t.find("1d") != std::string::npos) return TextureKind::Texture1D;
    return TextureKind::Texture2D;
}

namespace {

const char* dx9SamplerType(TextureKind k) {
    switch (k) {
    case TextureKind::Texture1D: return "sampler1D";
    case TextureKind::Texture2D: return "sampler2D";
    case TextureKind::Texture3D: return "sampler3D";
    case TextureKind::TextureCube: return "samplerCUBE";
    }
    return "sampler2D";
}

// The type a DX9 sampler is declared with for glslang: a 1D one reads the one-row 2D texture D3D9
// binds (one_row_textures.h).
const char* declaredDx9SamplerType(TextureKind k) { return k == TextureKind::Texture1D ? "sampler2D" : dx9SamplerType(k); }

// Which dimension a DX9 texture intrinsic implies: tex2Dlod -> 2D, texCUBEbias -> cube ...
std::optional<TextureKind> intrinsicKind(const std::string& name) {
    if (name.rfind("texCUBE", 0) == 0) return TextureKind::TextureCube;
    if (name.rfind("tex3D", 0) == 0) return TextureKind::Texture3D;
    if (name.rfind("tex2D", 0) == 0) return TextureKind::Texture2D;
    if (name.rfind("tex1D", 0) == 0) return TextureKind::Texture1D;
    return std::nullopt;
}

bool isUntypedSampler(const std::string& type) { return type == "sampler" || type == "Sampler"; }
bool isDx9Sampler(const std::string& type) {
    std::string t = toLower(type);
    return t == "sampler" || t == "sampler1d" || t == "sampler2d" || t == "sampler3d" || t == "samplercube";
}
// A type the source declares under such a name (OGRE's HLSL_SM4Support.hlsl: `#define sampler2D
// Sampler2D` and `struct Sampler2D { Texture2D t; SamplerState s; }`) is that type, not the keyword
// in another case.
bool isDx9SamplerIn(const EffectSyntax& syntax, const std::string& type) {
    return isDx9Sampler(type) && !syntax.findStruct(type) && !syntax.typedefs.count(type);
}

// Union-find over "sampler slots": global samplers and sampler-typed function parameters. Passing
// a sampler to a function joins the two slots; a texture intrinsic fixes the dimension of a set.
class SamplerSlots {
public:
    int slot(const std::string& key) {
        auto it = ids_.find(key);
        if (it != ids_.end()) return it->second;
        int id = static_cast<int>(parent_.size());
        parent_.push_back(id);
        kind_.push_back(std::nullopt);
        where_.push_back(0);
        ids_[key] = id;
        return id;
    }
    int find(int x) { return parent_[static_cast<size_t>(x)] == x ? x : parent_[static_cast<size_t>(x)] = find(parent_[static_cast<size_t>(x)]); }
    // Returns false on a contradiction.
    bool setKind(int s, TextureKind k, size_t token) {
        int r = find(s);
        auto& cur = kind_[static_cast<size_t>(r)];
        if (cur && *cur != k) return false;
        if (!cur) where_[static_cast<size_t>(r)] = token;
        cur = k;
        return true;
    }
    bool join(int a, int b) {
        a = find(a);
        b = find(b);
        if (a == b) return true;
        auto ka = kind_[static_cast<size_t>(a)], kb = kind_[static_cast<size_t>(b)];
        if (ka && kb && *ka != *kb) return false;
        parent_[static_cast<size_t>(b)] = a;
        if (!ka) {
            kind_[static_cast<size_t>(a)] = kb;
            where_[static_cast<size_t>(a)] = where_[static_cast<size_t>(b)];
        }
        return true;
    }
    std::optional<TextureKind> kind(int s) { return kind_[static_cast<size_t>(find(s))]; }
    size_t whereKindWasSet(int s) { return where_[static_cast<size_t>(find(s))]; }

private:
    std::map<std::string, int> ids_;
    std::vector<int> parent_;
    std::vector<std::optional<TextureKind>> kind_;
    std::vector<size_t> where_;
};

}  // namespace

namespace {

std::string applyEdits(const std::string& text, std::vector<TextEdit> edits) {
    // Outer edits first where two start together (`shared` blanked inside a blanked declaration);
    // an insertion (an empty range) before any edit that starts where it is inserted.
    // Stable: two insertions at one place keep the order the rewrites gave them (a closing `)`
    // of interlocked_values.h before compare_store.h's extra argument).
    std::stable_sort(edits.begin(), edits.end(), [](const TextEdit& a, const TextEdit& b) {
        if (a.begin != b.begin) return a.begin < b.begin;
        if ((a.begin == a.end) != (b.begin == b.end)) return a.begin == a.end;
        return a.end > b.end;
    });
    std::string hlsl;
    hlsl.reserve(text.size());
    size_t at = 0;
    for (auto e : edits) {
        if (e.begin < at) {
            // Nested in an earlier edit (annotations inside a blanked block): nothing left to do,
            // unless a blanking edit reaches past the earlier one; then blank the rest of it too.
            if (e.end <= at || !e.replacement.empty()) continue;
            e.begin = at;
        }
        hlsl.append(text, at, e.begin - at);
        std::string original = text.substr(e.begin, e.end - e.begin);
        // Keep the line count: the replacement goes first, then the original's newlines.
        std::string replacement = e.replacement;
        size_t replacementLen = replacement.size();
        for (size_t k = 0; k < original.size(); ++k) {
            char c = original[k];
            if (c == '\n') replacement += '\n';
            else if (k >= replacementLen) replacement += ' ';
        }
        hlsl += replacement;
        at = e.end;
    }
    hlsl.append(text, at, std::string::npos);
    return hlsl;
}

}  // namespace

std::string RewrittenEffect::hlslForGeometryShader(const std::string& entry, const std::vector<TextEdit>& extra) const {
    // Stream functions the entry calls (directly or through others: a helper that Appends for it)
    // stay; the others go.
    std::set<std::string> keep = {entry};
    for (bool grew = true; grew;) {
        grew = false;
        for (const auto& f : syntax->functions) {
            if (!keep.count(f.name)) continue;
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                const Token& t = syntax->tokens[i];
                if (t.isIdent() && syntax->tokens[i + 1].is("(") && !keep.count(t.text) && syntax->findFunction(t.text)) {
                    keep.insert(t.text);
                    grew = true;
                }
            }
        }
    }
    std::vector<TextEdit> all = edits;
    all.insert(all.end(), extra.begin(), extra.end());
    for (auto& e : geometryEntryOutputStreams(*syntax, entry)) all.push_back(std::move(e));
    for (auto& e : geometryEntryClipInputs(*syntax, entry)) all.push_back(std::move(e));
    for (const auto& f : syntax->functions) {
        if (!f.hasStreamParameter || keep.count(f.name) || f.declaration.empty()) continue;
        const Token& first = syntax->tokens[f.declaration.begin];
        const Token& last = syntax->tokens[f.declaration.end - 1];
        all.push_back({first.offset, last.end, {}});
    }
    return applyEdits(*sourceText, std::move(all));
}

RewrittenEffect rewriteEffect(const std::string& text, const EffectSyntax& syntax, const SourceMap& map,
                              std::vector<Diagnostic>& diagnostics, const std::string& defaultMajority) {
    RewrittenEffect out;
    const auto& tokens = syntax.tokens;
    auto fail = [&](const std::string& message, size_t token) {
        const Token& t = tokens[token];
        throw CompileError({map.make(Severity::Error, diag::kHlsl, message, t.line, t.column, t.text)});
    };

    // ---- 1. sampler dimensions ---------------------------------------------------------------
    SamplerSlots slots;
    struct SamplerAlias {
        std::string sampler, alias;
        TextureKind kind;
    };
    std::vector<SamplerAlias> aliases;  // a global sampler sampled with a second dimension
    std::vector<TextEdit> aliasEdits;
    for (const auto& s : syntax.samplers) {
        if (s.dx10) continue;
        out.dx9Samplers = true;
        int id = slots.slot("g:" + s.name);
        if (!isUntypedSampler(s.type)) slots.setKind(id, textureKindOfType(s.type), s.token);
    }
    auto functionKey = [](const FxFunction& f) { return f.name + "/" + std::to_string(f.parameters.size()); };
    for (const auto& f : syntax.functions)
        for (size_t i = 0; i < f.parameters.size(); ++i)
            if (isDx9SamplerIn(syntax, f.parameters[i].type)) {
                out.dx9Samplers = true;
                int id = slots.slot("p:" + functionKey(f) + ":" + std::to_string(i));
                if (!isUntypedSampler(f.parameters[i].type)) slots.setKind(id, textureKindOfType(f.parameters[i].type), f.parameters[i].typeToken);
            }
    // A sampler_state naming a typed texture (textureCUBE) fixes the sampler's dimension too.
    for (const auto& s : syntax.samplers) {
        if (s.dx10) continue;
        for (const auto& a : s.states) {
            if (!iequals(a.name, "texture")) continue;
            for (size_t i = a.value.begin; i < a.value.end; ++i)
                if (const FxTexture* t = syntax.findTexture(tokens[i].text); t && !iequals(t->type, "texture"))
                    if (!slots.setKind(slots.slot("g:" + s.name), textureKindOfType(t->type), s.token))
                        fail("sampler '" + s.name + "' is declared " + s.type + " but its texture '" + t->name + "' is a " + t->type, s.token);
        }
    }
    auto slotOfName = [&](const FxFunction& f, const std::string& name) -> std::optional<int> {
        for (size_t i = 0; i < f.parameters.size(); ++i)
            if (f.parameters[i].name == name && isDx9SamplerIn(syntax, f.parameters[i].type))
                return slots.slot("p:" + functionKey(f) + ":" + std::to_string(i));
        if (const FxSampler* s = syntax.findSampler(name); s && !s->dx10) return slots.slot("g:" + s->name);
        return std::nullopt;
    };
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 2 < f.body.end; ++i) {
            if (!tokens[i].isIdent() || !tokens[i + 1].is("(")) continue;
            // Arguments that are a bare identifier: (name , or (name ) at depth 1.
            std::vector<std::pair<size_t, std::string>> bareArgs;
            int depth = 0;
            size_t argIndex = 0, argStart = i + 2;
            for (size_t j = i + 1; j < f.body.end; ++j) {
                const Token& t = tokens[j];
                if (t.is("(") || t.is("[") || t.is("{")) {
                    ++depth;
                    continue;
                }
                if ((t.is(")") || t.is("]") || t.is("}")) && --depth == 0) {
                    if (j == argStart + 1 && tokens[argStart].isIdent()) bareArgs.push_back({argIndex, tokens[argStart].text});
                    break;
                }
                if (depth == 1 && t.is(",")) {
                    if (j == argStart + 1 && tokens[argStart].isIdent()) bareArgs.push_back({argIndex, tokens[argStart].text});
                    ++argIndex;
                    argStart = j + 1;
                }
            }
            const std::string& callee = tokens[i].text;
            if (auto k = intrinsicKind(callee)) {
                for (const auto& [index, name] : bareArgs)
                    if (index == 0)
                        if (auto s = slotOfName(f, name); s && !slots.setKind(*s, *k, i)) {
                            // fxc types a sampler per shader: a global one that functions for different
                            // shaders sample as 2D and as a cube gets a second declaration on its unit.
                            // A sampler declared with its dimension (sampler2D), or sampled both ways in
                            // one function, is an error in fxc too.
                            const std::string samplerName = name;  // clang 14 captures no structured binding
                            bool parameter = std::any_of(f.parameters.begin(), f.parameters.end(),
                                                         [&](const FxParameter& p) { return p.name == samplerName; });
                            const FxSampler* declared = syntax.findSampler(name);
                            size_t first = slots.whereKindWasSet(*s);
                            bool sameFunction = first >= f.body.begin && first < f.body.end;
                            if (parameter || !declared || !iequals(declared->type, "sampler") || sameFunction)
                                fail("sampler '" + name + "' is used as a " + std::string(dx9SamplerType(*slots.kind(*s))) +
                                         " elsewhere but with " + callee + " here; a sampler has one dimension",
                                     i);
                            std::string alias = name + "_fxport_" + dx9SamplerType(*k);
                            if (std::none_of(aliases.begin(), aliases.end(), [&](const SamplerAlias& a) { return a.alias == alias; }))
                                aliases.push_back({name, alias, *k});
                            aliasEdits.push_back({tokens[i + 2].offset, tokens[i + 2].end, alias});
                        }
                continue;
            }
            for (const auto& g : syntax.functions) {
                if (g.name != callee) continue;
                for (const auto& [index, name] : bareArgs) {
                    if (index >= g.parameters.size() || !isDx9SamplerIn(syntax, g.parameters[index].type)) continue;
                    auto s = slotOfName(f, name);
                    if (!s) continue;
                    if (!slots.join(*s, slots.slot("p:" + functionKey(g) + ":" + std::to_string(index))))
                        fail("sampler '" + name + "' is passed to parameter '" + g.parameters[index].name + "' of '" + g.name +
                                 "', which is used with a different texture dimension",
                             i);
                }
            }
        }
    }

    // ---- 2. sampler units and states ----------------------------------------------------------
    std::set<int> usedUnits;
    for (const auto& s : syntax.samplers)
        if (!s.dx10 && s.explicitUnit >= 0) usedUnits.insert(s.explicitUnit);
    StateContext stateContext{syntax, map, diagnostics};
    for (const auto& s : syntax.samplers) {
        EffectSampler es;
        es.name = s.name;
        es.dx10 = s.dx10;
        if (!s.dx10) {
            es.kind = slots.kind(slots.slot("g:" + s.name)).value_or(TextureKind::Texture2D);
            es.unit = s.explicitUnit;
            if (es.unit < 0) {
                int u = 0;
                while (usedUnits.count(u)) ++u;
                es.unit = u;
                usedUnits.insert(u);
            }
        }
        for (const auto& a : s.states) translateSamplerAssignment(a, stateContext, es.state, es.textureParameter, &es.parameterStates);
        // A comparison sampler compares even without ComparisonFunc (D3D10's default is NEVER).
        if (iequals(s.type, "SamplerComparisonState") && !es.state.comparison) es.state.comparison = CompareFunction::Never;
        out.samplers.push_back(std::move(es));
    }
    for (const auto& a : aliases)
        for (size_t i = 0; i < syntax.samplers.size(); ++i)
            if (syntax.samplers[i].name == a.sampler) {
                EffectSampler es = out.samplers[i];  // same unit, texture and states
                es.name = a.alias;
                es.kind = a.kind;
                out.samplers.push_back(std::move(es));
                break;
            }
    out.textureUnits = textureRegisters(syntax);

    // ---- 3. apply edits ------------------------------------------------------------------------
    std::vector<TextEdit> edits = syntax.edits;
    auto spanBytes = [&](TokenSpan span) {
        size_t b = tokens[span.begin].offset;
        const Token& last = tokens[span.end - 1];
        size_t e = last.end;
        return std::pair<size_t, size_t>(b, e);
    };
    for (size_t i = 0; i < syntax.samplers.size(); ++i) {
        const FxSampler& s = syntax.samplers[i];
        const EffectSampler& es = out.samplers[i];
        auto [b, e] = spanBytes(s.declaration);
        std::string decl = s.dx10 ? s.type + " " + s.name + ";"
                                  : std::string(declaredDx9SamplerType(es.kind)) + " " + s.name + " : register(s" + std::to_string(es.unit) + ");";
        for (const auto& a : aliases)
            if (a.sampler == s.name) decl += std::string(" ") + declaredDx9SamplerType(a.kind) + " " + a.alias + " : register(s" + std::to_string(es.unit) + ");";
        edits.push_back({b, e, decl});
    }
    for (const auto& f : syntax.functions)
        for (size_t i = 0; i < f.parameters.size(); ++i) {
            const FxParameter& p = f.parameters[i];
            if (!isDx9SamplerIn(syntax, p.type) || (!isUntypedSampler(p.type) && textureKindOfType(p.type) != TextureKind::Texture1D)) continue;
            auto k = slots.kind(slots.slot("p:" + functionKey(f) + ":" + std::to_string(i))).value_or(TextureKind::Texture2D);
            const Token& t = tokens[p.typeToken];
            edits.push_back({t.offset, t.end, declaredDx9SamplerType(k)});
        }
    // glslang's HLSL front end takes no `half` (nor min16float ...) as the component type of
    // vector<T, N> / matrix<T, R, C>; `half` alone it maps to float, as fxc does for SM4 (and SM2-3
    // only treat it as a precision hint), so the template argument becomes float too.
    // Nor the minimum-precision integers there, nor any minimum-precision matrix name
    // (`min16float4x4`, Windows-universal-samples; `min16int2x2`): each is its 32-bit type, as
    // glslang makes `min16float` float and as fxc stores them in constant buffers.
    for (size_t i = 0; i + 2 < tokens.size(); ++i) {
        const Token& t = tokens[i + 2];
        if ((tokens[i].text == "vector" || tokens[i].text == "matrix") && tokens[i + 1].is("<") && t.isIdent())
            if (const char* full = fullPrecisionScalar(t.text)) edits.push_back({t.offset, t.end, full});
    }
    for (const Token& t : tokens)
        if (std::string matrix = fullPrecisionMatrixName(t); !matrix.empty()) edits.push_back({t.offset, t.end, matrix});
    // `const static int N = 4;` is a constant to fxc as `static const` is; glslang keeps the last
    // storage word only, so N would be a plain static and `float w[N + 1]` no constant size.
    for (size_t i = 0; i + 1 < tokens.size(); ++i)
        if (tokens[i].text == "const" && tokens[i + 1].text == "static") edits.push_back({tokens[i].offset, tokens[i + 1].end, "static const"});
    // `const float4 f;` at global scope is a uniform the shader cannot write (fxc puts it in the
    // constant buffer); glslang makes it a constant 0. Without an initializer, `const` goes.
    std::set<std::size_t> constTokens;
    for (const FxGlobal& g : syntax.globals) {
        const bool isStatic = std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end();
        if (isStatic || !g.initializer.empty()) continue;
        for (std::size_t k = g.token; k-- > 0 && !tokens[k].is(";") && !tokens[k].is("{") && !tokens[k].is("}");)
            if (tokens[k].text == "const" && constTokens.insert(k).second) edits.push_back({tokens[k].offset, tokens[k].end, ""});
    }
    edits.insert(edits.end(), aliasEdits.begin(), aliasEdits.end());
    copyAssignedUniforms(syntax, edits);
    hoistLoopVariablesUsedAfterTheLoop(syntax, edits);
    splitConstructorAssignments(text, syntax, edits);
    for (auto& e : lowerMatrixSwizzles(tokens)) edits.push_back(std::move(e));
    for (auto& e : regroupFlatInitializers(syntax)) edits.push_back(std::move(e));
    for (auto& e : arraySizesAsLiterals(syntax)) edits.push_back(std::move(e));
    for (auto& e : threadGroupSizesAsLiterals(syntax)) edits.push_back(std::move(e));
    for (auto& e : initializerCallScopes(syntax)) edits.push_back(std::move(e));
    for (auto& e : lengthPropertiesAsCalls(syntax)) edits.push_back(std::move(e));
    for (auto& e : unusedUavsDropped(syntax)) edits.push_back(std::move(e));
    for (auto& e : refractVectorEta(syntax)) edits.push_back(std::move(e));
    for (auto& e : overflowingIntFoldsAsFxc(syntax)) edits.push_back(std::move(e));
    for (auto& e : intrinsicsAsGlslangSpellsThem(syntax)) edits.push_back(std::move(e));
    for (auto& e : pow2PartitioningAsInteger(syntax)) edits.push_back(std::move(e));
    for (auto& e : tessFactorIntrinsics(syntax)) edits.push_back(std::move(e));
    for (auto& e : interlockedValueConversions(syntax)) edits.push_back(std::move(e));  // before compare_store: see there
    for (auto& e : compareStoreAsExchange(syntax)) edits.push_back(std::move(e));
    for (auto& e : byteAddressStoreValues(syntax)) edits.push_back(std::move(e));
    for (auto& e : bufferLoadLocationsAsScalars(syntax)) edits.push_back(std::move(e));
    for (auto& e : sampleIndexersAsLoads(syntax)) edits.push_back(std::move(e));
    for (auto& e : mixedDimensionOutputs(syntax)) edits.push_back(std::move(e));
    for (auto& e : switchLabelsAsIntegers(syntax)) edits.push_back(std::move(e));
    for (auto& e : matrixConstructorArgumentsAsRows(syntax)) edits.push_back(std::move(e));
    for (auto& e : keywordIdentifiersRenamed(syntax)) edits.push_back(std::move(e));
    for (auto& e : negatedBoolLiteralsAsInts(syntax)) edits.push_back(std::move(e));
    for (auto& e : unrollLimitsAsConditions(syntax)) edits.push_back(std::move(e));
    for (auto& e : castQualifiersDropped(syntax)) edits.push_back(std::move(e));
    for (auto& e : localStateBlocksDropped(syntax)) edits.push_back(std::move(e));
    for (auto& e : matrixIntrinsicsByRow(syntax)) edits.push_back(std::move(e));
    for (auto& e : staticObjectAliases(syntax)) edits.push_back(std::move(e));
    for (auto& e : staticObjectStructs(syntax)) edits.push_back(std::move(e));
    for (auto& e : localObjectArraysResolved(syntax)) edits.push_back(std::move(e));
    for (auto& e : objectArraysFlattened(syntax)) edits.push_back(std::move(e));
    for (auto& e : shaderValuedDefaultsDropped(syntax)) edits.push_back(std::move(e));
    for (auto& e : respellOneComponentVectors(syntax)) edits.push_back(std::move(e));
    std::vector<TextEdit> vectorSwizzles;  // ahead of lowerMatrixSwizzles' edits of the same tokens (applyEdits keeps order)
    for (auto& e : degenerateMatricesAsVectors(syntax, defaultMajority, &vectorSwizzles)) edits.push_back(std::move(e));
    edits.insert(edits.begin(), vectorSwizzles.begin(), vectorSwizzles.end());
    for (auto& e : lvalueCastsAsAssignments(syntax)) edits.push_back(std::move(e));
    for (auto& e : outArgumentsThroughConversions(syntax)) edits.push_back(std::move(e));
    for (auto& e : indexBeforeBaseForCalls(syntax)) edits.push_back(std::move(e));
    for (auto& e : componentwiseCasts(syntax)) edits.push_back(std::move(e));
    for (auto& e : aggregateConversions(syntax)) edits.push_back(std::move(e));
    for (auto& e : uniformObjectStructs(syntax)) edits.push_back(std::move(e));
    for (auto& e : outOfRangeIndicesDeferred(syntax)) edits.push_back(std::move(e));
    for (auto& e : intrinsicsAsFxc(syntax)) edits.push_back(std::move(e));
    for (auto& e : scalarIntrinsicCalls(syntax)) edits.push_back(std::move(e));
    for (auto& e : signResultsAsInts(syntax)) edits.push_back(std::move(e));
    for (auto& e : ldexpAsExp2(syntax)) edits.push_back(std::move(e));
    if (out.dx9Samplers)
        for (auto& e : oneDimensionalSamplingAsRows(syntax)) edits.push_back(std::move(e));
    for (auto& e : mixedShapeConversions(syntax)) edits.push_back(std::move(e));
    for (auto& e : arrayArgumentOverloads(syntax)) edits.push_back(std::move(e));
    for (auto& e : fxcOverloadChoices(syntax)) edits.push_back(std::move(e));
    for (auto& e : intrinsicOverrides(syntax)) edits.push_back(std::move(e));
    for (auto& e : spellOutPackMatrixPragmas(syntax, defaultMajority)) edits.push_back(std::move(e));
    out.sourceText = &text;
    out.syntax = &syntax;
    out.edits = std::move(edits);
    out.hlsl = out.hlslForGeometryShader({});
    return out;
}

}  // namespace fxport::xlate
