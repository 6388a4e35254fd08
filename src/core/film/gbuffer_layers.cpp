#include "core/film/gbuffer_layers.h"

#include <cmath>

namespace kiln {

void GBufferLayers::Add(size_t index, const VisibleSurface& vs, const RGB& albedo,
                        const RGB& sensorRGB, Float weight) {
    Pixel& px = pixels[index];
    const double w = weight;
    Point3f p = outputFromRender(vs.p);
    Normal3f n = outputFromRender(vs.n), ns = outputFromRender(vs.ns);
    for (int c = 0; c < 3; ++c) {
        px.albedo[c] += w * albedo[c];
        px.p[c] += w * p[c];
        px.n[c] += w * n[c];
        px.ns[c] += w * ns[c];
    }
    px.dzdx += w * outputFromRender(vs.dpdx).z;
    px.dzdy += w * outputFromRender(vs.dpdy).z;
    px.uv[0] += w * vs.uv.x;
    px.uv[1] += w * vs.uv.y;
    px.weightSum += w;
    // Welford's update
    px.count += 1;
    for (int c = 0; c < 3; ++c) {
        double delta = sensorRGB[c] - px.mean[c];
        px.mean[c] += delta / px.count;
        px.m2[c] += delta * (sensorRGB[c] - px.mean[c]);
    }
}

const std::vector<std::string>& GBufferLayers::ChannelNames() {
    static const std::vector<std::string> names = {"Albedo.R",
                                                   "Albedo.G",
                                                   "Albedo.B",
                                                   "P.X",
                                                   "P.Y",
                                                   "P.Z",
                                                   "dzdx",
                                                   "dzdy",
                                                   "N.X",
                                                   "N.Y",
                                                   "N.Z",
                                                   "Ns.X",
                                                   "Ns.Y",
                                                   "Ns.Z",
                                                   "u",
                                                   "v",
                                                   "Variance.R",
                                                   "Variance.G",
                                                   "Variance.B",
                                                   "RelativeVariance.R",
                                                   "RelativeVariance.G",
                                                   "RelativeVariance.B"};
    return names;
}

void GBufferLayers::WritePixel(Image& image, Point2i xy, int first, size_t index,
                               double pixelWeightSum) const {
    const Pixel& px = pixels[index];
    const double wAll = pixelWeightSum != 0 ? 1 / pixelWeightSum : 0;
    const double wHit = px.weightSum != 0 ? 1 / px.weightSum : 0;
    int c = first;
    auto put = [&](double v) { image.SetChannel(xy, c++, Float(v)); };
    for (double a : px.albedo) put(a * wAll);
    for (double p : px.p) put(p * wHit);
    // pbrt-v4 writes the magnitudes of the averaged slopes
    put(std::abs(px.dzdx * wHit));
    put(std::abs(px.dzdy * wHit));
    // Unit normals: the direction of the weighted sum (zero where nothing was hit)
    for (const double* n : {px.n, px.ns}) {
        double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) put(len > 0 ? n[k] / len : 0);
    }
    put(px.uv[0] * wHit);
    put(px.uv[1] * wHit);
    // Sample variance (n - 1 in the denominator; 0 below two samples), and variance over mean
    // (0 where the mean is 0), as pbrt-v4's VarianceEstimator
    double variance[3];
    for (int k = 0; k < 3; ++k) variance[k] = px.count > 1 ? px.m2[k] / (px.count - 1) : 0;
    for (double v : variance) put(v);
    for (int k = 0; k < 3; ++k)
        put(px.count >= 1 && px.mean[k] != 0 ? variance[k] / px.mean[k] : 0);
}

}  // namespace kiln
