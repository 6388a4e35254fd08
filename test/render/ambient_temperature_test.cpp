// Option "float ambienttemperature": all matter without a temperature of its own is at the
// ambient temperature. A closed cavity that names no temperature at all, whose walls and
// contents (a rough metal, a bump-mapped coated diffuse, thin glass, and glass filled with an
// absorbing, scattering medium) take the ambient one, renders B(T_ambient) in every direction,
// as the cavities of equilibrium_test.cpp and volume_equilibrium_test.cpp do with explicit
// temperatures. What has a temperature of its own keeps it (0 K: cold); shapes that cannot glow
// stay cold without the warnings an explicit temperature gives; bad values are located errors.
#include <gtest/gtest.h>

#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// The cavity: a textured diffuse wall around three objects, none with a temperature; extra is
// written after WorldBegin (e.g. an object with a temperature of its own).
std::string AmbientCavity(const std::string& option, int spp, const std::string& extra = "") {
    std::ostringstream s;
    s << option << "\n"
      << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"volpath\" \"integer maxdepth\" 500\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
      << "WorldBegin\n"
      << "MakeNamedMedium \"melt\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 0.5 2] "
         "\"rgb sigma_s\" [0.5 1 0.5]\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
      << "Texture \"bumps\" \"float\" \"wrinkled\" \"integer octaves\" 4\n"
      << "AttributeBegin Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
      << "Shape \"sphere\" \"float radius\" 6 AttributeEnd\n"
      << "AttributeBegin Translate -0.8 0.5 0.5 Material \"conductor\" \"spectrum eta\" "
         "\"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\" \"float roughness\" 0.2\n"
      << "Shape \"sphere\" \"float radius\" 0.6 AttributeEnd\n"
      << "AttributeBegin Translate 0.8 0.5 0.5 Material \"coateddiffuse\" \"rgb reflectance\" "
         "[0.7 0.3 0.2] \"float roughness\" 0.05 \"texture displacement\" \"bumps\"\n"
      << "Shape \"sphere\" \"float radius\" 0.6 AttributeEnd\n"
      << "AttributeBegin Translate 0 -0.6 0.5 Material \"dielectric\" \"float eta\" 1.5\n"
      << "MediumInterface \"melt\" \"\" Shape \"sphere\" \"float radius\" 0.6 AttributeEnd\n"
      << "AttributeBegin Translate 0 0 2.5 Material \"thindielectric\" \"float eta\" 1.5\n"
      << "Shape \"sphere\" \"float radius\" 0.7 AttributeEnd\n"
      << extra;
    return s.str();
}

TEST(AmbientTemperature, AClosedCavityWithoutTemperaturesRendersTheBlackbody) {
    for (double T : {1000.0, 3000.0}) {
        SCOPED_TRACE(T);
        std::string option = "Option \"float ambienttemperature\" " + std::to_string(T);
        testing::RenderedScene r = testing::RenderText(AmbientCavity(option, 512));
        EXPECT_GT(r.scene->lights.size(), 0u);  // the wall and the opaque objects are lights
        testing::ExpectBlackbodyImage(r, T, "ambient cavity");
    }
}

// An open scene: objects at the ambient temperature under a sky (an infinite light) at the
// same temperature. The sky is the enclosure: every direction sees B(T).
TEST(AmbientTemperature, ObjectsUnderASkyAtTheirTemperatureVanishIntoIt) {
    const double T = 1200;
    std::ostringstream s;
    s << "Option \"float ambienttemperature\" " << T << "\n"
      << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 256\n"
      << "Integrator \"path\" \"integer maxdepth\" 100\n"
      << "LookAt 0 1 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
      << "WorldBegin\n"
      << "LightSource \"infinite\" \"float temperature\" " << T << "\n"
      << "AttributeBegin Material \"diffuse\" \"rgb reflectance\" [0.8 0.5 0.2]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-3 -0.6 -3 3 -0.6 -3 -3 -0.6 3 3 -0.6 3] "
         "AttributeEnd\n"
      << "AttributeBegin Translate -0.6 0 0 Material \"conductor\" \"spectrum eta\" "
         "\"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" \"float roughness\" 0.1\n"
      << "Shape \"sphere\" \"float radius\" 0.5 AttributeEnd\n"
      << "AttributeBegin Translate 0.6 0 0 Material \"conductor\" \"spectrum eta\" "
         "\"metal-Ag-eta\" \"spectrum k\" \"metal-Ag-k\" \"float roughness\" 0\n"
      << "Shape \"sphere\" \"float radius\" 0.5 AttributeEnd\n";
    testing::ExpectBlackbodyImage(testing::RenderText(s.str()), T, "objects under a sky");
}

