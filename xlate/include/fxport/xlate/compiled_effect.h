// What the effect compiler produces: GLSL per shader, reflection, and per-pass render-state
// assignments in one canonical vocabulary (DX9 `AlphaBlendEnable = true;` and DX10
// `SetBlendState(...)` both end up as StateAssignment rows). No GL here: the runtime maps this onto
// its own cached state objects.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/stream_output.h"

namespace fxport::xlate {

enum class ShaderStage : std::uint8_t { Vertex, Pixel, Geometry, Hull, Domain, Compute };

// "vs_3_0" -> {Vertex, 3, 0}; "cs_5_0" -> {Compute, 5, 0}; "hs_5_0" / "ds_5_0" -> Hull / Domain; "ps_4_0_level_9_1" -> {Pixel, 4, 0}; "ps_2_a" -> {Pixel, 2, 1}.
struct ShaderProfile {
    ShaderStage stage = ShaderStage::Vertex;
    int major = 0;
    int minor = 0;
    std::string name;  // as written in the effect

    // D3D9 rasterisation rules (pixel centres at integer coordinates) apply to SM 1-3 shaders.
    bool isD3D9() const { return major <= 3; }
};

// ---------------------------------------------------------------------------------------------
// Parameters (the effect's global variables, as XNA's EffectParameterCollection sees them)

enum class ParameterClass : std::uint8_t { Scalar, Vector, Matrix, Object, Struct };
enum class ParameterType : std::uint8_t {
    Void, Bool, Int, UInt, Float, String,
    Texture, Texture1D, Texture2D, Texture3D, TextureCube,
    Sampler, Sampler1D, Sampler2D, Sampler3D, SamplerCube, SamplerState,
};

struct Annotation {
    std::string type;   // "string", "float", "int", "bool", "float4" ...
    std::string name;
    std::string value;  // initializer text as written (strings without quotes)
};

struct Parameter {
    std::string name;
    std::string semantic;  // SAS semantic, e.g. WORLDVIEWPROJECTION (upper-cased as written)
    ParameterClass parameterClass = ParameterClass::Scalar;
    ParameterType type = ParameterType::Float;
    int rows = 1;          // matrix rows / 1 for vectors and scalars
    int columns = 1;       // vector size / matrix columns
    int elements = 0;      // array length; 0 = not an array
    bool rowMajor = false; // HLSL packing: false = column_major (the HLSL default)
    bool isStatic = false; // `static`/`const` globals are not parameters of the constant buffer

    // Placement in a uniform block: CompiledEffect::uniformBlocks[block] ($Global is block 0, a
    // user `cbuffer` is 1 + its declaration order). offset < 0 when the parameter is in no block
    // (objects, statics) or no shader of the effect reads its block (then `block` still names it).
    // For a matrix, element [r][c] (HLSL indexing) lives at
    //   offset + (rowMajor ? r*matrixStride + c*4 : c*matrixStride + r*4)
    // and array element i at offset + i*arrayStride (all in bytes from the start of the block).
    int block = 0;
    int offset = -1;
    int size = 0;
    int matrixStride = 0;
    int arrayStride = 0;

    // Default value from the source initializer, flattened row by row (bools and ints as numbers).
    std::vector<double> defaultValue;
    std::string defaultString;  // for `string` parameters
    std::vector<Annotation> annotations;
    std::vector<Parameter> members;  // for ParameterClass::Struct
    SourceLocation declaredAt;
};

// ---------------------------------------------------------------------------------------------
// Sampler states: only what the effect specified is set; the rest is left to the device.

enum class CompareFunction : std::uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };
enum class TextureFilter : std::uint8_t { None, Point, Linear, Anisotropic };
enum class TextureAddress : std::uint8_t { Wrap, Mirror, Clamp, Border, MirrorOnce };
enum class TextureKind : std::uint8_t { Texture1D, Texture2D, Texture3D, TextureCube };

// An index the effect framework evaluates at Apply() over the current parameter values: a stack
// program (`VSIndices[ShaderIndex]` is PushParameter ShaderIndex, IndexParameter VSIndices).
struct SelectorOp {
    enum class Kind : std::uint8_t { PushConstant, PushParameter, IndexParameter } kind = Kind::PushConstant;
    int value = 0;  // constant, or parameter index (IndexParameter pops an index, pushes param[index])
    bool operator==(const SelectorOp&) const = default;
};

