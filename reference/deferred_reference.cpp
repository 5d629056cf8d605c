#include "reference/deferred_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fxport::reference {

namespace {

V3 decode(V3 enc) { return enc * 2 - V3{1, 1, 1}; }

V2 inverse(V2 size) { return {1 / size.x, 1 / size.y}; }

// manualSample(Sampler, UV, textureSize) as the seed writes it: four tex2D one texel apart, with
// texelSize = 1.0 / textureSize truncated to .x (so the v step is 1/width too), blended by
// frac(textureSize * UV). Where that fraction is within kPointBand of 0 or 1 the shader's float
// may land on the other side (frac ~ 1 - f with the texture unit still on the nominal texels), so
// both weights are admissible; point samples contribute their candidate ranges.
Range4 manualSample(Eval& ev, const CpuTexture& t, SamplerDesc s, V2 uv, V2 size, unsigned used) {
    double lx = frac(size.x * uv.x), ly = frac(size.y * uv.y);
    double ts = 1.0 / size.x;
    const V2 offsets[4] = {{0, 0}, {ts, 0}, {0, ts}, {ts, ts}};
    Range4 v[4];
    for (int k = 0; k < 4; ++k)
        v[k] = s.filter == Filter::Point ? tex2DPointRange(ev, t, s, uv + offsets[k], used)
                                         : Range4::of(tex2D(ev, t, s, uv + offsets[k], used));
    double ax[2] = {lx, 1 - lx}, ay[2] = {ly, 1 - ly};
    int nx = (lx < kPointBand || lx > 1 - kPointBand) ? 2 : 1, ny = (ly < kPointBand || ly > 1 - kPointBand) ? 2 : 1;
    Range4 out;
    bool first = true;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            double a = ax[i], b = ay[j];
            const double w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
            Range4 r;
            for (int k = 0; k < 4; ++k) {
                r.lo = r.lo + v[k].lo * w[k];
                r.hi = r.hi + v[k].hi * w[k];
            }
            out = first ? r : hull(out, r);
            first = false;
        }
    return out;
}

double gbufferDepth(Eval& ev, const CpuTexture& depth, V2 uv, V2 size) {
    Range4 r = manualSample(ev, depth, kPointClamp, uv, size, kX);
    if (r.lo.x == r.hi.x) return r.lo.x;
    return ev.choose(2) ? r.hi.x : r.lo.x;
}

// manualSampleCUBE(Sampler, UVW, textureSize) of PointLight.fx: eight texCUBE at the direction
// rounded to a 1/size lattice, blended trilinearly by frac(UVW * size + 0.5). Where that fraction
// is within kPointBand of 0 or 1 the shader's floor() may take the neighbouring lattice point
// (with the complementary weight): both are admissible.
Range4 manualSampleCube(Eval& ev, const CpuCube& cube, V3 uvw, double size) {
    double pos[3] = {uvw.x * size + 0.5, uvw.y * size + 0.5, uvw.z * size + 0.5};
    struct Option {
        double base, blend;
    };
    std::vector<Option> axis[3];
    for (int a = 0; a < 3; ++a) {
        double f = std::floor(pos[a]);
        double b = pos[a] - f;
        axis[a].push_back({f, b});
        if (b < kPointBand) axis[a].push_back({f - 1, 1 - b});
        if (b > 1 - kPointBand) axis[a].push_back({f + 1, 1 - b});
    }
    Range4 out;
    bool first = true;
    for (const Option& ox : axis[0])
        for (const Option& oy : axis[1])
            for (const Option& oz : axis[2]) {
                Range4 r;
                for (int k = 0; k < 8; ++k) {
                    int a = (k >> 2) & 1, b = (k >> 1) & 1, c = k & 1;
                    V3 dir{(ox.base + a) / size, (oy.base + b) / size, (oz.base + c) / size};
                    double w = (a ? ox.blend : 1 - ox.blend) * (b ? oy.blend : 1 - oy.blend) * (c ? oz.blend : 1 - oz.blend);
                    Range4 s = texCUBEPointRange(ev, cube, dir);
                    r.lo.x += s.lo.x * w;
                    r.hi.x += s.hi.x * w;
                }
                out = first ? r : hull(out, r);
                first = false;
            }
    return out;
}

