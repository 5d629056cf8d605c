// glTF 2.0 -> GltfModel: parsing with tinygltf (Debian's shared libtinygltf), then every accessor,
// index and reference checked before use, so a broken file ends in an ArgumentError, never a crash.
#include "helpers/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>

#include "fxport/graphics/errors.h"
#include "fxport/platform/file_reading.h"
#include "helpers/tangent_generation.h"

namespace fxport::detail {

Matrix gltfNodeMatrix(const std::vector<double>& matrix, const std::vector<double>& translation,
                      const std::vector<double>& rotation, const std::vector<double>& scale) {
    Matrix result = Matrix::Identity;
    float* x = result.data();
    if (matrix.size() == 16) {
        // glTF stores the column-vector matrix M column by column: m[c * 4 + r] = M[r][c]. XNA's
        // row-vector matrix is its transpose, X[r][c] = M[c][r] = m[r * 4 + c]: the same 16 numbers
        // in XNA's row-by-row memory order.
        for (int i = 0; i < 16; ++i) {
            x[i] = float(matrix[std::size_t(i)]);
        }
        return result;
    }
    double t[3] = {0, 0, 0}, s[3] = {1, 1, 1}, q[4] = {0, 0, 0, 1};
    if (translation.size() == 3) {
        std::copy(translation.begin(), translation.end(), t);
    }
    if (scale.size() == 3) {
        std::copy(scale.begin(), scale.end(), s);
    }
    if (rotation.size() == 4) {
        const double len = std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] +
                                     rotation[2] * rotation[2] + rotation[3] * rotation[3]);
        if (len > 0.0 && std::isfinite(len)) {
            for (int i = 0; i < 4; ++i) {
                q[i] = rotation[std::size_t(i)] / len;
            }
        }
    }
    const double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
    // R: the column-vector rotation matrix of the unit quaternion (glTF's and XNA's quaternions
    // are both Hamilton quaternions with the vector part first).
    const double r[3][3] = {
        {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)},
        {2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)},
        {2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)},
    };
    // glTF M = T * R * S (column vectors); XNA X = transpose(M) = S * transpose(R) * T in row-vector
    // terms: row i is the image of axis i, scale[i] * R's column i, then the translation row.
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) {
            x[row * 4 + col] = float(r[col][row] * s[row]);
        }
        x[12 + row] = float(t[row]);
    }
    return result;
}

BoundingSphere vertexBounds(const std::vector<ModelVertex>& vertices) {
    if (vertices.empty()) {
        return BoundingSphere();
    }
    Vector3 lo = vertices[0].Position, hi = lo;
    for (const ModelVertex& v : vertices) {
        lo = Vector3::Min(lo, v.Position);
        hi = Vector3::Max(hi, v.Position);
    }
    const Vector3 center = (lo + hi) * 0.5f;
    float radius = 0.0f;
    for (const ModelVertex& v : vertices) {
        radius = std::max(radius, Vector3::Distance(center, v.Position));
    }
    return BoundingSphere(center, radius);
}

