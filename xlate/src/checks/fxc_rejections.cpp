// See fxc_rejections.h.
#include "checks/fxc_rejections.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "hlsl/hlsl_types.h"
#include "fx/shader_profile.h"

namespace fxport::xlate {

namespace {

bool isOneOf(const std::string& s, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (s == n) return true;
    return false;
}

bool isModifier(const std::string& s) {
    return isOneOf(s, {"static", "uniform", "const", "extern", "shared", "groupshared", "volatile", "precise", "row_major",
                       "column_major", "in", "out", "inout", "nointerpolation", "linear", "centroid", "noperspective", "sample"});
}

bool isAssignment(const Token& t) {
    return t.kind == Token::Kind::Punct &&
           isOneOf(t.text, {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="});
}

class RejectionFinder {
public:
    RejectionFinder(const EffectSyntax& syntax, const SourceMap& map) : syntax_(syntax), t_(syntax.tokens), map_(map) {}

    std::vector<Diagnostic> run() {
        for (size_t i = 0; i + 1 < t_.size(); ++i) {
            if (t_[i].is("switch")) switchCases(i);
            if (t_[i].is("[")) statementAttributes(i);
            if (t_[i].isIdent() && isModifier(t_[i].text)) modifiers(i);
            if (t_[i].is(".")) swizzleWrite(i);
            if (t_[i].is("packoffset")) packOffsetPlace(i);
            if (t_[i].isIdent()) typeNameAsVariable(i);
        }
        for (const auto& f : syntax_.functions) constWithoutValue(f);
        for (const auto& f : syntax_.functions) outArgumentsAreLValues(f);
        packOffsetOnAllOrNone();
        packOffsetOutsideCbuffer();
        for (const auto& v : syntax_.shaderVariables)
            for (const auto& e : v.elements) compiledShaderVariable(e);
        std::stable_sort(found_.begin(), found_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<Diagnostic> out;
        size_t last = size_t(-1);
        for (auto& [token, d] : found_)
            if (token != last) out.push_back(std::move(d)), last = token;  // one error per place
        return out;
    }

private:
    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    const SourceMap& map_;
    std::vector<std::pair<size_t, Diagnostic>> found_;

    const Token& tok(size_t i) const { return t_[std::min(i, t_.size() - 1)]; }
    void report(const std::string& message, size_t token) {
        const Token& t = tok(token);
        found_.push_back({token, map_.make(Severity::Error, diag::kHlsl, message, t.line, t.column, t.text)});
    }
    // The index of the bracket closing the one at `open` (or the end token).
    size_t closing(size_t open) const {
        const std::string o = t_[open].text, c = o == "(" ? ")" : o == "[" ? "]" : "}";
        int depth = 0;
        for (size_t i = open; i < t_.size(); ++i) {
            if (t_[i].is(o)) ++depth;
            else if (t_[i].is(c) && --depth == 0) return i;
        }
        return t_.size() - 1;
    }
    bool inFunction(size_t at) const {
        for (const auto& f : syntax_.functions)
            if (at >= f.declaration.begin && at < f.declaration.end) return true;
        return syntax_.inMemberFunctionBody(at);
    }
    static bool opens(const Token& t) { return t.is("(") || t.is("[") || t.is("{"); }

    // --- switch: every non-empty case ends in break, return or continue (fxc SM4/5, X3533) -------
    void switchCases(size_t at) {
        if (!tok(at + 1).is("(")) return;
        size_t body = closing(at + 1) + 1;
        if (!tok(body).is("{")) return;
        size_t end = closing(body);
        size_t clauseBegin = 0, labelToken = 0;
        bool inClause = false;
        for (size_t i = body + 1; i < end;) {
            if (t_[i].is("case") || t_[i].is("default")) {
                if (inClause) checkClause(clauseBegin, i, labelToken, false);
                labelToken = i;
                size_t colon = i;
                while (colon < end && !t_[colon].is(":")) colon = opens(t_[colon]) ? closing(colon) + 1 : colon + 1;
                clauseBegin = colon + 1;
                inClause = true;
                i = clauseBegin;
                continue;
            }
            i = opens(t_[i]) ? closing(i) + 1 : i + 1;
        }
        if (inClause) checkClause(clauseBegin, end, labelToken, true);
    }
    // fxc's rule (X3533) is that a non-empty case has a break or return somewhere in it (a case
    // whose break sits in an `if` and which then falls through still compiles); an empty last case
    // is an error too.
    void checkClause(size_t begin, size_t end, size_t label, bool last) {
        if (begin >= end) {
            if (last) report("the last case of a switch is empty: fxc wants a statement, at least 'break;' (X3533)", label);
            return;  // labels that share one clause
        }
        continueInCase(begin, end);
        for (size_t i = begin; i < end; ++i)
            if (t_[i].is("break") || t_[i].is("return") || t_[i].is("continue")) return;
        report("non-empty case statements must have break or return: this case falls through to the next (fxc X3533)", label);
    }
    // fxc refuses `continue` in a case, even inside a loop around the switch (vkd3d's switch); a
    // loop inside the case owns its continues. Cases with a loop are not judged.
    void continueInCase(size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            if (t_[i].is("for") || t_[i].is("while") || t_[i].is("do") || t_[i].is("switch")) return;
            if (t_[i].is("continue")) report("'continue' cannot be used in a switch case (fxc)", i);
        }
    }

    // --- statement attributes ------------------------------------------------------------------
    void statementAttributes(size_t at) {
        if (at > 0 && !(t_[at - 1].is(";") || t_[at - 1].is("{") || t_[at - 1].is("}") || t_[at - 1].is(")"))) return;
        std::vector<std::pair<std::string, size_t>> seen;
        size_t i = at;
        while (tok(i).is("[") && tok(i + 1).isIdent() && (tok(i + 2).is("]") || tok(i + 2).is("("))) {
            seen.push_back({t_[i + 1].text, i + 1});
            i = tok(i + 2).is("(") ? closing(i + 2) + 1 : i + 2;
            if (!tok(i).is("]")) return;
            ++i;
        }
        const Token& statement = tok(i);
        if (!isOneOf(statement.text, {"if", "for", "while", "do", "switch"}) || seen.size() < 2) return;
        for (size_t a = 0; a < seen.size(); ++a)
            for (size_t b = 0; b < a; ++b) {
                const std::string &x = seen[a].first, &y = seen[b].first;
                if (x == y) report("attribute '" + x + "' is already given on this statement (fxc X3524)", seen[a].second);
                else if (conflicting(x, y))
                    report("attributes '" + y + "' and '" + x + "' contradict each other (fxc X3525)", seen[a].second);
            }
    }
    static bool conflicting(const std::string& a, const std::string& b) {
        auto pair = [&](const char* p, const char* q) { return (a == p && b == q) || (a == q && b == p); };
        return pair("branch", "flatten") || pair("loop", "unroll") || pair("fastopt", "unroll");
    }

    // --- modifiers -----------------------------------------------------------------------------
    void modifiers(size_t at) {
        if (at > 0 && t_[at - 1].isIdent() && isModifier(t_[at - 1].text)) return;  // not the run's first
        std::set<std::string> seen;
        size_t i = at;
        for (; tok(i).isIdent() && isModifier(t_[i].text); ++i) {
            const std::string& m = t_[i].text;
            if (seen.count(m)) report("modifier '" + m + "' is given twice (fxc X3048)", i);
            for (const auto& [p, q] : {std::pair{"static", "uniform"}, {"row_major", "column_major"}, {"out", "uniform"},
                                       {"inout", "uniform"}, {"out", "const"}, {"static", "extern"},
                                       {"nointerpolation", "centroid"}})  // a constant value has no centroid (vkd3d's nointerpolation)
                if ((m == p && seen.count(q)) || (m == q && seen.count(p)))
                    report(std::string("modifiers '") + p + "' and '" + q + "' exclude each other (fxc X3049)", i);
            seen.insert(m);
        }
        if ((seen.count("row_major") || seen.count("column_major")) && tok(i).isIdent()) {
            BasicType b = describeBasicType(syntax_.resolveType(t_[i].text));
            if (b.ok && !b.isMatrix) report("'row_major' and 'column_major' apply to matrices only, not '" + t_[i].text + "' (fxc X3025)", i);
        }
    }

    // --- `v.xx = ...` ----------------------------------------------------------------------------
    void swizzleWrite(size_t dot) {
        const Token& s = tok(dot + 1);
        if (!s.isIdent() || !isAssignment(tok(dot + 2)) || s.text.size() < 2) return;
        std::string components = s.text;
        if (components[0] == '_') {  // matrix swizzle `_m01_m01` / `_11_11`: compare its elements
            std::set<std::string> elements;
            for (size_t k = 0; k < components.size();) {
                size_t next = components.find('_', k + 1);
                std::string e = components.substr(k, next == std::string::npos ? std::string::npos : next - k);
                if (!elements.insert(e).second) {
                    report("an assigned swizzle names element '" + e + "' twice (fxc X3018)", dot + 1);
                    return;
                }
                k = next == std::string::npos ? components.size() : next;
            }
            return;
        }
        const std::string xyzw = "xyzw", rgba = "rgba";
        bool isSwizzle = components.size() <= 4 &&
                         (components.find_first_not_of(xyzw) == std::string::npos || components.find_first_not_of(rgba) == std::string::npos);
        if (!isSwizzle) return;
        for (const auto& st : syntax_.structs)  // a member spelled like a swizzle: `data.aa = ...`
            for (const auto& m : st.members)
                if (m.name == components) return;
        for (size_t k = 0; k < components.size(); ++k)
            if (components.find(components[k], k + 1) != std::string::npos) {
                report("an assigned swizzle names component '" + std::string(1, components[k]) + "' twice (fxc X3018)", dot + 1);
                return;
            }
    }

    // --- `const float f;` in a function ------------------------------------------------------
    void constWithoutValue(const FxFunction& f) {
        for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
            if (!t_[i].is("const") || (i > f.body.begin && !(t_[i - 1].is(";") || t_[i - 1].is("{") || t_[i - 1].is("}")))) continue;
            size_t k = i + 1;
            while (k < f.body.end && t_[k].isIdent() && isModifier(t_[k].text)) ++k;
            if (t_[k].is("struct")) ++k;  // `const struct s a;`
            if (k + 2 < f.body.end && t_[k].isIdent() && t_[k + 1].isIdent() && t_[k + 2].is(";"))
                report("const variable '" + t_[k + 1].text + "' has no initial value (fxc X3012)", k + 1);
        }
    }

    // --- out/inout arguments are l-values (X3025); glslang crashes on some that are not ---------
    void outArgumentsAreLValues(const FxFunction& caller) {
        for (size_t i = caller.body.begin; i + 1 < caller.body.end; ++i) {
            if (!t_[i].isIdent() || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
            std::vector<std::pair<size_t, size_t>> args;  // token ranges
            size_t close = closing(i + 1), start = i + 2;
            for (size_t k = i + 2; k <= close; ++k) {
                if (k < close && opens(t_[k])) {
                    k = closing(k);
                    continue;
                }
                if (k == close || t_[k].is(",")) {
                    if (k > start) args.push_back({start, k});
                    start = k + 1;
                }
            }
            const FxFunction* callee = onlyOverloadTaking(t_[i].text, args.size());
            if (!callee) continue;
            for (size_t a = 0; a < args.size(); ++a) {
                const auto& mods = callee->parameters[a].modifiers;
                bool out = std::find(mods.begin(), mods.end(), "out") != mods.end() || std::find(mods.begin(), mods.end(), "inout") != mods.end();
                if (out && !isWritable(caller, args[a].first, args[a].second))
                    report("argument " + std::to_string(a + 1) + " of '" + callee->name + "' is an out parameter: it must be a variable fxc can write (X3025)",
                           args[a].first);
            }
        }
    }
    const FxFunction* onlyOverloadTaking(const std::string& name, size_t count) const {
        const FxFunction* found = nullptr;
        for (const auto& f : syntax_.functions)
            if (f.name == name && f.parameters.size() == count) {
                if (found) return nullptr;  // overloads of one count: glslang resolves them
                found = &f;
            }
        return found;
    }
    // `x`, `x.member`, `x[i]`, `x.yz` (no repeated component), `(T)x`; not a const, a literal or an expression.
    bool isWritable(const FxFunction& caller, size_t begin, size_t end) const {
        if (begin + 3 < end && t_[begin].is("(") && t_[begin + 1].isIdent() && t_[begin + 2].is(")")) begin += 3;  // `(float4)x`: fxc converts back
        if (!t_[begin].isIdent() || isOneOf(t_[begin].text, {"true", "false"})) return false;
        for (size_t k = begin + 1; k < end; ++k) {
            if (t_[k].is("[")) {
                k = closing(k);
                continue;
            }
            if (!t_[k].is(".") || k + 1 >= end || !t_[k + 1].isIdent()) return false;
            const std::string& m = t_[++k].text;
            if (k + 1 == end && m.size() > 1 && m.find_first_not_of("xyzwrgba") == std::string::npos)
                for (size_t c = 0; c < m.size(); ++c)
                    if (m.find(m[c], c + 1) != std::string::npos) return false;
        }
        const std::string& name = t_[begin].text;
        for (size_t k = caller.body.begin; k + 2 < begin; ++k)  // `const float x = ...;` earlier in the caller
            if (t_[k].is("const") && t_[k + 1].isIdent() && t_[k + 2].is(name)) return false;
        return true;
    }

    // --- packoffset -----------------------------------------------------------------------------
    void packOffsetPlace(size_t at) {
        for (const auto& f : syntax_.functions)
            if (at >= f.declaration.begin && at < f.declaration.end) {
                report("packoffset is only for members of a cbuffer, not a function's parameters or result (fxc X3591)", at);
                return;
            }
        if (!tok(at + 1).is("(")) return;
        size_t close = closing(at + 1);
        std::string text;
        for (size_t k = at + 2; k < close; ++k) text += t_[k].text;
        size_t digits = text.size() > 1 && (text[0] == 'c' || text[0] == 'C') ? text.find_first_not_of("0123456789", 1) : 0;
        bool ok = digits != 1 && digits != 0;
        if (ok && digits != std::string::npos)
            ok = text.size() == digits + 2 && text[digits] == '.' && std::string("xyzwrgba").find(text[digits + 1]) != std::string::npos;
        if (!ok) report("packoffset(" + text + ") is not a constant register like c4 or c4.y (fxc X3591)", at + 2);
    }
    void packOffsetOnAllOrNone() {
        for (const auto& name : syntax_.cbuffers) {
            const FxGlobal* with = nullptr;
            const FxGlobal* without = nullptr;
            for (const auto& g : syntax_.globals) {
                // Objects in a cbuffer are placed by register(), which the rule also counts: only
                // numbers are judged here.
                std::string type = syntax_.resolveType(g.type);
                if (g.cbuffer != name || g.isStringParameter || !(describeBasicType(type).ok || syntax_.findStruct(type))) continue;
                if (g.packOffset < 0 && placedByRegister(g.token)) continue;
                if (g.packOffset >= 0) with = &g;
                else if (!without) without = &g;
                if (g.packOffset >= 0) packedMemberFits(g);
            }
            if (with && without)
                report("cbuffer '" + name + "' places some members with packoffset but not '" + without->name +
                           "': fxc wants all or none (X3592)",
                       without->token);
        }
    }
    // packoffset places a member of a cbuffer: not a $Globals variable, not a struct's member.
    void packOffsetOutsideCbuffer() {
        for (const auto& g : syntax_.globals)
            if (g.cbuffer.empty() && g.packOffset >= 0)
                report("packoffset on '" + g.name + "', which is in no cbuffer: it places cbuffer members only (fxc X3591)", g.token);
        for (size_t i = 0; i + 2 < t_.size(); ++i) {
            if (!t_[i].is("struct") || !(t_[i + 1].is("{") || t_[i + 2].is("{"))) continue;
            size_t open = t_[i + 1].is("{") ? i + 1 : i + 2, close = closing(open);
            for (size_t k = open; k < close; ++k)
                if (t_[k].is("packoffset")) report("packoffset on a struct member: it places cbuffer members only (fxc X3591)", k);
            i = close;
        }
    }
    // `register(t1)` on a member (not register(cN), which fxc ignores in a cbuffer) places it too.
    bool placedByRegister(size_t nameToken) const {
        for (size_t i = nameToken; i + 2 < t_.size() && !t_[i].is(";"); ++i)
            if (t_[i].is("register") && t_[i + 1].is("(") && t_[i + 2].isIdent() && std::tolower(static_cast<unsigned char>(t_[i + 2].text[0])) != 'c')
                return true;
        return false;
    }
    void packedMemberFits(const FxGlobal& g) {
        int component = g.packOffset % 4;
        if (component == 0) return;
        std::string type = syntax_.resolveType(g.type);
        BasicType b = describeBasicType(type);
        if (!b.ok) {
            if (syntax_.findStruct(type) || !g.arrayDims.empty())
                report("a struct placed by packoffset must start a register (.x) (fxc X3593)", g.token);
            return;
        }
        if (b.isMatrix || !g.arrayDims.empty())
            report(std::string(b.isMatrix ? "a matrix" : "an array") + " placed by packoffset must start a register (.x) (fxc X3593)", g.token);
        else if (component + b.columns > 4)
            report("'" + g.name + "' (" + g.type + ") placed at component " + std::to_string(component) +
                       " by packoffset crosses a register boundary (fxc X3594)",
                   g.token);
    }

    // --- `PixelShader ps = CompileShader(ps_4_0, main(a));` outside a pass ---------------------
    // fxc compiles a shader variable where it is declared: its profile must be one, and its
    // arguments values it knows (inside a pass, undefined names are allowed; not here).
    void compiledShaderVariable(const FxShaderExpr& e) {
        if (e.kind != FxShaderExpr::Kind::Compile) return;
        if (!parseShaderProfile(e.profile)) {
            report("'" + e.profile + "' is not a shader profile fxc compiles (vs_1_1..vs_5_0, ps_2_0..ps_5_0, gs_4_0.., cs_4_0.., hs_5_0, ds_5_0)", e.token);
            return;
        }
        std::string argument;
        auto check = [&](std::string a) {
            while (!a.empty() && a.front() == ' ') a.erase(a.begin());
            while (!a.empty() && a.back() == ' ') a.pop_back();
            if (a.empty() || !(std::isalpha(static_cast<unsigned char>(a[0])) || a[0] == '_')) return;
            if (a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos) return;
            if (a == "true" || a == "false") return;
            for (const auto& g : syntax_.globals)
                if (g.name == a) return;
            report("undeclared identifier '" + a + "' in the arguments of a compiled shader variable (fxc X3004)", e.token);
        };
        int depth = 0;
        for (char c : e.arguments) {
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            if (c == ',' && depth == 0) {
                check(argument);
                argument.clear();
            } else {
                argument += c;
            }
        }
        check(argument);
    }

    // --- `float4 float;` ---------------------------------------------------------------------
    // At file scope only: fxc lets a function declare `float4 float = ...` or typedef `float`.
    void typeNameAsVariable(size_t at) {
        const Token& type = t_[at];
        const Token& name = tok(at + 1);
        if (!name.isIdent() || !tok(at + 2).is(";") || inFunction(at)) return;
        if (isModifier(type.text) || type.is("return") || type.is("typedef")) return;
        bool typeIsType = describeBasicType(syntax_.resolveType(type.text)).ok || syntax_.findStruct(type.text) || syntax_.typedefs.count(type.text);
        bool nameIsType = describeBasicType(name.text).ok || name.is("vector") || name.is("matrix");
        if (typeIsType && nameIsType) report("'" + name.text + "' is a type name; it cannot name a variable (fxc X3000)", at + 1);
    }
};

}  // namespace

std::vector<Diagnostic> findFxcRejections(const EffectSyntax& syntax, const SourceMap& map) {
    return RejectionFinder(syntax, map).run();
}

}  // namespace fxport::xlate
