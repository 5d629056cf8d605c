// Robustness (issue 15): inputs that crashed, hung or exhausted fxport before. Each fixture under
// tests/fixtures/broken/ fails with its own diagnostic id at the right file:line, in the library and
// through `fxport check` (which must exit 1, never die of a signal); inputs of the sizes that did the
// damage (30 000 nested parentheses, 2 000 nested includes ...) are generated at run time. Also: the
// front-end worker's containment, the command line's argument checks and atomic output.
//
// Paths are relative to the repository root (the tests run there, see CMakeLists.txt).
#include <gtest/gtest.h>

#include <cstdint>
#include <variant>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "effect/effect_validation.h"
#include "frontend/front_end_worker.h"
#include "fx/text_util.h"
#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "run_cli.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

using fxport::test::RunResult;
using fxport::test::runCli;

const std::string kDir = "tests/fixtures/broken/";
const std::string kTail =
    "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
    "float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

struct LimitCase {
    const char* name;
    std::string effect;
    const char* id;
    int line;  // of the first error, in the effect itself
};

void PrintTo(const LimitCase& c, std::ostream* os) { *os << c.name; }

std::vector<LimitCase> fixtureCases() {
    return {
        {"NestedInitializer", kDir + "limit_nesting_initializer.fx", diag::kNestingTooDeep, 2},
        {"NestedShaderCode", kDir + "limit_nesting_code.fx", diag::kNestingTooDeep, 3},
        {"NestedIfExpression", kDir + "limit_nesting_if.fx", diag::kNestingTooDeep, 2},
        {"NestedMacroCalls", kDir + "limit_nested_macro_calls.fx", diag::kNestingTooDeep, 3},
        {"MacroCallsNestedInArguments", kDir + "limit_macro_call_nesting.fx", diag::kMacroLimit, 5},
        {"NestingOnlyAfterExpansion", kDir + "limit_nesting_after_expansion.fx", diag::kNestingTooDeep, 303},
        {"ArrayTooLarge", kDir + "limit_array_too_large.fx", diag::kArrayTooLarge, 2},
        {"LineDirectiveOverflow", kDir + "limit_line_directive.fx", diag::kPreprocessor, 1},
        // glslang 12 crashed on each of these; fxport reports them first.
        {"RedefinedGlobal", kDir + "redefined_global.fx", diag::kHlsl, 3},
        {"GsUnnamedParameter", kDir + "gs_unnamed_parameter.fx", diag::kHlsl, 5},
        {"GsSliceParameter", kDir + "gs_slice_parameter.fx", diag::kHlsl, 5},
        {"GsPointInputNotArray", kDir + "gs_point_not_array.fx", diag::kHlsl, 5},
        {"MismatchedBracket", kDir + "mismatched_bracket.fx", diag::kHlsl, 3},
        {"NestedFunction", kDir + "nested_function.fx", diag::kHlsl, 5},
        {"UndeclaredNameInTernary", kDir + "ternary_undeclared.fx", diag::kHlsl, 5},
        {"MatrixDimensionOverFour", kDir + "matrix_dimension.fx", diag::kHlsl, 3},
        {"AdjacentNamesInTernary", kDir + "ternary_adjacent_names.fx", diag::kHlsl, 6},
        {"UndeclaredSwizzleNameInTernary", kDir + "ternary_undeclared_swizzle_name.fx", diag::kHlsl, 5},
        {"UndeclaredNameInTernaryNamedInAsm", kDir + "ternary_undeclared_asm_name.fx", diag::kHlsl, 14},
        {"PostfixOnLiteral", kDir + "postfix_on_literal.fx", diag::kHlsl, 5},
        {"PostfixOnUndeclaredName", kDir + "postfix_on_undeclared.fx", diag::kHlsl, 5},
        {"PostfixOnCall", kDir + "postfix_on_call.fx", diag::kHlsl, 5},
        {"PostfixOnUnknownMember", kDir + "postfix_on_unknown_member.fx", diag::kHlsl, 6},
        {"UndeclaredNameInInitializedArraySize", kDir + "array_size_undeclared.fx", diag::kHlsl, 7},
        // fxport's own: wrong compiled effects that failed their own validation on load.
        {"PackoffsetOverlap", kDir + "packoffset_overlap.fx", diag::kHlsl, 7},
        {"InitializerTooLong", kDir + "initializer_too_long.fx", diag::kHlsl, 3},
        {"EmptyBracesInInitializerArithmetic", kDir + "initializer_empty_braces_arithmetic.fx", diag::kHlsl, 6},
        // A crash the checks above do not know: contained in the worker, reported at the entry point.
        {"ContainedGlslangCrash", kDir + "contained_glslang_crash.fx", diag::kFrontEndCrashed, 10},
    };
}

