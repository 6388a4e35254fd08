// Parser: every directive, every parameter type, Include and Import.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "../temp_dir.h"
#include "core/parser/parser.h"
#include "recording_target.h"

namespace kiln {

namespace {

RecordingTarget Parse(std::string_view text, Diagnostics* diag = nullptr) {
    RecordingTarget target;
    Diagnostics silent(nullptr);
    ParseString(target, text, diag ? *diag : silent, "test.pbrt");
    return target;
}

namespace fs = std::filesystem;

// A fresh directory under the system temp dir, removed at the end of the test.
using test::TempDir;

}  // namespace

TEST(Parser, TransformDirectives) {
    RecordingTarget t = Parse(
        "Identity\nTranslate 1 -2 3.5\nScale 2 2 2 Rotate 90 0 0 1\n"
        "LookAt 0 0 5  0 0 0  0 1 0\n"
        "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\n"
        "ConcatTransform [ 2 0 0 0 0 2 0 0 0 0 2 0 1 2 3 1 ]\n"
        "CoordinateSystem \"cam\" CoordSysTransform \"camera\"\n"
        "ActiveTransform StartTime ActiveTransform EndTime ActiveTransform All\n"
        "TransformTimes 0 1 ReverseOrientation\n");
    EXPECT_EQ(t.Text(),
              "Identity\nTranslate 1 -2 3.5\nScale 2 2 2\nRotate 90 0 0 1\n"
              "LookAt 0 0 5 0 0 0 0 1 0\n"
              "Transform 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n"
              "ConcatTransform 2 0 0 0 0 2 0 0 0 0 2 0 1 2 3 1\n"
              "CoordinateSystem cam\nCoordSysTransform camera\n"
              "ActiveTransform StartTime\nActiveTransform EndTime\nActiveTransform All\n"
              "TransformTimes 0 1\nReverseOrientation\n");
    EXPECT_EQ(t.endOfFiles, 1);
    EXPECT_EQ(t.calls[2].loc.ToString(), "test.pbrt:3:1");
    EXPECT_EQ(t.calls[3].loc.ToString(), "test.pbrt:3:13");
}

TEST(Parser, OptionsAndWorldDirectives) {
    Diagnostics diag(nullptr);
    RecordingTarget t = Parse(
        "Option \"bool disablepixeljitter\" true\n"
        "Option \"string rendercoordsys\" \"world\"\n"
        "ColorSpace \"rec2020\"\n"
        "Camera \"perspective\" \"float fov\" 45\n"
        "Film \"rgb\" \"string filename\" \"out.exr\"\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "Integrator \"volpath\" \"integer maxdepth\" [ 5 ]\n"
        "PixelFilter \"gaussian\"\n"
        "Accelerator \"bvh\"\n"
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "MediumInterface \"fog\"\n"
        "MediumInterface \"in\" \"out\"\n"
        "MediumInterface \"\" \"fog\" WorldBegin\n"
        "AttributeBegin Attribute \"shape\" \"float radius\" 2 AttributeEnd\n"
        "TransformBegin TransformEnd TransformBegin TransformEnd\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 4\n"
        "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
        "MakeNamedMaterial \"gold\" \"string type\" \"conductor\"\n"
        "NamedMaterial \"gold\"\n"
        "LightSource \"point\" \"blackbody I\" 3000\n"
        "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Shape \"sphere\"\n"
        "ObjectBegin \"thing\" ObjectEnd ObjectInstance \"thing\"\n"
        "WorldEnd\n",
        &diag);
    EXPECT_EQ(t.Text(),
              "Option bool disablepixeljitter = true\n"
              "Option string rendercoordsys = \"world\"\n"
              "ColorSpace rec2020\nCamera perspective\nFilm rgb\nSampler zsobol\n"
              "Integrator volpath\nPixelFilter gaussian\nAccelerator bvh\n"
              "MakeNamedMedium fog\nMediumInterface fog fog\nMediumInterface in out\n"
              "MediumInterface  fog\nWorldBegin\nAttributeBegin\nAttribute shape\n"
              "AttributeEnd\nAttributeBegin\nAttributeEnd\nAttributeBegin\nAttributeEnd\n"
              "Texture checks spectrum checkerboard\nMaterial diffuse\n"
              "MakeNamedMaterial gold\nNamedMaterial gold\nLightSource point\n"
              "AreaLightSource diffuse\nShape sphere\nObjectBegin thing\nObjectEnd\n"
              "ObjectInstance thing\n");
    // TransformBegin and TransformEnd warn once each; WorldEnd warns.
    std::vector<Diagnostics::Warning> w = diag.Warnings();
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0].loc.ToString(), "test.pbrt:15:1");
    EXPECT_NE(w[0].message.find("TransformBegin"), std::string::npos);
    EXPECT_EQ(w[1].loc.ToString(), "test.pbrt:15:16");
    EXPECT_EQ(w[2].loc.ToString(), "test.pbrt:24:1");
    EXPECT_EQ(t.Find("Integrator").params[0].ints, std::vector<int>{5});
    EXPECT_EQ(t.Find("Material").params[0].type, "texture");
    EXPECT_EQ(t.Find("Material").params[0].strings[0], "checks");
}

