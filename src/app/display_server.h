// pbrt-v4's --display-server host:port: the image being rendered, sent to a viewer that speaks
// tev's protocol (tev, https://github.com/Tom94/tev, listens on 127.0.0.1:14158 by default) so
// that a render can be watched as it converges.
//
// Messages (tev's IPC format; little-endian; strings are NUL-terminated): a uint32 length of
// the whole message including itself, a uint8 type, then
//   CreateImage (4): uint8 grabFocus, string image name, int32 width, height, channel count,
//                    then the channel names;
//   UpdateImage (3): uint8 grabFocus, string image name, string channel name, int32 x, y,
//                    width, height of a tile, then width x height float values, row by row.
// Tiles are at most 128 x 128 pixels.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/image/image.h"

namespace kiln {

class DisplayServerClient {
  public:
    // Connects to "host:port"; throws std::runtime_error naming the address when it cannot.
    static std::unique_ptr<DisplayServerClient> Connect(const std::string& address);
    ~DisplayServerClient();
    DisplayServerClient(const DisplayServerClient&) = delete;
    DisplayServerClient& operator=(const DisplayServerClient&) = delete;

    // Opens an image of the given size and channels in the viewer.
    void CreateImage(const std::string& name, Point2i resolution,
                     const std::vector<std::string>& channels);
    // Sends every channel of `image` (named as in CreateImage) to the image `name`, tile by tile.
    void UpdateImage(const std::string& name, const Image& image);
    // False once a send failed (the viewer closed): later calls do nothing.
    bool Connected() const { return socket >= 0; }

    static constexpr int kTileSize = 128;

  private:
    explicit DisplayServerClient(int socket) : socket(socket) {}
    void Send(std::string message);

    int socket = -1;
};

}  // namespace kiln