std::string shellQuoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

// The first error of compiling `path`; fails the test if it compiles.
Diagnostic firstError(const std::string& path, const CompileOptions& options = noCache()) {
    try {
        compileEffectFile(path, options);
    } catch (const CompileError& e) {
        for (const auto& d : e.diagnostics())
            if (d.severity == Severity::Error) return d;
    }
    ADD_FAILURE() << path << " compiled";
    return {};
}

class LimitFixture : public ::testing::TestWithParam<LimitCase> {};

TEST_P(LimitFixture, LibraryNamesIdFileAndLine) {
    const LimitCase& c = GetParam();
    ASSERT_TRUE(fs::exists(c.effect)) << c.effect;
    Diagnostic d = firstError(c.effect);
    EXPECT_EQ(d.id, c.id) << d.format();
    EXPECT_EQ(d.location.file, c.effect) << d.format();
    EXPECT_EQ(d.location.line, c.line) << d.format();
    EXPECT_GT(d.location.column, 0) << d.format();
    EXPECT_EQ(d.message.find('\n'), std::string::npos) << d.message;
}

TEST_P(LimitFixture, CliCheckExitsOneWithTheLocation) {
    const LimitCase& c = GetParam();
    RunResult r = runCli("check " + shellQuoted(c.effect) + " --no-cache");
    ASSERT_TRUE(r.exited) << "fxport check died:\n" << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(c.effect + "(" + std::to_string(c.line) + ","), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(std::string("error ") + c.id + ":"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("0 passed, 1 failed"), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, LimitFixture, ::testing::ValuesIn(fixtureCases()),
                         [](const ::testing::TestParamInfo<LimitCase>& p) { return std::string(p.param.name); });

// A folder of generated inputs, removed at the end.
struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("fxport_robustness_" + std::to_string(::getpid()));
    Scratch() { fs::create_directories(dir); }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir / name, std::ios::binary) << text;
        return (dir / name).string();
    }
};

