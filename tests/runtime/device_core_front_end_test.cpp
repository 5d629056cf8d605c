// The device core under a front end, with no GL context: a GraphicsDevice over the recording
// backend (createDeviceOver, tests/runtime/recording_backend.h) driven through the entry
// points the D3D11 front end sits on (runtime/graphics/src/device/front_end_core.h) and XNA's
// DispatchCompute. Each test checks what reaches the backend -- the objects made and deleted, the
// bindings, the draw's parameters -- or that a call refused reaches it with nothing.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "device/front_end_core.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_2d_array.h"
#include "fxport/xlate/compiled_effect.h"
#include "recording_backend.h"

namespace fxport {
namespace {

using Calls = std::vector<std::string>;
using core::ByteBuffer;
using core::DrawArguments;
using core::InstancedStream;
using core::ShaderCode;

xlate::CompiledShader shaderOf(xlate::ShaderStage stage, const std::string& source) {
    xlate::CompiledShader s;
    s.profile.stage = stage;
    s.profile.major = 5;
    s.profile.name = "x_5_0";
    s.entryPoint = "Main";
    s.glsl = source;
    s.outputTargets = stage == xlate::ShaderStage::Pixel ? 1 : 0;
    return s;
}

xlate::VertexInput input(const std::string& semantic, int location) {
    xlate::VertexInput in;
    in.semantic = semantic;
    in.location = location;
    return in;
}

// Shaders 0 vertex (POSITION0 at 0, TEXCOORD0 at 1), 1 pixel, 2 hull, 3 domain, 4 compute
// (writing u0), 5 a vertex shader reading NORMAL0, 6 one the backend rejects, 7 a vertex shader
// writing three clip distances.
std::shared_ptr<const xlate::CompiledEffect> shaders() {
    auto effect = std::make_shared<xlate::CompiledEffect>();
    xlate::CompiledShader vs = shaderOf(xlate::ShaderStage::Vertex, "vertex");
    vs.inputs = {input("POSITION0", 0), input("TEXCOORD0", 1)};
    xlate::CompiledShader cs = shaderOf(xlate::ShaderStage::Compute, "compute");
    xlate::StorageBinding uav;
    uav.name = "Output";
    uav.slot = 0;
    uav.binding = 3;
    uav.writes = true;
    cs.storage = {uav};
    xlate::CompiledShader normals = shaderOf(xlate::ShaderStage::Vertex, "normals");
    normals.inputs = {input("POSITION0", 0), input("NORMAL0", 1)};
    xlate::CompiledShader clipping = shaderOf(xlate::ShaderStage::Vertex, "clipping");
    clipping.inputs = vs.inputs;
    clipping.clipDistances = 3;
    effect->shaders = {vs,
                       shaderOf(xlate::ShaderStage::Pixel, "pixel"),
                       shaderOf(xlate::ShaderStage::Hull, "hull"),
                       shaderOf(xlate::ShaderStage::Domain, "domain"),
                       cs,
                       normals,
                       shaderOf(xlate::ShaderStage::Pixel, "reject"),
                       clipping};
    return effect;
}

// A device over a recording backend, the test's shaders and buffers; `backend` stays readable.
struct Fixture {
    test::RecordingBackend* backend;
    std::unique_ptr<GraphicsDevice> device;
    std::shared_ptr<const xlate::CompiledEffect> effect = shaders();
    core::StreamLayout positions = core::streamLayoutOf(VertexDeclaration{{VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0)}});
    core::StreamLayout texcoords = core::streamLayoutOf(VertexDeclaration{{VertexElement(0, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0)}});

