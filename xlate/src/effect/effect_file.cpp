#include "fxport/xlate/effect_file.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include "effect/effect_validation.h"
#include "fx/shader_profile.h"
#include "fx/input_limits.h"
#include "fx/text_util.h"

using nlohmann::json;

namespace fxport::xlate {

namespace {

// Enum <-> name tables: the file is meant to be read by people (golden reflection is reviewed).
template <typename E, size_t N>
struct Names {
    std::array<const char*, N> names;
    const char* of(E e) const { return static_cast<size_t>(e) < N ? names[static_cast<size_t>(e)] : "?"; }
    E parse(const std::string& s) const {
        for (size_t i = 0; i < N; ++i)
            if (s == names[i]) return static_cast<E>(i);
        throw std::runtime_error("unknown name '" + s + "'");
    }
};

constexpr Names<ShaderStage, 6> kStage{{"vertex", "pixel", "geometry", "hull", "domain", "compute"}};
constexpr Names<StorageKind, 4> kStorage{{"buffer", "image", "texel-buffer", "image-buffer"}};
constexpr Names<ParameterClass, 5> kClass{{"scalar", "vector", "matrix", "object", "struct"}};
constexpr Names<ParameterType, 17> kType{{"void", "bool", "int", "uint", "float", "string", "texture", "texture1D",
                                          "texture2D", "texture3D", "textureCube", "sampler", "sampler1D", "sampler2D",
                                          "sampler3D", "samplerCube", "samplerState"}};
constexpr Names<TextureFilter, 4> kFilter{{"none", "point", "linear", "anisotropic"}};
constexpr Names<TextureAddress, 5> kAddress{{"wrap", "mirror", "clamp", "border", "mirrorOnce"}};
constexpr Names<SamplerStateField, 9> kSamplerField{
    {"minFilter", "magFilter", "mipFilter", "addressU", "addressV", "addressW", "maxAnisotropy", "maxMipLevel", "mipLodBias"}};
constexpr Names<TextureKind, 4> kKind{{"1D", "2D", "3D", "cube"}};
constexpr Names<RenderState, 52> kState{
    {"AlphaBlendEnable", "SrcBlend", "DestBlend", "BlendOp", "SeparateAlphaBlendEnable", "SrcBlendAlpha",
     "DestBlendAlpha", "BlendOpAlpha", "BlendFactor", "ColorWriteEnable", "MultiSampleMask", "ZEnable",
     "ZWriteEnable", "ZFunc", "StencilEnable", "StencilFunc", "StencilPass", "StencilFail", "StencilZFail",
     "StencilRef", "StencilMask", "StencilWriteMask", "TwoSidedStencilMode", "CcwStencilFunc", "CcwStencilPass",
     "CcwStencilFail", "CcwStencilZFail", "CullMode", "FillMode", "ScissorTestEnable", "MultiSampleAntiAlias",
     "DepthBias", "SlopeScaleDepthBias", "DepthClipEnable", "AlphaTestEnable", "AlphaFunc", "AlphaRef",
     "SrgbWriteEnable", "FogEnable", "FogColor", "FogTableMode", "FogVertexMode", "FogStart", "FogEnd", "FogDensity",
     "PointSize", "PointSizeMin", "PointSizeMax", "PointSpriteEnable", "ClipPlaneEnable", "ClipPlane", "ShadeMode"}};
constexpr Names<Blend, 13> kBlend{{"Zero", "One", "SourceColor", "InverseSourceColor", "SourceAlpha",
                                   "InverseSourceAlpha", "DestinationAlpha", "InverseDestinationAlpha",
                                   "DestinationColor", "InverseDestinationColor", "SourceAlphaSaturation",
                                   "BlendFactor", "InverseBlendFactor"}};
constexpr Names<BlendFunction, 5> kBlendOp{{"Add", "Subtract", "ReverseSubtract", "Min", "Max"}};
constexpr Names<CompareFunction, 8> kCompare{{"Never", "Less", "Equal", "LessEqual", "Greater", "NotEqual", "GreaterEqual", "Always"}};
constexpr Names<StencilOperation, 8> kStencil{{"Keep", "Zero", "Replace", "IncrementSaturation", "DecrementSaturation", "Invert", "Increment", "Decrement"}};
constexpr Names<CullMode, 3> kCull{{"None", "CullClockwiseFace", "CullCounterClockwiseFace"}};
constexpr Names<FillMode, 3> kFill{{"Point", "WireFrame", "Solid"}};

// A state's value as people read it: enum names, true/false, numbers, a float4 as an array.
json valueJson(const StateValue& value) {
    struct ToJson {
        json operator()(bool v) const { return v; }
        json operator()(int v) const { return v; }
        json operator()(float v) const { return v; }
        json operator()(Blend v) const { return kBlend.of(v); }
        json operator()(BlendFunction v) const { return kBlendOp.of(v); }
        json operator()(CompareFunction v) const { return kCompare.of(v); }
        json operator()(StencilOperation v) const { return kStencil.of(v); }
        json operator()(CullMode v) const { return kCull.of(v); }
        json operator()(FillMode v) const { return kFill.of(v); }
        json operator()(const std::array<float, 4>& v) const { return v; }
    };
    return std::visit(ToJson{}, value);
}

// The inverse, for a value of `state` (whose alternative says how to read the JSON).
StateValue valueFrom(RenderState state, const json& j) {
    struct FromJson {
        const json& j;
        StateValue operator()(bool) const { return j.get<bool>(); }
        StateValue operator()(int) const {
            if (!j.is_number_integer()) throw std::runtime_error("an integer state value is " + j.dump());
            return j.get<int>();
        }
        StateValue operator()(float) const { return j.get<float>(); }
        StateValue operator()(Blend) const { return kBlend.parse(j.get<std::string>()); }
        StateValue operator()(BlendFunction) const { return kBlendOp.parse(j.get<std::string>()); }
        StateValue operator()(CompareFunction) const { return kCompare.parse(j.get<std::string>()); }
        StateValue operator()(StencilOperation) const { return kStencil.parse(j.get<std::string>()); }
        StateValue operator()(CullMode) const { return kCull.parse(j.get<std::string>()); }
        StateValue operator()(FillMode) const { return kFill.parse(j.get<std::string>()); }
        StateValue operator()(const std::array<float, 4>&) const { return j.get<std::array<float, 4>>(); }
    };
    return std::visit(FromJson{j}, defaultStateValue(state));
}

json toJson(const SourceLocation& l) { return json{{"file", l.file}, {"line", l.line}, {"column", l.column}}; }
SourceLocation locationFrom(const json& j) {
    return {j.value("file", std::string()), j.value("line", 0), j.value("column", 0)};
}

json toJson(const std::vector<Annotation>& list) {
    json a = json::array();
    for (const auto& x : list) a.push_back({{"type", x.type}, {"name", x.name}, {"value", x.value}});
    return a;
}
std::vector<Annotation> annotationsFrom(const json& j) {
    std::vector<Annotation> out;
    for (const auto& x : j) out.push_back({x.at("type"), x.at("name"), x.at("value")});
    return out;
}

json toJson(const Parameter& p, bool withLocation) {
    json j{{"name", p.name}, {"class", kClass.of(p.parameterClass)}, {"type", kType.of(p.type)}};
    if (!p.semantic.empty()) j["semantic"] = p.semantic;
    if (p.parameterClass != ParameterClass::Object) {
        j["rows"] = p.rows;
        j["columns"] = p.columns;
    }
    if (p.elements) j["elements"] = p.elements;
    if (p.parameterClass == ParameterClass::Matrix) j["rowMajor"] = p.rowMajor;
    if (p.block) j["block"] = p.block;
    if (p.offset >= 0) {
        j["offset"] = p.offset;
        j["size"] = p.size;
        if (p.matrixStride) j["matrixStride"] = p.matrixStride;
        if (p.arrayStride) j["arrayStride"] = p.arrayStride;
    }
    if (!p.defaultValue.empty()) j["default"] = p.defaultValue;
    if (!p.defaultString.empty()) j["defaultString"] = p.defaultString;
    if (!p.annotations.empty()) j["annotations"] = toJson(p.annotations);
    if (!p.members.empty()) {
        json m = json::array();
        for (const auto& x : p.members) m.push_back(toJson(x, withLocation));
        j["members"] = m;
    }
    if (withLocation) j["declaredAt"] = toJson(p.declaredAt);
    return j;
}
Parameter parameterFrom(const json& j) {
    Parameter p;
    p.name = j.at("name");
    p.parameterClass = kClass.parse(j.at("class"));
    p.type = kType.parse(j.at("type"));
    p.semantic = j.value("semantic", std::string());
    p.rows = j.value("rows", 1);
    p.columns = j.value("columns", 1);
    p.elements = j.value("elements", 0);
    p.rowMajor = j.value("rowMajor", false);
    p.block = j.value("block", 0);
    p.offset = j.value("offset", -1);
    p.size = j.value("size", 0);
    p.matrixStride = j.value("matrixStride", 0);
    p.arrayStride = j.value("arrayStride", 0);
    if (j.contains("default")) p.defaultValue = j["default"].get<std::vector<double>>();
    p.defaultString = j.value("defaultString", std::string());
    if (j.contains("annotations")) p.annotations = annotationsFrom(j["annotations"]);
    if (j.contains("members"))
        for (const auto& m : j["members"]) p.members.push_back(parameterFrom(m));
    if (j.contains("declaredAt")) p.declaredAt = locationFrom(j["declaredAt"]);
    return p;
}

json toJson(const SamplerStateDesc& s) {
    json j = json::object();
    if (s.minFilter) j["minFilter"] = kFilter.of(*s.minFilter);
    if (s.magFilter) j["magFilter"] = kFilter.of(*s.magFilter);
    if (s.mipFilter) j["mipFilter"] = kFilter.of(*s.mipFilter);
    if (s.addressU) j["addressU"] = kAddress.of(*s.addressU);
    if (s.addressV) j["addressV"] = kAddress.of(*s.addressV);
    if (s.addressW) j["addressW"] = kAddress.of(*s.addressW);
    if (s.borderColor) j["borderColor"] = *s.borderColor;
    if (s.maxAnisotropy) j["maxAnisotropy"] = *s.maxAnisotropy;
    if (s.maxMipLevel) j["maxMipLevel"] = *s.maxMipLevel;
    if (s.mipLodBias) j["mipLodBias"] = *s.mipLodBias;
    if (s.minLod) j["minLod"] = *s.minLod;
    if (s.maxLod) j["maxLod"] = *s.maxLod;
    if (s.comparison) j["comparison"] = kCompare.of(*s.comparison);
    return j;
}
SamplerStateDesc samplerStateFrom(const json& j) {
    SamplerStateDesc s;
    if (j.contains("minFilter")) s.minFilter = kFilter.parse(j["minFilter"]);
    if (j.contains("magFilter")) s.magFilter = kFilter.parse(j["magFilter"]);
    if (j.contains("mipFilter")) s.mipFilter = kFilter.parse(j["mipFilter"]);
    if (j.contains("addressU")) s.addressU = kAddress.parse(j["addressU"]);
    if (j.contains("addressV")) s.addressV = kAddress.parse(j["addressV"]);
    if (j.contains("addressW")) s.addressW = kAddress.parse(j["addressW"]);
    if (j.contains("borderColor")) s.borderColor = j["borderColor"].get<std::array<float, 4>>();
    if (j.contains("maxAnisotropy")) s.maxAnisotropy = j["maxAnisotropy"].get<int>();
    if (j.contains("maxMipLevel")) s.maxMipLevel = j["maxMipLevel"].get<int>();
    if (j.contains("mipLodBias")) s.mipLodBias = j["mipLodBias"].get<float>();
    if (j.contains("minLod")) s.minLod = j["minLod"].get<float>();
    if (j.contains("maxLod")) s.maxLod = j["maxLod"].get<float>();
    if (j.contains("comparison")) s.comparison = kCompare.parse(j["comparison"]);
    return s;
}

json selectorJson(const std::vector<SelectorOp>& selector);
std::vector<SelectorOp> selectorFrom(const json& j);

// `MinFilter = <Filter>;`: the field, the parameter's index and the element program.
json toJson(const SamplerStateParameter& p) {
    json j{{"field", kSamplerField.of(p.field)}, {"parameter", p.parameter}};
    if (!p.element.empty()) j["element"] = selectorJson(p.element);
    return j;
}

json toJson(const CompiledShader& s, const CompiledEffect& effect, bool withGlsl) {
    json j{{"stage", kStage.of(s.profile.stage)}, {"profile", s.profile.name}, {"entryPoint", s.entryPoint}};
    if (!s.arguments.empty()) j["arguments"] = s.arguments;
    json inputs = json::array();
    for (const auto& i : s.inputs)
        inputs.push_back({{"semantic", i.semantic}, {"location", i.location}, {"components", i.components}, {"integer", i.isInteger}});
    if (s.profile.stage == ShaderStage::Vertex) j["inputs"] = inputs;
    json samplers = json::array();
    for (const auto& b : s.samplers) {
        json sj{{"unit", b.unit}, {"kind", kKind.of(b.kind)}, {"glslName", b.glslName}, {"sampler", b.samplerName},
                {"texture", b.textureParameter}, {"state", toJson(b.state)}, {"elements", b.elements},
                {"textureRegister", b.textureRegister}, {"samplerRegister", b.samplerRegister}};
        for (const auto& p : b.stateParameters) sj["stateParameters"].push_back(toJson(p));
        samplers.push_back(sj);
    }
    j["samplers"] = samplers;
    json read = json::array();
    for (int p : s.parametersRead) read.push_back(effect.parameters[static_cast<size_t>(p)].name);
    j["parametersRead"] = read;
    json ranges = json::array();
    for (const auto& r : s.uniformRangesRead)  // [offset, size] in $Global, [offset, size, block] elsewhere
        ranges.push_back(r.block ? json{r.offset, r.size, r.block} : json{r.offset, r.size});
    j["uniformRangesRead"] = ranges;
    json live = json::array();
    for (const auto& r : s.uniformRangesLive) live.push_back(json{r.offset, r.size, r.block});
    j["uniformRangesLive"] = live;
    if (s.profile.stage == ShaderStage::Pixel) {
        j["outputTargets"] = s.outputTargets;
        j["writesDepth"] = s.writesDepth;
    }
    j["d3d9PixelOffset"] = s.needsD3D9PixelOffset;
    if (s.clipDistances > 0) j["clipDistances"] = s.clipDistances;  // written only where a shader clips
    auto varyings = [](const std::vector<Varying>& list) {
        json a = json::array();
        for (const Varying& v : list) a.push_back(json{v.semantic, v.location});
        return a;
    };
    // The locations are the GLSL's: written with it (the golden reflection has neither).
    if (withGlsl && !s.varyingInputs.empty()) j["varyingInputs"] = varyings(s.varyingInputs);
    if (withGlsl && !s.varyingOutputs.empty()) j["varyingOutputs"] = varyings(s.varyingOutputs);
    // What stream output captures: the outputs by GLSL name (with the GLSL), the declaration.
    if (withGlsl && !s.outputs.empty()) {
        json outputs = json::array();
        for (const ShaderOutput& o : s.outputs) outputs.push_back(json{o.semantic, o.glslName, o.components});
        j["outputs"] = outputs;
    }
    if (s.outputPrimitiveVertices > 0) j["outputPrimitiveVertices"] = s.outputPrimitiveVertices;
    if (!s.streamOutput.empty()) {
        json entries = json::array();
        for (const StreamOutputEntry& e : s.streamOutput.entries)
            entries.push_back({{"stream", e.stream}, {"semantic", e.semanticName}, {"index", e.semanticIndex}, {"start", e.startComponent},
                               {"count", e.componentCount}, {"slot", e.outputSlot}, {"varying", e.varying}});
        j["streamOutput"] = {{"entries", entries}, {"strides", s.streamOutput.strides}, {"rasterizedStream", s.streamOutput.rasterizedStream}};
    }
    // Compute, hull and domain shaders' reflection: written only where there is some, so effects
    // without them read as before.
    if (!s.storage.empty()) {
        json storage = json::array();
        for (const auto& b : s.storage)
            storage.push_back({{"kind", kStorage.of(b.kind)}, {"name", b.name}, {"register", std::string(1, b.registerClass) + std::to_string(b.slot)},
                               {"binding", b.binding}, {"stride", b.stride}, {"writes", b.writes}, {"dimension", kKind.of(b.dimension)},
                               {"format", b.format}});
        j["storage"] = storage;
    }
    if (s.profile.stage == ShaderStage::Compute) j["threadGroupSize"] = s.threadGroupSize;
    if (s.profile.stage == ShaderStage::Hull || s.profile.stage == ShaderStage::Domain) {
        const Tessellation& t = s.tessellation;
        j["tessellation"] = {{"domain", t.domain}, {"partitioning", t.partitioning}, {"outputTopology", t.outputTopology},
                             {"patchConstantFunction", t.patchConstantFunction}, {"inputControlPoints", t.inputControlPoints},
                             {"outputControlPoints", t.outputControlPoints}};
    }
    if (withGlsl) {
        j["glsl"] = s.glsl;
        j["glslHash"] = contentHash(s.glsl);
    }
    return j;
}

json selectorJson(const std::vector<SelectorOp>& selector) {
    json ops = json::array();
    for (const auto& op : selector) {
        const char* kind = op.kind == SelectorOp::Kind::PushConstant ? "const" : op.kind == SelectorOp::Kind::PushParameter ? "param" : "index";
        ops.push_back({kind, op.value});
    }
    return ops;
}
std::vector<SelectorOp> selectorFrom(const json& j) {
    std::vector<SelectorOp> ops;
    for (const auto& op : j) {
        std::string k = op.at(0);
        SelectorOp s;
        s.kind = k == "const" ? SelectorOp::Kind::PushConstant : k == "param" ? SelectorOp::Kind::PushParameter : SelectorOp::Kind::IndexParameter;
        s.value = op.at(1);
        ops.push_back(s);
    }
    return ops;
}

json toJson(const ShaderChoice& c) {
    json j{{"shaders", c.shaders}};
    if (!c.selector.empty()) j["selector"] = selectorJson(c.selector);
    return j;
}
ShaderChoice choiceFrom(const json& j) {
    ShaderChoice c;
    c.shaders = j.at("shaders").get<std::vector<int>>();
    if (j.contains("selector")) c.selector = selectorFrom(j["selector"]);
    return c;
}

json techniquesJson(const CompiledEffect& effect, bool withLocation) {
    json techniques = json::array();
    for (const auto& t : effect.techniques) {
        json passes = json::array();
        for (const auto& p : t.passes) {
            json states = json::array();
            for (const auto& s : p.states) {
                json sj{{"state", kState.of(s.state)}};
                if (s.parameter >= 0) sj["parameter"] = effect.parameters[static_cast<size_t>(s.parameter)].name;
                else sj["value"] = valueJson(s.value);
                if (!s.element.empty()) sj["element"] = selectorJson(s.element);
                if (s.index) sj["index"] = s.index;
                if (withLocation) sj["where"] = toJson(s.where);
                states.push_back(sj);
            }
            json pj{{"name", p.name}, {"valid", p.valid}, {"vertexShader", toJson(p.vertexShader)},
                    {"pixelShader", toJson(p.pixelShader)}, {"geometryShader", toJson(p.geometryShader)}, {"states", states}};
            if (p.nullPixelShader) pj["nullPixelShader"] = true;
            for (const TextureStage& ts : p.textureStages)
                pj["textureStages"].push_back(json{{"stage", ts.stage}, {"texture", ts.textureParameter}, {"state", toJson(ts.state)}});
            if (!p.hullShader.shaders.empty()) pj["hullShader"] = toJson(p.hullShader);
            if (!p.domainShader.shaders.empty()) pj["domainShader"] = toJson(p.domainShader);
            if (!p.computeShader.shaders.empty()) pj["computeShader"] = toJson(p.computeShader);
            if (!p.annotations.empty()) pj["annotations"] = toJson(p.annotations);
            if (withLocation) pj["declaredAt"] = toJson(p.declaredAt);
            passes.push_back(pj);
        }
        json tj{{"name", t.name}, {"passes", passes}};
        if (!t.annotations.empty()) tj["annotations"] = toJson(t.annotations);
        if (withLocation) tj["declaredAt"] = toJson(t.declaredAt);
        techniques.push_back(tj);
    }
    return techniques;
}

json effectJson(const CompiledEffect& effect, bool full) {
    json params = json::array();
    for (const auto& p : effect.parameters) params.push_back(toJson(p, full));
    json shaders = json::array();
    for (const auto& s : effect.shaders) shaders.push_back(toJson(s, effect, full));
    json j;
    if (full) {
        j["format"] = "fxport-effect";
        j["version"] = kEffectFileVersion;
        j["sourcePath"] = effect.sourcePath;
    }
    j["uniformBufferSize"] = effect.uniformBufferSize;
    json blocks = json::array();
    for (const auto& b : effect.uniformBlocks) blocks.push_back({{"name", b.name}, {"binding", b.binding}, {"size", b.size}, {"d3dPacking", b.d3dPacking}});
    j["uniformBlocks"] = blocks;
    if (full) {  // D3D registers as declared (not part of the golden reflection)
        json resources = json::array();
        for (const auto& r : effect.resources) resources.push_back({{"kind", int(r.kind)}, {"name", r.name}, {"register", r.explicitRegister}});
        j["resources"] = resources;
    }
    j["parameters"] = params;
    j["techniques"] = techniquesJson(effect, full);
    j["shaders"] = shaders;
    if (full) {
        json diags = json::array();
        for (const auto& d : effect.diagnostics)
            diags.push_back({{"severity", d.severity == Severity::Error ? "error" : "warning"}, {"id", d.id}, {"message", d.message},
                             {"where", toJson(d.location)}, {"sourceLine", d.sourceLine}});
        j["diagnostics"] = diags;
    }
    return j;
}

// The file's checksum: a hash of its canonical (compact, key-sorted) JSON without the checksum.
std::string checksumOf(json j) {
    j.erase("checksum");
    return contentHash(j.dump(-1, ' ', false, json::error_handler_t::replace));
}

// Only the fields below hold floats; every other number in the file is read as an int. A float
// anywhere else (a damaged file, or a fuzzer's `1e+40`) would reach nlohmann's get<int>, whose
// double-to-int cast is undefined out of range (UBSan, CI fuzz smoke 2026-11-25, twice: first
// `size`, then a shader index under `shaders`). The list is of float fields, not of int fields, so a
// field added later is safe by default. Found once here, before any field is read.
std::optional<std::string> floatOutsideAFloatField(const json& j, const std::string& key) {
    static const std::set<std::string> kFloatFields = {"default", "borderColor", "mipLodBias", "minLod", "maxLod", "value"};
    if (j.is_object()) {
        for (const auto& [k, v] : j.items())
            if (auto bad = floatOutsideAFloatField(v, k)) return bad;
    } else if (j.is_array()) {
        for (const auto& v : j)
            if (auto bad = floatOutsideAFloatField(v, key)) return bad;
    } else if (j.is_number_float() && !kFloatFields.count(key)) {
        return "'" + key + "' is " + j.dump() + ", not an integer";
    }
    return std::nullopt;
}

// True when `text` opens more than limits::kMaxEffectFileNesting arrays and objects at once
// (outside strings). Checked before parsing: nlohmann's parser recurses once per level, so a file
// of 200 000 `[` overflows the stack before any checksum could be compared.
bool nestsTooDeep(std::string_view text) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limits::kMaxEffectFileNesting) return true;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

}  // namespace

