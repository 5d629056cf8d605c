// D3D9 shader-assembly instructions -> HLSL statements (see d3d9_asm.h for the whole idea). Each
// instruction computes a float4 result from its modified sources, applies the instruction
// modifiers (_x2 ... _d8, _sat, then ps_1_x's [-1, 1] range) and writes the destination's mask;
// a ps_1_x co-issued pair (`+mov r0.a, ...`) computes both results before either is written.
#include <algorithm>
#include <set>
#include <sstream>

#include "d3d9asm/d3d9_asm.h"
#include "fx/source_map.h"
#include "fx/text_util.h"

namespace fxport::xlate {

std::string asmSamplerName(const std::string& functionName, int stage) { return functionName + "_s" + std::to_string(stage); }

namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(9);
    s << v;
    std::string out = s.str();
    if (out.find_first_of(".eEin") == std::string::npos) out += ".0";
    return out;
}

// D3D9 swizzles shorter than four components repeat their last one (`.xy` = `.xyyy`).
std::string fullSwizzle(const std::string& s) {
    if (s.empty()) return "xyzw";
    std::string out = s;
    while (out.size() < 4) out += out.back();
    return out;
}

const char* semanticOfUsage(const std::string& usage) {
    static const std::pair<const char*, const char*> k[] = {
        {"position", "POSITION"}, {"blendweight", "BLENDWEIGHT"}, {"blendindices", "BLENDINDICES"}, {"normal", "NORMAL"},
        {"psize", "PSIZE"}, {"texcoord", "TEXCOORD"}, {"tangent", "TANGENT"}, {"binormal", "BINORMAL"},
        {"color", "COLOR"}, {"fog", "FOG"}, {"depth", "DEPTH"}, {"positiont", "POSITIONT"}, {"tessfactor", "TESSFACTOR"}};
    for (const auto& [name, semantic] : k)
        if (usage == name) return semantic;
    return nullptr;
}

class Translator {
public:
    Translator(const AsmProgram& p, const std::string& fn, const AsmBindings& b, const SourceMap& map, std::vector<Diagnostic>& d)
        : p_(p), fn_(fn), bindings_(b), map_(map), diagnostics_(d) {
        vertex_ = p.profile.stage == ShaderStage::Vertex;
        ps1_ = !vertex_ && p.profile.major == 1;
        ps14_ = ps1_ && p.profile.minor == 4;
    }

    TranslatedAsm run();

private:
    const AsmProgram& p_;
    std::string fn_;
    const AsmBindings& bindings_;
    const SourceMap& map_;
    std::vector<Diagnostic>& diagnostics_;
    bool vertex_ = false, ps1_ = false, ps14_ = false;
    bool ok_ = true;

    std::map<int, std::string> defs_;            // def c# -> float4 literal
    std::map<int, std::string> inputSemantic_;   // v# (vertex) / t#, v# (pixel) -> semantic
    std::map<int, TextureKind> samplerDcl_;      // ps_2_0 dcl_2d s# ...
    std::set<std::string> inputsRead_;           // parameter names
    std::set<std::string> outputsWritten_;       // o_* locals
    std::set<int> temps_;
    std::set<int> textureRegisters_;              // ps_1_1-1_3 t# (locals written by tex/texcoord)
    std::set<int> warnedConstants_;
    std::map<int, TextureKind> samplersUsed_;
    std::vector<std::string> rows_;              // texm3x2pad/texm3x3pad results waiting for their texm3x*
    bool usesAddress_ = false, relative_ = false;
    const AsmInstruction* ins_ = nullptr;        // being translated (for diagnostics)
    std::ostringstream body_;
    int tempCounter_ = 0;

    void error(const std::string& message, const std::string& token = {}) {
        diagnostics_.push_back(map_.make(Severity::Error, diag::kUnsupported, message, ins_->line, 0, token.empty() ? ins_->text : token));
        ok_ = false;
    }
    void warning(const std::string& message, const std::string& token = {}) {
        diagnostics_.push_back(map_.make(Severity::Warning, diag::kUnsupported, message, ins_->line, 0, token.empty() ? ins_->text : token));
    }

