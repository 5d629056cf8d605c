#include "report/report_files.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "report/report_plot.h"

namespace fxport::report {

namespace {

std::string fixed(double v, const char* format) {
    if (std::isinf(v)) return "inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string passes(const Measurement& m, const char* separator) {
    std::string s;
    for (std::size_t i = 0; i < m.passMs.size(); ++i) {
        const auto& [name, ms] = m.passMs[i];
        s += (s.empty() ? "" : separator) + name + " " + fixed(ms, "%.3f");
        // --bounds: "(fill 0.147 fetch 0.021 bound 0.147 x1.3)", the bound's terms, the bound and ms / bound
        if (i < m.passBoundMs.size() && m.passBoundMs[i] > 0) {
            s += " (";
            if (i < m.passFillMs.size() && i < m.passFetchMs.size())
                s += "fill " + fixed(m.passFillMs[i], "%.3f") + " fetch " + fixed(m.passFetchMs[i], "%.3f") + " ";
            s += "bound " + fixed(m.passBoundMs[i], "%.3f") + " x" + fixed(ms / m.passBoundMs[i], "%.1f") + ")";
        }
    }
    return s;
}

std::ofstream open(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    return out;
}

std::string csvField(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace

void writeCsv(const std::vector<Measurement>& rows, const std::string& path) {
    std::ofstream out = open(path);
    out << "demo,knob,setting,seed_default,size,frames,frame_ms_median,rms,max,psnr_db,passes_ms_median,reference,"
           "light_map_rms,light_map_max,light_map_psnr_db,light_map_reference,light_map_rms_off_terminator,"
           "light_map_max_off_terminator,light_map_rms_vs_ideal_esm,light_map_max_vs_ideal_esm\n";
    for (const Measurement& m : rows)
        out << m.demo << ',' << csvField(m.knob) << ',' << csvField(m.setting) << ',' << (m.seedDefault ? 1 : 0) << ','
            << m.size << ',' << m.frames << ',' << fixed(m.frameMs, "%.4f") << ',' << fixed(m.error.rms, "%.6g") << ','
            << fixed(m.error.max, "%.6g") << ',' << fixed(m.error.psnr, "%.2f") << ',' << csvField(passes(m, "; ")) << ','
            << csvField(m.reference) << ',' << (m.hasLightMapError ? fixed(m.lightMapError.rms, "%.6g") : "") << ','
            << (m.hasLightMapError ? fixed(m.lightMapError.max, "%.6g") : "") << ','
            << (m.hasLightMapError ? fixed(m.lightMapError.psnr, "%.2f") : "") << ',' << csvField(m.lightMapReference) << ','
            << (m.hasLightMapError ? fixed(m.lightMapErrorOffTerminator.rms, "%.6g") : "") << ','
            << (m.hasLightMapError ? fixed(m.lightMapErrorOffTerminator.max, "%.6g") : "") << ','
            << (m.hasLightMapError ? fixed(m.lightMapErrorVsIdealEsm.rms, "%.6g") : "") << ','
            << (m.hasLightMapError ? fixed(m.lightMapErrorVsIdealEsm.max, "%.6g") : "") << '\n';
}

void writeMarkdown(const std::vector<Measurement>& rows, const RunInfo& info, const std::string& path) {
    std::ofstream out = open(path);
    out << "# fxdemo report: error against GPU time\n\n"
        << "- command: `" << info.command << "`\n- renderer: " << info.renderer << "\n- date: " << info.date
        << "\n- frames per setting: " << info.warmupFrames << " or more untimed (" << info.warmupSeconds << " s at least), then " << info.frames
        << " timed (times are medians over them; GPU timestamp queries)\n\n"
        << "Each knob is varied alone, the others at the seed's setting (marked *). Error: RMS, max and PSNR "
           "(peak 1) over the R, G, B values in [0, 1] of the final 8-bit image against the reference named "
           "for each demo; the deferred demo adds the same three for its light map against an exact one. Pareto: no other setting of the same demo is both faster and more exact (settings "
           "that change the scene, pointlights' light count, are left out). "
           "On OSMesa (llvmpipe) every pass is finished before and after it is timed, so its times add up "
           "but include the synchronisation. The plot is `report.png`.\n";
    std::map<std::string, std::vector<Measurement>> byDemo;
    std::vector<std::string> order;
    for (const Measurement& m : rows) {
        if (!byDemo.count(m.demo)) order.push_back(m.demo);
        byDemo[m.demo].push_back(m);
    }
    for (const std::string& demo : order) {
        const std::vector<Measurement>& mine = byDemo[demo];
        std::vector<bool> pareto(mine.size());
        for (std::size_t i : paretoFront(mine)) pareto[i] = true;
        const bool lightMap = mine.front().hasLightMapError;
        out << "\n## " << demo << " (" << mine.front().size << ")\n\nReference: " << mine.front().reference << ".\n";
        if (lightMap)
            out << "Light map columns (LM): the LightMap target (RGBA, A = specular) against the " << mine.front().lightMapReference
                << ". Pareto uses the final image's RMS.\n";
        out << "\n| knob | setting | frame ms | RMS | max | PSNR dB |" << (lightMap ? " LM RMS | LM max | LM PSNR dB | LM RMS off term. | LM RMS vs ESM | LM max vs ESM |" : "")
            << " Pareto | per pass ms |\n"
            << "|---|---|---:|---:|---:|---:|" << (lightMap ? "---:|---:|---:|---:|---:|---:|" : "") << ":-:|---|\n";
        for (std::size_t i = 0; i < mine.size(); ++i) {
            const Measurement& m = mine[i];
            out << "| " << m.knob << " | " << m.setting << (m.seedDefault ? " *" : "") << " | " << fixed(m.frameMs, "%.3f")
                << " | " << fixed(m.error.rms, "%.5f") << " | " << fixed(m.error.max, "%.4f") << " | "
                << fixed(m.error.psnr, "%.2f") << " | ";
            if (lightMap)
                out << fixed(m.lightMapError.rms, "%.5f") << " | " << fixed(m.lightMapError.max, "%.4f") << " | "
                    << fixed(m.lightMapError.psnr, "%.2f") << " | " << fixed(m.lightMapErrorOffTerminator.rms, "%.5f")
                    << " | " << fixed(m.lightMapErrorVsIdealEsm.rms, "%.5f") << " | " << fixed(m.lightMapErrorVsIdealEsm.max, "%.4f")
                    << " | ";
            out << (pareto[i] ? "yes" : "") << " | " << passes(m, ", ") << " |\n";
        }
    }
}

}  // namespace fxport::report
