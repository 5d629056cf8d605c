// Parser of D3D9 shader assembly text (the inside of an effect's `asm { }` block) into
// instructions. Instructions need no line breaks: an operand is a register with optional modifiers,
// so the first token after an operand that is not ',' starts the next instruction.
#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "d3d9asm/d3d9_asm.h"
#include "fx/lexer.h"
#include "fx/shader_profile.h"
#include "fx/source_map.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

std::vector<std::string> splitUnderscore(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == '_') {
            out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    out.push_back(cur);
    return out;
}

// "r12" -> ("r", 12); "oPos" -> ("opos", 0); "c" (relative) -> ("c", -1). False if not a register.
bool splitRegister(const std::string& name, AsmRegister& reg) {
    std::string n = toLower(name);
    for (const char* fixed : {"opos", "ofog", "opts", "odepth"})
        if (n == fixed) {
            reg.type = fixed;
            reg.index = 0;
            return true;
        }
    size_t digits = n.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(n[digits - 1]))) --digits;
    std::string base = n.substr(0, digits);
    static const char* const kTypes[] = {"r", "v", "c", "t", "s", "a", "b", "i", "od", "ot", "oc", "p"};
    for (const char* t : kTypes)
        if (base == t) {
            reg.type = base;
            // No register file has more than a few hundred registers; 4096 keeps index arithmetic
            // (m4x4 reads index + 3, c[a0.x + n]) far from overflow.
            reg.index = digits == n.size() ? -1 : n.size() - digits > 4 ? 4096 : std::atoi(n.c_str() + digits);
            return true;
        }
    return false;
}

std::string normaliseSwizzle(const std::string& s) {
    std::string out;
    for (char c : toLower(s)) {
        switch (c) {
        case 'r': out += 'x'; break;
        case 'g': out += 'y'; break;
        case 'b': out += 'z'; break;
        case 'a': out += 'w'; break;
        default: out += c;
        }
    }
    return out;
}

bool isSwizzle(const std::string& s) {
    if (s.empty() || s.size() > 4) return false;
    for (char c : s)
        if (std::string("xyzwrgba").find(c) == std::string::npos) return false;
    return true;
}

class AsmParser {
public:
    AsmParser(std::vector<Token> tokens, const SourceMap& map, std::vector<Diagnostic>& diagnostics)
        : t_(std::move(tokens)), map_(map), diagnostics_(diagnostics) {}

    bool run(ShaderStage expected, AsmProgram& out) {
        if (!parseVersion(expected, out)) return false;
        while (cur().kind != Token::Kind::End) {
            AsmInstruction ins;
            if (!parseInstruction(ins)) return false;
            out.instructions.push_back(std::move(ins));
        }
        return true;
    }

private:
    std::vector<Token> t_;
    size_t pos_ = 0;
    const SourceMap& map_;
    std::vector<Diagnostic>& diagnostics_;

    const Token& cur() const { return t_[std::min(pos_, t_.size() - 1)]; }
    const Token& peek(size_t k) const { return t_[std::min(pos_ + k, t_.size() - 1)]; }

    bool fail(std::string message, const Token& where) {
        if (where.kind == Token::Kind::End) {
            size_t found = message.find(", found ''");
            if (found != std::string::npos) message = message.substr(0, found) + ", but the asm block ends here";
        }
        diagnostics_.push_back(map_.make(Severity::Error, diag::kSyntax, message, where.line, where.column,
                                         where.kind == Token::Kind::End ? std::string() : where.text));
        return false;
    }

