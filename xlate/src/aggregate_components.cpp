// See aggregate_components.h.
#include "aggregate_components.h"

#include "hlsl_types.h"

namespace fxport::xlate {

namespace {
constexpr size_t kMaxComponents = 64;
}

bool aggregateComponents(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims, const std::string& access,
                         bool inStruct, std::vector<AggregateComponent>& out, int depth) {
    if (depth > 8 || out.size() > kMaxComponents) return false;
    if (!dims.empty()) {
        if (dims[0] <= 0) return false;
        std::vector<int> rest(dims.begin() + 1, dims.end());
        for (int i = 0; i < dims[0]; ++i)
            if (!aggregateComponents(syntax, type, rest, access + "[" + std::to_string(i) + "]", inStruct, out, depth + 1)) return false;
        return true;
    }
    const std::string& resolved = syntax.resolveType(type);
    if (const FxStruct* s = syntax.findStruct(resolved)) {
        for (const auto& m : s->members)
            if (!aggregateComponents(syntax, m.type, m.arrayDims, access + "." + m.name, true, out, depth + 1)) return false;
        return true;
    }
    BasicType b = describeBasicType(resolved);
    if (!b.ok) return false;
    const bool degenerate = b.isMatrix && (b.rows == 1 || b.columns == 1);
    if (degenerate && inStruct) return false;  // a matrix to glslang there, and one it cannot build
    if (b.isMatrix && !degenerate) {
        for (int r = 0; r < b.rows; ++r)
            for (int c = 0; c < b.columns; ++c) out.push_back({access + "[" + std::to_string(r) + "][" + std::to_string(c) + "]", b.scalar});
    } else if (b.rows * b.columns > 1) {  // a vector (a one-row or one-column matrix is one to glslang)
        for (int i = 0; i < b.rows * b.columns; ++i) out.push_back({access + "[" + std::to_string(i) + "]", b.scalar});
    } else {
        out.push_back({access, b.scalar});
    }
    return true;
}

}  // namespace fxport::xlate
