// Splitting a .shader_test file into blocks (see shader_test_file.h).
#include "shader_test_file.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace conformance {

const char* stageName(Stage stage) {
    switch (stage) {
    case Stage::Pixel: return "pixel";
    case Stage::Vertex: return "vertex";
    case Stage::Effect: return "effect";
    case Stage::Geometry: return "geometry";
    case Stage::Compute: return "compute";
    case Stage::Hull: return "hull";
    case Stage::Domain: return "domain";
    }
    return "?";
}

std::string Block::source() const {
    std::string out;
    for (const Line& l : lines) out += l.text + "\n";
    return out;
}

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

std::string trimmed(const std::string& s) {
    std::size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    std::size_t e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

bool parseSlotHeader(const std::string& header, const std::string& word, int& slot) {
    if (!startsWith(header, word + " ")) return false;
    slot = std::stoi(header.substr(word.size() + 1));
    return true;
}

bool parseShaderHeader(const std::string& header, Block& block) {
    static const struct { const char* name; Stage stage; } kStages[] = {
        {"pixel shader", Stage::Pixel},     {"vertex shader", Stage::Vertex},  {"effect", Stage::Effect},
        {"geometry shader", Stage::Geometry}, {"compute shader", Stage::Compute}, {"hull shader", Stage::Hull},
        {"domain shader", Stage::Domain},
    };
    for (const auto& s : kStages) {
        std::string name = s.name;
        if (header != name && !startsWith(header, name + " ")) continue;
        block.kind = BlockKind::Shader;
        block.stage = s.stage;
        block.qualifiers = trimmed(header.substr(name.size()));
        block.hexBytecode = block.qualifiers.find("-hex") != std::string::npos;
        return true;
    }
    return false;
}

// Fills kind/slot/stage of a block from its header; false when the header is unknown.
bool classifyHeader(const std::string& header, Block& block) {
    static const struct { const char* name; BlockKind kind; } kPlain[] = {
        {"require", BlockKind::Require}, {"test", BlockKind::Test},       {"dsv", BlockKind::Dsv},
        {"input layout", BlockKind::InputLayout}, {"preproc", BlockKind::Preproc},
        {"preproc fail", BlockKind::PreprocFail},
    };
    for (const auto& p : kPlain)
        if (header == p.name) { block.kind = p.kind; return true; }
    static const struct { const char* word; BlockKind kind; } kSlotted[] = {
        {"srv", BlockKind::Srv}, {"texture", BlockKind::Srv}, {"uav", BlockKind::Uav}, {"rtv", BlockKind::Rtv},
        {"vb", BlockKind::VertexBuffer}, {"sampler", BlockKind::Sampler},
    };
    for (const auto& s : kSlotted)
        if (parseSlotHeader(header, s.word, block.slot)) { block.kind = s.kind; return true; }
    return parseShaderHeader(header, block);
}

bool keepsEveryLine(const Block& block) {
    return block.kind == BlockKind::Shader || block.kind == BlockKind::Preproc || block.kind == BlockKind::PreprocFail;
}

}  // namespace

ShaderTestFile parseShaderTestFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    ShaderTestFile file;
    file.path = path;
    std::size_t slash = path.find_last_of('/');
    file.name = path.substr(slash == std::string::npos ? 0 : slash + 1);
    if (file.name.size() > 12 && file.name.ends_with(".shader_test")) file.name.resize(file.name.size() - 12);
    std::string text;
    int number = 0;
    while (std::getline(in, text)) {
        ++number;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (startsWith(text, "[")) {
            std::size_t close = text.find(']');
            Block block;
            block.line = number;
            block.header = text.substr(1, close == std::string::npos ? std::string::npos : close - 1);
            if (!classifyHeader(block.header, block))
                throw std::runtime_error(path + ":" + std::to_string(number) + ": unknown section '[" + block.header + "]'");
            file.blocks.push_back(std::move(block));
            continue;
        }
        if (file.blocks.empty()) continue;
        Block& block = file.blocks.back();
        if (!keepsEveryLine(block) && (trimmed(text).empty() || startsWith(text, "%"))) continue;
        // vkd3d drops `%` lines everywhere; in a shader they become blank so that line k of the
        // section is still line (header + k) of the file in diagnostics.
        if (startsWith(text, "%")) text.clear();
        block.lines.push_back({number, text});
    }
    return file;
}

}  // namespace conformance
