#include "PortableMath.hpp"

#include <cmath>

namespace stoa::assets {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The Taylor series of sin on [-pi/2, pi/2], to the x^17 term: the first term
// left out is below (pi/2)^19 / 19! < 2e-13.
double sinNearZero(double x) {
    const double x2 = x * x;
    double term = x, sum = x;
    for (int n = 1; n <= 8; ++n) {
        term *= -x2 / static_cast<double>((2 * n) * (2 * n + 1));
        sum += term;
    }
    return sum;
}

} // namespace

double portableSin(double x) {
    // Reduce to [-pi, pi], then to [-pi/2, pi/2] with sin(pi - x) = sin(x).
    // std::nearbyint is exact, so the reduction uses basic operations only.
    x -= 2.0 * kPi * std::nearbyint(x / (2.0 * kPi));
    if (x > 0.5 * kPi) x = kPi - x;
    if (x < -0.5 * kPi) x = -kPi - x;
    return sinNearZero(x);
}

double portableCos(double x) { return portableSin(x + 0.5 * kPi); }

double portableExp(double x) {
    if (x < -700.0) return 0.0;
    // exp(x) = 2^k exp(r) with |r| <= ln(2) / 2; std::ldexp scales exactly.
    constexpr double kLn2 = 0.69314718055994530942;
    const double k = std::nearbyint(x / kLn2);
    const double r = x - k * kLn2;
    double term = 1.0, sum = 1.0;
    for (int n = 1; n <= 14; ++n) {  // (ln 2 / 2)^15 / 15! < 1e-19
        term *= r / static_cast<double>(n);
        sum += term;
    }
    return std::ldexp(sum, static_cast<int>(k));
}

} // namespace stoa::assets
