// See uniform_object_structs.h.
#include "rewrite/uniform_object_structs.h"

#include <algorithm>
#include <map>
#include <set>

#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

struct Contents {
    bool numbers = false;
    bool objects = false;
    bool unsupported = false;  // an array of structs holding objects, a size not a literal
};

Contents contentsOf(const EffectSyntax& syntax, const std::string& type, int depth = 0) {
    Contents c;
    const std::string& resolved = syntax.resolveType(type);
    const FxStruct* s = syntax.findStruct(resolved);
    if (!s) {
        (isResourceType(resolved) ? c.objects : c.numbers) = true;
        return c;
    }
    if (depth > 16) {
        c.unsupported = true;
        return c;
    }
    for (const auto& m : s->members) {
        Contents inner = contentsOf(syntax, m.type, depth + 1);
        c.numbers |= inner.numbers;
        c.objects |= inner.objects;
        c.unsupported |= inner.unsupported;
        for (int d : m.arrayDims) c.unsupported |= d <= 0;
        if (!m.arrayDims.empty() && inner.objects && syntax.findStruct(syntax.resolveType(m.type))) c.unsupported = true;
    }
    return c;
}

std::string dimsSpelled(const std::vector<int>& dims) {
    std::string out;
    for (int d : dims) out += "[" + std::to_string(d) + "]";
    return out;
}

// A parameter or local of the function named `name`: its uses are not the global's.
bool declaresOwn(const EffectSyntax& syntax, const FxFunction& f, const std::string& name) {
    for (const auto& p : f.parameters)
        if (p.name == name) return true;
    const auto& t = syntax.tokens;
    for (size_t k = f.body.begin + 1; k < f.body.end; ++k)
        if (t[k].is(name) && t[k - 1].isIdent() && !t[k - 1].is("return")) return true;
    return false;
}

class Splitter {
public:
    explicit Splitter(const EffectSyntax& syntax) : syntax_(syntax), t_(syntax.tokens) {}

    void split(const FxGlobal& g) {
        const FxStruct* s = syntax_.findStruct(syntax_.resolveType(g.type));
        if (!s || !g.arrayDims.empty() || g.initializer.begin < g.initializer.end) return;
        if (std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end()) return;
        const Contents c = contentsOf(syntax_, g.type);
        if (!c.numbers || !c.objects || c.unsupported) return;
        const size_t typeToken = typeTokenOf(g);
        if (typeToken == 0) return;
        std::string declarations;
        const std::string numbers = numbersStruct(*s, declarations);
        declareObjects(*s, "fxport_" + g.name, declarations);
        edits.push_back({t_[insertionPoint(g)].offset, t_[insertionPoint(g)].offset, declarations});
        edits.push_back({t_[typeToken].offset, t_[typeToken].end, numbers});
        for (const FxFunction& f : syntax_.functions)
            if (!f.body.empty() && f.body.begin > g.token && !declaresOwn(syntax_, f, g.name)) uses(f, g, *s);
    }

    std::vector<TextEdit> edits;

private:
    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    std::set<std::string> numbersDefined_, buildersDefined_;

    // The declaration's type name token (the same for `Material a, b;`), 0 where it is not one token.
    size_t typeTokenOf(const FxGlobal& g) const {
        for (size_t k = g.token; k > 0; --k) {
            const Token& t = t_[k - 1];
            if (t.is(";") || t.is("{") || t.is("}")) return 0;
            if (t.isIdent() && t.text == g.type) return k - 1;
        }
        return 0;
    }
    // Where the split-out declarations go: the declaration's first token, or its cbuffer's keyword.
    size_t insertionPoint(const FxGlobal& g) const {
        size_t k = typeTokenOf(g);
        while (k > 0 && !t_[k - 1].is(";") && !t_[k - 1].is("{") && !t_[k - 1].is("}")) --k;
        if (g.cbuffer.empty()) return k;
        for (size_t j = k; j > 0; --j)
            if ((t_[j - 1].is("cbuffer") || t_[j - 1].is("tbuffer")) && t_[j].is(g.cbuffer)) return j - 1;
        return k;
    }

