// One file at one shader model (see model_run.h).
#include "model_run.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "fxport/graphics.h"
#include "fxport/xlate/compiled_effect.h"
#include "fxport/xlate/diagnostics.h"
#include "qualifiers.h"
#include "uniform_layout.h"

namespace conformance {

namespace {


bool startsWith(const std::string& s, const char* prefix) { return s.compare(0, std::strlen(prefix), prefix) == 0; }

bool stageRunsAt(Stage stage, int model) {
    if (stage == Stage::Geometry || stage == Stage::Compute) return model >= 40;
    if (stage == Stage::Hull || stage == Stage::Domain) return model >= 50;
    return true;
}

// Capabilities of [require] this runner can honour; the rest skip the tests after them.
bool capabilityHonoured(const std::string& capability, SessionKind session) {
    // D3D9's fixed-function fog, points and clip planes: GraphicsDevice::FixedFunction of the XNA
    // session (as vkd3d's Vulkan runner emulates them at every model); D3D11 has none.
    if (isFixedFunctionCapability(capability)) return session == SessionKind::Xna;
    // Float and integer formats: their typed UAV loads ("uav-load") are core GL image loads
    // (r32f ... rgba32f, r32ui ... rgba32i). The XNA session has no integer SurfaceFormat: it
    // skips such resources itself (Unsupported), the D3D11 session makes them.
    if (capability == "tessellation-shader") return true;  // hull and domain shaders: DrawPatches
    if (capability == "geometry-shader") return true;      // the effect's pass takes the geometry shader
    if (!startsWith(capability, "format ")) return false;
    for (const char* type : {"-float", "-uint", "-sint"})
        if (capability.find(type) != std::string::npos) return true;
    return false;
}

std::string firstWords(const std::string& s, int words) {
    std::istringstream in(s);
    std::string out, w;
    for (int i = 0; i < words && in >> w; ++i) out += (out.empty() ? "" : " ") + w;
    return out;
}

}  // namespace

bool fileAllowsModel(const ShaderTestFile& file, int model) {
    bool sawRequire = false;
    for (const Block& b : file.blocks) {
        if (b.kind != BlockKind::Require) continue;
        sawRequire = true;
        RequireDesc r = parseRequire(b);
        if (model >= r.minModel && model <= r.maxModel) return true;
    }
    // Sections before the first [require] run at every model.
    return !sawRequire || (!file.blocks.empty() && file.blocks.front().kind != BlockKind::Require);
}

ModelRun::ModelRun(const ShaderTestFile& file, int model, const RunOptions& options, SessionKind session)
    : file_(file), model_(model), options_(options), sessionKind_(session), compiler_(options.tempDir, options.cacheDir, file.name) {
    result_.file = file.name;
    result_.model = model;
    result_.session = session == SessionKind::D3d11 ? "d3d11" : "xna";
}

ModelRun::~ModelRun() = default;

std::string ModelRun::where(int line) const { return file_.name + ".shader_test:" + std::to_string(line); }

void ModelRun::log(const std::string& text) {
    if (options_.verbose) *options_.verbose << "  sm" << shaderModelName(model_) << " " << text << "\n";
}

void ModelRun::mark(int line) const {
    if (options_.markerFd < 0) return;
    std::string text = "M\t" + std::to_string(line) + "\n";
    if (::write(options_.markerFd, text.data(), text.size()) < 0) return;
}

// Every section's compile check before the first [test] block makes a GL session: each compile
// runs in a forked worker (fxport's containment), and a fork of a process holding a GL context
// costs several times more (page tables, copy-on-write faults). Same order, same crash markers.
void ModelRun::compileSectionsAhead() {
    RequireDesc require = require_;
    bool inRange = inRange_;
    for (const Block& block : file_.blocks) {
        if (block.kind == BlockKind::Require) {
            require = parseRequire(block);
            inRange = model_ >= require.minModel && model_ <= require.maxModel;
        }
        if (!inRange || block.kind != BlockKind::Shader || block.hexBytecode || !stageRunsAt(block.stage, model_) ||
            crashedBefore(block.line))
            continue;
        mark(block.line);
        compiledAhead_[&block] = compiler_.compile(block, model_, require);
    }
}

ModelResult ModelRun::run() {
    compileSectionsAhead();
    for (const Block& block : file_.blocks) {
        if (block.kind == BlockKind::Require) { onRequire(block); continue; }
        if (!inRange_) continue;
        switch (block.kind) {
        case BlockKind::Shader: onShader(block); break;
        case BlockKind::Test: onTest(block); break;
        case BlockKind::Preproc: case BlockKind::PreprocFail: break;  // preprocessor-only checks: not sections
        default: onResource(block); break;
        }
    }
    SectionCounts t = result_.total();
    log("summary: compiled " + std::to_string(t.compiled) + "/" + std::to_string(t.shouldCompile) + ", rejected " +
        std::to_string(t.rejected) + "/" + std::to_string(t.shouldFail) + ", probes passed " +
        std::to_string(result_.probesPassed) + "/" + std::to_string(result_.probesRun) + ", skipped " +
        std::to_string(result_.probesSkipped));
    return result_;
}

void ModelRun::onRequire(const Block& block) {
    require_ = parseRequire(block);
    inRange_ = model_ >= require_.minModel && model_ <= require_.maxModel;
    missingCapability_.clear();
    for (const std::string& c : require_.capabilities)
        if (!capabilityHonoured(c, sessionKind_) && missingCapability_.empty()) missingCapability_ = c;
}

void ModelRun::onShader(const Block& block) {
    SectionKind kind = sectionKindOf(block.stage);
    SectionExpectation expect = sectionExpectation(block.qualifiers, model_);
    shaders_[block.stage] = ShaderSlot{&block, false, ""};
    testsRun_ = !expect.expectsReject();
    testsSkipReason_.clear();
    if (block.hexBytecode) { testsSkipReason_ = "precompiled bytecode section (no HLSL to compile)"; return; }
    if (!stageRunsAt(block.stage, model_)) return;  // vkd3d compiles these stages only from SM4 (hull/domain SM5)
    if (crashedBefore(block.line)) {
        // A crash is neither a compile nor a rejection (fxc answers with a diagnostic).
        ++result_.crashed;
        SectionCounts& c = result_.sections[std::size_t(kind)];
        ++(expect.expectsReject() ? c.shouldFail : c.shouldCompile);
        // The failure (with the signal) is recorded by file_pool.cpp, which saw the process die.
        log("L" + std::to_string(block.line) + " [" + block.header + "]: the compile CRASHED the process");
        shaders_[block.stage].diagnostic = "the compile crashed the process";
        return;
    }
    auto ahead = compiledAhead_.find(&block);
    if (ahead == compiledAhead_.end()) mark(block.line);
    CompileOutcome outcome = ahead != compiledAhead_.end() ? ahead->second : compiler_.compile(block, model_, require_);
    shaders_[block.stage].compiled = outcome.compiled;
    shaders_[block.stage].diagnostic = outcome.diagnostic;
    countCompile(block, kind, expect.expectsReject(), outcome);
}

void ModelRun::countCompile(const Block& block, SectionKind kind, bool expectReject, const CompileOutcome& outcome) {
    SectionCounts& c = result_.sections[std::size_t(kind)];
    std::string head = "L" + std::to_string(block.line) + " [" + block.header + "] ";
    if (expectReject) {
        ++c.shouldFail;
        if (!outcome.compiled) {
            ++c.rejected;
            log(head + "should be rejected: rejected (" + outcome.diagnostic + ")");
        } else {
            failures_.push_back({file_.name, model_, block.line, "accepted", "invalid HLSL accepted (fxc rejects it)"});
            log(head + "should be rejected: ACCEPTED");
        }
        return;
    }
    ++c.shouldCompile;
    if (outcome.compiled) {
        ++c.compiled;
        log(head + "should compile: compiled");
    } else {
        failures_.push_back({file_.name, model_, block.line, "refused", outcome.id + ": " + outcome.message});
        log(head + "should compile: REFUSED\n      " + outcome.diagnostic);
    }
}

GpuBackend& ModelRun::gpu() {
    if (!gpu_) gpu_ = makeBackend(sessionKind_, model_, compiler_, options_.cacheDir);
    return *gpu_;
}

void ModelRun::onResource(const Block& block) {
    try {
        if (block.kind == BlockKind::Sampler) { gpu().setSampler(parseSampler(block)); return; }
        if (block.kind == BlockKind::InputLayout) { gpu().setInputLayout(parseInputLayout(block)); return; }
        gpu().setResource(parseResource(block));
    } catch (const Unsupported&) {
        // Recorded by the session; a draw or probe that needs the resource reports it.
    } catch (const std::exception& e) {
        testsSkipReason_ = std::string("resource the runner cannot parse: ") + e.what();
    }
}

void ModelRun::onTest(const Block& block) {
    if (!testsRun_) return;  // vkd3d runs no test after a section that should fail here
    for (const Line& line : block.lines) {
        TestLinePrefix prefix = parseTestLinePrefix(line.text, model_);
        if (!prefix.runs) continue;
        std::string skip = !missingCapability_.empty() ? "requires '" + missingCapability_ + "'" : testsSkipReason_;
        if (!skip.empty()) {
            if (startsWith(prefix.rest, "probe")) skipProbe(skip);
            continue;
        }
        runTestLine(line, prefix.rest);
    }
}

void ModelRun::runTestLine(const Line& line, const std::string& d) {
    try {
        if (startsWith(d, "uniform")) doUniform(d.substr(7));
        else if (startsWith(d, "draw")) doDraw(d.substr(4), line.number);
        else if (startsWith(d, "probe")) doProbe(d.substr(5), line.number);
        else if (startsWith(d, "clear rtv")) doClear(d.substr(9));
        else if (startsWith(d, "dispatch")) doDispatch(d.substr(8), line.number);
        else if (parseFixedFunctionState(d, fixedFunction_)) return;
        else if (startsWith(d, "sample mask")) gpu().setSampleMask(unsigned(std::stoul(d.substr(11), nullptr, 0)));
        else if (startsWith(d, "copy ")) doCopy(d.substr(5));
        else if (d.find("disable") != std::string::npos || d.find(" off") != std::string::npos) {
            stickyStates_.erase(firstWords(d, 1));
        } else {
            stickyStates_[firstWords(d, 1)] = firstWords(d, 2);
        }
    } catch (const std::exception& e) {
        failures_.push_back({file_.name, model_, line.number, "runner", e.what()});
        log("L" + std::to_string(line.number) + " runner error: " + e.what());
    }
}

void ModelRun::doUniform(const std::string& args) {
    std::istringstream in(args);
    unsigned offset = 0;
    std::string type;
    in >> offset >> type;
    std::vector<std::uint32_t> words;
    if (type == "float4" || type == "float") {
        // strtof as vkd3d's sscanf("%f"): 1.0e39 is +inf, where `in >> f` fails and drops the rest.
        std::string t;
        while (in >> t) {
            float f = std::strtof(t.c_str(), nullptr);
            std::uint32_t w;
            std::memcpy(&w, &f, 4);
            words.push_back(w);
        }
    } else if (type == "int4" || type == "int" || type == "uint4" || type == "uint") {
        std::string t;
        while (in >> t) words.push_back(std::uint32_t(std::strtoll(t.c_str(), nullptr, 0)));
    } else if (type == "double2") {
        double d;
        while (in >> d) { std::uint32_t w[2]; std::memcpy(w, &d, 8); words.push_back(w[0]); words.push_back(w[1]); }
    } else {
        std::string t;
        while (in >> t) {
            std::uint64_t v = std::uint64_t(std::strtoull(t.c_str(), nullptr, 0));
            words.push_back(std::uint32_t(v));
            words.push_back(std::uint32_t(v >> 32));
        }
    }
    std::size_t size = std::max(uniforms_.size(), std::size_t(offset) + words.size());
    uniforms_.resize((size + 3) / 4 * 4, 0x7f7f7f7fu);  // vkd3d fills gaps with 0x7f bytes
    for (std::size_t k = 0; k < words.size(); ++k) uniforms_[offset + k] = words[k];
}

void ModelRun::skipProbe(const std::string& reason) {
    ++result_.probesSkipped;
    ++result_.skipReasons[reason];
}

void ModelRun::failProbe(int line, const std::string& detail) {
    ++result_.probesRun;
    failures_.push_back({file_.name, model_, line, "probe", detail});
    log("L" + std::to_string(line) + " probe FAILED: " + detail);
}

}  // namespace conformance
