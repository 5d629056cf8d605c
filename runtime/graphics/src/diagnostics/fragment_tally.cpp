// FragmentRuns: GL_SAMPLES_PASSED per run of draws with the same texture fetches per fragment.
#include "diagnostics/fragment_tally.h"


namespace fxport {

FragmentRuns::~FragmentRuns() {
    end();
    for (Run& run : runs_)
        if (run.query) device_.remove(run.query);
}

void FragmentRuns::beforeDraw(const xlate::TextureFetches& fetches) {
    if (open_) {
        const xlate::TextureFetches& now = runs_.back().fetches;
        if (now.least == fetches.least && now.most == fetches.most && now.unbounded == fetches.unbounded) return;
        end();
    }
    Run run;
    run.fetches = fetches;
    run.query = device_.create(QueryKind::SamplesPassed);
    device_.beginSamplesPassed(run.query);
    runs_.push_back(run);
    open_ = true;
}

void FragmentRuns::end() {
    if (!open_) return;
    device_.endSamplesPassed();
    open_ = false;
}

void FragmentRuns::read(Run& run, bool wait) {
    if (!run.query) return;
    if (!wait && !device_.ready(run.query)) return;
    run.fragments = double(device_.result(run.query));
    device_.remove(run.query);  // results are kept, queries are not: a long run holds few
}

std::size_t FragmentRuns::mark() {
    end();
    // Results arrive in order: read those that are ready, so the queries do not pile up.
    for (; firstUnread_ < runs_.size(); ++firstUnread_) {
        read(runs_[firstUnread_], false);
        if (runs_[firstUnread_].query) break;
    }
    return runs_.size();
}

std::vector<GraphicsDevice::FragmentTally> FragmentRuns::between(std::size_t from, std::size_t to) {
    std::vector<GraphicsDevice::FragmentTally> out;
    for (std::size_t i = from; i < to && i < runs_.size(); ++i) {
        if (open_ && i + 1 == runs_.size()) break;  // still counting
        read(runs_[i], true);
        out.push_back({runs_[i].fragments, runs_[i].fetches.least, runs_[i].fetches.most, runs_[i].fetches.unbounded});
    }
    return out;
}

}  // namespace fxport
