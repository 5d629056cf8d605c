// ReadFontDescription and FindFontFile: XNA's .spritefont XML description, and the font file its
// FontName and Style stand for (a file beside it, else fontconfig's match).
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fxport/platform/utf8.h"
#include "fxport/platform/file_reading.h"
#include "fxport/framework/sprite_font_import.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

namespace fs = std::filesystem;

// A tiny reader for the flat XML of .spritefont files: elements with text, comments, the XML
// declaration, character references (&#32; &#x20;) and the five named entities.
class DescriptionReader {
public:
    DescriptionReader(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}

    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        const int line = 1 + int(std::count(text_.begin(), text_.begin() + std::ptrdiff_t(std::min(at, text_.size())), '\n'));
        throw ArgumentError(path_ + "(" + std::to_string(line) + "): " + message);
    }

    // The decoded text of every <name>...</name> element, with where each starts.
    std::vector<std::pair<std::string, std::size_t>> elements(const std::string& name) const {
        std::vector<std::pair<std::string, std::size_t>> found;
        const std::string open = "<" + name, close = "</" + name + ">";
        for (std::size_t at = text_.find(open); at != std::string::npos; at = text_.find(open, at + 1)) {
            if (insideComment(at)) continue;
            const std::size_t after = at + open.size();
            if (after >= text_.size() || (text_[after] != '>' && text_[after] != ' ' && text_[after] != '/')) continue;
            const std::size_t gt = text_.find('>', after);
            if (gt == std::string::npos) fail(at, "<" + name + " is not closed");
            if (text_[gt - 1] == '/') {  // <Name/>
                found.emplace_back("", at);
                continue;
            }
            const std::size_t end = text_.find(close, gt);
            if (end == std::string::npos) fail(at, "<" + name + "> has no " + close);
            found.emplace_back(decode(text_.substr(gt + 1, end - gt - 1), at), at);
        }
        return found;
    }

    std::optional<std::pair<std::string, std::size_t>> element(const std::string& name) const {
        auto all = elements(name);
        if (all.empty()) return std::nullopt;
        return all.front();
    }

    // Text between an element's tags, for nested elements (CharacterRegion's Start/End).
    std::string rawInner(std::size_t at, const std::string& name) const {
        const std::size_t gt = text_.find('>', at);
        const std::size_t end = text_.find("</" + name + ">", gt);
        return text_.substr(gt + 1, end - gt - 1);
    }

    std::string decode(const std::string& raw, std::size_t at) const {
        std::string out;
        for (std::size_t i = 0; i < raw.size();) {
            if (raw[i] != '&') {
                out += raw[i++];
                continue;
            }
            const std::size_t semicolon = raw.find(';', i);
            if (semicolon == std::string::npos) fail(at, "'&' without ';'");
            const std::string entity = raw.substr(i + 1, semicolon - i - 1);
            char32_t c = 0;
            if (entity == "amp") c = '&';
            else if (entity == "lt") c = '<';
            else if (entity == "gt") c = '>';
            else if (entity == "quot") c = '"';
            else if (entity == "apos") c = '\'';
            else if (entity.size() > 1 && entity[0] == '#') {
                const bool hex = entity[1] == 'x' || entity[1] == 'X';
                char* end = nullptr;
                const std::string digits = entity.substr(hex ? 2 : 1);
                const unsigned long v = std::strtoul(digits.c_str(), &end, hex ? 16 : 10);
                if (digits.empty() || *end != '\0' || v > 0x10FFFF) fail(at, "bad character reference &" + entity + ";");
                c = char32_t(v);
            } else {
                fail(at, "unknown entity &" + entity + ";");
            }
            platform::appendUtf8(out, c);
            i = semicolon + 1;
        }
        return out;
    }

private:
    bool insideComment(std::size_t at) const {
        const std::size_t open = text_.rfind("<!--", at);
        if (open == std::string::npos) return false;
        const std::size_t close = text_.find("-->", open);
        return close == std::string::npos || close > at;
    }

    std::string path_;
    std::string text_;
};

std::string trim(const std::string& s) {
    const std::size_t first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// The one code point of a decoded UTF-8 text (a character element).
char32_t singleCharacter(const DescriptionReader& reader, const std::string& text, std::size_t at, const char* what) {
    const auto* p = reinterpret_cast<const unsigned char*>(text.data());
    char32_t c = 0;
    std::size_t length = 0;
    if (text.empty()) reader.fail(at, std::string(what) + " is empty");
    if (p[0] < 0x80) c = p[0], length = 1;
    else if ((p[0] & 0xE0) == 0xC0 && text.size() >= 2) c = char32_t(((p[0] & 0x1F) << 6) | (p[1] & 0x3F)), length = 2;
    else if ((p[0] & 0xF0) == 0xE0 && text.size() >= 3)
        c = char32_t(((p[0] & 0x0F) << 12) | ((p[1] & 0x3F) << 6) | (p[2] & 0x3F)), length = 3;
    else if ((p[0] & 0xF8) == 0xF0 && text.size() >= 4)
        c = char32_t(((p[0] & 0x07) << 18) | ((p[1] & 0x3F) << 12) | ((p[2] & 0x3F) << 6) | (p[3] & 0x3F)), length = 4;
    if (length != text.size()) reader.fail(at, std::string(what) + " '" + text + "' is not one character");
    return c;
}

float number(const DescriptionReader& reader, const std::string& text, std::size_t at, const char* what) {
    char* end = nullptr;
    const std::string t = trim(text);
    const float v = std::strtof(t.c_str(), &end);
    if (t.empty() || *end != '\0') reader.fail(at, std::string(what) + " '" + t + "' is not a number");
    return v;
}

}  // namespace

