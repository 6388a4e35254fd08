#include "render/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "spectral/color.h"

namespace kiln {

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
    if (Y.empty()) return 0;
    size_t k = std::min(Y.size() - 1, size_t(Clamp(percentile, 0, 1) * (Y.size() - 1)));
    std::nth_element(Y.begin(), Y.begin() + k, Y.end());
    return std::log2(target / Y[k]);
}

}  // namespace kiln
