// Containment (issue 26): nothing a compile is handed takes the caller down. Loose shader files
// (compileShaderFiles, `fxport compile X.hlsl --entry --profile`) and compiles that keep the
// rewritten HLSL (FXPORT_DUMP, keepRewrittenHlsl) run in the front-end worker as effect files do;
// each case runs the library in a child process (a gtest death-test fork) or the real `fxport`
// binary and requires a normal exit with a diagnostic.
//
// Paths are relative to the repository root (the tests run there, see CMakeLists.txt).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "effect/effect_validation.h"
#include "frontend/front_end_worker.h"
#include "effect/keyed_hash.h"
#include "fx/text_util.h"
#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "run_cli.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;
using fxport::test::RunResult;
using fxport::test::runCli;

namespace {

// Bytes this process has read through read() and its kin (Linux's /proc/self/io rchar), page cache
// included: what shows whether a file was read, whatever the machine's speed.
std::uint64_t bytesReadByThisProcess() {
    std::ifstream io("/proc/self/io");
    std::string key;
    std::uint64_t value = 0;
    while (io >> key >> value)
        if (key == "rchar:") return value;
    ADD_FAILURE() << "/proc/self/io has no rchar line";
    return 0;
}

// A folder of its own per test, removed afterwards.
class Containment : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("fxport-containment-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        std::string path = (dir_ / name).string();
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string sh(const std::string& s) { return "'" + s + "'"; }

// glslang folds INT_MIN / -1 with the host's division: SIGFPE on x86 (fxc folds it to INT_MIN).
const std::string kIntMinDivision =
    "float4 main() : SV_Target { int x = -2147483648; int y = -1; return float4(x / y, 0, 0, 1); }\n";

// A mutation that crashes glslang 12 (tests/fixtures/broken/contained_glslang_crash.fx).
const std::string kCrashingEffect = "tests/fixtures/broken/contained_glslang_crash.fx";

// Compiles in a child: prints the first diagnostic's id (or "compiled") and exits 0; a signal
// there fails the death-test expectation.
void compileLooseAndExit(const std::vector<ShaderEntry>& entries, const CompileOptions& options) {
    try {
        CompiledEffect e = compileShaderFiles(entries, options);
        std::cerr << "compiled " << e.shaders.size() << " shaders\n";
    } catch (const CompileError& error) {
        std::cerr << error.diagnostics().front().format() << "\n";
    }
    std::exit(0);
}

CompileOptions uncached() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

TEST_F(Containment, LooseIntMinDivisionDoesNotKillTheCaller) {
    std::string ps = write("div.hlsl", kIntMinDivision);
    EXPECT_EXIT(compileLooseAndExit({{ps, "main", "ps_5_0"}}, uncached()), ::testing::ExitedWithCode(0), "compiled|div.hlsl");
}

TEST_F(Containment, LooseGlslangCrashIsALocatedFrontEndError) {
    EXPECT_EXIT(compileLooseAndExit({{kCrashingEffect, "VS", "vs_4_0"}, {kCrashingEffect, "PS", "ps_4_0"}}, uncached()),
                ::testing::ExitedWithCode(0), "contained_glslang_crash.fx\\([0-9]+,[0-9]+\\): error FX9001");
}

TEST_F(Containment, LooseFilesApartShareOneWorker) {
    // Two files (not cacheable, varyings shared): the crash in the second is still contained.
    std::string vs = write("vs.hlsl", "float4 main(float4 p : POSITION) : SV_Position { return p; }\n");
    EXPECT_EXIT(compileLooseAndExit({{vs, "main", "vs_4_0"}, {kCrashingEffect, "PS", "ps_4_0"}}, uncached()),
                ::testing::ExitedWithCode(0), "error FX9001");
}

TEST_F(Containment, LooseCompileStillWorksAndCaches) {
    std::string vs = write("vs.hlsl", "struct O { float4 p : SV_Position; float4 c : CUSTOM; };\n"
                                      "O main(float4 p : POSITION) { O o; o.p = p; o.c = p; return o; }\n");
    std::string ps = write("ps.hlsl", "float4 main(float4 p : SV_Position, float4 c : CUSTOM) : SV_Target { return c; }\n");
    CompiledEffect e = compileShaderFiles({{vs, "main", "vs_4_0"}, {ps, "main", "ps_4_0"}}, uncached());
    ASSERT_EQ(e.shaders.size(), 2u);
    // The shared custom varying has one location in both stages, although they compiled apart.
    EXPECT_NE(e.shaders[0].glsl.find("location"), std::string::npos);
    CompileOptions cached;
    cached.cacheDir = path("cache");
    CompiledEffect first = compileShaderFiles({{vs, "main", "vs_4_0"}}, cached);
    CompiledEffect second = compileShaderFiles({{vs, "main", "vs_4_0"}}, cached);  // from the cache
    EXPECT_EQ(first.shaders.at(0).glsl, second.shaders.at(0).glsl);
    EXPECT_FALSE(fs::is_empty(path("cache")));
}

TEST_F(Containment, KeptRewrittenHlslComesBackFromTheWorker) {
    std::string vs = write("vs.hlsl", "float4 main(float4 p : POSITION) : SV_Position { return p; }\n");
    CompileOptions o = uncached();
    o.keepRewrittenHlsl = true;
    CompiledEffect e = compileShaderFiles({{vs, "main", "vs_4_0"}}, o);
    ASSERT_EQ(e.shaders.size(), 1u);
    EXPECT_NE(e.shaders[0].hlslAfterRewrite.find("main"), std::string::npos);
    CompiledEffect f = compileEffectFile("tests/fixtures/broken/blend_full_sample_mask.fx", o);
    ASSERT_FALSE(f.shaders.empty());
    EXPECT_FALSE(f.shaders[0].hlslAfterRewrite.empty());
}

TEST_F(Containment, KeepRewrittenHlslDoesNotTurnAContainedCrashIntoASignal) {
    CompileOptions o = uncached();
    o.keepRewrittenHlsl = true;
    EXPECT_EXIT(
        {
            try {
                compileEffectFile(kCrashingEffect, o);
            } catch (const CompileError& error) {
                std::cerr << error.diagnostics().front().format() << "\n";
            }
            std::exit(0);
        },
        ::testing::ExitedWithCode(0), "error FX9001");
}

// The real binary.
TEST_F(Containment, CliLooseShaderIntMinDivisionExitsNormally) {
    std::string ps = write("div.hlsl", kIntMinDivision);
    RunResult r = runCli("compile " + sh(ps) + " --entry main --profile ps_5_0 --no-cache -o " + sh(path("out.fxeffect")));
    ASSERT_TRUE(r.exited) << r.output;
    if (r.status != 0) {
        EXPECT_NE(r.output.find("div.hlsl("), std::string::npos) << r.output;
    }
}

TEST_F(Containment, CliLooseShaderCrashIsFx9001) {
    RunResult r = runCli("compile " + sh(kCrashingEffect) + " --entry VS --profile vs_4_0 --no-cache -o " + sh(path("out.fxeffect")));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("error FX9001"), std::string::npos) << r.output;
}

TEST_F(Containment, CliLooseShaderGeometryUnnamedParameterExitsNormally) {
    std::string gs = write("gs.hlsl", "struct V { float4 p : SV_Position; };\n"
                                      "[maxvertexcount(3)] void main(point V[1], inout TriangleStream<V> s) { }\n");
    RunResult r = runCli("compile " + sh(gs) + " --entry main --profile gs_4_0 --no-cache -o " + sh(path("out.fxeffect")));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("gs.hlsl("), std::string::npos) << r.output;
}

