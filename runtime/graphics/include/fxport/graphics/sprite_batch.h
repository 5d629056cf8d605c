// SpriteBatch: XNA 4's 2D sprite renderer, with XNA 4's behaviour on Direct3D 9.
//
//   SpriteBatch spriteBatch(device);
//   spriteBatch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
//   spriteBatch.Draw(texture, Rectangle(0, 0, 128, 128), Color::White);
//   spriteBatch.DrawString(*font, "Sample Radius: 0.5", Vector2(0, 128), Color::Red);
//   spriteBatch.End();
//
// Sprites are queued between Begin and End and drawn at End (Immediate mode: at each Draw), one
// draw call per run of sprites sharing a texture (after sorting, for the Texture / BackToFront /
// FrontToBack modes). Drawing sets, as XNA does and without restoring them afterwards, the device's
// BlendState, DepthStencilState, RasterizerState, SamplerStates[0] and Textures[0], and leaves the
// built-in SpriteEffect's shaders bound.
//
// The built-in effect (runtime/graphics/shaders/SpriteEffect.fx, a vs_2_0/ps_2_0 effect like XNA's)
// receives in MatrixTransform exactly what XNA 4 puts there: transformMatrix * (a half-pixel shift
// and an orthographic projection of the viewport, y down). The runtime's D3D9 pixel-centre emulation
// for SM2 vertex shaders does the rest, so a sprite at Rectangle(x, y, w, h) covers exactly the
// pixels x..x+w-1, y..y+h-1 and texel (i, j) lands on pixel (x+i, y+j) at scale 1.
//
// A custom effect given to Begin is applied after the built-in one, for each batch and each pass
// of its CurrentTechnique (Apply, then Textures[0] = the sprite texture, then draw). A pass that
// sets only a pixel shader runs with SpriteBatch's vertex shader, as on XNA.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/vertex_types.h"
#include "fxport/math.h"

namespace fxport {

class Effect;
class EffectParameter;
class GraphicsDevice;
class SpriteFont;
class Texture2D;

enum class SpriteSortMode : std::uint8_t {
    Deferred,     // in Draw order, drawn at End
    Immediate,    // drawn at each Draw; device state is set at Begin
    Texture,      // grouped by texture (fewest draw calls)
    BackToFront,  // by layerDepth, largest (farthest) first
    FrontToBack,  // by layerDepth, smallest (nearest) first
};

// Flags, as in XNA: FlipHorizontally | FlipVertically turns a sprite by 180 degrees.
enum class SpriteEffects : std::uint8_t { None = 0, FlipHorizontally = 1, FlipVertically = 2 };
constexpr SpriteEffects operator|(SpriteEffects a, SpriteEffects b) {
    return SpriteEffects(std::uint8_t(a) | std::uint8_t(b));
}
constexpr SpriteEffects operator&(SpriteEffects a, SpriteEffects b) {
    return SpriteEffects(std::uint8_t(a) & std::uint8_t(b));
}

// An argument that C# passes by reference and may be null: a T, a pointer to one, nullptr, or a
// smart pointer. What XNA ports write — Begin(SpriteSortMode.Deferred, blend, null, null, null,
// effect), Draw(texture, dest, null, color) — then reads the same in C++. A temporary passed as a
// T lives until the end of the call, which copies what it needs.
template <class T>
class NullableRef {
public:
    NullableRef(std::nullptr_t) {}  // NOLINT: implicit on purpose (C#'s null)
    NullableRef(T& value) : pointer_(&value) {}  // NOLINT
    NullableRef(T* value) : pointer_(value) {}   // NOLINT
    template <class U> NullableRef(const std::unique_ptr<U>& value) : pointer_(value.get()) {}  // NOLINT
    template <class U> NullableRef(const std::shared_ptr<U>& value) : pointer_(value.get()) {}  // NOLINT

    T* get() const { return pointer_; }
    explicit operator bool() const { return pointer_ != nullptr; }

private:
    T* pointer_ = nullptr;
};

class SpriteBatch {
public:
    explicit SpriteBatch(fxport::GraphicsDevice& device);
    ~SpriteBatch();
    SpriteBatch(const SpriteBatch&) = delete;
    SpriteBatch& operator=(const SpriteBatch&) = delete;

