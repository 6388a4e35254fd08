// Writing images on a full disk (issue 23): the file-size limit (RLIMIT_FSIZE, with SIGXFSZ
// ignored) makes every write past it fail with EFBIG, as a full disk fails with ENOSPC. Every
// format is an error naming the file, an existing file keeps its bytes, and no temporary is
// left; with the limit lifted the same write succeeds.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

// The process's file-size limit lowered to `bytes` for the lifetime of this object
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &saved);
        previous = signal(SIGXFSZ, SIG_IGN);
        rlimit lowered = saved;
        lowered.rlim_cur = bytes;
        EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &lowered), 0);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved);
        signal(SIGXFSZ, previous);
    }

  private:
    rlimit saved{};
    sighandler_t previous;
};

std::string Contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(FullDisk, EveryFormatIsAnErrorAndTheOldFileStays) {
    fs::path dir =
        fs::temp_directory_path() / ("kiln_full_disk_" + std::to_string(std::random_device()()));
    fs::create_directories(dir);
    // Noise, so that no format compresses it below the limit
    std::mt19937 rng(7);
    Image im(PixelFormat::Float, {64, 64}, {"R", "G", "B"});
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                im.SetChannel({x, y}, c, std::uniform_real_distribution<float>(0, 1)(rng));
    const std::string old = "the previous render";
    for (const char* ext : {"exr", "png", "hdr", "jpg", "tif"}) {
        fs::path file = dir / (std::string("out.") + ext);
        std::ofstream(file) << old;
        {
            FileSizeLimit limit(2000);
            try {
                im.Write(file.string());
                ADD_FAILURE() << ext << ": no error";
            } catch (const std::runtime_error& e) {
                EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            }
        }
        EXPECT_EQ(Contents(file), old) << ext;
        int entries = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
        EXPECT_EQ(entries, 1) << ext << ": a temporary was left";
        im.Write(file.string());
        EXPECT_EQ(Image::Read(file.string()).Resolution(), Point2i(64, 64)) << ext;
        fs::remove(file);
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
