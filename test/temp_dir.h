// A scratch folder for one test: <temp>/kiln_<suite>_<test>_<pid>_<random>, made empty and
// removed, with all it holds, when the object goes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace kiln::test {

struct TempDir {
    std::filesystem::path path;

    TempDir() {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name =
            info ? std::string(info->test_suite_name()) + "_" + info->name() : "scratch";
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        path = std::filesystem::temp_directory_path() /
               ("kiln_" + name + "_" + std::to_string(::getpid()) + "_" +
                std::to_string(std::random_device()()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    // Writes text to the file `name` under the folder, making the folders it names.
    void Write(const std::string& name, const std::string& text) const {
        std::filesystem::create_directories((path / name).parent_path());
        std::ofstream(path / name) << text;
    }
    // How many entries the folder holds.
    int Files() const {
        int n = 0;
        for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(path)) ++n;
        return n;
    }
};

}  // namespace kiln::test
