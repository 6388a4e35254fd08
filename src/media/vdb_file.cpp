#include "media/vdb_file.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/memory_budget.h"
#include "base/plugin.h"
#include "base/system_memory.h"
#include "core/parser/diagnostics.h"
#include "media/nanovdb_file.h"
#include "media/nanovdb_volume.h"
#include "media/vdb_reader.h"

namespace kiln {

namespace {

// Reading in a child process
//
// OpenVDB trusts the lengths and counts a file states: a damaged .vdb (a garbage name length or
// grid count, a flipped byte in a tree, a truncated file) made it allocate gigabytes or grow
// without end, and end in std::bad_alloc. kiln reads a .vdb in a child process whose address
// space may grow by no more than the memory the scene may still commit (--memory-limit, else
// half the machine's memory); the child sends the dense grids through a pipe. A child that runs
// out of that memory, fails or crashes is an error naming the file, and the scene is unharmed.

struct VDBHeader {
    int32_t status = 0;  // 0: grids follow; 1: error message follows; 2: out of memory
    int32_t box[6] = {};
    int32_t hasTemperature = 0;
    double indexToWorld[16] = {};
    uint64_t messageBytes = 0;
};

bool WriteAll(int fd, const void* data, size_t n) {
    auto p = static_cast<const char*>(data);
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w, n -= size_t(w);
    }
    return true;
}

bool ReadAll(int fd, void* data, size_t n) {
    auto p = static_cast<char*>(data);
    while (n > 0) {
        ssize_t r = read(fd, p, n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        p += r, n -= size_t(r);
    }
    return true;
}

// The bytes of address space the process uses now (/proc/self/statm), 0 if unknown
double AddressSpaceBytes() {
    unsigned long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    return double(pages) * double(sysconf(_SC_PAGESIZE));
}

using OpenVDB = VDBFileReader* (*)(const char*, const char*, const char*);

}  // namespace
}  // namespace kiln

// Set by a sanitizer runtime, if one is linked (weak: null otherwise). A fuzzer's death
// callback would record the child's running out of memory as a crash of the fuzzer.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace kiln {
namespace {

// The child: reads, sends, exits (never returns)
[[noreturn]] void ReadInChild(int fd, OpenVDB open, const std::string& filename,
                              const std::string& densityName, const std::string& temperatureName,
                              size_t maxVoxels, double allowance, double cpuSeconds) {
    // The parent's handlers (kiln's interrupt handling, a sanitizer's or fuzzer's crash
    // reports) are not the child's: a crash ends it, and the parent reports it
    for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGINT, SIGTERM})
        signal(sig, SIG_DFL);
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
    signal(SIGPIPE, SIG_IGN);
    rlimit limit;
    double cap = AddressSpaceBytes() + allowance;
    limit.rlim_cur = limit.rlim_max = cap < 9e18 ? rlim_t(cap) : RLIM_INFINITY;
    setrlimit(RLIMIT_AS, &limit);
    // A damaged count can also make OpenVDB loop on a failed stream for a very long time
    rlimit cpu;
    cpu.rlim_cur = cpu.rlim_max = rlim_t(cpuSeconds);
    setrlimit(RLIMIT_CPU, &cpu);
    VDBHeader h;
    std::string message;
    std::vector<float> d, t;
    try {
        std::unique_ptr<VDBFileReader> file(
            open(filename.c_str(), densityName.c_str(), temperatureName.c_str()));
        std::array<int, 6> box = file->ActiveBox();
        for (int i = 0; i < 6; ++i) h.box[i] = box[i];
        h.hasTemperature = file->HasTemperature();
        std::array<double, 16> m = file->IndexToWorld();
        for (int i = 0; i < 16; ++i) h.indexToWorld[i] = m[i];
        size_t n = size_t(int64_t(box[3]) - box[0] + 1) * size_t(int64_t(box[4]) - box[1] + 1) *
                   size_t(int64_t(box[5]) - box[2] + 1);
        if (n <= maxVoxels) {  // else the parent refuses it from the box
            d.resize(n);
            t.resize(h.hasTemperature ? n : 0);
            file->ReadDense(d.data(), h.hasTemperature ? t.data() : nullptr);
        }
    } catch (const std::bad_alloc&) {
        h.status = 2;
    } catch (const std::exception& e) {
        h.status = 1;
        message = e.what();
    } catch (...) {
        h.status = 1;
        message = "OpenVDB failed to read it";
    }
    h.messageBytes = message.size();
    bool ok = WriteAll(fd, &h, sizeof(h)) && WriteAll(fd, message.data(), message.size()) &&
              WriteAll(fd, d.data(), d.size() * sizeof(float)) &&
              WriteAll(fd, t.data(), t.size() * sizeof(float));
    _exit(ok ? 0 : 1);
}

}  // namespace

