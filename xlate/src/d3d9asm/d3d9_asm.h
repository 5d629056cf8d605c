// D3D9 shader assembly (`VertexShader = asm { vs_1_1 ... };`) translated to an HLSL function that
// goes through the same pipeline as any effect shader (entry wrapper -> glslang -> SPIRV-Cross).
//
// The whole idea: an asm block is parsed into instructions (d3d9_asm_parse.cpp) and each
// instruction becomes one or two HLSL statements on float4 variables named like the registers
// (d3d9_asm_hlsl.cpp): r0..rN and a0 are locals, v#/t# inputs are parameters with the semantic
// their dcl (or the register number, for ps_1_x colours and texture coordinates) gives, outputs
// (oPos, oD#, oT#, oFog, oPts, oC#, oDepth, and r0 for ps_1_x) are `out` parameters. Constant
// registers are not uniforms: each c# read becomes the `def` literal or the expression the pass
// binds to it (`VertexShaderConstant4[0] = <WorldViewProj>` -> a column of WorldViewProj, see
// asm_pass_bindings.h), so the effect's parameters stay the only uniforms and the runtime uploads
// them as for HLSL shaders. Samplers are `<function>_s<stage>`; the caller turns them into effect
// samplers at the stage's texture unit. The result is a plain FxFunction the entry wrapper wraps.
//
// ps_1_x fixed point: D3D9 keeps ps_1_x temporaries in [-PixelShader1xMaxValue, +...], which is
// at least 1 (what D3D8-class hardware had). We compute in float and clamp every arithmetic result
// and every constant read to [-1, 1], the range every ps_1_x device guarantees; the final r0 is
// saturated as the colour output. The precision of 8-12 bit hardware is not imitated.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

class SourceMap;

// ---- parsed assembly ------------------------------------------------------------------------

struct AsmRegister {
    std::string type;      // lower-case: r v c t s a b i opos od ot ofog opts oc odepth
    int index = 0;
    bool relative = false; // c[a0.x + index]
    char relativeComponent = 'x';
};

struct AsmOperand {
    AsmRegister reg;
    std::string swizzle;   // as written, xyzw letters (rgba mapped); empty = none (dest: full mask)
    bool negate = false;   // -r0
    bool invert = false;   // 1-r0
    std::vector<std::string> modifiers;  // bias bx2 x2 dz db dw da abs (lower-case)
    bool isNumber = false; // def operands
    double number = 0;
    std::string text;      // first token, for diagnostics
};

struct AsmInstruction {
    std::string opcode;                  // lower-case base name: mad, dcl, texld ...
    std::vector<std::string> modifiers;  // after the opcode: sat x2 d2 pp / dcl usage (texcoord0, 2d ...)
    bool coissue = false;                // `+mov r0.a, ...` (ps_1_x)
    std::vector<AsmOperand> operands;
    int line = 0;                        // preprocessed line
    std::string text;                    // the opcode as written
};

struct AsmProgram {
    ShaderProfile profile;
    bool dx8Syntax = false;  // `vs.1.1`: a scalar source without swizzle reads .w (DX8), not .x (DX9)
    int versionLine = 0;
    std::vector<AsmInstruction> instructions;
};

// Parses the text between the braces of an asm block. `firstLine` is the preprocessed line the
// text starts on. Problems are appended to `diagnostics` (located through `map`); returns false
// when the block cannot be used.
bool parseAsmProgram(const std::string& text, int firstLine, ShaderStage expected, const SourceMap& map,
                     std::vector<Diagnostic>& diagnostics, AsmProgram& out);

// The source with every `;` comment inside an asm block turned into spaces (newlines kept). Run
// before the preprocessor, which would otherwise choke on `; it's` (an unclosed character literal).
std::string blankAsmLineComments(const std::string& source);

// ---- translation ----------------------------------------------------------------------------

struct AsmBindings {
    // Constant register -> float4 HLSL expression, from the pass's *ShaderConstant* states.
    std::map<int, std::string> constants;
    // Sampler stage -> what the pass binds there (ps_1_x declares no sampler dimensions).
    std::map<int, TextureKind> stageKinds;
    // Sampler stage -> bump-environment state (bumpenvmat00 ... bumpenvmat11, bumpenvlscale,
    // bumpenvloffset, lower-case) -> float HLSL expression, for texbem/texbeml/bem. Unset = 0.
    std::map<int, std::map<std::string, std::string>> bumpEnvironment;
};

struct TranslatedAsm {
    bool ok = false;
    std::string code;                     // HLSL: sampler declarations + the function
    FxFunction entry;                     // its signature, for the entry wrapper
    std::map<int, TextureKind> samplers;  // stage -> dimension the shader samples
};

std::string asmSamplerName(const std::string& functionName, int stage);

// `functionName` names the generated function (and its samplers, asmSamplerName); diagnostics go to
// `diagnostics`, located through `map`. `ok` is false after an error.
TranslatedAsm translateAsmProgram(const AsmProgram& program, const std::string& functionName, const AsmBindings& bindings,
                                  const SourceMap& map, std::vector<Diagnostic>& diagnostics);

}  // namespace fxport::xlate
