// What lazy effects rely on (runtime/graphics/src/effect.cpp): the outline (skipShaders) describes
// the same techniques, passes and parameters as the full compile without compiling a shader, and a
// compile of one technique compiles only that technique's shaders and lays out every uniform block
// it reads exactly as the full compile does (so values set before can be moved into place).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

std::vector<std::string> effects() {
    std::vector<std::string> out;
    for (const char* dir : {"hlsl", "tests/fixtures/realworld"})
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().extension() == ".fx") out.push_back(e.path().generic_string());
    std::sort(out.begin(), out.end());
    return out;
}

CompileOptions options() {
    CompileOptions o;
    o.useCache = false;
    o.keepValidPasses = true;  // some real-world effects have asm passes; the rest must still agree
    return o;
}

using ShaderId = std::tuple<ShaderStage, std::string, std::string, std::string>;  // stage, profile, entry, arguments
ShaderId idOf(const CompiledShader& s) { return {s.profile.stage, s.profile.name, s.entryPoint, s.arguments}; }

// Every shader a technique's passes can bind.
std::set<ShaderId> shadersOf(const CompiledEffect& e, const Technique& t) {
    std::set<ShaderId> out;
    for (const Pass& p : t.passes)
        for (const ShaderChoice* c : {&p.vertexShader, &p.pixelShader, &p.geometryShader})
            for (int s : c->shaders)
                if (s >= 0) out.insert(idOf(e.shaders[std::size_t(s)]));
    return out;
}

TEST(Outline, DescribesTheEffectWithoutCompilingShaders) {
    int checked = 0;
    for (const std::string& path : effects()) {
        SCOPED_TRACE(path);
        CompiledEffect full;
        try {
            full = compileEffectFile(path, options());
        } catch (const CompileError&) {
            continue;  // effects that cannot compile at all are the broken-input tests' business
        }
        CompileOptions o = options();
        o.skipShaders = true;
        CompiledEffect outline = compileEffectFile(path, o);
        ++checked;

        ASSERT_EQ(outline.techniques.size(), full.techniques.size());
        for (std::size_t t = 0; t < full.techniques.size(); ++t) {
            const Technique& a = outline.techniques[t];
            const Technique& b = full.techniques[t];
            EXPECT_EQ(a.name, b.name);
            ASSERT_EQ(a.passes.size(), b.passes.size()) << b.name;
            for (std::size_t p = 0; p < b.passes.size(); ++p) {
                EXPECT_EQ(a.passes[p].name, b.passes[p].name);
                EXPECT_EQ(a.passes[p].states.size(), b.passes[p].states.size()) << b.name << "/" << b.passes[p].name;
            }
            if (std::all_of(b.passes.begin(), b.passes.end(), [](const Pass& p) { return p.valid; })) {
                EXPECT_EQ(shadersOf(outline, a), shadersOf(full, b)) << "technique " << b.name;
            }
        }
        ASSERT_EQ(outline.parameters.size(), full.parameters.size());
        for (std::size_t i = 0; i < full.parameters.size(); ++i) {
            const Parameter& a = outline.parameters[i];
            const Parameter& b = full.parameters[i];
            EXPECT_EQ(a.name, b.name);
            EXPECT_EQ(a.parameterClass, b.parameterClass) << b.name;
            EXPECT_EQ(a.type, b.type) << b.name;
            EXPECT_EQ(std::tie(a.rows, a.columns, a.elements, a.block), std::tie(b.rows, b.columns, b.elements, b.block)) << b.name;
            EXPECT_EQ(a.defaultValue, b.defaultValue) << b.name;
            EXPECT_EQ(a.offset, -1) << b.name << ": the outline knows no layout";
        }
        ASSERT_EQ(outline.uniformBlocks.size(), full.uniformBlocks.size());
        for (std::size_t k = 0; k < full.uniformBlocks.size(); ++k) {
            EXPECT_EQ(outline.uniformBlocks[k].name, full.uniformBlocks[k].name);
            EXPECT_EQ(outline.uniformBlocks[k].binding, full.uniformBlocks[k].binding);
            EXPECT_EQ(outline.uniformBlocks[k].size, 0);
        }
        for (const CompiledShader& s : outline.shaders) EXPECT_TRUE(s.glsl.empty()) << s.entryPoint;
    }
    EXPECT_GT(checked, 40);
}

