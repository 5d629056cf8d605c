// Loose shader files compiled by entry point and profile, merged into one effect of one pass (see
// loose_shaders.h and compileShaderFiles in effect_compiler.h).
#include "effect/loose_shaders.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "fx/input_limits.h"
#include "fx/shader_profile.h"
#include "glsl/spirv_to_glsl.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

constexpr const char* kTechnique = kLooseTechnique;

[[noreturn]] void fail(const char* id, const std::string& file, const std::string& message) {
    Diagnostic d;
    d.id = id;
    d.message = message;
    d.location = {file, 0, 0};  // an option's value, not a place in the file
    throw CompileError({d});
}

}  // namespace

bool isLooseShaderCompile(const CompileOptions& options) { return options.techniques.size() == 1 && options.techniques[0] == kTechnique; }

namespace {

// One file with the technique that names its entry points appended (after its last line, so its
// own lines keep their numbers).
// Thrown by compileOneFile when only the cache was to be asked and it had no entry.
struct NotCached {};

// `given`: the file's text when held in memory (D3DCompile), else empty and the file is read.
CompiledEffect compileOneFile(const std::string& path, const std::vector<const ShaderEntry*>& entries, CompileOptions options,
                              VaryingLocations* shared, bool cacheOnly, const std::string& given) {
    std::error_code ec;
    const std::uintmax_t size = given.empty() ? std::filesystem::file_size(path, ec) : given.size();
    if (!ec && size > limits::kMaxFileBytes)
        fail(diag::kInputTooLarge, path, "the file has " + std::to_string(size) + " bytes; fxport compiles source files of at most " +
                                             std::to_string(limits::kMaxFileBytes >> 20) + " MiB");
    auto raw = given.empty() ? readFile(path) : std::optional<std::string>(given);
    if (!raw) fail(diag::kFileUnreadable, path, "cannot open '" + path + "'");
    std::string pass;
    for (const ShaderEntry* e : entries) {
        auto profile = parseShaderProfile(e->profile);
        if (!profile)
            fail(diag::kBadProfile, path, "profile '" + e->profile + "' (--profile, fxc /T) is not a shader profile fxport knows (vs_1_1..vs_5_0, ps_2_0..ps_5_0, gs_4_0..gs_5_0, cs_4_0..cs_5_0, hs_5_0, ds_5_0)");
        static const char* const kStates[] = {"VertexShader", "PixelShader", "GeometryShader", "HullShader", "DomainShader", "ComputeShader"};
        const char* state = kStates[static_cast<int>(profile->stage)];
        pass += std::string(" ") + state + " = compile " + e->profile + " " + e->entryPoint + "();";
    }
    // Raw bytes first (a BOM or UTF-16 stays what the compiler decodes); the technique is ASCII,
    // appended in the file's own encoding.
    std::string technique = std::string("\ntechnique ") + kTechnique + " { pass P0 {" + pass + " } }\n";
    std::string source = *raw;
    if (source.size() >= 2 && (source.compare(0, 2, "\xFF\xFE") == 0 || source.compare(0, 2, "\xFE\xFF") == 0)) {
        bool little = source[0] == '\xFF';
        for (char c : technique) {
            source += little ? c : '\0';
            source += little ? '\0' : c;
        }
    } else {
        source += technique;
    }
    options.techniques = {kTechnique};
    if (cacheOnly) {
        if (auto cached = cachedEffectText(source, path, path, options)) return std::move(*cached);
        throw NotCached{};
    }
    try {
        return compileEffectText(source, path, path, options, shared);
    } catch (const CompileError& error) {
        // The appended technique is ours: an entry point it names that is missing is the option's fault.
        std::vector<Diagnostic> out = error.diagnostics();
        for (auto& d : out)
            if (d.id == diag::kMissingEntry || (d.sourceLine.find(kTechnique) != std::string::npos)) {
                d.location = {path, 0, 0};
                d.sourceLine.clear();
                if (d.id == diag::kMissingEntry) d.message = d.message.substr(0, d.message.find(" is not")) + " (--entry, fxc /E) is not a function of '" + path + "'";
            }
        throw CompileError(std::move(out));
    }
}

bool sameShape(const Parameter& a, const Parameter& b) {
    return a.parameterClass == b.parameterClass && a.type == b.type && a.rows == b.rows && a.columns == b.columns && a.elements == b.elements;
}

// Adds `part` (one file's effect) to `merged`; returns the merged indices of part's shaders.
std::vector<int> mergeInto(CompiledEffect& merged, const CompiledEffect& part, const std::string& path) {
    // Blocks: one that both files declare alike (a shared header's cbuffer: name, binding, size and
    // member places equal) is one block; any other is its own (each stage binds its blocks apart).
    std::vector<int> blockMap(part.uniformBlocks.size(), -1);
    for (size_t b = 0; b < part.uniformBlocks.size(); ++b) {
        const UniformBlock& pb = part.uniformBlocks[b];
        for (size_t m = 0; m < merged.uniformBlocks.size() && blockMap[b] < 0; ++m) {
            const UniformBlock& mb = merged.uniformBlocks[m];
            if (mb.name != pb.name || mb.binding != pb.binding || (mb.size && pb.size && mb.size != pb.size)) continue;
            bool alike = true;
            for (const auto& p : part.parameters) {
                if (p.block != int(b) || p.offset < 0 || p.parameterClass == ParameterClass::Object) continue;
                const Parameter* q = merged.findParameter(p.name);
                bool placed = q && q->block == int(m) && q->offset >= 0;
                if (placed && (q->offset != p.offset || !sameShape(*q, p))) alike = false;
            }
            if (alike) {
                blockMap[b] = int(m);
                merged.uniformBlocks[m].size = std::max(mb.size, pb.size);
            }
        }
        if (blockMap[b] < 0) {
            blockMap[b] = int(merged.uniformBlocks.size());
            merged.uniformBlocks.push_back(pb);
        }
    }
    std::vector<int> paramMap(part.parameters.size(), -1);
    for (size_t i = 0; i < part.parameters.size(); ++i) {
        Parameter p = part.parameters[i];
        if (p.block >= 0 && size_t(p.block) < blockMap.size()) p.block = blockMap[size_t(p.block)];
        int existing = -1;
        for (size_t k = 0; k < merged.parameters.size(); ++k)
            if (merged.parameters[k].name == p.name) existing = int(k);
        if (existing < 0) {
            paramMap[i] = int(merged.parameters.size());
            merged.parameters.push_back(std::move(p));
            continue;
        }
        Parameter& q = merged.parameters[size_t(existing)];
        paramMap[i] = existing;
        if (!sameShape(q, p))
            fail(diag::kSyntax, path, "parameter '" + p.name + "' is declared in '" + merged.sourcePath + "' and in '" + path +
                                          "' with different types; one effect has one parameter of a name");
        if (p.offset < 0) continue;  // not in a block any shader of this file reads
        if (q.offset < 0) {
            q = std::move(p);
        } else if (q.block != p.block || q.offset != p.offset) {
            fail(diag::kSyntax, path, "parameter '" + p.name + "' is a global of both '" + merged.sourcePath + "' and '" + path +
                                          "' at different places; declare it once, in a cbuffer both files include, so one SetValue reaches both");
        }
    }
    std::vector<int> shaderMap;
    for (const auto& s : part.shaders) {
        CompiledShader shader = s;
        for (int& p : shader.parametersRead) p = paramMap[size_t(p)];
        std::sort(shader.parametersRead.begin(), shader.parametersRead.end());
        for (auto& r : shader.uniformRangesRead)
            if (r.block >= 0 && size_t(r.block) < blockMap.size()) r.block = blockMap[size_t(r.block)];
        shaderMap.push_back(int(merged.shaders.size()));
        merged.shaders.push_back(std::move(shader));
    }
    merged.diagnostics.insert(merged.diagnostics.end(), part.diagnostics.begin(), part.diagnostics.end());
    return shaderMap;
}

// The files compiled one by one and merged; with `cacheOnly`, from the cache alone (NotCached
// when an entry is missing).
CompiledEffect compileAndMerge(const std::vector<ShaderEntry>& entries, const CompileOptions& optionsIn, bool cacheOnly,
                               const std::string& source = {}) {
    if (entries.empty()) fail(diag::kMissingEntry, "", "no entry point given (--entry NAME --profile vs_5_0, fxc /E /T)");
    std::vector<std::string> files;  // in the order first named
    std::map<std::string, std::vector<const ShaderEntry*>> byFile;
    for (const auto& e : entries) {
        if (e.entryPoint.empty()) fail(diag::kMissingEntry, e.path, "no entry point given for '" + e.path + "' (--entry NAME, fxc /E)");
        if (!byFile.count(e.path)) files.push_back(e.path);
        byFile[e.path].push_back(&e);
    }
    CompileOptions options = optionsIn;
    // Apart, files must agree on custom varying locations: they share them, which the cache (keyed
    // by one file) cannot know.
    if (files.size() > 1) options.useCache = false;
    std::set<std::string> hullFiles;
    for (const auto& e : entries) {
        auto profile = parseShaderProfile(e.profile);
        if (profile && (profile->stage == ShaderStage::Geometry || profile->stage == ShaderStage::Domain))
            options.besideGeometryOrDomainShader = true;
        if (profile && profile->stage == ShaderStage::Hull) hullFiles.insert(e.path);
    }
    // The hull shader's file first: its attributes go into the domain shader's GLSL (GL declares
    // partitioning and topology there), which a later file then compiles with.
    std::stable_partition(files.begin(), files.end(), [&](const std::string& f) { return hullFiles.count(f) > 0; });
    VaryingLocations varyings;

    CompiledEffect merged;
    merged.sourcePath = files.front();
    Technique technique;
    for (const auto& e : entries) technique.name += (technique.name.empty() ? "" : "+") + e.entryPoint;
    Pass pass;
    pass.name = "P0";
    for (const auto& file : files) {
        CompiledEffect part = compileOneFile(file, byFile[file], options, &varyings, cacheOnly, source);
        const Pass& partPass = part.techniques.at(0).passes.at(0);
        for (int s : partPass.hullShader.shaders)
            if (s >= 0) options.hullOfDomainShader = part.shaders[size_t(s)].tessellation;
        pass.valid = pass.valid && partPass.valid;
        if (&file == &files.front()) {
            merged = part;
            merged.techniques.clear();
            pass = partPass;
            pass.name = "P0";
            continue;
        }
        std::vector<int> shaderMap = mergeInto(merged, part, file);
        auto take = [&](const ShaderChoice& from, ShaderChoice& to) {
            if (from.shaders.empty()) return;
            to = from;
            for (int& s : to.shaders) s = s < 0 ? s : shaderMap[size_t(s)];
        };
        take(partPass.vertexShader, pass.vertexShader);
        take(partPass.pixelShader, pass.pixelShader);
        take(partPass.geometryShader, pass.geometryShader);
        take(partPass.hullShader, pass.hullShader);
        take(partPass.domainShader, pass.domainShader);
        take(partPass.computeShader, pass.computeShader);
    }
    // D3D10/11 give each stage its own texture slots; fxport's units are shared. Two stages that
    // sample different textures on one unit would see one of them: say so instead.
    std::map<int, std::string> unitTexture;
    for (const auto* choice : {&pass.vertexShader, &pass.geometryShader, &pass.pixelShader, &pass.hullShader, &pass.domainShader, &pass.computeShader})
        for (int s : choice->shaders) {
            if (s < 0) continue;
            for (const auto& b : merged.shaders[size_t(s)].samplers) {
                if (b.textureParameter.empty()) continue;
                auto [it, fresh] = unitTexture.emplace(b.unit, b.textureParameter);
                if (!fresh && it->second != b.textureParameter)
                    fail(diag::kUnsupported, merged.sourcePath, "textures '" + it->second + "' and '" + b.textureParameter +
                                                                    "' of different shader files both use texture unit " + std::to_string(b.unit) +
                                                                    "; give one of them another register(tN)");
            }
        }
    technique.passes.push_back(std::move(pass));
    merged.techniques = {std::move(technique)};
    merged.uniformBufferSize = merged.uniformBlocks.empty() ? 0 : merged.uniformBlocks[0].size;
    return merged;
}

}  // namespace

