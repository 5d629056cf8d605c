// Evaluates parameter initialisers (see constant_eval.h) by recursive descent, nesting bounded.
#include "fx/constant_eval.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fx/input_limits.h"

#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

class Evaluator {
public:
    Evaluator(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup, bool integers)
        : syntax_(syntax), pos_(span.begin), end_(span.end), lookup_(lookup), integers_(integers) {}

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
        if (a.size() != b.size() && a.size() != 1 && b.size() != 1) return std::nullopt;
        std::vector<double> r(n);
        for (size_t i = 0; i < n; ++i) {
            double x = a[a.size() == 1 ? 0 : i], y = b[b.size() == 1 ? 0 : i];
            r[i] = op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : integers_ ? std::trunc(x / y) : x / y;
        }
        return r;
    }

    std::optional<std::vector<double>> expression() {
        Level level(*this);
        if (tooDeep_) return std::nullopt;
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

std::optional<std::vector<double>> evaluateConstantWith(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup,
                                                        bool* tooDeep, bool integers) {
    Evaluator evaluator(syntax, span, lookup, integers);
    auto value = evaluator.run();
    if (tooDeep) *tooDeep = evaluator.tooDeep();
    return value;
}

}  // namespace fxport::xlate
