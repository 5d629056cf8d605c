// The effect compiler's driver: preprocess -> parse effect framework -> rewrite -> per shader
// (entry wrapper -> glslang -> SPIRV-Cross) -> reflection. Each unique (stage, profile, entry,
// arguments) is compiled once per effect, however many passes use it.
#include "fxport/xlate/effect_compiler.h"

#include <nlohmann/json.hpp>

#include <csignal>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <functional>
#include <mutex>
#include <new>
#include <tuple>

#include "d3d9asm/asm_pass_bindings.h"
#include "fx/constant_eval.h"
#include "d3d9asm/d3d9_asm.h"
#include "effect/effect_cache.h"
#include "effect/d3d_registers.h"
#include "checks/effect_profile_rules.h"
#include "fxport/xlate/effect_file.h"
#include "entry/entry_wrapper.h"
#include "rewrite/tessellation_clip_semantics.h"
#include "rewrite/fx_rewrite.h"
#include "rewrite/degenerate_matrices.h"
#include "hlsl/variable_declarations.h"
#include "fx/parameter_selector.h"
#include "frontend/front_end_hazards.h"
#include "checks/fxc_checks.h"
#include "frontend/front_end_worker.h"
#include "fx/fx_syntax.h"
#include "frontend/hlsl_to_spirv.h"
#include "checks/implicit_conversions.h"
#include "fx/input_limits.h"
#include "effect/loose_shaders.h"
#include "fx/preprocess.h"
#include "rewrite/cbuffer_objects.h"
#include "rewrite/uniform_resource_parameters.h"
#include "rewrite/struct_definitions.h"
#include "rewrite/unused_sampler_arrays.h"
#include "rewrite/sampler_array_elements.h"
#include "rewrite/sampler_textures.h"
#include "rewrite/attribute_case.h"
#include "rewrite/builtin_type_typedefs.h"
#include "rewrite/keyword_case.h"
#include "rewrite/rasterizer_ordered_views.h"
#include "rewrite/literal_suffixes.h"
#include "fx/render_states.h"
#include "fx/shader_profile.h"
#include "spirv/spirv_sizes.h"
#include "glsl/spirv_to_glsl.h"
#include "entry/patch_constant_wrapper.h"
#include "entry/stage_attributes.h"
#include "rewrite/numthreads_sizes.h"
#include "fx/text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

const char* compilerVersion() { return "fxport-xlate-44"; }  // 3: asm { } blocks translate; 4: compute, hull, domain; 5: D3D resource registers; 6: one-row/one-column matrices as vectors, lhs and componentwise casts, scalar intrinsics; 7: mixed shapes, fxc signature layout, geometry entries, struct inheritance, more fxc rejections; 8: D3D integer fix-ups, out-argument wrappers, clip-distance packing, serialised varyings, typed buffers, constant-expression sizes, component-wise casts; 9: cbuffers at D3D offsets (packoffset, register(cN), register arrays); 10: D3D9 fixed-function variants, tight structured buffers, sampler-array elements, integer matrices, fetch offsets, negated comparisons, pow2 partitioning and ProcessTessFactors, split-array semantics; 11: live SM1-3 constant ranges, zero-initialised statics, fxc string escapes, nested struct reflection; 12: objects in cbuffers moved out, constant-array sizes, SV_Coverage input, struct-parameter interpolation modifiers; 13: ByteAddressBuffer sizes in bytes, packed GS clip/cull inputs, per-sample input evaluation, no fxport_Internal block; 14: fxc's overload choices, Interlocked float values, vector-to-array casts, statics in cbuffers, VS without position, sampler states from parameters, keyword spellings; 15: fxc's t#/s# registers and array elements in sampler bindings; 16: int literal folding as fxc, half-only overloads, SM2-3 lvalue casts with swizzles; 17: stream-output declarations (ConstructGSWithSO), SetPixelShader(NULL); 18: SM1-3 sampler registers (combined samplers), D3D9 pass texture stages for HLSL pixel shaders; 19: pass texture stages kept for later passes; 20: one-row/one-column matrix uniforms in register arrays; 21: DX9 1D sampling on one-row 2D textures; 22: GatherCmpGreen/Blue/Alpha; 23: earlydepthstencil on the wrapper, conservative depth outputs; 24: impossible ## pastes, empty cbuffer declarations; 25: scoped local constants, implicit-size uniform arrays, numthreads constant expressions, struct conversions; 26: matrix operators per component

namespace {

const char* stageName(ShaderStage s) {
    switch (s) {
    case ShaderStage::Vertex: return "vertex";
    case ShaderStage::Pixel: return "pixel";
    case ShaderStage::Geometry: return "geometry";
    case ShaderStage::Hull: return "hull";
    case ShaderStage::Domain: return "domain";
    case ShaderStage::Compute: return "compute";
    }
    return "?";
}

ParameterType scalarType(const std::string& scalar) {
    if (scalar == "bool") return ParameterType::Bool;
    if (scalar == "int" || scalar == "min16int" || scalar == "min12int") return ParameterType::Int;
    if (scalar == "uint" || scalar == "dword" || scalar == "min16uint") return ParameterType::UInt;
    return ParameterType::Float;
}

ParameterType objectType(const std::string& type) {
    std::string t = toLower(type.substr(0, type.find('<')));
    if (t == "texture") return ParameterType::Texture;
    if (t == "texture1d") return ParameterType::Texture1D;
    if (t == "texture2d" || t == "texture2darray" || t == "texture2dms") return ParameterType::Texture2D;
    if (t == "texture3d") return ParameterType::Texture3D;
    if (t == "texturecube" || t == "texturecubearray") return ParameterType::TextureCube;
    if (t == "sampler") return ParameterType::Sampler;
    if (t == "sampler1d") return ParameterType::Sampler1D;
    if (t == "sampler2d") return ParameterType::Sampler2D;
    if (t == "sampler3d") return ParameterType::Sampler3D;
    if (t == "samplercube") return ParameterType::SamplerCube;
    if (t == "samplerstate" || t == "samplercomparisonstate") return ParameterType::SamplerState;
    return ParameterType::Void;
}

// RWStructuredBuffer<T>, StructuredBuffer<T>, (RW)ByteAddressBuffer, RWTexture2D<T> ...: bound by
// register through GraphicsDevice::SetUnorderedAccess / SetShaderResource, not parameters.
bool isStorageType(const std::string& type) {
    std::string t = toLower(type.substr(0, type.find('<')));
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t.rfind("rw", 0) == 0 || t == "structuredbuffer" || t == "byteaddressbuffer" || t == "appendstructuredbuffer" ||
           t == "consumestructuredbuffer" || t.rfind("rasterizerordered", 0) == 0;
}

struct ShaderKey {
    ShaderStage stage;
    std::string profile, entry, arguments;
    bool nextToGeometryShader;
    bool operator<(const ShaderKey& o) const {
        return std::tie(stage, profile, entry, arguments, nextToGeometryShader) <
               std::tie(o.stage, o.profile, o.entry, o.arguments, o.nextToGeometryShader);
    }
    // One line naming the shader, for the worker's progress records.
    std::string text() const {
        return std::to_string(static_cast<int>(stage)) + "|" + profile + "|" + entry + "|" + arguments + "|" + (nextToGeometryShader ? "g" : "");
    }
};

// Shaders whose compile took the front-end worker down (ShaderKey::text() -> the diagnostic that
// says so): a later attempt skips them and compiles the rest of the effect.
using FailedShaders = std::map<std::string, Diagnostic>;

// A front-end request that owns its source (HlslToSpirvRequest points at the builder's), and
// the text that tells requests apart.
struct OwnedRequest {
    std::string source;
    HlslToSpirvRequest request;
    static std::string joinedNames(const std::vector<std::string>& names) {
        std::string joined;
        for (const auto& n : names) joined += n + ",";
        return joined;
    }
    static std::string keyOf(const HlslToSpirvRequest& r) {
        return std::to_string(static_cast<int>(r.stage)) + "|" + r.entryPoint + "|" + (r.dx9Compatible ? "9" : "") + "|" +
               std::to_string(r.shaderModel) + "|" + r.hullPartitioning + "|" + joinedNames(r.rasterizerOrderedViews) + "|" + *r.source;
    }
};

// What the prefetch found for each request: the module, or how its worker failed.
struct Prefetched {
    std::map<std::string, SpirvModule> modules;
    std::map<std::string, WorkerOutcome> failures;
};

class EffectBuilder {
public:
    EffectBuilder(const PreprocessedEffect& pre, const EffectSyntax& syntax, RewrittenEffect& rewritten,
                  const CompileOptions& options, CompiledEffect& effect, VaryingLocations* sharedVaryings,
                  const FailedShaders& failedShaders)
        : pre_(pre), syntax_(syntax), rewritten_(rewritten), options_(options), effect_(effect), failedShaders_(failedShaders),
          varyings_(sharedVaryings ? *sharedVaryings : ownVaryings_) {
        baseLines_ = static_cast<int>(std::count(rewritten.hlsl.begin(), rewritten.hlsl.end(), '\n')) + 1;
    }

    void buildParameters();
    // `s`'s members into `p.members`, a member of struct type with its own members (any depth).
    void describeStructMembers(const FxStruct& s, Parameter& p, size_t token, int depth);
    void checkMemberCounts() const;
    void checkStatementCount() const;
    struct PackedMember {
        int begin = 0, end = 0;  // floats from the cbuffer's start, [begin, end)
        std::string name;
        size_t token = 0;
    };
    void checkPackOffsets(std::vector<PackedMember> packed);
    bool cbufferRead(const std::string& cbuffer) const;
    void buildTechniques();
    void finishReflection();
    void checkTessellationPass(Pass& pass, size_t token);
    // Shaders compiled in parallel (prefetchFrontEnd below): a pass that only lists the front-end
    // requests the build would make, and the results of those requests computed ahead.
    void collectRequestsInto(std::map<std::string, OwnedRequest>* requests) { collecting_ = requests; }
    void usePrefetched(const Prefetched* results) { prefetched_ = results; }

private:
    const PreprocessedEffect& pre_;
    const EffectSyntax& syntax_;
    RewrittenEffect& rewritten_;  // asm shaders add their texture stages' samplers
    const CompileOptions& options_;
    CompiledEffect& effect_;
    const FailedShaders& failedShaders_;
    int baseLines_ = 0;
    std::map<ShaderKey, int> compiled_;  // -> index in effect_.shaders, -1 = failed
    std::map<int, GlslShader> reflections_;
    VaryingLocations ownVaryings_;
    VaryingLocations& varyings_;  // custom semantics' locations: this effect's, or shared by loose files
    bool passHasGeometryShader_ = false;  // of the pass being built
    Tessellation passHull_;               // of the pass being built: its hull shader's attributes (domain shaders take them)
    void findPassHull(const FxPass& pass);
    AsmPassBindings passAsm_;             // of the pass being built: what its asm shaders' registers hold
    int asmFunctions_ = 0;
    std::map<std::string, OwnedRequest>* collecting_ = nullptr;
    const Prefetched* prefetched_ = nullptr;
    SpirvModule frontEnd(const HlslToSpirvRequest& request);
    std::string effectText(ShaderStage stage, const std::string& entry, std::vector<TextEdit> extra = {}) const;

    Diagnostic at(Severity s, const char* id, const std::string& message, size_t token) const {
        const Token& t = syntax_.tokens[std::min(token, syntax_.tokens.size() - 1)];
        return pre_.map.make(s, id, message, t.line, t.column, t.kind == Token::Kind::End ? std::string() : t.text);
    }
    void error(const char* id, const std::string& message, size_t token) {
        effect_.diagnostics.push_back(at(Severity::Error, id, message, token));
    }

