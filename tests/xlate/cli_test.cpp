// The fxport command line explains itself: --help (and per command), --version, fxc aliases,
// --depfile; and a table of bad invocations, each exiting 2 with one line naming the option and value.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>

#include "run_cli.h"

namespace fs = std::filesystem;

namespace {

using fxport::test::RunResult;
using fxport::test::runCli;

int lineCount(const std::string& s) {
    int lines = 0;
    for (char c : s) lines += c == '\n';
    return lines;
}

const std::string kEffect = "hlsl/xna-deferred/Clear.fx";

struct BadUsage {
    const char* name;
    std::string args;
    std::string mustName;  // the option (and value) the one line must contain
};

void PrintTo(const BadUsage& c, std::ostream* os) { *os << "fxport " << c.args; }

class CliBadUsage : public ::testing::TestWithParam<BadUsage> {};

TEST_P(CliBadUsage, ExitsTwoWithOneLineNamingTheOption) {
    const BadUsage& c = GetParam();
    RunResult r = runCli(c.args);
    EXPECT_EQ(r.status, 2) << "fxport " << c.args << "\n" << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_EQ(r.output.rfind("fxport: ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(c.mustName), std::string::npos) << "expected '" << c.mustName << "' in: " << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Table, CliBadUsage,
    ::testing::Values(
        BadUsage{"NoCommand", "", "missing command"},
        BadUsage{"UnknownCommand", "frobnicate", "'frobnicate'"},
        BadUsage{"UnknownOption", "compile " + kEffect + " -o x --frob", "option '--frob' is unknown"},
        BadUsage{"UnknownOptionDump", "dump " + kEffect + " --verbose", "option '--verbose' is unknown"},
        BadUsage{"UnknownSingleDash", "check hlsl -q", "option '-q' is unknown"},
        BadUsage{"OutputWithoutValue", "compile " + kEffect + " -o", "option '-o' needs a value"},
        BadUsage{"FxcOutputWithoutValue", "compile " + kEffect + " /Fo", "option '/Fo' needs a value"},
        BadUsage{"IncludeWithoutValue", "dump " + kEffect + " -I", "option '-I' needs a value"},
        BadUsage{"TechniqueWithoutValue", "compile " + kEffect + " -o x --technique", "option '--technique' needs a value"},
        BadUsage{"DepfileWithoutValue", "compile " + kEffect + " -o x --depfile", "option '--depfile' needs a value"},
        BadUsage{"EmptyTechnique", "compile " + kEffect + " -o x --technique ''", "option '--technique' has an empty value"},
        BadUsage{"DefineNotIdentifier", "compile " + kEffect + " -o x -D 1X=2", "option '-D' has a bad value '1X=2'"},
        BadUsage{"DefineEmptyName", "compile " + kEffect + " -o x -D=3", "option '-D' has a bad value '=3'"},
        BadUsage{"FxcDefineNotIdentifier", "compile " + kEffect + " -o x /D 'A B'", "option '/D' has a bad value 'A B'"},
        BadUsage{"OutputOnDump", "dump " + kEffect + " -o x", "option '-o' is not an option of 'dump'"},
        BadUsage{"DepfileOnCheck", "check hlsl --depfile x.d", "option '--depfile' is not an option of 'check'"},
        BadUsage{"ReflectionOnCompile", "compile " + kEffect + " -o x --reflection", "option '--reflection' is not an option of 'compile'"},
        BadUsage{"WarningsOnDump", "dump " + kEffect + " --warnings", "option '--warnings' is not an option of 'dump'"},
        BadUsage{"CompileWithoutOutput", "compile " + kEffect, "compile needs one input and -o OUT"},
        BadUsage{"DumpWithoutInput", "dump", "dump needs one input"},
        BadUsage{"CheckWithoutPath", "check", "check needs at least one path"},
        BadUsage{"VersionWithExtra", "--version now", "option '--version' takes no further arguments (got 'now')"},
        // An fxc switch fxport does not know was taken for a second input, and the message named none.
        BadUsage{"UnknownSlashSwitch", "compile " + kEffect + " -o x /Xyz", "option '/Xyz' is unknown"},
        BadUsage{"UnknownSlashSwitchDump", "dump " + kEffect + " /WX", "option '/WX' is unknown"},
        BadUsage{"BackwardsCompatibilityRefused", "compile " + kEffect + " -o x /Gec", "option '/Gec' is fxc's backwards-compatibility mode"},
        BadUsage{"AvoidFlowControlRefused", "compile " + kEffect + " -o x -Gfa", "option '-Gfa' makes fxc avoid flow control"},
        BadUsage{"PreferFlowControlRefused", "check hlsl /Gfp", "option '/Gfp' makes fxc prefer flow control"},
        BadUsage{"PartialPrecisionRefused", "compile " + kEffect + " -o x /Gpp", "option '/Gpp' makes fxc compute at partial precision"},
        BadUsage{"BothPackings", "compile " + kEffect + " -o x /Zpr -Zpc", "options '/Zpr' and '-Zpc' exclude each other"}),
    [](const ::testing::TestParamInfo<BadUsage>& p) { return std::string(p.param.name); });

TEST(Cli, HelpListsCommandsAndExitsZero) {
    for (const char* help : {"--help", "-h", "/?"}) {
        RunResult r = runCli(help);
        EXPECT_EQ(r.status, 0) << help << "\n" << r.output;
        for (const char* word : {"compile", "dump", "check", "--version", "/I", "/Zpr", "/Qstrip_reflect", "/Gec"})
            EXPECT_NE(r.output.find(word), std::string::npos) << help << " does not mention " << word;
    }
}

TEST(Cli, EveryCommandHasHelpWithItsOptions) {
    struct Expect {
        const char* command;
        const char* option;
    };
    for (Expect e : {Expect{"compile", "--depfile"}, Expect{"compile", "/Fo"}, Expect{"compile", "/Zpr"}, Expect{"dump", "--reflection"},
                     Expect{"check", "--warnings"}}) {
        RunResult r = runCli(std::string(e.command) + " --help");
        EXPECT_EQ(r.status, 0) << e.command << "\n" << r.output;
        EXPECT_EQ(r.output.rfind(std::string("usage: fxport ") + e.command, 0), 0u) << r.output;
        EXPECT_NE(r.output.find(e.option), std::string::npos) << e.command << " --help lacks " << e.option;
    }
}

TEST(Cli, VersionIsTheProjectVersion) {
    RunResult r = runCli("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.output.rfind(std::string("fxport ") + FXPORT_PROJECT_VERSION + " ", 0), 0u) << r.output;
}

// fxc's /Fo and /D (separate and attached) do what -o and -D do; the define reaches the effect
// (an #if on it picks an #error).
TEST(Cli, FxcAliasesCompile) {
    fs::path dir = fs::path(::testing::TempDir()) / "fxport_cli_aliases";
    fs::create_directories(dir);
    {
        std::ofstream fx(dir / "Defined.fx");
        fx << "#if !defined(WANTED) || WANTED != 3\n#error WANTED is not 3\n#endif\n"
              "float4 PS() : COLOR0 { return 1; }\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    }
    std::string fx = (dir / "Defined.fx").string(), out = (dir / "Defined.fxeffect").string();
    RunResult plain = runCli("compile '" + fx + "' --no-cache -o '" + out + "'");
    EXPECT_EQ(plain.status, 1) << plain.output;  // #error without the define
    EXPECT_NE(plain.output.find("Defined.fx(2,"), std::string::npos) << plain.output;
    fs::remove(out);
    RunResult fxc = runCli("compile '" + fx + "' --no-cache /Fo '" + out + "' /D WANTED=3");
    EXPECT_EQ(fxc.status, 0) << fxc.output;
    EXPECT_TRUE(fs::exists(out));
    fs::remove(out);
    RunResult attached = runCli("compile '" + fx + "' --no-cache /Fo'" + out + "' /DWANTED=3");
    EXPECT_EQ(attached.status, 0) << attached.output;
    EXPECT_TRUE(fs::exists(out));
}

// fxc's /Zpr and /Zpc (also -Zpr): a matrix that names no majority is row_major or column_major,
// as D3DCompile's D3DCOMPILE_PACK_MATRIX_* make it; the reflection says which.
TEST(Cli, FxcPackingSwitchesSetTheDefaultMajority) {
    fs::path dir = fs::path(::testing::TempDir()) / "fxport_cli_packing";
    fs::create_directories(dir);
    std::ofstream(dir / "m.hlsl") << "float4x4 M;\nfloat4 main(float4 p : SV_Position) : SV_Target { return mul(p, M); }\n";
    const std::string dump = "dump '" + (dir / "m.hlsl").string() + "' --entry main --profile ps_5_0 ";
    struct Expect {
        const char* switches;
        const char* majority;
    };
    for (Expect e : {Expect{"", "column_major"}, Expect{"/Zpr", "row_major"}, Expect{"-Zpr", "row_major"}, Expect{"/Zpc", "column_major"},
                     Expect{"/Zpr /Zpr", "row_major"}}) {
        RunResult r = runCli(dump + e.switches);
        ASSERT_EQ(r.status, 0) << e.switches << "\n" << r.output;
        EXPECT_NE(r.output.find(std::string("float4x4 M   @0 size 64 ") + e.majority + "\n"), std::string::npos) << e.switches << "\n" << r.output;
    }
}

// fxc's optimisation, debug, strip and strictness switches (real build scripts: /O3 /Qstrip_reflect,
// /nologo /O1, /Ges) are accepted and change nothing: the compiled effect is the same file.
TEST(Cli, FxcSwitchesThatChangeNothingAreIgnored) {
    fs::path dir = fs::path(::testing::TempDir()) / "fxport_cli_ignored";
    fs::create_directories(dir);
    const std::string plain = (dir / "plain.fxeffect").string(), flagged = (dir / "flagged.fxeffect").string();
    ASSERT_EQ(runCli("compile " + kEffect + " --no-cache -o '" + plain + "'").status, 0);
    RunResult r = runCli("compile " + kEffect + " --no-cache /O3 /Od -O0 /O1 /O2 /Zi /nologo /Qstrip_reflect /Qstrip_debug /Ges /Gis -o '" + flagged + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    auto read = [](const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    };
    EXPECT_EQ(read(plain), read(flagged));
    EXPECT_FALSE(read(plain).empty());
}

// --depfile names the output and the effect and every file it includes, in Make syntax.
TEST(Cli, DepfileListsEveryInclude) {
    fs::path dir = fs::path(::testing::TempDir()) / "fxport_cli_depfile";
    fs::create_directories(dir / "common");
    std::ofstream(dir / "common" / "Colour Helpers.fxh") << "float4 Grey(float g) { return float4(g, g, g, 1); }\n";
    std::ofstream(dir / "Inner.fxh") << "#include \"common/Colour Helpers.fxh\"\n";
    std::ofstream(dir / "Uses.fx") << "#include \"Inner.fxh\"\nfloat4 PS() : COLOR0 { return Grey(0.5); }\n"
                                      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    std::string out = (dir / "Uses.fxeffect").string(), dep = (dir / "Uses.d").string();
    RunResult r = runCli("compile '" + (dir / "Uses.fx").string() + "' -o '" + out + "' --depfile '" + dep + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(dep);
    std::stringstream text;
    text << in.rdbuf();
    std::string d = text.str();
    EXPECT_EQ(d.rfind(out + ":", 0), 0u) << d;
    EXPECT_NE(d.find(fs::weakly_canonical(dir / "Uses.fx").string()), std::string::npos) << d;
    EXPECT_NE(d.find(fs::weakly_canonical(dir / "Inner.fxh").string()), std::string::npos) << d;
    // A space in a path is escaped for Make and Ninja.
    EXPECT_NE(d.find((fs::weakly_canonical(dir / "common").string()) + "/Colour\\ Helpers.fxh"), std::string::npos) << d;
}

}  // namespace
