// Emissivity of the measured material (thermal/measured_emissivity.h): its per-file table of
// directional albedo against the BxDF's own albedo (the mean of f cos / pdf of Sample_f over a
// 256 x 256 grid of cell midpoints, which the luminance sampling makes nearly exact), for the
// committed isotropic test file and an anisotropic one, at wavelengths between the file's.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "../bxdfs/rgl_test_data.h"
#include "base/rng.h"
#include "materials/bxdfs/measured_albedo.h"
#include "materials/materials.h"
#include "thermal/material_albedo.h"
#include "thermal_test_util.h"

namespace kiln {
namespace {

using namespace kiln::test;

SampledSpectrum StratifiedAlbedo(const BSDF& bsdf, Vector3f wo, int n) {
    double sum[NSpectrumSamples] = {};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            auto bs = bsdf.Sample_f(wo, 0.5f, Point2f((i + 0.5f) / n, (j + 0.5f) / n));
            if (!bs || !(bs->pdf > 0)) continue;
            for (int l = 0; l < NSpectrumSamples; ++l)
                sum[l] += double(bs->f[l]) * AbsDot(bs->wi, Vector3f(0, 0, 1)) / bs->pdf;
        }
    SampledSpectrum a;
    for (int l = 0; l < NSpectrumSamples; ++l) a[l] = float(sum[l] / (double(n) * n));
    return a;
}

struct Errors {
    double table = 0;       // |table - quadrature at wo|, largest
    double quadrature = 0;  // |quadrature - BxDF's stratified albedo|, largest
};

// Over random directions (both sides) and wavelengths: the table against the quadrature at wo
// (order 8) and, at the first, the quadrature against the mean of Sample_f's weights over
// 512 x 512 points (whose own error is about 1e-4)
Errors MaxErrors(ThermalFixture& f, const Material& m, uint64_t seed) {
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(m, f.tables, f.arena);
    const MeasuredBxDFData& data = *m.GetIf<MeasuredMaterial>()->Data();
    RNG rng(seed);
    Errors e;
    for (int p = 0; p < 12; ++p) {
        Float mu = std::max(0.02f, rng.UniformFloat()) * (p % 4 == 3 ? -1 : 1);
        Float phi = 2 * Pi * rng.UniformFloat(), s = std::sqrt(1 - mu * mu);
        Vector3f wo(s * std::cos(phi), s * std::sin(phi), mu);
        // The file's wavelengths are 400, 500, 600, 700 nm
        SampledWavelengths lambda = SampledWavelengths::SampleUniform(rng.UniformFloat(), 350, 750);
        BSDF bsdf = m.GetBSDF(Context(Point2f(0.5f, 0.5f), wo), lambda);
        EXPECT_TRUE(bsdf.GetBxDF().Is<MeasuredBxDF>());
        SampledSpectrum table = albedo->Evaluate(&m, bsdf, wo, lambda);
        std::vector<double> q = MeasuredAlbedo(data, wo, 8);
        auto atLambda = [&](Float l) {
            if (l <= 400) return q[0];
            if (l >= 700) return q[3];
            int i = std::min(2, int((l - 400) / 100));
            double t = (l - 400) / 100 - i;
            return (1 - t) * q[i] + t * q[i + 1];
        };
        for (int i = 0; i < NSpectrumSamples; ++i)
            e.table = std::max(e.table, std::abs(table[i] - atLambda(lambda[i])));
        if (p == 0) {
            SampledSpectrum direct = StratifiedAlbedo(bsdf, wo, 512);
            for (int i = 0; i < NSpectrumSamples; ++i)
                e.quadrature = std::max(e.quadrature, std::abs(direct[i] - atLambda(lambda[i])));
        }
    }
    return e;
}

}  // namespace

TEST(MeasuredEmissivity, TableMatchesTheBxDF) {
    ThermalFixture f;
    const std::string committed =
        std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/measured-ggx.bsdf";
    const Material* iso = f.Make("measured", {Strings("string", "filename", {committed})});
    Errors e = MaxErrors(f, *iso, 3);
    std::printf("isotropic: table %.2e, quadrature %.2e\n", e.table, e.quadrature);
    // Measured: 4.5e-4 (table), 3e-5 (quadrature)
    EXPECT_LT(e.table, 1e-3);
    EXPECT_LT(e.quadrature, 5e-4);

    // The albedo of this coarse file (9 azimuths) has cusps between its azimuths (from the
    // interpolation of its tables), which 4 nodes per interval follow to 2.4e-3
    RGLConductor model;
    model.alphaX = 0.2f, model.alphaY = 0.5f, model.nPhi = 9, model.nTheta = 6;
    const std::string file = ::testing::TempDir() + "kiln_measured_aniso.bsdf";
    std::ofstream(file, std::ios::binary) << WriteRGLConductor(model);
    const Material* aniso = f.Make("measured", {Strings("string", "filename", {file})});
    e = MaxErrors(f, *aniso, 4);
    std::printf("anisotropic: table %.2e, quadrature %.2e\n", e.table, e.quadrature);
    EXPECT_LT(e.table, 3e-3);
    EXPECT_LT(e.quadrature, 5e-4);
    std::remove(file.c_str());

    // Materials naming one file share its table
    const Material* again = f.Make("measured", {Strings("string", "filename", {committed})});
    auto table = [&](const Material* m) {
        return MeasuredEmissivity(*m->GetIf<MeasuredMaterial>(), f.tables, f.arena).GetTable();
    };
    EXPECT_EQ(table(iso), table(again));
    EXPECT_NE(table(iso), table(aniso));
}

}  // namespace kiln