    explicit Fixture(PresentationParameters parameters = small()) {
        auto recording = std::make_unique<test::RecordingBackend>();
        backend = recording.get();
        device = createDeviceOver(std::move(recording), parameters);
    }
    static PresentationParameters small() {
        PresentationParameters p;
        p.BackBufferWidth = 64;
        p.BackBufferHeight = 32;
        return p;
    }
    std::unique_ptr<ShaderCode> shader(int index) {
        return std::make_unique<ShaderCode>(*device, effect, index, "test shader " + std::to_string(index));
    }
};

TEST(DeviceOverBackend, EveryObjectTheCoreMakesIsDeletedOnceWhenTheDeviceGoes) {
    std::shared_ptr<test::RecordingBackend::Objects> objects;
    {
        Fixture f;
        objects = f.backend->objects;
        EXPECT_EQ(f.backend->matching("adoptD3DConventions").size(), 1u);
        EXPECT_EQ(f.backend->matching("createTexture 2d 64x32").size(), 1u);  // the back buffer
        auto vs = f.shader(0), ps = f.shader(1);
        const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
        core::setShaderStages(*f.device, stages);
        ByteBuffer vertices(*f.device, 36, nullptr, false), instances(*f.device, 32, nullptr, true);
        core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}, {{&instances, 0, &f.texcoords}, 1}},
                          DrawArguments{PrimitiveType::TriangleList, 3});
        EXPECT_GE(objects->live.size(), 9u);  // buffers, textures, programs, pipeline, vertex array, framebuffer
        f.device.reset();  // before the resources: the device disposes what the program still holds
    }
    EXPECT_EQ(objects->live, std::set<BackendObject>{}) << "objects the core made and never deleted";
    EXPECT_EQ(objects->badDeletes, Calls{}) << "deletions of objects not made, or deleted twice";
}

// Array textures (D3D11's ArraySize > 1): one backend array, a layer's texels travel as the
// backend's `face`, views of a range and of one layer share the array's texels, a range outside
// the array is refused before the backend makes anything, and every object goes once.
TEST(FrontEndCore, ArrayTexturesAndTheirViewsReachTheBackendWithTheirRanges) {
    std::shared_ptr<test::RecordingBackend::Objects> objects;
    {
        Fixture f;
        objects = f.backend->objects;
        f.backend->take();
        Texture2DArray array(*f.device, 4, 2, 3, 2, SurfaceFormat::Color);
        const std::string name = std::to_string(array.backendObject());
        EXPECT_EQ(f.backend->take(), (Calls{"createArrayTexture 4x2 layers 3 levels 2 -> " + name}));
        const std::uint32_t texels[2] = {1, 2};
        array.setData(1, 2, nullptr, texels, sizeof texels);
        EXPECT_EQ(f.backend->matching("writeTexture " + name + " face 2 level 1").size(), 1u);
        EXPECT_THROW(array.setData(0, 3, nullptr, texels, sizeof texels), ArgumentError);
        Texture2DArray part(array, 1, 1, 1, 2);
        EXPECT_EQ(part.Width(), 2);
        EXPECT_EQ(part.Layers(), 2);
        EXPECT_EQ(f.backend->matching("createTextureView " + name + " array levels 1+1 layers 1+2").size(), 1u);
        RenderTarget2D slice(array, 2, 0);
        EXPECT_EQ(f.backend->matching("createTextureView " + name + " 2d levels 0+1 layers 2+1").size(), 1u);
        f.backend->take();
        EXPECT_THROW(Texture2DArray(array, 0, 1, 2, 2), ArgumentError);
        EXPECT_THROW(RenderTarget2D(array, 3, 0), ArgumentError);
        EXPECT_EQ(f.backend->take(), Calls{});
        EXPECT_THROW(Texture2DArray(*f.device, 4, 2, 0, 1, SurfaceFormat::Color), ArgumentError);
        EXPECT_THROW(Texture2DArray(*f.device, 4, 2, 1, 4, SurfaceFormat::Color), ArgumentError);  // a 4x2 chain has 3 levels
        EXPECT_EQ(f.backend->take(), Calls{});
    }
    EXPECT_EQ(objects->live, std::set<BackendObject>{}) << "objects the core made and never deleted";
    EXPECT_EQ(objects->badDeletes, Calls{}) << "deletions of objects not made, or deleted twice";
}

