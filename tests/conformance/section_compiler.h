// Compile checks of one shader section at one shader model through fxport's public compile API:
// loose shaders (entry `main`, profile ps_4_0 ...) with xlate::compileShaderFiles, [effect]
// sections with xlate::compileEffectSource. Sections are written to a private temporary folder
// (the suite's files are read in place, never copied into the repository).
#pragma once

#include <string>

#include "resource_desc.h"
#include "shader_test_file.h"

namespace conformance {

struct CompileOutcome {
    bool compiled = false;
    std::string diagnostic;  // the first error, "file.shader_test:LINE: error FXnnnn: message"
    std::string id;          // its FXnnnn
    std::string message;     // its sentence, without location
};

// "ps_4_0", "vs_2_0", "gs_5_0" ...
std::string shaderProfile(Stage stage, int model);

class SectionCompiler {
public:
    SectionCompiler(std::string tempDir, std::string cacheDir, std::string testFileName);

    CompileOutcome compile(const Block& section, int model, const RequireDesc& require);
    // The section's HLSL as compiled (with the matrix-packing pragma that [require] options ask),
    // written to a temporary file; returns its path. `tag` keeps files of one run apart.
    std::string writeSource(const std::string& source, int firstLine, const RequireDesc& require, const std::string& ext);
    const std::string& cacheDir() const { return cacheDir_; }

private:
    CompileOutcome compileLoose(const std::string& path, const std::string& profile, int firstLine);
    CompileOutcome compileEffect(const std::string& source, int firstLine, int model, const RequireDesc& require);

    std::string tempDir_;
    std::string cacheDir_;
    std::string testFileName_;
    int serial_ = 0;
};

// HLSL text as compiled: `#pragma pack_matrix(...)` first where [require] asks for it.
std::string preparedSource(const std::string& source, const RequireDesc& require);
int preparedPrefixLines(const RequireDesc& require);

}  // namespace conformance
