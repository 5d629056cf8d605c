// See struct_definitions.h.
#include "rewrite/struct_definitions.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "fx/lexer.h"

namespace fxport::xlate {

namespace {

// Replaces [begin, end) of the text with `text`, then the original's newlines (the line count holds).
struct Edit {
    size_t begin = 0;
    size_t end = 0;
    std::string text;
};

std::string applyKeepingLines(const std::string& source, size_t from, size_t to, std::vector<Edit> edits) {
    // Insertions (empty ranges) before a replacement that starts at the same place; otherwise in
    // the order they were made.
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
        if (a.begin != b.begin) return a.begin < b.begin;
        return (a.begin == a.end) && (b.begin != b.end);
    });
    std::string out;
    size_t at = from;
    for (const auto& e : edits) {
        if (e.begin < at || e.end > to) continue;  // overlapping: never made, kept safe
        out.append(source, at, e.begin - at);
        out += e.text;
        for (size_t k = e.begin; k < e.end; ++k)
            if (source[k] == '\n') out += '\n';
        at = e.end;
    }
    out.append(source, at, to - at);
    return out;
}

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    return s;
}

struct Definition {
    std::string name;          // as written, or made up
    bool anonymous = false;
    size_t open = 0;           // token of '{'
    size_t close = 0;          // token of '}'
    std::vector<Edit> memberEdits;  // member definitions replaced by their names
    std::string hoisted;       // the member definitions, inner ones first, on one line
};

class Splitter {
public:
    explicit Splitter(const std::string& text) : text_(text), t_(tokenize(text)) {}

    std::string run() {
        enum class Scope { Cbuffer, Other };
        std::vector<Scope> scopes;
        bool cbufferPending = false;
        size_t declarationStart = 0;  // first token of the current file-scope declaration
        for (size_t i = 0; i < t_.size() && t_[i].kind != Token::Kind::End; ++i) {
            const Token& tok = t_[i];
            if (tok.is("cbuffer") || tok.is("tbuffer")) cbufferPending = true;
            if (tok.is("{")) {
                scopes.push_back(cbufferPending ? Scope::Cbuffer : Scope::Other);
                cbufferPending = false;
            } else if (tok.is("}") || tok.is(";")) {
                if (tok.is("}") && !scopes.empty()) scopes.pop_back();
                if (tok.is(";")) cbufferPending = false;
                if (scopes.empty()) declarationStart = i + 1;
            } else if (tok.is("struct") && definitionAt(i)) {
                auto def = readDefinition(i);
                if (!def) {
                    i = closeOf(i);  // left as written, nested definitions too
                    continue;
                }
                if (!scopes.empty() && scopes.back() == Scope::Cbuffer) hoistOut(*def, i, declarationStart);
                else if (!scopes.empty()) hoistOutOfFunction(*def, i, declarationStart);
                else splitInPlace(*def, i);
                i = def->close;
            }
        }
        if (edits_.empty()) return text_;
        return applyKeepingLines(text_, 0, text_.size(), std::move(edits_));
    }

private:
    const std::string& text_;
    std::vector<Token> t_;
    std::vector<Edit> edits_;
    int made_ = 0;

    bool ident(size_t i) const { return i < t_.size() && t_[i].isIdent(); }
    bool is(size_t i, const char* s) const { return i < t_.size() && t_[i].is(s); }

    // `struct [Name] [: Base] {` at i: the index of '{', or 0.
    size_t openOf(size_t i) const {
        size_t j = i + 1;
        if (ident(j)) ++j;
        if (is(j, ":") && ident(j + 1)) j += 2;
        return is(j, "{") ? j : 0;
    }
    bool definitionAt(size_t i) const { return openOf(i) != 0; }

    static bool isModifier(const Token& t) {
        static const char* const kWords[] = {"static", "const", "uniform", "extern", "volatile", "shared", "groupshared",
                                              "row_major", "column_major", "typedef", "precise", "in", "out", "inout"};
        for (const char* w : kWords)
            if (t.is(w)) return true;
        return false;
    }

    size_t matching(size_t open) const {
        int depth = 0;
        for (size_t k = open; k < t_.size() && t_[k].kind != Token::Kind::End; ++k) {
            if (t_[k].is("{")) ++depth;
            if (t_[k].is("}") && --depth == 0) return k;
        }
        return t_.size() - 1;
    }
    size_t closeOf(size_t i) const { return matching(openOf(i)); }