struct SamplerStateDesc {
    std::optional<TextureFilter> minFilter, magFilter, mipFilter;
    std::optional<TextureAddress> addressU, addressV, addressW;
    std::optional<std::array<float, 4>> borderColor;
    std::optional<int> maxAnisotropy;
    std::optional<int> maxMipLevel;
    std::optional<float> mipLodBias;
    std::optional<float> minLod, maxLod;
    // D3D10 SamplerComparisonState's ComparisonFunc: SampleCmp passes where `reference FUNC texel`
    // (GL's TEXTURE_COMPARE_FUNC has the same operand order).
    std::optional<CompareFunction> comparison;
    bool operator==(const SamplerStateDesc&) const = default;
};

// A sampler state the effect framework reads from a parameter at Apply() (`MinFilter = <Filter>;`,
// `AddressU = <Modes[Mode]>;`): the parameter (element) holds D3D9's number for it (D3DTEXF_*,
// D3DTADDRESS_*, or the anisotropy, level or bias itself).
enum class SamplerStateField : std::uint8_t { MinFilter, MagFilter, MipFilter, AddressU, AddressV, AddressW, MaxAnisotropy, MaxMipLevel, MipLodBias };
struct SamplerStateParameter {
    SamplerStateField field = SamplerStateField::MinFilter;
    int parameter = -1;               // index into CompiledEffect::parameters
    std::vector<SelectorOp> element;  // the element to read, as StateAssignment::element; empty = 0
    bool operator==(const SamplerStateParameter&) const = default;
};
// Sets `field` of `desc` from D3D9's number for it; a code D3D9 does not define leaves it as it was.
void setSamplerStateFromD3D9(SamplerStateDesc& desc, SamplerStateField field, double number);

// One texture unit a shader samples. For DX9 samplers the unit is the sampler register
// (register(sN) or the order fxc would give); `GraphicsDevice.Textures[unit]` feeds it unless the
// effect names a texture parameter.
struct SamplerBinding {
    int unit = 0;
    TextureKind kind = TextureKind::Texture2D;
    std::string glslName;          // the uniform's name in the GLSL
    std::string samplerName;       // effect sampler (DX9 `sampler S` / DX10 `SamplerState S`), may be empty
    std::string textureParameter;  // texture parameter feeding it (`Texture = <T>` / DX10 Texture2D), may be empty
    SamplerStateDesc state;        // the effect's sampler_state, applied at Apply()
    std::vector<SamplerStateParameter> stateParameters;  // states read from parameters at Apply(), over `state`
    // GL units unit .. unit + elements - 1: an array of samplers (`Texture2D t[3]`) binds one per
    // element, consecutively.
    int elements = 1;
    // The t# and s# registers fxc gives this texture and sampler (element 0 of an array; -1 where
    // D3D has none, as a Load without sampler); SM 1-3: the s# (texture stage) in both, combined
    // samplers too, -1 past s15 (d3d_registers.h has the rules). XNA binds SM 1-3 by `unit` alone.
    int textureRegister = -1;
    int samplerRegister = -1;
};

// ---------------------------------------------------------------------------------------------
// Compiled shaders

struct VertexInput {
    std::string semantic;  // upper case with index: "POSITION0", "TEXCOORD1"
    int location = 0;
    int components = 4;    // 1..4
    bool isInteger = false;
};

// A value passed between stages by a user semantic, at the GL location xlate gave it.
struct Varying {
    std::string semantic;  // upper case with index: "TEXCOORD2", "RESULT0"
    int location = 0;
};

struct UniformRange {  // a byte range of a uniform block this shader actually reads
    int offset = 0;
    int size = 0;
    int block = 0;    // index into CompiledEffect::uniformBlocks
};

// One GL uniform block of the effect. The layout is what the generated GLSL declares: D3D's cbuffer
// packing (explicit member offsets, or an array of registers where GLSL cannot declare them);
// parameter offsets are relative to the block's start.
struct UniformBlock {
    std::string name;  // "$Global" or the cbuffer's name
    int binding = 0;   // GL uniform-buffer binding: $Global 0, user cbuffers 2 + declaration order
    int size = 0;      // bytes; 0 when no shader of the effect reads the block
    // Every member at its D3D cbuffer offset (packoffset, register(cN) and D3D's packing rules
    // honoured), so a host's D3D bytes can be bound as they are. False only where fxport had to
    // re-lay the block out with std140 (set its parameters by name then).
    bool d3dPacking = false;
};

