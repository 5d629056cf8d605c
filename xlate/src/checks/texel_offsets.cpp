// A texture fetch's texel offset is an immediate of the instruction (D3D10's aoffimmi), a 4-bit
// signed number per coordinate: fxc refuses a constant offset outside -8..7 (vkd3d's
// texture-load-offset: `t.Load(c, int2(8, 1))` is refused, `int2(-2, 0)` compiles). GL's
// textureOffset takes a wider range, so glslang lets it through. Judged where the offset argument
// is `intN(...)` / `uintN(...)` of integer literals, on a texture declared as an object of the
// D3D10 kind (not multisampled: its Load takes the sample first); other offsets are left alone.
#include <cstdlib>

#include "checks/fxc_checks.h"
#include "hlsl/call_arguments.h"

namespace fxport::xlate {

namespace {

// The argument that holds the offset in each method, counted from 0.
int offsetArgument(const std::string& method) {
    if (method == "Load") return 1;
    if (method == "Sample" || method == "Gather") return 2;
    if (method == "SampleBias" || method == "SampleLevel" || method == "SampleCmp" || method == "SampleCmpLevelZero") return 3;
    if (method == "SampleGrad") return 4;
    return -1;
}

bool isOffsetConstructor(const std::string& s) {
    for (const char* n : {"int1", "int2", "int3", "uint1", "uint2", "uint3"})
        if (s == n) return true;
    return false;
}

class TexelOffsets : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
                if (!t_[i].isIdent() || !t_[i + 1].is(".") || !t_[i + 2].isIdent() || !t_[i + 3].is("(")) continue;
                const int k = offsetArgument(t_[i + 2].text);
                const FxTexture* texture = syntax_.findTexture(t_[i].text);
                if (k < 0 || !texture || texture->dx9Object || texture->type.find("MS") != std::string::npos) continue;
                auto args = callArgumentSpans(t_, i + 3, f.body.end);
                if (int(args.size()) > k) offset(args[size_t(k)].first, args[size_t(k)].second);
            }
    }

private:
    // `int2(8, 1)` in [b, e): the first component outside -8..7.
    void offset(size_t b, size_t e) {
        if (e - b < 3 || !isOffsetConstructor(t_[b].text) || !t_[b + 1].is("(") || closing(b + 1) != e - 1) return;
        for (size_t i = b + 2; i < e - 1; ++i) {
            const bool negative = t_[i].is("-");
            if (negative) ++i;
            if (t_[i].kind != Token::Kind::Number || !(t_[i + 1].is(",") || t_[i + 1].is(")"))) return;  // not literals alone
            const long v = std::strtol(t_[i].text.c_str(), nullptr, 0) * (negative ? -1 : 1);
            if (v < -8 || v > 7)
                return report("texel offset " + std::string(negative ? "-" : "") + t_[i].text +
                                  " is out of range: fxc takes an immediate offset from -8 to 7",
                              i);
            ++i;  // past the comma
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findTexelOffsetErrors(const EffectSyntax& syntax, const SourceMap& map) {
    TexelOffsets check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
