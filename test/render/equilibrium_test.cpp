// Kirchhoff equilibrium, kiln's sharpest test: inside a closed cavity whose walls and contents
// are all at one temperature T, every direction must see exactly B(T), whatever the materials
// and geometry, because emission is 1 - albedo of the very BSDF that scatters. Each case puts
// one large object of the tested material (a sphere, or a low-poly triangle mesh with smooth
// per-vertex shading normals) in front of the camera inside a closed wall (a textured diffuse
// sphere, or a mesh with shading normals too), spheres at 1000 K and meshes at 5000 K; one case
// bump-maps the object, so that its shading frame departs far from the geometric one. The image
// mean must be B(T) within 4 standard errors of the pixel noise (plus 1e-3 for the tables), and the
// test renders enough samples for that to be tighter than 0.5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"
#include "spectral/cie.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

struct Case {
    const char* name;
    const char* material;
    // The samples per pixel that make the test's 4 standard errors smaller than 0.5 %
    int spp = 256;
};
// What ctest prints for a parameter (instead of its bytes)
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string Cavity(const Case& c, bool meshes, double T, int spp) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 500\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\n"
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
      << "Texture \"rough\" \"float\" \"checkerboard\" \"float uscale\" 6 \"float vscale\" 6"
         " \"float tex1\" 0.001 \"float tex2\" 0.5\n"
      << "Texture \"bumps\" \"float\" \"wrinkled\" \"integer octaves\" 4\n"
      << "MakeNamedMaterial \"gold\" \"string type\" \"conductor\" \"spectrum eta\" "
         "\"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" \"float roughness\" 0.05\n"
      << "MakeNamedMaterial \"checks\" \"string type\" \"diffuse\" \"texture reflectance\" "
         "\"checks\"\n"
      << "MakeNamedMaterial \"thin\" \"string type\" \"thindielectric\" \"float eta\" 1.33\n"
      << "NamedMaterial \"checks\"\n"
      << (meshes ? testing::MeshSphere(6, 12, 8, 0, 0, 0, true)
                 : "Shape \"sphere\" \"float radius\" 6\n")
      << "Material " << c.material << "\n"
      << (meshes ? testing::MeshSphere(1.2, 10, 6, 0, 0, 0.3, false)
                 : "AttributeBegin Translate 0 0 0.3 Shape \"sphere\" \"float radius\" 1.2 "
                   "AttributeEnd\n");
    return s.str();
}

class Equilibrium : public ::testing::TestWithParam<std::tuple<Case, bool>> {};

// Each material at 1000 K (deep red, most of the glow beyond the visible) in one geometry and
// 5000 K (visible) in the other: every material meets both temperatures and both geometries.
// Temperature acts on Planck's spectrum and the sampling by power, geometry on hits and shading
// frames, so the other two pairs (which doubled the cost) would test nothing new.
TEST_P(Equilibrium, CavityRendersTheBlackbody) {
    auto [c, meshes] = GetParam();
    const double T = meshes ? 5000 : 1000;
    testing::ExpectBlackbodyImage(testing::RenderText(Cavity(c, meshes, T, c.spp)), T,
                                  std::string(c.name) + (meshes ? ", meshes" : ", spheres"));
}