// A buffer or image a shader reads or writes outside the sampler path: D3D11 UAVs (RWStructuredBuffer,
// RWByteAddressBuffer, RWTexture2D, register uN) and structured/raw buffer SRVs (StructuredBuffer,
// ByteAddressBuffer, register tN). GL bindings: a buffer is an SSBO at `binding` (uN -> N,
// tN -> kSrvBufferBindingBase + N); an image is an image unit `binding` (uN -> N). Typed buffers:
// Buffer<T> (register tN) is a texel buffer read by texelFetch from texture unit
// kTexelBufferUnitBase + N; RWBuffer<T> (uN) an image buffer at image unit N.
enum class StorageKind : std::uint8_t { Buffer, Image, TexelBuffer, ImageBuffer };
inline constexpr int kSrvBufferBindingBase = 8;
inline constexpr int kTexelBufferUnitBase = 32;  // past the sampler units a draw uses (0-31)
struct StorageBinding {
    StorageKind kind = StorageKind::Buffer;
    std::string name;          // the HLSL variable
    char registerClass = 'u';  // 'u' (UAV) or 't' (read-only SRV)
    int slot = 0;              // the register number (register(u2) -> 2; unassigned: declaration order)
    int binding = 0;           // GL SSBO binding or image unit
    int stride = 0;            // buffers: bytes per element (structured: the struct; raw: 4)
    bool writes = false;       // the shader may write it
    TextureKind dimension = TextureKind::Texture2D;  // images
    std::string format;        // images: the GLSL format qualifier ("r32f", "rgba32f", "r32ui" ...); "" = none
};

// Hull/domain shader attributes ([domain], [partitioning], [outputtopology], [outputcontrolpoints],
// [patchconstantfunc]) and their GL equivalents, as the runtime and readers need them.
struct Tessellation {
    std::string domain;                  // "tri", "quad", "isoline"
    std::string partitioning;            // "integer", "fractional_even", "fractional_odd", "pow2"
    std::string outputTopology;          // "triangle_cw", "triangle_ccw", "line", "point"
    std::string patchConstantFunction;   // hull shaders
    int inputControlPoints = 0;          // hull: InputPatch<T, N>; domain: OutputPatch<T, N>
    int outputControlPoints = 0;         // hull: [outputcontrolpoints(N)]
};

// The int uniform a vertex shader that reads SV_VertexID subtracts from gl_VertexID (xlate's GLSL
// declares it only then): D3D's SV_VertexID leaves out the draw's StartVertexLocation (Draw*) and
// BaseVertexLocation (DrawIndexed*), GL's gl_VertexID counts them in. The runtime sets it to that
// value before each draw.
inline constexpr const char* kStartVertexUniform = "fxport_startVertex";

struct CompiledShader {
    ShaderProfile profile;
    std::string entryPoint;
    std::string arguments;   // literal arguments of `compile ps_2_0 PS(true, 3)`, as written
    std::string glsl;        // GLSL 4.50 core, separable (has gl_PerVertex redeclared); empty in
                             // an outline (CompileOptions::skipShaders), as are the fields below
                             // except needsD3D9PixelOffset
    std::vector<VertexInput> inputs;  // vertex shaders only
    std::vector<SamplerBinding> samplers;
    std::vector<int> parametersRead;      // indices into CompiledEffect::parameters
    std::vector<UniformRange> uniformRangesRead;
    // The bytes of those ranges whose values can reach the shader's results, component by component
    // after dead-code analysis (glslang loads a whole matrix for `m[0].x`): what fxc sizes an SM 1-3
    // parameter's constant registers by. A subset of uniformRangesRead.
    std::vector<UniformRange> uniformRangesLive;
    int outputTargets = 0;                // pixel shaders: number of SV_Target outputs (MRT)
    bool writesDepth = false;
    // Vertex, geometry and domain shaders: how many SV_ClipDistance values they write (gl_ClipDistance
    // 0..n-1, packed in semantic order); the runtime clips by that many planes when the shader is
    // the last before the rasteriser.
    int clipDistances = 0;
    // Values between stages, by user semantic (system values are GL built-ins): what a stage reads
    // (all but vertex shaders) and writes (all but pixel shaders). Locations of standard semantics
    // are fixed; other names are numbered in the order a shader declares them, so a runtime links
    // shaders compiled apart by semantic, moving a reader's locations to its writer's.
    std::vector<Varying> varyingInputs;
    std::vector<Varying> varyingOutputs;
    // Vertex, geometry and domain shaders: every value they write by semantic (user semantics and
    // SV_Position), with its GLSL name, for stream output to find; and the declaration a shader made
    // by ConstructGSWithSO streams (empty for the others). A vertex shader with one is D3D's "null"
    // geometry shader with stream output: its own outputs are captured.
    std::vector<ShaderOutput> outputs;
    StreamOutput streamOutput;
    int outputPrimitiveVertices = 0;      // geometry shaders: 1 points, 2 line strips, 3 triangle strips
    std::vector<StorageBinding> storage;  // UAVs and buffer SRVs
    std::array<int, 3> threadGroupSize{};  // compute shaders: [numthreads(x, y, z)]
    Tessellation tessellation;            // hull and domain shaders
    // Vertex shaders compiled for vs_1_1..vs_3_0: they draw with D3D9's pixel centres, which the
    // runtime applies by moving the viewport's origin while they draw (docs/DESIGN.md).
    bool needsD3D9PixelOffset = false;
    std::string hlslAfterRewrite;         // for debugging (FXPORT_DUMP); not serialised
};

