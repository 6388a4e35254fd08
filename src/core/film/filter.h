// Pixel reconstruction filters (pbrt-v4's Filter): box, gaussian, mitchell, sinc (Lanczos)
// and triangle, and the tabulated FilterSampler used to importance-sample the filters that have
// no analytic inverse.
//
// Filter coordinates are offsets from the pixel centre in pixels (raster units). A filter
// sample carries the weight f(p) / pdf(p), so that film estimates are
//   sum(weight * L) / sum(weight)   (pbrt-v4's filter importance sampling).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "base/sampling.h"
#include "base/vecmath.h"
#include "core/parser/diagnostics.h"
#include "core/parser/file_loc.h"

namespace kiln {

class ParameterDictionary;
class Filter;

// FilterSample: an offset p from the pixel centre (pixels) and its weight f(p) / pdf(p).
struct FilterSample {
    Point2f p;
    Float weight;
};

// FilterSampler: samples |f| through a piecewise-constant tabulation (32 cells per pixel of
// radius, evaluated at cell centres, as pbrt-v4); weight = f(cell) / pdf(cell), whose
// magnitude is the same for every sample and whose sign is the filter's.
class FilterSampler {
  public:
    FilterSampler() = default;
    explicit FilterSampler(const Filter& filter);
    FilterSample Sample(Point2f u) const;

  private:
    Vector2f radius;
    int nx = 0, ny = 0;
    std::vector<Float> f;  // ny rows of nx values
    PiecewiseConstant2D distrib;
};

// BoxFilter: 1 inside [-radius, radius]^2 (default radius 0.5).
class BoxFilter {
  public:
    explicit BoxFilter(Vector2f radius = Vector2f(0.5f, 0.5f)) : radius(radius) {}
    Vector2f Radius() const { return radius; }
    Float Evaluate1D(int axis, Float x) const {
        return std::abs(x) <= (axis ? radius.y : radius.x) ? 1 : 0;
    }
    Float Evaluate(Point2f p) const { return Evaluate1D(0, p.x) * Evaluate1D(1, p.y); }
    Float Integral() const { return 2 * radius.x * 2 * radius.y; }
    FilterSample Sample(Point2f u) const {
        return {Point2f(Lerp(u.x, -radius.x, radius.x), Lerp(u.y, -radius.y, radius.y)), 1};
    }

  private:
    Vector2f radius;
};

// GaussianFilter: separable Gaussian of standard deviation sigma (pixels), shifted down so it
// reaches zero at the radius (defaults radius 1.5, sigma 0.5).
class GaussianFilter {
  public:
    GaussianFilter(Vector2f radius, Float sigma = 0.5f);
    Vector2f Radius() const { return radius; }
    Float Evaluate1D(int axis, Float x) const;
    Float Evaluate(Point2f p) const { return Evaluate1D(0, p.x) * Evaluate1D(1, p.y); }
    Float Integral() const;
    FilterSample Sample(Point2f u) const { return sampler.Sample(u); }

  private:
    Vector2f radius;
    Float sigma, expX, expY;
    FilterSampler sampler;
};

// MitchellFilter: Mitchell-Netravali cubic with parameters B and C over the radius (defaults
// radius 2, B = C = 1/3). Has negative lobes.
class MitchellFilter {
  public:
    MitchellFilter(Vector2f radius, Float b = 1.f / 3.f, Float c = 1.f / 3.f);
    Vector2f Radius() const { return radius; }
    Float Evaluate1D(int axis, Float x) const {
        return Mitchell1D(2 * x / (axis ? radius.y : radius.x));
    }
    Float Evaluate(Point2f p) const { return Evaluate1D(0, p.x) * Evaluate1D(1, p.y); }
    Float Integral() const { return radius.x * radius.y / 4; }
    FilterSample Sample(Point2f u) const { return sampler.Sample(u); }

  private:
    Float Mitchell1D(Float x) const;
    Vector2f radius;
    Float b, c;
    FilterSampler sampler;
};

// LanczosSincFilter: sinc(x) windowed by sinc(x / tau) (pbrt-v4 "sinc"; defaults radius 4,
// tau 3). Has negative lobes.
class LanczosSincFilter {
  public:
    LanczosSincFilter(Vector2f radius, Float tau = 3.f);
    Vector2f Radius() const { return radius; }
    Float Evaluate1D(int axis, Float x) const {
        return WindowedSinc(x, axis ? radius.y : radius.x, tau);
    }
    Float Evaluate(Point2f p) const { return Evaluate1D(0, p.x) * Evaluate1D(1, p.y); }
    // Separable; each factor integrated numerically once at construction.
    Float Integral() const { return integral; }
    FilterSample Sample(Point2f u) const { return sampler.Sample(u); }

    static Float WindowedSinc(Float x, Float radius, Float tau);

  private:
    Vector2f radius;
    Float tau, integral = 0;
    FilterSampler sampler;
};

// TriangleFilter: separable tent falling linearly to zero at the radius (default radius 2).
class TriangleFilter {
  public:
    explicit TriangleFilter(Vector2f radius = Vector2f(2, 2)) : radius(radius) {}
    Vector2f Radius() const { return radius; }
    Float Evaluate1D(int axis, Float x) const {
        return std::max<Float>(0, (axis ? radius.y : radius.x) - std::abs(x));
    }
    Float Evaluate(Point2f p) const { return Evaluate1D(0, p.x) * Evaluate1D(1, p.y); }
    Float Integral() const { return Sqr(radius.x) * Sqr(radius.y); }
    FilterSample Sample(Point2f u) const {
        return {Point2f(SampleTent(u.x, radius.x), SampleTent(u.y, radius.y)), 1};
    }

  private:
    // Density (r - |x|) / r^2 on [-r, r].
    static Float SampleTent(Float u, Float r);
    Vector2f radius;
};

// Filter: the closed set of pixel filters.
class Filter : public ClosedSet<const BoxFilter*, const GaussianFilter*, const MitchellFilter*,
                                const LanczosSincFilter*, const TriangleFilter*> {
  public:
    using ClosedSet::ClosedSet;
    // Half-widths of the filter's support, in pixels.
    Vector2f Radius() const {
        return Dispatch([](auto f) { return f->Radius(); });
    }
    Float Evaluate(Point2f p) const {
        return Dispatch([&](auto f) { return f->Evaluate(p); });
    }
    // Every filter is separable: Evaluate(p) = Evaluate1D(0, p.x) * Evaluate1D(1, p.y).
    Float Evaluate1D(int axis, Float x) const {
        return Dispatch([&](auto f) { return f->Evaluate1D(axis, x); });
    }
    // Integral of f over its support (pixel^2).
    Float Integral() const {
        return Dispatch([](auto f) { return f->Integral(); });
    }
    FilterSample Sample(Point2f u) const {
        return Dispatch([&](auto f) { return f->Sample(u); });
    }

    // pbrt-v4 names: "box", "gaussian", "mitchell", "sinc", "triangle"; parameters "xradius",
    // "yradius", "sigma" (gaussian), "B"/"C" (mitchell), "tau" (sinc). Unknown name:
    // SceneError.
    static Filter Create(const std::string& name, const ParameterDictionary& params,
                         const FileLoc& loc, ObjectArena& arena, Diagnostics& diag);
};

}  // namespace kiln
