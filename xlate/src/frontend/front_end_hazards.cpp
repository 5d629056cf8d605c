// Token-level checks for the glslang crash shapes listed in front_end_hazards.h.
#include "frontend/front_end_hazards.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "hlsl/hlsl_types.h"
#include "rewrite/mixed_shapes.h"

namespace fxport::xlate {

namespace {

class HazardFinder {
public:
    HazardFinder(const EffectSyntax& syntax, const SourceMap& map) : syntax_(syntax), map_(map) {}

    std::vector<Diagnostic> run() {
        redefinedGlobals();
        unnamedParameters();
        mismatchedBrackets();
        nestedFunctions();
        float1InMul();
        undeclaredInTernary();
        postfixOnNonLValues();
        templateDimensions();
        undeclaredInInitializedArraySizes();
        std::stable_sort(found_.begin(), found_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<Diagnostic> out;
        for (auto& [token, d] : found_) out.push_back(std::move(d));
        return out;
    }

private:
    const EffectSyntax& syntax_;
    const SourceMap& map_;
    std::vector<std::pair<size_t, Diagnostic>> found_;  // (token, diagnostic)

    const Token& tok(size_t i) const { return syntax_.tokens[std::min(i, syntax_.tokens.size() - 1)]; }
    void report(const char* id, const std::string& message, size_t token) {
        const Token& t = tok(token);
        found_.push_back({token, map_.make(Severity::Error, id, message, t.line, t.column, t.kind == Token::Kind::End ? std::string() : t.text)});
    }

    // How often each name occurs in the text glslang compiles: not after '.', not in what the
    // parser removes (techniques, asm blocks, annotations), where `c[a0]` of an asm block made an
    // undeclared `c` in a ternary look declared (fuzzer, device run 6).
    const std::map<std::string, int>& namesGlslangSees() {
        if (occurrences_) return *occurrences_;
        std::vector<std::pair<size_t, size_t>> removed;
        for (const auto& e : syntax_.edits) removed.push_back({e.begin, e.end});
        std::sort(removed.begin(), removed.end());
        std::vector<std::pair<size_t, size_t>> merged;  // edits nest (an annotation in a technique)
        for (const auto& r : removed) {
            if (!merged.empty() && r.first <= merged.back().second) merged.back().second = std::max(merged.back().second, r.second);
            else merged.push_back(r);
        }
        removed = std::move(merged);
        auto isRemoved = [&](size_t offset) {
            auto it = std::upper_bound(removed.begin(), removed.end(), std::make_pair(offset, size_t(-1)));
            return it != removed.begin() && offset < std::prev(it)->second;
        };
        std::map<std::string, int> counts;
        for (size_t i = 0; i < syntax_.tokens.size(); ++i)
            if (syntax_.tokens[i].isIdent() && !(i > 0 && syntax_.tokens[i - 1].is(".")) && !isRemoved(syntax_.tokens[i].offset))
                ++counts[syntax_.tokens[i].text];
        occurrences_ = std::move(counts);
        return *occurrences_;
    }
    std::optional<std::map<std::string, int>> occurrences_;
    static int timesSeen(const std::map<std::string, int>& counts, const std::string& name) {
        auto it = counts.find(name);
        return it == counts.end() ? 0 : it->second;
    }

    void redefinedGlobals() {
        std::map<std::string, const FxGlobal*> seen;
        for (const auto& g : syntax_.globals) {
            if (g.isStringParameter) continue;  // removed from the HLSL
            auto [it, inserted] = seen.emplace(g.name, &g);
            if (!inserted)
                report(diag::kHlsl, "redefinition of '" + g.name + "' (declared before as '" + it->second->type + " " + g.name + "')", g.token);
        }
    }

    void unnamedParameters() {
        for (const auto& f : syntax_.functions) {
            if (f.body.empty() && f.declaration.empty()) continue;
            static const std::set<std::string> kPrimitives = {"point", "line", "triangle", "lineadj", "triangleadj"};
            for (size_t i = 0; i < f.parameters.size(); ++i) {
                const FxParameter& p = f.parameters[i];
                if (p.name.empty()) {
                    report(diag::kHlsl, "parameter " + std::to_string(i + 1) + " of '" + f.name + "' (of type '" + p.type + "') has no name",
                           p.typeToken);
                    continue;
                }
                // A geometry shader's input primitive is an array of vertices (`point V v[1]`).
                for (const auto& m : p.modifiers)
                    if (kPrimitives.count(m) && p.arrayDims.empty())
                        report(diag::kHlsl, "geometry shader input '" + p.name + "' of '" + f.name + "' must be an array of vertices ('" + m + " " +
                                                p.type + " " + p.name + "[" + (m == "point" ? "1" : m == "line" ? "2" : m == "triangle" ? "3" : m == "lineadj" ? "4" : "6") + "]')",
                               p.typeToken);
            }
        }
    }

    void mismatchedBrackets() {
        std::vector<size_t> open;
        for (size_t i = 0; i < syntax_.tokens.size(); ++i) {
            const Token& t = syntax_.tokens[i];
            if (t.kind != Token::Kind::Punct) continue;
            if (t.is("(") || t.is("[") || t.is("{")) {
                open.push_back(i);
            } else if (t.is(")") || t.is("]") || t.is("}")) {
                const char* want = t.is(")") ? "(" : t.is("]") ? "[" : "{";
                if (open.empty() || !tok(open.back()).is(want)) {
                    report(diag::kHlsl, "syntax error: unexpected token '" + t.text + "'" +
                                            (open.empty() ? std::string() : " (the open bracket is '" + tok(open.back()).text + "')"),
                           i);
                    return;  // one is enough: everything after it is out of step
                }
                open.pop_back();
            }
        }
    }

    // Matching '(' of the ')' at `close`, searching backwards within [begin, close).
    std::optional<size_t> openParen(size_t begin, size_t close) const {
        int depth = 0;
        for (size_t i = close + 1; i-- > begin;) {
            if (tok(i).is(")")) ++depth;
            else if (tok(i).is("(") && --depth == 0) return i;
        }
        return std::nullopt;
    }

    void nestedFunctions() {
        static const std::set<std::string> kStatements = {"if", "for", "while", "switch"};
        for (const auto& f : syntax_.functions) {
            for (size_t i = f.body.begin + 1; i < f.body.end; ++i) {
                if (!tok(i).is("{") || !tok(i - 1).is(")")) continue;
                auto open = openParen(f.body.begin, i - 1);
                if (!open || *open == f.body.begin) continue;
                const Token& before = tok(*open - 1);
                if (!before.isIdent() || kStatements.count(before.text)) continue;
                report(diag::kHlsl, "'" + before.text + "' looks like a function defined inside function '" + f.name +
                                        "', which HLSL does not allow (is a ';' missing before it?)",
                       *open - 1);
                break;
            }
        }
    }

    static bool isOneComponent(const std::string& typeIn) {
        std::string type;
        for (char c : typeIn)
            if (c != ' ') type += c;
        BasicType b = describeBasicType(type);
        if (!b.ok || b.rows != 1 || b.columns != 1) return false;
        // float1x1, float1, vector<float,1>; not float or min16float (scalars).
        return b.isMatrix || type.back() == '1' || (type.size() > 3 && type.compare(type.size() - 3, 3, ",1>") == 0);
    }

    // Names declared with a one-component vector or matrix type (float1, half1, float1x1, vector<float, 1>)
    // in the function's parameters and body, and the globals.
    std::set<std::string> oneComponentNames(const FxFunction& f) const {
        std::set<std::string> names;
        for (const auto& g : syntax_.globals)
            if (isOneComponent(syntax_.resolveType(g.type))) names.insert(g.name);
        for (const auto& p : f.parameters)
            if (isOneComponent(syntax_.resolveType(p.type))) names.insert(p.name);
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i)
            if (tok(i).isIdent() && tok(i + 1).isIdent() && isOneComponent(syntax_.resolveType(tok(i).text))) names.insert(tok(i + 1).text);
        // Members of a struct-typed variable: `input.Normal` where the struct declares `float1 Normal`
        // (fuzzer, device run 2026-11-25), kept as "input.Normal".
        auto addMembers = [&](const std::string& type, const std::string& name) {
            if (const FxStruct* s = syntax_.findStruct(syntax_.resolveType(type)))
                for (const auto& m : s->members)
                    if (m.arrayDims.empty() && isOneComponent(syntax_.resolveType(m.type))) names.insert(name + "." + m.name);
        };
        for (const auto& g : syntax_.globals) addMembers(g.type, g.name);
        for (const auto& p : f.parameters) addMembers(p.type, p.name);
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i)
            if (tok(i).isIdent() && tok(i + 1).isIdent()) addMembers(tok(i).text, tok(i + 1).text);
        return names;
    }

