// Stream-output declarations: parsed as the D3D10/11 effect runtimes parse them, checked by D3D's
// rules and resolved to GLSL variables (stream_output.h).
#include "fxport/xlate/stream_output.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace fxport::xlate {

namespace {

std::string trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return std::string(s);
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// "[slot:]SEMANTIC[index][.mask]" -> one entry.
bool parseEntry(std::string text, int stream, StreamOutputEntry& e, std::string& error) {
    e = {};
    e.stream = stream;
    if (size_t colon = text.find(':'); colon != std::string::npos) {
        std::string slot = trimmed(std::string_view(text).substr(0, colon));
        if (slot.empty() || !std::all_of(slot.begin(), slot.end(), [](unsigned char c) { return std::isdigit(c); }) || slot.size() > 3 ||
            std::stoi(slot) >= kStreamOutputSlots) {
            error = "invalid output slot '" + slot + "' in '" + text + "' (0 to 3)";
            return false;
        }
        e.outputSlot = std::stoi(slot);
        text = trimmed(std::string_view(text).substr(colon + 1));
    }
    if (size_t dot = text.find('.'); dot != std::string::npos) {
        const std::string mask = text.substr(dot + 1);
        size_t at = std::string_view("xyzw").find(mask);
        if (at == std::string_view::npos) at = std::string_view("rgba").find(mask);
        if (mask.empty() || at == std::string_view::npos) {
            error = "invalid component mask '" + mask + "' in '" + text + "' (a run of xyzw or rgba, such as .xyz or .w)";
            return false;
        }
        e.startComponent = static_cast<int>(at);
        e.componentCount = static_cast<int>(mask.size());
        text.resize(dot);
    }
    size_t digits = text.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(text[digits - 1]))) --digits;
    if (digits < text.size()) {
        if (text.size() - digits > 4) {
            error = "semantic index out of range in '" + text + "'";
            return false;
        }
        e.semanticIndex = std::stoi(text.substr(digits));
        text.resize(digits);
    }
    const bool identifier = !text.empty() && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_') &&
                            std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
    if (text == "$SKIP") return true;  // a gap: no semantic
    if (!identifier) {
        error = "invalid semantic '" + text + "'";
        return false;
    }
    e.semanticName = text;
    return true;
}

std::string entryText(const StreamOutputEntry& e) {
    static const char* kMask = "xyzw";
    return (e.semanticName.empty() ? std::string("$SKIP") : e.semanticName + std::to_string(e.semanticIndex)) + "." +
           std::string(kMask + e.startComponent, kMask + e.startComponent + e.componentCount);
}

}  // namespace

bool parseStreamOutputDeclaration(std::string_view text, int stream, std::vector<StreamOutputEntry>& entries, std::string& error) {
    while (true) {
        const size_t semi = text.find(';');
        std::string one = trimmed(text.substr(0, semi));
        if (!one.empty()) {
            StreamOutputEntry e;
            if (!parseEntry(one, stream, e, error)) return false;
            entries.push_back(e);
        }
        if (semi == std::string_view::npos) return true;
        text.remove_prefix(semi + 1);
    }
}

