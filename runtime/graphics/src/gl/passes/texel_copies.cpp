// Texel-copy reductions (GlComputePasses::tryTexelCopies, issue 16): a SpriteBatch batch whose every
// sprite copies texels 1:1 into a target of the texture's format, under a Min or Max blend. The
// pixel shader is SpriteBatch's own (tex2D * colour) with a white colour, Point sampling lands on
// the texel under each pixel centre, so each fragment's output is that texel exactly, and Min/Max
// of exact values does not depend on the order the blender sees them in. One dispatch therefore
// gives the fragment stage's pixels bit for bit: per pixel, min (max) over the target and every
// sprite covering it. The rasteriser serialises blends to one pixel; a reduction of many sprites
// onto few pixels (lighting2d's occlusion map: 1920 one-row sprites onto a 1920x1 target) is the
// case where that costs most, and the one this is for.
#include <algorithm>
#include <cstdio>

#include "gl/passes/compute_pass.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture.h"
#include "gl/gl_formats.h"
#include "device/sampler_filter.h"

namespace fxport {

namespace detail {

namespace {
constexpr int kTileWidth = 8;  // pixels of a row per workgroup
constexpr int kSlices = 32;    // invocations per pixel, each over every kSlices-th sprite (a 1920-pixel row: 240 workgroups)
constexpr int kCopiesBinding = 0;
}  // namespace

std::string texelCopyShaderSource(const std::string& imageFormat, BlendOp color, BlendOp alpha, unsigned writeMask) {
    auto op = [](BlendOp o) { return o == BlendOp::Min ? std::string("min") : std::string("max"); };
    std::string s = "#version 450\n";
    s += "layout(local_size_x = " + std::to_string(kTileWidth) + ", local_size_y = " + std::to_string(kSlices) + ") in;\n";
    s += "layout(" + imageFormat + ", binding = 0) uniform restrict image2D fxport_target;\n";
    s += "layout(" + imageFormat + ", binding = 1) uniform restrict readonly image2D fxport_source;\n";
    // Per sprite: its clipped pixels (x0, y0, x1, y1), then the offset from a pixel to its texel.
    s += "layout(std430, binding = " + std::to_string(kCopiesBinding) + ") restrict readonly buffer Copies { ivec4 fxport_copies[]; };\n";
    s += "uniform ivec4 fxport_box;  // the pixels any sprite covers: x0, y0, x1, y1\n";
    s += "uniform int fxport_count;\n";
    s += "shared vec4 fxport_partial[" + std::to_string(kSlices) + "][" + std::to_string(kTileWidth) + "];\n";
    s += "shared bool fxport_hit[" + std::to_string(kSlices) + "][" + std::to_string(kTileWidth) + "];\n";
    s += "vec4 fxport_op(vec4 a, vec4 b) { return vec4(" + op(color) + "(a.rgb, b.rgb), " + op(alpha) + "(a.a, b.a)); }\n";
    s += "void main() {\n";
    s += "    const uint lx = gl_LocalInvocationID.x, slice = gl_LocalInvocationID.y;\n";
    s += "    const ivec2 p = ivec2(fxport_box.x + int(gl_WorkGroupID.x) * " + std::to_string(kTileWidth) +
         " + int(lx), fxport_box.y + int(gl_WorkGroupID.y));\n";
    s += "    const bool inside = p.x < fxport_box.z;\n";
    s += "    vec4 acc = vec4(0.0);\n";
    s += "    bool hit = false;\n";
    s += "    if (inside) {\n";
    s += "        for (int i = int(slice); i < fxport_count; i += " + std::to_string(kSlices) + ") {\n";
    s += "            const ivec4 r = fxport_copies[2 * i];\n";
    s += "            if (p.x >= r.x && p.y >= r.y && p.x < r.z && p.y < r.w) {\n";
    s += "                const vec4 t = imageLoad(fxport_source, p + fxport_copies[2 * i + 1].xy);\n";
    s += "                acc = hit ? fxport_op(acc, t) : t;\n";
    s += "                hit = true;\n";
    s += "            }\n";
    s += "        }\n";
    s += "    }\n";
    s += "    fxport_partial[slice][lx] = acc;\n";
    s += "    fxport_hit[slice][lx] = hit;\n";
    s += "    barrier();\n";
    s += "    if (slice != 0u || !inside) return;\n";
    s += "    for (int k = 1; k < " + std::to_string(kSlices) + "; ++k) {\n";
    s += "        if (!fxport_hit[k][lx]) continue;\n";
    s += "        acc = hit ? fxport_op(acc, fxport_partial[k][lx]) : fxport_partial[k][lx];\n";
    s += "        hit = true;\n";
    s += "    }\n";
    s += "    if (!hit) return;  // no sprite covers the pixel: the target keeps it\n";
    s += "    const vec4 before = imageLoad(fxport_target, p);\n";
    s += "    vec4 after = fxport_op(before, acc);\n";
    static const char* kChannel[4] = {"r", "g", "b", "a"};
    for (int c = 0; c < 4; ++c)
        if (!(writeMask & (1u << c))) s += std::string("    after.") + kChannel[c] + " = before." + kChannel[c] + ";\n";
    s += "    imageStore(fxport_target, p, after);\n";
    s += "}\n";
    return s;
}

}  // namespace detail

bool GlComputePasses::tryTexelCopies(const Texture2D& texture, const std::vector<detail::TexelCopy>& copies) {
    const GraphicsDevice& dev = device;
    const std::vector<RenderTargetBinding>& boundTargets = prepared::targets(dev);
    const PassEmulation& emulation = prepared::emulation(dev);
    const BlendState& blend = dev.BlendState;
    auto reduction = [](BlendFunction f, detail::BlendOp& op) {
        op = f == BlendFunction::Min ? detail::BlendOp::Min : detail::BlendOp::Max;
        return f == BlendFunction::Min || f == BlendFunction::Max;  // GL and D3D ignore the factors
    };
    detail::BlendOp color{}, alpha{};
    if (!reduction(blend.ColorBlendFunction, color) || !reduction(blend.AlphaBlendFunction, alpha) || copies.empty())
        return false;  // not a reduction: SpriteBatch draws it (and the draw may still be a compute pass)

    const Texture* target = boundTargets.empty() ? prepared::backBuffer(dev) : boundTargets[0].RenderTarget;
    if (target->kind() != Texture::Kind::Texture2D) return fallBack("texel copies: a cube map face target");
    const auto& target2D = *static_cast<const Texture2D*>(target);
    if (target == &texture) return fallBack("texel copies: the sprite texture is the target");
    const SurfaceFormat format = target2D.Format();
    if (texture.Format() != format) return fallBack("texel copies: the texture's format is not the target's");
    const char* image = detail::imageFormatOf(format);
    // Alpha8 is stored as red with a swizzle: what a sample returns is not what an image load does.
    if (!image || format == SurfaceFormat::Alpha8) return fallBack(std::string("texel copies: target format ") + surfaceFormatName(format));
    const unsigned mask = unsigned(blend.ColorWriteChannels) & 15u;
    if (mask == 0 || blend.MultiSampleMask != -1) return fallBack("texel copies: write mask or multisample mask");
    const DepthStencilState& depth = dev.DepthStencilState;
    // Without a depth buffer GL passes every depth and stencil test (the first target's format
    // says whether it has one, however its storage is made).
    const DepthFormat depthFormat = boundTargets.empty() ? dev.PresentationParameters().DepthStencilFormat
                                                      : static_cast<const RenderTarget2D*>(target)->DepthStencilFormat();
    if (depthFormat != DepthFormat::None && (depth.DepthBufferEnable || depth.StencilEnable))
        return fallBack("texel copies: depth or stencil test");
    if (emulation.alphaTest || emulation.fixedFunction || emulation.srgbWrite)
        return fallBack("texel copies: alpha test, D3D9 fixed-function emulation or sRGB write");
    const RasterizerState& raster = dev.RasterizerState;
    // SpriteBatch's sprites are clockwise on screen: CullClockwiseFace culls them all.
    if (raster.FillMode != FillMode::Solid || raster.CullMode == CullMode::CullClockwiseFace)
        return fallBack("texel copies: wireframe or culled");
    const SamplerState& sampler = dev.SamplerStates[0];
    const FilterParts filter = splitFilter(sampler.Filter);
    if (filter.anisotropic || filter.minLinear || filter.magLinear) return fallBack("texel copies: not Point sampling");
    if (sampler.UseMipMaps && texture.LevelCount() > 1) return fallBack("texel copies: mipmapped texture");

    // The pixels each sprite writes: its rectangle in the viewport, within the viewport (GL clips
    // to it), the target and the scissor. The offset takes a pixel to its texel.
    const Viewport& viewport = dev.Viewport;
    const auto [cx0, cy0, cx1, cy1] = detail::drawablePixels(dev, target2D.Width(), target2D.Height());
    std::vector<GLint> words;
    words.reserve(copies.size() * 8);
    int bx0 = cx1, by0 = cy1, bx1 = cx0, by1 = cy0;
    std::int64_t covered = 0;
    for (const detail::TexelCopy& c : copies) {
        const int x0 = std::max(viewport.X + c.x0, cx0), y0 = std::max(viewport.Y + c.y0, cy0);
        const int x1 = std::min(viewport.X + c.x1, cx1), y1 = std::min(viewport.Y + c.y1, cy1);
        if (x1 <= x0 || y1 <= y0) continue;
        words.insert(words.end(), {x0, y0, x1, y1, c.sourceX - (viewport.X + c.x0), c.sourceY - (viewport.Y + c.y0), 0, 0});
        bx0 = std::min(bx0, x0), by0 = std::min(by0, y0), bx1 = std::max(bx1, x1), by1 = std::max(by1, y1);
        covered += std::int64_t(x1 - x0) * (y1 - y0);
    }
    const std::int64_t count = std::int64_t(words.size() / 8);
    if (count == 0) return false;  // nothing to write: drawn as usual, which draws nothing either
    // Every invocation tests every sprite: worth it when the sprites overlap (a reduction), not
    // for sprites scattered over the target.
    if (covered * 4 < count * std::int64_t(bx1 - bx0) * (by1 - by0)) return fallBack("texel copies: sprites overlap too little");

    const std::array<int, 4> key{int(format), int(color), int(alpha), int(mask)};
    auto found = reductionPrograms.find(key);
    if (found == reductionPrograms.end()) {
        Reduction made;
        made.program = detail::linkProgram(GL_COMPUTE_SHADER, detail::texelCopyShaderSource(image, color, alpha, mask), {},
                                           printOutcomes, made.failure);
        if (made.program) {
            made.box = glGetUniformLocation(made.program, "fxport_box");
            made.count = glGetUniformLocation(made.program, "fxport_count");
        } else {
            made.failure = "texel copies: compute shader " + made.failure;
        }
        found = reductionPrograms.emplace(key, made).first;
    }
    if (!found->second.program) return fallBack(found->second.failure);
    const Reduction& program = found->second;

    // What a draw does first: the pending clear the blend reads, the state shadow, the
    // bookkeeping of written targets.
    prepared::flush(device, "SpriteBatch.End");
    ++statistics.issued;
    ++statistics.dispatched;
    if (!copiesBuffer) glCreateBuffers(1, &copiesBuffer);
    glNamedBufferData(copiesBuffer, GLsizeiptr(words.size() * sizeof(GLint)), words.data(), GL_STREAM_DRAW);
    glUseProgram(program.program);
    const GLenum internalFormat = detail::glFormat(format).internalFormat;
    glBindImageTexture(0, target2D.backendObject(), 0, GL_FALSE, 0, GL_READ_WRITE, internalFormat);
    glBindImageTexture(1, texture.backendObject(), 0, GL_FALSE, 0, GL_READ_ONLY, internalFormat);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kCopiesBinding, copiesBuffer);
    const GLint box[4] = {bx0, by0, bx1, by1};
    glProgramUniform4iv(program.program, program.box, 1, box);
    glProgramUniform1i(program.program, program.count, GLint(count));
    glDispatchCompute(GLuint((bx1 - bx0 + detail::kTileWidth - 1) / detail::kTileWidth), GLuint(by1 - by0), 1);
    // Later draws, texture fetches, read-backs and dispatches see the stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    glUseProgram(0);  // the device's program pipeline is in use again
    if (printOutcomes)
        std::fprintf(stderr, "compute pass: %lld texel copies reduced over %dx%d pixels\n", static_cast<long long>(count),
                     bx1 - bx0, by1 - by0);
    return true;
}

}  // namespace fxport
