// DeviceOptimizations: the passes a GraphicsDevice may run between the calls it is given and the GPU
// (docs/DESIGN.md, "What a draw does"), each an fxport addition that leaves the pixels as XNA draws
// them. PresentationParameters::Optimizations holds them; DeviceOptimizations::None() switches every
// one off (each clear, buffer and draw runs as written). Their effects are counted in
// fxport/graphics/device_statistics.h.
#pragma once

#include <optional>

namespace fxport {

struct DeviceOptimizations {
    // Clears of a whole target are recorded and sent to the GPU only when a draw or read needs the
    // channel; a clear replaced by a later one, or a depth/stencil clear of a DiscardContents target
    // that no draw tested, never runs (ClearStatistics). $FXPORT_DEFER_CLEARS=0 or 1 overrides it.
    bool DeferClears = true;
    // GraphicsDevice::DiscardContents drops what it names; off, it does nothing, so every clear runs
    // as written. $FXPORT_HONOUR_DISCARDS=0 or 1 overrides it.
    bool HonourDiscards = true;
    // A render target's depth/stencil buffer (the back buffer's too) is made at the first draw into
    // it that tests depth or stencil, so a target never drawn with depth takes no memory
    // (DepthStorageStatistics); leaving a DiscardContents target tells the GPU its depth/stencil is
    // no longer needed (XNA clears them at its next binding). DepthStencilFormat reports the format
    // asked for either way. $FXPORT_LAZY_DEPTH=0 or 1 overrides it.
    bool LazyDepthStorage = true;
    // A pending colour clear is dropped under a SpriteBatch sprite that provably writes every pixel
    // of the target (ClearStatistics::covered), and a draw that blends onto a zero colour clear
    // executed for it, on an unsigned-normalized target with source factor One and Add, Subtract or
    // Max, draws as the write it amounts to (ClearStatistics::blendsAsWrites; same bytes).
    // $FXPORT_DROP_COVERED_CLEARS=0 or 1 overrides it.
    bool DropCoveredClears = true;
    // A draw of at most two triangles (a FullscreenQuad, a one-sprite SpriteBatch batch) whose state a
    // compute dispatch honours exactly -- no depth or stencil test, no blending but Min/Max (and
    // One/One on 32-bit float targets), targets with an image format, a pixel shader without
    // derivatives -- runs as a compute shader generated from its pixel shader, fed the values the
    // rasteriser itself interpolated for an earlier draw with bit-identical vertices, so the pixels
    // are the fragment stage's (ComputePassStatistics). Unset (the default): on where this GPU's
    // compute shaders write images at least kComputePassesWhereFaster times as fast as its fragment
    // stage writes a Color target (GpuLimits, measured once per GPU and cached), never on a software
    // rasteriser; true/false force it. $FXPORT_COMPUTE_PASSES=1 or 0 overrides both.
    std::optional<bool> ComputePasses;

    // Every optimisation off.
    static DeviceOptimizations None() { return {false, false, false, false, false}; }
    // These, with the environment's overrides above applied: the one place fxport reads them (the
    // device calls it once, when it is made). A value other than 0 or 1 is ignored with a message on
    // stderr.
    DeviceOptimizations withEnvironment() const;
};

// ComputePasses left unset turns compute passes on where the GPU's compute image writes are at least
// this many times its fragment output (the H100 measured 393 against 56 GB/s: x7; llvmpipe runs
// compute passes several times slower than its rasteriser).
inline constexpr double kComputePassesWhereFaster = 2.0;

}  // namespace fxport
