// See unused_uavs.h.
#include "rewrite/unused_uavs.h"

#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// `RWTexture2D<float2x2>` / `RWBuffer<struct s>` / `RWBuffer<double2>`: a UAV whose element glslang cannot take.
bool uavOfMatrixOrStruct(const EffectSyntax& syntax, const std::string& type) {
    if (type.rfind("RW", 0) != 0 && type.rfind("RasterizerOrdered", 0) != 0) return false;
    size_t open = type.find('<'), close = type.rfind('>');
    if (open == std::string::npos || close == std::string::npos || close < open) return false;
    std::string element = type.substr(open + 1, close - open - 1);
    while (!element.empty() && element.front() == ' ') element.erase(element.begin());
    while (!element.empty() && element.back() == ' ') element.pop_back();
    if (element.rfind("struct ", 0) == 0) element = element.substr(7);
    const std::string& resolved = syntax.resolveType(element);
    BasicType b = describeBasicType(resolved);
    if (b.ok && b.scalar == "double") return b.rows * b.columns <= 2;  // two 32-bit words each: double2 fits, double3 not
    if (!syntax.findStruct(resolved) && !(b.ok && b.isMatrix && b.rows > 1 && b.columns > 1)) return false;
    // fxc takes up to four numeric components there; more, or an object, is its error (and glslang's).
    std::vector<AggregateComponent> parts;
    return aggregateComponents(syntax, resolved, {}, "", false, parts) && parts.size() <= 4;
}

bool usedByAFunction(const EffectSyntax& syntax, const std::string& name) {
    const auto& t = syntax.tokens;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i < f.body.end; ++i)
            if (t[i].isIdent() && t[i].text == name && !(i > 0 && t[i - 1].is("."))) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> unusedUavsDropped(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const FxGlobal& g : syntax.globals) {
        if (!g.cbuffer.empty() || !uavOfMatrixOrStruct(syntax, g.type) || usedByAFunction(syntax, g.name)) continue;
        size_t first = g.token, last = g.token;
        while (first > 0 && !t[first - 1].is(";") && !t[first - 1].is("}") && !t[first - 1].is("{")) --first;
        while (last + 1 < t.size() && !t[last].is(";") && t[last].kind != Token::Kind::End) ++last;
        if (!t[last].is(";")) continue;
        edits.push_back({t[first].offset, t[last].end, {}});
    }
    return edits;
}

}  // namespace fxport::xlate
