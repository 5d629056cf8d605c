// INTERNAL: one uniform block's CPU copy and the packing rules of the parameters in it: where
// scalar (element, row, column) of a parameter lives (HLSL packing, column_major or row_major, as
// the reflection says), how a value is stored as the parameter's scalar type, and the byte range
// that changed since the last upload. SetValue/GetValue, parameter defaults, layout changes and
// parameter-driven pass states all go through it; none walks the bytes on its own.
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport {

struct ConstantBlock {
    std::vector<std::uint8_t> bytes;
    int dirtyBegin = INT_MAX;  // [dirtyBegin, dirtyEnd): changed since the last upload
    int dirtyEnd = 0;

    // One scalar of a parameter: its index counted row by row, element by element (the order of
    // SetValue(float[]) and of parameter defaults), where it is, and its byte offset in the block.
    struct Scalar {
        int index, element, row, column, offset;
    };

    // Byte offset of element `element`, row `row`, column `column` (HLSL indexing) of `p`.
    static int offsetOf(const xlate::Parameter& p, int element, int row, int column) {
        int offset = p.offset + element * p.arrayStride;
        if (p.parameterClass == xlate::ParameterClass::Matrix)
            offset += p.rowMajor ? row * p.matrixStride + column * 4 : column * p.matrixStride + row * 4;
        else
            offset += column * 4;
        return offset;
    }
    bool holds(int offset) const { return offset >= 0 && std::size_t(offset) + 4 <= bytes.size(); }

    // Calls f(Scalar) for each scalar of the first `elements` elements of `p` that the block
    // holds (the optimiser may have trimmed the tail of an array or matrix).
    template <class F>
    void forEachScalar(const xlate::Parameter& p, int elements, F&& f) const {
        int index = 0;
        for (int el = 0; el < elements; ++el)
            for (int r = 0; r < p.rows; ++r)
                for (int c = 0; c < p.columns; ++c, ++index) {
                    int at = offsetOf(p, el, r, c);
                    if (holds(at)) f(Scalar{index, el, r, c, at});
                }
    }

    // Writes `value` at `offset` as `p`'s scalar type (float, int, bool as 0/1, uint).
    void encode(const xlate::Parameter& p, int offset, double value) {
        std::uint8_t* at = &bytes[std::size_t(offset)];
        if (p.type == xlate::ParameterType::Float) {
            float f = float(value);
            std::memcpy(at, &f, 4);
        } else if (p.type == xlate::ParameterType::Int) {
            std::int32_t n = std::int32_t(value);
            std::memcpy(at, &n, 4);
        } else {
            std::uint32_t n = p.type == xlate::ParameterType::Bool ? (value != 0 ? 1u : 0u) : std::uint32_t(value);
            std::memcpy(at, &n, 4);
        }
    }
    double decode(const xlate::Parameter& p, int offset) const {
        const std::uint8_t* at = &bytes[std::size_t(offset)];
        if (p.type == xlate::ParameterType::Float) {
            float f;
            std::memcpy(&f, at, 4);
            return f;
        }
        if (p.type == xlate::ParameterType::Int) {
            std::int32_t n;
            std::memcpy(&n, at, 4);
            return n;
        }
        std::uint32_t n;
        std::memcpy(&n, at, 4);
        return n;
    }

    // Stores value(Scalar) into every scalar of the first `elements` elements of `p` for which
    // wanted(Scalar) holds; one dirty range for the lot.
    template <class Value, class Wanted>
    void store(const xlate::Parameter& p, int elements, Value&& value, Wanted&& wanted) {
        int lo = INT_MAX, hi = 0;
        auto each = [&](auto&& write) {
            forEachScalar(p, elements, [&](const Scalar& s) {
                if (!wanted(s)) return;
                write(s);
                lo = std::min(lo, s.offset);
                hi = std::max(hi, s.offset + 4);
            });
        };
        if (p.type == xlate::ParameterType::Float) {  // the common case (matrices, float vectors): plain stores
            each([&](const Scalar& s) {
                float f = float(value(s));
                std::memcpy(&bytes[std::size_t(s.offset)], &f, 4);
            });
        } else {
            each([&](const Scalar& s) { encode(p, s.offset, value(s)); });
        }
        if (hi > lo) markDirty(lo, hi);
    }
    template <class Value>
    void store(const xlate::Parameter& p, int elements, Value&& value) {
        store(p, elements, value, [](const Scalar&) { return true; });
    }

    // Scalar `index` (row by row, element by element) of `p`; 0 where the block does not hold it.
    double load(const xlate::Parameter& p, int index) const {
        int perElement = p.rows * p.columns;
        int element = index / perElement, r = (index % perElement) / p.columns, c = index % p.columns;
        int at = offsetOf(p, element, r, c);
        return holds(at) ? decode(p, at) : 0.0;
    }

    void markDirty(int begin, int end) {
        dirtyBegin = std::min(dirtyBegin, begin);
        dirtyEnd = std::max(dirtyEnd, end);
    }
};

}  // namespace fxport
