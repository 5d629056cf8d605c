// Which session's run counts (see session_choice.h).
#include "session_choice.h"

#include "qualifiers.h"

namespace conformance {

namespace {

ModelOutcome runWith(const ShaderTestFile& file, int model, const RunOptions& options, SessionKind session) {
    ModelRun run(file, model, options, session);
    ModelOutcome out;
    out.result = run.run();
    out.failures = run.failures();
    return out;
}

bool sameCompileChecks(const ModelResult& a, const ModelResult& b) {
    const SectionCounts x = a.total(), y = b.total();
    return x.compiled == y.compiled && x.shouldCompile == y.shouldCompile && x.rejected == y.rejected && x.shouldFail == y.shouldFail;
}

}  // namespace

bool worthXnaRerun(const ModelOutcome& d3d11) {
    for (const Failure& f : d3d11.failures)
        if (f.category == "probe" || f.category == "draw") return true;
    // D3D9's fixed-function states exist only on the XNA session (fixed_function_states.h).
    for (const auto& [reason, count] : d3d11.result.skipReasons)
        if (reason.find("D3D9 fixed-function") != std::string::npos || reason == "requires 'fog'" ||
            reason == "requires 'point-size'" || reason == "requires 'clip-planes'")
            return true;
    return false;
}

ModelOutcome chooseSession(ModelOutcome d3d11, ModelOutcome xna) {
    if (xna.result.probesPassed <= d3d11.result.probesPassed || !sameCompileChecks(d3d11.result, xna.result)) return d3d11;
    xna.result.session = "xna-kept";
    return xna;
}

ModelOutcome runModel(const ShaderTestFile& file, int model, const RunOptions& options) {
    if (model < 40) return runWith(file, model, options, SessionKind::Xna);
    ModelOutcome d3d11 = runWith(file, model, options, SessionKind::D3d11);
    if (!worthXnaRerun(d3d11)) return d3d11;
    RunOptions quiet = options;  // the verbose log shows the D3D11 run; the choice is logged below
    quiet.verbose = nullptr;
    ModelOutcome chosen = chooseSession(d3d11, runWith(file, model, quiet, SessionKind::Xna));
    if (options.verbose && chosen.result.session == "xna-kept")
        *options.verbose << "  sm" << shaderModelName(model) << " XNA session kept: it passed " << chosen.result.probesPassed
                         << " probes, the D3D11 one above " << d3d11.result.probesPassed << "\n";
    return chosen;
}

}  // namespace conformance