namespace {

// Attributes are read into doubles: exact for every glTF component type, 32-bit indices included.
struct AccessorData {
    std::size_t count = 0;
    int components = 0;
    std::vector<double> values;  // count * components
};

int componentBytes(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

int typeComponents(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

// One component at `p`, normalised integers mapped to [0, 1] / [-1, 1] as glTF specifies.
double decodeComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(double(v) / 127.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        std::uint8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? double(v) / 255.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? double(v) / 65535.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? double(v) / 4294967295.0 : double(v);
    }
    default: {  // FLOAT (the caller checked the type)
        float v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    }
}

// Largest element count accepted for an accessor without a buffer view (all zeros): guards against
// a tiny file asking for gigabytes.
constexpr std::size_t kMaxZeroFilledElements = std::size_t(1) << 26;

// One primitive's vertices as addPrimitive builds them (normals and tangents empty when the file
// has none).
struct PrimitiveVertices {
    std::vector<Vector3> p, n;
    std::vector<Vector2> uv;
    std::vector<Vector4> t;
    bool hasNormals = false;
};

// glTF: "When normals are not specified, client implementations MUST calculate flat normals."
// Unshares the vertices so each triangle carries its own face normal; `triangles` becomes 0, 1, 2 ...
void unshareWithFlatNormals(PrimitiveVertices& v, std::vector<std::uint32_t>& triangles) {
    std::vector<Vector3> fp, fn;
    std::vector<Vector2> fuv;
    std::vector<Vector4> ft;
    for (std::size_t i = 0; i < triangles.size(); i += 3) {
        const Vector3 a = v.p[triangles[i]], b = v.p[triangles[i + 1]], c = v.p[triangles[i + 2]];
        Vector3 face = Vector3::Cross(b - a, c - a);
        const float length = face.Length();
        face = length > 0.0f && std::isfinite(length) ? face / length : Vector3::UnitZ;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t vertex = triangles[i + k];
            fp.push_back(v.p[vertex]);
            fn.push_back(face);
            fuv.push_back(v.uv[vertex]);
            if (!v.t.empty()) {
                ft.push_back(v.t[vertex]);
            }
        }
    }
    v.p = std::move(fp);
    v.n = std::move(fn);
    v.uv = std::move(fuv);
    v.t = std::move(ft);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        triangles[i] = std::uint32_t(i);
    }
}

// Appends the vertices (tangent frames from t, XNA's binormal) and the triangles, reversed from
// glTF's counter-clockwise fronts to XNA's clockwise ones, as one part of `mesh`.
void appendPart(GltfMesh& mesh, GltfPart part, const PrimitiveVertices& v, const std::vector<std::uint32_t>& triangles) {
    part.vertexOffset = int(mesh.vertices.size());
    part.numVertices = int(v.p.size());
    part.startIndex = int(mesh.indices.size());
    part.primitiveCount = int(triangles.size() / 3);
    for (std::size_t i = 0; i < v.p.size(); ++i) {
        ModelVertex vertex;
        vertex.Position = v.p[i];
        vertex.Normal = v.n[i];
        vertex.TextureCoordinate = v.uv[i];
        vertex.Tangent = Vector3(v.t[i].X, v.t[i].Y, v.t[i].Z);
        vertex.Binormal = Vector3::Cross(v.n[i], vertex.Tangent) * v.t[i].W;
        mesh.vertices.push_back(vertex);
    }
    for (std::size_t i = 0; i < triangles.size(); i += 3) {
        mesh.indices.insert(mesh.indices.end(), {triangles[i], triangles[i + 2], triangles[i + 1]});
    }
    mesh.parts.push_back(part);
}

class GltfReader {
public:
    GltfReader(const std::string& path, const tinygltf::Model& gltf, std::string warnings)
        : path_(path), gltf_(gltf), warnings_(std::move(warnings)) {}

    GltfModel read();

private:
    [[noreturn]] void fail(const std::string& message) const { throw ArgumentError(path_ + ": " + message); }

    std::string describeMesh(int meshIndex) const {
        const tinygltf::Mesh& mesh = gltf_.meshes[std::size_t(meshIndex)];
        return "mesh " + std::to_string(meshIndex) + (mesh.name.empty() ? "" : " '" + mesh.name + "'");
    }

    // Byte range [offset, offset + length) of buffer view `index`, checked against its buffer.
    const unsigned char* bufferViewBytes(int index, std::size_t& length, const std::string& what) const;
    AccessorData readAccessor(int index, const std::string& what) const;
    void applySparse(const tinygltf::Accessor& accessor, AccessorData& data, const std::string& what) const;

    int meshFor(int gltfMesh);
    int materialFor(int gltfMaterial, const std::string& what);
    int imageForTexture(int textureIndex, const std::string& what);
    void addPrimitive(GltfMesh& mesh, int meshIndex, int primitiveIndex);
    // addPrimitive's steps: the triangle list in glTF winding (indices or vertex order, strips and
    // fans unrolled; empty: nothing to draw), and the vertex attributes it indexes.
    std::vector<std::uint32_t> triangleList(const tinygltf::Primitive& primitive, int mode, std::size_t count,
                                            const std::string& what);
    PrimitiveVertices readVertices(const tinygltf::Primitive& primitive, const std::string& what);

