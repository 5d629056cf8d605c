// The work the OpenGL backend issues (gl_backend.h): draws, texel transfers and copies, clears of
// a texture or a depth buffer, storage images, and the flipped blit a window shows.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gl/gl_backend.h"
#include "gl/gl_formats.h"

namespace fxport {

GLenum glModeOf(const DrawCall& call) {
    if (call.controlPoints > 0) return GL_PATCHES;
    switch (call.type) {
    case PrimitiveType::TriangleList: return GL_TRIANGLES;
    case PrimitiveType::TriangleStrip: return GL_TRIANGLE_STRIP;
    case PrimitiveType::LineList: return GL_LINES;
    case PrimitiveType::LineStrip: return GL_LINE_STRIP;
    case PrimitiveType::PointList: return GL_POINTS;
    }
    return GL_TRIANGLES;
}

void GlBackend::draw(const DrawCall& call) {
    const GLenum mode = glModeOf(call);
    if (call.controlPoints > 0) glPatchParameteri(GL_PATCH_VERTICES, call.controlPoints);
    const void* firstIndex = reinterpret_cast<const void*>(std::uintptr_t(call.first) * std::uintptr_t(call.indexSize));
    if (call.instanced) {
        if (call.indexed)
            glDrawElementsInstancedBaseVertexBaseInstance(mode, call.count, glIndexTypeOf(call), firstIndex, call.instances,
                                                          call.baseVertex, GLuint(call.firstInstance));
        else
            glDrawArraysInstancedBaseInstance(mode, call.first, call.count, call.instances, GLuint(call.firstInstance));
    } else if (call.indexed) {
        glDrawElementsBaseVertex(mode, call.count, glIndexTypeOf(call), firstIndex, call.baseVertex);
    } else {
        glDrawArrays(mode, call.first, call.count);
    }
}

void GlBackend::writeTexture(BackendObject texture, SurfaceFormat format, int face, int level, const Rectangle& area,
                             const void* data) {
    const detail::GlTextureFormat& f = detail::glFormat(format);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (!f.isCompressed && writeLine(lineTargetOf(texture), texture, format, face, level, area, data)) return;
    if (f.isCompressed) {
        const auto bytes = GLsizei(regionBytes(format, area.Width, area.Height));
        if (face < 0)
            glCompressedTextureSubImage2D(texture, level, area.X, area.Y, area.Width, area.Height, f.internalFormat, bytes, data);
        else
            glCompressedTextureSubImage3D(texture, level, area.X, area.Y, face, area.Width, area.Height, 1, f.internalFormat, bytes, data);
    } else if (face < 0)
        glTextureSubImage2D(texture, level, area.X, area.Y, area.Width, area.Height, f.format, f.type, data);
    else
        glTextureSubImage3D(texture, level, area.X, area.Y, face, area.Width, area.Height, 1, f.format, f.type, data);
}

void GlBackend::writeVolume(BackendObject texture, SurfaceFormat format, int level, int width, int height, int depth, const void* data) {
    const detail::GlTextureFormat& f = detail::glFormat(format);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (f.isCompressed)
        glCompressedTextureSubImage3D(texture, level, 0, 0, 0, width, height, depth, f.internalFormat,
                                      GLsizei(regionBytes(format, width, height) * std::size_t(depth)), data);
    else
        glTextureSubImage3D(texture, level, 0, 0, 0, width, height, depth, f.format, f.type, data);
}

void GlBackend::copySamples(const SampleCopy& c) {
    GLuint fbos[2] = {0, 0};
    glCreateFramebuffers(2, fbos);
    if (c.sourceLayer >= 0) glNamedFramebufferTextureLayer(fbos[0], GL_COLOR_ATTACHMENT0, c.source, 0, c.sourceLayer);
    else glNamedFramebufferTexture(fbos[0], GL_COLOR_ATTACHMENT0, c.source, 0);
    glNamedFramebufferReadBuffer(fbos[0], GL_COLOR_ATTACHMENT0);
    if (c.destinationLayer >= 0) glNamedFramebufferTextureLayer(fbos[1], GL_COLOR_ATTACHMENT0, c.destination, c.destinationLevel, c.destinationLayer);
    else glNamedFramebufferTexture(fbos[1], GL_COLOR_ATTACHMENT0, c.destination, c.destinationLevel);
    glNamedFramebufferDrawBuffer(fbos[1], GL_COLOR_ATTACHMENT0);
    // A blit is clipped by the scissor test and writes through the colour mask, neither of which a
    // resolve has: both are set aside for it and put back.
    const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);  // draw buffer 0's
    glDisable(GL_SCISSOR_TEST);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlitNamedFramebuffer(fbos[0], fbos[1], 0, 0, c.width, c.height, 0, 0, c.width, c.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glColorMaski(0, mask[0], mask[1], mask[2], mask[3]);
    if (scissor) glEnable(GL_SCISSOR_TEST);
    glDeleteFramebuffers(2, fbos);
}

void GlBackend::readTexture(BackendObject texture, SurfaceFormat format, int face, int level, std::size_t bytes, void* out) {
    const detail::GlTextureFormat& f = detail::glFormat(format);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (!f.isCompressed && readLine(lineTargetOf(texture), texture, f.format, f.type, face, level, bytes, out)) return;
    if (f.isCompressed) {
        if (face < 0) return glGetCompressedTextureImage(texture, level, GLsizei(bytes), out);
        const Rectangle size = textureLevelSize(texture, level);
        glGetCompressedTextureSubImage(texture, level, 0, 0, face, size.Width, size.Height, 1, GLsizei(bytes), out);
    } else if (face < 0) {
        glGetTextureImage(texture, level, f.format, f.type, GLsizei(bytes), out);
    } else {
        // A cube's face or an array's layer: the level's width x height at depth `face`.
        const Rectangle size = textureLevelSize(texture, level);
        glGetTextureSubImage(texture, level, 0, 0, face, size.Width, size.Height, 1, f.format, f.type, GLsizei(bytes), out);
    }
}

void GlBackend::readTextureFloats(BackendObject texture, int face, int level, std::size_t bytes, void* out) {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (readLine(lineTargetOf(texture), texture, GL_RGBA, GL_FLOAT, face, level, bytes, out)) return;
    if (face < 0) {
        glGetTextureImage(texture, level, GL_RGBA, GL_FLOAT, GLsizei(bytes), out);
    } else {
        const Rectangle size = textureLevelSize(texture, level);
        glGetTextureSubImage(texture, level, 0, 0, face, size.Width, size.Height, 1, GL_RGBA, GL_FLOAT, GLsizei(bytes), out);
    }
}

Rectangle GlBackend::textureLevelSize(BackendObject texture, int level) {
    GLint w = 0, h = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
    return Rectangle(0, 0, w, h);
}

void GlBackend::copyTexture(const TextureCopy& c) {
    const GLenum target = c.cube ? GL_TEXTURE_CUBE_MAP : c.multisampled ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    // An array's layer is addressed as its z (GL copies between a 2D texture and an array's layer).
    // 1D textures keep their own target (a 1D array's layer is its y: copyOrigin).
    const GLenum sourceActual = lineTargetOf(c.source), destinationActual = lineTargetOf(c.destination);
    const auto lineTarget = [](GLenum t) { return t == GL_TEXTURE_1D || t == GL_TEXTURE_1D_ARRAY; };
    const GLenum sourceTarget = lineTarget(sourceActual) ? sourceActual : c.sourceLayer >= 0 ? GL_TEXTURE_2D_ARRAY : target;
    const GLenum destinationTarget = lineTarget(destinationActual) ? destinationActual : c.destinationLayer >= 0 ? GL_TEXTURE_2D_ARRAY : target;
    GLint from[3], to[3];
    copyOrigin(sourceTarget, c.sourceX, c.sourceY, c.sourceLayer, from);
    copyOrigin(destinationTarget, c.destinationX, c.destinationY, c.destinationLayer, to);
    glCopyImageSubData(c.source, sourceTarget, c.sourceLevel, from[0], from[1], from[2], c.destination, destinationTarget, c.destinationLevel,
                       to[0], to[1], to[2], c.width, c.height, c.cube ? 6 : 1);
}

void GlBackend::presentFlipped(BackendObject framebuffer, int width, int height) {
    glBlitNamedFramebuffer(framebuffer, 0, 0, 0, width, height, 0, height, width, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

namespace {

// D3D11's rule for a float clear of an integer texture: each value is truncated toward zero and
// clamped to the channel's range (NaN to 0).
template <class Integer>
Integer clearValueOf(float v, int bits, bool isSigned) {
    if (!(v == v)) return 0;
    const double top = isSigned ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
    const double bottom = isSigned ? -std::ldexp(1.0, bits - 1) : 0.0;
    return Integer(std::clamp(std::trunc(double(v)), bottom, top));
}

}  // namespace

void GlBackend::clearTexture(BackendObject texture, int level, const float (&rgba)[4]) {
    GLint type = GL_NONE, bits = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_RED_TYPE, &type);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_RED_SIZE, &bits);
    if (type == GL_UNSIGNED_INT) {
        GLuint u[4];
        for (int i = 0; i < 4; ++i) u[i] = clearValueOf<GLuint>(rgba[i], bits, false);
        glClearTexImage(texture, level, GL_RGBA_INTEGER, GL_UNSIGNED_INT, u);
    } else if (type == GL_INT) {
        GLint n[4];
        for (int i = 0; i < 4; ++i) n[i] = clearValueOf<GLint>(rgba[i], bits, true);
        glClearTexImage(texture, level, GL_RGBA_INTEGER, GL_INT, n);
    } else {
        glClearTexImage(texture, level, GL_RGBA, GL_FLOAT, rgba);
    }
}

void GlBackend::clearDepthStencil(BackendObject renderbuffer, bool hasStencil, bool isTexture, bool depth, bool stencil, float depthValue,
                                  int stencilValue) {
    // A framebuffer of its own, so that neither the bound targets nor the viewport matter.
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    const GLenum attachment = hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (isTexture) glNamedFramebufferTexture(fbo, attachment, renderbuffer, 0);
    else glNamedFramebufferRenderbuffer(fbo, attachment, GL_RENDERBUFFER, renderbuffer);
    glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    // glClear* honour the write masks and the scissor.
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat clamped = std::clamp(depthValue, 0.0f, 1.0f);
    if (depth && stencil) glClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, clamped, stencilValue);
    else if (depth) glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &clamped);
    else glClearNamedFramebufferiv(fbo, GL_STENCIL, 0, &stencilValue);
    glDeleteFramebuffers(1, &fbo);
}

