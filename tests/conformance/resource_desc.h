// What the resource-like blocks of a .shader_test say, parsed: [srv N]/[uav N]/[rtv N]/[dsv]/[vb N],
// [sampler N], [input layout] and [require]. Parsing only; gpu_session.cpp makes the objects.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shader_test_file.h"

namespace conformance {

// DXGI-style formats the suite names ("r32g32b32a32-float" ...).
struct Format {
    std::string name = "r32g32b32a32-float";
    int components = 4;
    char type = 'f';  // 'f' float, 'u' uint, 's' sint, 't' typeless
    bool shadow = false;
};
Format parseFormat(const std::string& text, std::string* rest = nullptr);

struct ResourceDesc {
    BlockKind kind = BlockKind::Srv;
    int slot = 0;
    Format format;
    std::string dimension = "2d";  // 2d, 2dms, 2darray, 3d, cube, buffer, raw_buffer, counter_buffer
    int width = 1, height = 1, depth = 1, levels = 1, samples = 1;
    int stride = 0;                  // structured buffers
    std::vector<std::uint32_t> data;  // raw 32-bit words as vkd3d reads them (ints unless a '.' is seen)
    bool sizeGiven = false;
};
ResourceDesc parseResource(const Block& block);

enum class Filter { Point, Linear };
enum class Address { Wrap, Mirror, Clamp, Border, MirrorOnce };
struct SamplerDesc {
    int slot = 0;
    Filter min = Filter::Point, mag = Filter::Point, mip = Filter::Point;  // vkd3d's default: point, clamp
    Address u = Address::Clamp, v = Address::Clamp, w = Address::Clamp;
    bool comparison = false;
    std::string comparisonFunc;
};
SamplerDesc parseSampler(const Block& block);

struct InputElement {
    int slot = 0;
    Format format;
    std::string semantic;  // as written ("position", "TEXCOORD")
    int index = 0;
};
std::vector<InputElement> parseInputLayout(const Block& block);

// A [require] block: the model range and what else the section after it needs.
struct RequireDesc {
    int minModel = 20;
    int maxModel = 62;
    std::string matrixPacking;              // "", "row-major", "column-major"
    bool backcompat = false;
    std::vector<std::string> capabilities;  // float64, geometry-shader, "format r32-float uav-load" ...
};
RequireDesc parseRequire(const Block& block);

}  // namespace conformance