    const std::string& path_;
    const tinygltf::Model& gltf_;
    std::string warnings_;
    GltfModel model_;
    std::map<int, int> meshes_;     // glTF mesh -> model_.meshes
    std::map<int, int> materials_;  // glTF material -> model_.materials
    std::map<int, int> images_;     // glTF image -> model_.images
};

const unsigned char* GltfReader::bufferViewBytes(int index, std::size_t& length, const std::string& what) const {
    if (index < 0 || std::size_t(index) >= gltf_.bufferViews.size()) {
        fail(what + ": buffer view " + std::to_string(index) + " does not exist");
    }
    const tinygltf::BufferView& view = gltf_.bufferViews[std::size_t(index)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= gltf_.buffers.size()) {
        fail(what + ": buffer view " + std::to_string(index) + " names buffer " + std::to_string(view.buffer) +
             ", which does not exist");
    }
    const std::vector<unsigned char>& data = gltf_.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
        fail(what + ": buffer view " + std::to_string(index) + " (bytes " + std::to_string(view.byteOffset) + " + " +
             std::to_string(view.byteLength) + ") lies outside buffer " + std::to_string(view.buffer) + " (" +
             std::to_string(data.size()) + " bytes)");
    }
    length = view.byteLength;
    return data.data() + view.byteOffset;
}

