// The runner's own rules, pinned without a GPU: vkd3d's qualifiers, its ULP comparison, probe
// parsing, explicit register bindings, the D3D placement of `uniform N` (uniform_layout.cpp) and the
// D3D11 session's descriptions of the suite's blocks (d3d11_descs.cpp), and which session's run
// of a model counts (session_choice.cpp).
#include <gtest/gtest.h>

#include <cstring>

#include "d3d11_descs.h"
#include "fixed_function_states.h"
#include "fxport/xlate/compiled_effect.h"
#include "probe.h"
#include "qualifiers.h"
#include "register_binding.h"
#include "session_choice.h"
#include "uniform_layout.h"

namespace conformance {
namespace {

TEST(Qualifiers, SectionFailHoldsOnlyAtTheModelsItNames) {
    EXPECT_TRUE(sectionExpectation("fail(sm>=2&sm<4)", 30).fail);
    EXPECT_FALSE(sectionExpectation("fail(sm>=2&sm<4)", 40).fail);
    EXPECT_TRUE(sectionExpectation("fail", 50).expectsReject());
    EXPECT_TRUE(sectionExpectation("notimpl(sm<6)", 50).expectsReject());
    // Backend tags do not narrow a section's models (vkd3d's model mask ignores them).
    EXPECT_TRUE(sectionExpectation("todo(glsl) fail(sm<4 | d3d12)", 20).fail);
    EXPECT_TRUE(sectionExpectation("todo(glsl)", 20).todo);
}

TEST(Qualifiers, TestLinePrefixesAtAModel) {
    EXPECT_TRUE(parseTestLinePrefix("if(sm<4) probe (0, 0) rgba (1, 1, 1, 1)", 30).runs);
    EXPECT_FALSE(parseTestLinePrefix("if(sm<4) probe (0, 0) rgba (1, 1, 1, 1)", 40).runs);
    EXPECT_EQ(parseTestLinePrefix("todo(sm<6 | msl) draw quad", 40).rest, "draw quad");
    // No vkd3d backend tag describes native D3D: `!d3d12` holds, `glsl` does not.
    EXPECT_TRUE(parseTestLinePrefix("if(!d3d12) draw quad", 50).runs);
    EXPECT_FALSE(parseTestLinePrefix("if(glsl) draw quad", 50).runs);
    EXPECT_EQ(parseShaderModel("4"), 40);
    EXPECT_EQ(parseShaderModel("4.1"), 41);
}

TEST(Probes, UlpsAsVkd3dCountsThem) {
    float one = 1.0f, next;
    std::uint32_t bits;
    std::memcpy(&bits, &one, 4);
    ++bits;
    std::memcpy(&next, &bits, 4);
    EXPECT_TRUE(floatsMatch(next, one, 1));
    EXPECT_FALSE(floatsMatch(next, one, 0));
    EXPECT_TRUE(floatsMatch(-0.0f, 0.0f, 0));
    EXPECT_FALSE(floatsMatch(-1.0f, 1.0f, 1000));
}

TEST(Probes, RectangleKindValuesAndUlps) {
    Probe p = parseProbe(" rtv 1 (2, 3, 10, 20) rgba (0.5, -1, 2e3, 4) 7");
    EXPECT_EQ(p.target, Probe::Target::Rtv);
    EXPECT_EQ(p.slot, 1);
    EXPECT_EQ(p.right, 10);
    EXPECT_EQ(p.bottom, 20);
    EXPECT_EQ(p.kind, "rgba");
    EXPECT_DOUBLE_EQ(p.expected[2], 2000.0);
    EXPECT_EQ(p.ulps, 7u);
    Probe u = parseProbe(" uav 2 (5) u32(0xffffffff, 3)");
    EXPECT_EQ(u.target, Probe::Target::Uav);
    EXPECT_EQ(u.components, 2);
    EXPECT_EQ(u.expectedBits[0], 0xffffffffu);
}

TEST(RegisterBinding, IndexExpressionsAndAnnotationChains) {
    EXPECT_EQ(explicitRegister("float a : register (c0[0.6 + 0.6]);", "a", 'c'), 1);
    EXPECT_EQ(explicitRegister("float a : register (c[1 + 1 * 2 * 0]);", "a", 'c'), 1);
    EXPECT_EQ(explicitRegister("Texture2D t : register(space0, t1);", "t", 't'), 1);
    EXPECT_EQ(explicitRegister("float b : packoffset(c2) : register(c1);", "b", 'c'), 1);
    EXPECT_EQ(explicitPackOffset("float b : packoffset(c2) : register(c1);", "b"), 8);
    EXPECT_EQ(explicitPackOffset("float b : packoffset(c1.y);", "b"), 5);
    EXPECT_EQ(explicitRegister("float b;", "b", 'c'), -1);
}

fxport::xlate::Parameter numeric(const char* name, fxport::xlate::ParameterClass cls, int rows, int columns) {
    fxport::xlate::Parameter p;
    p.name = name;
    p.parameterClass = cls;
    p.rows = rows;
    p.columns = columns;
    return p;
}

TEST(UniformLayout, Sm4PacksLikeD3D10CBuffers) {
    using C = fxport::xlate::ParameterClass;
    fxport::xlate::CompiledEffect e;
    e.parameters = {numeric("a", C::Scalar, 1, 1), numeric("b", C::Vector, 1, 2), numeric("c", C::Vector, 1, 2),
                    numeric("m", C::Matrix, 4, 4)};
    UniformLayout l = computeUniformLayout(e, "", 40);
    ASSERT_EQ(l.placements.size(), 4u);
    EXPECT_EQ(l.placements[0].scalarOffsets[0], 0);  // a: c0.x
    EXPECT_EQ(l.placements[1].scalarOffsets[0], 1);  // b: c0.yz (fits after a)
    EXPECT_EQ(l.placements[2].scalarOffsets[0], 4);  // c: would cross into c1: c1.xy
    // m column_major from c2: m[0][1] (scalar 1) is column 1, row 0 = c3.x.
    EXPECT_EQ(l.placements[3].scalarOffsets[0], 8);
    EXPECT_EQ(l.placements[3].scalarOffsets[1], 12);
}

TEST(UniformLayout, Sm4ImplicitGlobalsFollowTheExplicitOnes) {
    using C = fxport::xlate::ParameterClass;
    fxport::xlate::CompiledEffect e;
    e.parameters = {numeric("a", C::Vector, 1, 4), numeric("b", C::Vector, 1, 4)};
    UniformLayout l = computeUniformLayout(e, "float4 a;\nfloat4 b : register(c0);\n", 40);
    EXPECT_EQ(l.placements[0].scalarOffsets[0], 4);  // a after b's c0
    EXPECT_EQ(l.placements[1].scalarOffsets[0], 0);
}

TEST(UniformLayout, Sm2AllocatesReadParametersByRegistersUsed) {
    using C = fxport::xlate::ParameterClass;
    fxport::xlate::CompiledEffect e;
    fxport::xlate::Parameter f = numeric("f", C::Vector, 1, 4);
    f.offset = 0;
    f.size = 16;
    fxport::xlate::Parameter m = numeric("m", C::Matrix, 4, 2);  // column_major: 2 registers
    m.offset = 16;
    m.size = 32;
    m.matrixStride = 16;
    e.parameters = {f, m};
    fxport::xlate::CompiledShader shader;
    shader.uniformRangesRead = {{0, 16, 0}, {16, 32, 0}};
    shader.uniformRangesLive = shader.uniformRangesRead;
    e.shaders = {shader};
    UniformLayout l = computeUniformLayout(e, "", 20);
    ASSERT_EQ(l.placements.size(), 2u);
    // Larger first: m takes c0-c1, f c2.
    EXPECT_EQ(l.placements[0].parameter, 1);
    EXPECT_EQ(l.placements[0].scalarOffsets[0], 0);
    EXPECT_EQ(l.placements[1].scalarOffsets[0], 8);

    // Only m's first column live (`m[0].x + m[1].x + ...`): one register each, declaration order
    // breaks the tie (sm1-const-allocation's first case: a c0, b c1).
    e.shaders[0].uniformRangesLive = {{0, 16, 0}, {16, 16, 0}};
    l = computeUniformLayout(e, "", 20);
    ASSERT_EQ(l.placements.size(), 2u);
    EXPECT_EQ(l.placements[0].parameter, 0);
    EXPECT_EQ(l.placements[0].scalarOffsets[0], 0);
    EXPECT_EQ(l.placements[1].scalarOffsets[0], 4);  // m's column 0 (rows at 4..7): c1
}

// A struct's members each get a placement and the path EffectParameter takes to them: SM4 packs
// them like cbuffer members from the struct's register (cbuffer.shader_test: `float a; struct {
// float b; float c; } p; float d;` reads b, c, d from c1.xyz); SM2-3 give each member a register
// (register-reservations-numeric: `struct { float2 a; float b; } apple : register(c2)` reads b from c3).
fxport::xlate::Parameter appleStruct(int elements) {
    using C = fxport::xlate::ParameterClass;
    fxport::xlate::Parameter s = numeric("apple", C::Struct, 1, 1);
    s.elements = elements;
    s.members = {numeric("a", C::Vector, 1, 2), numeric("b", C::Scalar, 1, 1)};
    return s;
}

TEST(UniformLayout, Sm4PlacesStructMembersAndElements) {
    using C = fxport::xlate::ParameterClass;
    fxport::xlate::CompiledEffect e;
    e.parameters = {numeric("x", C::Scalar, 1, 1), appleStruct(2), numeric("y", C::Scalar, 1, 1)};
    UniformLayout l = computeUniformLayout(e, "", 40);
    ASSERT_EQ(l.placements.size(), 6u);
    EXPECT_EQ(l.placements[1].path, (std::vector<std::pair<bool, int>>{{false, 0}, {true, 0}}));
    EXPECT_EQ(l.placements[1].scalarOffsets, (std::vector<int>{4, 5}));  // apple[0].a: c1.xy
    EXPECT_EQ(l.placements[2].scalarOffsets, (std::vector<int>{6}));     // apple[0].b: c1.z
    EXPECT_EQ(l.placements[3].scalarOffsets, (std::vector<int>{8, 9}));  // apple[1]: the next register
    EXPECT_EQ(l.placements[4].path, (std::vector<std::pair<bool, int>>{{false, 1}, {true, 1}}));
    EXPECT_EQ(l.placements[4].scalarOffsets, (std::vector<int>{10}));
    EXPECT_EQ(l.placements[5].scalarOffsets, (std::vector<int>{11}));  // y in apple[1]'s last register
}

TEST(UniformLayout, Sm3GivesEachStructMemberARegister) {
    fxport::xlate::CompiledEffect e;
    e.parameters = {appleStruct(0)};
    UniformLayout l = computeUniformLayout(e, "struct { float2 a; float b; } apple : register(c2);\n", 30);
    ASSERT_EQ(l.placements.size(), 2u);
    EXPECT_EQ(l.placements[0].path, (std::vector<std::pair<bool, int>>{{true, 0}}));
    EXPECT_EQ(l.placements[0].scalarOffsets, (std::vector<int>{8, 9}));
    EXPECT_EQ(l.placements[1].scalarOffsets, (std::vector<int>{12}));
}

TEST(D3d11Descs, FormatsNamedByTheSuite) {
    using namespace fxport::d3d11;
    EXPECT_EQ(dxgiFormat(parseFormat("r32g32b32a32-uint")), DXGI_FORMAT_R32G32B32A32_UINT);
    EXPECT_EQ(dxgiFormat(parseFormat("r32g32-float")), DXGI_FORMAT_R32G32_FLOAT);
    EXPECT_EQ(dxgiFormat(parseFormat("r32-uint")), DXGI_FORMAT_R32_UINT);
    EXPECT_EQ(dxgiFormat(parseFormat("r32g32b32a32-sint")), DXGI_FORMAT_R32G32B32A32_SINT);
    EXPECT_EQ(dxgiFormat(parseFormat("r32g32-sint")), DXGI_FORMAT_R32G32_SINT);
    EXPECT_EQ(dxgiFormat(parseFormat("r32-sint")), DXGI_FORMAT_R32_SINT);
    // A format with no DXGI value is a skip with its name, never a wrong format.
    try {
        dxgiFormat(parseFormat("unknown"));
        ADD_FAILURE() << "'unknown' has no DXGI_FORMAT value a texture can have";
    } catch (const Unsupported& e) {
        EXPECT_NE(std::string(e.what()).find("unknown"), std::string::npos) << e.what();
    }
    EXPECT_EQ(dxgiFormat(parseFormat("r32-float-shadow")), DXGI_FORMAT_R32_TYPELESS);  // viewed as R32_FLOAT
}

TEST(D3d11Descs, SamplerFilterBitsAndComparison) {
    using namespace fxport::d3d11;
    SamplerDesc s;
    s.min = Filter::Linear;
    s.mip = Filter::Linear;
    s.u = Address::Wrap;
    s.comparison = true;
    s.comparisonFunc = "greater equal";
    D3D11_SAMPLER_DESC d = samplerDescOf(s);
    EXPECT_EQ(UINT(d.Filter), 0x91u);  // comparison | min linear | mip linear, mag point
    EXPECT_EQ(d.ComparisonFunc, D3D11_COMPARISON_GREATER_EQUAL);
    EXPECT_EQ(d.AddressU, D3D11_TEXTURE_ADDRESS_WRAP);
    EXPECT_EQ(d.AddressV, D3D11_TEXTURE_ADDRESS_CLAMP);
    s.comparisonFunc = "less";
    EXPECT_EQ(samplerDescOf(s).ComparisonFunc, D3D11_COMPARISON_LESS);  // not "less equal"
    s.comparisonFunc = "sometimes";
    EXPECT_THROW(samplerDescOf(s), Unsupported);
}

TEST(D3d11Descs, InputElementsPackEachSlotInOrder) {
    std::vector<InputElement> layout = {{0, parseFormat("r32g32-float"), "position", 0},
                                        {1, parseFormat("r32-float"), "texcoord", 1},
                                        {0, parseFormat("r32g32b32a32-float"), "color", 0},
                                        {1, parseFormat("r32-uint"), "texcoord", 2}};
    InputElements e = inputElementsOf(layout);
    ASSERT_EQ(e.elements.size(), 4u);
    EXPECT_EQ(e.elements[2].InputSlot, 0u);
    EXPECT_EQ(e.elements[2].AlignedByteOffset, 8u);  // after slot 0's float2, not after slot 1's float
    EXPECT_EQ(e.elements[3].AlignedByteOffset, 4u);
    EXPECT_STREQ(e.elements[1].SemanticName, "texcoord");
    EXPECT_EQ(e.elements[1].SemanticIndex, 1u);
    EXPECT_EQ(e.strides.at(0), 24u);
    EXPECT_EQ(e.strides.at(1), 8u);
    layout[0].slot = 32;
    EXPECT_THROW(inputElementsOf(layout), std::runtime_error);
}

TEST(D3d11Descs, Topologies) {
    using namespace fxport::d3d11;
    DrawCall call;
    call.topology = "patch list";
    call.controlPoints = 3;
    EXPECT_EQ(topologyOf(call), D3D11_PRIMITIVE_TOPOLOGY_3_CONTROL_POINT_PATCHLIST);
    call.topology = "triangle strip";
    EXPECT_EQ(topologyOf(call), D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    call.topology = "line list";
    EXPECT_THROW(topologyOf(call), Unsupported);
}

ModelOutcome outcome(int passed, int compiled, const char* failureCategory = nullptr) {
    ModelOutcome o;
    o.result.probesPassed = passed;
    o.result.sections[0].shouldCompile = 5;
    o.result.sections[0].compiled = compiled;
    o.result.session = "d3d11";
    if (failureCategory) o.failures.push_back({"f", 40, 12, failureCategory, "detail"});
    return o;
}

TEST(SessionChoice, XnaRunCountsOnlyWhenItPassesMoreWithTheSameCompileChecks) {
    // Only a failed draw or probe is worth a second run; a refused section is not (both runs compile alike).
    EXPECT_FALSE(worthXnaRerun(outcome(3, 5)));
    EXPECT_FALSE(worthXnaRerun(outcome(3, 4, "refused")));
    EXPECT_TRUE(worthXnaRerun(outcome(3, 5, "probe")));
    EXPECT_TRUE(worthXnaRerun(outcome(3, 5, "draw")));
    ModelOutcome kept = chooseSession(outcome(3, 5, "probe"), outcome(4, 5));
    EXPECT_EQ(kept.result.probesPassed, 4);
    EXPECT_EQ(kept.result.session, "xna-kept");
    EXPECT_TRUE(kept.failures.empty());  // the failures of the run that counts
    EXPECT_EQ(chooseSession(outcome(4, 5, "probe"), outcome(4, 5)).result.session, "d3d11");  // a tie keeps D3D11
    EXPECT_EQ(chooseSession(outcome(3, 5, "probe"), outcome(4, 4)).result.session, "d3d11");  // other compile counts
    // The session travels from the child process with the counts.
    EXPECT_EQ(ModelResult::decode(kept.result.encode()).session, "xna-kept");
}

TEST(SessionChoice, FixedFunctionSkipsOfTheD3d11SessionAreWorthAnXnaRun) {
    ModelOutcome skipped = outcome(3, 5);
    skipped.result.skipReasons["requires 'fog'"] = 4;
    EXPECT_TRUE(worthXnaRerun(skipped));
    ModelOutcome state = outcome(3, 5);
    state.result.skipReasons["test state 'point-size' (D3D11 has no D3D9 fixed-function states)"] = 2;
    EXPECT_TRUE(worthXnaRerun(state));
}

TEST(FixedFunctionStates, ParsedAsVkd3dWritesThem) {
    FixedFunctionDesc f;
    EXPECT_TRUE(parseFixedFunctionState("fog-colour 0.0 1.0 1.0 1.0", f));
    EXPECT_EQ(f.fogColour[1], 1.0f);
    EXPECT_TRUE(parseFixedFunctionState("fog none", f));
    EXPECT_TRUE(f.fog);
    EXPECT_EQ(f.fogMode, 0);
    EXPECT_TRUE(parseFixedFunctionState("fog linear non-ortho 0.1 1.1", f));
    EXPECT_EQ(f.fogMode, 3);
    EXPECT_TRUE(f.fogFromW);
    EXPECT_FLOAT_EQ(f.fogEnd, 1.1f);
    EXPECT_TRUE(parseFixedFunctionState("fog exp2 ortho 2.0", f));
    EXPECT_EQ(f.fogMode, 2);
    EXPECT_FALSE(f.fogFromW);
    EXPECT_FLOAT_EQ(f.fogDensity, 2.0f);
    EXPECT_TRUE(parseFixedFunctionState("fog disable", f));
    EXPECT_FALSE(f.fog);
    EXPECT_TRUE(parseFixedFunctionState("point-size 40.0 1.0 20.0", f));
    EXPECT_EQ(f.pointSizeMax, 20.0f);
    EXPECT_TRUE(parseFixedFunctionState("point-sprite on", f));
    EXPECT_TRUE(f.pointSprite);
    EXPECT_TRUE(parseFixedFunctionState("clip-plane 3 -1.0 1.0 0.0 0.0", f));
    EXPECT_EQ(f.clipPlaneMask, 8u);
    EXPECT_EQ(f.clipPlanes[3][0], -1.0f);
    EXPECT_TRUE(parseFixedFunctionState("alpha test greater equal 1.0", f));
    EXPECT_EQ(f.alphaFunction, "greater equal");
    EXPECT_EQ(f.alphaReference, 1.0f);
    EXPECT_TRUE(parseFixedFunctionState("alpha test less 1.0", f));
    EXPECT_EQ(f.alphaFunction, "less");
    EXPECT_TRUE(parseFixedFunctionState("shade mode flat", f));
    EXPECT_TRUE(f.flatShading);
    EXPECT_FALSE(parseFixedFunctionState("sample mask 3", f));
    EXPECT_THROW(parseFixedFunctionState("fog linear sideways 0 1", f), std::runtime_error);
    EXPECT_EQ(FixedFunctionDesc{}.firstSet(), "");
    EXPECT_EQ(f.firstSet(), "point-size");
}

}  // namespace
}  // namespace conformance
