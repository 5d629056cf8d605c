// effectDependencies: the files an effect's compile reads (the effect and everything it #includes),
// found by running only the preprocessor; what build systems need for a depfile.
#include <algorithm>
#include <filesystem>

#include "fxport/xlate/effect_compiler.h"
#include "fx/preprocess.h"
#include "fx/text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

std::vector<std::string> effectDependencies(const std::string& path, const CompileOptions& options) {
    auto text = readFile(path);
    if (!text) {
        Diagnostic d;
        d.id = diag::kFileUnreadable;
        d.message = "cannot open '" + path + "'";
        d.location = {path, 0, 0};
        throw CompileError({d});
    }
    std::error_code ec;
    std::vector<std::string> files{fs::weakly_canonical(fs::absolute(path, ec), ec).string()};
    PreprocessedEffect pre = preprocessEffect(*text, path, path, options);
    // Paths the include search found empty (hash "") are left out: a depfile cannot say "rebuild when
    // this file appears"; the compile cache still notices them.
    for (const auto& d : pre.dependencies)
        if (!d.hash.empty() && std::find(files.begin(), files.end(), d.path) == files.end()) files.push_back(d.path);
    return files;
}

void preprocessSource(const std::string& source, const std::string& virtualPath, const CompileOptions& options) {
    (void)preprocessEffect(source, virtualPath, virtualPath, options);
}

}  // namespace fxport::xlate
