// Effect-framework parser. It walks top-level declarations of the preprocessed text, records what
// glslang cannot read (techniques, passes, sampler_state, texture objects, state objects, shader
// variables, annotations, string parameters), and marks those byte ranges for removal. Everything it
// does not recognise as effect syntax is left for glslang, which is the authority on plain HLSL.
#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>

#include "fx/constant_eval.h"
#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"
#include "fx/source_map.h"
#include "fx/text_util.h"
#include "fx/unsigned_types.h"

namespace fxport::xlate {

const FxFunction* EffectSyntax::findFunction(const std::string& name) const {
    for (const auto& f : functions)
        if (f.name == name) return &f;
    return nullptr;
}
static size_t countArguments(const std::string& arguments) {
    if (arguments.find_first_not_of(" \t") == std::string::npos) return 0;
    size_t n = 1;
    int depth = 0;
    for (char c : arguments) {
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
        if (c == ',' && depth == 0) ++n;
    }
    return n;
}
const FxFunction* EffectSyntax::findEntry(const std::string& name, const std::string& literalArguments) const {
    const size_t given = countArguments(literalArguments);
    const FxFunction* first = nullptr;
    const FxFunction* takes = nullptr;
    const FxFunction* takesFewer = nullptr;  // some uniforms left over: made parameters of the effect
    auto later = [](const FxFunction* best, const FxFunction& f) { return !best || f.firstDeclared > best->firstDeclared; };
    for (const auto& f : functions) {
        if (f.name != name) continue;
        if (!first) first = &f;
        size_t uniforms = 0, required = 0;
        for (const auto& p : f.parameters)
            if (std::find(p.modifiers.begin(), p.modifiers.end(), "uniform") != p.modifiers.end()) {
                ++uniforms;
                if (p.defaultValue.empty()) ++required;
            }
        if (given <= uniforms && given >= required && later(takes, f)) takes = &f;
        if (given < uniforms && later(takesFewer, f)) takesFewer = &f;
    }
    return takes ? takes : takesFewer ? takesFewer : first;
}
const FxStruct* EffectSyntax::findStruct(const std::string& name) const {
    for (const auto& s : structs)
        if (s.name == name) return &s;
    return nullptr;
}
const FxSampler* EffectSyntax::findSampler(const std::string& name) const {
    for (const auto& s : samplers)
        if (s.name == name) return &s;
    return nullptr;
}
const FxTexture* EffectSyntax::findTexture(const std::string& name) const {
    for (const auto& t : textures)
        if (t.name == name) return &t;
    return nullptr;
}
const std::string& EffectSyntax::resolveType(const std::string& type) const {
    auto it = typedefs.find(type);
    return it == typedefs.end() ? type : it->second;
}
std::string EffectSyntax::text(TokenSpan span) const {
    std::string out;
    for (size_t i = span.begin; i < span.end && i < tokens.size(); ++i) {
        if (!out.empty()) out += ' ';
        if (tokens[i].kind == Token::Kind::String) out += '"' + tokens[i].text + '"';
        else out += tokens[i].text;
    }
    return out;
}

namespace {

bool isTechniqueKeyword(const std::string& s) {
    return iequals(s, "technique") || iequals(s, "technique10") || iequals(s, "technique11");
}
// DX9 texture objects. The DX10 spellings (Texture2D ...) are DX10 objects unless a DX9
// sampler_state names them (decided after parsing, see Parser::run).
bool isDx9TextureType(const std::string& s) {
    if (s == "Texture1D" || s == "Texture2D" || s == "Texture3D" || s == "TextureCube") return false;
    return iequals(s, "texture") || iequals(s, "texture1D") || iequals(s, "texture2D") || iequals(s, "texture3D") ||
           iequals(s, "textureCUBE");
}
bool isDx10TextureType(const std::string& full) {
    const std::string s = full.substr(0, full.find('<'));  // Texture2D<float4>
    static const char* const k[] = {"Texture1D", "Texture2D", "Texture3D", "TextureCube", "Texture1DArray",
                                    "Texture2DArray", "TextureCubeArray", "Texture2DMS", "Texture2DMSArray", "Buffer"};
    for (const char* t : k)
        if (s == t) return true;
    return false;
}
bool isDx9SamplerType(const std::string& s) {
    return iequals(s, "sampler") || iequals(s, "sampler1D") || iequals(s, "sampler2D") || iequals(s, "sampler3D") ||
           iequals(s, "samplerCUBE");
}
bool isDx10SamplerType(const std::string& s) {
    return iequals(s, "SamplerState") || iequals(s, "SamplerComparisonState");
}
bool isStateObjectType(const std::string& s) {
    return iequals(s, "BlendState") || iequals(s, "DepthStencilState") || iequals(s, "RasterizerState");
}
bool isShaderObjectType(const std::string& s) {
    return iequals(s, "VertexShader") || iequals(s, "PixelShader") || iequals(s, "GeometryShader") || iequals(s, "HullShader") ||
           iequals(s, "DomainShader") || iequals(s, "ComputeShader");
}
// Effects 10's render-target and depth-stencil view variables: the application sets them through
// the effect; no shader reads them (fxc takes them in a plain shader too, vkd3d's null L55).
bool isViewObjectType(const std::string& s) { return s == "RenderTargetView" || s == "DepthStencilView"; }
// A resource a global declares, which `= NULL` leaves unbound (fxc takes that initializer).
bool isResourceObjectType(const std::string& s) {
    for (const char* prefix : {"Texture", "RWTexture", "Buffer", "RWBuffer", "StructuredBuffer", "RWStructuredBuffer",
                               "AppendStructuredBuffer", "ConsumeStructuredBuffer", "ByteAddressBuffer", "RWByteAddressBuffer"})
        if (s.rfind(prefix, 0) == 0) return true;
    return false;
}
bool isTypeModifier(const std::string& s) {
    static const std::set<std::string> k = {"static", "const", "uniform", "extern", "shared", "volatile", "precise",
                                            "row_major", "column_major", "inline", "groupshared", "nointerpolation",
                                            "linear", "centroid", "noperspective", "sample", "snorm", "unorm", "export"};
    return k.count(toLower(s)) > 0 && s == toLower(s);
}
bool isParameterModifier(const std::string& s) {
    static const std::set<std::string> k = {"in", "out", "inout", "uniform", "const", "nointerpolation", "linear",
                                            "centroid", "noperspective", "sample", "point", "line", "triangle",
                                            "lineadj", "triangleadj", "row_major", "column_major", "precise"};
    return k.count(s) > 0;
}

class Parser {
public:
    Parser(const std::string& text, const SourceMap& map, bool looseShaders) : text_(text), map_(map) {
        syntax_.tokens = tokenize(text);
        syntax_.looseShaders = looseShaders;
        if (auto refused = mergeUnsignedTypes(syntax_.tokens, syntax_.edits)) fail(diag::kSyntax, refused->second, refused->first);
    }