AccessorData GltfReader::readAccessor(int index, const std::string& what) const {
    if (index < 0 || std::size_t(index) >= gltf_.accessors.size()) {
        fail(what + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = gltf_.accessors[std::size_t(index)];
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    const int bytes = componentBytes(accessor.componentType);
    const int components = typeComponents(accessor.type);
    if (bytes == 0 || components == 0) {
        fail(where + ": unsupported component type " + std::to_string(accessor.componentType) + " or type " +
             std::to_string(accessor.type));
    }
    AccessorData data;
    data.count = accessor.count;
    data.components = components;
    const std::size_t elementBytes = std::size_t(bytes) * std::size_t(components);

    if (accessor.bufferView < 0) {
        if (accessor.count > kMaxZeroFilledElements) {
            fail(where + ": " + std::to_string(accessor.count) + " elements without a buffer view");
        }
        data.values.assign(accessor.count * std::size_t(components), 0.0);
    } else {
        std::size_t viewLength = 0;
        const unsigned char* view = bufferViewBytes(accessor.bufferView, viewLength, where);
        const tinygltf::BufferView& bufferView = gltf_.bufferViews[std::size_t(accessor.bufferView)];
        const std::size_t stride = bufferView.byteStride == 0 ? elementBytes : bufferView.byteStride;
        if (stride < elementBytes) {
            fail(where + ": byte stride " + std::to_string(stride) + " is smaller than an element (" +
                 std::to_string(elementBytes) + " bytes)");
        }
        if (accessor.count > 0) {
            const bool fits = accessor.byteOffset <= viewLength && elementBytes <= viewLength - accessor.byteOffset &&
                              accessor.count - 1 <= (viewLength - accessor.byteOffset - elementBytes) / stride;
            if (!fits) {
                fail(where + ": " + std::to_string(accessor.count) + " elements at offset " +
                     std::to_string(accessor.byteOffset) + " with stride " + std::to_string(stride) +
                     " overrun buffer view " + std::to_string(accessor.bufferView) + " (" +
                     std::to_string(viewLength) + " bytes)");
            }
        }
        data.values.resize(accessor.count * std::size_t(components));
        for (std::size_t i = 0; i < accessor.count; ++i) {
            const unsigned char* element = view + accessor.byteOffset + i * stride;
            for (int c = 0; c < components; ++c) {
                data.values[i * std::size_t(components) + std::size_t(c)] =
                    decodeComponent(element + c * bytes, accessor.componentType, accessor.normalized);
            }
        }
    }
    if (accessor.sparse.isSparse) {
        applySparse(accessor, data, where);
    }
    return data;
}

void GltfReader::applySparse(const tinygltf::Accessor& accessor, AccessorData& data, const std::string& what) const {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 0 || std::size_t(sparse.count) > data.count) {
        fail(what + ": sparse count " + std::to_string(sparse.count) + " exceeds the accessor's " +
             std::to_string(data.count) + " elements");
    }
    const std::size_t count = std::size_t(sparse.count);
    const int indexBytes = componentBytes(sparse.indices.componentType);
    if (indexBytes == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        fail(what + ": sparse indices have unsupported component type " +
             std::to_string(sparse.indices.componentType));
    }
    const std::size_t valueBytes = std::size_t(componentBytes(accessor.componentType)) * std::size_t(data.components);
    std::size_t indexViewLength = 0, valueViewLength = 0;
    const unsigned char* indexView = bufferViewBytes(sparse.indices.bufferView, indexViewLength, what + " sparse indices");
    const unsigned char* valueView = bufferViewBytes(sparse.values.bufferView, valueViewLength, what + " sparse values");
    const std::size_t indexOffset = std::size_t(std::max(sparse.indices.byteOffset, 0));
    const std::size_t valueOffset = std::size_t(std::max(sparse.values.byteOffset, 0));
    if (indexOffset > indexViewLength || count > (indexViewLength - indexOffset) / std::size_t(indexBytes) ||
        valueOffset > valueViewLength || count > (valueViewLength - valueOffset) / valueBytes) {
        fail(what + ": sparse data overruns its buffer views");
    }
    for (std::size_t i = 0; i < count; ++i) {
        const double target = decodeComponent(indexView + indexOffset + i * std::size_t(indexBytes),
                                              sparse.indices.componentType, false);
        if (target >= double(data.count)) {
            fail(what + ": sparse index " + std::to_string(std::size_t(target)) + " is out of range");
        }
        const unsigned char* element = valueView + valueOffset + i * valueBytes;
        const int bytes = componentBytes(accessor.componentType);
        for (int c = 0; c < data.components; ++c) {
            data.values[std::size_t(target) * std::size_t(data.components) + std::size_t(c)] =
                decodeComponent(element + c * bytes, accessor.componentType, accessor.normalized);
        }
    }
}

int GltfReader::imageForTexture(int textureIndex, const std::string& what) {
    if (textureIndex < 0 || std::size_t(textureIndex) >= gltf_.textures.size()) {
        fail(what + ": texture " + std::to_string(textureIndex) + " does not exist");
    }
    const int source = gltf_.textures[std::size_t(textureIndex)].source;
    if (source < 0 || std::size_t(source) >= gltf_.images.size()) {
        fail(what + ": texture " + std::to_string(textureIndex) +
             " has no image fxport can read (no 'source'; image extensions such as KHR_texture_basisu are not "
             "supported)");
    }
    if (auto it = images_.find(source); it != images_.end()) {
        return it->second;
    }
    const tinygltf::Image& image = gltf_.images[std::size_t(source)];
    GltfImage out;
    out.name = !image.name.empty() ? image.name
               : (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) ? image.uri
                                                                          : "image " + std::to_string(source);
    const std::string where = what + ": image " + std::to_string(source) + " '" + out.name + "'";
    if (image.image.empty() || image.width < 1 || image.height < 1) {
        fail(where + " could not be loaded" + (warnings_.empty() ? std::string() : " (" + warnings_ + ")"));
    }
    const int components = image.component;
    const int channelBytes = image.bits == 16 ? 2 : 1;
    if (components < 1 || components > 4 || (image.bits != 8 && image.bits != 16)) {
        fail(where + ": unsupported pixel layout (" + std::to_string(components) + " channels of " +
             std::to_string(image.bits) + " bits)");
    }
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    if (image.image.size() < pixels * std::size_t(components) * std::size_t(channelBytes)) {
        fail(where + ": pixel data is shorter than " + std::to_string(image.width) + "x" + std::to_string(image.height));
    }
    out.width = image.width;
    out.height = image.height;
    out.texels.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint8_t channel[4] = {0, 0, 0, 255};
        for (int c = 0; c < components; ++c) {
            const std::size_t at = (i * std::size_t(components) + std::size_t(c)) * std::size_t(channelBytes);
            // 16-bit channels: the nearest 8-bit value of v / 65535.
            channel[c] = channelBytes == 2
                             ? std::uint8_t((std::uint32_t(image.image[at]) | std::uint32_t(image.image[at + 1]) << 8) *
                                                255u / 65535u)
                             : image.image[at];
        }
        if (components <= 2) {  // grey (+ alpha)
            channel[3] = components == 2 ? channel[1] : 255;
            channel[1] = channel[2] = channel[0];
        }
        out.texels[i] = Color(channel[0], channel[1], channel[2], channel[3]);
    }
    const int index = int(model_.images.size());
    model_.images.push_back(std::move(out));
    images_[source] = index;
    return index;
}

