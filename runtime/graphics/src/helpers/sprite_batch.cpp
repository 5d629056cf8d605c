// SpriteBatch: queue, sort, batch by texture, draw through the built-in SpriteEffect. The vertex
// math (corner offsets, origin in source texels, flips in texture space, rotation about the origin)
// and the projection are XNA 4's, so sprites land on the same pixels as on XNA.
#include "fxport/graphics/sprite_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "device/draw_hints.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/texture.h"
#include "fxport/xlate/compiled_effect.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport_generated/sprite_effect_source.h"

namespace fxport {

namespace {

// Compiled once per process (xlate has no GL); each SpriteBatch makes its own Effect from it, as
// each XNA SpriteBatch has its own SpriteEffect.
const xlate::CompiledEffect& compiledSpriteEffect() {
    static const xlate::CompiledEffect compiled =
        xlate::compileEffectSource(detail::kSpriteEffectSource, "<builtin>/SpriteEffect.fx", xlate::CompileOptions{});
    return compiled;
}

// Corner order of a sprite's four vertices and its two triangles (0 1 2, 1 3 2): clockwise on
// screen, so XNA's default CullCounterClockwise keeps them.
constexpr float kCornerX[4] = {0.0f, 1.0f, 0.0f, 1.0f};
constexpr float kCornerY[4] = {0.0f, 0.0f, 1.0f, 1.0f};

std::string textureLabel(const Texture2D& texture) {
    return texture.Name.empty() ? std::string("Texture2D") : "Texture2D '" + texture.Name + "'";
}

// Whether a queued sprite is an unrotated rectangle at depths that are not clipped: its corners
// as queue() lays them out (kCornerX/Y: 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right),
// with left < right and top < bottom (the clockwise winding XNA's culling keeps), z in [0, 1].
bool uprightRectangle(const VertexPositionColorTexture* v) {
    const float left = v[0].Position.X, right = v[1].Position.X, top = v[0].Position.Y, bottom = v[2].Position.Y;
    bool kept = v[2].Position.X == left && v[3].Position.X == right && v[1].Position.Y == top && v[3].Position.Y == bottom &&
                left < right && top < bottom;
    for (int c = 0; c < 4; ++c) kept &= v[c].Position.Z >= 0.0f && v[c].Position.Z <= 1.0f;
    return kept;
}

// Issue 16 (texel copies, texel_copies.cpp): whether each sprite copies texels 1:1 -- an
// unrotated, unflipped white rectangle with whole-pixel edges, at a depth that is not clipped,
// whose texture rectangle lies in the texture and has its size in texels -- and if so, the copies.
// Point sampling then lands every pixel centre half a texel from the texel's edges, on the texel
// `source + (pixel - corner)`, and SpriteEffect's tex2D * colour returns it unchanged.
bool texelCopiesOf(const Texture2D& texture, const VertexPositionColorTexture* vertices, int sprites,
                   std::vector<TexelCopy>& out) {
    out.clear();
    const float textureW = float(texture.Width()), textureH = float(texture.Height());
    auto whole = [](float f, int& i) {
        if (!(std::fabs(f) < 16777216.0f) || std::floor(f) != f) return false;
        i = int(f);
        return true;
    };
    // Texture coordinates are texels times 1/size in float: within a thousandth of a whole texel.
    auto nearWhole = [](float f, int& i) {
        const float r = std::round(f);
        if (!(std::fabs(f) < 16777216.0f) || std::fabs(f - r) > 1e-3f) return false;
        i = int(r);
        return true;
    };
    for (int s = 0; s < sprites; ++s) {
        const VertexPositionColorTexture* v = vertices + std::size_t(s) * 4;
        if (!uprightRectangle(v)) return false;
        const Vector3 p0 = v[0].Position, p1 = v[1].Position, p2 = v[2].Position;
        const Vector2 t0 = v[0].TextureCoordinate, t1 = v[1].TextureCoordinate, t2 = v[2].TextureCoordinate,
                      t3 = v[3].TextureCoordinate;
        // Unflipped: the texture rectangle runs the way the sprite does.
        if (!(t2.X == t0.X && t3.X == t1.X && t1.Y == t0.Y && t3.Y == t2.Y && t0.X < t1.X && t0.Y < t2.Y)) return false;
        for (int c = 0; c < 4; ++c)
            if (!(v[c].Color == Color::White)) return false;
        TexelCopy copy;
        int sourceX1 = 0, sourceY1 = 0;
        if (!whole(p0.X, copy.x0) || !whole(p0.Y, copy.y0) || !whole(p1.X, copy.x1) || !whole(p2.Y, copy.y1) ||
            !nearWhole(t0.X * textureW, copy.sourceX) || !nearWhole(t0.Y * textureH, copy.sourceY) ||
            !nearWhole(t1.X * textureW, sourceX1) || !nearWhole(t2.Y * textureH, sourceY1))
            return false;
        if (sourceX1 - copy.sourceX != copy.x1 - copy.x0 || sourceY1 - copy.sourceY != copy.y1 - copy.y0 || copy.sourceX < 0 ||
            copy.sourceY < 0 || sourceX1 > texture.Width() || sourceY1 > texture.Height())
            return false;
        out.push_back(copy);
    }
    return true;
}

}  // namespace

SpriteBatch::SpriteBatch(fxport::GraphicsDevice& device) : device_(device) {
    spriteEffect_ = std::make_unique<Effect>(device, compiledSpriteEffect());
    spriteEffect_->Name = "SpriteEffect";
    spriteEffect_->CurrentTechnique = spriteEffect_->Techniques["SpriteBatch"];
    matrixTransform_ = &spriteEffect_->Parameters["MatrixTransform"];

    indices_.resize(std::size_t(kMaxBatchSize) * 6);
    for (int sprite = 0; sprite < kMaxBatchSize; ++sprite) {
        const auto base = std::uint16_t(sprite * 4);
        std::uint16_t* quad = indices_.data() + std::size_t(sprite) * 6;
        quad[0] = base;
        quad[1] = std::uint16_t(base + 1);
        quad[2] = std::uint16_t(base + 2);
        quad[3] = std::uint16_t(base + 1);
        quad[4] = std::uint16_t(base + 3);
        quad[5] = std::uint16_t(base + 2);
    }
}

SpriteBatch::~SpriteBatch() = default;

void SpriteBatch::Begin() { Begin(SpriteSortMode::Deferred, nullptr); }

void SpriteBatch::Begin(SpriteSortMode sortMode, NullableRef<const fxport::BlendState> blendState,
                        NullableRef<const fxport::SamplerState> samplerState,
                        NullableRef<const fxport::DepthStencilState> depthStencilState,
                        NullableRef<const fxport::RasterizerState> rasterizerState, NullableRef<Effect> effect,
                        const Matrix& transformMatrix) {
    if (begun_) {
        throw InvalidOperation("SpriteBatch.Begin: End must be called before Begin can be called again");
    }
    sortMode_ = sortMode;
    blendState_ = blendState ? *blendState.get() : fxport::BlendState::AlphaBlend;
    samplerState_ = samplerState ? *samplerState.get() : fxport::SamplerState::LinearClamp;
    depthStencilState_ = depthStencilState ? *depthStencilState.get() : fxport::DepthStencilState::None;
    rasterizerState_ = rasterizerState ? *rasterizerState.get() : fxport::RasterizerState::CullCounterClockwise;
    customEffect_ = effect.get();
    transformMatrix_ = transformMatrix;
    sprites_.clear();
    vertices_.clear();
    drawCalls_ = 0;
    if (sortMode_ == SpriteSortMode::Immediate) {
        setRenderState();
    }
    begun_ = true;
}

void SpriteBatch::End() {
    if (!begun_) {
        throw InvalidOperation("SpriteBatch.End: Begin must be called before End");
    }
    // Whatever happens, the batch is closed and empty afterwards, so it can Begin again.
    struct Reset {
        SpriteBatch& batch;
        ~Reset() {
            batch.begun_ = false;
            batch.sprites_.clear();
            batch.vertices_.clear();
            batch.drawCallsLastEnd_ = batch.drawCalls_;
        }
    } reset{*this};
    // XNA sets the states even for an empty batch (ports use Begin/End to reset device state).
    if (sortMode_ != SpriteSortMode::Immediate) {
        setRenderState();
        flush();
    }
}

void SpriteBatch::throwIfNotBegun(const char* operation) const {
    if (!begun_) {
        throw InvalidOperation(std::string("SpriteBatch.") + operation + ": Begin must be called before " + operation);
    }
}

// XNA's SetRenderState: the device states given to Begin, then MatrixTransform and the built-in
// pass. Done at End (at Begin in Immediate mode) so it sees the viewport of that moment.
void SpriteBatch::setRenderState() {
    device_.BlendState = blendState_;
    device_.DepthStencilState = depthStencilState_;
    device_.RasterizerState = rasterizerState_;
    device_.SamplerStates[0] = samplerState_;

    // Exactly XNA 4's matrix: Translation(-0.5, -0.5, 0) * an orthographic projection of the
    // viewport with y down, depth passed through (M33 = 1, so layerDepth in [0, 1] is never clipped;
    // CreateOrthographicOffCenter(..., 0, 1) would negate it). On D3D9 the -0.5 puts the sprite's
    // edges on pixel edges; fxport's vs_2_0 pixel-centre emulation turns that into GL's convention.
    const fxport::Viewport& viewport = device_.Viewport;
    const float invWidth = viewport.Width > 0 ? 1.0f / float(viewport.Width) : 0.0f;
    const float invHeight = viewport.Height > 0 ? -1.0f / float(viewport.Height) : 0.0f;
    const Matrix projection(invWidth * 2.0f, 0.0f, 0.0f, 0.0f,
                            0.0f, invHeight * 2.0f, 0.0f, 0.0f,
                            0.0f, 0.0f, 1.0f, 0.0f,
                            -1.0f - invWidth, 1.0f - invHeight, 0.0f, 1.0f);
    matrixTransform_->SetValue(transformMatrix_ * projection);
    spriteEffect_->CurrentTechnique->Passes[0].Apply();
    ownVertexShader_ = hints::boundVertexShader(device_);
}

// Issue 16: whether one of these sprites is an unrotated, unflipped rectangle at or beyond every
// edge of the viewport, at a depth that is not clipped, drawn with XNA's matrix alone -- so that,
// through SpriteBatch's vertex shader, it covers every pixel of the viewport (the device checks
// the rest: hints::nextDrawCoversViewport in device/draw_hints.h).
bool SpriteBatch::coversViewport(const VertexPositionColorTexture* vertices, int sprites) const {
    // Immediate mode set the matrix at Begin, from the viewport of that moment: not proven here.
    if (!(transformMatrix_ == Matrix::Identity) || sortMode_ == SpriteSortMode::Immediate) return false;
    const float width = float(device_.Viewport.Width), height = float(device_.Viewport.Height);
    for (int s = 0; s < sprites; ++s) {
        const VertexPositionColorTexture* v = vertices + std::size_t(s) * 4;
        if (uprightRectangle(v) && v[0].Position.X <= 0.0f && v[0].Position.Y <= 0.0f && v[1].Position.X >= width &&
            v[2].Position.Y >= height)
            return true;
    }
    return false;
}

void SpriteBatch::Draw(Texture2D& texture, Rectangle destinationRectangle, Color color) {
    Draw(texture, destinationRectangle, nullptr, color, 0.0f, Vector2::Zero, SpriteEffects::None, 0.0f);
}

void SpriteBatch::Draw(Texture2D& texture, Rectangle destinationRectangle, NullableRef<const Rectangle> sourceRectangle,
                       Color color) {
    Draw(texture, destinationRectangle, sourceRectangle, color, 0.0f, Vector2::Zero, SpriteEffects::None, 0.0f);
}

void SpriteBatch::Draw(Texture2D& texture, Rectangle destinationRectangle, NullableRef<const Rectangle> sourceRectangle,
                       Color color, float rotation, Vector2 origin, SpriteEffects effects, float layerDepth) {
    queue(texture, float(destinationRectangle.X), float(destinationRectangle.Y), float(destinationRectangle.Width),
          float(destinationRectangle.Height), false, sourceRectangle.get(), color, rotation, origin, effects,
          layerDepth);
}

void SpriteBatch::Draw(Texture2D& texture, Vector2 position, Color color) {
    Draw(texture, position, nullptr, color, 0.0f, Vector2::Zero, 1.0f, SpriteEffects::None, 0.0f);
}

void SpriteBatch::Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle,
                       Color color) {
    Draw(texture, position, sourceRectangle, color, 0.0f, Vector2::Zero, 1.0f, SpriteEffects::None, 0.0f);
}