std::string repeat(const std::string& s, int n) {
    std::string out;
    out.reserve(s.size() * static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

// The sizes from the issue: each crashed (stack overflow) or took seconds to gigabytes before.
// mul() with a float1, a float1 member or a float1 call result crashed glslang 12 and was refused
// (FX1404); mixed_shapes.h now writes fxc's product out, so they compile (values: HlslShapes).
TEST(Robustness, FormerGlslangCrashesInMulNowCompile) {
    for (const char* name : {"float1_mul.fx", "float1_member_mul.fx", "float1_call_mul.fx"}) {
        CompiledEffect e = compileEffectFile(std::string("tests/fixtures/former_crashes/") + name, noCache());
        EXPECT_EQ(e.shaders.size(), 2u) << name;
    }
}

// The check for `(a + 1)--` leaves alone a `++` that starts the statement after a `for`, `while`
// or `if` header (`for (...) ++n;` was refused as a postfix on a value).
TEST(Robustness, PrefixIncrementAfterAStatementHeaderCompiles) {
    CompiledEffect e = compileShaderSource("RWStructuredBuffer<int> o;\n[numthreads(1, 1, 1)] void main() {\n"
                                           "int n = 0; for (int k = 0; k < 2; k++) ++n; while (n < 5) ++n; if (n > 0) --n; o[0] = n; }\n",
                                           "prefix_after_header.hlsl", {{"prefix_after_header.hlsl", "main", "cs_5_0"}}, noCache());
    EXPECT_EQ(e.shaders.size(), 1u);
}

TEST(Robustness, InputsOfTheSizesThatCrashedGetDiagnostics) {
    Scratch s;
    struct Big {
        std::string path;
        const char* id;
        int line;
    };
    std::vector<Big> inputs = {
        {s.write("parens30000.fx", "float K = " + repeat("(", 30000) + "1" + repeat(")", 30000) + ";\n" + kTail), diag::kNestingTooDeep, 1},
        {s.write("braces30000.fx", "float K = " + repeat("{", 30000) + "1" + repeat("}", 30000) + ";\n" + kTail), diag::kNestingTooDeep, 1},
        {s.write("code4500.fx", "float4 F(float4 p) { return " + repeat("(", 4500) + "p" + repeat(")", 4500) + "; }\n" + kTail),
         diag::kNestingTooDeep, 1},
        {s.write("if100000.fx", "#if " + repeat("(", 100000) + "1" + repeat(")", 100000) + "\n#endif\n" + kTail), diag::kNestingTooDeep, 1},
        {s.write("macro2000.fx", "#define F(x) (x)\nfloat K = " + repeat("F(", 2000) + "1" + repeat(")", 2000) + ";\n" + kTail),
         diag::kNestingTooDeep, 2},
    };
    // 2 000 nested includes: refused at the 33rd level, where the 32nd file includes the next.
    for (int i = 0; i < 2000; ++i) s.write("chain" + std::to_string(i) + ".fxh", "#include \"chain" + std::to_string(i + 1) + ".fxh\"\n");
    s.write("chain2000.fxh", "float4 Last;\n");
    inputs.push_back({s.write("chain.fx", "#include \"chain0.fxh\"\n" + kTail), diag::kIncludeLimit, 1});
    // A hang here is caught by the test's ctest TIMEOUT (tests/xlate/CMakeLists.txt); how fast the
    // refusals are is not asserted (speed belongs in benchmarks).
    for (const auto& in : inputs) {
        Diagnostic d = firstError(in.path);
        EXPECT_EQ(d.id, in.id) << in.path << ": " << d.format().substr(0, 300);
        if (in.id != diag::kIncludeLimit) EXPECT_EQ(d.location.line, in.line) << in.path;
        else EXPECT_NE(d.location.file.find("chain30.fxh"), std::string::npos) << d.format();
    }
    // More #include directives than the limit, none nested: FX1105 at the one past it.
    std::string many;
    for (int i = 0; i < 1100; ++i) many += "#include \"leaf.fxh\"\n";
    s.write("leaf.fxh", "\n");
    Diagnostic d = firstError(s.write("many.fx", many + kTail));
    EXPECT_EQ(d.id, diag::kIncludeLimit) << d.format();
    EXPECT_EQ(d.location.line, 1025) << d.format();
}

TEST(Robustness, FileOverTheSizeLimitIsRefusedBeforeReading) {
    Scratch s;
    std::string path = s.write("huge.fx", "// " + std::string(5u << 20, 'x') + "\n" + kTail);
    Diagnostic d = firstError(path);
    EXPECT_EQ(d.id, diag::kInputTooLarge) << d.format();
}

TEST(Robustness, SampleMaskBeyondIntCompiles) {
    // Valid: D3D10's SetBlendState(..., 0xFFFFFFFF). The value used to reach an int conversion
    // that UBSan reports (the sanitizer build runs this test).
    CompiledEffect e = compileEffectFile(kDir + "blend_full_sample_mask.fx", noCache());
    ASSERT_EQ(e.techniques.size(), 1u);
    // The typed state keeps the mask's 32 bits (an int, all bits set).
    bool found = false;
    for (const auto& st : e.techniques[0].passes[0].states)
        if (st.state == RenderState::MultiSampleMask) {
            found = std::holds_alternative<int>(st.value) && static_cast<std::uint32_t>(std::get<int>(st.value)) == 0xFFFFFFFFu;
            EXPECT_NE(describeStateAssignment(st, e).find("MultiSampleMask"), std::string::npos);
        }
    EXPECT_TRUE(found);
}

TEST(Robustness, OutOfOrderPackoffsetCompilesAndLoadsBack) {
    CompiledEffect e = compileEffectFile(kDir + "packoffset_out_of_order.fx", noCache());
    ASSERT_EQ(e.shaders.size(), 2u);
    for (const auto& shader : e.shaders)
        for (const auto& r : shader.uniformRangesRead) {
            EXPECT_GT(r.size, 0) << shader.entryPoint;
            EXPECT_GE(r.offset, 0) << shader.entryPoint;
        }
    // The file a cache or `fxport compile` writes passes the loader's validation.
    CompiledEffect back = deserializeEffect(serializeEffect(e), "packoffset_out_of_order.fxeffect");
    EXPECT_EQ(back.shaders.size(), 2u);
}

// A macro that doubles 40 times: refused by its size before glslang expands it (macro_bounds.h),
// located where it is used by that size (FX1106), not by the worker's CPU limit (it was the worker's
// 60 s CPU limit); `fxport check` goes on to the next file and prints its summary.
TEST(Robustness, RunawayMacroIsRefusedBySizeAndCheckGoesOn) {
    RunResult r = runCli("check " + shellQuoted(kDir + "limit_exponential_macro.fx") + " " + shellQuoted(kDir + "blend_full_sample_mask.fx") + " --no-cache");
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("limit_exponential_macro.fx(43,15): error FX1106: macro 'D40' expands to more than 32 MiB"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("blend_full_sample_mask.fx: ok"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1 passed, 1 failed"), std::string::npos) << r.output;
}

// The chain split over an include, defined in reverse order (a macro names one defined after it),
// and doubled through a function-like macro's body: all bounded by size.
TEST(Robustness, RunawayMacroAcrossAnIncludeIsRefusedBySize) {
    fs::path dir = fs::temp_directory_path() / ("fxport-macro-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string header, effect = "#include \"half.fxh\"\n";
    for (int i = 40; i > 20; --i) effect += "#define D" + std::to_string(i) + " D" + std::to_string(i - 1) + " D" + std::to_string(i - 1) + "\n";
    header += "#define TWICE(a) a a\n#define D0 x\n";
    for (int i = 1; i <= 20; ++i) header += "#define D" + std::to_string(i) + " TWICE(D" + std::to_string(i - 1) + ")\n";
    effect += "float Scale = D40;\nfloat4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
              "technique T { pass P { VertexShader = compile vs_2_0 VS(); } }\n";
    std::ofstream(dir / "half.fxh") << header;
    std::ofstream(dir / "split.fx") << effect;
    RunResult r = runCli("check " + shellQuoted((dir / "split.fx").string()) + " --no-cache");
    fs::remove_all(dir);
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("error FX1106: macro 'D40' expands to more than"), std::string::npos) << r.output;
}

// A large macro that is never used is no error (fxc expands only what is used).
TEST(Robustness, UnusedLargeMacroIsNoError) {
    std::string text = "#define D0 x\n";
    for (int i = 1; i <= 40; ++i) text += "#define D" + std::to_string(i) + " D" + std::to_string(i - 1) + " D" + std::to_string(i - 1) + "\n";
    text += "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
            "float4 PS() : COLOR0 { return float4(1, 1, 1, 1); }\n"
            "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    CompiledEffect e = compileEffectSource(text, "unused_macro.fx", noCache());
    EXPECT_EQ(e.shaders.size(), 2u);
}

// A function-like macro repeating its argument, called nested 40 deep: the call is bounded by size
// too (each level doubles), at the call.
TEST(Robustness, RunawayNestedMacroCallsAreRefusedBySize) {
    std::string text = "#define D(a) a a\nfloat Scale = ";
    for (int i = 0; i < 40; ++i) text += "D(";
    text += "x";
    for (int i = 0; i < 40; ++i) text += ")";
    text += ";\nfloat4 VS(float4 p : POSITION0) : POSITION0 { return p; }\ntechnique T { pass P { VertexShader = compile vs_2_0 VS(); } }\n";
    fs::path file = fs::temp_directory_path() / ("fxport-nested-macro-" + std::to_string(::getpid()) + ".fx");
    std::ofstream(file) << text;
    RunResult r = runCli("check " + shellQuoted(file.string()) + " --no-cache");
    fs::remove(file);
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(".fx(2,15): error FX1106: macro 'D' expands to more than"), std::string::npos) << r.output;
}

// What the size bound does not foresee: a macro name made by token pasting (`CAT(D, 40)` becomes
// D40 only when expanded). The worker's limits still stop it (FX1106 at the effect).
TEST(Robustness, RunawayMacroThroughTokenPastingIsStoppedByTheWorker) {
    std::string text = "#define CAT(a, b) a##b\n#define D0 x\n";
    for (int i = 1; i <= 40; ++i) text += "#define D" + std::to_string(i) + " D" + std::to_string(i - 1) + " D" + std::to_string(i - 1) + "\n";
    text += "float Scale = CAT(D, 40);\nfloat4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
            "technique T { pass P { VertexShader = compile vs_2_0 VS(); } }\n";
    fs::path file = fs::temp_directory_path() / ("fxport-pasted-macro-" + std::to_string(::getpid()) + ".fx");
    std::ofstream(file) << text;
    RunResult r = runCli("check " + shellQuoted(file.string()) + " --no-cache", "FXPORT_WORKER_SECONDS=2");
    fs::remove(file);
    ASSERT_TRUE(r.exited) << r.output;
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("error FX1106: preprocessing the effect ran past its limit"), std::string::npos) << r.output;
}

// The worker itself: what comes back for each way a front end can fail.
TEST(FrontEndWorker, ReturnsThePayload) {
    WorkerOutcome o = runInWorker([] { return std::string("compiled"); }, WorkerLimits{});
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::Done);
    EXPECT_EQ(o.payload, "compiled");
}

TEST(FrontEndWorker, CrashIsReportedWithTheLastProgress) {
    WorkerOutcome o = runInWorker(
        [] {
            reportWorkerProgress("shader one");
            reportWorkerProgress("shader two");
            ::raise(SIGSEGV);
            return std::string("unreachable");
        },
        WorkerLimits{});
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::Crashed);
    EXPECT_EQ(o.signal, SIGSEGV);
    EXPECT_EQ(o.progress, "shader two");
}

