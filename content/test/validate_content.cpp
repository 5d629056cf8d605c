// content.validate: loads what fxport_content generated (glTF through tinygltf, PNGs through
// stb_image) and checks what the demo and the runtime's Model loader rely on. See content/README.md.
//   fxport_content_validate <content-dir>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <stb/stb_image.h>
#include <tiny_gltf.h>

namespace {

int g_failures = 0;

void Fail(const std::string& what) {
    ++g_failures;
    std::printf("FAIL: %s\n", what.c_str());
}

void Check(bool ok, const std::string& what) {
    if (!ok) Fail(what);
}

struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 Cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double Length(V3 a) { return std::sqrt(Dot(a, a)); }

// ---- glTF access ---------------------------------------------------------------------------------

bool LoadGltf(const std::string& path, tinygltf::Model& model) {
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok = loader.LoadASCIIFromFile(&model, &err, &warn, path);
    Check(ok, path + ": tinygltf cannot load it: " + err);
    Check(warn.empty(), path + ": tinygltf warnings: " + warn);
    return ok;
}

// Floats of a float accessor with `components` per element (stride honoured).
std::vector<float> ReadFloats(const tinygltf::Model& m, int accessorIndex, int components, const std::string& what) {
    std::vector<float> out;
    if (accessorIndex < 0 || accessorIndex >= static_cast<int>(m.accessors.size())) {
        Fail(what + ": accessor index out of range");
        return out;
    }
    const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(accessorIndex)];
    Check(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT, what + ": not float");
    Check(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) == components,
          what + ": wrong element type");
    const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::vector<unsigned char>& data = m.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : static_cast<std::size_t>(components) * 4;
    const std::size_t start = view.byteOffset + a.byteOffset;
    if (start + (a.count == 0 ? 0 : (a.count - 1) * stride + static_cast<std::size_t>(components) * 4) > data.size()) {
        Fail(what + ": accessor runs past its buffer");
        return out;
    }
    out.resize(a.count * static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < a.count; ++i) {
        std::memcpy(&out[i * static_cast<std::size_t>(components)], &data[start + i * stride],
                    static_cast<std::size_t>(components) * 4);
    }
    return out;
}

std::vector<std::uint32_t> ReadIndices(const tinygltf::Model& m, int accessorIndex, const std::string& what) {
    std::vector<std::uint32_t> out;
    if (accessorIndex < 0) {
        Fail(what + ": no indices");
        return out;
    }
    const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(accessorIndex)];
    const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::vector<unsigned char>& data = m.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t start = view.byteOffset + a.byteOffset;
    const std::size_t size = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 4;
    Check(a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
              a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
          what + ": indices are not unsigned short/int");
    if (start + a.count * size > data.size()) {
        Fail(what + ": indices run past their buffer");
        return out;
    }
    for (std::size_t i = 0; i < a.count; ++i) {
        if (size == 2) {
            std::uint16_t v;
            std::memcpy(&v, &data[start + i * 2], 2);
            out.push_back(v);
        } else {
            std::uint32_t v;
            std::memcpy(&v, &data[start + i * 4], 4);
            out.push_back(v);
        }
    }
    return out;
}

V3 At3(const std::vector<float>& f, std::size_t i) { return {f[i * 3], f[i * 3 + 1], f[i * 3 + 2]}; }

// A triangle primitive read back: positions, normals, uvs, tangents (if any), indices.
struct Geometry {
    std::vector<float> position, normal, uv, tangent;
    std::vector<std::uint32_t> index;
    std::size_t Vertices() const { return position.size() / 3; }
    std::size_t Triangles() const { return index.size() / 3; }
};

