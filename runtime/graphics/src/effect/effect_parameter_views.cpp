// XNA's EffectParameter.StructureMembers and .Elements: parameters inside an effect's parameter. A
// view keeps the path from the effect's parameter (member k, element i ...) and computes its
// reflection from the effect's current one on each use, so it follows the layout a compiled
// technique gives (effect.cpp adoptLayouts) like the effect's own parameters do.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "effect/effect_impl.h"

namespace fxport {

struct EffectParameter::View {
    std::vector<std::pair<bool, int>> path;  // (is a member, index): member k or element i, outermost first
    xlate::Parameter current;                 // the last desc() computed
};

EffectParameter::EffectParameter(Effect* effect, int index, std::shared_ptr<View> view)
    : effect_(effect), index_(index), view_(std::move(view)) {}

// Member offsets in the reflection are those inside element 0 of every enclosing array; `shift`
// carries the elements taken on the way.
const xlate::Parameter& EffectParameter::desc() const {
    const xlate::Parameter& top = effectImpl(*effect_).outline.parameters[std::size_t(index_)];
    if (!view_) return top;
    xlate::Parameter d = top;
    int shift = 0;
    for (const auto& [isMember, i] : view_->path) {
        if (isMember) {
            xlate::Parameter m = d.members[std::size_t(i)];
            m.isStatic = d.isStatic;
            m.offset = d.offset >= 0 && m.offset >= 0 ? m.offset + shift : -1;
            d = std::move(m);
        } else {
            int delta = i * d.arrayStride;
            if (d.offset >= 0) d.offset += delta;
            shift += delta;
            d.name += "[" + std::to_string(i) + "]";
            d.elements = 0;
            d.defaultValue.clear();
        }
    }
    view_->current = std::move(d);
    return view_->current;
}

EffectParameterCollection& EffectParameter::StructureMembers() {
    if (!members_) {
        members_ = std::make_shared<EffectParameterCollection>();
        members_->effect_ = effect_;
        members_->nested_ = true;
        const xlate::Parameter& d = desc();
        if (d.parameterClass == xlate::ParameterClass::Struct && d.elements == 0) {
            const std::size_t count = d.members.size();
            for (std::size_t k = 0; k < count; ++k) {
                auto view = std::make_shared<View>();
                if (view_) view->path = view_->path;
                view->path.push_back({true, int(k)});
                members_->items_.push_back(EffectParameter(effect_, index_, std::move(view)));
            }
        }
    }
    return *members_;
}

EffectParameterCollection& EffectParameter::Elements() {
    if (!elements_) {
        elements_ = std::make_shared<EffectParameterCollection>();
        elements_->effect_ = effect_;
        elements_->nested_ = true;
        const int count = desc().elements;
        for (int i = 0; i < count; ++i) {
            auto view = std::make_shared<View>();
            if (view_) view->path = view_->path;
            view->path.push_back({false, i});
            elements_->items_.push_back(EffectParameter(effect_, index_, std::move(view)));
        }
    }
    return *elements_;
}

}  // namespace fxport
