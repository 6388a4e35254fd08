// Pixel reconstruction filters: evaluation helpers, tabulated sampling and creation from scene
// parameters (pbrt-v4 semantics).
#include "core/film/filter.h"

#include <cmath>

#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"

namespace kiln {

namespace {

// Normal density with mean mu and standard deviation sigma.
double Gaussian(double x, double mu, double sigma) {
    return 1 / std::sqrt(2 * double(Pi) * sigma * sigma) *
           std::exp(-Sqr(x - mu) / (2 * sigma * sigma));
}

// Integral of Gaussian(x, mu, sigma) over [x0, x1].
double GaussianIntegral(double x0, double x1, double mu, double sigma) {
    double sigmaRoot2 = sigma * 1.414213562373095;
    return 0.5 * (std::erf((mu - x0) / sigmaRoot2) - std::erf((mu - x1) / sigmaRoot2));
}

double Sinc(double x) {
    if (1 - x * x == 1) return 1;  // sin(pi x) / (pi x) -> 1
    return std::sin(double(Pi) * x) / (double(Pi) * x);
}

}  // namespace

// FilterSampler
FilterSampler::FilterSampler(const Filter& filter) : radius(filter.Radius()) {
    nx = std::max(1, int(32 * radius.x));
    ny = std::max(1, int(32 * radius.y));
    f.resize(size_t(nx) * ny);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            Point2f p(Lerp((x + 0.5f) / nx, -radius.x, radius.x),
                      Lerp((y + 0.5f) / ny, -radius.y, radius.y));
            f[size_t(y) * nx + x] = filter.Evaluate(p);
        }
    distrib = PiecewiseConstant2D(f, nx, ny);
}

FilterSample FilterSampler::Sample(Point2f u) const {
    Float pdf01;
    Point2f p01 = distrib.Sample(u, &pdf01);
    int ix = Clamp(int(p01.x * nx), 0, nx - 1), iy = Clamp(int(p01.y * ny), 0, ny - 1);
    Point2f p(Lerp(p01.x, -radius.x, radius.x), Lerp(p01.y, -radius.y, radius.y));
    // Density with respect to filter-space area: the [0,1]^2 density over the domain's area.
    Float pdf = pdf01 / (4 * radius.x * radius.y);
    Float fv = f[size_t(iy) * nx + ix];
    return {p, pdf > 0 ? fv / pdf : 0};
}

// GaussianFilter
GaussianFilter::GaussianFilter(Vector2f radius, Float sigma)
    : radius(radius),
      sigma(sigma),
      expX(Float(Gaussian(radius.x, 0, sigma))),
      expY(Float(Gaussian(radius.y, 0, sigma))),
      sampler(Filter(this)) {}

Float GaussianFilter::Evaluate1D(int axis, Float x) const {
    return std::max<Float>(0, Float(Gaussian(x, 0, sigma)) - (axis ? expY : expX));
}

Float GaussianFilter::Integral() const {
    return Float((GaussianIntegral(-radius.x, radius.x, 0, sigma) - 2 * radius.x * expX) *
                 (GaussianIntegral(-radius.y, radius.y, 0, sigma) - 2 * radius.y * expY));
}

// MitchellFilter
MitchellFilter::MitchellFilter(Vector2f radius, Float b, Float c)
    : radius(radius), b(b), c(c), sampler(Filter(this)) {}

Float MitchellFilter::Mitchell1D(Float x) const {
    x = std::abs(x);
    if (x <= 1)
        return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) *
               (1.f / 6.f);
    if (x <= 2)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x +
                (8 * b + 24 * c)) *
               (1.f / 6.f);
    return 0;
}

// LanczosSincFilter
Float LanczosSincFilter::WindowedSinc(Float x, Float radius, Float tau) {
    if (std::abs(x) > radius) return 0;
    return Float(Sinc(x) * Sinc(double(x) / tau));
}

LanczosSincFilter::LanczosSincFilter(Vector2f radius, Float tau)
    : radius(radius), tau(tau), sampler(Filter(this)) {
    // Composite Simpson's rule on each separable factor.
    auto integrate1D = [&](Float r) {
        const int n = 4096;  // even
        double h = 2.0 * r / n, sum = 0;
        for (int i = 0; i <= n; ++i) {
            double x = -r + i * h;
            double w = (i == 0 || i == n) ? 1 : ((i & 1) ? 4 : 2);
            sum += w * Sinc(x) * Sinc(x / tau);
        }
        return sum * h / 3;
    };
    integral = Float(integrate1D(radius.x) * integrate1D(radius.y));
}

// TriangleFilter
Float TriangleFilter::SampleTent(Float u, Float r) {
    // Pick a half with probability 1/2, then invert the linear ramp's CDF within it.
    if (u < 0.5f) {
        Float up = std::min<Float>(2 * u, OneMinusEpsilon);
        return -r + r * std::sqrt(up);
    }
    Float up = std::min<Float>(2 * u - 1, OneMinusEpsilon);
    return r * (1 - std::sqrt(1 - up));
}

// Filter creation
Filter Filter::Create(const std::string& name, const ParameterDictionary& params,
                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    (void)diag;
    auto radius = [&](Float def) {
        return Vector2f(params.GetOneFloat("xradius", def), params.GetOneFloat("yradius", def));
    };
    auto checkRadius = [&](Vector2f r) {
        if (!(r.x > 0) || !(r.y > 0))
            throw SceneError(params.Has("xradius") && !(r.x > 0) ? params.Loc("xradius")
                             : params.Has("yradius")             ? params.Loc("yradius")
                                                                 : loc,
                             "filter radius must be positive", name);
        return r;
    };
    if (name == "box") return arena.New<BoxFilter>(checkRadius(radius(0.5f)));
    if (name == "gaussian") {
        Vector2f r = checkRadius(radius(1.5f));
        Float sigma = params.GetOneFloat("sigma", 0.5f);
        if (!(sigma > 0)) throw SceneError(params.Loc("sigma"), "\"sigma\" must be positive");
        return arena.New<GaussianFilter>(r, sigma);
    }
    if (name == "mitchell") {
        Vector2f r = checkRadius(radius(2.f));
        return arena.New<MitchellFilter>(r, params.GetOneFloat("B", 1.f / 3.f),
                                         params.GetOneFloat("C", 1.f / 3.f));
    }
    if (name == "sinc") {
        Vector2f r = checkRadius(radius(4.f));
        return arena.New<LanczosSincFilter>(r, params.GetOneFloat("tau", 3.f));
    }
    if (name == "triangle") return arena.New<TriangleFilter>(checkRadius(radius(2.f)));
    throw SceneError(
        loc,
        "unknown filter type \"" + name + "\"" +
            DidYouMean(name, std::initializer_list<std::string_view>{"box", "gaussian", "mitchell",
                                                                     "sinc", "triangle"}),
        name);
}

}  // namespace kiln
