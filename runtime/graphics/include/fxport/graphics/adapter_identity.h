// AdapterIdentity: what the driver says of the GPU it drives -- its name, its vendor, and its video
// memory where the driver tells it (front ends' adapter descriptions: DXGI's IDXGIAdapter::GetDesc).
//
//   AdapterIdentity id = device.adapterIdentity();  // "llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa", 0
#pragma once

#include <cstdint>
#include <string>

namespace fxport {

struct AdapterIdentity {
    std::string renderer;  // the driver's name of the GPU (GL_RENDERER), e.g. "NVIDIA H200/PCIe/SSE2"
    std::string vendor;    // the driver's vendor (GL_VENDOR), e.g. "NVIDIA Corporation", "Mesa"
    // How much video memory the driver reports, and what the number is: drivers tell it only through
    // vendor extensions, and not all of them (a software rasteriser has none).
    enum class Memory {
        Unknown,         // no extension: videoMemoryBytes is 0
        Dedicated,       // GL_NVX_gpu_memory_info's dedicated video memory (NVIDIA, Mesa)
        FreeForTextures  // GL_ATI_meminfo's free texture memory when asked (AMD's own driver)
    };
    Memory memory = Memory::Unknown;
    std::uint64_t videoMemoryBytes = 0;
};

}  // namespace fxport
