#include "fx/render_states.h"

#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "fx/parameter_selector.h"
#include "fx/source_map.h"
#include "fx/state_values.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// Enum values are compared after normalisation: lower case, D3D prefixes and underscores removed,
// so `SrcAlpha`, `SRCALPHA`, `D3DBLEND_SRCALPHA` and DX10's `SRC_ALPHA` are one name.
std::string normalizeEnumName(std::string_view raw) {
    std::string s = toLower(raw);
    static const char* const kPrefixes[] = {"d3d10_blend_op_", "d3d10_blend_", "d3d10_comparison_", "d3d10_cull_",
                                            "d3d10_fill_", "d3d10_stencil_op_", "d3d11_", "d3dblendop_", "d3dblend_",
                                            "d3dcmp_", "d3dcull_", "d3dfill_", "d3dstencilop_", "d3dtexf_",
                                            "d3dtaddress_", "d3dzb_", "d3dfog_", "d3dshade_", "blend_op_", "comparison_", "stencil_op_"};
    for (const char* p : kPrefixes) {
        std::string_view pv(p);
        if (s.rfind(pv, 0) == 0) {
            s = s.substr(pv.size());
            break;
        }
    }
    std::string out;
    for (char c : s)
        if (c != '_') out += c;
    return out;
}

// A state (or value) the runtime cannot reproduce: accepted, ignored, and said so at file:line.
void warnUnhonoured(StateContext& ctx, const FxAssignment& a, const std::string& why) {
    const Token& t = ctx.syntax.tokens[a.nameToken];
    ctx.diagnostics.push_back(ctx.map.make(Severity::Warning, diag::kUnhonouredState, "state '" + a.name + "' " + why,
                                           t.line, t.column, t.text));
}

struct EnumTable {
    std::map<std::string, int> names;  // normalised name -> value
    std::map<int, int> d3d9Codes;      // numeric D3D9 code -> value
};

const EnumTable& blendTable() {
    static const EnumTable t{{{"zero", int(Blend::Zero)}, {"one", int(Blend::One)},
                              {"srccolor", int(Blend::SourceColor)}, {"invsrccolor", int(Blend::InverseSourceColor)},
                              {"srcalpha", int(Blend::SourceAlpha)}, {"invsrcalpha", int(Blend::InverseSourceAlpha)},
                              {"destalpha", int(Blend::DestinationAlpha)}, {"invdestalpha", int(Blend::InverseDestinationAlpha)},
                              {"destcolor", int(Blend::DestinationColor)}, {"invdestcolor", int(Blend::InverseDestinationColor)},
                              {"srcalphasat", int(Blend::SourceAlphaSaturation)}, {"blendfactor", int(Blend::BlendFactor)},
                              {"invblendfactor", int(Blend::InverseBlendFactor)}},
                             {{1, int(Blend::Zero)}, {2, int(Blend::One)}, {3, int(Blend::SourceColor)},
                              {4, int(Blend::InverseSourceColor)}, {5, int(Blend::SourceAlpha)},
                              {6, int(Blend::InverseSourceAlpha)}, {7, int(Blend::DestinationAlpha)},
                              {8, int(Blend::InverseDestinationAlpha)}, {9, int(Blend::DestinationColor)},
                              {10, int(Blend::InverseDestinationColor)}, {11, int(Blend::SourceAlphaSaturation)},
                              {14, int(Blend::BlendFactor)}, {15, int(Blend::InverseBlendFactor)}}};
    return t;
}
const EnumTable& blendOpTable() {
    static const EnumTable t{{{"add", int(BlendFunction::Add)}, {"subtract", int(BlendFunction::Subtract)},
                              {"revsubtract", int(BlendFunction::ReverseSubtract)}, {"min", int(BlendFunction::Min)},
                              {"max", int(BlendFunction::Max)}},
                             {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}}};
    return t;
}
const EnumTable& compareTable() {
    static const EnumTable t{{{"never", 0}, {"less", 1}, {"equal", 2}, {"lessequal", 3}, {"greater", 4},
                              {"notequal", 5}, {"greaterequal", 6}, {"always", 7}},
                             {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}, {6, 5}, {7, 6}, {8, 7}}};
    return t;
}
const EnumTable& stencilOpTable() {
    static const EnumTable t{{{"keep", 0}, {"zero", 1}, {"replace", 2}, {"incrsat", 3}, {"decrsat", 4},
                              {"invert", 5}, {"incr", 6}, {"decr", 7}},
                             {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}, {6, 5}, {7, 6}, {8, 7}}};
    return t;
}
const EnumTable& cullTable() {
    static const EnumTable t{{{"none", int(CullMode::None)}, {"cw", int(CullMode::CullClockwiseFace)},
                              {"ccw", int(CullMode::CullCounterClockwiseFace)}},
                             {{1, 0}, {2, 1}, {3, 2}}};
    return t;
}
// D3DFOGMODE and D3DSHADEMODE: names and codes are D3D9's (kept as the int value).
const EnumTable& fogModeTable() {
    static const EnumTable t{{{"none", 0}, {"exp", 1}, {"exp2", 2}, {"linear", 3}}, {{0, 0}, {1, 1}, {2, 2}, {3, 3}}};
    return t;
}
const EnumTable& shadeModeTable() {
    static const EnumTable t{{{"flat", 1}, {"gouraud", 2}, {"phong", 3}}, {{1, 1}, {2, 2}, {3, 3}}};
    return t;
}
const EnumTable& fillTable() {
    static const EnumTable t{{{"point", int(FillMode::Point)}, {"wireframe", int(FillMode::WireFrame)},
                              {"solid", int(FillMode::Solid)}},
                             {{1, 0}, {2, 1}, {3, 2}}};
    return t;
}

}  // namespace