    EffectSyntax run() {
        while (!isEnd()) parseTopLevel();
        // In SM4 code `sampler` is another name for SamplerState: a plain `sampler S` used as the
        // sampler argument of Texture.Sample(S, ...) (Gather, CalculateLevelOfDetail) is a DX10
        // sampler, not a DX9 one.
        for (auto& smp : syntax_.samplers) {
            if (smp.dx10 || !iequals(smp.type, "sampler")) continue;
            for (size_t i = 0; i + 3 < syntax_.tokens.size(); ++i) {
                const std::string& m = tok(i + 1).text;
                if (tok(i).is(".") && (m.rfind("Sample", 0) == 0 || m.rfind("Gather", 0) == 0 || m.rfind("CalculateLevelOfDetail", 0) == 0) &&
                    tok(i + 2).is("(") &&
                    tok(i + 3).text == smp.name) {
                    smp.dx10 = true;
                    smp.type = "SamplerState";
                    break;
                }
            }
        }
        for (auto& t : syntax_.textures) {
            if (t.dx9Object) continue;
            // A Texture2D named by a DX9 sampler_state is the DX9 texture of that sampler, unless
            // code uses it as an object too (`T.Sample(s, uv)`: effects mixing DX10 objects with
            // DX9-style sampler blocks). A DX10 SamplerState's `Texture = <T>` binds nothing.
            bool namedBySamplerState = false;
            for (const auto& s : syntax_.samplers)
                for (const auto& a : s.states)
                    if (!s.dx10 && iequals(a.name, "texture"))
                        for (size_t i = a.value.begin; i < a.value.end; ++i) namedBySamplerState |= tok(i).text == t.name;
            bool usedInCode = false;
            for (const auto& f : syntax_.functions)
                for (size_t i = f.body.begin; i < f.body.end && !usedInCode; ++i) usedInCode = tok(i).isIdent() && tok(i).text == t.name;
            if (namedBySamplerState && !usedInCode) t.dx9Object = true;
        }
        // fxc takes the DX9 spellings (texture, texture2D, textureCUBE ...) as DX10 objects too
        // where SM4 code calls their methods: `texture2D T; ... T.Sample(s, uv)`.
        std::set<size_t> retypedStatements;
        for (auto& t : syntax_.textures)
            if (t.dx9Object && usedAsObject(t.name)) {
                t.dx9Object = false;
                t.type = dx10TextureType(t.type);
                retypedStatements.insert(t.declaration.begin);
            }
        rewriteTextureStatements(retypedStatements);
        declareTexturesNamedOnlyBySamplers();
        declareUniformEntryParameters();
        return std::move(syntax_);
    }

private:
    // `T.Method(` or `T` passed as an argument, inside some function body.
    bool usedAsObject(const std::string& name) const {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i < f.body.end; ++i)
                if (tok(i).isIdent() && tok(i).text == name &&
                    (tok(i + 1).is(".") || ((tok(i - 1).is("(") || tok(i - 1).is(",")) && (tok(i + 1).is(")") || tok(i + 1).is(",")))))
                    return true;
        return false;
    }
    static std::string dx10TextureType(const std::string& dx9) {
        switch (textureKindOfName(dx9)) {
        case 1: return "Texture1D";
        case 3: return "Texture3D";
        case 6: return "TextureCube";
        default: return "Texture2D";
        }
    }
    static int textureKindOfName(const std::string& type) {
        std::string t = toLower(type);
        return t.find("cube") != std::string::npos ? 6 : t.find("3d") != std::string::npos ? 3 : t.find("1d") != std::string::npos ? 1 : 2;
    }
    // MonoGame's effect processor makes the texture parameter of `sampler_state { Texture = <Name>; }`
    // when the effect never declares `Name` (its templates leave the declaration out): so does fxport,
    // as a DX9 `texture` declared where the sampler names it. A name declared as something else
    // stays an error (effect_compiler).
    void declareTexturesNamedOnlyBySamplers() {
        std::set<std::string> declared;
        for (const auto& t : syntax_.textures) declared.insert(t.name);
        for (const auto& g : syntax_.globals) declared.insert(g.name);
        for (const auto& s : syntax_.samplers) declared.insert(s.name);
        for (const auto& s : syntax_.samplers) {
            for (const auto& a : s.states) {  // MonoGame reads `Texture =` in SamplerState blocks too
                if (!iequals(a.name, "texture")) continue;
                size_t i = a.value.begin;
                while (i < a.value.end && (tok(i).is("<") || tok(i).is("("))) ++i;
                if (i >= a.value.end || !tok(i).isIdent() || declared.count(tok(i).text)) continue;
                FxTexture t;
                t.name = tok(i).text;
                t.type = "texture";
                t.dx9Object = true;
                t.token = i;
                syntax_.textures.push_back(std::move(t));
                declared.insert(tok(i).text);
            }
        }
    }
    // `uniform bool hasShadow` of an entry compiled as `PS()`: fxc puts it in the shader's constant
    // table under its own name, a parameter the application sets. So does fxport: a global of that
    // name and type is declared at the end of the effect, and the entry wrapper passes it.
    void declareUniformEntryParameters() {
        std::vector<FxShaderExpr> compiles;
        for (const auto& t : syntax_.techniques)
            for (const auto& p : t.passes)
                for (const auto& a : p.assignments)
                    if (isShaderStateName(a.name)) compiles.push_back(parseShaderExpr(syntax_, a.value));
        for (const auto& v : syntax_.shaderVariables) compiles.insert(compiles.end(), v.elements.begin(), v.elements.end());
        std::set<std::string> declared;
        for (const auto& g : syntax_.globals) declared.insert(g.name);
        for (const auto& e : compiles) {
            if (e.kind != FxShaderExpr::Kind::Compile) continue;
            const FxFunction* f = syntax_.findEntry(e.entry, e.arguments);
            if (!f) continue;
            size_t literals = countArguments(e.arguments), k = 0;
            for (const auto& p : f->parameters) {
                if (std::find(p.modifiers.begin(), p.modifiers.end(), "uniform") == p.modifiers.end()) continue;
                if (k++ < literals || !p.defaultValue.empty() || p.name.empty() || !declared.insert(p.name).second) continue;
                if (isDx9SamplerType(p.type) || isDx10SamplerType(p.type) || isDx9TextureType(p.type) || isDx10TextureType(p.type)) continue;
                FxGlobal g;
                g.name = p.name;
                g.type = p.type;
                g.modifiers = {"uniform"};
                g.arrayDims = p.arrayDims;
                g.token = p.typeToken;
                syntax_.globals.push_back(g);
                std::string dims;
                for (int d : p.arrayDims) dims += "[" + std::to_string(d) + "]";
                syntax_.edits.push_back({text_.size(), text_.size(), " " + p.type + " " + p.name + dims + ";"});
            }
        }
    }
    static bool isShaderStateName(const std::string& name) {
        static const char* const k[] = {"VertexShader", "PixelShader", "GeometryShader", "HullShader", "DomainShader", "ComputeShader",
                                        "SetVertexShader", "SetPixelShader", "SetGeometryShader", "SetHullShader", "SetDomainShader",
                                        "SetComputeShader"};
        for (const char* n : k)
            if (iequals(name, n)) return true;
        return false;
    }
    // One texture statement (`texture A, B;`) holds DX9 textures (removed) and DX10 objects (kept).
    // A statement of DX9 ones only is blanked; one with a texture retyped or removed beside kept
    // ones is written anew, one declaration per kept texture (units come from FxTexture).
    void rewriteTextureStatements(const std::set<size_t>& retyped) {
        std::map<size_t, std::vector<const FxTexture*>> statements;
        for (const auto& t : syntax_.textures) statements[t.declaration.begin].push_back(&t);
        for (const auto& [begin, list] : statements) {
            TokenSpan decl = list.front()->declaration;
            std::string kept;
            bool removed = false;
            for (const FxTexture* t : list) {
                if (t->dx9Object) removed = true;
                else kept += t->type + " " + t->name + "; ";
            }
            if (kept.empty()) blank(decl.begin, decl.end);
            else if (removed || retyped.count(begin))
                syntax_.edits.push_back({tok(decl.begin).offset, tok(decl.end - 1).end, kept});
        }
    }

    const std::string& text_;
    const SourceMap& map_;
    EffectSyntax syntax_;
    size_t pos_ = 0;

    // --- token helpers -------------------------------------------------------------------
    const Token& tok(size_t i) const { return syntax_.tokens[std::min(i, syntax_.tokens.size() - 1)]; }
    const Token& cur() const { return tok(pos_); }
    const Token& peek(size_t k = 1) const { return tok(pos_ + k); }
    bool isEnd() const { return cur().kind == Token::Kind::End; }
    bool accept(std::string_view p) {
        if (cur().kind != Token::Kind::String && cur().text == p) {
            ++pos_;
            return true;
        }
        return false;
    }

    [[noreturn]] void fail(const char* id, const std::string& message, size_t tokenIndex) const {
        const Token& t = tok(tokenIndex);
        throw CompileError({map_.make(Severity::Error, id, message, t.line, t.column,
                                      t.kind == Token::Kind::End ? std::string() : t.text)});
    }
    void expect(std::string_view p, const char* what) {
        if (accept(p)) return;
        if (isEnd()) fail(diag::kUnterminated, std::string("unexpected end of file: expected '") + std::string(p) + "' " + what, pos_);
        fail(diag::kSyntax, std::string("expected '") + std::string(p) + "' " + what + ", found '" + cur().text + "'", pos_);
    }
    std::string expectIdentifier(const char* what) {
        if (cur().isIdent()) return syntax_.tokens[pos_++].text;
        if (isEnd()) fail(diag::kUnterminated, std::string("unexpected end of file: expected ") + what, pos_);
        fail(diag::kSyntax, std::string("expected ") + what + ", found '" + cur().text + "'", pos_);
    }

    // Skips a balanced group starting at an opening bracket; returns the index after its closer.
    size_t skipGroup(size_t i, const char* context) const {
        const std::string open = tok(i).text;
        const std::string close = open == "(" ? ")" : open == "[" ? "]" : open == "{" ? "}" : ">";
        int depth = 0;
        size_t start = i;
        for (; tok(i).kind != Token::Kind::End; ++i) {
            const Token& t = tok(i);
            if (t.kind == Token::Kind::String) continue;
            if (t.text == open) ++depth;
            else if (t.text == close && --depth == 0) return i + 1;
        }
        fail(diag::kUnterminated, std::string("'") + open + "' of " + context + " is never closed", start);
    }

    void blank(size_t firstToken, size_t endToken) {
        if (endToken <= firstToken) return;
        size_t b = tok(firstToken).offset;
        size_t e = endToken < syntax_.tokens.size() ? tok(endToken - 1).end : text_.size();
        syntax_.edits.push_back({b, e, {}});
    }

    // `float f { ... };` in a loose-shader compile: fxc parses a state block on any variable and
    // ignores it. It is blanked with a warning that names what is ignored; in an effect it stays a
    // syntax error.
    void ignoreStateBlock(const std::string& name) {
        if (!syntax_.looseShaders || !cur().is("{")) return;
        size_t open = pos_, after = skipGroup(pos_, ("state block of '" + name + "'").c_str());
        const Token& t = tok(open);
        syntax_.warnings.push_back(map_.make(Severity::Warning, diag::kIgnoredState,
                                             "the state block of '" + name + "' is ignored (fxc ignores state blocks outside an effect)",
                                             t.line, t.column, t.text));
        blank(open, after);
        pos_ = after;
    }