Geometry ReadPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& p, bool needTangents, const std::string& what) {
    Geometry g;
    Check(p.mode == TINYGLTF_MODE_TRIANGLES, what + ": not a triangle list");
    for (const char* name : {"POSITION", "NORMAL", "TEXCOORD_0"}) {
        Check(p.attributes.count(name) == 1, what + ": no " + name);
    }
    if (needTangents) Check(p.attributes.count("TANGENT") == 1, what + ": no TANGENT");
    if (p.attributes.count("POSITION") == 0 || p.attributes.count("NORMAL") == 0 || p.attributes.count("TEXCOORD_0") == 0) {
        return g;
    }
    g.position = ReadFloats(m, p.attributes.at("POSITION"), 3, what + " POSITION");
    g.normal = ReadFloats(m, p.attributes.at("NORMAL"), 3, what + " NORMAL");
    g.uv = ReadFloats(m, p.attributes.at("TEXCOORD_0"), 2, what + " TEXCOORD_0");
    if (p.attributes.count("TANGENT") == 1) g.tangent = ReadFloats(m, p.attributes.at("TANGENT"), 4, what + " TANGENT");
    g.index = ReadIndices(m, p.indices, what);
    const std::size_t n = g.Vertices();
    Check(g.normal.size() == n * 3 && g.uv.size() == n * 2 && (g.tangent.empty() || g.tangent.size() == n * 4),
          what + ": attribute counts differ");
    Check(g.index.size() % 3 == 0 && !g.index.empty(), what + ": index count is not a positive multiple of 3");
    for (std::uint32_t i : g.index) {
        if (i >= n) {
            Fail(what + ": index out of range");
            break;
        }
    }
    // POSITION min/max must be present and right (glTF requires them).
    const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))];
    Check(a.minValues.size() == 3 && a.maxValues.size() == 3, what + ": POSITION has no min/max");
    if (a.minValues.size() == 3 && a.maxValues.size() == 3) {
        for (int c = 0; c < 3; ++c) {
            float lo = 1e30f, hi = -1e30f;
            for (std::size_t i = 0; i < n; ++i) {
                lo = std::min(lo, g.position[i * 3 + static_cast<std::size_t>(c)]);
                hi = std::max(hi, g.position[i * 3 + static_cast<std::size_t>(c)]);
            }
            Check(static_cast<float>(a.minValues[static_cast<std::size_t>(c)]) == lo &&
                      static_cast<float>(a.maxValues[static_cast<std::size_t>(c)]) == hi,
                  what + ": POSITION min/max do not match the data");
        }
    }
    return g;
}

// Unit normals; unit tangents orthogonal to them with w = +-1.
void CheckFrames(const Geometry& g, const std::string& what) {
    double worstNormal = 0, worstTangent = 0, worstDot = 0;
    bool badW = false;
    for (std::size_t i = 0; i < g.Vertices(); ++i) {
        const V3 n = At3(g.normal, i);
        worstNormal = std::max(worstNormal, std::fabs(Length(n) - 1.0));
        if (g.tangent.empty()) continue;
        const V3 t{g.tangent[i * 4], g.tangent[i * 4 + 1], g.tangent[i * 4 + 2]};
        worstTangent = std::max(worstTangent, std::fabs(Length(t) - 1.0));
        worstDot = std::max(worstDot, std::fabs(Dot(n, t)));
        const float w = g.tangent[i * 4 + 3];
        badW = badW || (w != 1.0f && w != -1.0f);
    }
    Check(worstNormal < 1e-5, what + ": a normal is not unit length (off by " + std::to_string(worstNormal) + ")");
    Check(worstTangent < 1e-5, what + ": a tangent is not unit length (off by " + std::to_string(worstTangent) + ")");
    Check(worstDot < 1e-5, what + ": a tangent is not orthogonal to its normal (dot " + std::to_string(worstDot) + ")");
    Check(!badW, what + ": a tangent's w is not +1 or -1");
}

