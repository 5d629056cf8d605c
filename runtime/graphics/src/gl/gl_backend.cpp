// The OpenGL 4.5 backend's state setting (gl_backend.h): XNA's state descriptions in GL's words.
// The device's StateShadow decides whether a state is sent; here each set* compares with the state
// it was last given (`had`, null: set every field) and calls GL only for the fields that differ.
#include <algorithm>
#include <array>

#include "gl/gl_backend.h"

#include "device/sampler_filter.h"

namespace fxport {

namespace {

GLenum glBlend(Blend b) {
    switch (b) {
    case Blend::One: return GL_ONE;
    case Blend::Zero: return GL_ZERO;
    case Blend::SourceColor: return GL_SRC_COLOR;
    case Blend::InverseSourceColor: return GL_ONE_MINUS_SRC_COLOR;
    case Blend::SourceAlpha: return GL_SRC_ALPHA;
    case Blend::InverseSourceAlpha: return GL_ONE_MINUS_SRC_ALPHA;
    case Blend::DestinationColor: return GL_DST_COLOR;
    case Blend::InverseDestinationColor: return GL_ONE_MINUS_DST_COLOR;
    case Blend::DestinationAlpha: return GL_DST_ALPHA;
    case Blend::InverseDestinationAlpha: return GL_ONE_MINUS_DST_ALPHA;
    case Blend::BlendFactor: return GL_CONSTANT_COLOR;
    case Blend::InverseBlendFactor: return GL_ONE_MINUS_CONSTANT_COLOR;
    case Blend::SourceAlphaSaturation: return GL_SRC_ALPHA_SATURATE;
    }
    return GL_ONE;
}

GLenum glBlendEquation(BlendFunction f) {
    switch (f) {
    case BlendFunction::Add: return GL_FUNC_ADD;
    case BlendFunction::Subtract: return GL_FUNC_SUBTRACT;
    case BlendFunction::ReverseSubtract: return GL_FUNC_REVERSE_SUBTRACT;
    case BlendFunction::Min: return GL_MIN;
    case BlendFunction::Max: return GL_MAX;
    }
    return GL_FUNC_ADD;
}

GLenum glCompare(CompareFunction f) {
    switch (f) {
    case CompareFunction::Always: return GL_ALWAYS;
    case CompareFunction::Never: return GL_NEVER;
    case CompareFunction::Less: return GL_LESS;
    case CompareFunction::LessEqual: return GL_LEQUAL;
    case CompareFunction::Equal: return GL_EQUAL;
    case CompareFunction::GreaterEqual: return GL_GEQUAL;
    case CompareFunction::Greater: return GL_GREATER;
    case CompareFunction::NotEqual: return GL_NOTEQUAL;
    }
    return GL_ALWAYS;
}

GLenum glStencilOp(StencilOperation op) {
    switch (op) {
    case StencilOperation::Keep: return GL_KEEP;
    case StencilOperation::Zero: return GL_ZERO;
    case StencilOperation::Replace: return GL_REPLACE;
    case StencilOperation::Increment: return GL_INCR_WRAP;
    case StencilOperation::Decrement: return GL_DECR_WRAP;
    case StencilOperation::IncrementSaturation: return GL_INCR;
    case StencilOperation::DecrementSaturation: return GL_DECR;
    case StencilOperation::Invert: return GL_INVERT;
    }
    return GL_KEEP;
}

GLenum glAddress(TextureAddressMode m) {
    switch (m) {
    case TextureAddressMode::Wrap: return GL_REPEAT;
    case TextureAddressMode::Clamp: return GL_CLAMP_TO_EDGE;
    case TextureAddressMode::Mirror: return GL_MIRRORED_REPEAT;
    case TextureAddressMode::Border: return GL_CLAMP_TO_BORDER;
    }
    return GL_REPEAT;
}

std::array<float, 4> colorFloats(Color c) {
    return {c.R / 255.0f, c.G / 255.0f, c.B / 255.0f, c.A / 255.0f};
}

// XNA culling on GL. ARB_clip_control judges winding as it appears in NDC (with GL_UPPER_LEFT it
// negates the window-space area to undo its own y flip), and our images show NDC +y at the top: a
// triangle clockwise in the final image is clockwise to GL. XNA's front faces are clockwise, so
// glFrontFace(GL_CW), and CullCounterClockwiseFace culls GL's back faces. (Pinned by
// Conventions.CullModesFollowWindingAsSeen.) The winding is set without culling too: it also
// decides gl_FrontFacing (SV_IsFrontFace, VFACE) and which stencil ops a triangle uses, and GL's
// default (GL_CCW) would invert both until a culled draw first set it. D3D10/11's
// FrontCounterClockwise makes counter-clockwise triangles the front ones (glFrontFace(GL_CCW));
// the cull mode still names the winding as seen, so the GL face it culls swaps with it.
void applyCull(const RasterizerState& state) {
    glFrontFace(state.FrontCounterClockwise ? GL_CCW : GL_CW);
    if (state.CullMode == CullMode::None) {
        glDisable(GL_CULL_FACE);
        return;
    }
    glEnable(GL_CULL_FACE);
    const bool cullsClockwise = state.CullMode == CullMode::CullClockwiseFace;
    glCullFace(cullsClockwise != state.FrontCounterClockwise ? GL_FRONT : GL_BACK);
}


struct AttributeFormat {
    GLint size;
    GLenum type;
    GLboolean normalized;
};

GLenum componentType(VertexComponent c) {
    switch (c) {
    case VertexComponent::Float32: return GL_FLOAT;
    case VertexComponent::Float16: return GL_HALF_FLOAT;
    case VertexComponent::UInt8: return GL_UNSIGNED_BYTE;
    case VertexComponent::SInt8: return GL_BYTE;
    case VertexComponent::UInt16: return GL_UNSIGNED_SHORT;
    case VertexComponent::SInt16: return GL_SHORT;
    case VertexComponent::UInt32: return GL_UNSIGNED_INT;
    case VertexComponent::SInt32: return GL_INT;
    case VertexComponent::UInt1010102: return GL_UNSIGNED_INT_2_10_10_10_REV;
    case VertexComponent::UInt8Bgra: return GL_UNSIGNED_BYTE;
    case VertexComponent::UFloat111110: return GL_UNSIGNED_INT_10F_11F_11F_REV;
    }
    return GL_FLOAT;
}

AttributeFormat attributeFormat(const VertexFormat& f) {
    // GL reads B, G, R, A bytes when the size is GL_BGRA (normalised bytes only).
    const GLint size = f.component == VertexComponent::UInt8Bgra ? GLint(GL_BGRA) : GLint(f.count);
    return {size, componentType(f.component), f.normalized ? GLboolean(GL_TRUE) : GLboolean(GL_FALSE)};
}

}  // namespace

std::unique_ptr<Backend> createGlBackend() { return std::make_unique<GlBackend>(); }

BackendObject GlBackend::createPipeline(const std::array<BackendObject, 5>& programs) {
    GLuint pipeline = 0;
    glCreateProgramPipelines(1, &pipeline);
    glUseProgramStages(pipeline, GL_VERTEX_SHADER_BIT, programs[0]);
    glUseProgramStages(pipeline, GL_FRAGMENT_SHADER_BIT, programs[1]);
    if (programs[2]) glUseProgramStages(pipeline, GL_GEOMETRY_SHADER_BIT, programs[2]);
    if (programs[3]) glUseProgramStages(pipeline, GL_TESS_CONTROL_SHADER_BIT, programs[3]);
    if (programs[4]) glUseProgramStages(pipeline, GL_TESS_EVALUATION_SHADER_BIT, programs[4]);
    return pipeline;
}

BackendObject GlBackend::createVertexArray(const std::vector<VertexAttribute>& attributes, const std::vector<int>& divisors) {
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    for (const VertexAttribute& a : attributes) {
        const GLuint location = GLuint(a.location);
        const AttributeFormat f = attributeFormat(a.format);
        glEnableVertexArrayAttrib(vao, location);
        // An integer input fed 32-bit floats gets their bits, as a D3D register holds them (GL has
        // no float type for integer attributes).
        if (a.integer) glVertexArrayAttribIFormat(vao, location, f.size, f.type == GL_FLOAT ? GLenum(GL_INT) : f.type, GLuint(a.offset));
        else glVertexArrayAttribFormat(vao, location, f.size, f.type, f.normalized, GLuint(a.offset));
        glVertexArrayAttribBinding(vao, location, GLuint(a.binding));
    }
    for (std::size_t binding = 0; binding < divisors.size(); ++binding)
        glVertexArrayBindingDivisor(vao, GLuint(binding), GLuint(std::max(divisors[binding], 0)));
    return vao;
}

void GlBackend::setBlend(const BlendState& w, const BlendState* had) {
    const bool forceAll = had == nullptr;
    const BlendState& a = had ? *had : w;
    if (forceAll || w.blendingEnabled() != a.blendingEnabled()) {
        if (w.blendingEnabled()) glEnable(GL_BLEND);
        else glDisable(GL_BLEND);
    }
    if (forceAll || w.ColorSourceBlend != a.ColorSourceBlend || w.ColorDestinationBlend != a.ColorDestinationBlend ||
        w.AlphaSourceBlend != a.AlphaSourceBlend || w.AlphaDestinationBlend != a.AlphaDestinationBlend)
        glBlendFuncSeparate(glBlend(w.ColorSourceBlend), glBlend(w.ColorDestinationBlend), glBlend(w.AlphaSourceBlend),
                            glBlend(w.AlphaDestinationBlend));
    if (forceAll || w.ColorBlendFunction != a.ColorBlendFunction || w.AlphaBlendFunction != a.AlphaBlendFunction)
        glBlendEquationSeparate(glBlendEquation(w.ColorBlendFunction), glBlendEquation(w.AlphaBlendFunction));
    if (forceAll || w.BlendFactor != a.BlendFactor) {
        auto c = colorFloats(w.BlendFactor);
        glBlendColor(c[0], c[1], c[2], c[3]);
    }
    const fxport::ColorWriteChannels wanted[4] = {w.ColorWriteChannels, w.ColorWriteChannels1, w.ColorWriteChannels2,
                                                  w.ColorWriteChannels3};
    const fxport::ColorWriteChannels hadMasks[4] = {a.ColorWriteChannels, a.ColorWriteChannels1, a.ColorWriteChannels2,
                                                    a.ColorWriteChannels3};
    for (GLuint i = 0; i < 4; ++i) {
        if (!forceAll && wanted[i] == hadMasks[i]) continue;
        unsigned m = unsigned(wanted[i]);
        glColorMaski(i, (m & 1) != 0, (m & 2) != 0, (m & 4) != 0, (m & 8) != 0);
    }
    if (forceAll || w.MultiSampleMask != a.MultiSampleMask) {
        // GL applies the mask only with GL_SAMPLE_MASK on; all ones (-1) is D3D's default, no masking.
        if (w.MultiSampleMask == -1) glDisable(GL_SAMPLE_MASK);
        else glEnable(GL_SAMPLE_MASK);
        glSampleMaski(0, GLbitfield(w.MultiSampleMask));
    }
}

void GlBackend::setDepthStencil(const DepthStencilState& w, const DepthStencilState* had) {
    const bool forceAll = had == nullptr;
    const DepthStencilState& a = had ? *had : w;
    // GL skips depth writes when the test is off; D3D too (ZENABLE false disables both).
    if (forceAll || w.DepthBufferEnable != a.DepthBufferEnable) {
        if (w.DepthBufferEnable) glEnable(GL_DEPTH_TEST);
        else glDisable(GL_DEPTH_TEST);
    }
    if (forceAll || w.DepthBufferWriteEnable != a.DepthBufferWriteEnable) glDepthMask(w.DepthBufferWriteEnable);
    if (forceAll || w.DepthBufferFunction != a.DepthBufferFunction) glDepthFunc(glCompare(w.DepthBufferFunction));
    if (forceAll || w.StencilEnable != a.StencilEnable) {
        if (w.StencilEnable) glEnable(GL_STENCIL_TEST);
        else glDisable(GL_STENCIL_TEST);
    }
    // Front faces (clockwise as seen, XNA's front; GL_CW, see applyCull) use the main stencil ops;
    // with two-sided mode the back faces use the CounterClockwise ones.
    if (forceAll || !(w == a)) {
        CompareFunction backFunc = w.TwoSidedStencilMode ? w.CounterClockwiseStencilFunction : w.StencilFunction;
        StencilOperation backFail = w.TwoSidedStencilMode ? w.CounterClockwiseStencilFail : w.StencilFail;
        StencilOperation backZFail = w.TwoSidedStencilMode ? w.CounterClockwiseStencilDepthBufferFail : w.StencilDepthBufferFail;
        StencilOperation backPass = w.TwoSidedStencilMode ? w.CounterClockwiseStencilPass : w.StencilPass;
        glStencilFuncSeparate(GL_FRONT, glCompare(w.StencilFunction), w.ReferenceStencil, GLuint(w.StencilMask));
        glStencilFuncSeparate(GL_BACK, glCompare(backFunc), w.ReferenceStencil, GLuint(w.StencilMask));
        glStencilOpSeparate(GL_FRONT, glStencilOp(w.StencilFail), glStencilOp(w.StencilDepthBufferFail), glStencilOp(w.StencilPass));
        glStencilOpSeparate(GL_BACK, glStencilOp(backFail), glStencilOp(backZFail), glStencilOp(backPass));
        glStencilMask(GLuint(w.StencilWriteMask));
    }
}

void GlBackend::setRasterizer(const RasterizerState& w, const RasterizerState* had) {
    const bool forceAll = had == nullptr;
    const RasterizerState& a = had ? *had : w;
    if (forceAll || w.CullMode != a.CullMode || w.FrontCounterClockwise != a.FrontCounterClockwise) applyCull(w);
    if (forceAll || w.FillMode != a.FillMode) glPolygonMode(GL_FRONT_AND_BACK, w.FillMode == FillMode::Solid ? GL_FILL : GL_LINE);
    if (forceAll || w.DepthBias != a.DepthBias || w.SlopeScaleDepthBias != a.SlopeScaleDepthBias) {
        // D3D's DepthBias is in depth-range units; GL's units are the depth buffer's resolution
        // (2^-24 for 24-bit depth), hence the scale.
        if (w.DepthBias == 0 && w.SlopeScaleDepthBias == 0) {
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_POLYGON_OFFSET_LINE);
        } else {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glPolygonOffset(w.SlopeScaleDepthBias, w.DepthBias * float(1 << 24));
        }
    }
    if (forceAll || w.ScissorTestEnable != a.ScissorTestEnable) {
        if (w.ScissorTestEnable) glEnable(GL_SCISSOR_TEST);
        else glDisable(GL_SCISSOR_TEST);
    }
    if (forceAll || w.MultiSampleAntiAlias != a.MultiSampleAntiAlias) {
        if (w.MultiSampleAntiAlias) glEnable(GL_MULTISAMPLE);
        else glDisable(GL_MULTISAMPLE);
    }
}