TEST_F(Containment, CliLooseShaderExponentialMacroIsStopped) {
    std::string text;
    text += "#define D0 x\n";
    for (int i = 1; i <= 40; ++i) text += "#define D" + std::to_string(i) + " D" + std::to_string(i - 1) + " D" + std::to_string(i - 1) + "\n";
    text += "float Scale = D40;\nfloat4 main() : SV_Target { return Scale; }\n";
    std::string ps = write("macro.hlsl", text);
    RunResult r = runCli("compile " + sh(ps) + " --entry main --profile ps_4_0 --no-cache -o " + sh(path("out.fxeffect")),
                         "FXPORT_WORKER_SECONDS=2 FXPORT_WORKER_MEMORY_MB=512");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("macro.hlsl"), std::string::npos) << r.output;
}

TEST_F(Containment, CliDumpOfACrashingEffectIsFx9001NotASignal) {
    RunResult r = runCli("compile " + sh(kCrashingEffect) + " --no-cache -o " + sh(path("out.fxeffect")),
                         "FXPORT_DUMP=" + sh(path("dump")));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("error FX9001"), std::string::npos) << r.output;
}

TEST_F(Containment, CliDumpWritesTheRewrittenHlslFromTheWorker) {
    RunResult r = runCli("compile tests/fixtures/broken/blend_full_sample_mask.fx --no-cache -o " + sh(path("out.fxeffect")),
                         "FXPORT_DUMP=" + sh(path("dump")));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 0) << r.output;
    bool hlsl = false;
    for (const auto& entry : fs::directory_iterator(path("dump"))) hlsl |= entry.path().extension() == ".hlsl";
    EXPECT_TRUE(hlsl);
}

