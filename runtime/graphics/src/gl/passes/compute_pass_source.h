// INTERNAL: the text transform behind compute passes (DeviceOptimizations::ComputePasses): a
// translated pixel shader's GLSL made into a compute shader that does, for each pixel a small draw
// covers, what the fragment stage would have done (the pixel function, blending and write masks,
// imageStore), reading the inputs the rasteriser itself interpolated from a replay store that a
// "fill" fragment shader wrote; plus the one-invocation compare step that decides, on the GPU,
// whether the store still holds this draw's interpolants. Pure text: no GL.
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
    std::string qualifiers;  // as declared ("noperspective ", "flat ", "centroid "...): the fill shader repeats them
    unsigned readMask = 15;  // pixel inputs: the components the shader reads (bit 0 = x); only those are replayed
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
    bool readsFragCoord = false;       // gl_FragCoord: its z and w are replayed too
    std::string refusal;
};
PixelFunction pixelFunctionFromShader(const std::string& pixelGlsl);

// What a dispatch does with a pixel function's output to one colour target.
enum class BlendOp { Write, Add, Min, Max };  // Add: One/One
struct ComputeTarget {
    const char* imageFormat = "";  // "rgba8", "rgba16f" ... (imageFormatOf's)
    bool normalized = false;  // unorm: the source is clamped to [0,1] before Min/Max, as GL does
    BlendOp color = BlendOp::Write, alpha = BlendOp::Write;
    unsigned writeMask = 15;  // bit 0 red .. bit 3 alpha; 0: the target is left alone
};

// Bindings shared by the generated programs: shader-storage blocks of the captured vertices, the
// compare step's commands and the replay entry; the image unit of the replay store (targets take
// units 0..3).
inline constexpr int kCaptureBinding = 7;
inline constexpr int kCommandsBinding = 6;
inline constexpr int kEntryBinding = 5;
// The compare step's counters, 4 words: refilled, replayed, fell back (w != 1), fell back (not one
// layer). The device reads them from a persistently mapped buffer, without waiting.
inline constexpr int kCountersBinding = 4;
inline constexpr int kStoreUnit = 7;

// The commands buffer, in 32-bit words: what the compare step writes and the dispatch, the fill
// draw and the fall-back draw read (indirect commands at these word offsets).
inline constexpr int kCommandsGroups = 0;      // 3: indirect dispatch groups
                                               // 3, 4: the dispatch's origin; 5: the stamp of the store's current fill
inline constexpr int kCommandsFill = 8;        // 5: indirect draw of the fill (instance count 0 or 1)
inline constexpr int kCommandsFallBack = 16;   // 5: indirect draw of the fragment fall-back (instance count 0 or 1)
inline constexpr int kCommandsWords = 24;
// A replay entry's buffer: word 0 the stamp of its fill (0: never filled), words 4.. the captured
// vertices that fill was drawn from.
inline constexpr int kEntryHeaderWords = 4;

// The compare step: one invocation that reads the captured vertices and the entry's, and writes
// the commands (above): a dispatch over the captured triangles' window rectangle clipped to
// fxport_rect when the draw may replay, a fill when the capture differs from the entry's in any
// bit (copying it and the new stamp into the entry), the fall-back draw when it may not replay.
// A draw may replay when every captured w is exactly 1 or fxport_unitW is 0 (no perspective float
// input), and its triangles cannot cover a pixel twice: one triangle, or two that share an edge
// (bit-identical clip positions) with their third vertices more than a pixel apart on opposite
// sides of it, inside the clip volume. Uniforms: ivec4 fxport_rect, vec4 fxport_viewport, int
// fxport_vertices, int fxport_stride (floats per vertex), int fxport_unitW, uint fxport_stamp,
// ivec4 fxport_draw (count, first vertex or index, base vertex, indexed).
std::string compareShaderSource();

// Floats per captured vertex: gl_Position, then each of `captured` tightly packed.
int capturedFloatsPerVertex(const std::vector<GlslVarying>& captured);

// Layers of a replay store for `pixel`: the stamp, each input component it reads, gl_FragCoord's z and w if read.
int replayLayers(const PixelFunction& pixel);
// The replay key's part that depends on the pixel shader: its inputs' locations, types and qualifiers.
std::string inputSignature(const PixelFunction& pixel);
// Whether a pixel input it reads is interpolated with perspective (float, neither flat nor noperspective):
// then only w = 1 replays exactly (the driver may fuse the correction into the shader's arithmetic).
bool hasPerspectiveInput(const PixelFunction& pixel);
// Why `pixel`'s inputs cannot be fed by `captured` (an input without a vertex output at its location,
// or one with fewer components or another scalar kind); empty when they can.
std::string inputsRefusal(const PixelFunction& pixel, const std::vector<GlslVarying>& captured);

// The fill fragment shader (a separable program beside the draw's own vertex program): declares
// `pixel`'s inputs with their locations and qualifiers and imageStores their bits, then the
// uniform uint fxport_stamp, at its pixel of the store (no colour output).
std::string fillShaderSource(const PixelFunction& pixel);

// The compute shader (8x8 work groups) of `pixel` drawing into `targets`: each pixel of the
// dispatch whose store stamp is the current fill's runs the pixel function on the stored inputs.
// Uniform: ivec4 fxport_rect (x0, y0, x1, y1 exclusive, window pixels). Empty with `refusal` set
// when a target has no pixel shader output.
std::string computeShaderSource(const PixelFunction& pixel, const std::vector<ComputeTarget>& targets, std::string& refusal);

}  // namespace fxport::detail
