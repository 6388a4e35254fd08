// The table axes and the tables every material's emissivity shares (materials/emissivity.h),
// built while the scene is created and only read while rendering.
#pragma once

#include <memory>
#include <vector>

#include "core/base/table_axis.h"

namespace kiln {

class EmissivityTables {
  public:
    EmissivityTables();
    ~EmissivityTables();
    EmissivityTables(const EmissivityTables&) = delete;
    EmissivityTables& operator=(const EmissivityTables&) = delete;

    // cos theta_o in [0, 1]: 64 nodes, spaced twice as densely at grazing as at normal
    // incidence, where albedos change fastest.
    const TableAxis& Cosines() const { return cosines; }
    // Wavelengths 360-830 nm in 5 nm steps.
    const TableAxis& Wavelengths() const { return wavelengths; }
    // log(alpha) for Trowbridge-Reitz alpha from 1e-3 (smooth below) to 4 (clamped above).
    const TableAxis& LogAlphas() const { return logAlphas; }

    // Fresnel-moment weights of the rough conductor (ConductorAlbedoMoments) on the cosine x
    // log-alpha grid: [(cos * LogAlphas().Size() + alpha) * kNodes + j]. Built on first use
    // (when a hot conductor has textured roughness); not thread-safe: call during scene
    // creation only.
    const std::vector<float>& ConductorMoments();

    static float CosineNode(int i, int n);

  private:
    TableAxis cosines, wavelengths, logAlphas;
    std::vector<float> conductorMoments;
};

}  // namespace kiln