    int compileShader(const FxShaderExpr& expr, ShaderStage expected, size_t blameToken);
    bool threadGroupSizesEvaluate(const FxFunction& entry, const ShaderProfile& profile);
    int compileAsmShader(const FxShaderExpr& expr, ShaderStage expected);
    bool isAsmShader(const FxShaderExpr& expr) const;
    // glslang + SPIRV-Cross + reflection of one shader; `source` is the whole HLSL to compile.
    int emitShader(const ShaderKey& key, const ShaderProfile& profile, const FxShaderExpr& expr, const std::string& displayEntry,
                   const std::string& arguments, const std::string& source, const std::string& entryName,
                   const EntryWrapper& wrapper, bool dx9Compatible);
    bool resolveShader(const FxShaderExpr& expr, ShaderStage stage, ShaderChoice& choice, size_t blameToken);
    bool resolveStreamOutShader(const FxShaderExpr& expr, ShaderChoice& choice, size_t blameToken);
    bool readStreamOutput(const FxShaderExpr& expr, const CompiledShader& shader, StreamOutput& so);
    std::optional<ShaderStage> stageOf(const FxShaderExpr& expr) const;
    bool foldNullGeometryShader(Pass& pass, size_t token);
    void applyPassSamplerStages(ShaderChoice& pixel, const std::map<int, PassSamplerStage>& stages, std::vector<TextureStage>& unsampled);
    // Pixel shaders with a pass's sampler stages: (the shader, the stages' text) -> the copy.
    std::map<std::pair<int, std::string>, int> stageCopies_;
    // Shaders made by ConstructGSWithSO: (the shader streamed, its declaration) -> the copy with it,
    // and each copy's shader.
    std::map<std::pair<int, std::string>, int> streamCopies_;
    std::map<int, int> streamBase_;
    void reportOversized(const OversizedVariable& over, size_t blameToken);
    bool buildSelector(TokenSpan span, std::vector<SelectorOp>& ops, size_t blameToken);
    int parameterIndex(const std::string& name) const {
        for (size_t i = 0; i < effect_.parameters.size(); ++i)
            if (effect_.parameters[i].name == name) return static_cast<int>(i);
        return -1;
    }
};

namespace {

// The floats a constant occupies from its first register's first component under D3D's cbuffer
// packing: each array element and each matrix row (row_major) or column (column_major) starts a
// register. A struct gives 0: not checked.
int floatsSpanned(const Parameter& p) {
    if (p.parameterClass == ParameterClass::Struct || p.parameterClass == ParameterClass::Object) return 0;
    int registers = 1, last = p.columns;
    if (p.parameterClass == ParameterClass::Matrix) {
        registers = p.rowMajor ? p.rows : p.columns;
        last = p.rowMajor ? p.columns : p.rows;
    }
    int element = (registers - 1) * 4 + last;
    return p.elements > 1 ? (p.elements - 1) * 4 * registers + element : element;
}

std::string registerName(int floats) { return "c" + std::to_string(floats / 4) + "." + "xyzw"[floats % 4]; }

}  // namespace

// Whether a function names a member of the cbuffer (fxc checks packoffset overlaps only then).
bool EffectBuilder::cbufferRead(const std::string& cbuffer) const {
    std::set<std::string> members;
    for (const auto& g : syntax_.globals)
        if (g.cbuffer == cbuffer) members.insert(g.name);
    for (const auto& f : syntax_.functions)
        for (size_t i = f.body.begin; i < f.body.end; ++i)
            if (syntax_.tokens[i].isIdent() && members.count(syntax_.tokens[i].text)) return true;
    return false;
}

// fxc's X4019: two cbuffer members placed over the same components. glslang takes the offsets as
// given and the reflected ranges come out negative; report it where the later one is declared.
void EffectBuilder::checkPackOffsets(std::vector<PackedMember> packed) {
    std::sort(packed.begin(), packed.end(), [](const PackedMember& a, const PackedMember& b) { return a.begin < b.begin; });
    for (size_t i = 1; i < packed.size(); ++i) {
        const PackedMember& prev = packed[i - 1];
        if (packed[i].begin < prev.end)
            error(diag::kHlsl, "packoffset(" + registerName(packed[i].begin) + ") of '" + packed[i].name + "' overlaps '" + prev.name +
                                   "', which fills " + registerName(prev.begin) + " to " + registerName(prev.end - 1),
                  packed[i].token);
    }
}

// A SPIR-V instruction has at most 65535 words, so a struct (a cbuffer is one) of more members than
// that comes out of glslang as an invalid module (raw validator lines on stderr, then FX2101 for
// every shader, after seconds). D3D's 4096-register cbuffers hold at most 16384 scalars: refused
// here, at the member past the limit, before any shader compiles.
void EffectBuilder::checkMemberCounts() const {
    auto refuse = [&](const std::string& what, size_t token) {
        throw CompileError({at(Severity::Error, diag::kTooManyMembers,
                               what + " has more than " + std::to_string(limits::kMaxMembers) + " members, the most fxport accepts in one", token)});
    };
    std::map<std::string, size_t> perBuffer;
    for (const auto& g : syntax_.globals) {
        if (std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end()) continue;
        if (++perBuffer[g.cbuffer] > limits::kMaxMembers) refuse(g.cbuffer.empty() ? std::string("the global constant buffer ($Global)") : "cbuffer '" + g.cbuffer + "'", g.token);
    }
    for (const auto& s : syntax_.structs)
        if (s.members.size() > limits::kMaxMembers) refuse("struct '" + s.name + "'", s.token);
}

// glslang, spirv-opt and SPIRV-Cross take time and memory in proportion to the code (and spirv-opt's
// inlining multiplies it): 150 000 statements took a minute and 1.1 GB. Counted as the `;` of the
// function bodies, refused at the one past the limit before any shader compiles.
void EffectBuilder::checkStatementCount() const {
    size_t statements = 0;
    for (const auto& f : syntax_.functions)
        for (size_t i = f.body.begin; i < f.body.end; ++i)
            if (syntax_.tokens[i].is(";") && ++statements > limits::kMaxStatements)
                throw CompileError({at(Severity::Error, diag::kTooManyStatements,
                                       "the functions have more than " + std::to_string(limits::kMaxStatements) +
                                           " statements, the most fxport compiles in one effect",
                                       i)});
}

void EffectBuilder::describeStructMembers(const FxStruct& s, Parameter& p, size_t token, int depth) {
    p.parameterClass = ParameterClass::Struct;
    p.type = ParameterType::Void;
    if (depth > 32) return;  // HLSL structs cannot contain themselves; a broken source is refused elsewhere
    for (const auto& m : s.members) {
        Parameter mp;
        mp.name = m.name;
        mp.elements = m.arrayDims.empty() ? 0 : int(arrayElementCount(m.arrayDims));  // float a[2][3]: 6, as D3D reflects it
        if (long long n = arrayElementCount(m.arrayDims); n > limits::kMaxArrayElements)
            error(diag::kArrayTooLarge, "member '" + m.name + "' of struct '" + s.name + "' has " + std::to_string(n) +
                                            " elements; fxport accepts at most " + std::to_string(limits::kMaxArrayElements) + " in one array",
                  token);
        if (const FxStruct* inner = syntax_.findStruct(syntax_.resolveType(m.type))) {
            describeStructMembers(*inner, mp, token, depth + 1);
        } else {
            auto b = describeBasicType(syntax_.resolveType(m.type));
            mp.parameterClass = b.isMatrix ? ParameterClass::Matrix : b.columns > 1 ? ParameterClass::Vector : ParameterClass::Scalar;
            mp.type = scalarType(b.scalar);
            mp.rows = b.rows;
            mp.columns = b.columns;
        }
        p.members.push_back(mp);
    }
}

void EffectBuilder::buildParameters() {
    checkMemberCounts();
    checkStatementCount();
    struct Item {
        size_t token;
        Parameter p;
    };
    std::vector<Item> items;
    std::map<std::string, std::vector<PackedMember>> packed;  // per cbuffer, members placed with packoffset
    std::map<std::string, std::vector<double>> constants;  // earlier globals, for initializers like `= A * 2`
    for (const auto& g : syntax_.globals) {
        // groupshared: a compute shader's thread-group memory, no constant.
        if (std::find(g.modifiers.begin(), g.modifiers.end(), "groupshared") != g.modifiers.end()) continue;
        bool isStatic = std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end();
        Parameter p;
        p.name = g.name;
        p.semantic = toUpper(g.semantic);
        p.annotations = g.annotations;
        p.isStatic = isStatic;
        p.declaredAt = pre_.map.locate(syntax_.tokens[g.token].line, syntax_.tokens[g.token].column, g.name);
        p.elements = g.arrayDims.empty() ? 0 : int(arrayElementCount(g.arrayDims));  // float a[2][3]: 6, as D3D reflects it
        if (long long n = arrayElementCount(g.arrayDims); n > limits::kMaxArrayElements) {
            error(diag::kArrayTooLarge, "array '" + g.name + "' has " + std::to_string(n) + " elements; fxport accepts at most " +
                                            std::to_string(limits::kMaxArrayElements) + " in one array",
                  g.token);
            continue;
        }
        p.rowMajor = std::find(g.modifiers.begin(), g.modifiers.end(), "row_major") != g.modifiers.end();
        if (g.isStringParameter) {
            p.parameterClass = ParameterClass::Object;
            p.type = ParameterType::String;
            if (!g.initializer.empty() && syntax_.tokens[g.initializer.begin].kind == Token::Kind::String)
                p.defaultString = syntax_.tokens[g.initializer.begin].text;
        } else if (const FxStruct* s = syntax_.findStruct(syntax_.resolveType(g.type))) {
            describeStructMembers(*s, p, g.token, 0);
        } else {
            auto b = describeBasicType(syntax_.resolveType(g.type));
            if (!b.ok && isStorageType(g.type)) continue;  // a UAV or buffer SRV: reflected per shader (CompiledShader::storage)
            if (!b.ok) {
                effect_.diagnostics.push_back(at(Severity::Warning, diag::kSyntax,
                                                 "global '" + g.name + "' has type '" + g.type + "', which fxport does not expose as a parameter", g.token));
                continue;
            }
            p.parameterClass = b.isMatrix ? ParameterClass::Matrix : b.columns > 1 ? ParameterClass::Vector : ParameterClass::Scalar;
            p.type = scalarType(b.scalar);
            p.rows = b.rows;
            p.columns = b.columns;
            if (!g.initializer.empty()) {
                bool tooDeep = false;
                auto v = evaluateConstant(syntax_, g.initializer, constants, &tooDeep);
                if (tooDeep)
                    error(diag::kNestingTooDeep, "the initializer of '" + g.name + "' nests more than " + std::to_string(limits::kMaxNesting) +
                                                     " levels deep, the most fxport evaluates", g.token);
                if (v) {
                    size_t want = static_cast<size_t>(b.rows * b.columns * std::max(1, p.elements));
                    if (v->size() == 1 && want > 1) v->assign(want, (*v)[0]);  // `float4 c = 0;`
                    bool dimsKnown = std::all_of(g.arrayDims.begin(), g.arrayDims.end(), [](int d) { return d > 0; });
                    size_t holds = static_cast<size_t>(b.rows * b.columns) * static_cast<size_t>(arrayElementCount(g.arrayDims));
                    if (dimsKnown && v->size() > holds) {  // fxc rejects `float2 t = {1, 2, 3, 4};` (glslang may not)
                        error(diag::kHlsl, "the initializer of '" + g.name + "' gives " + std::to_string(v->size()) + " values; its type '" +
                                               g.type + "' holds " + std::to_string(holds),
                              g.token);
                        continue;
                    }
                    p.defaultValue = *v;
                    constants[g.name] = *v;
                }
            }
        }
        if (isStatic) continue;  // statics are not parameters in XNA (and not in $Global)
        if (!g.cbuffer.empty()) {
            auto it = std::find(syntax_.cbuffers.begin(), syntax_.cbuffers.end(), g.cbuffer);
            p.block = 1 + static_cast<int>(it - syntax_.cbuffers.begin());
        }
        if (g.packOffset >= 0 && !g.cbuffer.empty()) packed[g.cbuffer].push_back({g.packOffset, g.packOffset + floatsSpanned(p), g.name, g.token});
        items.push_back({g.token, std::move(p)});
    }
    for (auto& [cbuffer, members] : packed)
        if (cbufferRead(cbuffer)) checkPackOffsets(std::move(members));  // fxc lets an unread cbuffer's members overlap
    for (const auto& t : syntax_.textures) {
        Parameter p;
        p.name = t.name;
        p.semantic = toUpper(t.semantic);
        p.parameterClass = ParameterClass::Object;
        p.type = objectType(t.type);
        p.annotations = t.annotations;
        p.declaredAt = pre_.map.locate(syntax_.tokens[t.token].line, syntax_.tokens[t.token].column, t.name);
        items.push_back({t.token, std::move(p)});
    }
    for (size_t i = 0; i < syntax_.samplers.size(); ++i) {
        const FxSampler& s = syntax_.samplers[i];
        Parameter p;
        p.name = s.name;
        p.parameterClass = ParameterClass::Object;
        p.type = s.dx10 ? ParameterType::SamplerState : objectType(std::string("sampler") + (rewritten_.samplers[i].kind == TextureKind::TextureCube ? "CUBE"
                                                                                             : rewritten_.samplers[i].kind == TextureKind::Texture3D ? "3D"
                                                                                             : rewritten_.samplers[i].kind == TextureKind::Texture1D ? "1D" : "2D"));
        p.declaredAt = pre_.map.locate(syntax_.tokens[s.token].line, syntax_.tokens[s.token].column, s.name);
        items.push_back({s.token, std::move(p)});
    }
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.token < b.token; });
    for (auto& it : items) effect_.parameters.push_back(std::move(it.p));
    // Texture parameters named by a sampler_state must exist.
    for (const auto& s : rewritten_.samplers)
        if (!s.textureParameter.empty() && parameterIndex(s.textureParameter) < 0)
            if (const FxSampler* fs = syntax_.findSampler(s.name))
                error(diag::kBadStateValue, "sampler '" + s.name + "' uses texture '" + s.textureParameter + "', which is not declared", fs->token);
}

