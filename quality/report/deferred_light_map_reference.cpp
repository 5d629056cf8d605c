#include "report/deferred_light_map_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "reference/deferred_reference.h"
#include "reference/triangle_bvh.h"

namespace fxport::report {

namespace rt = fxport::reference;
using reference::Triangle;
using reference::TriangleBvh;
using TheCansinDeferredRenderer::Game1;

namespace {

rt::M4 toM4(const Matrix& m) {
    const float* f = &m.M11;
    rt::M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = double(f[i * 4 + j]);
    return r;
}
rt::V3 toV3(Vector3 v) { return {v.X, v.Y, v.Z}; }
rt::V4 toV4(Vector4 v) { return {v.X, v.Y, v.Z, v.W}; }

rt::CpuTexture readFloatTarget(const RenderTarget2D& target) {
    if (target.Format() != SurfaceFormat::Vector4)
        throw ArgumentError("exactDeferredLightMap: G-buffer target '" + target.Name + "' is " +
                            std::to_string(int(target.Format())) + ", not Vector4: the reference starts from the float32 G-buffer");
    rt::CpuTexture t(target.Width(), target.Height(), rt::TexelFormat::Float32, 4);
    const std::vector<Vector4> texels = target.GetDataAsVector4();
    for (std::size_t i = 0; i < texels.size(); ++i) t.texels[i] = toV4(texels[i]);
    return t;
}

rt::CpuTexture readColorTexture(const Texture2D& texture) {
    rt::CpuTexture t(texture.Width(), texture.Height(), rt::TexelFormat::Unorm8, 4);
    const std::vector<Color> texels = texture.GetData<Color>();
    for (std::size_t i = 0; i < texels.size(); ++i)
        t.texels[i] = {texels[i].R / 255.0, texels[i].G / 255.0, texels[i].B / 255.0, texels[i].A / 255.0};
    return t;
}

// Every triangle of `model` in world space (its bones' absolute transforms, then `world`), in the
// winding the GPU sees.
std::vector<Triangle> worldTriangles(const Model& model, const Matrix& world) {
    std::vector<Matrix> transforms(std::size_t(model.Bones.Count()));
    model.CopyAbsoluteBoneTransformsTo(transforms);
    std::vector<Triangle> out;
    for (const ModelMesh& mesh : model.Meshes) {
        const rt::M4 m = toM4(transforms[std::size_t(mesh.ParentBone->Index)] * world);
        for (const ModelMeshPart& part : mesh.MeshParts) {
            std::vector<ModelVertex> vertices(std::size_t(part.VertexBuffer->VertexCount()));
            part.VertexBuffer->GetData(vertices.data(), vertices.size());
            const std::vector<std::uint32_t> indices = part.IndexBuffer->GetIndices();
            for (int k = 0; k < part.PrimitiveCount; ++k) {
                Triangle tri;
                for (int c = 0; c < 3; ++c) {
                    const int index = part.VertexOffset + int(indices[std::size_t(part.StartIndex + 3 * k + c)]);
                    const Vector3 p = vertices[std::size_t(index)].Position;
                    tri[std::size_t(c)] = (rt::mul(rt::V4{p.X, p.Y, p.Z, 1}, m)).xyz();
                }
                out.push_back(tri);
            }
        }
    }
    return out;
}

// XNA's culling: a triangle is clockwise as seen from `eye` when (c - a) x (b - a) points at it;
// CullCounterClockwise keeps those, CullClockwise the others.
bool kept(const Triangle& t, rt::V3 eye, bool cullClockwise) {
    const bool clockwise = rt::dot(rt::cross(t[2] - t[0], t[1] - t[0]), eye - t[0]) > 0;
    return cullClockwise ? !clockwise : clockwise;
}

// How many kept triangles of a light volume the pixel's ray crosses between the near and far planes.
int volumeFragments(const TriangleBvh& volume, const rt::View3D& camera, bool cullClockwise, int x, int y) {
    const rt::Ray ray = rt::ndcRay(camera, rt::pixelNdc(x, y, camera.width, camera.height));
    int n = 0;
    volume.forEachHit(ray.origin, ray.direction, 0, 1, [&](int tri) { n += kept(volume.triangle(tri), camera.eye, cullClockwise) ? 1 : 0; });
    return n;
}

}  // namespace

std::vector<double> readDeferredLightMap(Game1& game) {
    const std::vector<Vector4> texels = game.getDeferredRenderer().getLightMap().GetDataAsVector4();
    std::vector<double> rgba;
    rgba.reserve(texels.size() * 4);
    for (const Vector4& t : texels) rgba.insert(rgba.end(), {t.X, t.Y, t.Z, t.W});
    return rgba;
}

ExactLightMap exactDeferredLightMap(Game1& game) {
    auto& renderer = game.getDeferredRenderer();
    const std::vector<const RenderTarget2D*> gbuffer = renderer.getTargets();  // G-buffer 0..2, then LightMap
    const rt::CpuTexture albedo = readFloatTarget(*gbuffer[0]);
    const rt::CpuTexture normals = readFloatTarget(*gbuffer[1]);
    const rt::CpuTexture depth = readFloatTarget(*gbuffer[2]);
    const rt::GBufferTextures gb{&albedo, &normals, &depth};
    const int W = albedo.width, H = albedo.height;

    // The camera as MakeLightMap hands it to the effects (the point light effect holds every value).
    Effect* pointEffect = game.Content.Load<Effect>("Effects/PointLight");
    const rt::M4 view = toM4(pointEffect->Parameters["View"].GetValueMatrix());
    const rt::M4 projection = toM4(pointEffect->Parameters["Projection"].GetValueMatrix());
    const rt::View3D camera = rt::makeView(view, projection, W, H);
    const rt::M4 inverseView = toM4(pointEffect->Parameters["inverseView"].GetValueMatrix());
    const rt::M4 inverseViewProjection = toM4(pointEffect->Parameters["InverseViewProjection"].GetValueMatrix());
    const rt::V3 cameraPosition = toV3(pointEffect->Parameters["CameraPosition"].GetValueVector3());
    const rt::V2 gbufferSize{double(W), double(H)};
    const Vector3 cameraAt = pointEffect->Parameters["CameraPosition"].GetValueVector3();

    const TriangleBvh scene(worldTriangles(*game.Content.Load<Model>("Scene"), Matrix::Identity));
    const Model& cone = *game.Content.Load<Model>("SpotLightGeometry");
    const Model& sphere = *game.Content.Load<Model>("PointLightGeometry");
    const auto& stats = renderer.getFrameStats();
    const auto& lights = game.getLightManager();

    // A pass's value at a pixel: the exact-arithmetic path of the pass reference, with ray-cast
    // visibility (first) and with the ideal exponential shadow test (second).
    using PassValue = std::pair<rt::V4, rt::V4>;
    using PassFunction = std::function<PassValue(int x, int y)>;
    std::vector<PassFunction> passes;
    for (const auto& light : lights.getDirectionalLights()) {
        rt::DirectionalLightParams q;
        q.inverseViewProjection = inverseViewProjection;
        q.inverseView = inverseView;
        q.cameraPosition = cameraPosition;
        const Vector3 L = Vector3::Normalize(light->getDirection());
        q.L = toV3(L);
        q.lightColor = toV4(light->getColor());
        q.lightIntensity = light->getIntensity();
        q.gbufferTextureSize = gbufferSize;
        passes.push_back([&gb, q, W, H](int x, int y) {
            rt::Eval ev;
            const rt::V4 lit = rt::directionalLightPixel(ev, gb, q, {x, y, W, H}).lo;
            return PassValue{lit, lit};
        });
    }
    // Where a shadow ray starts: the surface point of the G-buffer texel whose depth the pass
    // samples (SpotLight.fx/PointLight.fx read the G-buffer at UV one texel up-left of the pixel),
    // at that texel's own screen position: a point on the surface up to float32 depth rounding.
    // (The pass shades the pixel's screen position at that depth, a point up to one depth step off
    // the surface; rays from there would hit their own surface where the light grazes it.)
    // shaded: the point the pass itself shades instead (the pixel's screen position at that depth).
    auto texelPoint = [&](int x, int y, bool shaded) {
        const rt::V2 ndc = rt::pixelNdc(x, y, W, H);
        const rt::V2 uv = rt::V2{ndc.x + 1, -ndc.y + 1} * 0.5 - rt::V2{1.0 / W, 1.0 / H};
        const int tx = std::clamp(int(std::floor(W * uv.x)), 0, W - 1), ty = std::clamp(int(std::floor(H * uv.y)), 0, H - 1);
        const rt::V2 tndc = shaded ? ndc : rt::pixelNdc(tx, ty, W, H);
        const rt::V4 s = rt::mul(rt::V4{tndc.x, tndc.y, depth.at(tx, ty).x, 1}, inverseViewProjection);
        return s.xyz() / s.w;
    };
    auto texelSurface = [&](int x, int y) { return texelPoint(x, y, false); };
    // The terminator (see the header): does the facet under the pixel's surface point face away from
    // `light`? The facet: of the scene triangles the camera ray crosses within 2 % of the point's
    // distance, the one whose plane passes nearest the point; its normal turned towards the camera.
    ExactLightMap out;
    out.terminator.assign(std::size_t(W) * std::size_t(H), 0);
    auto facetFacesAway = [&](int x, int y, rt::V3 light) {
        const rt::V3 surface = texelSurface(x, y);
        const rt::V3 toSurface = surface - cameraPosition;
        const double distance = rt::length(toSurface);
        const rt::V3 direction = toSurface / distance;
        double nearest = 1e300;
        rt::V3 facetNormal{};
        scene.forEachHit(cameraPosition, direction, 0.98 * distance, 1.02 * distance, [&](int i) {
            const Triangle& t = scene.triangle(i);
            rt::V3 n = rt::cross(t[1] - t[0], t[2] - t[0]);
            const double len = rt::length(n);
            if (len == 0) return;
            n = n / len;
            const double off = std::fabs(rt::dot(n, surface - t[0]));
            if (off < nearest) nearest = off, facetNormal = rt::dot(n, direction) > 0 ? n * -1.0 : n;
        });
        return nearest < 1e300 && rt::dot(facetNormal, light - surface) <= 0;
    };
    auto markTerminator = [&](int x, int y, rt::V4 lit, rt::V3 light) {
        if ((lit.x > 0 || lit.y > 0 || lit.z > 0 || lit.w > 0) && facetFacesAway(x, y, light))
            out.terminator[std::size_t(y) * std::size_t(W) + std::size_t(x)] = 1;
    };
    // ShadowFactor with an exact shadow map (see idealEsmRgba in the header).
    // Evaluated where the effect evaluates it, at the shaded point: a point a depth step off the
    // surface only moves d_occ or d by that step, which the exponential test's bias absorbs.
    auto idealEsm = [&](int x, int y, rt::V3 light, double depthPrecision, double depthBias) {
        const rt::V3 surface = texelPoint(x, y, true);
        const rt::V3 d = surface - light;
        const double distance = rt::length(d);
        const double occluder = std::min(distance, scene.closestHit(light, d / distance, 0, distance));
        const double len = std::max(0.01, distance) / depthPrecision;
        return std::exp(0.5 * std::max(0.01, occluder)) * std::exp(-(depthPrecision * 0.5) * (len - depthBias));
    };
    auto visible = [&](int x, int y, rt::V3 light) {
        const rt::V3 surface = texelSurface(x, y);
        const rt::V3 d = light - surface;
        const double distance = rt::length(d);
        if (distance <= kShadowRayStart) return 1.0;
        return scene.anyHit(surface, d / distance, kShadowRayStart, distance) ? 0.0 : 1.0;
    };
    struct Volume {
        std::unique_ptr<TriangleBvh> mesh;
        bool cullClockwise;
    };
    std::vector<std::unique_ptr<Volume>> volumes;
    std::vector<std::unique_ptr<rt::CpuTexture>> cookies;
    static const rt::CpuTexture noShadowMap = [] {
        rt::CpuTexture t(1, 1, rt::TexelFormat::Float32, 1);
        t.at(0, 0) = {1, 1, 1, 1};
        return t;
    }();
    static const rt::CpuCube noShadowCube = [] {
        rt::CpuCube c;
        c.size = 1;
        for (rt::CpuTexture& f : c.faces) f = noShadowMap;
        return c;
    }();
    if (stats.spotLightsDrawn + stats.spotLightsCulled != int(lights.getSpotLights().size()))
        throw ArgumentError("exactDeferredLightMap: the game has not drawn a frame with its spot lights");
    for (const auto& light : lights.getSpotLights()) {
        const Vector3 toCamera = cameraAt - light->getPosition();
        const float SL = std::fabs(Vector3::Dot(toCamera, light->getDirection()));
        volumes.push_back(std::make_unique<Volume>(Volume{std::make_unique<TriangleBvh>(worldTriangles(cone, light->getWorld())),
                                                          !(SL < light->LightAngleCos())}));
        cookies.push_back(std::make_unique<rt::CpuTexture>(readColorTexture(*light->getAttenuationTexture())));
        rt::SpotLightParams q;
        q.inverseView = inverseView;
        q.inverseViewProjection = inverseViewProjection;
        q.lightViewProjection = toM4(light->getView() * light->getProjection());
        q.cameraPosition = cameraPosition;
        q.lightPosition = toV3(light->getPosition());
        q.S = toV3(light->getDirection());
        q.lightColor = toV4(light->getColor());
        q.lightIntensity = light->getIntensity();
        q.lightAngleCos = light->LightAngleCos();
        q.lightHeight = light->getFarPlane();
        q.gbufferTextureSize = gbufferSize;
        q.shadows = false;
        q.shadowMapSize = 1;
        const Volume* volume = volumes.back().get();
        const rt::CpuTexture* cookie = cookies.back().get();
        const bool shadowed = light->getIsWithShadows();
        const double depthPrecision = light->getFarPlane(), depthBias = light->getDepthBias();
        passes.push_back([&, q, volume, cookie, shadowed, depthPrecision, depthBias](int x, int y) {
            const int fragments = volumeFragments(*volume->mesh, camera, volume->cullClockwise, x, y);
            if (fragments == 0) return PassValue{};
            rt::Eval ev;
            const rt::V4 lit = rt::spotLightPixel(ev, gb, *cookie, noShadowMap, q, {fragments}, {x, y, W, H}).lo;
            if (!shadowed) return PassValue{lit, lit};
            markTerminator(x, y, lit, q.lightPosition);
            return PassValue{lit * visible(x, y, q.lightPosition), lit * idealEsm(x, y, q.lightPosition, depthPrecision, depthBias)};
        });
    }
    for (const auto& light : lights.getPointLights()) {
        const Vector3 diff = cameraAt - light->getPosition();
        const float cameraToLight = float(std::sqrt(float(Vector3::Dot(diff, diff)))) / 100.0f;
        volumes.push_back(std::make_unique<Volume>(Volume{std::make_unique<TriangleBvh>(worldTriangles(sphere, light->World())),
                                                          cameraToLight <= light->getRadius()}));
        rt::PointLightParams q;
        q.inverseView = inverseView;
        q.inverseViewProjection = inverseViewProjection;
        q.cameraPosition = cameraPosition;
        q.lightPosition = toV3(light->getPosition());
        q.lightRadius = light->getRadius();
        q.lightColor = toV4(light->getColor());
        q.lightIntensity = light->getIntensity();
        q.gbufferTextureSize = gbufferSize;
        q.shadows = false;
        q.shadowMapSize = 1;
        const Volume* volume = volumes.back().get();
        const bool shadowed = light->getIsWithShadows();
        const double depthPrecision = light->getRadius(), depthBias = light->getDepthBias();
        passes.push_back([&, q, volume, shadowed, depthPrecision, depthBias](int x, int y) {
            const int fragments = volumeFragments(*volume->mesh, camera, volume->cullClockwise, x, y);
            if (fragments == 0) return PassValue{};
            rt::Eval ev;
            const rt::V4 lit = rt::pointLightPixel(ev, gb, noShadowCube, q, {fragments}, {x, y, W, H}).lo;
            if (!shadowed) return PassValue{lit, lit};
            markTerminator(x, y, lit, q.lightPosition);
            return PassValue{lit * visible(x, y, q.lightPosition), lit * idealEsm(x, y, q.lightPosition, depthPrecision, depthBias)};
        });
    }

    out.rgba.assign(std::size_t(W) * std::size_t(H) * 4, 0.0);
    out.idealEsmRgba.assign(std::size_t(W) * std::size_t(H) * 4, 0.0);
    out.defined.assign(std::size_t(W) * std::size_t(H), 1);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const rt::V2 ndc = rt::pixelNdc(x, y, W, H);
            const rt::V4 own = rt::mul(rt::V4{ndc.x, ndc.y, depth.at(x, y).x, 1}, inverseViewProjection);
            const rt::V3 surface = texelSurface(x, y);
            if (rt::length(own.xyz() / own.w - surface) > kUndefinedAt * rt::length(surface - cameraPosition))
                out.defined[std::size_t(y) * std::size_t(W) + std::size_t(x)] = 0;
            const std::size_t at = (std::size_t(y) * std::size_t(W) + std::size_t(x)) * 4;
            double* px = &out.rgba[at];
            double* esm = &out.idealEsmRgba[at];
            for (const PassFunction& pass : passes) {
                const auto [exact, withEsm] = pass(x, y);
                for (int c = 0; c < 4; ++c) {
                    px[c] = std::min(1.0, px[c] + rt::saturate(exact[c]));
                    esm[c] = std::min(1.0, esm[c] + rt::saturate(withEsm[c]));
                }
            }
        }
    return out;
}

}  // namespace fxport::report
