// The geometric and statistical layers of pbrt-v4's GBufferFilm: per pixel, filter-weighted
// averages of the first visible surface's albedo, position, depth slopes, normals and (u, v), and
// the sample variance of the pixel's sensor RGB.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/transform.h"
#include "core/film/visible_surface.h"
#include "core/image/image.h"
#include "spectral/color.h"

namespace kiln {

class GBufferLayers {
  public:
    // The space P, N, Ns and the depth slopes are written in (film "coordinatesystem").
    enum class Space { Camera, World };

    // Per pixel sums, all doubles (checkpoints check them for finiteness as such).
    struct Pixel {
        double albedo[3] = {0, 0, 0};  // output-colour-space RGB of the albedo, weighted
        double p[3] = {0, 0, 0};       // position in output space, weighted
        double dzdx = 0, dzdy = 0;     // output-space z of dp/dx and dp/dy, weighted
        double n[3] = {0, 0, 0}, ns[3] = {0, 0, 0};  // normals in output space, weighted
        double uv[2] = {0, 0};                       // weighted
        double weightSum = 0;                        // of the samples with a visible surface
        // Welford's running mean and sum of squared deviations of the sensor RGB of those
        // samples (unweighted), and their count
        double count = 0, mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
    };

    GBufferLayers() = default;
    // nPixels: pixels of the film's bounds. outputFromRender: render space to the output space.
    GBufferLayers(size_t nPixels, const Transform& outputFromRender)
        : outputFromRender(outputFromRender), pixels(nPixels) {}

    bool Empty() const { return pixels.empty(); }
    std::vector<Pixel>& Pixels() { return pixels; }
    const std::vector<Pixel>& Pixels() const { return pixels; }

    // One sample with a visible surface: its albedo (output RGB), sensor RGB (after the film's
    // maxcomponentvalue scale) and filter weight.
    void Add(size_t index, const VisibleSurface& vs, const RGB& albedo, const RGB& sensorRGB,
             Float weight);

    // pbrt-v4's GBufferFilm channels after R, G, B, in its order: Albedo.R/G/B, P.X/Y/Z, dzdx,
    // dzdy, N.X/Y/Z, Ns.X/Y/Z, u, v, Variance.R/G/B, RelativeVariance.R/G/B.
    static const std::vector<std::string>& ChannelNames();
    // Writes pixel `index`'s channels to image pixel xy from channel `first` on. pixelWeightSum:
    // the filter weight of all the pixel's samples (the albedo is averaged over them, escaped
    // rays counting as black, as pbrt-v4 does; the other layers over the samples that hit).
    void WritePixel(Image& image, Point2i xy, int first, size_t index, double pixelWeightSum) const;

  private:
    Transform outputFromRender;
    std::vector<Pixel> pixels;
};

}  // namespace kiln
