// INTERNAL: compute passes (PresentationParameters::ComputePasses, issue 16 item 4). A draw of at
// most two triangles whose state a compute dispatch can honour exactly runs as one: its own vertex
// shader through transform feedback (rasteriser discarded) into a small buffer, then a compute
// shader generated from its pixel shader (compute_pass_source.h) that rasterises those triangles
// per pixel and imageStores the targets. Everything else draws as before; why a candidate fell
// back is counted per reason (GraphicsDevice::computePassStatistics, fxdemo --explain).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "compute_pass_source.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/gl.h"

namespace fxport {

// What a shader's GLSL allows, read once per ShaderProgram (ShaderProgram::computeAnalysis).
struct ComputeAnalysis {
    int serial = 0;          // names the analysis in the program caches (a ShaderProgram's address may be reused)
    std::string refusal;     // why this shader cannot take part; empty when it can
    detail::VertexOutputs vertex;  // vertex shaders
    detail::PixelFunction pixel;   // pixel shaders
};

struct ComputePasses {
    explicit ComputePasses(GraphicsDevice::Impl& owner);
    ~ComputePasses();
    GraphicsDevice::Impl& device;

    // Runs the current draw (flushed, vertex array bound) as a compute dispatch when it may:
    // `issueDraw` repeats the draw's GL call under transform feedback. False: draw it as usual.
    bool tryDraw(PrimitiveType type, int primitiveCount, const std::function<void()>& issueDraw);

    // Deletes the programs made for a shader whose effect releases its programs.
    void forget(const ComputeAnalysis& analysis);

    ComputePassStatistics statistics;

private:
    bool fallBack(const std::string& reason);
    const ComputeAnalysis& analysisOf(const struct ShaderProgram& program);
    GLuint captureProgram(const struct ShaderProgram& vertex, const ComputeAnalysis& analysis, std::string& refusal);

    bool printOutcomes = false;  // $FXPORT_COMPUTE_PASSES_DEBUG: each candidate's outcome and failed compiles on stderr
    int nextSerial = 1;
    std::map<int, GLuint> captureProgramsBySerial;  // 0: the capture program did not link
    struct Dispatcher {
        GLuint program = 0;  // 0: it could not be made (failures says why)
        GLint rect = -1, viewport = -1, depthRange = -1, triangles = -1, cull = -1;
    };
    std::map<std::string, Dispatcher> computePrograms;  // "vertex serial/pixel serial/targets" -> program
    std::map<std::string, std::string> failures;        // why a capture or compute program could not be made
    GLuint captureBuffer = 0;
    GLsizeiptr captureBytes = 0;
    // The bounds step (detail::boundsShaderSource) and the buffer it writes: made at the first dispatch.
    struct Bounds {
        GLuint program = 0, buffer = 0;
        GLint rect = -1, viewport = -1, vertices = -1, stride = -1;
        bool failed = false;
    } bounds;
};

}  // namespace fxport