const Case kCases[] = {
    {"diffuse, textured", "\"diffuse\" \"texture reflectance\" \"checks\""},
    {"gold, roughness 0.001",
     "\"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" "
     "\"metal-Au-k\" \"float roughness\" 0.001"},
    {"copper, roughness 0.01",
     "\"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" "
     "\"metal-Cu-k\" \"float roughness\" 0.01"},
    {"silver, roughness 0.1",
     "\"conductor\" \"spectrum eta\" \"metal-Ag-eta\" \"spectrum k\" "
     "\"metal-Ag-k\" \"float roughness\" 0.1"},
    {"platinum, roughness 1",
     "\"conductor\" \"spectrum eta\" \"metal-Pt-eta\" \"spectrum k\" "
     "\"metal-Pt-k\" \"float roughness\" 1"},
    {"brushed copper, anisotropic roughness",
     "\"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" "
     "\"metal-Cu-k\" \"float uroughness\" 0.02 \"float vroughness\" 0.4"},
    {"gold, textured roughness",
     "\"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" "
     "\"metal-Au-k\" \"texture roughness\" \"rough\""},
    {"coateddiffuse, textured",
     "\"coateddiffuse\" \"texture reflectance\" \"checks\" "
     "\"texture roughness\" \"rough\""},
    {"coatedconductor",
     "\"coatedconductor\" \"float interface.roughness\" 0.05 "
     "\"float conductor.roughness\" 0.2"},
    {"gold, bump-mapped",
     "\"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" "
     "\"metal-Au-k\" \"float roughness\" 0.05 \"texture displacement\" \"bumps\""},
    {"mix gold/diffuse",
     "\"mix\" \"string materials\" [\"gold\" \"checks\"] "
     "\"float amount\" 0.4"},
    // Shadow rays cross thin sheets (thin_sheet_test.cpp); paths straight through them must
    // not count again what light sampling found
    {"thin glass sheet", "\"thindielectric\" \"float eta\" 1.5"},
    {"mix thin glass/gold",
     "\"mix\" \"string materials\" [\"thin\" \"gold\"] \"float amount\" 0.5"},
    // A diffusing sheet emits 1 - R - T from each side
    {"diffusetransmission, textured",
     "\"diffusetransmission\" \"texture reflectance\" \"checks\" \"rgb transmittance\" "
     "[0.05 0.1 0.3]"},
    // An RGL measured BRDF (its albedo tabulated per file, thermal/measured_emissivity.h)
    {"measured, RGL file", "\"measured\" \"string filename\" \"" KILN_SOURCE_DIR
                           "/test/regression/pbrt_features/measured-ggx.bsdf\""},
    // Tungsten's optical constants follow the temperature (spectral/metal_temperature.h; so do
    // gold's and silver's above): at 1000 K partly the named table's, at 5000 K the melting
    // point's; smooth, so the polarised cavity sees its polarised emission
    {"tungsten, smooth, constants at temperature",
     "\"conductor\" \"spectrum eta\" \"metal-W-eta\" \"spectrum k\" \"metal-W-k\" "
     "\"float roughness\" 0"},
    // Tungsten under a rough coat, its constants at temperature: the coated tables span
    // temperature (thermal/coated_emissivity.h)
    {"coated tungsten, constants at temperature",
     "\"coatedconductor\" \"spectrum conductor.eta\" \"metal-W-eta\" \"spectrum conductor.k\" "
     "\"metal-W-k\" \"float interface.roughness\" 0.1 \"float conductor.roughness\" 0.2"},
    // n and k measured at two temperatures (a made-up metal: measured_constants_test.cpp):
    // between them at 1000 K, the last one's at 5000 K; rough, so its emissivity tables span
    // temperature
    {"measured constants at two temperatures, rough",
     "\"conductor\" \"string nkfiles\" [\"" KILN_SOURCE_DIR
     "/test/render/data/fictional_metal_300K.csv\" \"" KILN_SOURCE_DIR
     "/test/render/data/fictional_metal_1500K.csv\"] \"float nktemperatures\" [300 1500] "
     "\"float roughness\" 0.1"},
    // A rough dielectric body, vacuum inside: pbrt-v4's single-scattering microfacets lose
    // energy from either side, which the surface emits (outwards B (1 - E), inwards
    // eta^2 B (1 - E): thermal/dielectric_emissivity.h; a body holding a hot melt rendered
    // 3-13 % dark without it at roughness 0.1-0.6). The mesh's shading normals put some
    // directions on one side of the shading surface and the other of the geometric one: see
    // SmoothShadedGlassMesh below. 512 spp: this body's glow is the noisiest of the cavities
    {"rough glass, nothing inside", "\"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.3",
     512},
};