int GltfReader::materialFor(int gltfMaterial, const std::string& what) {
    if (gltfMaterial < 0) {
        return -1;
    }
    if (std::size_t(gltfMaterial) >= gltf_.materials.size()) {
        fail(what + ": material " + std::to_string(gltfMaterial) + " does not exist");
    }
    if (auto it = materials_.find(gltfMaterial); it != materials_.end()) {
        return it->second;
    }
    const tinygltf::Material& material = gltf_.materials[std::size_t(gltfMaterial)];
    const std::string where =
        "material " + std::to_string(gltfMaterial) + (material.name.empty() ? "" : " '" + material.name + "'");
    GltfMaterial out;
    out.name = material.name;
    const std::vector<double>& base = material.pbrMetallicRoughness.baseColorFactor;
    if (base.size() == 4) out.baseColorFactor = Vector4(float(base[0]), float(base[1]), float(base[2]), float(base[3]));
    if (material.emissiveFactor.size() == 3)
        out.emissiveFactor = Vector3(float(material.emissiveFactor[0]), float(material.emissiveFactor[1]), float(material.emissiveFactor[2]));
    if (material.pbrMetallicRoughness.baseColorTexture.index >= 0) {
        out.texture = imageForTexture(material.pbrMetallicRoughness.baseColorTexture.index, where + " baseColorTexture");
    }
    if (material.normalTexture.index >= 0) {
        out.normalMap = imageForTexture(material.normalTexture.index, where + " normalTexture");
    }
    // Specular: KHR_materials_specular's specularTexture, else extras.fxportSpecularMap (a texture
    // index, or a textureInfo-like object with "index").
    auto textureIndexOf = [&](const tinygltf::Value& value, const std::string& field) -> int {
        if (value.IsNumber()) {
            return value.GetNumberAsInt();
        }
        if (value.IsObject() && value.Has("index") && value.Get("index").IsNumber()) {
            return value.Get("index").GetNumberAsInt();
        }
        fail(where + ": " + field + " must be a texture index");
    };
    if (auto ext = material.extensions.find("KHR_materials_specular");
        ext != material.extensions.end() && ext->second.IsObject() && ext->second.Has("specularTexture")) {
        const std::string field = "KHR_materials_specular.specularTexture";
        out.specularMap = imageForTexture(textureIndexOf(ext->second.Get("specularTexture"), field), where + " " + field);
    } else if (material.extras.IsObject() && material.extras.Has("fxportSpecularMap")) {
        const std::string field = "extras.fxportSpecularMap";
        out.specularMap = imageForTexture(textureIndexOf(material.extras.Get("fxportSpecularMap"), field), where + " " + field);
    }
    const int index = int(model_.materials.size());
    model_.materials.push_back(std::move(out));
    materials_[gltfMaterial] = index;
    return index;
}

void GltfReader::addPrimitive(GltfMesh& mesh, int meshIndex, int primitiveIndex) {
    const tinygltf::Primitive& primitive = gltf_.meshes[std::size_t(meshIndex)].primitives[std::size_t(primitiveIndex)];
    const std::string what = describeMesh(meshIndex) + ", primitive " + std::to_string(primitiveIndex);

    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        static const char* const names[] = {"points", "lines", "line loop", "line strip"};
        fail(what + ": unsupported primitive mode " + std::to_string(mode) +
             (mode >= 0 && mode < 4 ? std::string(" (") + names[mode] + ")" : std::string()) +
             "; a Model holds triangles only");
    }
    PrimitiveVertices v = readVertices(primitive, what);
    std::vector<std::uint32_t> triangles = triangleList(primitive, mode, v.p.size(), what);
    if (triangles.empty()) {
        return;
    }
    if (!v.hasNormals) {
        unshareWithFlatNormals(v, triangles);
    } else {
        for (Vector3& normal : v.n) {
            const float length = normal.Length();
            if (length > 0.0f && std::isfinite(length)) {
                normal /= length;
            }
        }
    }
    if (v.t.empty()) {
        v.t = generateTangents(v.p, v.n, v.uv, triangles);
    }
    if (v.p.size() > std::size_t(std::numeric_limits<int>::max()) - mesh.vertices.size() ||
        triangles.size() > std::size_t(std::numeric_limits<int>::max()) - mesh.indices.size()) {
        fail(describeMesh(meshIndex) + ": too many vertices or indices");
    }
    GltfPart part;
    part.material = materialFor(primitive.material, what);
    appendPart(mesh, part, v, triangles);
}

