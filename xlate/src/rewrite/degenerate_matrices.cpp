// See degenerate_matrices.h: one-row and one-column matrices respelled as vectors, and their
// indexing with them.
#include "rewrite/degenerate_matrices.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"
#include "rewrite/matrix_swizzle.h"
#include "rewrite/mixed_shapes.h"

namespace fxport::xlate {

namespace {

// How indexing of a variable of such a type changes.
enum class Shape { Row, Column, Scalar };  // 1xN, Nx1, 1x1

struct Degenerate {
    size_t end = 0;       // one past the type's last token
    std::string vector;   // the type that replaces it: float4, int3, float
    std::string scalar;   // its component type
    Shape shape = Shape::Row;
};

// A type starting at token i that is a matrix of one row or column: `float1x4`, `matrix<int, 3, 1>`.
std::optional<Degenerate> degenerateAt(const std::vector<Token>& t, size_t i) {
    if (!t[i].isIdent() || (i > 0 && t[i - 1].is("."))) return std::nullopt;
    std::string text = t[i].text;
    size_t end = i + 1;
    if (text == "matrix" && i + 7 < t.size() && t[i + 1].is("<") && t[i + 3].is(",") && t[i + 5].is(",") && t[i + 7].is(">")) {
        text = "matrix<" + t[i + 2].text + "," + t[i + 4].text + "," + t[i + 6].text + ">";
        end = i + 8;
    }
    BasicType b = describeBasicType(text);
    if (!b.ok || !b.isMatrix || (b.rows != 1 && b.columns != 1)) return std::nullopt;
    const int n = b.rows * b.columns;
    Degenerate d;
    d.end = end;
    d.vector = n == 1 ? b.scalar : b.scalar + std::to_string(n);
    d.scalar = b.scalar;
    d.shape = n == 1 ? Shape::Scalar : b.rows == 1 ? Shape::Row : Shape::Column;
    return d;
}

// Index one past the `]` matching the `[` at token i.
size_t pastBracket(const std::vector<Token>& t, size_t i, size_t end) {
    int depth = 0;
    for (; i < end; ++i) {
        if (t[i].is("[")) ++depth;
        else if (t[i].is("]") && --depth == 0) return i + 1;
    }
    return end;
}

// Names declared by `T a, b = x, c;` after the type's last token: variables, not arrays.
void declaredNames(const std::vector<Token>& t, size_t i, size_t end, Shape shape, std::map<std::string, Shape>& names) {
    bool expectName = true;
    int depth = 0;
    for (; i < end; ++i) {
        if (depth == 0 && (t[i].is(";") || t[i].is(")"))) return;
        if (t[i].is("(") || t[i].is("[") || t[i].is("{")) {
            if (depth == 0 && t[i].is("[") && i > 0 && t[i - 1].isIdent()) names.erase(t[i - 1].text);  // an array
            ++depth;
        } else if (t[i].is(")") || t[i].is("]") || t[i].is("}")) {
            --depth;
        } else if (depth == 0 && t[i].is(",")) {
            expectName = true;
        } else if (expectName && depth == 0 && t[i].isIdent()) {
            names[t[i].text] = shape;
            expectName = false;
        } else if (depth == 0) {
            expectName = false;
        }
    }
}

bool isStatic(const FxGlobal& g) { return std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end(); }

// The global declared by the type at token i, if any (its name within a few tokens after it).
const FxGlobal* globalTypedAt(const EffectSyntax& syntax, size_t i) {
    for (const auto& g : syntax.globals)
        if (g.token > i && g.token <= i + 8 && syntax.tokens[g.token].text == g.name) return &g;
    return nullptr;
}

// Whether the type at token i may become a vector, and the variables it declares.
bool mayRespell(const EffectSyntax& syntax, size_t i, const FxFunction*& inFunction) {
    inFunction = nullptr;
    for (const auto& f : syntax.functions) {
        if (i < f.declaration.begin || i >= f.declaration.end) continue;
        inFunction = &f;
        if (i >= f.body.begin && i < f.body.end) return true;
        // Parameters and the return type, with a semantic or not: the entry wrapper maps the
        // vector onto the matrix's semantic registers (signature_layout.h).
        for (const auto& p : f.parameters)
            if (p.typeToken == i) return true;
        return i < f.token;  // the return type
    }
    for (const auto& g : syntax.globals)
        if (i >= g.initializer.begin && i < g.initializer.end) return true;
    const FxGlobal* g = globalTypedAt(syntax, i);
    return g && isStatic(*g);
}

// The majority the latest `#pragma pack_matrix(...)` before token `at` names, or "".
std::string pragmaMajorityBefore(const std::vector<Token>& t, size_t at) {
    for (size_t i = std::min(at, t.size()); i-- > 2;)
        if (t[i].is("pack_matrix") && t[i - 1].is("pragma") && t[i - 2].is("#") && i + 2 < t.size() && t[i + 1].is("(") &&
            (t[i + 2].is("row_major") || t[i + 2].is("column_major")))
            return t[i + 2].text;
    return {};
}

// A uniform's use in a function body: the vector its register storage holds.
std::string vectorFromStorage(const std::string& name, const std::string& scalar, const VectorUniformStorage& s) {
    if (s.registers == 1) return name + "[0]";
    std::string out = "(" + scalar + std::to_string(s.registers) + "(";
    for (int r = 0; r < s.registers; ++r) out += (r ? ", " : "") + name + "[" + std::to_string(r) + "]";
    return out + "))";
}

// Edits declaring the uniform whose type is tokens [begin, end) as register storage: the type
// becomes the register's, each declared name gets the register count.
void declareStorage(const EffectSyntax& syntax, size_t begin, size_t end, const std::string& scalar, const VectorUniformStorage& s,
                    std::vector<TextEdit>& edits) {
    const std::vector<Token>& t = syntax.tokens;
    edits.push_back({t[begin].offset, t[end - 1].end, s.perRegister == 1 ? scalar : scalar + std::to_string(s.perRegister)});
    int depth = 0;
    for (size_t k = end; k < t.size(); ++k) {
        if (depth == 0 && t[k].is(";")) return;
        if (t[k].is("(") || t[k].is("[") || t[k].is("{")) ++depth;
        else if (t[k].is(")") || t[k].is("]") || t[k].is("}")) --depth;
        else if (depth == 0 && t[k].isIdent() && (k == end || t[k - 1].is(",")))
            edits.push_back({t[k].end, t[k].end, "[" + std::to_string(s.registers) + "]"});
    }
}

// `._m01_m02` of a one-row or one-column matrix as the components of its vector (`.yz`); "" if an
// element is outside it (glslang then reports the swizzle).
std::string vectorSwizzle(const std::string& swizzle, Shape shape) {
    auto elements = parseMatrixSwizzle(swizzle);
    if (!elements) return {};
    std::string out;
    for (const auto& e : *elements) {
        const int inLine = shape == Shape::Column ? e.column : e.row;  // 0 within the vector's line
        if (inLine != 0 || (shape == Shape::Scalar && e.column != 0)) return {};
        out += "xyzw"[shape == Shape::Column ? e.row : e.column];
    }
    return out;
}

}  // namespace

VectorUniformStorage vectorUniformStorage(const EffectSyntax& syntax, const FxGlobal& g, const std::string& defaultMajority) {
    const BasicType b = describeBasicType(g.type);
    std::string majority;
    for (const auto& m : g.modifiers)
        if (m == "row_major" || m == "column_major") majority = m;
    if (majority.empty()) majority = pragmaMajorityBefore(syntax.tokens, g.token);
    if (majority.empty()) majority = defaultMajority;
    VectorUniformStorage s;
    s.rowMajor = majority == "row_major";
    s.registers = s.rowMajor ? b.rows : b.columns;
    s.perRegister = s.rowMajor ? b.columns : b.rows;
    return s;
}

std::string degenerateAsVector(const std::string& type) {
    BasicType b = describeBasicType(type);
    if (!b.ok || !b.isMatrix || (b.rows != 1 && b.columns != 1)) return type;
    const int n = b.rows * b.columns;
    return n == 1 ? b.scalar : b.scalar + std::to_string(n);
}

std::string entryReturnType(const EffectSyntax&, const FxFunction& entry) { return degenerateAsVector(entry.returnType); }

std::vector<TextEdit> degenerateMatricesAsVectors(const EffectSyntax& syntax, const std::string& defaultMajority,
                                                 std::vector<TextEdit>* swizzles) {
    const std::vector<Token>& t = syntax.tokens;
    struct Respelled {
        size_t begin, end;  // the type's tokens
        std::string vector;
        const FxFunction* function;  // null: a global
        std::map<std::string, Shape> names;  // the variables it declares
        const FxGlobal* uniform = nullptr;  // a uniform becoming register storage
        std::string scalar;
    };
    std::vector<Respelled> found;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        auto d = degenerateAt(t, i);
        if (!d) continue;
        const FxFunction* f = nullptr;
        const FxGlobal* uniform = globalTypedAt(syntax, i);
        if (uniform && !isVectorUniform(syntax, *uniform)) uniform = nullptr;
        const bool inFunction = std::any_of(syntax.functions.begin(), syntax.functions.end(),
                                            [&](const FxFunction& fn) { return i >= fn.declaration.begin && i < fn.declaration.end; });
        if (inFunction) uniform = nullptr;  // a local named like the uniform
        if (!uniform && !mayRespell(syntax, i, f)) continue;
        Respelled r{i, d->end, d->vector, f, {}, uniform, d->scalar};
        if (!f) {
            declaredNames(t, d->end, t.size(), d->shape, r.names);
        } else if (i >= f->body.begin && i < f->body.end) {
            declaredNames(t, d->end, f->body.end, d->shape, r.names);
        } else {
            for (const auto& p : f->parameters)
                if (p.typeToken == i && p.arrayDims.empty()) r.names[p.name] = d->shape;
        }
        found.push_back(std::move(r));
        i = d->end - 1;
    }
    // An indexed group `(c ? a : b)[0]` indexes as its values do (a ternary's condition is not
    // one); values of different shapes there, a 1xN second or an Nx1 first argument of mul (an
    // outer product to fxc) keep those variables matrices, and glslang refuses them as before.
    std::map<std::string, Shape> all;
    for (const auto& r : found) all.insert(r.names.begin(), r.names.end());
    std::set<std::string> unsafe;
    const std::set<size_t> spelledOut = mulCallsSpelledOut(syntax);  // mul calls with fxc's product written out
    struct Group {
        size_t close;  // the ')' before '['
        Shape shape;
        std::vector<std::string> names;
    };
    std::vector<Group> groups;
    for (size_t i = 1; i + 1 < t.size(); ++i) {
        if (t[i].is(")") && t[i + 1].is("[")) {
            Group g{i, Shape::Row, {}};
            bool mixed = false;
            int depth = 0;
            size_t k = i;
            for (; k > 0; --k) {
                if (t[k].is(")")) ++depth;
                else if (t[k].is("(") && --depth == 0) break;
                auto n = all.find(t[k].text);
                if (n == all.end() || t[k + 1].is("?") || t[k - 1].is(".")) continue;
                mixed |= !g.names.empty() && n->second != g.shape;
                g.shape = n->second;
                g.names.push_back(n->first);
            }
            const bool call = k > 0 && t[k - 1].isIdent() && !t[k - 1].is("return");  // `mul(x, y)[1]` indexes the result
            if (call) continue;
            if (mixed) unsafe.insert(g.names.begin(), g.names.end());
            else if (!g.names.empty()) groups.push_back(g);
        }
        if (t[i].is("mul") && t[i + 1].is("(") && !t[i - 1].is(".") && !spelledOut.count(i)) {
            const size_t a = i + 2;
            if (a + 1 < t.size() && t[a + 1].is(",") && all.count(t[a].text) && all[t[a].text] == Shape::Column) unsafe.insert(t[a].text);
            if (a + 3 < t.size() && t[a + 1].is(",") && t[a + 3].is(")") && all.count(t[a + 2].text) && all[t[a + 2].text] == Shape::Row)
                unsafe.insert(t[a + 2].text);
        }
    }
    std::vector<TextEdit> edits;
    std::map<std::string, Shape> statics;
    std::map<std::string, std::string> uniformReads;  // a uniform's name -> the vector it reads
    std::map<const FxFunction*, std::map<std::string, Shape>> locals;
    for (const auto& r : found) {
        bool keep = false;
        for (const auto& [name, shape] : r.names) keep |= unsafe.count(name) > 0;
        if (keep) continue;
        if (r.uniform) {
            const VectorUniformStorage storage = vectorUniformStorage(syntax, *r.uniform, defaultMajority);
            declareStorage(syntax, r.begin, r.end, r.scalar, storage, edits);
            for (const auto& [name, shape] : r.names) uniformReads[name] = vectorFromStorage(name, r.scalar, storage);
        } else {
            edits.push_back({t[r.begin].offset, t[r.end - 1].end, r.vector});
        }
        auto& into = r.function ? locals[r.function] : statics;
        into.insert(r.names.begin(), r.names.end());
    }
    auto blank = [&](size_t b, size_t e) { edits.push_back({t[b].offset, t[e - 1].end, {}}); };
    for (const auto& g : groups) {
        bool safe = true;
        for (const auto& n : g.names) safe = safe && !unsafe.count(n);
        if (!safe) continue;
        size_t first = pastBracket(t, g.close + 1, t.size());
        size_t second = first < t.size() && t[first].is("[") ? pastBracket(t, first, t.size()) : first;
        if (g.shape != Shape::Column) blank(g.close + 1, first);
        if (g.shape != Shape::Row && second > first) blank(first, second);
    }
    // `m[0]` of a 1xN is the vector itself; `m[i][0]` of an Nx1 is `m[i]`; a 1x1's indices go.
    // A uniform's every use reads the vector from its storage.
    for (const auto& f : syntax.functions) {
        std::map<std::string, Shape> names = statics;
        for (const auto& [name, shape] : locals[&f]) names[name] = shape;
        for (const auto& p : f.parameters)
            if (!locals[&f].count(p.name)) names.erase(p.name);  // a parameter hides a static
        for (const auto& [name, sites] : f.declarationSites)
            if (uniformReads.count(name) && !locals[&f].count(name)) names.erase(name);  // so does a local
        if (names.empty()) continue;
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            auto n = names.find(t[i].text);
            if (n == names.end() || !t[i].isIdent() || (i > 0 && t[i - 1].is("."))) continue;
            auto read = uniformReads.find(n->first);
            const std::string value = read != uniformReads.end() && !locals[&f].count(n->first) ? read->second : t[i].text;
            if (i + 2 < f.body.end && t[i + 1].is(".") && t[i + 2].isIdent()) {
                // Matrix swizzles become the vector's; ahead of matrix_swizzle.h's edit of the same range.
                const std::string components = vectorSwizzle(t[i + 2].text, n->second);
                if (!components.empty() && swizzles) swizzles->push_back({t[i].offset, t[i + 2].end, value + "." + components});
                else if (value != t[i].text) edits.push_back({t[i].offset, t[i].end, value});
                continue;
            }
            if (value != t[i].text) edits.push_back({t[i].offset, t[i].end, value});
            if (!t[i + 1].is("[")) continue;
            size_t first = pastBracket(t, i + 1, f.body.end);
            size_t second = first < f.body.end && t[first].is("[") ? pastBracket(t, first, f.body.end) : first;
            if (n->second != Shape::Column) blank(i + 1, first);
            if (n->second != Shape::Row && second > first) blank(first, second);
            i = second - 1;
        }
    }
    return edits;
}

}  // namespace fxport::xlate
