// Clip/cull semantics of hull and domain shaders as user semantics (tessellation_clip_semantics.h).
#include "rewrite/tessellation_clip_semantics.h"

#include <cctype>

#include "fx/text_util.h"

namespace fxport::xlate {

std::vector<TextEdit> tessellationClipSemantics(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const auto& t = syntax.tokens;
    for (size_t i = 1; i < t.size(); ++i) {
        if (!t[i].isIdent() || !t[i - 1].is(":")) continue;
        const std::string upper = toUpper(t[i].text);
        for (const auto& [d3d, user] : {std::pair<std::string, const char*>{"SV_CLIPDISTANCE", kTessellationClipSemantic},
                                        {"SV_CULLDISTANCE", kTessellationCullSemantic}}) {
            if (upper.rfind(d3d, 0) != 0) continue;
            std::string index = upper.substr(d3d.size());
            bool digits = true;
            for (char c : index) digits &= std::isdigit(static_cast<unsigned char>(c)) != 0;
            if (!digits) continue;
            edits.push_back({t[i].offset, t[i].end, user + (index.empty() ? std::string("0") : index)});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
