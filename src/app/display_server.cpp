#include "app/display_server.h"

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace kiln {

namespace {

enum MessageType : uint8_t { kUpdateImage = 3, kCreateImage = 4 };

// Little-endian, as tev reads them (kiln builds for x86-64 and little-endian targets only)
template <typename T>
void Append(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}
void AppendString(std::string& out, const std::string& s) {
    out.append(s);
    out.push_back('\0');
}
// A message with room for its length, which Send fills in
std::string Begin(MessageType type) {
    std::string m(4, '\0');
    Append(m, uint8_t(type));
    return m;
}

}  // namespace

std::unique_ptr<DisplayServerClient> DisplayServerClient::Connect(const std::string& address) {
    size_t colon = address.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == address.size())
        throw std::runtime_error("display server \"" + address + "\": expected host:port");
    std::string host = address.substr(0, colon), port = address.substr(colon + 1);
    addrinfo hints = {};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (int e = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); e != 0)
        throw std::runtime_error("display server \"" + address + "\": " + gai_strerror(e));
    int fd = -1, err = 0;
    for (addrinfo* a = found; a && fd < 0; a = a->ai_next) {
        fd = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
        if (fd < 0) continue;
        if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0) {
            err = errno;
            ::close(fd);
            fd = -1;
        }
    }
    freeaddrinfo(found);
    if (fd < 0)
        throw std::runtime_error("display server \"" + address +
                                 "\": cannot connect: " + std::strerror(err));
    return std::unique_ptr<DisplayServerClient>(new DisplayServerClient(fd));
}

DisplayServerClient::~DisplayServerClient() {
    if (socket >= 0) ::close(socket);
}

void DisplayServerClient::Send(std::string message) {
    if (socket < 0) return;
    uint32_t length = uint32_t(message.size());
    std::memcpy(message.data(), &length, sizeof(length));
    for (size_t done = 0; done < message.size();) {
        ssize_t n = ::send(socket, message.data() + done, message.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {  // the viewer went away: stop sending, rendering goes on
            ::close(socket);
            socket = -1;
            return;
        }
        done += size_t(n);
    }
}

void DisplayServerClient::CreateImage(const std::string& name, Point2i resolution,
                                      const std::vector<std::string>& channels) {
    std::string m = Begin(kCreateImage);
    Append(m, uint8_t(1));  // grab focus
    AppendString(m, name);
    Append(m, int32_t(resolution.x));
    Append(m, int32_t(resolution.y));
    Append(m, int32_t(channels.size()));
    for (const std::string& c : channels) AppendString(m, c);
    Send(std::move(m));
}

void DisplayServerClient::UpdateImage(const std::string& name, const Image& image) {
    Point2i res = image.Resolution();
    for (int c = 0; c < image.NChannels(); ++c)
        for (int y0 = 0; y0 < res.y; y0 += kTileSize)
            for (int x0 = 0; x0 < res.x; x0 += kTileSize) {
                int w = std::min(kTileSize, res.x - x0), h = std::min(kTileSize, res.y - y0);
                std::string m = Begin(kUpdateImage);
                Append(m, uint8_t(0));
                AppendString(m, name);
                AppendString(m, image.ChannelNames()[size_t(c)]);
                for (int v : {x0, y0, w, h}) Append(m, int32_t(v));
                for (int y = y0; y < y0 + h; ++y)
                    for (int x = x0; x < x0 + w; ++x) Append(m, float(image.GetChannel({x, y}, c)));
                Send(std::move(m));
                if (socket < 0) return;
            }
}

}  // namespace kiln