    bool parseVersion(ShaderStage expected, AsmProgram& out) {
        const Token& first = cur();
        if (first.kind == Token::Kind::End) return fail("the asm block is empty: it needs a version (vs_1_1, ps_2_0 ...) and instructions", first);
        std::string name = toLower(first.text);
        std::string version;
        if ((name == "vs" || name == "ps") && peek(1).kind == Token::Kind::Number) {
            // DX8 spelling `ps.1.1`: the tokens are `ps`, `.1`, `.1` (or `.1.1`).
            std::string digits;
            size_t k = 1;
            while (peek(k).kind == Token::Kind::Number && peek(k).line == first.line) digits += peek(k++).text;
            std::string v;
            for (char c : digits)
                if (std::isdigit(static_cast<unsigned char>(c))) v += c;
            if (v.size() != 2) return fail("'" + first.text + digits + "' is not a shader version", first);
            if (name == "vs" && v == "10") v = "11";  // vs.1.0 runs as vs_1_1
            version = name + "_" + v.substr(0, 1) + "_" + v.substr(1, 1);
            out.dx8Syntax = true;
            pos_ += k;
        } else {
            version = name;
            ++pos_;
        }
        auto profile = parseShaderProfile(version);
        static const char* const kSupported[] = {"vs_1_1", "vs_2_0", "vs_2_x", "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4", "ps_2_0", "ps_2_x"};
        bool supported = false;
        for (const char* s : kSupported) supported |= version == s;
        if (!profile) return fail("an asm block starts with its shader version (vs_1_1, vs_2_0, ps_1_1 ... ps_2_0), not '" + first.text + "'", first);
        if (!supported) {
            diagnostics_.push_back(map_.make(Severity::Error, diag::kUnsupported,
                                             "shader assembly for " + version + " is not supported (vs_1_1, vs_2_0, ps_1_1 - ps_1_4 and ps_2_0 are)",
                                             first.line, first.column, first.text));
            return false;
        }
        if (profile->stage != expected) {
            diagnostics_.push_back(map_.make(Severity::Error, diag::kBadProfile,
                                             "the asm block is a " + std::string(profile->stage == ShaderStage::Vertex ? "vertex" : "pixel") +
                                                 " shader (" + version + ") but it is assigned to a " +
                                                 (expected == ShaderStage::Vertex ? "vertex" : "pixel") + " shader",
                                             first.line, first.column, first.text));
            return false;
        }
        out.profile = *profile;
        out.profile.name = version;
        out.versionLine = first.line;
        return true;
    }

    bool parseInstruction(AsmInstruction& ins) {
        if (cur().is("+")) {
            ins.coissue = true;
            ++pos_;
        }
        const Token& op = cur();
        if (!op.isIdent()) return fail("expected an instruction, found '" + op.text + "'", op);
        ins.line = op.line;
        ins.text = op.text;
        std::vector<std::string> parts = splitUnderscore(toLower(op.text));
        ins.opcode = parts[0];
        ins.modifiers.assign(parts.begin() + 1, parts.end());
        ++pos_;
        // `def c0, 1, 0, 0, 1` and every other instruction: operands separated by commas. An
        // instruction with no operands (nop, phase) is followed directly by the next one.
        if (ins.opcode == "nop" || ins.opcode == "phase" || ins.opcode == "ret" || ins.opcode == "else" ||
            ins.opcode.rfind("end", 0) == 0)
            return true;
        while (true) {
            AsmOperand o;
            if (!parseOperand(o)) return false;
            ins.operands.push_back(std::move(o));
            if (!cur().is(",")) break;
            ++pos_;
        }
        return true;
    }

    bool parseOperand(AsmOperand& o) {
        o.text = cur().text;
        if (cur().is("-")) {
            o.negate = true;
            ++pos_;
        }
        if (cur().kind == Token::Kind::Number) {
            const Token& n = cur();
            if (peek(1).is("-") && std::atof(n.text.c_str()) == 1.0 && peek(2).isIdent()) {  // 1-r0
                o.invert = true;
                pos_ += 2;
            } else {
                o.isNumber = true;
                o.number = std::strtod(n.text.c_str(), nullptr);
                if (o.negate) o.number = -o.number;
                o.negate = false;
                ++pos_;
                return true;
            }
        }
        const Token& r = cur();
        if (!r.isIdent()) return fail("expected a register, found '" + r.text + "'", r);
        if (o.text == "-" || o.invert) o.text = r.text;
        std::vector<std::string> parts = splitUnderscore(r.text);
        if (!splitRegister(parts[0], o.reg)) return fail("'" + parts[0] + "' is not a D3D9 shader register", r);
        for (size_t k = 1; k < parts.size(); ++k) o.modifiers.push_back(toLower(parts[k]));
        ++pos_;
        if (cur().is("[")) {  // c[a0.x + 5], c5[a0.x]
            const Token& open = cur();
            ++pos_;
            int offset = o.reg.index < 0 ? 0 : o.reg.index;
            bool sawAddress = false;
            int sign = 1;
            while (!cur().is("]")) {
                const Token& k = cur();
                if (k.kind == Token::Kind::End) return fail("'[' of a relative address is never closed", open);
                if (k.isIdent() && toLower(k.text) == "a0") {
                    sawAddress = true;
                    if (peek(1).is(".") && peek(2).isIdent()) {
                        o.reg.relativeComponent = normaliseSwizzle(peek(2).text)[0];
                        pos_ += 2;
                    }
                } else if (k.is("+")) {
                    sign = 1;
                } else if (k.is("-")) {
                    sign = -1;
                } else if (k.kind == Token::Kind::Number) {
                    offset += sign * (k.text.size() > 4 ? 4096 : std::atoi(k.text.c_str()));
                } else {
                    return fail("a register index takes a0.x and numbers, not '" + k.text + "'", k);
                }
                ++pos_;
            }
            ++pos_;
            o.reg.relative = sawAddress;  // c[2] (DX8 spelling) is just c2
            o.reg.index = offset;
        }
        if (o.reg.index < 0) return fail("register '" + r.text + "' has no number", r);
        if (o.reg.index >= 4096 || o.reg.index < -4096) return fail("register '" + r.text + "' is out of range", r);
        if (cur().is(".") && peek(1).isIdent()) {
            std::vector<std::string> sw = splitUnderscore(peek(1).text);
            if (!isSwizzle(toLower(sw[0]))) return fail("'" + sw[0] + "' is not a swizzle or write mask", peek(1));
            o.swizzle = normaliseSwizzle(sw[0]);
            for (size_t k = 1; k < sw.size(); ++k) o.modifiers.push_back(toLower(sw[k]));
            pos_ += 2;
        }
        return true;
    }
};

}  // namespace