    // An argument whose value is one-component: one-component names (not swizzled or indexed),
    // one-component constructors and literals, joined by operators; at least one not a literal.
    bool argumentIsOneComponent(size_t begin, size_t end, const std::set<std::string>& names) const {
        bool any = false;
        for (size_t i = begin; i < end; ++i) {
            const Token& t = tok(i);
            if (t.kind == Token::Kind::Number) continue;
            if (t.kind == Token::Kind::Punct) {
                if (t.is(".") || t.is("[")) return false;
                continue;
            }
            if (!t.isIdent()) return false;
            const FxFunction* called = tok(i + 1).is("(") ? syntax_.findFunction(t.text) : nullptr;
            if (tok(i + 1).is("(") && (isOneComponent(syntax_.resolveType(t.text)) || (called && isOneComponent(syntax_.resolveType(called->returnType))))) {
                // float1(...), or a call of a function returning float1 (`float1 decode(...)`; fuzzer,
                // device run 2026-11-25): its own arguments do not matter.
                any = true;
                int depth = 0;
                for (++i; i < end; ++i) {
                    if (tok(i).is("(")) ++depth;
                    else if (tok(i).is(")") && --depth == 0) break;
                }
                continue;
            }
            if (tok(i + 1).is(".") && tok(i + 2).isIdent() && names.count(t.text + "." + tok(i + 2).text) && i + 3 <= end &&
                !tok(i + 3).is(".") && !tok(i + 3).is("[")) {
                any = true;  // a one-component struct member
                i += 2;
                continue;
            }
            if (!names.count(t.text) || tok(i + 1).is(".") || tok(i + 1).is("[")) return false;
            any = true;
        }
        return any;
    }

