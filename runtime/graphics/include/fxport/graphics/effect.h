// Effect: a .fx file run the way the XNA 4 / D3D effect framework runs it.
//
//   Effect gbuffer(device, "hlsl/xna-deferred/GBuffer.fx");   // compiled by xlate, cached
//   gbuffer.Parameters["World"].SetValue(world);
//   gbuffer.CurrentTechnique = gbuffer.Techniques["Technique1"];
//   gbuffer.CurrentTechnique->Passes[0].Apply();               // program, constants, textures, states
//   device.DrawIndexedPrimitives(...);
//
// Loading an effect parses it (techniques, passes, parameters: all usable at once); a technique's
// shaders are cross-compiled and linked the first time one of its passes is applied, or all at once
// by Precompile() / EffectOptions::precompile for hosts that want no compile during a frame.
//
// Apply() binds the pass's shaders (a stage the pass does not assign keeps what was bound, as on
// D3D9: a pixel-shader-only pass runs with SpriteBatch's vertex shader), uploads the constants that
// changed since the last Apply and that the pass's shaders read (the others stay pending), sets
// Textures[unit] from texture parameters and merges the effect's sampler_state over
// SamplerStates[unit], and applies the pass's render states to the device's
// BlendState/DepthStencilState/RasterizerState. Device states set after Apply() win, as in XNA.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fxport/graphics/graphics_resource.h"
#include "fxport/math.h"

namespace fxport::xlate {
struct CompiledEffect;
struct Parameter;
}

namespace fxport {

class Effect;
class Texture;
class Texture2D;
class TextureCube;

enum class EffectParameterClass : std::uint8_t { Scalar, Vector, Matrix, Object, Struct };
enum class EffectParameterType : std::uint8_t {
    Void, Bool, Int32, Single, String, Texture, Texture1D, Texture2D, Texture3D, TextureCube, Sampler,
};

struct EffectAnnotation {
    std::string Name;
    std::string ParameterType;  // "string", "float", ...
    std::string Value;          // as written in the source
};

class EffectParameter {
public:
    const std::string& Name() const;
    const std::string& Semantic() const;
    EffectParameterClass ParameterClass() const;
    EffectParameterType ParameterType() const;
    int RowCount() const;
    int ColumnCount() const;
    int ElementCount() const;  // 0 when not an array
    const std::vector<EffectAnnotation>& Annotations() const;

    // Each setter checks the parameter's class, type and size and throws ArgumentError naming the
    // effect, the parameter, its HLSL type and what was passed. Values are written to the effect's
    // constant buffer shadow; the next Apply() whose shaders read them uploads what changed.
    void SetValue(bool value);
    void SetValue(int value);
    void SetValue(float value);
    void SetValue(const Vector2& value);
    void SetValue(const Vector3& value);
    void SetValue(const Vector4& value);
    void SetValue(const Quaternion& value);
    // XNA matrices: HLSL sees M[r][c] = XNA M(r+1)(c+1), for column_major and row_major alike. A
    // float3x3 / float4x3 parameter takes the top-left part.
    void SetValue(const Matrix& value);
    void SetValueTranspose(const Matrix& value);
    // Arrays: the values given are written from element 0; a shorter array than the parameter
    // leaves the elements after it as they were (XNA does the same), a longer one throws.
    void SetValue(std::span<const float> values);
    void SetValue(std::span<const int> values);
    void SetValue(std::span<const Vector2> values);
    void SetValue(std::span<const Vector3> values);
    void SetValue(std::span<const Vector4> values);
    void SetValue(std::span<const Matrix> values);
    void SetValue(const std::vector<float>& values) { SetValue(std::span<const float>(values)); }
    void SetValue(const std::vector<Vector2>& values) { SetValue(std::span<const Vector2>(values)); }
    void SetValue(const std::vector<Vector3>& values) { SetValue(std::span<const Vector3>(values)); }
    void SetValue(const std::vector<Vector4>& values) { SetValue(std::span<const Vector4>(values)); }
    void SetValue(const std::vector<Matrix>& values) { SetValue(std::span<const Matrix>(values)); }
    // Textures (nullptr unbinds). The texture must outlive its use or be disposed (which clears it).
    void SetValue(Texture* texture);
    void SetValue(Texture& texture) { SetValue(&texture); }
    template <class T> void SetValue(const std::unique_ptr<T>& texture) { SetValue(static_cast<Texture*>(texture.get())); }
    template <class T> void SetValue(const std::shared_ptr<T>& texture) { SetValue(static_cast<Texture*>(texture.get())); }

    bool GetValueBoolean() const;
    int GetValueInt32() const;
    float GetValueSingle() const;
    Vector2 GetValueVector2() const;
    Vector3 GetValueVector3() const;
    Vector4 GetValueVector4() const;
    Matrix GetValueMatrix() const;
    std::vector<float> GetValueSingleArray() const;   // every float of the parameter, row by row
    std::vector<Matrix> GetValueMatrixArray(int count) const;
    std::string GetValueString() const;
    Texture* GetValueTexture() const;
    Texture2D* GetValueTexture2D() const;
    TextureCube* GetValueTextureCube() const;