    // --- annotations ---------------------------------------------------------------------
    // `< type name = value; ... >`: returns the list; pos_ ends after '>'.
    std::vector<Annotation> parseAnnotations() {
        std::vector<Annotation> list;
        size_t open = pos_;
        expect("<", "to open annotations");
        while (!accept(">")) {
            if (isEnd()) fail(diag::kUnterminated, "annotation list is never closed with '>'", open);
            Annotation a;
            while (cur().is("row_major") || cur().is("column_major")) ++pos_;  // `row_major float3x2 m = {...}`
            size_t typeToken = pos_;
            a.type = expectIdentifier("an annotation type");
            size_t nameToken = pos_;
            a.name = expectIdentifier("an annotation name");
            // fxc: an annotation is a number or a string, named once per list.
            if (a.type == "BlendState" || a.type == "DepthStencilState" || a.type == "RasterizerState")
                fail(diag::kSyntax, "annotation '" + a.name + "' is a " + a.type + ": annotations are numbers or strings", typeToken);
            for (const auto& earlier : list)
                if (earlier.name == a.name) fail(diag::kSyntax, "annotation '" + a.name + "' is already declared in this list", nameToken);
            if (accept("[")) {  // array annotation
                while (!accept("]")) {
                    if (isEnd()) fail(diag::kUnterminated, "annotation array size is never closed", open);
                    ++pos_;
                }
            }
            expect("=", "in annotation");
            size_t vb = pos_;
            int depth = 0;
            while (!isEnd() && !(depth == 0 && cur().is(";"))) {
                if (cur().is("{") || cur().is("(")) ++depth;
                if (cur().is("}") || cur().is(")")) --depth;
                if (depth == 0 && cur().is(">")) break;
                ++pos_;
            }
            // fxc: a value is constant; another annotation of the list is none.
            for (size_t k = vb; k < pos_; ++k) {
                bool named = tok(k).isIdent() && tok(k).text == a.name;  // `int a = 1, b = a;`
                for (const auto& earlier : list) named |= tok(k).isIdent() && tok(k).text == earlier.name;
                if (named)
                    fail(diag::kSyntax, "annotation '" + a.name + "' takes its value from annotation '" + tok(k).text + "': annotation values are constants", k);
            }
            // A lone string keeps its text without quotes; anything else is kept as written.
            if (pos_ == vb + 1 && tok(vb).kind == Token::Kind::String) a.value = tok(vb).text;
            else a.value = syntax_.text({vb, pos_});
            if (!accept(";")) fail(diag::kSyntax, "expected ';' after annotation '" + a.name + "', found '" + cur().text + "'", pos_);
            list.push_back(std::move(a));
        }
        return list;
    }

    // --- state blocks: `{ Name[i] = value; ... }` ------------------------------------------
    std::vector<FxAssignment> parseStateBlock(const char* context) {
        std::vector<FxAssignment> list;
        size_t open = pos_;
        expect("{", context);
        while (!accept("}")) {
            if (isEnd()) fail(diag::kUnterminated, std::string(context) + " is never closed with '}'", open);
            if (accept(";")) continue;
            if (syntax_.looseShaders && cur().is("{")) {  // a list of blocks, `{ {...}, {...} }`: ignored there
                ignoreStateBlock("a state block list");
                accept(",");
                continue;
            }
            FxAssignment a;
            a.nameToken = pos_;
            a.name = expectIdentifier("a state name");
            if (accept("[")) {
                const Token& n = cur();
                a.index = std::atoi(n.text.c_str());
                ++pos_;
                expect("]", "after state index");
            }
            if (cur().is("(")) {  // DX10 SetVertexShader(...);
                a.isCall = true;
                size_t after = skipGroup(pos_, context);
                a.value = {pos_ + 1, after - 1};
                pos_ = after;
                expect(";", ("after " + a.name + "(...)").c_str());
                list.push_back(std::move(a));
                continue;
            }
            expect("=", ("after state '" + a.name + "'").c_str());
            size_t vb = pos_;
            int depth = 0;
            while (true) {
                if (isEnd()) fail(diag::kUnterminated, "state '" + a.name + "' has no ';' before the end of the file", a.nameToken);
                const Token& t = cur();
                if (t.kind != Token::Kind::String) {
                    if (t.text == "(" || t.text == "{" || t.text == "[") ++depth;
                    else if (t.text == ")" || t.text == "]") --depth;
                    else if (t.text == "}") {
                        if (depth == 0) fail(diag::kSyntax, "missing ';' after state '" + a.name + "'", pos_ > vb ? pos_ - 1 : a.nameToken);
                        --depth;
                    } else if (t.text == ";" && depth == 0) break;
                }
                ++pos_;
            }
            a.value = {vb, pos_};
            ++pos_;  // ';'
            list.push_back(std::move(a));
        }
        return list;
    }

    // --- techniques ----------------------------------------------------------------------
    void parseTechnique() {
        size_t start = pos_;
        FxTechnique tech;
        tech.token = pos_;
        ++pos_;
        if (cur().isIdent()) tech.name = syntax_.tokens[pos_++].text;
        if (cur().is("<")) tech.annotations = parseAnnotations();
        if (!cur().is("{")) {
            if (isEnd()) fail(diag::kUnterminated, "technique '" + tech.name + "' has no body", start);
            fail(diag::kSyntax, "expected '{' to open technique '" + tech.name + "', found '" + cur().text + "'", pos_);
        }
        ++pos_;
        while (!accept("}")) {
            if (isEnd()) fail(diag::kUnterminated, "technique '" + tech.name + "' is never closed with '}'", start);
            if (accept(";")) continue;
            if (!iequals(cur().text, "pass"))
                fail(diag::kSyntax, "expected 'pass' inside technique '" + tech.name + "', found '" + cur().text + "'", pos_);
            FxPass pass;
            pass.token = pos_;
            ++pos_;
            if (cur().isIdent()) pass.name = syntax_.tokens[pos_++].text;
            if (cur().is("<")) pass.annotations = parseAnnotations();
            if (!cur().is("{")) {
                if (isEnd()) fail(diag::kUnterminated, "pass '" + pass.name + "' has no body", pass.token);
                fail(diag::kSyntax, "expected '{' to open pass '" + pass.name + "', found '" + cur().text + "'", pos_);
            }
            pass.assignments = parseStateBlock("pass");
            tech.passes.push_back(std::move(pass));
        }
        accept(";");
        blank(start, pos_);
        syntax_.techniques.push_back(std::move(tech));
    }

    // Effects 11 `fxgroup Name <annotations> { technique11 ... }`: a named set of techniques. XNA
    // has no groups, so the group is dissolved: its techniques join the effect's list under their
    // own names (or "Group|Name", Effects 11's spelling, when an earlier technique has that name).
    void parseGroup() {
        size_t start = pos_++;
        std::string group = cur().isIdent() ? syntax_.tokens[pos_++].text : std::string();
        if (cur().is("<")) parseAnnotations();
        if (!cur().is("{")) {
            if (isEnd()) fail(diag::kUnterminated, "fxgroup '" + group + "' has no body", start);
            fail(diag::kSyntax, "expected '{' to open fxgroup '" + group + "', found '" + cur().text + "'", pos_);
        }
        if (group.empty()) fail(diag::kSyntax, "an fxgroup needs a name (fxc: it belongs to the global scope)", start);
        size_t techniquesBefore = syntax_.techniques.size();
        blank(start, ++pos_);
        while (!cur().is("}")) {
            if (isEnd()) fail(diag::kUnterminated, "fxgroup '" + group + "' is never closed with '}'", start);
            if (accept(";")) continue;
            if (!cur().isIdent() || !isTechniqueKeyword(cur().text))
                fail(diag::kSyntax, "expected a technique inside fxgroup '" + group + "', found '" + cur().text + "'", pos_);
            parseTechnique();
            FxTechnique& tech = syntax_.techniques.back();
            for (size_t i = 0; i + 1 < syntax_.techniques.size(); ++i)
                if (syntax_.techniques[i].name == tech.name) tech.name = group + "|" + tech.name;
        }
        if (syntax_.techniques.size() == techniquesBefore) fail(diag::kSyntax, "fxgroup '" + group + "' holds no technique; fxc refuses an empty group", start);
        for (const auto& g : syntax_.globals)
            if (g.name == group) fail(diag::kSyntax, "fxgroup '" + group + "' has the name of a variable declared before it", start);
        size_t close = pos_++;
        if (cur().is(";")) ++pos_;
        blank(close, pos_);
    }