void SpriteBatch::Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle, Color color,
                       float rotation, Vector2 origin, float scale, SpriteEffects effects, float layerDepth) {
    Draw(texture, position, sourceRectangle, color, rotation, origin, Vector2(scale, scale), effects, layerDepth);
}

void SpriteBatch::Draw(Texture2D& texture, Vector2 position, NullableRef<const Rectangle> sourceRectangle, Color color,
                       float rotation, Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth) {
    queue(texture, position.X, position.Y, scale.X, scale.Y, true, sourceRectangle.get(), color, rotation, origin,
          effects, layerDepth);
}

void SpriteBatch::DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color) {
    DrawString(spriteFont, text, position, color, 0.0f, Vector2::Zero, Vector2::One, SpriteEffects::None, 0.0f);
}

void SpriteBatch::DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color,
                             float rotation, Vector2 origin, float scale, SpriteEffects effects, float layerDepth) {
    DrawString(spriteFont, text, position, color, rotation, origin, Vector2(scale, scale), effects, layerDepth);
}

void SpriteBatch::DrawString(const SpriteFont& spriteFont, const std::string& text, Vector2 position, Color color,
                             float rotation, Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth) {
    throwIfNotBegun("DrawString");
    spriteFont.draw(*this, text, position, color, rotation, origin, scale, effects, layerDepth);
}

