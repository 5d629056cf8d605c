// D3DCompile and friends over xlate's loose-shader compiler: one entry point and profile in, a blob
// holding the compiled shader (xlate's compiled-effect text: GLSL, reflection and D3D's registers
// as declared) out, or an error blob of fxc-style "file(line,col): error ..." lines. Compiles are
// cached by content like every fxport compile ($FXPORT_CACHE_DIR).
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <mutex>
#include <string_view>

#include "fxport/platform/utf8.h"
#include "d3d11_impl.h"
#include "include_handler.h"
#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fxport::d3d11 {

namespace {

constexpr const char* kShaderHeader = "fxport shader\n";
constexpr const char* kEffectHeader = "fxport effect\n";

class Blob final : public ID3DBlob {
public:
    explicit Blob(std::string bytes) : bytes_(std::move(bytes)) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    void* GetBufferPointer() override { return bytes_.data(); }
    SIZE_T GetBufferSize() override { return bytes_.size(); }

private:
    std::string bytes_;
    std::atomic<ULONG> references_{1};
};

}  // namespace

std::string narrowPath(const wchar_t* w) {
    std::string out;
    for (; w && *w; ++w) platform::appendUtf8(out, char32_t(*w));
    return out;
}

namespace {

std::optional<std::string> readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Compiles one entry point from a file (`source` null) or from text; fills the blobs.
HRESULT compile(const char* call, const std::string& path, const std::string* source, const D3D_SHADER_MACRO* defines,
                ID3DInclude* include, LPCSTR entry, LPCSTR target, UINT flags, ID3DBlob** code, ID3DBlob** errors) {
    if (code) *code = nullptr;
    if (errors) *errors = nullptr;
    auto error = [&](HRESULT hr, const std::string& message) {
        if (errors) *errors = new Blob(message + "\n");
        return fail(hr, std::string(call) + ": " + message);
    };
    if (!target) return error(E_INVALIDARG, "pTarget is required");
    // fx_4_0 / fx_5_0: the whole effect (techniques, passes, every shader they name).
    const bool effect = std::string(target).rfind("fx_", 0) == 0;
    if (!effect && !entry) return error(E_INVALIDARG, "pEntrypoint is required for a shader target");
    const UINT packing = flags & (D3DCOMPILE_PACK_MATRIX_ROW_MAJOR | D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR);
    if (packing == (D3DCOMPILE_PACK_MATRIX_ROW_MAJOR | D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR))
        return error(E_INVALIDARG, "Flags1 = " + std::to_string(flags) + ": D3DCOMPILE_PACK_MATRIX_ROW_MAJOR and D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR exclude each other");
    xlate::CompileOptions options;
    if (effect) options.effectProfile = target;  // fxc's /T: fx_4_0 and fx_5_0 rules (an effect may have no technique)
    if (packing) options.defaultMatrixMajority = packing == D3DCOMPILE_PACK_MATRIX_ROW_MAJOR ? "row_major" : "column_major";
    for (const D3D_SHADER_MACRO* d = defines; d && d->Name; ++d) options.defines.emplace_back(d->Name, d->Definition ? d->Definition : "1");
    const std::vector<xlate::ShaderEntry> entries = {{path, entry ? entry : "", target}};
    std::optional<IncludeRecorder> recorder;  // closes what the handler opened when the compile is done
    try {
        if (include && include != D3D_COMPILE_STANDARD_FILE_INCLUDE) {
            // The handler sees each #include as the preprocessor reaches it, in this process; the
            // compile proper gets the same texts (and is not cached: the handler's files are unknown).
            recorder.emplace(include, path);
            options.readInclude = [&](const std::string& header, bool system, const std::string& includer) {
                return recorder->open(header, system, includer);
            };
            if (const std::optional<std::string> text = source ? *source : readTextFile(path)) xlate::preprocessSource(*text, path, options);
            options.readInclude = recorder->replay();
            options.useCache = false;
        }
        xlate::CompiledEffect compiled =
            effect ? (source ? xlate::compileEffectSource(*source, path, options) : xlate::compileEffectFile(path, options))
                   : (source ? xlate::compileShaderSource(*source, path, entries, options) : xlate::compileShaderFiles(entries, options));
        std::string text = std::string(effect ? kEffectHeader : kShaderHeader) + xlate::serializeEffect(compiled, /*compact=*/true);
        // Warnings go to the error blob, as fxc's do.
        std::string warnings;
        for (const auto& d : compiled.diagnostics) warnings += d.format() + "\n";
        if (errors && !warnings.empty()) *errors = new Blob(warnings);
        if (code) *code = new Blob(std::move(text));
        return succeed();
    } catch (const xlate::CompileError& e) {
        std::string text;
        for (const auto& d : e.diagnostics()) text += d.format() + "\n";
        if (!text.empty()) text.pop_back();
        return error(E_FAIL, text);
    } catch (const std::exception& e) {
        return error(E_FAIL, e.what());
    }
}

}  // namespace