// Counter-clockwise front faces: each triangle's geometric normal agrees with its vertex normals.
// With tangents: tangent = direction of increasing u, and cross(n, t) * w = direction of decreasing
// v (glTF's bitangent, where normal maps put +Y).
void CheckTriangles(const Geometry& g, const std::string& what) {
    int wrongWinding = 0, degenerate = 0, wrongTangent = 0, wrongHandedness = 0;
    for (std::size_t t = 0; t < g.Triangles(); ++t) {
        const std::uint32_t i[3] = {g.index[t * 3], g.index[t * 3 + 1], g.index[t * 3 + 2]};
        const V3 p0 = At3(g.position, i[0]), p1 = At3(g.position, i[1]), p2 = At3(g.position, i[2]);
        const V3 e1 = p1 - p0, e2 = p2 - p0;
        const V3 face = Cross(e1, e2);
        if (Length(face) < 1e-12) {
            ++degenerate;
            continue;
        }
        for (std::uint32_t k : i) {
            if (Dot(face, At3(g.normal, k)) <= 0) {
                ++wrongWinding;
                break;
            }
        }
        if (g.tangent.empty()) continue;
        // Solve e = du * dPdu + dv * dPdv for the triangle's uv derivatives.
        const double du1 = g.uv[i[1] * 2] - g.uv[i[0] * 2], dv1 = g.uv[i[1] * 2 + 1] - g.uv[i[0] * 2 + 1];
        const double du2 = g.uv[i[2] * 2] - g.uv[i[0] * 2], dv2 = g.uv[i[2] * 2 + 1] - g.uv[i[0] * 2 + 1];
        const double det = du1 * dv2 - du2 * dv1;
        if (std::fabs(det) < 1e-12) continue;
        const V3 dPdu = (e1 * dv2 - e2 * dv1) * (1.0 / det);
        const V3 dPdv = (e2 * du1 - e1 * du2) * (1.0 / det);
        for (std::uint32_t k : i) {
            const V3 n = At3(g.normal, k);
            const V3 tan{g.tangent[k * 4], g.tangent[k * 4 + 1], g.tangent[k * 4 + 2]};
            const V3 bitangent = Cross(n, tan) * g.tangent[k * 4 + 3];
            if (Dot(tan, dPdu) <= 0) ++wrongTangent;
            if (Dot(bitangent, dPdv * -1.0) <= 0) ++wrongHandedness;
        }
    }
    Check(degenerate == 0, what + ": " + std::to_string(degenerate) + " degenerate triangles");
    Check(wrongWinding == 0, what + ": " + std::to_string(wrongWinding) + " triangles are not counter-clockwise around their normals");
    Check(wrongTangent == 0, what + ": " + std::to_string(wrongTangent) + " tangents do not point towards increasing u");
    Check(wrongHandedness == 0, what + ": " + std::to_string(wrongHandedness) +
                                    " bitangents (cross(n, t) * w) do not point towards decreasing v");
}

