#include "fx/shader_profile.h"

#include <map>
#include <tuple>

#include "fx/text_util.h"

namespace fxport::xlate {

std::optional<ShaderProfile> parseShaderProfile(const std::string& name) {
    std::string n = toLower(name);
    ShaderProfile p;
    p.name = name;
    if (n.rfind("vs_", 0) == 0) p.stage = ShaderStage::Vertex;
    else if (n.rfind("ps_", 0) == 0) p.stage = ShaderStage::Pixel;
    else if (n.rfind("gs_", 0) == 0) p.stage = ShaderStage::Geometry;
    else if (n.rfind("hs_", 0) == 0) p.stage = ShaderStage::Hull;
    else if (n.rfind("ds_", 0) == 0) p.stage = ShaderStage::Domain;
    else if (n.rfind("cs_", 0) == 0) p.stage = ShaderStage::Compute;
    else return std::nullopt;
    std::string rest = n.substr(3);
    size_t level = rest.find("_level_9_");
    if (level != std::string::npos) rest = rest.substr(0, level);
    static const std::map<std::string, std::pair<int, int>> versions = {
        {"1_1", {1, 1}}, {"1_2", {1, 2}}, {"1_3", {1, 3}}, {"1_4", {1, 4}}, {"2_0", {2, 0}}, {"2_a", {2, 1}},
        {"2_b", {2, 2}}, {"2_sw", {2, 0}}, {"2_x", {2, 1}}, {"3_0", {3, 0}}, {"3_sw", {3, 0}}, {"4_0", {4, 0}},
        {"4_1", {4, 1}}, {"5_0", {5, 0}}};
    auto it = versions.find(rest);
    if (it == versions.end()) return std::nullopt;
    std::tie(p.major, p.minor) = it->second;
    if (p.stage == ShaderStage::Geometry && p.major < 4) return std::nullopt;
    // fxc: cs_4_0/cs_4_1 (DirectCompute on D3D10 hardware), hull and domain shaders from 5.0 only.
    if (p.stage == ShaderStage::Compute && p.major < 4) return std::nullopt;
    if ((p.stage == ShaderStage::Hull || p.stage == ShaderStage::Domain) && p.major < 5) return std::nullopt;
    if (p.stage >= ShaderStage::Hull && level != std::string::npos) return std::nullopt;
    if (p.stage == ShaderStage::Vertex && p.major == 1 && p.minor != 1) return std::nullopt;
    return p;
}

}  // namespace fxport::xlate