double hlslPow(double x, double y) { return std::pow(x, y); }

V4 withW(V3 v, double w) { return {v.x, v.y, v.z, w}; }

}  // namespace

V2 fullscreenUV(PixelPos p) { return {(p.x + kPixelBiasX) / p.width, (p.y + kPixelBiasY) / p.height}; }
V2 fullscreenNdc(PixelPos p) { return pixelNdc(p.x, p.y, p.width, p.height); }

Range4 clearPixel(int target) {
    switch (target) {
    case 0: return Range4::exactly({0, 0, 0, 0});        // Albedo = 0
    case 1: return Range4::exactly({0.5, 0.5, 0.5, 0});  // Normals.xyz = 0.5, .w = 0
    default: return Range4::exactly({1, 1, 1, 1});       // Depth = 1
    }
}

Range4 gbufferPixel(Eval& ev, const GBufferPass& g, const std::vector<int>& visible, PixelPos p, int target) {
    int tri = visible[std::size_t(ev.choose(int(visible.size())))];
    if (tri < 0) return clearPixel(target);
    Ray ray = ndcRay(g.camera, pixelNdc(p.x, p.y, p.width, p.height, ev.pixelShift()));
    V3 lam = planeBarycentrics(g.worldMesh, tri, ray);
    // VS outputs at the three vertices, interpolated (perspective-correctly: barycentrics in space).
    V2 uv;
    V3 depth, T, B, N;
    const auto& t = g.mesh->triangles[std::size_t(tri)];
    for (int k = 0; k < 3; ++k) {
        const MeshVertex& v = g.mesh->vertices[std::size_t(t[std::size_t(k)])];
        double l = k == 0 ? lam.x : k == 1 ? lam.y : lam.z;
        V4 worldPosition = mul(point(v.position), g.world);
        V4 viewPosition = mul(worldPosition, g.view);
        V4 position = mul(viewPosition, g.projection);
        depth = depth + V3{position.z, position.w, viewPosition.z} * l;
        T = T + normalize(mul3(v.tangent, g.worldViewIT)) * l;
        B = B + normalize(mul3(v.binormal, g.worldViewIT)) * l;
        N = N + normalize(mul3(v.normal, g.worldViewIT)) * l;
        uv = uv + v.uv * l;
    }
    switch (target) {
    case 0: {
        V4 albedo = tex2D(ev, *g.albedoMap, kLinearWrap, uv, kXYZ);
        albedo.w = tex2D(ev, *g.specularMap, kLinearWrap, uv, kX).x;
        return Range4::of(albedo);
    }
    case 1: {
        V3 n = decode(tex2D(ev, *g.normalMap, kLinearWrap, uv, kXYZ).xyz());
        V3 normal = normalize(T * n.x + B * n.y + N * n.z);  // mul(normal, TBN), TBN rows T, B, N
        V3 enc = (normalize(normal) + V3{1, 1, 1}) * 0.5;
        return Range4::of(withW(enc, tex2D(ev, *g.specularMap, kLinearWrap, uv, kY).y));
    }
    default: {
        double d = depth.x / depth.y;
        return Range4::of({d, depth.z, d, d});
    }
    }
}

Range4 depthWriterPixel(Eval& ev, const DepthWriterPass& d, const std::vector<int>& visible, PixelPos p) {
    int tri = visible[std::size_t(ev.choose(int(visible.size())))];
    if (tri < 0) return Range4::exactly({0, 0, 0, 0});  // Clear(Color.Transparent)
    Ray ray = ndcRay(d.lightView, pixelNdc(p.x, p.y, p.width, p.height, ev.pixelShift()));
    V3 lam = planeBarycentrics(d.worldMesh, tri, ray);
    const auto& t = d.mesh->triangles[std::size_t(tri)];
    V4 wp;
    for (int k = 0; k < 3; ++k) {
        double l = k == 0 ? lam.x : k == 1 ? lam.y : lam.z;
        wp = wp + mul(point(d.mesh->vertices[std::size_t(t[std::size_t(k)])].position), d.world) * l;
    }
    wp = wp / wp.w;
    double depth = std::max(0.01, length(d.lightPosition - wp.xyz())) / d.depthPrecision;
    double e = std::exp((d.depthPrecision * 0.5) * depth);
    return Range4::of({e, e, e, e});
}