const std::set<std::string>& fixedFunctionStateNames() {
    static const std::set<std::string> k = {
        "lighting", "rangefogenable", "specularenable", "normalizenormals", "localviewer", "colorvertex", "ambient",
        "ambientmaterialsource", "diffusematerialsource", "specularmaterialsource", "emissivematerialsource",
        "texturefactor", "ditherenable", "lastpixel", "clipping", "pointscaleenable", "pointscale_a", "pointscale_b",
        "pointscale_c", "vertexblend", "indexedvertexblendenable", "tweenfactor", "texture", "sampler", "colorop",
        "colorarg0", "colorarg1", "colorarg2", "alphaop", "alphaarg0", "alphaarg1", "alphaarg2", "resultarg",
        "texcoordindex", "texturetransformflags", "bumpenvmat00", "bumpenvmat01", "bumpenvmat10", "bumpenvmat11",
        "bumpenvlscale", "bumpenvloffset", "minfilter", "magfilter", "mipfilter", "addressu", "addressv", "addressw",
        "bordercolor", "maxanisotropy", "maxmiplevel", "mipmaplodbias", "srgbtexture", "wrap0", "wrap1", "wrap2",
        "wrap3", "wrap4", "wrap5", "wrap6", "wrap7", "worldtransform", "viewtransform", "projectiontransform",
        "texturetransform", "material", "materialambient", "materialdiffuse", "materialspecular",
        "materialemissive", "materialpower", "lightenable", "lighttype", "lightdiffuse", "lightspecular",
        "lightambient", "lightposition", "lightdirection", "lightrange", "lightfalloff", "lightattenuation0",
        "lightattenuation1", "lightattenuation2", "lighttheta", "lightphi", "fvf", "vertexshaderconstant",
        "vertexshaderconstantf", "vertexshaderconstantb", "vertexshaderconstanti", "vertexshaderconstant1",
        "vertexshaderconstant2", "vertexshaderconstant3", "vertexshaderconstant4", "pixelshaderconstant",
        "pixelshaderconstantf", "pixelshaderconstantb", "pixelshaderconstanti", "pixelshaderconstant1",
        "pixelshaderconstant2", "pixelshaderconstant4", "antialiasedlineenable", "patchedgestyle",
        "debugmonitortoken", "positiondegree", "normaldegree", "minimumtessellationlevel",
        "maximumtessellationlevel", "adaptivetess_x", "adaptivetess_y", "adaptivetess_z", "adaptivetess_w",
        "enableadaptivetessellation", "dmapoffset", "elementindex", "alphatocoverageenable"};
    return k;
}

namespace {

bool isFixedFunctionState(const std::string& lower) { return fixedFunctionStateNames().count(lower) > 0; }

struct ValueReader {
    StateContext& ctx;
    const FxAssignment& a;
    // A sampler's state block in a loose-shader compile: fxc ignores its content, so a value
    // fxport cannot read is a warning that it is ignored (see EffectSyntax::looseShaders).
    bool warnOnly = false;

    const Token& tok(size_t i) const { return ctx.syntax.tokens[i]; }
    std::string text() const { return ctx.syntax.text(a.value); }

    void error(const char* id, const std::string& message) const {
        const Token& t = tok(a.nameToken);
        ctx.diagnostics.push_back(ctx.map.make(warnOnly ? Severity::Warning : Severity::Error, id,
                                               warnOnly ? message + "; ignored, as fxc ignores a state block outside an effect" : message,
                                               t.line, t.column, t.text));
    }
    void bad(const std::string& expected) const {
        error(diag::kBadStateValue, "value '" + text() + "' of state '" + a.name + "' is not " + expected);
    }

    // A single (possibly parenthesised) token, or "-" number.
    std::optional<std::string> single() const {
        TokenSpan s = a.value;
        while (s.end > s.begin + 1 && tok(s.begin).is("(") && tok(s.end - 1).is(")")) {
            ++s.begin;
            --s.end;
        }
        if (s.end == s.begin + 1) return tok(s.begin).text;
        if (s.end == s.begin + 2 && tok(s.begin).is("-") && tok(s.begin + 1).kind == Token::Kind::Number)
            return "-" + tok(s.begin + 1).text;
        return std::nullopt;
    }

    std::optional<double> number() const {
        auto s = single();
        if (!s) return std::nullopt;
        if (iequals(*s, "true")) return 1.0;
        if (iequals(*s, "false")) return 0.0;
        const char* c = s->c_str();
        char* end = nullptr;
        double v = (s->find("0x") != std::string::npos || s->find("0X") != std::string::npos)
                       ? static_cast<double>(std::strtoull(c, &end, 16))
                       : std::strtod(c, &end);
        if (end == c) return std::nullopt;
        return v;
    }

    std::optional<bool> boolean() const {
        auto s = single();
        if (!s) return std::nullopt;
        std::string n = normalizeEnumName(*s);
        if (n == "true" || n == "1") return true;
        if (n == "false" || n == "0") return false;
        return std::nullopt;
    }

    std::optional<int> enumeration(const EnumTable& table) const {
        auto s = single();
        if (!s) return std::nullopt;
        auto it = table.names.find(normalizeEnumName(*s));
        if (it != table.names.end()) return it->second;
        auto n = number();
        if (n && *n >= -1024 && *n <= 1024) {  // converting a double beyond int's range is undefined
            auto c = table.d3d9Codes.find(static_cast<int>(*n));
            if (c != table.d3d9Codes.end()) return c->second;
        }
        return std::nullopt;
    }

    // float4(a, b, c, d), {a, b, c, d}, a single number, or 0xAARRGGBB (D3DCOLOR).
    std::optional<std::array<double, 4>> vector4() const {
        std::vector<double> nums;
        bool neg = false;
        for (size_t i = a.value.begin; i < a.value.end; ++i) {
            const Token& t = tok(i);
            if (t.is("-")) neg = true;
            else if (t.kind == Token::Kind::Number) {
                double v = std::strtod(t.text.c_str(), nullptr);
                if (t.text.find("0x") != std::string::npos || t.text.find("0X") != std::string::npos) {
                    unsigned long long c = std::strtoull(t.text.c_str(), nullptr, 16);
                    return std::array<double, 4>{((c >> 16) & 255) / 255.0, ((c >> 8) & 255) / 255.0,
                                                 (c & 255) / 255.0, ((c >> 24) & 255) / 255.0};
                }
                nums.push_back(neg ? -v : v);
                neg = false;
            }
        }
        if (nums.size() == 1) return std::array<double, 4>{nums[0], nums[0], nums[0], nums[0]};
        if (nums.size() != 4) return std::nullopt;
        return std::array<double, 4>{nums[0], nums[1], nums[2], nums[3]};
    }