PrimitiveVertices GltfReader::readVertices(const tinygltf::Primitive& primitive, const std::string& what) {
    auto attribute = [&](const char* name) { return primitive.attributes.find(name); };
    const auto positionIt = attribute("POSITION");
    if (positionIt == primitive.attributes.end()) {
        fail(what + ": no POSITION attribute");
    }
    auto readVectors = [&](int accessor, const char* name, std::initializer_list<int> allowedComponents) {
        AccessorData data = readAccessor(accessor, what + " " + name);
        if (std::find(allowedComponents.begin(), allowedComponents.end(), data.components) == allowedComponents.end()) {
            fail(what + " " + name + ": accessor " + std::to_string(accessor) + " has " +
                 std::to_string(data.components) + " components per element");
        }
        return data;
    };
    const AccessorData positions = readVectors(positionIt->second, "POSITION", {3});
    const std::size_t count = positions.count;
    if (count > std::size_t(std::numeric_limits<int>::max() / 2)) {
        fail(what + ": too many vertices (" + std::to_string(count) + ")");
    }
    auto optional = [&](const char* name, std::initializer_list<int> allowed) {
        AccessorData data;
        if (auto it = attribute(name); it != primitive.attributes.end()) {
            data = readVectors(it->second, name, allowed);
            if (data.count != count) {
                fail(what + " " + name + ": " + std::to_string(data.count) + " elements, but POSITION has " +
                     std::to_string(count));
            }
        }
        return data;
    };
    const AccessorData normals = optional("NORMAL", {3});
    const AccessorData uvs = optional("TEXCOORD_0", {2});
    const AccessorData tangents = optional("TANGENT", {3, 4});

    auto vec3 = [](const AccessorData& data, std::size_t i) {
        const double* values = &data.values[i * std::size_t(data.components)];
        return Vector3(float(values[0]), float(values[1]), float(values[2]));
    };
    PrimitiveVertices v;
    v.hasNormals = normals.count != 0;
    v.p.resize(count);
    v.n.resize(count);
    v.uv.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        v.p[i] = vec3(positions, i);
        if (normals.count) {
            v.n[i] = vec3(normals, i);
        }
        if (uvs.count) {
            v.uv[i] = Vector2(float(uvs.values[i * 2]), float(uvs.values[i * 2 + 1]));
        }
    }
    if (tangents.count) {
        v.t.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const Vector3 xyz = vec3(tangents, i);
            const float w = tangents.components == 4 && tangents.values[i * 4 + 3] < 0.0 ? -1.0f : 1.0f;
            v.t[i] = Vector4(xyz, w);
        }
    }
    return v;
}