void GlBackend::setViewport(const Viewport& w, ViewportShift shift) {
    // Under GL_UPPER_LEFT, window y runs from the top row of the (top-row-first) target, like D3D:
    // the viewport needs no flip. A shifted origin is exact in window coordinates (GL 4.1's float
    // viewport), where a shift added in clip space rounds (1/640 of the NDC range is not a float).
    if (shift == ViewportShift{}) glViewport(w.X, w.Y, w.Width, w.Height);
    else glViewportIndexedf(0, float(w.X) + shift.x, float(w.Y) + shift.y, float(w.Width), float(w.Height));
    glDepthRangef(w.MinDepth, w.MaxDepth);
}

void GlBackend::setMoreViewports(const std::vector<Viewport>& more, ViewportShift shift) {
    // glViewport and glDepthRangef (setViewport) set every index; these follow them.
    for (std::size_t i = 0; i < more.size(); ++i) {
        const Viewport& w = more[i];
        const GLuint index = GLuint(i + 1);
        glViewportIndexedf(index, float(w.X) + shift.x, float(w.Y) + shift.y, float(w.Width), float(w.Height));
        glDepthRangeIndexed(index, w.MinDepth, w.MaxDepth);
    }
}

// glScissor sets the rectangle of every viewport.
void GlBackend::setScissor(const Rectangle& w) { glScissor(w.X, w.Y, std::max(0, w.Width), std::max(0, w.Height)); }

