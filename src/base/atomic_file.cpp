#include "base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace kiln {

namespace {

// The temporaries of path are <folder>/<name>.tmp.XXXXXX, the name shortened so that the
// whole fits NAME_MAX (255 bytes on Linux file systems)
std::string TemporaryPrefix(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path target(path);
    std::string name = target.filename().string() + ".tmp.";
    constexpr size_t kMaxName = 255, kRandom = 6;
    if (name.size() + kRandom > kMaxName) {
        name.resize(kMaxName - kRandom - 5);
        name += ".tmp.";
    }
    return (target.parent_path() / name).string();
}

// The temporary being written, for RemovePendingTemporaryFile (see the header)
char pendingTemporary[4096];
std::atomic<bool> pendingSlotTaken{false}, hasPendingTemporary{false};

}  // namespace

void RemovePendingTemporaryFile() noexcept {
    if (hasPendingTemporary.load()) unlink(pendingTemporary);
}

void WriteFileAtomically(const std::string& path, std::string_view data, bool executable) {
    auto fail = [&](const std::string& what, int err) {
        throw std::runtime_error(path + ": " + what + ": " + std::strerror(err));
    };
    // mkstemp creates the file with O_CREAT | O_EXCL under a name no other file has
    std::string pattern = TemporaryPrefix(path) + "XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = mkstemp(name.data());
    if (fd < 0) fail("cannot create a temporary file beside it", errno);
    std::string tmp(name.data());
    // One writer at a time is remembered (the first); the others are cleaned up by
    // RemoveStaleTemporaries when their target is next written
    bool pending = tmp.size() < sizeof(pendingTemporary) && !pendingSlotTaken.exchange(true);
    if (pending) {
        std::memcpy(pendingTemporary, tmp.c_str(), tmp.size() + 1);
        hasPendingTemporary.store(true);
    }
    struct Forget {
        bool pending;
        ~Forget() {
            if (!pending) return;
            hasPendingTemporary.store(false);
            pendingSlotTaken.store(false);
        }
    } forget{pending};
    auto abandon = [&](const std::string& what, int err) {
        if (fd >= 0) close(fd);
        unlink(tmp.c_str());
        fail(what, err);
    };
    if (fchmod(fd, executable ? 0755 : 0644) != 0) abandon("cannot set permissions", errno);
    for (size_t done = 0; done < data.size();) {
        ssize_t n = write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) abandon("cannot write", n < 0 ? errno : ENOSPC);
        done += size_t(n);
    }
    if (fsync(fd) != 0) abandon("cannot flush", errno);
    int closed = close(fd);
    fd = -1;
    if (closed != 0) abandon("cannot close", errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) abandon("cannot rename into place", errno);
}

void RemoveStaleTemporaries(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path target(path);
    fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string prefix = fs::path(TemporaryPrefix(path)).filename().string();
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (name.size() == prefix.size() + 6 && name.compare(0, prefix.size(), prefix) == 0 &&
            it->is_regular_file(ec) && !it->is_symlink(ec))
            fs::remove(it->path(), ec);
    }
}

}  // namespace kiln
