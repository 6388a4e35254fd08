// The table axes and the tables every material's emissivity shares (thermal/material_albedo.h),
// built while the scene is created and only read while rendering.
#pragma once

#include <memory>
#include <vector>

#include "base/table_axis.h"
#include "materials/bxdfs/conductor_albedo.h"
#include "spectral/spectral_range.h"

namespace kiln {

class EmissivityTables {
  public:
    // Tables over wavelength cover range (the scene's: SpectralRange).
    explicit EmissivityTables(SpectralRange range = {});
    ~EmissivityTables();
    EmissivityTables(const EmissivityTables&) = delete;
    EmissivityTables& operator=(const EmissivityTables&) = delete;

    // cos theta_o in [0, 1]: 64 nodes, spaced twice as densely at grazing as at normal
    // incidence, where albedos change fastest.
    const TableAxis& Cosines() const { return cosines; }
    // The wavelengths the tables cover.
    const SpectralRange& Range() const { return range; }
    // 95 wavelengths over the range: 360-830 nm in 5 nm steps in the visible.
    const TableAxis& Wavelengths() const { return wavelengths; }
    // 471 wavelengths over the range: 360-830 nm in 1 nm steps in the visible, for conductors,
    // whose Fresnel reflectance follows measured optical constants that change quickly with
    // wavelength (gold's albedo changes by up to 1.5e-3 between 5 nm nodes, less than 1e-4
    // between 1 nm nodes). Optical constants change more slowly in the infrared, where the
    // same number of nodes is spread over the wider band.
    const TableAxis& FineWavelengths() const { return fineWavelengths; }
    // log(alpha) for Trowbridge-Reitz alpha from 1e-3 (smooth below) to 4 (clamped above).
    const TableAxis& LogAlphas() const { return logAlphas; }

    // Fresnel-moment weights of the rough conductor (ConductorAlbedoMoments) on the cosine x
    // log-alpha grid: [(cos * LogAlphas().Size() + alpha) * kNodes + j]. Built on first use
    // (when a hot conductor has textured roughness); not thread-safe: call during scene
    // creation only.
    const std::vector<float>& ConductorMoments();
    // The same grid of ConductorAlbedoMoments::ComputeLinearPolarization weights, for polarised
    // emission of rough conductors (built on first use, as ConductorMoments).
    const std::vector<float>& ConductorPolarizationMoments();

    // Whether the scene renders polarised light: materials then also build what polarised
    // emission needs. Set before any material's emissivity is created.
    bool polarized = false;

    static float CosineNode(int i, int n);

  private:
    // Fills table with compute(alpha, cos theta) on the cosine x log-alpha grid.
    void FillConductorGrid(std::vector<float>& table,
                           ConductorAlbedoMoments::Weights (*compute)(double, double)) const;

    SpectralRange range;
    TableAxis cosines, wavelengths, fineWavelengths, logAlphas;
    std::vector<float> conductorMoments, conductorPolarizationMoments;
};

}  // namespace kiln
