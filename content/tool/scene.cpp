#include "scene.h"

#include <string>

#include "gltf_writer.h"
#include "image.h"
#include "material_textures.h"
#include "mesh_builders.h"

namespace fxport::content {

namespace {

constexpr int kTextureSize = 256;

// Writes a material's three maps and registers them; returns the material index.
int AddMaterial(GltfWriter& gltf, const std::filesystem::path& dir, const std::string& name,
                const MaterialTextures& textures) {
    const std::string albedo = name + "_Albedo.png";
    const std::string normal = name + "_Normal.png";
    const std::string specular = name + "_Specular.png";
    WritePng(textures.albedo, dir / albedo);
    WritePng(textures.normal, dir / normal);
    WritePng(textures.specular, dir / specular);
    // One statement per texture: argument evaluation order is unspecified, file order must not be.
    const int albedoTexture = gltf.AddTexture(albedo);
    const int normalTexture = gltf.AddTexture(normal);
    const int specularTexture = gltf.AddTexture(specular);
    return gltf.AddMaterial(name, albedoTexture, normalTexture, specularTexture);
}

Mesh SingleMaterialMesh(const std::string& name, int material) {
    Mesh mesh;
    mesh.name = name;
    mesh.primitives.emplace_back();
    mesh.primitives.back().material = material;
    return mesh;
}

NodeTransform At(float x, float y, float z, float yawDegrees = 0.0f, Vec3 scale = {1, 1, 1}) {
    NodeTransform t;
    t.translation = {x, y, z};
    if (yawDegrees != 0.0f) t.rotation = RotationY(yawDegrees);
    t.scale = scale;
    return t;
}

}  // namespace

void WriteScene(const std::filesystem::path& dir) {
    GltfWriter gltf("Scene");

    const int tiles = AddMaterial(gltf, dir, "FloorTiles", MakeFloorTiles(kTextureSize));
    const int bricks = AddMaterial(gltf, dir, "WallBricks", MakeWallBricks(kTextureSize));
    const int stone = AddMaterial(gltf, dir, "Stone", MakeStone(kTextureSize));
    const int wood = AddMaterial(gltf, dir, "WoodCrate", MakeWoodCrate(kTextureSize));

    // Texel density: tiles repeat every 4 units (2 x 2 tiles of 2 units), bricks every 2 units
    // (bricks 0.5 x 0.25), stone every 2 units.
    constexpr float kBrickRepeat = 2.0f;

    // Floor: 60 x 60 at y = 0, normal +Y, read with -Z as "up".
    Mesh floor = SingleMaterialMesh("Floor", tiles);
    {
        PatchDesc p;
        p.center = {0, 0, 0};
        p.axisU = {1, 0, 0};
        p.axisUp = {0, 0, -1};
        p.sizeU = p.sizeUp = 60.0f;
        p.cellsU = p.cellsUp = 20;
        p.uvBottomRight = {15.0f, 15.0f};
        AddPatch(floor.primitives.back(), p);
    }

    // Walls of a 14 x 14 courtyard (inner faces at x = +-7 and z = +-7), 0.5 thick. Back and side
    // walls are 8 high; the front wall (+Z, towards the usual camera) is a 1.2-high parapet.
    auto wallMesh = [&](const std::string& name, Vec3 size) {
        Mesh mesh = SingleMaterialMesh(name, bricks);
        AddBox(mesh.primitives.back(), {{0, 0, 0}, size, kBrickRepeat, 1.0f});
        return mesh;
    };
    const Mesh wallBack = wallMesh("WallBack", {15.0f, 8.0f, 0.5f});
    const Mesh wallSide = wallMesh("WallSide", {0.5f, 8.0f, 14.5f});
    const Mesh wallFront = wallMesh("WallFront", {14.0f, 1.2f, 0.5f});

    // Pillar: a stone shaft on a brick plinth under a brick capital; two parts (ModelMeshParts)
    // with different materials. 7.4 high, origin at its foot.
    Mesh pillar;
    pillar.name = "Pillar";
    pillar.primitives.resize(2);
    pillar.primitives[0].material = stone;
    AddCylinderSide(pillar.primitives[0], {{0, 0.5f, 0}, 0.45f, 6.4f, 24, 8, 1.0f, kBrickRepeat});
    pillar.primitives[1].material = bricks;
    AddBox(pillar.primitives[1], {{0, 0.25f, 0}, {1.3f, 0.5f, 1.3f}, kBrickRepeat, 0.0f});
    AddBox(pillar.primitives[1], {{0, 7.15f, 0}, {1.3f, 0.5f, 1.3f}, kBrickRepeat, 0.0f});

    // A unit crate (each face maps the whole crate texture), sized by its nodes' scale.
    Mesh crate = SingleMaterialMesh("Crate", wood);
    AddBox(crate.primitives.back(), {{0, 0, 0}, {1, 1, 1}, 0.0f, 0.0f});

    // A unit sphere (radius 1), sized by its nodes' scale.
    Mesh sphere = SingleMaterialMesh("Sphere", stone);
    AddUvSphere(sphere.primitives.back(), {{0, 0, 0}, 1.0f, 40, 20, 2.0f, 1.0f});

    const int floorMesh = gltf.AddMesh(floor);
    const int wallBackMesh = gltf.AddMesh(wallBack);
    const int wallSideMesh = gltf.AddMesh(wallSide);
    const int wallFrontMesh = gltf.AddMesh(wallFront);
    const int pillarMesh = gltf.AddMesh(pillar);
    const int crateMesh = gltf.AddMesh(crate);
    const int sphereMesh = gltf.AddMesh(sphere);

    // Node tree (bones): Scene -> Floor, Walls/*, Pillars/*, crates (one with a crate and one with a
    // sphere on top, as children), a plank (non-uniform scale), two spheres.
    const int root = gltf.AddNode("Scene", -1);
    gltf.AddChild(root, gltf.AddNode("Floor", floorMesh));

    const int walls = gltf.AddNode("Walls", -1);
    gltf.AddChild(root, walls);
    gltf.AddChild(walls, gltf.AddNode("WallBack", wallBackMesh, At(0, 4, -7.25f)));
    gltf.AddChild(walls, gltf.AddNode("WallLeft", wallSideMesh, At(-7.25f, 4, 0.25f)));
    gltf.AddChild(walls, gltf.AddNode("WallRight", wallSideMesh, At(7.25f, 4, 0.25f, 180.0f)));
    gltf.AddChild(walls, gltf.AddNode("WallFront", wallFrontMesh, At(0, 0.6f, 7.25f)));

    const int pillars = gltf.AddNode("Pillars", -1);
    gltf.AddChild(root, pillars);
    gltf.AddChild(pillars, gltf.AddNode("PillarLeft", pillarMesh, At(-5.0f, 0, -2.0f)));
    gltf.AddChild(pillars, gltf.AddNode("PillarRight", pillarMesh, At(5.0f, 0, -2.0f)));
    gltf.AddChild(pillars, gltf.AddNode("PillarBackLeft", pillarMesh, At(-2.5f, 0, -5.0f, 45.0f)));
    gltf.AddChild(pillars, gltf.AddNode("PillarBackRight", pillarMesh, At(2.5f, 0, -5.0f, 45.0f)));

    // 2-unit crate; the 1.2-unit crate on top is its child (local units are the parent's: scale
    // 0.6 and an offset of 0.8 put it on the parent's lid).
    const int crateLarge = gltf.AddNode("CrateLarge", crateMesh, At(2.6f, 1.0f, 1.4f, 25.0f, {2, 2, 2}));
    gltf.AddChild(root, crateLarge);
    gltf.AddChild(crateLarge, gltf.AddNode("CrateSmall", crateMesh, At(0.05f, 0.8f, -0.05f, 35.0f, {0.6f, 0.6f, 0.6f})));

    // 1.5-unit crate with a sphere of radius 0.6 resting on it (local scale 0.4, offset 0.9).
    const int crateLow = gltf.AddNode("CrateLow", crateMesh, At(-2.8f, 0.75f, -1.2f, 10.0f, {1.5f, 1.5f, 1.5f}));
    gltf.AddChild(root, crateLow);
    gltf.AddChild(crateLow, gltf.AddNode("SphereOnCrate", sphereMesh, At(0, 0.9f, 0, 0.0f, {0.4f, 0.4f, 0.4f})));

    gltf.AddChild(root, gltf.AddNode("Plank", crateMesh, At(-0.8f, 0.2f, 4.2f, -30.0f, {3.0f, 0.4f, 0.8f})));
    gltf.AddChild(root, gltf.AddNode("SphereFront", sphereMesh, At(-3.4f, 1.0f, 2.0f)));
    gltf.AddChild(root, gltf.AddNode("SphereBack", sphereMesh, At(1.6f, 1.3f, -3.0f, 0.0f, {1.3f, 1.3f, 1.3f})));

    gltf.SetScene("Scene", {root});
    gltf.Write(dir);
}

}  // namespace fxport::content
