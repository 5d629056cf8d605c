// Compile checks through xlate's public API (see section_compiler.h).
#include "section_compiler.h"

#include <algorithm>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"

namespace conformance {

std::string shaderProfile(Stage stage, int model) {
    const char* prefix = stage == Stage::Vertex ? "vs" : stage == Stage::Geometry ? "gs" : stage == Stage::Compute ? "cs"
                       : stage == Stage::Hull ? "hs" : stage == Stage::Domain ? "ds" : "ps";
    return std::string(prefix) + "_" + std::to_string(model / 10) + "_" + std::to_string(model % 10);
}

std::string preparedSource(const std::string& source, const RequireDesc& require) {
    if (require.matrixPacking == "row-major") return "#pragma pack_matrix(row_major)\n" + source;
    if (require.matrixPacking == "column-major") return "#pragma pack_matrix(column_major)\n" + source;
    return source;
}

int preparedPrefixLines(const RequireDesc& require) { return require.matrixPacking.empty() ? 0 : 1; }

SectionCompiler::SectionCompiler(std::string tempDir, std::string cacheDir, std::string testFileName)
    : tempDir_(std::move(tempDir)), cacheDir_(std::move(cacheDir)), testFileName_(std::move(testFileName)) {}

std::string SectionCompiler::writeSource(const std::string& source, int firstLine, const RequireDesc& require,
                                         const std::string& ext) {
    std::string path = tempDir_ + "/" + testFileName_ + "-L" + std::to_string(firstLine) + "-" +
                       std::to_string(serial_++) + ext;
    std::ofstream(path) << preparedSource(source, require);
    return path;
}

namespace {

fxport::xlate::CompileOptions optionsFor(const std::string& cacheDir) {
    fxport::xlate::CompileOptions options;
    options.cacheDir = cacheDir;
    options.useCache = !cacheDir.empty();
    return options;
}

// The first error of a failed compile, its line moved from the temporary file to the test file.
CompileOutcome refused(const std::vector<fxport::xlate::Diagnostic>& diagnostics, const std::string& fileName,
                       int firstLine) {
    CompileOutcome out;
    for (const auto& d : diagnostics) {
        if (d.severity != fxport::xlate::Severity::Error) continue;
        out.id = d.id;
        out.message = d.message;
        int line = d.location.line > 0 ? firstLine + d.location.line : 0;
        out.diagnostic = fileName + ".shader_test:" + std::to_string(line) + ": error " + d.id + ": " + d.message;
        return out;
    }
    out.message = "compile failed without an error diagnostic";
    out.diagnostic = fileName + ".shader_test: " + out.message;
    return out;
}

// The effect profile of an [effect] section: fx_2_0 on the D3D9 models; from 4.0 on, the lowest
// model the file's [require] allows (vkd3d's effect-variables-fx_4 expects fx_4_0's rules in its
// 5.0 run too, effect-variables-fx_4_1 requires 4.1 for fx_4_1's).
std::string effectProfileFor(int model, const RequireDesc& require) {
    if (model < 40) return "fx_2_0";
    int lowest = std::max(require.minModel, 40);
    return lowest >= 50 ? "fx_5_0" : lowest >= 41 ? "fx_4_1" : "fx_4_0";
}

}  // namespace

CompileOutcome SectionCompiler::compileLoose(const std::string& path, const std::string& profile, int firstLine) {
    try {
        fxport::xlate::CompiledEffect effect =
            fxport::xlate::compileShaderFiles({{path, "main", profile}}, optionsFor(cacheDir_));
        if (effect.hasErrors()) return refused(effect.diagnostics, testFileName_, firstLine);
        return CompileOutcome{true, "", "", ""};
    } catch (const fxport::xlate::CompileError& e) {
        return refused(e.diagnostics(), testFileName_, firstLine);
    } catch (const std::exception& e) {
        return CompileOutcome{false, testFileName_ + ".shader_test: exception: " + e.what(), "exception", e.what()};
    }
}

CompileOutcome SectionCompiler::compileEffect(const std::string& source, int firstLine, int model, const RequireDesc& require) {
    std::string path = tempDir_ + "/" + testFileName_ + "-L" + std::to_string(firstLine) + ".fx";
    try {
        fxport::xlate::CompileOptions options = optionsFor(cacheDir_);
        options.effectProfile = effectProfileFor(model, require);
        fxport::xlate::CompiledEffect effect = fxport::xlate::compileEffectSource(preparedSource(source, require), path, options);
        if (effect.hasErrors()) return refused(effect.diagnostics, testFileName_, firstLine);
        return CompileOutcome{true, "", "", ""};
    } catch (const fxport::xlate::CompileError& e) {
        return refused(e.diagnostics(), testFileName_, firstLine);
    } catch (const std::exception& e) {
        return CompileOutcome{false, testFileName_ + ".shader_test: exception: " + e.what(), "exception", e.what()};
    }
}

CompileOutcome SectionCompiler::compile(const Block& section, int model, const RequireDesc& require) {
    // Diagnostic line k of the compiled text is file line (header + k - prefix lines).
    int firstLine = section.line - preparedPrefixLines(require);
    if (section.stage == Stage::Effect) return compileEffect(section.source(), firstLine, model, require);
    std::string path = writeSource(section.source(), section.line, require, ".hlsl");
    return compileLoose(path, shaderProfile(section.stage, model), firstLine);
}

}  // namespace conformance
