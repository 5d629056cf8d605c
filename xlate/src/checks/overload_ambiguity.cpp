// Overloads fxc can define but not call (vkd3d's function-overload pins it): `f(float)` and
// `f(float1)` are two functions, yet fxc ranks a scalar and a one-component vector alike in
// either direction, so every call of `f` with that many arguments is ambiguous (X3067) -- even
// when one of the two is only a prototype. glslang picks one silently, so the call is judged here.
#include <algorithm>
#include <cctype>
#include <map>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Signature {
    std::vector<std::string> written;     // parameter types as written (spaces removed)
    std::vector<std::string> normalized;  // with T1 / vector<T, 1> read as T
};

std::string withoutSpaces(std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
    return s;
}

bool isParameterModifier(const Token& t) {
    for (const char* m : {"in", "out", "inout", "uniform", "const", "static", "precise", "row_major", "column_major", "nointerpolation",
                          "linear", "centroid", "noperspective", "sample", "triangle", "line", "point", "lineadj", "triangleadj"})
        if (t.is(m)) return true;
    return false;
}

class OverloadAmbiguity : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::map<std::string, std::vector<Signature>> byName;
        for (const auto& f : syntax_.functions) {
            Signature s;
            for (const auto& p : f.parameters) add(s, p.arrayDims.empty() ? p.type : p.type + "[]");
            byName[f.name].push_back(s);
        }
        prototypes(byName);
        for (const auto& [name, signatures] : byName)
            for (size_t a = 0; a < signatures.size(); ++a)
                for (size_t b = 0; b < a; ++b)
                    if (signatures[a].normalized == signatures[b].normalized && signatures[a].written != signatures[b].written)
                        calls(name, signatures[a], signatures[b]);
    }

private:
    void add(Signature& s, const std::string& type) const {
        std::string written = withoutSpaces(syntax_.resolveType(type));
        BasicType b = describeBasicType(written);
        s.written.push_back(written);
        s.normalized.push_back(b.ok && !b.isMatrix && b.columns == 1 ? b.scalar : written);
    }

    // `float f(float1 x);` at file scope: a prototype counts as an overload for the ranking.
    void prototypes(std::map<std::string, std::vector<Signature>>& byName) const {
        for (size_t i = 1; i + 1 < t_.size(); ++i) {
            if (!t_[i].isIdent() || !t_[i + 1].is("(") || !t_[i - 1].isIdent() || !byName.count(t_[i].text) || inFunction(i)) continue;
            size_t close = closing(i + 1);
            if (!tok(close + 1).is(";")) continue;
            Signature s;
            bool ok = true;
            for (size_t j = i + 2; j < close && ok;) {
                while (j < close && isParameterModifier(t_[j])) ++j;
                if (j >= close || !t_[j].isIdent()) {
                    ok = false;
                    break;
                }
                std::string type = t_[j].text;
                ++j;
                if (tok(j).is("<")) {
                    size_t end = closing(j);
                    for (; j <= end; ++j) type += t_[j].text;
                }
                bool array = false;
                while (j < close && !t_[j].is(",")) array |= t_[j++].is("[");
                add(s, array ? type + "[]" : type);
                ++j;
            }
            if (ok) byName[t_[i].text].push_back(s);
        }
    }

    static std::string show(const std::string& name, const Signature& s) {
        std::string out = name + "(";
        for (size_t k = 0; k < s.written.size(); ++k) out += (k ? ", " : "") + s.written[k];
        return out + ")";
    }

    // Calls of `name` with as many arguments as the two look-alike overloads take.
    void calls(const std::string& name, const Signature& a, const Signature& b) {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                if (!t_[i].is(name) || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
                if (arguments(i + 1) != a.written.size()) continue;
                report("ambiguous function call: '" + show(name, a) + "' and '" + show(name, b) +
                           "' take the same arguments (a scalar and a one-component vector rank alike; fxc X3067)",
                       i);
            }
    }

    size_t arguments(size_t open) const {
        size_t close = closing(open);
        if (close == open + 1) return 0;
        size_t n = 1;
        for (size_t j = open + 1; j < close; ++j) {
            if (t_[j].is("(") || t_[j].is("[") || t_[j].is("{")) j = closing(j);
            else if (t_[j].is(",")) ++n;
        }
        return n;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findOverloadAmbiguityErrors(const EffectSyntax& syntax, const SourceMap& map) {
    OverloadAmbiguity check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