    // XNA's StructureMembers (a struct's members; of an array of structs, take Elements[i] first)
    // and Elements (an array's elements, empty when not an array): parameters of their own, at the
    // place of that member or element in the constant buffer, set and read like any other. Built on
    // first use; valid as long as the effect.
    class EffectParameterCollection& StructureMembers();
    class EffectParameterCollection& Elements();

    int index() const { return index_; }  // of the effect's parameter this one is, or is inside

private:
    friend class Effect;
    friend struct ParameterAccess;  // effect_parameter.cpp
    struct View;  // the path from the effect's parameter to a member or element (effect_parameter_views.cpp)
    EffectParameter(Effect* effect, int index) : effect_(effect), index_(index) {}
    EffectParameter(Effect* effect, int index, std::shared_ptr<View> view);
    const xlate::Parameter& desc() const;  // the reflection of this parameter (of a member or element: computed)
    Effect* effect_;
    int index_;
    std::shared_ptr<View> view_;  // null: one of the effect's parameters
    std::shared_ptr<class EffectParameterCollection> members_, elements_;
};

class EffectParameterCollection {
public:
    // Throws ArgumentError naming the effect and listing its parameters when `name` is unknown.
    EffectParameter& operator[](const std::string& name);
    EffectParameter& operator[](int index);
    // nullptr when absent (XNA's Parameters["x"] == null check).
    EffectParameter* find(const std::string& name);
    int Count() const { return int(items_.size()); }
    auto begin() { return items_.begin(); }
    auto end() { return items_.end(); }

private:
    friend class Effect;
    friend class EffectParameter;
    Effect* effect_ = nullptr;
    bool nested_ = false;  // StructureMembers or Elements: found by name among items_
    std::vector<EffectParameter> items_;
};

class EffectPass {
public:
    const std::string& Name() const { return name_; }
    const std::vector<EffectAnnotation>& Annotations() const { return annotations_; }
    void Apply();

private:
    friend class Effect;
    void applyThis();
    EffectPass(Effect* effect, int technique, int pass, std::string name, std::vector<EffectAnnotation> annotations)
        : effect_(effect), technique_(technique), pass_(pass), name_(std::move(name)), annotations_(std::move(annotations)) {}
    Effect* effect_;
    int technique_;
    int pass_;
    std::string name_;
    std::vector<EffectAnnotation> annotations_;
};

class EffectPassCollection {
public:
    EffectPass& operator[](int index);
    EffectPass& operator[](const std::string& name);
    // nullptr when absent (XNA's Passes["x"] == null check; docs/API.md rule 2).
    EffectPass* find(const std::string& name);
    int Count() const { return int(items_.size()); }
    auto begin() { return items_.begin(); }
    auto end() { return items_.end(); }

private:
    friend class Effect;
    std::string owner_;
    std::vector<EffectPass> items_;
};

class EffectTechnique {
public:
    const std::string& Name() const { return name_; }
    const std::vector<EffectAnnotation>& Annotations() const { return annotations_; }
    EffectPassCollection Passes;
    // Whether this technique's shaders have been compiled (by an Apply of one of its passes, or by
    // Precompile). fxport addition.
    bool IsCompiled() const;

private:
    friend class Effect;
    Effect* effect_ = nullptr;
    int index_ = 0;
    std::string name_;
    std::vector<EffectAnnotation> annotations_;
};

class EffectTechniqueCollection {
public:
    // Pointers, as C# references: effect.CurrentTechnique = effect.Techniques["Shadow"];
    EffectTechnique* operator[](int index);
    EffectTechnique* operator[](const std::string& name);
    // nullptr when absent (XNA's Techniques["x"] == null check; docs/API.md rule 2).
    EffectTechnique* find(const std::string& name);
    int Count() const { return int(items_.size()); }

private:
    friend class Effect;
    std::string owner_;
    std::vector<std::unique_ptr<EffectTechnique>> items_;
};

struct EffectOptions {
    std::vector<std::string> includeDirs;                        // extra #include folders
    std::string includeRoot;  // set: every #include must stay inside it (empty: no confinement, as fxc)
    std::vector<std::pair<std::string, std::string>> defines;    // -D NAME=VALUE
    std::vector<std::string> techniques;                         // compile only these; empty = all
    bool useCache = true;                                        // xlate's content-hash cache
    std::string cacheDir;                                        // empty = xlate's default
    // Compile every technique while loading, instead of each at the first Apply of one of its
    // passes (no compile hitch later; load takes longer).
    bool precompile = false;
};

// What an effect has compiled and uploaded so far (GL-free; for tools and tests).
struct EffectStatistics {
    std::vector<std::string> compiledTechniques;  // in the effect's order
    int techniqueCount = 0;
    double loadMilliseconds = 0;     // xlate at load: the outline (or the whole effect if precompiled)
    double compileMilliseconds = 0;  // xlate for techniques compiled after load (cache hits included)
    double linkMilliseconds = 0;     // making GL programs of compiled shaders
    std::uint64_t constantBytesUploaded = 0;  // uniform-buffer bytes sent by Apply(), in total
    std::uint64_t constantUploads = 0;        // uniform-buffer updates (buffer sub-data calls)
};

// An effect's source text held in memory, compiled as if it were the file `virtualPath` (the stock
// effects embed theirs in the library). fxport addition.
struct EffectSource {
    std::string text;
    std::string virtualPath;
};

// Pass states the effect sets that fxport cannot honour (fixed-function states, AlphaToCoverage,
// DepthClipEnable = FALSE ...; xlate's FX1303/FX1304 warnings) are reported once per effect when it
// loads, one call per state: "file(line,col): warning FX1304: ...". The default handler writes them
// to stderr; a host may set its own, or an empty function to silence them. Returns the old handler.
// The handler also gets, once per effect, the first draw of an SRGBWriteEnable pass into a
// SurfaceFormat::Color target (GL encodes sRGB only into SurfaceFormat::ColorSRgb ones).
using EffectWarningHandler = std::function<void(const std::string& warning)>;
EffectWarningHandler SetEffectWarningHandler(EffectWarningHandler handler);

class Effect : public GraphicsResource {
public:
    // Compiles `fxPath` through xlate (cached). Throws xlate::CompileError with file:line diagnostics.
    Effect(fxport::GraphicsDevice& device, const std::string& fxPath, const EffectOptions& options = {});
    // The same from source text in memory (lazy like a file: techniques compile at first Apply).
    Effect(fxport::GraphicsDevice& device, const EffectSource& source, const EffectOptions& options = {});
    // From an effect already compiled (e.g. read from a compiled-effect file).
    Effect(fxport::GraphicsDevice& device, const xlate::CompiledEffect& compiled);
    // Loose shader files (D3D10/11 style, no technique), as D3DCompileFromFile(path, ..., entry,
    // profile) names them: an effect of one technique with one pass "P0" running both entry
    // points; globals and cbuffer members are Parameters like an effect's (effect_from_shaders.cpp).
    struct ShaderFile {
        std::string path;
        std::string entryPoint;  // fxc /E
        std::string profile;     // fxc /T: vs_5_0, ps_4_0, ps_2_0 ...
    };
    static std::unique_ptr<Effect> FromShaderFiles(fxport::GraphicsDevice& device, const ShaderFile& vertexShader,
                                                   const ShaderFile& pixelShader, const EffectOptions& options = {});
    // Any set of stages, one file each (a compute shader alone; vertex, hull, domain and pixel
    // shaders of a tessellated draw ...): the stage of each comes from its profile.
    static std::unique_ptr<Effect> FromShaderFiles(fxport::GraphicsDevice& device, const std::vector<ShaderFile>& shaders,
                                                   const EffectOptions& options = {});
    // Reads a compiled-effect file written by `fxport compile`.
    static std::unique_ptr<Effect> FromCompiledFile(fxport::GraphicsDevice& device, const std::string& path);
    ~Effect() override;