void GlBackend::setMoreScissors(const std::vector<Rectangle>& more) {
    for (std::size_t i = 0; i < more.size(); ++i) {
        const Rectangle& w = more[i];
        glScissorIndexed(GLuint(i + 1), w.X, w.Y, std::max(0, w.Width), std::max(0, w.Height));
    }
}

void GlBackend::setSrgbWrite(bool enabled) {
    // Converts only on sRGB-encoded attachments (SurfaceFormat::ColorSRgb); others are written
    // unconverted (docs/DESIGN.md, "Pass states GL core lacks").
    if (enabled) glEnable(GL_FRAMEBUFFER_SRGB);
    else glDisable(GL_FRAMEBUFFER_SRGB);
}

void GlBackend::setClipPlanes(int count) {
    // GL 4.5 guarantees 8 clip distances (GL_MAX_CLIP_DISTANCES), D3D11's count.
    for (int i = 0; i < 8; ++i) {
        if (i < count) glEnable(GLenum(GL_CLIP_DISTANCE0 + i));
        else glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    }
}

void GlBackend::setPointSize(float size, bool fromShader) {
    // Core GL has no point-size clamp (POINT_SIZE_MIN/MAX are compatibility-only): the device
    // clamps `size`, and a vertex shader's gl_PointSize is clamped by the shader variant.
    if (fromShader) glEnable(GL_PROGRAM_POINT_SIZE);
    else glDisable(GL_PROGRAM_POINT_SIZE);
    glPointSize(size);
}