std::vector<std::uint32_t> GltfReader::triangleList(const tinygltf::Primitive& primitive, int mode, std::size_t count,
                                                    const std::string& what) {
    // Vertex order of the triangle list, before any unsharing.
    std::vector<std::uint32_t> order;
    if (primitive.indices >= 0) {
        const AccessorData indices = readAccessor(primitive.indices, what + " indices");
        const tinygltf::Accessor& accessor = gltf_.accessors[std::size_t(primitive.indices)];
        if (indices.components != 1 || accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
            accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
            accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) {
            fail(what + " indices: accessor " + std::to_string(primitive.indices) +
                 " is not a scalar of unsigned integers");
        }
        order.reserve(indices.count);
        for (double value : indices.values) {
            if (value >= double(count)) {
                fail(what + " indices: index " + std::to_string(std::uint64_t(value)) + " is out of range (" +
                     std::to_string(count) + " vertices)");
            }
            order.push_back(std::uint32_t(value));
        }
    } else {
        // Pushed rather than resized: GCC 12 at -O3 calls resize() here a null dereference.
        order.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            order.push_back(std::uint32_t(i));
        }
    }

    std::vector<std::uint32_t> triangles;  // glTF (counter-clockwise) winding
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (order.size() % 3 != 0) {
            fail(what + ": " + std::to_string(order.size()) + " vertices/indices do not make whole triangles");
        }
        triangles = std::move(order);
    } else if (order.size() >= 3) {
        for (std::size_t i = 0; i + 2 < order.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // glTF: {v[i], v[i + (1 + i % 2)], v[i + (2 - i % 2)]}
                triangles.insert(triangles.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
            } else {  // fan: {v[i + 1], v[i + 2], v[0]}
                triangles.insert(triangles.end(), {order[i + 1], order[i + 2], order[0]});
            }
        }
    }
    return triangles;
}

int GltfReader::meshFor(int gltfMesh) {
    if (auto it = meshes_.find(gltfMesh); it != meshes_.end()) {
        return it->second;
    }
    const tinygltf::Mesh& source = gltf_.meshes[std::size_t(gltfMesh)];
    GltfMesh mesh;
    mesh.name = source.name;
    for (std::size_t i = 0; i < source.primitives.size(); ++i) {
        addPrimitive(mesh, gltfMesh, int(i));
    }
    mesh.bounds = vertexBounds(mesh.vertices);
    for (const GltfPart& part : mesh.parts) {
        mesh.sixteenBitIndices = mesh.sixteenBitIndices && part.numVertices < 65536;
    }
    const int index = int(model_.meshes.size());
    model_.meshes.push_back(std::move(mesh));
    meshes_[gltfMesh] = index;
    return index;
}

GltfModel GltfReader::read() {
    const int nodeCount = int(gltf_.nodes.size());
    // The scene's root nodes.
    std::vector<int> roots;
    std::string sceneName;
    const int scene = gltf_.defaultScene >= 0 ? gltf_.defaultScene : (gltf_.scenes.empty() ? -1 : 0);
    if (scene >= int(gltf_.scenes.size())) {
        fail("default scene " + std::to_string(scene) + " does not exist");
    }
    if (scene >= 0) {
        roots = gltf_.scenes[std::size_t(scene)].nodes;
        sceneName = gltf_.scenes[std::size_t(scene)].name;
    } else {
        std::vector<bool> isChild(std::size_t(nodeCount), false);
        for (const tinygltf::Node& node : gltf_.nodes) {
            for (int child : node.children) {
                if (child >= 0 && child < nodeCount) {
                    isChild[std::size_t(child)] = true;
                }
            }
        }
        for (int i = 0; i < nodeCount; ++i) {
            if (!isChild[std::size_t(i)]) {
                roots.push_back(i);
            }
        }
    }

    int parentOfRoots = -1;
    if (roots.size() != 1) {
        GltfBone root;
        root.name = sceneName.empty() ? "Root" : sceneName;
        model_.bones.push_back(root);
        parentOfRoots = 0;
    }
    // Depth first, children in file order: (node, parent bone) pairs on a stack, pushed reversed.
    std::vector<bool> visited(std::size_t(nodeCount), false);
    std::vector<std::pair<int, int>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        stack.emplace_back(*it, parentOfRoots);
    }
    while (!stack.empty()) {
        const auto [nodeIndex, parent] = stack.back();
        stack.pop_back();
        if (nodeIndex < 0 || nodeIndex >= nodeCount) {
            fail("node " + std::to_string(nodeIndex) + " does not exist" +
                 (parent >= 0 ? " (child of bone '" + model_.bones[std::size_t(parent)].name + "')" : std::string()));
        }
        if (visited[std::size_t(nodeIndex)]) {
            fail("node " + std::to_string(nodeIndex) + " is reached twice: the node hierarchy is not a tree");
        }
        visited[std::size_t(nodeIndex)] = true;
        const tinygltf::Node& node = gltf_.nodes[std::size_t(nodeIndex)];
        const std::string what = "node " + std::to_string(nodeIndex) + (node.name.empty() ? "" : " '" + node.name + "'");
        if ((!node.matrix.empty() && node.matrix.size() != 16) || (!node.translation.empty() && node.translation.size() != 3) ||
            (!node.rotation.empty() && node.rotation.size() != 4) || (!node.scale.empty() && node.scale.size() != 3)) {
            fail(what + ": matrix/translation/rotation/scale has the wrong number of elements");
        }
        GltfBone bone;
        bone.name = node.name;
        bone.parent = parent;
        bone.transform = gltfNodeMatrix(node.matrix, node.translation, node.rotation, node.scale);
        if (node.mesh >= 0) {
            if (node.mesh >= int(gltf_.meshes.size())) {
                fail(what + ": mesh " + std::to_string(node.mesh) + " does not exist");
            }
            bone.mesh = meshFor(node.mesh);
        }
        const int boneIndex = int(model_.bones.size());
        model_.bones.push_back(std::move(bone));
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
            stack.emplace_back(*it, boneIndex);
        }
    }
    return std::move(model_);
}

