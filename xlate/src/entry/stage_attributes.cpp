// Entry attributes of compute, hull and domain shaders (see stage_attributes.h).
#include "entry/stage_attributes.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <regex>
#include <vector>

#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

struct Attribute {
    bool hasArguments = false;
    std::vector<std::string> arguments;  // trimmed, quotes removed
};

std::string trimmed(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(s.begin());
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
    return s;
}

// Where the bracket, parenthesis or quote opened at `text[open]` closes (npos when it does not).
size_t closingOf(const std::string& text, size_t open) {
    std::string expected;  // the closers still owed, innermost last
    for (size_t k = open; k < text.size(); ++k) {
        const char c = text[k];
        if (!expected.empty() && expected.back() == '"') {
            if (c == '"') expected.pop_back();
        } else if (c == '"') {
            expected += '"';
        } else if (c == '(' || c == '[' || c == '{') {
            expected += c == '(' ? ')' : c == '[' ? ']' : '}';
        } else if (!expected.empty() && c == expected.back()) {
            expected.pop_back();
        }
        if (expected.empty()) return k;
    }
    return std::string::npos;
}

// `args` split at its top-level commas: `max(128, 32), 1, 1` is three arguments.
std::vector<std::string> splitArguments(const std::string& args) {
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t k = 0; k <= args.size(); ++k) {
        if (k < args.size() && (args[k] == '(' || args[k] == '[' || args[k] == '{' || args[k] == '"')) {
            size_t close = closingOf(args, k);
            k = close == std::string::npos ? args.size() - 1 : close;
        } else if (k == args.size() || args[k] == ',') {
            out.push_back(trimmed(args.substr(start, k - start)));
            start = k + 1;
        }
    }
    if (out.size() == 1 && out[0].empty()) out.clear();
    return out;
}

// "[numthreads(8, 8, 1)] [domain("tri")]" -> {numthreads: [8, 8, 1], domain: [tri]}. Names as
// written: fxc's attribute names are case-sensitive ([NumThreads] is no numthreads).
std::map<std::string, Attribute> parseAttributes(const std::string& text) {
    std::map<std::string, Attribute> out;
    size_t i = 0;
    while ((i = text.find('[', i)) != std::string::npos) {
        size_t end = closingOf(text, i);
        if (end == std::string::npos) break;
        std::string body = text.substr(i + 1, end - i - 1);
        i = end + 1;
        size_t open = body.find('(');
        Attribute a;
        std::string name = trimmed(body.substr(0, open));
        if (open != std::string::npos) {
            a.hasArguments = true;
            size_t close = body.rfind(')');
            a.arguments = splitArguments(body.substr(open + 1, (close == std::string::npos ? body.size() : close) - open - 1));
        }
        out[name] = a;
    }
    return out;
}

// The N of an `InputPatch<T, N>` / `OutputPatch<T, N>` parameter of `entry`; 0 if none.
int patchSize(const FxFunction& entry, const char* patchType) {
    for (const auto& p : entry.parameters) {
        std::string t = p.type;
        t.erase(std::remove_if(t.begin(), t.end(), [](unsigned char c) { return std::isspace(c); }), t.end());
        if (toLower(t).rfind(toLower(patchType) + "<", 0) != 0) continue;
        size_t comma = t.rfind(','), close = t.rfind('>');
        if (comma == std::string::npos || close == std::string::npos || close < comma) return 0;
        try {
            return std::stoi(t.substr(comma + 1, close - comma - 1));
        } catch (const std::exception&) {
            return 0;
        }
    }
    return 0;
}

bool oneOf(const std::string& v, std::initializer_list<const char*> allowed) {
    for (const char* a : allowed)
        if (v == a) return true;
    return false;
}

// One string attribute: present, one argument, one of `allowed`; "" when fine.
std::string stringAttribute(const std::map<std::string, Attribute>& attrs, const char* name, std::initializer_list<const char*> allowed,
                            std::string& value) {
    auto it = attrs.find(name);
    if (it == attrs.end()) return std::string("needs the attribute [") + name + "(...)]";
    if (it->second.arguments.size() != 1) return std::string("[") + name + "] takes one string argument";
    value = toLower(it->second.arguments[0]);
    if (!oneOf(value, allowed)) {
        std::string list;
        for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string("\"") + a + "\"";
        return std::string("[") + name + "(\"" + it->second.arguments[0] + "\")] is not one of " + list;
    }
    return {};
}

}  // namespace

bool hasAttribute(const FxFunction& entry, const std::string& name) { return parseAttributes(entry.attributes).count(name) > 0; }

