// ParameterDictionary: typed lookups, defaults, precedence, unused reporting and spectra.

#include "core/parser/parameter_dictionary.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/parser/parser.h"
#include "recording_target.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

namespace kiln {

namespace {

ParsedParameterVector ParamsOf(const std::string& params, const std::string& searchDir = "") {
    RecordingTarget target;
    Diagnostics diag(nullptr);
    ParseString(target, "Shape \"x\" " + params, diag, "p.pbrt", searchDir);
    return target.calls.at(0).params;
}

ParameterDictionary Dict(const std::string& params, const std::string& searchDir = "") {
    return ParameterDictionary(ParamsOf(params, searchDir), nullptr);
}

}  // namespace

TEST(ParameterDictionary, SingleValuesAndDefaults) {
    ParameterDictionary d = Dict(
        "\"float f\" 2.5 \"integer i\" 7 \"bool b\" true \"string s\" \"hi\" \"point2 p2\" [1 2] "
        "\"vector2 v2\" [3 4] \"point p3\" [1 2 3] \"vector v3\" [4 5 6] \"normal n\" [0 0 1] "
        "\"texture t\" \"checks\"");
    EXPECT_EQ(d.GetOneFloat("f", 0), 2.5f);
    EXPECT_EQ(d.GetOneInt("i", 0), 7);
    EXPECT_TRUE(d.GetOneBool("b", false));
    EXPECT_EQ(d.GetOneString("s", ""), "hi");
    EXPECT_EQ(d.GetOnePoint2f("p2", {}), Point2f(1, 2));
    EXPECT_EQ(d.GetOneVector2f("v2", {}), Vector2f(3, 4));
    EXPECT_EQ(d.GetOnePoint3f("p3", {}), Point3f(1, 2, 3));
    EXPECT_EQ(d.GetOneVector3f("v3", {}), Vector3f(4, 5, 6));
    EXPECT_EQ(d.GetOneNormal3f("n", {}), Normal3f(0, 0, 1));
    EXPECT_EQ(d.GetTexture("t"), "checks");
    EXPECT_EQ(d.GetTexture("missing"), "");
    // Defaults for absent names.
    EXPECT_EQ(d.GetOneFloat("nope", -1), -1);
    EXPECT_EQ(d.GetOneString("nope", "def"), "def");
    EXPECT_EQ(d.GetOnePoint3f("nope", Point3f(9, 9, 9)), Point3f(9, 9, 9));
    EXPECT_TRUE(d.Has("f"));
    EXPECT_FALSE(d.Has("nope"));
    EXPECT_EQ(d.TypeOf("p3"), "point3");
    EXPECT_EQ(d.TypeOf("nope"), "");
    EXPECT_EQ(d.Loc("i").ToString(), "p.pbrt:1:25");
    EXPECT_EQ(d.ColorSpace(), &RGBColorSpace::sRGB());
    Diagnostics diag(nullptr);
    d.ReportUnused(diag);
    EXPECT_EQ(diag.WarningCount(), 0);
}

TEST(ParameterDictionary, TypeMustMatch) {
    ParameterDictionary d = Dict("\"integer nsamples\" 3 \"float radius\" 1");
    // GetOneFloat does not see an integer parameter, nor GetOneInt a float one.
    EXPECT_EQ(d.GetOneFloat("nsamples", -1), -1);
    EXPECT_EQ(d.GetOneInt("radius", -2), -2);
    EXPECT_TRUE(d.GetFloatArray("nsamples").empty());
    Diagnostics diag(nullptr);
    d.ReportUnused(diag);
    std::vector<Diagnostics::Warning> w = diag.Warnings();
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(FormatDiagnostic(w[0].loc, "warning", w[0].message),
              "p.pbrt:1:32: warning: unused parameter 'float radius'");
    EXPECT_EQ(w[1].message, "unused parameter 'integer nsamples'");
}

// A name neither kiln nor pbrt-v4 reads anywhere is a misspelling: an error at the parameter
// with the nearest name (pbrt-v4 stops at every unused parameter); a known name unused here
// stays a warning
TEST(ParameterDictionary, AnUnknownUnusedNameIsAnErrorWithASuggestion) {
    ParameterDictionary d = Dict("\"float radius\" 1 \"float temprature\" 1400");
    d.GetOneFloat("radius", 0);
    Diagnostics diag(nullptr);
    try {
        d.ReportUnused(diag);
        FAIL() << "an unknown parameter was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "p.pbrt:1:28: error: unknown parameter 'float temprature'; did you mean "
                  "\"temperature\"? (at 'temprature')");
    }
    // Far from every name: no suggestion
    ParameterDictionary far = Dict("\"float zzqqxx\" 1");
    try {
        far.ReportUnused(diag);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
    }
    // Looked up, or marked as allowed to be unused: nothing
    ParameterDictionary used = Dict("\"float temprature\" 1400");
    used.GetOneFloat("temprature", 0);
    EXPECT_NO_THROW(used.ReportUnused(diag));
}

