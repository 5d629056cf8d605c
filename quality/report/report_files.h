// report.md (one table per demo and knob) and report.csv (one row per measurement).
#pragma once

#include <string>
#include <vector>

#include "report/measurement.h"

namespace fxport::report {

struct RunInfo {
    std::string command;   // how the report was made
    std::string renderer;  // GL renderer string
    std::string date;      // UTC
    int frames = 0;
    int warmupFrames = 0;
    double warmupSeconds = 0;
};

void writeCsv(const std::vector<Measurement>& rows, const std::string& path);
void writeMarkdown(const std::vector<Measurement>& rows, const RunInfo& info, const std::string& path);

}  // namespace fxport::report
