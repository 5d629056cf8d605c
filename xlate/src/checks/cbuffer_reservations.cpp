// fxc's all-or-none rule for manual packing in a cbuffer, objects included (vkd3d's cbuffer pins
// it; fxc_rejections.cpp judges the numeric members among themselves, X3592): once one member is
// placed by hand -- packoffset(), or a register() of another class than c -- every member must be,
// a texture or sampler by register() (or packoffset), a number by packoffset(). register(cN) on a
// number is ignored by fxc and places nothing. Judged on the tokens of each cbuffer's body, since
// the parser moves its objects out of the cbuffer.
#include <cctype>

#include "checks/fxc_checks.h"
#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Member {
    size_t name = 0;          // token of the declared name
    bool placed = false;      // packoffset, or register() of a class other than c
    bool sampler = false;     // sampler, SamplerState, SamplerComparisonState ...
    bool packed = false;      // packoffset()
    bool registered = false;  // register() of a class other than c
};

class CbufferReservations : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 0; i + 2 < t_.size(); ++i) {
            if (!(t_[i].is("cbuffer") || t_[i].is("tbuffer")) || !t_[i + 1].isIdent() || inFunction(i)) continue;
            size_t open = i + 2;
            while (open < t_.size() && !t_[open].is("{") && !t_[open].is(";")) ++open;
            if (open >= t_.size() || !t_[open].is("{")) continue;
            size_t close = closing(open);
            const std::vector<Member> found = members(open + 1, close);
            judge(t_[i + 1].text, found);
            samplersPackedOnly(found, close);
            i = close;
        }
    }

private:
    std::vector<Member> members(size_t begin, size_t end) const {
        std::vector<Member> out;
        size_t start = begin;
        for (size_t j = begin; j < end; ++j) {
            bool annotations = t_[j].is("<") && j > begin && t_[j - 1].isIdent();  // `float4 x <string UIName = "x";>` or a template
            if (t_[j].is("{") || t_[j].is("(") || t_[j].is("[") || annotations) {
                j = closing(j);
                continue;
            }
            if (!t_[j].is(";")) continue;
            if (j > start) out.push_back(member(start, j));
            start = j + 1;
        }
        return out;
    }

    // One declaration `[modifiers] type name[dims] [: semantic | packoffset(..) | register(..)]*`.
    Member member(size_t begin, size_t end) const {
        Member m;
        for (size_t j = begin; j < end; ++j) {
            if (t_[j].is(":") && !m.name && j > begin) m.name = lastName(begin, j);
            if (t_[j].is("packoffset")) m.placed = m.packed = true;
            if (t_[j].is("register") && tok(j + 1).is("(") && tok(j + 2).isIdent()) {
                char c = char(std::tolower(static_cast<unsigned char>(tok(j + 2).text[0])));
                if (c != 'c') m.placed = m.registered = true;
            }
        }
        if (!m.name) m.name = lastName(begin, end);
        const size_t type = firstAfterModifiers(begin, end);
        m.sampler = type < end && resourceRegisterClass(t_[type].text) == 's';
        return m;
    }

    size_t firstAfterModifiers(size_t begin, size_t end) const {
        static const char* const kModifiers[] = {"uniform", "const", "static", "extern", "shared", "volatile"};
        size_t j = begin;
        for (bool more = true; more && j < end;) {
            more = false;
            for (const char* k : kModifiers)
                if (t_[j].is(k)) more = true;
            if (more) ++j;
        }
        return j;
    }

    // A sampler placed by packoffset() alone, which a shader uses (vkd3d's cbuffer test: fxc refuses
    // it; unused, or with a register() too, it is taken).
    void samplersPackedOnly(const std::vector<Member>& members, size_t close) {
        for (const auto& m : members) {
            if (!m.sampler || !m.packed || m.registered) continue;
            for (size_t j = close + 1; j < t_.size(); ++j)
                if (t_[j].is(tok(m.name).text) && !tok(j - 1).is(".")) {
                    report("sampler '" + tok(m.name).text + "' is placed in its cbuffer by packoffset() only; a sampler a shader uses needs a register() too",
                           m.name);
                    break;
                }
        }
    }

    size_t lastName(size_t begin, size_t end) const {
        for (size_t j = end; j-- > begin;) {
            if (t_[j].is("]")) {
                while (j > begin && !t_[j].is("[")) --j;
                continue;
            }
            if (t_[j].isIdent()) return j;
        }
        return begin;
    }

    void judge(const std::string& cbuffer, const std::vector<Member>& members) {
        const Member* placed = nullptr;
        for (const auto& m : members)
            if (m.placed) placed = &m;
        if (!placed) return;
        for (const auto& m : members)
            if (!m.placed)
                report("cbuffer '" + cbuffer + "' places '" + tok(placed->name).text + "' by hand, so '" + tok(m.name).text +
                           "' needs a packoffset() (a number) or a register() (an object) too (fxc X3592)",
                       m.name);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findCbufferReservationErrors(const EffectSyntax& syntax, const SourceMap& map) {
    CbufferReservations check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
