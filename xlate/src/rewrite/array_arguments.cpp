// See array_arguments.h.
#include "rewrite/array_arguments.h"

#include <algorithm>
#include <map>
#include <string>

#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

int elementCount(const std::vector<int>& dims) {
    int n = 1;
    for (int d : dims) n *= d;
    return n;
}

// `[i][j]` of flat element k in an array of sizes `dims`.
std::string indexOf(const std::vector<int>& dims, int k) {
    std::string out;
    for (size_t d = dims.size(); d-- > 0;) {
        out = "[" + std::to_string(k % dims[d]) + "]" + out;
        k /= dims[d];
    }
    return out;
}

std::string sizes(const std::vector<int>& dims) {
    std::string out;
    for (int d : dims) out += "[" + std::to_string(d) + "]";
    return out;
}

bool isIn(const FxParameter& p) {
    for (const auto& m : p.modifiers)
        if (m == "out" || m == "inout") return false;
    return true;
}

std::string declaration(const FxParameter& p, const std::string& name, const std::vector<int>& dims) {
    std::string out;
    for (const auto& m : p.modifiers) out += m + " ";
    return out + p.type + " " + name + sizes(dims);
}

// The overload of `f` taking `dims` at parameter `index`.
std::string overload(const FxFunction& f, size_t index, const std::vector<int>& dims) {
    const FxParameter& p = f.parameters[index];
    std::string params, args;
    for (size_t k = 0; k < f.parameters.size(); ++k) {
        const FxParameter& q = f.parameters[k];
        params += (k ? ", " : "") + (k == index ? declaration(q, "fxport_a", dims) : declaration(q, q.name, q.arrayDims));
        args += (k ? ", " : "") + (k == index ? std::string("fxport_b") : q.name);
    }
    std::string body = p.type + " fxport_b" + sizes(p.arrayDims) + "; ";
    for (int k = 0; k < elementCount(dims); ++k) body += "fxport_b" + indexOf(p.arrayDims, k) + " = fxport_a" + indexOf(dims, k) + "; ";
    body += (f.returnType == "void" ? "" : "return ") + f.name + "(" + args + "); ";
    return " " + f.returnType + " " + f.name + "(" + params + ") { " + body + "}";
}

}  // namespace

std::vector<TextEdit> arrayArgumentOverloads(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::map<std::string, int> definitions;
    for (const auto& f : syntax.functions) ++definitions[f.name];
    std::map<std::pair<const FxFunction*, std::string>, std::string> overloads;  // (function, signature) -> code
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is(".")) || definitions[t[i].text] != 1) continue;
            const FxFunction* callee = syntax.findFunction(t[i].text);
            if (!callee || callee->body.empty()) continue;
            // Arguments that are one name each: `fun(f, x)`.
            size_t a = 0;
            for (size_t j = i + 2; j + 1 < f.body.end && a < callee->parameters.size(); j += 2, ++a) {
                const FxParameter& p = callee->parameters[a];
                const bool alone = t[j].isIdent() && (t[j + 1].is(",") || t[j + 1].is(")"));
                if (alone && !p.arrayDims.empty() && isIn(p)) {
                    auto d = declaredVariable(syntax, f, t[j].text, j);
                    if (d && !d->dims.empty() && d->dims != p.arrayDims && elementCount(d->dims) == elementCount(p.arrayDims) &&
                        syntax.resolveType(d->type) == syntax.resolveType(p.type) &&
                        std::all_of(d->dims.begin(), d->dims.end(), [](int n) { return n > 0; }))
                        overloads.emplace(std::make_pair(callee, std::to_string(a) + sizes(d->dims)), overload(*callee, a, d->dims));
                }
                if (!alone || t[j + 1].is(")")) break;
            }
        }
    }
    std::vector<TextEdit> edits;
    for (const auto& [key, code] : overloads) {
        const Token& last = t[key.first->declaration.end - 1];
        edits.push_back({last.end, last.end, code});
    }
    return edits;
}

}  // namespace fxport::xlate