bool EffectBuilder::buildSelector(TokenSpan span, std::vector<SelectorOp>& ops, size_t blameToken) {
    auto problem = appendSelector(syntax_.tokens, span, [&](const std::string& name) { return parameterIndex(name); }, ops);
    if (!problem) return true;
    error(problem->unsupported ? diag::kUnsupported : diag::kUnknownShader, "shader index: " + problem->message, blameToken);
    return false;
}

// Each [numthreads] size is an integer constant fxport evaluates (numthreads_sizes.h); otherwise
// the error is at that size's file:line.
bool EffectBuilder::threadGroupSizesEvaluate(const FxFunction& entry, const ShaderProfile& profile) {
    for (const ThreadGroupSize& size : threadGroupSizes(syntax_, entry))
        if (!size.problem.empty()) {
            error(diag::kBadEntrySignature, "'" + entry.name + "' (" + profile.name + ") [numthreads]: " + size.problem, size.span.begin);
            return false;
        }
    return true;
}

int EffectBuilder::compileShader(const FxShaderExpr& expr, ShaderStage expected, size_t /*blameToken*/) {
    auto profile = parseShaderProfile(expr.profile);
    if (!profile) {
        std::string p = toLower(expr.profile);
        bool profileLike = p.size() > 3 && p[2] == '_' && p[1] == 's' && std::string("vpghdc").find(p[0]) != std::string::npos;
        if (!profileLike) {
            // An identifier the preprocessor left alone: a macro nobody defined. Effect hosts
            // (Lightworks' PROFILE, BF2's LOWPSMODEL) define such profile macros themselves.
            const char* example = expected == ShaderStage::Vertex ? "vs_3_0" : expected == ShaderStage::Pixel ? "ps_3_0"
                                   : expected == ShaderStage::Hull ? "hs_5_0" : expected == ShaderStage::Domain ? "ds_5_0"
                                   : expected == ShaderStage::Compute ? "cs_5_0" : "gs_4_0";
            error(diag::kBadProfile, "'" + expr.profile + "' is not a shader profile, and no macro '" + expr.profile +
                                         "' is defined; if the application that hosts this effect defines it, define it too (-D " +
                                         expr.profile + "=" + example + ")",
                  expr.token + 1);
            return -1;
        }
        error(diag::kBadProfile, "'" + expr.profile + "' is not a shader profile fxport knows (vs_1_1..vs_5_0, ps_2_0..ps_5_0, gs_4_0..gs_5_0, cs_4_0..cs_5_0, hs_5_0, ds_5_0)", expr.token + 1);
        return -1;
    }
    if (profile->stage != expected) {
        error(diag::kBadProfile, "profile '" + expr.profile + "' compiles a " + stageName(profile->stage) + " shader, but it is assigned to a " +
                                     stageName(expected) + " shader",
              expr.token + 1);
        return -1;
    }
    ShaderKey key{expected, toLower(expr.profile), expr.entry, expr.arguments, passHasGeometryShader_};
    // A domain shader's GLSL carries its hull shader's partitioning and topology: one per pairing.
    if (expected == ShaderStage::Domain) key.arguments += "\x01" + passHull_.partitioning + "," + passHull_.outputTopology;
    if (auto it = compiled_.find(key); it != compiled_.end()) return it->second;
    compiled_[key] = -1;

    const FxFunction* entry = syntax_.findEntry(expr.entry, expr.arguments);
    if (!entry) {
        error(diag::kMissingEntry, "entry point '" + expr.entry + "' is not a function of this effect", expr.token);
        return -1;
    }
    std::string entryName = expr.entry;
    if (expected == ShaderStage::Hull || expected == ShaderStage::Domain || expected == ShaderStage::Compute) {
        Tessellation unused;
        if (std::string why = checkStageAttributes(syntax_, *entry, *profile, unused); !why.empty()) {
            error(diag::kBadEntrySignature, why, entry->token);
            return -1;
        }
        if (expected == ShaderStage::Compute && !threadGroupSizesEvaluate(*entry, *profile)) return -1;
    }
    // Vertex and pixel shaders get a wrapper that maps D3D9 semantics; the D3D10+ stages are
    // compiled as written.
    bool wrapped = expected == ShaderStage::Vertex || expected == ShaderStage::Pixel;
    EntryWrapper wrapper;
    if (wrapped) {
        wrapper = buildEntryWrapper(syntax_, *entry, *profile, expr.arguments, passHasGeometryShader_);
        if (!wrapper.error.empty()) {
            error(diag::kBadEntrySignature, wrapper.error, entry->token);
            return -1;
        }
        entryName = kWrapperEntry;
    }
    std::string source;
    if (!options_.skipShaders) {
        source = effectText(expected, expr.entry);
        if (wrapped) source += wrapper.code;
        if (expected == ShaderStage::Hull) {
            Tessellation t;
            checkStageAttributes(syntax_, *entry, *profile, t);
            // fxc (SM 5) takes the last definition of an overloaded patch-constant function.
            const FxFunction* constants = nullptr;
            for (const auto& f : syntax_.functions)
                if (f.name == t.patchConstantFunction) constants = &f;
            if (auto passThrough = passThroughHullEntry(*entry, constants)) {
                source += passThrough->code;
                entryName = passThrough->name;
            }
            if (auto pcf = constants ? patchConstantWrapper(*constants) : std::nullopt) {
                source = redirectPatchConstantFunction(source, constants->name, pcf->name) + pcf->code;
            }
        }
    }
    return emitShader(key, *profile, expr, expr.entry, expr.arguments, source, entryName, wrapper, rewritten_.dx9Samplers);
}

bool EffectBuilder::isAsmShader(const FxShaderExpr& expr) const {
    if (expr.kind == FxShaderExpr::Kind::Asm) return true;
    if (expr.kind != FxShaderExpr::Kind::Variable && expr.kind != FxShaderExpr::Kind::ArrayElement) return false;
    for (const auto& v : syntax_.shaderVariables)
        if (v.name == expr.variable)
            for (const auto& e : v.elements)
                if (e.kind == FxShaderExpr::Kind::Asm) return true;
    return false;
}

// The hook for shader assembly: translate the block to an HLSL function (d3d9_asm.h) with the
// registers the pass binds, then compile it like any entry point.
int EffectBuilder::compileAsmShader(const FxShaderExpr& expr, ShaderStage expected) {
    if (expr.asmBlock.empty()) {
        error(diag::kSyntax, "'asm' must be followed by the shader assembly in braces: asm { ps_1_1 ... }", expr.token);
        return -1;
    }
    const Token& open = syntax_.tokens[expr.asmBlock.begin];
    const Token& close = syntax_.tokens[expr.asmBlock.end - 1];
    std::string text = pre_.text.substr(open.end, close.offset - open.end);
    AsmProgram program;
    if (!parseAsmProgram(text, open.line, expected, pre_.map, effect_.diagnostics, program)) return -1;
    const bool vertex = expected == ShaderStage::Vertex;
    std::string signature = vertex ? passAsm_.vertexSignature : passAsm_.pixelSignature;
    if (!vertex)
        for (const auto& [n, stage] : passAsm_.stages) signature += "s" + std::to_string(n) + ":" + stage.signature;
    // Shown as the entry point (dumps, `fxport dump`): where the block is.
    std::string displayEntry = "asm_line" + std::to_string(pre_.map.locate(program.versionLine).line);
    ShaderKey key{expected, toLower(program.profile.name), displayEntry + "@" + std::to_string(expr.asmBlock.begin), signature,
                  passHasGeometryShader_};
    if (auto it = compiled_.find(key); it != compiled_.end()) return it->second;
    compiled_[key] = -1;
    std::string function = "fxport_asm" + std::to_string(asmFunctions_++);
    TranslatedAsm translated = translateAsmProgram(program, function, vertex ? passAsm_.vertex : passAsm_.pixel, pre_.map, effect_.diagnostics);
    if (!translated.ok) return -1;
    for (const auto& [n, kind] : translated.samplers) {
        EffectSampler es;
        es.name = asmSamplerName(function, n);
        es.kind = kind;
        es.unit = n;  // D3D9 texture stage n is GraphicsDevice.Textures[n]
        if (auto it = passAsm_.stages.find(n); it != passAsm_.stages.end()) {
            es.textureParameter = it->second.textureParameter;
            es.state = it->second.state;
        }
        rewritten_.samplers.push_back(std::move(es));
    }
    EntryWrapper wrapper = buildEntryWrapper(syntax_, translated.entry, program.profile, {}, passHasGeometryShader_);
    if (!wrapper.error.empty()) {
        error(diag::kBadEntrySignature, wrapper.error, expr.token);
        return -1;
    }
    std::string source;
    if (!options_.skipShaders) source = rewritten_.hlsl + translated.code + wrapper.code;
    FxShaderExpr shown = expr;
    shown.entry = displayEntry;
    shown.profile = program.profile.name;
    return emitShader(key, program.profile, shown, displayEntry, signature, source, kWrapperEntry, wrapper,
                      rewritten_.dx9Samplers || !translated.samplers.empty());
}

// The effect's HLSL for compiling `entry` at `stage`, with `extra` edits. A stage compiled as
// written (geometry, hull, domain, compute: no entry wrapper) loses the entry's prototypes: glslang
// names its own entry function like the HLSL one and resolves a call through `void main();` to
// itself ("Recursion detected"), or takes the prototype as the entry ("No function definition");
// nothing can call an entry point, so no prototype is needed (numthreads L111, L208).
std::string EffectBuilder::effectText(ShaderStage stage, const std::string& entry, std::vector<TextEdit> extra) const {
    const bool asWritten = stage != ShaderStage::Vertex && stage != ShaderStage::Pixel;
    const auto& t = syntax_.tokens;
    if (asWritten)
        for (const FxFunction& f : syntax_.functions)
            if (f.name == entry)
                for (const TokenSpan& p : f.prototypes) extra.push_back({t[p.begin].offset, t[p.end - 1].end, {}});
    if (stage == ShaderStage::Hull || stage == ShaderStage::Domain)
        for (TextEdit& e : tessellationClipSemantics(syntax_)) extra.push_back(std::move(e));
    if (extra.empty() && stage != ShaderStage::Geometry) return rewritten_.hlsl;
    return rewritten_.hlslForGeometryShader(stage == ShaderStage::Geometry ? entry : std::string(), extra);
}

// hlslToSpirv(), or what the prefetch computed for the same request, or (collecting) nothing: the
// request is recorded and the shader fails, which the collecting pass throws away.
SpirvModule EffectBuilder::frontEnd(const HlslToSpirvRequest& request) {
    if (collecting_) {
        std::string key = OwnedRequest::keyOf(request);
        if (!collecting_->count(key)) {
            OwnedRequest& owned = (*collecting_)[key];
            owned.source = *request.source;
            owned.request = request;
            owned.request.source = &owned.source;
        }
        SpirvModule none;
        none.errors.push_back({0, "", "(collected)", false});
        return none;
    }
    if (prefetched_) {
        std::string key = OwnedRequest::keyOf(request);
        if (auto it = prefetched_->modules.find(key); it != prefetched_->modules.end()) return it->second;
        // Its worker failed: this worker fails the same way here, where the progress record names
        // the shader (emitShader), without running glslang on it again.
        if (auto it = prefetched_->failures.find(key); it != prefetched_->failures.end()) {
            if (it->second.kind == WorkerOutcome::Kind::OutOfMemory) throw std::bad_alloc();
            int sig = it->second.kind == WorkerOutcome::Kind::TimedOut ? SIGXCPU : it->second.signal ? it->second.signal : SIGABRT;
            ::signal(sig, SIG_DFL);
            ::raise(sig);
        }
    }
    return hlslToSpirv(request);
}

