#include "glsl/spirv_to_glsl.h"

#include "glsl/arrayed_clip_inputs.h"
#include "glsl/pre_raster_builtins.h"

#include "spirv/domain_layer_outputs.h"
#include "spirv/fetch_offsets.h"
#include "spirv/out_of_range_accesses.h"
#include "spirv/gather_offsets.h"
#include "spirv/integer_matrices.h"
#include "spirv/live_uniform_bytes.h"
#include "spirv/write_only_images.h"

#include <spirv_cross/spirv_glsl.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include "spirv/cbuffer_packing.h"
#include "entry/entry_wrapper.h"
#include "fx/text_util.h"

namespace fxport::xlate {

int VaryingLocations::locationOf(const std::string& semanticIn) {
    auto [base, index] = splitSemantic(semanticIn);
    const std::string semantic = base + std::to_string(index);  // "POSITION" and "POSITION0" are one
    // The fixed table: identical in every effect, so shaders of different effects link.
    if (base == "TEXCOORD" && index < 16) return index;
    if (base == "COLOR" && index < 4) return 16 + index;
    if (base == "NORMAL" && index < 2) return 20 + index;
    if (base == "TANGENT" && index == 0) return 22;
    if (base == "BINORMAL" && index == 0) return 23;
    if (base == "FOG") return 24;
    if (base == "POSITION" && index >= 1 && index <= 2) return 24 + index;
    if (base == "BLENDWEIGHT" && index == 0) return 27;
    if (base == "BLENDINDICES" && index == 0) return 28;
    auto it = custom_.find(semantic);
    if (it != custom_.end()) return it->second;
    // Other names: 29..31 first, then the high TEXCOORD slots (15, 14 ...), which effects rarely use.
    // Locations must stay below 32, the smallest GL_MAX_VARYING_VECTORS we target.
    std::set<int> used;
    for (const auto& [k, v] : custom_) used.insert(v);
    int loc = 29;
    while (loc < 32 && used.count(loc)) ++loc;
    if (loc == 32) {
        loc = 15;
        while (loc > 0 && used.count(loc)) --loc;
    }
    custom_[semantic] = loc;
    return loc;
}

namespace {

// CompilerGLSL with access to its own test of whether GLSL can declare a block's layout.
class GlslCompiler : public spirv_cross::CompilerGLSL {
public:
    using CompilerGLSL::CompilerGLSL;
    bool glslCanDeclare(const spirv_cross::SPIRType& block) {
        return buffer_is_packing_standard(block, spirv_cross::BufferPackingStd140) ||
               buffer_is_packing_standard(block, spirv_cross::BufferPackingStd140EnhancedLayout);
    }
    // SV_VertexID as D3D counts it (pre_raster_builtins.h).
    std::string builtin_to_glsl(spv::BuiltIn builtin, spv::StorageClass storage) override {
        if (builtin == spv::BuiltInVertexIndex && get_execution_model() == spv::ExecutionModelVertex) return vertexIdExpression();
        return CompilerGLSL::builtin_to_glsl(builtin, storage);
    }
};

bool readsVertexId(const spirv_cross::ShaderResources& res, ShaderStage stage) {
    if (stage == ShaderStage::Vertex)
        for (const auto& b : res.builtin_inputs)
            if (b.builtin == spv::BuiltInVertexIndex) return true;
    return false;
}

// The header lines writing gl_Layer and gl_ViewportIndex before the geometry stage needs
// (pre_raster_builtins.h); whether there are any.
bool declareLayerViewportOutputs(GlslCompiler& compiler, const spirv_cross::ShaderResources& res, ShaderStage stage) {
    if (stage != ShaderStage::Vertex && stage != ShaderStage::Domain) return false;
    bool layer = false, viewport = false;
    for (const auto& b : res.builtin_outputs) {
        layer |= b.builtin == spv::BuiltInLayer;
        viewport |= b.builtin == spv::BuiltInViewportIndex;
    }
    for (const std::string& line : layerViewportExtensionLines(stage, layer, viewport)) compiler.add_header_line(line);
    return layer || viewport;
}

// GL texture units a shader's samplers take (0..31, effect_validation's kMaxUnit).
constexpr int kGlTextureUnits = 32;
constexpr const char* kSampleMaskInName = "fxport_sampleMaskIn";

// The wrapper's stand-in for SV_Coverage (kSampleMaskInSemantic) becomes GL's gl_SampleMaskIn[0]:
// SPIRV-Cross declares the input on one line, which turns into a macro of the same name.
std::string sampleMaskInFromGl(std::string glsl) {
    static const std::regex declaration(R"(layout\(location = \d+\) flat in uint fxport_sampleMaskIn;)");
    return std::regex_replace(glsl, declaration, "#define fxport_sampleMaskIn uint(gl_SampleMaskIn[0])");
}

uint32_t roundUp(uint32_t v, uint32_t to) { return (v + to - 1) / to * to; }

// The k of a name ending in "[k]" (glslang's name for element k of a split array); -1 otherwise.
int splitArrayElement(const std::string& name) {
    if (name.size() < 3 || name.back() != ']') return -1;
    const size_t open = name.rfind('[');
    if (open == std::string::npos || open + 2 > name.size() - 1) return -1;
    int k = 0;
    for (size_t i = open + 1; i + 1 < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9' || k > 1000) return -1;
        k = k * 10 + (name[i] - '0');
    }
    return k;
}

// The stride between the innermost elements of member i, an array: D3D reflects an array of
// arrays as one (float a[2][3]: 6 elements), and std140 lays the inner arrays one after another
// (each inner stride is whole registers), so the outer stride is the inner one times the count.
int innermostArrayStride(GlslCompiler& c, const spirv_cross::SPIRType& type, uint32_t i) {
    const auto& mt = c.get_type(type.member_types[i]);
    std::uint32_t stride = c.type_struct_member_array_stride(type, i);
    for (size_t d = 0; d + 1 < mt.array.size(); ++d)  // SPIRV-Cross keeps the outermost size last
        if (mt.array_size_literal[d] && mt.array[d] > 0) stride /= mt.array[d];
    return static_cast<int>(stride);
}

// Re-lays out struct `structId` (a uniform block or a struct inside one) with std140 rules and
// returns its std140 size. glslang packs a user cbuffer the HLSL way (a vector may start anywhere
// that keeps it inside one 16-byte register; a member may use the tail of an array's last
// register), which GLSL cannot always declare; std140 is what glslang uses for $Global. Array and
// matrix strides are already 16-byte multiples in HLSL, so only offsets (and the strides of
// arrays of re-laid-out structs) change.
// GLSL requires each member's offset to be at least the previous one's; packoffset may place
// members in any order (`float3 L : packoffset(c5); float A : packoffset(c4.w);`).
bool offsetsIncrease(GlslCompiler& c, const spirv_cross::SPIRType& type) {
    for (uint32_t i = 1; i < type.member_types.size(); ++i)
        if (c.type_struct_member_offset(type, i) < c.type_struct_member_offset(type, i - 1)) return false;
    return true;
}

uint32_t relayoutStd140(GlslCompiler& c, uint32_t structId) {
    const spirv_cross::SPIRType& type = c.get_type(structId);
    uint32_t offset = 0;
    for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        uint32_t memberTypeId = type.member_types[i];
        const spirv_cross::SPIRType& mt = c.get_type(memberTypeId);
        uint32_t align = 16, size = 0;
        if (!mt.array.empty()) {
            uint32_t stride = c.type_struct_member_array_stride(type, i);
            if (mt.basetype == spirv_cross::SPIRType::Struct) {
                uint32_t elementSize = roundUp(relayoutStd140(c, mt.self), 16);
                if (elementSize > stride) {
                    stride = elementSize;
                    c.set_decoration(memberTypeId, spv::DecorationArrayStride, stride);
                }
            }
            uint32_t count = 1;
            for (uint32_t d = 0; d < mt.array.size(); ++d) count *= mt.array_size_literal[d] ? mt.array[d] : c.get_constant(mt.array[d]).scalar();
            size = std::max(stride, 16u) * count;
        } else if (mt.basetype == spirv_cross::SPIRType::Struct) {
            size = roundUp(relayoutStd140(c, mt.self), 16);
        } else if (mt.columns > 1) {
            uint32_t stride = c.type_struct_member_matrix_stride(type, i);
            bool rowMajor = c.has_member_decoration(structId, i, spv::DecorationRowMajor);
            size = std::max(stride, 16u) * (rowMajor ? mt.vecsize : mt.columns);
        } else {
            uint32_t component = std::max(1u, mt.width / 8);
            size = component * mt.vecsize;
            align = mt.vecsize == 1 ? component : mt.vecsize == 2 ? 2 * component : 4 * component;
        }
        offset = roundUp(offset, align);
        c.set_member_decoration(structId, i, spv::DecorationOffset, offset);
        offset += size;
    }
    return offset;
}

TextureKind kindOfImage(const spirv_cross::SPIRType& t) {
    switch (t.image.dim) {
    case spv::Dim1D: return TextureKind::Texture1D;
    case spv::Dim3D: return TextureKind::Texture3D;
    case spv::DimCube: return TextureKind::TextureCube;
    default: return TextureKind::Texture2D;
    }
}

const char* imageFormatName(spv::ImageFormat f) {
    switch (f) {
    case spv::ImageFormatRgba32f: return "rgba32f";
    case spv::ImageFormatRgba16f: return "rgba16f";
    case spv::ImageFormatR32f: return "r32f";
    case spv::ImageFormatRgba8: return "rgba8";
    case spv::ImageFormatRg32f: return "rg32f";
    case spv::ImageFormatRg16f: return "rg16f";
    case spv::ImageFormatR16f: return "r16f";
    case spv::ImageFormatRgba32i: return "rgba32i";
    case spv::ImageFormatRg32i: return "rg32i";
    case spv::ImageFormatR32i: return "r32i";
    case spv::ImageFormatRgba32ui: return "rgba32ui";
    case spv::ImageFormatRg32ui: return "rg32ui";
    case spv::ImageFormatR32ui: return "r32ui";
    default: return "";
    }
}

// UAVs and buffer SRVs: D3D11 registers (register(uN)/(tN), else the next free one of the class
// in declaration order, as fxc assigns them) -> GL bindings. SSBOs and image units are their own
// binding spaces in GL; UAV buffers and UAV images both sit at N (one uN names one of them), SRV
// buffers at kSrvBufferBindingBase + N so they do not meet the UAVs.
void bindStorage(GlslCompiler& compiler, const spirv_cross::ShaderResources& res, const EffectSyntax& syntax,
                 const std::map<std::string, int>& textureUnits, int firstFreeUav, std::vector<StorageBinding>& out) {
    // glslang gives every resource a Binding (0 where no register was written): the register, if
    // any, comes from the declaration.
    auto declaredRegister = [&](const std::string& name, char registerClass) {
        for (const auto& g : syntax.globals)
            if (g.name == name && g.registerClass == registerClass && g.registerIndex >= 0) return g.registerIndex;
        return -1;
    };
    struct Found {
        spirv_cross::ID id;
        StorageBinding b;
        bool explicitSlot = false;
        int count = 1;  // an array (`RWTexture2D<float4> u[2] : register(u2)`) takes consecutive registers
    };
    auto elements = [&](spirv_cross::TypeID typeId) {
        const spirv_cross::SPIRType& type = compiler.get_type(typeId);
        int n = 1;
        for (size_t d = 0; d < type.array.size(); ++d)
            n *= static_cast<int>(type.array_size_literal[d] ? type.array[d] : compiler.get_constant(type.array[d]).scalar());
        return std::max(n, 1);
    };
    std::vector<Found> found;
    for (const auto& r : res.storage_buffers) {
        Found f{r.id, {}, false};
        f.b.kind = StorageKind::Buffer;
        f.b.name = compiler.get_name(r.id);
        if (f.b.name.empty()) f.b.name = compiler.get_name(r.base_type_id);
        const spirv_cross::SPIRType& type = compiler.get_type(r.base_type_id);
        bool readOnly = compiler.get_buffer_block_flags(r.id).get(spv::DecorationNonWritable);
        f.b.registerClass = readOnly ? 't' : 'u';
        f.b.writes = !readOnly;
        if (!type.member_types.empty() && !compiler.get_type(type.member_types[0]).array.empty())
            f.b.stride = static_cast<int>(compiler.type_struct_member_array_stride(type, 0));
        f.b.slot = declaredRegister(f.b.name, f.b.registerClass);
        f.explicitSlot = f.b.slot >= 0;
        f.count = elements(r.type_id);
        found.push_back(f);
    }
    for (const auto& r : res.storage_images) {
        Found f{r.id, {}, false};
        f.b.name = compiler.get_name(r.id);
        const spirv_cross::SPIRType& type = compiler.get_type(r.type_id);
        f.b.kind = type.image.dim == spv::DimBuffer ? StorageKind::ImageBuffer : StorageKind::Image;  // RWBuffer<T> / RWTexture*
        f.b.dimension = kindOfImage(type);
        f.b.format = imageFormatName(type.image.format);
        f.b.writes = !compiler.has_decoration(r.id, spv::DecorationNonWritable);
        f.b.slot = declaredRegister(f.b.name, 'u');
        f.explicitSlot = f.b.slot >= 0;
        f.count = elements(r.type_id);
        found.push_back(f);
    }
    // Buffer<T>: an image without a sampler, read by texelFetch (Load / operator[]).
    for (const auto& r : res.separate_images) {
        const spirv_cross::SPIRType& type = compiler.get_type(r.type_id);
        if (type.image.dim != spv::DimBuffer) continue;
        Found f{r.id, {}, false};
        f.b.kind = StorageKind::TexelBuffer;
        f.b.name = compiler.get_name(r.id);
        f.b.registerClass = 't';
        // A texture object to the effect parser: its t# is the one fxc gives it among the textures.
        auto unit = textureUnits.find(f.b.name);
        f.b.slot = unit != textureUnits.end() ? unit->second : -1;
        f.explicitSlot = f.b.slot >= 0;
        found.push_back(f);
    }
    // fxc hands out the free registers in declaration order.
    auto declaredAt = [&](const std::string& name) {
        for (size_t i = 0; i < syntax.globals.size(); ++i)
            if (syntax.globals[i].name == name) return i;
        return syntax.globals.size();
    };
    std::stable_sort(found.begin(), found.end(), [&](const Found& a, const Found& b) { return declaredAt(a.b.name) < declaredAt(b.b.name); });
    std::set<std::pair<char, int>> taken;
    for (const Found& f : found)
        if (f.explicitSlot)
            for (int k = 0; k < f.count; ++k) taken.insert({f.b.registerClass, f.b.slot + k});
    for (Found& f : found) {
        if (!f.explicitSlot) {
            int n = f.b.registerClass == 'u' ? firstFreeUav : 0;
            auto freeFrom = [&](int at) {
                for (int k = 0; k < f.count; ++k)
                    if (taken.count({f.b.registerClass, at + k})) return false;
                return true;
            };
            while (!freeFrom(n)) ++n;
            f.b.slot = n;
            for (int k = 0; k < f.count; ++k) taken.insert({f.b.registerClass, n + k});
        }
        f.b.binding = f.b.kind == StorageKind::TexelBuffer ? kTexelBufferUnitBase + f.b.slot
                      : f.b.registerClass == 't'         ? kSrvBufferBindingBase + f.b.slot
                                                         : f.b.slot;
        compiler.unset_decoration(f.id, spv::DecorationDescriptorSet);
        compiler.set_decoration(f.id, spv::DecorationBinding, static_cast<uint32_t>(f.b.binding));
        // GL gives element k of an array binding + k; each is listed as a binding of its own, fed
        // from register slot + k as D3D binds the array's elements.
        for (int k = 0; k < f.count; ++k) {
            StorageBinding element = f.b;
            if (f.count > 1) element.name += "[" + std::to_string(k) + "]";
            element.slot += k;
            element.binding += k;
            out.push_back(element);
        }
    }
}

// The hull shader's partitioning and output topology as the domain shader's execution modes (GL's
// tessellation evaluation layout). pow2 has no GL spacing: equal spacing, the same for factors
// that are powers of two.
void declareHullModes(GlslCompiler& compiler, const Tessellation& hull) {
    for (spv::ExecutionMode m : {spv::ExecutionModeSpacingEqual, spv::ExecutionModeSpacingFractionalEven, spv::ExecutionModeSpacingFractionalOdd,
                                 spv::ExecutionModeVertexOrderCw, spv::ExecutionModeVertexOrderCcw, spv::ExecutionModePointMode})
        compiler.unset_execution_mode(m);
    if (hull.partitioning == "fractional_even") compiler.set_execution_mode(spv::ExecutionModeSpacingFractionalEven);
    else if (hull.partitioning == "fractional_odd") compiler.set_execution_mode(spv::ExecutionModeSpacingFractionalOdd);
    else if (!hull.partitioning.empty()) compiler.set_execution_mode(spv::ExecutionModeSpacingEqual);
    if (hull.outputTopology == "triangle_cw") compiler.set_execution_mode(spv::ExecutionModeVertexOrderCw);
    else if (hull.outputTopology == "triangle_ccw") compiler.set_execution_mode(spv::ExecutionModeVertexOrderCcw);
    else if (hull.outputTopology == "point") compiler.set_execution_mode(spv::ExecutionModePointMode);
}

// A cbuffer named like a GLSL keyword (`cbuffer buffer`, `cbuffer shared`) cannot name a GLSL
// block, and SPIRV-Cross writes block names as they are: such a block is declared under another
// name (bindings, not names, connect it).
bool isGlslKeyword(const std::string& name) {
    static const std::set<std::string> kKeywords = {
        "active", "asm", "atomic_uint", "attribute", "buffer", "cast", "centroid", "class", "coherent", "common", "const",
        "enum", "extern", "external", "filter", "fixed", "flat", "goto", "half", "highp", "image1D", "image2D", "image3D",
        "input", "inline", "interface", "invariant", "layout", "long", "lowp", "mediump", "namespace", "noinline",
        "noperspective", "output", "partition", "patch", "precise", "precision", "public", "readonly", "resource",
        "restrict", "sample", "shared", "short", "sizeof", "smooth", "static", "subroutine", "superp", "template", "this",
        "typedef", "union", "unsigned", "using", "varying", "volatile", "writeonly", "main"};
    return kKeywords.count(name) > 0 || name.rfind("gl_", 0) == 0;
}

// The block's live bytes (live_uniform_bytes.h); all it reads where the analysis gave up.
void addLiveRanges(const std::optional<std::map<std::uint32_t, std::vector<LiveRange>>>& live, std::uint32_t variable, int block,
                   GlslShader& out) {
    if (!live) {
        for (const UniformRange& r : out.rangesRead)
            if (r.block == block) out.rangesLive.push_back(r);
        return;
    }
    if (auto it = live->find(variable); it != live->end())
        for (const LiveRange& r : it->second) out.rangesLive.push_back({r.offset, r.size, block});
}

// What stream output may capture (stream_output.h): each user-semantic output by the name
// SPIRV-Cross gave it in the GLSL just made, and gl_Position; for a geometry shader, the vertices
// of its output primitives.
template <typename SemanticOf>
void recordOutputs(spirv_cross::CompilerGLSL& compiler, const spirv_cross::ShaderResources& res, const SemanticOf& semanticOf, GlslShader& out) {
    for (const auto& r : res.stage_outputs) {
        std::string sem = semanticOf(r.id);
        const auto& t = compiler.get_type(r.type_id);
        if (sem.empty() || t.columns > 1 || !t.array.empty()) continue;  // matrices and arrays: several registers, not captured
        auto [base, index] = splitSemantic(sem);
        out.outputs.push_back({base + std::to_string(index), compiler.get_name(r.id), static_cast<int>(t.vecsize)});
    }
    for (const auto& b : res.builtin_outputs)
        if (b.builtin == spv::BuiltInPosition) out.outputs.push_back({"SV_POSITION0", "gl_Position", 4});
    const auto& modes = compiler.get_execution_mode_bitset();
    if (modes.get(spv::ExecutionModeOutputPoints)) out.outputPrimitiveVertices = 1;
    if (modes.get(spv::ExecutionModeOutputLineStrip)) out.outputPrimitiveVertices = 2;
    if (modes.get(spv::ExecutionModeOutputTriangleStrip)) out.outputPrimitiveVertices = 3;
}

}  // namespace

