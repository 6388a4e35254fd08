// A thermal sensor's spectral response (core/film/sensor_response.h): its Planck integral
// against fine direct sums and a flat band's closed form, the inversion to temperature, the
// sensor's parameters, errors and metadata.
#include "core/film/sensor_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/film/thermal_sensor.h"
#include "core/parser/parameter_dictionary.h"
#include "film_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// A triangular response peaking at 10 um (a filtered microbolometer), 0 at 7 and 13 um
SensorResponse Triangle() {
    std::vector<float> l = {7000, 10000, 13000}, v = {0, 1, 0};
    return SensorResponse(l, v);
}

// integral R B by the midpoint rule in steps of `step` nm
double DirectSum(const SensorResponse& r, double T, double step = 0.1) {
    double sum = 0;
    for (double l = r.Support().min + step / 2; l < r.Support().max; l += step)
        sum += r(float(l)) * planck_radiance(l, T) * step;
    return sum;
}

TEST(SensorResponse, PlanckIntegralMatchesDirectSumsAndAFlatBand) {
    SensorResponse tri = Triangle();
    EXPECT_EQ(tri.Support().min, 7000);
    EXPECT_EQ(tri.Support().max, 13000);
    EXPECT_NEAR(tri.Integral(7000, 13000), 3000, 1e-6);
    EXPECT_NEAR(tri.Integral(7000, 8500), 375, 1e-6);
    for (double T : {200.0, 300.0, 1000.0, 3000.0})
        EXPECT_NEAR(tri.BandRadiance(T) / DirectSum(tri, T), 1, 1e-5) << T;
    // A flat response equals Planck's band radiance in closed form
    std::vector<float> l = {8000, 14000}, v = {1, 1};
    SensorResponse flat(l, v);
    for (double T : {250.0, 300.0, 500.0, 2000.0})
        EXPECT_NEAR(flat.BandRadiance(T) / planck_band_radiance(8000, 14000, T), 1, 1e-5) << T;
    // Narrow at 650 nm, and cold (B about 1e-240 at 40 K, falling 2.3x per nm): the sum in
    // logarithms keeps it; the exponent's curvature over a 1.3 nm step costs 3.4e-4 in L, which
    // is 6e-7 in the temperature it reports (d ln L / d ln T = 553 there)
    std::vector<float> nl = {645, 650, 655}, nv = {0, 1, 0};
    SensorResponse narrow(nl, nv);
    EXPECT_GT(narrow.BandRadiance(40), 0);
    EXPECT_NEAR(narrow.BandRadiance(40) / DirectSum(narrow, 40, 0.001), 1, 1e-3);
    EXPECT_NEAR(narrow.BandRadiance(2000) / DirectSum(narrow, 2000), 1, 1e-5);
}

TEST(SensorResponse, TemperatureInvertsThePlanckIntegral) {
    SensorResponse tri = Triangle();
    std::vector<float> nl = {645, 650, 655}, nv = {0, 1, 0};
    SensorResponse narrow(nl, nv);
    double worst = 0;
    for (const SensorResponse* r : {&tri, &narrow})
        for (double T = 2; T < 9e5; T *= 1.137) {
            double L = r->BandRadiance(T);
            if (!(L > 1e-300)) continue;  // below what a double holds
            double back = r->Temperature(L);
            worst = std::max(worst, std::abs(back / T - 1));
        }
    std::printf("largest relative error of the inverted temperature: %.2e\n", worst);
    EXPECT_LT(worst, 2e-5);
    EXPECT_EQ(tri.Temperature(0), 0);
    EXPECT_EQ(tri.Temperature(-1), 0);
    EXPECT_EQ(tri.Temperature(NAN), 0);
}

TEST(SensorResponse, BadTablesAreRefused) {
    auto refuse = [](std::vector<float> l, std::vector<float> v, const char* what) {
        try {
            SensorResponse r(l, v);
            ADD_FAILURE() << "accepted: " << what;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    refuse({500}, {1}, "two");
    refuse({500, 400}, {1, 1}, "increase");
    refuse({500, 600}, {1, -1}, ">= 0");
    refuse({500, 600}, {0, 0}, "0 everywhere");
    refuse({200, 600}, {1, 1}, "300 nm - 20 um");
    refuse({500, 600}, {1, NAN}, "finite");
}

ThermalSensor SensorFrom(ParsedParameterVector params) {
    ParameterDictionary dict(std::move(params), nullptr);
    return ThermalSensor::Create(dict, FileLoc());
}

TEST(SensorResponse, TheSensorMeasuresAndReportsThroughItsResponse) {
    ThermalSensor s = SensorFrom(
        {Param("string", "sensor", {}, {}, {"response"}),
         Param("spectrum", "response", {6000, 0, 7000, 0, 10000, 1, 13000, 0}),
         Param("float", "emissivity", {0.8f}), Param("float", "reflectedtemperature", {290})});
    ASSERT_TRUE(s.Response());
    EXPECT_EQ(s.Band().min, 7000);  // from the last zero before the response rises
    EXPECT_EQ(s.Band().max, 13000);
    // A surface of emissivity 0.8 at 400 K among matter at 290 K reads 400 K
    SensorResponse tri = Triangle();
    double L = 0.8 * tri.BandRadiance(400) + 0.2 * tri.BandRadiance(290);
    EXPECT_NEAR(s.ApparentTemperature(L), 400, 0.01);
    // A path sample: R L / pdf averaged over its wavelengths
    SampledWavelengths lambda = SampledWavelengths::SampleUniform(0.3f, 7000, 13000);
    SampledSpectrum Lsample(2.f);
    double expected = 0;
    for (int i = 0; i < NSpectrumSamples; ++i)
        expected += tri(lambda[i]) * 2 / lambda.PDF()[i] / NSpectrumSamples;
    EXPECT_NEAR(s.InBandRadiance(Lsample, lambda), expected, 1e-6 * expected);
    // The metadata carries the response: a merge reports the same temperature
    std::optional<ThermalSensor> back = ThermalSensor::FromSettings(s.Settings());
    ASSERT_TRUE(back);
    ASSERT_TRUE(back->Response());
    EXPECT_EQ(back->ApparentTemperature(L), s.ApparentTemperature(L));
    EXPECT_FALSE(ThermalSensor::FromSettings("7000 13000 1 0 response 7000 0 10000"));
    EXPECT_FALSE(ThermalSensor::FromSettings("7000 13000 1 0 response 7000 0 10000 -1"));
    EXPECT_FALSE(ThermalSensor::FromSettings("7000 13000 1 0 other"));
}

}  // namespace
}  // namespace kiln
