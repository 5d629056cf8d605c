// Compiles HLSL text as a loose shader file (what fxc /E /T does with a file) for the xlate tests:
// the text is written under a per-process temporary folder, so includes beside it and file names in
// diagnostics behave as they do for a user's file. One helper for every test that needs it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/xlate/effect_compiler.h"

namespace fxport::test {

// Writes `source` to `name` (which may hold folders) under this process's temporary folder.
inline std::filesystem::path writeLooseSource(const std::string& name, const std::string& source) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("fxport-loose-" + std::to_string(::getpid()));
    std::filesystem::create_directories((dir / name).parent_path());
    std::ofstream(dir / name) << source;
    return dir / name;
}

// `source` written as `name` and compiled with entry `entry` and `profile`, without the cache.
inline xlate::CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main",
                                          const std::string& name = "shader.hlsl") {
    xlate::CompileOptions options;
    options.useCache = false;
    return xlate::compileShaderFiles({{writeLooseSource(name, source).string(), entry, profile}}, options);
}

// The GLSL of `source`'s one shader (entry main); a compile error fails the test.
inline std::string glslOfLoose(const std::string& source, const std::string& profile) {
    try {
        return compileLoose(source, profile).shaders.at(0).glsl;
    } catch (const xlate::CompileError& err) {
        ADD_FAILURE() << err.what();
        return {};
    }
}

// The diagnostics that refuse `source` (entry main); compiling fails the test.
inline std::vector<xlate::Diagnostic> errorsOfLoose(const std::string& source, const std::string& profile) {
    try {
        compileLoose(source, profile);
    } catch (const xlate::CompileError& err) {
        return err.diagnostics();
    }
    ADD_FAILURE() << "compiled";
    return {};
}

}  // namespace fxport::test
