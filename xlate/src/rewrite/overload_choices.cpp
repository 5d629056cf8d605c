// See overload_choices.h.
#include "rewrite/overload_choices.h"

#include <map>
#include <optional>
#include <string>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "rewrite/min_precision_types.h"

namespace fxport::xlate {

namespace {

// The steps of overload_choices.h, each worth more than all milder ones together: the steps an
// overload needs, OR-ed, compare as numbers worst step first.
enum Step : unsigned {
    kCountWidening = 1u << 0,
    kPromotion = 1u << 1,
    kSignChange = 1u << 2,
    kTypeNarrowing = 1u << 3,
    kClassChange = 1u << 4,
    kCountNarrowing = 1u << 5,
};

struct ScalarKind {
    char family = 0;       // 'b' bool, 'i' integer, 'f' floating point
    bool isSigned = true;  // integers
    int width = 0;         // within the family: minimum precision < half < float/int < double
};

std::optional<ScalarKind> kindOf(const std::string& s) {
    static const std::map<std::string, ScalarKind> kinds = {
        {"bool", {'b', false, 0}},      {"min10float", {'f', true, 0}}, {"min16float", {'f', true, 1}},
        {"half", {'f', true, 2}},       {"float", {'f', true, 3}},      {"double", {'f', true, 4}},
        {"min12int", {'i', true, 0}},   {"min16int", {'i', true, 1}},   {"int", {'i', true, 3}},
        {"min16uint", {'i', false, 1}}, {"uint", {'i', false, 3}},      {"dword", {'i', false, 3}},
    };
    auto it = kinds.find(s);
    return it == kinds.end() ? std::nullopt : std::optional<ScalarKind>(it->second);
}

bool isLowPrecisionOrDouble(const std::string& s) { return s != "float" && s != "int" && s != "uint" && s != "dword" && s != "bool"; }

int components(const BasicType& b) { return b.rows * b.columns; }

// fxc's implicit conversions between shapes: a scalar to anything, anything to a scalar, a vector
// to a shorter one, a matrix to a smaller one, and between shapes of as many components.
bool shapeConverts(const BasicType& a, const BasicType& p) {
    if (components(a) == 1 || components(p) == 1 || components(a) == components(p)) return true;
    if (a.isMatrix && p.isMatrix) return p.rows <= a.rows && p.columns <= a.columns;
    if (!a.isMatrix && !p.isMatrix) return p.columns <= a.columns;
    return false;
}

// The steps an argument of type `a` needs to become a parameter of type `p`; nothing when it
// cannot. An unsuffixed integer literal is int and uint alike to fxc.
std::optional<unsigned> steps(const BasicType& a, const BasicType& p, bool intLiteral) {
    auto ka = kindOf(a.scalar), kp = kindOf(p.scalar);
    if (!ka || !kp || !shapeConverts(a, p)) return std::nullopt;
    unsigned s = 0;
    if (components(p) < components(a)) s |= kCountNarrowing;
    if (components(p) > components(a)) s |= kCountWidening;
    if (ka->family != kp->family) return s | kClassChange;
    if (ka->isSigned != kp->isSigned && !intLiteral) s |= kSignChange;
    if (kp->width < ka->width) s |= kTypeNarrowing;
    if (kp->width > ka->width) s |= kPromotion;
    return s;
}

class OverloadChoices {
public:
    explicit OverloadChoices(const EffectSyntax& syntax) : syntax_(syntax), t_(syntax.tokens) {}

    std::vector<TextEdit> run() {
        std::map<std::string, std::vector<const FxFunction*>> byName;
        for (const auto& f : syntax_.functions) byName[f.name].push_back(&f);
        for (const auto& [name, overloads] : byName)
            if (overloads.size() > 1 && inScope(overloads)) choose(name, overloads);
        return std::move(edits_);
    }

private:
    struct Call {
        size_t at;
        const FxFunction* chosen;
    };

    // Sets whose parameters glslang reads as fxc does are left alone; so are sets with a
    // parameter this ranking does not know (arrays, structs, objects, out, defaults).
    bool inScope(const std::vector<const FxFunction*>& overloads) const {
        bool lowOrDouble = false;
        for (const FxFunction* f : overloads)
            for (const auto& p : f->parameters) {
                BasicType b = describeBasicType(syntax_.resolveType(p.type));
                if (!b.ok || !p.arrayDims.empty() || !p.defaultValue.empty() || !kindOf(b.scalar)) return false;
                for (const auto& m : p.modifiers)
                    if (m == "out" || m == "inout") return false;
                lowOrDouble |= isLowPrecisionOrDouble(b.scalar);
            }
        return lowOrDouble;
    }

