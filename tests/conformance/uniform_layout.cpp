// D3D offsets of an effect's numeric parameters (see uniform_layout.h).
#include "uniform_layout.h"

#include <algorithm>

#include "fxport/xlate/compiled_effect.h"
#include "register_binding.h"

namespace conformance {

namespace {

using fxport::xlate::CompiledEffect;
using fxport::xlate::Parameter;
using fxport::xlate::ParameterClass;

bool isNumeric(const Parameter& p) {
    return p.parameterClass == ParameterClass::Scalar || p.parameterClass == ParameterClass::Vector ||
           p.parameterClass == ParameterClass::Matrix;
}

// Registers one element takes and the components used in each (a column_major matrix stores a
// column per register).
struct ElementShape {
    int registers = 1;
    int componentsPerRegister = 1;
};

ElementShape shapeOf(const Parameter& p) {
    if (p.parameterClass != ParameterClass::Matrix) return {1, p.columns};
    return p.rowMajor ? ElementShape{p.rows, p.columns} : ElementShape{p.columns, p.rows};
}

// Component offset of scalar (element e, row r, column c) relative to the parameter's start.
int scalarOffset(const Parameter& p, int e, int r, int c) {
    ElementShape s = shapeOf(p);
    int base = e * s.registers * 4;
    if (p.parameterClass != ParameterClass::Matrix) return base + c;
    return base + (p.rowMajor ? r * 4 + c : c * 4 + r);
}

std::vector<int> scalarOffsets(const Parameter& p, int start) {
    std::vector<int> out;
    for (int e = 0; e < std::max(1, p.elements); ++e)
        for (int r = 0; r < p.rows; ++r)
            for (int c = 0; c < p.columns; ++c) out.push_back(start + scalarOffset(p, e, r, c));
    return out;
}

// Components the parameter spans (the last register only as far as it is used).
int footprint(const Parameter& p) {
    ElementShape s = shapeOf(p);
    return (std::max(1, p.elements) * s.registers - 1) * 4 + s.componentsPerRegister;
}

bool startsOnRegister(const Parameter& p) {
    return p.elements > 0 || p.parameterClass == ParameterClass::Matrix || p.parameterClass == ParameterClass::Struct;
}

// Struct size under cbuffer packing (members packed from the struct's start).
int structFootprint(const Parameter& p);

int memberFootprint(const Parameter& m) {
    if (m.parameterClass != ParameterClass::Struct) return footprint(m);
    int one = structFootprint(m);
    int regs = (one + 3) / 4;
    return (std::max(1, m.elements) - 1) * regs * 4 + one;
}

int packNext(int offset, const Parameter& p, int size) {
    bool crosses = (offset % 4) + size > 4;
    if (startsOnRegister(p) || crosses) offset = (offset + 3) / 4 * 4;
    return offset;
}

int structFootprint(const Parameter& p) {
    int offset = 0;
    for (const Parameter& m : p.members) {
        int size = memberFootprint(m);
        offset = packNext(offset, m, size) + size;
    }
    return offset;
}

// An explicit placement in the source as a component offset; -1 if none. D3D9 honours
// register(cN); SM4 honours it only in $Globals (block 0) and packoffset(cN.y) in cbuffers.
int explicitOffset(const std::string& source, const Parameter& p, int model) {
    if (model < 40 || p.block == 0) {
        int reg = explicitRegister(source, p.name, 'c');
        if (reg >= 0) return reg * 4;
    }
    return model >= 40 && p.block != 0 ? explicitPackOffset(source, p.name) : -1;
}

// D3D9 registers of one struct element: each member starts a register (register-reservations-
// numeric: `struct { float2 a; float b; }` at c2 puts b at c3).
int structRegisters(const Parameter& p) {
    int n = 0;
    for (const Parameter& m : p.members) n += shapeOf(m).registers * std::max(1, m.elements);
    return n;
}

// Placements of the parameter at component `start`: itself, or for a struct each member of each
// element (SM4 packing, or a register per member at SM2-3).
std::vector<ParameterPlacement> placeAt(const CompiledEffect& effect, int index, int start, bool d3d9) {
    const Parameter& p = effect.parameters[std::size_t(index)];
    ParameterPlacement out;
    out.parameter = index;
    out.leaf = &p;
    if (p.parameterClass != ParameterClass::Struct) {
        out.scalarOffsets = scalarOffsets(p, start);
        return {out};
    }
    for (const Parameter& m : p.members)
        if (m.parameterClass == ParameterClass::Struct) {
            out.settable = false;
            out.why = "struct uniform '" + p.name + "' with a struct member (the runner sets one level of members)";
            return {out};
        }
    std::vector<ParameterPlacement> leaves;
    const int elementComponents = d3d9 ? structRegisters(p) * 4 : (structFootprint(p) + 3) / 4 * 4;
    for (int e = 0; e < std::max(1, p.elements); ++e) {
        int offset = start + e * elementComponents;
        for (std::size_t k = 0; k < p.members.size(); ++k) {
            const Parameter& m = p.members[k];
            ParameterPlacement leaf;
            leaf.parameter = index;
            leaf.leaf = &m;
            if (p.elements > 0) leaf.path.push_back({false, e});
            leaf.path.push_back({true, int(k)});
            int size = d3d9 ? shapeOf(m).registers * std::max(1, m.elements) * 4 : memberFootprint(m);
            if (!d3d9) offset = packNext(offset, m, size);
            leaf.scalarOffsets = scalarOffsets(m, offset);
            offset += size;
            leaves.push_back(std::move(leaf));
        }
    }
    return leaves;
}

void addPlacements(UniformLayout& layout, std::vector<ParameterPlacement> placements) {
    for (ParameterPlacement& p : placements) layout.placements.push_back(std::move(p));
}

// Which block vkd3d's uniforms feed at SM4+: the cbuffer at register b0 -- $Globals when it has
// numeric members, else the first user cbuffer (explicit register(bN) is not in the reflection).
int slotZeroBlock(const CompiledEffect& effect) {
    int first = -1;
    for (const Parameter& p : effect.parameters) {
        if (p.isStatic || !(isNumeric(p) || p.parameterClass == ParameterClass::Struct)) continue;
        if (p.block == 0) return 0;
        if (first < 0 || p.block < first) first = p.block;
    }
    return first < 0 ? 0 : first;
}

// Whether components [start, start + size) meet an explicitly placed parameter's.
bool overlapsReserved(const std::vector<std::pair<int, int>>& reserved, int start, int size) {
    for (const auto& [from, length] : reserved)
        if (start < from + length && from < start + size) return true;
    return false;
}

// SM4+: D3D10 cbuffer packing of the block at slot 0. Explicit placements first; fxc packs the
// other parameters in declaration order from the end of the last explicit one (register-
// reservations-numeric: `float a : register(c2); float b;` puts b at c2.y, not c0).
UniformLayout cbufferLayout(const CompiledEffect& effect, const std::string& source, int model) {
    UniformLayout layout;
    int block = slotZeroBlock(effect);
    auto inBlock = [&](const Parameter& p) {
        return !p.isStatic && p.block == block && (isNumeric(p) || p.parameterClass == ParameterClass::Struct);
    };
    auto sizeOf = [](const Parameter& p) { return p.parameterClass == ParameterClass::Struct ? memberFootprint(p) : footprint(p); };
    std::vector<std::pair<int, int>> reserved;
    for (const Parameter& p : effect.parameters) {
        int start = inBlock(p) ? explicitOffset(source, p, model) : -1;
        if (start >= 0) reserved.push_back({start, sizeOf(p)});
    }
    int offset = 0;
    for (const auto& [from, length] : reserved) offset = std::max(offset, from + length);
    for (std::size_t i = 0; i < effect.parameters.size(); ++i) {
        const Parameter& p = effect.parameters[i];
        if (!inBlock(p)) continue;
        int size = sizeOf(p);
        int start = explicitOffset(source, p, model);
        if (start < 0) {
            start = packNext(offset, p, size);
            while (overlapsReserved(reserved, start, size)) start = packNext((start / 4 + 1) * 4, p, size);
            offset = start + size;
        }
        addPlacements(layout, placeAt(effect, int(i), start, false));
    }
    return layout;
}

// Whether a shader's result depends on bytes [offset, offset + size) of the block (xlate's
// component-exact liveness, CompiledShader::uniformRangesLive).
bool rangeRead(const CompiledEffect& effect, int block, int offset, int size) {
    for (const auto& shader : effect.shaders)
        for (const auto& r : shader.uniformRangesLive)
            if (r.block == block && r.offset < offset + size && offset < r.offset + r.size) return true;
    return false;
}

// D3D9 reserves a parameter's registers only up to the last one the optimised shader reads (sm1-
// const-allocation: a float4x2 read only in column 0 takes one register). Register k of the
// parameter is found in fxport's own layout (the reflection's offset, array and matrix strides),
// where each D3D9 register is one 16-byte slot too.
int usedRegisters(const CompiledEffect& effect, const Parameter& p) {
    if (p.offset < 0) return 0;
    ElementShape s = shapeOf(p);
    int used = 0;
    for (int k = 0; k < std::max(1, p.elements) * s.registers; ++k) {
        int e = k / s.registers, j = k % s.registers;
        int start = p.offset + e * p.arrayStride + (p.parameterClass == ParameterClass::Matrix ? j * p.matrixStride : 0);
        if (rangeRead(effect, p.block, start, 16)) used = k + 1;
    }
    return used;
}

// The same for a struct, whose D3D9 registers are its members' one after another; member k's
// register j is found in fxport's layout from the member's reflected offset and strides.
int usedStructRegisters(const CompiledEffect& effect, const Parameter& p) {
    if (p.offset < 0) return 0;
    int used = 0, k = 0;
    for (int e = 0; e < std::max(1, p.elements); ++e)
        for (const Parameter& m : p.members) {
            ElementShape s = shapeOf(m);
            for (int j = 0; j < std::max(1, m.elements); ++j)
                for (int r = 0; r < s.registers; ++r, ++k) {
                    int start = m.offset + e * p.arrayStride + j * m.arrayStride + (m.parameterClass == ParameterClass::Matrix ? r * m.matrixStride : 0);
                    if (m.offset >= 0 && rangeRead(effect, p.block, start, s.componentsPerRegister * 4)) used = k + 1;
                }
        }
    return used;
}

// D3D9: parameters with explicit register(cN) keep them; the others the shaders read take whole
// float registers, in decreasing order of registers used, ties in declaration order (as fxc does;
// sm1-const-allocation.shader_test documents it).
UniformLayout registerLayout(const CompiledEffect& effect, const std::string& source, int model) {
    UniformLayout layout;
    std::vector<bool> taken;
    auto reserve = [&](int reg, int count) {
        if (int(taken.size()) < reg + count) taken.resize(std::size_t(reg + count), false);
        for (int r = reg; r < reg + count; ++r) taken[std::size_t(r)] = true;
    };
    auto isFree = [&](int reg, int count) {
        for (int r = reg; r < reg + count; ++r)
            if (r < int(taken.size()) && taken[std::size_t(r)]) return false;
        return true;
    };
    std::vector<std::pair<int, int>> pending;  // (registers used, parameter)
    for (std::size_t i = 0; i < effect.parameters.size(); ++i) {
        const Parameter& p = effect.parameters[i];
        if (p.isStatic || !(isNumeric(p) || p.parameterClass == ParameterClass::Struct)) continue;
        int start = explicitOffset(source, p, model);
        int used = p.parameterClass == ParameterClass::Struct ? usedStructRegisters(effect, p) : usedRegisters(effect, p);
        if (start >= 0) {
            // A register reservation takes the whole variable, read or not (register-reservations-
            // numeric: `float4 a[3]; float4 b[2] : register(c1);` puts a at c3).
            int whole = std::max(1, p.elements) * (p.parameterClass == ParameterClass::Struct ? structRegisters(p) : shapeOf(p).registers);
            reserve(start / 4, std::max(1, whole));
            addPlacements(layout, placeAt(effect, int(i), start, true));
        } else if (used > 0) {
            pending.push_back({used, int(i)});
        }
    }
    std::stable_sort(pending.begin(), pending.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // fxc sizes each by the registers its optimised code reads; xlate's liveness follows values
    // through the translated code, where fxc's optimiser can go further (a local array indexed at
    // run time read as a relative-addressed constant). Where that can move a parameter, say so.
    int multi = 0;
    for (const auto& [used, i] : pending) multi += used > 1 ? 1 : 0;
    if (multi > 0 && pending.size() > 1)
        layout.guess = "D3D9 registers of matrices/arrays sized by xlate's liveness analysis, fxc's optimiser may read fewer or more";
    for (const auto& [used, i] : pending) {
        int reg = 0;
        while (!isFree(reg, used)) ++reg;
        reserve(reg, used);
        addPlacements(layout, placeAt(effect, i, reg * 4, true));
    }
    return layout;
}

}  // namespace

std::string uncoveredUniformRead(const CompiledEffect& effect) {
    for (const auto& shader : effect.shaders) {
        for (const auto& r : shader.uniformRangesRead) {
            for (int byte = r.offset; byte < r.offset + r.size; byte += 4) {
                bool covered = false;
                for (const Parameter& p : effect.parameters)
                    covered = covered || (p.offset >= 0 && p.block == r.block && byte >= p.offset && byte < p.offset + p.size);
                if (!covered) return "a global the reflection does not list (a struct or unnamed one): no parameter to set";
            }
        }
    }
    return "";
}

UniformLayout computeUniformLayout(const CompiledEffect& effect, const std::string& source, int model) {
    return model >= 40 ? cbufferLayout(effect, source, model) : registerLayout(effect, source, model);
}

}  // namespace conformance
