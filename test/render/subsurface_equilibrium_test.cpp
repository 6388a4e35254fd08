// Kirchhoff equilibrium of hot subsurface matter (pbrt-v4's "subsurface" through volpath):
// inside a closed isothermal cavity a subsurface sphere must render B(T). Its emissivity is
// 1 - A, A = R + (1 - R) rhoEff C the albedo of the boundary and the BSSRDF
// (thermal/material_albedo.h); on a sphere whose diameter exceeds the probe radius the BSSRDF's
// exit points integrate Sp exactly as over a plane (a spherical cap within chord d has area
// pi d^2), so the transport's albedo is A for grey coefficients and the image mean is B(T) to
// within the pixel noise (4 standard errors, plus 1e-3 as the other cavities).
#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include "render_test_util.h"

namespace kiln {
namespace {

struct SubsurfaceCase {
    const char* name;
    const char* material;
    int spp;  // for a standard error below 0.125 % (the albedos' paths are long)
    std::vector<double> temperatures;
};
// What ctest prints for a parameter (instead of its bytes)
inline void PrintTo(const SubsurfaceCase& c, std::ostream* os) { *os << c.name; }

std::string Cavity(const SubsurfaceCase& c, double T, int spp) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 500\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\n"
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
      << "Texture \"grey\" \"spectrum\" \"checkerboard\" \"float uscale\" 6 \"float vscale\" 6"
         " \"spectrum tex1\" [300 0.7 900 0.7] \"spectrum tex2\" [300 0.2 900 0.2]\n"
      << "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
      << "Shape \"sphere\" \"float radius\" 6\n"
      << "Material " << c.material << "\n"
      << "AttributeBegin Translate 0 0 0.3 Shape \"sphere\" \"float radius\" 1.2 AttributeEnd\n";
    return s.str();
}

class SubsurfaceEquilibrium : public ::testing::TestWithParam<SubsurfaceCase> {};

TEST_P(SubsurfaceEquilibrium, CavityRendersTheBlackbody) {
    const SubsurfaceCase& c = GetParam();
    for (double T : c.temperatures) {
        SCOPED_TRACE(T);
        testing::ExpectBlackbodyImage(testing::RenderText(Cavity(c, T, c.spp)), T, c.name);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cavities, SubsurfaceEquilibrium,
    ::testing::Values(
        // rhoEff from "reflectance" (textured, grey per texel), mean free path 0.02
        SubsurfaceCase{
            "reflectance_mfp",
            "\"subsurface\" \"texture reflectance\" \"grey\" \"spectrum mfp\" [300 0.02 900 0.02]",
            256,
            {1500}},
        // rhoEff from the table at sigma_s / sigma_t, forward scattering, eta 1.5
        SubsurfaceCase{
            "sigma_g_eta",
            "\"subsurface\" \"spectrum sigma_a\" [300 10 900 10] \"spectrum sigma_s\" [300 40 900 "
            "40] "
            "\"float g\" 0.5 \"float eta\" 1.5",
            32,
            {1000, 5000}}),
    [](const ::testing::TestParamInfo<SubsurfaceCase>& info) {
        return std::string(info.param.name);
    });

// Subsurface transport is volpath's: a scene with a subsurface material runs VolPathIntegrator,
// "path" renders the boundary alone (a warning, as pbrt-v4's path integrator ignores BSSRDFs)
// and "bdpt" falls back to volpath (a warning)
TEST(Subsurface, IntegratorChoice) {
    const std::string scene =
        "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "LightSource \"point\" \"point3 from\" [0 0 -2]\n"
        "Material \"subsurface\"\nShape \"sphere\"\n";
    struct Expectation {
        const char* integrator;
        bool volumetric;
        int warnings;
    };
    for (Expectation e : {Expectation{"volpath", true, 0}, Expectation{"path", false, 1},
                          Expectation{"bdpt", true, 1}}) {
        Diagnostics diag(nullptr);
        std::unique_ptr<Scene> s =
            testing::BuildScene(std::string("Integrator \"") + e.integrator + "\"\n" + scene, diag);
        EXPECT_EQ(s->features.volumetric, e.volumetric) << e.integrator;
        EXPECT_FALSE(s->features.bidirectional) << e.integrator;
        EXPECT_EQ(s->features.subsurface, 1) << e.integrator;
        EXPECT_EQ(diag.WarningCount(), e.warnings) << e.integrator;
    }
}

}  // namespace
}  // namespace kiln