FontDescription ReadFontDescription(const std::string& spritefontFile) {
    platform::FileBytes file = platform::readUntrustedFile(spritefontFile);
    if (!file.ok()) throw ArgumentError("SpriteFont: " + file.error);
    const DescriptionReader reader(spritefontFile, std::string(file.bytes.begin(), file.bytes.end()));
    FontDescription d;
    auto name = reader.element("FontName");
    if (!name || trim(name->first).empty()) reader.fail(0, "no <FontName>");
    d.FontName = trim(name->first);
    if (auto size = reader.element("Size")) d.Size = number(reader, size->first, size->second, "<Size>");
    if (!(d.Size > 0)) reader.fail(reader.element("Size")->second, "<Size> must be positive");
    if (auto spacing = reader.element("Spacing")) d.Spacing = number(reader, spacing->first, spacing->second, "<Spacing>");
    if (auto kerning = reader.element("UseKerning")) {
        const std::string v = trim(kerning->first);
        if (v == "true") d.UseKerning = true;
        else if (v == "false") d.UseKerning = false;
        else reader.fail(kerning->second, "<UseKerning> '" + v + "' is not true or false");
    }
    if (auto style = reader.element("Style")) {
        std::string v = trim(style->first);
        v.erase(std::remove(v.begin(), v.end(), ' '), v.end());
        if (v == "Regular") d.Style = FontDescriptionStyle::Regular;
        else if (v == "Bold") d.Style = FontDescriptionStyle::Bold;
        else if (v == "Italic") d.Style = FontDescriptionStyle::Italic;
        else if (v == "Bold,Italic" || v == "Italic,Bold") d.Style = FontDescriptionStyle::BoldItalic;
        else reader.fail(style->second, "<Style> '" + trim(style->first) + "' is not Regular, Bold, Italic or \"Bold, Italic\"");
    }
    if (auto c = reader.element("DefaultCharacter"))
        d.DefaultCharacter = singleCharacter(reader, c->first, c->second, "<DefaultCharacter>");
    const auto regions = reader.elements("CharacterRegion");
    if (!regions.empty()) {
        d.CharacterRegions.clear();
        for (const auto& [text, at] : regions) {
            const DescriptionReader inner(spritefontFile, reader.rawInner(at, "CharacterRegion"));
            auto start = inner.element("Start");
            auto end = inner.element("End");
            if (!start || !end) reader.fail(at, "<CharacterRegion> needs <Start> and <End>");
            const char32_t first = singleCharacter(reader, start->first, at, "<Start>");
            const char32_t last = singleCharacter(reader, end->first, at, "<End>");
            if (last < first) reader.fail(at, "<CharacterRegion> ends before it starts");
            d.CharacterRegions.emplace_back(first, last);
        }
    }
    return d;
}

std::string FindFontFile(const FontDescription& description, const std::string& besideFile) {
    // A font file named like FontName beside the description (or FontName is itself a path).
    const fs::path folder = fs::path(besideFile).parent_path();
    for (const fs::path& candidate : {folder / description.FontName, folder / (description.FontName + ".ttf"),
                                     folder / (description.FontName + ".otf"), fs::path(description.FontName)}) {
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return candidate.string();
    }
    // fontconfig's best match for the family and style.
    if (!FcInit()) throw ArgumentError(besideFile + ": fontconfig could not start to find '" + description.FontName + "'");
    FcPattern* pattern = FcPatternCreate();
    FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>(description.FontName.c_str()));
    const bool bold = description.Style == FontDescriptionStyle::Bold || description.Style == FontDescriptionStyle::BoldItalic;
    const bool italic = description.Style == FontDescriptionStyle::Italic || description.Style == FontDescriptionStyle::BoldItalic;
    FcPatternAddInteger(pattern, FC_WEIGHT, bold ? FC_WEIGHT_BOLD : FC_WEIGHT_REGULAR);
    FcPatternAddInteger(pattern, FC_SLANT, italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN);
    FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(nullptr, pattern, &result);
    FcPatternDestroy(pattern);
    std::string file, family;
    if (match) {
        FcChar8* value = nullptr;
        if (FcPatternGetString(match, FC_FILE, 0, &value) == FcResultMatch) file = reinterpret_cast<const char*>(value);
        if (FcPatternGetString(match, FC_FAMILY, 0, &value) == FcResultMatch) family = reinterpret_cast<const char*>(value);
        FcPatternDestroy(match);
    }
    if (file.empty())
        throw ArgumentError(besideFile + ": no font file for FontName '" + description.FontName + "' (none beside it, and fontconfig found none)");
    if (family != description.FontName)
        std::fprintf(stderr, "fxport: note: %s: font '%s' is not installed; using '%s' (%s)\n", besideFile.c_str(),
                     description.FontName.c_str(), family.c_str(), file.c_str());
    return file;
}

}  // namespace fxport
