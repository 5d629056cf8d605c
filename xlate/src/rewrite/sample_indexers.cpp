// See sample_indexers.h.
#include "rewrite/sample_indexers.h"

#include "hlsl/method_receivers.h"

namespace fxport::xlate {

namespace {

bool isMultisampleTexture(const std::string& type) {
    const std::string name = type.substr(0, type.find('<'));
    return name.rfind("Texture2DMS", 0) == 0;  // Texture2DMS, Texture2DMSArray (with or without <T, N>)
}

// The index of the ']' closing the '[' at `open`, or `end` when it does not close before it.
size_t closingBracket(const std::vector<Token>& t, size_t open, size_t end) {
    int depth = 0;
    for (size_t i = open; i < end; ++i) {
        if (t[i].is("[")) ++depth;
        if (t[i].is("]") && --depth == 0) return i;
    }
    return end;
}

}  // namespace

std::vector<TextEdit> sampleIndexersAsLoads(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin + 1; i + 2 < f.body.end; ++i) {
            if (!t[i].is("sample") || !t[i - 1].is(".") || !t[i + 1].is("[")) continue;
            const size_t sampleClose = closingBracket(t, i + 1, f.body.end);
            if (sampleClose + 1 >= f.body.end || !t[sampleClose + 1].is("[")) continue;
            const size_t texelClose = closingBracket(t, sampleClose + 1, f.body.end);
            if (texelClose >= f.body.end || t[texelClose].line != t[i].line) continue;  // lines kept
            auto receiver = methodReceiver(syntax, f, i - 1);
            if (!receiver || !isMultisampleTexture(receiver->type)) continue;
            // `.sample[S][P]` -> `.Load(P, S)`: the two index expressions swap places.
            auto between = [&](size_t open, size_t close) { return syntax.text({open + 1, close}); };
            edits.push_back({t[i].offset, t[texelClose].end,
                             "Load(" + between(sampleClose + 1, texelClose) + ", " + between(i + 1, sampleClose) + ")"});
            i = texelClose;
        }
    return edits;
}

}  // namespace fxport::xlate
