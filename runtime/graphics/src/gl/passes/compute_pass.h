// INTERNAL: compute passes (DeviceOptimizations::ComputePasses, issue 16 item 4). A draw of at
// most two triangles whose state a compute dispatch can honour exactly runs as one, fed the
// values the rasteriser itself interpolated, so its pixels are the fragment stage's bit for bit:
//  1. its own vertex shader under transform feedback (rasteriser discarded) into a small buffer;
//  2. a one-invocation compare step (detail::compareShaderSource) that compares that capture,
//     bit for bit, with the one its replay entry was filled from, and writes indirect commands;
//  3. when they differ, a "fill" draw -- the draw itself, its own vertex program and raster state,
//     with a fragment shader that stores the pixel shader's inputs per covered pixel -- refills the
//     entry's store (an r32ui 2D array texture);
//  4. a compute shader generated from the pixel shader reads the inputs back and imageStores the
//     targets, only where the fill covered;
//  5. when the draw may not replay exactly (a perspective input with w != 1, triangles that could
//     cover a pixel twice) the GPU draws it with the fragment stage instead (an indirect draw).
// Everything else draws as before; why a candidate fell back is counted per reason
// (GraphicsDevice::computePassStatistics, fxdemo --explain).
#pragma once

#include <array>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/compute_passes.h"
#include "device/draw_hints.h"
#include "gl/passes/compute_pass_source.h"
#include "gl/draw_call.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/gl.h"

namespace fxport {

class Texture2D;

namespace detail {
// The image format a compute shader stores `format` with; null when GL has none for it (packed
// 16-bit formats, sRGB).
const char* imageFormatOf(SurfaceFormat format);
// Compiles and links one stage; 0 and the log's first line in `error` on failure. `captured`:
// transform feedback varyings.
GLuint linkProgram(GLenum stage, const std::string& source, const std::vector<std::string>& captured, bool printLog,
                   std::string& error, bool separable = false);
// The pixels a draw may touch, [x0, x1) x [y0, y1): the viewport (GL clips to it) within a
// targetWidth x targetHeight target and, when the rasterizer state enables it, the scissor.
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PixelBox drawablePixels(const GraphicsDevice& device, int targetWidth, int targetHeight);
// One sprite that copies texels 1:1 (texel_copies.cpp): the pixels [x0, x1) x [y0, y1) of the
// viewport, and the texel that lands on pixel (x0, y0).
using TexelCopy = fxport::TexelCopy;  // device/draw_hints.h
// GLSL of the reduction over texel copies (texel_copies.cpp): `op` min or max per part.
std::string texelCopyShaderSource(const std::string& imageFormat, BlendOp color, BlendOp alpha, unsigned writeMask);
}  // namespace detail

// What a shader's GLSL allows, read once per ShaderProgram (ShaderProgram::computeAnalysis).
struct ComputeAnalysis {
    int serial = 0;          // names the analysis in the program caches (a ShaderProgram's address may be reused)
    std::string refusal;     // why this shader cannot take part; empty when it can
    detail::VertexOutputs vertex;  // vertex shaders
    detail::PixelFunction pixel;   // pixel shaders
    int inputsId = 0;  // pixel shaders: names detail::inputSignature (pixel shaders that read the same inputs share replay entries)
};

// The GL implementation of device/compute_passes.h.
struct GlComputePasses final : ComputePasses {
    explicit GlComputePasses(GraphicsDevice& owner);
    ~GlComputePasses() override;
    GraphicsDevice& device;

    // Runs the current draw (flushed, vertex array bound) as a compute dispatch when it may.
    // False: draw it as usual.
    bool tryDraw(PrimitiveType type, int primitiveCount, const DrawCall& draw) override;

    // SpriteBatch (sprite_batch.cpp), for a batch of sprites drawn with its own effect whose every
    // sprite copies texels 1:1 (white, unrotated, unflipped, whole pixels, Point sampling): under a
    // Min or Max blend the batch's pixels are the min (max) over the sprites covering them and the
    // target, in any order, so one dispatch computes them (texel_copies.cpp). Flushes and
    // dispatches, or returns false (nothing done: draw it as usual).
    bool tryTexelCopies(const Texture2D& texture, const std::vector<detail::TexelCopy>& copies) override;

    // Deletes the programs and replay entries made for a shader whose effect releases its programs.
    void forget(const ComputeAnalysis& analysis) override;

    // The statistics, with the GPU's counters as far as it has got (read without waiting: draws it
    // has not run yet are not counted; a read-back of a target waits for them).
    ComputePassStatistics currentStatistics() override;

private:
    bool fallBack(const std::string& reason);
    const ComputeAnalysis& analysisOf(const struct ShaderProgram& program);
    GLuint captureProgram(const struct ShaderProgram& vertex, const ComputeAnalysis& analysis, std::string& refusal);
    GLuint fillPipeline(const struct ShaderProgram& vertex, int vertexSerial, const ComputeAnalysis& pixel, std::string& refusal);
    struct ReplayEntry;
    struct EntryKey;
    ReplayEntry* entryFor(const EntryKey& key, int width, int height, int layers, int capturedFloats, std::string& refusal);
    void readCounters();