    void float1InMul() {
        const std::set<size_t> spelledOut = mulCallsSpelledOut(syntax_);  // glslang never sees those
        for (const auto& f : syntax_.functions) {
            std::set<std::string> names;
            bool namesKnown = false;
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                if (!tok(i).is("mul") || !tok(i + 1).is("(") || spelledOut.count(i)) continue;
                if (!namesKnown) names = oneComponentNames(f), namesKnown = true;
                // Split the arguments at top-level commas.
                size_t argStart = i + 2;
                int depth = 0;
                for (size_t k = i + 2; k < f.body.end; ++k) {
                    const Token& t = tok(k);
                    if (t.is("(") || t.is("[") || t.is("{")) ++depth;
                    bool closes = (t.is(")") || t.is("]") || t.is("}")) && depth-- == 0;
                    if ((t.is(",") && depth == 0) || closes) {
                        if (argumentIsOneComponent(argStart, k, names)) {
                            report(diag::kUnsupported, "'mul' with a one-component argument ('" + syntax_.text({argStart, k}) +
                                                           "') crashes fxport's HLSL front end (glslang); make it a float or a full vector",
                                   argStart);
                            return;
                        }
                        argStart = k + 1;
                    }
                    if (closes) break;
                }
            }
        }
    }

    // An undeclared name in a branch of `c ? a : b` (`return v ? 1 : stor;`, `F(v ? x : B)`): glslang
    // reports it, then dereferences the missing branch (handleReturnValue, handleFunctionArgument).
    // A name is taken as undeclared only when it occurs once in the whole effect (a declared name
    // occurs at least twice: its declaration and this use), is not called, not a member, not a type
    // or keyword, so a valid effect is never refused here. fxc: X3004 undeclared identifier.
    void undeclaredInTernary() {
        // Members and swizzles (`.w`) declare nothing: `? t2 : w;` with only `p.w` elsewhere is still
        // undeclared (fuzzer, local run 2026-11-25).
        const std::map<std::string, int>& occurrences = namesGlslangSees();
        static const std::set<std::string> kWords = {"true", "false", "return", "sizeof", "NULL"};
        for (const auto& f : syntax_.functions) {
            for (size_t q = f.body.begin; q < f.body.end; ++q) {
                if (!tok(q).is("?")) continue;
                // The ternary's operands run to the first ';' ',' or closing bracket at their own depth.
                int depth = 0;
                for (size_t i = q + 1; i < f.body.end; ++i) {
                    const Token& t = tok(i);
                    if (t.is("(") || t.is("[") || t.is("{")) ++depth;
                    else if (t.is(")") || t.is("]") || t.is("}")) {
                        if (depth-- == 0) break;
                    } else if (depth == 0 && (t.is(";") || t.is(","))) {
                        break;
                    }
                    // Two names, or a name and a number, side by side: a syntax error in any expression
                    // (`which == 2 ? t2 : m4x4 oPos, r0` — a name declared elsewhere, so the count below
                    // misses it; glslang crashed in isConversionAllowed, fuzzer, local run 2026-11-25).
                    if (t.isIdent() && !kWords.count(t.text) && (tok(i + 1).isIdent() || tok(i + 1).kind == Token::Kind::Number) &&
                        i + 1 < f.body.end) {
                        report(diag::kHlsl, "syntax error: unexpected token '" + tok(i + 1).text + "' after '" + t.text + "'", i + 1);
                        return;
                    }
                    if (!t.isIdent() || timesSeen(occurrences, t.text) != 1 || tok(i + 1).is("(") || tok(i - 1).is(".") || kWords.count(t.text) ||
                        describeBasicType(syntax_.resolveType(t.text)).ok)
                        continue;
                    report(diag::kHlsl, "undeclared identifier '" + t.text + "'", i);
                    return;
                }
            }
        }
    }