// ---------------------------------------------------------------------------------------------
// Passes and render states

// Canonical render states. DX9 names map 1:1; DX10 state objects are expanded into these.
enum class RenderState : std::uint8_t {
    AlphaBlendEnable, SrcBlend, DestBlend, BlendOp,
    SeparateAlphaBlendEnable, SrcBlendAlpha, DestBlendAlpha, BlendOpAlpha,
    BlendFactor, ColorWriteEnable, MultiSampleMask,
    ZEnable, ZWriteEnable, ZFunc,
    StencilEnable, StencilFunc, StencilPass, StencilFail, StencilZFail,
    StencilRef, StencilMask, StencilWriteMask, TwoSidedStencilMode,
    CcwStencilFunc, CcwStencilPass, CcwStencilFail, CcwStencilZFail,
    CullMode, FillMode, ScissorTestEnable, MultiSampleAntiAlias,
    DepthBias, SlopeScaleDepthBias, DepthClipEnable,
    AlphaTestEnable, AlphaFunc, AlphaRef, SrgbWriteEnable,
    // D3D9 fixed-function states the runtime emulates (runtime FixedFunctionState). The enumerated
    // ones keep D3D9's codes as int: FogTableMode/FogVertexMode D3DFOGMODE (0 NONE, 1 EXP, 2 EXP2,
    // 3 LINEAR), ShadeMode D3DSHADEMODE (1 FLAT, 2 GOURAUD, 3 PHONG); FogColor a D3DCOLOR;
    // ClipPlane[n] a float4.
    FogEnable, FogColor, FogTableMode, FogVertexMode, FogStart, FogEnd, FogDensity,
    PointSize, PointSizeMin, PointSizeMax, PointSpriteEnable, ClipPlaneEnable, ClipPlane, ShadeMode,
};

// Values of enumerated states.
enum class Blend : std::uint8_t {
    Zero, One, SourceColor, InverseSourceColor, SourceAlpha, InverseSourceAlpha,
    DestinationAlpha, InverseDestinationAlpha, DestinationColor, InverseDestinationColor,
    SourceAlphaSaturation, BlendFactor, InverseBlendFactor,
};
enum class BlendFunction : std::uint8_t { Add, Subtract, ReverseSubtract, Min, Max };
enum class StencilOperation : std::uint8_t { Keep, Zero, Replace, IncrementSaturation, DecrementSaturation, Invert, Increment, Decrement };
// D3D9 CullMode names which winding is culled: CCW culls counter-clockwise (XNA CullCounterClockwiseFace).
enum class CullMode : std::uint8_t { None, CullClockwiseFace, CullCounterClockwiseFace };
enum class FillMode : std::uint8_t { Point, WireFrame, Solid };

// A state's value, typed: which alternative a state holds is fixed by the state (see
// defaultStateValue): bool for the *Enable states, Blend for SrcBlend ..., int for masks, stencil
// and alpha references, float for the depth biases, a float4 for BlendFactor.
using StateValue = std::variant<bool, int, float, Blend, BlendFunction, CompareFunction, StencilOperation, CullMode,
                                FillMode, std::array<float, 4>>;


