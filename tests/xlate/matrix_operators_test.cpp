// Operators on matrices computed per component, as fxc computes them (xlate/src/rewrite/
// matrix_operators.h): each form compiles as a loose shader (fxc /T), where glslang 12 refused it,
// crashed or computed a matrix product. The values are pinned by tests/runtime (hlsl_shapes_test,
// hlsl_integer_matrices_test) against C++ arithmetic.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

// `body` as the statements of a compute shader's main, after `globals`; the GLSL compiled.
std::string compileCompute(const std::string& globals, const std::string& body) {
    fs::path dir = fs::temp_directory_path() / ("fxport-matrix-operators-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "shader.hlsl";
    std::ofstream(file) << globals << "\nRWStructuredBuffer<float4> o;\n[numthreads(1, 1, 1)]\nvoid main(uint i : SV_GroupIndex)\n{\n"
                        << body << "\n}\n";
    CompileOptions options;
    options.useCache = false;
    return compileShaderFiles({{file.string(), "main", "cs_5_0"}}, options).shaders.at(0).glsl;
}

}  // namespace

// float2x3 * float2x3 and `*=`: glslang refused them ("Could not perform requested binary operation").
TEST(MatrixOperators, NonSquareMatrixTimesMatrixCompiles) {
    EXPECT_NE(compileCompute("float2x3 C;", "float2x3 q = C * C; q *= C; o[0] = float4(q[0], q[1].x);"), "");
}

// float2x2 * float2x2 multiplies rows in the GLSL, not the whole matrices (glslang's
// OpMatrixTimesMatrix before: `spvWorkaroundRowMajor(_19.A) * spvWorkaroundRowMajor(_19.B)`).
TEST(MatrixOperators, SquareMatrixTimesMatrixIsNoMatrixProduct) {
    const std::string glsl = compileCompute("float2x2 A; float2x2 B;", "float2x2 p = A * B; o[0] = float4(p[0], p[1]);");
    EXPECT_FALSE(std::regex_search(glsl, std::regex(R"(\(\w+\.A\) \*)"))) << glsl;
    EXPECT_TRUE(std::regex_search(glsl, std::regex(R"(\(\w+\.A\)\[1\] \*)"))) << glsl;
}

// Every operator on int and uint matrices of each shape (glslang crashed on them with SIGSEGV, or
// failed with "Id is 0" for the compound assignments and `++`/`--` and refused `e * e`); DirectXTex BC7Encode's
// `return quantized << 2;` on a uint2x4.
TEST(MatrixOperators, IntegerMatrixOperatorsCompile) {
    const char* const types[] = {"int2x3", "uint2x4", "int2x2", "int3x3"};
    const char* const forms[] = {"e + 1", "e - 1", "e / 2", "e % 3", "e & 3", "e | e", "e ^ 1", "e << 2", "e >> 2", "-e", "2 + e", "e * e"};
    for (const char* type : types) {
        std::string body = std::string(type) + " e = (" + type + ")i;\n";
        for (const char* form : forms) body += std::string("e = ") + form + ";\n";
        body += "e += 1; e -= i; e *= e; e /= 2; e %= 5; e &= 3; e |= 4; e ^= 1; e <<= 2; e >>= 1; e++; ++e; e--; --e;\no[0] = float4(e[0].xy, e[1].xy);";
        EXPECT_NE(compileCompute(std::string(type) + " f(inout " + type + " q) { q[0] <<= 3; return q << 2; }", body + " f(e);"), "") << type;
    }
}

// Comparisons of matrices give bool matrices (glslang crashed on them), stored, passed to any()
// or used as a `?:` condition, also with branches of other types (a uint scalar and an int2x3:
// fxport's select helper took both as uint2x3 before) and scalar branches (BC6HEncode's
// `uint2x3 s = color >= 0 ? 0 : 1;`).
TEST(MatrixOperators, MatrixComparisonsCompile) {
    EXPECT_NE(compileCompute("uint g;",
                             "float2x2 m = (float2x2)i; bool2x2 b = m > 1; float2x2 f = (m > 1) ? m : 0; o[0] = any(m > 1);\n"
                             "int2x3 e = (int2x3)i; e = (e == 7) ? g : e; uint2x3 s = e >= 0 ? 0 : 1;\n"
                             "e = ((i >= 15) | (e == 0)) ? e : -e; o[1] = float4(b[0], f[1]) + e[0].xyzz + s[1].xyzz;"),
              "");
}

// Operators on matrices in an `if` or `while` condition, in the arguments of a call made as a
// statement and in a `for` header's step are spelled out too (glslang crashed on them there as well).
TEST(MatrixOperators, OperatorsInConditionsAndCallStatementsCompile) {
    EXPECT_NE(compileCompute("static int2x3 kept; void put(int2x3 v) { kept = v; }",
                             "int2x3 e = (int2x3)i; float2x2 m = (float2x2)i;\n"
                             "if (any(m > 1)) o[0] = 1;\nelse put(e << 2);\nwhile (all(e == 3)) { put(-e); e += 1; }\n"
                             "for (int k = 0; k < 2; e = e << 1) ++k;\no[0] = kept[0].xyzz;"),
              "");
}
