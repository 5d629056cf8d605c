#include "hlsl/hlsl_types.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "fx/text_util.h"

namespace fxport::xlate {

BasicType describeBasicType(const std::string& typeIn) {
    BasicType b;
    std::string t;
    for (char c : typeIn)
        if (c != ' ') t += c;
    if (t.rfind("vector<", 0) == 0 || t.rfind("matrix<", 0) == 0) {
        bool matrix = t[0] == 'm';
        std::string inner = t.substr(7, t.size() - 8);
        std::vector<std::string> parts;
        std::stringstream ss(inner);
        std::string p;
        while (std::getline(ss, p, ',')) parts.emplace_back(p);
        if (parts.empty()) return b;
        b.scalar = parts[0];
        if (matrix && parts.size() == 3) {
            b.rows = std::atoi(parts[1].c_str());
            b.columns = std::atoi(parts[2].c_str());
            b.isMatrix = true;
        } else if (!matrix && parts.size() == 2) {
            b.columns = std::atoi(parts[1].c_str());
        } else {
            return b;
        }
        b.ok = b.rows >= 1 && b.rows <= 4 && b.columns >= 1 && b.columns <= 4;
        return b;
    }
    static const char* const scalars[] = {"min16float", "min10float", "min16int", "min12int", "min16uint",
                                          "float", "half", "double", "int", "uint", "bool", "dword"};
    for (const char* s : scalars) {
        std::string_view sv(s);
        if (t.rfind(sv, 0) != 0) continue;
        std::string rest = t.substr(sv.size());
        b.scalar = s;
        if (rest.empty()) {
            b.ok = true;
        } else if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') {
            b.columns = rest[0] - '0';
            b.ok = true;
        } else if (rest.size() == 3 && rest[1] == 'x' && rest[0] >= '1' && rest[0] <= '4' && rest[2] >= '1' && rest[2] <= '4') {
            b.rows = rest[0] - '0';
            b.columns = rest[2] - '0';
            b.isMatrix = true;
            b.ok = true;
        }
        return b;
    }
    if (t == "matrix") return {"float", 4, 4, true, true};
    if (t == "vector") return {"float", 1, 4, false, true};
    return b;
}

}  // namespace fxport::xlate
