#include "render/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "spectral/color.h"

namespace kiln {

namespace {

// 2^ev Y_p = target for the percentile Y_p of the positive luminances Y
Float ExposureFor(std::vector<Float> Y, Float percentile, Float target) {
    if (Y.empty()) return 0;
    size_t k = std::min(Y.size() - 1, size_t(Clamp(percentile, 0, 1) * (Y.size() - 1)));
    std::nth_element(Y.begin(), Y.begin() + k, Y.end());
    return std::log2(target / Y[k]);
}

}  // namespace

Float AutoExposureEV(const Image& rgb, const RGBColorSpace& colorSpace, Float percentile,
                     Float target) {
    std::vector<Float> Y;
    for (int y = 0; y < rgb.Resolution().y; ++y)
        for (int x = 0; x < rgb.Resolution().x; ++x) {
            RGB c(rgb.GetChannel({x, y}, 0), rgb.GetChannel({x, y}, 1), rgb.GetChannel({x, y}, 2));
            Float lum = colorSpace.ToXYZ(c).Y;
            if (lum > 0 && std::isfinite(lum)) Y.push_back(lum);
        }
    return ExposureFor(std::move(Y), percentile, target);
}

Float AutoExposureEV(const RGBFilm& film, Float percentile, Float target) {
    // Luminance of every pixel with the film's current exposure, then undo that exposure
    Float current = std::exp2(film.GetOptions().exposureEV);
    std::vector<Float> Y;
    Bounds2i b = film.PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            Float lum = film.ColorSpace()->ToXYZ(film.GetPixelRGB({x, y})).Y / current;
            if (lum > 0 && std::isfinite(lum)) Y.push_back(lum);
        }
    return ExposureFor(std::move(Y), percentile, target);
}

}  // namespace kiln
