// See initializer_lists.h.
#include "rewrite/initializer_lists.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>

#include "hlsl/aggregate_components.h"
#include "rewrite/array_sizes.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

// Enough for any real declaration; deeper type nesting (a struct holding itself through typedefs)
// or larger arrays are left to glslang.
constexpr int kMaxDepth = 16;
constexpr size_t kMaxLeaves = 65536;

bool isLiteral(const Token& t) { return t.kind == Token::Kind::Number || t.is("true") || t.is("false"); }

// The literal texts of a brace list, flattened: `{1, -2, float2(3, 4), {5}}` -> 1 -2 3 4 5.
// A constructor of one literal is broadcast to its size (`float3(0)`). nullopt for anything else.
// A variable named alone in the list (`{1, v, 4}`) gives its components (aggregate_components.h)
// through `variable`, when one is given and knows it.
class LeafReader {
public:
    using Variable = std::function<bool(const std::string& name, std::vector<std::string>& out)>;
    LeafReader(const std::vector<Token>& tokens, size_t at, Variable variable = {}) : t_(tokens), at_(at), variable_(std::move(variable)) {}

    std::optional<std::vector<std::string>> list() {
        std::vector<std::string> out;
        if (!braced(out, 0)) return std::nullopt;
        return out;
    }
    size_t end() const { return at_; }  // one past the closing brace
    bool sawVariable() const { return sawVariable_; }

private:
    bool braced(std::vector<std::string>& out, int depth) {
        if (depth > kMaxDepth || !t_[at_].is("{")) return false;
        ++at_;
        while (!t_[at_].is("}")) {
            if (!item(out, depth)) return false;
            if (t_[at_].is(",")) ++at_;
            else if (!t_[at_].is("}")) return false;
        }
        ++at_;
        return out.size() <= kMaxLeaves;
    }
    bool item(std::vector<std::string>& out, int depth) {
        if (t_[at_].is("{")) return braced(out, depth + 1);
        if (auto s = scalar()) {
            out.push_back(*s);
            return true;
        }
        if (t_[at_].isIdent() && (t_[at_ + 1].is(",") || t_[at_ + 1].is("}"))) {
            if (!variable_ || !variable_(t_[at_].text, out)) return false;
            ++at_;
            sawVariable_ = true;
            return true;
        }
        if (!t_[at_].isIdent() || !t_[at_ + 1].is("(")) return false;
        BasicType type = describeBasicType(t_[at_].text);
        if (!type.ok) return false;
        at_ += 2;
        std::vector<std::string> args;
        while (!t_[at_].is(")")) {
            auto s = scalar();
            if (!s) return false;
            args.push_back(*s);
            if (t_[at_].is(",")) ++at_;
            else if (!t_[at_].is(")")) return false;
        }
        ++at_;
        size_t size = size_t(type.rows * type.columns);
        if (args.size() == 1) {
            const std::string one = args.front();
            args = std::vector<std::string>(size, one);
        }
        if (args.size() != size) return false;
        out.insert(out.end(), args.begin(), args.end());
        return true;
    }
    std::optional<std::string> scalar() {
        std::string sign;
        if (t_[at_].is("-") || t_[at_].is("+")) sign = t_[at_++].text;
        if (!isLiteral(t_[at_])) return std::nullopt;
        return sign + t_[at_++].text;
    }

    const std::vector<Token>& t_;
    size_t at_;
    Variable variable_;
    bool sawVariable_ = false;
};

// Writes the declared type's initializer from `leaves`, in fxc's order (array elements, struct
// members, matrix rows). False when the type is not one we can spell or the count differs.
class Regrouper {
public:
    Regrouper(const EffectSyntax& syntax, const std::vector<std::string>& leaves) : syntax_(syntax), leaves_(leaves) {}

    bool write(const std::string& type, const std::vector<int>& dims, size_t dim, std::string& out, int depth = 0) {
        if (depth > kMaxDepth) return false;
        if (dim < dims.size()) {
            out += "{";
            for (int i = 0; i < dims[dim]; ++i) {
                if (i) out += ", ";
                if (!write(type, dims, dim + 1, out, depth + 1)) return false;
            }
            out += "}";
            return true;
        }
        if (const FxStruct* s = syntax_.findStruct(type)) {
            out += "{";
            for (size_t m = 0; m < s->members.size(); ++m) {
                if (m) out += ", ";
                if (!write(s->members[m].type, s->members[m].arrayDims, 0, out, depth + 1)) return false;
            }
            out += "}";
            return true;
        }
        BasicType basic = describeBasicType(type);
        if (!basic.ok && isResourceType(type) && next_ < leaves_.size()) {  // a texture member: one item, as written
            out += leaves_[next_++];
            return true;
        }
        if (!basic.ok || type.find('<') != std::string::npos) return false;
        size_t size = size_t(basic.rows * basic.columns);
        if (next_ + size > leaves_.size()) return false;
        // A one-row or one-column matrix is a vector to glslang (see degenerate_matrices.h).
        const bool degenerate = basic.isMatrix && (basic.rows == 1 || basic.columns == 1);
        const bool constructor = size > 1 || (basic.isMatrix && !degenerate);
        if (constructor) out += (degenerate ? basic.scalar + std::to_string(size) : type) + "(";
        for (size_t k = 0; k < size; ++k) out += (k ? ", " : "") + leaves_[next_++];
        if (constructor) out += ")";
        return true;
    }
    bool usedAll() const { return next_ == leaves_.size(); }

private:
    const EffectSyntax& syntax_;
    const std::vector<std::string>& leaves_;
    size_t next_ = 0;
};