    EffectParameterCollection Parameters;
    EffectTechniqueCollection Techniques;
    EffectTechnique* CurrentTechnique = nullptr;

    // XNA's Effect.Clone: a new effect of the same code (compiled and linked now), its own copy of
    // every parameter value (constants, textures), the same CurrentTechnique and Name. The stock
    // effects clone as their own type with their properties. The clone is the caller's.
    virtual std::unique_ptr<Effect> Clone();

    // The whole effect compiled (compiles the techniques not compiled yet).
    const xlate::CompiledEffect& compiled() const;
    // Compiles and links every technique not compiled yet.
    void Precompile();
    EffectStatistics statistics() const;
    // The source path (for messages).
    const std::string& sourcePath() const;

    struct Impl;  // the library's own state (not API)

protected:
    void releaseGpuObjects() override;
    // XNA's Effect.OnApply: EffectPass::Apply calls it first. A derived effect (the stock effects)
    // pushes its properties into Parameters here and returns the pass to apply instead of `pass`
    // (its shader permutation's); the default applies `pass`.
    virtual EffectPass& OnApply(EffectPass& pass) { return pass; }
    // Clone's second half: every parameter value and the current technique into `clone`, an effect
    // of the same code (a stock effect's Clone makes its own type, then calls this).
    void copyValuesTo(Effect& clone);

private:
    friend class EffectPass;   // calls OnApply
    friend struct ImplAccess;  // the library reaches Impl through it (src/device/impl_access.h)
    void build();
    void linkWhole(std::shared_ptr<const xlate::CompiledEffect> whole);
    std::unique_ptr<Impl> impl_;
};

}  // namespace fxport
