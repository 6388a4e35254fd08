#include "thermal/measured_emissivity.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "materials/bxdfs/measured_albedo.h"
#include "materials/measured_material.h"

namespace kiln {

MeasuredEmissivity::MeasuredEmissivity(const MeasuredMaterial& material,
                                       const EmissivityTables& tables, ObjectArena& arena)
    : table(arena.Shared<Table>(material.Filename(),
                                [&] { return Build(*material.Data(), tables.Cosines()); })) {}

MeasuredEmissivity::Table MeasuredEmissivity::Build(const MeasuredBxDFData& data,
                                                    const TableAxis& cosines) {
    Table t;
    // Anisotropic files: every other cosine (their azimuths multiply the cost)
    if (data.isotropic) {
        t.cosines = cosines;
    } else {
        std::vector<float> nodes;
        for (int i = 0; i < cosines.Size(); i += 2) nodes.push_back(cosines.Node(i));
        if (nodes.back() != cosines.Nodes().back()) nodes.push_back(cosines.Nodes().back());
        t.cosines = TableAxis(std::move(nodes));
    }
    t.wavelengths = TableAxis(data.wavelengths);
    t.nAzimuth = data.isotropic ? 1 : 4 * (data.azimuths - 1);
    const int nCos = t.cosines.Size(), nl = t.wavelengths.Size();
    t.values.resize(size_t(nCos) * t.nAzimuth * nl);
    tbb::parallel_for(0, nCos * t.nAzimuth, [&](int cell) {
        const double mu = std::max(1e-4, double(t.cosines.Node(cell / t.nAzimuth)));
        const double phi = 2 * Pi * (cell % t.nAzimuth) / t.nAzimuth;
        const double s = std::sqrt(1 - mu * mu);
        const Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
        std::vector<double> a = MeasuredAlbedo(data, wo);
        for (int l = 0; l < nl; ++l) t.values[size_t(cell) * nl + l] = float(a[l]);
    });
    return t;
}

SampledSpectrum MeasuredEmissivity::Albedo(Vector3f wo, const SampledWavelengths& lambda) const {
    if (wo.z < 0) wo = -wo;
    const std::pair<int, float> cosine = table->cosines.Locate(wo.z);
    const int ci = cosine.first;
    const float ct = cosine.second;
    const int cn = table->cosines.Next(ci), na = table->nAzimuth, nl = table->wavelengths.Size();
    // Azimuth nodes at 2 pi k / na, periodic
    int a0 = 0, a1 = 0;
    float at = 0;
    if (na > 1) {
        double x = std::atan2(double(wo.y), double(wo.x)) / (2 * Pi) * na;
        x -= na * std::floor(x / na);
        a0 = std::min(int(x), na - 1);
        at = float(x - a0);
        a1 = (a0 + 1) % na;
    }
    auto value = [&](int l) {
        auto v = [&](int c, int a) { return table->values[(size_t(c) * na + a) * nl + l]; };
        return (1 - ct) * ((1 - at) * v(ci, a0) + at * v(ci, a1)) +
               ct * ((1 - at) * v(cn, a0) + at * v(cn, a1));
    };
    SampledSpectrum albedo;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        const auto [li, lt] = table->wavelengths.Locate(lambda[i]);
        albedo[i] = (1 - lt) * value(li) + lt * value(table->wavelengths.Next(li));
    }
    return albedo;
}

}  // namespace kiln