    // The numbers-only twin of `s`, its definition (after those of nested twins) appended to `out`.
    std::string numbersStruct(const FxStruct& s, std::string& out) {
        const std::string name = kNumbersStructPrefix + s.name;
        if (!numbersDefined_.insert(name).second) return name;
        std::string body;
        for (const auto& m : s.members) {
            const Contents c = contentsOf(syntax_, m.type);
            if (!c.numbers) continue;
            std::string type = m.type;
            if (c.objects) type = numbersStruct(*syntax_.findStruct(syntax_.resolveType(m.type)), out);
            for (const auto& mod : m.modifiers) body += mod + " ";
            body += type + " " + m.name + dimsSpelled(m.arrayDims) + "; ";
        }
        out += "struct " + name + " { " + body + "}; ";
        return name;
    }
    // The objects of `s` as globals named `prefix_member`.
    void declareObjects(const FxStruct& s, const std::string& prefix, std::string& out) const {
        for (const auto& m : s.members) {
            const std::string& resolved = syntax_.resolveType(m.type);
            if (const FxStruct* inner = syntax_.findStruct(resolved)) {
                if (contentsOf(syntax_, m.type).objects) declareObjects(*inner, prefix + "_" + m.name, out);
            } else if (isResourceType(resolved)) {
                out += m.type + " " + prefix + "_" + m.name + dimsSpelled(m.arrayDims) + "; ";
            }
        }
    }

    // `fxport_uniform_<path>()`, building struct `s` (at `path`, dots between members) from the
    // numbers and the objects; defined before function f.
    std::string builder(const FxFunction& f, const FxStruct& s, const std::string& path) {
        std::string flat = path;
        std::replace(flat.begin(), flat.end(), '.', '_');
        const std::string name = "fxport_uniform_" + flat;
        if (!buildersDefined_.insert(name).second) return name;
        std::string body;
        fill(s, path, "fxport_" + flat, "r", body);
        edits.push_back({t_[f.declaration.begin].offset, t_[f.declaration.begin].offset,
                         s.name + " " + name + "() { " + s.name + " r; " + body + "return r; } "});
        return name;
    }
    void fill(const FxStruct& s, const std::string& numbers, const std::string& objects, const std::string& to, std::string& body) const {
        for (const auto& m : s.members) {
            const std::string& resolved = syntax_.resolveType(m.type);
            const FxStruct* inner = syntax_.findStruct(resolved);
            if (inner && contentsOf(syntax_, m.type).objects) {
                fill(*inner, numbers + "." + m.name, objects + "_" + m.name, to + "." + m.name, body);
            } else if (isResourceType(resolved)) {
                body += to + "." + m.name + " = " + objects + "_" + m.name + "; ";
            } else {
                body += to + "." + m.name + " = " + numbers + "." + m.name + "; ";
            }
        }
    }

    // In f: `g.a.tex` -> `fxport_g_a_tex`; `g` or `g.a` as a whole struct holding objects -> a
    // builder's call; numbers stay as written (the twin has the same member names).
    void uses(const FxFunction& f, const FxGlobal& g, const FxStruct& s) {
        for (size_t k = f.body.begin; k < f.body.end; ++k) {
            if (!t_[k].is(g.name) || t_[k - 1].is(".")) continue;
            const FxStruct* at = &s;
            std::string path = g.name;
            size_t last = k;
            while (at && t_[last + 1].is(".") && t_[last + 2].isIdent()) {
                const FxStructMember* member = nullptr;
                for (const auto& m : at->members)
                    if (m.name == t_[last + 2].text) member = &m;
                if (!member) break;  // a method or a swizzle: left as written
                const std::string& resolved = syntax_.resolveType(member->type);
                if (isResourceType(resolved)) {
                    std::string flat = path + "." + member->name;
                    std::replace(flat.begin(), flat.end(), '.', '_');
                    edits.push_back({t_[k].offset, t_[last + 2].end, "fxport_" + flat});
                    at = nullptr;
                    break;
                }
                const FxStruct* inner = syntax_.findStruct(resolved);
                if (!inner || !contentsOf(syntax_, member->type).objects) {
                    at = nullptr;  // numbers: the twin has them under the same name
                    break;
                }
                at = inner;
                path += "." + member->name;
                last += 2;
            }
            if (at) edits.push_back({t_[k].offset, t_[last].end, builder(f, *at, path) + "()"});
            k = last;
        }
    }
};

}  // namespace

std::vector<TextEdit> uniformObjectStructs(const EffectSyntax& syntax) {
    Splitter splitter(syntax);
    for (const FxGlobal& g : syntax.globals) splitter.split(g);
    return std::move(splitter.edits);
}

std::vector<bool> numbersStructRegisterStarts(const EffectSyntax& syntax, const FxStruct& s) {
    std::vector<bool> starts;
    bool pending = false;
    for (const auto& m : s.members) {
        const Contents c = contentsOf(syntax, m.type);
        if (c.numbers) {
            starts.push_back(pending);
            pending = false;
        } else if (!m.arrayDims.empty() || syntax.findStruct(syntax.resolveType(m.type))) {
            pending = true;  // an object array or a struct of objects: a register started, no space taken
        }
    }
    starts.push_back(pending);
    return starts;
}

}  // namespace fxport::xlate
