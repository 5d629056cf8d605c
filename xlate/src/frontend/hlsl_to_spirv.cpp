#include "frontend/hlsl_to_spirv.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <regex>

#include "frontend/glslang_process.h"
#include "spirv/byte_address_lengths.h"
#include "spirv/clip_distance_packing.h"
#include "spirv/constant_index_bounds.h"
#include "spirv/structured_buffer_layout.h"
#include "rewrite/keyword_identifiers.h"
#include "spirv/spirv_fixups.h"
#include "spirv/pixel_interlock.h"
#include "spirv/rounding.h"
#include "spirv/legacy_division.h"
#include "spirv/ps2_equality.h"
#include "spirv/static_zero_init.h"
#include "spirv/tessellation_clip_distances.h"
#include "spirv/unset_static_resources.h"
#include "rewrite/pow2_partitioning.h"
#include "spirv/spirv_integer_fixups.h"
#include "rewrite/tess_factor_intrinsics.h"

namespace fxport::xlate {

namespace {

EShLanguage languageOf(ShaderStage s) {
    switch (s) {
    case ShaderStage::Vertex: return EShLangVertex;
    case ShaderStage::Pixel: return EShLangFragment;
    case ShaderStage::Geometry: return EShLangGeometry;
    case ShaderStage::Hull: return EShLangTessControl;
    case ShaderStage::Domain: return EShLangTessEvaluation;
    case ShaderStage::Compute: return EShLangCompute;
    }
    return EShLangVertex;
}

// glslang logs "ERROR: <name>:<line>: '<token>' : <message>".
std::vector<HlslError> parseLog(const std::string& log) {
    std::vector<HlslError> errors;
    static const std::regex re(R"(ERROR: [^:]*:(\d+): '([^']*)' : (.*))");
    static const std::regex plain(R"(ERROR: (.*))");
    size_t pos = 0;
    while (pos < log.size()) {
        size_t end = log.find('\n', pos);
        if (end == std::string::npos) end = log.size();
        std::string line = log.substr(pos, end - pos);
        pos = end + 1;
        std::smatch m;
        if (std::regex_match(line, m, re)) {
            HlslError e;
            e.line = std::stoi(m[1].str());
            e.token = m[2].str();
            e.message = m[3].str();
            while (!e.message.empty() && (e.message.back() == ' ' || e.message.back() == '\r')) e.message.pop_back();
            if (!e.token.empty()) e.message = "'" + e.token + "' : " + e.message;
            errors.push_back(e);
        } else if (std::regex_match(line, m, plain)) {
            std::string msg = m[1].str();
            if (msg.find("compilation errors") != std::string::npos || msg.find("HLSL parsing failed") != std::string::npos) continue;
            errors.push_back({0, {}, msg});
        }
    }
    return errors;
}

}  // namespace

SpirvModule hlslToSpirv(const HlslToSpirvRequest& request) {
    ensureGlslangInitialized();
    SpirvModule out;
    EShLanguage lang = languageOf(request.stage);
    glslang::TShader shader(lang);
    const char* text = request.source->c_str();
    int length = static_cast<int>(request.source->size());
    const char* name = "effect";
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    // The partitioning the ProcessTessFactors helpers round for (tess_factor_intrinsics.h).
    const std::string preamble = "#define FXPORT_PARTITIONING " + std::to_string(partitioningCode(request.hullPartitioning)) + "\n";
    shader.setPreamble(preamble.c_str());
    shader.setEntryPoint(request.entryPoint.c_str());
    shader.setSourceEntryPoint(request.entryPoint.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    // Emits the HLSL semantic of every stage input/output (UserSemantic), which spirv_to_glsl uses
    // to give varyings their fixed locations.
    shader.setEnvTargetHlslFunctionality1();
    shader.setHlslIoMapping(true);
    // SV_Position.w in a pixel shader is the clip-space w on D3D; GL's gl_FragCoord.w is 1/w.
    // glslang inverts it on reading (a no-op for shaders that read only .xy).
    if (lang == EShLangFragment) shader.setDxPositionW(true);
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgSpvRules | EShMsgVulkanRules |
                                             (request.dx9Compatible ? int(EShMsgHlslDX9Compatible) : 0));
    if (!shader.parse(GetDefaultResources(), 100, false, messages)) {
        out.errors = parseLog(shader.getInfoLog());
        if (out.errors.empty()) out.errors.push_back({0, {}, shader.getInfoLog()});
        return out;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        out.errors = parseLog(program.getInfoLog());
        if (out.errors.empty()) out.errors.push_back({0, {}, program.getInfoLog()});
        return out;
    }
    glslang::SpvOptions options;
    // glslang's own spirv-opt run stays off: our fix-ups (spirv_fixups.h) must see the module before
    // folding bakes glslang's meaning of an operation into constants; legalizeSpirv then runs the
    // same passes. Legalisation is needed, not optional: it makes sampler function parameters valid.
    options.disableOptimizer = true;
    options.optimizeSize = false;
    options.validate = false;
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(lang), out.words, &logger, &options);
    std::string msgs = logger.getAllMessages();
    if (msgs.find("error") != std::string::npos) {
        out.errors.push_back({0, {}, msgs});
        return out;
    }
    out.warnings = msgs;
    // The SPIR-V passes (parsed_spirv.h), each a function over one parsed module; the spirv-opt
    // runs (the division check, legalisation) work on the words between them.
    const bool sm2or3 = request.shaderModel < 4;
    const bool ps2 = request.shaderModel == 2 && request.stage == ShaderStage::Pixel;
    runSpirvPasses(out.words, {restoreKeywordIdentifiers, staticVariablesStartAtZero, tessellationClipDistances});  // `precise` as a name (keyword_identifiers.h); statics start at zero before the division check (static_zero_init.h); hull/domain clip distances as built-ins (tessellation_clip_distances.h)
    if (dividesByConstantZero(out.words, sm2or3)) {
        out.errors.push_back({0, {}, "division by zero: a divisor of this shader folds to the constant 0, which fxc refuses", true});
        return out;
    }
    runSpirvPasses(out.words, {applySpirvFixups, structuredBufferStridesAsD3D,
                               sm2or3 ? SpirvPass(integerNegationInFloats) : nullptr,  // SM2-3 integers are floats
                               ps2 ? SpirvPass(equalityBySquaredDifference) : nullptr,  // a == b as (a - b)² == 0 (ps2_equality.h)
                               sm2or3 ? SpirvPass(divisionAsRcpTimes) : nullptr,       // 0 / 0 is 0 (legacy_division.h)
                               sm2or3 ? nullptr : SpirvPass(roundHalvesToEven)});     // round_ne (rounding.h)
    std::string legalizeError;
    if (!legalizeSpirv(out.words, &legalizeError, sm2or3)) {
        out.errors.push_back({0, {}, legalizeError});
        return out;
    }
    if (auto past = constantIndexPastArrayEnd(out.words)) {  // after dead code is gone, as fxc judges it
        out.errors.push_back({deferredIndexLine(*request.source, past->index), {},
                              "array index " + std::to_string(past->index) + " is out of range (an array of " + std::to_string(past->length) +
                                  " elements; fxc refuses a constant index out of range where the code runs)"});
        return out;
    }
    if (std::string unset = staticResourceReadWithoutValue(out.words); !unset.empty()) {  // after dead code is gone
        out.errors.push_back({staticDeclarationLine(*request.source, unset), unset,
                              "static resource '" + unset + "' is read but never given a value: fxc binds only a resource it can trace to a register"});
        return out;
    }
    if (!localResourceVariableLeft(out.words).empty() && !forwardResourceCopies(out.words, &legalizeError)) {
        out.errors.push_back({0, {}, legalizeError});
        return out;
    }
    if (std::string local = localResourceVariableLeft(out.words); !local.empty()) {
        out.errors.push_back({resourceDeclarationLine(*request.source, local), local,
                              (local == "(unnamed)" ? std::string("a local resource variable") : "local resource variable '" + local + "'") +
                                  " does not hold one known resource where it is used (fxc traces such copies, fxport does not yet; GLSL has no "
                                  "resource variables): use the global resource directly"});
        return out;
    }
    runSpirvPasses(out.words, {sm2or3 ? SpirvPass(integerDivisionInFloats) : nullptr,  // after folding: fxc folds constants exactly
                               packClipCullDistances, packStructuredBuffersTightly,
                               [&](ParsedSpirv& m) { return byteAddressLengthsInBytes(m, byteAddressBufferNames(*request.source)); },
                               request.hullPartitioning == "pow2" ? SpirvPass(roundTessFactorsToPowersOfTwo) : nullptr,
                               [&](ParsedSpirv& m) { return pixelInterlockForOrderedViews(m, request.rasterizerOrderedViews); }});
    return out;
}

}  // namespace fxport::xlate
