#include "deferred_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/deterministic_random.h"
#include "render_harness.h"

namespace fxport::render_test {

TestCamera makeCamera(Vector3 position, Vector3 target, int width, int height) {
    TestCamera c;
    c.Position = position;
    c.Target = target;
    c.AspectRatio = float(width) / float(height);
    c.View = Matrix::CreateLookAt(position, target, Vector3::Up);
    c.Projection = Matrix::CreatePerspectiveFieldOfView(c.FieldOfView, c.AspectRatio, c.NearPlane, c.FarPlane);
    return c;
}

float SpotLightSetup::LightAngleCos() const { return float(std::cos(double(FOV))); }

SpotLightSetup makeSpotLight(Vector3 position, Vector3 direction, Vector4 color, float intensity, bool shadows,
                             int shadowMapResolution) {
    SpotLightSetup s;
    s.Position = position;
    direction.Normalize();
    s.Direction = direction;
    s.Color = color;
    s.Intensity = intensity;
    s.Shadows = shadows;
    s.ShadowMapResolution = shadowMapResolution;
    s.Projection = Matrix::CreatePerspectiveFieldOfView(s.FOV, 1.0f, s.NearPlane, s.FarPlane);
    // SpotLight::Update()
    Vector3 target = s.Position + s.Direction;
    if (target == Vector3::Zero) target = -Vector3::Up;
    Vector3 up = Vector3::Cross(s.Direction, Vector3::Up);
    if (up == Vector3::Zero) up = Vector3::Right;
    else up = Vector3::Up;
    s.View = Matrix::CreateLookAt(s.Position, target, up);
    float radial = float(std::tan(double(s.FOV) / 2.0)) * 2 * s.FarPlane;
    Matrix scaling = Matrix::CreateScale(radial, radial, s.FarPlane);
    Matrix translation = Matrix::CreateTranslation(s.Position.X, s.Position.Y, s.Position.Z);
    Matrix inverseView = Matrix::Invert(s.View);
    Matrix semiProduct = scaling * inverseView;
    Vector3 S, P;
    Quaternion Q;
    semiProduct.Decompose(S, Q, P);
    Matrix rotation = Matrix::CreateFromQuaternion(Q);
    s.World = scaling * rotation * translation;
    return s;
}

Matrix PointLightSetup::World() const { return Matrix::CreateScale(Radius / 100.0f) * Matrix::CreateTranslation(Position); }

Matrix PointLightSetup::FaceView(CubeMapFace face) const {
    switch (face) {
    case CubeMapFace::PositiveZ: return Matrix::CreateLookAt(Position, Position + Vector3::Forward, Vector3::Up);
    case CubeMapFace::NegativeZ: return Matrix::CreateLookAt(Position, Position + Vector3::Backward, Vector3::Up);
    case CubeMapFace::NegativeX: return Matrix::CreateLookAt(Position, Position + Vector3::Left, Vector3::Up);
    case CubeMapFace::PositiveX: return Matrix::CreateLookAt(Position, Position + Vector3::Right, Vector3::Up);
    case CubeMapFace::NegativeY: return Matrix::CreateLookAt(Position, Position + Vector3::Down, Vector3::Forward);
    default: return Matrix::CreateLookAt(Position, Position + Vector3::Up, Vector3::Backward);
    }
}

Matrix PointLightSetup::FaceProjection() const {
    return Matrix::CreatePerspectiveFieldOfView(MathHelper::ToRadians(90.0f), 1.0f, 1.0f, Radius);
}

Mesh testSceneMesh() {
    Mesh m = makeTestScene();
    roundToFloat(m);
    return m;
}
Mesh pointLightGeometry() {
    Mesh m = makeSphere(100, 8, 12);
    roundToFloat(m);
    return m;
}
Mesh spotLightGeometry() {
    Mesh m = makeCone(16);
    roundToFloat(m);
    return m;
}

namespace {

V3 randomTilt(Random& r, V3 n, double maxAngle) {
    // n tilted by up to maxAngle towards a random perpendicular direction.
    V3 a = std::fabs(n.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
    V3 u = normalize(cross(n, a)), v = cross(n, u);
    double phi = r.uniform(0, 2 * std::numbers::pi), theta = r.uniform(0, maxAngle);
    return normalize(n * std::cos(theta) + (u * std::cos(phi) + v * std::sin(phi)) * std::sin(theta));
}

V4 encode(V3 n, double w) { return {n.x * 0.5 + 0.5, n.y * 0.5 + 0.5, n.z * 0.5 + 0.5, w}; }

}  // namespace

Materials makeMaterials() {
    const int n = 16;
    Random r(0xA1BED0);
    Materials m;
    m.albedo = quantize(n, n, SurfaceFormat::Color, [&](int x, int y) {
        double t = 0.5 + 0.5 * std::sin(0.7 * x + 0.3 * y);
        return V4{0.25 + 0.6 * t + r.uniform(-0.05, 0.05), 0.3 + 0.4 * r.uniform(), 0.6 - 0.4 * t + r.uniform(-0.05, 0.05), 1};
    });
    m.normal = quantize(n, n, SurfaceFormat::Color, [&](int, int) { return encode(randomTilt(r, {0, 0, 1}, 0.6), 1); });
    m.specular = quantize(n, n, SurfaceFormat::Color, [&](int, int) {
        return V4{r.uniform(), std::floor(r.uniform(4, 81)) / 255, 0, 1};
    });
    return m;
}

GBufferImages makeSyntheticGBuffer(const Mesh& scene, const TestCamera& camera, int width, int height) {
    WorldMesh world = toWorld(scene, M4::identity());
    View3D v = makeView(toM4(camera.View), toM4(camera.Projection), width, height);
    Random r(0x6BF0FF);
    std::vector<V4> albedo, normals, depth;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            reference::Ray ray = ndcRay(v, pixelNdc(x, y, width, height));
            double len = length(ray.direction);
            int tri = -1;
            double d = nearestDistance(world, ray.origin, ray.direction / len, v.eye, Cull::CounterClockwiseFace, &tri);
            if (d < 0 || d > len) {
                albedo.push_back({0, 0, 0, 0});
                normals.push_back({0.5, 0.5, 0.5, 0});
                depth.push_back({1, 1, 1, 1});
                continue;
            }
            V3 p = ray.origin + ray.direction * (d / len);
            const auto& t = world.triangles[std::size_t(tri)];
            V3 a = world.positions[std::size_t(t[0])], b = world.positions[std::size_t(t[1])], c = world.positions[std::size_t(t[2])];
            V3 n = normalize(cross(c - a, b - a));   // the front (clockwise) side
            V3 nv = normalize(mul3(n, v.view));       // view space, as GBuffer.fx writes it
            nv = randomTilt(r, nv, r.uniform() < 0.85 ? 0.03 : 0.45);
            int surface = tri / 2;
            double shade = 0.8 + 0.2 * r.uniform();
            albedo.push_back({(0.3 + 0.5 * ((surface * 37) % 11) / 10.0) * shade, (0.25 + 0.6 * ((surface * 17) % 7) / 6.0) * shade,
                              (0.2 + 0.7 * ((surface * 53) % 5) / 4.0) * shade, r.uniform()});
            normals.push_back(encode(nv, std::floor(r.uniform(4, 81)) / 255));
            V4 clip = mul(point(p), v.viewProjection);
            V4 view = mul(point(p), v.view);
            depth.push_back({clip.z / clip.w, view.z, 0, 0});
        }
    auto at = [&](const std::vector<V4>& img) {
        return [&img, width](int x, int y) { return img[std::size_t(y) * std::size_t(width) + std::size_t(x)]; };
    };
    return {quantize(width, height, SurfaceFormat::Rgba64, at(albedo)), quantize(width, height, SurfaceFormat::Rgba64, at(normals)),
            quantize(width, height, SurfaceFormat::Vector2, at(depth))};
}

CpuTexture makeSpotShadowMap(const Mesh& scene, const SpotLightSetup& light) {
    int n = light.ShadowMapResolution;
    WorldMesh world = toWorld(scene, M4::identity());
    View3D v = makeView(toM4(light.View), toM4(light.Projection), n, n);
    return quantize(n, n, SurfaceFormat::Single, [&](int x, int y) {
        reference::Ray ray = ndcRay(v, {2 * (x + 0.5) / n - 1, 1 - 2 * (y + 0.5) / n});
        V3 dir = normalize(ray.direction);
        double d = nearestDistance(world, v.eye, dir, v.eye, Cull::CounterClockwiseFace);
        double e = d < 0 ? 0 : std::exp(0.5 * d);
        return V4{e, 0, 0, 0};
    });
}

CpuCube makePointShadowCube(const Mesh& scene, const PointLightSetup& light) {
    CpuCube cube;
    cube.size = light.ShadowMapResolution;
    int n = cube.size;
    WorldMesh world = toWorld(scene, M4::identity());
    V3 eye = toV3(light.Position);
    for (int f = 0; f < 6; ++f)
        cube.faces[std::size_t(f)] = quantize(n, n, SurfaceFormat::Single, [&](int x, int y) {
            V3 l = cubeDirection(f, (x + 0.5) / n, (y + 0.5) / n);
            V3 w = normalize(V3{l.x, l.y, -l.z});
            double d = nearestDistance(world, eye, w, eye, Cull::CounterClockwiseFace);
            double e = d < 0 ? 0 : std::exp(0.5 * d);
            return V4{e, 0, 0, 0};
        });
    return cube;
}

CpuTexture makeSpotCookie(int size) {
    return quantize(size, size, SurfaceFormat::Color, [&](int x, int y) {
        double u = (x + 0.5) / size, v = (y + 0.5) / size;
        double r = std::hypot(u - 0.5, v - 0.5);
        double spot = std::clamp(1.15 - 2.3 * r, 0.0, 1.0);
        double ring = std::fabs(r - 0.3) < 0.04 ? 0.55 : 1.0;
        double notch = (u < 0.45 && v < 0.3) ? 0.25 : 1.0;  // makes flips and transpositions visible
        double g = spot * ring * notch;
        return V4{g, g, g, 1};
    });
}

CpuTexture makeRandomNormals(int size) {
    Random r(0x52616e64);
    return quantize(size, size, SurfaceFormat::Color, [&](int, int) {
        double z = r.uniform(-1, 1), phi = r.uniform(0, 2 * std::numbers::pi), s = std::sqrt(1 - z * z);
        return encode({s * std::cos(phi), s * std::sin(phi), z}, 1);
    });
}

CpuTexture makeLightMapImage(int width, int height) {
    Random r(0x11647);
    return quantize(width, height, SurfaceFormat::Color, [&](int x, int y) {
        double a = 0.5 + 0.45 * std::sin(0.21 * x + 0.05 * y), b = 0.5 + 0.45 * std::cos(0.13 * y - 0.07 * x);
        return V4{a, 0.7 * a + 0.3 * b, b, 0.35 * r.uniform() * a};
    });
}

CpuTexture makeSsaoImage(int width, int height) {
    Random r(0x55A0);
    return quantize(width, height, SurfaceFormat::Color, [&](int x, int y) {
        double base = 0.65 + 0.3 * std::sin(0.17 * x) * std::cos(0.23 * y);
        double v = std::clamp(base + r.uniform(-0.12, 0.12), 0.0, 1.0);
        return V4{v, v, v, 1};
    });
}

CpuTexture makeSceneImage(int width, int height) {
    Random r(0x5CE4E);
    return quantize(width, height, SurfaceFormat::Color, [&](int x, int y) {
        return V4{0.5 + 0.4 * std::sin(0.3 * x), 0.5 + 0.4 * std::cos(0.25 * y), r.uniform(0.1, 0.9), 1};
    });
}

}  // namespace fxport::render_test