int EffectBuilder::emitShader(const ShaderKey& key, const ShaderProfile& profile, const FxShaderExpr& expr, const std::string& displayEntry,
                              const std::string& arguments, const std::string& source, const std::string& entryName,
                              const EntryWrapper& wrapper, bool dx9Compatible) {
    const ShaderStage expected = profile.stage;
    if (options_.skipShaders) {  // the outline: which entry point, not its code
        CompiledShader shader;
        shader.profile = profile;
        shader.entryPoint = displayEntry;
        shader.arguments = arguments;
        shader.needsD3D9PixelOffset = wrapper.usesPixelOffset;
        int index = static_cast<int>(effect_.shaders.size());
        effect_.shaders.push_back(std::move(shader));
        compiled_[key] = index;
        return index;
    }
    if (auto failed = failedShaders_.find(key.text()); failed != failedShaders_.end()) {
        effect_.diagnostics.push_back(failed->second);
        return -1;
    }
    // Where a crash inside glslang would be reported: the entry point, as fxc names the shader (an
    // asm block: where it is written).
    const FxFunction* entryFunction = syntax_.findEntry(expr.entry, expr.arguments);
    const Token& entryToken = syntax_.tokens[entryFunction ? entryFunction->token : std::min(expr.token, syntax_.tokens.size() - 1)];
    SourceLocation entryAt = pre_.map.locate(entryToken.line, entryToken.column, entryFunction ? entryFunction->name : displayEntry);
    reportWorkerProgress("shader\t" + key.text() + "\t" + displayEntry + "\t" + profile.name + "\t" + entryAt.file + "\t" +
                         std::to_string(entryAt.line) + "\t" + std::to_string(entryAt.column));
    std::string current = source;  // replaced when overloads are added below
    HlslToSpirvRequest request;
    request.source = &current;
    request.stage = expected;
    request.entryPoint = entryName;
    request.dx9Compatible = dx9Compatible;
    request.shaderModel = profile.major;
    // A hull or domain shader's attributes, read once: the front end needs the partitioning, the
    // compiled shader all of them (their errors were reported before the shader was reached).
    Tessellation stageAttributes;
    const bool tessellationStage = (expected == ShaderStage::Hull || expected == ShaderStage::Domain) && entryFunction;
    if (tessellationStage) checkStageAttributes(syntax_, *entryFunction, profile, stageAttributes);
    if (expected == ShaderStage::Hull) request.hullPartitioning = stageAttributes.partitioning;
    if (expected == ShaderStage::Pixel) request.rasterizerOrderedViews = syntax_.rasterizerOrderedViews;
    SpirvModule spirv = frontEnd(request);
    // A vector passed to a scalar parameter of the effect's own function: fxc uses .x (warning
    // X3206), glslang finds no overload. Compile again with overloads that take vectors there
    // (glslang stops at the first such call, so as often as new functions turn up).
    std::set<std::string> unmatched;
    std::vector<HlslError> conversionCalls;  // the calls glslang rejected, for the warnings
    auto collect = [&](const SpirvModule& m) {
        bool grew = false;
        for (const auto& e : m.errors)
            if (e.message.find("no matching overloaded function") != std::string::npos && syntax_.findFunction(e.token)) {
                grew |= unmatched.insert(e.token).second;
                conversionCalls.push_back(e);
            }
        return grew;
    };
    // The effect's part of the source (what follows it: the entry wrapper, translated asm) is kept.
    const std::string base = effectText(expected, expr.entry);
    const bool retryable = source.compare(0, base.size(), base) == 0;
    for (int round = 0; retryable && round < 16 && collect(spirv); ++round) {
        std::vector<TextEdit> overloads = vectorToScalarOverloads(syntax_, unmatched);
        std::string retried = effectText(expected, expr.entry, overloads);
        retried += source.substr(base.size());
        request.source = &retried;
        SpirvModule next = frontEnd(request);
        if (!next.errors.empty() && next.errors.front().message.find("no matching overloaded function") == std::string::npos) break;
        spirv = std::move(next);
        current = std::move(retried);
        request.source = &current;
    }
    if (!conversionCalls.empty() && spirv.errors.empty()) {
        for (const auto& e : conversionCalls) {
            Diagnostic d = pre_.map.make(Severity::Warning, diag::kImplicitConversion,
                                         std::string(kTruncationWarning) + ": a vector argument of '" + e.token +
                                             "' is passed to a scalar parameter; its first component is used",
                                         e.line, 0, e.token + "(");
            bool known = false;  // already said, with the types, by findImplicitTruncations
            for (const auto& w : effect_.diagnostics) known |= w.id == d.id && w.location.file == d.location.file && w.location.line == d.location.line;
            if (!known) effect_.diagnostics.push_back(std::move(d));
        }
    }
    if (!spirv.errors.empty()) {
        for (const auto& e : spirv.errors) {
            if (e.aboutTheEntryPoint && entryFunction) {
                effect_.diagnostics.push_back(pre_.map.make(Severity::Error, diag::kHlsl, "'" + entryFunction->name + "' (" + expr.profile + "): " + e.message,
                                                            entryToken.line, entryToken.column, entryFunction->name));
            } else if (e.line > 0 && e.line <= baseLines_) {
                effect_.diagnostics.push_back(pre_.map.make(Severity::Error, diag::kHlsl, e.message, e.line, 0, e.token));
            } else {
                error(diag::kHlsl, "in the generated entry point for '" + expr.entry + "' (" + expr.profile + "): " + e.message, expr.token);
            }
        }
        return -1;
    }
    if (auto over = findOversizedVariable(spirv.words)) {
        reportOversized(*over, expr.token);
        return -1;
    }
    GlslShader glsl = spirvToGlsl(std::move(spirv.words), expected, rewritten_, varyings_,
                                  expected == ShaderStage::Domain ? &passHull_ : nullptr);
    if (!glsl.error.empty()) {
        error(diag::kSpirv, "SPIRV-Cross could not translate '" + expr.entry + "': " + glsl.error, expr.token);
        return -1;
    }
    if (!glsl.unsupported.empty()) {
        error(diag::kUnsupported, "'" + expr.entry + "' (" + expr.profile + ") cannot run on GL: " + glsl.unsupported, expr.token);
        return -1;
    }
    CompiledShader shader;
    shader.profile = profile;
    shader.entryPoint = displayEntry;
    shader.arguments = arguments;
    shader.glsl = glsl.glsl;
    shader.inputs = glsl.inputs;
    shader.samplers = glsl.samplers;
    if (profile.major >= 4) {
        std::vector<int> bufferRegisters;
        for (const StorageBinding& b : glsl.storage)
            if (b.registerClass == 't') bufferRegisters.push_back(b.slot);
        assignD3dRegisters(shader.samplers, glsl.samplerFirstUse, syntax_, bufferRegisters, profile);
    } else {
        assignD3d9SamplerRegisters(shader.samplers, syntax_, profile);
    }
    shader.uniformRangesRead = glsl.rangesRead;
    shader.uniformRangesLive = glsl.rangesLive;
    shader.outputTargets = glsl.outputTargets;
    shader.writesDepth = glsl.writesDepth;
    shader.clipDistances = glsl.clipDistances;
    shader.varyingInputs = glsl.varyingInputs;
    shader.varyingOutputs = glsl.varyingOutputs;
    shader.outputs = glsl.outputs;
    shader.outputPrimitiveVertices = glsl.outputPrimitiveVertices;
    shader.needsD3D9PixelOffset = wrapper.usesPixelOffset;
    shader.storage = glsl.storage;
    shader.threadGroupSize = glsl.threadGroupSize;
    if (expected == ShaderStage::Compute) {
        if (std::string why = checkThreadGroupSize(shader.threadGroupSize, profile); !why.empty()) {
            effect_.diagnostics.push_back(pre_.map.make(Severity::Error, diag::kBadEntrySignature, "'" + displayEntry + "' (" + expr.profile + "): " + why,
                                                        entryToken.line, entryToken.column, displayEntry));
            return -1;
        }
    }
    if (tessellationStage) shader.tessellation = stageAttributes;
    if (options_.keepRewrittenHlsl) shader.hlslAfterRewrite = current;
    for (const auto& name : glsl.membersRead) {
        int p = parameterIndex(name);
        if (p >= 0 && std::find(shader.parametersRead.begin(), shader.parametersRead.end(), p) == shader.parametersRead.end())
            shader.parametersRead.push_back(p);
    }
    for (const auto& s : glsl.samplers) {
        for (const std::string& name : {s.textureParameter, s.samplerName}) {
            int p = name.empty() ? -1 : parameterIndex(name);
            if (p >= 0 && std::find(shader.parametersRead.begin(), shader.parametersRead.end(), p) == shader.parametersRead.end())
                shader.parametersRead.push_back(p);
        }
    }
    std::sort(shader.parametersRead.begin(), shader.parametersRead.end());
    int index = static_cast<int>(effect_.shaders.size());
    effect_.shaders.push_back(std::move(shader));
    reflections_[index] = std::move(glsl);
    compiled_[key] = index;
    return index;
}

// FX1204 at the declaration of the variable SPIR-V names: a global, else the first `Type name[`
// in the source (a local or a static), else the shader's assignment.
void EffectBuilder::reportOversized(const OversizedVariable& over, size_t blameToken) {
    size_t token = blameToken;
    bool found = false;
    for (const auto& g : syntax_.globals)
        if (!found && g.name == over.name) token = g.token, found = true;
    // `Type name[`: by the name, or (a local SPIR-V left unnamed) by the array's length.
    for (size_t i = 1; !found && i + 2 < syntax_.tokens.size(); ++i) {
        const Token& t = syntax_.tokens[i];
        if (!t.isIdent() || !syntax_.tokens[i + 1].is("[") || !syntax_.tokens[i - 1].isIdent()) continue;
        if (over.name.empty() ? over.length > 0 && syntax_.tokens[i + 2].text == std::to_string(over.length) : t.text == over.name)
            token = i, found = true;
    }
    auto count = [](std::uint64_t n) { return n >= (std::uint64_t{1} << 62) ? std::string("more than 2^62") : std::to_string(n); };
    const std::string limit = "fxport accepts at most " + std::to_string(limits::kMaxVariableBytes >> 20) + " MiB and " +
                              std::to_string(limits::kMaxArrayElements) + " array elements in one variable";
    if (!over.block.empty())
        error(diag::kArrayTooLarge, "constant buffer '" + over.block + "' takes " + count(over.bytes) + " bytes (its largest member is '" + over.name +
                                        "'); fxport accepts at most " + std::to_string(limits::kMaxVariableBytes >> 20) + " MiB in one constant buffer",
              token);
    else
        error(diag::kArrayTooLarge, (!over.name.empty() ? "'" + over.name + "'" : found ? "'" + syntax_.tokens[token].text + "'" : std::string("a local array")) + " takes " + count(over.bytes) + " bytes (" +
                                        count(over.elements) + " array elements in all, nested arrays multiplied); " + limit,
              token);
}

bool EffectBuilder::resolveShader(const FxShaderExpr& expr, ShaderStage stage, ShaderChoice& choice, size_t blameToken) {
    switch (expr.kind) {
    case FxShaderExpr::Kind::Null:
        choice = {};
        return true;
    case FxShaderExpr::Kind::Compile: {
        int s = compileShader(expr, stage, blameToken);
        if (s < 0) return false;
        choice.shaders = {s};
        return true;
    }
    case FxShaderExpr::Kind::Asm: {
        int s = compileAsmShader(expr, stage);
        if (s < 0) return false;
        choice.shaders = {s};
        return true;
    }
    case FxShaderExpr::Kind::StreamOut:
        if (stage != ShaderStage::Geometry) {
            error(diag::kBadProfile, std::string("ConstructGSWithSO makes a geometry shader, but it is assigned to a ") + stageName(stage) + " shader", expr.token);
            return false;
        }
        return resolveStreamOutShader(expr, choice, blameToken);
    case FxShaderExpr::Kind::Variable:
    case FxShaderExpr::Kind::ArrayElement: {
        const FxShaderVariable* var = nullptr;
        for (const auto& v : syntax_.shaderVariables)
            if (v.name == expr.variable) var = &v;
        if (!var) {
            error(diag::kUnknownShader, "'" + expr.variable + "' is not a shader variable of this effect", expr.token);
            return false;
        }
        if ((expr.kind == FxShaderExpr::Kind::ArrayElement) != var->isArray) {
            error(diag::kUnknownShader, var->isArray ? "shader array '" + var->name + "' needs an index" : "'" + var->name + "' is not an array", expr.token);
            return false;
        }
        choice.shaders.clear();
        for (const auto& element : var->elements) {
            ShaderChoice one;
            if (!resolveShader(element, stage, one, blameToken)) return false;
            if (one.shaders.size() > 1) {
                error(diag::kUnsupported, "nested shader arrays are not supported", expr.token);
                return false;
            }
            choice.shaders.push_back(one.shaders.empty() ? -1 : one.shaders[0]);
        }
        if (expr.kind == FxShaderExpr::Kind::ArrayElement) return buildSelector(expr.index, choice.selector, expr.token);
        return true;
    }
    case FxShaderExpr::Kind::Invalid: break;
    }
    error(diag::kSyntax, "cannot understand this shader assignment (expected compile <profile> <entry>(...), a shader variable, or NULL)", blameToken);
    return false;
}

