// Evaluates parameter initialisers (see constant_eval.h) by recursive descent, nesting bounded.
#include "fx/constant_eval.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "fx/input_limits.h"

#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// Which components a swizzle picks of a numeric value of shape `b`: `zxy` of a vector (or `x` of a
// scalar), `_13_22` / `_m02_m11` of a matrix; nothing for anything else.
std::optional<std::vector<size_t>> swizzleComponents(const BasicType& b, const std::string& s) {
    std::vector<size_t> picked;
    if (b.isMatrix) {
        for (size_t i = 0; i < s.size();) {
            if (s[i] != '_') return std::nullopt;
            const bool zeroBased = i + 1 < s.size() && s[i + 1] == 'm';
            const size_t at = i + (zeroBased ? 2 : 1);
            if (at + 2 > s.size()) return std::nullopt;
            const int r = s[at] - '0' - (zeroBased ? 0 : 1), c = s[at + 1] - '0' - (zeroBased ? 0 : 1);
            if (r < 0 || r >= b.rows || c < 0 || c >= b.columns) return std::nullopt;
            picked.push_back(size_t(r * b.columns + c));
            i = at + 2;
        }
    } else {
        for (char ch : s) {
            const char* sets[] = {"xyzw", "rgba"};
            size_t k = std::string::npos;
            for (const char* set : sets)
                if (const char* p = std::strchr(set, ch); p && ch) k = size_t(p - set);
            if (k == std::string::npos || int(k) >= b.columns) return std::nullopt;
            picked.push_back(k);
        }
    }
    if (picked.empty() || picked.size() > 4) return std::nullopt;
    return picked;
}

class Evaluator {
public:
    Evaluator(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup, bool integers, const TypedConstantLookup* typed)
        : syntax_(syntax), pos_(span.begin), end_(span.end), lookup_(lookup), integers_(integers), typed_(typed) {}

    std::optional<std::vector<double>> run() {
        auto v = expression();
        if (!v || pos_ != end_) return std::nullopt;
        return v;
    }
    bool tooDeep() const { return tooDeep_; }

private:
    const EffectSyntax& syntax_;
    size_t pos_, end_;
    const ConstantLookup& lookup_;
    const bool integers_;
    const TypedConstantLookup* typed_;
    // Every level of ( or { is one level of recursion here: bounded, so that 30 000
    // nested parentheses are a diagnostic and not a stack overflow.
    int depth_ = 0;
    bool tooDeep_ = false;
    struct Level {
        Evaluator& e;
        explicit Level(Evaluator& ev) : e(ev) {
            if (++e.depth_ > limits::kMaxNesting + 1) e.tooDeep_ = true;  // + 1: the initializer itself
        }
        ~Level() { --e.depth_; }
        Level(const Level&) = delete;
        Level& operator=(const Level&) = delete;
    };

    const Token* cur() const { return pos_ < end_ ? &syntax_.tokens[pos_] : nullptr; }
    bool accept(const char* p) {
        if (cur() && cur()->is(p)) {
            ++pos_;
            return true;
        }
        return false;
    }

    std::optional<std::vector<double>> combine(const std::vector<double>& a, const std::vector<double>& b, char op) const {
        size_t n = std::max(a.size(), b.size());
        // An empty brace list (`{} - 2`, fuzzing) has no value to combine; one operand of size 1 is broadcast.
        if (a.empty() || b.empty() || (a.size() != b.size() && a.size() != 1 && b.size() != 1)) return std::nullopt;
        std::vector<double> r(n);
        for (size_t i = 0; i < n; ++i) {
            double x = a[a.size() == 1 ? 0 : i], y = b[b.size() == 1 ? 0 : i];
            r[i] = op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : integers_ ? std::trunc(x / y) : x / y;
        }
        return r;
    }