    // ---- registers ----
    std::string inputName(const AsmRegister& r) {
        if (vertex_) {
            if (!inputSemantic_.count(r.index)) {
                // D3D8's fixed vertex-stream mapping (what vs.1.x without dcl meant there).
                static const char* const k[] = {"POSITION0", "BLENDWEIGHT0", "BLENDINDICES0", "NORMAL0", "PSIZE0", "COLOR0", "COLOR1",
                                                "TEXCOORD0", "TEXCOORD1", "TEXCOORD2", "TEXCOORD3", "TEXCOORD4", "TEXCOORD5", "TEXCOORD6",
                                                "TEXCOORD7", "POSITION1"};
                std::string sem = r.index < 16 ? k[r.index] : "TEXCOORD" + std::to_string(r.index);
                warning("input register v" + std::to_string(r.index) + " has no dcl_* declaration; it is read as " + sem +
                            " (D3D8's fixed vertex-stream mapping)",
                        "v" + std::to_string(r.index));
                inputSemantic_[r.index] = sem;
            }
            std::string name = "v" + std::to_string(r.index);
            inputsRead_.insert(name);
            return name;
        }
        std::string name = "v" + std::to_string(r.index);
        inputsRead_.insert(name);
        return name;
    }
    std::string texcoordInput(int index) {
        std::string name = "fxport_tc" + std::to_string(index);
        inputsRead_.insert(name);
        return name;
    }
    std::string constant(const AsmRegister& r, const std::string& token) {
        std::string value;
        if (auto d = defs_.find(r.index); d != defs_.end()) value = d->second;
        else if (auto b = bindings_.constants.find(r.index); b != bindings_.constants.end()) value = b->second;
        else {
            if (warnedConstants_.insert(r.index).second)
                warning("constant register c" + std::to_string(r.index) + " is read but neither a def nor a " +
                            (vertex_ ? "VertexShaderConstant" : "PixelShaderConstant") + "[" + std::to_string(r.index) +
                            "] = <parameter> pass state sets it; it reads (0, 0, 0, 0)",
                        token);
            value = "float4(0, 0, 0, 0)";
        }
        // ps_1_x constants hold [-1, 1] (D3D9 clamps them when they are set).
        return ps1_ ? "clamp(" + value + ", -1.0, 1.0)" : value;
    }
    std::string read(const AsmRegister& r, const std::string& token) {
        const std::string n = std::to_string(r.index);
        if (r.type == "r") {
            if (!temps_.count(r.index)) {
                if (!(ps1_ && r.index == 0)) warning("temporary register r" + n + " is read before it is written; it reads (0, 0, 0, 0)", token);
                temps_.insert(r.index);
            }
            return "r" + n;
        }
        if (r.type == "v") return inputName(r);
        if (r.type == "c") {
            if (r.relative) {
                relative_ = true;
                return "fxport_c[clamp((int)a0." + std::string(1, r.relativeComponent) + " + " + n + ", 0, fxport_cCount - 1)]";
            }
            return constant(r, token);
        }
        if (r.type == "t" && !vertex_) {
            if (ps1_ && !ps14_) {  // written by tex/texcoord first
                textureRegisters_.insert(r.index);
                return "t" + n;
            }
            std::string name = "t" + n;
            inputsRead_.insert(name);
            return name;
        }
        if (r.type == "a") {
            usesAddress_ = true;
            return "a0";
        }
        error("register " + r.type + n + " cannot be read here", token);
        return "float4(0, 0, 0, 0)";
    }

    // A source operand: register, swizzle, then the modifiers in D3D's order (bias / bx2 / x2,
    // invert, negate last; abs before negate).
    std::string source(const AsmOperand& o) {
        if (o.isNumber) return "float4(" + number(o.number) + ", " + number(o.number) + ", " + number(o.number) + ", " + number(o.number) + ")";
        std::string v = read(o.reg, o.text);
        std::string sw = fullSwizzle(o.swizzle);
        if (sw != "xyzw") v = "(" + v + ")." + sw;
        for (const std::string& m : o.modifiers) {
            if (m == "bias") v = "(" + v + " - 0.5)";
            else if (m == "bx2") v = "(2.0 * (" + v + " - 0.5))";
            else if (m == "x2") v = "(2.0 * " + v + ")";
            else if (m == "abs") v = "abs(" + v + ")";
            else if (m == "dz" || m == "db" || m == "dw" || m == "da") continue;  // texld/texcrd only (see there)
            else error("source modifier '_" + m + "' is not supported", o.text);
        }
        if (o.invert) v = "(1.0 - " + v + ")";
        if (o.negate) v = "(-" + v + ")";
        return v;
    }
    // The scalar a replicate-swizzle source names. Without a swizzle D3D9 reads .x; DX8's
    // `vs.1.x` spelling read .w (its scalar instructions took src.w).
    std::string scalar(const AsmOperand& o) {
        return "(" + source(o) + ")." + (o.swizzle.empty() && p_.dx8Syntax ? "w" : "x");
    }
    std::string replicate(const std::string& s) { return "((float4)(" + s + "))"; }

