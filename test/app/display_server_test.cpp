// kiln --display-server speaks tev's protocol (app/display_server.h) to a listener in the test:
// one CreateImage naming the image's size and R, G, B, then UpdateImage tiles after every wave
// whose last values are the image kiln writes; a viewer that is not there is a warning and the
// render goes on.
#include <gtest/gtest.h>

#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "app_test_util.h"
#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::Q;

// What a tev-like viewer received
struct Received {
    int creates = 0, updates = 0;
    std::string name;
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::map<std::string, std::vector<float>> pixels;  // channel -> width x height values
    bool malformed = false;
};

// Reads messages from a connected socket until it closes
void Listen(int fd, Received& r) {
    std::string buffer;
    char chunk[65536];
    for (ssize_t n; (n = ::recv(fd, chunk, sizeof(chunk), 0)) > 0;) buffer.append(chunk, size_t(n));
    size_t at = 0;
    auto read32 = [&](size_t& p) {
        int32_t v;
        std::memcpy(&v, buffer.data() + p, 4);
        p += 4;
        return v;
    };
    auto readString = [&](size_t& p) {
        std::string s(buffer.data() + p);
        p += s.size() + 1;
        return s;
    };
    while (at + 5 <= buffer.size()) {
        size_t p = at;
        uint32_t length = uint32_t(read32(p));
        if (length < 5 || at + length > buffer.size()) {
            r.malformed = true;
            return;
        }
        uint8_t type = uint8_t(buffer[p++]);
        ++p;  // grab focus
        std::string name = readString(p);
        if (type == 4) {
            ++r.creates;
            r.name = name;
            r.width = read32(p);
            r.height = read32(p);
            int n = read32(p);
            for (int c = 0; c < n; ++c) r.channels.push_back(readString(p));
            for (const std::string& c : r.channels)
                r.pixels[c].assign(size_t(r.width) * r.height, -1.f);
        } else if (type == 3) {
            ++r.updates;
            std::string channel = readString(p);
            int x0 = read32(p), y0 = read32(p), w = read32(p), h = read32(p);
            if (p + size_t(w) * h * 4 != at + length || !r.pixels.count(channel)) {
                r.malformed = true;
                return;
            }
            for (int y = y0; y < y0 + h; ++y)
                for (int x = x0; x < x0 + w; ++x, p += 4)
                    std::memcpy(&r.pixels[channel][size_t(y) * r.width + x], buffer.data() + p, 4);
        } else {
            r.malformed = true;
            return;
        }
        at += length;
    }
    if (at != buffer.size()) r.malformed = true;
}

TEST(DisplayServer, TheViewerGetsEveryWaveAndTheFinalImage) {
    fs::path dir = fs::path(::testing::TempDir()) / ("kiln_display_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // 150 x 40 pixels: two tiles across (128 + 22)
    std::ofstream(dir / "glow.pbrt")
        << "Film \"rgb\" \"integer xresolution\" 150 \"integer yresolution\" 40\n"
           "Sampler \"independent\" \"integer pixelsamples\" 6\n"
           "LookAt 0 0 -4 0 0 0 0 1 0 Camera \"perspective\" \"float fov\" 30\nWorldBegin\n"
           "Material \"conductor\" \"float temperature\" 1400\nShape \"sphere\"\n";
    int server = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(server, 0);
    sockaddr_in addr = {};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;  // any free port
    ASSERT_EQ(::bind(server, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    socklen_t len = sizeof(addr);
    ASSERT_EQ(::getsockname(server, reinterpret_cast<sockaddr*>(&addr), &len), 0);
    ASSERT_EQ(::listen(server, 1), 0);
    Received received;
    std::thread viewer([&] {
        int fd = ::accept(server, nullptr, nullptr);
        if (fd < 0) return;
        Listen(fd, received);
        ::close(fd);
    });
    std::string address = "127.0.0.1:" + std::to_string(ntohs(addr.sin_port));
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    int status = std::system(("cd " + Q(dir.string()) + " && " + Q(kiln) +
                              " glow.pbrt --quiet -o glow.pfm --display-server " + address)
                                 .c_str());
    viewer.join();
    ::close(server);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_FALSE(received.malformed);
    EXPECT_EQ(received.creates, 1);
    EXPECT_EQ(received.name, "glow");
    EXPECT_EQ(received.width, 150);
    EXPECT_EQ(received.height, 40);
    EXPECT_EQ(received.channels, (std::vector<std::string>{"R", "G", "B"}));
    // Waves of 1, 2 and 3 samples, each sent as 3 channels x 2 tiles
    EXPECT_EQ(received.updates, 3 * 3 * 2);
    // The last update is the written image
    Image written = Image::Read((dir / "glow.pfm").string());
    double largest = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 150; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = received.pixels[received.channels[size_t(c)]][size_t(y) * 150 + x];
                ASSERT_EQ(v, written.GetChannel({x, y}, c)) << x << " " << y << " " << c;
                largest = std::max<double>(largest, v);
            }
    EXPECT_GT(largest, 0);
    fs::remove_all(dir);
}

TEST(DisplayServer, AViewerThatIsNotThereIsAWarning) {
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    fs::path dir =
        fs::path(::testing::TempDir()) / ("kiln_display_none_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "s.pbrt")
        << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
           "Camera \"perspective\"\nWorldBegin\nShape \"sphere\"\n";
    std::string log = (dir / "log.txt").string();
    int status =
        std::system(("cd " + Q(dir.string()) + " && " + Q(kiln) +
                     " s.pbrt --quiet --spp 1 -o s.exr --display-server 127.0.0.1:1 2> " + Q(log))
                        .c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_NE(testing::ReadAll(log).find("rendering without it"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "s.exr"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
