// Explicit register bindings in HLSL source (see register_binding.h).
#include "register_binding.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <regex>

namespace conformance {

namespace {

// A tiny evaluator for index expressions: numbers, true/false, + - * /, parentheses.
struct Expression {
    const char* p;
    void spaces() { while (std::isspace(static_cast<unsigned char>(*p))) ++p; }
    double primary() {
        spaces();
        if (*p == '(') { ++p; double v = sum(); spaces(); if (*p == ')') ++p; return v; }
        if (*p == '-') { ++p; return -primary(); }
        if (!std::strncmp(p, "true", 4)) { p += 4; return 1; }
        if (!std::strncmp(p, "false", 5)) { p += 5; return 0; }
        char* end = nullptr;
        double v = std::strtod(p, &end);
        p = end == p ? p + 1 : end;
        return v;
    }
    double product() {
        double v = primary();
        for (spaces(); *p == '*' || *p == '/'; spaces()) {
            char op = *p++;
            double r = primary();
            v = op == '*' ? v * r : (r != 0 ? v / r : 0);
        }
        return v;
    }
    double sum() {
        double v = product();
        for (spaces(); *p == '+' || *p == '-'; spaces()) {
            char op = *p++;
            double r = product();
            v = op == '+' ? v + r : v - r;
        }
        return v;
    }
};

// "c2", "c0[1 + 1]", "c[2]" -> the index; -1 when `text` is not of class `letter`.
int registerIndex(std::string text, char letter) {
    std::size_t b = text.find_first_not_of(" \t");
    if (b == std::string::npos || std::tolower(static_cast<unsigned char>(text[b])) != letter) return -1;
    const char* p = text.c_str() + b + 1;
    int index = std::atoi(p);
    while (std::isdigit(static_cast<unsigned char>(*p))) ++p;
    while (*p && *p != '[') ++p;
    if (*p == '[') {
        Expression e{p + 1};
        index += int(e.sum());
    }
    return index;
}

// The arguments of the last `keyword(...)` among the `: ...` annotations after global `name`
// (`float b : packoffset(c2) : register(c1)`); "" when there is none.
std::string bindingArguments(const std::string& source, const std::string& name, const char* keyword) {
    std::regex declaration("\\b" + name + "\\s*(\\[[^\\]]*\\]\\s*)*((:\\s*[A-Za-z_][A-Za-z_0-9]*\\s*(\\([^)]*\\))?\\s*)+)");
    std::smatch m;
    if (!std::regex_search(source, m, declaration)) return "";
    std::string chain = m[2].str();
    std::regex binding(std::string(keyword) + "\\s*\\(([^)]*)\\)");
    std::string last;
    for (std::sregex_iterator it(chain.begin(), chain.end(), binding), end; it != end; ++it) last = (*it)[1].str();
    return last;
}

}  // namespace

int explicitRegister(const std::string& source, const std::string& name, char letter) {
    std::string args = bindingArguments(source, name, "register");
    // register(ps_5_0, c1) / register(space0, t1): the binding is the last argument of its class.
    std::size_t start = 0;
    int found = -1;
    while (start <= args.size()) {
        std::size_t comma = args.find(',', start);
        std::string part = args.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        int index = registerIndex(part, letter);
        if (index >= 0) found = index;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return found;
}

int explicitPackOffset(const std::string& source, const std::string& name) {
    std::string args = bindingArguments(source, name, "packoffset");
    int reg = registerIndex(args, 'c');
    if (reg < 0) return -1;
    std::size_t dot = args.find('.');
    int component = 0;
    if (dot != std::string::npos && dot + 1 < args.size()) {
        std::size_t at = std::string("xyzw").find(args[dot + 1]);
        if (at == std::string::npos) at = std::string("rgba").find(args[dot + 1]);
        component = at == std::string::npos ? 0 : int(at);
    }
    return reg * 4 + component;
}

}  // namespace conformance