std::string blankAsmLineComments(const std::string& source) {
    std::string out = source;
    enum class In { Code, LineComment, BlockComment, String } state = In::Code;
    int asmDepth = 0;          // > 0 inside the braces of an asm block
    bool afterAsmKeyword = false;
    for (size_t i = 0; i < out.size(); ++i) {
        char c = out[i];
        char next = i + 1 < out.size() ? out[i + 1] : '\0';
        switch (state) {
        case In::LineComment:
            if (c == '\n') state = In::Code;
            continue;
        case In::BlockComment:
            if (c == '*' && next == '/') {
                state = In::Code;
                ++i;
            }
            continue;
        case In::String:
            if (c == '\\') ++i;
            else if (c == '"' || c == '\n') state = In::Code;
            continue;
        case In::Code: break;
        }
        if (c == '/' && next == '/') {
            state = In::LineComment;
            ++i;
            continue;
        }
        if (c == '/' && next == '*') {
            state = In::BlockComment;
            ++i;
            continue;
        }
        if (asmDepth > 0) {
            if (c == ';') {
                while (i < out.size() && out[i] != '\n') out[i++] = ' ';
                --i;
            } else if (c == '{') {
                ++asmDepth;
            } else if (c == '}') {
                --asmDepth;
            }
            continue;
        }
        if (c == '"') {
            state = In::String;
            continue;
        }
        bool wordStart = i == 0 || !(std::isalnum(static_cast<unsigned char>(out[i - 1])) || out[i - 1] == '_');
        if (wordStart && (c == 'a' || c == 'A') && i + 3 <= out.size() && iequals(std::string_view(out).substr(i, 3), "asm") &&
            !(i + 3 < out.size() && (std::isalnum(static_cast<unsigned char>(out[i + 3])) || out[i + 3] == '_'))) {
            afterAsmKeyword = true;
            i += 2;
            continue;
        }
        if (afterAsmKeyword && c == '{') {
            asmDepth = 1;
            afterAsmKeyword = false;
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            afterAsmKeyword = false;
        }
    }
    return out;
}

bool parseAsmProgram(const std::string& text, int firstLine, ShaderStage expected, const SourceMap& map,
                     std::vector<Diagnostic>& diagnostics, AsmProgram& out) {
    // `;` starts a comment to the end of the line in shader assembly (// and /* */ are gone already).
    std::string clean = text;
    bool inComment = false;
    for (char& c : clean) {
        if (c == '\n') inComment = false;
        else if (c == ';') inComment = true;
        if (inComment) c = ' ';
    }
    std::vector<Token> tokens = tokenize(clean);
    for (Token& t : tokens) t.line += firstLine - 1;
    return AsmParser(std::move(tokens), map, diagnostics).run(expected, out);
}

}  // namespace fxport::xlate