TEST(FrontEndWorker, EndlessWorkIsStoppedByTheCpuLimit) {
    WorkerLimits limits;
    limits.cpuSeconds = 1;  // a worker that outlived it would hang the test: its ctest TIMEOUT says so
    WorkerOutcome o = runInWorker(
        [] {
            volatile unsigned long n = 0;
            for (;;) n = n + 1;
            return std::string();
        },
        limits);
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::TimedOut);
}

#if !defined(__SANITIZE_ADDRESS__)
// (Under ASan the worker has no address-space limit: ASan's shadow memory is most of it.)
TEST(FrontEndWorker, AllocationPastTheMemoryLimitIsOutOfMemory) {
    WorkerLimits limits;
    limits.memoryBytes = size_t{64} << 20;
    WorkerOutcome o = runInWorker(
        [] {
            std::vector<std::string> hog;
            for (int i = 0; i < 4096; ++i) hog.emplace_back(size_t{1} << 20, 'x');  // 4 GiB
            return std::to_string(hog.size());
        },
        limits);
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::OutOfMemory);
}
#endif

// Command line: usage errors name the option and the value (exit 2); -o is written atomically
// and never over the input.
TEST(RobustnessCli, IncludeFolderMustExist) {
    RunResult r = runCli("check " + shellQuoted(kDir + "empty.fx") + " -I /nonexistent-fxport-folder");
    ASSERT_TRUE(r.exited);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("-I"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/nonexistent-fxport-folder"), std::string::npos) << r.output;
}

TEST(RobustnessCli, DefineWithoutNameIsAUsageError) {
    RunResult r = runCli("check " + shellQuoted(kDir + "empty.fx") + " -D =");
    ASSERT_TRUE(r.exited);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("option '-D' has a bad value '='"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("(1,1)"), std::string::npos) << r.output;
}

TEST(RobustnessCli, OutputEqualToInputIsRefused) {
    Scratch s;
    std::string fx = s.write("self.fx", "float4x4 World;\n" + kTail);
    RunResult r = runCli("compile " + shellQuoted(fx) + " -o " + shellQuoted((s.dir / "." / "self.fx").string()) + " --no-cache");
    ASSERT_TRUE(r.exited);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(readText(fx), "float4x4 World;\n" + kTail);
}

TEST(RobustnessCli, OutputIsReplacedWholeOrNotAtAll) {
    Scratch s;
    std::string out = s.write("out.fxeffect", "previous good output");
    // A failed compile leaves the previous output as it was.
    RunResult bad = runCli("compile " + shellQuoted(kDir + "redefined_global.fx") + " -o " + shellQuoted(out) + " --no-cache");
    ASSERT_TRUE(bad.exited);
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_EQ(readText(out), "previous good output");
    // A good one replaces it with a loadable file, and leaves no temporary file beside it.
    RunResult good = runCli("compile " + shellQuoted(kDir + "blend_full_sample_mask.fx") + " -o " + shellQuoted(out) + " --no-cache");
    ASSERT_TRUE(good.exited);
    EXPECT_EQ(good.status, 0) << good.output;
    EXPECT_EQ(loadEffectFile(out).techniques.size(), 1u);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(s.dir)) files += entry.path().filename().string().rfind("out.fxeffect", 0) == 0;
    EXPECT_EQ(files, 1);
}

