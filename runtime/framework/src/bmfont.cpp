// LoadBMFont: AngelCode BMFont text-format .fnt files (info/common/page/char/kerning lines of
// key=value pairs) and their page images, mapped onto XNA's SpriteFont (sprite_font_import.h).
#include <stb_image.h>

#include <climits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fxport/framework/sprite_font_import.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/platform/file_reading.h"
#include "glyph_atlas.h"

namespace fxport {

namespace {

// One line: its tag and its key=value pairs (values may be "quoted").
struct FntLine {
    std::string tag;
    std::map<std::string, std::string> values;
};

FntLine parseLine(const std::string& line) {
    FntLine result;
    std::size_t i = 0;
    auto skipSpace = [&] { while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i; };
    skipSpace();
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') result.tag += line[i++];
    for (;;) {
        skipSpace();
        if (i >= line.size()) break;
        std::string key;
        while (i < line.size() && line[i] != '=' && line[i] != ' ') key += line[i++];
        std::string value;
        if (i < line.size() && line[i] == '=') {
            ++i;
            if (i < line.size() && line[i] == '"') {
                ++i;
                while (i < line.size() && line[i] != '"') value += line[i++];
                ++i;
            } else {
                while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') value += line[i++];
            }
        }
        result.values[key] = value;
    }
    return result;
}

class FntReader {
public:
    FntReader(std::string path) : path_(std::move(path)) {}
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw ArgumentError(path_ + "(" + std::to_string(line) + "): " + message);
    }
    int integer(const FntLine& l, int line, const char* key) const {
        auto it = l.values.find(key);
        if (it == l.values.end()) fail(line, "'" + l.tag + "' has no " + key + "=");
        char* end = nullptr;
        const long v = std::strtol(it->second.c_str(), &end, 10);
        if (it->second.empty() || *end != '\0') fail(line, std::string(key) + "=" + it->second + " is not a number");
        return int(v);
    }

private:
    std::string path_;
};

}  // namespace