std::string checkStageAttributes(const EffectSyntax& syntax, const FxFunction& entry, const ShaderProfile& profile, Tessellation& out) {
    std::map<std::string, Attribute> attrs = parseAttributes(entry.attributes);
    const std::string who = "'" + entry.name + "' (" + profile.name + ") ";
    if (profile.stage == ShaderStage::Compute) {
        auto it = attrs.find("numthreads");
        if (it == attrs.end()) return who + "needs the attribute [numthreads(x, y, z)] (fxc X3647)";
        if (it->second.arguments.size() != 3) return who + "[numthreads] takes three arguments: [numthreads(x, y, z)]";
        // Literal sizes are checked here (what glslang makes of 0 or -1 is its own); sizes from
        // constants are checked on the SPIR-V's LocalSize (checkThreadGroupSize).
        for (const std::string& a : it->second.arguments) {
            // A vector of one component is no scalar here: `uint(1)` compiles, `uint1(1)` is
            // refused (vkd3d's numthreads).
            static const std::regex vector(R"(^\s*(u?int|float|half|double|bool|dword|min16u?int|min16float)[1-4]\s*\()");
            if (std::regex_search(a, vector))
                return who + "[numthreads]: '" + a + "' is a vector; each thread-group dimension is one integer";
            char* end = nullptr;
            long n = std::strtol(a.c_str(), &end, 0);
            if (end && *end == '\0' && !a.empty() && n < 1)
                return who + "[numthreads(" + it->second.arguments[0] + ", " + it->second.arguments[1] + ", " + it->second.arguments[2] +
                       ")]: each thread-group dimension must be at least 1";
        }
        return {};
    }
    if (profile.stage != ShaderStage::Hull && profile.stage != ShaderStage::Domain) return {};
    if (std::string e = stringAttribute(attrs, "domain", {"tri", "quad", "isoline"}, out.domain); !e.empty()) return who + e;
    if (profile.stage == ShaderStage::Domain) {
        out.inputControlPoints = patchSize(entry, "OutputPatch");
        return {};
    }
    if (std::string e = stringAttribute(attrs, "partitioning", {"integer", "fractional_even", "fractional_odd", "pow2"}, out.partitioning); !e.empty())
        return who + e;
    if (std::string e = stringAttribute(attrs, "outputtopology", {"point", "line", "triangle_cw", "triangle_ccw"}, out.outputTopology); !e.empty())
        return who + e;
    if (out.domain == "isoline" && (out.outputTopology == "triangle_cw" || out.outputTopology == "triangle_ccw"))
        return who + "[outputtopology(\"" + out.outputTopology + "\")] cannot tessellate an isoline domain";
    // Lines come out of an isoline domain only (vkd3d's hull-shader-attributes: "line" with a tri
    // or quad domain is refused).
    if (out.outputTopology == "line" && out.domain != "isoline")
        return who + "[outputtopology(\"line\")] needs [domain(\"isoline\")]: a " + out.domain + " domain tessellates to triangles or points";
    auto points = attrs.find("outputcontrolpoints");
    if (points == attrs.end()) return who + "needs the attribute [outputcontrolpoints(N)]";
    int n = 0;
    try {
        if (points->second.arguments.size() == 1) n = std::stoi(points->second.arguments[0]);
    } catch (const std::exception&) {
        n = -1;
    }
    if (n < 0 || n > 32 || points->second.arguments.size() != 1) return who + "[outputcontrolpoints] must be one number from 0 to 32";
    out.outputControlPoints = n;
    std::string function;
    auto pc = attrs.find("patchconstantfunc");
    if (pc == attrs.end()) return who + "needs the attribute [patchconstantfunc(\"name\")]";
    if (pc->second.arguments.size() != 1 || pc->second.arguments[0].empty()) return who + "[patchconstantfunc] takes the name of a function";
    out.patchConstantFunction = pc->second.arguments[0];
    // The patch-constant function runs once per patch beside the per-control-point entry: fxc
    // does not take the entry itself there (vkd3d's hull-shader-attributes, not implemented).
    if (out.patchConstantFunction == entry.name)
        return who + "[patchconstantfunc(\"" + out.patchConstantFunction + "\")] names the entry point itself, which fxc does not implement";
    if (!syntax.findFunction(out.patchConstantFunction))
        return who + "[patchconstantfunc(\"" + out.patchConstantFunction + "\")] names no function of this shader";
    out.inputControlPoints = patchSize(entry, "InputPatch");
    if (out.inputControlPoints == 0)
        if (const FxFunction* f = syntax.findFunction(out.patchConstantFunction)) out.inputControlPoints = patchSize(*f, "InputPatch");
    if (out.inputControlPoints < 0 || out.inputControlPoints > 32) return who + "InputPatch takes 1 to 32 control points";
    return {};
}

std::string checkThreadGroupSize(const std::array<int, 3>& size, const ShaderProfile& profile) {
    const bool sm5 = profile.major >= 5;
    const int maxXY = sm5 ? 1024 : 768, maxZ = sm5 ? 64 : 1, maxTotal = sm5 ? 1024 : 768;
    double total = 1;  // in double: three source numbers up to 2^31 each
    for (int n : size) total *= n;
    auto text = [&] { return "[numthreads(" + std::to_string(size[0]) + ", " + std::to_string(size[1]) + ", " + std::to_string(size[2]) + ")]"; };
    if (size[0] < 1 || size[1] < 1 || size[2] < 1) return text() + ": each thread-group dimension must be at least 1";
    if (size[0] > maxXY || size[1] > maxXY || size[2] > maxZ || total > maxTotal)
        return text() + " is outside " + profile.name + "'s limits (x, y <= " + std::to_string(maxXY) + ", z <= " + std::to_string(maxZ) +
               ", x*y*z <= " + std::to_string(maxTotal) + ")";
    return {};
}

}  // namespace fxport::xlate
