// Diagnostics of the effect compiler: a stable id, a sentence, and a location in the ORIGINAL source
// (through includes and macros), printed the way fxc prints them so editors can jump to them:
//   hlsl/xna-deferred/GBuffer.fx(57,12): error X3004: undeclared identifier 'foo'
//       float4 c = foo;
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace fxport::xlate {

struct SourceLocation {
    std::string file;  // path as the user named it (or as resolved for an include)
    int line = 0;      // 1-based; 0 = whole file
    int column = 0;    // 1-based; 0 = unknown
};

enum class Severity { Error, Warning };

// Stable ids. Tests assert these; never renumber, only add.
namespace diag {
inline constexpr const char* kFileUnreadable = "FX1001";      // cannot open/read the .fx file
inline constexpr const char* kNotText = "FX1002";             // binary garbage / NUL bytes / invalid text
inline constexpr const char* kEmptyEffect = "FX1003";         // no technique in the effect
inline constexpr const char* kPreprocessor = "FX1101";        // #error, bad directive, bad macro
inline constexpr const char* kIncludeNotFound = "FX1102";     // #include target missing
inline constexpr const char* kIncludeOutside = "FX1103";      // #include escapes the allowed folders
inline constexpr const char* kIncludeCycle = "FX1104";        // #include recursion
inline constexpr const char* kSyntax = "FX1201";              // effect-framework syntax error
inline constexpr const char* kUnterminated = "FX1202";        // block or string not closed before end of file
inline constexpr const char* kUnknownState = "FX1301";        // pass/sampler/state-object assignment not known
inline constexpr const char* kBadStateValue = "FX1302";       // known state, value not understood
inline constexpr const char* kIgnoredState = "FX1303";        // fixed-function state accepted and ignored (warning)
inline constexpr const char* kUnhonouredState = "FX1304";     // state or value GL/XNA cannot reproduce, ignored (warning)
inline constexpr const char* kBadProfile = "FX1401";          // compile target like vs_9_9 or a ps profile for a VS
inline constexpr const char* kMissingEntry = "FX1402";        // compile names a function that does not exist
inline constexpr const char* kBadEntrySignature = "FX1403";   // entry parameter/return we cannot map
inline constexpr const char* kUnsupported = "FX1404";         // asm {} blocks, stream output, ... (per pass)
inline constexpr const char* kUnknownShader = "FX1405";       // pass refers to an undeclared shader variable
inline constexpr const char* kBadStreamOutput = "FX1406";     // a ConstructGSWithSO declaration D3D or fxport refuses
inline constexpr const char* kHlsl = "FX2001";                // glslang rejected the HLSL (type errors etc.)
inline constexpr const char* kImplicitConversion = "FX2002";  // fxc's implicit truncation of an argument (warning X3206)
inline constexpr const char* kSpirv = "FX2101";               // SPIR-V optimisation / cross-compilation failed
inline constexpr const char* kCache = "FX3001";               // cache read/write problem (warning)
inline constexpr const char* kEffectFile = "FX3101";          // compiled-effect file unreadable or wrong version
// Limits on what one effect may cost (docs/limits.md lists the values).
inline constexpr const char* kInputTooLarge = "FX1005";       // a source file (or all of them) larger than the limit
inline constexpr const char* kIncludeLimit = "FX1105";        // #include nested too deep or too many files
inline constexpr const char* kMacroLimit = "FX1106";          // macro expansion too large, or preprocessing ran out of time/memory
inline constexpr const char* kNestingTooDeep = "FX1203";      // ( [ { nested deeper than the limit
inline constexpr const char* kArrayTooLarge = "FX1204";       // an array with more elements than the limit
inline constexpr const char* kTooManyMembers = "FX1205";      // a constant buffer or struct with more members than the limit
inline constexpr const char* kTooManyStatements = "FX1206";   // more statements in the functions of one effect than the limit
// The HLSL front end (glslang + SPIRV-Cross) runs in a worker process; what it could not survive:
inline constexpr const char* kFrontEndCrashed = "FX9001";     // the worker died (a crash inside glslang/SPIRV-Cross)
inline constexpr const char* kFrontEndTimeout = "FX9002";     // the worker ran past its time limit
inline constexpr const char* kFrontEndMemory = "FX9003";      // the worker ran past its memory limit
}  // namespace diag

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string id;            // one of diag::k*
    std::string message;       // one sentence, no location
    SourceLocation location;
    std::string sourceLine;    // the offending line of the original file, when known

    // "file(line,col): error FX1201: message" plus, when known, the source line on the next row.
    std::string format() const;
    // A state the effect sets that fxport ignores (FX1303, FX1304): reported by default, by
    // `fxport check` and by the runtime when the effect loads, so that none is dropped silently.
    bool dropsState() const { return id == diag::kIgnoredState || id == diag::kUnhonouredState; }
};

// Thrown by the compiler for errors that stop the whole effect (fatal). Per-pass problems are
// recorded in CompiledEffect::diagnostics instead, and the rest of the effect still compiles.
class CompileError : public std::runtime_error {
public:
    explicit CompileError(std::vector<Diagnostic> diagnostics);
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::vector<Diagnostic> diagnostics_;
};

}  // namespace fxport::xlate