TEST(Parser, ParameterTypesAndAliases) {
    RecordingTarget t = Parse(
        "Shape \"test\"\n"
        "  \"integer i\" [ 1 -2 +3 ] \"float f\" 1.5e2 \"bool b1\" true \"bool b2\" \"false\"\n"
        "  \"bool b3\" [ false \"true\" ] \"string s\" \"a \\\"q\\\" \\\\ \\n\"\n"
        "  \"texture t\" \"tex\" \"point2 p2\" [1 2 3 4] \"vector2 v2\" [5 6]\n"
        "  \"point3 p3\" [1 2 3] \"point p\" [4 5 6] \"vector3 v3\" [7 8 9] \"vector v\" [1 1 1]\n"
        "  \"normal n\" [0 0 1] \"normal3 n3\" [0 1 0] \"rgb c1\" [.1 .2 .3]\n"
        "  \"color c2\" [1 1 1] \"spectrum sp\" [300 .3 800 .8] \"spectrum sn\" \"metal-Cu-eta\"\n"
        "  \"blackbody bb\" 6500\n");
    const ParsedParameterVector& p = t.Find("Shape").params;
    ASSERT_EQ(p.size(), 20u);
    auto get = [&](const std::string& name) -> const ParsedParameter& {
        for (const ParsedParameter& q : p)
            if (q.name == name) return q;
        ADD_FAILURE() << name;
        return p[0];
    };
    EXPECT_EQ(get("i").ints, (std::vector<int>{1, -2, 3}));
    EXPECT_EQ(get("f").floats, std::vector<Float>{150});
    EXPECT_EQ(get("b1").bools, std::vector<uint8_t>{1});
    EXPECT_EQ(get("b2").bools, std::vector<uint8_t>{0});
    EXPECT_EQ(get("b3").bools, (std::vector<uint8_t>{0, 1}));
    EXPECT_EQ(get("s").strings[0], "a \"q\" \\ \n");
    EXPECT_EQ(get("t").type, "texture");
    EXPECT_EQ(get("p2").floats.size(), 4u);
    EXPECT_EQ(get("v2").type, "vector2");
    EXPECT_EQ(get("p").type, "point3");
    EXPECT_EQ(get("v").type, "vector3");
    EXPECT_EQ(get("n3").type, "normal");
    EXPECT_EQ(get("c2").type, "rgb");
    EXPECT_EQ(get("c1").floats, (std::vector<Float>{0.1f, 0.2f, 0.3f}));
    EXPECT_EQ(get("sp").floats.size(), 4u);
    EXPECT_EQ(get("sn").strings, std::vector<std::string>{"metal-Cu-eta"});
    EXPECT_EQ(get("bb").type, "blackbody");
    EXPECT_EQ(get("bb").floats, std::vector<Float>{6500});
    EXPECT_EQ(get("i").loc.ToString(), "test.pbrt:2:3");
    EXPECT_EQ(get("i").Declaration(), "integer i");
    EXPECT_EQ(get("i").searchDirectory, "");
}

TEST(Parser, CommentsWhitespaceAndEmptyLists) {
    Diagnostics diag(nullptr);
    RecordingTarget t = Parse(
        "# comment\r\nShape \"trianglemesh\"# comment right after\n\t\"integer indices\" []\n"
        "  \"float x\" [1] \"float x\" [2] # repeated: warning\n",
        &diag);
    ASSERT_EQ(t.calls.size(), 1u);
    EXPECT_TRUE(t.calls[0].params[0].ints.empty());
    EXPECT_EQ(t.calls[0].loc.ToString(), "test.pbrt:2:1");
    ASSERT_EQ(diag.WarningCount(), 1);
    EXPECT_EQ(diag.Warnings()[0].loc.ToString(), "test.pbrt:4:17");
}