    // RED | GREEN | BLUE | ALPHA, D3DCOLORWRITEENABLE_*, a number, or MonoGame's true/false/None.
    std::optional<int> colorMask() const {
        int mask = 0;
        bool any = false;
        for (size_t i = a.value.begin; i < a.value.end; ++i) {
            const Token& t = tok(i);
            if (t.is("|") || t.is("(") || t.is(")")) continue;
            std::string n = toLower(t.text);
            if (n.rfind("d3dcolorwriteenable_", 0) == 0) n = n.substr(20);
            if (n.rfind("d3d10_color_write_enable_", 0) == 0) n = n.substr(25);
            if (n.rfind("color_write_enable_", 0) == 0) n = n.substr(19);
            if (n == "red") mask |= 1;
            else if (n == "green") mask |= 2;
            else if (n == "blue") mask |= 4;
            else if (n == "alpha") mask |= 8;
            else if (n == "all" || n == "true") mask |= 15;  // MonoGame's dialect: true / false / None
            else if (n == "none" || n == "false") mask |= 0;
            else if (t.kind == Token::Kind::Number) mask |= static_cast<int>(std::strtol(t.text.c_str(), nullptr, 0));
            else return std::nullopt;
            any = true;
        }
        if (!any) return std::nullopt;
        return mask & 15;
    }

