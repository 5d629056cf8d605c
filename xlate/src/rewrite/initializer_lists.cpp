// See initializer_lists.h.
#include "rewrite/initializer_lists.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>

#include "hlsl/aggregate_components.h"
#include "hlsl/expression_types.h"
#include "rewrite/array_sizes.h"
#include "rewrite/min_precision_types.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

// Enough for any real declaration; deeper type nesting (a struct holding itself through typedefs)
// or larger arrays are left to glslang.
constexpr int kMaxDepth = 16;
constexpr size_t kMaxLeaves = 65536;

bool isLiteral(const Token& t) { return t.kind == Token::Kind::Number || t.is("true") || t.is("false"); }

// One item of a brace list, braces flattened away: what it gives, component by component.
struct Element {
    size_t begin = 0, end = 0;       // its tokens
    std::vector<std::string> parts;  // each component spelled on its own (text repeated)
    bool vectorLike = false;         // a scalar, vector or object: it can stand whole where its components go together
    bool literal = false;            // nothing to evaluate (a literal, a constructor of literals)
    bool pure = true;                // repeating its text changes nothing (no call, no assignment)
    std::string whole;               // its text where it is not kept in place (a temporary's name)
    std::string tempType;            // the type a temporary holding it is declared with (as glslang spells it; a variable's as declared)
    std::vector<int> tempDims;
    std::string componentType;       // the type its components are named through (aggregate_components.h)
};

// Whether repeating tokens [b, e) is harmless: no call (but numeric constructors), no assignment,
// no increment.
bool isPure(const EffectSyntax& syntax, size_t b, size_t e) {
    const auto& t = syntax.tokens;
    for (size_t k = b; k < e; ++k) {
        const std::string& x = t[k].text;
        if (t[k].kind != Token::Kind::Punct) continue;
        if (x == "++" || x == "--") return false;
        if (x.back() == '=' && x != "==" && x != "!=" && x != "<=" && x != ">=") return false;
        if (x == "(" && k > b && t[k - 1].isIdent() && !describeBasicType(syntax.resolveType(t[k - 1].text)).ok) return false;
    }
    return true;
}

// The items of a brace list, flattened: `{1, -2, float2(3, 4), {p.x}}` gives four elements. A
// literal, a constructor of literals (one literal broadcast to its size: `float3(0)`), a variable
// named alone (its components, aggregate_components.h) or, inside a function, any expression whose
// type expression_types.h knows. nullopt where an item is none of these: the list is glslang's then.
class ListReader {
public:
    ListReader(const EffectSyntax& syntax, const FxFunction* f, size_t at) : syntax_(syntax), t_(syntax.tokens), f_(f), at_(at) {}

