#include "entry/entry_wrapper.h"

#include "rewrite/degenerate_matrices.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include "hlsl/hlsl_types.h"
#include "entry/signature_layout.h"
#include "entry/stage_attributes.h"
#include "fx/text_util.h"
#include "rewrite/keyword_identifiers.h"
#include "rewrite/static_initializer_calls.h"

namespace fxport::xlate {

std::pair<std::string, int> splitSemantic(const std::string& semantic) {
    std::string s = toUpper(semantic);
    size_t digits = s.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(s[digits - 1]))) --digits;
    if (digits == s.size()) return {s, 0};
    return {s.substr(0, digits), std::atoi(s.c_str() + digits)};
}

namespace {

bool isIntegerScalar(const std::string& s) {
    return s == "int" || s == "uint" || s == "dword" || s == "min16int" || s == "min12int" || s == "min16uint" || s == "bool";
}

std::string vectorType(const std::string& scalar, int n) {
    std::string s = scalar == "dword" ? "uint" : scalar;
    return n == 1 ? s : s + std::to_string(n);
}

struct Leaf {
    std::string access;      // HLSL l-value/r-value, e.g. "a0.tbn[1]"; a matrix column: the matrix
    std::string scalar;
    int components = 4;
    std::string semanticBase;
    int semanticIndex = 0;
    std::vector<std::string> interpolation;
    int column = -1;         // >= 0: the leaf is this column of the matrix `access` (components rows)
};

bool isInterpolationModifier(const std::string& m) {
    return m == "nointerpolation" || m == "linear" || m == "centroid" || m == "noperspective" || m == "sample";
}

// A member's modifiers plus the interpolation modifiers of the struct-typed declaration holding it:
// `nointerpolation ps_input input` makes every member of input flat, as fxc does.
std::vector<std::string> withInterpolationOf(const std::vector<std::string>& holder, std::vector<std::string> member) {
    for (const auto& m : holder)
        if (isInterpolationModifier(m) && std::find(member.begin(), member.end(), m) == member.end()) member.push_back(m);
    return member;
}

class Flattener {
public:
    explicit Flattener(const EffectSyntax& syntax) : syntax_(syntax) {}
    std::string error;

    // Appends the leaves of `type access[dims] : semantic`; `modifiers` are the declaration's own
    // (interpolation, row_major ...). Semantics follow signature_layout.h.
    bool flatten(const std::string& type, const std::string& access, const std::string& semantic,
                 const std::vector<int>& dims, const std::vector<std::string>& modifiers, std::vector<Leaf>& out,
                 int depth = 0, SemanticCascade* cascade = nullptr) {
        if (depth > 8) {
            error = "structures nested too deeply at '" + access + "'";
            return false;
        }
        std::vector<std::string> elements = arrayElementAccesses(access, dims);
        if (elements.empty()) {
            const bool unsized = std::find(dims.begin(), dims.end(), 0) != dims.end();
            error = unsized ? "array '" + access + "' has a size that is no constant (a macro the application defines, left undefined?)"
                            : "array '" + access + "' is too large to be a shader input or output";
            return false;
        }
        if (const FxStruct* s = syntax_.findStruct(syntax_.resolveType(type))) {
            SemanticCascade own = SemanticCascade::from(semantic);
            SemanticCascade* c = cascade ? cascade : (own.active ? &own : nullptr);
            for (const auto& e : elements)
                for (const auto& m : s->members) {
                    // A resource member is bound, not part of the signature; fxc refuses one with a semantic.
                    if (isObjectMember(m) && m.semantic.empty()) continue;
                    if (!flatten(m.type, e + "." + m.name, m.semantic, m.arrayDims, withInterpolationOf(modifiers, m.modifiers), out,
                                 depth + 1, c))
                        return false;
                }
            return true;
        }
        BasicType b = describeBasicType(syntax_.resolveType(type));
        if (!b.ok) {
            error = typeError(type, access);
            return false;
        }
        if (semantic.empty() && !cascade) {
            error = "'" + access + "' has no semantic; every shader input and output needs one";
            return false;
        }
        std::vector<std::string> interpolation;
        for (const auto& m : modifiers)
            if (isInterpolationModifier(m)) interpolation.push_back(m);
        const int registers = signatureRegisters(b, modifiers);
        const bool rowMajor = std::find(modifiers.begin(), modifiers.end(), "row_major") != modifiers.end();
        // A one-row or one-column matrix parameter or result is a vector in the rewritten source
        // (degenerate_matrices.h): its registers are its components, or the whole vector.
        const bool asVector = depth == 0 && b.isMatrix && (b.rows == 1 || b.columns == 1);
        const bool columns = b.isMatrix && !rowMajor && !asVector;
        auto [base, index] = cascade ? cascade->take(registers * int(elements.size())) : splitSemantic(semantic);
        for (size_t e = 0; e < elements.size(); ++e) {
            for (int r = 0; r < registers; ++r) {
                Leaf leaf;
                leaf.access = elements[e];
                if (asVector && registers > 1) leaf.access += "[" + std::to_string(r) + "]";
                else if (b.isMatrix && !asVector && !columns) leaf.access += "[" + std::to_string(r) + "]";
                leaf.scalar = b.scalar;
                leaf.components = signatureWidth(b, modifiers);
                leaf.column = columns ? r : -1;
                leaf.semanticBase = base;
                leaf.semanticIndex = index + int(e) * registers + r;
                leaf.interpolation = interpolation;
                out.push_back(leaf);
            }
        }
        return true;
    }

private:
    const EffectSyntax& syntax_;