    // `c ? a : b` and the comparisons under it, of scalars (Wicked Engine's gpusortlib sizes its
    // thread group `[numthreads(N / (N > 1024 ? N / 1024 : 1), ...)]`); then + and -.
    std::optional<std::vector<double>> expression() {
        Level level(*this);
        if (tooDeep_) return std::nullopt;
        auto condition = comparison();
        if (!condition || !accept("?")) return condition;
        auto yes = expression();
        if (!yes || !accept(":")) return std::nullopt;
        auto no = expression();
        if (!no || condition->size() != 1) return std::nullopt;
        return (*condition)[0] != 0 ? yes : no;
    }
    std::optional<std::vector<double>> comparison() { return compared(true); }
    // == and != over <, >, <= and >= (C's precedence), each left to right; scalars only. The
    // lexer keeps `<=` and `>=` as two tokens (`<` closes templates and annotations).
    std::optional<std::vector<double>> compared(bool equality) {
        auto left = equality ? compared(false) : additive();
        while (left && cur()) {
            std::string op = cur()->text;
            if (equality ? op != "==" && op != "!=" : op != "<" && op != ">") break;
            ++pos_;
            if (!equality && cur() && cur()->is("=") && cur()->offset == syntax_.tokens[pos_ - 1].end) {
                op += "=";
                ++pos_;
            }
            auto right = equality ? compared(false) : additive();
            if (!right || left->size() != 1 || right->size() != 1) return std::nullopt;
            const double x = (*left)[0], y = (*right)[0];
            left = std::vector<double>{double(op == "<" ? x < y : op == ">" ? x > y : op == "<=" ? x <= y : op == ">=" ? x >= y : op == "==" ? x == y : x != y)};
        }
        return left;
    }
    std::optional<std::vector<double>> additive() {
        auto left = term();
        while (left && cur() && (cur()->is("+") || cur()->is("-"))) {
            char op = cur()->text[0];
            ++pos_;
            auto right = term();
            if (!right) return std::nullopt;
            left = combine(*left, *right, op);
        }
        return left;
    }
    std::optional<std::vector<double>> term() {
        auto left = unary();
        while (left && cur() && (cur()->is("*") || cur()->is("/"))) {
            char op = cur()->text[0];
            ++pos_;
            auto right = unary();
            if (!right) return std::nullopt;
            left = combine(*left, *right, op);
        }
        return left;
    }
    std::optional<std::vector<double>> unary() {
        bool negate = false;  // a loop, not recursion: `- - - 1` costs no stack
        for (;;) {
            if (accept("-")) negate = !negate;
            else if (!accept("+")) break;
        }
        auto v = primary();
        if (v && negate)
            for (double& x : *v) x = -x;
        return v;
    }
    std::optional<std::vector<double>> list(const char* close) {
        std::vector<double> all;
        while (!accept(close)) {
            auto v = expression();
            if (!v) return std::nullopt;
            all.insert(all.end(), v->begin(), v->end());
            if (!accept(",")) {
                if (!accept(close)) return std::nullopt;
                break;
            }
        }
        return all;
    }
    static bool isFoldedIntrinsic(const std::string& name) { return name == "min" || name == "max" || name == "abs" || name == "clamp"; }
    // min, max, abs and clamp of constants, per component, a scalar argument going to every one
    // (fxc folds them: OutdoorLightScattering's `[numthreads(max(INITIAL_SAMPLE_STEP, 32), 1, 1)]`).
    std::optional<std::vector<double>> intrinsic(const std::string& name) {
        ++pos_;  // '('
        std::vector<std::vector<double>> args;
        while (!accept(")")) {
            if (!args.empty() && !accept(",")) return std::nullopt;
            auto v = expression();
            if (!v || v->empty()) return std::nullopt;
            args.push_back(std::move(*v));
        }
        if (args.size() != (name == "abs" ? 1u : name == "clamp" ? 3u : 2u)) return std::nullopt;
        size_t n = 1;
        for (const auto& a : args) n = std::max(n, a.size());
        for (const auto& a : args)
            if (a.size() != 1 && a.size() != n) return std::nullopt;
        std::vector<double> r(n);
        for (size_t i = 0; i < n; ++i) {
            auto at = [&](size_t k) { return args[k][args[k].size() == 1 ? 0 : i]; };
            r[i] = name == "abs" ? std::fabs(at(0)) : name == "min" ? std::min(at(0), at(1)) : name == "max" ? std::max(at(0), at(1))
                                                                                       : std::min(std::max(at(0), at(1)), at(2));
        }
        return r;
    }
    // `name[index]` of a constant array of scalars; the index truncates, as fxc's does.
    std::optional<std::vector<double>> element(const std::string& name) {
        const std::vector<double>* array = lookup_(name, true);
        if (!array) return std::nullopt;
        ++pos_;  // '['
        auto index = expression();
        if (!index || index->size() != 1 || !accept("]")) return std::nullopt;
        const double i = (*index)[0];
        if (!(i >= 0) || i >= double(array->size())) return std::nullopt;
        return std::vector<double>{(*array)[static_cast<size_t>(i)]};
    }
    // A typed constant read through `[i]`, `.member` and swizzles down to a numeric value.
    std::optional<std::vector<double>> access(const TypedConstant& c) {
        std::string type = syntax_.resolveType(c.type);
        std::vector<int> dims = c.dims;
        std::vector<double> v = c.values;
        BasicType b = describeBasicType(type);
        for (;;) {
            if (accept("[")) {
                auto index = expression();
                if (!index || index->size() != 1 || !accept("]") || !((*index)[0] >= 0)) return std::nullopt;
                const size_t i = static_cast<size_t>((*index)[0]);
                // An array's element, a matrix's row, a vector's component.
                const size_t count = !dims.empty() ? size_t(dims.front()) : b.isMatrix ? size_t(b.rows) : b.ok ? size_t(b.columns) : 0;
                if (i >= count || v.size() % count != 0) return std::nullopt;
                const size_t n = v.size() / count;
                v = std::vector<double>(v.begin() + std::ptrdiff_t(i * n), v.begin() + std::ptrdiff_t((i + 1) * n));
                if (!dims.empty()) dims.erase(dims.begin());
                else b = BasicType{b.scalar, 1, b.isMatrix ? b.columns : 1, false, true};
            } else if (cur() && cur()->is(".") && pos_ + 1 < end_ && syntax_.tokens[pos_ + 1].isIdent() && dims.empty()) {
                const std::string& name = syntax_.tokens[pos_ + 1].text;
                pos_ += 2;
                if (const FxStruct* st = b.ok ? nullptr : syntax_.findStruct(type)) {
                    size_t offset = 0;
                    const FxStructMember* member = nullptr;
                    for (const auto& m : st->members) {
                        auto scalars = componentScalars(syntax_, m.type, m.arrayDims);
                        if (!scalars) return std::nullopt;
                        if (m.name == name) {
                            member = &m;
                            if (offset + scalars->size() > v.size()) return std::nullopt;
                            v = std::vector<double>(v.begin() + std::ptrdiff_t(offset), v.begin() + std::ptrdiff_t(offset + scalars->size()));
                            break;
                        }
                        offset += scalars->size();
                    }
                    if (!member) return std::nullopt;
                    type = syntax_.resolveType(member->type);
                    dims = member->arrayDims;
                    b = describeBasicType(type);
                } else {
                    auto picked = b.ok ? swizzleComponents(b, name) : std::nullopt;
                    if (!picked) return std::nullopt;
                    std::vector<double> out;
                    for (size_t k : *picked) out.push_back(v[k]);
                    v = std::move(out);
                    b = BasicType{b.scalar, 1, int(v.size()), false, true};
                }
            } else {
                break;
            }
        }
        if (!dims.empty() || !b.ok) return std::nullopt;
        return v;
    }