GlslShader spirvToGlsl(std::vector<std::uint32_t> spirv, ShaderStage stage, const RewrittenEffect& effect,
                       VaryingLocations& varyings, const Tessellation* hull) {
    GlslShader out;
    try {
        // The SPIR-V passes before SPIRV-Cross, on one parsed module (parsed_spirv.h).
        std::vector<PackedBlock> packed;
        if (ParsedSpirv module; module.parse(spirv)) {
            packed = packConstantBuffers(module, *effect.syntax);
            for (PackedBlock& b : packed)
                if (!b.glslDeclarable && module.reparse()) flattenConstantBuffer(module, b);
            if (module.reparse())
                runSpirvPasses(module, {integerMatricesAsArrays, fetchOffsetsIntoCoordinates, outOfRangeReadsReadZero, outOfRangeBufferWritesDropped, gatherOffsetsAsFourGathers, domainLayerOutputs,
                                        writeOnlyImagesWithoutFormat});
            spirv = module.assemble();
        }
        const auto live = liveUniformBytes(spirv);
        GlslCompiler compiler(std::move(spirv));
        compiler.build_dummy_sampler_for_combined_images();
        compiler.build_combined_image_samplers();
        spirv_cross::ShaderResources res = compiler.get_shader_resources();
        spirv_cross::CompilerGLSL::Options options = compiler.get_common_options();
        options.version = 450;
        options.es = false;
        options.separate_shader_objects = true;  // program pipelines: any VS with any PS
        options.vertex.fixup_clipspace = false;  // D3D's z in [0, w] is kept: the runtime uses glClipControl
        options.vertex.flip_vert_y = false;      // and an upper-left origin, so no flip either
        // D3D's SV_InstanceID counts from 0 whatever StartInstanceLocation is, as GL's gl_InstanceID
        // does; Vulkan's InstanceIndex (glslang's mapping) adds the base instance, which SPIRV-Cross
        // would add back through gl_BaseInstanceARB.
        options.vertex.support_nonzero_base_instance = false;
        // A vertex or domain shader writing gl_Layer or gl_ViewportIndex: see perVertexForLayerOutputs.
        const bool layerOutputs = declareLayerViewportOutputs(compiler, res, stage);
        compiler.set_common_options(options);

        // ---- uniform blocks
        for (const auto& ubo : res.uniform_buffers) {
            std::string blockName = compiler.get_name(ubo.base_type_id);
            compiler.unset_decoration(ubo.id, spv::DecorationDescriptorSet);
            UniformBlockLayout block;
            block.name = blockName;
            if (isGlslKeyword(blockName)) compiler.set_name(ubo.base_type_id, "fxport_cbuffer_" + blockName);
            if (blockName != "$Global") {
                // User cbuffers: binding 2 + their declaration order in the effect, the same in
                // every stage whichever cbuffers a stage happens to use.
                const auto& names = effect.syntax->cbuffers;
                auto it = std::find(names.begin(), names.end(), blockName);
                block.index = 1 + static_cast<int>(it - names.begin());  // one past the end: unknown, still distinct
            }
            compiler.set_decoration(ubo.id, spv::DecorationBinding, block.index == 0 ? 0u : static_cast<uint32_t>(1 + block.index));
            const PackedBlock* d3d = nullptr;
            for (const PackedBlock& b : packed)
                if (b.variable == ubo.id) d3d = &b;
            if (d3d && d3d->flattened) {
                block.size = d3d->size;
                block.members = d3d->members;
                block.d3dPacking = true;
                for (const UniformRange& r : d3d->rangesRead) out.rangesRead.push_back({r.offset, r.size, block.index});
                addLiveRanges(live, ubo.id, block.index, out);
                out.membersRead.insert(out.membersRead.end(), d3d->membersRead.begin(), d3d->membersRead.end());
                out.blocks.push_back(std::move(block));
                continue;
            }
            const spirv_cross::SPIRType& type = compiler.get_type(ubo.base_type_id);
            bool relaid = !compiler.glslCanDeclare(type) || !offsetsIncrease(compiler, type);
            if (relaid) relayoutStd140(compiler, ubo.base_type_id);
            block.d3dPacking = d3d && !relaid;
            // std140 pads a block to a 16-byte multiple (GL_BUFFER_DATA_SIZE counts the padding,
            // and a bound buffer must be at least that big); D3D sizes cbuffers the same way.
            block.size = static_cast<int>(roundUp(static_cast<uint32_t>(compiler.get_declared_struct_size(type)), 16));
            for (uint32_t i = 0; i < type.member_types.size(); ++i) {
                UniformMember m;
                m.name = compiler.get_member_name(ubo.base_type_id, i);
                m.offset = static_cast<int>(compiler.type_struct_member_offset(type, i));
                m.size = static_cast<int>(compiler.get_declared_struct_member_size(type, i));
                if (d3d && !relaid && i < d3d->members.size()) {
                    m.size = d3d->members[i].size;  // D3D's, without std140's tail
                    m.members = d3d->members[i].members;
                }
                const auto& mt = compiler.get_type(type.member_types[i]);
                if (mt.columns > 1) {
                    m.matrixStride = static_cast<int>(compiler.type_struct_member_matrix_stride(type, i));
                    // SPIR-V sees HLSL's matrix transposed: RowMajor there is HLSL column_major.
                    m.hlslRowMajor = !compiler.has_member_decoration(ubo.base_type_id, i, spv::DecorationRowMajor);
                }
                if (!mt.array.empty()) m.arrayStride = innermostArrayStride(compiler, type, i);
                block.members.push_back(m);
            }
            for (const auto& range : compiler.get_active_buffer_ranges(ubo.id)) {
                out.membersRead.push_back(compiler.get_member_name(ubo.base_type_id, range.index));
                // SPIRV-Cross's range runs to the next member's offset (padding included); offsets
                // increase here (relaid out above otherwise), so it is positive.
                int size = static_cast<int>(range.range);
                // At D3D's offsets the member's own bytes (a scalar may follow in its padding).
                if (d3d && !relaid && range.index < d3d->members.size()) size = std::min(size, d3d->members[range.index].size);
                out.rangesRead.push_back({static_cast<int>(range.offset), size, block.index});
            }
            addLiveRanges(live, ubo.id, block.index, out);
            out.blocks.push_back(std::move(block));
        }

        // A pixel shader's UAVs share D3D11's output slots with its render targets: fxc gives
        // unregistered ones the registers after the last SV_Target.
        int firstFreeUav = 0;
        if (stage == ShaderStage::Pixel)
            for (const auto& r : res.stage_outputs)
                firstFreeUav = std::max(firstFreeUav, static_cast<int>(compiler.get_decoration(r.id, spv::DecorationLocation)) + 1);
        bindStorage(compiler, res, *effect.syntax, effect.textureUnits, firstFreeUav, out.storage);
        if (stage == ShaderStage::Domain && hull) declareHullModes(compiler, *hull);
        if (stage == ShaderStage::Compute)
            for (uint32_t d = 0; d < 3; ++d)
                out.threadGroupSize[d] = static_cast<int>(compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, d));

        // ---- samplers: DX9 combined samplers keep their names; DX10 pairs get one per pair
        std::set<int> usedUnits;
        for (const auto& s : effect.samplers)
            if (!s.dx10) usedUnits.insert(s.unit);
        for (const auto& [name, unit] : effect.textureUnits) usedUnits.insert(unit);
        // The GL units this shader's DX9 samplers take: a DX10 pair must not share one (a sampler2D
        // and a texture object on GL unit 0 would read the same texture).
        std::set<int> dx9Units;
        auto elementsOf = [&](const spirv_cross::SPIRType& type) {
            int n = 1;
            for (uint32_t a : type.array) n *= std::max<int>(1, static_cast<int>(a));
            return n;
        };
        for (const auto& img : res.sampled_images) {
            std::string name = compiler.get_name(img.id);
            bool combined = false;
            for (const auto& c : compiler.get_combined_image_samplers()) combined |= c.combined_id == img.id;
            if (combined) continue;
            SamplerBinding b;
            b.glslName = name;
            b.samplerName = name;
            b.kind = kindOfImage(compiler.get_type(img.type_id));
            for (const auto& s : effect.samplers)
                if (s.name == name) {
                    b.unit = s.unit;
                    b.textureParameter = s.textureParameter;
                    b.state = s.state;
                    b.stateParameters = s.stateParameters;
                }
            b.elements = elementsOf(compiler.get_type(img.type_id));
            for (int k = 0; k < b.elements; ++k) dx9Units.insert(b.unit + k);
            compiler.unset_decoration(img.id, spv::DecorationDescriptorSet);
            compiler.set_decoration(img.id, spv::DecorationBinding, static_cast<uint32_t>(b.unit));
            out.samplers.push_back(b);
            out.samplerFirstUse.push_back(img.id);
        }
        std::set<int> pairUnits;
        for (const auto& c : compiler.get_combined_image_samplers()) {
            std::string image = compiler.get_name(c.image_id);
            std::string sampler = compiler.get_name(c.sampler_id);
            SamplerBinding b;
            b.textureParameter = image;
            b.kind = kindOfImage(compiler.get_type(compiler.get_type_from_variable(c.image_id).self));
            for (const auto& s : effect.samplers)
                if (s.name == sampler) {
                    b.samplerName = sampler;
                    b.state = s.state;
                    b.stateParameters = s.stateParameters;
                }
            b.elements = elementsOf(compiler.get_type_from_variable(c.image_id));
            auto unit = effect.textureUnits.find(image);
            int u = unit != effect.textureUnits.end() ? unit->second : 0;
            auto runTaken = [&](int first, bool anyUsed) {
                for (int k = 0; k < b.elements; ++k)
                    if (pairUnits.count(first + k) || dx9Units.count(first + k) || (anyUsed && usedUnits.count(first + k))) return true;
                return false;
            };
            // The same texture with a second sampler, or a unit a DX9 sampler of this shader has:
            // the next free run of units. So does a register past the GL units (MiniEngine's
            // register(t64); D3D11 has t0..t127): the D3D slot stays its textureRegister.
            // Units the effect's other textures take are avoided where the GL units allow; where
            // they take them all (OGRE's Hair.hlsl declares Buffer<> t0..t35), only this shader's own.
            if (runTaken(u, false) || u + b.elements > kGlTextureUnits) {
                u = 0;
                while (runTaken(u, true)) ++u;
                if (u + b.elements > kGlTextureUnits)
                    for (u = 0; runTaken(u, false);) ++u;
            }
            for (int k = 0; k < b.elements; ++k) pairUnits.insert(u + k);
            if (u + b.elements > kGlTextureUnits) {
                // D3D11 gives a stage 128 texture slots; GL drivers give 32 units (NVIDIA, Mesa).
                out.unsupported = "'" + image + "' is its texture and sampler pair number " + std::to_string(pairUnits.size() + dx9Units.size()) +
                                  ", and a GL stage has " + std::to_string(kGlTextureUnits) + " texture units (D3D11 has 128 slots)";
                return out;
            }
            b.unit = u;
            b.glslName = "fxport_" + image + "_" + (sampler.empty() ? std::string("default") : sampler);
            compiler.set_name(c.combined_id, b.glslName);
            compiler.set_decoration(c.combined_id, spv::DecorationBinding, static_cast<uint32_t>(u));
            out.samplers.push_back(b);
            out.samplerFirstUse.push_back(c.image_id);
        }

        // ---- interface locations
        // glslang splits an array member of a stage's struct input or output into a variable per
        // element ("@patchConstantOutput.uv[2]"), each with the member's semantic; D3D gives element
        // k the semantic index plus k (uv[3] : TEXCOORD0 is TEXCOORD0..2).
        auto semanticOf = [&](spirv_cross::ID id) {
            std::string semantic = toUpper(compiler.get_decoration_string(id, spv::DecorationUserSemantic));
            const int element = splitArrayElement(compiler.get_name(id));
            if (element <= 0 || semantic.empty()) return semantic;
            auto [base, index] = splitSemantic(semantic);
            return base + std::to_string(index + element);
        };
        if (stage == ShaderStage::Compute) {
            // no stage inputs or outputs: thread ids are built-ins
        } else if (stage == ShaderStage::Vertex) {
            std::vector<const spirv_cross::Resource*> inputs;
            for (const auto& r : res.stage_inputs) inputs.push_back(&r);
            std::sort(inputs.begin(), inputs.end(), [&](auto* a, auto* b) {
                return compiler.get_decoration(a->id, spv::DecorationLocation) < compiler.get_decoration(b->id, spv::DecorationLocation);
            });
            int loc = 0;
            for (const auto* r : inputs) {
                const auto& t = compiler.get_type(r->type_id);
                VertexInput vi;
                vi.semantic = semanticOf(r->id);
                auto [base, index] = splitSemantic(vi.semantic);
                vi.semantic = base + std::to_string(index);
                vi.location = loc;
                vi.components = static_cast<int>(t.vecsize);
                vi.isInteger = t.basetype != spirv_cross::SPIRType::Float && t.basetype != spirv_cross::SPIRType::Half &&
                               t.basetype != spirv_cross::SPIRType::Double;
                compiler.set_decoration(r->id, spv::DecorationLocation, static_cast<uint32_t>(loc));
                loc += static_cast<int>(std::max(1u, t.columns));
                out.inputs.push_back(vi);
            }
        } else {
            for (const auto& r : res.stage_inputs) {
                std::string sem = semanticOf(r.id);
                if (sem.empty()) continue;
                if (stage == ShaderStage::Pixel && splitSemantic(sem).first == kSampleMaskInSemantic) {
                    compiler.set_name(r.id, kSampleMaskInName);  // no varying: see sampleMaskInFromGl
                    continue;
                }
                const int location = varyings.locationOf(sem);
                compiler.set_decoration(r.id, spv::DecorationLocation, static_cast<uint32_t>(location));
                auto [base, index] = splitSemantic(sem);
                out.varyingInputs.push_back({base + std::to_string(index), location});
            }
        }
        if (stage != ShaderStage::Pixel) {
            for (const auto& r : res.stage_outputs) {
                std::string sem = semanticOf(r.id);
                if (sem.empty()) continue;
                const int location = varyings.locationOf(sem);
                compiler.set_decoration(r.id, spv::DecorationLocation, static_cast<uint32_t>(location));
                auto [base, index] = splitSemantic(sem);
                out.varyingOutputs.push_back({base + std::to_string(index), location});
            }
        } else {
            for (const auto& r : res.stage_outputs)
                out.outputTargets = std::max(out.outputTargets, static_cast<int>(compiler.get_decoration(r.id, spv::DecorationLocation)) + 1);
        }

        if (stage != ShaderStage::Pixel && stage != ShaderStage::Hull)
            for (const auto& b : res.builtin_outputs)
                if (b.builtin == spv::BuiltInClipDistance) {
                    const auto& t = compiler.get_type(b.value_type_id);
                    if (!t.array.empty()) out.clipDistances = static_cast<int>(t.array[0]);
                }
        out.glsl = sampleMaskInFromGl(compiler.compile());
        if (readsVertexId(res, stage)) out.glsl = withStartVertexDeclared(out.glsl);
        if (layerOutputs) out.glsl = perVertexForLayerOutputs(out.glsl);
        if (stage != ShaderStage::Pixel && stage != ShaderStage::Hull) recordOutputs(compiler, res, semanticOf, out);
        // A hull shader's clip/cull inputs (spirv/tessellation_clip_distances.h) are arrayed as a
        // geometry shader's are.
        if (stage == ShaderStage::Geometry || stage == ShaderStage::Hull) {
            int clip = 0, cull = 0;  // per vertex: the inner of the input's two dimensions
            for (const auto& b : res.builtin_inputs) {
                // The variable's type: a hull shader's value_type_id lacks the per-vertex dimension.
                const auto& t = compiler.get_type_from_variable(b.resource.id);
                const int inner = t.array.size() >= 2 ? static_cast<int>(t.array.front()) : 0;
                if (b.builtin == spv::BuiltInClipDistance) clip = inner;
                if (b.builtin == spv::BuiltInCullDistance) cull = inner;
            }
            out.glsl = geometryClipInputsRespelled(out.glsl, clip, cull);
        }
        out.writesDepth = out.glsl.find("gl_FragDepth") != std::string::npos;
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    return out;
}

}  // namespace fxport::xlate
