// INTERNAL: an Effect's GL side: one separable program per compiled shader, one uniform buffer per
// uniform block with a CPU shadow and a dirty byte range, and the texture each texture parameter
// holds.
#pragma once

#include <climits>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "device_impl.h"
#include "fxport/graphics/effect.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

struct Effect::Impl {
    xlate::CompiledEffect compiled;
    std::string displayName;  // file name for messages: "GBuffer.fx"

    struct Block {
        GLuint buffer = 0;
        int binding = 0;
        std::vector<std::uint8_t> shadow;
        int dirtyBegin = INT_MAX;
        int dirtyEnd = 0;
    };
    std::vector<Block> blocks;
    std::vector<Texture*> textures;           // per parameter (objects only)
    std::vector<ShaderProgram> programs;      // per compiled shader
    std::unordered_map<std::string, int> parameterIndex;

    void forgetTexture(const Texture* texture) {
        for (Texture*& t : textures)
            if (t == texture) t = nullptr;
    }
    void markDirty(int block, int begin, int end) {
        Block& b = blocks[std::size_t(block)];
        b.dirtyBegin = std::min(b.dirtyBegin, begin);
        b.dirtyEnd = std::max(b.dirtyEnd, end);
    }
    void uploadDirty() {
        for (Block& b : blocks) {
            if (b.dirtyEnd <= b.dirtyBegin) continue;
            glNamedBufferSubData(b.buffer, b.dirtyBegin, b.dirtyEnd - b.dirtyBegin, b.shadow.data() + b.dirtyBegin);
            b.dirtyBegin = INT_MAX;
            b.dirtyEnd = 0;
        }
    }
    // "float4x4", "float3[8]", "texture2D", for messages.
    static std::string hlslTypeName(const xlate::Parameter& p);
    // Byte offset in its block of element `element`, row `row`, column `column` (HLSL indexing).
    static int byteOffset(const xlate::Parameter& p, int element, int row, int column) {
        int offset = p.offset + element * p.arrayStride;
        if (p.parameterClass == xlate::ParameterClass::Matrix)
            offset += p.rowMajor ? row * p.matrixStride + column * 4 : column * p.matrixStride + row * 4;
        else
            offset += column * 4;
        return offset;
    }
};

}  // namespace fxport
