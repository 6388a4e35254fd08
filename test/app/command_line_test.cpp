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

TEST(CommandLineTest, FrameFilenamesArePadded) {
    EXPECT_EQ(FrameFilename("out/f.####.exr", 7), "out/f.0007.exr");
    EXPECT_EQ(FrameFilename("f#.png", 12), "f12.png");
    EXPECT_EQ(FrameFilename("f.##.png", 123), "f.123.png");
    EXPECT_EQ(FrameFilename("still.exr", 4), "still.exr");
}

}  // namespace
}  // namespace kiln