// Compiled-effect files are untrusted: a changed byte fails the checksum, a consistent-looking
// file with impossible values fails validation, GLSL that does not match its hash is refused.
class UntrustedEffectFile : public ::testing::Test {
protected:
    std::string file = serializeEffect(compileEffectFile(kDir + "blend_full_sample_mask.fx", noCache()));
    static std::string loadError(const std::string& text) {
        try {
            deserializeEffect(text, "tampered.fxeffect");
        } catch (const CompileError& e) {
            EXPECT_EQ(e.diagnostics().front().id, diag::kEffectFile);
            EXPECT_EQ(e.diagnostics().front().location.file, "tampered.fxeffect");
            return e.diagnostics().front().message;
        }
        ADD_FAILURE() << "a tampered compiled effect loaded";
        return {};
    }
};

TEST_F(UntrustedEffectFile, IntactFileLoads) { EXPECT_EQ(deserializeEffect(file, "ok.fxeffect").techniques.size(), 1u); }

TEST_F(UntrustedEffectFile, ChangedByteFailsTheChecksum) {
    auto j = nlohmann::json::parse(file);
    j["uniformBlocks"][0]["size"] = 4096;
    EXPECT_NE(loadError(j.dump()).find("checksum"), std::string::npos);
}

// A sampler binding's array elements, registers and parameter-driven states are bounded too: the
// runtime binds units unit..unit+elements-1 and reads the parameter at Apply().
TEST_F(UntrustedEffectFile, SamplerBindingsOutOfRangeFailValidation) {
    const std::string sampled = serializeEffect(compileEffectFile("tests/fixtures/runtime/ParameterStates.fx", noCache()));
    auto withSampler = [&](const std::function<void(nlohmann::json&)>& change) {
        auto j = nlohmann::json::parse(sampled);
        for (auto& shader : j["shaders"])
            if (!shader["samplers"].empty() && shader["samplers"][0].contains("stateParameters")) {
                change(shader["samplers"][0]);
                break;
            }
        return loadError(resealEffectFile(j.dump()));
    };
    EXPECT_NE(withSampler([](nlohmann::json& b) { b["elements"] = 1 << 30; }).find("binds a sampler of"), std::string::npos);
    EXPECT_NE(withSampler([](nlohmann::json& b) { b["textureRegister"] = 100000; }).find("binds a sampler of"), std::string::npos);
    EXPECT_NE(withSampler([](nlohmann::json& b) { b["stateParameters"][0]["parameter"] = 999; }).find("reads a sampler state from parameter"),
              std::string::npos);
}