// Outputs (issue 26 items 6, 7, 10): never replaced when not a regular file, never an input,
// never each other; every write checked, with the OS's reason.
const std::string kEffect = "tests/fixtures/broken/blend_full_sample_mask.fx";

TEST_F(Containment, OutputOnADeviceIsWrittenThroughNotReplaced) {
    RunResult r = runCli("compile " + kEffect + " --no-cache -o /dev/null");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::is_character_file("/dev/null"));  // still the device
}

TEST_F(Containment, OutputOnAFullDeviceFailsWithTheReason) {
    RunResult r = runCli("compile " + kEffect + " --no-cache -o /dev/full");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("cannot write '/dev/full' (No space left on device)"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST_F(Containment, OutputOnAFifoWithoutReaderIsRefusedAtOnce) {
    std::string fifo = path("fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(fifo), "timeout 20");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("a FIFO that nothing reads"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(Containment, OutputFolderIsRefusedWithAReason) {
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(dir_.string()));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("it is a folder"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("(Success)"), std::string::npos) << r.output;
}

TEST_F(Containment, ReadOnlyOutputIsRefused) {
    std::string out = write("out.fxeffect", "keep me");
    fs::permissions(out, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(out));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("read-only"), std::string::npos) << r.output;
    EXPECT_EQ(readAll(out), "keep me");
}

TEST_F(Containment, DepfileNamingTheInputIsRefused) {
    std::string fx = path("a.fx");
    fs::copy_file(kEffect, fx);
    std::string before = std::to_string(fs::file_size(fx));
    RunResult r = runCli("compile " + sh(fx) + " --no-cache -o " + sh(path("a.fxeffect")) + " --depfile " + sh(fx));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--depfile '" + fx + "' is also the input '" + fx + "'"), std::string::npos) << r.output;
    EXPECT_EQ(std::to_string(fs::file_size(fx)), before);
}

TEST_F(Containment, DepfileEqualToOutputIsRefused) {
    std::string out = path("a.fxeffect");
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(out) + " --depfile " + sh(out));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("-o '" + out + "' is also --depfile"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Containment, OutputNamingAnIncludedFileIsRefused) {
    std::string header = write("common.fxh", "float4 Tint;\n");
    std::string fx = write("a.fx", "#include \"common.fxh\"\n"
                                   "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
                                   "float4 PS() : COLOR0 { return Tint; }\n"
                                   "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
    RunResult r = runCli("compile " + sh(fx) + " --no-cache -o " + sh(header));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("the included file"), std::string::npos) << r.output;
    EXPECT_EQ(readAll(header), "float4 Tint;\n");
}

TEST_F(Containment, DepfileInAMissingFolderIsAnErrorWithTheReason) {
    std::string out = path("a.fxeffect");
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(out) + " --depfile " + sh(path("missing/a.d")));
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("No such file or directory"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

TEST_F(Containment, DepfileOnAFullDeviceFails) {
    RunResult r = runCli("compile " + kEffect + " --no-cache -o " + sh(path("a.fxeffect")) + " --depfile /dev/full");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
}

// Compiled effects and cache entries (issue 26 items 5, 8): nesting checked before parsing, every
// index's lower bound validated, entries that record their key and body checksum, sizes capped
// before reading, and a refused entry replaced by the next compile.
std::string effectWithTechnique(const std::string& technique) {
    return "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
           "float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }\n"
           "technique " + technique + " { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
}

std::vector<fs::path> cacheEntries(const std::string& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".fxeffect") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

TEST_F(Containment, DeeplyNestedCompiledEffectIsRefusedBeforeParsing) {
    EXPECT_EXIT(
        {
            try {
                deserializeEffect(std::string(200000, '[') + std::string(200000, ']'), "deep.fxeffect");
                std::cerr << "accepted\n";
            } catch (const CompileError& error) {
                std::cerr << error.diagnostics().front().format() << "\n";
            }
            std::exit(0);
        },
        ::testing::ExitedWithCode(0), "deep.fxeffect: error FX3101: .*nests more than 64 levels");
}

TEST_F(Containment, PassNamingShaderMinusOneIsRefused) {
    std::string text = serializeEffect(compileEffectFile(kEffect, uncached()));
    nlohmann::json j = nlohmann::json::parse(text);
    j["techniques"][0]["passes"][0]["pixelShader"]["shaders"] = nlohmann::json::array({-1});
    try {
        deserializeEffect(resealEffectFile(j.dump()), "minus.fxeffect");
        ADD_FAILURE() << "a valid pass with shader #-1 was accepted";
    } catch (const CompileError& error) {
        EXPECT_NE(error.diagnostics().front().message.find("shader #-1"), std::string::npos) << error.diagnostics().front().format();
    }
}

TEST_F(Containment, CacheEntryUnderAnotherKeyIsRefusedAndReplaced) {
    CompileOptions o;
    o.cacheDir = path("cache");
    std::string a = write("a.fx", effectWithTechnique("FromA"));
    compileEffectFile(a, o);
    std::vector<fs::path> first = cacheEntries(o.cacheDir);
    ASSERT_EQ(first.size(), 1u);
    std::string b = write("b.fx", effectWithTechnique("FromB"));
    compileEffectFile(b, o);
    std::vector<fs::path> both = cacheEntries(o.cacheDir);
    ASSERT_EQ(both.size(), 2u);
    fs::path entryOfB = both[0] == first[0] ? both[1] : both[0];
    fs::copy_file(first[0], entryOfB, fs::copy_options::overwrite_existing);  // A's entry under B's key
    CompiledEffect e = compileEffectFile(b, o);
    ASSERT_EQ(e.techniques.size(), 1u);
    EXPECT_EQ(e.techniques[0].name, "FromB");
    EXPECT_NE(readAll(entryOfB.string()), readAll(first[0].string()));  // replaced
}

TEST_F(Containment, PaddedCacheEntryIsRefusedAndReplaced) {
    CompileOptions o;
    o.cacheDir = path("cache");
    std::string a = write("a.fx", effectWithTechnique("T"));
    compileEffectFile(a, o);
    fs::path entry = cacheEntries(o.cacheDir).at(0);
    auto size = fs::file_size(entry);
    std::ofstream(entry, std::ios::binary | std::ios::app) << std::string(size_t{1} << 20, '\0');
    compileEffectFile(a, o);
    EXPECT_EQ(fs::file_size(entry), size);
}

TEST_F(Containment, HugeCacheEntryIsNotReadAndIsReplaced) {
    CompileOptions o;
    o.cacheDir = path("cache");
    std::string a = write("a.fx", effectWithTechnique("T"));
    compileEffectFile(a, o);
    fs::path entry = cacheEntries(o.cacheDir).at(0);
    auto size = fs::file_size(entry);
    fs::resize_file(entry, uintmax_t{4} << 30);  // sparse: 4 GiB of NULs after the entry
    const std::uint64_t before = bytesReadByThisProcess();
    compileEffectFile(a, o);
    EXPECT_LT(bytesReadByThisProcess() - before, std::uint64_t{64} << 20) << "the 4 GiB entry was read";
    EXPECT_EQ(fs::file_size(entry), size);
}

TEST_F(Containment, OversizedCompiledEffectFileIsRefusedBeforeReading) {
    std::string big = write("big.fxeffect", "{}");
    fs::resize_file(big, uintmax_t{1} << 30);
    try {
        loadEffectFile(big);
        ADD_FAILURE() << "a 1 GiB compiled effect was read";
    } catch (const CompileError& error) {
        EXPECT_NE(error.diagnostics().front().message.find("MiB fxport reads"), std::string::npos) << error.diagnostics().front().format();
    }
}

// Sizes (issue 26 item 4): computed in 64 bits from the compiled shader, through typedefs, nested
// struct arrays and locals; refused with FX1204 at the declaration.
struct SizeCase {
    const char* name;
    std::string effect;
    int line;
};

void expectTooLarge(const SizeCase& c) {
    try {
        compileEffectSource(c.effect, std::string(c.name) + ".fx", uncached());
        ADD_FAILURE() << c.name << " compiled";
    } catch (const CompileError& error) {
        const Diagnostic& d = error.diagnostics().front();
        EXPECT_EQ(d.id, diag::kArrayTooLarge) << d.format();
        EXPECT_EQ(d.location.line, c.line) << d.format();
        EXPECT_EQ(d.location.file, std::string(c.name) + ".fx") << d.format();
    }
}

const std::string kSizeTail = "float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }\n"
                              "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

TEST_F(Containment, ArrayBehindATypedefIsMeasured) {
    // At the typedef's dimension, where fxc reports X3059.
    expectTooLarge({"typedef_array",
                    "typedef float4 Row[100000];\nRow Big;\nfloat4 VS(float4 p : POSITION0) : POSITION0 { return p + Big[3]; }\n" + kSizeTail, 1});
}

TEST_F(Containment, NestedStructArraysAreMultipliedIn64Bits) {
    expectTooLarge({"nested_arrays",
                    "struct Inner { float4 m[60000]; };\nstruct Outer { Inner i[60000]; };\nOuter Nested;\n"
                    "float4 VS(float4 p : POSITION0) : POSITION0 { return p + Nested.i[1].m[2]; }\n" + kSizeTail,
                    3});
}

TEST_F(Containment, HugeLocalArrayIsRefusedWhereDeclared) {
    expectTooLarge({"local_array",
                    "float4 VS(float4 p : POSITION0) : POSITION0 {\n    float4 a[10000000];\n    a[int(p.x)] = p;\n    return a[int(p.y)];\n}\n" + kSizeTail,
                    2});
}

TEST_F(Containment, BonesAtTheElementLimitGetALocatedError) {
    expectTooLarge({"bones", "float4x4 Bones[65536];\nfloat4 VS(float4 p : POSITION0, int i : BLENDINDICES0) : POSITION0 { return mul(p, Bones[i]); }\n" + kSizeTail, 1});
}

TEST_F(Containment, LargeButReasonableArraysStillCompile) {
    CompiledEffect e = compileEffectSource(
        "float4 Table[4096];\nfloat4 VS(float4 p : POSITION0, int i : BLENDINDICES0) : POSITION0 { return p + Table[i]; }\n" + kSizeTail, "ok.fx", uncached());
    EXPECT_EQ(e.shaders.size(), 2u);
}

// Messages (issue 26 item 10).
TEST_F(Containment, ErrorOnAHugeLineQuotesOnlyAroundTheColumn) {
    std::string line = "float4 VS(float4 p : POSITION0) : POSITION0 { return p; } " + std::string(3 << 20, ' ') + " float x = ;";
    try {
        compileEffectSource(line + "\n" + kSizeTail, "long_line.fx", uncached());
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& error) {
        std::string text = error.diagnostics().front().format();
        EXPECT_LT(text.size(), 600u) << text.substr(0, 600);
        EXPECT_NE(text.find("..."), std::string::npos) << text.substr(0, 600);
    }
}

TEST_F(Containment, HundredThousandParametersAreOneLocatedError) {
    std::string text;
    for (int i = 0; i < 100000; ++i) text += "float P" + std::to_string(i) + ";\n";
    text += "float4 VS(float4 p : POSITION0) : POSITION0 { return p * (P0 + P99999); }\n" + kSizeTail;
    std::string fx = write("many.fx", text);
    RunResult r = runCli("compile " + sh(fx) + " --no-cache -o " + sh(path("many.fxeffect")));
    ASSERT_TRUE(r.exited) << r.output.substr(0, 2000);
    EXPECT_EQ(r.status, 1) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find("many.fx(16385,7): error FX1205:"), std::string::npos) << r.output.substr(0, 2000);
    EXPECT_EQ(r.output.find("input:0:0"), std::string::npos) << r.output.substr(0, 2000);
}

// 230 000 statements took 43 s and 2.7 GB in glslang/spirv-opt before a worker limit answered
// (issue 26 item 9): now one located error before any shader compiles.
TEST_F(Containment, StatementsPastTheLimitAreOneLocatedError) {
    std::string text = "float4 PS(float2 uv : TEXCOORD0) : COLOR0\n{\n    float x = uv.x;\n";
    for (int i = 0; i < 70000; ++i) text += "    x = x * 1.0001 + " + std::to_string(i % 7) + ".0;\n";
    text += "    return float4(x, 0, 0, 1);\n}\ntechnique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";
    std::string fx = write("statements.fx", text);
    RunResult r = runCli("compile " + sh(fx) + " --no-cache -o " + sh(path("statements.fxeffect")));
    ASSERT_TRUE(r.exited) << r.output.substr(0, 2000);
    EXPECT_EQ(r.status, 1) << r.output.substr(0, 2000);
    // `float x = uv.x;` is statement 1, so statement 65 537 is on line 3 + 65 536.
    EXPECT_NE(r.output.find("statements.fx(65539,"), std::string::npos) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find("error FX1206:"), std::string::npos) << r.output.substr(0, 2000);
}

