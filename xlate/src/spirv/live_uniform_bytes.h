// Which bytes of each uniform block a shader's results can depend on: a backward liveness analysis
// over the legalised SPIR-V, per scalar component. SPIRV-Cross's active ranges count a member as read
// when any of it is loaded (glslang loads a whole matrix for `m[0].x`); fxc sizes an SM 1-3
// parameter's constant registers by the last register its optimised code reads, after dead-code
// removal (vkd3d's sm1-const-allocation tests show it). These ranges are the component-exact set,
// which the D3D9 register allocation is then computed from.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace fxport::xlate {

struct LiveRange {
    int offset = 0;  // bytes from the block's start (the SPIR-V Offset/ArrayStride/MatrixStride layout)
    int size = 0;
};

// Per uniform-block variable id, the merged byte ranges whose values reach an output, a store, a
// branch or any other effect. Empty optional when the module uses a form the analysis does not
// follow (then every read must be assumed live).
std::optional<std::map<std::uint32_t, std::vector<LiveRange>>> liveUniformBytes(const std::vector<std::uint32_t>& words);

}  // namespace fxport::xlate