    // XNA 4's Begin overloads in one: a null state means XNA's default (AlphaBlend, LinearClamp,
    // DepthStencilState::None, CullCounterClockwise). States are copied. The effect (if any) must
    // live until End. Throws InvalidOperation when Begin was already called without End.
    void Begin();
    void Begin(SpriteSortMode sortMode, NullableRef<const fxport::BlendState> blendState,
               NullableRef<const fxport::SamplerState> samplerState = nullptr,
               NullableRef<const fxport::DepthStencilState> depthStencilState = nullptr,
               NullableRef<const fxport::RasterizerState> rasterizerState = nullptr,
               NullableRef<Effect> effect = nullptr, const Matrix& transformMatrix = Matrix::Identity);

    // The source rectangle (in texels; null = the whole texture) may be given as a Rectangle, a
    // pointer to one, or nullptr. Throws InvalidOperation before Begin.
    void Draw(Texture2D& texture, Rectangle destinationRectangle, Color color);
    void Draw(Texture2D& texture, Rectangle destinationRectangle, NullableRef<const Rectangle> sourceRectangle,
              Color color);
    // rotation in radians (clockwise on screen) about origin, given in source texels.
    void Draw(Texture2D& texture, Rectangle destinationRectangle, NullableRef<const Rectangle> sourceRectangle,
              Color color, float rotation, Vector2 origin, SpriteEffects effects, float layerDepth);
    void Draw(Texture2D& texture, Vector2 position, Color color);
    void Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle, Color color);
    void Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle, Color color,
              float rotation, Vector2 origin, float scale, SpriteEffects effects, float layerDepth);
    void Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle, Color color,
              float rotation, Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth);

    // Text in UTF-8; '\n' starts a new line (LineSpacing lower), '\r' is ignored. Characters the
    // font lacks draw as its DefaultCharacter, or throw ArgumentError when it has none.
    void DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color);
    void DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color,
                    float rotation, Vector2 origin, float scale, SpriteEffects effects, float layerDepth);
    void DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color,
                    float rotation, Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth);

    // Draws what is queued. Throws InvalidOperation without a Begin.
    void End();

    fxport::GraphicsDevice& device() const { return device_; }
    // The built-in SpriteEffect (technique "SpriteBatch", parameter MatrixTransform).
    Effect& spriteEffect() { return *spriteEffect_; }

    // fxport: device draw calls issued between the last Begin and End (with a multi-pass custom
    // effect, one per pass and batch). For tests and benchmarks of batching.
    int drawCallsLastEnd() const { return drawCallsLastEnd_; }
    // Most sprites in one draw call (16-bit indices).
    static constexpr int kMaxBatchSize = 16384;

private:
    struct QueuedSprite {
        Texture2D* texture;
        float depth;
        int firstVertex;  // into vertices_
    };

    void throwIfNotBegun(const char* operation) const;
    void queue(Texture2D& texture, float destX, float destY, float destW, float destH, bool scaleDestination,
               const Rectangle* source, Color color, float rotation, Vector2 origin, SpriteEffects effects,
               float depth);
    void setRenderState();
    void flush();
    // Draws `count` sprites of one texture whose vertices start at `vertices`.
    void drawBatch(Texture2D& texture, const VertexPositionColorTexture* vertices, int count);

    fxport::GraphicsDevice& device_;
    std::unique_ptr<Effect> spriteEffect_;
    EffectParameter* matrixTransform_ = nullptr;

    bool begun_ = false;
    SpriteSortMode sortMode_ = SpriteSortMode::Deferred;
    fxport::BlendState blendState_;
    fxport::SamplerState samplerState_;
    fxport::DepthStencilState depthStencilState_;
    fxport::RasterizerState rasterizerState_;
    Effect* customEffect_ = nullptr;
    Matrix transformMatrix_ = Matrix::Identity;

    std::vector<QueuedSprite> sprites_;
    std::vector<VertexPositionColorTexture> vertices_;        // 4 per queued sprite
    std::vector<VertexPositionColorTexture> sortedVertices_;  // scratch for the sorted modes
    std::vector<std::uint16_t> indices_;                       // 6 per sprite, kMaxBatchSize sprites
    int drawCalls_ = 0;
    int drawCallsLastEnd_ = 0;
    const void* ownVertexShader_ = nullptr;  // the built-in pass's vertex program (issue 16: covering sprites)
    bool coversViewport(const VertexPositionColorTexture* vertices, int sprites) const;
};

}  // namespace fxport