void EffectBuilder::buildTechniques() {
    StateContext stateContext{syntax_, pre_.map, effect_.diagnostics, &effect_.parameters};
    // Sampler states read from parameters (`MinFilter = <Filter>;`), now that the parameters are
    // known; the shaders' sampler bindings carry them.
    for (auto& es : rewritten_.samplers) {
        es.stateParameters.clear();
        for (const auto& a : es.parameterStates)
            if (SamplerStateParameter p; resolveSamplerStateParameter(a, stateContext, p)) es.stateParameters.push_back(p);
    }
    for (const auto& t : syntax_.techniques) {
        if (!options_.techniques.empty() &&
            std::find(options_.techniques.begin(), options_.techniques.end(), t.name) == options_.techniques.end())
            continue;
        Technique tech;
        tech.name = t.name;
        tech.annotations = t.annotations;
        tech.declaredAt = pre_.map.locate(syntax_.tokens[t.token].line, syntax_.tokens[t.token].column);
        for (const auto& p : t.passes) {
            Pass pass;
            pass.name = p.name;
            pass.annotations = p.annotations;
            pass.declaredAt = pre_.map.locate(syntax_.tokens[p.token].line, syntax_.tokens[p.token].column);
            bool fixedFunction = false;
            passHasGeometryShader_ = options_.besideGeometryOrDomainShader;
            findPassHull(p);
            for (const auto& a : p.assignments) {
                std::string n = toLower(a.name);
                // A domain shader, like a geometry shader, takes the vertex shader's outputs (through
                // the hull shader) and feeds the pixel shader: both sides keep their declared types.
                if ((n == "geometryshader" || n == "setgeometryshader" || n == "domainshader" || n == "setdomainshader") &&
                    parseShaderExpr(syntax_, a.value).kind != FxShaderExpr::Kind::Null)
                    passHasGeometryShader_ = true;
            }
            bool vertexIsAsm = false, pixelIsAsm = false, setsPixelShader = false;
            for (const auto& a : p.assignments) {
                std::string n = toLower(a.name);
                if (n != "vertexshader" && n != "pixelshader") continue;
                (n == "vertexshader" ? vertexIsAsm : pixelIsAsm) |= isAsmShader(parseShaderExpr(syntax_, a.value));
                setsPixelShader |= n == "pixelshader";
            }
            std::vector<bool> consumedByAsm;
            size_t errorsBefore = effect_.diagnostics.size();
            passAsm_ = collectAsmPassBindings(p, vertexIsAsm, pixelIsAsm, rewritten_, stateContext, consumedByAsm);
            std::map<int, PassSamplerStage> samplerStages;
            if (setsPixelShader && !pixelIsAsm) samplerStages = collectPassSamplerStages(p, rewritten_, stateContext, consumedByAsm);
            for (size_t d = errorsBefore; d < effect_.diagnostics.size(); ++d)
                if (effect_.diagnostics[d].severity == Severity::Error) pass.valid = false;
            for (size_t ai = 0; ai < p.assignments.size(); ++ai) {
                const FxAssignment& a = p.assignments[ai];
                if (consumedByAsm[ai]) continue;
                StateResult r = translatePassAssignment(a, stateContext, pass.states);
                if (r == StateResult::Failed) pass.valid = false;
                if (r == StateResult::Ignored) fixedFunction = true;
                if (r != StateResult::NotAState) continue;
                std::string n = toLower(a.name);
                ShaderStage stage = n.find("vertex") != std::string::npos    ? ShaderStage::Vertex
                                    : n.find("pixel") != std::string::npos   ? ShaderStage::Pixel
                                    : n.find("hull") != std::string::npos    ? ShaderStage::Hull
                                    : n.find("domain") != std::string::npos  ? ShaderStage::Domain
                                    : n.find("compute") != std::string::npos ? ShaderStage::Compute
                                                                             : ShaderStage::Geometry;
                FxShaderExpr e = parseShaderExpr(syntax_, a.value);
                if (e.kind == FxShaderExpr::Kind::Invalid && !a.value.empty() && iequals(syntax_.tokens[a.value.begin].text, "decl")) {
                    error(diag::kUnsupported, "DirectX 8 vertex declarations (VertexShader = decl { ... } asm { ... }) are not supported: "
                                              "declare the inputs with dcl_position v0 ... inside the asm block (vs_1_1)", a.nameToken);
                    pass.valid = false;
                    continue;
                }
                if (e.kind == FxShaderExpr::Kind::Invalid) e.token = a.nameToken;
                ShaderChoice& target = stage == ShaderStage::Vertex    ? pass.vertexShader
                                       : stage == ShaderStage::Pixel   ? pass.pixelShader
                                       : stage == ShaderStage::Hull    ? pass.hullShader
                                       : stage == ShaderStage::Domain  ? pass.domainShader
                                       : stage == ShaderStage::Compute ? pass.computeShader
                                                                       : pass.geometryShader;
                if (!resolveShader(e, stage, target, a.nameToken)) pass.valid = false;
                if (stage == ShaderStage::Pixel && a.isCall) pass.nullPixelShader = e.kind == FxShaderExpr::Kind::Null;
            }
            if (t.name != kLooseTechnique) checkTessellationPass(pass, p.token);
            if (pass.valid && !foldNullGeometryShader(pass, p.token)) pass.valid = false;
            if (!samplerStages.empty()) applyPassSamplerStages(pass.pixelShader, samplerStages, pass.textureStages);
            const bool anyShader = !pass.vertexShader.shaders.empty() || !pass.pixelShader.shaders.empty() || !pass.computeShader.shaders.empty() ||
                                   !pass.geometryShader.shaders.empty() || !pass.hullShader.shaders.empty() || !pass.domainShader.shaders.empty();
            if (pass.valid && !anyShader) {
                // A state-only pass (restoring states) is fine to Apply(); one that relies on the
                // fixed-function pipeline (Lighting, TextureStage states ...) cannot draw anything.
                if (fixedFunction) {
                    error(diag::kUnsupported, "pass '" + p.name + "' uses the fixed-function pipeline (no shaders), which is not supported", p.token);
                    pass.valid = false;
                } else {
                    effect_.diagnostics.push_back(at(Severity::Warning, diag::kUnsupported,
                                                     "pass '" + p.name + "' has no shaders: Apply() sets its render states, but drawing with it needs shaders",
                                                     p.token));
                }
            }
            tech.passes.push_back(std::move(pass));
        }
        effect_.techniques.push_back(std::move(tech));
    }
}

// The D3D9 texture stage (s# register) that sampler binding `b` reads: fxc's register where the
// reflection has one, else (SM 1-3) its unit, which XNA's Textures[] index is.
static int textureStageOf(const SamplerBinding& b, const ShaderProfile& profile) {
    if (b.samplerRegister >= 0) return b.samplerRegister;
    return profile.major < 4 ? b.unit : -1;
}

// D3D9 pass states for texture stages (`Texture[0] = <T>; MagFilter[0] = Linear;`) reach an HLSL
// pixel shader's sampler at register s<n> (D3D9 sets the stage, whatever samples it): each pixel
// shader the pass may run becomes a copy whose sampler there takes the stage's texture and, over
// its own sampler_state, the states the pass names. A stage no pixel shader of the pass samples
// goes to Pass::textureStages: Apply() sets the device's stage, which later passes may sample.
void EffectBuilder::applyPassSamplerStages(ShaderChoice& pixel, const std::map<int, PassSamplerStage>& stages, std::vector<TextureStage>& unsampled) {
    std::string key;
    for (const auto& [n, s] : stages) key += std::to_string(n) + "{" + s.stage.signature + "}";
    std::set<int> sampled;
    for (int& index : pixel.shaders) {
        if (index < 0) continue;
        auto [it, made] = stageCopies_.try_emplace({index, key}, static_cast<int>(effect_.shaders.size()));
        if (made) {
            CompiledShader copy = effect_.shaders[static_cast<size_t>(index)];
            for (SamplerBinding& b : copy.samplers) {
                const int reg = textureStageOf(b, copy.profile);
                auto stage = stages.find(reg);
                if (reg < 0 || stage == stages.end()) continue;
                const AsmTextureStage& s = stage->second.stage;
                if (!s.textureParameter.empty()) b.textureParameter = s.textureParameter;
                overlaySamplerState(b.state, s.state);
            }
            effect_.shaders.push_back(std::move(copy));
            if (auto r = reflections_.find(index); r != reflections_.end()) reflections_[it->second] = r->second;
        }
        index = it->second;
        for (const SamplerBinding& b : effect_.shaders[static_cast<size_t>(index)].samplers)
            sampled.insert(textureStageOf(b, effect_.shaders[static_cast<size_t>(index)].profile));
    }
    for (const auto& [n, s] : stages)
        if (!sampled.count(n)) unsampled.push_back({n, s.stage.textureParameter, s.stage.state});
}

// The stage `expr` compiles for (what ConstructGSWithSO wraps): by its profile, through shader variables.
std::optional<ShaderStage> EffectBuilder::stageOf(const FxShaderExpr& expr) const {
    if (expr.kind == FxShaderExpr::Kind::Compile) {
        auto profile = parseShaderProfile(expr.profile);
        return profile ? std::optional(profile->stage) : std::nullopt;
    }
    if (expr.kind != FxShaderExpr::Kind::Variable) return std::nullopt;
    for (const auto& v : syntax_.shaderVariables)
        if (v.name == expr.variable && !v.isArray && v.elements.size() == 1) return stageOf(v.elements[0]);
    return std::nullopt;
}

// ConstructGSWithSO(shader, declaration...): a copy of the shader (a geometry shader, or a vertex
// shader: D3D's "null" geometry shader that streams the vertex shader's outputs) that carries the
// declaration, resolved against its outputs.
bool EffectBuilder::resolveStreamOutShader(const FxShaderExpr& expr, ShaderChoice& choice, size_t blameToken) {
    FxShaderExpr inner = parseShaderExpr(syntax_, expr.streamShader);
    if (inner.kind == FxShaderExpr::Kind::Invalid) inner.token = expr.token;
    const ShaderStage stage = stageOf(inner).value_or(ShaderStage::Geometry);
    if (stage != ShaderStage::Vertex && stage != ShaderStage::Geometry) {
        error(diag::kBadProfile, std::string("ConstructGSWithSO streams a geometry or a vertex shader, not a ") + stageName(stage) + " shader", inner.token);
        return false;
    }
    ShaderChoice streamed;
    if (!resolveShader(inner, stage, streamed, blameToken)) return false;
    if (streamed.shaders.size() != 1 || streamed.shaders[0] < 0 || !streamed.selector.empty()) {
        error(diag::kUnsupported, "ConstructGSWithSO of NULL or of a shader array is not supported", inner.token);
        return false;
    }
    const int base = streamed.shaders[0];
    StreamOutput so;
    if (!readStreamOutput(expr, effect_.shaders[static_cast<size_t>(base)], so)) return false;
    std::string key = std::to_string(so.rasterizedStream);
    for (const auto& e : so.entries)
        key += ";" + std::to_string(e.stream) + ":" + std::to_string(e.outputSlot) + ":" + e.semanticName + ":" + std::to_string(e.semanticIndex) + ":" +
               std::to_string(e.startComponent) + ":" + std::to_string(e.componentCount);
    auto [it, made] = streamCopies_.try_emplace({base, key}, static_cast<int>(effect_.shaders.size()));
    if (made) {
        CompiledShader copy = effect_.shaders[static_cast<size_t>(base)];
        copy.streamOutput = so;
        effect_.shaders.push_back(std::move(copy));
        if (auto r = reflections_.find(base); r != reflections_.end()) reflections_[it->second] = r->second;
        streamBase_[it->second] = base;
    }
    choice = {};
    choice.shaders = {it->second};
    return true;
}