    void choose(const std::string& name, const std::vector<const FxFunction*>& overloads) {
        std::vector<Call> calls;
        size_t uses = 0, undecided = 0;
        for (size_t i = 0; i < t_.size(); ++i) uses += t_[i].is(name) && t_[i].isIdent();
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                if (!t_[i].is(name) || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
                bool tie = false;
                const FxFunction* chosen = best(f, i, overloads, tie);
                if (tie) return;  // ambiguous or matching none: left to the checks (overload_ties.cpp) and glslang
                if (!chosen) ++undecided;
                else calls.push_back({i, chosen});
            }
        for (const TokenSpan& body : syntax_.memberFunctionBodies)  // no FxFunction to read the types in
            for (size_t i = body.begin; i + 1 < body.end; ++i)
                undecided += t_[i].is(name) && t_[i + 1].is("(") && !(i > 0 && t_[i - 1].is("."));
        // A call this ranking cannot decide (MAGE's `Max(abs(p))` in a struct's member function, beside
        // Max(half3) ... Max(uint3))
        // leaves the set to glslang, whose reading of the twins must still compile: one of each pair
        // keeps the name, and to glslang it is the same function as the renamed one (half read as
        // float), so glslang's pick computes the same.
        if (undecided) return calls.size() + undecided + overloads.size() == uses ? renameCalledTwins(name, overloads) : void();
        if (calls.empty() && overloads.size() == uses) return renameUncalledTwins(name, overloads);
        // A prototype, a compile statement ... name it too; an entry point is named by the caller
        // of the compiler and never called (so a set without calls keeps its names).
        if (calls.empty() || calls.size() + overloads.size() != uses) return;
        std::map<const FxFunction*, std::string> renamed;
        for (size_t k = 0; k < overloads.size(); ++k) {
            renamed[overloads[k]] = name + "_fxport_o" + std::to_string(k + 1);
            const Token& n = t_[overloads[k]->token];
            edits_.push_back({n.offset, n.end, renamed[overloads[k]]});
        }
        for (const Call& c : calls) edits_.push_back({t_[c.at].offset, t_[c.at].end, renamed[c.chosen]});
    }

    // A set nothing calls (FidelityFX's `AToThreeF1(AF1)` beside `AToThreeF1(AH1)`, AH1 being
    // min16float, on a path that uses neither) has no call to choose for, but two definitions
    // glslang reads alike are still one function defined twice to it. Each that a later one
    // repeats for glslang is renamed: uncalled, its name matters to no call, and the last keeps
    // the name, as fxc's entry point among overloads is the one declared last.
    void renameUncalledTwins(const std::string& name, const std::vector<const FxFunction*>& overloads) {
        for (size_t k = 0; k < overloads.size(); ++k)
            for (size_t j = k + 1; j < overloads.size(); ++j)
                if (sameToGlslang(*overloads[k], *overloads[j])) {
                    const Token& n = t_[overloads[k]->token];
                    edits_.push_back({n.offset, n.end, name + "_fxport_o" + std::to_string(k + 1)});
                    break;
                }
    }

    // The calls left to glslang must see a definition declared before them, as glslang's
    // (and fxc's) lookup does: here the first of twins keeps the name, each later one is renamed.
    void renameCalledTwins(const std::string& name, const std::vector<const FxFunction*>& overloads) {
        for (size_t k = 0; k < overloads.size(); ++k)
            for (size_t j = 0; j < k; ++j)
                if (sameToGlslang(*overloads[k], *overloads[j])) {
                    const Token& n = t_[overloads[k]->token];
                    edits_.push_back({n.offset, n.end, name + "_fxport_o" + std::to_string(k + 1)});
                    break;
                }
    }

    bool sameToGlslang(const FxFunction& a, const FxFunction& b) const {
        if (a.parameters.size() != b.parameters.size()) return false;
        for (size_t k = 0; k < a.parameters.size(); ++k) {
            BasicType x = describeBasicType(syntax_.resolveType(a.parameters[k].type));
            BasicType y = describeBasicType(syntax_.resolveType(b.parameters[k].type));
            auto scalar = [](const std::string& s) { return fullPrecisionScalar(s) ? std::string(fullPrecisionScalar(s)) : s; };
            if (x.rows != y.rows || x.columns != y.columns || x.isMatrix != y.isMatrix || scalar(x.scalar) != scalar(y.scalar)) return false;
        }
        return true;
    }

    // fxc's pick for the call whose name is at `at` in `caller`; nothing for a tie or no match
    // (`tied` set) or an argument whose type is not evident.
    const FxFunction* best(const FxFunction& caller, size_t at, const std::vector<const FxFunction*>& overloads, bool& tied) const {
        tied = false;
        auto spans = callArgumentSpans(t_, at + 1, caller.body.end);
        if (spans.empty() && !t_[at + 2].is(")")) return nullptr;
        std::vector<BasicType> args;
        std::vector<bool> literal;
        for (auto [b, e] : spans) {
            auto type = expressionType(syntax_, caller, b, e);
            if (!type || !type->isNumeric()) return nullptr;
            args.push_back(type->basic);
            literal.push_back(e == b + 1 && t_[b].kind == Token::Kind::Number && type->basic.scalar == "int");
        }
        const FxFunction* winner = nullptr;
        std::optional<unsigned> winning;
        bool tie = false;
        for (const FxFunction* f : overloads) {
            auto rank = rankOf(*f, args, literal);
            if (!rank) continue;
            if (!winning || *rank < *winning) {
                winner = f;
                winning = rank;
                tie = false;
            } else if (*rank == *winning) {
                tie = true;
            }
        }
        tied = tie || !winner;  // every argument's type known: fxc's answer is this one (or its error)
        return tie ? nullptr : winner;
    }

    std::optional<unsigned> rankOf(const FxFunction& f, const std::vector<BasicType>& args, const std::vector<bool>& literal) const {
        if (f.parameters.size() != args.size()) return std::nullopt;
        unsigned rank = 0;
        for (size_t k = 0; k < args.size(); ++k) {
            auto s = steps(args[k], describeBasicType(syntax_.resolveType(f.parameters[k].type)), literal[k]);
            if (!s) return std::nullopt;
            rank |= *s;
        }
        return rank;
    }

    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    std::vector<TextEdit> edits_;
};

}  // namespace

std::vector<TextEdit> fxcOverloadChoices(const EffectSyntax& syntax) { return OverloadChoices(syntax).run(); }

}  // namespace fxport::xlate
