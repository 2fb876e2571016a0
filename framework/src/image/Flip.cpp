#include <stoa/image/Flip.hpp>

#include "SeparableFilter.hpp"

#include <stoa/core/Assert.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace stoa {

namespace {

using detail::Kernel;
using detail::Plane;

constexpr double kPi = 3.14159265358979323846;

// --- Constants of the paper -------------------------------------------------
// Contrast sensitivity, as a sum of two Gaussians per opponent channel:
//   S(x) = a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2),  x in degrees.
struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kAchromatic{1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kRedGreen{1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kLargestCsfScale = 0.04;        // the largest b: sets the common filter radius
constexpr double kColourExponent = 0.7;          // qc
constexpr double kFeatureExponent = 0.5;         // qf
constexpr double kCompressionKnee = 0.4;         // pc
constexpr double kCompressionTarget = 0.95;      // pt
constexpr double kFeatureWidthDegrees = 0.082;   // w, peak to trough of the edge detector

// Linear sRGB (D65) to CIE XYZ, and the white point it implies (the row sums).
constexpr double kRgbToXyz[3][3] = {{0.4123908, 0.3575843, 0.1804808},
                                    {0.2126390, 0.7151687, 0.0721923},
                                    {0.0193308, 0.1191948, 0.9505322}};

struct Colour {
    double x, y, z;
};

struct Matrices {
    double toXyz[3][3];
    double toRgb[3][3];
    double white[3];
};

const Matrices& matrices() {
    static const Matrices m = [] {
        Matrices result{};
        const auto& a = kRgbToXyz;
        for (int r = 0; r < 3; ++r) {
            result.white[r] = a[r][0] + a[r][1] + a[r][2];
            for (int c = 0; c < 3; ++c) result.toXyz[r][c] = a[r][c];
        }
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                // Inverse = adjugate / det; cofactor (c, r) with cyclic indices.
                const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
                result.toRgb[r][c] = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) / det;
            }
        return result;
    }();
    return m;
}

Colour multiply(const double m[3][3], Colour v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// CIELAB's f(t): a cube root above (6/29)^3, a line below.
double labCurve(double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// f(t) for t in [0, 1] (what a colour of the RGB unit cube gives, relative to the
// white point), linearly interpolated from a table: std::cbrt for three channels of
// every pixel would take a third of FLIP's time. The interpolation error is below
// 5e-6 in f (f'' is largest just above (6/29)^3), 6e-4 in L*: far below a visible step.
class LabCurveTable {
public:
    LabCurveTable() {
        for (int i = 0; i <= kSteps; ++i) m_values[i] = static_cast<float>(labCurve(double(i) / kSteps));
    }
    float operator()(float t) const {
        const float position = std::clamp(t, 0.0f, 1.0f) * kSteps;
        const int index = std::min(static_cast<int>(position), kSteps - 1);
        const float fraction = position - static_cast<float>(index);
        return m_values[index] + fraction * (m_values[index + 1] - m_values[index]);
    }

private:
    static constexpr int kSteps = 4096;
    float m_values[kSteps + 1];
};

// Linear RGB in [0, 1] to Hunt-adjusted L*a*b*: a* and b* scaled by 0.01 L*.
Colour huntLab(Colour rgb) {
    const Matrices& m = matrices();
    const Colour xyz = multiply(m.toXyz, rgb);
    const double fx = labCurve(xyz.x / m.white[0]), fy = labCurve(xyz.y / m.white[1]),
                 fz = labCurve(xyz.z / m.white[2]);
    const double L = 116.0 * fy - 16.0;
    return {L, 0.01 * L * 500.0 * (fx - fy), 0.01 * L * 200.0 * (fy - fz)};
}

double hyab(Colour a, Colour b) {
    return std::abs(a.x - b.x) + std::sqrt((a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// --- Filters ----------------------------------------------------------------
struct CsfTerm {
    Kernel kernel;   // normalised 1D Gaussian; the 2D term is kernel x kernel
    float weight;    // the term's share of the normalised 2D filter
};

// The separable terms of one channel's 2D filter S(sqrt(x^2 + y^2)) / sum S: each
// Gaussian term factors into x and y, so the 2D filter is a weighted sum of
// separable filters (one term where a2 = 0).
std::vector<CsfTerm> csfTerms(const Csf& csf, double ppd) {
    const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(kLargestCsfScale / (2.0 * kPi * kPi)) * ppd));
    std::vector<CsfTerm> terms;
    std::vector<double> masses;
    for (const auto& [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
        if (a == 0.0) continue;
        std::vector<double> g(2 * radius + 1);
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;
            g[i + radius] = std::exp(-kPi * kPi * x * x / b);
            sum += g[i + radius];
        }
        // Taps below 1e-7 of the centre change no float sum: the narrow achromatic and
        // red-green Gaussians (about 1 pixel at 67 PPD) need far fewer than 2r+1.
        int used = radius;
        while (used > 0 && g[radius + used] < 1e-7 * g[radius]) --used;
        CsfTerm term;
        for (int i = radius - used; i <= radius + used; ++i) term.kernel.push_back(static_cast<float>(g[i] / sum));
        terms.push_back(term);
        masses.push_back(a * std::sqrt(kPi / b) * sum * sum);  // this term's sum over the 2D grid
    }
    double total = 0.0;
    for (const double mass : masses) total += mass;
    for (std::size_t i = 0; i < terms.size(); ++i) terms[i].weight = static_cast<float>(masses[i] / total);
    return terms;
}

// Positive taps scaled to sum to 1, negative taps to -1.
Kernel balanced(const std::vector<double>& taps) {
    double positive = 0.0, negative = 0.0;
    for (const double t : taps) (t > 0.0 ? positive : negative) += t;
    Kernel kernel;
    for (const double t : taps) kernel.push_back(static_cast<float>(t > 0.0 ? t / positive : t / -negative));
    return kernel;
}

struct FeatureKernels {
    Kernel gaussian, edge, point;
};

// The 2D detectors -x g(x, y) and (x^2 / s^2 - 1) g(x, y), each normalised so
// that its positive weights sum to 1 and its negative ones to -1, factor into
// (derivative in x) x (normalised Gaussian in y); likewise for y.
FeatureKernels featureKernels(double ppd) {
    const double sd = 0.5 * kFeatureWidthDegrees * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sd));
    std::vector<double> g, edge, point;
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double value = std::exp(-(i * i) / (2.0 * sd * sd));
        g.push_back(value);
        sum += value;
        edge.push_back(-i * value);
        point.push_back((i * i / (sd * sd) - 1.0) * value);
    }
    FeatureKernels kernels;
    for (const double v : g) kernels.gaussian.push_back(static_cast<float>(v / sum));
    kernels.edge = balanced(edge);
    kernels.point = balanced(point);
    return kernels;
}

// --- Per image --------------------------------------------------------------
struct Prepared {
    Plane L, A, B;          // Hunt-adjusted L*a*b* of the CSF-filtered image
    Plane edges, points;    // feature magnitudes of the luminance
};

float srgbToLinear(int level) {
    const double c = level / 255.0;
    return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

void filterCsf(const Plane& in, const std::vector<CsfTerm>& terms, Plane& out, Plane& scratch, Plane& term) {
    out = Plane(in.width, in.height);
    for (const CsfTerm& t : terms) {
        detail::filterRows(in, t.kernel, scratch);
        detail::filterColumns(scratch, t.kernel, term);
        for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] += t.weight * term.values[i];
    }
}

Plane magnitude(const Plane& x, const Plane& y) {
    Plane out(x.width, x.height);
    for (std::size_t i = 0; i < out.values.size(); ++i)
        out.values[i] = std::sqrt(x.values[i] * x.values[i] + y.values[i] * y.values[i]);
    return out;
}

Prepared prepare(const Image& image, double ppd) {
    static const std::array<float, 256> linear = [] {
        std::array<float, 256> table{};
        for (int i = 0; i < 256; ++i) table[i] = srgbToLinear(i);
        return table;
    }();
    const Matrices& m = matrices();
    const int width = image.width(), height = image.height();
    const Image rgbaCopy = image.channels() >= 3 ? Image() : image.converted(4);
    const Image& source = image.channels() >= 3 ? image : rgbaCopy;
    const int channels = source.channels();

    // YCxCz: Y' = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn); and Y/Yn for the features.
    Plane opponent[3] = {Plane(width, height), Plane(width, height), Plane(width, height)};
    Plane luminance(width, height);
    const std::uint8_t* pixel = source.data();
    for (std::size_t i = 0; i < luminance.values.size(); ++i, pixel += channels) {
        const Colour xyz = multiply(m.toXyz, {linear[pixel[0]], linear[pixel[1]], linear[pixel[2]]});
        const double x = xyz.x / m.white[0], y = xyz.y / m.white[1], z = xyz.z / m.white[2];
        opponent[0].values[i] = static_cast<float>(116.0 * y - 16.0);
        opponent[1].values[i] = static_cast<float>(500.0 * (x - y));
        opponent[2].values[i] = static_cast<float>(200.0 * (y - z));
        luminance.values[i] = static_cast<float>(y);
    }

    // Contrast sensitivity per channel, then back to linear RGB in the unit cube and on to L*a*b*.
    Plane filtered[3], scratch, term;
    filterCsf(opponent[0], csfTerms(kAchromatic, ppd), filtered[0], scratch, term);
    filterCsf(opponent[1], csfTerms(kRedGreen, ppd), filtered[1], scratch, term);
    filterCsf(opponent[2], csfTerms(kBlueYellow, ppd), filtered[2], scratch, term);
    Prepared prepared;
    prepared.L = Plane(width, height);
    prepared.A = Plane(width, height);
    prepared.B = Plane(width, height);
    // In float, with the matrices folded: (Y', Cx, Cz) -> XYZ -> linear RGB, clamped,
    // -> XYZ relative to the white point -> f -> L*a*b* -> Hunt.
    static const LabCurveTable curve;
    float toRgb[3][3], toRelative[3][3], white[3];
    for (int r = 0; r < 3; ++r) {
        white[r] = static_cast<float>(m.white[r]);
        for (int c = 0; c < 3; ++c) {
            toRgb[r][c] = static_cast<float>(m.toRgb[r][c]);
            toRelative[r][c] = static_cast<float>(m.toXyz[r][c] / m.white[r]);
        }
    }
    for (std::size_t i = 0; i < luminance.values.size(); ++i) {
        const float y = (filtered[0].values[i] + 16.0f) * (1.0f / 116.0f);
        const float xyz[3] = {(y + filtered[1].values[i] * (1.0f / 500.0f)) * white[0], y * white[1],
                              (y - filtered[2].values[i] * (1.0f / 200.0f)) * white[2]};
        float rgb[3];
        for (int r = 0; r < 3; ++r)
            rgb[r] = std::clamp(toRgb[r][0] * xyz[0] + toRgb[r][1] * xyz[1] + toRgb[r][2] * xyz[2], 0.0f, 1.0f);
        float f[3];
        for (int r = 0; r < 3; ++r)
            f[r] = curve(toRelative[r][0] * rgb[0] + toRelative[r][1] * rgb[1] + toRelative[r][2] * rgb[2]);
        const float L = 116.0f * f[1] - 16.0f;
        prepared.L.values[i] = L;
        prepared.A.values[i] = 0.01f * L * 500.0f * (f[0] - f[1]);
        prepared.B.values[i] = 0.01f * L * 200.0f * (f[1] - f[2]);
    }

    // Edges and points of the unfiltered luminance.
    const FeatureKernels k = featureKernels(ppd);
    Plane smoothX, edgeX, pointX, dx, dy;
    detail::filterRows(luminance, k.gaussian, smoothX);
    detail::filterRows(luminance, k.edge, edgeX);
    detail::filterRows(luminance, k.point, pointX);
    detail::filterColumns(edgeX, k.gaussian, dx);
    detail::filterColumns(smoothX, k.edge, dy);
    prepared.edges = magnitude(dx, dy);
    detail::filterColumns(pointX, k.gaussian, dx);
    detail::filterColumns(smoothX, k.point, dy);
    prepared.points = magnitude(dx, dy);
    return prepared;
}

} // namespace