// The declaration strings (and, in the Effects 11 form, the rasterized stream) of `expr`.
bool EffectBuilder::readStreamOutput(const FxShaderExpr& expr, const CompiledShader& shader, StreamOutput& so) {
    const auto& args = expr.streamArguments;
    if (args.size() != 1 && args.size() != 5) return false;  // fxc's argument count: checks/effect_object_values.cpp
    for (size_t k = 0; k < std::min<size_t>(args.size(), 4); ++k) {
        const Token& first = syntax_.tokens[args[k].begin];
        if (args[k].end == args[k].begin + 1 && (iequals(first.text, "NULL") || first.text == "0") && first.kind != Token::Kind::String) continue;
        if (args[k].end != args[k].begin + 1 || first.kind != Token::Kind::String) {
            error(diag::kBadStreamOutput, "a stream-output declaration is a string (\"POSITION.xyz; TEXCOORD0.xy\") or NULL", args[k].begin);
            return false;
        }
        std::string why;
        if (!parseStreamOutputDeclaration(first.text, static_cast<int>(k), so.entries, why)) {
            error(diag::kBadStreamOutput, "ConstructGSWithSO: " + why, args[k].begin);
            return false;
        }
    }
    if (args.size() == 5) {
        std::string number = syntax_.text(args[4]);
        number.erase(std::remove_if(number.begin(), number.end(), [](unsigned char c) { return std::isspace(c); }), number.end());
        char* end = nullptr;
        long value = std::strtol(number.c_str(), &end, 0);
        if (number.empty() || *end != '\0') {
            error(diag::kBadStreamOutput, "ConstructGSWithSO: the rasterized stream '" + number + "' is not a number (0 to 3, or -1 for none)", args[4].begin);
            return false;
        }
        so.rasterizedStream = value == 0xFFFFFFFFL ? kNoRasterizedStream : static_cast<int>(value);
    }
    if (options_.skipShaders) return true;  // an outline compiles no shader: there are no outputs to resolve against
    std::string why;
    if (!resolveStreamOutput(shader.outputs, so, why)) {
        error(diag::kBadStreamOutput, "ConstructGSWithSO('" + shader.entryPoint + "'): " + why, args.empty() ? expr.token : args[0].begin);
        return false;
    }
    return true;
}

// A pass whose geometry shader streams its vertex shader's outputs (ConstructGSWithSO of a vertex
// shader) runs that vertex shader with the stream output and no geometry shader, as GL captures a
// vertex shader's outputs itself.
bool EffectBuilder::foldNullGeometryShader(Pass& pass, size_t token) {
    if (pass.geometryShader.shaders.size() != 1 || pass.geometryShader.shaders[0] < 0) return true;
    const int gs = pass.geometryShader.shaders[0];
    if (effect_.shaders[static_cast<size_t>(gs)].profile.stage != ShaderStage::Vertex) return true;
    const int streamed = streamBase_.count(gs) ? streamBase_.at(gs) : -1;
    if (pass.vertexShader.shaders.size() != 1 || !pass.vertexShader.selector.empty() || pass.vertexShader.shaders[0] != streamed) {
        error(diag::kUnsupported, "pass '" + pass.name + "' streams the outputs of a vertex shader (ConstructGSWithSO) other than its own vertex shader", token);
        return false;
    }
    pass.vertexShader.shaders = {gs};
    pass.geometryShader = {};
    return true;
}

// The attributes of the hull shader `pass` compiles (SetHullShader(CompileShader(hs_5_0, HS()))),
// else those the options give for loose files; a hull shader chosen from a shader variable or
// array gives none (GL's defaults: equal spacing, counter-clockwise).
void EffectBuilder::findPassHull(const FxPass& pass) {
    passHull_ = options_.hullOfDomainShader;
    for (const auto& a : pass.assignments) {
        std::string n = toLower(a.name);
        if (n != "hullshader" && n != "sethullshader") continue;
        FxShaderExpr e = parseShaderExpr(syntax_, a.value);
        if (e.kind != FxShaderExpr::Kind::Compile) continue;
        auto profile = parseShaderProfile(e.profile);
        const FxFunction* entry = syntax_.findEntry(e.entry, e.arguments);
        if (!profile || profile->stage != ShaderStage::Hull || !entry) continue;
        Tessellation t;
        if (checkStageAttributes(syntax_, *entry, *profile, t).empty()) passHull_ = t;
    }
}

// D3D11 runs a hull shader only with a domain shader and the other way round; a pass with one of
// them alone could never draw.
void EffectBuilder::checkTessellationPass(Pass& pass, size_t token) {
    bool hull = !pass.hullShader.shaders.empty(), domain = !pass.domainShader.shaders.empty();
    if (!pass.valid || hull == domain) return;
    error(diag::kBadEntrySignature, "pass '" + pass.name + "' sets a " + (hull ? "hull shader but no domain shader" : "domain shader but no hull shader") +
                                        "; tessellation needs both", token);
    pass.valid = false;
}

namespace {

// A struct parameter's members at their offsets in the block (those of element 0 of an array of
// structs; element i is arrayStride further), so they can be set one by one.
void placeStructMembers(Parameter& param, const UniformMember& layout) {
    const bool byPosition = param.members.size() == layout.members.size();  // names may repeat (struct b : a shadowing)
    for (size_t k = 0; k < param.members.size(); ++k)
        for (size_t j = 0; j < layout.members.size(); ++j) {
            Parameter& member = param.members[k];
            const UniformMember& u = layout.members[j];
            if (byPosition ? j != k : u.name != member.name) continue;
            member.block = param.block;
            member.offset = param.offset + u.offset;
            member.size = u.size;
            member.matrixStride = u.matrixStride;
            member.arrayStride = u.arrayStride;
            if (member.parameterClass == ParameterClass::Matrix) member.rowMajor = u.hlslRowMajor;
            placeStructMembers(member, u);
            break;
        }
}

// A one-row or one-column matrix uniform lives in an array of registers (degenerate_matrices.h):
// the block reflects the array, the parameter is still the matrix, one register per column
// (column_major) or row (row_major).
void placeVectorUniform(Parameter& param, const EffectSyntax& syntax, const std::string& defaultMajority) {
    if (param.parameterClass != ParameterClass::Matrix || param.elements != 0) return;
    for (const auto& g : syntax.globals) {
        if (g.name != param.name || !isVectorUniform(syntax, g)) continue;
        param.rowMajor = vectorUniformStorage(syntax, g, defaultMajority).rowMajor;
        param.matrixStride = 16;
        param.arrayStride = 0;
        return;
    }
}

}  // namespace

void EffectBuilder::finishReflection() {
    // Block list: $Global, then every user cbuffer in declaration order (bindings as spirv_to_glsl
    // assigns them). All shaders compile the same rewritten source, so each block has one layout;
    // take it from the first shader that declares the block and check the others agree. A block no
    // shader reads keeps size 0 (its parameters keep offset -1).
    effect_.uniformBlocks.clear();
    effect_.uniformBlocks.push_back({"$Global", 0, 0});
    for (size_t k = 0; k < syntax_.cbuffers.size(); ++k)
        effect_.uniformBlocks.push_back({syntax_.cbuffers[k], static_cast<int>(2 + k), 0});
    // D3D's registers as declared, for the D3D11 front end's b#/t#/s# slots.
    effect_.resources.clear();
    using RK = ResourceDeclaration::Kind;
    for (size_t k = 0; k < syntax_.cbuffers.size(); ++k)
        effect_.resources.push_back({RK::ConstantBuffer, syntax_.cbuffers[k], syntax_.cbufferRegisters[k]});
    for (const auto& t : syntax_.textures)
        if (!t.dx9Object) effect_.resources.push_back({RK::Texture, t.name, t.explicitUnit});
    for (const auto& s : syntax_.samplers)
        if (s.dx10) effect_.resources.push_back({RK::Sampler, s.name, s.explicitUnit});
    std::map<int, const UniformBlockLayout*> layouts;
    for (const auto& [index, g] : reflections_) {
        for (const auto& block : g.blocks) {
            auto [it, inserted] = layouts.emplace(block.index, &block);
            if (inserted) continue;
            const UniformBlockLayout& first = *it->second;
            bool same = block.size == first.size && block.members.size() == first.members.size();
            for (size_t i = 0; same && i < block.members.size(); ++i)
                same = block.members[i].name == first.members[i].name && block.members[i].offset == first.members[i].offset &&
                       block.d3dPacking == first.d3dPacking;
            if (!same) error(diag::kSpirv, "shaders of this effect disagree on the layout of constant buffer '" + block.name + "' (internal error)", 0);
        }
    }
    for (const auto& [index, layout] : layouts) {
        if (index < 0 || static_cast<size_t>(index) >= effect_.uniformBlocks.size()) continue;
        effect_.uniformBlocks[static_cast<size_t>(index)].size = layout->size;
        effect_.uniformBlocks[static_cast<size_t>(index)].d3dPacking = layout->d3dPacking;
        for (const auto& m : layout->members) {
            int p = parameterIndex(m.name);
            if (p < 0) continue;
            Parameter& param = effect_.parameters[static_cast<size_t>(p)];
            param.block = index;
            param.offset = m.offset;
            param.size = m.size;
            param.matrixStride = m.matrixStride;
            param.arrayStride = m.arrayStride;
            if (param.parameterClass == ParameterClass::Matrix) param.rowMajor = m.hlslRowMajor;
            placeVectorUniform(param, syntax_, options_.defaultMatrixMajority);
            placeStructMembers(param, m);
        }
    }
    effect_.uniformBufferSize = effect_.uniformBlocks[0].size;
}

// The cache key: everything a compile reads except the include files, which the entry lists with
// their content hashes (see effect_cache.h). Fields are length-prefixed, so no two different
// inputs concatenate to the same text. The whole text: the cache names and seals the entry with a
// keyed hash of it.
std::string cacheKey(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                     const CompileOptions& options) {
    std::error_code ec;
    std::string key;
    key.reserve(source.size() + 256);
    auto field = [&](std::string_view tag, std::string_view value) {
        key += tag;
        key += std::to_string(value.size());
        key += ':';
        key += value;
    };
    field("V", compilerVersion());
    field("P", displayPath);
    // Includes resolve beside the effect and in the include folders: where those are matters.
    field("A", fs::weakly_canonical(fs::absolute(absolutePath, ec), ec).string());
    for (const auto& dir : options.includeDirs) {
        field("I", dir);
        field("i", fs::weakly_canonical(fs::absolute(dir, ec), ec).string());
    }
    if (!options.includeRoot.empty()) field("R", fs::weakly_canonical(fs::absolute(options.includeRoot, ec), ec).string());
    for (const auto& [name, value] : options.defines) {
        field("D", name);
        field("d", value);
    }
    for (const auto& t : options.techniques) field("T", t);
    field("K", options.keepValidPasses ? "1" : "0");
    if (options.besideGeometryOrDomainShader) field("G", "1");
    if (!options.effectProfile.empty()) field("F", options.effectProfile);
    if (!options.hullOfDomainShader.partitioning.empty())
        field("H", options.hullOfDomainShader.partitioning + "," + options.hullOfDomainShader.outputTopology);
    if (options.skipShaders) field("O", "outline");
    if (!options.defaultMatrixMajority.empty()) field("M", options.defaultMatrixMajority);
    field("S", source);
    return key;
}

void dumpIfAsked(const CompiledEffect& effect) {
    const char* dir = std::getenv("FXPORT_DUMP");
    if (!dir || !*dir) return;
    std::error_code ec;
    fs::create_directories(dir, ec);
    std::string stem = fs::path(effect.sourcePath).stem().string();
    for (size_t i = 0; i < effect.shaders.size(); ++i) {
        const auto& s = effect.shaders[i];
        if (s.glsl.empty()) continue;  // an outline (CompileOptions::skipShaders) compiled nothing
        std::string base = std::string(dir) + "/" + stem + "." + std::to_string(i) + "." + s.entryPoint + "." + s.profile.name;
        std::ofstream(base + ".glsl") << s.glsl;
        if (!s.hlslAfterRewrite.empty()) std::ofstream(base + ".hlsl") << s.hlslAfterRewrite;
    }
}

// Candidate entry points of a file without techniques: functions with a semantic on their result
// or on a parameter, directly or on a member of their struct (what fxc's /E would name).
std::string entryPointCandidates(const EffectSyntax& syntax) {
    auto structHasSemantics = [&](const std::string& type) {
        const FxStruct* s = syntax.findStruct(syntax.resolveType(type));
        return s && std::any_of(s->members.begin(), s->members.end(), [](const FxStructMember& m) { return !m.semantic.empty(); });
    };
    std::string names;
    for (const auto& f : syntax.functions) {
        bool semantic = !f.returnSemantic.empty() || structHasSemantics(f.returnType);
        for (const auto& p : f.parameters) semantic |= !p.semantic.empty() || structHasSemantics(p.type);
        if (semantic && names.find(" " + f.name + ",") == std::string::npos) names += " " + f.name + ",";
    }
    if (!names.empty()) names.pop_back();
    return names;
}

bool isLooseShaderPath(const std::string& path) {
    std::string ext = toLower(fs::path(path).extension().string());
    return ext == ".hlsl" || ext == ".vs" || ext == ".ps" || ext == ".gs" || ext == ".vsh" || ext == ".psh" || ext == ".shader";
}

