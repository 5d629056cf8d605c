// Step 2 of the compiler: what the effect framework says, parsed from the preprocessed tokens.
// glslang knows plain HLSL only; everything here (techniques, passes, sampler_state, texture
// objects, state objects, shader variables, annotations) is recorded and later removed from the
// text, keeping line numbers (see fx_rewrite).
#pragma once

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "fxport/xlate/compiled_effect.h"
#include "fx/lexer.h"

namespace fxport::xlate {

struct TokenSpan {
    size_t begin = 0;  // first token index
    size_t end = 0;    // one past the last token
    bool empty() const { return begin >= end; }
};

// `Name[index] = value;` in a pass, sampler_state or state object, or `SetX(args);` in a DX10 pass
// (then `isCall` and `value` spans the arguments).
struct FxAssignment {
    std::string name;
    int index = -1;
    TokenSpan value;
    size_t nameToken = 0;
    bool isCall = false;
};

// The right-hand side of `VertexShader = ...` / `SetVertexShader(...)` / a shader variable.
struct FxShaderExpr {
    enum class Kind { Compile, Variable, ArrayElement, Null, Asm, StreamOut, Invalid } kind = Kind::Invalid;
    std::string profile;    // Compile
    std::string entry;      // Compile
    std::string arguments;  // Compile: literal arguments as written, e.g. "true, 3"
    std::string variable;   // Variable / ArrayElement
    TokenSpan index;        // ArrayElement: the index expression
    TokenSpan asmBlock;     // Asm: from '{' to '}' of `asm { ... }` (see d3d9_asm.h)
    // StreamOut: ConstructGSWithSO(shader, decl) (Effects 10) or (shader, decl0..decl3, rasterized
    // stream) (Effects 11): the shader's tokens and each argument after it (a string, NULL or a number).
    TokenSpan streamShader;
    std::vector<TokenSpan> streamArguments;
    size_t token = 0;       // for diagnostics
};

struct FxPass {
    std::string name;
    std::vector<Annotation> annotations;
    std::vector<FxAssignment> assignments;
    size_t token = 0;
};

struct FxTechnique {
    std::string name;
    std::vector<Annotation> annotations;
    std::vector<FxPass> passes;
    size_t token = 0;
};

// DX10 BlendState / DepthStencilState / RasterizerState objects.
struct FxStateObject {
    std::string type;
    std::string name;
    std::vector<FxAssignment> assignments;
    size_t token = 0;
};

// One `register([profile,] xN)` of an object, as written: which shaders it binds in is decided per
// shader (d3d_registers.h).
struct FxRegister {
    std::string profile;  // "", "ps", "ps[5]", "ps_4_0" ...
    char registerClass = 0;  // lower case
    int index = -1;
};

// A sampler: DX9 `sampler S = sampler_state {...};` / `sampler2D S : register(s1);`, or DX10
// `SamplerState S { ... };`.
struct FxSampler {
    std::string name;
    std::string type;          // as written: sampler, sampler2D, samplerCUBE, SamplerState ...
    bool dx10 = false;         // SamplerState / SamplerComparisonState
    int explicitUnit = -1;     // register(sN)
    std::vector<FxRegister> registers;  // every register() written
    std::vector<FxAssignment> states;
    TokenSpan declaration;     // the whole declaration incl. ';' (rewritten later)
    size_t token = 0;
};

struct FxTexture {
    std::string name;
    std::string type;  // texture, texture2D, textureCUBE ... (DX9 objects), Texture2D ... (DX10)
    bool dx9Object = false;
    std::vector<int> arrayDims;  // `Texture2D T[5]` -> {5}
    int explicitUnit = -1;  // register(tN)
    std::vector<FxRegister> registers;  // every register() written
    std::string semantic;
    std::vector<Annotation> annotations;
    TokenSpan declaration;
    size_t token = 0;
};

struct FxShaderVariable {
    std::string name;
    std::string type;  // VertexShader / PixelShader / GeometryShader
    bool isArray = false;
    std::vector<FxShaderExpr> elements;
    size_t token = 0;
};

// A global variable kept in the HLSL (it becomes a constant-buffer member unless static).
struct FxGlobal {
    std::string name;
    std::string type;  // type text, e.g. "float4x4", "bool", "vector<float,4>"
    std::vector<std::string> modifiers;  // lower-case: static, const, uniform, row_major ...
    std::vector<int> arrayDims;          // `float4 x[8]` -> {8}
    std::string semantic;
    std::vector<Annotation> annotations;
    TokenSpan initializer;
    std::string cbuffer;                 // enclosing cbuffer, empty for $Global
    int packOffset = -1;                 // packoffset(cN.y): 4 * N + component, in floats; -1 none
    char registerClass = 0;              // register(u3) -> 'u', 3 (UAVs and buffer SRVs are bound by it); 0 none
    int registerIndex = -1;
    size_t token = 0;
    bool isStringParameter = false;      // `string Name = "...";` (removed from HLSL)
};

struct FxStructMember {
    std::string type;
    std::string name;
    std::vector<int> arrayDims;
    std::string semantic;
    std::vector<std::string> modifiers;  // interpolation modifiers
};

struct FxMemberFunction {
    std::string name;
    TokenSpan span;  // from its first modifier or type to its closing '}'
    size_t body = 0;  // its '{'
};

struct FxStruct {
    std::string name;
    std::vector<FxStructMember> members;
    std::vector<FxMemberFunction> memberFunctions;  // left to glslang; copied into derived structs
    size_t token = 0;
};

struct FxParameter {
    std::vector<std::string> modifiers;  // lower-case: in, out, inout, uniform, triangle, nointerpolation ...
    std::string type;
    size_t typeToken = 0;
    std::string name;
    std::vector<int> arrayDims;
    std::string semantic;
    TokenSpan defaultValue;
};

struct FxFunction {
    std::string name;
    std::string returnType;
    std::string returnSemantic;
    std::vector<FxParameter> parameters;
    TokenSpan body;  // tokens between the braces
    TokenSpan declaration;  // attributes, signature and body
    bool hasStreamParameter = false;  // a geometry shader (inout TriangleStream<T> ...)
    size_t token = 0;
    // The name token of this overload's first declaration: a prototype of the same parameter types
    // before the definition, else `token`. fxc's entry point among overloads is the one declared
    // last by this measure (findEntry).
    size_t firstDeclared = 0;
    std::vector<TokenSpan> prototypes;  // earlier declarations of this overload (`void main();`), attributes and ';' included
    std::string attributes;  // e.g. "[maxvertexcount(3)]"
    TokenSpan attributeTokens;  // where `attributes` is written: before the function, or its first prototype with attributes
    // Where the body may declare each name: the token positions of `T name` (an identifier after an
    // identifier, not a call), ascending. declaredVariable looks up here instead of scanning the
    // body backwards, which made a body of n statements cost n^2.
    std::unordered_map<std::string, std::vector<size_t>> declarationSites;
};

// A byte range of the preprocessed text to replace. Replacements keep the line count.
struct TextEdit {
    size_t begin = 0;
    size_t end = 0;
    std::string replacement;  // empty = blank out (spaces, newlines kept)
};

struct EffectSyntax {
    std::vector<Token> tokens;
    std::vector<FxTechnique> techniques;
    std::vector<FxGlobal> globals;
    std::vector<FxStruct> structs;
    std::vector<FxFunction> functions;
    std::vector<TokenSpan> memberFunctionBodies;  // `struct S { float f() { ... } };`: left to glslang, bodies here
    bool inMemberFunctionBody(size_t token) const {
        for (const auto& b : memberFunctionBodies)
            if (token >= b.begin && token < b.end) return true;
        return false;
    }
    std::vector<FxSampler> samplers;
    std::vector<FxTexture> textures;
    std::vector<FxStateObject> stateObjects;
    std::vector<FxShaderVariable> shaderVariables;
    std::vector<TextEdit> edits;  // framework syntax to remove before glslang sees the text
    std::vector<std::string> cbuffers;  // names of user cbuffers, in declaration order
    std::vector<std::string> rasterizerOrderedViews;  // variables declared RasterizerOrdered* (spelled RW* since)
    std::vector<int> cbufferRegisters;  // per cbuffer: register(bN) as written, -1 when none
    std::map<std::string, std::string> typedefs;  // `typedef vector<half, 3> vec3;`: vec3 -> vector<half,3>
    // Compiled as fxc /T ps_4_0 compiles a file (loose shaders, no effect profile): fxc then parses
    // a variable's state block and ignores what it holds, so what fxport cannot honour there is a
    // warning, not an error.
    bool looseShaders = false;
    std::vector<Diagnostic> warnings;  // what the parser ignored, with its place

