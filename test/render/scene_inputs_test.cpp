// SceneInputFiles and HashInputFiles (render/scene_inputs.h): every file a scene reads is
// listed once (the scene file, its includes, a PLY mesh, a spectrum file, an image texture),
// not the film's output nor names that are no files; the hash changes with any byte of any of
// them and with nothing else.
#include "render/scene_inputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "core/parser/parser.h"
#include "render/scene_builder.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

TEST(SceneInputs, EveryFileReadIsListedAndHashed) {
    fs::path dir =
        fs::temp_directory_path() / ("kiln_inputs_" + std::to_string(std::random_device()()));
    fs::create_directories(dir / "sub");
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
    };
    write("main.pbrt", R"(Film "rgb" "string filename" "out.exr"
Camera "perspective"
WorldBegin
Include "sub/world.pbrt"
Texture "grid" "spectrum" "imagemap" "string filename" "grid.png"
Material "conductor" "spectrum eta" "eta.spd" "spectrum k" "metal-Cu-k"
Shape "plymesh" "string filename" "mesh.ply"
Shape "sphere" "string name" "not a file"
)");
    write("sub/world.pbrt", "LightSource \"infinite\"\n");
    write("eta.spd", "300 0.3\n900 0.4\n");
    write("mesh.ply", "ply\n");
    write("grid.png", "png");
    write("out.exr", "the output");
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    std::vector<std::string> parsed = ParseFile(builder, (dir / "main.pbrt").string(), diag);
    std::vector<std::string> files = SceneInputFiles(builder.Description(), parsed);
    std::vector<std::string> names;
    for (const std::string& f : files) names.push_back(fs::relative(f, dir).string());
    EXPECT_EQ(names, (std::vector<std::string>{"main.pbrt", "sub/world.pbrt", "eta.spd", "grid.png",
                                               "mesh.ply"}));
    const std::string hash = HashInputFiles(files);
    EXPECT_EQ(hash.size(), 16u);
    EXPECT_EQ(HashInputFiles(files), hash);
    write("out.exr", "another output");
    EXPECT_EQ(HashInputFiles(files), hash);
    for (const char* name : {"main.pbrt", "sub/world.pbrt", "eta.spd", "grid.png", "mesh.ply"}) {
        std::ifstream in(dir / name, std::ios::binary);
        std::string before((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string changed = before;
        changed.back() ^= 1;  // one bit of the last byte
        write(name, changed);
        EXPECT_NE(HashInputFiles(files), hash) << name;
        write(name, before);
        EXPECT_EQ(HashInputFiles(files), hash) << name;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
