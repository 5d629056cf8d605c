// The effect compiler: .fx source in, CompiledEffect out. No GL, no runtime.
//
//   fxport::xlate::CompileOptions options;            // zero value = sensible defaults
//   options.includeDirs.push_back("hlsl/common");
//   CompiledEffect effect = fxport::xlate::compileEffectFile("hlsl/xna-deferred/GBuffer.fx", options);
//
// Errors that make the whole effect unusable throw CompileError (with file:line diagnostics);
// problems confined to one pass (an `asm {}` shader, say) leave that pass invalid and are listed in
// CompiledEffect::diagnostics.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

struct CompileOptions {
    // Extra folders `#include` searches (fxc /I), after the including files' folders.
    std::vector<std::string> includeDirs;
    // Confines `#include`: when set, every file read lies under it or under includeDirs (an include
    // that escapes is FX1103), for compiling effects one does not trust. Empty = no confinement:
    // `#include "../Common/x.fxh"` and `<..\Helpers\y.fxh>` resolve wherever they lead, as with
    // fxc. `fxport check DIR` uses DIR; `--root`. Files are judged by their real path: a symbolic
    // link leaving the root is outside it.
    std::string includeRoot;
    // `-D NAME=VALUE` style macros, applied before the source.
    std::vector<std::pair<std::string, std::string>> defines;
    // Compile only these techniques (by name); empty = all. Lets the runtime compile lazily what a
    // scene uses.
    std::vector<std::string> techniques;
    // Errors confined to a pass (an `asm {}` shader, a bad state) normally fail the whole compile.
    // With this set, such passes are kept with valid=false and the rest of the effect is returned.
    bool keepValidPasses = false;
    // Result cache. Empty = the default folder ($FXPORT_CACHE_DIR, else $XDG_CACHE_HOME/fxport,
    // else ~/.cache/fxport). Set useCache=false to always compile. An entry is found by the raw
    // bytes of the .fx and these options (no preprocessing) and used only while every file it
    // #included still has the same content.
    std::string cacheDir;
    bool useCache = true;
    // Keep the rewritten HLSL of each shader in CompiledShader::hlslAfterRewrite. Also turned on
    // (and written to files) by the environment variable FXPORT_DUMP=<folder>.
    bool keepRewrittenHlsl = false;
    // Parse the effect and build its outline -- techniques, passes (states, which entry point each
    // stage uses), parameters with defaults -- but cross-compile no shader: CompiledShader::glsl
    // stays empty, uniform blocks have size 0 and parameters offset -1. Profiles, entry points and
    // entry signatures are still checked. What the runtime loads so that an effect's shaders are
    // compiled only when one of its passes is first applied (then with `techniques` = that one).
    bool skipShaders = false;
    // Run the HLSL front end (preprocessing, glslang, SPIRV-Cross) in this process. By default a
    // compile that misses the cache runs in a forked worker process with time and memory limits,
    // so that a crash inside glslang on a malformed effect becomes a diagnostic (FX9001-FX9003)
    // instead of taking the caller down. The fuzzers set this to find such crashes.
    bool inProcess = false;
    // Loose files (compileShaderFiles sets it): another file of the pass holds a geometry or domain
    // shader, so this file's vertex outputs and pixel inputs keep their declared types (as they
    // do in an effect whose pass has such a shader) instead of D3D9's float4 varyings.
    bool besideGeometryOrDomainShader = false;
    // Loose files (compileShaderFiles sets it): the attributes of the hull shader another file of
    // the pass holds; GL declares its partitioning and topology in the domain shader.
    Tessellation hullOfDomainShader;
    // The majority of matrices that name none, before any `#pragma pack_matrix` (fxc's /Zpr and
    // /Zpc, D3DCOMPILE_PACK_MATRIX_*): "row_major", "column_major", or empty (column-major).
    std::string defaultMatrixMajority;
    // `#include`s read through the caller instead of the file system (D3DCompile's ID3DInclude):
    // called with the header as written, whether it was written <header>, and the including file's
    // name (the root's path, or a header an earlier call returned); returns the text, or nullopt
    // when there is none. Runs wherever the preprocessor runs (a worker process unless the compile
    // is in this process), and is no part of the cache key: set it with useCache = false.
    std::function<std::optional<std::string>(const std::string& header, bool system, const std::string& includer)> readInclude;
    // The effect profile fxc's /T would name: "fx_2_0", "fx_4_0", "fx_4_1" or "fx_5_0". Empty:
    // XNA's fx_2_0 rules. fxc accepts an effect without a technique from fx_4_0 on (variables
    // only, for effect pools); fx_2_0 and the empty default refuse it (FX1003).
    std::string effectProfile;
};

// Compiles a file. Throws CompileError for fatal problems.
CompiledEffect compileEffectFile(const std::string& path, const CompileOptions& options = {});

// The outcome of one file of compileEffectFiles(): the effect, or the errors that stopped it (what
// compileEffectFile() would have thrown).
struct EffectFileResult {
    std::optional<CompiledEffect> effect;
    std::vector<Diagnostic> errors;
};

// Compiles several effect files, each as compileEffectFile() would, the cache's misses in parallel:
// up to $FXPORT_JOBS workers at once (else one per CPU), each with its own limits. `done(i, result)`
// is called for files[i], in the order of `files`, as soon as it and every file before it are done.
// Results and output are the same as compiling the files one by one.
void compileEffectFiles(const std::vector<std::pair<std::string, CompileOptions>>& files,
                        const std::function<void(size_t, EffectFileResult&&)>& done);

// Compiles source text as if it were the file `virtualPath` (includes resolve beside it).
CompiledEffect compileEffectSource(const std::string& source, const std::string& virtualPath,
                                   const CompileOptions& options = {});

// The files compiling `path` reads: the effect itself, then every file it #includes (absolute
// paths, each once), for build systems (`fxport compile --depfile`). Runs only the preprocessor.
// Throws CompileError (file:line) when the effect cannot be read or preprocessed.
std::vector<std::string> effectDependencies(const std::string& path, const CompileOptions& options = {});
// Runs only the preprocessor over `source` as if it were the file `virtualPath`, in this process
// (options.readInclude sees each #include the preprocessor reaches). Throws CompileError.
void preprocessSource(const std::string& source, const std::string& virtualPath, const CompileOptions& options);

// One entry point of a loose shader file (D3D10/11 style: no technique), as fxc's /E and /T name it.
struct ShaderEntry {
    std::string path;        // the .hlsl / .vs / .ps file
    std::string entryPoint;  // fxc /E: the function
    std::string profile;     // fxc /T: vs_5_0, ps_4_0, gs_4_0, ps_2_0 ...
};

// Compiles loose shader files into an effect with one technique (named after the entry points,
// joined by '+') holding one pass "P0" that uses each entry point for its profile's stage. Its
// globals and cbuffer members are parameters like an effect's. Entry points in the same file
// compile together; different files are compiled apart and merged, so each may declare its own
// structs and cbuffers; a parameter both declare must agree (a shared header's cbuffer does).
// Throws CompileError (a bad profile or a missing entry point names the option and the file).
CompiledEffect compileShaderFiles(const std::vector<ShaderEntry>& entries, const CompileOptions& options = {});
// The same for one source held in memory (D3DCompile): `source` is compiled as if it were the file
// every entry's path names (`virtualPath`; its #includes resolve beside it).
CompiledEffect compileShaderSource(const std::string& source, const std::string& virtualPath,
                                   const std::vector<ShaderEntry>& entries, const CompileOptions& options = {});

// A version string that changes whenever compiled output may change (part of every cache key).
const char* compilerVersion();

}  // namespace fxport::xlate