// A coarse smooth-shaded mesh of rough glass (36 triangles, normals interpolated from the
// sphere's), so that many directions near its silhouettes lie outside the geometric surface but
// inside the shading one: the BSDF must scale a refraction there for the crossing the light
// really makes, and the surface emit on its geometric side (bsdf.h). Scaling by the shading
// frame's side, as pbrt-v4 does, this cavity rendered 1.031 of B(T) (with the finer mesh of
// the cases above and eta 1.5, 0.996). Unpolarised and polarised; and under volpath holding
// a hot scattering melt (eta 1.5, roughness 0.3: 1.0105 before).
std::string GlassMeshCavity(double T, const char* integrator, const char* glass, const char* melt) {
    std::ostringstream s;
    s << testing::CavityPreamble(T, 512, integrator)
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << testing::MeshSphere(6, 12, 8, 0, 0, 0, true);
    if (*melt)
        s << "MakeNamedMedium \"melt\" " << melt << " \"float temperature\" " << T << "\n"
          << "MediumInterface \"melt\" \"\"\n";
    s << "Material " << glass << "\n" << testing::MeshSphere(1.2, 6, 4, 0, 0, 0.3, false);
    return s.str();
}

TEST(Equilibrium, SmoothShadedGlassMesh) {
    const double T = 5000;
    const char* glass = "\"dielectric\" \"float eta\" 2.4 \"float roughness\" 0.5";
    std::string scene = GlassMeshCavity(T, "path", glass, "");
    testing::ExpectBlackbodyImage(testing::RenderText(scene), T, "coarse glass mesh");
    RenderOptions stokes;
    stokes.stokes = true;
    testing::RenderedScene r = testing::RenderText(scene, 0, stokes);
    ASSERT_TRUE(r.scene->features.polarized);
    testing::ExpectBlackbodyImage(r, T, "coarse glass mesh, polarised");
    testing::ExpectBlackbodyImage(
        testing::RenderText(GlassMeshCavity(
            T, "volpath", "\"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.3",
            "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.8 1.5 3] \"rgb sigma_s\" "
            "[0.5 0.5 0.5]")),
        T, "coarse glass mesh holding a melt, volpath");
}

// Cavities of transformed quadrics (quadrics.h): a sphere under a uniform scale, one under a
// non-uniform scale holding an ellipsoid, and a tube closed by two disks under a non-uniform
// scale. Sampling these emitters with object-space densities (pbrt-v4's) rendered them 0.966,
// 0.974 and 0.984 of B(T). And a rough glass sphere under a mirroring transform, which
// pbrt-v4's normals turn inside out (quadrics.h): 1.20 of B(T).
TEST(Equilibrium, TransformedQuadrics) {
    const double T = 5000;
    const char* cavities[] = {
        "AttributeBegin Scale 2 2 2 Shape \"sphere\" \"float radius\" 3 AttributeEnd\n"
        "AttributeBegin Translate 0 0 0.5 Scale 2 2 2 Shape \"sphere\" \"float radius\" 0.4 "
        "AttributeEnd\n",
        "AttributeBegin Scale 1.5 1 0.8 Shape \"sphere\" \"float radius\" 6 AttributeEnd\n"
        "Material \"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\" "
        "\"float roughness\" 0.2\n"
        "AttributeBegin Translate 0 0 0.5 Scale 1 0.5 2 Shape \"sphere\" \"float radius\" 0.6 "
        "AttributeEnd\n",
        "AttributeBegin Scale 1.3 0.9 1 Rotate 90 1 0 0 Translate 0 0 -5\n"
        "  Shape \"cylinder\" \"float radius\" 5 \"float zmin\" 0 \"float zmax\" 10\n"
        "  Shape \"disk\" \"float radius\" 5 AttributeEnd\n"
        "AttributeBegin Scale 1.3 0.9 1 Rotate 90 1 0 0 Translate 0 0 5 ReverseOrientation\n"
        "  Shape \"disk\" \"float radius\" 5 AttributeEnd\n"
        "Material \"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.2\n"
        "AttributeBegin Translate 0 0 0.5 Shape \"sphere\" \"float radius\" 0.8 AttributeEnd\n",
        "Shape \"sphere\" \"float radius\" 6\n"
        "Material \"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.3\n"
        "AttributeBegin Translate 0 0 0.5 Scale -1 1 1 Shape \"sphere\" \"float radius\" 0.9 "
        "AttributeEnd\n",
    };
    for (const char* cavity : cavities) {
        SCOPED_TRACE(cavity);
        std::string scene = testing::CavityPreamble(T, 256) +
                            "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n" + cavity;
        testing::ExpectBlackbodyImage(testing::RenderText(scene), T, "transformed quadrics");
    }
}

