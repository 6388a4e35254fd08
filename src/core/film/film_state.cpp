// RGBFilm's checkpoint state (SaveState, LoadState): the pixel sums of every layer, as bytes.
#include <cmath>
#include <cstring>

#include "core/film/film.h"

namespace kiln {

// Checkpoint state
namespace {
constexpr char kStateMagic[8] = {'k', 'f', 'i', 'l', 'm', 0, 0, 4};

template <typename T>
void AppendRaw(std::string& out, const T* data, size_t count) {
    if (count > 0) out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}
}  // namespace

std::string RGBFilm::SaveState() const {
    std::string out(kStateMagic, sizeof(kStateMagic));
    const int64_t header[10] = {opts.pixelBounds.pMin.x,        opts.pixelBounds.pMin.y,
                                opts.pixelBounds.pMax.x,        opts.pixelBounds.pMax.y,
                                int64_t(pixels.size()),         int64_t(aovs.Pixels().size()),
                                int64_t(stokesPixels.size()),   int64_t(splats.size()),
                                int64_t(buckets.Sums().size()), int64_t(buckets.SplatCount())};
    AppendRaw(out, header, 10);
    AppendRaw(out, pixels.data(), pixels.size());
    AppendRaw(out, aovs.Pixels().data(), aovs.Pixels().size());
    AppendRaw(out, stokesPixels.data(), stokesPixels.size());
    std::vector<double> splatValues(splats.size());
    for (size_t i = 0; i < splats.size(); ++i) splatValues[i] = splats[i].load();
    AppendRaw(out, splatValues.data(), splatValues.size());
    AppendRaw(out, buckets.Sums().data(), buckets.Sums().size());
    std::vector<double> bucketSplats = buckets.SplatValues();
    AppendRaw(out, bucketSplats.data(), bucketSplats.size());
    const int64_t counters[2] = {nonFiniteCount.load(), firstNonFinite.load()};
    AppendRaw(out, counters, 2);
    return out;
}

bool RGBFilm::LoadState(std::string_view state) {
    const int64_t expect[10] = {opts.pixelBounds.pMin.x,        opts.pixelBounds.pMin.y,
                                opts.pixelBounds.pMax.x,        opts.pixelBounds.pMax.y,
                                int64_t(pixels.size()),         int64_t(aovs.Pixels().size()),
                                int64_t(stokesPixels.size()),   int64_t(splats.size()),
                                int64_t(buckets.Sums().size()), int64_t(buckets.SplatCount())};
    const size_t bucketValues = buckets.Sums().size() + buckets.SplatCount();
    size_t size = sizeof(kStateMagic) + sizeof(expect) + pixels.size() * sizeof(Pixel) +
                  aovs.Pixels().size() * sizeof(GBufferLayers::Pixel) +
                  stokesPixels.size() * sizeof(StokesPixel) + splats.size() * sizeof(double) +
                  bucketValues * sizeof(double) + 2 * sizeof(int64_t);
    if (state.size() != size || std::memcmp(state.data(), kStateMagic, sizeof(kStateMagic)) != 0 ||
        std::memcmp(state.data() + sizeof(kStateMagic), expect, sizeof(expect)) != 0)
        return false;
    const char* p = state.data() + sizeof(kStateMagic) + sizeof(expect);
    // The layers are sums of doubles, each finite as kiln adds only finite values (the film
    // rejects the others): a state with anything else is damaged and is not resumed
    static_assert(sizeof(Pixel) % sizeof(double) == 0 &&
                  sizeof(GBufferLayers::Pixel) % sizeof(double) == 0 &&
                  sizeof(StokesPixel) % sizeof(double) == 0);
    size_t sums =
        (pixels.size() * sizeof(Pixel) + aovs.Pixels().size() * sizeof(GBufferLayers::Pixel) +
         stokesPixels.size() * sizeof(StokesPixel)) /
            sizeof(double) +
        splats.size() + bucketValues;
    for (size_t i = 0; i < sums; ++i) {
        double v;
        std::memcpy(&v, p + i * sizeof(double), sizeof(double));
        if (!std::isfinite(v)) return false;
    }
    int64_t stored[2];
    std::memcpy(stored, p + sums * sizeof(double), sizeof(stored));
    if (stored[0] < 0 || stored[1] < -1 || stored[1] >= int64_t(pixels.size())) return false;
    auto take = [&](void* to, size_t bytes) {
        if (bytes == 0) return;  // an empty layer's data() may be null
        std::memcpy(to, p, bytes);
        p += bytes;
    };
    take(pixels.data(), pixels.size() * sizeof(Pixel));
    take(aovs.Pixels().data(), aovs.Pixels().size() * sizeof(GBufferLayers::Pixel));
    take(stokesPixels.data(), stokesPixels.size() * sizeof(StokesPixel));
    for (std::atomic<double>& s : splats) {
        double v;
        take(&v, sizeof(v));
        s.store(v);
    }
    take(buckets.Sums().data(), buckets.Sums().size() * sizeof(double));
    std::vector<double> bucketSplats(buckets.SplatCount());
    take(bucketSplats.data(), bucketSplats.size() * sizeof(double));
    buckets.SetSplatValues(bucketSplats);
    int64_t counters[2];
    take(counters, sizeof(counters));
    nonFiniteCount = counters[0];
    firstNonFinite = counters[1];
    return true;
}

}  // namespace kiln
