#pragma once
// atan2 in double for the hot paths that need an angle to full precision, in about a third of
// glibc's instructions and two divisions: Moshier's Cephes atan (the quotient reduced to
// |t| <= 0.66 by tan(π/4 + a) and tan(π/2 - a), then a rational function of degree 4/5), within
// about an ulp of the correctly rounded angle (the test compares it with std::atan2).
#include <cmath>

namespace whitted {

namespace atan2_detail {
// The angle of (ax, ay) for ax, ay >= 0, not both zero or both infinite, in [0, π/2]: the
// quotient reduced to |t| <= 0.66 by tan(π/4 + a) and tan(π/2 - a) in the same one division.
inline double first_quadrant(double ay, double ax) {
    constexpr double P0 = -8.750608600031904122785e-1, P1 = -1.615753718733365076637e1,
                     P2 = -7.500855792314704667340e1, P3 = -1.228866684490136173410e2,
                     P4 = -6.485021904942025371773e1;
    constexpr double Q0 = 2.485846490142306297962e1, Q1 = 1.650270098316988542046e2,
                     Q2 = 4.328810604912902668951e2, Q3 = 4.853903996359136964868e2,
                     Q4 = 1.945506571482613964425e2;
    // π/2 and π/4 as two doubles each: the low part is added last.
    constexpr double kHalfPi = 1.57079632679489661923, kHalfPiLow = 6.123233995736765886130e-17;
    constexpr double kQuarterPi = 0.78539816339744830962, kTanThreeEighthsPi = 2.41421356237309504880;
    double base = 0.0, low = 0.0, t;
    if (ay > kTanThreeEighthsPi * ax) {
        base = kHalfPi;
        low = kHalfPiLow;
        t = -ax / ay;
    } else if (ay > 0.66 * ax) {
        base = kQuarterPi;
        low = 0.5 * kHalfPiLow;
        t = (ay - ax) / (ay + ax);
    } else {
        t = ay / ax;
    }
    const double z = t * t;
    const double p = (((P0 * z + P1) * z + P2) * z + P3) * z + P4;
    const double q = ((((z + Q0) * z + Q1) * z + Q2) * z + Q3) * z + Q4;
    return base + (t * (z * p / q) + t + low);
}
}  // namespace atan2_detail

// The angle of (x, y) in [-π, π], as std::atan2 for arguments below 1e300 in magnitude (the sum
// y + x must not overflow) or one of them infinite; NaN for NaN.
inline double fast_atan2(double y, double x) {
    constexpr double kPi = 3.14159265358979323846, kHalfPi = 1.57079632679489661923;
    const double ay = std::abs(y);
    double a;
    if (x > 0.0)
        a = atan2_detail::first_quadrant(ay, x);
    else if (x < 0.0)
        a = kPi - atan2_detail::first_quadrant(ay, -x);
    else if (x == 0.0)
        a = ay > 0.0 ? kHalfPi : std::signbit(x) ? kPi : 0.0;
    else
        return x;  // NaN
    return std::copysign(a, y);
}

}  // namespace whitted