    // `<Name>`, `(Name)` or `Name`: an object reference.
    std::optional<std::string> objectName() const {
        TokenSpan s = a.value;
        if (s.end == s.begin + 3 && ((tok(s.begin).is("<") && tok(s.end - 1).is(">")) ||
                                     (tok(s.begin).is("(") && tok(s.end - 1).is(")"))))
            return tok(s.begin + 1).text;
        if (s.end == s.begin + 1 && tok(s.begin).isIdent()) return tok(s.begin).text;
        return std::nullopt;
    }
};

void push(std::vector<StateAssignment>& out, RenderState s, double v, const SourceLocation& where, int index = 0) {
    StateAssignment a;
    a.state = s;
    a.index = index;
    a.value = stateValueFromCanonical(s, v);
    a.where = where;
    out.push_back(a);
}

// DX9 state name -> (state, kind of value).
enum class ValueKind { Bool, Int, Float, Blend, BlendOp, Compare, StencilOp, Cull, Fill, ColorMask, Vector4, ZEnable, FogMode, ShadeMode };
struct Dx9State {
    RenderState state;
    ValueKind kind;
};
const std::map<std::string, Dx9State>& dx9States() {
    static const std::map<std::string, Dx9State> k = {
        {"alphablendenable", {RenderState::AlphaBlendEnable, ValueKind::Bool}},
        {"srcblend", {RenderState::SrcBlend, ValueKind::Blend}},
        {"destblend", {RenderState::DestBlend, ValueKind::Blend}},
        {"blendop", {RenderState::BlendOp, ValueKind::BlendOp}},
        {"separatealphablendenable", {RenderState::SeparateAlphaBlendEnable, ValueKind::Bool}},
        {"srcblendalpha", {RenderState::SrcBlendAlpha, ValueKind::Blend}},
        {"destblendalpha", {RenderState::DestBlendAlpha, ValueKind::Blend}},
        {"blendopalpha", {RenderState::BlendOpAlpha, ValueKind::BlendOp}},
        {"blendfactor", {RenderState::BlendFactor, ValueKind::Vector4}},
        {"colorwriteenable", {RenderState::ColorWriteEnable, ValueKind::ColorMask}},
        {"multisamplemask", {RenderState::MultiSampleMask, ValueKind::Int}},
        {"zenable", {RenderState::ZEnable, ValueKind::ZEnable}},
        {"zwriteenable", {RenderState::ZWriteEnable, ValueKind::Bool}},
        {"zfunc", {RenderState::ZFunc, ValueKind::Compare}},
        {"stencilenable", {RenderState::StencilEnable, ValueKind::Bool}},
        {"stencilfunc", {RenderState::StencilFunc, ValueKind::Compare}},
        {"stencilpass", {RenderState::StencilPass, ValueKind::StencilOp}},
        {"stencilfail", {RenderState::StencilFail, ValueKind::StencilOp}},
        {"stencilzfail", {RenderState::StencilZFail, ValueKind::StencilOp}},
        {"stencilref", {RenderState::StencilRef, ValueKind::Int}},
        {"stencilmask", {RenderState::StencilMask, ValueKind::Int}},
        {"stencilwritemask", {RenderState::StencilWriteMask, ValueKind::Int}},
        {"twosidedstencilmode", {RenderState::TwoSidedStencilMode, ValueKind::Bool}},
        {"ccwstencilfunc", {RenderState::CcwStencilFunc, ValueKind::Compare}},
        {"ccwstencilpass", {RenderState::CcwStencilPass, ValueKind::StencilOp}},
        {"ccwstencilfail", {RenderState::CcwStencilFail, ValueKind::StencilOp}},
        {"ccwstencilzfail", {RenderState::CcwStencilZFail, ValueKind::StencilOp}},
        // D3DX's own spellings of the same states (D3DRS_CCW_STENCILFUNC ...), as the DirectX
        // SDK's ShadowVolume writes them.
        {"ccw_stencilfunc", {RenderState::CcwStencilFunc, ValueKind::Compare}},
        {"ccw_stencilpass", {RenderState::CcwStencilPass, ValueKind::StencilOp}},
        {"ccw_stencilfail", {RenderState::CcwStencilFail, ValueKind::StencilOp}},
        {"ccw_stencilzfail", {RenderState::CcwStencilZFail, ValueKind::StencilOp}},
        {"cullmode", {RenderState::CullMode, ValueKind::Cull}},
        {"fillmode", {RenderState::FillMode, ValueKind::Fill}},
        {"scissortestenable", {RenderState::ScissorTestEnable, ValueKind::Bool}},
        {"multisampleantialias", {RenderState::MultiSampleAntiAlias, ValueKind::Bool}},
        {"depthbias", {RenderState::DepthBias, ValueKind::Float}},
        {"slopescaledepthbias", {RenderState::SlopeScaleDepthBias, ValueKind::Float}},
        {"alphatestenable", {RenderState::AlphaTestEnable, ValueKind::Bool}},
        {"alphafunc", {RenderState::AlphaFunc, ValueKind::Compare}},
        {"alpharef", {RenderState::AlphaRef, ValueKind::Int}},
        {"srgbwriteenable", {RenderState::SrgbWriteEnable, ValueKind::Bool}},
        {"fogenable", {RenderState::FogEnable, ValueKind::Bool}},
        {"fogcolor", {RenderState::FogColor, ValueKind::Int}},
        {"fogtablemode", {RenderState::FogTableMode, ValueKind::FogMode}},
        {"fogvertexmode", {RenderState::FogVertexMode, ValueKind::FogMode}},
        {"fogstart", {RenderState::FogStart, ValueKind::Float}},
        {"fogend", {RenderState::FogEnd, ValueKind::Float}},
        {"fogdensity", {RenderState::FogDensity, ValueKind::Float}},
        {"pointsize", {RenderState::PointSize, ValueKind::Float}},
        {"pointsize_min", {RenderState::PointSizeMin, ValueKind::Float}},
        {"pointsize_max", {RenderState::PointSizeMax, ValueKind::Float}},
        {"pointspriteenable", {RenderState::PointSpriteEnable, ValueKind::Bool}},
        {"clipplaneenable", {RenderState::ClipPlaneEnable, ValueKind::Int}},
        {"clipplane", {RenderState::ClipPlane, ValueKind::Vector4}},
        {"shademode", {RenderState::ShadeMode, ValueKind::ShadeMode}},
    };
    return k;
}

bool readValue(const ValueReader& r, ValueKind kind, std::array<double, 4>& value) {
    std::optional<double> v;
    switch (kind) {
    case ValueKind::Bool:
        if (auto b = r.boolean()) v = *b ? 1 : 0;
        break;
    case ValueKind::ZEnable:  // D3DZB_TRUE / D3DZB_USEW / FALSE
        if (auto b = r.boolean()) v = *b ? 1 : 0;
        else if (auto s = r.single(); s && normalizeEnumName(*s) == "usew") v = 1;
        else if (auto n = r.number()) v = *n != 0 ? 1 : 0;
        break;
    case ValueKind::Int:
    case ValueKind::Float:
        v = r.number();
        break;
    case ValueKind::Blend: if (auto e = r.enumeration(blendTable())) v = *e; break;
    case ValueKind::BlendOp: if (auto e = r.enumeration(blendOpTable())) v = *e; break;
    case ValueKind::Compare: if (auto e = r.enumeration(compareTable())) v = *e; break;
    case ValueKind::StencilOp: if (auto e = r.enumeration(stencilOpTable())) v = *e; break;
    case ValueKind::Cull: if (auto e = r.enumeration(cullTable())) v = *e; break;
    case ValueKind::Fill: if (auto e = r.enumeration(fillTable())) v = *e; break;
    case ValueKind::ColorMask: if (auto m = r.colorMask()) v = *m; break;
    case ValueKind::FogMode:
        if (auto e = r.enumeration(fogModeTable())) v = *e;
        break;
    case ValueKind::ShadeMode:
        if (auto e = r.enumeration(shadeModeTable())) v = *e;
        break;
    case ValueKind::Vector4:
        if (auto f = r.vector4()) {
            value = *f;
            return true;
        }
        break;
    }
    if (!v) return false;
    value = {*v, 0, 0, 0};
    return true;
}

const char* describe(ValueKind kind) {
    switch (kind) {
    case ValueKind::Bool: return "true or false";
    case ValueKind::ZEnable: return "true, false or USEW";
    case ValueKind::Int: return "an integer";
    case ValueKind::Float: return "a number";
    case ValueKind::Blend: return "a blend factor (Zero, One, SrcAlpha, InvSrcAlpha, ...)";
    case ValueKind::BlendOp: return "a blend operation (Add, Subtract, RevSubtract, Min, Max)";
    case ValueKind::Compare: return "a comparison (Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always)";
    case ValueKind::StencilOp: return "a stencil operation (Keep, Zero, Replace, IncrSat, DecrSat, Invert, Incr, Decr)";
    case ValueKind::Cull: return "a cull mode (None, CW, CCW)";
    case ValueKind::Fill: return "a fill mode (Point, Wireframe, Solid)";
    case ValueKind::ColorMask: return "a colour mask (RED | GREEN | BLUE | ALPHA, All, None, true, false or a number)";
    case ValueKind::Vector4: return "a float4";
    case ValueKind::FogMode: return "a fog mode (None, Exp, Exp2, Linear)";
    case ValueKind::ShadeMode: return "a shade mode (Flat, Gouraud, Phong)";
    }
    return "valid";
}

// ---- DX10 state objects -----------------------------------------------------------------------

const FxStateObject* findObject(const StateContext& ctx, const std::string& name, const std::string& type) {
    for (const auto& o : ctx.syntax.stateObjects)
        if (o.name == name && iequals(o.type, type)) return &o;
    return nullptr;
}

// Expands a DX10 object into full rows: DX10 objects define every field (unset = D3D10 default).
bool expandDx10Object(const FxStateObject* object, const std::string& type, StateContext& ctx,
                      const SourceLocation& where, std::vector<StateAssignment>& out) {
    std::map<std::string, const FxAssignment*> fields;  // "blendenable[1]" -> assignment
    if (object)
        for (const auto& a : object->assignments)
            fields[toLower(a.name) + (a.index >= 0 ? "[" + std::to_string(a.index) + "]" : "")] = &a;
    bool ok = true;
    auto get = [&](const std::string& key, ValueKind kind, double fallback) -> double {
        auto it = fields.find(key);
        if (it == fields.end() && key.find('[') == std::string::npos) it = fields.find(key + "[0]");
        if (it == fields.end()) return fallback;
        ValueReader r{ctx, *it->second};
        std::array<double, 4> v{};
        if (kind == ValueKind::Bool && toLower(it->second->name) == "depthwritemask") {
            auto s = r.single();
            std::string n = s ? normalizeEnumName(*s) : "";
            fields.erase(it);
            if (n == "all" || n == "depthwritemaskall" || n == "1") return 1;
            if (n == "zero" || n == "depthwritemaskzero" || n == "0") return 0;
            r.bad("ALL or ZERO");
            ok = false;
            return fallback;
        }
        if (!readValue(r, kind, v)) {
            r.bad(describe(kind));
            ok = false;
            return fallback;
        }
        fields.erase(it);
        return v[0];
    };
    auto cullDx10 = [&](bool frontCcw) -> double {
        auto it = fields.find("cullmode");
        std::string n = "back";
        if (it != fields.end()) {
            ValueReader r{ctx, *it->second};
            auto s = r.single();
            n = s ? normalizeEnumName(*s) : "";
            fields.erase(it);
        }
        if (n == "none" || n == "1") return int(CullMode::None);
        bool cullBackFaces = n == "back" || n == "3";
        if (!cullBackFaces && n != "front" && n != "2") {
            ok = false;
            ctx.diagnostics.push_back(ctx.map.makeAt(Severity::Error, diag::kBadStateValue,
                                                     "CullMode of '" + (object ? object->name : type) + "' must be NONE, FRONT or BACK", where));
            return 0;
        }
        // Front faces are clockwise unless FrontCounterClockwise; culling back faces then culls CCW.
        bool cullsCcw = cullBackFaces != frontCcw;
        return cullsCcw ? int(CullMode::CullCounterClockwiseFace) : int(CullMode::CullClockwiseFace);
    };

    if (iequals(type, "BlendState")) {
        double firstEnable = 0;
        for (int i = 0; i < 8; ++i) {
            std::string idx = "[" + std::to_string(i) + "]";
            bool any = fields.count("blendenable" + idx) || fields.count("rendertargetwritemask" + idx) || i == 0;
            if (!any) continue;
            const FxAssignment* enable = fields.count("blendenable" + idx) ? fields["blendenable" + idx] : nullptr;
            double enabled = get("blendenable" + idx, ValueKind::Bool, 0);
            if (i == 0) firstEnable = enabled;
            else if (enable && enabled != firstEnable)
                warnUnhonoured(ctx, *enable, "is not honoured: render target " + std::to_string(i) +
                                                 " blends as target 0 does (XNA's BlendState has one blend enable)");
            if (i >= 4 && fields.count("rendertargetwritemask" + idx))
                warnUnhonoured(ctx, *fields["rendertargetwritemask" + idx], "is not honoured: XNA has four render targets");
            push(out, RenderState::AlphaBlendEnable, enabled, where, i);
            auto mask = fields.find("rendertargetwritemask" + idx);
            double m = 15;
            if (mask != fields.end()) {
                ValueReader r{ctx, *mask->second};
                if (auto c = r.colorMask()) m = *c;
                else {
                    r.bad(describe(ValueKind::ColorMask));
                    ok = false;
                }
                fields.erase(mask);
            }
            push(out, RenderState::ColorWriteEnable, m, where, i);
        }
        push(out, RenderState::SrcBlend, get("srcblend", ValueKind::Blend, int(Blend::One)), where);
        push(out, RenderState::DestBlend, get("destblend", ValueKind::Blend, int(Blend::Zero)), where);
        push(out, RenderState::BlendOp, get("blendop", ValueKind::BlendOp, int(BlendFunction::Add)), where);
        push(out, RenderState::SeparateAlphaBlendEnable, 1, where);
        push(out, RenderState::SrcBlendAlpha, get("srcblendalpha", ValueKind::Blend, int(Blend::One)), where);
        push(out, RenderState::DestBlendAlpha, get("destblendalpha", ValueKind::Blend, int(Blend::Zero)), where);
        push(out, RenderState::BlendOpAlpha, get("blendopalpha", ValueKind::BlendOp, int(BlendFunction::Add)), where);
        if (auto it = fields.find("alphatocoverageenable"); it != fields.end()) {
            if (ValueReader{ctx, *it->second}.boolean().value_or(true))
                warnUnhonoured(ctx, *it->second, "is not honoured: alpha-to-coverage is not implemented (XNA's BlendState has none)");
            fields.erase(it);
        }
    } else if (iequals(type, "DepthStencilState")) {
        push(out, RenderState::ZEnable, get("depthenable", ValueKind::Bool, 1), where);
        push(out, RenderState::ZWriteEnable, get("depthwritemask", ValueKind::Bool, 1), where);
        push(out, RenderState::ZFunc, get("depthfunc", ValueKind::Compare, int(CompareFunction::Less)), where);
        push(out, RenderState::StencilEnable, get("stencilenable", ValueKind::Bool, 0), where);
        push(out, RenderState::StencilMask, get("stencilreadmask", ValueKind::Int, 255), where);
        push(out, RenderState::StencilWriteMask, get("stencilwritemask", ValueKind::Int, 255), where);
        push(out, RenderState::TwoSidedStencilMode, 1, where);
        push(out, RenderState::StencilFunc, get("frontfacestencilfunc", ValueKind::Compare, 7), where);
        push(out, RenderState::StencilPass, get("frontfacestencilpass", ValueKind::StencilOp, 0), where);
        push(out, RenderState::StencilFail, get("frontfacestencilfail", ValueKind::StencilOp, 0), where);
        push(out, RenderState::StencilZFail, get("frontfacestencildepthfail", ValueKind::StencilOp, 0), where);
        push(out, RenderState::CcwStencilFunc, get("backfacestencilfunc", ValueKind::Compare, 7), where);
        push(out, RenderState::CcwStencilPass, get("backfacestencilpass", ValueKind::StencilOp, 0), where);
        push(out, RenderState::CcwStencilFail, get("backfacestencilfail", ValueKind::StencilOp, 0), where);
        push(out, RenderState::CcwStencilZFail, get("backfacestencildepthfail", ValueKind::StencilOp, 0), where);
    } else {  // RasterizerState
        bool frontCcw = get("frontcounterclockwise", ValueKind::Bool, 0) != 0;
        push(out, RenderState::CullMode, cullDx10(frontCcw), where);
        auto fill = fields.find("fillmode");
        double fillValue = int(FillMode::Solid);
        if (fill != fields.end()) {
            ValueReader r{ctx, *fill->second};
            auto s = r.single();
            std::string n = s ? normalizeEnumName(*s) : "";
            if (n == "wireframe" || n == "2") fillValue = int(FillMode::WireFrame);
            else if (n != "solid" && n != "3") {
                r.bad("SOLID or WIREFRAME");
                ok = false;
            }
            fields.erase(fill);
        }
        push(out, RenderState::FillMode, fillValue, where);
        // D3D10's DepthBias counts steps of a 24-bit depth buffer (r = 2^-24); the row holds
        // D3D9's (and XNA's) depth-range units, which the runtime turns back into steps.
        push(out, RenderState::DepthBias, get("depthbias", ValueKind::Float, 0) / 16777216.0, where);
        push(out, RenderState::SlopeScaleDepthBias, get("slopescaleddepthbias", ValueKind::Float, 0), where);
        const FxAssignment* depthClip = fields.count("depthclipenable") ? fields["depthclipenable"] : nullptr;
        double clip = get("depthclipenable", ValueKind::Bool, 1);
        if (depthClip && clip == 0)
            warnUnhonoured(ctx, *depthClip, "= FALSE is not honoured: geometry is clipped at the near and far planes");
        push(out, RenderState::DepthClipEnable, clip, where);
        push(out, RenderState::ScissorTestEnable, get("scissorenable", ValueKind::Bool, 0), where);
        push(out, RenderState::MultiSampleAntiAlias, get("multisampleenable", ValueKind::Bool, 0), where);
        if (auto it = fields.find("antialiasedlineenable"); it != fields.end()) {
            if (ValueReader{ctx, *it->second}.boolean().value_or(true))
                warnUnhonoured(ctx, *it->second, "is not honoured: lines are drawn without antialiasing");
            fields.erase(it);
        }
        if (auto it = fields.find("depthbiasclamp"); it != fields.end()) {
            if (ValueReader{ctx, *it->second}.number().value_or(1) != 0)
                warnUnhonoured(ctx, *it->second, "is not honoured: the depth bias is not clamped");
            fields.erase(it);
        }
    }
    for (const auto& [key, assignment] : fields) {  // whatever is left was not understood
        const Token& t = ctx.syntax.tokens[assignment->nameToken];
        ctx.diagnostics.push_back(ctx.map.make(Severity::Error, diag::kUnknownState,
                                               "unknown field '" + assignment->name + "' in " + type + " '" +
                                                   (object ? object->name : std::string()) + "'",
                                               t.line, t.column, t.text));
        ok = false;
    }
    return ok;
}

StateResult translateDx10Call(const FxAssignment& a, StateContext& ctx, std::vector<StateAssignment>& out,
                              const SourceLocation& where) {
    std::string lower = toLower(a.name);
    // Split arguments at depth-0 commas.
    std::vector<TokenSpan> args;
    size_t b = a.value.begin;
    int depth = 0;
    for (size_t i = a.value.begin; i < a.value.end; ++i) {
        const Token& t = ctx.syntax.tokens[i];
        if (t.is("(")) ++depth;
        if (t.is(")")) --depth;
        if (depth == 0 && t.is(",")) {
            args.push_back({b, i});
            b = i + 1;
        }
    }
    if (b < a.value.end) args.push_back({b, a.value.end});
    std::string type = lower == "setblendstate" ? "BlendState" : lower == "setdepthstencilstate" ? "DepthStencilState" : "RasterizerState";
    if (args.empty()) {
        ctx.diagnostics.push_back(ctx.map.makeAt(Severity::Error, diag::kBadStateValue, a.name + " needs a state object argument", where));
        return StateResult::Failed;
    }
    std::string objectName = ctx.syntax.text(args[0]);
    const FxStateObject* object = nullptr;
    if (!iequals(objectName, "NULL")) {
        object = findObject(ctx, objectName, type);
        if (!object) {
            ctx.diagnostics.push_back(ctx.map.makeAt(Severity::Error, diag::kBadStateValue,
                                                     a.name + " refers to '" + objectName + "', which is not a " + type + " declared in this effect", where));
            return StateResult::Failed;
        }
    }
    if (!expandDx10Object(object, type, ctx, where, out)) return StateResult::Failed;
    if (type == "BlendState" && args.size() >= 2) {
        FxAssignment factor = a;
        factor.value = args[1];
        ValueReader r{ctx, factor};
        if (auto v = r.vector4()) {
            StateAssignment s;
            s.state = RenderState::BlendFactor;
            s.value = std::array<float, 4>{float((*v)[0]), float((*v)[1]), float((*v)[2]), float((*v)[3])};
            s.where = where;
            out.push_back(s);
        }
        if (args.size() >= 3) {
            FxAssignment mask = a;
            mask.value = args[2];
            if (auto m = ValueReader{ctx, mask}.number()) push(out, RenderState::MultiSampleMask, *m, where);
        }
    }
    if (type == "DepthStencilState" && args.size() >= 2) {
        FxAssignment ref = a;
        ref.value = args[1];
        if (auto m = ValueReader{ctx, ref}.number()) push(out, RenderState::StencilRef, *m, where);
    }
    return StateResult::Applied;
}

}  // namespace

