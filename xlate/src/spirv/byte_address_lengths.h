// Step 4d: ByteAddressBuffer.GetDimensions in bytes. D3D reports a (RW)ByteAddressBuffer's size in
// bytes; glslang declares the buffer as a runtime array of uint and answers GetDimensions with
// OpArrayLength, the count of words, so a shader that loops to `size` or divides it by a stride
// read a quarter of the buffer. In SPIR-V such a buffer cannot be told from a
// StructuredBuffer<uint>, so the HLSL text names them: every OpArrayLength of a global buffer
// declared as a byte-address buffer is multiplied by 4. Run after legalisation, when every access
// goes through the global variable (a buffer passed to a function has been inlined).
#pragma once

#include <set>
#include <string>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// The names declared with type ByteAddressBuffer or RWByteAddressBuffer in `hlsl`.
std::set<std::string> byteAddressBufferNames(const std::string& hlsl);

// Multiplies the OpArrayLength of each global buffer named in `names` by 4.
bool byteAddressLengthsInBytes(ParsedSpirv& m, const std::set<std::string>& names);

}  // namespace fxport::xlate
