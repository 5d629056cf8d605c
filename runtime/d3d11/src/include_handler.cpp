// See include_handler.h.
#include "include_handler.h"

namespace fxport::d3d11 {

IncludeRecorder::IncludeRecorder(ID3DInclude* handler, std::string rootName) : handler_(handler) { dataOf_[std::move(rootName)] = nullptr; }

void IncludeRecorder::closeAfter(const std::string& includer) {
    while (!chain_.empty() && chain_.back().first != includer) {
        handler_->Close(chain_.back().second);
        chain_.pop_back();
    }
}

std::optional<std::string> IncludeRecorder::open(const std::string& header, bool system, const std::string& includer) {
    closeAfter(includer);  // the files opened since `includer` are done (the root's: every one)
    auto& recorded = texts_[{includer, header}];
    const auto parent = dataOf_.find(includer);
    LPCVOID data = nullptr;
    UINT bytes = 0;
    const HRESULT hr = handler_->Open(system ? D3D_INCLUDE_SYSTEM : D3D_INCLUDE_LOCAL, header.c_str(),
                                      parent == dataOf_.end() ? nullptr : parent->second, &data, &bytes);
    if (FAILED(hr)) return recorded = std::nullopt;
    chain_.emplace_back(header, data);
    dataOf_[header] = data;
    // A null pointer with a size is the handler's mistake; it reads as an empty file, not a crash.
    recorded = data ? std::string(static_cast<const char*>(data), bytes) : std::string();
    return recorded;
}

decltype(xlate::CompileOptions::readInclude) IncludeRecorder::replay() const {
    return [texts = texts_](const std::string& header, bool, const std::string& includer) -> std::optional<std::string> {
        const auto it = texts.find({includer, header});
        return it == texts.end() ? std::nullopt : it->second;
    };
}

}  // namespace fxport::d3d11
