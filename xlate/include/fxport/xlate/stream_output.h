// Stream output (D3D10/11's SO stage): which values of a geometry shader's (or, for a "null" geometry
// shader, a vertex shader's) output vertices are written to buffers. An effect declares it with
// ConstructGSWithSO(shader, "POSITION.xyz; NORMAL.xyz; ..."), a D3D10/11 host with
// CreateGeometryShaderWithStreamOutput and its D3D1x_SO_DECLARATION_ENTRY array; both end here,
// resolved against the shader's outputs to the GLSL variables a GL program captures.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace fxport::xlate {

// A value a vertex-processing stage writes, as stream output finds it by semantic.
struct ShaderOutput {
    std::string semantic;  // upper case with index: "POSITION0", "SV_POSITION0"
    std::string glslName;  // the GLSL variable that holds it ("stream_pos", "gl_Position")
    int components = 4;    // 1..4
};

// One D3D1x_SO_DECLARATION_ENTRY.
struct StreamOutputEntry {
    int stream = 0;             // GS output stream 0..3
    std::string semanticName;   // as written; empty = a gap of componentCount components ($SKIP)
    int semanticIndex = 0;
    int startComponent = 0;     // 0..3
    int componentCount = 4;     // 1..4, startComponent + componentCount <= 4
    int outputSlot = 0;         // buffer slot 0..3
    std::string varying;        // resolved: the GLSL variable captured; empty for a gap
    bool operator==(const StreamOutputEntry&) const = default;
};

inline constexpr int kStreamOutputSlots = 4;
inline constexpr int kNoRasterizedStream = -1;  // D3D11_SO_NO_RASTERIZED_STREAM

struct StreamOutput {
    std::vector<StreamOutputEntry> entries;  // empty: no stream output
    std::array<int, kStreamOutputSlots> strides{};  // bytes from one vertex to the next, per slot
    int rasterizedStream = 0;                // 0..3, or kNoRasterizedStream
    bool empty() const { return entries.empty(); }
    bool operator==(const StreamOutput&) const = default;
};

// Appends the entries of one declaration string of `stream` ("[slot:]SEMANTIC[index][.mask]; ..."
// as the D3D10/11 effect runtimes read it: a mask is a run of xyzw or rgba, none means all four,
// `$SKIP` names a gap). False with the reason in `error`.
bool parseStreamOutputDeclaration(std::string_view text, int stream, std::vector<StreamOutputEntry>& entries, std::string& error);

// Checks `so` against the outputs of the shader that streams (D3D's rules, and what GL can capture),
// fills each entry's `varying` and, where a stride is 0, the slot's stride from its entries. False
// with the reason in `error`.
bool resolveStreamOutput(const std::vector<ShaderOutput>& outputs, StreamOutput& so, std::string& error);

// What a GL program is linked to capture (glTransformFeedbackVaryings, interleaved): the varyings
// of slot 0, `gl_NextBuffer`, slot 1 ..., gaps and stride padding as `gl_SkipComponentsN`. Only
// stream 0 is captured.
std::vector<std::string> capturedVaryings(const StreamOutput& so);

}  // namespace fxport::xlate