// XNA's InternalDraw + RenderSprite. destW/destH are a size in pixels, or (scaleDestination) a scale
// of the source size.
void SpriteBatch::queue(Texture2D& texture, float destX, float destY, float destW, float destH, bool scaleDestination,
                        const Rectangle* source, Color color, float rotation, Vector2 origin, SpriteEffects effects,
                        float depth) {
    throwIfNotBegun("Draw");
    if (texture.IsDisposed()) {
        throw InvalidOperation("SpriteBatch.Draw: " + textureLabel(texture) + " was disposed");
    }
    float sourceX = 0.0f;
    float sourceY = 0.0f;
    float sourceW = float(texture.Width());
    float sourceH = float(texture.Height());
    if (source != nullptr) {
        sourceX = float(source->X);
        sourceY = float(source->Y);
        sourceW = float(source->Width);
        sourceH = float(source->Height);
    }
    if (scaleDestination) {
        destW *= sourceW;
        destH *= sourceH;
    }

    float cosine = 1.0f;
    float sine = 0.0f;
    if (rotation != 0.0f) {
        cosine = std::cos(rotation);
        sine = std::sin(rotation);
    }
    // The origin is given in source texels; as a fraction of the sprite (XNA's 2e32 stands in for
    // "infinitely far" when the source is empty).
    const float originX = sourceW != 0.0f ? origin.X / sourceW : origin.X * 2e32f;
    const float originY = sourceH != 0.0f ? origin.Y / sourceH : origin.Y * 2e32f;
    const bool flipX = (effects & SpriteEffects::FlipHorizontally) != SpriteEffects::None;
    const bool flipY = (effects & SpriteEffects::FlipVertically) != SpriteEffects::None;
    const float invTextureW = 1.0f / float(texture.Width());
    const float invTextureH = 1.0f / float(texture.Height());

    VertexPositionColorTexture quad[4];
    for (int corner = 0; corner < 4; ++corner) {
        const float offsetX = (kCornerX[corner] - originX) * destW;
        const float offsetY = (kCornerY[corner] - originY) * destH;
        const float u = flipX ? 1.0f - kCornerX[corner] : kCornerX[corner];
        const float v = flipY ? 1.0f - kCornerY[corner] : kCornerY[corner];
        quad[corner].Position = Vector3(destX + offsetX * cosine - offsetY * sine,
                                        destY + offsetX * sine + offsetY * cosine, depth);
        quad[corner].Color = color;
        quad[corner].TextureCoordinate = Vector2((sourceX + u * sourceW) * invTextureW,
                                                 (sourceY + v * sourceH) * invTextureH);
    }

    if (sortMode_ == SpriteSortMode::Immediate) {
        drawBatch(texture, quad, 1);
        return;
    }
    sprites_.push_back(QueuedSprite{&texture, depth, int(vertices_.size())});
    vertices_.insert(vertices_.end(), quad, quad + 4);
}