TEST(ParameterDictionary, MoreThanOneValueIsAnError) {
    ParameterDictionary d = Dict("\"float r\" [1 2] \"point3 p\" [1 2 3 4 5 6] \"float e\" []");
    try {
        d.GetOneFloat("r", 0);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "p.pbrt:1:11: error: more than one value provided for parameter 'r' (at "
                  "'float r')");
    }
    EXPECT_THROW(d.GetOnePoint3f("p", {}), SceneError);
    EXPECT_THROW(d.GetOneFloat("e", 0), SceneError);
    EXPECT_EQ(d.GetFloatArray("r"), (std::vector<Float>{1, 2}));
    std::vector<Point3f> p = d.GetPoint3fArray("p");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[1], Point3f(4, 5, 6));
}

TEST(ParameterDictionary, Arrays) {
    ParameterDictionary d = Dict(
        "\"integer indices\" [0 1 2 2 1 3] \"bool flags\" [true false] "
        "\"string names\" [\"a\" \"b\"] \"point2 uv\" [0 0 1 1] \"vector2 d\" [1 0] "
        "\"vector3 dirs\" [1 0 0 0 1 0] \"normal N\" [0 0 1 0 1 0]");
    EXPECT_EQ(d.GetIntArray("indices"), (std::vector<int>{0, 1, 2, 2, 1, 3}));
    EXPECT_EQ(d.GetBoolArray("flags"), (std::vector<uint8_t>{1, 0}));
    EXPECT_EQ(d.GetStringArray("names"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.GetPoint2fArray("uv").at(1), Point2f(1, 1));
    EXPECT_EQ(d.GetVector2fArray("d").size(), 1u);
    EXPECT_EQ(d.GetVector3fArray("dirs").at(1), Vector3f(0, 1, 0));
    EXPECT_EQ(d.GetNormal3fArray("N").at(0), Normal3f(0, 0, 1));
    EXPECT_TRUE(d.GetIntArray("missing").empty());
}

TEST(ParameterDictionary, PrecedenceAttributesAndSet) {
    ParsedParameterVector attrs = ParamsOf("\"float radius\" 5 \"float zmax\" 2 \"float extra\" 1");
    ParameterDictionary d(ParamsOf("\"float radius\" 1 \"float radius\" 3"), attrs, nullptr);
    // The last of the directive's own parameters wins; attributes fill in the rest.
    EXPECT_EQ(d.GetOneFloat("radius", 0), 3);
    EXPECT_EQ(d.GetOneFloat("zmax", 0), 2);
    Diagnostics diag(nullptr);
    d.ReportUnused(diag);  // The shadowed radius 1 and unused attributes are not reported.
    EXPECT_EQ(diag.WarningCount(), 0);

    ParsedParameter p = ParamsOf("\"float radius\" 7")[0];
    d.Set(p);
    EXPECT_EQ(d.GetOneFloat("radius", 0), 7);
    ParsedParameter q = ParamsOf("\"string newone\" \"v\"")[0];
    d.Set(q);
    EXPECT_EQ(d.GetOneString("newone", ""), "v");
    EXPECT_EQ(d.GetOneFloat("zmax", 0), 2);
}

TEST(ParameterDictionary, Filenames) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("kiln_pd_fn_" + std::to_string(getpid()));
    fs::create_directories(dir / "tex");
    std::ofstream(dir / "tex/wood.png") << "x";
    ParameterDictionary d =
        Dict("\"string filename\" \"tex/wood.png\" \"string other\" \"nothere.png\"", dir.string());
    EXPECT_EQ(d.GetOneFilename("filename", ""), (dir / "tex/wood.png").string());
    EXPECT_EQ(d.GetOneFilename("other", ""), "nothere.png");  // left for the working directory
    EXPECT_EQ(d.GetOneFilename("absent", "def.png"), "def.png");
    fs::remove_all(dir);
}