    // --- top level -------------------------------------------------------------------------
    void parseTopLevel() {
        const Token& t = cur();
        if (t.is(";")) {
            ++pos_;
            return;
        }
        // `NAME(...)` where a declaration must start is a macro call the preprocessor did not
        // expand: no macro of that name is defined (MonoGame's TECHNIQUE(...) with a Macros.fxh that
        // lacks it, say). Said plainly, rather than "expected '{'" or "expected a name after type".
        if (t.isIdent() && peek().is("("))
            fail(diag::kPreprocessor, "'" + t.text + "(...)' is used like a macro, but no macro '" + t.text +
                                          "' is defined here (is the header that should define it included, and does it define it?)",
                 pos_);
        if (t.isIdent() && isTechniqueKeyword(t.text)) return parseTechnique();
        if (t.isIdent() && t.text == "fxgroup") return parseGroup();
        if ((t.is("interface") || t.is("class")) && peek().isIdent())
            fail(diag::kUnsupported, std::string("HLSL ") + (t.is("class") ? "classes" : "interfaces") + " (dynamic shader linkage: '" + t.text + " " + peek().text +
                                         "') are not supported: fxport compiles each shader with its calls resolved; write the "
                                         "implementation the shader uses as plain functions",
                 pos_);
        if (t.is("struct")) return parseStruct();
        if (t.is("cbuffer") || t.is("tbuffer")) return parseCbuffer();
        // D3D10 effect pools (`shared`) and fx_5_0's `single` (a cbuffer not shared): meaningless here.
        if ((t.is("shared") || (t.is("single") && !syntax_.typedefs.count("single"))) && (peek().is("cbuffer") || peek().is("tbuffer"))) {
            blank(pos_, pos_ + 1);
            ++pos_;
            return parseCbuffer();
        }
        if (t.is("typedef")) {
            // `typedef vector<half, 3> vec3;`: remembered, so declarations typed `vec3` are known
            // numeric types (parameters, entry signatures). The typedef stays for glslang.
            size_t start = pos_++;
            // `typedef row_major float2x2 m_t;` names float2x2 (matrix_majority.cpp keeps its majority).
            while (accept("const") || accept("row_major") || accept("column_major")) continue;
            if (cur().isIdent() && !cur().is("struct")) {
                std::string type = parseTypeName();
                while (cur().isIdent()) {
                    std::string name = syntax_.tokens[pos_++].text;
                    if (!cur().is("[")) syntax_.typedefs[name] = syntax_.resolveType(type);  // arrays: left to glslang
                    parseArrayDims();
                    if (!accept(",")) break;
                }
            }
            while (!isEnd() && !cur().is(";")) pos_ = cur().is("{") ? skipGroup(pos_, "typedef") : pos_ + 1;
            if (isEnd()) fail(diag::kUnterminated, "typedef is cut off by the end of the file", start);
            accept(";");
            return;
        }
        if (t.is("[")) {  // attributes before a function: [maxvertexcount(3)]
            if (pendingAttributes_.empty()) pendingAttributesStart_ = pos_;
            size_t after = skipGroup(pos_, "attribute");
            pendingAttributes_ += syntax_.text({pos_, after});
            pos_ = after;
            return;
        }
        if (t.is("#")) {  // stray directive left by the preprocessor (e.g. #pragma): skip the line
            int line = t.line;
            while (!isEnd() && cur().line == line) ++pos_;
            return;
        }
        if (!t.isIdent()) fail(diag::kSyntax, "unexpected '" + t.text + "' at file scope", pos_);
        parseDeclaration();
    }

    void parseStruct() {
        FxStruct s;
        s.token = pos_;
        ++pos_;
        if (cur().isIdent()) s.name = syntax_.tokens[pos_++].text;
        std::vector<FxStructMember> inherited;
        if (cur().is(":") && !s.name.empty()) inherited = parseStructBase(s.name);  // `struct b : a {`
        if (!cur().is("{")) {  // `struct X var;` use as a type
            pos_ = s.token;
            return parseDeclaration();
        }
        size_t open = pos_++;
        while (!accept("}")) {
            if (isEnd()) fail(diag::kUnterminated, "struct '" + s.name + "' is never closed with '}'", open);
            FxStructMember m;
            size_t memberStart = pos_;
            while (cur().isIdent() && isParameterModifier(cur().text) && !peek().is(";") && !peek().is(":") &&
                   !peek().is("["))
                m.modifiers.push_back(syntax_.tokens[pos_++].text);
            if (cur().is("struct") && peek().isIdent()) ++pos_;  // `struct apple aa;`: the type is apple
            if (skipMemberFunction(s, memberStart)) continue;
            m.type = parseTypeName();
            m.name = expectIdentifier("a struct member name");
            m.arrayDims = parseArrayDims();
            while (accept(":")) {
                std::string sem = expectIdentifier("a semantic");
                if (cur().is("(")) pos_ = skipGroup(pos_, "semantic");  // packoffset(...)
                else m.semantic = sem;
            }
            if (cur().is("<")) {
                size_t a = pos_;
                parseAnnotations();
                blank(a, pos_);
            }
            // `float4 a, b : TEXCOORD1;` declares two members of one type (and modifiers); each has its
            // own dimensions and semantic. Every one is a member: reflection, layout and linkage see them all.
            std::vector<FxStructMember> more;
            while (accept(",")) {
                FxStructMember next;
                next.type = m.type;
                next.modifiers = m.modifiers;
                next.name = expectIdentifier("a struct member name");
                next.arrayDims = parseArrayDims();
                while (accept(":")) {
                    std::string sem = expectIdentifier("a semantic");
                    if (cur().is("(")) pos_ = skipGroup(pos_, "semantic");
                    else next.semantic = sem;
                }
                more.push_back(std::move(next));
            }
            expect(";", ("after member '" + m.name + "' of struct '" + s.name + "'").c_str());
            s.members.push_back(std::move(m));
            for (auto& n : more) s.members.push_back(std::move(n));
        }
        if (!inherited.empty() || !inheritedFunctions_.empty()) inheritMembers(s, std::move(inherited), open);
        std::set<std::string> methods;
        for (const auto& f : s.memberFunctions) methods.insert(f.name);
        for (const auto& f : s.memberFunctions)
            if (f.span.begin > open)  // its own, not a base's copied in
                for (size_t i = f.body + 1; i < f.span.end; ++i)
                    if (callsSibling(i, methods)) syntax_.edits.push_back({tok(i).offset, tok(i).offset, "this."});
        while (!isEnd() && !cur().is(";")) ++pos_;  // optional declarators
        accept(";");
        syntax_.structs.push_back(std::move(s));
    }

    // A member function (`inline bool IsLit() { return options & 1; }`, Wicked Engine's
    // ShaderInterop structs, MAGE's ShadowMap): fxc compiles it, and so does glslang, which calls it
    // on any value of the struct. It is no data member: nothing of the layout, the reflection or
    // the entry signature sees it, so the parser steps over it and leaves its text to glslang.
    bool skipMemberFunction(FxStruct& s, size_t start) {
        size_t i = pos_;
        if (tok(i).is("inline")) ++i;
        if (!tok(i).isIdent()) return false;
        ++i;
        if (tok(i).is("<")) i = skipGroup(i, "a template argument list");  // vector<float, 3> f()
        if (!tok(i).isIdent() || !tok(i + 1).is("(")) return false;
        std::string name = tok(i).text;
        i = skipGroup(i + 1, "a member function's parameters");
        if (tok(i).is(":") && tok(i + 1).isIdent()) i += 2;  // a return semantic
        if (!tok(i).is("{")) return false;
        pos_ = skipGroup(i, "a member function's body");
        syntax_.memberFunctionBodies.push_back({i, pos_});
        s.memberFunctions.push_back({name, {start, pos_}, i});
        accept(";");
        return true;
    }

    // `Sibling(args)` inside a member function: glslang's lookup of an unqualified member call
    // converts no argument (MAGE's `GetRadianceAndAO(cone, m_max_cone_distance)`, a float for a
    // float4: "no matching overloaded function found"); called as `this.Sibling(args)` it
    // converts them as for any call, as fxc does.
    bool callsSibling(size_t i, const std::set<std::string>& methods) const {
        return tok(i).isIdent() && methods.count(tok(i).text) && tok(i + 1).is("(") && !tok(i - 1).is(".") && !tok(i - 1).is("::");
    }

    // `struct b : a {`: fxc's single inheritance. The base must be one struct declared before;
    // its members come first. Returns them; blanks ` : a`.
    std::vector<FxStructMember> parseStructBase(const std::string& name) {
        size_t colon = pos_++;
        const FxStruct* base = cur().isIdent() ? syntax_.findStruct(cur().text) : nullptr;
        if (!base)
            fail(diag::kSyntax, "the base of struct '" + name + "' must be a struct declared before it; '" + cur().text + "' is not", pos_);
        std::vector<FxStructMember> members = base->members;
        inheritedFunctions_ = base->memberFunctions;
        inheritedBase_ = base->name;
        ++pos_;
        if (cur().is(","))
            fail(diag::kSyntax, "struct '" + name + "' names more than one base struct; fxc takes one", pos_);
        if (!cur().is("{")) fail(diag::kSyntax, "expected '{' after the base of struct '" + name + "', found '" + cur().text + "'", pos_);
        blank(colon, pos_);
        return members;
    }