void SpriteBatch::flush() {
    if (sprites_.empty()) {
        return;
    }
    const VertexPositionColorTexture* vertices = vertices_.data();
    if (sortMode_ == SpriteSortMode::Texture || sortMode_ == SpriteSortMode::BackToFront ||
        sortMode_ == SpriteSortMode::FrontToBack) {
        // Stable, so equal keys keep their Draw order (deterministic, unlike XNA's Array.Sort).
        // Textures are ordered by GL name: unique among live textures and roughly creation order.
        if (sortMode_ == SpriteSortMode::Texture) {
            std::stable_sort(sprites_.begin(), sprites_.end(), [](const QueuedSprite& a, const QueuedSprite& b) {
                return a.texture->backendObject() < b.texture->backendObject();
            });
        } else if (sortMode_ == SpriteSortMode::BackToFront) {
            std::stable_sort(sprites_.begin(), sprites_.end(),
                             [](const QueuedSprite& a, const QueuedSprite& b) { return a.depth > b.depth; });
        } else {
            std::stable_sort(sprites_.begin(), sprites_.end(),
                             [](const QueuedSprite& a, const QueuedSprite& b) { return a.depth < b.depth; });
        }
        sortedVertices_.clear();
        sortedVertices_.reserve(vertices_.size());
        for (const QueuedSprite& sprite : sprites_) {
            const auto first = vertices_.begin() + sprite.firstVertex;
            sortedVertices_.insert(sortedVertices_.end(), first, first + 4);
        }
        vertices = sortedVertices_.data();
    }

    // One batch per run of sprites with the same texture.
    std::size_t runStart = 0;
    for (std::size_t i = 1; i <= sprites_.size(); ++i) {
        if (i == sprites_.size() || sprites_[i].texture != sprites_[runStart].texture) {
            drawBatch(*sprites_[runStart].texture, vertices + runStart * 4, int(i - runStart));
            runStart = i;
        }
    }
}