    std::optional<std::vector<double>> primary() {
        const Token* t = cur();
        if (!t) return std::nullopt;
        if (t->kind == Token::Kind::Number) {
            ++pos_;
            // strtod stops at a suffix (1.0f, 2h); hex literals have none.
            const std::string& s = t->text;
            double v = (s.size() > 2 && (s[1] == 'x' || s[1] == 'X')) ? static_cast<double>(std::strtoull(s.c_str(), nullptr, 16))
                                                                      : std::strtod(s.c_str(), nullptr);
            return std::vector<double>{v};
        }
        if (t->is("(")) {
            ++pos_;
            auto v = expression();
            if (!v || !accept(")")) return std::nullopt;
            return v;
        }
        if (t->is("{")) {
            ++pos_;
            return list("}");
        }
        if (t->isIdent()) {
            ++pos_;
            if (t->text == "true") return std::vector<double>{1.0};
            if (t->text == "false") return std::vector<double>{0.0};
            if (cur() && cur()->is("(") && isFoldedIntrinsic(t->text)) return intrinsic(t->text);
            if (accept("(")) {  // constructor: float3(1, 2, 3) / float4(v, 1)
                BasicType b = describeBasicType(syntax_.resolveType(t->text));
                if (!b.ok) return std::nullopt;
                auto v = list(")");
                if (!v) return std::nullopt;
                size_t want = static_cast<size_t>(b.rows * b.columns);
                if (v->size() == 1 && want > 1) v->assign(want, (*v)[0]);
                if (v->size() != want) return std::nullopt;
                return v;
            }
            if (const std::vector<double>* value = lookup_(t->text, false)) return *value;
            if (const TypedConstant* c = typed_ && *typed_ ? (*typed_)(t->text) : nullptr) return access(*c);
            if (cur() && cur()->is("[")) return element(t->text);
        }
        return std::nullopt;
    }
};

}  // namespace

