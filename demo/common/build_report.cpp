#include "common/build_report.h"

#include "common/pass_bound.h"

#include <algorithm>
#include <set>

namespace fxport::demo {

namespace {

int depthBytes(DepthFormat depth) {
    switch (depth) {
    case DepthFormat::None: return 0;
    case DepthFormat::Depth16: return 2;
    case DepthFormat::Depth24: return 4;
    case DepthFormat::Depth24Stencil8: return 4;
    case DepthFormat::Depth32F: return 4;
    case DepthFormat::Depth32FStencil8: return 8;
    }
    return 0;
}

std::string sizeText(const BuildReport::TargetEntry& t) {
    std::string text = std::to_string(t.width) + "x" + std::to_string(t.height);
    if (t.faces > 1) text += "x" + std::to_string(t.faces);
    text += std::string(" ") + surfaceFormatName(t.format);
    if (t.depth != DepthFormat::None) text += std::string("+") + depthFormatName(t.depth);
    return text;
}

std::string techniquesText(const BuildReport::EffectEntry& e) {
    std::string text;
    for (const std::string& t : e.techniques) text += (text.empty() ? "" : " ") + t;
    return text;
}

const char* mark(bool built) { return built ? "built   " : "left out"; }

const BuildReport::EffectEntry* findEffect(const BuildReport& r, const std::string& asset) {
    for (const auto& e : r.effects)
        if (e.asset == asset) return &e;
    return nullptr;
}

void printTarget(std::FILE* out, bool built, const BuildReport::TargetEntry& t) {
    std::fprintf(out, "  %s  %-22s %-34s %12lld B\n", mark(built), t.name.c_str(), sizeText(t).c_str(),
                 static_cast<long long>(t.bytes));
}

}  // namespace

std::int64_t RenderTargetBytes(int width, int height, int faces, SurfaceFormat format, DepthFormat depth) {
    const std::int64_t texels = std::int64_t(width) * std::int64_t(height);
    return texels * faces * bytesPerPixel(format) + texels * depthBytes(depth);
}

std::int64_t BuildReport::targetBytes() const {
    std::int64_t sum = 0;
    for (const TargetEntry& t : targets) sum += t.bytes;
    return sum;
}

double BuildReport::effectLoadMs() const {
    double sum = 0;
    for (const EffectEntry& e : effects) sum += e.loadMs;
    return sum;
}

bool BuildReport::hasEffect(const std::string& asset) const { return findEffect(*this, asset) != nullptr; }

int BuildReport::countTargets(const std::string& prefix) const {
    return int(std::count_if(targets.begin(), targets.end(),
                             [&](const TargetEntry& t) { return t.name.rfind(prefix, 0) == 0; }));
}

bool BuildReport::hasPass(const std::string& name) const {
    return std::find(passes.begin(), passes.end(), name) != passes.end();
}

void BuildReport::addLoadedEffects(const ContentManager& content) {
    for (const ContentManager::LoadRecord& record : content.loadLog()) {
        if (record.type != "Effect") continue;
        Effect* effect = content.findLoadedEffect(record.assetName);
        if (effect) addEffect(record.assetName, *effect);
    }
}

void BuildReport::addEffect(const std::string& name, Effect& effect) {
    EffectEntry e;
    e.asset = name;
    const EffectStatistics stats = effect.statistics();
    e.loadMs = stats.loadMilliseconds + stats.compileMilliseconds + stats.linkMilliseconds;
    for (int i = 0; i < effect.Techniques.Count(); ++i) {
        EffectTechnique& technique = *effect.Techniques[i];
        e.techniques.push_back(technique.Name() + "(" + std::to_string(technique.Passes.Count()) + ")" +
                               (technique.IsCompiled() ? "+" : ""));
        e.passes += technique.Passes.Count();
    }
    effects.push_back(std::move(e));
}

void BuildReport::addTarget(const RenderTarget2D& target) {
    TargetEntry e;
    e.name = target.Name;
    e.width = target.Width();
    e.height = target.Height();
    e.format = target.Format();
    e.depth = target.DepthStencilFormat();
    e.bytes = RenderTargetBytes(e.width, e.height, 1, e.format, e.depth);
    targets.push_back(std::move(e));
}

void BuildReport::addTarget(const RenderTargetCube& target) {
    TargetEntry e;
    e.name = target.Name;
    e.width = e.height = target.Size();
    e.faces = 6;
    e.format = target.Format();
    e.depth = target.DepthStencilFormat();
    e.bytes = RenderTargetBytes(e.width, e.height, 6, e.format, e.depth);
    targets.push_back(std::move(e));
}

void BuildReport::addPasses(const GpuTimer& timer) {
    for (const GpuTimer::Section& section : timer.Sections())
        if (section.name != "frame") passes.push_back(section.name), passMs.push_back(section.medianMs());
}

void BuildReport::addClears(const GraphicsDevice& device) {
    depthStorage = device.depthStorageStatistics();
    hasClears = true;
    clears = device.clearStatistics();
    computePasses = device.computePassStatistics();
}

namespace {

void printClears(std::FILE* out, const char* label, const BuildReport& r) {
    if (!r.hasClears) return;
    std::fprintf(out, "  %-12s requested %6ld  executed %6ld  replaced %6ld  dropped %6ld  discarded %6ld  covered %6ld  blends as writes %6ld\n",
                 label, r.clears.requested, r.clears.executed, r.clears.replaced, r.clears.dropped, r.clears.discarded,
                 r.clears.covered, r.clears.blendsAsWrites);
}

void printDepthStorage(std::FILE* out, const char* label, const BuildReport& r) {
    if (!r.hasClears) return;
    const DepthStorageStatistics& d = r.depthStorage;
    std::fprintf(out, "  %-12s asked for %3ld (%lld B)  allocated %3ld (%lld B)  never allocated %3ld (%lld B saved)  invalidated %ld\n",
                 label, d.requested, static_cast<long long>(d.requestedBytes), d.allocated,
                 static_cast<long long>(d.allocatedBytes), d.unallocated(), static_cast<long long>(d.savedBytes()),
                 d.invalidated);
}

}  // namespace

void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& all, const char* allFeaturesText) {
    std::fprintf(out, "explain: what this scene built, against the all-features scene built by the same code in this run\n"
                      "  all-features: %s\n",
                 allFeaturesText);

    std::fprintf(out, "effects (techniques(passes), + = compiled; time = outline at load + techniques compiled at\n"
                      "first Apply + GL programs; the process's first compile also pays xlate's start-up):\n");
    std::set<std::string> seen;
    auto printEffect = [&](const std::string& asset) {
        if (!seen.insert(asset).second) return;
        const BuildReport::EffectEntry* mine = findEffect(built, asset);
        const BuildReport::EffectEntry* other = findEffect(all, asset);
        const BuildReport::EffectEntry& shown = mine ? *mine : *other;
        std::fprintf(out, "  %s  %-26s %-22s %9.1f ms", mark(mine != nullptr), asset.c_str(), techniquesText(shown).c_str(),
                     mine ? mine->loadMs : 0.0);
        if (other) std::fprintf(out, "   (all-features %9.1f ms)", other->loadMs);
        std::fprintf(out, "\n");
    };
    for (const auto& e : built.effects) printEffect(e.asset);
    for (const auto& e : all.effects) printEffect(e.asset);
    std::fprintf(out, "  effects: %zu built, %.1f ms; all-features %zu, %.1f ms\n", built.effects.size(), built.effectLoadMs(),
                 all.effects.size(), all.effectLoadMs());

    std::fprintf(out, "render targets (bytes = colour faces + depth buffer):\n");
    // Matched by name and occurrence (a scene may have several lights' maps of one name).
    std::vector<bool> used(all.targets.size(), false);
    for (const auto& t : built.targets) {
        for (std::size_t i = 0; i < all.targets.size(); ++i) {
            if (!used[i] && all.targets[i].name == t.name) {
                used[i] = true;
                break;
            }
        }
        printTarget(out, true, t);
    }
    for (std::size_t i = 0; i < all.targets.size(); ++i)
        if (!used[i]) printTarget(out, false, all.targets[i]);
    std::fprintf(out, "  targets: %zu built, %lld B; all-features %zu, %lld B (%lld B not allocated)\n", built.targets.size(),
                 static_cast<long long>(built.targetBytes()), all.targets.size(), static_cast<long long>(all.targetBytes()),
                 static_cast<long long>(all.targetBytes() - built.targetBytes()));

    std::fprintf(out, "passes run:");
    for (const auto& p : built.passes) std::fprintf(out, " %s", p.c_str());
    std::fprintf(out, "\npasses left out:");
    int leftOut = 0;
    for (const auto& p : all.passes) {
        if (built.hasPass(p)) continue;
        std::fprintf(out, " %s", p.c_str());
        ++leftOut;
    }
    std::fprintf(out, "%s\n", leftOut ? "" : " none");
    // --bounds: each pass of this run against its bound (common/pass_bound.h), as the timing table.
    bool boundsHeader = false;
    for (std::size_t i = 0; i < built.passes.size() && i < built.passMs.size(); ++i) {
        if (PassBound::boundMs(built.passes[i]) <= 0) continue;
        if (!boundsHeader) std::fprintf(out, "pass bounds (ms; bytes written; fill, fetch and bound ms; ms / bound):\n");
        boundsHeader = true;
        std::fprintf(out, "  %-16s %9.3f ms%s\n", built.passes[i].c_str(), built.passMs[i],
                     PassBound::columns(built.passes[i], built.passMs[i]).c_str());
    }

    if (built.hasClears || all.hasClears) {
        // Targets' and back buffers' depth/stencil buffers over the run: made at the first draw that
        // tested depth or stencil, never made for a target no draw tested them on.
        std::fprintf(out, "depth/stencil buffers (made when a draw first tests depth or stencil; "
                          "DeviceOptimizations::LazyDepthStorage):\n");
        printDepthStorage(out, "this scene", built);
        if (&all != &built) printDepthStorage(out, "all-features", all);
    }
    if (built.hasClears || all.hasClears) {
        // Channel clears (colour, depth, stencil each count; SetRenderTargets' too) over every frame
        // the device drew; executed + replaced + dropped = requested once nothing is pending.
        std::fprintf(out, "clears (channel clears over the run's frames; DeviceOptimizations::DeferClears):\n");
        printClears(out, "this scene", built);
        if (&all != &built) printClears(out, "all-features", all);
    }
    const ComputePassStatistics& compute = built.computePasses;
    if (compute.dispatched > 0 || !compute.fellBack.empty()) {
        // Candidates: draws of at most two triangles (FXPORT_COMPUTE_PASSES=1).
        std::fprintf(out, "compute passes (draws of <= 2 triangles over the run's frames; DeviceOptimizations::ComputePasses):\n");
        std::fprintf(out, "  run as compute %6ld  (%ld from the replay store without a fill)\n", compute.dispatched,
                     compute.replayed);
        std::fprintf(out, "  replay entries %6ld  %.1f MiB held, %ld evicted\n", compute.entries,
                     double(compute.entryBytes) / (1 << 20), compute.evicted);
        for (const auto& [reason, count] : compute.fellBack) std::fprintf(out, "  fell back %6ld  %s\n", count, reason.c_str());
    }
}

}  // namespace fxport::demo
