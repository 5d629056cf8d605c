// What fxc checks in a state block that fxport ignores in a loose-shader compile (fxc /T ps_4_0
// parses a variable's `{ ... }` block and the file's passes, and drops what they hold; vkd3d's
// state-block-syntax and state-block-function-syntax pin the rules). fxport warns that it ignores
// such a block (fx_parser.cpp); these are the errors fxc still gives there:
//  - a list of blocks `{ {...}, {...} }` has one block per component (numbers) or element
//    (objects), and blocks nest one level only; a block is never followed by `= value`;
//  - an entry's index is a non-negative integer literal, one dimension;
//  - a value is an expression: not a type name, no cast to a type that is not numeric, no call of
//    an undeclared function or of a declared one with no overload of that many parameters (nor one
//    whose parameter is an array: the value's constants are `const int`), no index of an undeclared
//    name and no swizzle past a name's components (an undeclared name is a scalar);
//  - a call statement is one of D3D's pass functions, spelled exactly, with its parameter count;
//    a pass function is no value.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// D3D11's pass functions and how many parameters each takes.
const std::map<std::string, std::pair<int, int>>& passFunctions() {
    static const std::map<std::string, std::pair<int, int>> k = {
        {"SetBlendState", {3, 3}},    {"SetDepthStencilState", {2, 2}}, {"SetRasterizerState", {1, 1}},
        {"SetVertexShader", {1, 1}},  {"SetDomainShader", {1, 1}},      {"SetHullShader", {1, 1}},
        {"SetGeometryShader", {1, 1}}, {"SetPixelShader", {1, 1}},      {"SetComputeShader", {1, 1}},
        {"OMSetRenderTargets", {2, 9}}};
    return k;
}

bool isTypeWord(const std::string& s) {
    return describeBasicType(s).ok || s == "sampler" || s == "sampler1D" || s == "sampler2D" || s == "sampler3D" || s == "samplerCUBE" ||
           s == "SamplerState" || s == "Texture" || s == "texture" || s == "Texture2D" || s == "vector" || s == "matrix" || s == "string";
}

class StateBlockRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        if (!syntax_.looseShaders) return;
        for (size_t i = 1; i + 1 < t_.size(); ++i) {
            if (!t_[i].is("{") || inFunction(i)) continue;
            const Token& before = t_[i - 1];
            if (!(before.isIdent() || before.is("]"))) continue;
            size_t start = statementStart(i);
            const std::string& head = t_[start].text;
            if (head == "struct" || head == "cbuffer" || head == "tbuffer" || head == "typedef" || head == "fxgroup") continue;
            if (head.rfind("technique", 0) == 0) {
                if (!isAppended(start, closing(i))) passes(i);
                i = closing(i);
                continue;
            }
            declarationBlock(start, i);
            i = closing(i);
        }
    }

