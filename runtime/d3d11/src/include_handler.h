// D3DCompile's ID3DInclude: the caller's handler reads the #includes. The preprocessor runs once in
// the caller's process with the handler (Open for each #include it reaches, as D3D calls it); the
// compile proper, which may run in a worker process, is then fed the same texts from memory.
// Close comes in D3DCompile's order, each file closed once the preprocessor is done with it: an
// Open whose includer is an outer file (or the source itself) shows that the files opened since
// are finished, so they are closed first (innermost first); the rest close when preprocessing ends.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fxport/d3d11/d3dcompiler.h"
#include "fxport/xlate/effect_compiler.h"

namespace fxport::d3d11 {

class IncludeRecorder {
public:
    // `rootName` is the name the preprocessor gives the source itself (its parent data is null).
    IncludeRecorder(ID3DInclude* handler, std::string rootName);
    ~IncludeRecorder() { closeAfter(""); }  // Close for every file still open, innermost first
    IncludeRecorder(const IncludeRecorder&) = delete;
    IncludeRecorder& operator=(const IncludeRecorder&) = delete;

    // Calls the handler's Open (what CompileOptions::readInclude is during the first preprocessing).
    std::optional<std::string> open(const std::string& header, bool system, const std::string& includer);
    // Serves the texts Open returned, by (includer, header): readInclude for the compile proper.
    decltype(xlate::CompileOptions::readInclude) replay() const;

private:
    // Closes the open files nested deeper than `includer` (all of them for ""), innermost first.
    void closeAfter(const std::string& includer);
    ID3DInclude* handler_;
    std::map<std::string, LPCVOID> dataOf_;  // file name -> the data its Open returned (its children's parent data)
    std::vector<std::pair<std::string, LPCVOID>> chain_;  // the files open now, outermost first (name, data)
    std::map<std::pair<std::string, std::string>, std::optional<std::string>> texts_;  // (includer, header) -> text
};

}  // namespace fxport::d3d11
