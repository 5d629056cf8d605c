#include "fx_rewrite.h"

#include "matrix_swizzle.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <set>

#include "matrix_swizzle.h"
#include "render_states.h"
#include "source_map.h"
#include "text_util.h"

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

private:
    std::map<std::string, int> ids_;
    std::vector<int> parent_;
    std::vector<std::optional<TextureKind>> kind_;
    std::vector<size_t> where_;
};

}  // namespace

namespace {

std::string applyEdits(const std::string& text, std::vector<TextEdit> edits) {
    // Outer edits first where two start together (`shared` blanked inside a blanked declaration).
    std::sort(edits.begin(), edits.end(), [](const TextEdit& a, const TextEdit& b) {
        return a.begin != b.begin ? a.begin < b.begin : a.end > b.end;
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

namespace {

bool isAssignmentOperator(const Token& t) {
    static const std::set<std::string> k = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
    return t.kind == Token::Kind::Punct && k.count(t.text) > 0;
}

// Where `name` at token i is the target of an assignment or of ++/--: `Scale *= 2`, `Tint.a = 1`,
// `W[i] += x`, `++Count`. (<<= and >>= arrive as single characters, so they are not seen.)
bool isWrittenAt(const std::vector<Token>& t, size_t i, size_t end) {
    if (i > 0 && (t[i - 1].is("++") || t[i - 1].is("--"))) return true;
    size_t j = i + 1;
    while (j < end) {
        if (t[j].is(".") && j + 1 < end && t[j + 1].isIdent()) {
            j += 2;
        } else if (t[j].is("[")) {
            int depth = 0;
            for (; j < end; ++j) {
                if (t[j].is("[")) ++depth;
                if (t[j].is("]") && --depth == 0) break;
            }
            ++j;
        } else {
            break;
        }
    }
    return j < end && (isAssignmentOperator(t[j]) || t[j].is("++") || t[j].is("--"));
}

// A parameter or local of that name hides the global in this function.
bool hidesGlobal(const FxFunction& f, const std::vector<Token>& t, const std::string& name) {
    for (const auto& p : f.parameters)
        if (p.name == name) return true;
    static const std::set<std::string> statementWords = {"return", "else", "do", "case", "goto"};
    for (size_t i = f.body.begin + 1; i + 1 < f.body.end; ++i)
        if (t[i].isIdent() && t[i].text == name && t[i - 1].isIdent() && !statementWords.count(t[i - 1].text) &&
            (t[i + 1].is("=") || t[i + 1].is(";") || t[i + 1].is(",") || t[i + 1].is("[") || t[i + 1].is(":")))
            return true;
    return false;
}

// fxc lets a shader assign to a global uniform (`Scale *= 2;`): the shader then works on its own
// copy, made from the uniform when it starts. glslang refuses ("l-value required"). Each such
// global gets `static T fxport_copy_NAME = NAME;` after its declaration, and every function that
// does not hide it uses the copy; the uniform itself stays the effect's parameter.
void copyAssignedUniforms(const EffectSyntax& syntax, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    for (const auto& g : syntax.globals) {
        bool constant = std::find_if(g.modifiers.begin(), g.modifiers.end(), [](const std::string& m) { return m == "static" || m == "const"; }) !=
                        g.modifiers.end();
        if (constant || g.isStringParameter) continue;
        bool written = false;
        for (const auto& f : syntax.functions)
            for (size_t i = f.body.begin; i < f.body.end && !written; ++i)
                written = t[i].isIdent() && t[i].text == g.name && !(i > 0 && t[i - 1].is(".")) && isWrittenAt(t, i, f.body.end) &&
                          !hidesGlobal(f, t, g.name);
        if (!written) continue;
        size_t end = g.token;
        for (int depth = 0; end < t.size() && t[end].kind != Token::Kind::End; ++end) {
            if (t[end].is("(") || t[end].is("{") || t[end].is("[")) ++depth;
            if (t[end].is(")") || t[end].is("}") || t[end].is("]")) --depth;
            if (depth == 0 && t[end].is(";")) break;
        }
        if (t[end].kind == Token::Kind::End) continue;
        const std::string copy = "fxport_copy_" + g.name;
        std::string dims;
        for (int d : g.arrayDims) dims += "[" + (d > 0 ? std::to_string(d) : std::string()) + "]";
        std::string type = g.type;
        for (const auto& m : g.modifiers)
            if (m == "row_major" || m == "column_major") type = m + " " + type;
        edits.push_back({t[end].end, t[end].end, " static " + type + " " + copy + dims + " = " + g.name + ";"});
        for (const auto& f : syntax.functions) {
            if (hidesGlobal(f, t, g.name)) continue;
            for (size_t i = f.body.begin; i < f.body.end; ++i)
                if (t[i].isIdent() && t[i].text == g.name && !(i > 0 && t[i - 1].is("."))) edits.push_back({t[i].offset, t[i].end, copy});
        }
    }
}

// Index one past the statement that starts at token i: a `{...}` block, or tokens to the `;` at
// depth 0 (an `if`/`for` header's parentheses are passed over).
size_t statementEnd(const std::vector<Token>& t, size_t i, size_t end) {
    int depth = 0;
    for (; i < end; ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
        else if (t[i].is(")") || t[i].is("]") || t[i].is("}")) {
            if (--depth == 0 && t[i].is("}")) return i + 1;
        } else if (depth == 0 && t[i].is(";")) {
            return i + 1;
        }
    }
    return end;
}

// fxc (as C++ compilers of its time) puts a variable declared in a `for` header in the enclosing
// scope: `for (int i = 0; ...) ...; for (i = 1; ...)` uses the same `i`. Where a header's variable is
// used after its loop, the declaration moves in front of the loop (`int i; for (i = 0; ...)`); a
// later header declaring the same name again at the same brace depth (fxc's warning X3078) then
// assigns it instead.
void hoistLoopVariablesUsedAfterTheLoop(const EffectSyntax& syntax, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    static const std::set<std::string> statementWords = {"return", "else", "do", "case", "goto"};
    for (const auto& f : syntax.functions) {
        std::map<std::string, size_t> hoisted;  // name -> the '{' of the block its declaration moved into
        std::vector<size_t> blocks = {f.body.begin};  // open blocks, innermost last (the body: its first token)
        for (size_t i = f.body.begin; i < f.body.end; ++i) {
            if (t[i].is("{")) blocks.push_back(i);
            if (t[i].is("}") && blocks.size() > 1) blocks.pop_back();
            if (!(t[i].is("for") && i + 3 < f.body.end && t[i + 1].is("(") && t[i + 2].isIdent() && t[i + 3].isIdent())) continue;
            // Names declared in the header: after the type, and after each ',' at depth 1.
            size_t typeToken = i + 2, initEnd = i + 2;
            std::vector<std::string> names;
            for (int d = 0; initEnd < f.body.end; ++initEnd) {
                if (t[initEnd].is("(") || t[initEnd].is("[") || t[initEnd].is("{")) ++d;
                if (t[initEnd].is(")") || t[initEnd].is("]") || t[initEnd].is("}")) --d;
                if (d == 0 && t[initEnd].is(";")) break;
                if (d == 0 && (initEnd == typeToken + 1 || t[initEnd - 1].is(",")) && t[initEnd].isIdent()) names.push_back(t[initEnd].text);
            }
            size_t headerClose = initEnd;
            for (int d = 1; headerClose < f.body.end && d > 0; ++headerClose) {
                if (t[headerClose].is("(")) ++d;
                if (t[headerClose].is(")")) --d;
            }
            size_t loopEnd = statementEnd(t, headerClose, f.body.end);
            // Used (not declared again) after the loop, before the enclosing block closes.
            bool usedAfter = false;
            for (size_t k = loopEnd, d = 0; k < f.body.end && !usedAfter; ++k) {
                if (t[k].is("{")) ++d;
                if (t[k].is("}") && d-- == 0) break;
                bool declared = t[k - 1].isIdent() && !statementWords.count(t[k - 1].text);
                for (const auto& n : names) usedAfter |= t[k].isIdent() && t[k].text == n && !t[k - 1].is(".") && !declared;
            }
            auto earlier = names.empty() ? hoisted.end() : hoisted.find(names.front());
            bool reuse = earlier != hoisted.end() && earlier->second == blocks.back();
            if (!usedAfter && !reuse) continue;
            std::string declaration;
            if (!reuse) {
                for (const auto& n : names) declaration += (declaration.empty() ? t[typeToken].text + " " : ", ") + n;
                declaration += "; ";
                for (const auto& n : names) hoisted[n] = blocks.back();
            }
            edits.push_back({t[i].offset, t[i].offset, declaration});
            edits.push_back({t[typeToken].offset, t[typeToken].end, std::string(t[typeToken].text.size(), ' ')});
        }
    }
}

// Components of a vector type name: float3 -> 3, half -> 1; 0 for anything else.
int vectorWidth(const std::string& type) {
    static const std::set<std::string> scalars = {"float", "half", "int", "uint", "bool", "double", "min16float", "min10float", "min16int"};
    if (scalars.count(type)) return 1;
    if (type.size() < 2 || !scalars.count(type.substr(0, type.size() - 1))) return 0;
    char n = type.back();
    return n >= '1' && n <= '4' ? n - '0' : 0;
}

// Components an l-value argument of `float4(a.xy, b) = v` stands for: a swizzle's length, or the
// width of a variable declared before it (parameter, local or global); 0 when unknown.
int lvalueWidth(const EffectSyntax& syntax, const FxFunction& f, size_t begin, size_t end) {
    const auto& t = syntax.tokens;
    if (end >= begin + 3 && t[end - 2].is(".") && t[end - 1].isIdent()) {
        const std::string& sw = t[end - 1].text;
        bool swizzle = sw.size() <= 4 && (sw.find_first_not_of("xyzw") == std::string::npos || sw.find_first_not_of("rgba") == std::string::npos);
        return swizzle ? int(sw.size()) : 0;
    }
    if (end != begin + 1 || !t[begin].isIdent()) return 0;
    const std::string& name = t[begin].text;
    // A local declared before: `float2 a;` or a later declarator of `float2 a, b;` (the type is
    // the statement's first word past storage modifiers).
    for (size_t i = begin; i-- > f.body.begin + 1;) {
        if (!t[i].isIdent() || t[i].text != name || !(t[i - 1].isIdent() || t[i - 1].is(","))) continue;
        size_t s = i;
        while (s > f.body.begin && !t[s - 1].is(";") && !t[s - 1].is("{") && !t[s - 1].is("}")) --s;
        while (s < i && (t[s].is("const") || t[s].is("static") || t[s].is("uniform"))) ++s;
        if (s < i && t[s].isIdent()) return vectorWidth(syntax.resolveType(t[s].text));
    }
    for (const auto& p : f.parameters)
        if (p.name == name) return vectorWidth(syntax.resolveType(p.type));
    for (const auto& g : syntax.globals)
        if (g.name == name && g.arrayDims.empty()) return vectorWidth(syntax.resolveType(g.type));
    return 0;
}

// `float4(a.xy, b.zw) = ddx(p);` (a constructor as the target, which fxc takes) assigns the parts:
// `{ float4 fxport_parts0 = ddx(p); a.xy = fxport_parts0.xy; b.zw = fxport_parts0.zw; }`.
void splitConstructorAssignments(const std::string& text, const EffectSyntax& syntax, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    int serial = 0;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
            const Token& prev = t[i - 1];
            int width = t[i].isIdent() ? vectorWidth(syntax.resolveType(t[i].text)) : 0;
            if (width < 2 || !t[i + 1].is("(") || !(prev.is(";") || prev.is("{") || prev.is("}") || prev.is(")") || prev.is("else"))) continue;
            size_t close = i + 1;
            for (int d = 0; close < f.body.end; ++close) {
                if (t[close].is("(")) ++d;
                if (t[close].is(")") && --d == 0) break;
            }
            if (close + 1 >= f.body.end || !t[close + 1].is("=")) continue;
            size_t semicolon = close + 1;
            for (int d = 0; semicolon < f.body.end && !(d == 0 && t[semicolon].is(";")); ++semicolon) {
                if (t[semicolon].is("(") || t[semicolon].is("[") || t[semicolon].is("{")) ++d;
                if (t[semicolon].is(")") || t[semicolon].is("]") || t[semicolon].is("}")) --d;
            }
            if (semicolon >= f.body.end) continue;
            const std::string parts = "fxport_parts" + std::to_string(serial);
            std::string assigns;
            int used = 0;
            for (size_t a = i + 2; a <= close && used >= 0;) {
                size_t b = a;
                for (int d = 0; b < close && !(d == 0 && t[b].is(",")); ++b) {
                    if (t[b].is("(") || t[b].is("[")) ++d;
                    if (t[b].is(")") || t[b].is("]")) --d;
                }
                int w = b > a ? lvalueWidth(syntax, f, a, b) : 0;
                if (w == 0 || used + w > width) {
                    used = -1;
                    break;
                }
                assigns += " " + text.substr(t[a].offset, t[b - 1].end - t[a].offset) + " = " + parts + "." + std::string("xyzw").substr(size_t(used), size_t(w)) + ";";
                used += w;
                a = b + 1;
            }
            if (used != width) continue;
            ++serial;
            edits.push_back({t[i].offset, t[close + 1].end, "{ " + t[i].text + " " + parts + " ="});
            edits.push_back({t[semicolon].end, t[semicolon].end, assigns + " }"});
            i = semicolon;
        }
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
    for (const auto& f : syntax->functions) {
        if (!f.hasStreamParameter || keep.count(f.name) || f.declaration.empty()) continue;
        const Token& first = syntax->tokens[f.declaration.begin];
        const Token& last = syntax->tokens[f.declaration.end - 1];
        all.push_back({first.offset, last.end, {}});
    }
    return applyEdits(*sourceText, std::move(all));
}

RewrittenEffect rewriteEffect(const std::string& text, const EffectSyntax& syntax, const SourceMap& map,
                              std::vector<Diagnostic>& diagnostics) {
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
            if (isDx9Sampler(f.parameters[i].type)) {
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
            if (f.parameters[i].name == name && isDx9Sampler(f.parameters[i].type))
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
                            bool parameter = std::any_of(f.parameters.begin(), f.parameters.end(), [&](const FxParameter& p) { return p.name == name; });
                            if (parameter || !syntax.findSampler(name))
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
                    if (index >= g.parameters.size() || !isDx9Sampler(g.parameters[index].type)) continue;
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
        for (const auto& a : s.states) translateSamplerAssignment(a, stateContext, es.state, es.textureParameter);
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
    std::set<int> usedTextureUnits;
    for (const auto& t : syntax.textures)
        if (!t.dx9Object && t.explicitUnit >= 0) {
            out.textureUnits[t.name] = t.explicitUnit;
            usedTextureUnits.insert(t.explicitUnit);
        }
    for (const auto& t : syntax.textures) {
        if (t.dx9Object || out.textureUnits.count(t.name)) continue;
        int u = 0;
        while (usedTextureUnits.count(u)) ++u;
        out.textureUnits[t.name] = u;
        usedTextureUnits.insert(u);
    }

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
                                  : std::string(dx9SamplerType(es.kind)) + " " + s.name + " : register(s" + std::to_string(es.unit) + ");";
        for (const auto& a : aliases)
            if (a.sampler == s.name) decl += std::string(" ") + dx9SamplerType(a.kind) + " " + a.alias + " : register(s" + std::to_string(es.unit) + ");";
        edits.push_back({b, e, decl});
    }
    for (const auto& f : syntax.functions)
        for (size_t i = 0; i < f.parameters.size(); ++i)
            if (isUntypedSampler(f.parameters[i].type)) {
                auto k = slots.kind(slots.slot("p:" + functionKey(f) + ":" + std::to_string(i))).value_or(TextureKind::Texture2D);
                const Token& t = tokens[f.parameters[i].typeToken];
                edits.push_back({t.offset, t.end, dx9SamplerType(k)});
            }
    // glslang's HLSL front end takes no `half` (nor min16float ...) as the component type of
    // vector<T, N> / matrix<T, R, C>; `half` alone it maps to float, as fxc does for SM4 (and SM2-3
    // only treat it as a precision hint), so the template argument becomes float too.
    for (size_t i = 0; i + 2 < tokens.size(); ++i) {
        const Token& t = tokens[i + 2];
        if ((tokens[i].text == "vector" || tokens[i].text == "matrix") && tokens[i + 1].is("<") && t.isIdent() &&
            (t.text == "half" || t.text == "min16float" || t.text == "min10float"))
            edits.push_back({t.offset, t.end, "float"});
    }
    // `const static int N = 4;` is a constant to fxc as `static const` is; glslang keeps the last
    // storage word only, so N would be a plain static and `float w[N + 1]` no constant size.
    for (size_t i = 0; i + 1 < tokens.size(); ++i)
        if (tokens[i].text == "const" && tokens[i + 1].text == "static") edits.push_back({tokens[i].offset, tokens[i + 1].end, "static const"});
    edits.insert(edits.end(), aliasEdits.begin(), aliasEdits.end());
    copyAssignedUniforms(syntax, edits);
    hoistLoopVariablesUsedAfterTheLoop(syntax, edits);
    splitConstructorAssignments(text, syntax, edits);
    for (auto& e : lowerMatrixSwizzles(tokens)) edits.push_back(std::move(e));
    out.sourceText = &text;
    out.syntax = &syntax;
    out.edits = std::move(edits);
    out.hlsl = out.hlslForGeometryShader({});
    return out;
}

}  // namespace fxport::xlate
