#include "gltf_writer.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace fxport::content {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

namespace {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kTriangles = 4;
constexpr int kLinear = 9729;
constexpr int kLinearMipmapLinear = 9987;
constexpr int kRepeat = 10497;

Json Array3(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

void WriteFile(const std::filesystem::path& path, const void* data, std::size_t bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

Vec4 RotationY(float degrees) {
    const double half = static_cast<double>(degrees) * 3.14159265358979323846 / 360.0;
    // Snap the rounding residue of exact angles (cos 90 degrees = 6e-17) to 0.
    const auto snap = [](double v) { return static_cast<float>(std::fabs(v) < 1e-9 ? 0.0 : v); };
    return {0.0f, snap(std::sin(half)), 0.0f, snap(std::cos(half))};
}

GltfWriter::GltfWriter(std::string baseName) : baseName_(std::move(baseName)) {
    root_["asset"] = {{"version", "2.0"}, {"generator", "fxport_content (content/tool)"}};
}

int GltfWriter::AddView(const void* data, std::size_t bytes, int target) {
    const std::size_t offset = buffer_.size();
    buffer_.resize(offset + bytes);
    std::memcpy(buffer_.data() + offset, data, bytes);
    buffer_.resize((buffer_.size() + 3) & ~std::size_t{3}, 0);  // keep the next view 4-byte aligned
    Json& views = root_["bufferViews"];
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
    return static_cast<int>(views.size()) - 1;
}

int GltfWriter::AddAccessor(int view, int componentType, std::size_t count, const char* type) {
    Json& accessors = root_["accessors"];
    accessors.push_back({{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
    return static_cast<int>(accessors.size()) - 1;
}

int GltfWriter::AddTexture(const std::string& uri) {
    if (!root_.contains("samplers")) {
        root_["samplers"].push_back({{"magFilter", kLinear}, {"minFilter", kLinearMipmapLinear},
                                     {"wrapS", kRepeat}, {"wrapT", kRepeat}});
    }
    Json& images = root_["images"];
    images.push_back({{"uri", uri}});
    Json& textures = root_["textures"];
    textures.push_back({{"sampler", 0}, {"source", images.size() - 1}});
    return static_cast<int>(textures.size()) - 1;
}

int GltfWriter::AddMaterial(const std::string& name, int albedoTexture, int normalTexture, int specularTexture) {
    Json& materials = root_["materials"];
    materials.push_back({
        {"name", name},
        {"pbrMetallicRoughness",
         {{"baseColorTexture", {{"index", albedoTexture}}}, {"metallicFactor", 0.0f}, {"roughnessFactor", 1.0f}}},
        {"normalTexture", {{"index", normalTexture}}},
        {"extras", {{"fxportSpecularMap", specularTexture}}},
    });
    return static_cast<int>(materials.size()) - 1;
}

int GltfWriter::AddMesh(const Mesh& mesh) {
    Json primitives = Json::array();
    for (const Primitive& p : mesh.primitives) {
        const std::size_t n = p.vertices.size();
        std::vector<float> positions, normals, uvs, tangents;
        Vec3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
        Vec3 hi{-lo.x, -lo.y, -lo.z};
        for (const Vertex& v : p.vertices) {
            positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
            normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
            uvs.insert(uvs.end(), {v.uv.x, v.uv.y});
            tangents.insert(tangents.end(), {v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w});
            lo = {std::fmin(lo.x, v.position.x), std::fmin(lo.y, v.position.y), std::fmin(lo.z, v.position.z)};
            hi = {std::fmax(hi.x, v.position.x), std::fmax(hi.y, v.position.y), std::fmax(hi.z, v.position.z)};
        }
        Json attributes;
        const int position = AddAccessor(AddView(positions.data(), positions.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
        root_["accessors"][static_cast<std::size_t>(position)]["min"] = Array3(lo);
        root_["accessors"][static_cast<std::size_t>(position)]["max"] = Array3(hi);
        attributes["POSITION"] = position;
        attributes["NORMAL"] = AddAccessor(AddView(normals.data(), normals.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
        attributes["TEXCOORD_0"] = AddAccessor(AddView(uvs.data(), uvs.size() * 4, kArrayBuffer), kFloat, n, "VEC2");
        if (mesh.writeTangents) {
            attributes["TANGENT"] = AddAccessor(AddView(tangents.data(), tangents.size() * 4, kArrayBuffer), kFloat, n, "VEC4");
        }

        int indices;
        if (n <= 65535) {  // 16-bit, as XNA's content pipeline prefers
            std::vector<std::uint16_t> small(p.indices.begin(), p.indices.end());
            indices = AddAccessor(AddView(small.data(), small.size() * 2, kElementArrayBuffer), kUnsignedShort,
                                  small.size(), "SCALAR");
        } else {
            indices = AddAccessor(AddView(p.indices.data(), p.indices.size() * 4, kElementArrayBuffer), kUnsignedInt,
                                  p.indices.size(), "SCALAR");
        }
        Json primitive = {{"attributes", attributes}, {"indices", indices}};
        if (p.material >= 0) primitive["material"] = p.material;
        primitive["mode"] = kTriangles;
        primitives.push_back(primitive);
    }
    Json& meshes = root_["meshes"];
    meshes.push_back({{"name", mesh.name}, {"primitives", primitives}});
    return static_cast<int>(meshes.size()) - 1;
}

int GltfWriter::AddNode(const std::string& name, int mesh, const NodeTransform& t) {
    Json node = {{"name", name}};
    if (mesh >= 0) node["mesh"] = mesh;
    if (t.translation.x != 0 || t.translation.y != 0 || t.translation.z != 0) node["translation"] = Array3(t.translation);
    if (t.rotation.x != 0 || t.rotation.y != 0 || t.rotation.z != 0 || t.rotation.w != 1) {
        node["rotation"] = Json::array({t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w});
    }
    if (t.scale.x != 1 || t.scale.y != 1 || t.scale.z != 1) node["scale"] = Array3(t.scale);
    Json& nodes = root_["nodes"];
    nodes.push_back(node);
    return static_cast<int>(nodes.size()) - 1;
}

void GltfWriter::AddChild(int parent, int child) {
    root_["nodes"][static_cast<std::size_t>(parent)]["children"].push_back(child);
}

void GltfWriter::SetScene(const std::string& name, const std::vector<int>& roots) {
    root_["scene"] = 0;
    Json scene = Json::object();
    scene["name"] = name;
    scene["nodes"] = roots;
    root_["scenes"] = Json::array();
    root_["scenes"].push_back(scene);
}

void GltfWriter::Write(const std::filesystem::path& dir) const {
    Json document = root_;
    const std::string binName = baseName_ + ".bin";
    Json buffer = Json::object();
    buffer["uri"] = binName;
    buffer["byteLength"] = buffer_.size();
    document["buffers"] = Json::array();
    document["buffers"].push_back(buffer);
    const std::string text = document.dump(1) + "\n";
    WriteFile(dir / (baseName_ + ".gltf"), text.data(), text.size());
    WriteFile(dir / binName, buffer_.data(), buffer_.size());
}

}  // namespace fxport::content
