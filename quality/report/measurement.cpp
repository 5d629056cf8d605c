#include "report/measurement.h"

#include <cmath>
#include <limits>

#include "fxport/graphics/errors.h"

namespace fxport::report {

ImageError compareImages(const std::vector<double>& got, const std::vector<double>& reference, const std::string& what,
                         const std::vector<char>* defined) {
    if (got.size() != reference.size() || got.empty())
        throw ArgumentError(what + ": image of " + std::to_string(got.size()) + " values against a reference of " +
                            std::to_string(reference.size()));
    if (defined && (defined->empty() || got.size() % defined->size() != 0))
        throw ArgumentError(what + ": " + std::to_string(defined->size()) + " pixel flags for " + std::to_string(got.size()) + " values");
    const std::size_t perPixel = defined ? got.size() / defined->size() : 1;
    ImageError e;
    double sum = 0;
    std::size_t counted = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (defined && !(*defined)[i / perPixel]) continue;
        ++counted;
        if (std::isnan(got[i]) || std::isnan(reference[i]))
            throw ArgumentError(what + ": NaN at value " + std::to_string(i) + (std::isnan(got[i]) ? " of the image" : " of the reference"));
        const double d = got[i] - reference[i];
        sum += d * d;
        e.max = std::max(e.max, std::fabs(d));
    }
    if (counted == 0) throw ArgumentError(what + ": every pixel is left out");
    e.rms = std::sqrt(sum / double(counted));
    e.psnr = e.rms > 0 ? 10.0 * std::log10(1.0 / (e.rms * e.rms)) : std::numeric_limits<double>::infinity();
    return e;
}

std::vector<double> toRgb(const std::vector<Color>& pixels) {
    std::vector<double> rgb;
    rgb.reserve(pixels.size() * 3);
    for (const Color& c : pixels) {
        rgb.push_back(c.R / 255.0);
        rgb.push_back(c.G / 255.0);
        rgb.push_back(c.B / 255.0);
    }
    return rgb;
}

}  // namespace fxport::report