TEST(ParameterDictionary, SpectrumKinds) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("kiln_pd_spd_" + std::to_string(getpid()));
    fs::create_directories(dir / "spd");
    std::ofstream(dir / "spd/ramp.spd") << "# lambda value\n400 1\n500 2\n600 3\n";
    ParameterDictionary d = Dict(
        "\"spectrum eta\" \"metal-Cu-eta\" \"spectrum pairs\" [400 0.5 700 1.5] "
        "\"spectrum file\" \"spd/ramp.spd\" \"blackbody L\" 5000 \"rgb c\" [0.2 0.4 0.8] "
        "\"rgb bright\" [2 1 0.5] \"rgb neg\" [-1 0 0] \"spectrum bad\" \"no-such-spectrum\" "
        "\"spectrum decreasing\" [500 1 400 1] \"blackbody two\" [3000 4000]",
        dir.string());

    std::optional<Spectrum> eta = d.GetOneSpectrum("eta", std::nullopt, SpectrumType::Unbounded);
    ASSERT_TRUE(eta);
    const Spectrum* cu = GetNamedSpectrum("metal-Cu-eta");
    ASSERT_NE(cu, nullptr);
    EXPECT_FLOAT_EQ((*eta)(550), (*cu)(550));

    std::optional<Spectrum> pairs = d.GetOneSpectrum("pairs", {}, SpectrumType::Unbounded);
    ASSERT_TRUE(pairs && pairs->Is<PiecewiseLinearSpectrum>());
    EXPECT_NEAR((*pairs)(550), 1.0f, 1e-5f);

    std::optional<Spectrum> file = d.GetOneSpectrum("file", {}, SpectrumType::Unbounded);
    ASSERT_TRUE(file);
    EXPECT_NEAR((*file)(450), 1.5f, 1e-5f);

    std::optional<Spectrum> bb = d.GetOneSpectrum("L", {}, SpectrumType::Illuminant);
    ASSERT_TRUE(bb && bb->Is<BlackbodySpectrum>());
    // Normalised to a peak of 1, at Wien's lambda_max = 2.8977721e6 nm K / T = 579.6 nm.
    EXPECT_NEAR((*bb)(579.55f), 1.0f, 1e-4f);
    EXPECT_LT((*bb)(400), 0.9f);

    std::optional<Spectrum> albedo = d.GetOneSpectrum("c", {}, SpectrumType::Albedo);
    ASSERT_TRUE(albedo && albedo->Is<RGBAlbedoSpectrum>());
    EXPECT_TRUE(d.GetOneSpectrum("c", {}, SpectrumType::Unbounded)->Is<RGBUnboundedSpectrum>());
    EXPECT_TRUE(d.GetOneSpectrum("c", {}, SpectrumType::Illuminant)->Is<RGBIlluminantSpectrum>());
    // Blue-ish: more reflectance at 450 nm than at 650 nm.
    EXPECT_GT((*albedo)(450), (*albedo)(650));

    // > 1 is fine unbounded, an error for an albedo; negative is always an error.
    EXPECT_TRUE(d.GetOneSpectrum("bright", {}, SpectrumType::Unbounded));
    EXPECT_THROW(d.GetOneSpectrum("bright", {}, SpectrumType::Albedo), SceneError);
    EXPECT_THROW(d.GetOneSpectrum("neg", {}, SpectrumType::Unbounded), SceneError);
    EXPECT_THROW(d.GetOneSpectrum("bad", {}, SpectrumType::Unbounded), SceneError);
    EXPECT_THROW(d.GetOneSpectrum("decreasing", {}, SpectrumType::Unbounded), SceneError);
    EXPECT_THROW(d.GetOneSpectrum("two", {}, SpectrumType::Illuminant), SceneError);
    EXPECT_EQ(d.GetSpectrumArray("two", SpectrumType::Illuminant).size(), 2u);

    // Defaults
    std::optional<Spectrum> def =
        d.GetOneSpectrum("absent", Spectrum(ConstantSpectrum(0.25f)), SpectrumType::Albedo);
    ASSERT_TRUE(def);
    EXPECT_EQ((*def)(500), 0.25f);
    EXPECT_FALSE(d.GetOneSpectrum("absent", std::nullopt, SpectrumType::Albedo));
    fs::remove_all(dir);
}

TEST(ParameterDictionary, SpectrumUsesColorSpace) {
    ParameterDictionary srgb(ParamsOf("\"rgb c\" [1 0 0]"), &RGBColorSpace::sRGB());
    ParameterDictionary rec(ParamsOf("\"rgb c\" [1 0 0]"), &RGBColorSpace::Rec2020());
    EXPECT_EQ(rec.ColorSpace(), &RGBColorSpace::Rec2020());
    Spectrum a = *srgb.GetOneSpectrum("c", {}, SpectrumType::Unbounded);
    Spectrum b = *rec.GetOneSpectrum("c", {}, SpectrumType::Unbounded);
    // Rec.2020 red is more saturated: less response in the green.
    EXPECT_NE(a(540), b(540));
}

}  // namespace kiln
