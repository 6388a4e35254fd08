// Named metals' optical constants at temperature (spectral/metal_temperature.h): the named
// tables at room temperature, the load-time table against direct evaluation, tungsten against
// measurements of hot tungsten, gold and silver against their measured change.
#include "spectral/metal_temperature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "nk_csv.h"
#include "spectral/named_spectra.h"
#include "spectral/spectrum.h"

namespace kiln {
namespace {

constexpr double kC2 = 1.438776877e7;  // second radiation constant, nm K

double HotNormalEmissivity(std::complex<double> eps) {
    std::complex<double> n = std::sqrt(eps);
    return 4 * n.real() / ((n.real() + 1) * (n.real() + 1) + n.imag() * n.imag());
}

// eps of the named table at lambda
std::complex<double> NamedEps(std::string_view symbol, double lambda) {
    std::string p = "metal-" + std::string(symbol);
    std::complex<double> n((*GetNamedSpectrum(p + "-eta"))(Float(lambda)),
                           (*GetNamedSpectrum(p + "-k"))(Float(lambda)));
    return n * n;
}

std::complex<double> HotModelEps(std::string_view symbol, double lambda, double T) {
    return MetalPermittivityAt(symbol, lambda, T, NamedEps(symbol, lambda));
}

// The table's n + i k at one wavelength
std::complex<double> Tabulated(const MetalTemperatureTable& table, double lambda, double T) {
    SampledWavelengths l = SampledWavelengths::FromWavelength(Float(lambda));
    SampledSpectrum eta, k;
    table.Evaluate(l, Float(T), &eta, &k);
    return {eta[0], k[0]};
}

// Wien's radiance temperature of a surface of emissivity e at T (a narrow-band pyrometer)
double RadianceTemperature(double e, double lambda, double T) {
    return 1 / (1 / T - lambda / kC2 * std::log(e));
}

const char* const kMetals[] = {"W", "Au", "Ag"};

TEST(MetalTemperature, WithoutATemperatureTheConstantsAreTheNamedTables) {
    for (const char* m : kMetals) {
        const MetalTemperatureTable* table = MetalTemperatureTable::Find(m);
        ASSERT_TRUE(table) << m;
        std::string p = "metal-" + std::string(m);
        for (double T : {0.0, 250.0, double(table->RoomTemperature())})
            for (double lambda : {310.0, 450.5, 653.0, 999.0, 4321.0, 15000.0}) {
                std::complex<double> nk = Tabulated(*table, lambda, T);
                EXPECT_EQ(nk.real(), (*GetNamedSpectrum(p + "-eta"))(Float(lambda))) << m;
                EXPECT_EQ(nk.imag(), (*GetNamedSpectrum(p + "-k"))(Float(lambda))) << m;
            }
    }
    EXPECT_FALSE(MetalTemperatureTable::Find("Cu"));
    EXPECT_FALSE(HasMetalTemperatureModel("Fe"));
}

// The load-time table (1 % in wavelength, 25 K) against direct evaluation of the model at
// random wavelengths (300 nm - 20 um, uniform in log) and temperatures. Tungsten's model is
// smooth (1.2e-3); gold's and silver's direct evaluation follows the measurements' scatter from
// point to point (3.2 nm apart), which the table smooths (up to 0.8 % in emissivity, in the
// visible).
TEST(MetalTemperature, TableMatchesTheModel) {
    std::mt19937 rng(26);
    for (const char* m : kMetals) {
        const MetalTemperatureTable& table = *MetalTemperatureTable::Find(m);
        const double room = table.RoomTemperature(), top = std::string(m) == "W" ? 3695 : 1234;
        double worst = 0;
        for (int i = 0; i < 300; ++i) {
            double lambda =
                300 * std::pow(20000 / 300.0, std::uniform_real_distribution(0.0, 1.0)(rng));
            double T = std::uniform_real_distribution(room, top)(rng);
            double e = HotNormalEmissivity(HotModelEps(m, lambda, T));
            std::complex<double> nk = Tabulated(table, lambda, T);
            double t = HotNormalEmissivity(nk * nk);
            worst = std::max(worst, std::abs(t - e) / e);
        }
        std::printf("%s: largest relative error of the tabulated normal emissivity %.2e\n", m,
                    worst);
        EXPECT_LT(worst, std::string(m) == "W" ? 0.003 : 0.012) << m;
    }
}

// Tungsten hot: Larrabee's fit of his measurements (J. Opt. Soc. Am. 49, 619 (1959)), which the
// model's two temperature coefficients were fitted to (gen/hot_tungsten_fit.py), over his range
TEST(MetalTemperature, HotTungstenFollowsLarrabeesMeasurements) {
    double sum = 0, worst = 0;
    int n = 0;
    for (double lambda = 310; lambda <= 800; lambda += 10)
        for (double T = 1600; T <= 2800; T += 100) {
            double l = lambda / 1000;
            double larrabee = 0.4655 + 0.01558 * l + 0.2675e-4 * T - 0.7305e-4 * l * T;
            double d = HotNormalEmissivity(HotModelEps("W", lambda, T)) - larrabee;
            sum += d * d, ++n;
            worst = std::max(worst, std::abs(d));
        }
    double rms = std::sqrt(sum / n);
    std::printf("tungsten against Larrabee 1959: RMS %.4f, largest %.4f\n", rms, worst);
    EXPECT_LT(rms, 0.008);
    EXPECT_LT(worst, 0.03);
}

// The validation issue 26 asks for: tungsten at its melting point, 3695 K, has a radiance
// temperature of 3208 +- 10 K at 653 nm (Cezairliyan and Miiller, Int. J. Thermophys. 3, 89
// (1982)), a measurement the model was not fitted to. Room-temperature constants read 3307 K.
TEST(MetalTemperature, TungstenAtItsMeltingPointHasTheMeasuredRadianceTemperature) {
    double e = HotNormalEmissivity(HotModelEps("W", 653, 3695));
    double Tr = RadianceTemperature(e, 653, 3695);
    double room = RadianceTemperature(HotNormalEmissivity(NamedEps("W", 653)), 653, 3695);
    std::printf(
        "tungsten at 3695 K, 653 nm: emissivity %.4f, radiance temperature %.1f K "
        "(room-temperature constants: %.1f K)\n",
        e, Tr, room);
    EXPECT_NEAR(Tr, 3208, 15);
    EXPECT_GT(room - 3208, 50);  // what the temperature model corrects
}

// De Vos (Physica 20, 690 (1954)) found tungsten's emissivity independent of temperature near
// 1.27 um (its "X-point"): falling with temperature below, rising above
TEST(MetalTemperature, TungstenHasAnXPointInTheNearInfrared) {
    auto e = [](double lambda, double T) {
        return HotNormalEmissivity(HotModelEps("W", lambda, T));
    };
    EXPECT_LT(e(653, 2800), e(653, 1600) - 0.02);
    EXPECT_GT(e(3000, 2800), e(3000, 1600) + 0.02);
    EXPECT_NEAR(e(1270, 2800) / e(1270, 1600), 1, 0.03);
}

// Gold and silver: the change of permittivity from room temperature is the measured one
// (../shared/data's full tables; kiln embeds every second row) below the blend into the
// Drude model (the last 15 % of the measured wavelengths)
TEST(MetalTemperature, GoldAndSilverChangeAsMeasured) {
    struct Metal {
        const char* symbol;
        std::vector<int> temperatures;
    };
    for (const Metal& m : {Metal{"Au", {298, 498, 623}}, Metal{"Ag", {298, 404, 501, 600}}}) {
        std::vector<test::NK> room = test::ReadNkCSV("nk_" + std::string(m.symbol) + "_298K.csv");
        if (room.empty()) GTEST_SKIP() << "reference data " KILN_SHARED_DIR "/data not available";
        const MetalTemperatureTable& table = *MetalTemperatureTable::Find(m.symbol);
        for (size_t t = 1; t < m.temperatures.size(); ++t) {
            const int T = m.temperatures[t];
            std::vector<test::NK> hot =
                test::ReadNkCSV("nk_" + std::string(m.symbol) + "_" + std::to_string(T) + "K.csv");
            ASSERT_EQ(hot.size(), room.size());
            double worst = 0, sumError = 0, sumChange = 0;
            for (size_t r = 0; r < room.size(); ++r) {
                double lambda = room[r].lambda;
                if (lambda < 300 || lambda > 800) continue;
                std::complex<double> n0(room[r].n, room[r].k), n1(hot[r].n, hot[r].k);
                std::complex<double> measured = n1 * n1 - n0 * n0;
                std::complex<double> nk = Tabulated(table, lambda, T);
                std::complex<double> kiln = nk * nk - NamedEps(m.symbol, lambda);
                worst = std::max(worst, std::abs(kiln - measured));
                sumError += std::norm(kiln - measured), sumChange += std::norm(measured);
            }
            // The measurements' point-to-point scatter (kiln's table keeps every second point,
            // 1 % apart in wavelength) bounds the largest error from below
            double relative = std::sqrt(sumError / sumChange);
            std::printf(
                "%s at %d K, 300-800 nm: permittivity change's RMS error %.1f %% of its "
                "RMS, largest error %.3f\n",
                m.symbol, T, 100 * relative, worst);
            EXPECT_LT(relative, 0.1) << m.symbol << " " << T;
            EXPECT_LT(worst, 0.12) << m.symbol << " " << T;
        }
    }
}

// Beyond the measurements: the free-electron damping grows with temperature, so the infrared
// emissivity rises with it; no step where the measured change goes over into the Drude model's
// (833-958 nm for gold, whose emissivity is smooth there)
TEST(MetalTemperature, GoldAndSilverInfraredEmissivityRisesSmoothly) {
    for (const char* m : {"Au", "Ag"}) {
        double previous = 0;
        for (double T : {298.0, 400.0, 600.0, 900.0, 1200.0}) {
            double e = HotNormalEmissivity(HotModelEps(m, 10000, T));
            EXPECT_GT(e, previous) << m << " " << T;
            previous = e;
        }
        const MetalTemperatureTable& table = *MetalTemperatureTable::Find(m);
        for (double T : {500.0, 1000.0}) {
            double last = 0;
            for (double lambda = 800; lambda < 1400; lambda *= 1.005) {
                std::complex<double> nk = Tabulated(table, lambda, T);
                double e = HotNormalEmissivity(nk * nk);
                if (last > 0) {
                    EXPECT_NEAR(e / last, 1, 0.02) << m << " at " << lambda << " nm, " << T << " K";
                }
                last = e;
            }
        }
    }
}

}  // namespace
}  // namespace kiln