// `AlphaRef = <AlphaReference>;` or `ZWriteEnable = <ZWrites[Mode]>;` (also in parentheses): the
// effect framework reads the parameter (element) at Apply(). Nothing when the value names no
// parameter; Failed (error added) when its index is wrong.
static std::optional<StateResult> fromParameter(const FxAssignment& a, StateContext& ctx, StateAssignment& s) {
    if (!ctx.parameters) return std::nullopt;
    const std::vector<Token>& t = ctx.syntax.tokens;
    TokenSpan v = a.value;
    bool bracketed = v.end >= v.begin + 3 && ((t[v.begin].is("<") && t[v.end - 1].is(">")) ||
                                              (t[v.begin].is("(") && t[v.end - 1].is(")")));
    if (bracketed) v = {v.begin + 1, v.end - 1};
    if (v.empty() || !t[v.begin].isIdent()) return std::nullopt;
    auto parameterIndex = [&](const std::string& name) {
        for (std::size_t p = 0; p < ctx.parameters->size(); ++p)
            if ((*ctx.parameters)[p].name == name) return static_cast<int>(p);
        return -1;
    };
    int p = parameterIndex(t[v.begin].text);
    if (p < 0) return std::nullopt;
    if (v.end == v.begin + 1) {
        s.parameter = p;
        return StateResult::Applied;
    }
    if (!t[v.begin + 1].is("[") || !t[v.end - 1].is("]")) return std::nullopt;
    if (auto problem = appendSelector(t, {v.begin + 2, v.end - 1}, parameterIndex, s.element)) {
        ctx.diagnostics.push_back(ctx.map.makeAt(Severity::Error, problem->unsupported ? diag::kUnsupported : diag::kBadStateValue,
                                                 "state '" + a.name + "': " + problem->message, s.where));
        return StateResult::Failed;
    }
    s.parameter = p;
    return StateResult::Applied;
}

