#include "fx/preprocess.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "d3d9asm/d3d9_asm.h"
#include "fx/define_ternaries.h"
#include "fx/glslang_predefines.h"
#include "frontend/glslang_process.h"
#include "fx/macro_bounds.h"
#include "fx/stray_quotes.h"
#include "fx/string_escapes.h"
#include "fx/text_encoding.h"
#include "fx/input_limits.h"
#include "fx/text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

void checkIsText(const std::string& source, const std::string& displayPath) {
    // NUL and control bytes anywhere mean a binary file. Bytes that are not UTF-8 are fine inside
    // comments and string literals (effects written on Windows carry Latin-1, GBK or Shift-JIS
    // there: comments never reach the compiler, strings are annotation metadata, made UTF-8 by the
    // lexer); anywhere else they cannot be HLSL.
    enum class In { Code, LineComment, BlockComment, String } state = In::Code;
    int line = 1;
    size_t i = 0, lineStart = 0;
    auto fail = [&](const std::string& what) {
        Diagnostic d;
        d.id = diag::kNotText;
        d.message = "the file is not HLSL text (" + what + ")";
        d.location = {displayPath, line, static_cast<int>(i - lineStart) + 1};
        throw CompileError({d});
    };
    // A repository cloned without Git LFS leaves small text pointers where the files were; they
    // would fail as HLSL on their first line, which says nothing of the cause.
    if (source.rfind("version https://git-lfs.github.com/spec/", 0) == 0)
        fail("it is a Git LFS pointer, not the file's content: fetch the content with `git lfs pull`");
    while (i < source.size()) {
        auto c = static_cast<unsigned char>(source[i]);
        if (c == 0) fail("it contains a NUL byte");
        if (c == '\n') {
            // A // comment ends with its line unless the line ends in a backslash; strings end there too.
            size_t last = i;
            while (last > lineStart && source[last - 1] == '\r') --last;
            bool continued = last > lineStart && source[last - 1] == '\\';
            if ((state == In::LineComment && !continued) || state == In::String) state = In::Code;
            ++line;
            lineStart = ++i;
            continue;
        }
        if (c < 0x20 && c != '\r' && c != '\t' && c != '\f' && c != '\v') fail("it contains control characters");
        char next = i + 1 < source.size() ? source[i + 1] : '\0';
        switch (state) {
        case In::Code:
            if (c == '/' && next == '/') state = In::LineComment;
            else if (c == '/' && next == '*') state = In::BlockComment;
            else if (c == '"') state = In::String;
            if (state != In::Code) {
                i += c == '"' ? 1 : 2;
                continue;
            }
            break;
        case In::LineComment:
            ++i;
            continue;
        case In::BlockComment:
            if (c == '*' && next == '/') {
                state = In::Code;
                i += 2;
            } else {
                ++i;
            }
            continue;
        case In::String:
            if (c == '\\' && next != '\n' && next != '\0') ++i;
            else if (c == '"') state = In::Code;
            ++i;
            continue;
        }
        if (c < 0x80) {
            ++i;
            continue;
        }
        int extra = (c & 0xE0) == 0xC0 ? 1 : (c & 0xF0) == 0xE0 ? 2 : (c & 0xF8) == 0xF0 ? 3 : -1;
        if (extra < 0) fail("it is not valid UTF-8 outside comments and strings");
        for (int k = 1; k <= extra; ++k)
            if (i + static_cast<size_t>(k) >= source.size() || (static_cast<unsigned char>(source[i + static_cast<size_t>(k)]) & 0xC0) != 0x80)
                fail("it is not valid UTF-8 outside comments and strings");
        i += static_cast<size_t>(extra) + 1;
    }
}

