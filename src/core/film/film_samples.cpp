// RGBFilm: how samples reach the pixels (filter importance sampling and spreading, see
// PixelReconstruction in film.h).
#include <algorithm>
#include <cmath>

#include "core/film/film.h"

namespace kiln {

std::optional<RGBFilm::SampleResponse> RGBFilm::Respond(
    const SampledSpectrum& L, const Stokes* S, const SampledWavelengths& lambda,
    const VisibleSurface* visibleSurface) const {
    // Reject NaN/Inf radiance, and radiance so large that its sensor response overflows float
    // (a finite spectrum near 1e38 times the matching functions)
    if (!(L.IsFinite() && (!S || S->IsFinite()))) return std::nullopt;
    auto finite = [](const RGB& c) {
        return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
    };
    SampleResponse r;
    // Sensor response, clamped to maxComponentValue preserving ratios (pbrt-v4).
    r.rgb = Response(L, lambda);
    if (!finite(r.rgb)) return std::nullopt;
    Float m = std::max({r.rgb.r, r.rgb.g, r.rgb.b}), scale = 1;
    if (m > opts.maxComponentValue) scale = opts.maxComponentValue / m;
    r.rgb = r.rgb * scale;
    r.withStokes = S && !stokesPixels.empty();
    if (r.withStokes)
        for (int k = 1; k < 4; ++k) {
            r.stokes[size_t(k - 1)] = Response((*S)[k], lambda) * scale;
            if (!finite(r.stokes[size_t(k - 1)])) return std::nullopt;
        }
    if (!buckets.Empty()) {
        // Spectral radiance clamped to maxComponentValue on its own (pbrt-v4)
        Float lm = L.MaxComponentValue();
        r.L = lm > opts.maxComponentValue ? L * (opts.maxComponentValue / lm) : L;
    }
    if (!aovs.Empty() && visibleSurface && visibleSurface->set) {
        // Albedo as the colour of the reflectance under the colour space's illuminant (an
        // albedo of 1 gives RGB (1, 1, 1)).
        SampledSpectrum lit = visibleSurface->albedo * colorSpace->Illuminant().Sample(lambda);
        r.albedo = colorSpace->ToRGB(SpectrumToXYZ(lit, lambda));
    }
    return r;
}

void RGBFilm::Accumulate(size_t idx, const SampleResponse& r, const SampledWavelengths& lambda,
                         const VisibleSurface* visibleSurface, Float weight) {
    Pixel& px = pixels[idx];
    for (int c = 0; c < 3; ++c) px.rgbSum[c] += double(weight) * r.rgb[c];
    px.weightSum += weight;
    if (r.withStokes) {
        StokesPixel& sp = stokesPixels[idx];
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) sp.rgbSum[k][c] += double(weight) * r.stokes[size_t(k)][c];
    }
    if (!buckets.Empty()) buckets.Add(idx, r.L, lambda, weight);
    if (!aovs.Empty() && visibleSurface && visibleSurface->set)
        aovs.Add(idx, *visibleSurface, r.albedo, r.rgb, weight);
}

// Counts a rejected sample and remembers the first pixel that had one.
void RGBFilm::Reject(size_t idx) {
    nonFiniteCount.fetch_add(1, std::memory_order_relaxed);
    int64_t expected = -1;
    firstNonFinite.compare_exchange_strong(expected, int64_t(idx));
}

void RGBFilm::AddSample(Point2i pPixel, const SampledSpectrum& L, const Stokes* S,
                        const SampledWavelengths& lambda, const VisibleSurface* visibleSurface,
                        Float weight) {
    // Nothing of a rejected sample reaches any layer.
    size_t idx = PixelIndex(pPixel);
    if (!std::isfinite(weight)) return Reject(idx);
    std::optional<SampleResponse> r = Respond(L, S, lambda, visibleSurface);
    if (!r) return Reject(idx);
    Accumulate(idx, *r, lambda, visibleSurface, weight);
}

Vector2i RGBFilm::SpreadMargin() const {
    if (opts.reconstruction != PixelReconstruction::Spread) return Vector2i(0, 0);
    // A sample in pixel q reaches pixel p when |x - (p + 1/2)| <= r for some x in [q, q + 1],
    // i.e. |q - p| <= r - 1/2 pixels away
    Vector2f r = filter.Radius();
    return Vector2i(std::max(0, int(std::ceil(r.x - 0.5f))),
                    std::max(0, int(std::ceil(r.y - 0.5f))));
}

Bounds2i RGBFilm::SpreadPixelBounds() const {
    Vector2i m = SpreadMargin();
    const Bounds2i& b = opts.pixelBounds;
    return Bounds2i{{b.pMin.x - m.x, b.pMin.y - m.y}, {b.pMax.x + m.x, b.pMax.y + m.y}};
}

Point2i RGBFilm::SamplerResolution() const {
    Vector2i m = SpreadMargin();
    return Point2i(opts.fullResolution.x + 2 * m.x, opts.fullResolution.y + 2 * m.y);
}

void RGBFilm::SpreadSample(Point2f pFilm, const SampledSpectrum& L, const Stokes* S,
                           const SampledWavelengths& lambda, const VisibleSurface* visibleSurface) {
    const Bounds2i& b = opts.pixelBounds;
    // The pixels whose centres x + 1/2 lie within the radius of pFilm (at most 2 r + 1 per
    // axis, r <= kMaxSpreadRadius), inside the bounds
    constexpr int kMaxSide = 2 * int(kMaxSpreadRadius) + 2;
    const Vector2f r = filter.Radius();
    int x0 = std::max(b.pMin.x, int(std::ceil(pFilm.x - 0.5f - r.x)));
    int x1 = std::min({b.pMax.x, int(std::floor(pFilm.x - 0.5f + r.x)) + 1, x0 + kMaxSide});
    int y0 = std::max(b.pMin.y, int(std::ceil(pFilm.y - 0.5f - r.y)));
    int y1 = std::min({b.pMax.y, int(std::floor(pFilm.y - 0.5f + r.y)) + 1, y0 + kMaxSide});
    if (x0 >= x1 || y0 >= y1) return;
    std::optional<SampleResponse> response = Respond(L, S, lambda, visibleSurface);
    if (!response) {
        Point2i p(std::clamp(int(std::floor(pFilm.x)), b.pMin.x, b.pMax.x - 1),
                  std::clamp(int(std::floor(pFilm.y)), b.pMin.y, b.pMax.y - 1));
        return Reject(PixelIndex(p));
    }
    // Separable filters: one evaluation per column and per row
    std::array<Float, kMaxSide> wx, wy;
    for (int x = x0; x < x1; ++x) wx[size_t(x - x0)] = filter.Evaluate1D(0, pFilm.x - (x + 0.5f));
    for (int y = y0; y < y1; ++y) wy[size_t(y - y0)] = filter.Evaluate1D(1, pFilm.y - (y + 0.5f));
    for (int y = y0; y < y1; ++y) {
        if (wy[size_t(y - y0)] == 0) continue;
        for (int x = x0; x < x1; ++x) {
            Float w = wx[size_t(x - x0)] * wy[size_t(y - y0)];
            if (w != 0) Accumulate(PixelIndex({x, y}), *response, lambda, visibleSurface, w);
        }
    }
}

}  // namespace kiln
