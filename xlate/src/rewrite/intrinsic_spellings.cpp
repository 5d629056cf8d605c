// See intrinsic_spellings.h.
#include "rewrite/intrinsic_spellings.h"

namespace fxport::xlate {

namespace {

struct Spelling {
    const char* d3d;
    const char* glslang;
    bool method;  // `t.Name(...)`, else a free function
};

// GatherCmpGreen/Blue/Alpha: glslang refuses them ("unimplemented: component-level gather
// compare"). Comparison sampling reads single-channel formats (R32_FLOAT, R24_UNORM_X8, R16_UNORM),
// and D3D compares their red channel whichever component is named: vkd3d's gather-cmp, whose
// expected values come from native D3D, gives GatherCmpGreen/Blue/Alpha GatherCmpRed's results.
constexpr Spelling kSpellings[] = {{"EvaluateAttributeCentroid", "EvaluateAttributeAtCentroid", false},
                                   {"GatherCmpGreen", "GatherCmpRed", true},
                                   {"GatherCmpBlue", "GatherCmpRed", true},
                                   {"GatherCmpAlpha", "GatherCmpRed", true}};

}  // namespace

std::vector<TextEdit> intrinsicsAsGlslangSpellsThem(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const std::vector<Token>& t = syntax.tokens;
    for (const auto& s : kSpellings) {
        if (!s.method && syntax.findFunction(s.d3d)) continue;
        for (size_t i = 0; i + 1 < t.size(); ++i)
            if (t[i].text == s.d3d && t[i + 1].is("(") && (i > 0 && t[i - 1].is(".")) == s.method)
                edits.push_back({t[i].offset, t[i].end, s.glslang});
    }
    return edits;
}

}  // namespace fxport::xlate