// The sky alone: B(T) in absolute units, times "scale"
TEST(AmbientTemperature, ASkyAtATemperatureIsBlackbodyRadiance) {
    for (double scale : {1.0, 0.25}) {
        std::ostringstream s;
        // Too few pixels for blocks (testing::BlockStats): each pixel its own samples
        s << "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4 "
             "\"string reconstruction\" \"importance\"\n"
          << "Sampler \"zsobol\" \"integer pixelsamples\" 64\n"
          << "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
          << "LightSource \"infinite\" \"float temperature\" 2500 \"float scale\" " << scale
          << "\n";
        testing::RenderedScene r = testing::RenderText(s.str());
        for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
        double B = testing::BlackbodyLuminance(2500);
        // Pixels differ only by the film's wavelength samples: within 4 standard errors
        RunningStats y;
        for (int py = 0; py < 4; ++py)
            for (int px = 0; px < 4; ++px) y.Add(testing::PixelY(*r.scene, {px, py}) / B);
        EXPECT_NEAR(y.Mean(), scale, 4 * y.StandardError() + 1e-4 * scale);
        EXPECT_LT(y.StandardError(), 0.01 * scale);
    }
    for (std::string bad :
         {"\"float temperature\" -1", "\"float temperature\" 300 \"rgb L\" [1 1 1]",
          "\"float temperature\" 1e20", "\"float temperature\" 300 \"float scale\" -1"}) {
        SCOPED_TRACE(bad);
        Diagnostics diag(nullptr);
        EXPECT_THROW(
            testing::BuildScene("WorldBegin\nLightSource \"infinite\" " + bad + "\n", diag),
            SceneError);
    }
}

TEST(AmbientTemperature, WithoutTheOptionNothingGlows) {
    testing::RenderedScene r = testing::RenderText(AmbientCavity("", 4));
    EXPECT_TRUE(r.scene->lights.empty());
    Bounds2i b = r.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) EXPECT_EQ(testing::PixelY(*r.scene, {x, y}), 0);
    r = testing::RenderText(AmbientCavity("Option \"float ambienttemperature\" 0", 4));
    EXPECT_TRUE(r.scene->lights.empty());
}

TEST(AmbientTemperature, OwnTemperaturesWin) {
    const double T = 1500, B = testing::BlackbodyLuminance(T);
    std::string option = "Option \"float ambienttemperature\" 1500";
    // A black sphere filling the middle of the view, at 0 K (cold) or at 3000 K
    auto centre = [&](const std::string& temperature) {
        testing::RenderedScene r = testing::RenderText(AmbientCavity(
            option, 16,
            "AttributeBegin Translate 0 0 -1.5 Material \"diffuse\" \"rgb reflectance\" [0 0 0] "
            "\"float temperature\" " +
                temperature + " Shape \"sphere\" \"float radius\" 0.5 AttributeEnd\n"));
        return testing::PixelY(*r.scene, {12, 12}) / B;
    };
    EXPECT_LT(centre("0"), 1e-3);
    double hot = testing::BlackbodyLuminance(3000) / B;
    EXPECT_NEAR(centre("3000"), hot, 0.02 * hot);
}

TEST(AmbientTemperature, ShapesThatCannotGlowStayColdWithoutWarnings) {
    std::string text = AmbientCavity(
        "Option \"float ambienttemperature\" 800", 1,
        "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Shape \"sphere\" \"float radius\" 0.1 AttributeEnd\n"
        "AttributeBegin Material \"interface\" Shape \"sphere\" \"float radius\" 5 AttributeEnd\n"
        "AttributeBegin Material \"hair\" Shape \"curve\" \"point3 P\" [0 0 0 0 0.1 0 0 0.2 0 0 "
        "0.3 0] \"float width\" 0.01 AttributeEnd\n");
    testing::RenderedScene r = testing::RenderText(text);
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
}

TEST(AmbientTemperature, MediaWithEmissionOfTheirOwnKeepIt) {
    // "Le" and an ambient temperature would be two emissions, which a medium may not have
    std::string text =
        "Option \"float ambienttemperature\" 900\n"
        "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "Sampler \"independent\" \"integer pixelsamples\" 1\nLookAt 0 0 -3 0 0 0 0 1 0\n"
        "Camera \"perspective\"\nWorldBegin\n"
        "MakeNamedMedium \"glow\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1 1] "
        "\"rgb sigma_s\" [0 0 0] \"rgb Le\" [1 1 1]\n"
        "MakeNamedMedium \"warm\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1 1] "
        "\"rgb sigma_s\" [0 0 0] \"float temperature\" 2000\n"
        "AttributeBegin Material \"interface\" MediumInterface \"glow\" \"\"\n"
        "Shape \"sphere\" \"float radius\" 1 AttributeEnd\n"
        "AttributeBegin Translate 0 0 3 Material \"interface\" MediumInterface \"warm\" \"\"\n"
        "Shape \"sphere\" \"float radius\" 1 AttributeEnd\n";
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(text, diag);
    ASSERT_EQ(scene->media.size(), 2u);
    EXPECT_EQ(scene->media[0].EmissionTemperature(), std::nullopt);  // Le, not thermal
    EXPECT_EQ(scene->media[1].EmissionTemperature(), std::optional<Float>(2000));
}

TEST(AmbientTemperature, BadValuesAreLocatedErrors) {
    for (std::string value : {"-5", "\"warm\"", "1e30", "nan"}) {
        SCOPED_TRACE(value);
        Diagnostics diag(nullptr);
        try {
            testing::BuildScene("WorldBegin\nOption \"float ambienttemperature\" " + value + "\n",
                                diag);
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.Loc().line, 2);
            EXPECT_NE(std::string(e.what()).find("ambienttemperature"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace kiln
