#include "fx/source_map.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>
#include <sstream>

#include "fx/text_util.h"

namespace fxport::xlate {

int SourceMap::fileIndex(const std::string& file) {
    for (size_t i = 0; i < fileOrder_.size(); ++i)
        if (fileOrder_[i] == file) return static_cast<int>(i);
    fileOrder_.push_back(file);
    return static_cast<int>(fileOrder_.size() - 1);
}

std::string SourceMap::build(const std::string& preprocessed, const std::string& rootFile) {
    lines_.clear();
    int current = fileIndex(rootFile);
    int nextLine = 1;
    std::string out;
    out.reserve(preprocessed.size());
    size_t pos = 0;
    while (pos <= preprocessed.size()) {
        size_t end = preprocessed.find('\n', pos);
        if (end == std::string::npos) end = preprocessed.size();
        std::string_view line(preprocessed.data() + pos, end - pos);
        std::string_view t = trim(line);
        if (t.rfind("#line", 0) == 0) {
            // `#line N "file"`: the NEXT line is line N of file.
            std::string rest(trim(t.substr(5)));
            char* after = nullptr;
            long n = std::strtol(rest.c_str(), &after, 10);
            std::string_view tail = trim(std::string_view(after));
            if (tail.size() >= 2 && tail.front() == '"') {
                // The preprocessor's markers name files as we gave them. A `#line 2 "Road.fx"` the
                // effect itself wrote, naming its own file by its bare name, keeps the path we know
                // (so the diagnostic can quote the line and editors can open it).
                std::string name(tail.substr(1, tail.find('"', 1) - 1));
                auto baseIs = [&](const std::string& path) {
                    size_t slash = path.find_last_of("/\\");
                    return slash != std::string::npos && path.compare(slash + 1, std::string::npos, name) == 0;
                };
                if (fileLines_.count(name) || !baseIs(fileOrder_[static_cast<size_t>(current)])) {
                    int known = -1;
                    for (size_t i = 0; i < fileOrder_.size() && known < 0 && !fileLines_.count(name); ++i)
                        if (baseIs(fileOrder_[i])) known = static_cast<int>(i);
                    current = known >= 0 ? known : fileIndex(name);
                }
            }
            lines_.push_back({current, 0});
            nextLine = static_cast<int>(std::clamp<long>(n, 0, INT_MAX));  // input_limits rejects #line past INT_MAX
            out.append("\n");
        } else {
            lines_.push_back({current, nextLine});
            if (nextLine < INT_MAX) ++nextLine;
            out.append(line);
            out.append("\n");
        }
        if (end == preprocessed.size()) break;
        pos = end + 1;
    }
    return out;
}

void SourceMap::addFileText(const std::string& file, std::string text) {
    std::vector<std::string> lines;
    std::string cur;
    for (char c : text) {
        if (c == '\n') {
            if (!cur.empty() && cur.back() == '\r') cur.pop_back();
            lines.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    lines.push_back(cur);
    fileLines_[file] = std::move(lines);
}

std::string SourceMap::originalLine(const std::string& file, int line) const {
    auto it = fileLines_.find(file);
    if (it == fileLines_.end() || line < 1 || line > static_cast<int>(it->second.size())) return {};
    return it->second[static_cast<size_t>(line - 1)];
}

namespace {

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Where `token` is on the original line: the preprocessed column is right unless a macro or a
// removed comment moved the text, so the occurrence nearest to it wins, a whole word before a
// part of one (an undeclared `c` is not the `c` in `which` before it).
size_t findToken(const std::string& text, const std::string& token, int column) {
    if (token.empty()) return std::string::npos;
    size_t best = std::string::npos;
    long bestScore = 0;
    for (size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + 1)) {
        bool word = (at == 0 || !isWordChar(text[at - 1]) || !isWordChar(token.front())) &&
                    (at + token.size() >= text.size() || !isWordChar(text[at + token.size()]) || !isWordChar(token.back()));
        long score = (word ? 0 : 1L << 30) + std::labs(static_cast<long>(at) + 1 - std::max(column, 1));
        if (best == std::string::npos || score < bestScore) {
            best = at;
            bestScore = score;
        }
    }
    return best;
}

}  // namespace

SourceLocation SourceMap::locate(int line, int column, const std::string& token) const {
    SourceLocation loc;
    if (lines_.empty()) {
        loc.file = fileOrder_.empty() ? std::string() : fileOrder_[0];
        return loc;
    }
    // Past the last line, or on a line of no file (a marker, what glslang appends at the end): the
    // end of the nearest line before it that has one (where "unexpected end of file" happens).
    size_t index = static_cast<size_t>(std::clamp(line, 1, static_cast<int>(lines_.size())) - 1);
    bool atEnd = line > static_cast<int>(lines_.size());
    while (index > 0 && lines_[index].line == 0) {
        --index;
        atEnd = true;
    }
    const LineOrigin& o = lines_[index];
    if (atEnd && o.line > 0) {
        loc.file = fileOrder_[static_cast<size_t>(o.fileIndex)];
        loc.line = o.line;
        loc.column = static_cast<int>(originalLine(loc.file, o.line).size()) + 1;
        return loc;
    }
    loc.file = fileOrder_[static_cast<size_t>(o.fileIndex)];
    loc.line = o.line;
    auto it = fileLines_.find(loc.file);
    if (it != fileLines_.end() && o.line >= 1 && o.line <= static_cast<int>(it->second.size())) {
        const std::string& text = it->second[static_cast<size_t>(o.line - 1)];
        size_t at = findToken(text, token, column);
        if (at != std::string::npos) {
            loc.column = static_cast<int>(at) + 1;
        } else if (column > 0) {
            loc.column = column;
        } else {
            size_t first = text.find_first_not_of(" \t");
            loc.column = first == std::string::npos ? 1 : static_cast<int>(first) + 1;
        }
    } else {
        loc.column = column;
    }
    return loc;
}

Diagnostic SourceMap::make(Severity severity, const char* id, std::string message, int line, int column,
                           const std::string& token) const {
    return makeAt(severity, id, std::move(message), locate(line, column, token));
}

Diagnostic SourceMap::makeAt(Severity severity, const char* id, std::string message, SourceLocation where) const {
    Diagnostic d;
    d.severity = severity;
    d.id = id;
    d.message = std::move(message);
    d.sourceLine = originalLine(where.file, where.line);
    d.location = std::move(where);
    return d;
}

}  // namespace fxport::xlate