StateResult translatePassAssignment(const FxAssignment& a, StateContext& ctx, std::vector<StateAssignment>& out) {
    std::string lower = toLower(a.name);
    const Token& nameTok = ctx.syntax.tokens[a.nameToken];
    SourceLocation where = ctx.map.locate(nameTok.line, nameTok.column, nameTok.text);
    static const std::set<std::string> shaderStates = {"vertexshader", "pixelshader", "geometryshader",
                                                       "hullshader", "domainshader", "computeshader",
                                                       "setvertexshader", "setpixelshader", "setgeometryshader",
                                                       "sethullshader", "setdomainshader", "setcomputeshader"};
    if (shaderStates.count(lower)) return StateResult::NotAState;
    if (a.isCall) {
        if (lower == "setblendstate" || lower == "setdepthstencilstate" || lower == "setrasterizerstate")
            return translateDx10Call(a, ctx, out, where);
        ctx.diagnostics.push_back(ctx.map.make(Severity::Error, diag::kUnknownState, "unknown pass function '" + a.name + "'",
                                               nameTok.line, nameTok.column, nameTok.text));
        return StateResult::Failed;
    }
    // ColorWriteEnable1..3 are the MRT masks.
    int index = a.index >= 0 ? a.index : 0;
    std::string key = lower;
    if (key.size() == 17 && key.rfind("colorwriteenable", 0) == 0 && key[16] >= '1' && key[16] <= '3') {
        index = key[16] - '0';
        key = "colorwriteenable";
    }
    auto it = dx9States().find(key);
    if (it == dx9States().end()) {
        if (isFixedFunctionState(key)) {
            ctx.diagnostics.push_back(ctx.map.make(Severity::Warning, diag::kIgnoredState,
                                                   "fixed-function state '" + a.name + "' has no effect with shaders and is ignored",
                                                   nameTok.line, nameTok.column, nameTok.text));
            return StateResult::Ignored;
        }
        ctx.diagnostics.push_back(ctx.map.make(Severity::Error, diag::kUnknownState, "unknown render state '" + a.name + "'",
                                               nameTok.line, nameTok.column, nameTok.text));
        return StateResult::Failed;
    }
    ValueReader r{ctx, a};
    StateAssignment s;
    s.state = it->second.state;
    s.index = index;
    s.where = where;
    std::array<double, 4> raw{};
    if (!readValue(r, it->second.kind, raw)) {
        if (auto result = fromParameter(a, ctx, s)) {
            if (*result == StateResult::Applied && s.state == RenderState::ClipPlane) {
                // The effect framework hands a parameter-driven state one number at Apply().
                warnUnhonoured(ctx, a, "from a parameter is not honoured: only a literal float4 plane is; the plane stays (0, 0, 0, 0)");
                return StateResult::Ignored;
            }
            if (*result == StateResult::Applied) out.push_back(s);
            return *result;
        }
        r.bad(describe(it->second.kind));
        return StateResult::Failed;
    }
    if (it->second.kind == ValueKind::Vector4)
        s.value = std::array<float, 4>{float(raw[0]), float(raw[1]), float(raw[2]), float(raw[3])};
    else
        s.value = stateValueFromCanonical(s.state, raw[0]);
    if (s.state == RenderState::FillMode && std::get<FillMode>(s.value) == FillMode::Point)
        warnUnhonoured(ctx, a, "= Point is not honoured: drawn as WireFrame (XNA's FillMode has no point mode)");
    if (s.state == RenderState::ZEnable && r.single() && normalizeEnumName(*r.single()) == "usew")
        warnUnhonoured(ctx, a, "= USEW is not honoured: w-buffering is not available, the z-buffer is used");
    if (s.state == RenderState::ClipPlane && s.index > 5)
        warnUnhonoured(ctx, a, "is not honoured: D3D9 drivers have six clip planes (0..5)");
    if (s.state == RenderState::ShadeMode && std::get<int>(s.value) == 3)
        warnUnhonoured(ctx, a, "= Phong is not honoured: shaded as Gouraud (as D3D9 drivers do)");
    if (s.state == RenderState::ColorWriteEnable && s.index > 3)
        warnUnhonoured(ctx, a, "is not honoured: XNA has four render targets");
    out.push_back(s);
    return StateResult::Applied;
}