    // Destination register name (a local float4); outputs are o_* locals copied out at the end.
    std::string destination(const AsmRegister& r, const std::string& token) {
        const std::string n = std::to_string(r.index);
        if (r.type == "r") {
            temps_.insert(r.index);
            return "r" + n;
        }
        if (r.type == "a" && vertex_) {
            usesAddress_ = true;
            return "a0";
        }
        if (r.type == "t" && ps1_ && !ps14_) {
            textureRegisters_.insert(r.index);
            return "t" + n;
        }
        std::string out;
        if (vertex_) {
            if (r.type == "opos") out = "o_Pos";
            else if (r.type == "od" && r.index < 2) out = "o_D" + n;
            else if (r.type == "ot" && r.index < 8) out = "o_T" + n;
            else if (r.type == "ofog") out = "o_Fog";
            else if (r.type == "opts") out = "o_Pts";
        } else if (!ps1_) {
            if (r.type == "oc" && r.index < 4) out = "o_C" + n;
            else if (r.type == "odepth") out = "o_Depth";
        }
        if (out.empty()) {
            error("register '" + token + "' cannot be written here", token);
            return "fxport_unused";
        }
        outputsWritten_.insert(out);
        return out;
    }

    struct PendingWrite {
        std::string target, value, mask;
    };
    std::vector<PendingWrite> pending_;

    // Instruction modifiers on a result: shift, saturate, then ps_1_x's register range.
    std::string finish(const std::string& value, bool arithmetic) {
        std::string v = value;
        for (const std::string& m : ins_->modifiers) {
            if (m == "x2") v = "(" + v + " * 2.0)";
            else if (m == "x4") v = "(" + v + " * 4.0)";
            else if (m == "x8") v = "(" + v + " * 8.0)";
            else if (m == "d2") v = "(" + v + " * 0.5)";
            else if (m == "d4") v = "(" + v + " * 0.25)";
            else if (m == "d8") v = "(" + v + " * 0.125)";
            else if (m == "sat") v = "saturate(" + v + ")";
            else if (m == "pp") continue;
            else error("instruction modifier '_" + m + "' is not supported");
        }
        if (ps1_ && arithmetic) v = "clamp(" + v + ", -1.0, 1.0)";
        return v;
    }
    void write(const AsmOperand& dst, const std::string& value, bool arithmetic = true, const std::string& defaultMask = "xyzw") {
        std::string target = destination(dst.reg, dst.text);
        std::string temp = "fxport_v" + std::to_string(tempCounter_++);
        body_ << "    float4 " << temp << " = " << finish(value, arithmetic) << ";\n";
        pending_.push_back({target, temp, dst.swizzle.empty() ? defaultMask : dst.swizzle});
    }
    void flush() {
        for (const auto& w : pending_) {
            if (w.mask == "xyzw") body_ << "    " << w.target << " = " << w.value << ";\n";
            else body_ << "    " << w.target << "." << w.mask << " = " << w.value << "." << w.mask << ";\n";
        }
        pending_.clear();
    }

    // The stage's bump-environment state as a float expression ("00" ... "11", "lscale", "loffset").
    std::string bump(int stage, const std::string& which) {
        std::string key = which.size() == 2 ? "bumpenvmat" + which : "bumpenv" + which;
        auto s = bindings_.bumpEnvironment.find(stage);
        if (s == bindings_.bumpEnvironment.end()) return "0.0";
        auto v = s->second.find(key);
        return v == s->second.end() ? "0.0" : v->second;
    }
    TextureKind kindOfStage(int stage) {
        if (auto it = samplerDcl_.find(stage); it != samplerDcl_.end()) return it->second;
        if (auto it = bindings_.stageKinds.find(stage); it != bindings_.stageKinds.end()) return it->second;
        return TextureKind::Texture2D;
    }
    std::string sample(int stage, const std::string& coords, const char* variant = "") {
        TextureKind k = kindOfStage(stage);
        samplersUsed_[stage] = k;
        std::string s = asmSamplerName(fn_, stage);
        std::string v = variant;
        switch (k) {
        case TextureKind::TextureCube: return "texCUBE" + v + "(" + s + ", " + (v.empty() ? "(" + coords + ").xyz" : coords) + ")";
        case TextureKind::Texture3D: return "tex3D" + v + "(" + s + ", " + (v.empty() ? "(" + coords + ").xyz" : coords) + ")";
        case TextureKind::Texture1D: return "tex1D" + v + "(" + s + ", " + (v.empty() ? "(" + coords + ").x" : coords) + ")";
        default: return "tex2D" + v + "(" + s + ", " + (v.empty() ? "(" + coords + ").xy" : coords) + ")";
        }
    }