    // `x++` / `x--` where x is not an l-value: a literal (`uv.y * 2-- 1`), a call or a parenthesised
    // expression (`F(p)--`, `(a + 1)--`), or an undeclared name (`F(p--)`). glslang reports it and
    // returns no node, then dereferences it as a function argument or an operand (handleFunctionArgument,
    // addBinaryMath; fuzzer, device run 6). fxc: X3025 (l-value specifies const
    // object) and X3004 (undeclared identifier). An undeclared name is one that occurs once, as in
    // undeclaredInTernary, so a valid effect is never refused.
    void postfixOnNonLValues() {
        const std::map<std::string, int>& occurrences = namesGlslangSees();
        for (const auto& f : syntax_.functions) {
            for (size_t i = f.body.begin + 1; i < f.body.end; ++i) {
                if (!tok(i).is("++") && !tok(i).is("--")) continue;
                const Token& operand = tok(i - 1);
                if (operand.kind == Token::Kind::Number || operand.is("true") || operand.is("false")) {
                    report(diag::kHlsl, "'" + tok(i).text + "' needs an l-value; '" + operand.text + "' is a constant", i);
                    return;
                }
                if (operand.isIdent() && !tok(i - 2).is(".") && timesSeen(occurrences, operand.text) == 1) {
                    report(diag::kHlsl, "undeclared identifier '" + operand.text + "'", i - 1);
                    return;
                }
                // `input.Nope--`: no struct has that member and it is no swizzle; glslang's node for
                // the member is null and addBinaryMath dereferences it (fuzzer, device run of session 17).
                // fxc: X3018.
                if (operand.isIdent() && tok(i - 2).is(".") && !isMemberOrSwizzle(operand.text)) {
                    report(diag::kHlsl, "invalid subscript '" + operand.text + "': no struct has such a member and it is no swizzle", i - 1);
                    return;
                }
                if (!operand.is(")")) continue;
                auto open = openParen(f.body.begin, i - 1);
                if (!open) continue;
                // `for (...) ++n;`: the `++` starts the statement after the header.
                if (tok(*open - 1).is("for") || tok(*open - 1).is("while") || tok(*open - 1).is("if")) continue;
                bool lvalue = !tok(*open - 1).isIdent();  // F(x)-- and float2(a, b)-- are values
                int index = 0;  // inside [...]: `(a[i + 1])--` is still an l-value
                for (size_t k = *open + 1; lvalue && k + 1 < i; ++k) {
                    if (tok(k).is("[")) ++index;
                    else if (tok(k).is("]")) --index;
                    else if (index == 0 && tok(k).kind == Token::Kind::Punct && !tok(k).is(".")) lvalue = false;
                }
                if (!lvalue) {
                    report(diag::kHlsl, "'" + tok(i).text + "' needs an l-value; '(...)' before it is a value", i);
                    return;
                }
            }
        }
    }