VDBVolume ReadVDBVolume(const std::string& filename, const std::string& densityName,
                        const std::string& temperatureName, const FileLoc& loc, size_t maxVoxels,
                        MemoryBudget* budget) {
    // NanoVDB files: by their magic number, or by name (then their reader says what is wrong)
    std::string magic(8, '\0');
    if (std::FILE* f = std::fopen(filename.c_str(), "rb")) {
        magic.resize(std::fread(magic.data(), 1, magic.size(), f));
        std::fclose(f);
    }
    if (NanoVDBFile::HasMagic(magic) ||
        (filename.size() >= 5 && filename.compare(filename.size() - 5, 5, ".nvdb") == 0))
        return ReadNanoVDBVolume(filename, densityName, temperatureName, loc, maxVoxels, budget);
    auto fail = [&](const std::string& why) {
        throw SceneError(loc, filename + ": " + why, filename);
    };
    OpenVDB open;
    try {  // loaded here, before the child exists
        open = reinterpret_cast<OpenVDB>(PluginSymbol("libkiln_openvdb.so", kOpenVDBFileSymbol));
    } catch (const std::runtime_error& e) {
        fail(e.what());
    }
    double allowance = budget ? budget->Remaining() : PhysicalMemoryBytes() / 2;
    // Time to read it: 2 s of CPU and 1 s per 10 MB (OpenVDB reads hundreds of MB/s). A child
    // that hangs without spending CPU time is ended after ten times that, at least 30 s, of wall
    // time: on a loaded machine starting the child and OpenVDB alone can take seconds (4 s
    // once, under a parallel test suite), which is no sign of a damaged file
    std::error_code ec;
    double fileBytes = double(std::filesystem::file_size(filename, ec));
    double cpuSeconds = 2 + (ec ? 0 : fileBytes / 10e6);
    if (!(allowance > 0)) allowance = 1e18;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) fail(std::string("cannot read it: ") + std::strerror(errno));
    pid_t child = fork();
    if (child < 0) {
        close(fds[0]), close(fds[1]);
        fail(std::string("cannot read it: ") + std::strerror(errno));
    }
    if (child == 0) {
        close(fds[0]);
        ReadInChild(fds[1], open, filename, densityName, temperatureName, maxVoxels, allowance,
                    cpuSeconds);
    }
    close(fds[1]);
    struct Reap {  // the child ends, whatever happens here
        int fd;
        pid_t child;
        int status = 0;
        ~Reap() { Wait(); }
        int Wait() {
            if (fd >= 0) close(fd), fd = -1;
            while (child > 0 && waitpid(child, &status, 0) < 0 && errno == EINTR) {
            }
            child = -1;
            return status;
        }
    } reap{fds[0], child};
    auto childFailure = [&] {
        int status = reap.Wait();
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
            return "OpenVDB did not finish reading it in " + std::to_string(int(cpuSeconds)) +
                   " s of CPU time: the file is damaged";
        if (WIFSIGNALED(status))
            return "OpenVDB crashed reading it (signal " + std::to_string(WTERMSIG(status)) +
                   "): the file is damaged";
        return std::string("OpenVDB failed to read it: the file is damaged");
    };
    pollfd ready{reap.fd, POLLIN, 0};
    int polled;
    const double wallSeconds = std::max(30.0, 10 * cpuSeconds);
    while ((polled = poll(&ready, 1, int(1000 * std::min(wallSeconds, 2e6)))) < 0 &&
           errno == EINTR) {
    }
    if (polled == 0) {
        kill(reap.child, SIGKILL);
        fail("OpenVDB did not finish reading it in " + std::to_string(int(wallSeconds)) +
             " s: the file is damaged");
    }
    VDBHeader h;
    if (!ReadAll(reap.fd, &h, sizeof(h))) fail(childFailure());
    if (h.status == 2)
        fail("reading it needed more memory than the " +
             std::string(budget && budget->Explicit() ? "--memory-limit leaves"
                                                      : "half of the machine's memory allows") +
             ": the file is damaged or too large");
    if (h.status == 1) {
        // OpenVDB's message may quote the damage: printable characters, at most 200
        std::string message(std::min<uint64_t>(h.messageBytes, 4096), '\0'), shown;
        ReadAll(reap.fd, message.data(), message.size());
        for (char c : message)
            if (c >= 32 && c < 127 && !(c == ' ' && !shown.empty() && shown.back() == ' '))
                shown += c;
        if (shown.size() > 200) shown = shown.substr(0, 200) + "...";
        fail(shown + " (the file is damaged or not a .vdb volume)");
    }
    const int64_t nx = int64_t(h.box[3]) - h.box[0] + 1, ny = int64_t(h.box[4]) - h.box[1] + 1,
                  nz = int64_t(h.box[5]) - h.box[2] + 1;
    if (nx <= 0 || ny <= 0 || nz <= 0) fail("the density grid has no active voxels");
    // The dense grid kiln keeps has one more layer each way (below)
    double voxels = double(nx + 1) * double(ny + 1) * double(nz + 1);
    const bool hasTemperature = h.hasTemperature != 0;
    ChargeDenseVolume(voxels, hasTemperature, filename, densityName, loc, maxVoxels, budget);
    // Dense copies over the density's active box; temperatures sampled (trilinearly) at the
    // density's voxel centres
    const size_t nRead = size_t(nx * ny * nz);  // what the reader sends
    std::vector<Float> d(nRead), t(hasTemperature ? nRead : 0);
    if (!ReadAll(reap.fd, d.data(), nRead * sizeof(Float)) ||
        !ReadAll(reap.fd, t.data(), t.size() * sizeof(Float)))
        fail(childFailure());
    if (int status = reap.Wait(); !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail("OpenVDB failed to read it: the file is damaged");
    // One more layer of the background (0) beyond the far faces: inside the box [min, max + 1]
    // values fade from the last voxels to it, as NanoVDB's sampler gives them
    const int64_t px = nx + 1, py = ny + 1, pz = nz + 1;
    auto pad = [&](const std::vector<Float>& in) {
        std::vector<Float> out(size_t(px * py * pz), 0.f);
        for (int64_t z = 0; z < nz; ++z)
            for (int64_t y = 0; y < ny; ++y)
                std::copy_n(in.begin() + (z * ny + y) * nx, nx, out.begin() + (z * py + y) * px);
        return out;
    };
    VDBVolume v;
    v.density = SampledGrid<Float>(pad(d), int(px), int(py), int(pz));
    if (hasTemperature) v.temperature = SampledGrid<Float>(pad(t), int(px), int(py), int(pz));
    // As a NanoVDB file converted from it (nanovdb_volume.cpp, pbrt-v4's NanoVDBMedium): the
    // medium fills the index box [min, max + 1] and voxel values sit at integer coordinates
    v.indexBounds = Bounds3f(Point3f(h.box[0], h.box[1], h.box[2]),
                             Point3f(h.box[3] + 1.f, h.box[4] + 1.f, h.box[5] + 1.f));
    v.sampleBounds = Bounds3f(Point3f(h.box[0] - 0.5f, h.box[1] - 0.5f, h.box[2] - 0.5f),
                              Point3f(h.box[3] + 1.5f, h.box[4] + 1.5f, h.box[5] + 1.5f));
    Float c[16];
    for (int i = 0; i < 16; ++i) c[i] = Float(h.indexToWorld[i]);
    v.mediumFromIndex = Transform(SquareMatrix4(c));
    return v;
}

size_t ChargeDenseVolume(double voxels, bool withTemperature, const std::string& filename,
                         const std::string& densityName, const FileLoc& loc, size_t maxVoxels,
                         MemoryBudget* budget) {
    if (voxels > double(maxVoxels))
        throw SceneError(loc,
                         filename + ": the density grid spans " + std::to_string(uint64_t(voxels)) +
                             " voxels; kiln resamples volumes densely and allows at most " +
                             std::to_string(maxVoxels),
                         densityName);
    size_t n = size_t(voxels);
    if (budget) {
        try {
            budget->Charge(
                double(n) * sizeof(Float) * (withTemperature ? 2 : 1),
                "the dense grids of \"" + filename + "\" (" + std::to_string(n) + " voxels)");
        } catch (const MemoryLimitError& e) {
            throw SceneError(loc, e.what(), filename);
        }
    }
    return n;
}

}  // namespace kiln