Range4 directionalLightPixel(Eval& ev, const GBufferTextures& gb, const DirectionalLightParams& q, PixelPos p) {
    V2 UV = fullscreenUV(p) - inverse(q.gbufferTextureSize);
    V4 encodedNormal = tex2D(ev, *gb.normals, kLinearClamp, UV);
    V3 N = mul3(decode(encodedNormal.xyz()), q.inverseView);
    double specularIntensity = tex2D(ev, *gb.albedo, kLinearClamp, UV, kW).w;
    double specularPower = encodedNormal.w * 255;
    double depth = gbufferDepth(ev, *gb.depth, UV, q.gbufferTextureSize);
    // The seed's Position.y = -(input.UV.x * 2.0f - 1.0f) (sic).
    V4 position{UV.x * 2 - 1, -(UV.x * 2 - 1), depth, 1};
    position = mul(position, q.inverseViewProjection);
    position = position / position.w;
    // Phong
    V3 R = normalize(reflect(q.L, N));
    V3 E = normalize(q.cameraPosition - position.xyz());
    double NL = dot(N, -q.L);
    V3 diffuse = q.lightColor.xyz() * NL;
    double specular = specularIntensity * hlslPow(saturate(dot(R, E)), specularPower);
    return Range4::of(withW(diffuse, specular) * q.lightIntensity);
}

namespace {

// What SpotLight.fx and PointLight.fx share before their Phong: the G-buffer at the pixel.
struct GBufferSample {
    V3 normal, position;
    double specularIntensity, specularPower;
};

GBufferSample readGBuffer(Eval& ev, const GBufferTextures& gb, const M4& inverseView, const M4& inverseViewProjection,
                          V2 gbufferTextureSize, PixelPos p) {
    // ScreenPosition.xy / w is the pixel's (unshifted) NDC sample point.
    V2 ndc = pixelNdc(p.x, p.y, p.width, p.height, ev.pixelShift());
    V2 UV = V2{ndc.x + 1, -ndc.y + 1} * 0.5 - inverse(gbufferTextureSize);
    GBufferSample s;
    V4 encodedNormal = tex2D(ev, *gb.normals, kLinearClamp, UV);
    s.normal = mul3(decode(encodedNormal.xyz()), inverseView);
    s.specularIntensity = tex2D(ev, *gb.albedo, kLinearClamp, UV, kW).w;
    s.specularPower = encodedNormal.w * 255;
    double depth = gbufferDepth(ev, *gb.depth, UV, gbufferTextureSize);
    V4 position = mul(V4{ndc.x, ndc.y, depth, 1}, inverseViewProjection);
    s.position = (position / position.w).xyz();
    return s;
}

// The exponential shadow factor both shadowed lights compute, lZ * exp(-(DepthPrecision / 2) *
// (len - DepthBias)) with len the light's distance over DepthPrecision, as [lo, hi] over the
// sampled depth's range; 1 without shadows.
struct ShadowFactor {
    double lo = 1, hi = 1;
};

template <class Params>
ShadowFactor exponentialShadow(const Range4& lZ, const Params& q, V3 position) {
    ShadowFactor f;
    if (q.shadows) {
        double len = std::max(0.01, length(q.lightPosition - position)) / q.depthPrecision;
        double e = std::exp(-(q.depthPrecision * 0.5) * (len - q.depthBias));
        f.lo = lZ.lo.x * e;
        f.hi = lZ.hi.x * e;
    }
    return f;
}

}  // namespace