// The sampler states the effect framework can read from a parameter, by lower-case name.
static std::optional<SamplerStateField> samplerStateField(const std::string& key) {
    static const std::map<std::string, SamplerStateField> fields = {
        {"minfilter", SamplerStateField::MinFilter}, {"magfilter", SamplerStateField::MagFilter}, {"mipfilter", SamplerStateField::MipFilter},
        {"addressu", SamplerStateField::AddressU},   {"addressv", SamplerStateField::AddressV},   {"addressw", SamplerStateField::AddressW},
        {"maxanisotropy", SamplerStateField::MaxAnisotropy}, {"maxmiplevel", SamplerStateField::MaxMipLevel},
        {"mipmaplodbias", SamplerStateField::MipLodBias}};
    auto it = fields.find(key);
    return it == fields.end() ? std::nullopt : std::optional(it->second);
}

bool resolveSamplerStateParameter(const FxAssignment& a, StateContext& ctx, SamplerStateParameter& out) {
    const Token& nameTok = ctx.syntax.tokens[a.nameToken];
    StateAssignment s;
    s.where = ctx.map.locate(nameTok.line, nameTok.column, nameTok.text);
    auto field = samplerStateField(toLower(a.name));
    auto result = field ? fromParameter(a, ctx, s) : std::nullopt;
    if (!result) {
        ctx.diagnostics.push_back(ctx.map.makeAt(Severity::Error, diag::kBadStateValue,
                                                 "sampler state '" + a.name + " = " + ctx.syntax.text(a.value) + "' names no parameter of the effect",
                                                 s.where));
        return false;
    }
    if (*result != StateResult::Applied) return false;
    out.field = *field;
    out.parameter = s.parameter;
    out.element = s.element;
    return true;
}