// tinygltf's own file access would open a buffer or image URI naming a FIFO (and block forever),
// read any size, and expand the URI with wordexp(); these read through the checked reader and take
// the path as written.
tinygltf::FsCallbacks checkedFileAccess() {
    tinygltf::FsCallbacks callbacks{};
    // Exists at all (without opening it): a FIFO is then refused by ReadWholeFile, saying why.
    callbacks.FileExists = [](const std::string& file, void*) {
        std::error_code error;
        return std::filesystem::exists(file, error);
    };
    callbacks.ExpandFilePath = [](const std::string& file, void*) { return file; };
    callbacks.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err, const std::string& file, void*) {
        platform::FileBytes read = platform::readUntrustedFile(file);
        if (!read.ok()) {
            if (err) *err += read.error + "\n";
            return false;
        }
        *out = std::move(read.bytes);
        return true;
    };
    callbacks.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "fxport does not write glTF files\n";
        return false;
    };
    return callbacks;
}

}  // namespace

GltfModel loadGltf(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw ArgumentError(path + ": no such file");
    }
    platform::FileBytes file = platform::readUntrustedFile(path);
    if (!file.ok()) {
        throw ArgumentError(path + ": " + file.error);
    }
    std::vector<unsigned char> bytes = std::move(file.bytes);
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
        throw ArgumentError(path + ": file too large for tinygltf");
    }
    std::string baseDir = std::filesystem::path(path).parent_path().string();
    if (baseDir.empty()) {
        baseDir = ".";
    }

    tinygltf::Model gltf;
    std::string err, warn;
    bool ok = false;
    try {
        tinygltf::TinyGLTF loader;
        loader.SetFsCallbacks(checkedFileAccess());
        // Binary glTF by its magic, whatever the extension.
        if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
            ok = loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir);
        } else {
            ok = loader.LoadASCIIFromString(&gltf, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                            unsigned(bytes.size()), baseDir);
        }
    } catch (const std::exception& e) {
        throw ArgumentError(path + ": not a valid glTF file: " + e.what());
    }
    // tinygltf's messages are lines ending in '\n': one line, "; " between them.
    auto trim = [](const std::string& text) {
        std::string out;
        for (char c : text) {
            if (c == '\n') {
                out += "; ";
            } else {
                out += c;
            }
        }
        while (!out.empty() && (out.back() == ' ' || out.back() == ';')) {
            out.pop_back();
        }
        return out;
    };
    if (!ok) {
        throw ArgumentError(path + ": not a valid glTF file: " + (err.empty() ? "tinygltf failed" : trim(err)));
    }
    for (const std::string& required : gltf.extensionsRequired) {
        if (required != "KHR_materials_specular" && required != "KHR_mesh_quantization") {
            throw ArgumentError(path + ": requires the glTF extension " + required + ", which fxport does not support");
        }
    }
    return GltfReader(path, gltf, trim(warn)).read();
}

}  // namespace fxport::detail
