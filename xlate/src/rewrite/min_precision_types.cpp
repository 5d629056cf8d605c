// See min_precision_types.h.
#include "rewrite/min_precision_types.h"

#include <regex>

namespace fxport::xlate {

const char* fullPrecisionScalar(const std::string& name) {
    if (name == "half" || name == "min16float" || name == "min10float") return "float";
    if (name == "min16int" || name == "min12int") return "int";
    if (name == "min16uint") return "uint";
    return nullptr;
}

std::string fullPrecisionMatrixName(const Token& t) { return t.isIdent() ? fullPrecisionMatrixName(t.text) : std::string(); }

std::string fullPrecisionMatrixName(const std::string& name) {
    if (name.rfind("min1", 0) != 0) return {};
    static const std::regex matrix(R"((min16float|min10float|min16int|min12int|min16uint)([1-4]x[1-4]))");
    std::smatch m;
    if (!std::regex_match(name, m, matrix)) return {};
    return fullPrecisionScalar(m[1].str()) + m[2].str();
}

}  // namespace fxport::xlate