bool resolveStreamOutput(const std::vector<ShaderOutput>& outputs, StreamOutput& so, std::string& error) {
    if (so.entries.size() > 128) {
        error = std::to_string(so.entries.size()) + " stream-output entries (D3D allows 128)";
        return false;
    }
    if (so.rasterizedStream != kNoRasterizedStream && (so.rasterizedStream < 0 || so.rasterizedStream > 3)) {
        error = "rasterized stream " + std::to_string(so.rasterizedStream) + " (0 to 3, or -1 for none)";
        return false;
    }
    if (so.rasterizedStream > 0) {  // GL rasterizes stream 0
        error = "rasterized stream " + std::to_string(so.rasterizedStream) + ": fxport rasterizes stream 0 only (or none)";
        return false;
    }
    std::array<int, kStreamOutputSlots> used{};
    std::array<int, kStreamOutputSlots> slotStream{-1, -1, -1, -1};
    std::set<std::string> captured;
    for (StreamOutputEntry& e : so.entries) {
        const std::string what = "stream-output entry '" + entryText(e) + "'";
        if (e.outputSlot < 0 || e.outputSlot >= kStreamOutputSlots || e.stream < 0 || e.stream > 3) {
            error = what + " names output slot " + std::to_string(e.outputSlot) + " of stream " + std::to_string(e.stream);
            return false;
        }
        if (e.startComponent < 0 || e.componentCount < 1 || e.startComponent + e.componentCount > 4) {
            error = what + ": components " + std::to_string(e.startComponent) + ".." + std::to_string(e.startComponent + e.componentCount - 1) +
                    " are outside a 4-component register";
            return false;
        }
        if (slotStream[e.outputSlot] >= 0 && slotStream[e.outputSlot] != e.stream) {
            error = what + ": output slot " + std::to_string(e.outputSlot) + " already takes stream " + std::to_string(slotStream[e.outputSlot]);
            return false;
        }
        slotStream[e.outputSlot] = e.stream;
        used[e.outputSlot] += 4 * e.componentCount;
        if (e.semanticName.empty()) continue;
        const std::string semantic = upper(e.semanticName) + std::to_string(e.semanticIndex);
        auto out = std::find_if(outputs.begin(), outputs.end(), [&](const ShaderOutput& o) { return o.semantic == semantic; });
        if (out == outputs.end()) {
            error = what + ": the shader has no output with semantic " + semantic;
            return false;
        }
        if (e.startComponent + e.componentCount > out->components) {
            error = what + ": output " + semantic + " has " + std::to_string(out->components) + " component" + (out->components > 1 ? "s" : "");
            return false;
        }
        if (e.stream != 0) {
            error = what + ": fxport captures stream 0 only";
            return false;
        }
        // GL captures whole variables: a part of one would need a variable of its own in the shader.
        if (e.startComponent != 0 || e.componentCount != out->components) {
            error = what + ": fxport captures an output whole (" + semantic + " has " + std::to_string(out->components) + " components)";
            return false;
        }
        if (!captured.insert(semantic).second) {
            error = what + ": " + semantic + " is captured twice (GL captures a variable once)";
            return false;
        }
        e.varying = out->glslName;
    }
    for (int slot = 0; slot < kStreamOutputSlots; ++slot) {
        int& stride = so.strides[static_cast<size_t>(slot)];
        if (stride == 0) stride = used[static_cast<size_t>(slot)];
        if (stride < used[static_cast<size_t>(slot)] || stride % 4 != 0 || stride > 2048) {
            error = "output slot " + std::to_string(slot) + " has stride " + std::to_string(stride) + " for " +
                    std::to_string(used[static_cast<size_t>(slot)]) + " bytes of entries (a multiple of 4, at most 2048)";
            return false;
        }
    }
    return true;
}

std::vector<std::string> capturedVaryings(const StreamOutput& so) {
    std::vector<std::string> names;
    auto skip = [&](int n) {
        for (; n > 0; n -= std::min(n, 4)) names.push_back("gl_SkipComponents" + std::to_string(std::min(n, 4)));
    };
    int buffer = 0;  // the GL buffer the names go to: gl_NextBuffer moves to the next
    for (int slot = 0; slot < kStreamOutputSlots; ++slot) {
        int components = 0;
        for (const StreamOutputEntry& e : so.entries) {
            if (e.outputSlot != slot || e.stream != 0) continue;
            for (; buffer < slot; ++buffer) names.push_back("gl_NextBuffer");
            if (e.varying.empty()) skip(e.componentCount);
            else names.push_back(e.varying);
            components += e.componentCount;
        }
        if (components > 0) skip(so.strides[static_cast<size_t>(slot)] / 4 - components);
    }
    return names;
}

}  // namespace fxport::xlate