    ComputePassStatistics statistics;  // what the CPU decided; the GPU's counters are added on reading
    bool printOutcomes = false;  // $FXPORT_COMPUTE_PASSES_DEBUG: each candidate's outcome and failed compiles on stderr
    int nextSerial = 1;
    std::map<std::string, int> inputSignatures;  // detail::inputSignature -> ComputeAnalysis::inputsId
    // The caches are keyed by numbers made once per shader (a draw builds no string): the programs
    // per shader serial, the compute programs also per target (detail::ComputeTarget, packed), and
    // each keeps why it could not be made beside its program 0.
    struct Capture {
        GLuint program = 0;
        std::string failure;
    };
    std::map<int, Capture> capturePrograms;  // per vertex shader serial
    struct Dispatcher {
        GLuint program = 0;
        GLint rect = -1;
        std::string failure;
    };
    using TargetKeys = std::array<std::uint32_t, kMaxRenderTargets>;  // 0: no target
    std::map<std::pair<int, TargetKeys>, Dispatcher> computePrograms;  // (pixel serial, targets)
    GLuint captureBuffer = 0;
    GLsizeiptr captureBytes = 0;

    // Fill fragment programs per pixel shader serial, and their pipelines with a vertex program
    // (vertex serial, pixel serial).
    struct Fill {
        GLuint program = 0;
        GLint stamp = -1;
        std::string failure;
    };
    std::map<int, Fill> fillPrograms;
    std::map<std::pair<int, int>, GLuint> fillPipelines;
    GLuint fillFramebuffer = 0;  // no attachments, as large as the target (GL_FRAMEBUFFER_DEFAULT_*)
    int fillWidth = 0, fillHeight = 0;
    std::uint32_t nextStamp = 1;

    // Replay entries, least recently used first in `recency`, bounded by `byteBudget`. The key is
    // everything besides the vertices that decides what the rasteriser gives the pixel shader
    // (floats by their bits: 0.5 and 0.5000001 are other depth ranges).
    struct EntryKey {
        int vertexSerial = 0, inputsId = 0;
        int viewportX = 0, viewportY = 0, viewportWidth = 0, viewportHeight = 0;
        std::uint32_t minDepthBits = 0, maxDepthBits = 0;
        int cullMode = 0;
        std::uint32_t depthBiasBits = 0, slopeScaleDepthBiasBits = 0;
        int primitiveType = 0, primitiveCount = 0, targetWidth = 0, targetHeight = 0;
        auto operator<=>(const EntryKey&) const = default;
    };
    struct ReplayEntry {
        GLuint store = 0;     // r32ui 2D array: layer 0 the stamp of the fill that covered the pixel, then the inputs' bits
        GLuint vertices = 0;  // the stamp of its fill and the captured vertices it was filled from (detail::kEntry*)
        std::int64_t bytes = 0;
        std::list<EntryKey>::iterator recency;
    };
    // User-vertex draws per replay key: the last one's DrawCall::userDataHash, and how many draws
    // in a row came with other bytes than the one before (a sprite that moves every draw would
    // refill every time, which costs more than drawing it: such draws are drawn as usual). Kept
    // apart from the entries so that a key drawn as usual holds no store.
    struct UserDataHistory {
        std::uint64_t lastHash = 0;
        int changedInARow = 0;
    };
    std::map<EntryKey, UserDataHistory> userDataHistory;
    std::map<EntryKey, ReplayEntry> entries;
    std::list<EntryKey> recency;
    std::int64_t entryBytes = 0, byteBudget = 512ll << 20;  // lighting2d at 1920x1080 holds 388 MiB
    void dropEntry(std::map<EntryKey, ReplayEntry>::iterator it);

    // The compare step (detail::compareShaderSource) and the commands buffer it writes: made at the first dispatch.
    struct Compare {
        GLuint program = 0, commands = 0;
        GLuint counters = 0;                            // persistently mapped (detail::kCountersBinding)
        const volatile std::uint32_t* mapped = nullptr;
        GLint rect = -1, viewport = -1, vertices = -1, stride = -1, unitW = -1, stamp = -1, draw = -1;
        bool failed = false;
        std::string failure;
    } compare;
    std::uint32_t counters[4] = {};  // the GPU's, as last read

    // Texel-copy reductions (texel_copies.cpp): programs per (format, colour op, alpha op, write
    // mask), the copies' buffer.
    struct Reduction {
        GLuint program = 0;
        GLint box = -1, count = -1;
        std::string failure;
    };
    std::map<std::array<int, 4>, Reduction> reductionPrograms;
    GLuint copiesBuffer = 0;
};

}  // namespace fxport
