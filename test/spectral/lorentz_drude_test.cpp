// The Lorentz-Drude optical constants of Rakic et al. (1998) and the named metals they extend
// into the infrared: the model as refractiveindex.info tabulates it, continuity where the
// measured tables end, the visible tables untouched, and aluminium's infrared emissivity against
// an independent fit (Rakic 1995).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "nk_csv.h"
#include "spectral/lorentz_drude.h"
#include "spectral/named_spectra.h"
#include "spectral/named_spectra_data.h"
#include "spectral/spectrum.h"

namespace kiln {
namespace {

using Row = test::NK;
const auto ReadNk = test::ReadNkCSV;

double NormalEmissivity(std::complex<double> nk) { return 1 - std::norm((nk - 1.0) / (nk + 1.0)); }

std::complex<double> Named(const std::string& metal, double lambda) {
    return {(*GetNamedSpectrum("metal-" + metal + "-eta"))(Float(lambda)),
            (*GetNamedSpectrum("metal-" + metal + "-k"))(Float(lambda))};
}

// refractiveindex.info's tabulation of the same model (4 significant figures), 248 nm - 12.4 um
TEST(LorentzDrude, ReproducesTheTabulatedModel) {
    for (const char* metal : {"W", "Pt"}) {
        std::vector<Row> rows = ReadNk(std::string("alt/nk_") + metal + "_RakicLD1998.csv");
        if (rows.empty()) GTEST_SKIP() << "reference data " KILN_SHARED_DIR "/data not available";
        for (const Row& r : rows) {
            std::complex<double> nk = *LorentzDrudeIndex(metal, r.lambda);
            ASSERT_NEAR(nk.real(), r.n, 1e-3 * r.n + 1e-3) << metal << " at " << r.lambda;
            ASSERT_NEAR(nk.imag(), r.k, 1e-3 * r.k + 1e-3) << metal << " at " << r.lambda;
        }
    }
    EXPECT_FALSE(LorentzDrudeIndex("Fe", 1000));
}

// The named metals cover 300 nm - 20 um: the visible values are the tables', the far infrared
// the model's, and no step where the tables end (neighbouring nodes differ by less than 10 %)
TEST(LorentzDrude, NamedMetalsReachTwentyMicrometresWithoutSteps) {
    for (const char* metal : {"Ag", "Au", "Cu", "Al", "Cr", "Ni", "Pt", "Ti", "W"}) {
        SCOPED_TRACE(metal);
        for (const char* part : {"-eta", "-k"}) {
            const std::string name = std::string("metal-") + metal + part;
            const auto* pl = GetNamedSpectrum(name)->GetIf<PiecewiseLinearSpectrum>();
            ASSERT_NE(pl, nullptr);
            EXPECT_LE(pl->Lambdas().front(), 300);
            EXPECT_GE(pl->Lambdas().back(), 20000);
            // The table it was built from: its nodes are kept, and from its last one on the
            // values move by less than 10 % (plus 0.02) from node to node
            const NamedSpectrumTable* table = nullptr;
            for (auto tables : {PbrtNamedSpectrumTables(), MeasuredNamedSpectrumTables()})
                for (const NamedSpectrumTable& t : tables)
                    if (name == t.name) table = &t;
            ASSERT_NE(table, nullptr);
            for (size_t i = 0; i + 1 < table->interleaved.size(); i += 2)
                EXPECT_FLOAT_EQ((*pl)(table->interleaved[i]), table->interleaved[i + 1]);
            const Float end = table->interleaved[table->interleaved.size() - 2];
            std::span<const Float> l = pl->Lambdas(), v = pl->Values();
            for (size_t i = 1; i < l.size(); ++i)
                if (l[i - 1] >= end) {
                    ASSERT_LT(std::abs(v[i] - v[i - 1]), 0.1 * std::max(v[i], v[i - 1]) + 0.02)
                        << name << " at " << l[i] << " nm";
                }
        }
        // Far beyond the tables: the model
        std::complex<double> model = *LorentzDrudeIndex(metal, 10000);
        std::complex<double> named = Named(metal, 10000);
        EXPECT_NEAR(named.real(), model.real(), 1e-3 * model.real());
        EXPECT_NEAR(named.imag(), model.imag(), 1e-3 * model.imag());
    }
}

// Iron, which the Lorentz-Drude fits lack, continues with Ordal et al.'s (1988) measured
// constants (infrared_metal_data.h) beyond its table: without steps, and far beyond it their
// values (polished iron's normal emissivity at 10 um about 0.034, where holding the table's
// near-infrared end, n 2.92 + 3.79i at 984 nm, gave 0.39)
TEST(LorentzDrude, IronContinuesWithMeasuredInfraredConstants) {
    for (const char* part : {"-eta", "-k"}) {
        const auto* pl =
            GetNamedSpectrum(std::string("metal-Fe") + part)->GetIf<PiecewiseLinearSpectrum>();
        ASSERT_NE(pl, nullptr);
        EXPECT_GE(pl->Lambdas().back(), 20000);
        std::span<const Float> l = pl->Lambdas(), v = pl->Values();
        for (size_t i = 1; i < l.size(); ++i)
            if (l[i - 1] >= 900) {
                ASSERT_LT(std::abs(v[i] - v[i - 1]), 0.1 * std::max(v[i], v[i - 1]) + 0.02)
                    << part << " at " << l[i] << " nm";
            }
    }
    for (auto [lambda, n, k] :
         {std::tuple{2000.0, 3.8476, 6.7152}, std::tuple{10000.0, 7.0687, 27.902},
          std::tuple{20000.0, 13.131, 53.124}}) {
        std::complex<double> named = Named("Fe", lambda);
        EXPECT_NEAR(named.real(), n, 5e-3 * n) << lambda;
        EXPECT_NEAR(named.imag(), k, 5e-3 * k) << lambda;
    }
    EXPECT_NEAR(NormalEmissivity(Named("Fe", 10000)), 0.0335, 0.001);
}

// pbrt-v4's brass and magnesia (metal-CuZn, metal-MgO) continue with their materials'
// measured constants (infrared_metal_data.h: Querry's brass, of which pbrt-v4's table is a part,
// and Synowicki and Tiwald's crystalline MgO) from 300 nm to 20 um: without a step where the
// tables end, the sources' values far beyond them, polished brass a poor emitter in the thermal
// infrared, magnesia clear to about 6 um and a strong reflector in its reststrahlen band
TEST(LorentzDrude, BrassAndMagnesiaContinueWithMeasuredInfraredConstants) {
    for (const char* metal : {"CuZn", "MgO"})
        for (const char* part : {"-eta", "-k"}) {
            const std::string name = std::string("metal-") + metal + part;
            const auto* pl = GetNamedSpectrum(name)->GetIf<PiecewiseLinearSpectrum>();
            ASSERT_NE(pl, nullptr);
            EXPECT_LE(pl->Lambdas().front(), 300) << name;
            EXPECT_GE(pl->Lambdas().back(), 20000) << name;
            // Where the table ends (850 and 768 nm) and the measurements take over
            std::span<const Float> l = pl->Lambdas(), v = pl->Values();
            for (size_t i = 1; i < l.size(); ++i)
                if (l[i - 1] >= 700 && l[i] <= 1500) {
                    ASSERT_LT(std::abs(v[i] - v[i - 1]), 0.1 * std::max(v[i], v[i - 1]) + 0.02)
                        << name << " at " << l[i] << " nm";
                }
        }
    for (auto [metal, lambda, n, k] :
         {std::tuple{"CuZn", 10204.0, 17.276, 52.438}, std::tuple{"CuZn", 4291.8, 5.646, 26.322},
          std::tuple{"MgO", 15384.0, 0.13611, 1.0228}, std::tuple{"MgO", 3430.2, 1.681, 0.0}}) {
        // (the named spectrum resamples the measurements at 2.7 % steps in wavelength, which
        // round the peak of n at 15.4 um by 2 %)
        std::complex<double> named = Named(metal, lambda);
        EXPECT_NEAR(named.real(), n, 3e-2 * n) << metal << " " << lambda;
        EXPECT_NEAR(named.imag(), k, 3e-2 * k + 1e-3) << metal << " " << lambda;
    }
    const double brass = NormalEmissivity(Named("CuZn", 10000));
    std::printf("polished brass: normal emissivity %.4f at 10 um\n", brass);
    EXPECT_GT(brass, 0.01);
    EXPECT_LT(brass, 0.05);
    for (double lambda : {1000.0, 3000.0, 6000.0}) EXPECT_LT(Named("MgO", lambda).imag(), 1e-3);
    for (double lambda : {15000.0, 18000.0, 20000.0})
        EXPECT_GT(1 - NormalEmissivity(Named("MgO", lambda)), 0.5) << lambda;
}

// Aluminium's normal emissivity from 2 to 20 um against Rakic (1995)'s fit to other
// measurements (nk_Al.csv, tabulated to 200 um): within 12 %
TEST(LorentzDrude, AluminiumInfraredEmissivityAgreesWithAnIndependentFit) {
    std::vector<Row> rows = ReadNk("nk_Al.csv");
    if (rows.empty()) GTEST_SKIP() << "reference data " KILN_SHARED_DIR "/data not available";
    int compared = 0;
    for (const Row& r : rows) {
        if (r.lambda < 2000 || r.lambda > 20000) continue;
        double kiln = NormalEmissivity(Named("Al", r.lambda));
        double reference = NormalEmissivity({r.n, r.k});
        EXPECT_NEAR(kiln / reference, 1, 0.12) << "at " << r.lambda << " nm";
        ++compared;
    }
    EXPECT_GE(compared, 3);
}

}  // namespace
}  // namespace kiln
