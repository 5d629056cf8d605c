// Which session's run of one (file, shader model) counts. SM 2.0/3.0 run on the XNA session. SM
// 4.0/5.0 run on the D3D11 session; where that run failed a draw or probe, the file is run again
// on the XNA session and the XNA run counts only if it passed more probes ("xna-kept", listed in
// the summary): those are gaps of fxport's D3D11 front end that the XNA path's parameter-by-name
// uniforms do not hit (docs/conformance.md lists them), kept visible rather than lowering the
// ratchet. Both runs make the same compile checks, so only probe counts can differ.
#pragma once

#include <vector>

#include "model_run.h"

namespace conformance {

struct ModelOutcome {
    ModelResult result;
    std::vector<Failure> failures;
};

ModelOutcome runModel(const ShaderTestFile& file, int model, const RunOptions& options);

// Whether a D3D11 run failed a draw or probe (so an XNA run might pass more).
bool worthXnaRerun(const ModelOutcome& d3d11);
// The run that counts: the XNA one (marked "xna-kept") only when it passed more probes and made
// the same compile checks.
ModelOutcome chooseSession(ModelOutcome d3d11, ModelOutcome xna);

}  // namespace conformance