    bool expectOperands(size_t n) {
        if (ins_->operands.size() == n) return true;
        diagnostics_.push_back(map_.make(Severity::Error, diag::kSyntax,
                                         "'" + ins_->text + "' takes " + std::to_string(n) + " operand(s), not " + std::to_string(ins_->operands.size()),
                                         ins_->line, 0, ins_->text));
        ok_ = false;
        return false;
    }

    void declaration(const AsmInstruction& ins);
    void instruction(const AsmInstruction& ins);
    void matrix(const AsmInstruction& ins, int columns, int rows);
};

void Translator::declaration(const AsmInstruction& ins) {
    if (!expectOperands(1)) return;
    const AsmOperand& o = ins.operands[0];
    std::string usage;
    for (const std::string& m : ins.modifiers)
        if (m != "centroid" && m != "pp") usage = m;
    if (o.reg.type == "s") {
        TextureKind k = usage == "cube" ? TextureKind::TextureCube : usage == "volume" ? TextureKind::Texture3D : TextureKind::Texture2D;
        if (!usage.empty() && usage != "2d" && usage != "cube" && usage != "volume") error("unknown sampler declaration 'dcl_" + usage + "'");
        samplerDcl_[o.reg.index] = k;
        return;
    }
    if (vertex_ && o.reg.type == "v") {
        size_t digits = usage.size();
        while (digits > 0 && std::isdigit(static_cast<unsigned char>(usage[digits - 1]))) --digits;
        const char* semantic = semanticOfUsage(usage.substr(0, digits));
        if (!semantic) {
            error("'dcl_" + usage + "' is not a vertex input usage fxport knows");
            return;
        }
        inputSemantic_[o.reg.index] = semantic + (digits == usage.size() ? std::string("0") : usage.substr(digits));
        return;
    }
    if (!vertex_ && (o.reg.type == "t" || o.reg.type == "v")) return;  // ps_2_0 `dcl t0.xy`: inputs by register number
    if (vertex_ && o.reg.type == "o") return;
    error("declaration of register " + o.reg.type + std::to_string(o.reg.index) + " is not supported");
}

void Translator::matrix(const AsmInstruction& ins, int columns, int rows) {
    // m4x4 dst, src0, cN: dst.i = dot(src0, register N+i) for i < rows, over `columns` components.
    if (!expectOperands(3)) return;
    const AsmOperand& m = ins.operands[2];
    std::string v = source(ins.operands[1]);
    std::string comps = columns == 4 ? "" : columns == 3 ? ".xyz" : ".xy";
    std::string out = "float4(";
    for (int i = 0; i < 4; ++i) {
        if (i) out += ", ";
        if (i >= rows) {
            out += "0";
            continue;
        }
        AsmRegister r = m.reg;
        r.index += i;
        out += "dot((" + v + ")" + comps + ", (" + read(r, m.text) + ")" + comps + ")";
    }
    out += ")";
    static const char* const masks[] = {"", "x", "xy", "xyz", "xyzw"};
    write(ins.operands[0], out, true, masks[rows]);
}