std::optional<std::vector<double>> evaluateConstant(const EffectSyntax& syntax, TokenSpan span,
                                                    const std::map<std::string, std::vector<double>>& known, bool* tooDeep,
                                                    const std::map<std::string, std::vector<double>>* arrays) {
    auto lookup = [&known, arrays](const std::string& name, bool array) -> const std::vector<double>* {
        const auto* names = array ? arrays : &known;
        if (!names) return nullptr;
        auto it = names->find(name);
        return it == names->end() ? nullptr : &it->second;
    };
    return evaluateConstantWith(syntax, span, lookup, tooDeep);
}

std::optional<std::vector<std::string>> componentScalars(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims) {
    std::vector<std::string> one;
    const std::string& resolved = syntax.resolveType(type);
    if (BasicType b = describeBasicType(resolved); b.ok) {
        one.assign(size_t(b.rows * b.columns), b.scalar);
    } else if (const FxStruct* st = syntax.findStruct(resolved)) {
        for (const auto& m : st->members) {
            if (syntax.resolveType(m.type) == resolved) return std::nullopt;  // no recursion through a broken definition
            auto member = componentScalars(syntax, m.type, m.arrayDims);
            if (!member) return std::nullopt;
            one.insert(one.end(), member->begin(), member->end());
        }
    } else {
        return std::nullopt;
    }
    std::vector<std::string> all;
    size_t copies = 1;
    for (int d : dims) {
        if (d <= 0 || copies * size_t(d) * one.size() > 65536) return std::nullopt;
        copies *= size_t(d);
    }
    for (size_t i = 0; i < copies; ++i) all.insert(all.end(), one.begin(), one.end());
    return all;
}

std::optional<TypedConstant> typedConstant(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims,
                                           std::vector<double> values) {
    auto scalars = componentScalars(syntax, type, dims);
    if (!scalars || scalars->size() != values.size()) return std::nullopt;
    for (size_t k = 0; k < values.size(); ++k) {
        const std::string& s = (*scalars)[k];
        const bool real = s == "float" || s == "half" || s == "double" || s.rfind("min16f", 0) == 0 || s.rfind("min10f", 0) == 0;
        if (!real) values[k] = std::trunc(values[k]);
    }
    return TypedConstant{type, dims, std::move(values)};
}

std::optional<std::vector<double>> evaluateConstantWith(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup,
                                                        bool* tooDeep, bool integers, const TypedConstantLookup* typed) {
    Evaluator evaluator(syntax, span, lookup, integers, typed);
    auto value = evaluator.run();
    if (tooDeep) *tooDeep = evaluator.tooDeep();
    return value;
}

}  // namespace fxport::xlate
