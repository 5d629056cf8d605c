// Parsing of vkd3d's fixed-function test states (see fixed_function_states.h).
#include "fixed_function_states.h"

#include <sstream>
#include <stdexcept>

namespace conformance {

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

std::istringstream rest(const std::string& s, const std::string& prefix) { return std::istringstream(s.substr(prefix.size())); }

void parseFog(const std::string& d, FixedFunctionDesc& f) {
    std::istringstream in = rest(d, "fog");
    std::string mode, projection;
    in >> mode;
    if (mode == "disable") { f.fog = false; return; }
    f.fog = true;
    f.fogFromW = false;
    if (mode == "none") { f.fogMode = 0; return; }
    in >> projection;
    if (projection != "ortho" && projection != "non-ortho") throw std::runtime_error("fog: unknown projection '" + projection + "'");
    f.fogFromW = projection == "non-ortho";
    if (mode == "linear") {
        f.fogMode = 3;
        if (!(in >> f.fogStart >> f.fogEnd)) throw std::runtime_error("fog linear: needs start and end");
    } else if (mode == "exp" || mode == "exp2") {
        f.fogMode = mode == "exp" ? 1 : 2;
        if (!(in >> f.fogDensity)) throw std::runtime_error("fog " + mode + ": needs a density");
    } else {
        throw std::runtime_error("fog: unknown mode '" + mode + "'");
    }
}

void parseAlphaTest(const std::string& d, FixedFunctionDesc& f) {
    static const char* const kFunctions[] = {"never", "less equal", "less", "equal", "greater equal", "greater", "not equal", "always"};
    std::string args = d.substr(std::string("alpha test").size());
    args.erase(0, args.find_first_not_of(' '));
    for (const char* name : kFunctions) {
        if (!startsWith(args, name)) continue;
        f.alphaTest = true;
        f.alphaFunction = name;
        std::istringstream(args.substr(std::string(name).size())) >> f.alphaReference;
        return;
    }
    throw std::runtime_error("alpha test: unknown function in '" + d + "'");
}

}  // namespace

bool parseFixedFunctionState(const std::string& d, FixedFunctionDesc& f) {
    if (startsWith(d, "fog-colour")) {
        std::istringstream in = rest(d, "fog-colour");
        if (!(in >> f.fogColour[0] >> f.fogColour[1] >> f.fogColour[2] >> f.fogColour[3])) throw std::runtime_error("fog-colour: needs r g b a");
        return true;
    }
    if (startsWith(d, "fog ") || d == "fog") {
        FixedFunctionDesc parsed = f;  // a malformed line changes nothing
        parseFog(d, parsed);
        f = parsed;
        return true;
    }
    if (startsWith(d, "point-size ")) {
        std::istringstream in = rest(d, "point-size");
        if (!(in >> f.pointSize >> f.pointSizeMin >> f.pointSizeMax)) throw std::runtime_error("point-size: needs size min max");
        return true;
    }
    if (startsWith(d, "point-sprite ")) {
        std::istringstream in = rest(d, "point-sprite");
        std::string state;
        in >> state;
        if (state != "on" && state != "off") throw std::runtime_error("point-sprite: on or off, not '" + state + "'");
        f.pointSprite = state == "on";
        return true;
    }
    if (startsWith(d, "clip-plane ")) {
        std::istringstream in = rest(d, "clip-plane");
        unsigned index = 0;
        std::array<float, 4> p{};
        if (!(in >> index >> p[0] >> p[1] >> p[2] >> p[3]) || index >= f.clipPlanes.size())
            throw std::runtime_error("clip-plane: needs an index below 8 and a b c d");
        f.clipPlanes[index] = p;
        f.clipPlaneMask |= 1u << index;
        return true;
    }
    if (startsWith(d, "alpha test")) { parseAlphaTest(d, f); return true; }
    if (startsWith(d, "shade mode")) {
        std::istringstream in = rest(d, "shade mode");
        std::string mode;
        in >> mode;
        if (mode != "flat" && mode != "linear") throw std::runtime_error("shade mode: flat or linear, not '" + mode + "'");
        f.flatShading = mode == "flat";
        return true;
    }
    return false;
}

std::string FixedFunctionDesc::firstSet() const {
    if (fog) return "fog";
    if (pointSize != 1 || pointSizeMin != 1 || pointSizeMax != 64) return "point-size";
    if (pointSprite) return "point-sprite";
    if (clipPlaneMask) return "clip-plane";
    if (alphaTest) return "alpha test";
    if (flatShading) return "shade mode";
    return "";
}

bool isFixedFunctionCapability(const std::string& c) { return c == "fog" || c == "point-size" || c == "clip-planes"; }

}  // namespace conformance