// Closed, consistently oriented surface: after welding equal positions, every directed edge
// appears exactly once and its reverse exactly once.
void CheckClosed(const Geometry& g, const std::string& what) {
    std::map<std::tuple<float, float, float>, std::uint32_t> weld;
    std::vector<std::uint32_t> id(g.Vertices());
    for (std::size_t i = 0; i < g.Vertices(); ++i) {
        const auto key = std::make_tuple(g.position[i * 3] + 0.0f, g.position[i * 3 + 1] + 0.0f, g.position[i * 3 + 2] + 0.0f);
        id[i] = weld.emplace(key, static_cast<std::uint32_t>(weld.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < g.Triangles(); ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = id[g.index[t * 3 + static_cast<std::size_t>(e)]];
            const std::uint32_t b = id[g.index[t * 3 + static_cast<std::size_t>((e + 1) % 3)]];
            ++edges[{a, b}];
        }
    }
    int bad = 0;
    for (const auto& [edge, count] : edges) {
        const auto reverse = edges.find({edge.second, edge.first});
        if (count != 1 || reverse == edges.end() || reverse->second != 1) ++bad;
    }
    Check(bad == 0, what + ": not closed/consistently oriented (" + std::to_string(bad) + " bad edges)");
}

// Outward faces of a convex volume: every face normal points away from an interior point.
void CheckOutward(const Geometry& g, V3 inside, const std::string& what) {
    int inward = 0;
    for (std::size_t t = 0; t < g.Triangles(); ++t) {
        const V3 p0 = At3(g.position, g.index[t * 3]), p1 = At3(g.position, g.index[t * 3 + 1]),
                 p2 = At3(g.position, g.index[t * 3 + 2]);
        const V3 centroid = (p0 + p1 + p2) * (1.0 / 3.0);
        if (Dot(Cross(p1 - p0, p2 - p0), centroid - inside) <= 0) ++inward;
    }
    Check(inward == 0, what + ": " + std::to_string(inward) + " faces point inwards");
}

// ---- node transforms (glTF column-vector convention, column-major 4x4) ------------------------------

using M4 = std::array<double, 16>;

M4 Multiply(const M4& a, const M4& b) {
    M4 r{};
    for (int c = 0; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[static_cast<std::size_t>(k * 4 + rr)] * b[static_cast<std::size_t>(c * 4 + k)];
            r[static_cast<std::size_t>(c * 4 + rr)] = s;
        }
    return r;
}

M4 LocalMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        M4 m{};
        std::copy(n.matrix.begin(), n.matrix.end(), m.begin());
        return m;
    }
    const double tx = n.translation.size() == 3 ? n.translation[0] : 0, ty = n.translation.size() == 3 ? n.translation[1] : 0,
                 tz = n.translation.size() == 3 ? n.translation[2] : 0;
    const double qx = n.rotation.size() == 4 ? n.rotation[0] : 0, qy = n.rotation.size() == 4 ? n.rotation[1] : 0,
                 qz = n.rotation.size() == 4 ? n.rotation[2] : 0, qw = n.rotation.size() == 4 ? n.rotation[3] : 1;
    const double sx = n.scale.size() == 3 ? n.scale[0] : 1, sy = n.scale.size() == 3 ? n.scale[1] : 1,
                 sz = n.scale.size() == 3 ? n.scale[2] : 1;
    const double r[9] = {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qz * qw),     2 * (qx * qz - qy * qw),
                         2 * (qx * qy - qz * qw),     1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + qx * qw),
                         2 * (qx * qz + qy * qw),     2 * (qy * qz - qx * qw),     1 - 2 * (qx * qx + qy * qy)};
    // Columns: R * S, then translation.
    return {r[0] * sx, r[1] * sx, r[2] * sx, 0, r[3] * sy, r[4] * sy, r[5] * sy, 0,
            r[6] * sz, r[7] * sz, r[8] * sz, 0, tx, ty, tz, 1};
}

V3 TransformPoint(const M4& m, V3 p) {
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

// ---- images ------------------------------------------------------------------------------------------

struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    unsigned char At(int x, int y, int c) const {
        return rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4 +
                    static_cast<std::size_t>(c)];
    }
};

Png LoadPng(const std::string& path) {
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 4);
    Check(data != nullptr, path + ": cannot load");
    if (data == nullptr) return png;
    Check(channels == 4, path + ": not RGBA");
    png.rgba.assign(data, data + static_cast<std::size_t>(png.width) * static_cast<std::size_t>(png.height) * 4);
    stbi_image_free(data);
    return png;
}

Png FromGltfImage(const tinygltf::Image& image) {
    Png png;
    png.width = image.width;
    png.height = image.height;
    Check(image.component == 4 && image.bits == 8, image.uri + ": not 8-bit RGBA as loaded by tinygltf");
    png.rgba = image.image;
    return png;
}

// ---- the checks ----------------------------------------------------------------------------------