    bool isObjectMember(const FxStructMember& m) const {
        return !syntax_.findStruct(syntax_.resolveType(m.type)) && !describeBasicType(syntax_.resolveType(m.type)).ok && isObjectType(m.type);
    }

    static bool isObjectType(const std::string& type) {
        static const char* const objectPrefixes[] = {"sampler", "Sampler", "texture", "Texture", "Buffer", "RW", "Structured",
                                                     "ByteAddress", "InputPatch", "OutputPatch", "PointStream", "LineStream",
                                                     "TriangleStream", "string"};
        for (const char* prefix : objectPrefixes)
            if (type.rfind(prefix, 0) == 0) return true;
        return false;
    }

    std::string typeError(const std::string& type, const std::string& access) const {
        // A name no declaration gives (a fragment meant to follow a header the engine prepends):
        // said so, rather than naming the wrapper's own variables.
        return isObjectType(type) || syntax_.typedefs.count(type) ? "type '" + type + "' of '" + access + "' cannot be a shader input or output"
                                                                  : "type '" + type + "' is not declared: no struct or typedef of that name";
    }
};

// The value of a leaf as an r-value: a matrix column is gathered from its rows.
std::string leafValue(const Leaf& leaf) {
    if (leaf.column < 0) return leaf.access;
    std::string v = (leaf.scalar == "dword" ? std::string("uint") : leaf.scalar) + (leaf.components > 1 ? std::to_string(leaf.components) : "") + "(";
    for (int r = 0; r < leaf.components; ++r)
        v += (r ? ", " : "") + leaf.access + "[" + std::to_string(r) + "][" + std::to_string(leaf.column) + "]";
    return v + ")";
}

// Statements storing `value` into a leaf: a matrix column is scattered to its rows.
std::string assignLeaf(const Leaf& leaf, const std::string& value) {
    if (leaf.column < 0) return "    " + leaf.access + " = " + value + ";\n";
    static const char kSwizzle[] = "xyzw";
    std::string out;
    for (int r = 0; r < leaf.components && r < 4; ++r)
        out += "    " + leaf.access + "[" + std::to_string(r) + "][" + std::to_string(leaf.column) + "] = (" + value + ")." + kSwizzle[r] + ";\n";
    return out;
}

std::string widen(const std::string& expr, int n) {
    switch (n) {
    case 1: return "float4(" + expr + ", 0, 0, 0)";
    case 2: return "float4(" + expr + ", 0, 0)";
    case 3: return "float4(" + expr + ", 0)";
    default: return "float4(" + expr + ")";
    }
}
// Pixel-shader outputs: a scalar is replicated like fxc does for `float PS() : COLOR0`.
std::string widenOutput(const std::string& expr, int n) {
    switch (n) {
    case 1: return "((float4)(" + expr + "))";
    case 2: return "float4(" + expr + ", 0, 1)";
    case 3: return "float4(" + expr + ", 1)";
    default: return "float4(" + expr + ")";
    }
}
std::string narrow(const std::string& v, int n) {
    switch (n) {
    case 1: return v + ".x";
    case 2: return v + ".xy";
    case 3: return v + ".xyz";
    default: return v;
    }
}

std::vector<std::string> splitArguments(const std::string& args) {
    std::vector<std::string> out;
    int depth = 0;
    std::string cur;
    for (char c : args) {
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
        if (c == ',' && depth == 0) {
            out.emplace_back(trim(cur));
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!trim(cur).empty()) out.emplace_back(trim(cur));
    return out;
}

std::string interpolationPrefix(const Leaf& leaf) {
    std::string out;
    for (const auto& m : leaf.interpolation) out += m + " ";
    return out;
}

bool has(const std::vector<std::string>& v, const char* s);

// Whether a pixel shader with these inputs runs once per sample: D3D's rule, an SV_SampleIndex
// input or one declared `sample`.
bool runsPerSample(const std::vector<Leaf>& inputs) {
    for (const Leaf& leaf : inputs)
        if (leaf.semanticBase == "SV_SAMPLEINDEX" || has(leaf.interpolation, "sample")) return true;
    return false;
}

// A float input of a shader that runs per sample, read where D3D evaluates it. GL evaluates every
// input (and gl_FragCoord) of such a shader at the sample's position; D3D only those declared
// `sample`, the others at the pixel centre, or the centroid for `centroid` ones.
std::string evaluatedAsD3D(const Leaf& leaf, const std::string& input) {
    if (has(leaf.interpolation, "sample") || has(leaf.interpolation, "nointerpolation")) return input;
    if (has(leaf.interpolation, "centroid")) return "EvaluateAttributeAtCentroid(" + input + ")";
    return "EvaluateAttributeSnapped(" + input + ", int2(0, 0))";
}

bool callsEvaluateAttribute(const EffectSyntax& syntax) {
    for (const Token& t : syntax.tokens)
        if (t.isIdent() && t.text.rfind("EvaluateAttribute", 0) == 0) return true;
    return false;
}

bool hasGlobal(const EffectSyntax& syntax, const std::string& name) {
    for (const auto& g : syntax.globals)
        if (g.name == name) return true;
    // A uniform sampler or texture parameter's global (uniform_resource_parameters.h).
    return syntax.findSampler(name) != nullptr || syntax.findTexture(name) != nullptr;
}

bool has(const std::vector<std::string>& v, const char* s) {
    for (const auto& x : v)
        if (x == s) return true;
    return false;
}

bool writesPosition(const std::vector<Leaf>& outputs) {
    for (const Leaf& leaf : outputs)
        if ((leaf.semanticBase == "POSITION" && leaf.semanticIndex == 0) || leaf.semanticBase == "SV_POSITION") return true;
    return false;
}

}  // namespace

EntryWrapper buildEntryWrapper(const EffectSyntax& syntax, const FxFunction& entry, const ShaderProfile& profile,
                               const std::string& arguments, bool nextToGeometryShader) {
    EntryWrapper w;
    const bool vertex = profile.stage == ShaderStage::Vertex;
    Flattener flat(syntax);
    std::vector<Leaf> inputs, outputs;
    std::vector<std::string> locals, callArgs;
    std::vector<std::string> literalArgs = splitArguments(arguments);
    size_t nextLiteral = 0;

    for (size_t i = 0; i < entry.parameters.size(); ++i) {
        const FxParameter& p = entry.parameters[i];
        std::string dims;
        for (int d : p.arrayDims) dims += "[" + std::to_string(d) + "]";
        if (has(p.modifiers, "uniform")) {
            // A literal goes through the parameter's own type: glslang 12 makes `VS(0)` for a `uniform
            // bool` an int condition (invalid GLSL, or a crash in spirv-opt), where fxc converts.
            if (nextLiteral < literalArgs.size())
                callArgs.push_back(describeBasicType(p.type).ok && p.arrayDims.empty()
                                       ? p.type + "(" + literalArgs[nextLiteral++] + ")"
                                       : literalArgs[nextLiteral++]);
            else if (!p.defaultValue.empty()) callArgs.push_back(syntax.text(p.defaultValue));
            else if (hasGlobal(syntax, p.name)) callArgs.push_back(p.name);  // the effect parameter fx_parser declared, as fxc makes one
            else {
                w.error = "uniform parameter '" + p.name + "' of '" + entry.name + "' gets no value: give it in the compile statement, e.g. compile " +
                          profile.name + " " + entry.name + "(value)";
                return w;
            }
            continue;
        }
        std::string local = "a" + std::to_string(i);
        locals.push_back(degenerateAsVector(p.type) + " " + local + dims + ";");
        callArgs.push_back(local);
        bool isOut = has(p.modifiers, "out") || has(p.modifiers, "inout");
        bool isIn = !has(p.modifiers, "out");
        if ((isIn && !flat.flatten(p.type, local, p.semantic, p.arrayDims, p.modifiers, inputs)) ||
            (isOut && !flat.flatten(p.type, local, p.semantic, p.arrayDims, p.modifiers, outputs))) {
            // The message names the wrapper's local (`a0.Verts`): say the parameter's own name.
            if (size_t at = flat.error.find("'" + local); at != std::string::npos) flat.error.replace(at + 1, local.size(), p.name);
            break;
        }
    }
    if (!flat.error.empty()) {
        w.error = flat.error + " (in '" + entry.name + "')";
        return w;
    }
    if (nextLiteral < literalArgs.size()) {
        w.error = "'" + entry.name + "' is compiled with " + std::to_string(literalArgs.size()) + " argument(s) but has only " +
                  std::to_string(nextLiteral) + " uniform parameter(s)";
        return w;
    }
    bool returns = entry.returnType != "void";
    // A one-row or one-column matrix returned is a vector to glslang (degenerate_matrices.h); its
    // declared type and majority say which registers it takes.
    const std::string returnType = keywordIdentifierSpelled(entryReturnType(syntax, entry));
    if (returns && !flat.flatten(entry.returnType, "r", entry.returnSemantic, {}, entryReturnModifiers(syntax, entry), outputs)) {
        w.error = flat.error + " (the return value of '" + entry.name + "')";
        return w;
    }

    std::ostringstream params, fill, outStruct, copyOut;
    bool firstParam = true;
    auto addParam = [&](const std::string& decl) {
        params << (firstParam ? "" : ", ") << decl;
        firstParam = false;
    };
    bool fragCoordDeclared = false, frontFaceDeclared = false;
    // The shader's own EvaluateAttribute* calls need the input itself (glslang follows the wrapper's
    // copy back to it), so its inputs stay plain copies there.
    const bool perSample = !vertex && runsPerSample(inputs);
    const bool evaluatesItself = perSample && callsEvaluateAttribute(syntax);
    int n = 0;
    std::map<std::string, std::string> inputNames;  // semantic -> wrapper parameter
    // A vertex element two members read (Source SDK's skin_vs20.fxc: `float3 vTangentS : TANGENT;`
    // and `float4 vUserData : TANGENT;`) is one input as wide as the widest of them; each member
    // takes its first components, as D3D9 fetches the element for each.
    std::map<std::string, int> inputWidths;  // semantic -> components of the widest leaf on it
    for (const Leaf& leaf : inputs) {
        int& width = inputWidths[leaf.semanticBase + std::to_string(leaf.semanticIndex)];
        width = std::max(width, leaf.components);
    }
    for (const Leaf& leaf : inputs) {
        std::string sem = leaf.semanticBase + std::to_string(leaf.semanticIndex);
        std::string name = "i" + std::to_string(n++);
        // Elements of an array of structs repeat their members' semantics (fxc reads one register
        // for them all): the first input declared on a semantic feeds the others.
        auto seen = inputNames.find(sem);
        const bool repeat = seen != inputNames.end();
        if (repeat) name = seen->second;
        else inputNames[sem] = name;
        if (vertex) {
            if (leaf.semanticBase == "SV_VERTEXID" || leaf.semanticBase == "SV_INSTANCEID") {
                if (!repeat) addParam("uint " + name + " : " + leaf.semanticBase);
            } else if (leaf.semanticBase == "SV_POSITION" && profile.isD3D9()) {
                // fxc reads an SV_Position vertex input as POSITION at SM2/3 (XNA's own stock
                // shaders declare one); the vertex declaration's Position element feeds it.
                if (!repeat) addParam(vectorType(leaf.scalar, leaf.components) + " " + name + " : POSITION" + std::to_string(leaf.semanticIndex));
            } else {
                const int width = inputWidths[sem];
                // GLSL has no bool vertex attribute: a bool input reads a uint one (nonzero is true).
                if (!repeat) addParam(vectorType(leaf.scalar == "bool" ? "uint" : leaf.scalar, width) + " " + name + " : " + sem);
                fill << assignLeaf(leaf, width > leaf.components ? narrow(name, leaf.components) : name);
                continue;
            }
            fill << assignLeaf(leaf, name);
            continue;
        }
        // Pixel shader inputs.
        const std::string& b = leaf.semanticBase;
        // From SM4 on POSITIONn is a user semantic like any other (only SV_Position is the pixel's
        // position): NvCloth's and FaceWorks' shaders pass a world position on POSITION0 beside it.
        if ((b == "POSITION" && profile.major < 4) || b == "SV_POSITION" || b == "VPOS") {
            if (!fragCoordDeclared) addParam("float4 fxport_fragCoord : SV_Position");
            fragCoordDeclared = true;
            // D3D9 VPOS counts pixels from 0 at pixel centres; GL's gl_FragCoord has them at +0.5.
            std::string v = b == "VPOS" ? "(fxport_fragCoord - float4(0.5, 0.5, 0, 0))" : "fxport_fragCoord";
            if (perSample && !has(leaf.interpolation, "sample")) v = "float4(floor(fxport_fragCoord.xy) + 0.5, fxport_fragCoord.zw)";
            fill << assignLeaf(leaf, narrow(v, leaf.components));
        } else if (b == "VFACE" || b == "SV_ISFRONTFACE") {
            if (!frontFaceDeclared) addParam("bool fxport_frontFace : SV_IsFrontFace");
            frontFaceDeclared = true;
            fill << assignLeaf(leaf, b == "VFACE" ? "(fxport_frontFace ? 1.0 : -1.0)" : "fxport_frontFace");
        } else if (b == "SV_COVERAGE") {
            if (!repeat) addParam("nointerpolation uint " + name + " : " + kSampleMaskInSemantic);
            fill << assignLeaf(leaf, name);
        } else if (b.rfind("SV_", 0) == 0) {
            // Clip and cull distances keep their index: SV_ClipDistance1 is another register.
            const bool distance = b == "SV_CLIPDISTANCE" || b == "SV_CULLDISTANCE";
            if (!repeat) addParam(vectorType(leaf.scalar, leaf.components) + " " + name + " : " + (distance ? sem : b));
            fill << assignLeaf(leaf, name);
        } else if (isIntegerScalar(leaf.scalar)) {
            if (!repeat) addParam("nointerpolation " + vectorType(leaf.scalar == "bool" ? "uint" : leaf.scalar, leaf.components) + " " + name + " : " + sem);
            fill << assignLeaf(leaf, name);
        } else if (nextToGeometryShader) {
            const std::string interp = interpolationPrefix(leaf);
            if (!repeat) addParam(interp + vectorType(leaf.scalar, leaf.components) + " " + name + " : " + sem);
            fill << assignLeaf(leaf, perSample && !evaluatesItself ? evaluatedAsD3D(leaf, name) : name);
        } else {
            const std::string interp = interpolationPrefix(leaf);
            if (!repeat) addParam(interp + "float4 " + name + " : " + sem);
            fill << assignLeaf(leaf, narrow(perSample && !evaluatesItself ? evaluatedAsD3D(leaf, name) : name, leaf.components));
        }
    }

    // From vs_4_0 on, fxc takes a vertex shader that writes no position: it feeds a hull or
    // geometry shader (SubD11's control-point VS), so its outputs keep their declared types as
    // beside one.
    if (vertex && profile.major >= 4 && !writesPosition(outputs)) nextToGeometryShader = true;
    std::string positionMember;
    // POSITION0 is the position up to SM3; from SM4 on only when no SV_Position is written (fxc
    // without /Gec would not rasterise it; taken as the position, it also stays the user varying
    // a pixel shader of SM4 reads on POSITION0).
    const bool writesSvPosition = std::any_of(outputs.begin(), outputs.end(), [](const Leaf& l) { return l.semanticBase == "SV_POSITION"; });
    int m = 0;
    for (const Leaf& leaf : outputs) {
        const std::string& b = leaf.semanticBase;
        std::string name = "o" + std::to_string(m++);
        if (vertex) {
            const bool position = b == "SV_POSITION" || (b == "POSITION" && leaf.semanticIndex == 0 && !nextToGeometryShader &&
                                                         (profile.major < 4 || !writesSvPosition));
            if (position) {
                outStruct << "    float4 " << name << " : SV_Position;\n";
                copyOut << "    o." << name << " = " << widen(leafValue(leaf), leaf.components) << ";\n";
                if (leaf.components < 4) copyOut << "    o." << name << ".w = 1;\n";
                positionMember = name;
                if (b == "POSITION" && profile.major >= 4) {
                    const std::string varying = "o" + std::to_string(m++);
                    outStruct << "    float4 " << varying << " : POSITION0;\n";
                    copyOut << "    o." << varying << " = " << widen(leafValue(leaf), leaf.components) << ";\n";
                }
            } else if (profile.major < 4 && ((b == "PSIZE" && leaf.components > 1) || (b == "FOG" && profile.major < 3 && leaf.components > 1))) {
                // D3D9's oPts and (before vs_3_0) oFog registers hold one float (fxc rejects more).
                w.error = "vertex shader output '" + leaf.access + "' has semantic " + b + " in " + profile.name +
                          ": it holds one float, not " + std::to_string(leaf.components) + " components";
                return w;
            } else if (b == "SV_RENDERTARGETARRAYINDEX" || b == "SV_VIEWPORTARRAYINDEX") {
                // glslang makes the semantic as written gl_Layer / gl_ViewportIndex (pre_raster_builtins.h)
                // and the one with an index a user varying, which is what a geometry shader reads. The
                // wrapper writes both unless it knows a geometry shader follows (D3D11's stages are
                // compiled apart: one may).
                const std::string type = vectorType(leaf.scalar == "int" ? "int" : "uint", 1);
                if (!nextToGeometryShader) {
                    outStruct << "    " << type << " " << name << " : " << b << ";\n";
                    copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
                    name = "o" + std::to_string(m++);
                }
                outStruct << "    nointerpolation " << type << " " << name << " : " << b << leaf.semanticIndex << ";\n";
                copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
            } else if (b.rfind("SV_", 0) == 0) {
                outStruct << "    " << vectorType(leaf.scalar, leaf.components) << " " << name << " : " << b << leaf.semanticIndex << ";\n";
                copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
            } else if (nextToGeometryShader) {
                const std::string interp = interpolationPrefix(leaf);
                outStruct << "    " << interp << vectorType(leaf.scalar, leaf.components) << " " << name << " : " << b << leaf.semanticIndex << ";\n";
                copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
            } else if (isIntegerScalar(leaf.scalar)) {
                outStruct << "    nointerpolation " << vectorType(leaf.scalar == "bool" ? "uint" : leaf.scalar, leaf.components) << " " << name
                          << " : " << b << leaf.semanticIndex << ";\n";
                copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
            } else {
                const std::string interp = interpolationPrefix(leaf);
                outStruct << "    " << interp << "float4 " << name << " : " << b << leaf.semanticIndex << ";\n";
                std::string value = widen(leafValue(leaf), leaf.components);
                // vs_1_1..vs_2_x colour outputs are clamped to [0, 1] by D3D9 (oD0/oD1 registers).
                if (b == "COLOR" && profile.major < 3) value = "saturate(" + value + ")";
                copyOut << "    o." << name << " = " << value << ";\n";
            }
        } else {
            if (b == "COLOR" || b == "SV_TARGET") {
                std::string target = "SV_Target" + std::to_string(leaf.semanticIndex);
                if (isIntegerScalar(leaf.scalar)) {
                    outStruct << "    " << vectorType(leaf.scalar, leaf.components) << " " << name << " : " << target << ";\n";
                    copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
                } else {
                    outStruct << "    float4 " << name << " : " << target << ";\n";
                    copyOut << "    o." << name << " = " << widenOutput(leafValue(leaf), leaf.components) << ";\n";
                }
            } else if (b == "DEPTH" || b == "SV_DEPTH" || b == "SV_DEPTHLESSEQUAL" || b == "SV_DEPTHGREATEREQUAL") {
                // SM5's conservative depth outputs promise only which way the depth moves (an early-Z
                // hint); written as the plain depth they mean the same value.
                outStruct << "    float " << name << " : SV_Depth;\n";
                copyOut << "    o." << name << " = " << narrow("(float4)(" + leafValue(leaf) + ")", 1) << ";\n";
            } else if (b == "SV_COVERAGE") {
                outStruct << "    uint " << name << " : SV_Coverage;\n";
                copyOut << "    o." << name << " = " << leafValue(leaf) << ";\n";
            } else {
                w.error = "pixel shader output '" + leaf.access + "' has semantic " + b + std::to_string(leaf.semanticIndex) +
                          ", which is not a render target (COLORn / SV_Targetn) or depth";
                return w;
            }
        }
    }
    if (vertex && positionMember.empty() && !nextToGeometryShader) {
        w.error = "vertex shader '" + entry.name + "' writes no position (POSITION or SV_Position)";
        return w;
    }
    // A pixel shader without outputs (a depth-only pass, maybe with clip()) is fine from ps_3_0 on;
    // fxc rejects it for ps_1_x/ps_2_x (X4530), so does fxport.
    bool noOutputs = m == 0 && !vertex;
    if (noOutputs && profile.major < 3) {
        w.error = "pixel shader '" + entry.name + "' has no output: " + profile.name +
                  " pixel shaders must minimally write all four components of COLOR0 (fxc X4530; ps_3_0 and later may write nothing)";
        return w;
    }

    std::ostringstream code;
    code << "\n// ---- generated by fxport: entry wrapper for " << entry.name << " (" << profile.name << ")\n";
    w.usesPixelOffset = vertex && profile.isD3D9();
    if (!noOutputs) code << "struct fxport_Output {\n" << outStruct.str() << "};\n";
    // [earlydepthstencil] on the entry: the depth-stencil test runs before the shader (a UAV write of
    // a hidden fragment never happens); the attribute belongs on the function GL runs.
    if (!vertex && hasAttribute(entry, "earlydepthstencil")) code << "[earlydepthstencil]\n";
    code << (noOutputs ? "void " : "fxport_Output ") << kWrapperEntry << "(" << params.str() << ") {\n";
    if (hasInitializerCalls(syntax)) code << "    " << kStaticInitializerScopes << "();\n";  // static_initializer_calls.h
    for (const auto& l : locals) code << "    " << l << "\n";
    code << fill.str();
    std::string call = entry.name + "(";
    for (size_t i = 0; i < callArgs.size(); ++i) call += (i ? ", " : "") + callArgs[i];
    call += ")";
    if (returns) code << "    " << returnType << " r = " << call << ";\n";
    else code << "    " << call << ";\n";
    if (noOutputs) {
        code << "}\n";
        w.code = code.str();
        return w;
    }
    code << "    fxport_Output o;\n" << copyOut.str();
    code << "    return o;\n}\n";
    w.code = code.str();
    return w;
}

}  // namespace fxport::xlate