    bool isMemberOrSwizzle(const std::string& name) const {
        for (const auto& st : syntax_.structs)
            for (const auto& m : st.members)
                if (m.name == name) return true;
        auto onlyOf = [&](const char* set) { return name.size() <= 4 && name.find_first_not_of(set) == std::string::npos; };
        if (onlyOf("xyzw") || onlyOf("rgba")) return true;
        // Matrix elements: _m00.._m33, _11.._44, repeated (`m._m00_m11`).
        return name.size() >= 3 && name[0] == '_' && name.find_first_not_of("_m0123456789") == std::string::npos;
    }

    // `matrix<float, 8, 4>` or `vector<half, 0>` (fuzzer, device run 2026-11-25): glslang makes a type it
    // cannot lay out (unbounded recursion in getBaseAlignment) or multiply (addGenMulArgumentConversion).
    // fxc: X3053, dimensions must be between 1 and 4.
    void templateDimensions() {
        for (size_t i = 0; i + 1 < syntax_.tokens.size(); ++i) {
            const Token& t = tok(i);
            if (!t.isIdent() || !(t.is("vector") || t.is("matrix")) || !tok(i + 1).is("<")) continue;
            std::vector<size_t> numbers;
            size_t k = i + 2;
            for (; k < syntax_.tokens.size() && !tok(k).is(">") && !tok(k).is(";") && k < i + 12; ++k)
                if (tok(k).kind == Token::Kind::Number) numbers.push_back(k);
            if (!tok(k).is(">")) continue;
            for (size_t n : numbers) {
                long v = std::strtol(tok(n).text.c_str(), nullptr, 0);
                if (v < 1 || v > 4) {
                    report(diag::kHlsl, std::string(t.is("matrix") ? "matrix" : "vector") + " dimensions must be between 1 and 4 (not " + tok(n).text + ")", n);
                    return;
                }
            }
        }
    }

    // `static const float W[Nope + 1] = { ... };` with `Nope` declared nowhere: glslang leaves the
    // array unsized and dereferences the missing size in convertInitializerList (fuzzer, device run of
    // session 17; a bare `W[Nope]` and locals get glslang's own diagnostic). fxc: X3004. At global
    // scope a size can only name another global (a static const), a type or a function.
    void undeclaredInInitializedArraySizes() {
        std::set<std::string> globals;
        for (const auto& g : syntax_.globals) globals.insert(g.name);
        static const std::set<std::string> kWords = {"true", "false", "sizeof"};
        for (const auto& g : syntax_.globals) {
            if (g.initializer.empty() || !tok(g.token + 1).is("[")) continue;
            // The sizes only (`W[N][M]`), not a semantic or annotation after them (`: Diffuse`).
            int depth = 0;
            for (size_t i = g.token + 1; i < g.initializer.begin && i < syntax_.tokens.size(); ++i) {
                const Token& t = tok(i);
                if (t.is("[")) ++depth;
                else if (t.is("]")) --depth;
                if (depth == 0 && !t.is("]")) break;
                if (!t.isIdent() || globals.count(t.text) || kWords.count(t.text) || tok(i + 1).is("(") || tok(i - 1).is(".") ||
                    describeBasicType(syntax_.resolveType(t.text)).ok)
                    continue;
                report(diag::kHlsl, "undeclared identifier '" + t.text + "' in the size of array '" + g.name + "'", i);
                return;
            }
        }
    }
};

}  // namespace

std::vector<Diagnostic> findFrontEndHazards(const EffectSyntax& syntax, const SourceMap& map) {
    return HazardFinder(syntax, map).run();
}

}  // namespace fxport::xlate