void CheckMaterialTextures(const tinygltf::Model& m, const tinygltf::Material& mat) {
    const std::string what = "material " + mat.name;
    const int albedo = mat.pbrMetallicRoughness.baseColorTexture.index;
    const int normal = mat.normalTexture.index;
    Check(mat.extras.Has("fxportSpecularMap") && mat.extras.Get("fxportSpecularMap").IsInt(),
          what + ": no extras.fxportSpecularMap");
    const int specular = mat.extras.Has("fxportSpecularMap") ? mat.extras.Get("fxportSpecularMap").GetNumberAsInt() : -1;
    const int count = static_cast<int>(m.textures.size());
    if (albedo < 0 || albedo >= count || normal < 0 || normal >= count || specular < 0 || specular >= count) {
        Fail(what + ": a texture index is missing or out of range");
        return;
    }
    auto image = [&](int texture) {
        return FromGltfImage(m.images[static_cast<std::size_t>(m.textures[static_cast<std::size_t>(texture)].source)]);
    };
    const Png a = image(albedo), n = image(normal), s = image(specular);
    for (const Png* p : {&a, &n, &s}) Check(p->width == 256 && p->height == 256, what + ": textures are not 256x256");
    if (a.width != 256 || n.width != 256 || s.width != 256) return;
    bool opaque = true, specPowerOk = true, specBlueZero = true;
    double worstNormal = 0;
    int negativeZ = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            opaque = opaque && a.At(x, y, 3) == 255;
            const V3 v{n.At(x, y, 0) / 255.0 * 2 - 1, n.At(x, y, 1) / 255.0 * 2 - 1, n.At(x, y, 2) / 255.0 * 2 - 1};
            worstNormal = std::max(worstNormal, std::fabs(Length(v) - 1));
            negativeZ += v.z <= 0 ? 1 : 0;
            // The light shaders use pow(x, G * 255): power 0 would light everything; keep it >= 2.
            specPowerOk = specPowerOk && s.At(x, y, 1) >= 2;
            specBlueZero = specBlueZero && s.At(x, y, 2) == 0 && s.At(x, y, 3) == 255;
        }
    Check(opaque, what + ": albedo is not opaque");
    Check(worstNormal < 0.02, what + ": normal map texel not unit length (off by " + std::to_string(worstNormal) + ")");
    Check(negativeZ == 0, what + ": normal map texels pointing into the surface");
    Check(specPowerOk, what + ": specular power (G) below 2");
    Check(specBlueZero, what + ": specular map B != 0 or A != 255");
}

