#include "fxport/graphics/gpu_timer.h"

#include <algorithm>

#include "device/device_probes.h"
#include "fxport/graphics/errors.h"

namespace fxport {

struct GpuTimer::Pending {
    int section = 0;
    BackendObject begin = 0;
    BackendObject end = 0;
    BackendObject samples = 0;  // GL_SAMPLES_PASSED, 0 when not counted
};

namespace {
double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

double GpuTimer::Section::medianMs() const { return median(milliseconds); }

double GpuTimer::Section::medianFragments() const { return median(fragments); }

GpuTimer::GpuTimer(GraphicsDevice& device) : device_(device) {}

GpuTimer::~GpuTimer() {
    for (BackendObject& q : allQueries_) DeviceQueries(device_).remove(q);
    for (auto& p : pending_)
        if (p->samples) DeviceQueries(device_).remove(p->samples);
    for (auto& p : open_)
        if (p->samples) DeviceQueries(device_).remove(p->samples);
}

std::uint32_t GpuTimer::newQuery() {
    if (!freeQueries_.empty()) {
        BackendObject q = freeQueries_.back();
        freeQueries_.pop_back();
        return q;
    }
    BackendObject q = DeviceQueries(device_).create(QueryKind::Timestamp);
    allQueries_.push_back(q);
    return q;
}

int GpuTimer::sectionIndex(const std::string& name) {
    for (std::size_t i = 0; i < sections_.size(); ++i)
        if (sections_[i].name == name) return int(i);
    sections_.push_back(Section{name, {}, {}});
    return int(sections_.size() - 1);
}

void GpuTimer::Begin(const std::string& name) {
    if (open_.empty() && frameStart_ == 0) {
        frameStart_ = newQuery();
        DeviceQueries(device_).writeTimestamp(frameStart_);
    }
    auto p = std::make_unique<Pending>();
    p->section = sectionIndex(name);
    if (countFragments_ && open_.empty() && !DeviceQueries(device_).fragmentTallyOn()) {
        p->samples = DeviceQueries(device_).create(QueryKind::SamplesPassed);
        DeviceQueries(device_).beginSamplesPassed(p->samples);
    }
    p->begin = newQuery();
    DeviceQueries(device_).writeTimestamp(p->begin);
    open_.push_back(std::move(p));
}

void GpuTimer::End() {
    if (open_.empty()) throw InvalidOperation("GpuTimer::End() without a matching Begin()");
    std::unique_ptr<Pending> p = std::move(open_.back());
    open_.pop_back();
    p->end = newQuery();
    DeviceQueries(device_).writeTimestamp(p->end);
    if (p->samples) DeviceQueries(device_).endSamplesPassed();
    pending_.push_back(std::move(p));
}

void GpuTimer::EndFrame() {
    if (!open_.empty()) throw InvalidOperation("GpuTimer::EndFrame() with section '" + sections_[std::size_t(open_.back()->section)].name + "' still open");
    if (frameStart_ != 0) {
        auto p = std::make_unique<Pending>();
        p->section = sectionIndex("frame");
        p->begin = frameStart_;
        p->end = newQuery();
        DeviceQueries(device_).writeTimestamp(p->end);
        pending_.push_back(std::move(p));
        frameStart_ = 0;
    }
    collect(false);
}

void GpuTimer::Finish() { collect(true); }

void GpuTimer::collect(bool wait) {
    // Results arrive in submission order, so stop at the first one that is not ready.
    std::size_t done = 0;
    for (; done < pending_.size(); ++done) {
        Pending& p = *pending_[done];
        DeviceQueries queries(device_);
        if (!wait && !queries.ready(p.end)) break;
        const std::uint64_t t0 = queries.result(p.begin), t1 = queries.result(p.end);
        sections_[std::size_t(p.section)].milliseconds.push_back(double(t1 - t0) * 1e-6);
        if (p.samples) {
            sections_[std::size_t(p.section)].fragments.push_back(double(queries.result(p.samples)));
            DeviceQueries(device_).remove(p.samples);
        }
        freeQueries_.push_back(p.begin);
        freeQueries_.push_back(p.end);
    }
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(done));
}

}  // namespace fxport