TEST(FrontEndCore, ByteBufferTransfersReachTheBackendAfterTheirRangeIsChecked) {
    Fixture f;
    ByteBuffer buffer(*f.device, 64, nullptr, true);
    ByteBuffer other(*f.device, 64, nullptr, false);
    const std::string name = std::to_string(buffer.backendObject()), otherName = std::to_string(other.backendObject());
    EXPECT_EQ(f.backend->matching("allocateBuffer " + name), Calls{"allocateBuffer " + name + " 64 filled streaming"});
    f.backend->take();
    const char bytes[16] = {};
    buffer.write(8, 16, bytes);
    char out[16];
    buffer.read(48, 16, out);
    buffer.copyFrom(other, 4, 40, 8);
    EXPECT_EQ(f.backend->take(), (Calls{"writeBuffer " + name + " 8 16", "readBuffer " + name + " 48 16",
                                        "copyBuffer " + otherName + "+4 -> " + name + "+40 8"}));
    EXPECT_THROW(buffer.write(60, 8, bytes), ArgumentError);
    EXPECT_THROW(buffer.read(64, 1, out), ArgumentError);
    EXPECT_THROW(buffer.copyFrom(other, 60, 0, 8), ArgumentError);
    ByteBuffer small(*f.device, 8, nullptr, false);
    f.backend->take();
    EXPECT_THROW(buffer.copyFrom(small), ArgumentError);
    EXPECT_EQ(f.backend->take(), Calls{}) << "a refused transfer reached the backend";
}

TEST(FrontEndCore, AnInstancedDrawFeedsEachStreamFromItsBindingWithItsStepRate) {
    Fixture f;
    auto vs = f.shader(0), ps = f.shader(1);
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer vertices(*f.device, 36, nullptr, false), instances(*f.device, 64, nullptr, true);
    const std::vector<InstancedStream> streams = {{{&vertices, 0, &f.positions}, 0}, {{&instances, 16, &f.texcoords}, 1}};
    DrawArguments a;
    a.count = 3;
    a.instances = 4;
    a.firstInstance = 1;
    f.backend->take();
    core::drawStreams(*f.device, streams, a);
    const Calls arrays = f.backend->matching("createVertexArray");
    ASSERT_EQ(arrays.size(), 1u);
    // POSITION0 (location 0) from binding 0, TEXCOORD0 (location 1) from binding 1, which steps per instance.
    EXPECT_EQ(arrays[0].substr(0, arrays[0].find(" ->")), "createVertexArray 2 attributes 0@0+0 1@1+0 divisors 0 1");
    const std::string vao = arrays[0].substr(arrays[0].find("-> ") + 3);
    EXPECT_EQ(f.backend->matching("setVertexBuffer"),
              (Calls{"setVertexBuffer " + vao + " 0 " + std::to_string(vertices.backendObject()) + " +0 stride 12",
                     "setVertexBuffer " + vao + " 1 " + std::to_string(instances.backendObject()) + " +16 stride 8"}));
    EXPECT_EQ(f.backend->matching("draw"), Calls{"draw 0 count 3 first 0 instances 4 from 1"});
    EXPECT_EQ(f.backend->matching("createPipeline").size(), 1u);
    // The same layout again: the vertex array and pipeline are reused, only the buffers and the draw are sent.
    f.backend->take();
    core::drawStreams(*f.device, streams, a);
    EXPECT_EQ(f.backend->matching("create"), Calls{});
    EXPECT_EQ(f.backend->matching("bindVertexArray"), Calls{});
    EXPECT_EQ(f.backend->matching("draw").size(), 1u);
}

// GL clips by a gl_ClipDistance only where its plane is enabled (llvmpipe clips regardless, so the
// pixel test in tests/d3d11 cannot see this): the draw enables as many as the last stage before the
// rasteriser writes, and the shadow sends a count once.
TEST(FrontEndCore, TheLastStageBeforeTheRasteriserSetsTheClipPlanes) {
    Fixture f;
    auto clipping = f.shader(7), plain = f.shader(0), ps = f.shader(1);
    ByteBuffer vertices(*f.device, 96, nullptr, false), texcoords(*f.device, 64, nullptr, false);
    const std::vector<InstancedStream> streams = {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}};
    auto drawWith = [&](const ShaderCode* vs) {
        const ShaderCode* stages[5] = {vs, ps.get(), nullptr, nullptr, nullptr};
        core::setShaderStages(*f.device, stages);
        core::drawStreams(*f.device, streams, DrawArguments{PrimitiveType::TriangleList, 3});
    };
    drawWith(plain.get());
    f.backend->take();
    drawWith(clipping.get());
    drawWith(clipping.get());
    EXPECT_EQ(f.backend->matching("setClipPlanes"), Calls{"setClipPlanes 3"});
    f.backend->take();
    drawWith(plain.get());
    EXPECT_EQ(f.backend->matching("setClipPlanes"), Calls{"setClipPlanes 0"});
}