void CheckScene(const std::string& dir) {
    tinygltf::Model m;
    if (!LoadGltf(dir + "/Scene.gltf", m)) return;

    // Materials.
    const std::set<std::string> expectedMaterials = {"FloorTiles", "WallBricks", "Stone", "WoodCrate"};
    std::set<std::string> materials;
    for (const tinygltf::Material& mat : m.materials) {
        materials.insert(mat.name);
        CheckMaterialTextures(m, mat);
    }
    Check(materials == expectedMaterials, "Scene: materials are not FloorTiles, WallBricks, Stone, WoodCrate");

    // Normal-map orientation (glTF convention: +X = increasing u, +Y = towards the top of the
    // image), read off the floor tiles' known relief: each tile (128 texels, top-left at 0, 0) rises
    // from the grout, so its bevels lean outwards.
    for (const tinygltf::Material& mat : m.materials) {
        if (mat.name != "FloorTiles" || mat.normalTexture.index < 0) continue;
        const Png n = FromGltfImage(
            m.images[static_cast<std::size_t>(m.textures[static_cast<std::size_t>(mat.normalTexture.index)].source)]);
        if (n.width != 256) continue;
        Check(n.At(5, 64, 0) < 100 && n.At(122, 64, 0) > 156, "FloorTiles normal map: left/right bevels do not lean -X/+X");
        Check(n.At(64, 5, 1) > 156 && n.At(64, 122, 1) < 100,
              "FloorTiles normal map: top/bottom bevels do not lean +Y/-Y (green must point up the image)");
    }

    // Meshes and their primitives.
    const std::set<std::string> expectedMeshes = {"Floor", "WallBack", "WallSide", "WallFront", "Pillar", "Crate", "Sphere"};
    std::set<std::string> meshNames;
    std::vector<std::size_t> meshTriangles(m.meshes.size(), 0);
    std::vector<std::pair<V3, V3>> meshBounds(m.meshes.size());
    for (std::size_t i = 0; i < m.meshes.size(); ++i) {
        const tinygltf::Mesh& mesh = m.meshes[i];
        meshNames.insert(mesh.name);
        V3 lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
        for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
            const std::string what = "Scene mesh " + mesh.name + " primitive " + std::to_string(k);
            const tinygltf::Primitive& p = mesh.primitives[k];
            Check(p.material >= 0 && p.material < static_cast<int>(m.materials.size()), what + ": no material");
            const Geometry g = ReadPrimitive(m, p, true, what);
            CheckFrames(g, what);
            CheckTriangles(g, what);
            meshTriangles[i] += g.Triangles();
            for (std::size_t v = 0; v < g.Vertices(); ++v) {
                const V3 q = At3(g.position, v);
                lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
                hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
            }
        }
        meshBounds[i] = {lo, hi};
    }
    Check(meshNames == expectedMeshes, "Scene: unexpected mesh names");
    for (const tinygltf::Mesh& mesh : m.meshes) {
        if (mesh.name == "Pillar") Check(mesh.primitives.size() == 2, "Scene: Pillar should have 2 parts");
    }

    // Node tree: one root, a tree (each node has one parent), depth >= 3, TRS used.
    Check(m.scenes.size() == 1 && m.defaultScene == 0, "Scene: expected exactly one (default) scene");
    if (m.scenes.empty() || m.scenes[0].nodes.size() != 1) {
        Fail("Scene: the scene should have exactly one root node");
        return;
    }
    std::vector<int> parent(m.nodes.size(), -1);
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
        for (int c : m.nodes[i].children) {
            Check(parent[static_cast<std::size_t>(c)] == -1, "Scene: node " + m.nodes[static_cast<std::size_t>(c)].name + " has two parents");
            parent[static_cast<std::size_t>(c)] = static_cast<int>(i);
        }
    const int root = m.scenes[0].nodes[0];
    Check(m.nodes[static_cast<std::size_t>(root)].name == "Scene", "Scene: root node is not named Scene");
    bool rotated = false, nonUniform = false, nested = false;
    std::size_t drawnTriangles = 0;
    std::vector<M4> world(m.nodes.size());
    std::vector<int> stack = {root};
    std::vector<int> depth(m.nodes.size(), 0);
    std::size_t visited = 0;
    const V3 pointLight{0, 5, 0}, spotLight{0, 15, 0};
    double lowestY = 1e30;
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        ++visited;
        const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(n)];
        const int up = parent[static_cast<std::size_t>(n)];
        world[static_cast<std::size_t>(n)] = up < 0 ? LocalMatrix(node) : Multiply(world[static_cast<std::size_t>(up)], LocalMatrix(node));
        rotated = rotated || node.rotation.size() == 4;
        nonUniform = nonUniform || (node.scale.size() == 3 && (node.scale[0] != node.scale[1] || node.scale[1] != node.scale[2]));
        if (up >= 0) depth[static_cast<std::size_t>(n)] = depth[static_cast<std::size_t>(up)] + 1;
        if (node.mesh >= 0) {
            nested = nested || depth[static_cast<std::size_t>(n)] >= 2;
            drawnTriangles += meshTriangles[static_cast<std::size_t>(node.mesh)];
            // World-space bounds of the node's mesh (corners of its local box).
            const auto& [lo, hi] = meshBounds[static_cast<std::size_t>(node.mesh)];
            V3 wlo{1e30, 1e30, 1e30}, whi{-1e30, -1e30, -1e30};
            for (int c = 0; c < 8; ++c) {
                const V3 corner{(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
                const V3 w = TransformPoint(world[static_cast<std::size_t>(n)], corner);
                wlo = {std::min(wlo.x, w.x), std::min(wlo.y, w.y), std::min(wlo.z, w.z)};
                whi = {std::max(whi.x, w.x), std::max(whi.y, w.y), std::max(whi.z, w.z)};
            }
            lowestY = std::min(lowestY, wlo.y);
            for (const V3& light : {pointLight, spotLight}) {
                const bool inside = light.x > wlo.x - 1 && light.x < whi.x + 1 && light.y > wlo.y - 1 &&
                                    light.y < whi.y + 1 && light.z > wlo.z - 1 && light.z < whi.z + 1;
                Check(!inside, "Scene: node " + node.name + " is within 1 unit of a light position");
            }
            if (node.name == "Floor") {
                Check(std::fabs(wlo.y) < 1e-6 && std::fabs(whi.y) < 1e-6, "Scene: the floor is not at y = 0");
                Check(whi.x - wlo.x >= 59.99 && whi.z - wlo.z >= 59.99, "Scene: the floor is not 60 x 60");
            }
        }
        for (int c : node.children) stack.push_back(c);
    }
    Check(visited == m.nodes.size(), "Scene: some nodes are not reachable from the root");
    Check(rotated, "Scene: no node has a rotation");
    Check(nonUniform, "Scene: no node has a non-uniform scale");
    Check(nested, "Scene: no mesh node below depth 2 (hierarchy not exercised)");
    Check(lowestY > -1e-4, "Scene: geometry below the floor");
    Check(drawnTriangles >= 2000 && drawnTriangles <= 20000,
          "Scene: " + std::to_string(drawnTriangles) + " triangles drawn (expected a few thousand)");
    std::printf("Scene: %zu meshes, %zu nodes, %zu materials, %zu triangles drawn\n", m.meshes.size(), m.nodes.size(),
                m.materials.size(), drawnTriangles);
}

