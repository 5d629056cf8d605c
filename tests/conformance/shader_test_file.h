// The parsed form of one vkd3d-shader `.shader_test` file: its blocks in file order, each with the
// lines it holds. Nothing here is evaluated for a shader model; file_run.cpp walks the blocks once
// per model. The format is vkd3d's (tests/shader_runner.c in a vkd3d tree): `[require]`, shader
// sections with `fail(...)`/`todo(...)`/`notimpl(...)` qualifiers, resources, `[test]` ...
#pragma once

#include <string>
#include <vector>

namespace conformance {

enum class BlockKind {
    Require, Shader, Srv, Uav, Rtv, Dsv, VertexBuffer, Sampler, InputLayout, Test, Preproc, PreprocFail,
};

// Shader section kinds, as the report groups them.
enum class Stage { Pixel, Vertex, Effect, Geometry, Compute, Hull, Domain };
const char* stageName(Stage stage);

struct Line {
    int number = 0;     // 1-based line in the file
    std::string text;   // without the newline
};

struct Block {
    BlockKind kind = BlockKind::Test;
    int line = 0;              // the `[...]` header's line
    std::string header;        // the header without brackets: "pixel shader fail(sm<4)"
    Stage stage = Stage::Pixel;        // Shader blocks
    std::string qualifiers;    // Shader blocks: what follows the stage name ("fail(sm<4) todo")
    bool hexBytecode = false;  // Shader blocks given as d3dbc-hex / dxbc-*-hex: no HLSL to compile
    int slot = 0;              // [srv N], [uav N], [rtv N], [vb N], [sampler N]
    std::vector<Line> lines;   // content lines; `%` comments and blank lines dropped except in shaders
    std::string source() const;  // Shader blocks: the HLSL text (every line, as written)
};

struct ShaderTestFile {
    std::string path;
    std::string name;  // file name without folder and ".shader_test"
    std::vector<Block> blocks;
};

// Throws std::runtime_error "file:line: ..." on a header it does not know.
ShaderTestFile parseShaderTestFile(const std::string& path);

}  // namespace conformance
