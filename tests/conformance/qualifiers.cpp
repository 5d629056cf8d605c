// Qualifier arguments of vkd3d's .shader_test format (see qualifiers.h).
#include "qualifiers.h"

#include <cctype>
#include <cstring>
#include <stdexcept>

namespace conformance {

namespace {

const struct { const char* text; int model; } kModels[] = {
    {"2.0", 20}, {"3.0", 30}, {"4.0", 40}, {"4.1", 41}, {"5.0", 50}, {"5.1", 51}, {"6.0", 60}, {"6.2", 62},
};

void skipSpaces(const char*& p) {
    while (*p && std::isspace(static_cast<unsigned char>(*p))) ++p;
}

// Reads a model at p ("4.1", or "4" for "4.0"), advancing p.
int readModel(const char*& p) {
    for (const auto& m : kModels) {
        std::size_t n = std::strlen(m.text);
        if (!std::strncmp(p, m.text, n)) { p += n; return m.model; }
    }
    for (const auto& m : kModels) {
        if (p[0] == m.text[0] && !std::strcmp(m.text + 1, ".0") && p[1] != '.' && !std::isdigit(static_cast<unsigned char>(p[1]))) {
            p += 1;
            return m.model;
        }
    }
    throw std::runtime_error(std::string("unknown shader model in '") + p + "'");
}

// The value of one term at `model`: an `sm` comparison, or a backend tag (never holds here).
// `tagsHold` says what a tag counts as (true where tags must not narrow, as for sections).
bool readTerm(const char*& p, int model, bool tagsHold) {
    skipSpaces(p);
    if (!std::strncmp(p, "sm>=", 4)) { p += 4; return model >= readModel(p); }
    if (!std::strncmp(p, "sm<", 3)) { p += 3; return model < readModel(p); }
    bool negate = *p == '!';
    if (negate) ++p;
    const char* start = p;
    while (*p && (std::isalnum(static_cast<unsigned char>(*p)) || *p == '<' || *p == '.' || *p == '_')) ++p;
    if (p == start) throw std::runtime_error(std::string("bad qualifier argument '") + start + "'");
    if (tagsHold) return true;
    return negate;  // no vkd3d backend tag describes native D3D
}

bool readConjunction(const char*& p, int model, bool tagsHold) {
    bool holds = true;
    for (;;) {
        holds = readTerm(p, model, tagsHold) && holds;
        skipSpaces(p);
        if (*p != '&') return holds;
        ++p;
    }
}

// `(...)` at p: whether it holds at `model` (true when p is not at '(').
bool evalArgs(const char*& p, int model, bool tagsHold) {
    if (*p != '(') return true;
    ++p;
    bool holds = false;
    for (;;) {
        holds = readConjunction(p, model, tagsHold) || holds;
        skipSpaces(p);
        if (*p == '|') { ++p; continue; }
        if (*p != ')') throw std::runtime_error(std::string("unclosed qualifier '") + p + "'");
        ++p;
        return holds;
    }
}

}  // namespace

int parseShaderModel(const std::string& text) {
    const char* p = text.c_str();
    try {
        return readModel(p);
    } catch (const std::exception&) {
        return -1;
    }
}

std::string shaderModelName(int model) { return std::to_string(model / 10) + "." + std::to_string(model % 10); }

namespace {

// vkd3d's match_string: `token` followed by a space, '(' or ']' (or the end).
bool matchWord(const char*& p, const char* token) {
    skipSpaces(p);
    std::size_t n = std::strlen(token);
    if (std::strncmp(p, token, n)) return false;
    char next = p[n];
    if (next && !std::isspace(static_cast<unsigned char>(next)) && next != '(' && next != ']') return false;
    p += n;
    return true;
}

}  // namespace

SectionExpectation sectionExpectation(const std::string& qualifiers, int model) {
    SectionExpectation out;
    const char* p = qualifiers.c_str();
    for (;;) {
        skipSpaces(p);
        if (!*p) return out;
        if (matchWord(p, "todo")) out.todo = evalArgs(p, model, true) || out.todo;
        else if (matchWord(p, "fail")) out.fail = evalArgs(p, model, true) || out.fail;
        else if (matchWord(p, "notimpl")) out.notImpl = evalArgs(p, model, true) || out.notImpl;
        else {
            while (*p && !std::isspace(static_cast<unsigned char>(*p))) ++p;  // d3dbc-hex and the like
        }
    }
}

TestLinePrefix parseTestLinePrefix(const std::string& line, int model) {
    TestLinePrefix out;
    const char* p = line.c_str();
    for (bool matched = true; matched;) {
        matched = false;
        if (matchWord(p, "todo")) { out.todo = evalArgs(p, model, false); matched = true; }
        if (matchWord(p, "bug")) { evalArgs(p, model, false); matched = true; }
        if (matchWord(p, "if")) {
            if (!evalArgs(p, model, false)) out.runs = false;
            matched = true;
        }
    }
    skipSpaces(p);
    out.rest = p;
    return out;
}

}  // namespace conformance