// One mesh, one primitive, under a single root node with no transform; closed, outward.
Geometry CheckLightVolume(const std::string& dir, const std::string& name, V3 inside) {
    tinygltf::Model m;
    Geometry g;
    if (!LoadGltf(dir + "/" + name + ".gltf", m)) return g;
    Check(m.meshes.size() == 1 && m.meshes[0].primitives.size() == 1, name + ": expected one mesh with one primitive");
    Check(m.nodes.size() == 1 && m.nodes[0].mesh == 0 && m.nodes[0].translation.empty() && m.nodes[0].rotation.empty() &&
              m.nodes[0].scale.empty() && m.nodes[0].matrix.empty(),
          name + ": expected one untransformed node");
    if (m.meshes.empty() || m.meshes[0].primitives.empty()) return g;
    g = ReadPrimitive(m, m.meshes[0].primitives[0], false, name);
    CheckFrames(g, name);
    CheckTriangles(g, name);
    CheckClosed(g, name);
    CheckOutward(g, inside, name);
    std::printf("%s: %zu vertices, %zu triangles\n", name.c_str(), g.Vertices(), g.Triangles());
    return g;
}

void CheckLightVolumes(const std::string& dir) {
    // PointLight.World() = CreateScale(radius / 100) * CreateTranslation(position): radius 100.
    const Geometry sphere = CheckLightVolume(dir, "PointLightGeometry", {0, 0, 0});
    double worst = 0;
    for (std::size_t i = 0; i < sphere.Vertices(); ++i) worst = std::max(worst, std::fabs(Length(At3(sphere.position, i)) - 100.0));
    Check(sphere.Vertices() > 0 && worst < 1e-3, "PointLightGeometry: vertices not on the radius-100 sphere");

    // SpotLight world = Scale(2 tan(FOV/2) far, same, far) * Rotation(-Z -> direction) * Translation:
    // apex at the origin, axis -Z, length 1, base radius 0.5 (vertices just outside it).
    const Geometry cone = CheckLightVolume(dir, "SpotLightGeometry", {0, 0, -0.5});
    bool apex = false, shape = true;
    double minBase = 1e30, maxBase = 0;
    for (std::size_t i = 0; i < cone.Vertices(); ++i) {
        const V3 p = At3(cone.position, i);
        apex = apex || Length(p) == 0.0;
        shape = shape && p.z <= 0.0 && p.z >= -1.0 && std::hypot(p.x, p.y) <= -p.z * 0.51 + 1e-9;
        if (p.z == -1.0 && std::hypot(p.x, p.y) > 0) {
            minBase = std::min(minBase, std::hypot(p.x, p.y));
            maxBase = std::max(maxBase, std::hypot(p.x, p.y));
        }
    }
    Check(apex, "SpotLightGeometry: no vertex at the apex (origin)");
    Check(shape, "SpotLightGeometry: vertices outside the cone z in [-1, 0], r <= 0.51 * -z");
    // The base polygon's edges must enclose the radius-0.5 circle: inradius = R cos(pi / N) >= 0.5.
    Check(minBase >= 0.5 && maxBase <= 0.51, "SpotLightGeometry: base radius not in [0.5, 0.51]");
}

