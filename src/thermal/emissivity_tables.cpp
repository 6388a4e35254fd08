#include "thermal/emissivity_tables.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "materials/bxdfs/conductor_albedo.h"

namespace kiln {

float EmissivityTables::CosineNode(int i, int n) {
    double x = double(i) / (n - 1);
    return float(x * x * (2 - x) * 0.5 + x * 0.5);  // spacing at 0 half that at 1
}

EmissivityTables::EmissivityTables(SpectralRange range) : range(range) {
    constexpr int nCos = 64, nLambda = 95, nFine = 471, nAlpha = 48;
    std::vector<float> c, l, fine, a;
    for (int i = 0; i < nCos; ++i) c.push_back(CosineNode(i, nCos));
    // Exact steps of 5 and 1 nm over the visible range
    const double step = (double(range.max) - range.min) / (nLambda - 1);
    const double fineStep = (double(range.max) - range.min) / (nFine - 1);
    for (int i = 0; i < nLambda; ++i) l.push_back(float(range.min + step * i));
    for (int i = 0; i < nFine; ++i) fine.push_back(float(range.min + fineStep * i));
    const double logMin = std::log(1e-3), logMax = std::log(4.0);
    for (int i = 0; i < nAlpha; ++i)
        a.push_back(float(logMin + (logMax - logMin) * i / (nAlpha - 1)));
    cosines = TableAxis(std::move(c));
    wavelengths = TableAxis(std::move(l));
    fineWavelengths = TableAxis(std::move(fine));
    logAlphas = TableAxis(std::move(a));
}

EmissivityTables::~EmissivityTables() = default;

void EmissivityTables::FillConductorGrid(std::vector<float>& table,
                                         ConductorAlbedoMoments::Weights (*compute)(double,
                                                                                    double)) const {
    const int nCos = cosines.Size(), nAlpha = logAlphas.Size(), H = ConductorAlbedoMoments::kNodes;
    table.resize(size_t(nCos) * nAlpha * H);
    tbb::parallel_for(0, nCos * nAlpha, [&](int cell) {
        int ci = cell / nAlpha, ai = cell % nAlpha;
        double mu = std::max(1e-4, double(cosines.Node(ci)));
        ConductorAlbedoMoments::Weights w = compute(std::exp(double(logAlphas.Node(ai))), mu);
        for (int j = 0; j < H; ++j) table[size_t(cell) * H + j] = float(w[size_t(j)]);
    });
}

const std::vector<float>& EmissivityTables::ConductorMoments() {
    if (conductorMoments.empty())
        FillConductorGrid(conductorMoments, &ConductorAlbedoMoments::Compute);
    return conductorMoments;
}

const std::vector<float>& EmissivityTables::ConductorPolarizationMoments() {
    if (conductorPolarizationMoments.empty())
        FillConductorGrid(conductorPolarizationMoments,
                          &ConductorAlbedoMoments::ComputeLinearPolarization);
    return conductorPolarizationMoments;
}

}  // namespace kiln
