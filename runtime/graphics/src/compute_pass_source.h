// INTERNAL: the text transform behind compute passes (PresentationParameters::ComputePasses): a
// translated pixel shader's GLSL made into a compute shader that does, for each pixel of a small
// draw, what the rasteriser and the fragment stage would have done (coverage with D3D's top-left
// rule, perspective-correct interpolation of the vertex shader's outputs as transform feedback
// captured them, the pixel function, blending and write masks, imageStore). Pure text: no GL.
#pragma once

#include <string>
#include <vector>

namespace fxport::detail {

enum class Interpolation { Smooth, Flat, NoPerspective };

// An `in` or `out` variable of a shader stage, as SPIRV-Cross declares it:
// `layout(location = 2) flat in ivec2 i2;`.
struct GlslVarying {
    int location = -1;
    std::string type;  // "vec4", "float", "ivec2" ...
    std::string name;
    int components = 0;
    char scalar = 'f';  // 'f' float, 'i' int, 'u' uint
    Interpolation interpolation = Interpolation::Smooth;
};

// A vertex shader's located outputs, in declaration order (what a transform-feedback capture
// records after gl_Position). `refusal` says why the outputs cannot be captured (an array or
// struct output, say); empty when they can.
struct VertexOutputs {
    std::vector<GlslVarying> varyings;
    std::string refusal;
};
VertexOutputs parseVertexOutputs(const std::string& vertexGlsl);

// A pixel shader made into a function: `in` and `out` variables are globals, `main` is
// fxport_pixelMain, gl_FragCoord is the global fxport_FragCoord and `discard` sets
// fxport_discarded and returns. `refusal` names what a compute shader cannot do as the fragment
// stage does (derivatives, gl_FrontFacing, gl_FragDepth, interpolateAt*, a discard outside main,
// an input or output it does not understand); empty when the function is usable.
struct PixelFunction {
    std::string text;  // without #version
    std::vector<GlslVarying> inputs;
    std::vector<GlslVarying> outputs;  // location = colour target
    std::string refusal;
};
PixelFunction pixelFunctionFromShader(const std::string& pixelGlsl);

// What a dispatch does with a pixel function's output to one colour target.
enum class BlendOp { Write, Add, Min, Max };  // Add: One/One
struct ComputeTarget {
    std::string imageFormat;  // "rgba8", "rgba16f" ...
    bool normalized = false;  // unorm: the source is clamped to [0,1] before Min/Max, as GL does
    BlendOp color = BlendOp::Write, alpha = BlendOp::Write;
    unsigned writeMask = 15;  // bit 0 red .. bit 3 alpha; 0: the target is left alone
};

// Image unit of target i, and the shader-storage binding of the captured vertices.
inline constexpr int kCaptureBinding = 7;
// Shader-storage binding of the dispatch's size and origin: the bounds step writes it, the
// indirect dispatch reads its first three words, the pixel step its origin.
inline constexpr int kDispatchBinding = 6;

// The bounds step: one invocation that reads the captured triangles' clip positions and writes
// the groups of a dispatch over their window rectangle, clipped to fxport_rect (a small sprite costs
// its own pixels, not the whole target's).
std::string boundsShaderSource();

// Floats per captured vertex: gl_Position, then each of `captured` tightly packed.
int capturedFloatsPerVertex(const std::vector<GlslVarying>& captured);

// The compute shader (8x8 work groups) of `pixel` drawing the triangles whose vertices (3 each,
// `captured` layout) are in the capture buffer into `targets`. Uniforms it declares, set per
// dispatch: ivec4 fxport_rect (x0, y0, x1, y1 exclusive, window pixels), vec4 fxport_viewport
// (X, Y, Width, Height), vec2 fxport_depthRange, int fxport_triangles, int fxport_cull (0 none,
// 1 cull counter-clockwise as seen, 2 cull clockwise). Empty with `refusal` set when a pixel
// input has no captured output at its location or needs more components than it has.
std::string computeShaderSource(const PixelFunction& pixel, const std::vector<GlslVarying>& captured,
                                const std::vector<ComputeTarget>& targets, std::string& refusal);

}  // namespace fxport::detail