void GlBackend::clearFramebuffer(BackendObject framebuffer, const Rectangle& area, int colourTargets, bool colour,
                                 const Vector4& color, bool depth, bool stencil, float depthValue, int stencilValue) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.X, area.Y, area.Width, area.Height);
    if (colour) {
        const float c[4] = {color.X, color.Y, color.Z, color.W};
        for (int i = 0; i < colourTargets; ++i) {
            glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            // An integer target (SurfaceFormat R32UInt ...) takes integers: a float clear of it is undefined in GL.
            GLint type = GL_FLOAT, bits = 32;
            if (framebuffer != 0) {
                glGetNamedFramebufferAttachmentParameteriv(framebuffer, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
                glGetNamedFramebufferAttachmentParameteriv(framebuffer, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &bits);
            }
            if (type == GL_UNSIGNED_INT) {
                GLuint u[4];
                for (int k = 0; k < 4; ++k) u[k] = clearValueOf<GLuint>(c[k], bits, false);
                glClearNamedFramebufferuiv(framebuffer, GL_COLOR, GLint(i), u);
            } else if (type == GL_INT) {
                GLint n[4];
                for (int k = 0; k < 4; ++k) n[k] = clearValueOf<GLint>(c[k], bits, true);
                glClearNamedFramebufferiv(framebuffer, GL_COLOR, GLint(i), n);
            } else {
                glClearNamedFramebufferfv(framebuffer, GL_COLOR, GLint(i), c);
            }
        }
    }
    if (depth) glDepthMask(GL_TRUE);
    if (stencil) glStencilMask(0xff);
    if (depth && stencil) glClearNamedFramebufferfi(framebuffer, GL_DEPTH_STENCIL, 0, depthValue, stencilValue);
    else if (depth) glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &depthValue);
    else if (stencil) glClearNamedFramebufferiv(framebuffer, GL_STENCIL, 0, &stencilValue);
}

void GlBackend::invalidateFramebuffer(int colourTargets, bool depth, bool stencil) {
    std::vector<GLenum> attachments;
    for (int i = 0; i < colourTargets; ++i) attachments.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    if (depth && stencil) attachments.push_back(GL_DEPTH_STENCIL_ATTACHMENT);
    else if (depth) attachments.push_back(GL_DEPTH_ATTACHMENT);
    else if (stencil) attachments.push_back(GL_STENCIL_ATTACHMENT);
    if (!attachments.empty()) glInvalidateFramebuffer(GL_FRAMEBUFFER, GLsizei(attachments.size()), attachments.data());
}

void GlBackend::bindStorageImage(int unit, BackendObject texture, SurfaceFormat format, bool writes) {
    // A 1D array is bound layered: a shader's image1DArray indexes its layers.
    const GLboolean layered = lineTargetOf(texture) == GL_TEXTURE_1D_ARRAY ? GL_TRUE : GL_FALSE;
    glBindImageTexture(GLuint(unit), texture, 0, layered, 0, writes ? GL_READ_WRITE : GL_READ_ONLY,
                       detail::glFormat(format).internalFormat);
}

}  // namespace fxport
