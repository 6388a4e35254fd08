// Optical constants measured at several temperatures: reading n, k files (spectral/nk_file.h)
// and the table over wavelength and temperature made from them (MetalTemperatureTable::
// FromMeasurements): each measurement's own values at its temperature, the permittivity linear
// in T between two, the ends held.
#include "spectral/nk_file.h"

#include <gtest/gtest.h>

#include <complex>
#include <stdexcept>
#include <string>

#include "../temp_dir.h"
#include "spectral/metal_temperature.h"

namespace kiln {
namespace {

std::string ErrorOf(const std::string& file) {
    try {
        ReadNkFile(file);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(NkFile, ReadsHeadersCommentsCommasAndSpaces) {
    test::TempDir dir;
    dir.Write("a.csv",
              "wavelength_nm,n,k\n# comment\n400,0.5,2.5\r\n\n500 , 0.6 ,3\n600\t0.7\t3.5\n");
    NkTable t = ReadNkFile((dir.path / "a.csv").string());
    ASSERT_EQ(t.lambdas.size(), 3u);
    EXPECT_EQ(t.lambdas[1], 500);
    EXPECT_FLOAT_EQ(t.n[2], 0.7f);
    EXPECT_FLOAT_EQ(t.k[0], 2.5f);
}

TEST(NkFile, MalformedFilesAreErrorsAtTheLine) {
    test::TempDir dir;
    auto error = [&](const std::string& text) {
        dir.Write("b.csv", text);
        return ErrorOf((dir.path / "b.csv").string());
    };
    EXPECT_NE(error("400 1 2\n300 1 2\n").find("b.csv:2: wavelengths must increase"),
              std::string::npos);
    EXPECT_NE(error("400 1 2\n500 1 -2\n").find(":2: n and k must be finite"), std::string::npos);
    EXPECT_NE(error("400 1 2\n500 1\n").find(":2: expected three numbers"), std::string::npos);
    EXPECT_NE(error("400 1 2\n500 1 x\n").find(":2: expected three numbers"), std::string::npos);
    EXPECT_NE(error("lambda n k\n400 1 2\n").find("at least two rows"), std::string::npos);
    EXPECT_NE(error("0 1 2\n500 1 2\n").find(":1: the wavelength must be a positive number"),
              std::string::npos);
    EXPECT_NE(ErrorOf((dir.path / "missing.csv").string()).find("missing.csv"), std::string::npos);
}

// Two measurements with n and k linear in wavelength between rows
TEST(NkFile, TableFollowsThePermittivityBetweenMeasurements) {
    NkTable cold{{300, 600, 20000}, {1.2f, 0.8f, 12}, {2.0f, 3.5f, 60}};
    NkTable hot{{300, 600, 20000}, {1.4f, 1.1f, 18}, {1.9f, 3.0f, 50}};
    MetalTemperatureTable table =
        MetalTemperatureTable::FromMeasurements({{300, cold}, {1500, hot}});
    EXPECT_EQ(table.RoomTemperature(), 300);
    EXPECT_EQ(table.Temperatures().Node(table.Temperatures().Size() - 1), 1500);
    auto at = [&](Float T, Float lambda) {
        SampledWavelengths l = SampledWavelengths::FromWavelength(lambda);
        SampledSpectrum eta, k;
        table.Evaluate(l, T, &eta, &k);
        return std::complex<double>(eta[0], k[0]);
    };
    auto nk = [](const NkTable& t, int row) { return std::complex<double>(t.n[row], t.k[row]); };
    for (int row : {0, 1}) {
        Float lambda = cold.lambdas[size_t(row)];
        // At and below the first measurement: it; at and above the last: it
        for (Float T : {0.f, 200.f, 300.f})
            EXPECT_LT(std::abs(at(T, lambda) - nk(cold, row)), 1e-4);
        for (Float T : {1500.f, 2500.f}) EXPECT_LT(std::abs(at(T, lambda) - nk(hot, row)), 1e-3);
        // Halfway: the root of the mean permittivity
        std::complex<double> mid =
            std::sqrt(0.5 * (nk(cold, row) * nk(cold, row) + nk(hot, row) * nk(hot, row)));
        EXPECT_LT(std::abs(at(900, lambda) - mid), 2e-3 * std::abs(mid)) << lambda;
    }
    // Between rows and beyond the ends (held)
    std::complex<double> n450 = at(300, 450), expected(1.0, 2.75);
    EXPECT_LT(std::abs(n450 - expected), 1e-4);
    EXPECT_LT(std::abs(at(300, 20000) - nk(cold, 2)), 1e-3 * 60);
}

}  // namespace
}  // namespace kiln
