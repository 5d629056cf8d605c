// What a GraphicsDevice's optimisation passes (fxport/graphics/device_optimizations.h) did, and the GPU
// objects it holds: GraphicsDevice::depthStorageStatistics(), clearStatistics(),
// computePassStatistics(), liveGpuObjects(). Reading them costs nothing when nobody asks.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace fxport {

// Live GL objects made by this device (textures, renderbuffers, buffers, programs, pipelines,
// framebuffers, vertex arrays, queries): what the resource-lifetime test checks returns to zero.
struct GpuObjectCounts {
    int textures = 0, renderbuffers = 0, buffers = 0, programs = 0, pipelines = 0, framebuffers = 0,
        vertexArrays = 0, queries = 0;
    int total() const { return textures + renderbuffers + buffers + programs + pipelines + framebuffers + vertexArrays + queries; }
};

// Depth/stencil buffers over the device's life (DeviceOptimizations::LazyDepthStorage): bytes
// as drivers store them (Depth16 2 per pixel, Depth24 and Depth24Stencil8 4).
struct DepthStorageStatistics {
    long requested = 0;                // render targets and back buffers made with a DepthFormat
    long allocated = 0;                // their buffers made in GL (at a draw that needed one, or at once)
    std::int64_t requestedBytes = 0, allocatedBytes = 0;
    long invalidated = 0;              // depth/stencil contents given up on leaving a DiscardContents target
    long unallocated() const { return requested - allocated; }  // targets never drawn with depth or stencil
    std::int64_t savedBytes() const { return requestedBytes - allocatedBytes; }
};

// What the device did with the clears it was asked for (DeviceOptimizations::DeferClears).
struct ClearStatistics {
    long requested = 0;  // channel clears asked for (colour, depth, stencil each count; SetRenderTargets' too)
    long executed = 0;   // channel clears sent to GL
    long replaced = 0;   // pending channel clears overwritten by a later clear before any use
    long dropped = 0;    // depth/stencil clears of a DiscardContents target left before any draw tested them
    long discarded = 0;  // pending channel clears dropped by DiscardContents
    long covered = 0;    // pending colour clears dropped under a SpriteBatch sprite that writes every pixel
    long blendsAsWrites = 0;  // draws blending onto the zero clear executed for them, drawn as writes (same bits)
};

// What DeviceOptimizations::ComputePasses did: draws run as compute dispatches, and, for draws
// that were candidates (at most two triangles) but were drawn as usual, how many per reason. The
// GPU decides part of it (whether the vertices changed, w = 1, overlap); its counters are read
// without waiting, so draws it has not run yet are not counted (a read-back of a target waits).
struct ComputePassStatistics {
    long issued = 0;      // draws sent to the GPU as compute passes, counted at once (the GPU may still
                          // draw some as usual: fellBack's GPU reasons)
    long dispatched = 0;  // draws run as compute dispatches
    long replayed = 0;    // of those, from interpolants stored by an earlier draw (no fill)
    std::map<std::string, long> fellBack;
    long entries = 0;              // replay entries held now
    std::int64_t entryBytes = 0;   // their GPU memory (bounded by $FXPORT_COMPUTE_PASS_CACHE_MB, 512 by default)
    long evicted = 0;              // entries dropped to stay within the bound
};

}  // namespace fxport
