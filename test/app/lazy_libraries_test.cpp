// Start-up cost: the kiln command links neither OpenImageIO nor OpenVDB. A render that writes
// EXR or an RGB PNG, or reads a PNG texture, never loads them (checked with the dynamic loader's
// own log, LD_DEBUG=files); a TIFF output loads the OpenImageIO plugin when the image is
// written, and works. (The CPU time
// and memory this saves are measured by bench/startup.sh.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "app_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

// Runs kiln with the loader's log on; returns that log (kiln's stderr) and sets *status
std::string LoaderLog(const std::string& args, int* status) {
    const std::string log =
        (fs::temp_directory_path() / ("kiln_ld_" + std::to_string(getpid()) + ".log")).string();
    const std::string command = "LD_DEBUG=files '" + std::string(KILN_BINARY_DIR) + "/kiln' " +
                                args + " --quiet 2> '" + log + "'";
    *status = std::system(command.c_str());
    std::string text = testing::ReadAll(log);
    fs::remove(log);
    return text;
}

TEST(LazyLibraries, AnExrRenderLoadsNeitherOpenImageIONorOpenVDB) {
    const fs::path dir = fs::temp_directory_path() / ("kiln_lazy_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string scene = (dir / "s.pbrt").string();
    std::ofstream(scene) << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 6\n"
                            "Sampler \"zsobol\" \"integer pixelsamples\" 2\n"
                            "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                            "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
                            "Shape \"sphere\" \"float radius\" 1\n";
    // EXR and grey/RGB PNG outputs are written without OpenImageIO; TIFF loads its plugin
    for (const char* output : {"out.exr", "out.png", "out.tif"}) {
        int status = 0;
        std::string log =
            LoaderLog("'" + scene + "' -o '" + (dir / output).string() + "'", &status);
        ASSERT_EQ(status, 0) << log;
        ASSERT_NE(log.find("file="), std::string::npos) << "no loader log: " << log;
        const bool oiio = std::string(output) == "out.tif";
        EXPECT_EQ(log.find("libOpenImageIO") != std::string::npos, oiio) << output;
        EXPECT_EQ(log.find("libkiln_oiio.so") != std::string::npos, oiio) << output;
        if (!oiio) {  // (OpenImageIO links OpenVDB itself)
            EXPECT_EQ(log.find("libopenvdb"), std::string::npos) << output;
        }
        EXPECT_EQ(log.find("libkiln_openvdb"), std::string::npos) << output;
        EXPECT_TRUE(fs::exists(dir / output));
    }
    // A scene with a PNG texture (the render just written) loads no OpenImageIO either
    const std::string textured = (dir / "t.pbrt").string();
    std::ofstream(textured) << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 6\n"
                               "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                               "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
                               "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \""
                            << (dir / "out.png").string()
                            << "\"\nMaterial \"diffuse\" \"texture reflectance\" \"t\"\n"
                               "Shape \"sphere\" \"float radius\" 1\n";
    int status = 0;
    std::string log =
        LoaderLog("'" + textured + "' -o '" + (dir / "textured.exr").string() + "'", &status);
    ASSERT_EQ(status, 0) << log;
    EXPECT_EQ(log.find("libOpenImageIO"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "textured.exr"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