void SpriteBatch::drawBatch(Texture2D& texture, const VertexPositionColorTexture* vertices, int count) {
    if (customEffect_ != nullptr && customEffect_->CurrentTechnique == nullptr) {
        throw InvalidOperation("SpriteBatch.End: the custom effect " +
                               (customEffect_->Name.empty() ? customEffect_->sourcePath() : customEffect_->Name) +
                               " has no CurrentTechnique");
    }
    // A custom effect of several passes draws the sprites once per pass: not proven here.
    const bool onePass = customEffect_ == nullptr || customEffect_->CurrentTechnique->Passes.Count() == 1;
    // Texel copies under a Min or Max blend reduce in one dispatch (texel_copies.cpp). Immediate
    // mode set the matrix at Begin, from the viewport of that moment: not proven here.
    const bool reduction = customEffect_ == nullptr && hints::texelCopiesAvailable(device_) && transformMatrix_ == Matrix::Identity &&
                           sortMode_ != SpriteSortMode::Immediate &&
                           (blendState_.ColorBlendFunction == BlendFunction::Min || blendState_.ColorBlendFunction == BlendFunction::Max);
    std::vector<TexelCopy> copies;
    while (count > 0) {
        const int sprites = std::min(count, kMaxBatchSize);
        if (reduction && texelCopiesOf(texture, vertices, sprites, copies)) {
            device_.Textures[0] = texture;
            if (hints::tryTexelCopies(device_, texture, copies)) {
                ++drawCalls_;
                vertices += std::size_t(sprites) * 4;
                count -= sprites;
                continue;
            }
        }
        const bool covers = onePass && coversViewport(vertices, sprites);
        auto draw = [&] {
            device_.Textures[0] = texture;
            if (covers) hints::nextDrawCoversViewport(device_, ownVertexShader_);
            device_.DrawUserIndexedPrimitives(PrimitiveType::TriangleList, vertices, 0, sprites * 4, indices_.data(), 0,
                                              sprites * 2);
            ++drawCalls_;
        };
        if (customEffect_ != nullptr) {
            // After the built-in pass (bound by setRenderState): a pass without a vertex shader keeps
            // SpriteBatch's. The sprite texture is set after Apply so it wins over texture parameters.
            for (EffectPass& pass : customEffect_->CurrentTechnique->Passes) {
                pass.Apply();
                draw();
            }
        } else {
            draw();
        }
        vertices += std::size_t(sprites) * 4;
        count -= sprites;
    }
}

}  // namespace fxport