    // The base's members are written out at the top of the derived struct (glslang has no
    // inheritance). A base member the derived struct shadows keeps its place in the layout under a
    // name no source can spell.
    void inheritMembers(FxStruct& s, std::vector<FxStructMember> inherited, size_t open) {
        std::string text;
        for (auto& m : inherited) {
            for (const auto& own : s.members)
                if (own.name == m.name) m.name += "_fxport_base";
            for (const auto& mod : m.modifiers) text += mod + " ";
            text += " " + m.type + " " + m.name;
            for (int d : m.arrayDims) text += "[" + std::to_string(d) + "]";
            if (!m.semantic.empty()) text += " : " + m.semantic;
            text += ";";
        }
        // The base's member functions too (MAGE's `struct OmniLight : PointLight` calls the base's
        // DistanceAttenuation), on the brace's line, token by token, unless the struct defines one
        // of that name itself (its own then stands alone, as a derived definition hides the base's).
        // One it hides is copied under a name of its own, which the struct's `Base::f(...)` calls name.
        std::set<std::string> methods, ownNames;
        for (const auto& f : s.memberFunctions) ownNames.insert(f.name);
        methods = ownNames;
        for (const auto& f : inheritedFunctions_) methods.insert(f.name);
        const size_t ownCount = s.memberFunctions.size();
        for (const auto& f : inheritedFunctions_) {
            const bool own = ownNames.count(f.name) > 0;
            std::string hidden = own ? f.name + "_fxport_" + inheritedBase_ : std::string();
            bool named = false;
            for (size_t i = f.span.begin; i < f.span.end; ++i) {
                bool isName = own && !named && tok(i).is(f.name) && tok(i + 1).is("(");
                named |= isName;
                text += " " + std::string(i > f.body && callsSibling(i, methods) ? "this." : "") + (isName ? hidden : tok(i).text);
            }
            if (!own) {
                s.memberFunctions.push_back(f);
                continue;
            }
            for (size_t k = 0; k < ownCount; ++k)
                for (size_t i = s.memberFunctions[k].span.begin; i + 3 < s.memberFunctions[k].span.end; ++i)
                    if (tok(i).is(inheritedBase_) && tok(i + 1).is("::") && tok(i + 2).is(f.name))
                        syntax_.edits.push_back({tok(i).offset, tok(i + 2).end, "this." + hidden});
        }
        inheritedFunctions_.clear();
        syntax_.edits.push_back({tok(open).end, tok(open).end, " " + text});
        inherited.insert(inherited.end(), s.members.begin(), s.members.end());
        s.members = std::move(inherited);
    }

    void parseCbuffer() {
        ++pos_;
        std::string name = cur().isIdent() ? syntax_.tokens[pos_++].text : std::string();
        // fxc takes two cbuffers of one name (cbuffer.shader_test); glslang would merge them into
        // one block. The later one is renamed for glslang and the reflection.
        if (!name.empty() && std::find(syntax_.cbuffers.begin(), syntax_.cbuffers.end(), name) != syntax_.cbuffers.end()) {
            name += "_fxport" + std::to_string(syntax_.cbuffers.size());
            syntax_.edits.push_back({tok(pos_ - 1).offset, tok(pos_ - 1).end, name});
        }
        syntax_.cbuffers.push_back(name);
        int reg = -1;
        while (accept(":")) {
            expectIdentifier("register");
            if (cur().is("(")) {
                size_t after = skipGroup(pos_, "register");
                const std::string& last = tok(after - 2).text;  // b3 (the last argument); c3 before SM 5.1 (register_reservations.cpp)
                const char letter = last.empty() ? 0 : char(std::tolower(static_cast<unsigned char>(last[0])));
                if (after >= pos_ + 3 && last.size() > 1 && (letter == 'b' || letter == 'c')) reg = std::atoi(last.c_str() + 1);
                pos_ = after;
            }
        }
        syntax_.cbufferRegisters.push_back(reg);
        if (cur().is("<")) {  // `cbuffer cb : register(b1) < int i = 1; >`: annotations, nothing to keep
            size_t a = pos_;
            parseAnnotations();
            blank(a, pos_);
        }
        size_t open = pos_;
        expect("{", ("to open cbuffer " + name).c_str());
        while (!accept("}")) {
            if (isEnd()) fail(diag::kUnterminated, "cbuffer '" + name + "' is never closed with '}'", open);
            if (accept(";")) {  // an empty declaration (HBAO+'s PAD_FLOAT; expands to nothing): fxc takes it, glslang does not
                blank(pos_ - 1, pos_);
                continue;
            }
            parseDeclaration(name);
        }
        accept(";");
    }

    std::vector<int> parseArrayDims() {
        std::vector<int> dims;
        while (cur().is("[")) {
            size_t after = skipGroup(pos_, "array size");
            dims.push_back(after == pos_ + 2 ? 0 : evaluateIntExpression({pos_ + 1, after - 1}));
            // glslang takes a constant size below 1 and lays the array out with a negative size.
            if (dims.back() < 0)
                fail(diag::kArrayTooLarge, "array size '" + syntax_.text({pos_ + 1, after - 1}) +
                                               "' is not a positive number; an array needs 1 to 65536 elements (fxc X3059)",
                     pos_);
            pos_ = after;
        }
        return dims;
    }

    int evaluateIntExpression(TokenSpan span) {
        // Array sizes are usually literals; simple products like [4*2] are evaluated, others -> 0.
        // Saturates at INT_MAX rather than overflowing: a size too large for an int is reported as
        // too large (FX1204) by the compiler, never wrapped into a small or negative one.
        long long value = 0;
        char op = '+';
        for (size_t i = span.begin; i < span.end; ++i) {
            const Token& t = tok(i);
            if (t.kind == Token::Kind::Number) {
                long long v = std::min<long long>(std::strtoll(t.text.c_str(), nullptr, 0), INT_MAX);
                long long r = 0;
                bool overflow = op == '+'   ? __builtin_add_overflow(value, v, &r)
                                : op == '-' ? __builtin_sub_overflow(value, v, &r)
                                : op == '*' ? __builtin_mul_overflow(value, v, &r)
                                            : (r = v ? value / v : 0, false);
                value = overflow ? INT_MAX : std::clamp<long long>(r, INT_MIN, INT_MAX);
            } else if (t.text.size() == 1 && std::string("+-*/").find(t.text[0]) != std::string::npos) {
                op = t.text[0];
            } else {
                return evaluateWithConstants(span);
            }
        }
        return static_cast<int>(value);
    }

    // `float w[N + 1]` with `static const int N = 4;` earlier: fxc sizes arrays by any constant
    // expression of constants declared before. 0 (unknown) where it is not one.
    int evaluateWithConstants(TokenSpan span) const {
        const TypedConstantLookup typed = [this](const std::string& name) -> const TypedConstant* {
            auto it = typedConstants_.find(name);
            return it == typedConstants_.end() ? nullptr : &it->second;
        };
        auto scalars = [this](const std::string& name, bool array) -> const std::vector<double>* {
            auto it = constants_.find(name);
            return array || it == constants_.end() ? nullptr : &it->second;
        };
        auto v = evaluateConstantWith(syntax_, span, scalars, nullptr, false, &typed);
        if (!v || v->size() != 1) return 0;
        if (!std::isfinite((*v)[0])) return -1;  // 1 / 0: no size
        return static_cast<int>(std::clamp<double>((*v)[0], INT_MIN, INT_MAX));
    }
    // Remembers a `static const` / `const` global's value for the array sizes after it.
    void rememberConstant(const FxGlobal& g) {
        bool isConst = std::find(g.modifiers.begin(), g.modifiers.end(), "const") != g.modifiers.end();
        if (!isConst || g.initializer.empty()) return;
        auto v = evaluateConstant(syntax_, g.initializer, constants_);
        if (!v) return;
        if (g.arrayDims.empty() && v->size() == 1) constants_[g.name] = *v;
        // A vector, matrix, struct or array constant: read through subscripts, members and
        // swizzles (`float b[s.m[1]._22]`), as the rewrite's ConstantSizes does.
        else if (auto c = typedConstant(syntax_, g.type, g.arrayDims, std::move(*v))) typedConstants_[g.name] = std::move(*c);
    }
    std::map<std::string, TypedConstant> typedConstants_;
    // `float2 P[] = { {1, 2}, {3, 4}, {5, 6} };`: fxc sizes the array by its initializer (3 elements;
    // NVIDIA SoftShadows' Poisson.fxh), a uniform as a static, so the parameter has that many
    // elements. Only initializers constant_eval reads (numbers, constructors, earlier constants)
    // of numeric types; others keep 0 for glslang to size.
    void sizeFromInitializer(FxGlobal& g) const {
        if (g.arrayDims.empty() || g.arrayDims[0] != 0 || g.initializer.empty()) return;
        BasicType b = describeBasicType(syntax_.resolveType(g.type));
        if (!b.ok) return;
        long long each = b.rows * b.columns;
        for (size_t d = 1; d < g.arrayDims.size(); ++d) each *= std::max(g.arrayDims[d], 0);
        auto v = evaluateConstant(syntax_, g.initializer, constants_);
        if (!v || v->empty() || each <= 0 || v->size() % size_t(each) != 0 || v->size() / size_t(each) > size_t(INT_MAX)) return;
        g.arrayDims[0] = static_cast<int>(v->size() / size_t(each));
    }
    std::map<std::string, std::vector<double>> constants_;

