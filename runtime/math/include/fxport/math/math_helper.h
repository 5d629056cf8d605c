// MathHelper: XNA's scalar helpers and constants. The constants are XNA's: the float nearest to the
// real value, so MathHelper::Pi == (float)Math.PI in C#.
#pragma once

#include <cmath>

namespace fxport {

struct MathHelper {
    static constexpr float E = 2.71828182845904523536f;
    static constexpr float Log10E = 0.43429448190325182765f;
    static constexpr float Log2E = 1.44269504088896340736f;
    static constexpr float Pi = 3.14159265358979323846f;
    static constexpr float PiOver2 = 1.57079632679489661923f;
    static constexpr float PiOver4 = 0.78539816339744830962f;
    static constexpr float TwoPi = 6.28318530717958647692f;

    // In double and rounded once, so ToRadians(180) == Pi and ToDegrees(Pi) == 180 exactly.
    static constexpr float ToRadians(float degrees) {
        return static_cast<float>(degrees * (3.14159265358979323846 / 180.0));
    }
    static constexpr float ToDegrees(float radians) {
        return static_cast<float>(radians * (180.0 / 3.14159265358979323846));
    }

    // XNA's order of tests: a NaN value passes through, min wins when min > max.
    static constexpr float Clamp(float value, float min, float max) {
        value = value > max ? max : value;
        return value < min ? min : value;
    }
    static constexpr float Min(float value1, float value2) { return value1 < value2 ? value1 : value2; }
    static constexpr float Max(float value1, float value2) { return value1 > value2 ? value1 : value2; }
    static float Distance(float value1, float value2) { return std::fabs(value1 - value2); }

    static constexpr float Lerp(float value1, float value2, float amount) {
        return value1 + (value2 - value1) * amount;
    }
    // Cubic ease between the two values; amount is clamped to [0, 1] first.
    static constexpr float SmoothStep(float value1, float value2, float amount) {
        const float t = Clamp(amount, 0.0f, 1.0f);
        return Lerp(value1, value2, t * t * (3.0f - 2.0f * t));
    }
    static constexpr float Barycentric(float value1, float value2, float value3, float amount1,
                                       float amount2) {
        return value1 + (value2 - value1) * amount1 + (value3 - value1) * amount2;
    }

    // Catmull-Rom spline through value2 (amount 0) and value3 (amount 1), value1 and value4 the
    // neighbours; computed in double as XNA.
    static constexpr float CatmullRom(float value1, float value2, float value3, float value4, float amount) {
        const double a = amount, a2 = a * a, a3 = a2 * a;
        return static_cast<float>(0.5 * (2.0 * value2 + (value3 - value1) * a +
                                         (2.0 * value1 - 5.0 * value2 + 4.0 * value3 - value4) * a2 +
                                         (3.0 * value2 - value1 - 3.0 * value3 + value4) * a3));
    }
    // Cubic Hermite spline from value1 (tangent1) to value2 (tangent2); exact at amount 0 and 1.
    static constexpr float Hermite(float value1, float tangent1, float value2, float tangent2, float amount) {
        if (amount == 0.0f) return value1;
        if (amount == 1.0f) return value2;
        const double s = amount, s2 = s * s, s3 = s2 * s;
        const double v1 = value1, v2 = value2, t1 = tangent1, t2 = tangent2;
        return static_cast<float>((2.0 * v1 - 2.0 * v2 + t2 + t1) * s3 + (3.0 * v2 - 3.0 * v1 - 2.0 * t1 - t2) * s2 +
                                  t1 * s + v1);
    }

    // Reduces an angle to (-Pi, Pi]. Like XNA, the remainder is taken in double against the float
    // 2*Pi, so angles that are exact multiples of TwoPi wrap to 0.
    static float WrapAngle(float angle) {
        angle = static_cast<float>(std::remainder(static_cast<double>(angle), static_cast<double>(TwoPi)));
        if (angle <= -Pi) {
            angle += TwoPi;
        } else if (angle > Pi) {
            angle -= TwoPi;
        }
        return angle;
    }
};

}  // namespace fxport
