// See rasterizer_ordered_views.h.
#include "rewrite/rasterizer_ordered_views.h"

#include <cctype>

namespace fxport::xlate {

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t skipSpace(const std::string& s, size_t at) {
    while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at]))) ++at;
    return at;
}

}  // namespace

std::string rasterizerOrderedViewsAsUavs(const std::string& preprocessed, std::vector<std::string>& names) {
    static const std::string kPrefix = "RasterizerOrdered";
    std::string out;
    size_t done = 0;
    for (size_t at = preprocessed.find(kPrefix); at != std::string::npos; at = preprocessed.find(kPrefix, at + 1)) {
        if (at > 0 && identifierChar(preprocessed[at - 1])) continue;
        size_t end = at + kPrefix.size();
        while (end < preprocessed.size() && identifierChar(preprocessed[end])) ++end;
        const std::string kind = preprocessed.substr(at + kPrefix.size(), end - at - kPrefix.size());
        if (kind.rfind("Texture", 0) != 0 && kind != "Buffer" && kind != "StructuredBuffer" && kind != "ByteAddressBuffer") continue;
        out += preprocessed.substr(done, at - done) + "RW" + kind;
        done = end;
        // The declared name: after the template arguments, if any.
        size_t k = skipSpace(preprocessed, end);
        if (k < preprocessed.size() && preprocessed[k] == '<') {
            int depth = 0;
            for (; k < preprocessed.size(); ++k) {
                if (preprocessed[k] == '<') ++depth;
                if (preprocessed[k] == '>' && --depth == 0) break;
            }
            k = skipSpace(preprocessed, k + 1);
        }
        size_t nameEnd = k;
        while (nameEnd < preprocessed.size() && identifierChar(preprocessed[nameEnd])) ++nameEnd;
        if (nameEnd > k) names.push_back(preprocessed.substr(k, nameEnd - k));
    }
    return out + preprocessed.substr(done);
}

}  // namespace fxport::xlate