std::string resealEffectFile(std::string_view text) {
    json j = json::parse(text.begin(), text.end(), nullptr, false);
    if (!j.is_object()) return std::string(text);
    if (j.contains("shaders") && j["shaders"].is_array())
        for (auto& sh : j["shaders"])
            if (sh.is_object() && sh.contains("glsl") && sh["glsl"].is_string()) sh["glslHash"] = contentHash(sh["glsl"].get<std::string>());
    j["checksum"] = checksumOf(j);
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string describeStateAssignment(const StateAssignment& s, const CompiledEffect& effect) {
    std::string out = kState.of(s.state);
    if (s.index) out += "[" + std::to_string(s.index) + "]";
    out += " = ";
    if (s.parameter >= 0 && static_cast<size_t>(s.parameter) < effect.parameters.size()) {
        auto name = [&](int p) {
            return p >= 0 && static_cast<size_t>(p) < effect.parameters.size() ? effect.parameters[static_cast<size_t>(p)].name : "#" + std::to_string(p);
        };
        std::vector<std::string> stack;  // the element program, read back as text
        for (const SelectorOp& op : s.element) {
            if (op.kind == SelectorOp::Kind::PushConstant) stack.push_back(std::to_string(op.value));
            else if (op.kind == SelectorOp::Kind::PushParameter) stack.push_back(name(op.value));
            else if (!stack.empty()) stack.back() = name(op.value) + "[" + stack.back() + "]";
        }
        std::string element = stack.empty() ? "" : "[" + stack.back() + "]";
        return out + "<" + name(s.parameter) + element + ">";
    }
    json v = valueJson(s.value);
    return out + (v.is_string() ? v.get<std::string>() : v.dump());
}

// Text that is not UTF-8 (a diagnostic quoting a Latin-1 comment, say) is written with U+FFFD in
// its place rather than failing the whole file.
std::string serializeEffect(const CompiledEffect& effect, bool compact) {
    json j = effectJson(effect, true);
    j["checksum"] = checksumOf(j);
    return j.dump(compact ? -1 : 1, ' ', false, json::error_handler_t::replace);
}

std::string reflectionJson(const CompiledEffect& effect) {
    return effectJson(effect, false).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

CompiledEffect deserializeEffect(std::string_view text, const std::string& nameForErrors) {
    auto fail = [&](const std::string& why) -> CompiledEffect {
        Diagnostic d;
        d.id = diag::kEffectFile;
        d.message = why;
        d.location = {nameForErrors, 0, 0};
        throw CompileError({d});
    };
    if (nestsTooDeep(text))
        return fail("not a compiled effect file: its JSON nests more than " + std::to_string(limits::kMaxEffectFileNesting) +
                    " levels deep (a compiled effect needs far fewer)");
    json j;
    try {
        j = json::parse(text.begin(), text.end());
    } catch (const std::exception& e) {
        return fail(std::string("not a compiled effect file (") + e.what() + ")");
    }
    if (!j.is_object() || j.value("format", std::string()) != "fxport-effect") return fail("not a compiled effect file");
    if (auto bad = floatOutsideAFloatField(j, std::string())) return fail("damaged compiled effect file (" + *bad + ")");
    if (j.value("version", 0) != kEffectFileVersion)
        return fail("compiled effect file version " + std::to_string(j.value("version", 0)) + " is not the supported version " +
                    std::to_string(kEffectFileVersion) + "; recompile it with fxport compile");
    if (!j.contains("checksum") || !j["checksum"].is_string() || j["checksum"].get<std::string>() != checksumOf(j))
        return fail("the compiled effect's checksum does not match its content: the file was changed or damaged; recompile it with fxport compile");
    try {
        CompiledEffect e;
        e.sourcePath = j.value("sourcePath", std::string());
        e.uniformBufferSize = j.value("uniformBufferSize", 0);
        for (const auto& b : j.at("uniformBlocks")) e.uniformBlocks.push_back({b.at("name"), b.at("binding"), b.at("size"), b.value("d3dPacking", false)});
        if (j.contains("resources"))
            for (const auto& r : j.at("resources")) {
                const int kind = r.at("kind");
                if (kind < 0 || kind > 2) return fail("resource '" + r.at("name").get<std::string>() + "' has kind " + std::to_string(kind));
                e.resources.push_back({ResourceDeclaration::Kind(kind), r.at("name"), r.at("register")});
            }
        for (const auto& p : j.at("parameters")) e.parameters.push_back(parameterFrom(p));
        std::map<std::string, int> paramIndex;
        for (size_t i = 0; i < e.parameters.size(); ++i) paramIndex[e.parameters[i].name] = static_cast<int>(i);
        for (const auto& s : j.at("shaders")) {
            CompiledShader cs;
            auto profile = parseShaderProfile(s.at("profile"));
            if (!profile || profile->stage != kStage.parse(s.at("stage")))
                return fail("shader profile '" + s.at("profile").get<std::string>() + "' does not match its stage");
            cs.profile = *profile;
            cs.entryPoint = s.at("entryPoint");
            cs.arguments = s.value("arguments", std::string());
            cs.glsl = s.at("glsl");
            if (s.at("glslHash").get<std::string>() != contentHash(cs.glsl))
                return fail("the GLSL of shader '" + cs.entryPoint + "' does not match its hash: the file was changed or damaged");
            if (s.contains("inputs"))
                for (const auto& i : s["inputs"]) cs.inputs.push_back({i.at("semantic"), i.at("location"), i.at("components"), i.at("integer")});
            for (const auto& b : s.at("samplers")) {
                SamplerBinding sb;
                sb.unit = b.at("unit");
                sb.kind = kKind.parse(b.at("kind"));
                sb.glslName = b.at("glslName");
                sb.samplerName = b.at("sampler");
                sb.textureParameter = b.at("texture");
                sb.state = samplerStateFrom(b.at("state"));
                if (b.contains("stateParameters"))
                    for (const auto& p : b["stateParameters"])
                        sb.stateParameters.push_back({kSamplerField.parse(p.at("field")), p.at("parameter").get<int>(),
                                                      p.contains("element") ? selectorFrom(p["element"]) : std::vector<SelectorOp>{}});
                sb.elements = b.value("elements", 1);
                sb.textureRegister = b.value("textureRegister", -1);
                sb.samplerRegister = b.value("samplerRegister", -1);
                cs.samplers.push_back(sb);
            }
            for (const auto& name : s.at("parametersRead")) cs.parametersRead.push_back(paramIndex.at(name.get<std::string>()));
            for (const auto& r : s.at("uniformRangesRead"))
                cs.uniformRangesRead.push_back({r.at(0), r.at(1), r.size() > 2 ? r.at(2).get<int>() : 0});
            if (s.contains("uniformRangesLive"))
                for (const auto& r : s.at("uniformRangesLive")) cs.uniformRangesLive.push_back({r.at(0), r.at(1), r.at(2)});
            else
                cs.uniformRangesLive = cs.uniformRangesRead;  // written before the analysis: all it reads
            cs.outputTargets = s.value("outputTargets", 0);
            cs.writesDepth = s.value("writesDepth", false);
            cs.needsD3D9PixelOffset = s.value("d3d9PixelOffset", false);
            cs.clipDistances = s.value("clipDistances", 0);
            auto readVaryings = [&](const char* key, std::vector<Varying>& out) {
                if (s.contains(key))
                    for (const auto& v : s[key]) out.push_back({v.at(0).get<std::string>(), v.at(1).get<int>()});
            };
            readVaryings("varyingInputs", cs.varyingInputs);
            readVaryings("varyingOutputs", cs.varyingOutputs);
            if (s.contains("outputs"))
                for (const auto& o : s["outputs"]) cs.outputs.push_back({o.at(0).get<std::string>(), o.at(1).get<std::string>(), o.at(2).get<int>()});
            cs.outputPrimitiveVertices = s.value("outputPrimitiveVertices", 0);
            if (s.contains("streamOutput")) {
                const json& so = s["streamOutput"];
                for (const auto& en : so.at("entries"))
                    cs.streamOutput.entries.push_back({en.at("stream"), en.at("semantic"), en.at("index"), en.at("start"), en.at("count"),
                                                       en.at("slot"), en.at("varying")});
                cs.streamOutput.strides = so.at("strides").get<std::array<int, kStreamOutputSlots>>();
                cs.streamOutput.rasterizedStream = so.at("rasterizedStream");
            }
            if (s.contains("storage"))
                for (const auto& b : s["storage"]) {
                    StorageBinding sb;
                    sb.kind = kStorage.parse(b.at("kind"));
                    sb.name = b.at("name");
                    std::string reg = b.at("register");
                    if (reg.size() < 2 || (reg[0] != 'u' && reg[0] != 't')) return fail("storage register '" + reg + "' is not uN or tN");
                    sb.registerClass = reg[0];
                    sb.slot = std::stoi(reg.substr(1));
                    sb.binding = b.at("binding");
                    sb.stride = b.at("stride");
                    sb.writes = b.at("writes");
                    sb.dimension = kKind.parse(b.at("dimension"));
                    sb.format = b.at("format");
                    cs.storage.push_back(sb);
                }
            if (s.contains("threadGroupSize")) cs.threadGroupSize = s["threadGroupSize"].get<std::array<int, 3>>();
            if (s.contains("tessellation")) {
                const json& t = s["tessellation"];
                cs.tessellation = {t.at("domain"), t.at("partitioning"), t.at("outputTopology"), t.at("patchConstantFunction"),
                                   t.at("inputControlPoints"), t.at("outputControlPoints")};
            }
            e.shaders.push_back(std::move(cs));
        }
        for (const auto& t : j.at("techniques")) {
            Technique tech;
            tech.name = t.at("name");
            if (t.contains("annotations")) tech.annotations = annotationsFrom(t["annotations"]);
            if (t.contains("declaredAt")) tech.declaredAt = locationFrom(t["declaredAt"]);
            for (const auto& p : t.at("passes")) {
                Pass pass;
                pass.name = p.at("name");
                pass.valid = p.at("valid");
                pass.vertexShader = choiceFrom(p.at("vertexShader"));
                pass.pixelShader = choiceFrom(p.at("pixelShader"));
                pass.geometryShader = choiceFrom(p.at("geometryShader"));
                pass.nullPixelShader = p.value("nullPixelShader", false);
                if (p.contains("textureStages"))
                    for (const auto& ts : p["textureStages"])
                        pass.textureStages.push_back({ts.at("stage").get<int>(), ts.at("texture").get<std::string>(), samplerStateFrom(ts.at("state"))});
                if (p.contains("hullShader")) pass.hullShader = choiceFrom(p["hullShader"]);
                if (p.contains("domainShader")) pass.domainShader = choiceFrom(p["domainShader"]);
                if (p.contains("computeShader")) pass.computeShader = choiceFrom(p["computeShader"]);
                if (p.contains("annotations")) pass.annotations = annotationsFrom(p["annotations"]);
                if (p.contains("declaredAt")) pass.declaredAt = locationFrom(p["declaredAt"]);
                for (const auto& s : p.at("states")) {
                    StateAssignment a;
                    a.state = kState.parse(s.at("state"));
                    a.index = s.value("index", 0);
                    if (s.contains("parameter")) a.parameter = paramIndex.at(s["parameter"].get<std::string>());
                    else a.value = valueFrom(a.state, s.at("value"));
                    if (s.contains("element")) a.element = selectorFrom(s["element"]);
                    if (s.contains("where")) a.where = locationFrom(s["where"]);
                    pass.states.push_back(a);
                }
                tech.passes.push_back(std::move(pass));
            }
            e.techniques.push_back(std::move(tech));
        }
        if (j.contains("diagnostics"))
            for (const auto& d : j["diagnostics"]) {
                Diagnostic diag;
                diag.severity = d.at("severity") == "error" ? Severity::Error : Severity::Warning;
                diag.id = d.at("id");
                diag.message = d.at("message");
                diag.location = locationFrom(d.at("where"));
                diag.sourceLine = d.value("sourceLine", std::string());
                e.diagnostics.push_back(diag);
            }
        if (auto problem = findEffectInconsistency(e)) return fail("the compiled effect is inconsistent: " + *problem);
        return e;
    } catch (const CompileError&) {
        throw;
    } catch (const std::exception& ex) {
        return fail(std::string("damaged compiled effect file (") + ex.what() + ")");
    }
}

void saveEffectFile(const CompiledEffect& effect, const std::string& path) {
    errno = 0;
    std::ofstream out(path, std::ios::binary);
    if (out) out << serializeEffect(effect);
    if (out) out.close();  // a full disk may only say so here
    if (!out) {
        Diagnostic d;
        d.id = diag::kEffectFile;
        d.message = "cannot write '" + path + "'" + (errno ? std::string(" (") + std::strerror(errno) + ")" : std::string());
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
}

CompiledEffect loadEffectFile(const std::string& path) {
    std::error_code ec;
    auto size = std::filesystem::file_size(path, ec);
    auto text = readFile(path, limits::kMaxEffectFileBytes);
    if (!text) {
        Diagnostic d;
        d.id = diag::kEffectFile;
        d.message = !ec && size > limits::kMaxEffectFileBytes
                        ? "compiled effect '" + path + "' has " + std::to_string(size) + " bytes, more than the " +
                              std::to_string(limits::kMaxEffectFileBytes >> 20) + " MiB fxport reads"
                        : "cannot open compiled effect '" + path + "'" +
                              (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec) ? ": not a regular file" : "");
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
    return deserializeEffect(*text, path);
}

}  // namespace fxport::xlate