TEST(Parser, IntegerGivenAsFloat) {
    Diagnostics diag(nullptr);
    RecordingTarget t = Parse("Shape \"x\" \"integer a\" [ 2.0 3.7 ]", &diag);
    EXPECT_EQ(t.calls[0].params[0].ints, (std::vector<int>{2, 3}));
    EXPECT_EQ(diag.WarningCount(), 1);  // only 3.7 is not integral
}

TEST(Parser, IncludeAndImportResolveAgainstTopLevelDirectory) {
    TempDir dir;
    // Nested include: sub/a.pbrt includes "sub/b.pbrt", relative to the top-level directory.
    dir.Write("scene.pbrt",
              "Include \"sub/a.pbrt\"\nWorldBegin\nImport \"sub/imp.pbrt\"\nShape \"after\"\n");
    dir.Write("sub/a.pbrt", "Translate 1 2 3\nInclude \"sub/b.pbrt\"\nScale 4 5 6\n");
    dir.Write("sub/b.pbrt", "Camera \"perspective\" \"string f\" \"x.spd\"\n");
    dir.Write("sub/imp.pbrt", "Shape \"imported\"\nMaterial \"diffuse\"\n");
    RecordingTarget t;
    Diagnostics diag(nullptr);
    ParseFile(t, (dir.path / "scene.pbrt").string(), diag);
    EXPECT_EQ(t.Text(),
              "Translate 1 2 3\nCamera perspective\nScale 4 5 6\nWorldBegin\nAttributeBegin\n"
              "Shape imported\nMaterial diffuse\nAttributeEnd\nShape after\n");
    EXPECT_EQ(t.endOfFiles, 1);
    const RecordingTarget::Call& cam = t.Find("Camera");
    EXPECT_EQ(cam.loc.ToString(), (dir.path / "sub/b.pbrt").string() + ":1:1");
    EXPECT_EQ(cam.params[0].searchDirectory, dir.path.string());
    EXPECT_EQ(t.Find("Scale").loc.ToString(), (dir.path / "sub/a.pbrt").string() + ":3:1");
    EXPECT_EQ(t.Find("AttributeBegin").loc.ToString(), (dir.path / "scene.pbrt").string() + ":3:1");
    EXPECT_EQ(t.Find("Shape imported").loc.ToString(),
              (dir.path / "sub/imp.pbrt").string() + ":1:1");
}

TEST(Parser, IncludedTokensContinueTheDirective) {
    // pbrt-v4 splices included tokens into the stream, so a directive may end after the file.
    TempDir dir;
    dir.Write("part.pbrt", "Translate 1 2");
    RecordingTarget t;
    Diagnostics diag(nullptr);
    ParseString(t, "Include \"part.pbrt\" 3\nScale 1 1 1", diag, "s.pbrt", dir.path.string());
    EXPECT_EQ(t.Text(), "Translate 1 2 3\nScale 1 1 1\n");
}

TEST(Parser, LargeMeshParses) {
    // 1e6 numbers (about 10 MB of text with indices); no timing assert.
    std::string text = "Shape \"trianglemesh\" \"point3 P\" [";
    text.reserve(12'000'000);
    const int nVerts = 300'000;
    char buf[64];
    for (int i = 0; i < nVerts; ++i) {
        int n =
            std::snprintf(buf, sizeof(buf), " %.6f %.6f %.6f", i * 0.001, -i * 0.002, i * 1.5e-5);
        text.append(buf, n);
    }
    text += " ] \"integer indices\" [";
    for (int i = 0; i < 100'000; ++i) {
        text += ' ';
        text += std::to_string(i % nVerts);
    }
    text += " ]\n";
    RecordingTarget t = Parse(text);
    ASSERT_EQ(t.calls.size(), 1u);
    const ParsedParameterVector& p = t.calls[0].params;
    ASSERT_EQ(p[0].floats.size(), size_t(3 * nVerts));
    EXPECT_FLOAT_EQ(p[0].floats[3 * 1234 + 1], -1234 * 0.002f);
    EXPECT_EQ(p[1].ints.size(), 100'000u);
}

}  // namespace kiln
