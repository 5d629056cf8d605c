// See include_handler.h.
#include "include_handler.h"

namespace fxport::d3d11 {

IncludeRecorder::IncludeRecorder(ID3DInclude* handler, std::string rootName) : handler_(handler) { dataOf_[std::move(rootName)] = nullptr; }

IncludeRecorder::~IncludeRecorder() {
    for (auto it = opened_.rbegin(); it != opened_.rend(); ++it) handler_->Close(*it);
}

std::optional<std::string> IncludeRecorder::open(const std::string& header, bool system, const std::string& includer) {
    auto& recorded = texts_[{includer, header}];
    const auto parent = dataOf_.find(includer);
    LPCVOID data = nullptr;
    UINT bytes = 0;
    const HRESULT hr = handler_->Open(system ? D3D_INCLUDE_SYSTEM : D3D_INCLUDE_LOCAL, header.c_str(),
                                      parent == dataOf_.end() ? nullptr : parent->second, &data, &bytes);
    if (FAILED(hr)) return recorded = std::nullopt;
    opened_.push_back(data);
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