namespace {

// `##` next to a parenthesis, comma, bracket, brace or ';' in a #define (HBAO+'s `register(##SLOT##)`)
// can paste nothing: fxc's preprocessor leaves the tokens side by side, glslang's refuses the paste
// ("'##' : not supported for these tokens"). Such a `##` becomes spaces (columns keep).
void dropImpossiblePastes(std::string& text, size_t start, size_t end) {
    static const std::string kNeverPasted = "()[]{},;";
    bool quoted = false;
    for (size_t k = start; k + 1 < end; ++k) {
        if (text[k] == '"') quoted = !quoted;
        if (quoted || text[k] != '#' || text[k + 1] != '#') continue;
        size_t before = k, after = k + 2;
        while (before > start && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
        while (after < end && (text[after] == ' ' || text[after] == '\t')) ++after;
        const bool previousNeverPastes = before > start && kNeverPasted.find(text[before - 1]) != std::string::npos;
        const bool nextNeverPastes = after < end && kNeverPasted.find(text[after]) != std::string::npos;
        if (previousNeverPastes || nextNeverPastes) text[k] = text[k + 1] = ' ';
        ++k;
    }
}

bool isDefineLine(const std::string& text, size_t start, size_t end) {
    size_t hash = text.find_first_not_of(" \t", start);
    if (hash >= end || text[hash] != '#') return false;
    size_t word = text.find_first_not_of(" \t", hash + 1);
    return word < end && text.compare(word, 6, "define") == 0;
}

// A Windows header name (`#include "..\Common\Common.hlsl"`, helix-toolkit): fxc takes its backslashes
// as separators. glslang does too in a taken #include, but in a skipped group (a guarded header
// included a second time) it reads the name as a string literal and stops at `\C` ("Invalid escape
// sequence"). The include search turns backslashes into slashes anyway (RestrictedIncluder), so the
// name is spelled with slashes before glslang sees it.
void slashIncludeName(std::string& text, size_t start, size_t end) {
    size_t hash = text.find_first_not_of(" \t", start);
    if (hash >= end || text[hash] != '#') return;
    size_t word = text.find_first_not_of(" \t", hash + 1);
    if (word >= end || text.compare(word, 7, "include") != 0) return;
    size_t open = text.find_first_not_of(" \t", word + 7);
    if (open >= end || (text[open] != '"' && text[open] != '<')) return;
    size_t close = text.find(text[open] == '"' ? '"' : '>', open + 1);
    if (close == std::string::npos || close >= end) return;
    std::replace(text.begin() + static_cast<std::ptrdiff_t>(open), text.begin() + static_cast<std::ptrdiff_t>(close), '\\', '/');
}

}  // namespace

void prepareSourceText(std::string& text, const std::string& displayPath, std::vector<Diagnostic>& warnings) {
    static const std::regex directive(R"(^[ \t]*#[ \t]*line\b)");
    static const std::regex wellFormed(R"(^[ \t]*#[ \t]*line[ \t]+[0-9]+([ \t]+"[^"\n]*")?[ \t]*(//.*)?\r?$)");
    int line = 1;
    for (size_t start = 0; start < text.size(); ++line) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        auto first = text.begin() + static_cast<std::ptrdiff_t>(start), last = text.begin() + static_cast<std::ptrdiff_t>(end);
        size_t hash = text.find_first_not_of(" \t", start);
        if (hash < end && text[hash] == '#' && std::regex_search(first, last, directive)) {
            std::string original(first, last);
            if (!std::regex_match(original, wellFormed)) {
                Diagnostic d;
                d.severity = Severity::Warning;
                d.id = diag::kPreprocessor;
                d.message = "malformed #line directive ignored (expected #line NUMBER or #line NUMBER \"file\")";
                d.location = {displayPath, line, static_cast<int>(original.find('#')) + 1};
                d.sourceLine = original;
                warnings.push_back(std::move(d));
            }
            for (size_t k = start; k < end; ++k)
                if (text[k] != '\r') text[k] = ' ';
        }
        slashIncludeName(text, start, end);
        if (isDefineLine(text, start, end)) {
            size_t tail = text.find_last_not_of(" \t\r", end == start ? start : end - 1);
            if (tail == std::string::npos || tail < start || text[tail] != '\\') integerTernariesAsArithmetic(text, start, end);
        }
        for (bool define = isDefineLine(text, start, end), continued = define; continued;) {  // and its continuation lines
            dropImpossiblePastes(text, start, end);
            size_t tail = text.find_last_not_of(" \t\r", end == start ? start : end - 1);
            continued = tail != std::string::npos && tail >= start && tail < end && text[tail] == '\\' && end < text.size();
            if (!continued) break;
            start = end + 1;
            end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            ++line;
        }
        start = end + 1;
    }
    if (!text.empty() && text.back() != '\n') text += '\n';
}

namespace {

// Finds `relative` under `dir`, exactly or else component by component ignoring case. Where a
// component matches several entries that differ only in case (and none exactly), which one Windows
// would open is unknown: they are listed in `ambiguous` and nothing is found.
std::optional<fs::path> findCaseInsensitive(const fs::path& dir, const fs::path& relative, std::vector<fs::path>& ambiguous) {
    fs::path exact = dir / relative;
    std::error_code ec;
    if (fs::is_regular_file(exact, ec)) return exact;
    fs::path cur = dir;
    for (const auto& part : relative) {
        if (part == "." || part.empty()) continue;
        if (part == "..") {
            cur = cur / "..";
            continue;
        }
        fs::path next = cur / part;
        if (!fs::exists(next, ec)) {
            std::vector<fs::path> matches;
            for (const auto& entry : fs::directory_iterator(cur, ec))
                if (iequals(entry.path().filename().string(), part.string())) matches.push_back(entry.path());
            if (matches.empty()) return std::nullopt;
            if (matches.size() > 1) {
                std::sort(matches.begin(), matches.end());
                ambiguous = std::move(matches);
                return std::nullopt;
            }
            next = matches.front();
        }
        cur = next;
    }
    if (fs::is_regular_file(cur, ec)) return cur;
    return std::nullopt;
}

// The first directive of a header, past comments and blank lines: `#pragma once`, or `#ifndef G`
// followed by `#define G` (`#if !defined(G)` too). Including such a file again while it is open
// yields nothing, so a guarded pair of headers that include each other is no cycle.
bool hasIncludeGuard(const std::string& text) {
    static const std::regex guard(R"(^(?:\s|//[^\n]*\n|/\*[\s\S]*?\*/)*#[ \t]*(?:pragma[ \t]+once\b|(?:ifndef[ \t]+(\w+)|if[ \t]+!\s*defined\s*\(?\s*(\w+)\s*\)?)[^\n]*\n(?:\s|//[^\n]*\n|/\*[\s\S]*?\*/)*#[ \t]*define[ \t]+(\w+)))");
    std::smatch m;
    if (!std::regex_search(text, m, guard)) return false;
    if (!m[3].matched) return true;  // #pragma once
    return m[3].str() == (m[1].matched ? m[1].str() : m[2].str());
}

bool hasPragmaOnce(const std::string& text) {
    static const std::regex once(R"((^|\n)[ \t]*#[ \t]*pragma[ \t]+once\b)");
    return std::regex_search(text, once);
}

bool isUnder(const fs::path& file, const fs::path& root) {
    auto f = file.lexically_normal();
    auto r = root.lexically_normal();
    auto mismatch = std::mismatch(r.begin(), r.end(), f.begin(), f.end());
    return mismatch.first == r.end() || (std::next(mismatch.first) == r.end() && mismatch.first->empty());
}

class RestrictedIncluder final : public glslang::TShader::Includer {
public:
    struct Root {
        fs::path absolute;   // canonical
        std::string display; // as the user named it
    };

    // `roots` are searched; `extraAllowed` (CompileOptions::includeRoot), when given, confines
    // every include to it and to `roots` (fxc reaches it through `../` from the including file,
    // never by searching it). Without it an include may be anywhere, as fxc and cpp allow.
    RestrictedIncluder(std::vector<Root> roots, std::optional<Root> extraAllowed, std::string rootDisplay, fs::path rootAbsolute)
        : roots_(std::move(roots)), extraAllowed_(std::move(extraAllowed)) {
        displayToAbsolute_[rootDisplay] = std::move(rootAbsolute);
    }

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
        return readInclude ? fromCaller(header, includer, depth, false) : resolve(header, includer, depth);
    }
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        return readInclude ? fromCaller(header, includer, depth, true) : resolve(header, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (result) {
            delete static_cast<std::string*>(result->userData);
            delete result;
        }
    }

    // Why each failed include failed, keyed by header name as written.
    std::map<std::string, std::pair<const char*, std::string>> failures;
    // A limit (input_limits.h) an include broke, located inside it: reported instead of glslang's
    // "could not process include" at the directive.
    std::optional<Diagnostic> limitProblem;
    size_t totalBytes = 0;  // of every file read, the effect's included
    std::vector<std::pair<std::string, std::string>> loaded;  // (display, text)
    std::vector<IncludeDependency> dependencies;
    std::vector<Diagnostic> warnings;
    void markIncludedOnce(const fs::path& canonical) { onceIncluded_.insert(canonical); }  // the root's #pragma once
    MacroBounds* macros = nullptr;  // the effect's macros so far: each include's join them
    decltype(CompileOptions::readInclude) readInclude;  // set: the caller's handler reads every include

private:
    // The limits on depth and count of includes: false (the failure noted) when one is broken.
    bool withinIncludeLimits(const std::string& header, size_t depth) {
        if (depth + 1 <= limits::kMaxIncludeDepth && ++includesFollowed_ <= limits::kMaxIncludeFiles) return true;
        failures[header] = {diag::kIncludeLimit, depth + 1 > limits::kMaxIncludeDepth
                                                     ? "#include nested more than " + std::to_string(limits::kMaxIncludeDepth) + " files deep, the most fxport follows"
                                                     : "more than " + std::to_string(limits::kMaxIncludeFiles) + " #include directives, the most fxport follows for one effect"};
        return false;
    }

    // CompileOptions::readInclude (D3DCompile's ID3DInclude) stands in for the file search: a file
    // is named by its header as written; `#pragma once`, guards, cycles and limits as for files.
    IncludeResult* fromCaller(const char* headerC, const char* includerC, size_t depth, bool system) {
        const std::string header = headerC;
        const std::string includer = includerC ? includerC : "";
        const fs::path key = fs::path("<include handler>") / header;  // what the canonical path is to a file
        chain_.resize(depth);
        if (depth >= 1) chain_[depth - 1] = {displayToAbsolute_[includer], includer};
        if (!withinIncludeLimits(header, depth)) return nullptr;
        if (onceIncluded_.count(key)) return emptyInclude(header, key);
        for (const auto& p : chain_)
            if (p.first == key) {
                if (hasIncludeGuard(callerTexts_[key])) return emptyInclude(header, key);
                failures[header] = {diag::kIncludeCycle, "include cycle: '" + header + "' includes itself (directly or through other files)"};
                return nullptr;
            }
        std::optional<std::string> text = readInclude(header, system, includer);
        if (!text) {
            failures[header] = {diag::kIncludeNotFound, "the include handler (ID3DInclude) found no file '" + header + "'"};
            return nullptr;
        }
        if (text->size() > limits::kMaxFileBytes) {
            failures[header] = {diag::kInputTooLarge, "include file '" + header + "' has " + std::to_string(text->size()) +
                                                          " bytes; fxport compiles source files of at most " + std::to_string(limits::kMaxFileBytes >> 20) + " MiB"};
            return nullptr;
        }
        callerTexts_[key] = sourceTextAsUtf8(*text);
        return accept(std::move(*text), header, header, key);
    }

    // A file found and read: checked against the limits, prepared for glslang and handed over.
    IncludeResult* accept(std::string text, const std::string& header, const std::string& display, const fs::path& canonical) {
        totalBytes += text.size();
        if (auto problem = checkSourceText(text, display)) {
            if (!limitProblem) limitProblem = std::move(problem);  // thrown as is when glslang gives up
            failures[header] = {diag::kPreprocessor, "include file '" + header + "' is beyond fxport's limits"};
            return nullptr;
        }
        if (totalBytes > limits::kMaxTotalBytes) {
            failures[header] = {diag::kInputTooLarge, "the effect and its includes have more than " + std::to_string(limits::kMaxTotalBytes >> 20) +
                                                          " MiB of source, the most fxport compiles"};
            return nullptr;
        }
        displayToAbsolute_[display] = canonical;
        text = sourceTextAsUtf8(text);
        if (hasPragmaOnce(text)) onceIncluded_.insert(canonical);
        prepareSourceText(text, display, warnings);
        if (auto problem = macros ? macros->addFile(text, display) : std::nullopt) {
            if (!limitProblem) limitProblem = std::move(problem);  // thrown as is when glslang gives up
            failures[header] = {diag::kMacroLimit, "include file '" + header + "' is beyond fxport's limits"};
            return nullptr;
        }
        loaded.push_back({display, text});
        auto* owned = new std::string(protectStringEscapes(hideStrayQuotes(blankAsmLineComments(text))));  // string_escapes.h, stray_quotes.h
        return new IncludeResult(display, owned->data(), owned->size(), owned);
    }

    IncludeResult* resolve(const char* headerC, const char* includerC, size_t depth) {
        std::string header = headerC;
        std::string includer = includerC ? includerC : "";
        auto absIt = displayToAbsolute_.find(includer);
        fs::path includerAbs = absIt != displayToAbsolute_.end() ? absIt->second : fs::path();
        std::error_code ec;

        // The files open right now: chain_[d] includes the file at depth d + 1 (glslang reports the
        // depth); the includer is the innermost one.
        chain_.resize(depth);
        if (depth >= 1) chain_[depth - 1] = {includerAbs, includer};
        if (!withinIncludeLimits(header, depth)) return nullptr;

        // fxc's search order for #include "file": the including file's folder, then the folders of
        // the other files that are open, innermost first (ending with the effect's own folder),
        // then the include folders. A file found outside the allowed roots is passed over.
        std::vector<std::pair<fs::path, std::string>> searchDirs;  // (absolute dir, display dir)
        std::set<fs::path> seenDirs;
        auto addDir = [&](const fs::path& dir, const std::string& displayDir) {
            if (seenDirs.insert(dir).second) searchDirs.push_back({dir, displayDir});
        };
        for (size_t d = chain_.size(); d-- > 0;)
            if (!chain_[d].first.empty()) addDir(chain_[d].first.parent_path(), fs::path(chain_[d].second).parent_path().string());
        for (const auto& r : roots_) addDir(r.absolute, r.display);
        // Games name includes from their working folder (`"Content/Shaders/Common/Fog.fxh"`), which
        // fxc resolves against the current directory: the folders from the effect's up to the
        // include root stand in for it, nearest first.
        if (!roots_.empty())
            for (fs::path dir = roots_.front().absolute.parent_path(), display = fs::path(roots_.front().display).parent_path();
                 (!extraAllowed_ || isUnder(dir, extraAllowed_->absolute)) && dir.has_relative_path();
                 dir = dir.parent_path(), display = display.parent_path())
                addDir(dir, display.string());

        std::optional<fs::path> found;
        fs::path canonical;
        std::string display;
        bool foundOutside = false;
        std::string outsidePath;  // the first candidate that exists but lies outside every root
        std::vector<std::string> looked;  // exact paths searched before the hit (they did not exist)
        std::vector<fs::path> ambiguous;  // files differing only in case, all matching the name
        // Windows paths (`#include <..\Helpers\Gamma.fxh>`, as fxc and Visual Studio take them).
        std::string lookup = header;
        std::replace(lookup.begin(), lookup.end(), '\\', '/');
        for (const auto& [dir, displayDir] : searchDirs) {
            if (fs::path(lookup).is_absolute()) {
                if (fs::is_regular_file(lookup, ec)) found = fs::path(lookup);
            } else {
                found = findCaseInsensitive(dir, lookup, ambiguous);
                if (!ambiguous.empty()) break;
                if (!found) looked.push_back((dir / lookup).lexically_normal().string());
            }
            if (!found) continue;
            // Canonical: a symbolic link inside a root that points outside it is outside.
            canonical = fs::weakly_canonical(*found, ec);
            bool allowed = !extraAllowed_ || isUnder(canonical, extraAllowed_->absolute);  // no root: anywhere, as fxc
            for (const auto& r : roots_)
                if (isUnder(canonical, r.absolute)) allowed = true;
            if (!allowed) {
                if (!foundOutside) outsidePath = canonical.string();
                foundOutside = true;
                found.reset();
                continue;
            }
            fs::path rel = fs::relative(*found, dir, ec);
            display = (fs::path(displayDir) / (ec ? fs::path(lookup) : rel)).lexically_normal().string();
            break;
        }
        if (!ambiguous.empty()) {
            std::string list;
            for (const auto& a : ambiguous) list += (list.empty() ? "'" : ", '") + a.lexically_normal().string() + "'";
            failures[header] = {diag::kIncludeNotFound, "include file '" + header + "' matches several files that differ only in case: " + list +
                                                            "; Windows would open one of them, fxport cannot tell which: name it exactly"};
            return nullptr;
        }
        if (!found && foundOutside) {
            std::string root = extraAllowed_ ? "the include root '" + extraAllowed_->display + "'" : std::string("the effect's folder");
            failures[header] = {diag::kIncludeOutside, "include file '" + header + "' resolves to '" + outsidePath + "', outside " + root +
                                " and the include folders; allow it with --root DIR (CompileOptions::includeRoot) "
                                "naming a folder that holds both, or -I with its folder"};
            return nullptr;
        }
        if (!found) {
            failures[header] = {diag::kIncludeNotFound, "cannot find include file '" + header +
                                "' beside the including file, the other open files, the effect or in the include folders"};
            return nullptr;
        }
        // The chain's paths are canonical already (displayToAbsolute_ holds only canonical ones):
        // comparing them costs no file-system call, so a long include chain stays linear.
        // `#pragma once` seen before, or a guarded header that is open right now: nothing to add.
        if (onceIncluded_.count(canonical)) return emptyInclude(display, canonical);
        for (const auto& p : chain_)
            if (!p.first.empty() && p.first == canonical) {
                if (auto open = readFile(canonical.string()); open && hasIncludeGuard(sourceTextAsUtf8(*open))) return emptyInclude(display, canonical);
                failures[header] = {diag::kIncludeCycle, "include cycle: '" + header + "' includes itself (directly or through other files)"};
                return nullptr;
            }
        if (auto size = fs::file_size(canonical, ec); !ec && size > limits::kMaxFileBytes) {
            failures[header] = {diag::kInputTooLarge, "include file '" + header + "' has " + std::to_string(size) +
                                                          " bytes; fxport compiles source files of at most " + std::to_string(limits::kMaxFileBytes >> 20) + " MiB"};
            return nullptr;
        }
        auto text = readFile(canonical.string());
        if (!text) {
            failures[header] = {diag::kFileUnreadable, "cannot read include file '" + header + "'"};
            return nullptr;
        }
        for (auto& path : looked) dependencies.push_back({std::move(path), {}});
        dependencies.push_back({canonical.string(), contentHash(*text)});  // the raw bytes, as the cache re-reads them
        return accept(std::move(*text), header, display, canonical);
    }

    IncludeResult* emptyInclude(const std::string& display, const fs::path& canonical) {
        displayToAbsolute_[display] = canonical;
        auto* owned = new std::string();
        return new IncludeResult(display, owned->data(), 0, owned);
    }

    std::vector<Root> roots_;
    std::optional<Root> extraAllowed_;
    std::set<fs::path> onceIncluded_;  // files with `#pragma once` already read
    std::map<std::string, fs::path> displayToAbsolute_;
    std::vector<std::pair<fs::path, std::string>> chain_;  // open files: (absolute, display)
    size_t includesFollowed_ = 0;
    std::map<fs::path, std::string> callerTexts_;  // what readInclude returned, by its stand-in path
};

// glslang's "'#define' : Macro redefined; different substitutions: NAME" (and its two siblings).
bool isMacroRedefinition(const Diagnostic& d) { return d.message.find("Macro redefined") != std::string::npos; }
bool onlyMacroRedefinitions(const std::vector<Diagnostic>& diags) {
    return std::all_of(diags.begin(), diags.end(), isMacroRedefinition);
}

std::string lastWordOf(const std::string& message) {
    std::string_view t = trim(message);
    size_t space = t.find_last_of(" :");
    return std::string(space == std::string_view::npos ? t : t.substr(space + 1));
}

// One run of glslang's preprocessor over the prepared root text (see preprocessEffect).
struct PreprocessRun {
    const std::string& source;
    const std::string& displayPath;
    const fs::path& rootAbs;
    const std::vector<RestrictedIncluder::Root>& roots;
    const std::optional<RestrictedIncluder::Root>& includeRoot;
    const CompileOptions& options;
    const std::vector<Diagnostic>& lineWarnings;
    // nullopt: the only errors were macro redefinitions and `cascading` was off (run again with it).
    std::optional<PreprocessedEffect> operator()(bool cascading) const;
};

}  // namespace

PreprocessedEffect preprocessEffect(const std::string& rawSource, const std::string& displayPath,
                                    const std::string& absolutePath, const CompileOptions& options) {
    ensureGlslangInitialized();
    std::string source = sourceTextAsUtf8(rawSource);  // BOM / UTF-16: fxc reads them all
    checkIsText(source, displayPath);
    if (auto problem = checkSourceText(source, displayPath)) throw CompileError({*problem});
    std::vector<Diagnostic> lineWarnings;
    prepareSourceText(source, displayPath, lineWarnings);

    std::vector<RestrictedIncluder::Root> roots;
    std::error_code ec;
    fs::path rootAbs = fs::weakly_canonical(fs::absolute(absolutePath, ec), ec);
    roots.push_back({rootAbs.parent_path(), fs::path(displayPath).parent_path().string()});
    for (const auto& dir : options.includeDirs)
        roots.push_back({fs::weakly_canonical(fs::absolute(dir, ec), ec), dir});

    std::optional<RestrictedIncluder::Root> includeRoot;
    if (!options.includeRoot.empty()) includeRoot = RestrictedIncluder::Root{fs::weakly_canonical(fs::absolute(options.includeRoot, ec), ec), options.includeRoot};
    // glslang stops at its first error; a macro redefinition (a warning to fxc) is seen again with
    // cascading errors on, so that everything after it is preprocessed.
    PreprocessRun run{source, displayPath, rootAbs, roots, includeRoot, options, lineWarnings};
    if (auto result = run(false)) return std::move(*result);
    return std::move(*run(true));
}

std::optional<PreprocessedEffect> PreprocessRun::operator()(bool cascading) const {
    RestrictedIncluder includer(roots, includeRoot, displayPath, rootAbs);
    includer.totalBytes = source.size();
    includer.readInclude = options.readInclude;
    if (hasPragmaOnce(source)) includer.markIncludedOnce(rootAbs);
    std::string preamble = undefineGlslangPredefines() + "#define FXPORT 1\n";
    for (const auto& [name, value] : options.defines) preamble += "#define " + name + " " + value + "\n";

    // Macro expansion bounded before glslang expands anything (macro_bounds.h).
    MacroBounds macros;
    if (auto problem = macros.addFile(preamble, displayPath)) throw CompileError({*problem});
    if (auto problem = macros.addFile(source, displayPath)) throw CompileError({*problem});
    includer.macros = &macros;

    glslang::TShader shader(EShLangFragment);
    const std::string cleaned = protectStringEscapes(hideStrayQuotes(blankAsmLineComments(source)));  // string_escapes.h, stray_quotes.h
    const char* text = cleaned.c_str();
    const char* name = displayPath.c_str();
    int length = static_cast<int>(cleaned.size());
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    shader.setEnvInput(glslang::EShSourceHlsl, EShLangFragment, glslang::EShClientOpenGL, 100);
    shader.setPreamble(preamble.c_str());
    std::string output;
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgOnlyPreprocessor | (cascading ? int(EShMsgCascadingErrors) : 0));
    bool ok = shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &output, includer);

    PreprocessedEffect result;
    result.map.addFileText(displayPath, source);
    for (const auto& [file, content] : includer.loaded) result.map.addFileText(file, content);
    result.dependencies = std::move(includer.dependencies);
    result.warnings = lineWarnings;
    result.warnings.insert(result.warnings.end(), includer.warnings.begin(), includer.warnings.end());
    if (!ok && includer.limitProblem) throw CompileError({*includer.limitProblem});
    if (!ok) {
        // glslang reports "ERROR: file:line: 'token' : message"; lines here are ORIGINAL lines.
        std::vector<Diagnostic> diags;
        static const std::regex re(R"(ERROR: (.*):(-?\d{1,9}): (.*))");
        std::string log = shader.getInfoLog();
        size_t pos = 0;
        while (pos < log.size()) {
            size_t end = log.find('\n', pos);
            if (end == std::string::npos) end = log.size();
            std::string line = log.substr(pos, end - pos);
            pos = end + 1;
            std::smatch m;
            if (!std::regex_match(line, m, re)) continue;
            SourceLocation where{m[1].str(), std::stoi(m[2].str()), 0};
            if (where.line < 1) where.line = 1;  // glslang's end-of-input errors can say line 0
            std::string msg(trim(m[3].str()));
            restoreStrayQuotes(msg);
            const char* id = diag::kPreprocessor;
            static const std::string kIncludeFailed = "Could not process include directive for header name: ";
            auto inc = msg.find(kIncludeFailed);
            std::string token;
            if (inc != std::string::npos) {
                std::string header(trim(msg.substr(inc + kIncludeFailed.size())));
                token = header;
                auto f = includer.failures.find(header);
                if (f != includer.failures.end()) {
                    id = f->second.first;
                    msg = f->second.second;
                }
            } else if (auto q = msg.find('\''); q != std::string::npos) {
                token = msg.substr(q + 1, msg.find('\'', q + 1) - q - 1);  // glslang quotes the offending token
            }
            // Column: the offending token in the original line, else the line's first character.
            std::string orig = result.map.originalLine(where.file, where.line);
            size_t at = token.empty() ? std::string::npos : orig.find(token);
            if (at == std::string::npos) at = orig.find_first_not_of(" \t");
            where.column = at == std::string::npos ? 1 : static_cast<int>(at) + 1;
            Diagnostic d = result.map.makeAt(Severity::Error, id, msg, where);
            diags.push_back(std::move(d));
        }
        if (diags.empty()) {
            Diagnostic d;
            d.id = diag::kPreprocessor;
            d.message = "preprocessing failed: " + std::string(trim(log));
            d.location = {displayPath, 1, 1};  // glslang named no line: the file as a whole
            diags.push_back(d);
        }
        // Without cascading errors glslang gave up at the first one, inside its #if groups: the
        // "missing #endif" it adds then is its own stop, not the file's.
        if (!cascading && diags.size() > 1)
            diags.erase(std::remove_if(diags.begin() + 1, diags.end(), [](const Diagnostic& d) { return d.message.find("missing #endif") != std::string::npos; }),
                        diags.end());
        if (!cascading && isMacroRedefinition(diags.front())) return std::nullopt;
        if (!onlyMacroRedefinitions(diags)) {
            // The real errors, without the redefinitions that are only warnings.
            diags.erase(std::remove_if(diags.begin(), diags.end(), isMacroRedefinition), diags.end());
            throw CompileError(std::move(diags));
        }
        // fxc warns (X1519) and uses the later definition, which glslang has already made current
        // (MonoGame's `#define VS_SHADERMODEL vs_4_0_level_9_1` after a header's own): warnings.
        for (auto& d : diags) {
            d.severity = Severity::Warning;
            d.message = "macro '" + lastWordOf(d.message) + "' redefined; the later definition is used, as fxc does (X1519)";
            result.warnings.push_back(std::move(d));
        }
    }
    if (output.size() > limits::kMaxPreprocessedBytes) {
        Diagnostic d;
        d.id = diag::kMacroLimit;
        d.message = "macro expansion makes the effect " + std::to_string(output.size() >> 20) + " MiB long; fxport compiles at most " +
                    std::to_string(limits::kMaxPreprocessedBytes >> 20) + " MiB after preprocessing";
        d.location = {displayPath, 0, 0};
        throw CompileError({d});
    }
    restoreStringEscapes(output);
    restoreStrayQuotes(output);
    result.text = result.map.build(output, displayPath);
    // Macros can nest brackets that no file shows (`#define P(x) (x)` called through other macros).
    if (auto p = findNestingPastLimit(result.text))
        throw CompileError({result.map.make(Severity::Error, diag::kNestingTooDeep,
                                            "after macro expansion, brackets are nested more than " + std::to_string(limits::kMaxNesting) +
                                                " levels deep here, the most fxport accepts",
                                            p->line, p->column)});
    return result;
}

}  // namespace fxport::xlate