TEST_F(UntrustedEffectFile, ImpossibleValuesFailValidationEvenWhenResealed) {
    auto j = nlohmann::json::parse(file);
    j["uniformBlocks"][0]["size"] = -64;  // what Bones[2147483647] produced
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("inconsistent"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["parameters"][0]["offset"] = 1 << 20;  // outside its block
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("outside its constant buffer"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["techniques"][0]["passes"][0]["vertexShader"]["shaders"][0] = 7;  // no shader #7
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("does not exist"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["techniques"][0]["passes"][0]["states"][0]["state"] = "NoSuchState";
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("NoSuchState"), std::string::npos);
}

// A float where an int belongs reached nlohmann's get<int>: UBSan, out-of-range double-to-int (CI's
// fuzz smoke, 2026-11-25). It is refused before any field is read.
TEST_F(UntrustedEffectFile, FloatWhereAnIntBelongsIsRefused) {
    auto j = nlohmann::json::parse(file);
    j["uniformBlocks"][0]["size"] = 1e40;
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("'size' is 1e+40, not an integer"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["version"] = -1e300;
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("'version'"), std::string::npos);
    // The second crash (CI fuzz smoke, 2026-11-25): a shader index read through get<std::vector<int>>.
    j = nlohmann::json::parse(file);
    j["techniques"][0]["passes"][0]["vertexShader"]["shaders"][0] = 3.33333e98;
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("'shaders' is 3.33333e+98, not an integer"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["techniques"][0]["passes"][0]["vertexShader"]["selector"] = nlohmann::json::array({nlohmann::json::array({"const", 2.5e30})});
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("'selector'"), std::string::npos);
    j = nlohmann::json::parse(file);
    j["futureField"] = 1.5;  // a field the reader does not know is an int field by default
    EXPECT_NE(loadError(resealEffectFile(j.dump())).find("'futureField'"), std::string::npos);
    // Float fields stay floats: a parameter's default value loads.
    j = nlohmann::json::parse(file);
    ASSERT_EQ(j["parameters"][0]["name"], "World");
    j["parameters"][0]["default"] = std::vector<double>(16, 0.5);
    EXPECT_EQ(deserializeEffect(resealEffectFile(j.dump()), "floats.fxeffect").parameters[0].defaultValue, std::vector<double>(16, 0.5));
}

TEST_F(UntrustedEffectFile, GlslMustMatchItsHash) {
    auto j = nlohmann::json::parse(file);
    j["shaders"][0]["glsl"] = j["shaders"][0]["glsl"].get<std::string>() + "\n// injected\n";
    j.erase("checksum");
    j["checksum"] = contentHash(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));  // checksum right, hash stale
    EXPECT_NE(loadError(j.dump()).find("does not match its hash"), std::string::npos);
}

// A cache entry with well-formed but wrong values is not used: the effect is compiled again and
// the entry replaced.
TEST(UntrustedCache, DamagedEntryIsRecompiled) {
    Scratch s;
    CompileOptions options;
    options.cacheDir = (s.dir / "cache").string();
    CompiledEffect first = compileEffectFile(kDir + "blend_full_sample_mask.fx", options);
    std::vector<fs::path> entries;
    for (const auto& e : fs::directory_iterator(options.cacheDir))
        if (e.path().extension() == ".fxeffect") entries.push_back(e.path());  // not the cache's secret
    ASSERT_EQ(entries.size(), 1u);
    std::string entry = readText(entries[0].string());
    size_t json = entry.find("\n=\n");
    ASSERT_NE(json, std::string::npos);
    auto j = nlohmann::json::parse(entry.substr(json + 3));
    j["uniformBlocks"][0]["size"] = -64;
    j["shaders"][0]["glsl"] = "void main() { /* injected */ }";
    std::ofstream(entries[0], std::ios::binary) << entry.substr(0, json + 3) << resealEffectFile(j.dump());
    CompiledEffect second = compileEffectFile(kDir + "blend_full_sample_mask.fx", options);
    EXPECT_EQ(second.uniformBufferSize, first.uniformBufferSize);
    EXPECT_EQ(second.shaders[0].glsl, first.shaders[0].glsl);
    EXPECT_EQ(readText(entries[0].string()).find("injected"), std::string::npos);  // replaced
}

}  // namespace