BackendObject GlBackend::createSampler(const SamplerState& s) {
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    auto [minLinear, magLinear, mipLinear, anisotropic] = splitFilter(s.Filter);
    GLenum minFilter = s.UseMipMaps ? (minLinear ? (mipLinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST)
                                                 : (mipLinear ? GL_NEAREST_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST))
                                    : (minLinear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, magLinear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GLint(glAddress(s.AddressU)));
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GLint(glAddress(s.AddressV)));
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_R, GLint(glAddress(s.AddressW)));
    glSamplerParameterf(sampler, GL_TEXTURE_MIN_LOD, float(s.MaxMipLevel));
    glSamplerParameterf(sampler, GL_TEXTURE_LOD_BIAS, s.MipMapLevelOfDetailBias);
    if (!s.UseMipMaps) glSamplerParameterf(sampler, GL_TEXTURE_MAX_LOD, float(s.MaxMipLevel));
    const float border[4] = {s.BorderColor.X, s.BorderColor.Y, s.BorderColor.Z, s.BorderColor.W};
    glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, border);
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, s.UseComparison ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GLint(glCompare(s.ComparisonFunction)));
    if (anisotropic)
        glSamplerParameterf(sampler, GL_TEXTURE_MAX_ANISOTROPY, float(std::max(1, s.MaxAnisotropy)));
    return sampler;
}

}  // namespace fxport