void CheckLightTextures(const std::string& dir) {
    for (const char* name : {"SpotCookie", "SquareCookie"}) {
        const Png p = LoadPng(dir + "/" + name + ".png");
        if (p.width == 0) continue;
        Check(p.width == 256 && p.height == 256, std::string(name) + ": not 256x256");
        bool grey = true, darkBorder = true;
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                grey = grey && p.At(x, y, 0) == p.At(x, y, 1) && p.At(x, y, 1) == p.At(x, y, 2) && p.At(x, y, 3) == 255;
                if (x == 0 || y == 0 || x == p.width - 1 || y == p.height - 1) darkBorder = darkBorder && p.At(x, y, 0) == 0;
            }
        Check(grey, std::string(name) + ": not grey (R = G = B, A = 255)");
        Check(darkBorder, std::string(name) + ": border texels are not 0 (LinearClamp would leak light)");
    }
    const Png spot = LoadPng(dir + "/SpotCookie.png");
    if (spot.width == 256) Check(spot.At(128, 128, 0) > 200, "SpotCookie: centre is not bright");
    const Png square = LoadPng(dir + "/SquareCookie.png");
    if (square.width == 256) {
        Check(square.At(64, 64, 0) == 255 && square.At(192, 192, 0) == 255, "SquareCookie: panes are not fully lit");
        Check(square.At(128, 64, 0) == 0 && square.At(64, 128, 0) == 0, "SquareCookie: mullions are not dark");
    }

    const Png rn = LoadPng(dir + "/RandomNormals.png");
    if (rn.width == 0) return;
    Check(rn.width == 64 && rn.height == 64, "RandomNormals: not 64x64");
    double worst = 0;
    V3 sum{};
    std::set<std::uint32_t> distinct;
    for (int y = 0; y < rn.height; ++y)
        for (int x = 0; x < rn.width; ++x) {
            const V3 v{rn.At(x, y, 0) / 255.0 * 2 - 1, rn.At(x, y, 1) / 255.0 * 2 - 1, rn.At(x, y, 2) / 255.0 * 2 - 1};
            worst = std::max(worst, std::fabs(Length(v) - 1));
            sum = sum + v;
            distinct.insert(static_cast<std::uint32_t>(rn.At(x, y, 0)) << 16 | static_cast<std::uint32_t>(rn.At(x, y, 1)) << 8 |
                            rn.At(x, y, 2));
        }
    Check(worst < 0.015, "RandomNormals: decoded vectors not unit length (off by " + std::to_string(worst) + ")");
    Check(Length(sum * (1.0 / (rn.width * rn.height))) < 0.05, "RandomNormals: mean vector not near 0 (not uniform)");
    Check(distinct.size() > 4000, "RandomNormals: too few distinct vectors");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fxport_content_validate <content-dir>\n");
        return 2;
    }
    const std::string dir = argv[1];
    CheckScene(dir);
    CheckLightVolumes(dir);
    CheckLightTextures(dir);
    if (g_failures != 0) {
        std::printf("%d check(s) failed\n", g_failures);
        return 1;
    }
    std::printf("content OK\n");
    return 0;
}
