#include "pointlights/reference_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pointlights/game1.h"

namespace DeferredLighting {

namespace {

struct D3 {
    double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(D3 a) { return std::sqrt(dot(a, a)); }
D3 normalize(D3 a) { return a * (1.0 / length(a)); }
double saturate(double v) { return std::clamp(v, 0.0, 1.0); }
D3 d3(Vector3 v) { return {v.X, v.Y, v.Z}; }
// HLSL reflect(i, n) = i - 2 * dot(n, i) * n
D3 reflect(D3 i, D3 n) { return i - n * (2 * dot(n, i)); }

}  // namespace

bool CheckLightMap(Game1& game) {
    DeferredRenderer& r = game.getRenderer();
    Camera& camera = game.getCamera();
    const int W = r.getColorRT().Width(), H = r.getColorRT().Height();
    std::vector<Color> color = r.getColorRT().GetData<Color>();
    std::vector<Color> normal = r.getNormalRT().GetData<Color>();
    std::vector<float> depth = r.getDepthRT().GetData<float>();
    std::vector<Color> light = r.getLightRT().GetData<Color>();
    const Matrix ivp = Matrix::Invert(camera.View * camera.Projection);
    const D3 cam = d3(camera.Position);
    auto toWorld = [&](double nx, double ny, double nz) {
        double x = nx * ivp.M11 + ny * ivp.M21 + nz * ivp.M31 + ivp.M41;
        double y = nx * ivp.M12 + ny * ivp.M22 + nz * ivp.M32 + ivp.M42;
        double z = nx * ivp.M13 + ny * ivp.M23 + nz * ivp.M33 + ivp.M43;
        double w = nx * ivp.M14 + ny * ivp.M24 + nz * ivp.M34 + ivp.M44;
        return D3{x / w, y / w, z / w};
    };

    long histogram[4][6] = {};  // channel x {0, 1, 2, 3-7, 8-31, >=32 LSB}
    long darker = 0, brighter = 0;
    int worst = 0, worstX = 0, worstY = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            // D3D9: pixel centre (x, y); texCoord - halfPixel -> centre of texel (x-1, y-1), clamped.
            const int tx = std::max(0, x - 1), ty = std::max(0, y - 1);
            const std::size_t t = std::size_t(ty) * std::size_t(W) + std::size_t(tx);
            const D3 n = {2.0 * normal[t].R / 255 - 1, 2.0 * normal[t].G / 255 - 1, 2.0 * normal[t].B / 255 - 1};
            const double specularPower = normal[t].A / 255.0 * 255;
            const double specularIntensity = color[t].A / 255.0;
            const double depthVal = depth[t];
            double sum[4] = {0, 0, 0, 0};
            auto add = [&](double c0, double c1, double c2, double c3) {
                // the target's 8-bit rounding of each light, clamped, added and clamped
                double c[4] = {c0, c1, c2, c3};
                for (int k = 0; k < 4; ++k) sum[k] = std::min(255.0, sum[k] + std::round(saturate(c[k]) * 255));
            };
            // Directional light (DirectionalLight.fx): position from the quad's texCoord.
            {
                const double u = (x - 0.5) / W, v = (y - 0.5) / H;
                D3 position = toWorld(u * 2 - 1, -(v * 2 - 1), depthVal);
                D3 lightVector = normalize(d3(r.drawnDirection)) * -1.0;
                double NdL = std::max(0.0, dot(n, lightVector));
                D3 c = d3(r.drawnDirectionalColor);
                D3 reflectionVector = normalize(reflect(lightVector, n));
                D3 directionToCamera = normalize(cam - position);
                double specularLight =
                    specularIntensity * std::pow(saturate(dot(reflectionVector, directionToCamera)), specularPower);
                add(NdL * c.x, NdL * c.y, NdL * c.z, specularLight);
            }
            // Point lights (PointLight.fx): position from the pixel's screen position.
            const D3 position = toWorld(2.0 * x / W - 1, 1 - 2.0 * y / H, depthVal);
            for (const auto& l : r.drawnPointLights) {
                D3 lightVector = d3(l.position) - position;
                double attenuation = saturate(1.0 - length(lightVector) / l.radius);
                if (attenuation <= 0) continue;
                lightVector = normalize(lightVector);
                double NdL = std::max(0.0, dot(n, lightVector));
                D3 reflectionVector = normalize(reflect(lightVector * -1.0, n));
                D3 directionToCamera = normalize(cam - position);
                double specularLight =
                    specularIntensity * std::pow(saturate(dot(reflectionVector, directionToCamera)), specularPower);
                double a = attenuation * l.intensity;
                add(a * NdL * l.color.X, a * NdL * l.color.Y, a * NdL * l.color.Z, a * specularLight);
            }
            const Color& g = light[std::size_t(y) * std::size_t(W) + std::size_t(x)];
            const int gpu[4] = {g.R, g.G, g.B, g.A};
            bool isDarker = false, isBrighter = false;
            for (int k = 0; k < 4; ++k) {
                int d = gpu[k] - int(sum[k]);
                int a = std::abs(d);
                int bin = a <= 2 ? a : a < 8 ? 3 : a < 32 ? 4 : 5;
                ++histogram[k][bin];
                if (k < 3 && d <= -8) isDarker = true;
                if (k < 3 && d >= 8) isBrighter = true;
                if (k < 3 && a > worst) worst = a, worstX = x, worstY = y;
            }
            darker += isDarker;
            brighter += isBrighter;
        }
    }
    const long total = long(W) * long(H);
    std::printf("CPU reference of lightRT (1 directional + %zu point lights, %d inside):\n",
                r.drawnPointLights.size(), r.insideLights);
    const char* names[4] = {"R", "G", "B", "A(spec)"};
    std::printf("  channel   |d|=0     1       2      3-7    8-31    >=32 LSB\n");
    for (int k = 0; k < 4; ++k)
        std::printf("  %-7s %7ld %7ld %7ld %7ld %7ld %7ld\n", names[k], histogram[k][0], histogram[k][1],
                    histogram[k][2], histogram[k][3], histogram[k][4], histogram[k][5]);
    std::printf("  rgb: %ld pixels darker than the reference by >= 8 LSB, %ld brighter (of %ld); worst %d LSB at "
                "(%d, %d)\n",
                darker, brighter, total, worst, worstX, worstY);
    // Pass: rgb within 2 LSB on 99.5 % of the pixels, and fewer than 0.2 % off by 8 or more.
    long within2 = 0;
    for (int k = 0; k < 3; ++k) within2 += histogram[k][0] + histogram[k][1] + histogram[k][2];
    const bool pass = within2 >= long(0.995 * double(3 * total)) && darker + brighter < total / 500;
    std::printf("  %s\n", pass ? "PASS" : "FAIL");
    return pass;
}

}  // namespace DeferredLighting