Range4 spotLightPixel(Eval& ev, const GBufferTextures& gb, const CpuTexture& cookie, const CpuTexture& shadowMap,
                      const SpotLightParams& q, const std::vector<int>& coverage, PixelPos p) {
    int fragments = coverage[std::size_t(ev.choose(int(coverage.size())))];
    if (fragments == 0) return Range4::exactly({0, 0, 0, 0});
    GBufferSample g = readGBuffer(ev, gb, q.inverseView, q.inverseViewProjection, q.gbufferTextureSize, p);
    V4 lightScreenPos = mul(point(g.position), q.lightViewProjection);
    lightScreenPos = lightScreenPos / lightScreenPos.w;
    V2 LUV = V2{lightScreenPos.x + 1, -lightScreenPos.y + 1} * 0.5;
    Range4 lZ = manualSample(ev, shadowMap, kPointClamp, LUV, {q.shadowMapSize, q.shadowMapSize}, kX);
    double attenuation = tex2D(ev, cookie, kLinearClamp, LUV, kX).x;
    const ShadowFactor shadow = exponentialShadow(lZ, q, g.position);
    // Phong(Position, N, radialAttenuation = cookie, SpecularIntensity, SpecularPower)
    V3 L = q.lightPosition - g.position;
    double heightAttenuation = 1 - saturate(length(L) - q.lightHeight / 2);
    double A = std::min(attenuation, heightAttenuation);
    L = normalize(L);
    double SL = dot(L, q.S);
    V4 shading;
    if (ev.decide(SL <= q.lightAngleCos, SL - q.lightAngleCos, 1e-6)) {
        V3 R = normalize(reflect(-L, g.normal));
        V3 E = normalize(q.cameraPosition - g.position);
        double NL = dot(g.normal, L);
        V3 diffuse = q.lightColor.xyz() * NL;
        double specular = g.specularIntensity * hlslPow(saturate(dot(R, E)), g.specularPower);
        shading = withW(diffuse, specular) * (A * q.lightIntensity);
    }
    return scaleByRange(shading * double(fragments), shadow.lo, shadow.hi);
}

Range4 pointLightPixel(Eval& ev, const GBufferTextures& gb, const CpuCube& shadowMap, const PointLightParams& q,
                       const std::vector<int>& coverage, PixelPos p) {
    int fragments = coverage[std::size_t(ev.choose(int(coverage.size())))];
    if (fragments == 0) return Range4::exactly({0, 0, 0, 0});
    GBufferSample g = readGBuffer(ev, gb, q.inverseView, q.inverseViewProjection, q.gbufferTextureSize, p);
    V3 L = q.lightPosition - g.position;
    double attenuation = saturate(1 - std::max(0.01, length(L)) / (q.lightRadius / 2));
    L = normalize(L);
    V3 R = normalize(reflect(-L, g.normal));
    V3 E = normalize(q.cameraPosition - g.position);
    double NL = dot(g.normal, L);
    V3 diffuse = q.lightColor.xyz() * NL;
    double specular = g.specularIntensity * hlslPow(saturate(dot(R, E)), g.specularPower);
    Range4 lZ = manualSampleCube(ev, shadowMap, {-L.x, -L.y, L.z}, q.shadowMapSize);
    const ShadowFactor shadow = exponentialShadow(lZ, q, g.position);
    V4 shading = withW(diffuse, specular) * (attenuation * q.lightIntensity * double(fragments));
    return scaleByRange(shading, shadow.lo, shadow.hi);
}

Range4 compositionPixel(Eval& ev, const CpuTexture& albedo, const CpuTexture& lightMap, V2 gbufferTextureSize, PixelPos p) {
    V2 UV = fullscreenUV(p) - inverse(gbufferTextureSize);
    V3 color = tex2D(ev, albedo, kLinearClamp, UV, kXYZ).xyz();
    V4 lighting = tex2D(ev, lightMap, kLinearClamp, UV);
    V3 c = color * lighting.xyz() + V3{lighting.w, lighting.w, lighting.w};
    return Range4::of(withW(c, 1));
}