FlipResult computeFlip(const Image& test, const Image& reference, const FlipOptions& options) {
    STOA_ASSERT(test.width() == reference.width() && test.height() == reference.height(),
                "computeFlip(): the images differ in size.");
    STOA_ASSERT(options.pixelsPerDegree > 0.0 && options.pixelsPerDegree <= 1000.0,
                "computeFlip(): FlipOptions::pixelsPerDegree must be in (0, 1000].");
    FlipResult result;
    result.width = test.width();
    result.height = test.height();
    if (test.empty()) return result;

    const Prepared t = prepare(test, options.pixelsPerDegree);
    const Prepared r = prepare(reference, options.pixelsPerDegree);
    // The largest colour error: green against blue.
    const double largest = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kColourExponent);
    const double knee = kCompressionKnee * largest;
    const double featureScale = 1.0 / std::sqrt(2.0);

    result.errorMap.resize(t.L.values.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < result.errorMap.size(); ++i) {
        const double da = t.A.values[i] - r.A.values[i], db = t.B.values[i] - r.B.values[i];
        const double distance = std::abs(t.L.values[i] - r.L.values[i]) + std::sqrt(da * da + db * db);
        const double powered = std::pow(static_cast<float>(distance), static_cast<float>(kColourExponent));
        const double colour = powered < knee
                                  ? kCompressionTarget / knee * powered
                                  : kCompressionTarget + (powered - knee) / (largest - knee) * (1.0 - kCompressionTarget);
        const double featureDifference =
            std::max(std::abs(t.edges.values[i] - r.edges.values[i]), std::abs(t.points.values[i] - r.points.values[i]));
        static_assert(kFeatureExponent == 0.5, "the feature exponent is computed as a square root");
        const double feature = std::min(1.0, std::sqrt(featureScale * featureDifference));
        const double error =
            std::clamp<double>(std::pow(static_cast<float>(std::min(colour, 1.0)), static_cast<float>(1.0 - feature)), 0.0, 1.0);
        result.errorMap[i] = static_cast<float>(error);
        sum += error;
    }
    result.mean = sum / static_cast<double>(result.errorMap.size());
    return result;
}

} // namespace stoa