// An entry whose checksum was recomputed by someone without the cache's secret (as anyone could
// with the unkeyed FNV sum before): refused, and the real effect compiled and stored again.
TEST_F(Containment, CacheEntryForgedWithoutTheSecretIsRefused) {
    CompileOptions o;
    o.cacheDir = path("cache");
    std::string a = write("a.fx", effectWithTechnique("Real"));
    compileEffectFile(a, o);
    fs::path entry = cacheEntries(o.cacheDir).at(0);
    CompileOptions other;
    other.cacheDir = path("other-cache");
    compileEffectFile(write("forged.fx", effectWithTechnique("Forged")), other);
    std::string forgedEntry = readAll(cacheEntries(other.cacheDir).at(0).string());
    std::string forgedBody = forgedEntry.substr(forgedEntry.find("\n=\n") + 3);
    // A's header and dependencies, the forged body, and every 32-digit checksum line but the key's
    // recomputed over the body, as the old unkeyed format was sealed.
    std::string text = readAll(entry.string());
    std::string header = text.substr(0, text.find("\n=\n") + 3);
    std::string sealed;
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) {
        if (line.size() == 36 && line.compare(0, 4, "key ") != 0 && line[3] == ' ') line = line.substr(0, 4) + fxport::xlate::contentHash(forgedBody);
        sealed += line + "\n";
    }
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << sealed << forgedBody;
    CompiledEffect e = compileEffectFile(a, o);
    ASSERT_EQ(e.techniques.size(), 1u);
    EXPECT_EQ(e.techniques[0].name, "Real");
    EXPECT_EQ(readAll(entry.string()), text);  // replaced by the real entry
}