    // `precise NAME` then a declarator's end: a type named `precise` (fxc's modifier needs a type after it).
    bool preciseIsTheType() {
        if (!cur().is("precise") || !peek().isIdent() || pos_ + 2 >= syntax_.tokens.size()) return false;
        const Token& after = syntax_.tokens[pos_ + 2];
        return after.is("(") || after.is(";") || after.is(",") || after.is("=") || after.is(":") || after.is("[") || after.is(")");
    }

    // A type name: identifier, optionally templated (`vector<float, 4>`, `Texture2D<float4>`).
    std::string parseTypeName() {
        std::string type = expectIdentifier("a type");
        if (cur().is("<") && !peek().is(">")) {
            size_t after = skipGroup(pos_, "template arguments");
            type += syntax_.text({pos_, after});
            pos_ = after;
        }
        return type;
    }

    void parseDeclaration(const std::string& cbuffer = {}) {
        size_t start = pos_;
        std::vector<std::string> modifiers;
        std::vector<size_t> sharedTokens;
        while (cur().isIdent() && isTypeModifier(cur().text)) {
            if (preciseIsTheType()) break;  // `typedef float4 precise; precise main()` (keyword_identifiers.h)
            if (cur().text == "shared") sharedTokens.push_back(pos_);
            if (cur().text == "export") blank(pos_, pos_ + 1);  // a library function's linkage: nothing to a whole shader
            modifiers.push_back(syntax_.tokens[pos_++].text);
        }
        if (cur().is("struct") && peek().isIdent()) {  // `uniform struct apple a;` (C's spelling): the type is apple
            if (!syntax_.findStruct(peek().text))  // fxc: not a typedef or a built-in type either
                fail(diag::kSyntax, "'struct " + peek().text + "' names no struct declared before it", pos_ + 1);
            blank(pos_, pos_ + 1);
            ++pos_;
        }
        size_t typeToken = pos_;
        std::string type = parseTypeName();
        if (!cur().isIdent()) {
            if (isEnd()) fail(diag::kUnterminated, "declaration of type '" + type + "' is cut off by the end of the file", typeToken);
            fail(diag::kSyntax, "expected a name after type '" + type + "', found '" + cur().text + "'", pos_);
        }
        size_t nameToken = pos_;
        std::string name = syntax_.tokens[pos_++].text;
        for (size_t s : sharedTokens) blank(s, s + 1);  // DX10 effect-pool keyword, meaningless here

        if (cur().is("(")) return parseFunction(type, name, nameToken, start);

        // A typedef of that name (`typedef float4 texturE;`) is no texture: fxc takes the typedef. So
        // is a struct the source declares (OGRE's `struct Sampler2D { Texture2D t; SamplerState s; }`)
        // no DX9 sampler.
        const bool typedefName = syntax_.typedefs.count(type) > 0;
        const bool userType = typedefName || syntax_.findStruct(type) != nullptr;
        if (!typedefName && (isDx9TextureType(type) || (isDx10TextureType(type) && cbuffer.empty()))) {
            return parseTexture(type, name, nameToken, start, isDx9TextureType(type));
        }
        if ((isDx9SamplerType(type) && !userType) || isDx10SamplerType(type)) return parseSampler(type, name, nameToken, start);
        if (isStateObjectType(type)) return parseStateObject(type, name, nameToken, start);
        if (isViewObjectType(type) && cbuffer.empty()) return parseViewObject(type, name, start);
        if (isShaderObjectType(type)) return parseShaderVariable(type, name, nameToken, start);
        if (iequals(type, "string")) return parseStringParameter(name, nameToken, start);
        parseVariable(type, modifiers, name, nameToken, cbuffer);
    }

    void parseFunction(const std::string& returnType, const std::string& name, size_t nameToken, size_t start) {
        FxFunction f;
        size_t declarationStart = pendingAttributes_.empty() ? start : pendingAttributesStart_;
        f.name = name;
        f.returnType = returnType;
        f.token = nameToken;
        f.attributes = std::move(pendingAttributes_);
        if (!f.attributes.empty()) f.attributeTokens = {declarationStart, start};
        pendingAttributes_.clear();
        size_t close = skipGroup(pos_, ("parameter list of '" + name + "'").c_str());
        // `float2 f(void)`: C's spelling of no parameters, which fxc takes; glslang does not.
        if (close == pos_ + 3 && tok(pos_ + 1).is("void")) blank(pos_ + 1, pos_ + 2);
        // Parameters: split at depth-0 commas.
        size_t i = close == pos_ + 3 && tok(pos_ + 1).is("void") ? close : pos_ + 1;
        while (i < close - 1) {
            size_t j = i;
            int depth = 0;
            while (j < close - 1) {
                const Token& t = tok(j);
                if (t.is("(") || t.is("[") || t.is("{") || t.is("<")) ++depth;
                if (t.is(")") || t.is("]") || t.is("}") || t.is(">")) --depth;
                if (depth == 0 && t.is(",")) break;
                ++j;
            }
            f.parameters.push_back(parseParameter({i, j}, name));
            i = j + 1;
        }
        pos_ = close;
        while (accept(":")) {
            std::string sem = expectIdentifier("a semantic");
            if (cur().is("(")) pos_ = skipGroup(pos_, "semantic");
            else f.returnSemantic = sem;
        }
        if (accept(";")) {  // prototype: its attributes are the function's (below)
            firstPrototypeHasAttributes_.emplace(name, !f.attributes.empty());
            if (!f.attributes.empty()) prototypeAttributes_.emplace(name, PrototypeAttributes{f.attributes, declarationStart, start});
            prototypes_.push_back({name, parameterTypes(f), nameToken, {declarationStart, pos_}});
            return;
        }
        f.firstDeclared = nameToken;
        for (const auto& p : prototypes_)
            if (p.name == name && p.parameterTypes == parameterTypes(f)) {
                if (f.prototypes.empty()) f.firstDeclared = p.token;
                f.prototypes.push_back(p.span);
            }
        if (!cur().is("{")) {
            if (isEnd()) fail(diag::kUnterminated, "function '" + name + "' has no body before the end of the file", nameToken);
            fail(diag::kSyntax, "expected '{' to open the body of function '" + name + "', found '" + cur().text + "'", pos_);
        }
        // fxc (SM 5) takes a function's attributes from its first declaration and drops the later
        // ones ([numthreads(2, 1, 1)] void main(uint2 id); ... void main(...) { }); glslang wants
        // them on the definition.
        // A first declaration without attributes gives the function none: the definition's go too
        // (numthreads L125: `void main(); [numthreads(1, 1, 1)] void main() {}` has no numthreads).
        if (auto first = firstPrototypeHasAttributes_.find(name); first != firstPrototypeHasAttributes_.end() && !first->second) {
            if (!f.attributes.empty()) blank(declarationStart, start);
            f.attributes.clear();
            f.attributeTokens = {};
        } else if (auto proto = prototypeAttributes_.find(name); proto != prototypeAttributes_.end() && start < syntax_.tokens.size()) {
            blank(proto->second.begin, proto->second.end);
            if (!f.attributes.empty()) blank(declarationStart, start);
            syntax_.edits.push_back({tok(start).offset, tok(start).offset, proto->second.text + " "});
            f.attributes = proto->second.text;
            f.attributeTokens = {proto->second.begin, proto->second.end};
        }
        size_t after = skipGroup(pos_, ("body of function '" + name + "'").c_str());
        f.body = {pos_ + 1, after - 1};
        f.declaration = {declarationStart, after};
        f.declarationSites = declarationSites(syntax_.tokens, f.body);
        for (const auto& p : f.parameters) f.hasStreamParameter |= p.type.find("Stream<") != std::string::npos;
        pos_ = after;
        syntax_.functions.push_back(std::move(f));
    }

    FxParameter parseParameter(TokenSpan span, const std::string& function) {
        FxParameter p;
        size_t i = span.begin;
        while (i < span.end && tok(i).isIdent() && isParameterModifier(tok(i).text) && i + 1 < span.end &&
               tok(i + 1).isIdent())
            p.modifiers.push_back(tok(i++).text);
        if (i >= span.end || !tok(i).isIdent())
            fail(diag::kSyntax, "malformed parameter in function '" + function + "'", i < span.end ? i : span.begin);
        if (tok(i).is("struct") && i + 2 < span.end && tok(i + 1).isIdent() && tok(i + 2).isIdent() && syntax_.findStruct(tok(i + 1).text)) {
            blank(i, i + 1);  // `in struct input i` (C's spelling): the type is `input`
            ++i;
        }
        p.typeToken = i;
        p.type = tok(i++).text;
        if (i < span.end && tok(i).is("<")) {
            size_t after = skipGroup(i, "template arguments");
            p.type += syntax_.text({i, after});
            i = after;
        }
        if (i < span.end && tok(i).isIdent()) p.name = tok(i++).text;
        while (i < span.end && tok(i).is("[")) {
            size_t after = skipGroup(i, "array size");
            // A size may be an expression of macros and constants (PRT.fx: `float4 w[NUM_PCA/4]`).
            p.arrayDims.push_back(after == i + 2 ? 0 : evaluateIntExpression({i + 1, after - 1}));
            i = after;
        }
        while (i < span.end && tok(i).is(":")) {
            ++i;
            if (i < span.end && tok(i).isIdent()) {
                std::string sem = tok(i++).text;
                if (i < span.end && tok(i).is("(")) i = skipGroup(i, "semantic");
                else p.semantic = sem;
            }
        }
        if (i < span.end && tok(i).is("=")) p.defaultValue = {i + 1, span.end};
        return p;
    }