    // The definition at i with its member definitions taken out; nothing when one of those has no
    // declarator, or the definition has no member (left to the parser and glslang as written).
    std::optional<Definition> readDefinition(size_t i) {
        Definition d;
        d.open = openOf(i);
        d.anonymous = !ident(i + 1);
        d.name = d.anonymous ? "fxport_struct_" + std::to_string(++made_) : t_[i + 1].text;
        if (is(d.open + 1, "}")) return std::nullopt;
        for (size_t k = d.open + 1; k < t_.size() && t_[k].kind != Token::Kind::End; ++k) {
            if (t_[k].is("}")) {
                d.close = k;
                return d;
            }
            if (t_[k].is("{") && !(k > 0 && t_[k - 1].is("struct"))) return std::nullopt;  // not a member list
            if (!t_[k].is("struct") || !definitionAt(k)) continue;
            auto member = readDefinition(k);
            if (!member || !ident(member->close + 1)) return std::nullopt;
            d.hoisted += member->hoisted + render(*member, k) + " ";
            d.memberEdits.push_back({t_[k].offset, t_[member->close].end, member->name});
            k = member->close;
        }
        return std::nullopt;  // cut off by the end of the file
    }

    // `struct N [: Base] { members };` on one line, member definitions replaced by their names.
    std::string render(const Definition& d, size_t at) const {
        size_t afterName = d.anonymous ? at + 1 : at + 2;
        std::string header = "struct " + d.name + " " + text_.substr(t_[afterName].offset, t_[d.open].offset - t_[afterName].offset);
        return oneLine(header + applyKeepingLines(text_, t_[d.open].offset, t_[d.close].end, d.memberEdits) + ";");
    }

    // A definition in a cbuffer: defined before the cbuffer, the member typed by its name.
    void hoistOut(const Definition& d, size_t at, size_t declarationStart) {
        if (!ident(d.close + 1)) return;
        edits_.push_back({t_[declarationStart].offset, t_[declarationStart].offset, d.hoisted + render(d, at) + " "});
        edits_.push_back({t_[at].offset, t_[d.close].end, d.name});
    }

    // A definition in a function body (glslang takes struct definitions at file scope only): defined
    // before the function, a declarator's type becomes its name; one with no declarator is blanked.
    void hoistOutOfFunction(const Definition& d, size_t at, size_t declarationStart) {
        if (ident(d.close + 1)) return hoistOut(d, at, declarationStart);
        if (d.anonymous || !is(d.close + 1, ";")) return;  // `struct { ... };` declares nothing: fxc's error
        edits_.push_back({t_[declarationStart].offset, t_[declarationStart].offset, d.hoisted + render(d, at) + " "});
        edits_.push_back({t_[at].offset, t_[d.close + 1].end, ""});
    }

    // A definition at file scope: member definitions before it, its declarators
    // (and the modifiers before `struct`) after it, as a declaration of their own.
    void splitInPlace(const Definition& d, size_t at) {
        const bool declarators = !is(d.close + 1, ";");
        if (d.anonymous && !declarators) return;  // `struct { ... };` declares nothing: fxc's error
        size_t first = at;
        while (first > 0 && isModifier(t_[first - 1])) --first;
        if (!d.hoisted.empty()) edits_.push_back({t_[first].offset, t_[first].offset, d.hoisted});
        for (const auto& e : d.memberEdits) edits_.push_back(e);
        if (d.anonymous) edits_.push_back({t_[at].end, t_[at].end, " " + d.name});
        if (!declarators) return;
        std::string modifiers;
        if (first < at) {
            modifiers = text_.substr(t_[first].offset, t_[at].offset - t_[first].offset);
            edits_.push_back({t_[first].offset, t_[at].offset, std::string(t_[at].offset - t_[first].offset, ' ')});
        }
        edits_.push_back({t_[d.close].end, t_[d.close].end, "; " + oneLine(modifiers) + d.name + " "});
    }
};

}  // namespace

std::string splitStructDefinitions(const std::string& preprocessed) { return Splitter(preprocessed).run(); }

}  // namespace fxport::xlate