// The secret must be the user's own: a secret file others may read is not used, and nothing is
// cached with it (an entry sealed with a secret others know could be forged).
TEST_F(Containment, CacheSecretOthersMayReadIsNotUsed) {
    CompileOptions o;
    o.cacheDir = path("cache");
    compileEffectFile(write("a.fx", effectWithTechnique("A")), o);
    fs::path secret = fs::path(o.cacheDir) / "secret";
    ASSERT_TRUE(fs::is_regular_file(secret));
    EXPECT_EQ(fs::status(secret).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(fs::file_size(secret), 32u);
    fs::permissions(secret, fs::perms::group_read | fs::perms::others_read, fs::perm_options::add);
    compileEffectFile(write("b.fx", effectWithTechnique("B")), o);
    EXPECT_EQ(cacheEntries(o.cacheDir).size(), 1u);  // b.fx compiled, not cached
}

// SipHash-2-4 against the reference implementation's vectors (key 00..0f, message 00..len-1).
TEST_F(Containment, KeyedHashIsTheReferenceSipHash) {
    fxport::xlate::SipKey key;
    for (int i = 0; i < 16; ++i) key[static_cast<size_t>(i)] = static_cast<uint8_t>(i);
    char message[64];
    for (int i = 0; i < 64; ++i) message[i] = static_cast<char>(i);
    const std::pair<size_t, uint64_t> vectors[] = {{0, 0x726fdb47dd0e0e31ull}, {1, 0x74f839c593dc67fdull}, {7, 0xab0200f58b01d137ull},
                                                   {8, 0x93f5f5799a932462ull}, {15, 0xa129ca6149be45e5ull}, {63, 0x958a324ceb064572ull}};
    for (auto [len, want] : vectors) EXPECT_EQ(fxport::xlate::sipHash24(key, std::string_view(message, len)), want) << len;
}

// Workers of a pool run at the same time, each returns under its own id, and one that crashes
// leaves the others alone. Each live worker leaves a mark and waits (10 s at most) for the other
// two: run one after another, the first would wait alone and say so.
TEST_F(Containment, WorkerPoolRunsWorkersAtOnce) {
    WorkerPool pool(WorkerLimits{}, 4);
    const std::string marks = path("marks");
    fs::create_directories(marks);
    for (size_t i = 0; i < 4; ++i)
        pool.submit(i, [i, marks] {
            if (i == 2) ::raise(SIGSEGV);
            std::ofstream(marks + "/" + std::to_string(i)) << i;
            for (int wait = 0; wait < 1000; ++wait, ::usleep(10000))
                if (fs::exists(marks + "/0") && fs::exists(marks + "/1") && fs::exists(marks + "/3")) return "worker " + std::to_string(i);
            return "worker " + std::to_string(i) + " ran alone";
        });
    std::map<size_t, WorkerOutcome> outcomes;
    while (auto done = pool.next()) outcomes[done->first] = done->second;
    ASSERT_EQ(outcomes.size(), 4u);
    for (size_t i : {0u, 1u, 3u}) {
        EXPECT_EQ(outcomes[i].kind, WorkerOutcome::Kind::Done) << i;
        EXPECT_EQ(outcomes[i].payload, "worker " + std::to_string(i));
    }
    EXPECT_EQ(outcomes[2].kind, WorkerOutcome::Kind::Crashed);
    EXPECT_EQ(outcomes[2].signal, SIGSEGV);
}

// compileEffectFiles gives, in the order of the files, what compileEffectFile gives for each
// (the same compiled output byte for byte), a contained crash among them included.
TEST_F(Containment, EffectsCompiledInParallelMatchOneByOne) {
    std::vector<std::string> files = {"hlsl/zima-lights/RenderGBuffer.fx", kCrashingEffect, "hlsl/xna-deferred/GBuffer.fx",
                                      "tests/fixtures/broken/limit_array_too_large.fx", "hlsl/rastertek/light.fx"};
    for (const auto& f : files) ASSERT_TRUE(fs::exists(f)) << f;
    std::vector<std::pair<std::string, CompileOptions>> jobs;
    for (const auto& f : files) jobs.push_back({f, uncached()});
    std::vector<std::string> parallel;
    std::vector<size_t> order;
    compileEffectFiles(jobs, [&](size_t i, EffectFileResult&& r) {
        order.push_back(i);
        parallel.push_back(r.effect ? serializeEffect(*r.effect) : r.errors.front().format());
    });
    ASSERT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
    for (size_t i = 0; i < files.size(); ++i) {
        std::string alone;
        try {
            alone = serializeEffect(compileEffectFile(files[i], uncached()));
        } catch (const CompileError& e) {
            alone = e.diagnostics().front().format();
        }
        EXPECT_EQ(parallel[i], alone) << files[i];
    }
    EXPECT_NE(parallel[1].find("FX9001"), std::string::npos) << parallel[1];
}

// One effect compiled alone: its shaders' front end in workers of the worker (FXPORT_JOBS=4) gives
// the bytes one by one gives (FXPORT_JOBS=1), and a shader that crashes glslang there is reported
// at the same shader, with the same retries, as when the build itself ran glslang on it.
std::string compiledWithJobs(const std::string& path, const char* jobs, bool keepValidPasses) {
    ::setenv("FXPORT_JOBS", jobs, 1);
    CompileOptions o = uncached();
    o.keepValidPasses = keepValidPasses;
    std::string out;
    try {
        CompiledEffect e = compileEffectFile(path, o);
        out = serializeEffect(e);
        for (const auto& d : e.diagnostics) out += "\n" + d.format();
    } catch (const CompileError& e) {
        for (const auto& d : e.diagnostics()) out += d.format() + "\n";
    }
    ::unsetenv("FXPORT_JOBS");
    return out;
}

TEST_F(Containment, ShadersCompiledInParallelMatchOneByOne) {
    for (const char* f : {"tests/fixtures/realworld/annotations_states/MacroTechniques.fx",
                          "tests/fixtures/realworld/asm_sm1/AsmPs11TextureAddressing.fx", "hlsl/xna-deferred/GBuffer.fx"}) {
        ASSERT_TRUE(fs::exists(f)) << f;
        std::string parallel = compiledWithJobs(f, "4", false);
        EXPECT_EQ(parallel, compiledWithJobs(f, "1", false)) << f;
        EXPECT_EQ(parallel.find("error"), std::string::npos) << parallel.substr(0, 500);
    }
    std::string crashing = write("crash.fx",
        "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
        "float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }\n"
        // glslang 12 dies (SIGSEGV) on a geometry shader reading SV_ClipDistance inputs held in a
        // struct nested in its input struct (rewrite/geometry_clip_inputs moves direct members only).
        "struct C { float3 d : SV_ClipDistance0; };\n"
        "struct V { float4 pos : SV_Position; C c; };\n"
        "V VS4(float4 p : POSITION0) { V v; v.pos = p; v.c.d = p.xyz; return v; }\n"
        "[maxvertexcount(3)] void GSBad(triangle V i[3], inout TriangleStream<V> s) {\n"
        "    for (int k = 0; k < 3; k++) s.Append(i[k]); }\n"
        "float4 PS4(V v) : SV_Target { return float4(1, 1, 1, 1); }\n"
        "float4 PS3() : COLOR0 { return float4(0, 1, 0, 1); }\n"
        "technique A { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n"
        "technique11 B { pass P { SetVertexShader(CompileShader(vs_4_0, VS4()));\n"
        "    SetGeometryShader(CompileShader(gs_4_0, GSBad())); SetPixelShader(CompileShader(ps_4_0, PS4())); } }\n"
        "technique C { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS3(); } }\n");
    std::string parallel = compiledWithJobs(crashing, "4", true);
    EXPECT_EQ(parallel, compiledWithJobs(crashing, "1", true));
    EXPECT_NE(parallel.find("FX9001"), std::string::npos) << parallel.substr(0, 2000);
}

// A worker killed from outside (the OOM killer, a user's kill -9) is not "ran past its limit".
TEST_F(Containment, WorkerKilledFromOutsideIsNotATimeLimit) {
    WorkerOutcome o = runInWorker(
        [] {
            ::raise(SIGKILL);
            return std::string("unreachable");
        },
        WorkerLimits{});
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::Crashed);
    EXPECT_EQ(o.signal, SIGKILL);
}

}  // namespace