    std::optional<std::vector<Element>> list() {
        std::vector<Element> out;
        if (!braced(out, 0)) return std::nullopt;
        return out;
    }
    size_t end() const { return at_; }  // one past the closing brace
    // Whether an item is a variable or an aggregate value: glslang does not flatten those for a vector.
    bool sawAggregate() const { return sawAggregate_; }

private:
    bool braced(std::vector<Element>& out, int depth) {
        if (depth > kMaxDepth || !t_[at_].is("{")) return false;
        ++at_;
        while (!t_[at_].is("}")) {
            if (!item(out, depth)) return false;
            if (t_[at_].is(",")) ++at_;
            else if (!t_[at_].is("}")) return false;
        }
        ++at_;
        return leaves_ <= kMaxLeaves;
    }
    bool item(std::vector<Element>& out, int depth) {
        if (t_[at_].is("{")) return braced(out, depth + 1);
        Element e;
        e.begin = at_;
        const bool ok = scalar(e) || constructorOfLiterals(e) || variable(e) || expression(e);
        if (!ok) return false;
        e.end = at_;
        leaves_ += e.parts.size();
        out.push_back(std::move(e));
        return true;
    }
    std::optional<std::string> literalText() {
        size_t k = at_;
        std::string sign;
        if (t_[k].is("-") || t_[k].is("+")) sign = t_[k++].text;
        if (!isLiteral(t_[k])) return std::nullopt;
        at_ = k + 1;
        return sign + t_[k].text;
    }
    bool scalar(Element& e) {
        size_t k = at_;
        auto text = literalText();
        if (!text || !(t_[at_].is(",") || t_[at_].is("}"))) {
            at_ = k;
            return false;
        }
        e.parts = {*text};
        e.vectorLike = e.literal = true;
        return true;
    }
    bool constructorOfLiterals(Element& e) {
        const size_t start = at_;
        if (!t_[at_].isIdent() || !t_[at_ + 1].is("(")) return false;
        BasicType type = describeBasicType(t_[at_].text);
        if (!type.ok) return false;
        at_ += 2;
        std::vector<std::string> args;
        while (!t_[at_].is(")")) {
            auto s = literalText();
            if (!s) return at_ = start, false;
            args.push_back(*s);
            if (t_[at_].is(",")) ++at_;
            else if (!t_[at_].is(")")) return at_ = start, false;
        }
        ++at_;
        const size_t size = size_t(type.rows * type.columns);
        if (args.size() == 1) args = std::vector<std::string>(size, args.front());
        if (args.size() != size || !(t_[at_].is(",") || t_[at_].is("}"))) return at_ = start, false;
        e.parts = std::move(args);
        e.literal = true;
        return true;
    }
    // A variable named alone: its components, as many as it has; a scalar, vector or object whole.
    bool variable(Element& e) {
        if (!f_ || !t_[at_].isIdent() || !(t_[at_ + 1].is(",") || t_[at_ + 1].is("}"))) return false;
        const std::string& name = t_[at_].text;
        auto declared = declaredVariable(syntax_, *f_, name, at_);
        if (!declared && (syntax_.findTexture(name) || syntax_.findSampler(name))) {  // an object: itself
            e.parts = {name};
            e.vectorLike = true;
        } else {
            std::vector<AggregateComponent> parts;
            if (!declared || !aggregateComponents(syntax_, declared->type, declared->dims, name, false, parts, true)) return false;
            for (auto& p : parts) e.parts.push_back(std::move(p.access));
            const BasicType b = describeBasicType(syntax_.resolveType(declared->type));
            e.vectorLike = declared->dims.empty() && b.ok && !b.isMatrix;
            if (std::none_of(parts.begin(), parts.end(), [](const AggregateComponent& c) { return c.object; })) {
                e.tempType = e.componentType = declared->type;
                e.tempDims = declared->dims;
            }
        }
        sawAggregate_ = true;
        ++at_;
        return true;
    }
    // Any other expression, up to the next `,` or `}` outside brackets, whose type is evident.
    bool expression(Element& e) {
        if (!f_) return false;
        size_t end = at_;
        for (int depth = 0; end < f_->body.end && !(depth == 0 && (t_[end].is(",") || t_[end].is("}"))); ++end) {
            if (t_[end].is("(") || t_[end].is("[") || t_[end].is("{")) ++depth;
            if (t_[end].is(")") || t_[end].is("]") || t_[end].is("}")) --depth;
            if (depth < 0 || t_[end].is(";")) return false;
        }
        auto type = expressionType(syntax_, *f_, at_, end);
        if (!type || type->keptMatrix || end == at_) return false;
        for (int d : type->dims)
            if (d <= 0) return false;
        if (type->structName.empty() && !type->basic.ok) return false;
        e.componentType = type->structName.empty() ? spellType(type->basic) : type->structName;
        e.tempType = type->structName.empty() ? glslangSpelling(type->basic) : type->structName;
        e.tempDims = type->dims;
        std::vector<AggregateComponent> parts;
        if (!aggregateComponents(syntax_, e.componentType, e.tempDims, "(" + syntax_.text({at_, end}) + ")", false, parts)) return false;
        for (auto& p : parts) e.parts.push_back(std::move(p.access));
        e.vectorLike = type->isNumeric() && !type->basic.isMatrix;
        e.pure = isPure(syntax_, at_, end);
        sawAggregate_ = sawAggregate_ || !e.vectorLike;
        at_ = end;
        return true;
    }

    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    const FxFunction* f_;
    size_t at_;
    size_t leaves_ = 0;
    bool sawAggregate_ = false;
};

// The regrouped initializer as it is written out: generated text, with the elements that stand
// whole in their place between (so other rewrites' edits inside them still apply).
struct Segment {
    std::string text;
    size_t element = SIZE_MAX;  // an element kept in place, else `text`
};

