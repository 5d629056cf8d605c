// Texture units of texture objects, as fxc hands out t registers (texture_registers.h).
#include "rewrite/texture_registers.h"

#include <algorithm>
#include <set>

namespace fxport::xlate {

// The registers an array takes: the product of its sizes (`Texture2D t[2][2]`: 4), read from the
// tokens after its name; a size that is not a literal counts as 1.
int textureElements(const EffectSyntax& syntax, const FxTexture& t) {
    int elements = 1;
    const auto& tokens = syntax.tokens;
    for (size_t i = t.token + 1; i + 2 < tokens.size() && tokens[i].is("[") && tokens[i + 2].is("]"); i += 3) {
        const std::string& n = tokens[i + 1].text;
        if (!n.empty() && n.find_first_not_of("0123456789") == std::string::npos && n.size() < 6) elements *= std::max(1, std::stoi(n));
    }
    return elements;
}

std::map<std::string, int> textureRegisters(const EffectSyntax& syntax) {
    std::map<std::string, int> units;
    std::set<int> taken;
    for (const auto& t : syntax.textures)
        if (!t.dx9Object && t.explicitUnit >= 0) {
            const int elements = textureElements(syntax, t);
            units[t.name] = t.explicitUnit;
            for (int k = 0; k < elements; ++k) taken.insert(t.explicitUnit + k);
        }
    for (const auto& t : syntax.textures) {
        if (t.dx9Object || units.count(t.name)) continue;
        const int elements = textureElements(syntax, t);
        int u = 0;
        auto runIsFree = [&](int first) {
            for (int k = 0; k < elements; ++k)
                if (taken.count(first + k)) return false;
            return true;
        };
        while (!runIsFree(u)) ++u;
        units[t.name] = u;
        for (int k = 0; k < elements; ++k) taken.insert(u + k);
    }
    return units;
}

}  // namespace fxport::xlate