void Translator::instruction(const AsmInstruction& ins) {
    ins_ = &ins;
    const std::string& op = ins.opcode;
    const auto& o = ins.operands;
    auto binary = [&](const char* fmt) {
        if (!expectOperands(3)) return;
        std::string a = source(o[1]), b = source(o[2]), r;
        for (const char* c = fmt; *c; ++c) r += *c == '$' ? (*++c == '0' ? a : b) : std::string(1, *c);
        write(o[0], r);
    };
    if (op == "dcl") return declaration(ins);
    if (op == "def") {
        if (o.size() != 5 || o[0].reg.type != "c" || !o[1].isNumber || !o[2].isNumber || !o[3].isNumber || !o[4].isNumber) {
            error("def takes a constant register and four numbers: def c0, 1, 0, 0, 1");
            return;
        }
        defs_[o[0].reg.index] = "float4(" + number(o[1].number) + ", " + number(o[2].number) + ", " + number(o[3].number) + ", " + number(o[4].number) + ")";
        return;
    }
    if (op == "nop" || op == "phase") return;  // ps_1_4 phases: the alpha loss across phase is not imitated
    if (op == "mov" || op == "mova") {
        if (!expectOperands(2)) return;
        std::string v = source(o[1]);
        if (o[0].reg.type == "a") {
            // vs_1_1 `mov a0.x` truncates towards -inf; vs_2_0 `mova` rounds to nearest.
            v = op == "mova" ? "floor(" + v + " + 0.5)" : "floor(" + v + ")";
            write(o[0], v, false);
            return;
        }
        return write(o[0], v);
    }
    if (op == "add") return binary("($0 + $1)");
    if (op == "sub") return binary("($0 - $1)");
    if (op == "mul") return binary("($0 * $1)");
    if (op == "min") return binary("min($0, $1)");
    if (op == "max") return binary("max($0, $1)");
    if (op == "slt") return binary("((float4)($0 < $1))");
    if (op == "sge") return binary("((float4)($0 >= $1))");
    if (op == "dp3") return binary("((float4)dot(($0).xyz, ($1).xyz))");
    if (op == "dp4") return binary("((float4)dot($0, $1))");
    if (op == "crs") return binary("float4(cross(($0).xyz, ($1).xyz), 0)");
    if (op == "dst") return binary("float4(1.0, ($0).y * ($1).y, ($0).z, ($1).w)");
    if (op == "mad") {
        if (!expectOperands(4)) return;
        return write(o[0], "(" + source(o[1]) + " * " + source(o[2]) + " + " + source(o[3]) + ")");
    }
    if (op == "lrp") {  // dst = src0 * src1 + (1 - src0) * src2
        if (!expectOperands(4)) return;
        std::string s0 = source(o[1]), s1 = source(o[2]), s2 = source(o[3]);
        return write(o[0], "(" + s2 + " + " + s0 + " * (" + s1 + " - " + s2 + "))");
    }
    if (op == "cnd") {  // ps_1_1-1_3 compare r0.a; ps_1_4 per component
        if (!expectOperands(4)) return;
        std::string c = source(o[1]);
        if (!ps14_) c = "(" + c + ").wwww";
        return write(o[0], "((" + c + " > 0.5) ? " + source(o[2]) + " : " + source(o[3]) + ")");
    }
    if (op == "cmp") {
        if (!expectOperands(4)) return;
        return write(o[0], "((" + source(o[1]) + " >= 0.0) ? " + source(o[2]) + " : " + source(o[3]) + ")");
    }
    if (op == "dp2add") {
        if (!expectOperands(4)) return;
        return write(o[0], replicate("dot((" + source(o[1]) + ").xy, (" + source(o[2]) + ").xy) + " + scalar(o[3])));
    }
    if (op == "rcp" || op == "rsq" || op == "exp" || op == "log" || op == "expp" || op == "logp" || op == "frc" || op == "abs" || op == "nrm") {
        if (!expectOperands(2)) return;
        if (op == "frc") return write(o[0], "frac(" + source(o[1]) + ")");
        if (op == "abs") return write(o[0], "abs(" + source(o[1]) + ")");
        if (op == "nrm") {
            std::string v = source(o[1]);
            return write(o[0], "(" + v + " * rsqrt(dot((" + v + ").xyz, (" + v + ").xyz)))");
        }
        std::string s = scalar(o[1]);
        if (op == "rcp") return write(o[0], replicate("1.0 / " + s));
        if (op == "rsq") return write(o[0], replicate("rsqrt(abs(" + s + "))"));
        if (op == "exp" || (op == "expp" && p_.profile.major >= 2)) return write(o[0], replicate("exp2(" + s + ")"));
        if (op == "log" || (op == "logp" && p_.profile.major >= 2)) return write(o[0], replicate("log2(abs(" + s + "))"));
        if (op == "expp")  // vs_1_1: (2^floor(s), frac(s), 2^s, 1)
            return write(o[0], "float4(exp2(floor(" + s + ")), frac(" + s + "), exp2(" + s + "), 1.0)");
        // logp vs_1_1: (exponent, mantissa, log2|s|, 1)
        return write(o[0], "float4(floor(log2(abs(" + s + "))), abs(" + s + ") / exp2(floor(log2(abs(" + s + ")))), log2(abs(" + s +
                               ")), 1.0)");
    }
    if (op == "pow") {
        if (!expectOperands(3)) return;
        return write(o[0], replicate("pow(abs(" + scalar(o[1]) + "), " + scalar(o[2]) + ")"));
    }
    if (op == "lit") {
        if (!expectOperands(2)) return;
        std::string s = source(o[1]);
        return write(o[0], "float4(1.0, max((" + s + ").x, 0.0), ((" + s + ").x > 0.0 && (" + s + ").y > 0.0) ? pow((" + s +
                               ").y, clamp((" + s + ").w, -128.0, 128.0)) : 0.0, 1.0)");
    }
    if (op == "sincos") {  // vs_2_0/ps_2_0: dst.x = cos, dst.y = sin (the two constant operands are the hardware's series)
        if (o.size() != 2 && o.size() != 4) return (void)expectOperands(4);
        std::string s = scalar(o[1]);
        return write(o[0], "float4(cos(" + s + "), sin(" + s + "), 0, 0)", true, "xy");
    }
    if (op == "m4x4") return matrix(ins, 4, 4);
    if (op == "m4x3") return matrix(ins, 4, 3);
    if (op == "m3x4") return matrix(ins, 3, 4);
    if (op == "m3x3") return matrix(ins, 3, 3);
    if (op == "m3x2") return matrix(ins, 3, 2);

    // ---- texture instructions ----
    if (op == "tex" && ps1_ && !ps14_) {  // tex tN: sample stage N at texture coordinate set N
        if (!expectOperands(1)) return;
        int n = o[0].reg.index;
        return write(o[0], sample(n, texcoordInput(n)), false);
    }
    if (op == "texcoord" && ps1_ && !ps14_) {  // (saturate(uvw), 1)
        if (!expectOperands(1)) return;
        return write(o[0], "float4(saturate(" + texcoordInput(o[0].reg.index) + ".xyz), 1.0)", false);
    }
    // ps_1_1-1_3 texture-address instructions: rows of a matrix multiply (texcoord set N . src),
    // dependent reads through another texture's colour.
    if (ps1_ && !ps14_ && (op == "texm3x2pad" || op == "texm3x3pad")) {
        if (!expectOperands(2)) return;
        std::string row = "fxport_row" + std::to_string(tempCounter_++);
        body_ << "    float " << row << " = dot(" << texcoordInput(o[0].reg.index) << ".xyz, (" << source(o[1]) << ").xyz);\n";
        rows_.push_back(row);
        return;
    }
    if (ps1_ && !ps14_ && (op == "texm3x2tex" || op == "texm3x3tex" || op == "texm3x3" || op == "texm3x3spec" || op == "texm3x3vspec")) {
        const bool three = op != "texm3x2tex";
        if (!expectOperands(op == "texm3x3spec" ? 3 : 2)) return;
        size_t need = three ? 2 : 1;
        if (rows_.size() < need) return error(op + " needs the " + (three ? "two texm3x3pad" : "texm3x2pad") + " instructions before it");
        int n = o[0].reg.index;
        std::string last = "dot(" + texcoordInput(n) + ".xyz, (" + source(o[1]) + ").xyz)";
        std::string coords = three ? "float4(" + rows_[rows_.size() - 2] + ", " + rows_.back() + ", " + last + ", 0)"
                                   : "float4(" + rows_.back() + ", " + last + ", 0, 0)";
        rows_.clear();
        // Written into a t register: ps_1_x's register range applies, as to arithmetic results.
        if (op == "texm3x3") return write(o[0], "float4((" + coords + ").xyz, 1.0)", true);
        if (op == "texm3x3spec" || op == "texm3x3vspec") {
            // Reflect the eye vector about the normal (u, v, w): 2 N (N.E) / (N.N) - E.
            std::string eye = op == "texm3x3spec" ? "(" + source(o[2]) + ").xyz"
                                                  : "float3(" + texcoordInput(n - 2) + ".w, " + texcoordInput(n - 1) + ".w, " + texcoordInput(n) + ".w)";
            std::string nv = "fxport_n" + std::to_string(tempCounter_++), ev = "fxport_e" + std::to_string(tempCounter_++);
            body_ << "    float3 " << nv << " = (" << coords << ").xyz;\n    float3 " << ev << " = " << eye << ";\n";
            coords = "float4(2.0 * " + nv + " * dot(" + nv + ", " + ev + ") / dot(" + nv + ", " + nv + ") - " + ev + ", 0)";
        }
        return write(o[0], sample(n, coords), false);
    }
    if (ps1_ && !ps14_ && (op == "texreg2ar" || op == "texreg2gb" || op == "texreg2rgb" || op == "texdp3" || op == "texdp3tex")) {
        if (!expectOperands(2)) return;
        int n = o[0].reg.index;
        std::string src = source(o[1]);
        if (op == "texdp3") return write(o[0], replicate("dot(" + texcoordInput(n) + ".xyz, (" + src + ").xyz)"), true);
        std::string coords = op == "texreg2ar"   ? "float4((" + src + ").w, (" + src + ").x, 0, 0)"
                             : op == "texreg2gb" ? "float4((" + src + ").y, (" + src + ").z, 0, 0)"
                             : op == "texreg2rgb" ? "float4((" + src + ").xyz, 0)"
                                                  : "float4(dot(" + texcoordInput(n) + ".xyz, (" + src + ").xyz), 0, 0, 0)";
        return write(o[0], sample(n, coords), false);
    }
    // Bump-environment mapping: the stage's 2x2 matrix (BumpEnvMat00[n] ...) turns src.rg into a
    // texture-coordinate offset; texbeml scales the sample by src.b * BumpEnvLScale + BumpEnvLOffset.
    if ((op == "texbem" || op == "texbeml") && ps1_ && !ps14_) {
        if (!expectOperands(2)) return;
        int n = o[0].reg.index;
        std::string src = source(o[1]), tc = texcoordInput(n);
        std::string coords = "float4(" + tc + ".x + " + bump(n, "00") + " * (" + src + ").x + " + bump(n, "10") + " * (" + src + ").y, " + tc +
                             ".y + " + bump(n, "01") + " * (" + src + ").x + " + bump(n, "11") + " * (" + src + ").y, 0, 0)";
        std::string v = sample(n, coords);
        if (op == "texbeml") v = "(" + v + " * saturate((" + src + ").z * " + bump(n, "lscale") + " + " + bump(n, "loffset") + "))";
        return write(o[0], v, false);
    }
    if (op == "bem" && ps14_) {  // ps_1_4: dst.rg = src0.rg + matrix(stage of dst) * src1.rg
        if (!expectOperands(3)) return;
        int n = o[0].reg.index;
        std::string a = source(o[1]), b = source(o[2]);
        return write(o[0], "float4((" + a + ").x + " + bump(n, "00") + " * (" + b + ").x + " + bump(n, "10") + " * (" + b + ").y, (" + a + ").y + " +
                               bump(n, "01") + " * (" + b + ").x + " + bump(n, "11") + " * (" + b + ").y, 0, 0)",
                     true, "xy");
    }
    if (op == "texkill") {
        if (!expectOperands(1)) return;
        std::string v = ps1_ && !ps14_ ? texcoordInput(o[0].reg.index) : source(o[0]);
        body_ << "    clip((" << v << ").xyz);\n";
        return;
    }
    if ((op == "texld" || op == "texcrd") && ps14_) {  // ps_1_4: texld rN, tM|rM (stage N); texcrd rN, tM
        if (!expectOperands(2)) return;
        const AsmOperand& src = o[1];
        std::string c = src.reg.type == "t" ? read(src.reg, src.text) : source(src);
        for (const std::string& m : src.modifiers) {
            if (m == "dz" || m == "db") c = "float4((" + c + ").xy / (" + c + ").z, 0, 1)";
            else if (m == "dw" || m == "da") c = "float4((" + c + ").xy / (" + c + ").w, 0, 1)";
        }
        if (!src.swizzle.empty()) c = "(" + c + ")." + fullSwizzle(src.swizzle);
        if (op == "texcrd") return write(o[0], "float4((" + c + ").xyz, 1.0)", false);
        return write(o[0], sample(o[0].reg.index, c), false);
    }
    if ((op == "texld" || op == "texldp" || op == "texldb") && !ps1_ && !vertex_) {  // ps_2_0: texld dst, coords, sN
        if (!expectOperands(3)) return;
        if (o[2].reg.type != "s") return error("the third operand of " + op + " is a sampler register (s#)", o[2].text);
        std::string c = source(o[1]);
        const char* variant = op == "texldp" ? "proj" : op == "texldb" ? "bias" : "";
        return write(o[0], sample(o[2].reg.index, c, variant), false);
    }
    error("instruction '" + ins.text + "' is not supported for " + p_.profile.name + " by fxport's shader-assembly translator");
}

