// Named spectra: pbrt-v4's names exist, and kiln's measured optical constants equal the
// reference CSVs of /work/shared/data at every tabulated wavelength.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "nk_csv.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

using namespace kiln;

namespace {

using test::NK;
const auto ReadCSV = test::ReadNkCSV;

// Every CSV row inside the visible range is reproduced to float precision (beyond the measured
// tables, the metals follow the Lorentz-Drude model: lorentz_drude_test.cpp).
void ExpectMatchesCSV(const std::string& name, const std::string& csv, bool isK) {
    SCOPED_TRACE(name);
    const Spectrum* s = GetNamedSpectrum(name);
    ASSERT_NE(s, nullptr);
    const auto* pl = s->GetIf<PiecewiseLinearSpectrum>();
    ASSERT_NE(pl, nullptr);
    std::vector<NK> rows = ReadCSV(csv);
    ASSERT_FALSE(rows.empty()) << "cannot read " << csv;
    // The stored table covers 360-830 nm (FromInterleaved may add end points at 359/831 nm)
    const double lo = pl->Lambdas().front(), hi = pl->Lambdas().back();
    EXPECT_LE(lo, 360);
    EXPECT_GE(hi, 830);
    int compared = 0;
    for (const NK& r : rows) {
        if (r.lambda < Lambda_min || r.lambda > Lambda_max) continue;
        const double expected = isK ? r.k : r.n;
        EXPECT_NEAR((*s)(Float(r.lambda)), expected, 1e-6 * std::max(1.0, expected))
            << "at " << r.lambda << " nm";
        ++compared;
    }
    EXPECT_GE(compared, 10);
}

}  // namespace

TEST(NamedSpectra, PbrtNames) {
    std::vector<std::string> names = {"glass-BK7",    "glass-BAF10",  "glass-FK51A",  "glass-LASF9",
                                      "glass-F5",     "glass-F10",    "glass-F11",    "stdillum-A",
                                      "stdillum-D50", "stdillum-D65", "illum-acesD60"};
    for (const char* m : {"Ag", "Al", "Au", "Cu", "CuZn", "MgO", "TiO2"}) {
        names.push_back(std::string("metal-") + m + "-eta");
        names.push_back(std::string("metal-") + m + "-k");
    }
    for (int i = 1; i <= 12; ++i) names.push_back("stdillum-F" + std::to_string(i));
    for (const std::string& n : names) {
        const Spectrum* s = GetNamedSpectrum(n);
        ASSERT_NE(s, nullptr) << n;
        // MgO and TiO2 are transparent: k = 0
        if (n.find("MgO-k") != std::string::npos || n.find("TiO2-k") != std::string::npos)
            EXPECT_GE((*s)(550), 0) << n;
        else
            EXPECT_GT((*s)(550), 0) << n;
    }
    EXPECT_EQ(GetNamedSpectrum("metal-Unobtainium-eta"), nullptr);
    EXPECT_EQ(NamedSpectrumNames().front(), "glass-BK7");
}

// Illuminants are normalised to the luminance of a constant 1 (pbrt-v4).
TEST(NamedSpectra, IlluminantsNormalised) {
    for (std::string_view n : NamedSpectrumNames()) {
        if (n.rfind("stdillum-", 0) != 0 && n.rfind("illum-", 0) != 0) continue;
        EXPECT_NEAR(SpectrumToXYZ(*GetNamedSpectrum(n)).Y, 1, 1e-4) << n;
    }
}

// Familiar values: BK7 n(587.6 nm) = 1.5168; pbrt-v4's gold k near 650 nm.
TEST(NamedSpectra, SpotValues) {
    EXPECT_NEAR((*GetNamedSpectrum("glass-BK7"))(587.6f), 1.5168, 2e-4);
    EXPECT_NEAR((*GetNamedSpectrum("glass-SiO2"))(587.6f), 1.4585, 2e-4);
    EXPECT_GT((*GetNamedSpectrum("metal-Au-k"))(650), 3);
}

TEST(NamedSpectra, KilnMetalsMatchReferenceData) {
    // The measured data live beside the checkout (../shared/data); a checkout without them
    // cannot run this comparison.
    if (!std::ifstream(std::string(KILN_SHARED_DIR) + "/data/nk_Pt.csv"))
        GTEST_SKIP() << "reference data " KILN_SHARED_DIR "/data not available";
    for (const char* m : {"Pt", "Ni", "Fe", "W", "Cr", "Ti", "Se"}) {
        const std::string csv = std::string("nk_") + m + ".csv";
        ExpectMatchesCSV(std::string("metal-") + m + "-eta", csv, false);
        ExpectMatchesCSV(std::string("metal-") + m + "-k", csv, true);
    }
    ExpectMatchesCSV("glass-SiO2", "nk_SiO2.csv", false);
}

// Normal-incidence reflectance R = ((n-1)^2 + k^2) / ((n+1)^2 + k^2) against the spot checks
// of /work/shared/data/README.md (3 decimals).
TEST(NamedSpectra, KilnMetalsReflectance) {
    struct Spot {
        const char* m;
        float lambda;
        double R;
    };
    const Spot spots[] = {{"Pt", 550, 0.642}, {"W", 550, 0.498},  {"Fe", 550, 0.512},
                          {"Ni", 650, 0.701}, {"Cr", 450, 0.555}, {"Ti", 650, 0.616}};
    for (const Spot& s : spots) {
        const double n = (*GetNamedSpectrum(std::string("metal-") + s.m + "-eta"))(s.lambda);
        const double k = (*GetNamedSpectrum(std::string("metal-") + s.m + "-k"))(s.lambda);
        const double R = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
        EXPECT_NEAR(R, s.R, 1.5e-3) << s.m;
    }
}