// Polarised transport: the cavity must also be unpolarised. Reflection from metals polarises
// (perpendicular to the plane of reflection) and Kirchhoff emission polarises the other way
// (thermal/material_albedo.h); only when the two cancel exactly are S1, S2 and S3 zero.
class PolarizedEquilibrium : public ::testing::TestWithParam<std::tuple<Case, bool>> {};

TEST_P(PolarizedEquilibrium, CavityIsUnpolarisedBlackbody) {
    auto [c, meshes] = GetParam();
    const double T = 1000, B = testing::BlackbodyLuminance(T);
    RenderOptions overrides;
    overrides.stokes = true;
    testing::RenderedScene r = testing::RenderText(Cavity(c, meshes, T, 256), 0, overrides);
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    ASSERT_TRUE(r.scene->features.polarized);
    // Per pixel: S0, then S1 and S2 re-expressed about the image's radial direction from the
    // centre (where the object's emission and reflection polarisations point: a mean over the
    // image of S1 or S2 alone would cancel), and S3
    RunningStats s[4];
    Bounds2i b = r.scene->job->film->PixelBounds();
    const RGBColorSpace* cs = r.scene->job->film->ColorSpace();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            double S[4];
            for (int k = 0; k < 4; ++k)
                S[k] = cs->ToXYZ(r.scene->job->film->GetPixelStokes({x, y}, k)).Y / B;
            // Image up is -y in raster space
            double phi = std::atan2(-(y + 0.5 - (b.pMin.y + b.pMax.y) / 2.0),
                                    x + 0.5 - (b.pMin.x + b.pMax.x) / 2.0);
            s[0].Add(S[0]);
            s[1].Add(S[1] * std::cos(2 * phi) + S[2] * std::sin(2 * phi));
            s[2].Add(-S[1] * std::sin(2 * phi) + S[2] * std::cos(2 * phi));
            s[3].Add(S[3]);
        }
    std::printf(
        "%-28s %-7s: S0 %.5f (se %.5f), radial %+.5f (%.5f), diagonal %+.5f (%.5f), S3 "
        "%+.5f (%.5f)\n",
        c.name, meshes ? "meshes" : "spheres", s[0].Mean(), s[0].StandardError(), s[1].Mean(),
        s[1].StandardError(), s[2].Mean(), s[2].StandardError(), s[3].Mean(), s[3].StandardError());
    EXPECT_NEAR(s[0].Mean(), 1, 4 * s[0].StandardError() + 1e-3);
    for (int k = 1; k < 4; ++k) {
        EXPECT_LT(4 * s[k].StandardError(), 0.005);  // the test can see 0.5 % polarisation
        EXPECT_NEAR(s[k].Mean(), 0, 4 * s[k].StandardError() + 1e-3) << "component " << k;
    }
}

INSTANTIATE_TEST_SUITE_P(Cavities, Equilibrium,
                         ::testing::Combine(::testing::ValuesIn(kCases), ::testing::Bool()),
                         testing::CavityCaseName<Case>);

// Each case in one geometry, spheres and meshes by turns (the unpolarised cases above render
// every material in both)
INSTANTIATE_TEST_SUITE_P(Cavities, PolarizedEquilibrium,
                         ::testing::ValuesIn(testing::AlternatingGeometry<Case>(
                             {kCases[0], kCases[1], kCases[2], kCases[3], kCases[4], kCases[5],
                              kCases[6], kCases[8], kCases[9], kCases[11], kCases[12], kCases[15],
                              kCases[16]})),
                         testing::CavityCaseName<Case>);

}  // namespace
}  // namespace kiln
