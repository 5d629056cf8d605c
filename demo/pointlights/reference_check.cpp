#include "pointlights/reference_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "pointlights/game1.h"
#include "reference/ref_image.h"
#include "reference/ref_math.h"

namespace DeferredLighting {

namespace {

// ---- double-precision HLSL math: tests/render's (ref_math.h) ------------------------------------

namespace rt = fxport::reference;
using D3 = rt::V3;
using D4 = rt::V4;
using rt::dot;
using rt::length;
using rt::M4;
using rt::mul;
using rt::mul3;
using rt::normalize;
using rt::reflect;
using rt::saturate;
using rt::operator+;
using rt::operator-;
using rt::operator*;
D3 d3(Vector3 v) { return {v.X, v.Y, v.Z}; }
// An XNA matrix (as the GPU receives it, in float) in double; points are row vectors (mul(v, M)).
M4 toM4(const Matrix& a) {
    const float v[16] = {a.M11, a.M12, a.M13, a.M14, a.M21, a.M22, a.M23, a.M24,
                         a.M31, a.M32, a.M33, a.M34, a.M41, a.M42, a.M43, a.M44};
    M4 r;
    for (int i = 0; i < 16; ++i) r.m[i / 4][i % 4] = v[i];
    return r;
}

// The runtime's D3D9 pixel-centre emulation: pixel (x, y) samples D3D9 screen position
// (x + kBiasXX, y + kBiasYY): exact across the columns, 1/256 pixel down the rows.
const double kBiasX = 0;
const double kBiasY = 1.0 / 256.0;
// Sample points D3D9 leaves open around that: rasterisers snap vertices to 1/256 pixel (varyings
// and edges move by up to 1/512), so the reference is the hull over these offsets (pixels).
const double kEdgeSlack = 1.0 / 256.0;
const double kSnap = 1.0 / 256.0;
const double kOffsets[5][2] = {{0, 0}, {-kSnap, 0}, {kSnap, 0}, {0, -kSnap}, {0, kSnap}};
// An 8-bit target stores one of the two integers closest to v * 255 (roundRange); the GPU's float32
// shader math may move v by this many LSB.
const double kRoundSlack = 0.05;
// How far the GPU's level of detail may be from ours (log2 texels per pixel).
const double kLodSlack = 0.5;
// Texture filtering in 8-bit fixed point: bilinear and mip weights of 8 bits and rounded results.
const double kFilterSlack = 1.0;

// ---- per-pixel intervals and their comparison: reference/ref_image.h ---------------------------

using fxport::reference::GpuImage;
using fxport::reference::RefImage;

GpuImage fromColors(const std::vector<Color>& data, int W, int H) {
    static_assert(sizeof(Color) == 4, "Color is R, G, B, A bytes");
    return GpuImage::fromRgba8(reinterpret_cast<const unsigned char*>(data.data()), W, H);
}

bool compare(const char* name, const char* bound, const RefImage& ref, const GpuImage& gpu, double changeThreshold,
             const std::vector<char>* mask = nullptr) {
    return fxport::reference::checkImage(name, bound, ref, gpu, changeThreshold, mask);
}

// 8-bit conversion of a value known to lie in [lo, hi] LSB (before conversion). Direct3D 10+'s
// data conversion rules let FLOAT -> UNORM land on any integer within 0.6 ULP of the value (GL 4.5,
// 2.3.5.2, only "prefers" rounding to nearest): llvmpipe rounds to nearest, an H100's blender put
// the additive light map 1 LSB under it. Integers within 0.6 LSB (plus the float-math slack) pass.
void roundRange(double& lo, double& hi) {
    lo = std::ceil(lo - 0.6 - kRoundSlack);
    hi = std::floor(hi + 0.6 + kRoundSlack);
}

// ---- G-buffer: RenderGBuffer.fx over the Scene, rasterised on the CPU ------------------------

struct TextureLevels {
    std::vector<std::vector<Color>> level;
    std::vector<int> w, h;
};

struct ClipVertex {
    D4 clip;
    D3 normal;  // mul(Normal, World), not normalised (the pixel shader normalises)
    double u, v;
};
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
    auto l = [t](double p, double q) { return p + (q - p) * t; };
    return {{l(a.clip.x, b.clip.x), l(a.clip.y, b.clip.y), l(a.clip.z, b.clip.z), l(a.clip.w, b.clip.w)},
            {l(a.normal.x, b.normal.x), l(a.normal.y, b.normal.y), l(a.normal.z, b.normal.z)},
            l(a.u, b.u),
            l(a.v, b.v)};
}

// A triangle after clipping, in D3D9 screen space (x right, y down).
struct ScreenTri {
    ClipVertex v[3];
    double sx[3], sy[3], zw[3], invW[3], area;
    const TextureLevels* texture;
};

// D3D clips to 0 <= z <= w (x and y need no clipping: the rasteriser's guard band does it).
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly) {
    for (int plane = 0; plane < 2; ++plane) {
        auto dist = [plane](const ClipVertex& p) { return plane == 0 ? p.clip.z : p.clip.w - p.clip.z; };
        std::vector<ClipVertex> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const ClipVertex& a = poly[i];
            const ClipVertex& b = poly[(i + 1) % poly.size()];
            const double da = dist(a), db = dist(b);
            if (da >= 0) out.push_back(a);
            if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
        }
        poly = std::move(out);
        if (poly.empty()) break;
    }
    return poly;
}