struct StateAssignment {
    RenderState state = RenderState::AlphaBlendEnable;
    int index = 0;                 // render-target index for ColorWriteEnable[n] / BlendEnable[n]
    StateValue value = false;      // the literal value (of the state's alternative)
    // `AlphaRef = <AlphaReference>;`: index into CompiledEffect::parameters of the parameter whose
    // current value the runtime reads at Apply() (the effect framework's parameter-driven states;
    // converted with stateValueFromD3D9). -1 for literal values.
    int parameter = -1;
    // `ZWriteEnable = <ZWrites[Mode]>;`: the element of `parameter` to read, evaluated at Apply()
    // like a shader selector; empty = element 0.
    std::vector<SelectorOp> element;
    SourceLocation where;
};

// The value `state` holds when nothing set it, and so the alternative of StateValue it uses.
StateValue defaultStateValue(RenderState state);
// A number as D3D9 stores the state (D3DBLEND/D3DCMPFUNC/D3DCULL ... codes, 0/1 for bools, the
// value itself for ints and floats) -> the state's typed value; codes D3D9 does not define give
// the default. For parameter-driven states, whose value is only known at Apply().
StateValue stateValueFromD3D9(RenderState state, double number);

// A pass's choice of shader: usually one; for `VertexShader = (VSArray[VSIndices[ShaderIndex]])`
// several, picked at Apply() by evaluating `selector` over the current parameter values.
struct ShaderChoice {
    std::vector<int> shaders;         // indices into CompiledEffect::shaders; empty = no shader (NULL)
    std::vector<SelectorOp> selector; // empty = shaders[0]
};

// A D3D9 texture stage a pass sets (`Texture[1] = <T>; MinFilter[1] = Linear;`) that none of its
// pixel shaders samples: Apply() sets the device's stage, which D3D9 keeps for later passes.
struct TextureStage {
    int stage = 0;                 // register s<stage>, 0..15
    std::string textureParameter;  // empty: the stage's texture is left as it is
    SamplerStateDesc state;        // the states the pass names (unset ones stay the device's)
};

struct Pass {
    std::string name;
    std::vector<Annotation> annotations;
    ShaderChoice vertexShader, pixelShader, geometryShader;
    ShaderChoice hullShader, domainShader, computeShader;  // technique11: SetHullShader ...
    std::vector<StateAssignment> states;  // in source order; later assignments win
    // SetPixelShader(NULL) (Effects 10/11): no pixel shader runs, where an unassigned stage keeps
    // the one before (a stream-output pass draws nothing, or depth only).
    bool nullPixelShader = false;
    std::vector<TextureStage> textureStages;  // stages no pixel shader of the pass samples
    bool valid = true;                    // false: a diagnostic says why (e.g. asm block)
    SourceLocation declaredAt;
};

struct Technique {
    std::string name;
    std::vector<Annotation> annotations;
    std::vector<Pass> passes;
    SourceLocation declaredAt;
};

// A D3D10/11 resource as the source declares it, for D3D's register rules (a D3D11 front end binds
// by b#/t#/s#): an explicit register(b3)/register(t1)/register(s0) holds; the others take, as fxc
// gives them, the lowest register of their kind that is free, in declaration order, among the
// resources a shader uses. GL bindings and units above are fxport's own numbering.
struct ResourceDeclaration {
    enum class Kind : std::uint8_t { ConstantBuffer, Texture, Sampler };
    Kind kind = Kind::ConstantBuffer;
    std::string name;           // the cbuffer's name (UniformBlock::name), the texture or the sampler
    int explicitRegister = -1;  // register(xN) as written, -1 when none
    bool operator==(const ResourceDeclaration&) const = default;
};

struct CompiledEffect {
    std::string sourcePath;
    std::vector<Technique> techniques;
    std::vector<Parameter> parameters;
    std::vector<CompiledShader> shaders;
    // [0] is $Global (GL binding 0), then every user cbuffer in declaration order (bindings 2, 3 ...;
    // binding 1 is left unused).
    std::vector<UniformBlock> uniformBlocks;
    int uniformBufferSize = 0;  // bytes of $Global, the same as uniformBlocks[0].size
    // User cbuffers, DX10 textures and DX10 samplers in declaration order (ResourceDeclaration).
    std::vector<ResourceDeclaration> resources;
    // Errors confined to a pass (the pass has valid=false) and warnings.
    std::vector<Diagnostic> diagnostics;

    bool hasErrors() const;
    const Parameter* findParameter(const std::string& name) const;
    int findTechnique(const std::string& name) const;  // -1 if absent
};

}  // namespace fxport::xlate
