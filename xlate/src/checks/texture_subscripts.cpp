// `tex[coords]` reads one texel of mip 0: the coordinates are exactly as many as the texture has
// dimensions (two for a Texture2D, three for a Texture2DArray or Texture3D), and fxc refuses a
// vector of another size there (vkd3d's load-level: `t[uint3(0, 0, 0)]` on a Texture2D; the mip
// belongs to Load's coordinates, not to the subscript), where glslang drops the extra component.
// Judged where the subscript is a constructor (`uint3(...)`, whose size is evident) on a texture
// declared as a D3D10 object of known dimension.
#include <cctype>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

// The coordinates a subscript of `type` takes, 0 when not judged.
int subscriptComponents(std::string type) {
    if (type.rfind("RW", 0) == 0) type = type.substr(2);
    if (type.rfind("RasterizerOrdered", 0) == 0) type = type.substr(17);
    const size_t angle = type.find('<');
    if (angle != std::string::npos) type = type.substr(0, angle);
    if (type == "Texture1D") return 1;
    if (type == "Texture2D" || type == "Texture1DArray") return 2;
    if (type == "Texture3D" || type == "Texture2DArray") return 3;
    return 0;
}

// The size N of a vector constructor `intN`/`uintN`/`floatN`, 0 for anything else.
int constructorSize(const std::string& s) {
    for (const char* base : {"int", "uint", "float", "half"}) {
        const std::string b = base;
        if (s.size() == b.size() + 1 && s.compare(0, b.size(), b) == 0 && s.back() >= '1' && s.back() <= '4') return s.back() - '0';
    }
    return 0;
}

class TextureSubscripts : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
                if (!t_[i].isIdent() || !t_[i + 1].is("[") || (i > 0 && t_[i - 1].is("."))) continue;
                const FxTexture* texture = syntax_.findTexture(t_[i].text);
                if (!texture || texture->dx9Object) continue;
                const int want = subscriptComponents(texture->type), given = constructorSize(t_[i + 2].text);
                if (!want || !given || !t_[i + 3].is("(") || closing(i + 3) + 1 != closing(i + 1)) continue;
                if (given != want)
                    report("'" + t_[i].text + "' is a " + texture->type + ": its subscript takes " + std::to_string(want) + " coordinates, not a " +
                               t_[i + 2].text + " (fxc cannot convert the index)",
                           i + 2);
            }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findTextureSubscriptErrors(const EffectSyntax& syntax, const SourceMap& map) {
    TextureSubscripts check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