// Writes the declared type's initializer from the elements' components, in fxc's order (array
// elements, struct members, matrix rows). False when the type is not one we can spell or the count
// differs. A run of components that is one whole scalar, vector or object element is that element
// (in place, or its `whole` text); other components are spelled one by one, and their element is
// marked split.
class Regrouper {
public:
    Regrouper(const EffectSyntax& syntax, const std::vector<Element>& elements) : syntax_(syntax), elements_(elements) {
        for (size_t e = 0; e < elements.size(); ++e)
            for (size_t c = 0; c < elements[e].parts.size(); ++c) leaves_.push_back({e, c});
        split.assign(elements.size(), false);
    }

    bool write(const std::string& type, const std::vector<int>& dims, size_t dim, int depth = 0) {
        if (depth > kMaxDepth) return false;
        if (dim < dims.size()) {
            text("{");
            for (int i = 0; i < dims[dim]; ++i) {
                if (i) text(", ");
                if (!write(type, dims, dim + 1, depth + 1)) return false;
            }
            text("}");
            return true;
        }
        if (const FxStruct* s = syntax_.findStruct(type)) {
            text("{");
            for (size_t m = 0; m < s->members.size(); ++m) {
                if (m) text(", ");
                if (!write(s->members[m].type, s->members[m].arrayDims, 0, depth + 1)) return false;
            }
            text("}");
            return true;
        }
        BasicType basic = describeBasicType(type);
        if (!basic.ok && isResourceType(type) && next_ < leaves_.size()) {  // a texture member: one item, as written
            components(1);
            return true;
        }
        if (!basic.ok || type.find('<') != std::string::npos) return false;
        size_t size = size_t(basic.rows * basic.columns);
        if (next_ + size > leaves_.size()) return false;
        // A one-row or one-column matrix is a vector to glslang (see degenerate_matrices.h).
        const bool degenerate = basic.isMatrix && (basic.rows == 1 || basic.columns == 1);
        const bool constructor = size > 1 || (basic.isMatrix && !degenerate);
        // A min-precision matrix constructor is spelled as its 32-bit type, as glslang reads the declaration's (min_precision_types.h).
        const std::string full = fullPrecisionMatrixName(type);
        if (constructor) text((degenerate ? basic.scalar + std::to_string(size) : full.empty() ? type : full) + "(");
        components(size, basic.isMatrix && !degenerate);
        if (constructor) text(")");
        return true;
    }
    bool usedAll() const { return next_ == leaves_.size(); }

    std::vector<Segment> segments;
    std::vector<bool> split;  // per element

private:
    struct Leaf {
        size_t element, component;
    };
    void text(const std::string& s) {
        if (segments.empty() || segments.back().element != SIZE_MAX) segments.push_back({});
        segments.back().text += s;
    }
    // The next `size` components, separated by commas. A matrix's constructor takes scalars only
    // (glslang 12 crashes on some vectors there).
    void components(size_t size, bool scalarsOnly = false) {
        for (size_t k = 0; k < size;) {
            if (k) text(", ");
            const Leaf& leaf = leaves_[next_ + k];
            const Element& e = elements_[leaf.element];
            const size_t count = e.parts.size();
            if (leaf.component == 0 && k + count <= size && e.vectorLike && (!scalarsOnly || count == 1)) {
                if (!e.whole.empty()) text(e.whole);
                else segments.push_back({{}, leaf.element});
                k += count;
                continue;
            }
            split[leaf.element] = true;
            text(e.parts[leaf.component]);
            ++k;
        }
        next_ += size;
    }

    const EffectSyntax& syntax_;
    const std::vector<Element>& elements_;
    std::vector<Leaf> leaves_;
    size_t next_ = 0;
};

// The edits that turn the brace list [open, close] into `segments`: the text between two elements
// kept in place replaces what lies between them.
std::vector<TextEdit> segmentEdits(const std::vector<Token>& t, size_t open, size_t close, const std::vector<Element>& elements,
                                   const std::vector<Segment>& segments) {
    std::vector<TextEdit> edits;
    size_t from = t[open].offset;
    std::string pending;
    for (const Segment& s : segments) {
        if (s.element == SIZE_MAX) {
            pending += s.text;
            continue;
        }
        const Element& e = elements[s.element];
        edits.push_back({from, t[e.begin].offset, pending});
        pending.clear();
        from = t[e.end - 1].end;
    }
    edits.push_back({from, t[close].end, pending});
    // An empty gap between two elements (no text, nothing between) is no edit.
    edits.erase(std::remove_if(edits.begin(), edits.end(), [](const TextEdit& x) { return x.begin == x.end && x.replacement.empty(); }), edits.end());
    return edits;
}

