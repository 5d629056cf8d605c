// See aggregate_components.h.
#include "hlsl/aggregate_components.h"

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

constexpr size_t kMaxComponents = 64;

bool components(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims, const std::string& access, bool inStruct,
                std::vector<AggregateComponent>& out, bool withObjects, int depth) {
    if (depth > 8 || out.size() > kMaxComponents) return false;
    if (!dims.empty()) {
        if (dims[0] <= 0) return false;
        std::vector<int> rest(dims.begin() + 1, dims.end());
        for (int i = 0; i < dims[0]; ++i)
            if (!components(syntax, type, rest, access + "[" + std::to_string(i) + "]", inStruct, out, withObjects, depth + 1)) return false;
        return true;
    }
    const std::string& resolved = syntax.resolveType(type);
    if (const FxStruct* s = syntax.findStruct(resolved)) {
        for (const auto& m : s->members)
            if (!components(syntax, m.type, m.arrayDims, access + "." + m.name, true, out, withObjects, depth + 1)) return false;
        return true;
    }
    BasicType b = describeBasicType(resolved);
    if (!b.ok && withObjects && isResourceType(resolved)) {
        out.push_back({access, resolved, true});
        return true;
    }
    if (!b.ok) return false;
    const bool degenerate = b.isMatrix && (b.rows == 1 || b.columns == 1);
    if (degenerate && inStruct) return false;  // a matrix to glslang there, and one it cannot build
    if (b.isMatrix && !degenerate) {
        for (int r = 0; r < b.rows; ++r)
            for (int c = 0; c < b.columns; ++c) out.push_back({access + "[" + std::to_string(r) + "][" + std::to_string(c) + "]", b.scalar, false});
    } else if (b.rows * b.columns > 1) {  // a vector (a one-row or one-column matrix is one to glslang)
        for (int i = 0; i < b.rows * b.columns; ++i) out.push_back({access + "[" + std::to_string(i) + "]", b.scalar, false});
    } else {
        out.push_back({access, b.scalar, false});
    }
    return true;
}

}  // namespace

bool aggregateComponents(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims, const std::string& access,
                         bool inStruct, std::vector<AggregateComponent>& out, bool withObjects) {
    return components(syntax, type, dims, access, inStruct, out, withObjects, 0);
}

bool isResourceType(const std::string& type) {
    for (const char* prefix : {"Texture", "texture", "sampler", "Sampler", "Buffer", "RWBuffer", "RWTexture", "StructuredBuffer",
                               "RWStructuredBuffer", "ByteAddressBuffer", "RWByteAddressBuffer", "AppendStructuredBuffer",
                               "ConsumeStructuredBuffer"})
        if (type.rfind(prefix, 0) == 0) return true;
    return false;
}

char resourceRegisterClass(const std::string& type) {
    if (!isResourceType(type)) return 0;
    if (type.rfind("sampler", 0) == 0 || type.rfind("Sampler", 0) == 0) return 's';
    if (type.rfind("RW", 0) == 0 || type.rfind("Append", 0) == 0 || type.rfind("Consume", 0) == 0) return 'u';
    return 't';
}

}  // namespace fxport::xlate
