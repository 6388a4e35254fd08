// The kiln command's option parsing and frame file names.
#include <gtest/gtest.h>

#include "app/command_line.h"

namespace kiln {
namespace {

TEST(CommandLineTest, ParsesOptions) {
    CommandLineOptions o = ParseCommandLine(
        {"scene.pbrt", "-o",      "a.##.exr",   "-o",        "a.##.png", "--spp", "16",
         "--threads",  "2",       "--seed",     "-3",        "--crop",   "0.1",   "0.5",
         "0.2",        "0.9",     "--emission", "additive",  "--frames", "3-7",   "--fps",
         "12",         "--quiet", "-o",         "f.####.exr"});
    EXPECT_EQ(o.sceneFile, "scene.pbrt");
    ASSERT_EQ(o.outputs.size(), 3u);
    EXPECT_EQ(o.spp, 16);
    EXPECT_EQ(o.threads, 2);
    EXPECT_EQ(o.seed, -3);
    ASSERT_TRUE(o.crop);
    EXPECT_FLOAT_EQ(o.crop->pMin.x, 0.1f);
    EXPECT_FLOAT_EQ(o.crop->pMax.y, 0.9f);
    EXPECT_EQ(o.emission, "additive");
    ASSERT_TRUE(o.frames);
    EXPECT_EQ(o.frames->first, 3);
    EXPECT_EQ(o.frames->second, 7);
    EXPECT_DOUBLE_EQ(o.fps, 12);
    EXPECT_TRUE(o.quiet);
    EXPECT_FALSE(o.pbrtv4LayeredMIS);
    EXPECT_TRUE(ParseCommandLine({"s.pbrt", "--layered-mis", "pbrt-v4"}).pbrtv4LayeredMIS);
    EXPECT_FALSE(ParseCommandLine({"s.pbrt", "--layered-mis", "kiln"}).pbrtv4LayeredMIS);
}

TEST(CommandLineTest, RejectsBadArguments) {
    for (std::vector<std::string> args : {std::vector<std::string>{"s.pbrt", "--spp", "0"},
                                          {"s.pbrt", "--spp", "ten"},
                                          {"s.pbrt", "--crop", "0.5", "0.2", "0", "1"},
                                          {"s.pbrt", "--emission", "glow"},
                                          {"s.pbrt", "--layered-mis", "pbrt"},
                                          {"s.pbrt", "--bogus"},
                                          {"a.pbrt", "b.pbrt"},
                                          {"s.pbrt", "-o"},
                                          {"s.pbrt", "--frames", "5-2"},
                                          {"s.pbrt", "--frames", "0-9", "-o", "still.exr"},
                                          {"s.pbrt", "--fps", "0"}}) {
        EXPECT_THROW(ParseCommandLine(args), std::invalid_argument) << args.back();
    }
}

// pbrt-v4's spellings: --name=value, and x0,x1,y0,y1 in one argument
TEST(CommandLineTest, TakesPbrtV4Syntax) {
    CommandLineOptions o = ParseCommandLine({"s.pbrt", "--spp=4", "--cropwindow", "0,0.5,0.25,0.75",
                                             "--pixelbounds=0,32,8,24", "--outfile=a.exr"});
    EXPECT_EQ(o.spp, 4);
    ASSERT_TRUE(o.crop && o.pixelBounds);
    CommandLineOptions spaced = ParseCommandLine({"s.pbrt", "--crop", "0", "0.5", "0.25", "0.75"});
    EXPECT_EQ(o.crop->pMin, spaced.crop->pMin);
    EXPECT_EQ(o.crop->pMax, spaced.crop->pMax);
    EXPECT_EQ(o.pixelBounds->pMin, Point2i(0, 8));
    EXPECT_EQ(o.pixelBounds->pMax, Point2i(32, 24));
    EXPECT_EQ(o.outputs, std::vector<std::string>{"a.exr"});
    for (std::vector<std::string> bad :
         {std::vector<std::string>{"s.pbrt", "--cropwindow", "0,1,0"},
          {"s.pbrt", "--pixelbounds", "0,8,x,6"},
          {"s.pbrt", "--spp="},
          {"s.pbrt", "--cropwindow", "0,0.5,0.5,0.25"}})
        EXPECT_THROW(ParseCommandLine(bad), std::invalid_argument) << bad.back();
}

TEST(CommandLineTest, AnUnknownOptionSuggestsTheNearestKnownOne) {
    auto message = [](const std::string& option) {
        try {
            ParseCommandLine({"s.pbrt", option});
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("--sp").find("did you mean --spp?"), std::string::npos) << message("--sp");
    EXPECT_NE(message("--pixelbound").find("did you mean --pixelbounds?"), std::string::npos);
    EXPECT_NE(message("--emision").find("did you mean --emission?"), std::string::npos);
    EXPECT_EQ(message("--frobnicate").find("did you mean"), std::string::npos);
}

TEST(CommandLineTest, FrameFilenamesArePadded) {
    EXPECT_EQ(FrameFilename("out/f.####.exr", 7), "out/f.0007.exr");
    EXPECT_EQ(FrameFilename("f#.png", 12), "f12.png");
    EXPECT_EQ(FrameFilename("f.##.png", 123), "f.123.png");
    EXPECT_EQ(FrameFilename("still.exr", 4), "still.exr");
}

}  // namespace
}  // namespace kiln