bool translateSamplerAssignment(const FxAssignment& a, StateContext& ctx, SamplerStateDesc& state,
                                std::string& textureParameter, std::vector<FxAssignment>* fromParameters) {
    ValueReader r{ctx, a, ctx.syntax.looseShaders};
    std::string key = toLower(a.name);
    auto filterOf = [&](const std::string& n) -> std::optional<TextureFilter> {
        if (n == "none" || n == "0") return TextureFilter::None;
        if (n == "point" || n == "1") return TextureFilter::Point;
        if (n == "linear" || n == "2" || n == "pyramidalquad" || n == "gaussianquad" || n == "convolutionmono")
            return TextureFilter::Linear;
        if (n == "anisotropic" || n == "3") return TextureFilter::Anisotropic;
        return std::nullopt;
    };
    auto addressOf = [&](const std::string& n) -> std::optional<TextureAddress> {
        if (n == "wrap" || n == "1") return TextureAddress::Wrap;
        if (n == "mirror" || n == "2") return TextureAddress::Mirror;
        if (n == "clamp" || n == "3") return TextureAddress::Clamp;
        if (n == "border" || n == "4") return TextureAddress::Border;
        if (n == "mirroronce" || n == "5") return TextureAddress::MirrorOnce;
        return std::nullopt;
    };
    auto single = r.single();
    std::string norm = single ? normalizeEnumName(*single) : std::string();
    if (norm.rfind("d3dtexf", 0) == 0) norm = norm.substr(7);
    if (norm.rfind("d3dtaddress", 0) == 0) norm = norm.substr(11);
    if (norm.rfind("textureaddress", 0) == 0) norm = norm.substr(14);

    const std::vector<Token>& tokens = ctx.syntax.tokens;
    if (key != "texture" && a.value.end > a.value.begin + 2 && tokens[a.value.begin].is("<") && tokens[a.value.end - 1].is(">")) {
        // D3D9's effect framework reads the parameter at Apply(): resolved once the effect's
        // parameters are known (resolveSamplerStateParameter).
        if (fromParameters && samplerStateField(key)) {
            fromParameters->push_back(a);
            return true;
        }
        r.error(diag::kUnsupported, "sampler state '" + a.name + " = " + r.text() +
                                        "' reads a parameter at Apply(); fxport reads filters, address modes, anisotropy, levels and bias so");
        return false;
    }
    if (key == "texture") {
        auto name = r.objectName();
        if (!name) {
            r.bad("a texture parameter (<Name> or (Name))");
            return false;
        }
        textureParameter = *name;
        return true;
    }
    if (key == "minfilter" || key == "magfilter" || key == "mipfilter") {
        auto f = filterOf(norm);
        if (!f) {
            r.bad("a filter (None, Point, Linear, Anisotropic)");
            return false;
        }
        if (norm == "pyramidalquad" || norm == "gaussianquad" || norm == "convolutionmono")
            warnUnhonoured(ctx, a, "= " + *single + " is not honoured: filtered as Linear");
        (key == "minfilter" ? state.minFilter : key == "magfilter" ? state.magFilter : state.mipFilter) = *f;
        return true;
    }
    if (key == "filter") {  // DX10: MIN_MAG_MIP_LINEAR, MIN_POINT_MAG_LINEAR_MIP_POINT, ANISOTROPIC ...
        std::string n = single ? toLower(*single) : std::string();
        for (const char* p : {"d3d10_filter_", "d3d11_filter_", "comparison_"})
            if (n.rfind(p, 0) == 0) n = n.substr(std::string_view(p).size());
        if (n.rfind("comparison_", 0) == 0) n = n.substr(11);
        if (n == "anisotropic") {
            state.minFilter = state.magFilter = state.mipFilter = TextureFilter::Anisotropic;
            return true;
        }
        std::vector<std::optional<TextureFilter>*> pending;
        size_t p = 0;
        bool okFilter = !n.empty();
        while (p < n.size() && okFilter) {
            size_t e = n.find('_', p);
            std::string word = n.substr(p, e == std::string::npos ? std::string::npos : e - p);
            p = e == std::string::npos ? n.size() : e + 1;
            if (word == "min") pending.push_back(&state.minFilter);
            else if (word == "mag") pending.push_back(&state.magFilter);
            else if (word == "mip") pending.push_back(&state.mipFilter);
            else if (word == "point" || word == "linear") {
                for (auto* target : pending) *target = word == "point" ? TextureFilter::Point : TextureFilter::Linear;
                pending.clear();
            } else okFilter = false;
        }
        if (!okFilter || !pending.empty()) {
            r.bad("a D3D10 filter such as MIN_MAG_MIP_LINEAR");
            return false;
        }
        return true;
    }
    if (key == "addressu" || key == "addressv" || key == "addressw") {
        auto ad = addressOf(norm);
        if (!ad) {
            r.bad("an address mode (Wrap, Mirror, Clamp, Border, MirrorOnce)");
            return false;
        }
        if (*ad == TextureAddress::MirrorOnce)
            warnUnhonoured(ctx, a, "= MirrorOnce is not honoured: sampled as Mirror (XNA's TextureAddressMode has no MirrorOnce)");
        (key == "addressu" ? state.addressU : key == "addressv" ? state.addressV : state.addressW) = *ad;
        return true;
    }
    if (key == "bordercolor") {
        auto v = r.vector4();
        if (!v) {
            r.bad("a colour (float4 or 0xAARRGGBB)");
            return false;
        }
        state.borderColor = std::array<float, 4>{float((*v)[0]), float((*v)[1]), float((*v)[2]), float((*v)[3])};
        return true;
    }
    auto numeric = [&](auto& field) {
        auto n = r.number();
        if (!n) {
            r.bad("a number");
            return false;
        }
        field = static_cast<std::remove_reference_t<decltype(*field)>>(*n);
        return true;
    };
    if (key == "maxanisotropy") return numeric(state.maxAnisotropy);
    if (key == "maxmiplevel") return numeric(state.maxMipLevel);
    if (key == "mipmaplodbias" || key == "miplodbias") return numeric(state.mipLodBias);
    if (key == "minlod" || key == "maxlod") {
        bool ok = numeric(key == "minlod" ? state.minLod : state.maxLod);
        // The defaults (0 and FLT_MAX) restrict nothing; a narrower mip range is not reproduced.
        if (ok && ((state.minLod && *state.minLod > 0) || (state.maxLod && *state.maxLod < 1000)))
            warnUnhonoured(ctx, a, "is not honoured: SamplerState has no mip-level range (MaxMipLevel is XNA's only limit)");
        return ok;
    }
    if (key == "comparisonfunc") {
        auto f = r.enumeration(compareTable());
        if (!f) {
            r.bad(describe(ValueKind::Compare));
            return false;
        }
        state.comparison = CompareFunction(*f);
        return true;
    }
    if (key == "srgbtexture" || key == "elementindex" || key == "dmapoffset") {
        const Token& t = ctx.syntax.tokens[a.nameToken];
        ctx.diagnostics.push_back(ctx.map.make(Severity::Warning, diag::kIgnoredState,
                                               "sampler state '" + a.name + "' is not supported and is ignored", t.line,
                                               t.column, t.text));
        return true;
    }
    r.error(diag::kUnknownState, "unknown sampler state '" + a.name + "'");
    return false;
}

bool isTextureStageSamplerState(const std::string& lower) {
    static const std::set<std::string> k = {"minfilter", "magfilter", "mipfilter", "addressu", "addressv", "addressw", "bordercolor",
                                            "maxanisotropy", "maxmiplevel", "mipmaplodbias", "srgbtexture"};
    return k.count(lower) > 0;
}

void overlaySamplerState(SamplerStateDesc& base, const SamplerStateDesc& over) {
    auto take = [](auto& to, const auto& from) {
        if (from) to = from;
    };
    take(base.minFilter, over.minFilter);
    take(base.magFilter, over.magFilter);
    take(base.mipFilter, over.mipFilter);
    take(base.addressU, over.addressU);
    take(base.addressV, over.addressV);
    take(base.addressW, over.addressW);
    take(base.borderColor, over.borderColor);
    take(base.maxAnisotropy, over.maxAnisotropy);
    take(base.maxMipLevel, over.maxMipLevel);
    take(base.mipLodBias, over.mipLodBias);
    take(base.minLod, over.minLod);
    take(base.maxLod, over.maxLod);
    take(base.comparison, over.comparison);
}

}  // namespace fxport::xlate
