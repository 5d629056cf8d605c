// Statement rewrites for what fxc takes in function bodies (see fxc_statements.h).
#include "rewrite/fxc_statements.h"

#include "hlsl/hlsl_types.h"

#include <algorithm>
#include <map>
#include <set>

namespace fxport::xlate {

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

}  // namespace

// fxc lets a shader assign to a global uniform (`Scale *= 2;`): the shader then works on its own
// copy, made from the uniform when it starts. glslang refuses ("l-value required"). Each such
// global gets `static T fxport_copy_NAME = NAME;` after its declaration, and every function that
// does not hide it uses the copy; the uniform itself stays the effect's parameter.
void copyAssignedUniforms(const EffectSyntax& syntax, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    for (const auto& g : syntax.globals) {
        // groupshared memory (compute shaders) is written by design: shared by the thread group, never a uniform.
        bool constant = std::find_if(g.modifiers.begin(), g.modifiers.end(), [](const std::string& m) {
                            return m == "static" || m == "const" || m == "groupshared";
                        }) != g.modifiers.end();
        if (constant || g.isStringParameter) continue;
        // Numbers only: a RWTexture or RWStructuredBuffer is written through, not copied.
        const std::string& resolved = syntax.resolveType(g.type);
        if (!describeBasicType(resolved).ok && !syntax.findStruct(resolved)) continue;
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
        // A cbuffer's member (a D3D11 course's `SetMeshWorld(World, input)` with an inout World,
        // compiled with /Gec) gets its copy after the cbuffer: glslang takes no static in a block.
        if (!g.cbuffer.empty()) {
            for (int depth = 0; end + 1 < t.size() && t[end].kind != Token::Kind::End; ++end) {
                if (t[end].is("{")) ++depth;
                if (t[end].is("}") && depth-- == 0) break;
            }
            if (t[end].kind == Token::Kind::End) continue;
            if (t[end + 1].is(";")) ++end;
        }
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

// fxc (as C++ compilers of its time) puts a variable declared in a `for` header in the enclosing
// scope: `for (int i = 0; ...) ...; for (i = 1; ...)` uses the same `i`. Where a header's variable is
// used after its loop, the declaration moves in front of the loop (`int i; for (i = 0; ...)`); a
// later header declaring the same name again in the same block (fxc's warning X3078) then
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

}  // namespace fxport::xlate
