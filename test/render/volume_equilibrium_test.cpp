// Kirchhoff equilibrium with participating media: a closed cavity at temperature T containing
// a glass body filled with a hot medium (absorbing, scattering, thin, graded, dispersive), or
// itself filled with hot scattering air, must render exactly B(T) in every direction. Inside
// glass of index n the equilibrium radiance is n^2 B and the medium emits sigma_a n^2 B; the
// Fresnel boundary passes (1 - R) of it out, scaled by 1 / n^2, and reflects R of the wall's
// B: B either way. Walls and bodies as in equilibrium_test.cpp (spheres, or low-poly meshes
// with smooth shading normals). The image mean must be B(T) within 4 standard errors of the
// pixel noise (plus 1e-3), and the test renders enough samples for that to be tighter than
// 0.5 %.
#include <gtest/gtest.h>

#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"

namespace kiln {
namespace {

struct VolumeCase {
    const char* name;
    const char* glass;   // the body's material ("" for no body)
    const char* inside;  // the medium in the body, without its temperature
    const char* air;     // the medium filling the cavity ("" for none)
    int spp;             // enough for a standard error below 0.125 %
};
// What ctest prints for a parameter (instead of its bytes)
inline void PrintTo(const VolumeCase& c, std::ostream* os) { *os << c.name; }

std::string Cavity(const VolumeCase& c, bool meshes, double T, int spp) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 500\n";
    if (*c.air) s << "MediumInterface \"\" \"air\"\n";  // the camera's medium
    s << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\n";
    if (*c.air) s << "MakeNamedMedium \"air\" " << c.air << " \"float temperature\" " << T << "\n";
    if (*c.inside)
        s << "MakeNamedMedium \"melt\" " << c.inside << " \"float temperature\" " << T << "\n";
    // The wall: the cavity is inside the sphere primitive, outside the inward-facing mesh
    s << "AttributeBegin\n"
      << (*c.air ? (meshes ? "MediumInterface \"\" \"air\"\n" : "MediumInterface \"air\" \"\"\n")
                 : "")
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
      << "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
      << (meshes ? testing::MeshSphere(6, 12, 8, 0, 0, 0, true)
                 : "Shape \"sphere\" \"float radius\" 6\n")
      << "AttributeEnd\n";
    if (*c.glass) {
        // Absorbing glass without a melt: its own medium (from k) glows at the body's
        // temperature. A rough surface emits what it loses at the body's temperature, and
        // without one of its own at its melt's (scene_emitters.h)
        std::string glass(c.glass);
        if (!*c.inside && (glass.find(" k\"") != std::string::npos ||
                           glass.find("roughness") != std::string::npos))
            s << "AttributeBegin\nAttribute \"shape\" \"float temperature\" " << T << "\n";
        else
            s << "AttributeBegin\n";
        s << "Material " << c.glass << "\n"
          << "MediumInterface \"" << (*c.inside ? "melt" : "") << "\" \"" << (*c.air ? "air" : "")
          << "\"\n"
          << (meshes ? testing::MeshSphere(1.2, 10, 6, 0, 0, 0.3, false)
                     : "Translate 0 0 0.3 Shape \"sphere\" \"float radius\" 1.2\n")
          << "AttributeEnd\n";
    }
    return s.str();
}

class VolumeEquilibrium : public ::testing::TestWithParam<std::tuple<VolumeCase, bool>> {};

TEST_P(VolumeEquilibrium, CavityRendersTheBlackbody) {
    auto [c, meshes] = GetParam();
    // One temperature (the equilibrium holds wavelength by wavelength; the dispersive case sees
    // the spectrum's shape)
    const double T = 1300;
    testing::RenderedScene r = testing::RenderText(Cavity(c, meshes, T, c.spp));
    ASSERT_TRUE(r.scene->features.volumetric);
    ASSERT_GE(r.scene->features.thermalMedia, 1);
    testing::ExpectBlackbodyImage(r, T, std::string(c.name) + (meshes ? ", meshes" : ", spheres"));
}

const VolumeCase kVolumeCases[] = {
    {"glass, absorbing melt", "\"dielectric\" \"float eta\" 1.5",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1.5 2] \"rgb sigma_s\" [0 0 0]", "", 256},
    {"glass, scattering melt", "\"dielectric\" \"float eta\" 1.5",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.3 0.2 0.1] \"rgb sigma_s\" [2 1 3] "
     "\"float g\" 0.5",
     "", 1024},
    {"glass, thin melt", "\"dielectric\" \"float eta\" 1.7",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.05 0.05 0.05] \"rgb sigma_s\" [0 0 0]", "",
     512},
    {"glass, graded melt", "\"dielectric\" \"float eta\" 1.5",
     "\"string type\" \"uniformgrid\" \"float density\" [0 4 1 2 3 0.5 2 1] \"integer nx\" 2 "
     "\"integer ny\" 2 \"integer nz\" 2 \"point3 p0\" [-1.2 -1.2 -0.9] \"point3 p1\" [1.2 1.2 "
     "1.5] \"rgb sigma_a\" [0.5 0.5 0.5] \"rgb sigma_s\" [1 1 1]",
     "", 1024},
    {"dispersive glass", "\"dielectric\" \"spectrum eta\" \"glass-BAF10\"",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 0.8 0.4] \"rgb sigma_s\" [0.5 0.5 "
     "0.5]",
     "", 1024},
    {"hot air, glass, melt", "\"dielectric\" \"float eta\" 1.5",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1 1] \"rgb sigma_s\" [1 1 1]",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.05 0.1 0.02] \"rgb sigma_s\" [0.2 0.1 "
     "0.3] \"float g\" -0.4",
     1024},
    // Shadow rays cross thin sheets: from the hot gas out to the wall, and from the hot air in
    {"thin glass bulb, hot gas", "\"thindielectric\" \"float eta\" 1.5",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 0.4 0.3] \"rgb sigma_s\" [0.5 1 0.5]",
     "", 512},
    {"hot air, thin glass bulb", "\"thindielectric\" \"float eta\" 1.5", "",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.05 0.1 0.02] \"rgb sigma_s\" [0.2 0.1 "
     "0.3]",
     512},
    // Rough glass: the surface emits what its single-scattering microfacets lose, outwards and
    // into the body (thermal/dielectric_emissivity.h)
    {"rough glass, absorbing melt", "\"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.3",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1.5 2] \"rgb sigma_s\" [0 0 0]", "", 512},
    {"rough dispersive glass, absorbing melt",
     "\"dielectric\" \"spectrum eta\" \"glass-BAF10\" \"float roughness\" 0.1",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 0.8 0.4] \"rgb sigma_s\" [0 0 0]", "",
     1024},
    // Absorbing glass (complex index): the body's medium absorbs 4 pi k / lambda (0.46 per unit
    // at 550 nm: partly transparent), and dispersive soda-lime glass (about 3 per unit: nearly
    // opaque)
    {"absorbing glass, constant k", "\"dielectric\" \"float eta\" 1.5 \"float k\" 2e-8", "", "",
     256},
    {"soda-lime glass",
     "\"dielectric\" \"spectrum eta\" \"glass-soda-lime-eta\" \"spectrum k\" "
     "\"glass-soda-lime-k\"",
     "", "", 1024},
    {"hot air only", "", "",
     "\"string type\" \"homogeneous\" \"rgb sigma_a\" [0.2 0.2 0.2] \"rgb sigma_s\" [0.3 0.3 "
     "0.3]",
     1024},
    // Graded, chromatic hot air filling the cavity: tracking meets null collisions, where
    // absorption weighs the path (Integrator "weightabsorption"), and light sampling from the
    // air (the wall) is weighed against it
    {"hot graded air", "\"dielectric\" \"float eta\" 1.5", "",
     "\"string type\" \"uniformgrid\" \"float density\" [0.2 1 0.5 0.1 0.8 0.3 1 0.6] "
     "\"integer nx\" 2 \"integer ny\" 2 \"integer nz\" 2 \"point3 p0\" [-6 -6 -6] \"point3 "
     "p1\" [6 6 6] \"rgb sigma_a\" [0.3 0.15 0.05] \"rgb sigma_s\" [0.1 0.2 0.3]",
     1024},
};

// Each case in one geometry, spheres and meshes by turns: every case, and meshes and spheres each
// in about half of them
INSTANTIATE_TEST_SUITE_P(Cavities, VolumeEquilibrium,
                         ::testing::ValuesIn(testing::AlternatingGeometry<VolumeCase>(
                             {std::begin(kVolumeCases), std::end(kVolumeCases)})),
                         testing::CavityCaseName<VolumeCase>);

}  // namespace
}  // namespace kiln
