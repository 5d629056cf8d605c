// Decoding of effect sources (see text_encoding.h).
#include "fx/text_encoding.h"

#include <cstdint>

namespace fxport::xlate {

namespace {

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

std::string utf16ToUtf8(std::string_view bytes, bool bigEndian) {
    constexpr std::uint32_t kReplacement = 0xFFFD;
    std::string out;
    out.reserve(bytes.size() / 2 + 8);
    auto unit = [&](size_t i) {
        auto a = static_cast<unsigned char>(bytes[i]), b = static_cast<unsigned char>(bytes[i + 1]);
        return static_cast<std::uint32_t>(bigEndian ? (a << 8) | b : (b << 8) | a);
    };
    size_t i = 0;
    for (; i + 1 < bytes.size(); i += 2) {
        std::uint32_t u = unit(i);
        if (u >= 0xD800 && u < 0xDC00 && i + 3 < bytes.size()) {
            std::uint32_t low = unit(i + 2);
            if (low >= 0xDC00 && low < 0xE000) {
                appendUtf8(out, 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00));
                i += 2;
                continue;
            }
        }
        appendUtf8(out, u >= 0xD800 && u < 0xE000 ? kReplacement : u);
    }
    if (i < bytes.size()) appendUtf8(out, kReplacement);
    return out;
}

// Whether text[end - 1] ends a well-formed UTF-8 sequence.
bool endsUtf8Sequence(const std::string& text, size_t end) {
    for (size_t len = 1; len <= 4 && len <= end; ++len) {
        auto lead = static_cast<unsigned char>(text[end - len]);
        if ((lead & 0xC0) == 0x80) continue;  // a continuation byte: look further back
        size_t want = lead < 0x80 ? 1 : (lead & 0xE0) == 0xC0 ? 2 : (lead & 0xF0) == 0xE0 ? 3 : (lead & 0xF8) == 0xF0 ? 4 : 0;
        return want == len;
    }
    return false;
}

// Shift-JIS writes the second byte of many characters as 0x5C, the backslash: a `//` comment ending
// in 表 or ソ would continue onto the next line and swallow it. Written by people who meant no
// continuation, in comments the compiler drops: that backslash becomes a space. (A backslash after
// text that is UTF-8, or after a byte that cannot lead a Shift-JIS pair, is left alone.)
void keepShiftJisCommentsOnTheirLine(std::string& text) {
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        size_t last = end;
        while (last > start && text[last - 1] == '\r') --last;
        if (last >= start + 2 && text[last - 1] == '\\') {
            auto lead = static_cast<unsigned char>(text[last - 2]);
            bool shiftJisLead = (lead >= 0x81 && lead <= 0x9F) || (lead >= 0xE0 && lead <= 0xFC);
            size_t comment = text.find("//", start);
            if (shiftJisLead && comment < last - 2 && !endsUtf8Sequence(text, last - 1)) text[last - 1] = ' ';
        }
        start = end + 1;
    }
}

}  // namespace

std::string sourceTextAsUtf8(std::string_view raw) {
    std::string text;
    if (raw.substr(0, 3) == "\xEF\xBB\xBF") text = std::string(raw.substr(3));
    else if (raw.substr(0, 2) == "\xFF\xFE") text = utf16ToUtf8(raw.substr(2), false);
    else if (raw.substr(0, 2) == "\xFE\xFF") text = utf16ToUtf8(raw.substr(2), true);
    else text = std::string(raw);
    // A DOS end-of-file mark (Ctrl-Z) ends the text; classic Mac line ends (a lone CR) are lines.
    while (!text.empty() && text.back() == '\x1A') text.pop_back();
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
    keepShiftJisCommentsOnTheirLine(text);
    return text;
}

}  // namespace fxport::xlate