Range4 ssaoPixel(Eval& ev, const CpuTexture& normals, const CpuTexture& depthTex, const CpuTexture& randomNormals,
                 const SsaoParams& q, PixelPos p) {
    static const V3 samples[8] = {
        {0.355512, -0.709318, -0.102371}, {0.534186, 0.71511, -0.115167},  {-0.87866, 0.157139, -0.115167},
        {0.140679, -0.475516, -0.0639818}, {-0.207641, 0.414286, 0.187755}, {-0.277332, -0.371262, 0.187755},
        {0.63864, -0.114214, 0.262857},   {-0.184051, 0.622119, 0.262857},
    };
    V2 UV = fullscreenUV(p) - inverse(q.gbufferTextureSize);
    V2 ndc = fullscreenNdc(p);
    V3 viewDirection = normalize(V3{-q.cornerFustrum.x * ndc.x, q.cornerFustrum.y * ndc.y, q.cornerFustrum.z});
    double depth = tex2D(ev, depthTex, kPointClamp, UV, kY).y;
    V3 se = viewDirection * depth;
    V3 randNormal = tex2D(ev, randomNormals, kLinearWrap, UV * 200, kXYZ).xyz();
    V3 normal = decode(tex2D(ev, normals, kLinearClamp, UV, kXYZ).xyz());
    // Each sample's contribution over its admissible paths (branch on dot(ray, normal), texel).
    double lo = 0, hi = 0;
    for (const V3& sample : samples) {
        V3 ray = reflect(sample, randNormal) * q.sampleRadius;
        double d = dot(ray, normal);
        std::vector<V3> rays;
        if (std::fabs(d) < 1e-6 * length(ray) * length(normal)) rays = {ray, ray + normal * q.sampleRadius};
        else rays = {d < 0 ? ray + normal * q.sampleRadius : ray};
        double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
        for (const V3& r : rays) {
            V4 ss = mul(point(se + r), q.projection);
            V2 sampleTexCoord = V2{ss.x, ss.y} * (0.5 / ss.w) + V2{0.5, 0.5};
            for (const V4& t : tex2DPointCandidates(ev, depthTex, kPointClamp, sampleTexCoord, kY)) {
                double sampleDepth = t.y;
                double c;
                if (sampleDepth == 1.0) {
                    c = 1;
                } else {
                    double occlusion = q.distanceScale * std::max(sampleDepth - depth, 0.0);
                    c = 1 / (1 + occlusion * occlusion * 0.1);
                }
                cmin = std::min(cmin, c);
                cmax = std::max(cmax, c);
            }
        }
        lo += cmin;
        hi += cmax;
    }
    return {{lo / 8, lo / 8, lo / 8, 1}, {hi / 8, hi / 8, hi / 8, 1}, false};
}

Range4 ssaoBlurPixel(Eval& ev, const CpuTexture& normals, const CpuTexture& ssaoTex, V2 blurDirection, V2 targetSize,
                     PixelPos p) {
    V2 UV = fullscreenUV(p) - inverse(targetSize);
    // (float depth = manualSample(GBuffer2, ...) is never used; the compiler drops it.)
    V3 normal = decode(tex2D(ev, normals, kLinearClamp, UV, kXYZ).xyz());
    Range4 ssao = Range4::of(splat(tex2D(ev, ssaoTex, kLinearClamp, UV, kX).x));
    double ssaoNormalizer = 1;
    const int blurSamples = 8;
    for (int i = -blurSamples / 2; i <= blurSamples / 2; ++i) {
        V2 newUV = UV + blurDirection * double(i);
        Range4 sample = manualSample(ev, ssaoTex, kLinearClamp, newUV, targetSize, kY);
        V3 samplenormal = decode(tex2D(ev, normals, kLinearClamp, newUV, kXYZ).xyz());
        double dp = dot(samplenormal, normal);
        if (ev.decide(dp > 0.99, dp - 0.99, 1e-6)) {
            double contribution = blurSamples / 2 - std::abs(i);
            ssaoNormalizer += contribution;
            ssao.lo = ssao.lo + splat(sample.lo.y * contribution);
            ssao.hi = ssao.hi + splat(sample.hi.y * contribution);
        }
    }
    return {ssao.lo / ssaoNormalizer, ssao.hi / ssaoNormalizer, false};
}

Range4 ssaoFinalPixel(Eval& ev, const CpuTexture& scene, const CpuTexture& ssao, V2 halfPixel, PixelPos p) {
    V2 UV = fullscreenUV(p) - halfPixel;
    return Range4::of(tex2D(ev, scene, kLinearClamp, UV) * tex2D(ev, ssao, kLinearClamp, UV));
}

}  // namespace fxport::reference
