// What the kiln command's tests share.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/image/image.h"

namespace kiln::testing {

// Every pixel value (all channels, row by row) of an image file, for bit-exact comparisons.
inline std::vector<float> Pixels(const std::string& file) {
    Image im = Image::Read(file);
    std::vector<float> v;
    for (int y = 0; y < im.Resolution().y; ++y)
        for (int x = 0; x < im.Resolution().x; ++x)
            for (int c = 0; c < im.NChannels(); ++c) v.push_back(im.GetChannel({x, y}, c));
    return v;
}

// A word for a test's shell commands: single-quoted, single quotes escaped
inline std::string ShellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
// Its short name, for command lines
inline constexpr auto Q = ShellQuote;

// The whole content of a file ("" if it cannot be read)
inline std::string ReadAll(const std::string& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A test that runs the kiln command in a fresh folder of its own (removed afterwards), holding
// scene.pbrt with the text the test passes to WriteScene.
class KilnCommandTest : public ::testing::Test {
  protected:
    explicit KilnCommandTest(std::string name) : name(std::move(name)) {}
    void SetUp() override {
        dir = std::filesystem::path(::testing::TempDir()) /
              ("kiln_" + name + "_" + std::to_string(getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    void WriteScene(const std::string& text) { std::ofstream(dir / "scene.pbrt") << text; }
    // Runs `kiln ARGS` in the folder; its standard output and error are in `log`. Returns the
    // exit status (-1 if it did not exit).
    int Run(const std::string& args) {
        std::string command = "cd " + ShellQuote(dir.string()) + " && " + ShellQuote(kiln) + " " +
                              args + " > " + ShellQuote((dir / "log.txt").string()) + " 2>&1";
        int status = std::system(command.c_str());
        log = ReadAll((dir / "log.txt").string());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    std::string name;
    std::filesystem::path dir;
    std::string log;
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
};

}  // namespace kiln::testing