// The start of the local declaration whose type token is `type`: back over its modifiers to the
// previous statement. nullopt where temporaries cannot go before it: a static (initialized once),
// a declaration inside a `for (...)`, after `else` or a `case` label.
std::optional<size_t> declarationStart(const std::vector<Token>& t, const FxFunction& f, size_t type) {
    size_t start = type;
    for (; start > f.body.begin + 1 && !(t[start - 1].is(";") || t[start - 1].is("{") || t[start - 1].is("}")); --start)
        if (!t[start - 1].isIdent() || t[start - 1].is("static") || t[start - 1].is("else") || t[start - 1].is("return")) return std::nullopt;
    return start > f.body.begin ? std::optional<size_t>(start) : std::nullopt;
}

// Elements split into components that must not be repeated (a call, an assignment) are evaluated
// once, in order, into temporaries declared just before the declaration: every element up to the
// last such one that is not a literal (an earlier one must still be read before it runs).
// The temporaries' declarations (one line); false where none can be declared.
bool evaluateOnce(const EffectSyntax& syntax, const FxFunction* f, size_t type, std::vector<Element>& elements, const std::vector<bool>& split,
                  std::string& declarations, size_t& at) {
    size_t last = SIZE_MAX;
    for (size_t e = 0; e < elements.size(); ++e)
        if (split[e] && !elements[e].pure) last = e;
    if (last == SIZE_MAX) return true;
    if (!f) return false;
    auto start = declarationStart(syntax.tokens, *f, type);
    if (!start) return false;
    at = *start;
    for (size_t e = 0; e <= last; ++e) {
        Element& x = elements[e];
        if (x.literal) continue;
        if (x.tempType.empty()) return false;  // an object
        const std::string name = "fxport_init_" + std::to_string(x.begin);
        std::string dims;
        for (int d : x.tempDims) dims += "[" + std::to_string(d) + "]";
        declarations += x.tempType + " " + name + dims + " = " + syntax.text({x.begin, x.end}) + "; ";
        std::vector<AggregateComponent> parts;
        if (!aggregateComponents(syntax, x.componentType, x.tempDims, name, false, parts)) return false;
        x.parts.clear();
        for (auto& p : parts) x.parts.push_back(std::move(p.access));
        x.whole = name;
    }
    return true;
}

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
        const bool nested = nestsBraces(t, i + 1);
        ListReader reader(syntax, f, i + 1);
        auto elements = reader.list();
        if (!elements) continue;
        std::string type = aggregateType(syntax, t[nameAt - 1].text, !dims->empty(), nested || reader.sawAggregate());
        if (type.empty()) continue;
        size_t leaves = 0;
        for (const Element& e : *elements) leaves += e.parts.size();
        if (!dims->empty() && (*dims)[0] == 0) {  // `float2 o[] = {...}`: fxc sizes it from the list
            size_t each = leafCount(syntax, type);
            for (size_t d = 1; d < dims->size(); ++d) each *= size_t((*dims)[d]);
            if (each == 0 || leaves % each != 0) continue;
            (*dims)[0] = int(leaves / each);
        }
        Regrouper regroup(syntax, *elements);
        if (!regroup.write(type, *dims, 0) || !regroup.usedAll()) continue;
        std::string temporaries;
        size_t start = 0;
        if (!evaluateOnce(syntax, f, nameAt - 1, *elements, regroup.split, temporaries, start)) continue;
        std::vector<Segment> segments = std::move(regroup.segments);
        if (!temporaries.empty()) {
            Regrouper again(syntax, *elements);  // the same grouping, through the temporaries
            again.write(type, *dims, 0);
            edits.push_back({t[start].offset, t[start].offset, temporaries});
            segments = std::move(again.segments);
        }
        for (auto& e : segmentEdits(t, i + 1, reader.end() - 1, *elements, segments)) edits.push_back(std::move(e));
        i = reader.end() - 1;
    }
    return edits;
}

}  // namespace fxport::xlate
