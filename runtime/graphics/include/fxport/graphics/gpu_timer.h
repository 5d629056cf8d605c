// GpuTimer: GPU time of named sections of a frame (e.g. one per render pass), measured with GL
// timestamp queries and read back a few frames later so measuring does not stall the pipeline.
//
//   GpuTimer timer(device);
//   for each frame: timer.Begin("GBuffer"); ...draws...; timer.End(); ...; timer.EndFrame();
//   timer.Finish();  for (auto& s : timer.Sections()) print(s.name, s.medianMs());
//
// With CountFragments(true) each outermost section also counts the fragments its draws wrote
// (a GL_SAMPLES_PASSED query: fragments that passed the depth/stencil test and were not
// discarded) -- the overdraw a pass's fill-rate bound is made of (issue 16). Not while the device
// tallies fragments (GraphicsDevice::tallyFragments, which counts them per run of draws instead):
// GL has one GL_SAMPLES_PASSED query at a time, so the sections then count none.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fxport {

class GraphicsDevice;

class GpuTimer {
public:
    struct Section {
        std::string name;
        std::vector<double> milliseconds;  // one entry per frame in which the section ran
        std::vector<double> fragments;     // per run, with CountFragments (outermost sections only)
        double medianMs() const;
        double medianFragments() const;  // 0 when not counted
    };

    explicit GpuTimer(GraphicsDevice& device);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    // Sections may nest; each Begin needs its End.
    void Begin(const std::string& name);
    void End();
    // Marks the end of a frame: records the frame's total and collects results that are ready.
    void EndFrame();
    // Waits for every outstanding query and collects it (call before reading Sections()).
    void Finish();

    // Count each outermost section's fragments from the next Begin on (GL has one such query
    // active at a time, so nested sections are not counted).
    void CountFragments(bool on) { countFragments_ = on; }

    // In order of first appearance; the frame total is the section "frame".
    const std::vector<Section>& Sections() const { return sections_; }

private:
    struct Pending;
    void collect(bool wait);
    std::uint32_t newQuery();
    int sectionIndex(const std::string& name);

    GraphicsDevice& device_;
    std::vector<Section> sections_;
    std::vector<std::unique_ptr<Pending>> pending_;
    std::vector<std::unique_ptr<Pending>> open_;
    std::vector<std::uint32_t> freeQueries_;
    std::vector<std::uint32_t> allQueries_;
    std::uint32_t frameStart_ = 0;
    bool countFragments_ = false;
};

}  // namespace fxport