TEST(Outline, OneTechniqueCompilesOnlyItsShadersWithTheFullLayout) {
    int techniquesChecked = 0;
    for (const std::string& path : effects()) {
        SCOPED_TRACE(path);
        CompiledEffect full;
        try {
            full = compileEffectFile(path, options());
        } catch (const CompileError&) {
            continue;
        }
        if (full.techniques.size() < 2) continue;  // a single technique compiles the same either way
        std::set<std::string> seen;
        for (const Technique& t : full.techniques) {
            if (!seen.insert(t.name).second) continue;
            if (!std::all_of(t.passes.begin(), t.passes.end(), [](const Pass& p) { return p.valid; })) continue;
            CompileOptions o = options();
            o.techniques = {t.name};
            CompiledEffect one = compileEffectFile(path, o);
            ++techniquesChecked;
            ASSERT_EQ(one.techniques.size(), std::size_t(std::count_if(full.techniques.begin(), full.techniques.end(),
                                                                        [&](const Technique& x) { return x.name == t.name; })));
            // Only this technique's shaders.
            std::set<ShaderId> compiled;
            for (const CompiledShader& s : one.shaders) compiled.insert(idOf(s));
            EXPECT_EQ(compiled, shadersOf(full, t)) << "technique " << t.name;
            // Each block it reads: the same size and the same place for every parameter.
            ASSERT_EQ(one.uniformBlocks.size(), full.uniformBlocks.size());
            for (std::size_t k = 0; k < one.uniformBlocks.size(); ++k)
                if (one.uniformBlocks[k].size > 0) {
                    EXPECT_EQ(one.uniformBlocks[k].size, full.uniformBlocks[k].size) << one.uniformBlocks[k].name;
                }
            ASSERT_EQ(one.parameters.size(), full.parameters.size());
            for (std::size_t i = 0; i < one.parameters.size(); ++i) {
                const Parameter& a = one.parameters[i];
                const Parameter& b = full.parameters[i];
                if (a.offset < 0) continue;
                EXPECT_EQ(std::tie(a.block, a.offset, a.size, a.matrixStride, a.arrayStride, a.rowMajor),
                          std::tie(b.block, b.offset, b.size, b.matrixStride, b.arrayStride, b.rowMajor))
                    << "parameter " << b.name << " in technique " << t.name;
            }
        }
    }
    EXPECT_GT(techniquesChecked, 10);
}

// The outline is cached apart from the full compile (its own key), and a warm outline is read back
// equal.
TEST(Outline, IsCachedUnderItsOwnKey) {
    fs::path dir = fs::temp_directory_path() / ("fxport_outline_cache_test_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    CompileOptions o;
    o.cacheDir = dir.string();
    o.skipShaders = true;
    CompiledEffect cold = compileEffectFile("hlsl/xna-deferred/SpotLight.fx", o);
    CompiledEffect warm = compileEffectFile("hlsl/xna-deferred/SpotLight.fx", o);
    EXPECT_EQ(warm.parameters.size(), cold.parameters.size());
    EXPECT_EQ(warm.shaders.size(), cold.shaders.size());
    for (const CompiledShader& s : warm.shaders) EXPECT_TRUE(s.glsl.empty());
    o.skipShaders = false;
    CompiledEffect full = compileEffectFile("hlsl/xna-deferred/SpotLight.fx", o);
    ASSERT_FALSE(full.shaders.empty());
    for (const CompiledShader& s : full.shaders) EXPECT_FALSE(s.glsl.empty()) << "the outline's cache entry was used for a full compile";
    fs::remove_all(dir);
}

}  // namespace