TranslatedAsm Translator::run() {
    TranslatedAsm out;
    // Pass 1: declarations and defs (a def may follow its first use in the text; D3D applies it anyway).
    for (const AsmInstruction& ins : p_.instructions) {
        ins_ = &ins;
        if (ins.opcode == "dcl" || ins.opcode == "def") instruction(ins);
    }
    for (size_t i = 0; i < p_.instructions.size(); ++i) {
        const AsmInstruction& ins = p_.instructions[i];
        if (ins.opcode == "dcl" || ins.opcode == "def") continue;
        if (ins.coissue && !ps1_) {
            ins_ = &ins;
            error("co-issued instructions ('+') exist only in ps_1_x");
        }
        body_ << "    // " << map_.locate(ins.line).line << ": " << ins.text << "\n";
        instruction(ins);
        bool nextIsCoissued = i + 1 < p_.instructions.size() && p_.instructions[i + 1].coissue;
        if (!nextIsCoissued) flush();
    }
    flush();
    if (!ok_) return out;

    // ---- signature ----
    FxFunction& f = out.entry;
    f.name = fn_;
    f.returnType = "void";
    std::ostringstream params, prologue, epilogue, decls;
    auto addParam = [&](const std::string& name, const std::string& semantic, bool isOut) {
        FxParameter p;
        p.type = "float4";
        p.name = name;
        p.semantic = semantic;
        if (isOut) p.modifiers.push_back("out");
        params << (f.parameters.empty() ? "" : ", ") << (isOut ? "out " : "") << "float4 " << name << " : " << semantic;
        f.parameters.push_back(p);
    };
    for (const std::string& name : inputsRead_) {
        if (vertex_) {
            int index = std::atoi(name.c_str() + 1);
            addParam(name, inputSemantic_[index], false);
        } else if (name.rfind("fxport_tc", 0) == 0) {
            addParam(name, "TEXCOORD" + name.substr(9), false);
        } else if (name[0] == 't') {
            addParam(name, "TEXCOORD" + name.substr(1), false);
        } else {
            addParam(name, "COLOR" + name.substr(1), false);
        }
    }
    if (vertex_) {
        if (!outputsWritten_.count("o_Pos")) {
            ins_ = p_.instructions.empty() ? nullptr : &p_.instructions.back();
            diagnostics_.push_back(map_.make(Severity::Error, diag::kBadEntrySignature, "the vertex shader never writes oPos", p_.versionLine));
            return out;
        }
        for (const std::string& o : outputsWritten_) {
            std::string semantic = o == "o_Pos" ? "POSITION0" : o == "o_Fog" ? "FOG0" : o == "o_Pts" ? "PSIZE0"
                                   : o[2] == 'D'                      ? "COLOR" + o.substr(3)
                                                                      : "TEXCOORD" + o.substr(3);
            addParam("fxport_" + o, semantic, true);
            epilogue << "    fxport_" << o << " = " << o << ";\n";
        }
    } else if (ps1_) {
        addParam("fxport_oC0", "COLOR0", true);
        epilogue << "    fxport_oC0 = saturate(r0);\n";  // ps_1_x: r0 is the colour, clamped to [0, 1]
        temps_.insert(0);
    } else {
        if (outputsWritten_.empty()) {
            diagnostics_.push_back(map_.make(Severity::Error, diag::kBadEntrySignature, "the pixel shader never writes oC0", p_.versionLine));
            return out;
        }
        for (const std::string& o : outputsWritten_) {
            addParam("fxport_" + o, o == "o_Depth" ? "DEPTH0" : "COLOR" + o.substr(3), true);
            epilogue << "    fxport_" << o << " = " << o << ";\n";
        }
    }
    for (int r : temps_) prologue << "    float4 r" << r << " = float4(0, 0, 0, 0);\n";
    for (int t : textureRegisters_) prologue << "    float4 t" << t << " = float4(0, 0, 0, 0);\n";
    if (usesAddress_) prologue << "    float4 a0 = float4(0, 0, 0, 0);\n";
    for (const std::string& o : outputsWritten_) prologue << "    float4 " << o << " = float4(0, 0, 0, 1);\n";
    if (relative_) {
        // Relative addressing reads the register file as an array: every register a def or the
        // pass sets, up to the highest one; the rest read 0 as unset registers do.
        int count = 1;
        for (const auto& [r, v] : defs_) count = std::max(count, r + 1);
        for (const auto& [r, v] : bindings_.constants) count = std::max(count, r + 1);
        prologue << "    const int fxport_cCount = " << count << ";\n    float4 fxport_c[" << count << "];\n";
        for (int r = 0; r < count; ++r) {
            AsmRegister reg;
            reg.type = "c";
            reg.index = r;
            bool known = defs_.count(r) || bindings_.constants.count(r);
            prologue << "    fxport_c[" << r << "] = " << (known ? constant(reg, {}) : std::string("float4(0, 0, 0, 0)")) << ";\n";
        }
    }
    for (const auto& [stage, kind] : samplersUsed_) {
        const char* type = kind == TextureKind::TextureCube ? "samplerCUBE" : kind == TextureKind::Texture3D ? "sampler3D"
                           : kind == TextureKind::Texture1D   ? "sampler1D"
                                                              : "sampler2D";
        decls << type << " " << asmSamplerName(fn_, stage) << ";\n";
    }
    std::ostringstream code;
    code << "\n// ---- generated by fxport from shader assembly (" << p_.profile.name << ", line " << map_.locate(p_.versionLine).line
         << ")\n"
         << decls.str() << "void " << fn_ << "(" << params.str() << ") {\n"
         << prologue.str() << body_.str() << epilogue.str() << "}\n";
    out.code = code.str();
    out.samplers = samplersUsed_;
    out.ok = true;
    return out;
}

}  // namespace

TranslatedAsm translateAsmProgram(const AsmProgram& program, const std::string& functionName, const AsmBindings& bindings,
                                  const SourceMap& map, std::vector<Diagnostic>& diagnostics) {
    return Translator(program, functionName, bindings, map, diagnostics).run();
}

}  // namespace fxport::xlate