TEST(FrontEndCore, AnIndexedDrawSetsItsIndexBufferOnceAndNamesIndexSizeAndBaseVertex) {
    Fixture f;
    auto vs = f.shader(0), ps = f.shader(1);
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer vertices(*f.device, 96, nullptr, false), texcoords(*f.device, 64, nullptr, false), indices(*f.device, 48, nullptr, false);
    const std::vector<InstancedStream> streams = {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}};
    DrawArguments a;
    a.type = PrimitiveType::TriangleStrip;
    a.count = 4;
    a.first = 6;
    a.baseVertex = 2;
    a.indices = &indices;
    a.indexSize = 4;
    f.backend->take();
    core::drawStreams(*f.device, streams, a);
    core::drawStreams(*f.device, streams, a);
    EXPECT_EQ(f.backend->matching("setIndexBuffer").size(), 1u);
    EXPECT_EQ(f.backend->matching("draw"), (Calls{"draw 1 count 4 first 6 indexed 4 base 2 instances 1 from 0",
                                                  "draw 1 count 4 first 6 indexed 4 base 2 instances 1 from 0"}));
}

TEST(FrontEndCore, ADrawWhoseLayoutLacksAShaderInputIsRefusedBeforeTheBackendMakesAnything) {
    Fixture f;
    auto vs = f.shader(5), ps = f.shader(1);  // reads NORMAL0
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer vertices(*f.device, 36, nullptr, false);
    f.backend->take();
    try {
        core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}}, DrawArguments{PrimitiveType::TriangleList, 3});
        FAIL() << "a draw without the vertex shader's NORMAL0 went through";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("NORMAL0"), std::string::npos) << e.what();
    }
    EXPECT_EQ(f.backend->matching("createVertexArray"), Calls{});
    EXPECT_EQ(f.backend->matching("draw"), Calls{});
    // Nothing to draw is no draw at all, not even its state.
    f.backend->take();
    core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}}, DrawArguments{PrimitiveType::TriangleList, 0});
    EXPECT_EQ(f.backend->take(), Calls{});
}

TEST(FrontEndCore, PatchDrawsNeedHullAndDomainShadersAndSayTheirControlPoints) {
    Fixture f;
    auto vs = f.shader(0), ps = f.shader(1), hs = f.shader(2), ds = f.shader(3);
    ByteBuffer vertices(*f.device, 36, nullptr, false), texcoords(*f.device, 24, nullptr, false);
    const std::vector<InstancedStream> streams = {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}};
    DrawArguments patches;
    patches.count = 3;
    patches.controlPoints = 3;
    const ShaderCode* plain[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, plain);
    EXPECT_THROW(core::drawStreams(*f.device, streams, patches), InvalidOperation);
    const ShaderCode* tessellated[5] = {vs.get(), ps.get(), nullptr, hs.get(), ds.get()};
    core::setShaderStages(*f.device, tessellated);
    f.backend->take();
    core::drawStreams(*f.device, streams, patches);
    EXPECT_EQ(f.backend->matching("draw"), Calls{"draw 0 count 3 first 0 instances 1 from 0 patches of 3"});
    patches.controlPoints = 33;
    EXPECT_THROW(core::drawStreams(*f.device, streams, patches), ArgumentError);
}

TEST(FrontEndCore, AShaderTheBackendRejectsIsAnInvalidOperationWithItsLabelAndLog) {
    Fixture f;
    try {
        f.shader(6);
        FAIL() << "a rejected shader made a ShaderCode";
    } catch (const InvalidOperation& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("test shader 6"), std::string::npos) << what;
        EXPECT_NE(what.find("the recording backend rejects this source"), std::string::npos) << what;
    }
    EXPECT_EQ(f.device->liveGpuObjects().programs, 0);
}

TEST(FrontEndCore, DisposingAShaderDeletesItsProgramAndThePipelinesAndVertexArraysMadeWithIt) {
    Fixture f;
    auto vs = f.shader(0), ps = f.shader(1);
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer vertices(*f.device, 36, nullptr, false), texcoords(*f.device, 24, nullptr, false);
    core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}},
                      DrawArguments{PrimitiveType::TriangleList, 3});
    const GpuObjectCounts before = f.device->liveGpuObjects();
    f.backend->take();
    vs.reset();
    EXPECT_EQ(f.backend->matching("deleteProgram").size(), 1u);
    EXPECT_EQ(f.backend->matching("deletePipeline").size(), 1u);
    EXPECT_EQ(f.backend->matching("deleteVertexArray").size(), 1u);
    const GpuObjectCounts after = f.device->liveGpuObjects();
    EXPECT_EQ(after.programs, before.programs - 1);
    EXPECT_EQ(after.pipelines, before.pipelines - 1);
    EXPECT_EQ(after.vertexArrays, before.vertexArrays - 1);
    EXPECT_EQ(f.backend->objects->badDeletes, Calls{});
    EXPECT_THROW(core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}}, DrawArguments{PrimitiveType::TriangleList, 3}),
                 InvalidOperation);  // the vertex stage is gone with it
}

