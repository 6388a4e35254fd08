#include "base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace kiln {

void WriteFileAtomically(const std::string& path, std::string_view data, bool executable) {
    auto fail = [&](const std::string& what, int err) {
        throw std::runtime_error(path + ": " + what + ": " + std::strerror(err));
    };
    // mkstemp creates the file with O_CREAT | O_EXCL under a name no other file has
    std::string pattern = path + ".tmp.XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = mkstemp(name.data());
    if (fd < 0) fail("cannot create a temporary file beside it", errno);
    std::string tmp(name.data());
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
    std::string prefix = target.filename().string() + ".tmp.";
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (name.size() == prefix.size() + 6 && name.compare(0, prefix.size(), prefix) == 0 &&
            it->is_regular_file(ec) && !it->is_symlink(ec))
            fs::remove(it->path(), ec);
    }
}

}  // namespace kiln