HRESULT D3DCompile(LPCVOID pSrcData, SIZE_T SrcDataSize, LPCSTR pSourceName, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude,
                   LPCSTR pEntrypoint, LPCSTR pTarget, UINT Flags1, UINT, ID3DBlob** ppCode, ID3DBlob** ppErrorMsgs) {
    if (!pSrcData || SrcDataSize == 0) return fail(E_INVALIDARG, "D3DCompile: pSrcData is null or empty");
    const std::string source(static_cast<const char*>(pSrcData), SrcDataSize);
    const std::string name = pSourceName && *pSourceName ? pSourceName : "memory.hlsl";
    return compile("D3DCompile", name, &source, pDefines, pInclude, pEntrypoint, pTarget, Flags1, ppCode, ppErrorMsgs);
}

HRESULT D3DCompileFromFile(LPCSTR pFileName, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude, LPCSTR pEntrypoint,
                           LPCSTR pTarget, UINT Flags1, UINT, ID3DBlob** ppCode, ID3DBlob** ppErrorMsgs) {
    if (!pFileName) return fail(E_INVALIDARG, "D3DCompileFromFile: pFileName is null");
    return compile("D3DCompileFromFile", pFileName, nullptr, pDefines, pInclude, pEntrypoint, pTarget, Flags1, ppCode, ppErrorMsgs);
}

HRESULT D3DCompileFromFile(const wchar_t* pFileName, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude, LPCSTR pEntrypoint,
                           LPCSTR pTarget, UINT Flags1, UINT Flags2, ID3DBlob** ppCode, ID3DBlob** ppErrorMsgs) {
    if (!pFileName) return fail(E_INVALIDARG, "D3DCompileFromFile: pFileName is null");
    return D3DCompileFromFile(narrowPath(pFileName).c_str(), pDefines, pInclude, pEntrypoint, pTarget, Flags1, Flags2, ppCode, ppErrorMsgs);
}

HRESULT D3DX11CompileFromFile(LPCSTR pSrcFile, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude, LPCSTR pFunctionName,
                              LPCSTR pProfile, UINT Flags1, UINT Flags2, void* pPump, ID3DBlob** ppShader, ID3DBlob** ppErrorMsgs,
                              HRESULT* pHResult) {
    HRESULT hr = pPump ? fail(E_NOTIMPL, "D3DX11CompileFromFile: thread pumps are not supported (pPump must be null)")
                       : D3DCompileFromFile(pSrcFile, pDefines, pInclude, pFunctionName, pProfile, Flags1, Flags2, ppShader, ppErrorMsgs);
    if (pHResult) *pHResult = hr;
    return hr;
}

HRESULT D3DCreateBlob(SIZE_T Size, ID3DBlob** ppBlob) {
    if (!ppBlob) return fail(E_INVALIDARG, "D3DCreateBlob: ppBlob is null");
    *ppBlob = new Blob(std::string(Size, '\0'));
    return succeed();
}

std::string shaderBlob(const xlate::CompiledEffect& shader) { return kShaderHeader + xlate::serializeEffect(shader, /*compact=*/true); }

std::shared_ptr<const xlate::CompiledEffect> effectFromBytecode(const void* bytecode, SIZE_T length, std::string& error, BlobKind* kind) {
    if (!bytecode || length == 0) {
        error = "the shader bytecode is null or empty";
        return nullptr;
    }
    std::string_view all(static_cast<const char*>(bytecode), length);
    const bool shader = all.substr(0, std::strlen(kShaderHeader)) == kShaderHeader;
    const bool wholeEffect = all.substr(0, std::strlen(kEffectHeader)) == kEffectHeader;
    if (!shader && !wholeEffect) {
        error = "not a shader D3DCompile made with fxport; fxport cannot run DXBC bytecode";
        return nullptr;
    }
    if (kind) *kind = shader ? BlobKind::Shader : BlobKind::Effect;
    bytecode = all.data() + std::strlen(shader ? kShaderHeader : kEffectHeader);
    length = all.size() - std::strlen(shader ? kShaderHeader : kEffectHeader);
    // The same blob is often given to CreateVertexShader and CreateInputLayout: parse it once.
    static std::mutex mutex;
    static std::string lastText;
    static std::shared_ptr<const xlate::CompiledEffect> lastEffect;
    const std::string_view text(static_cast<const char*>(bytecode), length);
    std::lock_guard<std::mutex> lock(mutex);
    if (lastEffect && text == lastText) return lastEffect;
    try {
        auto effect = std::make_shared<const xlate::CompiledEffect>(xlate::deserializeEffect(text, "shader bytecode"));
        lastText = std::string(text);
        lastEffect = effect;
        return effect;
    } catch (const std::exception& e) {
        error = std::string("not a shader D3DCompile made with fxport (") + e.what() + "); fxport cannot run DXBC bytecode";
        return nullptr;
    }
}

}  // namespace fxport::d3d11