TEST(FrontEndCore, UniformBuffersGoToTheirStagesRangeAndTheInternalBindingIsRefused) {
    Fixture f;
    auto vs = f.shader(0), ps = f.shader(1);
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer constants(*f.device, 256, nullptr, true), vertices(*f.device, 36, nullptr, false), texcoords(*f.device, 24, nullptr, false);
    core::setUniformBuffer(*f.device, 1, 2, &constants);  // the pixel stage's b2
    f.backend->take();
    core::drawStreams(*f.device, {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}},
                      DrawArguments{PrimitiveType::TriangleList, 3});
    EXPECT_EQ(f.backend->matching("bindUniformBuffer " + std::to_string(uniformBindingFor(1, 2))),
              Calls{"bindUniformBuffer " + std::to_string(uniformBindingFor(1, 2)) + " " + std::to_string(constants.backendObject())});
    EXPECT_THROW(core::setUniformBuffer(*f.device, 1, kUnusedUniformBinding, &constants), ArgumentError);
    EXPECT_THROW(core::setUniformBuffer(*f.device, kUniformStages, 0, &constants), ArgumentError);
}

TEST(FrontEndCore, ADepthBufferClearWaitsForTheBufferOrClearsItAndForgetsTheShadowedMasks) {
    if (FXPORT_LAZY_DEPTH_BUILT) {  // a build without lazy depth storage (FXPORT_PASS_LAZY_DEPTH=OFF) is eager
        Fixture f;  // lazy depth storage: the buffer is made at the first draw that tests depth
        core::DepthBuffer depth(*f.device, 64, 32, DepthFormat::Depth24Stencil8);
        f.backend->take();
        core::clearDepthBuffer(*f.device, depth, true, true, 0.5f, 3);
        EXPECT_EQ(f.backend->take(), Calls{});
    }
    PresentationParameters eager = Fixture::small();
    eager.Optimizations.LazyDepthStorage = false;
    Fixture f(eager);
    core::DepthBuffer depth(*f.device, 64, 32, DepthFormat::Depth24Stencil8);
    auto vs = f.shader(0), ps = f.shader(1);
    const ShaderCode* stages[5] = {vs.get(), ps.get(), nullptr, nullptr, nullptr};
    core::setShaderStages(*f.device, stages);
    ByteBuffer vertices(*f.device, 36, nullptr, false), texcoords(*f.device, 24, nullptr, false);
    const std::vector<InstancedStream> streams = {{{&vertices, 0, &f.positions}, 0}, {{&texcoords, 0, &f.texcoords}, 0}};
    core::drawStreams(*f.device, streams, DrawArguments{PrimitiveType::TriangleList, 3});
    f.backend->take();
    core::clearDepthBuffer(*f.device, depth, true, true, 0.5f, 3);
    EXPECT_EQ(f.backend->matching("clearDepthStencil"),
              Calls{"clearDepthStencil " + std::to_string(depth.storage().renderbuffer) + " depth 0.500000 stencil 3"});
    // The clear changed the masks and the scissor test behind the shadow: the next draw sends every state.
    f.backend->take();
    core::drawStreams(*f.device, streams, DrawArguments{PrimitiveType::TriangleList, 3});
    EXPECT_EQ(f.backend->matching("setBlend"), Calls{"setBlend whole"});
    EXPECT_EQ(f.backend->matching("setDepthStencil"), Calls{"setDepthStencil whole"});
    EXPECT_EQ(f.backend->matching("setRasterizer"), Calls{"setRasterizer whole"});
}