    // Declarator tail shared by objects: [dims] (: semantic|register(x))* <annotations>?
    struct Tail {
        std::vector<int> dims;
        std::string semantic;
        int registerIndex = -1;
        char registerClass = 0;  // its letter, lower case
        int packOffset = -1;  // packoffset(cN.y) in floats (checked for overlaps; cbuffer_packing places it)
        std::vector<Annotation> annotations;
        size_t annotationBegin = 0, annotationEnd = 0;
        size_t registerBegin = 0, registerEnd = 0;  // `: register(...)`, the last one
        std::vector<FxRegister> registers;          // all of them
    };
    // The tokens of `packoffset(c4.w)` between the parentheses, as 4 * 4 + 3 floats; -1 where they
    // are not a c-register (glslang reports those).
    int packOffsetIn(size_t begin, size_t end) const {
        std::string text;
        for (size_t i = begin; i < end && text.size() < 16; ++i) text += tok(i).text;
        if (text.size() < 2 || (text[0] != 'c' && text[0] != 'C')) return -1;
        size_t i = 1;
        long long reg = 0;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && reg < 100000) reg = reg * 10 + (text[i++] - '0');
        if (i == 1 || reg >= 100000) return -1;
        int component = 0;
        if (i < text.size()) {
            if (text[i] != '.' || i + 2 != text.size()) return -1;
            const char* comps = "xyzwrgba";  // c0.b is c0.z
            const char* c = std::strchr(comps, std::tolower(static_cast<unsigned char>(text[i + 1])));
            if (!c || !*c) return -1;
            component = int(c - comps) % 4;
        }
        return int(reg) * 4 + component;
    }

    Tail parseDeclaratorTail() {
        Tail tail;
        tail.dims = parseArrayDims();
        while (accept(":")) {
            std::string word = expectIdentifier("a semantic or register");
            if (cur().is("(")) {
                size_t after = skipGroup(pos_, word.c_str());
                if (iequals(word, "register") && after >= pos_ + 3) {
                    tail.registerBegin = pos_ - 2;
                    tail.registerEnd = after;
                    std::string reg = tok(after - 2).text;  // s0, t3, c4 ... (last argument)
                    if (reg.size() > 1) tail.registerIndex = std::atoi(reg.c_str() + 1);
                    if (reg.size() > 1) tail.registerClass = char(std::tolower(static_cast<unsigned char>(reg[0])));
                    FxRegister r;  // register(ps_4_0, t1): the tokens before the comma are the profile
                    size_t comma = pos_ + 1;
                    while (comma + 1 < after && !tok(comma).is(",")) ++comma;
                    if (comma + 1 < after)
                        for (size_t k = pos_ + 1; k < comma; ++k) r.profile += tok(k).text;
                    r.registerClass = tail.registerClass;
                    r.index = reg.size() > 1 ? tail.registerIndex : -1;
                    // register(ps, t[1]): a register written with its index in brackets.
                    if (tok(after - 2).is("]") && after >= pos_ + 6 && tok(after - 4).is("[") && tok(after - 5).text.size() == 1) {
                        r.registerClass = char(std::tolower(static_cast<unsigned char>(tok(after - 5).text[0])));
                        r.index = std::atoi(tok(after - 3).text.c_str());
                    }
                    if (r.index >= 0) tail.registers.push_back(r);
                    // DX9 constant registers (register(c8), register(vs, c8)) place a constant in ONE
                    // stage's register file; the VS and PS files overlap, one GL uniform buffer cannot.
                    // Only SetVertexShaderConstantF-style code cares, which XNA's Effect never is.
                    if (reg[0] == 'c' || reg[0] == 'C' || (after > pos_ + 3)) blank(pos_ - 2, after);
                } else if (iequals(word, "packoffset")) {
                    // cbuffer_packing.cpp places the member; glslang would refuse c0.b and C2.
                    tail.packOffset = packOffsetIn(pos_ + 1, after - 1);
                    if (tail.packOffset >= 0) blank(pos_ - 2, after);
                }
                pos_ = after;
            } else {
                tail.semantic = word;
            }
        }
        if (cur().is("<")) {
            tail.annotationBegin = pos_;
            tail.annotations = parseAnnotations();
            tail.annotationEnd = pos_;
        }
        return tail;
    }

    // Skips an initializer to the ',' or ';' that ends it (depth 0). Returns its span.
    // `T t = NULL;` of a resource: the initializer is fxc's spelling of no object bound, which
    // glslang refuses (a uniform initializer must be constant); ` = NULL` goes. True when it went.
    bool blankNullInitializer(TokenSpan init) {
        if (init.end != init.begin + 1 || !tok(init.begin).is("NULL") || tok(init.begin).kind == Token::Kind::String) return false;
        blank(init.begin - 1, init.end);
        return true;
    }

    // `RenderTargetView rtv = NULL;`: nothing any shader reads, so the declaration goes.
    void parseViewObject(const std::string& type, const std::string& name, size_t start) {
        parseDeclaratorTail();
        if (accept("=")) skipInitializer(name);
        expect(";", ("after " + type + " '" + name + "'").c_str());
        blank(start, pos_);
    }

    TokenSpan skipInitializer(const std::string& name) {
        size_t b = pos_;
        int depth = 0;
        while (true) {
            if (isEnd()) fail(diag::kUnterminated, "declaration of '" + name + "' has no ';' before the end of the file", b);
            const Token& t = cur();
            if (t.kind != Token::Kind::String) {
                if (t.is("(") || t.is("{") || t.is("[")) ++depth;
                else if (t.is(")") || t.is("}") || t.is("]")) --depth;
                else if (depth == 0 && (t.is(";") || t.is(","))) break;
            }
            ++pos_;
        }
        return {b, pos_};
    }

    // `texture T0, T1;` declares several, as fxc takes it. Each records the whole statement: a
    // statement of DX9 textures only is blanked, others are rewritten in Parser::run.
    void parseTexture(const std::string& type, std::string name, size_t nameToken, size_t start, bool dx9) {
        size_t first = syntax_.textures.size();
        while (true) {
            FxTexture tex;
            tex.name = name;
            tex.type = type;
            tex.dx9Object = dx9;
            tex.token = nameToken;
            Tail tail = parseDeclaratorTail();
            tex.arrayDims = tail.dims;
            tex.semantic = tail.semantic;
            tex.explicitUnit = tail.registerIndex;
            tex.registers = tail.registers;
            tex.annotations = tail.annotations;
            ignoreStateBlock(name);
            if (accept("=")) blankNullInitializer(skipInitializer(name));
            if (!dx9 && tail.annotationEnd > tail.annotationBegin) blank(tail.annotationBegin, tail.annotationEnd);
            syntax_.textures.push_back(std::move(tex));
            if (!accept(",")) break;
            nameToken = pos_;
            name = expectIdentifier("a texture name");
        }
        expect(";", ("after texture '" + name + "'").c_str());
        for (size_t i = first; i < syntax_.textures.size(); ++i) syntax_.textures[i].declaration = {start, pos_};
    }

    // `sampler S0, S1 = sampler_state {...};`: each sampler's declaration runs from its first token
    // (the type for the first one) to the ',' or ';' after it, so each is rewritten on its own.
    void parseSampler(const std::string& type, std::string name, size_t nameToken, size_t start) {
        while (true) {
            FxSampler s;
            s.name = name;
            s.type = type;
            s.dx10 = isDx10SamplerType(type);
            s.token = nameToken;
            Tail tail = parseDeclaratorTail();
            if (!tail.dims.empty())
                fail(diag::kUnsupported, "sampler arrays ('" + name + "[]') are not supported", nameToken);
            s.explicitUnit = tail.registerIndex;
            s.registers = tail.registers;
            if (accept("=")) {
                if (!iequals(cur().text, "sampler_state"))
                    fail(diag::kSyntax, "expected 'sampler_state' after '" + name + " =', found '" + cur().text + "'", pos_);
                ++pos_;
                s.states = parseStateBlock("sampler_state");
            } else if (cur().is("{")) {
                s.states = parseStateBlock("sampler state block");
            }
            bool more = cur().is(",");
            if (!more) expect(";", ("after sampler '" + name + "'").c_str());
            else ++pos_;
            s.declaration = {start, pos_};
            syntax_.samplers.push_back(std::move(s));
            if (!more) return;
            start = nameToken = pos_;
            name = expectIdentifier("a sampler name");
        }
    }

    void parseStateObject(const std::string& type, const std::string& name, size_t nameToken, size_t start) {
        FxStateObject o;
        o.type = type;
        o.name = name;
        o.token = nameToken;
        parseDeclaratorTail();
        accept("=");
        if (cur().is("{")) o.assignments = parseStateBlock((type + " block").c_str());
        expect(";", ("after " + type + " '" + name + "'").c_str());
        blank(start, pos_);
        syntax_.stateObjects.push_back(std::move(o));
    }