// All files and the merge in one front-end worker, as an effect file compiles: glslang, SPIRV-Tools
// and SPIRV-Cross crash on some shaders and have no bound on some work, and the files share
// custom varying locations, which must live in the process that compiles them all. A cache hit
// (one file; several are never cached) starts no worker.
CompiledEffect compileShaderFiles(const std::vector<ShaderEntry>& entries, const CompileOptions& options) {
    if (compilesInThisProcess(options)) return compileAndMerge(entries, options, false);
    if (options.useCache) {
        try {
            return compileAndMerge(entries, options, true);
        } catch (const NotCached&) {
        }
    }
    const std::string displayPath = entries.empty() ? std::string() : entries.front().path;
    return compileContained([&] { return compileAndMerge(entries, options, false); }, displayPath);
}

CompiledEffect compileShaderSource(const std::string& source, const std::string& virtualPath,
                                   const std::vector<ShaderEntry>& entriesIn, const CompileOptions& options) {
    std::vector<ShaderEntry> entries = entriesIn;
    for (auto& e : entries) e.path = virtualPath;  // one text: every entry is in it
    if (source.empty()) fail(diag::kFileUnreadable, virtualPath, "the source text is empty");
    if (compilesInThisProcess(options)) return compileAndMerge(entries, options, false, source);
    if (options.useCache) {
        try {
            return compileAndMerge(entries, options, true, source);
        } catch (const NotCached&) {
        }
    }
    return compileContained([&] { return compileAndMerge(entries, options, false, source); }, virtualPath);
}

}  // namespace fxport::xlate