private:
    size_t statementStart(size_t at) const {
        size_t i = at;
        while (i > 0 && !(t_[i - 1].is(";") || t_[i - 1].is("}"))) --i;
        return i;
    }
    // The technique fxport appends for a loose-shader compile is the last one: fxport's, not the file's.
    bool isAppended(size_t start, size_t end) const {
        return !syntax_.techniques.empty() && syntax_.techniques.back().token >= start && syntax_.techniques.back().token <= end;
    }

    // `technique { pass { ... } }` of the file: fxc parses its values as a block's.
    void passes(size_t open) {
        size_t end = closing(open);
        for (size_t i = open + 1; i < end; ++i)
            if (t_[i].is("{")) {
                entries(i, closing(i));
                i = closing(i);
            }
    }

    // `type name[dims] : ... { ... }`.
    void declarationBlock(size_t start, size_t open) {
        size_t close = closing(open);
        if (tok(close + 1).is("=")) report("a state block cannot be followed by an initial value", close + 1);
        bool list = tok(open + 1).is("{");
        if (!list) {
            entries(open, close);
            return;
        }
        int blocks = 0;
        for (size_t i = open + 1; i < close; ++i) {
            if (!t_[i].is("{")) continue;
            size_t inner = closing(i);
            for (size_t k = i + 1; k < inner; ++k)
                if (t_[k].is("{") && (t_[k - 1].is("{") || t_[k - 1].is(",") || t_[k - 1].is("}"))) {
                    report("state blocks nest one level only", k);
                    return;
                }
            entries(i, inner);
            ++blocks;
            i = inner;
        }
        int expected = componentsOf(start, open);
        if (expected > 0 && blocks != expected)
            report("the state block list has " + std::to_string(blocks) + " blocks; the variable has " + std::to_string(expected) +
                       (expected == 1 ? " component" : " components"),
                   open);
    }
    // Components (numbers) or elements (objects) of the declaration from `start` to the block; 0
    // when unknown.
    int componentsOf(size_t start, size_t open) const {
        size_t k = start;
        while (t_[k].isIdent() && (t_[k].is("static") || t_[k].is("uniform") || t_[k].is("const") || t_[k].is("extern"))) ++k;
        const std::string& type = t_[k].text;
        BasicType b = describeBasicType(syntax_.resolveType(type));
        bool object = type.rfind("sampler", 0) == 0 || type.rfind("Sampler", 0) == 0 || type.rfind("Texture", 0) == 0;
        if (!b.ok && !object) return 0;
        int count = b.ok ? b.rows * b.columns : 1;
        for (size_t i = k + 2; i < open && !t_[i].is(":"); ++i)
            if (t_[i].is("[")) {
                if (t_[i + 1].kind != Token::Kind::Number || !t_[i + 2].is("]")) return 0;
                count = int(std::min<long long>(1LL * count * std::clamp(std::strtoll(t_[i + 1].text.c_str(), nullptr, 10), 0LL, 1LL << 20), 1LL << 20));
            }
        return count;
    }

    // The entries between `open` and `close` (one block's braces).
    void entries(size_t open, size_t close) {
        size_t i = open + 1;
        while (i < close) {
            size_t end = i;
            int depth = 0;
            for (; end < close; ++end) {
                if (t_[end].is("(") || t_[end].is("{") || t_[end].is("[")) ++depth;
                else if (t_[end].is(")") || t_[end].is("}") || t_[end].is("]")) --depth;
                else if (depth == 0 && t_[end].is(";")) break;
            }
            if (end > i) entry(i, end);
            i = end + 1;
        }
    }

    void entry(size_t begin, size_t end) {
        if (!t_[begin].isIdent()) return;  // the parser reports what is no entry
        if (t_[begin + 1].is("(")) {
            call(begin);
            return;
        }
        size_t k = begin + 1;
        if (t_[k].is("[")) {
            size_t close = closing(k);
            if (close != k + 2 || t_[k + 1].kind != Token::Kind::Number || t_[k + 1].text.find_first_not_of("0123456789") != std::string::npos)
                report("the index of state '" + t_[begin].text + "' must be an integer literal", k + 1);
            k = close + 1;
            if (t_[k].is("[")) report("state '" + t_[begin].text + "' takes one index", k);
        }
        if (t_[k].is("=")) value(k + 1, end);
    }

    void call(size_t name) {
        size_t close = closing(name + 1);
        int count = arguments(name + 1, close);
        auto it = passFunctions().find(t_[name].text);
        if (it == passFunctions().end())
            report("'" + t_[name].text + "' is not a pass function (SetBlendState, SetPixelShader ..., spelled exactly)", name);
        else if (count < it->second.first || count > it->second.second)
            report("'" + t_[name].text + "' takes " + std::to_string(it->second.first) + (it->second.second != it->second.first ? " to " + std::to_string(it->second.second) : "") +
                       " parameters, not " + std::to_string(count),
                   name);
    }
    int arguments(size_t open, size_t close) const {
        if (close == open + 1) return 0;
        int count = 1, depth = 0;
        for (size_t k = open + 1; k < close; ++k) {
            if (t_[k].is("(") || t_[k].is("{") || t_[k].is("[")) ++depth;
            else if (t_[k].is(")") || t_[k].is("}") || t_[k].is("]")) --depth;
            else if (depth == 0 && t_[k].is(",")) ++count;
        }
        return count;
    }

    void value(size_t begin, size_t end) {
        if (begin < end && t_[begin].is("compile")) return;  // a shader; fxc compiles it (not here)
        if (end == begin + 1 && t_[begin].isIdent() && isTypeWord(t_[begin].text)) {
            report("'" + t_[begin].text + "' is a type, not a value", begin);
            return;
        }
        for (size_t k = begin; k < end; ++k) {
            const Token& t = t_[k];
            if (t.is("(") && k + 3 < end && t_[k + 1].isIdent() && t_[k + 2].is(")") && !t_[k + 3].is(")") && !isOperator(t_[k + 3])) {
                const std::string& type = t_[k + 1].text;
                if (!describeBasicType(syntax_.resolveType(type)).ok && !syntax_.findStruct(type) && !isVariable(type)) {
                    report("'" + type + "' is no numeric type to cast a state value to", k + 1);
                    return;
                }
            }
            if (!t.isIdent() || (k > begin && t_[k - 1].is("."))) continue;
            if (t_[k + 1].is("(") && k + 1 < end) {
                if (!callable(k)) return;
                continue;
            }
            if (!isVariable(t.text) && !isTypeWord(t.text) && t_[k + 1].is("[") && k + 1 < end) {
                report("'" + t.text + "' is undeclared, a scalar to fxc: it cannot be indexed", k);
                return;
            }
            if (t_[k + 1].is(".") && k + 2 < end && t_[k + 2].isIdent()) {
                int size = componentsOfName(t.text);
                const std::string& s = t_[k + 2].text;
                if (size > 0 && s.find_first_not_of("xyzw") == std::string::npos)
                    for (char c : s)
                        if (std::string("xyzw").find(c) >= size_t(size)) {
                            report("'" + t.text + "." + s + "' names a component '" + t.text + "' does not have", k + 2);
                            return;
                        }
            }
        }
    }
    static bool isOperator(const Token& t) {
        return t.kind == Token::Kind::Punct && !t.is("(") && !t.is("-") && !t.is("+") && !t.is("!") && !t.is("~");
    }
    bool isVariable(const std::string& name) const {
        for (const auto& g : syntax_.globals)
            if (g.name == name) return true;
        return syntax_.findSampler(name) || syntax_.findTexture(name);
    }
    // Components of a global number (1 for an undeclared name, a scalar to fxc); 0 when unknown.
    int componentsOfName(const std::string& name) const {
        for (const auto& g : syntax_.globals)
            if (g.name == name) {
                BasicType b = describeBasicType(syntax_.resolveType(g.type));
                return b.ok && !b.isMatrix && g.arrayDims.empty() ? b.columns : 0;
            }
        return isTypeWord(name) || syntax_.findSampler(name) || syntax_.findTexture(name) || syntax_.findStruct(name) ? 0 : 1;
    }
    // `name(...)` in a value: a numeric constructor, or a declared function with an overload of
    // that many parameters, none of them an array. False (and reported) otherwise.
    bool callable(size_t name) {
        const std::string& n = t_[name].text;
        if (isTypeWord(n) || n == "CompileShader" || n == "ConstructGSWithSO" || n == "sampler_state") return true;
        if (passFunctions().count(n)) {
            report("'" + n + "' is a pass function: it is called as a statement, not used as a value", name);
            return false;
        }
        int count = arguments(name + 1, closing(name + 1));
        bool declared = false;
        for (const auto& f : syntax_.functions) {
            if (f.name != n) continue;
            declared = true;
            if (int(f.parameters.size()) != count) continue;
            for (const auto& p : f.parameters)
                if (!p.arrayDims.empty()) {
                    report("'" + n + "' takes an array; a state value's constants are 'const int'", name);
                    return false;
                }
            return true;
        }
        report(declared ? "no overload of '" + n + "' takes " + std::to_string(count) + " parameters" : "'" + n + "' is not a declared function", name);
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findStateBlockErrors(const EffectSyntax& syntax, const SourceMap& map) {
    StateBlockRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
