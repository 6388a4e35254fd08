// SceneBuilder: graphics-state semantics of pbrt-v4's BasicSceneBuilder, without rendering.
#include <gtest/gtest.h>

#include "core/parser/parser.h"
#include "render/scene_builder.h"

namespace kiln {
namespace {

SceneDescription Describe(const std::string& text, Diagnostics* diagOut = nullptr) {
    Diagnostics diag(nullptr);
    SceneBuilder builder(diagOut ? *diagOut : diag);
    ParseString(builder, text, diagOut ? *diagOut : diag, "<test>");
    return std::move(builder.Description());
}

std::string BuildError(const std::string& text) {
    try {
        Describe(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(SceneBuilderTest, AttributesScopeMaterialsTransformsAndAreaLights) {
    SceneDescription d = Describe(R"(
WorldBegin
AttributeBegin
  Material "conductor"
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Translate 1 2 3
  Shape "sphere"
AttributeEnd
Shape "disk"
)");
    ASSERT_EQ(d.shapes.size(), 2u);
    EXPECT_EQ(d.shapes[0].areaLightIndex, 0);
    EXPECT_EQ(d.shapes[1].areaLightIndex, -1);
    EXPECT_EQ(d.materials[size_t(d.shapes[0].materialIndex)].name, "conductor");
    EXPECT_EQ(d.materials[size_t(d.shapes[1].materialIndex)].name, "diffuse");
    Point3f p = d.shapes[0].renderFromObject(Point3f(0, 0, 0));
    EXPECT_FLOAT_EQ(p.x, 1);
    EXPECT_FLOAT_EQ(p.y, 2);
    EXPECT_FLOAT_EQ(p.z, 3);
    Point3f q = d.shapes[1].renderFromObject(Point3f(0, 0, 0));
    EXPECT_FLOAT_EQ(q.x, 0);
}

TEST(SceneBuilderTest, RenderSpaceIsCameraWorld) {
    SceneDescription d = Describe(R"(
LookAt 5 0 0  0 0 0  0 1 0
Camera "perspective"
WorldBegin
Translate 5 0 0
Shape "sphere"
)");
    // The shape sits where the camera is: the render-space origin.
    Point3f p = d.shapes[0].renderFromObject(Point3f(0, 0, 0));
    EXPECT_NEAR(p.x, 0, 1e-5);
    EXPECT_NEAR(p.y, 0, 1e-5);
    EXPECT_NEAR(p.z, 0, 1e-5);
}

TEST(SceneBuilderTest, TransformIsGivenColumnByColumn) {
    SceneDescription d = Describe(R"(
WorldBegin
Transform [1 0 0 0  0 1 0 0  0 0 1 0  7 8 9 1]
Shape "sphere"
)");
    Point3f p = d.shapes[0].renderFromObject(Point3f(0, 0, 0));
    EXPECT_FLOAT_EQ(p.x, 7);
    EXPECT_FLOAT_EQ(p.y, 8);
    EXPECT_FLOAT_EQ(p.z, 9);
}

TEST(SceneBuilderTest, NamedMaterialsCoordinateSystemsAndInstances) {
    SceneDescription d = Describe(R"(
WorldBegin
MakeNamedMaterial "gold" "string type" "conductor"
CoordinateSystem "here"
Translate 1 0 0
CoordSysTransform "here"
NamedMaterial "gold"
ObjectBegin "thing"
  Shape "sphere"
ObjectEnd
Translate 0 4 0
ObjectInstance "thing"
ReverseOrientation
Shape "disk"
)");
    ASSERT_EQ(d.namedMaterials.size(), 1u);
    EXPECT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].materialName, "gold");
    EXPECT_TRUE(d.shapes[0].reverseOrientation);
    EXPECT_FLOAT_EQ(d.shapes[0].renderFromObject(Point3f(0, 0, 0)).x, 0);
    ASSERT_EQ(d.instanceDefinitions.count("thing"), 1u);
    EXPECT_EQ(d.instanceDefinitions["thing"].shapes.size(), 1u);
    ASSERT_EQ(d.instances.size(), 1u);
    EXPECT_FLOAT_EQ(d.instances[0].renderFromInstance(Point3f(0, 0, 0)).y, 4);
}

TEST(SceneBuilderTest, AttributeParametersApplyUnlessOverridden) {
    SceneDescription d = Describe(R"(
WorldBegin
Attribute "shape" "float radius" 3
Shape "sphere"
Shape "sphere" "float radius" 2
)");
    EXPECT_FLOAT_EQ(d.shapes[0].parameters.GetOneFloat("radius", 1), 3);
    EXPECT_FLOAT_EQ(d.shapes[1].parameters.GetOneFloat("radius", 1), 2);
}

TEST(SceneBuilderTest, MalformedStructureIsAnErrorWithItsLocation) {
    EXPECT_NE(BuildError("WorldBegin\nAttributeEnd\n").find("<test>:2:1"), std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nAttributeBegin\n").find("<test>:2:1"), std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nObjectInstance \"nope\"\n").find("nope"), std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nFilm \"rgb\"\n").find("before WorldBegin"),
              std::string::npos);
    EXPECT_NE(BuildError("Shape \"sphere\"\n").find("after WorldBegin"), std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nTexture \"t\" \"color\" \"constant\"\n").find("color"),
              std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nNamedMaterial \"m\"\nShape \"sphere\"\n").find("'m'"),
              std::string::npos);
    EXPECT_NE(BuildError("ColorSpace \"bogus\"\n").find("bogus"), std::string::npos);
    EXPECT_NE(BuildError("WorldBegin\nObjectBegin \"a\"\nObjectBegin \"b\"\n").find("<test>:3"),
              std::string::npos);
}

TEST(SceneBuilderTest, MediaAndMediumInterfacesAreRecorded) {
    Diagnostics diag(nullptr);
    SceneDescription d = Describe(
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n"
        "AttributeBegin MediumInterface \"glass\" \"fog\" Shape \"sphere\" AttributeEnd\n"
        "Shape \"sphere\"\nMediumInterface \"fog\"\nShape \"sphere\"\n",
        &diag);
    EXPECT_EQ(diag.WarningCount(), 0);
    ASSERT_EQ(d.media.size(), 1u);
    EXPECT_EQ(d.media[0].first, "fog");
    EXPECT_EQ(d.media[0].second.parameters.GetOneString("type", ""), "homogeneous");
    EXPECT_EQ(d.camera.medium, "fog");  // the outside medium when the camera is declared
    ASSERT_EQ(d.shapes.size(), 3u);
    EXPECT_EQ(d.shapes[0].insideMedium, "glass");
    EXPECT_EQ(d.shapes[0].outsideMedium, "fog");
    EXPECT_EQ(d.shapes[1].insideMedium, "");  // restored by AttributeEnd
    EXPECT_EQ(d.shapes[1].outsideMedium, "fog");
    EXPECT_EQ(d.shapes[2].insideMedium, "fog");  // one name: both sides
    EXPECT_EQ(d.shapes[2].outsideMedium, "fog");
}

TEST(SceneBuilderTest, RedefiningAMediumIsAnError) {
    Diagnostics diag(nullptr);
    EXPECT_THROW(Describe("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                          "MakeNamedMedium \"fog\" \"string type\" \"cloud\"\n",
                          &diag),
                 SceneError);
}

}  // namespace
}  // namespace kiln