std::unique_ptr<SpriteFont> LoadBMFont(GraphicsDevice& device, const std::string& fntFile) {
    platform::FileBytes fnt = platform::readUntrustedFile(fntFile);
    if (!fnt.ok()) throw ArgumentError("BMFont: " + fnt.error);
    std::istringstream in(std::string(fnt.bytes.begin(), fnt.bytes.end()));
    std::string firstBytes(3, '\0');
    in.read(firstBytes.data(), 3);
    in.clear();
    if (firstBytes == "BMF")
        throw ArgumentError(fntFile + ": binary BMFont files are not read; export the text format (.fnt 'text')");
    if (firstBytes[0] == '<')
        throw ArgumentError(fntFile + ": XML BMFont files are not read; export the text format (.fnt 'text')");
    in.seekg(0);

    const FntReader reader(fntFile);
    int lineHeight = -1, pageWidth = 0, pageHeight = 0, pageCount = 0, kerningPairs = 0;
    std::map<int, std::string> pageFiles;
    struct Char { int id, x, y, width, height, xoffset, yoffset, xadvance, page, line; };
    std::vector<Char> chars;
    std::string text;
    for (int lineNumber = 1; std::getline(in, text); ++lineNumber) {
        const FntLine l = parseLine(text);
        if (l.tag == "common") {
            lineHeight = reader.integer(l, lineNumber, "lineHeight");
            pageWidth = reader.integer(l, lineNumber, "scaleW");
            pageHeight = reader.integer(l, lineNumber, "scaleH");
            pageCount = reader.integer(l, lineNumber, "pages");
        } else if (l.tag == "page") {
            auto file = l.values.find("file");
            if (file == l.values.end()) reader.fail(lineNumber, "'page' has no file=");
            pageFiles[reader.integer(l, lineNumber, "id")] = file->second;
        } else if (l.tag == "char") {
            Char c{reader.integer(l, lineNumber, "id"),      reader.integer(l, lineNumber, "x"),
                   reader.integer(l, lineNumber, "y"),       reader.integer(l, lineNumber, "width"),
                   reader.integer(l, lineNumber, "height"),  reader.integer(l, lineNumber, "xoffset"),
                   reader.integer(l, lineNumber, "yoffset"), reader.integer(l, lineNumber, "xadvance"),
                   l.values.count("page") ? reader.integer(l, lineNumber, "page") : 0, lineNumber};
            if (c.id < 0 || c.width < 0 || c.height < 0) reader.fail(lineNumber, "negative id, width or height");
            chars.push_back(c);
        } else if (l.tag == "kerning") {
            ++kerningPairs;
        }
    }
    if (lineHeight < 0) reader.fail(1, "no 'common' line (lineHeight, scaleW, scaleH, pages)");
    if (chars.empty()) reader.fail(1, "no 'char' lines");

    // Page images, premultiplied (BMFont pages are straight alpha).
    struct Page { int width = 0, height = 0; std::vector<Color> texels; };
    std::map<int, Page> pages;
    for (const auto& [id, pageFile] : pageFiles) {
        const std::string path = (std::filesystem::path(fntFile).parent_path() / pageFile).string();
        int w = 0, h = 0, channels = 0;
        platform::FileBytes image = platform::readUntrustedFile(path);
        if (!image.ok()) throw ArgumentError(fntFile + ": page " + std::to_string(id) + ": " + image.error);
        if (image.bytes.size() > std::size_t(INT_MAX)) throw ArgumentError(fntFile + ": page '" + path + "' is too large");
        stbi_uc* data = stbi_load_from_memory(image.bytes.data(), int(image.bytes.size()), &w, &h, &channels, 4);
        if (!data) throw ArgumentError(fntFile + ": page " + std::to_string(id) + " '" + path + "': " + stbi_failure_reason());
        Page page;
        page.width = w;
        page.height = h;
        page.texels.resize(std::size_t(w) * std::size_t(h));
        for (std::size_t i = 0; i < page.texels.size(); ++i) {
            const stbi_uc* p = data + 4 * i;
            // A one-channel (grey) page is coverage: white glyphs, the grey value as alpha.
            const int a = channels == 1 ? p[0] : p[3];
            const int r = channels == 1 ? 255 : p[0], g = channels == 1 ? 255 : p[1], b = channels == 1 ? 255 : p[2];
            page.texels[i] = Color((r * a + 127) / 255, (g * a + 127) / 255, (b * a + 127) / 255, a);
        }
        stbi_image_free(data);
        pages[id] = std::move(page);
    }
    (void)pageWidth;
    (void)pageHeight;
    (void)pageCount;

    GlyphAtlasBuilder atlas;
    for (const Char& c : chars) {
        auto page = pages.find(c.page);
        if (page == pages.end())
            reader.fail(c.line, "char id=" + std::to_string(c.id) + " is on page " + std::to_string(c.page) + ", which has no 'page' line");
        if (c.x < 0 || c.y < 0 || c.x + c.width > page->second.width || c.y + c.height > page->second.height)
            reader.fail(c.line, "char id=" + std::to_string(c.id) + " lies outside its " + std::to_string(page->second.width) +
                                    "x" + std::to_string(page->second.height) + " page");
        AtlasGlyph g;
        g.character = char32_t(c.id);
        g.width = c.width;
        g.height = c.height;
        for (int row = 0; row < c.height; ++row)
            for (int column = 0; column < c.width; ++column)
                g.rgba.push_back(page->second.texels[std::size_t(c.y + row) * std::size_t(page->second.width) +
                                                     std::size_t(c.x + column)]);
        g.cropping = Rectangle(0, c.yoffset, c.width, lineHeight);
        g.kerning = Vector3(float(c.xoffset), float(c.width), float(c.xadvance - c.xoffset - c.width));
        atlas.add(std::move(g));
    }
    if (kerningPairs > 0)
        std::fprintf(stderr, "fxport: warning: %s: %d kerning pairs ignored (XNA's SpriteFont has per-glyph spacing only)\n",
                     fntFile.c_str(), kerningPairs);
    return atlas.build(device, fntFile, lineHeight, 0.0f, std::nullopt);
}

}  // namespace fxport