    const FxFunction* findFunction(const std::string& name) const;
    // The overload of `name` that `compile ps_2_0 name(literalArguments)` (or fxc /E name) means:
    // of those whose `uniform` parameters take that many literals (else of those that take fewer,
    // the rest becoming parameters), the one first declared last, as d3dcompiler_47 picks an
    // overloaded entry point (a later prototype of an earlier overload does not count, an earlier
    // prototype does); else the first of that name.
    const FxFunction* findEntry(const std::string& name, const std::string& literalArguments) const;
    const FxStruct* findStruct(const std::string& name) const;
    const FxSampler* findSampler(const std::string& name) const;
    const FxTexture* findTexture(const std::string& name) const;
    std::string text(TokenSpan span) const;  // tokens joined with single spaces
    const std::string& resolveType(const std::string& type) const;  // through typedefs (the type itself if none)
};

class SourceMap;

// Parses the preprocessed text. Throws CompileError (located through `map`) on syntax errors.
EffectSyntax parseEffect(const std::string& text, const SourceMap& map, bool looseShaders = false);

// Parses `<profile> <entry>(<args>)`-style shader expressions (pass values and shader variables).
FxShaderExpr parseShaderExpr(const EffectSyntax& syntax, TokenSpan span);

}  // namespace fxport::xlate