// Barycentrics (screen-space, linear) of point (px, py) in t.
std::array<double, 3> barycentrics(const ScreenTri& t, double px, double py) {
    auto edge = [&](int a, int b) { return (t.sx[b] - t.sx[a]) * (py - t.sy[a]) - (t.sy[b] - t.sy[a]) * (px - t.sx[a]); };
    return {edge(1, 2) / t.area, edge(2, 0) / t.area, edge(0, 1) / t.area};
}

struct GSample {
    double color[4], normal[4], depth;
};

// One sample point of a pixel covered by t (or by nothing: the clear values).
GSample shadeGBuffer(const ScreenTri* t, double px, double py, std::array<double, 3>* colorLo,
                     std::array<double, 3>* colorHi) {
    GSample s{};
    if (!t) {  // ClearGBuffer.fx
        for (int c = 0; c < 3; ++c) s.normal[c] = 0.5 * 255;
        s.depth = 1;
        for (int c = 0; c < 3; ++c) (*colorLo)[std::size_t(c)] = std::min((*colorLo)[std::size_t(c)], 0.0),
                                    (*colorHi)[std::size_t(c)] = std::max((*colorHi)[std::size_t(c)], 0.0);
        return s;
    }
    // perspective-correct interpolation of the varyings at (qx, qy)
    auto interp = [&](double qx, double qy, D3& normal, double& u, double& v) {
        const std::array<double, 3> b = barycentrics(*t, qx, qy);
        double wsum = 0, p[3];
        for (int i = 0; i < 3; ++i) p[i] = b[std::size_t(i)] * t->invW[i], wsum += p[i];
        normal = {0, 0, 0}, u = v = 0;
        for (int i = 0; i < 3; ++i) {
            normal = normal + t->v[i].normal * (p[i] / wsum);
            u += t->v[i].u * p[i] / wsum, v += t->v[i].v * p[i] / wsum;
        }
        return b;
    };
    D3 n;
    double u, v;
    const std::array<double, 3> b = interp(px, py, n, u, v);
    s.depth = b[0] * t->zw[0] + b[1] * t->zw[1] + b[2] * t->zw[2];  // Depth.x / Depth.y = z/w
    n = normalize(n);
    s.normal[0] = 0.5 * (n.x + 1) * 255, s.normal[1] = 0.5 * (n.y + 1) * 255, s.normal[2] = 0.5 * (n.z + 1) * 255;
    s.normal[3] = 0.5 * 255;  // specularPower
    s.color[3] = 0.8 * 255;   // specularIntensity
    // tex2D(diffuseSampler): trilinear, Wrap. The GPU's level of detail comes from its own
    // derivative estimate (per 2x2 quad, often max(|du|, |dv|) instead of the length): the colour is
    // the hull of the trilinear values for every LOD within kLodSlack of ours (piecewise linear in
    // the LOD: its ends and the whole levels between).
    D3 nx, ny;
    double ux, vx, uy, vy;
    interp(px + 1, py, nx, ux, vx);
    interp(px, py + 1, ny, uy, vy);
    const TextureLevels& tex = *t->texture;
    const double W0 = tex.w[0], H0 = tex.h[0];
    const double rho = std::max(std::hypot((ux - u) * W0, (vx - v) * H0), std::hypot((uy - u) * W0, (vy - v) * H0));
    const double lambda = std::log2(std::max(rho, 1e-30));
    const int last = int(tex.level.size()) - 1;
    auto bilinear = [&](int l, double out[3]) {
        const int w = tex.w[std::size_t(l)], h = tex.h[std::size_t(l)];
        const double tx = u * w - 0.5, ty = v * h - 0.5;
        const int ix = int(std::floor(tx)), iy = int(std::floor(ty));
        const double fx = tx - ix, fy = ty - iy;
        out[0] = out[1] = out[2] = 0;
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const int X = ((ix + dx) % w + w) % w, Y = ((iy + dy) % h + h) % h;
                const Color& c = tex.level[std::size_t(l)][std::size_t(Y) * std::size_t(w) + std::size_t(X)];
                const double weight = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
                out[0] += weight * c.R, out[1] += weight * c.G, out[2] += weight * c.B;
            }
    };
    std::vector<double> lods = {lambda - kLodSlack, lambda + kLodSlack};
    for (double l = std::ceil(lambda - kLodSlack); l < lambda + kLodSlack; l += 1) lods.push_back(l);
    for (double lod : lods) {
        lod = std::clamp(lod, 0.0, double(last));
        const int l = int(std::floor(lod));
        const double f = lod - l;
        double a[3], b[3];
        bilinear(l, a);
        if (l < last) bilinear(l + 1, b);
        else b[0] = a[0], b[1] = a[1], b[2] = a[2];
        for (int k = 0; k < 3; ++k) {
            const double value = a[k] * (1 - f) + b[k] * f;
            (*colorLo)[std::size_t(k)] = std::min((*colorLo)[std::size_t(k)], value);
            (*colorHi)[std::size_t(k)] = std::max((*colorHi)[std::size_t(k)], value);
        }
    }
    return s;
}