// Array dimensions of constant sizes (array_sizes.h), read backwards from the token before `=`;
// `[]` takes its size from the leaves. Sets `nameAt` to the declared name's token. nullopt: not a
// declaration we know.
std::optional<std::vector<int>> dimsBefore(const std::vector<Token>& t, const ConstantSizes& sizes, size_t equals, size_t& nameAt) {
    std::vector<int> dims;
    size_t at = equals;
    while (at >= 3 && t[at - 1].is("]")) {
        int depth = 0;
        size_t open = at - 1;
        for (; open > 0; --open) {
            if (t[open].is("]")) ++depth;
            if (t[open].is("[") && --depth == 0) break;
        }
        auto size = depth == 0 ? sizes.size(open, at - 1) : std::nullopt;
        if (!size) return std::nullopt;
        dims.push_back(*size);
        at = open;
    }
    if (at < 2 || !t[at - 1].isIdent()) return std::nullopt;
    nameAt = at - 1;
    std::reverse(dims.begin(), dims.end());  // read last to first
    return dims;
}

// The declared type's name with typedefs resolved, when it is an array, a struct or a matrix (the
// forms glslang refuses flat), or a vector whose list nests braces (`float4 v = {1, {{2, {3}}, 4}};`
// which glslang takes, but fills 1, 4, 0, 0) or names a variable (glslang takes a flat list of
// scalars for a vector, not one that names a variable) when `orVector`; empty otherwise.
std::string aggregateType(const EffectSyntax& syntax, const std::string& written, bool isArray, bool orVector) {
    std::string type = written;
    auto td = syntax.typedefs.find(type);
    if (td != syntax.typedefs.end()) type = td->second;
    if (isArray || syntax.findStruct(type)) return type;
    BasicType basic = describeBasicType(type);
    return basic.ok && (basic.isMatrix || (orVector && basic.columns > 1)) ? type : std::string();
}

// Whether the brace list opening at `open` holds another brace list.
bool nestsBraces(const std::vector<Token>& t, size_t open) {
    int depth = 0;
    for (size_t k = open; k < t.size(); ++k) {
        if (t[k].is("{") && ++depth > 1) return true;
        if (t[k].is("}") && --depth == 0) return false;
        if (t[k].is(";")) return false;
    }
    return false;
}

// The function whose body holds token i, or nullptr.
const FxFunction* functionAt(const EffectSyntax& syntax, size_t i) {
    for (const auto& f : syntax.functions)
        if (i > f.body.begin && i < f.body.end) return &f;
    return nullptr;
}

size_t leafCount(const EffectSyntax& syntax, const std::string& type, int depth = 0) {
    if (depth > kMaxDepth) return 0;
    if (const FxStruct* s = syntax.findStruct(type)) {
        size_t n = 0;
        for (const auto& m : s->members) {
            size_t each = leafCount(syntax, m.type, depth + 1);
            for (int d : m.arrayDims) each *= size_t(d > 0 ? d : 0);
            n += each;
        }
        return n;
    }
    BasicType basic = describeBasicType(type);
    return basic.ok ? size_t(basic.rows * basic.columns) : 0;
}

}  // namespace

std::vector<TextEdit> regroupFlatInitializers(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const std::vector<Token>& t = syntax.tokens;
    const ConstantSizes sizes(syntax);
    for (size_t i = 1; i + 1 < t.size(); ++i) {
        if (!t[i].is("=") || !t[i + 1].is("{")) continue;
        size_t nameAt = 0;
        auto dims = dimsBefore(t, sizes, i, nameAt);
        if (!dims || nameAt == 0 || !t[nameAt - 1].isIdent()) continue;
        const FxFunction* f = functionAt(syntax, i);
        LeafReader::Variable variable;
        if (f)
            variable = [&syntax, f, i](const std::string& name, std::vector<std::string>& out) {
                auto declared = declaredVariable(syntax, *f, name, i);
                if (!declared && (syntax.findTexture(name) || syntax.findSampler(name))) {  // an object: itself
                    out.push_back(name);
                    return true;
                }
                std::vector<AggregateComponent> parts;
                if (!declared || !aggregateComponents(syntax, declared->type, declared->dims, name, false, parts, true)) return false;
                for (auto& p : parts) out.push_back(std::move(p.access));
                return true;
            };
        const bool nested = nestsBraces(t, i + 1);
        LeafReader reader(t, i + 1, variable);
        auto leaves = reader.list();
        if (!leaves) continue;
        std::string type = aggregateType(syntax, t[nameAt - 1].text, !dims->empty(), nested || reader.sawVariable());
        if (type.empty()) continue;
        if (!dims->empty() && (*dims)[0] == 0) {  // `float2 o[] = {...}`: fxc sizes it from the list
            size_t each = leafCount(syntax, type);
            for (size_t d = 1; d < dims->size(); ++d) each *= size_t((*dims)[d]);
            if (each == 0 || leaves->size() % each != 0) continue;
            (*dims)[0] = int(leaves->size() / each);
        }
        std::string text;
        Regrouper regroup(syntax, *leaves);
        if (!regroup.write(type, *dims, 0, text) || !regroup.usedAll()) continue;
        edits.push_back({t[i + 1].offset, t[reader.end() - 1].end, text});
        i = reader.end() - 1;
    }
    return edits;
}

}  // namespace fxport::xlate
