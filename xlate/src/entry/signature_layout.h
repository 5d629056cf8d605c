// How fxc lays a shader entry's inputs and outputs onto semantics (its signature), for the entry
// wrapper (entry_wrapper.cpp) and fxc's semantic checks (entry_semantics.cpp) alike:
//  - a matrix takes one semantic index per register: one per column, or per row when row_major
//    (D3D's default packing is column-major);
//  - an array takes consecutive indices, element after element;
//  - a semantic on a struct (a parameter, the return value, a struct member of struct type)
//    cascades: it overrides every semantic inside, and the struct's leaves take consecutive
//    indices from it in declaration order, arrays of structs element after element (vkd3d's
//    semantic-cascading pins fxc's behaviour).
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

// Semantic registers one value of type `b` takes: 1 for scalars and vectors; a matrix's columns,
// or its rows when `modifiers` holds row_major.
int signatureRegisters(const BasicType& b, const std::vector<std::string>& modifiers);

// Width of each of those registers.
int signatureWidth(const BasicType& b, const std::vector<std::string>& modifiers);

// The outermost semantic on a struct while its leaves are flattened; inactive when none was given.
struct SemanticCascade {
    bool active = false;
    std::string base;  // upper case, without the index
    int next = 0;      // the index the next leaf takes

    // A cascade from `semantic` (e.g. "CASCADE", "SEMA3"); inactive when it is empty.
    static SemanticCascade from(const std::string& semantic);
    // The semantic (base and first index) of a leaf of `registers` registers; moves past it.
    std::pair<std::string, int> take(int registers);
};

// Majority modifiers (row_major, column_major) written before `entry`'s name: its result's.
std::vector<std::string> entryReturnModifiers(const EffectSyntax& syntax, const FxFunction& entry);

// Every element access of `access` with array dimensions `dims`, in memory order:
// ("a", {2, 2}) -> a[0][0], a[0][1], a[1][0], a[1][1]; ("a", {}) -> a. Empty when the product
// exceeds `limit` (sizes come from the source).
std::vector<std::string> arrayElementAccesses(const std::string& access, const std::vector<int>& dims, size_t limit = 1024);

}  // namespace fxport::xlate