bool checkGBuffer(Game1& game) {
    DeferredRenderer& r = game.getRenderer();
    Camera& camera = game.getCamera();
    const int W = r.getColorRT().Width(), H = r.getColorRT().Height();
    const M4 viewProjection = toM4(camera.View) * toM4(camera.Projection);

    // The triangles Scene::DrawScene draws, in its order (Scene.gltf, loaded once by the content manager).
    Model* model = game.Content.Load<Model>("Scene");
    std::vector<Matrix> transforms(std::size_t(model->Bones.Count()));
    model->CopyAbsoluteBoneTransformsTo(transforms);
    std::map<const Texture2D*, TextureLevels> textures;
    std::vector<ScreenTri> tris;
    for (ModelMesh& mesh : model->Meshes) {
        const M4 world = toM4(transforms[std::size_t(mesh.ParentBone->Index)]);
        for (ModelMeshPart& part : mesh.MeshParts) {
            const Texture2D* texture = part.Effect->Parameters["Texture"].GetValueTexture2D();
            TextureLevels& levels = textures[texture];
            if (levels.level.empty()) {
                for (int l = 0; l < texture->LevelCount(); ++l) {
                    const int w = std::max(1, texture->Width() >> l), h = std::max(1, texture->Height() >> l);
                    levels.level.emplace_back(std::size_t(w) * std::size_t(h));
                    texture->getData(l, levels.level.back().data(), levels.level.back().size() * sizeof(Color));
                    levels.w.push_back(w), levels.h.push_back(h);
                }
            }
            std::vector<ModelVertex> vertices(std::size_t(part.VertexBuffer->VertexCount()));
            part.VertexBuffer->GetData(vertices.data(), vertices.size());
            const std::vector<std::uint32_t> indices = part.IndexBuffer->GetIndices();
            for (int p = 0; p < part.PrimitiveCount; ++p) {
                std::vector<ClipVertex> poly;
                for (int k = 0; k < 3; ++k) {
                    const ModelVertex& mv =
                        vertices[std::size_t(part.VertexOffset + int(indices[std::size_t(part.StartIndex + 3 * p + k)]))];
                    const D4 worldPos = mul(D4{mv.Position.X, mv.Position.Y, mv.Position.Z, 1}, world);
                    poly.push_back({mul(worldPos, viewProjection), mul3(d3(mv.Normal), world),
                                    double(mv.TextureCoordinate.X), double(mv.TextureCoordinate.Y)});
                }
                poly = clipPolygon(poly);
                for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
                    ScreenTri t{};
                    const ClipVertex* src[3] = {&poly[0], &poly[k], &poly[k + 1]};
                    for (int i = 0; i < 3; ++i) {
                        t.v[i] = *src[i];
                        const D4& c = src[i]->clip;
                        t.sx[i] = (c.x / c.w + 1) * 0.5 * W, t.sy[i] = (1 - c.y / c.w) * 0.5 * H;
                        t.zw[i] = c.z / c.w, t.invW[i] = 1 / c.w;
                    }
                    t.area = (t.sx[1] - t.sx[0]) * (t.sy[2] - t.sy[0]) - (t.sy[1] - t.sy[0]) * (t.sx[2] - t.sx[0]);
                    // CullCounterClockwise: keep what is clockwise as seen (positive area with y down).
                    if (!(t.area > 0)) continue;
                    t.texture = &levels;
                    tris.push_back(t);
                }
            }
        }
    }

    // Which triangles may be what a pixel shows. Rasterisers snap vertices to 1/256 pixel, which moves
    // an edge by up to kEdgeSlack: a triangle covers the sample point for sure when the point is that
    // far inside all its edges, and may cover it when it is no further outside. Pass 1: the depth
    // test (LessEqual) over sure coverage; pass 2: every triangle that may cover the point and is not
    // behind the nearest sure one is a candidate. No sure triangle: the clear values are one too.
    const std::size_t N = std::size_t(W) * std::size_t(H);
    auto pixelsOf = [&](const ScreenTri& t, auto&& visit) {
        const int x0 = std::max(0, int(std::floor(std::min({t.sx[0], t.sx[1], t.sx[2]}))) - 1);
        const int x1 = std::min(W - 1, int(std::ceil(std::max({t.sx[0], t.sx[1], t.sx[2]}))) + 1);
        const int y0 = std::max(0, int(std::floor(std::min({t.sy[0], t.sy[1], t.sy[2]}))) - 1);
        const int y1 = std::min(H - 1, int(std::ceil(std::max({t.sy[0], t.sy[1], t.sy[2]}))) + 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + kBiasX, py = y + kBiasY;
                double inside = 1e300;  // the smallest distance inside the three edges (pixels)
                for (int e = 0; e < 3; ++e) {
                    const int a = (e + 1) % 3, b = (e + 2) % 3;
                    const double ex = t.sx[b] - t.sx[a], ey = t.sy[b] - t.sy[a];
                    inside = std::min(inside, (ex * (py - t.sy[a]) - ey * (px - t.sx[a])) / std::hypot(ex, ey));
                }
                const std::array<double, 3> bc = barycentrics(t, px, py);
                const double z = bc[0] * t.zw[0] + bc[1] * t.zw[1] + bc[2] * t.zw[2];
                visit(x, y, inside, z);
            }
    };
    // Surfaces this close in z/w may win the LessEqual test either way: the depth buffer stores z in
    // steps of 2^-24 (D24) and the GPU interpolates it in float32 (an ulp is 6e-8 near 1). Four steps
    // (an H100 showed a crate's side instead of the floor it stands on at 800x600 with 1e-7).
    const double kDepthTie = 4.0 / 16777216.0;
    std::vector<double> zSure(N, 2.0);  // 2: no sure triangle
    for (const ScreenTri& t : tris)
        pixelsOf(t, [&](int x, int y, double inside, double z) {
            const std::size_t k = std::size_t(y) * std::size_t(W) + std::size_t(x);
            if (inside >= kEdgeSlack && z >= 0 && z <= 1) zSure[k] = std::min(zSure[k], z);
        });
    struct Hull {
        std::array<double, 3> colorLo{1e9, 1e9, 1e9}, colorHi{-1e9, -1e9, -1e9};
        double nLo[4] = {1e9, 1e9, 1e9, 1e9}, nHi[4] = {-1e9, -1e9, -1e9, -1e9};
        double aLo = 1e9, aHi = -1e9, dLo = 1e9, dHi = -1e9;
        int candidates = 0;
        void add(const ScreenTri* t, int x, int y) {
            ++candidates;
            for (const auto& o : kOffsets) {  // varyings within the snapping distance
                const GSample g = shadeGBuffer(t, x + kBiasX + o[0], y + kBiasY + o[1], &colorLo, &colorHi);
                for (int c = 0; c < 4; ++c) nLo[c] = std::min(nLo[c], g.normal[c]), nHi[c] = std::max(nHi[c], g.normal[c]);
                aLo = std::min(aLo, g.color[3]), aHi = std::max(aHi, g.color[3]);
                dLo = std::min(dLo, g.depth), dHi = std::max(dHi, g.depth);
            }
        }
    };
    std::vector<Hull> hulls(N);
    for (const ScreenTri& t : tris)
        pixelsOf(t, [&](int x, int y, double inside, double z) {
            const std::size_t k = std::size_t(y) * std::size_t(W) + std::size_t(x);
            if (inside >= -kEdgeSlack && z >= 0 && z <= 1 && z <= zSure[k] + kDepthTie) hulls[k].add(&t, x, y);
        });
    long ambiguous = 0;
    RefImage refColor(W, H, 4), refNormal(W, H, 4), refDepth(W, H, 1);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(W) + std::size_t(x);
            Hull& h = hulls[k];
            if (zSure[k] > 1) h.add(nullptr, x, y);
            ambiguous += h.candidates > 1;
            for (int c = 0; c < 3; ++c) {
                double lo = h.colorLo[std::size_t(c)] - kFilterSlack, hi = h.colorHi[std::size_t(c)] + kFilterSlack;
                roundRange(lo, hi);
                refColor.set(x, y, c, lo, hi);
            }
            roundRange(h.aLo, h.aHi);
            refColor.set(x, y, 3, h.aLo, h.aHi);
            for (int c = 0; c < 4; ++c) {
                roundRange(h.nLo[c], h.nHi[c]);
                refNormal.set(x, y, c, h.nLo[c], h.nHi[c]);
            }
            // z/w in float32 on the GPU: the clip-space transform and the interpolation, a few ulps.
            refDepth.set(x, y, 0, h.dLo - 1e-6, h.dHi + 1e-6);
        }
    const GpuImage gpuColor = fromColors(r.getColorRT().GetData<Color>(), W, H);
    const GpuImage gpuNormal = fromColors(r.getNormalRT().GetData<Color>(), W, H);
    GpuImage gpuDepth{W, H, 1, {}};
    for (float d : r.getDepthRT().GetData<float>()) gpuDepth.values.push_back(double(d));
    std::printf("CPU reference of the G-buffer (RenderGBuffer.fx, %zu triangles after culling and clipping, %zu textures; "
                "%ld pixels with more than one candidate surface):\n",
                tris.size(), textures.size(), ambiguous);
    bool pass = compare("colorRT (texture, spec. intensity)", "trilinear at every LOD within 0.5 of the pixel's, +-1 LSB "
                        "(8-bit filter weights), rounding; hull over sample points +-1/256 px", refColor, gpuColor, 1.0);
    pass &= compare("normalRT (normal, spec. power)", "0.5 LSB rounding of 0.5*(normalize(N)+1); hull over sample points",
                    refNormal, gpuNormal, 1.0);
    pass &= compare("depthRT (z/w)", "1e-6 + hull over sample points", refDepth, gpuDepth, 1e-5);
    return pass;
}