// Shaders of one effect compiled in parallel: the front end (glslang and spirv-opt, most of a
// shader's cost) of every request the build will make runs ahead in workers of this worker, one
// per request, as many at once as there are CPUs; the build then takes their results in its own
// order, so the output is the same as compiling one by one. A request whose worker failed makes
// the build fail the same way when it reaches that shader (frontEnd), so a crash, timeout or
// out-of-memory is reported at its shader as before, without running glslang on it again.
std::string spirvPayload(const SpirvModule& m) {
    nlohmann::json errors = nlohmann::json::array();
    for (const auto& e : m.errors) errors.push_back({e.line, e.token, e.message, e.aboutTheEntryPoint});
    return nlohmann::json{{"words", m.words}, {"errors", errors}, {"warnings", m.warnings}}.dump(-1, ' ', false,
                                                                                               nlohmann::json::error_handler_t::replace);
}

SpirvModule spirvFromPayload(const std::string& payload) {
    nlohmann::json j = nlohmann::json::parse(payload);
    SpirvModule m;
    m.words = j.at("words").get<std::vector<std::uint32_t>>();
    for (const auto& e : j.at("errors")) m.errors.push_back({e.at(0).get<int>(), e.at(1).get<std::string>(), e.at(2).get<std::string>(), e.at(3).get<bool>()});
    m.warnings = j.at("warnings").get<std::string>();
    return m;
}

Prefetched prefetchFrontEnd(const std::map<std::string, OwnedRequest>& requests, int jobs) {
    Prefetched results;
    std::vector<const std::pair<const std::string, OwnedRequest>*> order;
    for (const auto& r : requests) order.push_back(&r);
    // The longest sources first: the last to finish is then a short one.
    std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->second.source.size() > b->second.source.size(); });
    const WorkerLimits limits = WorkerLimits::fromEnvironment();
    WorkerPool pool(limits, jobs);
    for (size_t i = 0; i < order.size(); ++i)
        pool.submit(i, [r = order[i]] { return spirvPayload(hlslToSpirv(r->second.request)); });
    while (auto done = pool.next()) {
        const std::string& key = order[done->first]->first;
        if (done->second.kind != WorkerOutcome::Kind::Done) {
            results.failures[key] = std::move(done->second);  // the build fails the same way at this shader
            continue;
        }
        try {
            results.modules[key] = spirvFromPayload(done->second.payload);
        } catch (const std::exception&) {
        }
    }
    return results;
}

// How many shaders a worker compiles at once (set in the worker, before it compiles): 1 where
// other effects' workers already share the CPUs (compileEffectFiles).
int g_shaderJobs = 1;

// The compile proper, after the cache missed (stores its result there when `key` is not empty).
CompiledEffect compileUncached(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                               const CompileOptions& options, const std::string& key, const FailedShaders& failedShaders,
                               VaryingLocations* sharedVaryings) {
    reportWorkerProgress("preprocess");
    PreprocessedEffect pre = preprocessEffect(source, displayPath, absolutePath, options);
    reportWorkerProgress("parse");
    pre.text = splitStructDefinitions(pre.text);  // `static struct { ... } x;` and definitions in definitions
    pre.text = textureTemplatesSpelledAsObjects(pre.text);  // texture2D<float> t -> Texture2D<float> t
    pre.text = dropUnusedSamplerArrays(pre.text);
    pre.text = samplerArraysAsElements(pre.text);  // sam[1] -> sam_fxport_1
    pre.text = samplerTexturesDeclared(pre.text);  // tex2D(sam, uv) beside tex.Sample(sam, uv)
    pre.text = longLiteralSuffixesDropped(pre.text);  // 3lu -> 3u
    pre.text = halfLiteralSuffixesDropped(pre.text);  // 0.1h -> 0.1
    pre.text = builtinTypeTypedefsResolved(pre.text);  // { typedef half2 float; float v; } -> { half2 v; }
    pre.text = typeKeywordsLowerCased(pre.text);      // Matrix m -> matrix m
    pre.text = entryAttributeNamesLowerCased(pre.text);  // [MaxVertexCount(3)] -> [maxvertexcount(3)]
    std::vector<std::string> orderedViews;
    pre.text = rasterizerOrderedViewsAsUavs(pre.text, orderedViews);  // RasterizerOrderedTexture2D -> RWTexture2D

    EffectSyntax syntax = parseEffect(pre.text, pre.map, isLooseShaderCompile(options));
    syntax.rasterizerOrderedViews = std::move(orderedViews);
    CompiledEffect effect;
    effect.sourcePath = displayPath;
    effect.diagnostics = pre.warnings;
    effect.diagnostics.insert(effect.diagnostics.end(), syntax.warnings.begin(), syntax.warnings.end());
    bool techniqueless = allowsTechniqueless(options.effectProfile, displayPath);
    if (syntax.techniques.empty() && !techniqueless) {
        Diagnostic d;
        d.id = diag::kEmptyEffect;
        // A file with code but no technique is most likely a header (a .fx/.fxh of shared functions,
        // structs or typedefs that effects #include), not an effect of its own.
        std::string candidates = entryPointCandidates(syntax);
        d.message = isLooseShaderPath(displayPath) || (!candidates.empty() && toLower(fs::path(displayPath).extension().string()) != ".fx")
                        ? "'" + displayPath + "' is a loose shader file (no technique): name the entry point and profile, as fxc /E /T does: "
                          "--entry NAME --profile ps_5_0 (fxport compile, check, dump; compileShaderFiles(), Effect::FromShaderFiles())" + (candidates.empty() ? std::string() : " (entry points here:" + candidates + ")")
                    : !candidates.empty()
                        ? "the file has no technique: if it holds loose shaders (entry points here:" + candidates +
                              "), name one and its profile as fxc /E /T does: --entry NAME --profile vs_4_0 (fxport compile, check; "
                              "compileShaderFiles(), Effect::FromShaderFiles()); if it is a header that effects #include, compile the "
                              "effect that includes it, since XNA needs at least one technique with a pass to draw with"
                    : syntax.tokens.size() > 1
                        ? "the file has no technique: it looks like a header that other effects #include (shared declarations or "
                          "functions); compile the effect that includes it, since XNA needs at least one technique with a pass to draw with"
                        : "the file has no code and no technique; XNA needs at least one technique with a pass to draw with";
        d.location = {displayPath, 1, 1};  // a whole-file problem: its first line
        throw CompileError({d});
    }
    // Code that would crash glslang instead of getting a diagnostic: reported here, before any
    // shader of the effect is handed over.
    if (auto hazards = findFrontEndHazards(syntax, pre.map); !hazards.empty()) throw CompileError(std::move(hazards));
    // What fxc rejects and glslang would accept (fxc_checks.h: every family of checks).
    if (auto rejected = runFxcChecks(syntax, pre.map); !rejected.empty()) throw CompileError(std::move(rejected));
    if (auto rejected = checkEffectProfile(syntax, pre.map, options.effectProfile); !rejected.empty()) throw CompileError(std::move(rejected));
    // Objects declared in a cbuffer move out of it (cbuffer_objects.h), after fxc's rules on them
    // were judged where they were written; the moved text is parsed again.
    if (std::string moved = nonMembersMovedOutOfCbuffers(pre.text); moved != pre.text) {
        pre.text = std::move(moved);
        syntax = parseEffect(pre.text, pre.map, isLooseShaderCompile(options));
    }
    // Uniform resource parameters of entry points without a value become globals the wrapper passes
    // (uniform_resource_parameters.h); the declared text is parsed again.
    if (std::string declared = uniformResourceParametersDeclared(pre.text, syntax); declared != pre.text) {
        pre.text = std::move(declared);
        syntax = parseEffect(pre.text, pre.map, isLooseShaderCompile(options));
    }
    RewrittenEffect rewritten = rewriteEffect(pre.text, syntax, pre.map, effect.diagnostics, options.defaultMatrixMajority);
    for (auto& w : findImplicitTruncations(syntax, pre.map)) effect.diagnostics.push_back(std::move(w));
    Prefetched prefetched;
    if (insideWorker() && g_shaderJobs > 1 && !options.skipShaders) {
        std::map<std::string, OwnedRequest> requests;
        try {  // the same build on copies, only listing what it would hand to the front end
            RewrittenEffect rewrittenCopy = rewritten;
            CompiledEffect scratch;
            VaryingLocations varyings;
            EffectBuilder collector(pre, syntax, rewrittenCopy, options, scratch, sharedVaryings ? &varyings : nullptr, failedShaders);
            collector.collectRequestsInto(&requests);
            collector.buildParameters();
            collector.buildTechniques();
        } catch (const std::exception&) {
            requests.clear();  // the build proper says what is wrong
        }
        reportWorkerProgress("prefetch");
        // Two shaders gain less than the forks and the listing pass cost (a vertex and a pixel shader
        // of a few milliseconds each); three or more gain.
        if (requests.size() > 2) prefetched = prefetchFrontEnd(requests, g_shaderJobs);
    }
    EffectBuilder builder(pre, syntax, rewritten, options, effect, sharedVaryings, failedShaders);
    builder.usePrefetched(&prefetched);
    builder.buildParameters();
    builder.buildTechniques();
    builder.finishReflection();
    if (!options.techniques.empty() && effect.techniques.empty()) {
        Diagnostic d;
        d.id = diag::kEmptyEffect;
        d.message = "none of the requested techniques exists in the effect";
        d.location = {displayPath, 0, 0};
        throw CompileError({d});
    }
    dumpIfAsked(effect);
    if (effect.hasErrors() && !options.keepValidPasses) {
        std::vector<Diagnostic> errors;
        for (const auto& d : effect.diagnostics)
            if (d.severity == Severity::Error) errors.push_back(d);
        throw CompileError(std::move(errors));
    }
    if (!key.empty()) storeCachedEffect(options.cacheDir, key, pre.dependencies, effect);
    return effect;
}

nlohmann::json diagnosticsJson(const std::vector<Diagnostic>& diagnostics) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& d : diagnostics)
        list.push_back({{"error", d.severity == Severity::Error}, {"id", d.id}, {"message", d.message}, {"file", d.location.file},
                        {"line", d.location.line}, {"column", d.location.column}, {"sourceLine", d.sourceLine}});
    return list;
}

std::vector<Diagnostic> diagnosticsFrom(const nlohmann::json& list) {
    std::vector<Diagnostic> out;
    for (const auto& j : list) {
        Diagnostic d;
        d.severity = j.at("error").get<bool>() ? Severity::Error : Severity::Warning;
        d.id = j.at("id");
        d.message = j.at("message");
        d.location = {j.at("file"), j.at("line"), j.at("column")};
        d.sourceLine = j.at("sourceLine");
        out.push_back(std::move(d));
    }
    return out;
}

const char* signalName(int sig) {
    switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    default: return "a signal";
    }
}

// compileUncached() in a worker process (front_end_worker.h). A shader that takes the worker down
// becomes an error at its entry point, and the effect is compiled again without it, so the rest
// still compiles (and keepValidPasses keeps the passes that do not use it).
// glslang builds its built-in symbol tables per stage on first use, in the process that compiles:
// built once here, before the first fork, every worker inherits them instead of rebuilding them
// (most of a small effect's compile time). The shaders are fixed and known to compile.
void warmFrontEnd() {
    static std::once_flag once;
    std::call_once(once, [] {
        const std::string vs = "float4 main(float4 p : POSITION) : SV_Position { return p; }\n";
        const std::string ps = "sampler2D s; float4 main(float2 t : TEXCOORD0) : SV_Target { return tex2D(s, t); }\n";
        const std::string gs = "struct V { float4 p : SV_Position; };\n"
                               "[maxvertexcount(1)] void main(point V v[1], inout PointStream<V> o) { o.Append(v[0]); }\n";
        for (auto [text, stage, dx9] : {std::tuple{&vs, ShaderStage::Vertex, false}, std::tuple{&ps, ShaderStage::Pixel, true},
                                        std::tuple{&ps, ShaderStage::Pixel, false}, std::tuple{&gs, ShaderStage::Geometry, false}}) {
            HlslToSpirvRequest request;
            request.source = text;
            request.stage = stage;
            request.entryPoint = "main";
            request.dx9Compatible = dx9;
            (void)hlslToSpirv(request);
        }
        (void)preprocessEffect(vs, "warm-up.fx", "warm-up.fx", CompileOptions{});  // its own tables (OpenGL client)
    });
}

