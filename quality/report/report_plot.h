// report.png: error against GPU time, one panel per demo, log axes, one curve per knob (its
// settings joined in sweep order), the Pareto front of each panel marked (settings no other setting
// beats in both time and error). Lines and markers are drawn on the CPU; the text is the runtime's
// 8x8 debug font drawn with SpriteBatch over that image, which is then saved as PNG.
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "report/measurement.h"

namespace fxport::report {

// Indices of the Pareto-optimal measurements among `rows` (lower frameMs and lower RMS are better).
std::vector<std::size_t> paretoFront(const std::vector<Measurement>& rows);

void writePlot(GraphicsDevice& device, const std::vector<Measurement>& rows, const std::string& title,
               const std::string& path);

}  // namespace fxport::report