// ---- light map: DirectionalLight.fx + PointLight.fx (+ SpotLight.fx) from the GPU's G-buffer ----

// The inscribed radius of a convex light volume centred at the origin, relative to its vertices'
// radius: the smallest distance of a face plane from the centre. Points of the true sphere beyond it
// may lie outside the drawn volume (the GPU leaves them unlit).
double inscribedRatio(Model& model) {
    double vertexRadius = 0, minPlane = 1e300;
    for (ModelMesh& mesh : model.Meshes)
        for (ModelMeshPart& part : mesh.MeshParts) {
            std::vector<ModelVertex> vertices(std::size_t(part.VertexBuffer->VertexCount()));
            part.VertexBuffer->GetData(vertices.data(), vertices.size());
            const std::vector<std::uint32_t> indices = part.IndexBuffer->GetIndices();
            for (const ModelVertex& v : vertices) vertexRadius = std::max(vertexRadius, length(d3(v.Position)));
            for (int p = 0; p < part.PrimitiveCount; ++p) {
                D3 q[3];
                for (int k = 0; k < 3; ++k)
                    q[k] = d3(vertices[std::size_t(part.VertexOffset + int(indices[std::size_t(part.StartIndex + 3 * p + k)]))].Position);
                const D3 e1 = q[1] - q[0], e2 = q[2] - q[0];
                D3 n = {e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
                if (length(n) == 0) continue;  // degenerate (pole) triangle
                minPlane = std::min(minPlane, std::fabs(dot(normalize(n), q[0])));
            }
        }
    return minPlane / vertexRadius;
}

struct SpotParams {
    D3 position, direction, color;
    double radius, intensity, angleCosine, decay;
};

// One light's contribution to one pixel, per channel, as a rounded 8-bit interval.
struct Contribution {
    double lo[4], hi[4];
};

// The inputs of a light pass at pixel (x, y): the G-buffer at texel (x-1, y-1) (texCoord - halfPixel).
struct PixelInputs {
    D3 normal;
    double specularPower, specIntLo, specIntHi, depth;
};

// A LINEAR sample of an 8-bit target at texCoord - halfPixel of pixel (x, y): texel (x-1, y-1) with
// weight 255/256 per axis and its right/lower neighbours with 1/256 (clamped); the interval spans the
// unfiltered texel and the filtered value, +-1 LSB where the texels differ (8-bit filters round after
// the horizontal lerps and again after the vertical one: seen on llvmpipe). Channel c, LSB.
void linearSample(const std::vector<Color>& img, int W, int H, int x, int y, int c, double& lo, double& hi) {
    fxport::reference::linearSample8(W, H, x - 1, y - 1, false, [&](int i, int j) {
        const Color& p = img[std::size_t(j) * std::size_t(W) + std::size_t(i)];
        const double v[4] = {double(p.R), double(p.G), double(p.B), double(p.A)};
        return v[c];
    }, lo, hi);
}

// pow(saturate(d), p) with p = 0 at d = 0: HLSL/GLSL leave pow(0, 0) open.
void specularPow(double d, double p, double& lo, double& hi) {
    const double s = saturate(d);
    if (p == 0 && s == 0) lo = 0, hi = 1;
    else lo = hi = std::pow(s, p);
}

bool checkLightMapAndCombine(Game1& game, bool spot, double time) {
    DeferredRenderer& r = game.getRenderer();
    Camera& camera = game.getCamera();
    const int W = r.getColorRT().Width(), H = r.getColorRT().Height();
    const std::vector<Color> color = r.getColorRT().GetData<Color>();
    const std::vector<Color> normal = r.getNormalRT().GetData<Color>();
    const std::vector<float> depth = r.getDepthRT().GetData<float>();
    const std::vector<Color> light = r.getLightRT().GetData<Color>();
    const M4 ivp = toM4(Matrix::Invert(camera.View * camera.Projection));  // as the effects get it
    const D3 cam = d3(camera.Position);
    auto toWorld = [&](double nx, double ny, double nz) {
        const D4 p = mul(D4{nx, ny, nz, 1}, ivp);
        return D3{p.x / p.w, p.y / p.w, p.z / p.w};
    };
    const double sphereRatio = inscribedRatio(*game.Content.Load<Model>("PointLightGeometry"));

    SpotParams sp{};
    if (spot) {  // DeferredRenderer::DrawLights' spot light at `time`, with the host's float math
        const Vector3 dir = Vector3::Normalize(Vector3(0.6f * float(std::sin(time)), -1.0f, 0.6f * float(std::cos(time))));
        sp = {{0, 7.5, 0}, d3(dir), {1, 1, 1}, 14.0, 3.0, double(std::cos(MathHelper::ToRadians(25.0f))), 4.0};
    }

    RefImage refLight(W, H, 4);
    std::vector<char> directionalOnly(std::size_t(W) * std::size_t(H), 0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int tx = std::max(0, x - 1), ty = std::max(0, y - 1);
            const std::size_t t = std::size_t(ty) * std::size_t(W) + std::size_t(tx);
            PixelInputs in;
            in.normal = {2.0 * normal[t].R / 255 - 1, 2.0 * normal[t].G / 255 - 1, 2.0 * normal[t].B / 255 - 1};
            in.specularPower = normal[t].A / 255.0 * 255;
            linearSample(color, W, H, x, y, 3, in.specIntLo, in.specIntHi);
            in.specIntLo /= 255, in.specIntHi /= 255;
            in.depth = depth[t];

            double sumLo[4] = {0, 0, 0, 0}, sumHi[4] = {0, 0, 0, 0};
            bool othersReach = false;
            // Adds a light's value in [lo, hi] (before saturate and rounding) per channel.
            auto add = [&](const double lo[4], const double hi[4], bool mayBeUncovered) {
                for (int c = 0; c < 4; ++c) {
                    double l = saturate(lo[c]) * 255, h = saturate(hi[c]) * 255;
                    roundRange(l, h);
                    if (mayBeUncovered) l = 0;
                    sumLo[c] += std::max(l, 0.0), sumHi[c] += h;
                }
            };
            // Directional light: position from the quad's texCoord (exact: the quad's corners are on
            // the snapping grid).
            {
                const double u = (x + kBiasX - 0.5) / W, v = (y + kBiasY - 0.5) / H;
                const D3 position = toWorld(u * 2 - 1, -(v * 2 - 1), in.depth);
                const D3 lightVector = normalize(d3(r.drawnDirection)) * -1.0;
                const double NdL = std::max(0.0, dot(in.normal, lightVector));
                const D3 c = d3(r.drawnDirectionalColor);
                const D3 reflectionVector = normalize(reflect(lightVector, in.normal));
                const D3 directionToCamera = normalize(cam - position);
                double pLo, pHi;
                specularPow(dot(reflectionVector, directionToCamera), in.specularPower, pLo, pHi);
                const double lo[4] = {NdL * c.x, NdL * c.y, NdL * c.z, in.specIntLo * pLo};
                const double hi[4] = {NdL * c.x, NdL * c.y, NdL * c.z, in.specIntHi * pHi};
                add(lo, hi, false);
            }
            // Point and spot lights: position from ScreenPosition, interpolated over the volume's
            // triangles: the hull over the sample points.
            auto volumeLight = [&](D3 lightPosition, D3 lightColor, double radius, double intensity, const SpotParams* s) {
                double lo[4] = {1e9, 1e9, 1e9, 1e9}, hi[4] = {-1e9, -1e9, -1e9, -1e9};
                bool mayBeUncovered = false;
                for (const auto& o : kOffsets) {
                    const double px = x + kBiasX + o[0], py = y + kBiasY + o[1];
                    const D3 position = toWorld(2.0 * px / W - 1, 1 - 2.0 * py / H, in.depth);
                    D3 lightVector = lightPosition - position;
                    const double distance = length(lightVector);
                    const double attenuation = saturate(1.0 - distance / radius);
                    if (!s && distance >= sphereRatio * radius * (1 - 1e-6)) mayBeUncovered = true;
                    lightVector = normalize(lightVector);
                    double spotLo = 1, spotHi = 1;
                    if (s) {
                        const double SdL = dot(s->direction, lightVector * -1.0);
                        const double spotIntensity = std::pow(std::max(SdL, 0.0), s->decay);
                        if (std::fabs(SdL - s->angleCosine) < 1e-5) spotLo = 0, spotHi = spotIntensity;  // either branch
                        else spotLo = spotHi = SdL > s->angleCosine ? spotIntensity : 0.0;
                    }
                    const double NdL = std::max(0.0, dot(in.normal, lightVector));
                    const D3 reflectionVector = normalize(reflect(lightVector * -1.0, in.normal));
                    const D3 directionToCamera = normalize(cam - position);
                    double pLo, pHi;
                    specularPow(dot(reflectionVector, directionToCamera), in.specularPower, pLo, pHi);
                    const double aLo = attenuation * spotLo * intensity, aHi = attenuation * spotHi * intensity;
                    const double vLo[4] = {aLo * NdL * lightColor.x, aLo * NdL * lightColor.y, aLo * NdL * lightColor.z,
                                           aLo * in.specIntLo * pLo};
                    const double vHi[4] = {aHi * NdL * lightColor.x, aHi * NdL * lightColor.y, aHi * NdL * lightColor.z,
                                           aHi * in.specIntHi * pHi};
                    for (int c = 0; c < 4; ++c) lo[c] = std::min(lo[c], vLo[c]), hi[c] = std::max(hi[c], vHi[c]);
                }
                if (hi[0] > 0 || hi[1] > 0 || hi[2] > 0 || hi[3] > 0) othersReach = true;
                add(lo, hi, mayBeUncovered);
            };
            for (const auto& l : r.drawnPointLights)
                volumeLight(d3(l.position), d3(l.color), l.radius, l.intensity, nullptr);
            if (spot) volumeLight(sp.position, sp.color, sp.radius, sp.intensity, &sp);
            // One-One additive blending of 8-bit values, saturating.
            for (int c = 0; c < 4; ++c) refLight.set(x, y, c, std::min(sumLo[c], 255.0), std::min(sumHi[c], 255.0));
            directionalOnly[std::size_t(y) * std::size_t(W) + std::size_t(x)] = !othersReach;
        }
    const GpuImage gpuLight = fromColors(light, W, H);
    std::printf("CPU reference of lightRT (DirectionalLight.fx + %zu x PointLight.fx%s, %d of them culled by the "
                "renderer but not by the reference, %d drawn from inside; sphere's inscribed radius %.4f of its "
                "vertices'):\n",
                r.drawnPointLights.size(), spot ? " + SpotLight.fx" : "", r.culledLights,
                r.insideLights + (spot && r.spotInside), sphereRatio);
    const char* lightBound = "each light's 8-bit conversion (any integer within 0.6 LSB), summed; hull over sample points; "
                             "0 accepted between a sphere's faces and its radius";
    bool pass = compare("lightRT", lightBound, refLight, gpuLight, 1.0);
    pass &= compare("lightRT, only the directional light", lightBound, refLight, gpuLight, 1.0, &directionalOnly);

    // CombineFinal.fx from the GPU's colorRT and lightRT, into the back buffer.
    const std::vector<Color> back = game.GraphicsDevice->GetBackBufferData();
    RefImage refFinal(W, H, 4);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double sLo, sHi;
            linearSample(light, W, H, x, y, 3, sLo, sHi);
            for (int c = 0; c < 3; ++c) {
                double cLo, cHi, lLo, lHi;
                linearSample(color, W, H, x, y, c, cLo, cHi);
                linearSample(light, W, H, x, y, c, lLo, lHi);
                double lo = (cLo / 255 * lLo / 255 + sLo / 255) * 255, hi = (cHi / 255 * lHi / 255 + sHi / 255) * 255;
                lo = std::min(lo, 255.0), hi = std::min(hi, 255.0);
                roundRange(lo, hi);
                refFinal.set(x, y, c, lo, hi);
            }
            refFinal.set(x, y, 3, 255, 255);
        }
    std::printf("CPU reference of the back buffer (CombineFinal.fx from the GPU's colorRT and lightRT):\n");
    pass &= compare("final", "8-bit conversion (within 0.6 LSB); each LINEAR sample between texel (x-1, y-1) and the 1/256-weighted blend, "
                    "+-1 LSB filter rounding", refFinal, fromColors(back, W, H), 1.0);
    return pass;
}

}  // namespace

bool CheckPasses(Game1& game, bool spot, double time) {
    // The references read the tutorial's targets and light volume (the report's quality knobs change them).
    DeferredRenderer& r = game.getRenderer();
    if (r.getColorRT().Format() != SurfaceFormat::Color || r.getNormalRT().Format() != SurfaceFormat::Color ||
        r.getDepthRT().Format() != SurfaceFormat::Single || r.getLightRT().Format() != SurfaceFormat::Color ||
        game.demo.quality.sphereSegments != 0) {
        std::printf("CPU reference: models the tutorial's Color/Color/Single G-buffer, Color lightRT and "
                    "PointLightGeometry only (quality knobs set): FAIL\n");
        return false;
    }
    bool pass = checkGBuffer(game);
    pass &= checkLightMapAndCombine(game, spot, time);
    std::printf("  %s\n", pass ? "PASS" : "FAIL");
    return pass;
}

}  // namespace DeferredLighting
