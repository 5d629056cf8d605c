// See cbuffer_objects.h.
#include "rewrite/cbuffer_objects.h"

#include <cctype>
#include <vector>

#include "fx/lexer.h"
#include "fx/text_util.h"
#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

bool isModifier(const std::string& s) {
    return s == "uniform" || s == "const" || s == "static" || s == "extern" || s == "shared" || s == "volatile" || s == "globallycoherent";
}

class Mover {
public:
    explicit Mover(const std::string& text) : text_(text), t_(tokenize(text)) {}

    std::string run() {
        int depth = 0;
        for (size_t i = 0; i < t_.size() && t_[i].kind != Token::Kind::End; ++i) {
            if (t_[i].is("{")) ++depth;
            else if (t_[i].is("}")) --depth;
            else if (depth == 0 && (t_[i].is("cbuffer") || t_[i].is("tbuffer"))) i = moveObjectsOf(i);
        }
        if (inserts_.empty()) return text_;
        return apply();
    }

private:
    const std::string& text_;
    std::vector<Token> t_;
    struct Edit {
        size_t begin, end;
        std::string text;
    };
    std::vector<Edit> inserts_;  // in text order: each an insertion before a cbuffer or a removal

    bool end(size_t i) const { return i >= t_.size() || t_[i].kind == Token::Kind::End; }

    // The body of the cbuffer whose keyword is at `keyword`: its objects and statics moved. Returns the last token seen.
    size_t moveObjectsOf(size_t keyword) {
        size_t open = keyword + 1;
        while (!end(open) && !t_[open].is("{") && !t_[open].is(";")) ++open;
        if (end(open) || !t_[open].is("{")) return open;
        std::string moved, statics;
        std::vector<Edit> removals;
        size_t i = open + 1;
        while (!end(i) && !t_[i].is("}")) {
            size_t first = i, last = declarationEnd(i);  // last: its ';' (or the '}' that ends the body)
            if (end(last)) return last;
            size_t type = first;
            bool isStatic = false;
            for (; type < last && t_[type].isIdent() && isModifier(t_[type].text); ++type) isStatic |= t_[type].is("static");
            const char cls = type < last ? resourceRegisterClass(t_[type].text) : 0;
            if ((cls || isStatic) && t_[last].is(";")) {
                (cls ? moved : statics) += withoutForeignPlacement(first, last, cls) + " ";
                removals.push_back({t_[first].offset, t_[last].end, ""});
            }
            i = t_[last].is(";") ? last + 1 : last;
        }
        if (moved.empty() && statics.empty()) return i;
        if (!moved.empty()) inserts_.push_back({t_[keyword].offset, t_[keyword].offset, moved});
        inserts_.insert(inserts_.end(), removals.begin(), removals.end());
        if (!statics.empty() && !end(i)) {
            // After the body (and its ';'), on the closing line: a static's initializer may read the members.
            const size_t after = !end(i + 1) && t_[i + 1].is(";") ? t_[i + 1].end : t_[i].end;
            inserts_.push_back({after, after, " " + statics});
        }
        return i;
    }

    // The ';' ending the member declaration at `i` (at its own bracket depth), or the body's '}'.
    size_t declarationEnd(size_t i) const {
        int nesting = 0;
        for (; !end(i); ++i) {
            if (t_[i].is("(") || t_[i].is("{") || t_[i].is("[")) ++nesting;
            else if (t_[i].is(")") || t_[i].is("]")) --nesting;
            else if (t_[i].is("}")) {
                if (nesting == 0) return i;
                --nesting;
            } else if (nesting == 0 && t_[i].is(";")) {
                return i;
            }
        }
        return i;
    }

    // The declaration's text on one line, less `: packoffset(...)` and `: register(...)` of another class.
    std::string withoutForeignPlacement(size_t first, size_t last, char cls) const {
        std::string out;
        size_t copied = t_[first].offset;
        for (size_t k = first; k < last; ++k) {
            if (!t_[k].is(":") || !t_[k + 1].isIdent() || !t_[k + 2].is("(")) continue;
            const bool pack = iequals(t_[k + 1].text, "packoffset"), reg = iequals(t_[k + 1].text, "register");
            if (!pack && !reg) continue;
            size_t close = k + 2;
            while (close < last && !t_[close].is(")")) ++close;
            if (close >= last) break;
            const std::string& slot = t_[close - 1].text;  // register(s2), register(ps_5_0, t1): the last argument
            if (reg && !slot.empty() && std::tolower(static_cast<unsigned char>(slot[0])) == cls) continue;
            out.append(text_, copied, t_[k].offset - copied);
            copied = t_[close].end;
            k = close;
        }
        out.append(text_, copied, t_[last].end - copied);
        for (char& c : out)
            if (c == '\n' || c == '\r') c = ' ';
        return out;
    }

    // The text with the insertions made and the removed declarations blanked (their newlines kept).
    std::string apply() const {
        std::string out;
        size_t at = 0;
        for (const Edit& e : inserts_) {
            out.append(text_, at, e.begin - at);
            out += e.text;
            for (size_t k = e.begin; k < e.end; ++k)
                if (text_[k] == '\n') out += '\n';
            at = e.end;
        }
        out.append(text_, at, std::string::npos);
        return out;
    }
};

}  // namespace

std::string nonMembersMovedOutOfCbuffers(const std::string& preprocessed) { return Mover(preprocessed).run(); }

}  // namespace fxport::xlate