// What a worker sends back: the effect (with each shader's rewritten HLSL when it was kept, which
// a compiled-effect file does not hold) or the errors that stopped the compile.
std::string workerPayload(const std::function<CompiledEffect()>& compile) {
    nlohmann::json result;
    try {
        CompiledEffect effect = compile();
        result["effect"] = serializeEffect(effect, true);
        nlohmann::json rewritten = nlohmann::json::array();
        for (const auto& s : effect.shaders) rewritten.push_back(s.hlslAfterRewrite);
        result["rewritten"] = std::move(rewritten);
    } catch (const CompileError& e) {
        result["errors"] = diagnosticsJson(e.diagnostics());
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        result["exception"] = e.what();
    }
    return result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

CompiledEffect effectFromPayload(const std::string& payload, const std::string& displayPath) {
    nlohmann::json result = nlohmann::json::parse(payload);
    if (result.contains("errors")) throw CompileError(diagnosticsFrom(result["errors"]));
    if (result.contains("exception")) throw std::runtime_error(result["exception"].get<std::string>());
    CompiledEffect effect = deserializeEffect(result.at("effect").get<std::string>(), displayPath);
    const auto& rewritten = result.at("rewritten");
    for (size_t i = 0; i < effect.shaders.size() && i < rewritten.size(); ++i) effect.shaders[i].hlslAfterRewrite = rewritten[i].get<std::string>();
    return effect;
}

// The diagnostic for a worker that did not return. `shaderKey` gets the ShaderKey::text() of the
// shader it was compiling, if any (the diagnostic then points at that shader's entry point).
Diagnostic describeWorkerFailure(const WorkerOutcome& outcome, const WorkerLimits& limits, const std::string& displayPath,
                                 const FailedShaders& failed, bool locateShader, std::string& shaderKey) {
    const std::string what = outcome.kind == WorkerOutcome::Kind::TimedOut
                                 ? "ran past its limit of " + std::to_string(limits.cpuSeconds) + " s of CPU time"
                             : outcome.kind == WorkerOutcome::Kind::OutOfMemory
                                 ? "ran past its limit of " + std::to_string(limits.memoryBytes >> 20) + " MiB of memory"
                             : outcome.signal == SIGKILL ? std::string("was killed from outside (SIGKILL: the OOM killer or a user)")
                                                         : std::string("crashed (") + signalName(outcome.signal) + ")";
    const char* id = outcome.kind == WorkerOutcome::Kind::TimedOut      ? diag::kFrontEndTimeout
                     : outcome.kind == WorkerOutcome::Kind::OutOfMemory ? diag::kFrontEndMemory
                                                                        : diag::kFrontEndCrashed;
    // progress: "shader\t<key>\t<entry>\t<profile>\t<file>\t<line>\t<column>", "preprocess" or "parse".
    std::vector<std::string> f;
    for (size_t at = 0;;) {
        size_t tab = outcome.progress.find('\t', at);
        f.push_back(outcome.progress.substr(at, tab == std::string::npos ? std::string::npos : tab - at));
        if (tab == std::string::npos) break;
        at = tab + 1;
    }
    Diagnostic d;
    if (f.size() == 7 && f[0] == "shader" && !failed.count(f[1]) && locateShader) {
        d.id = id;
        d.message = "the HLSL front end failed on this shader (" + f[2] + ", " + f[3] + "): glslang/SPIRV-Cross " + what;
        d.location = {f[4], std::atoi(f[5].c_str()), std::atoi(f[6].c_str())};
        shaderKey = f[1];
        return d;
    }
    if (f[0] == "preprocess" && outcome.kind != WorkerOutcome::Kind::Crashed) {
        d.id = diag::kMacroLimit;  // the preprocessor's only unbounded work is macro expansion
        d.message = "preprocessing the effect " + what + ": a macro expands without bound";
    } else {
        d.id = id;
        d.message = std::string("the HLSL front end failed on this effect while ") +
                    (f[0] == "preprocess" ? "preprocessing it" : f[0] == "parse" ? "reading it" : "compiling a shader") + ": it " + what;
    }
    d.location = {displayPath, 0, 0};
    return d;
}

// One effect compiled in workers, attempt after attempt: a shader that took a worker down is left
// out of the next attempt (at most 8 times), so the rest of the effect still compiles.
struct WorkerCompile {
    std::string source, displayPath, absolutePath;
    CompileOptions options;
    std::string key;
    FailedShaders failed;
    int attempt = 0;
    int shaderJobs = 1;  // shaders compiled at once in the worker

    // What the worker runs. Holds `this`: a WorkerCompile stays where it is while it compiles.
    std::function<std::string()> work() const {
        return [this] {
            g_shaderJobs = shaderJobs;
            return workerPayload([this] { return compileUncached(source, displayPath, absolutePath, options, key, failed, nullptr); });
        };
    }
    // The effect; nullopt when it must be compiled again without the shader that failed. Throws
    // CompileError when the worker failed outside a shader (or past the last attempt).
    std::optional<CompiledEffect> take(const WorkerOutcome& outcome, const WorkerLimits& limits) {
        if (outcome.kind == WorkerOutcome::Kind::Done) return effectFromPayload(outcome.payload, displayPath);
        std::string shaderKey;
        Diagnostic d = describeWorkerFailure(outcome, limits, displayPath, failed, attempt < 8, shaderKey);
        if (shaderKey.empty()) throw CompileError({d});
        failed[shaderKey] = d;  // again, without that shader
        ++attempt;
        return std::nullopt;
    }
};

CompiledEffect compileInWorker(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                               const CompileOptions& options, const std::string& key) {
    const WorkerLimits limits = WorkerLimits::fromEnvironment();
    warmFrontEnd();
    WorkerCompile compile{source, displayPath, absolutePath, options, key, {}, 0, workerJobs()};
    for (;;)
        if (auto effect = compile.take(runInWorker(compile.work(), limits), limits)) return std::move(*effect);
}

}  // namespace

bool compilesInThisProcess(const CompileOptions& options) {
    const char* inProcess = std::getenv("FXPORT_IN_PROCESS");
    return options.inProcess || insideWorker() || (inProcess && *inProcess == '1');
}

CompiledEffect compileContained(const std::function<CompiledEffect()>& compile, const std::string& displayPath) {
    const WorkerLimits limits = WorkerLimits::fromEnvironment();
    warmFrontEnd();
    WorkerOutcome outcome = runInWorker(
        [&] {
            g_shaderJobs = workerJobs();
            return workerPayload(compile);
        },
        limits);
    if (outcome.kind == WorkerOutcome::Kind::Done) return effectFromPayload(outcome.payload, displayPath);
    std::string shaderKey;
    throw CompileError({describeWorkerFailure(outcome, limits, displayPath, {}, true, shaderKey)});
}

std::optional<CompiledEffect> cachedEffectText(const std::string& source, const std::string& displayPath,
                                               const std::string& absolutePath, const CompileOptions& options) {
    const char* dump = std::getenv("FXPORT_DUMP");
    if (!options.useCache || options.keepRewrittenHlsl || (dump && *dump)) return std::nullopt;
    return loadCachedEffect(options.cacheDir, cacheKey(source, displayPath, absolutePath, options));
}

CompiledEffect compileEffectText(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                                 const CompileOptions& optionsIn, VaryingLocations* sharedVaryings) {
    CompileOptions options = optionsIn;
    if (const char* dump = std::getenv("FXPORT_DUMP"); dump && *dump) options.keepRewrittenHlsl = true;
    if (options.keepRewrittenHlsl) options.useCache = false;  // the cache does not keep the rewritten HLSL
    std::string key;
    if (options.useCache) {
        key = cacheKey(source, displayPath, absolutePath, options);
        if (auto cached = loadCachedEffect(options.cacheDir, key)) return std::move(*cached);
    }
    // Loose shader files compiled together share varying locations: compileShaderFiles() runs all
    // of them in one worker, and they compile here, inside it. FXPORT_IN_PROCESS=1 compiles every
    // effect here (debugging, measuring the worker's cost).
    if (sharedVaryings || compilesInThisProcess(options))
        return compileUncached(source, displayPath, absolutePath, options, key, {}, sharedVaryings);
    return compileInWorker(source, displayPath, absolutePath, options, key);
}

namespace {

CompiledEffect compile(const std::string& source, const std::string& displayPath, const std::string& absolutePath,
                       const CompileOptions& options) {
    return compileEffectText(source, displayPath, absolutePath, options, nullptr);
}

}  // namespace

namespace {

// The text of an effect file, after the checks made before reading it. Throws CompileError.
std::string readEffectSource(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        Diagnostic d;
        d.id = diag::kFileUnreadable;
        d.message = "'" + path + "' is a folder, not an effect file";
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
    if (auto size = fs::file_size(path, ec); !ec && size > limits::kMaxFileBytes) {
        Diagnostic d;  // said before reading it: a file of gigabytes is not read into memory
        d.id = diag::kInputTooLarge;
        d.message = "the file has " + std::to_string(size) + " bytes; fxport compiles source files of at most " +
                    std::to_string(limits::kMaxFileBytes >> 20) + " MiB";
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
    auto text = readFile(path);
    if (!text) {
        Diagnostic d;
        d.id = diag::kFileUnreadable;
        d.message = "cannot open '" + path + "'";
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
    return std::move(*text);
}

// Reports results in the order of the files, each as soon as those before it are reported.
class OrderedResults {
public:
    OrderedResults(size_t n, const std::function<void(size_t, EffectFileResult&&)>& done) : results_(n), done_(done) {}
    void set(size_t i, EffectFileResult r) {
        results_[i] = std::move(r);
        for (; next_ < results_.size() && results_[next_]; ++next_) done_(next_, std::move(*results_[next_]));
    }

private:
    std::vector<std::optional<EffectFileResult>> results_;
    const std::function<void(size_t, EffectFileResult&&)>& done_;
    size_t next_ = 0;
};

EffectFileResult resultOf(const std::function<CompiledEffect()>& compile) {
    EffectFileResult r;
    try {
        r.effect = compile();
    } catch (const CompileError& e) {
        r.errors = e.diagnostics();
    }
    return r;
}

}  // namespace

CompiledEffect compileEffectFile(const std::string& path, const CompileOptions& options) {
    return compile(readEffectSource(path), path, path, options);
}

// As compileEffectText() per file, with the misses of the cache compiled in a pool of workers.
void compileEffectFiles(const std::vector<std::pair<std::string, CompileOptions>>& files,
                        const std::function<void(size_t, EffectFileResult&&)>& done) {
    OrderedResults results(files.size(), done);
    const WorkerLimits limits = WorkerLimits::fromEnvironment();
    std::vector<std::unique_ptr<WorkerCompile>> compiles(files.size());
    std::unique_ptr<WorkerPool> pool;
    for (size_t i = 0; i < files.size(); ++i) {
        const std::string& path = files[i].first;
        CompileOptions options = files[i].second;
        if (const char* dump = std::getenv("FXPORT_DUMP"); dump && *dump) options.keepRewrittenHlsl = true;
        if (options.keepRewrittenHlsl) options.useCache = false;  // the cache does not keep the rewritten HLSL
        std::string source, key;
        try {
            source = readEffectSource(path);
            if (options.useCache) key = cacheKey(source, path, path, options);
        } catch (const CompileError& e) {
            results.set(i, {std::nullopt, e.diagnostics()});
            continue;
        }
        if (!key.empty())
            if (auto cached = loadCachedEffect(options.cacheDir, key)) {
                results.set(i, {std::move(*cached), {}});
                continue;
            }
        if (compilesInThisProcess(options)) {
            results.set(i, resultOf([&] { return compileUncached(source, path, path, options, key, {}, nullptr); }));
            continue;
        }
        compiles[i] = std::make_unique<WorkerCompile>(WorkerCompile{std::move(source), path, path, options, key, {}, 0, 1});
    }
    std::vector<size_t> misses;
    for (size_t i = 0; i < files.size(); ++i)
        if (compiles[i]) misses.push_back(i);
    if (!misses.empty()) {
        warmFrontEnd();  // before the first fork: every worker inherits glslang's tables
        const int jobs = workerJobs();
        pool = std::make_unique<WorkerPool>(limits, jobs);
        // Fewer effects than CPUs: the rest compile shaders of each effect in parallel.
        const int shaderJobs = std::max(1, jobs / static_cast<int>(misses.size()));
        // The largest first, so that the last to finish is a small one.
        std::stable_sort(misses.begin(), misses.end(), [&](size_t a, size_t b) { return compiles[a]->source.size() > compiles[b]->source.size(); });
        for (size_t i : misses) {
            compiles[i]->shaderJobs = shaderJobs;
            pool->submit(i, compiles[i]->work());
        }
    }
    while (pool)
        if (auto finished = pool->next()) {
            auto& [i, outcome] = *finished;
            WorkerCompile& c = *compiles[i];
            EffectFileResult r;
            try {
                if (auto effect = c.take(outcome, limits)) r.effect = std::move(*effect);
                else {
                    pool->submit(i, c.work());  // again, without the shader that failed
                    continue;
                }
            } catch (const CompileError& e) {
                r.errors = e.diagnostics();
            }
            compiles[i].reset();
            results.set(i, std::move(r));
        } else {
            pool.reset();
        }
}

CompiledEffect compileEffectSource(const std::string& source, const std::string& virtualPath, const CompileOptions& options) {
    return compile(source, virtualPath, virtualPath, options);
}

}  // namespace fxport::xlate
