// TimeSpan: .NET's System.TimeSpan as XNA's GameTime uses it, an interval counted in 100-nanosecond
// ticks (so sums of frame times are exact, as in .NET). Read-only properties are methods
// (docs/API.md): gameTime.ElapsedGameTime.TotalSeconds().
#pragma once

#include <cmath>
#include <compare>
#include <cstdint>

namespace fxport {

class TimeSpan {
public:
    static constexpr std::int64_t TicksPerMillisecond = 10'000;
    static constexpr std::int64_t TicksPerSecond = 10'000'000;

    constexpr TimeSpan() = default;
    constexpr explicit TimeSpan(std::int64_t ticks) : ticks_(ticks) {}
    // .NET's TimeSpan(hours, minutes, seconds) and (days, hours, minutes, seconds, milliseconds).
    constexpr TimeSpan(int hours, int minutes, int seconds)
        : ticks_((std::int64_t(hours) * 3600 + std::int64_t(minutes) * 60 + seconds) * TicksPerSecond) {}
    constexpr TimeSpan(int days, int hours, int minutes, int seconds, int milliseconds)
        : ticks_(((std::int64_t(days) * 86400 + std::int64_t(hours) * 3600 + std::int64_t(minutes) * 60 + seconds) * 1000 +
                  milliseconds) * TicksPerMillisecond) {}

    static constexpr TimeSpan FromTicks(std::int64_t ticks) { return TimeSpan(ticks); }
    // Rounded to the nearest tick (.NET Core's rule; .NET Framework rounded to whole milliseconds).
    static TimeSpan FromSeconds(double seconds) { return TimeSpan(std::llround(seconds * double(TicksPerSecond))); }
    static TimeSpan FromMilliseconds(double ms) { return TimeSpan(std::llround(ms * double(TicksPerMillisecond))); }

    constexpr std::int64_t Ticks() const { return ticks_; }
    constexpr double TotalSeconds() const { return double(ticks_) / double(TicksPerSecond); }
    constexpr double TotalMilliseconds() const { return double(ticks_) / double(TicksPerMillisecond); }
    // The whole-second and millisecond components, as .NET's Seconds/Milliseconds.
    constexpr int Seconds() const { return int((ticks_ / TicksPerSecond) % 60); }
    constexpr int Milliseconds() const { return int((ticks_ / TicksPerMillisecond) % 1000); }

    constexpr TimeSpan operator+(TimeSpan o) const { return TimeSpan(ticks_ + o.ticks_); }
    constexpr TimeSpan operator-(TimeSpan o) const { return TimeSpan(ticks_ - o.ticks_); }
    constexpr TimeSpan operator-() const { return TimeSpan(-ticks_); }
    constexpr TimeSpan& operator+=(TimeSpan o) { ticks_ += o.ticks_; return *this; }
    constexpr TimeSpan& operator-=(TimeSpan o) { ticks_ -= o.ticks_; return *this; }
    constexpr TimeSpan operator*(std::int64_t n) const { return TimeSpan(ticks_ * n); }
    constexpr auto operator<=>(const TimeSpan&) const = default;

    static const TimeSpan Zero;

private:
    std::int64_t ticks_ = 0;
};

inline constexpr TimeSpan TimeSpan::Zero{};

}  // namespace fxport