TEST(FrontEndCore, TextureCopiesCheckTheirBoxesAgainstTheLevelsBeforeCopying) {
    Fixture f;
    Texture2D source(*f.device, 16, 16, true, SurfaceFormat::Color), destination(*f.device, 16, 16, true, SurfaceFormat::Color);
    const std::string s = std::to_string(source.backendObject()), d = std::to_string(destination.backendObject());
    f.backend->take();
    core::copyTextureRegion(destination, 1, 2, 3, source, 0, Rectangle(1, 1, 4, 4));
    EXPECT_EQ(f.backend->matching("copyTexture"), Calls{"copyTexture " + s + " level 0 (1,1) -> " + d + " level 1 (2,3) 4x4"});
    f.backend->take();
    EXPECT_THROW(core::copyTextureRegion(destination, 0, 0, 0, source, 0, Rectangle(12, 0, 8, 4)), ArgumentError);  // past the source
    EXPECT_THROW(core::copyTextureRegion(destination, 1, 6, 0, source, 0, Rectangle(0, 0, 4, 4)), ArgumentError);   // level 1 is 8x8
    EXPECT_THROW(core::copyTextureRegion(destination, 5, 0, 0, source, 0, Rectangle(0, 0, 1, 1)), ArgumentError);   // no level 5
    EXPECT_EQ(f.backend->matching("copyTexture"), Calls{});
    core::copyTexture(destination, source);  // every level, at its size
    const Calls levels = f.backend->matching("copyTexture");
    ASSERT_EQ(levels.size(), 5u);
    EXPECT_EQ(levels[4], "copyTexture " + s + " level 4 (0,0) -> " + d + " level 4 (0,0) 1x1");
    Texture2D other(*f.device, 8, 8, false, SurfaceFormat::Color);
    EXPECT_THROW(core::copyTexture(other, source), ArgumentError);
}

TEST(ComputeDispatch, ADispatchMakesItsPipelineOnceBindsItsStorageAndBarriersBeforeTheRead) {
    Fixture f;
    EXPECT_THROW(f.device->DispatchCompute(1, 1, 1), InvalidOperation);  // no compute shader
    auto cs = f.shader(4);
    core::setComputeShader(*f.device, cs.get());
    f.backend->take();
    ByteBuffer output(*f.device, 64, nullptr, false);
    EXPECT_THROW(f.device->DispatchCompute(1, 1, 1), InvalidOperation);  // u0 is empty
    EXPECT_EQ(f.backend->matching("dispatch"), Calls{});
    core::setStorageBuffer(*f.device, true, 0, &output);
    f.device->DispatchCompute(2, 3, 1);
    f.device->DispatchCompute(2, 3, 1);
    const Calls pipelines = f.backend->matching("createComputePipeline");
    ASSERT_EQ(pipelines.size(), 1u);
    const std::string pipeline = pipelines[0].substr(pipelines[0].find("-> ") + 3);
    EXPECT_EQ(f.backend->matching("bindPipeline"), Calls{"bindPipeline " + pipeline});
    EXPECT_EQ(f.backend->matching("bindStorageBuffer"),
              (Calls{"bindStorageBuffer 3 " + std::to_string(output.backendObject()), "bindStorageBuffer 3 " + std::to_string(output.backendObject())}));
    EXPECT_EQ(f.backend->matching("dispatch"), (Calls{"dispatch 2 3 1", "dispatch 2 3 1"}));
    // The second dispatch waits for the first one's writes, and so does the read.
    f.backend->take();
    char out[4];
    output.read(0, 4, out);
    EXPECT_EQ(f.backend->take(), (Calls{"storageBarrier", "readBuffer " + std::to_string(output.backendObject()) + " 0 4"}));
    f.device->DispatchCompute(0, 4, 4);  // D3D11 runs nothing
    EXPECT_EQ(f.backend->take(), Calls{});
    EXPECT_THROW(f.device->DispatchCompute(65536, 1, 1), ArgumentError);
}

TEST(FrontEndCore, TargetsTheBackendCannotDrawToAreAnInvalidOperationNamingWhy) {
    Fixture f;
    RenderTarget2D target(*f.device, 16, 16, false, SurfaceFormat::Color, DepthFormat::None, 0, RenderTargetUsage::PreserveContents);
    f.backend->rejectFramebuffers = true;
    try {
        core::setTargets(*f.device, {RenderTargetBinding(&target)}, nullptr);
        FAIL() << "a framebuffer the backend rejected was bound";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("the recording backend rejects it"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fxport
