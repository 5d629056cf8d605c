// One .shader_test file run at one shader model, as vkd3d's runner runs it at that model: blocks
// in file order; [require] sets the range and options of what follows; each shader section is
// compile-checked (fail/notimpl sections must be rejected, the rest compiled); [test] lines run
// only after a section that should compile at this model, as in vkd3d; uniforms, resources and
// targets persist through the file.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "gpu_backend.h"
#include "results.h"
#include "section_compiler.h"
#include "shader_test_file.h"

namespace conformance {

struct RunOptions {
    std::string tempDir;
    std::string cacheDir;
    std::ostream* verbose = nullptr;  // each section's outcome and each failing probe
    // Crash containment (file_pool.cpp): before each compile and draw the run writes "M\tLINE" to
    // markerFd; a rerun after a crash gets that line in crashLines and counts it as crashed
    // instead of trying it again, so the rest of the file still runs.
    int markerFd = -1;
    std::set<int> crashLines;
};

// Models this runner covers; the others (5.1, 6.x) are out of scope.
inline constexpr int kModels[] = {20, 30, 40, 50};
// Whether any [require] range of the file allows `model` (files with none allow every model).
bool fileAllowsModel(const ShaderTestFile& file, int model);

class ModelRun {
public:
    ModelRun(const ShaderTestFile& file, int model, const RunOptions& options, SessionKind session);
    ~ModelRun();
    ModelResult run();
    const std::vector<Failure>& failures() const { return failures_; }

private:
    struct ShaderSlot {
        const Block* block = nullptr;
        bool compiled = false;     // fxport compiled it at this model
        std::string diagnostic;    // why not
    };
    enum class DrawState { None, Drawn, Failed, Skipped };

    void compileSectionsAhead();
    void onRequire(const Block& block);
    void onShader(const Block& block);
    void onResource(const Block& block);
    void onTest(const Block& block);
    void countCompile(const Block& block, SectionKind kind, bool expectReject, const CompileOutcome& outcome);
    void runTestLine(const Line& line, const std::string& directive);
    void doUniform(const std::string& args);
    void doDraw(const std::string& args, int line);
    void doDispatch(const std::string& args, int line);
    void gpuStep(int line, const std::function<void()>& step);
    void noteDrawOutcome(int line);  // records a failed or skipped draw/dispatch
    void doProbe(const std::string& args, int line);
    void doClear(const std::string& args);
    void doCopy(const std::string& args);
    void skipProbe(const std::string& reason);
    void failProbe(int line, const std::string& detail);
    ShaderSet drawStages(const DrawCall& call);  // the stages a draw runs (Unsupported when it cannot)
    StageSource stageSource(Stage stage) const;
    GpuBackend& gpu();  // the session of this model (gpu_backend.h), made on first use
    void log(const std::string& text);
    void mark(int line) const;
    bool crashedBefore(int line) const { return options_.crashLines.count(line) > 0; }
    std::string where(int line) const;

    const ShaderTestFile& file_;
    int model_;
    RunOptions options_;
    SessionKind sessionKind_;
    ModelResult result_;
    std::vector<Failure> failures_;
    SectionCompiler compiler_;

    RequireDesc require_;
    bool inRange_ = true;
    std::string missingCapability_;  // a [require] capability this runner does not claim
    std::map<Stage, ShaderSlot> shaders_;
    std::map<const Block*, CompileOutcome> compiledAhead_;  // compileSectionsAhead()'s outcomes
    bool testsRun_ = true;           // the last section should compile here (vkd3d's hlsl_hrs)
    std::string testsSkipReason_;    // set when tests run but cannot execute (reason of the skip)

    std::vector<std::uint32_t> uniforms_;
    std::unique_ptr<GpuBackend> gpu_;
    FixedFunctionDesc fixedFunction_;  // fog, point size, clip planes, alpha test, shade mode
    std::map<std::string, std::string> stickyStates_;                 // test states the runner cannot set
    DrawState drawState_ = DrawState::None;
    std::string drawNote_;  // why the last draw failed or was skipped
    std::string layoutGuess_;  // the last draw's uniform placement was a guess (UniformLayout::guess)
};

}  // namespace conformance
