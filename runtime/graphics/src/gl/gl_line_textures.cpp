// 1D textures in GL (gl_backend.h): the backend's transfers address a layer as `face`, which GL
// takes as z for 2D arrays and cubes but as y for a 1D array (its layers are rows), and a plain 1D
// texture only through the 1D entry points. These helpers take the 1D cases; the callers in
// gl_work.cpp keep the others.
#include "gl/gl_backend.h"
#include "gl/gl_formats.h"

namespace fxport {

bool writeLine(GLenum target, GLuint texture, SurfaceFormat format, int face, int level, const Rectangle& area, const void* data) {
    const detail::GlTextureFormat& f = detail::glFormat(format);
    if (target == GL_TEXTURE_1D)
        glTextureSubImage1D(texture, level, area.X, area.Width, f.format, f.type, data);
    else if (target == GL_TEXTURE_1D_ARRAY)
        glTextureSubImage2D(texture, level, area.X, face, area.Width, 1, f.format, f.type, data);
    else
        return false;
    return true;
}

bool readLine(GLenum target, GLuint texture, GLenum format, GLenum type, int face, int level, std::size_t bytes, void* out) {
    if (face < 0 || target != GL_TEXTURE_1D_ARRAY) return false;  // a plain 1D texture reads whole (glGetTextureImage)
    GLint width = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &width);
    glGetTextureSubImage(texture, level, 0, face, 0, width, 1, 1, format, type, GLsizei(bytes), out);
    return true;
}

void copyOrigin(GLenum target, int x, int y, int layer, GLint (&out)[3]) {
    const GLint l = layer < 0 ? 0 : layer;
    if (target == GL_TEXTURE_1D_ARRAY) {
        out[0] = x, out[1] = l, out[2] = 0;
    } else if (target == GL_TEXTURE_1D) {
        out[0] = x, out[1] = 0, out[2] = 0;
    } else {
        out[0] = x, out[1] = y, out[2] = l;
    }
}

}  // namespace fxport