    void parseShaderVariable(const std::string& type, const std::string& name, size_t nameToken, size_t start) {
        FxShaderVariable v;
        v.name = name;
        v.type = type;
        v.token = nameToken;
        Tail tail = parseDeclaratorTail();
        v.isArray = !tail.dims.empty();
        ignoreStateBlock(name);
        if (accept("=")) {
            if (cur().is("{")) {
                size_t after = skipGroup(pos_, ("initializer of '" + name + "'").c_str());
                size_t i = pos_ + 1;
                while (i < after - 1) {
                    size_t j = i;
                    int depth = 0;
                    while (j < after - 1) {
                        if (tok(j).is("(") || tok(j).is("{")) ++depth;
                        if (tok(j).is(")") || tok(j).is("}")) --depth;
                        if (depth == 0 && tok(j).is(",")) break;
                        ++j;
                    }
                    if (j > i) v.elements.push_back(parseShaderExpr(syntax_, {i, j}));
                    i = j + 1;
                }
                pos_ = after;
            } else {
                TokenSpan init = skipInitializer(name);
                v.elements.push_back(parseShaderExpr(syntax_, init));
            }
        }
        expect(";", ("after shader variable '" + name + "'").c_str());
        blank(start, pos_);
        syntax_.shaderVariables.push_back(std::move(v));
    }

    void parseStringParameter(const std::string& name, size_t nameToken, size_t start) {
        FxGlobal g;
        g.name = name;
        g.type = "string";
        g.token = nameToken;
        g.isStringParameter = true;
        Tail tail = parseDeclaratorTail();
        g.semantic = tail.semantic;
        g.annotations = tail.annotations;
        if (accept("=")) g.initializer = skipInitializer(name);
        expect(";", ("after string '" + name + "'").c_str());
        blank(start, pos_);
        syntax_.globals.push_back(std::move(g));
    }

    void parseVariable(const std::string& type, const std::vector<std::string>& modifiers, std::string name,
                       size_t nameToken, const std::string& cbuffer) {
        while (true) {
            FxGlobal g;
            g.name = name;
            g.type = type;
            g.modifiers = modifiers;
            g.token = nameToken;
            g.cbuffer = cbuffer;
            Tail tail = parseDeclaratorTail();
            g.arrayDims = tail.dims;
            g.semantic = tail.semantic;
            g.packOffset = tail.packOffset;
            g.registerClass = tail.registerClass;
            g.registerIndex = tail.registerIndex;
            // fxc discards any `register(b...)` of a numeric global (`register(banana)` too) at SM 4-5;
            // at SM 2-3 register_reservations.cpp refuses what is no register.
            if (g.registerClass == 'b' && cbuffer.empty() && describeBasicType(syntax_.resolveType(type)).ok && tail.registerEnd > tail.registerBegin)
                blank(tail.registerBegin, tail.registerEnd);
            g.annotations = tail.annotations;
            if (tail.annotationEnd > tail.annotationBegin) blank(tail.annotationBegin, tail.annotationEnd);
            ignoreStateBlock(name);
            if (accept("=")) g.initializer = skipInitializer(name);
            if (isResourceObjectType(type) && blankNullInitializer(g.initializer)) g.initializer = {};
            sizeFromInitializer(g);
            rememberConstant(g);
            syntax_.globals.push_back(std::move(g));
            if (accept(",")) {
                nameToken = pos_;
                name = expectIdentifier("a variable name");
                continue;
            }
            break;
        }
        if (!accept(";")) {
            if (isEnd()) fail(diag::kUnterminated, "declaration of '" + name + "' has no ';' before the end of the file", nameToken);
            fail(diag::kSyntax, "expected ';' after the declaration of '" + name + "', found '" + cur().text + "'", pos_);
        }
    }

    std::string pendingAttributes_;
    std::vector<FxMemberFunction> inheritedFunctions_;  // of the base named by the struct being parsed
    std::string inheritedBase_;
    size_t pendingAttributesStart_ = 0;
    struct PrototypeAttributes {
        std::string text;
        size_t begin = 0, end = 0;  // its tokens
    };
    std::map<std::string, bool> firstPrototypeHasAttributes_;  // by function name: whether its first prototype has attributes
    std::map<std::string, PrototypeAttributes> prototypeAttributes_;  // by function name, the first prototype with attributes
    // Every prototype, in source order: where each overload was first declared (FxFunction::firstDeclared).
    struct Prototype {
        std::string name;
        std::vector<std::string> parameterTypes;
        size_t token = 0;
        TokenSpan span;  // attributes, signature and ';'
    };
    std::vector<Prototype> prototypes_;

    // What tells overloads apart: each parameter's type (typedefs resolved) and array sizes.
    std::vector<std::string> parameterTypes(const FxFunction& f) const {
        std::vector<std::string> types;
        for (const auto& p : f.parameters) {
            std::string type = syntax_.resolveType(p.type);
            for (int d : p.arrayDims) type += "[" + std::to_string(d) + "]";
            types.push_back(std::move(type));
        }
        return types;
    }
};

}  // namespace

FxShaderExpr parseShaderExpr(const EffectSyntax& syntax, TokenSpan span) {
    FxShaderExpr e;
    e.token = span.begin;
    auto t = [&](size_t i) -> const Token& { return syntax.tokens[std::min(i, syntax.tokens.size() - 1)]; };
    // Strip surrounding parentheses: `(VSArray[i])`, and angle brackets: `<PS>` (DX8-era effects).
    while (span.end > span.begin + 1 && ((t(span.begin).is("(") && t(span.end - 1).is(")")) || (t(span.begin).is("<") && t(span.end - 1).is(">")))) {
        ++span.begin;
        --span.end;
    }
    if (span.empty()) return e;
    const Token& first = t(span.begin);
    if (span.end == span.begin + 1 && (iequals(first.text, "NULL") || first.text == "0")) {
        e.kind = FxShaderExpr::Kind::Null;
        return e;
    }
    if (iequals(first.text, "asm")) {
        e.kind = FxShaderExpr::Kind::Asm;
        if (span.end >= span.begin + 3 && t(span.begin + 1).is("{") && t(span.end - 1).is("}")) e.asmBlock = {span.begin + 1, span.end};
        return e;
    }
    if (iequals(first.text, "ConstructGSWithSO") || iequals(first.text, "ConstructGSWithSOExt")) {
        e.kind = FxShaderExpr::Kind::StreamOut;
        if (span.end < span.begin + 3 || !t(span.begin + 1).is("(") || !t(span.end - 1).is(")")) {
            e.kind = FxShaderExpr::Kind::Invalid;
            return e;
        }
        // Split the arguments at the commas outside parentheses.
        std::vector<TokenSpan> arguments;
        size_t start = span.begin + 2;
        int depth = 0;
        for (size_t i = start; i < span.end - 1; ++i) {
            if (t(i).is("(")) ++depth;
            if (t(i).is(")")) --depth;
            if (depth == 0 && t(i).is(",")) arguments.push_back({start, i}), start = i + 1;
        }
        arguments.push_back({start, span.end - 1});
        e.streamShader = arguments.front();
        e.streamArguments.assign(arguments.begin() + 1, arguments.end());
        return e;
    }
    auto parseCall = [&](size_t i, size_t end) {
        // ENTRY ( args )
        if (i >= end || !t(i).isIdent()) return false;
        e.entry = t(i).text;
        if (i + 1 < end && t(i + 1).is("(") && t(end - 1).is(")")) e.arguments = syntax.text({i + 2, end - 1});
        else if (i + 1 != end) return false;
        return true;
    };
    if (iequals(first.text, "compile")) {
        if (span.end < span.begin + 3) return e;
        e.profile = t(span.begin + 1).text;
        if (parseCall(span.begin + 2, span.end)) e.kind = FxShaderExpr::Kind::Compile;
        return e;
    }
    if (iequals(first.text, "CompileShader")) {
        // CompileShader( profile, ENTRY(args) )
        if (span.end < span.begin + 6 || !t(span.begin + 1).is("(") || !t(span.end - 1).is(")")) return e;
        e.profile = t(span.begin + 2).text;
        if (!t(span.begin + 3).is(",")) return e;
        if (parseCall(span.begin + 4, span.end - 1)) e.kind = FxShaderExpr::Kind::Compile;
        return e;
    }
    if (first.isIdent() && span.end == span.begin + 1) {
        e.kind = FxShaderExpr::Kind::Variable;
        e.variable = first.text;
        return e;
    }
    if (first.isIdent() && t(span.begin + 1).is("[") && t(span.end - 1).is("]")) {
        e.kind = FxShaderExpr::Kind::ArrayElement;
        e.variable = first.text;
        e.index = {span.begin + 2, span.end - 1};
        return e;
    }
    return e;
}

EffectSyntax parseEffect(const std::string& text, const SourceMap& map, bool looseShaders) {
    return Parser(text, map, looseShaders).run();
}

}  // namespace fxport::xlate
