// Directional albedo of the measured material's BSDF for Kirchhoff emission (material_albedo.h):
// the quadrature of bxdfs/measured_albedo.h (4 x 4 Gauss-Legendre points per cell of the file's
// vndf grid), tabulated once per file at load over the thermal module's 64 cosines
// (EmissivityTables::Cosines; every other one, 33, for anisotropic files), the azimuth of wo
// (anisotropic files: 4 (n_phi - 1) nodes evenly over 2 pi, periodic, four per interval of the
// file's azimuths; isotropic ones: one) and the file's wavelengths. Lookups interpolate
// linearly in each; outside the file's wavelengths the end values hold, as in the BxDF.
// test/thermal/measured_emissivity_test.cpp measures the quadrature against the BxDF's own
// albedo (512 x 512 points of its sampling): 1e-5 to 1e-4; the table's interpolation: 4.5e-4
// for the isotropic test file, 2.4e-3 for an anisotropic one of 9 azimuths, whose albedo has
// cusps between them (from the interpolation of its tables between azimuths, which pbrt-v4
// shares). Building takes about 0.7 ms of one core per node for 16 x 16 tables (64 nodes for
// the isotropic test file, 1056 for 9 azimuths), on all cores.
#pragma once

#include <vector>

#include "base/object_arena.h"
#include "base/table_axis.h"
#include "materials/bxdfs/measured_bxdf.h"
#include "thermal/emissivity_tables.h"

namespace kiln {

class MeasuredMaterial;

class MeasuredEmissivity {
  public:
    struct Table {
        TableAxis cosines, wavelengths;
        int nAzimuth = 1;
        std::vector<float> values;  // [(cosine * nAzimuth + azimuth) * nWavelengths + lambda]
    };
    // The table of the material's file (built by the first material that names it).
    MeasuredEmissivity(const MeasuredMaterial& material, const EmissivityTables& tables,
                       ObjectArena& arena);
    explicit MeasuredEmissivity(const Table* table) : table(table) {}
    static Table Build(const MeasuredBxDFData& data, const TableAxis& cosines);

    // A at wo (local shading frame; mirrored when wo.z < 0, as the BxDF is)
    SampledSpectrum Albedo(Vector3f wo, const SampledWavelengths& lambda) const;
    const Table* GetTable() const { return table; }

  private:
    const Table* table;
};

}  // namespace kiln
