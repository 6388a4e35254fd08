// SIGTERM (what Slurm and other schedulers send) and SIGINT stop the kiln command cleanly: the
// image rendered so far is written atomically, marked partial with the samples it holds, the
// exit status is 128 + the signal, and no temporary file is left behind. A render with
// --checkpoint killed outright (SIGKILL, as a preempted job) and started again with the same
// command resumes and ends bit-identical to an uninterrupted render. Runs the kiln binary.
#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "app/checkpoint.h"
#include "app_test_util.h"
#include "core/image/image.h"

extern char** environ;

namespace kiln {
namespace {

namespace fs = std::filesystem;

struct Child {
    pid_t pid = -1;
    int stderrFd = -1;
};

// Starts the kiln binary with `args`, its standard error on a pipe.
Child Spawn(const std::vector<std::string>& args) {
    int fds[2];
    EXPECT_EQ(pipe(fds), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    std::string binary = std::string(KILN_BINARY_DIR) + "/kiln";
    std::vector<char*> argv = {binary.data()};
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    Child c;
    EXPECT_EQ(posix_spawn(&c.pid, binary.c_str(), &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    c.stderrFd = fds[0];
    return c;
}

// Reads the child's standard error until `marker` appears (true) or it ends (false).
bool ReadUntil(int fd, const std::string& marker, std::string* seen) {
    char buf[4096];
    while (seen->find(marker) == std::string::npos) {
        ssize_t n = read(fd, buf, sizeof(buf));
        if (n <= 0) return false;
        seen->append(buf, size_t(n));
    }
    return true;
}

int ExitStatus(const Child& c) {
    int status = 0;
    EXPECT_EQ(waitpid(c.pid, &status, 0), c.pid);
    close(c.stderrFd);
    EXPECT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct SceneDir {
    fs::path path =
        fs::temp_directory_path() / ("kiln_signals_" + std::to_string(std::random_device()()));
    SceneDir() {
        fs::create_directories(path);
        // Far more samples than the test waits for: only a signal ends this render early
        std::ofstream(path / "scene.pbrt") << R"(
Film "rgb" "integer xresolution" 64 "integer yresolution" 64
Sampler "independent" "integer pixelsamples" 1000000
LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective"
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "conductor" "float roughness" 0.3
Shape "sphere"
)";
    }
    ~SceneDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::vector<std::string> Files() const {
        std::vector<std::string> names;
        for (auto& e : fs::directory_iterator(path)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
};

class Signals : public ::testing::TestWithParam<int> {};

TEST_P(Signals, StopRenderingAndWriteThePartialImage) {
    const int signal = GetParam();
    SceneDir dir;
    std::string out = (dir.path / "out.exr").string();
    Child c = Spawn({(dir.path / "scene.pbrt").string(), "--verbose", "--threads", "1", "-o", out});
    std::string seen;
    // The choices line comes after loading: from there on, the render runs
    ASSERT_TRUE(ReadUntil(c.stderrFd, "chosen:", &seen)) << seen;
    kill(c.pid, signal);
    ReadUntil(c.stderrFd, "\x04", &seen);  // the rest, to the end
    EXPECT_EQ(ExitStatus(c), 128 + signal) << seen;
    EXPECT_EQ(dir.Files(), (std::vector<std::string>{"out.exr", "scene.pbrt"})) << seen;
    ImageMetadata metadata;
    Image image = Image::Read(out, &metadata);
    EXPECT_EQ(metadata.strings["kiln:partial"], "true");
    ASSERT_TRUE(metadata.samplesPerPixel.has_value());
    EXPECT_LT(*metadata.samplesPerPixel, 1000000);
    EXPECT_NE(seen.find("(interrupted)"), std::string::npos) << seen;
}

TEST_P(Signals, ASecondSignalEndsAtOnceLeavingNoTemporaryFile) {
    const int signal = GetParam();
    SceneDir dir;
    std::string out = (dir.path / "out.png").string();
    Child c = Spawn({(dir.path / "scene.pbrt").string(), "--verbose", "--threads", "1", "-o", out});
    std::string seen;
    ASSERT_TRUE(ReadUntil(c.stderrFd, "chosen:", &seen)) << seen;
    kill(c.pid, signal);
    kill(c.pid, signal);
    ReadUntil(c.stderrFd, "\x04", &seen);
    EXPECT_EQ(ExitStatus(c), 128 + signal) << seen;
    // Either the image was written whole before the second signal, or nothing was
    for (const std::string& name : dir.Files())
        EXPECT_TRUE(name == "scene.pbrt" || name == "out.png") << name;
}

INSTANTIATE_TEST_SUITE_P(TermAndInt, Signals, ::testing::Values(SIGTERM, SIGINT),
                         [](const auto& info) {
                             return std::string(info.param == SIGTERM ? "SIGTERM" : "SIGINT");
                         });

// Runs the kiln binary with args and then extra to its end; returns what it wrote to stderr
// (expecting exit status 0).
std::string RunToEnd(std::vector<std::string> args, const std::vector<std::string>& extra) {
    args.insert(args.end(), extra.begin(), extra.end());
    Child c = Spawn(args);
    std::string seen;
    ReadUntil(c.stderrFd, "\x04", &seen);
    EXPECT_EQ(ExitStatus(c), 0) << seen;
    return seen;
}

// Runs the kiln binary with args (and --checkpoint 0 --verbose) until it has written
// `checkpoints` checkpoints, then kills it with SIGKILL: what a preempted job leaves.
void KillAfterCheckpoints(std::vector<std::string> args, int checkpoints = 1) {
    args.insert(args.end(), {"--checkpoint", "0", "--verbose"});
    Child c = Spawn(args);
    std::string seen;
    for (int k = 0; k < checkpoints; ++k)
        EXPECT_TRUE(ReadUntil(c.stderrFd, "checkpoint at", &seen));
    kill(c.pid, SIGKILL);
    int status = 0;
    waitpid(c.pid, &status, 0);
    close(c.stderrFd);
}

TEST(Checkpoints, AKilledRenderResumesBitIdentical) {
    SceneDir dir;
    std::string scene = (dir.path / "scene.pbrt").string();
    std::string ref = (dir.path / "ref.exr").string(), out = (dir.path / "out.exr").string();
    const std::vector<std::string> common = {scene, "--spp", "96", "--seed", "7", "--threads", "2"};
    auto run = [&](const std::vector<std::string>& extra) { return RunToEnd(common, extra); };
    run({"-o", ref, "--quiet"});
    // Killed after some checkpoints (a different number each time), then resumed
    for (int kills : {1, 5}) {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"-o", out});
        KillAfterCheckpoints(args, kills);
        ASSERT_TRUE(fs::exists(out + ".checkpoint"));
        std::string resumed = run({"-o", out, "--checkpoint", "0"});
        EXPECT_NE(resumed.find("resuming from"), std::string::npos) << resumed;
        EXPECT_EQ(testing::Pixels(out), testing::Pixels(ref)) << kills;
        // Done: no checkpoint is left
        EXPECT_EQ(dir.Files(), (std::vector<std::string>{"out.exr", "ref.exr", "scene.pbrt"}));
    }
    // A checkpoint of the same scene, seed and pixels rendered with other options (another
    // emission model) is another render: ignored, with a warning
    {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"-o", out});
        KillAfterCheckpoints(args);
        ASSERT_TRUE(fs::exists(out + ".checkpoint"));
        std::string other = run({"-o", out, "--checkpoint", "0", "--emission", "additive"});
        EXPECT_NE(other.find("another render"), std::string::npos) << other;
        EXPECT_EQ(other.find("resuming from"), std::string::npos) << other;
        // (the scene has nothing hot, so the additive render is the same image)
        EXPECT_EQ(testing::Pixels(out), testing::Pixels(ref));
    }
    // A damaged checkpoint, or one of another render, is ignored (with a warning): the render
    // starts over and still ends the same
    std::ofstream(out + ".checkpoint") << "kiln checkpoint 1\nscene 0\n\ngarbage";
    std::string again = run({"-o", out, "--checkpoint", "0"});
    EXPECT_NE(again.find("ignoring"), std::string::npos) << again;
    EXPECT_EQ(testing::Pixels(out), testing::Pixels(ref));
}

// A checkpoint whose sums were damaged is not resumed (issue 23: a NaN written into them ended
// in the final image): a changed byte fails the checksum, and a NaN with a matching checksum
// (as a careless tool would write) fails the film's check that every sum is finite. Each is
// ignored with a warning and the render ends as an uninterrupted one.
TEST(Checkpoints, DamagedCheckpointsAreNotResumed) {
    SceneDir dir;
    std::string scene = (dir.path / "scene.pbrt").string();
    std::string ref = (dir.path / "ref.exr").string(), out = (dir.path / "out.exr").string();
    const std::string checkpoint = out + ".checkpoint";
    const std::vector<std::string> common = {scene, "--spp", "96", "--seed", "5", "--threads", "2"};
    auto run = [&](const std::vector<std::string>& extra) { return RunToEnd(common, extra); };
    run({"-o", ref, "--quiet"});
    auto killedCheckpoint = [&] {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"-o", out});
        KillAfterCheckpoints(args);
        return testing::ReadAll(checkpoint);
    };
    for (bool fixChecksum : {false, true}) {
        std::string bytes = killedCheckpoint();
        size_t state = bytes.find("\n\n");
        ASSERT_NE(state, std::string::npos);
        // The first pixel's red sum: after the film state's magic (8 bytes) and layout (56)
        const double nan = std::nan("");
        std::memcpy(&bytes[state + 2 + 8 + 56], &nan, sizeof(nan));
        if (fixChecksum) {
            bytes.resize(bytes.size() - kCheckpointChecksumLineBytes);
            bytes += CheckpointChecksumLine(bytes);
        }
        std::ofstream(checkpoint, std::ios::binary) << bytes;
        std::string seen = run({"-o", out, "--checkpoint", "0"});
        EXPECT_NE(seen.find(fixChecksum ? "holds values kiln never writes"
                                        : "its checksum does not match"),
                  std::string::npos)
            << seen;
        EXPECT_EQ(seen.find("resuming from"), std::string::npos) << seen;
        EXPECT_EQ(testing::Pixels(out), testing::Pixels(ref)) << fixChecksum;
    }
}

// A checkpoint is another render's once any file the scene read has changed since (issue 23:
// only the main scene file was hashed, so a render resumed after an included file changed
// blended two renders): an Include and a spectrum file, each changed between the kill and the
// resumption, make the checkpoint ignored; unchanged, it is resumed.
TEST(Checkpoints, ACheckpointOfChangedInputsIsAnotherRender) {
    SceneDir dir;
    const fs::path scene = dir.path / "main.pbrt", include = dir.path / "world.pbrt",
                   spectrum = dir.path / "eta.spd";
    std::ofstream(scene) << R"(Film "rgb" "integer xresolution" 32 "integer yresolution" 32
Sampler "independent" "integer pixelsamples" 1000000
LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective"
WorldBegin
Include "world.pbrt"
)";
    std::ofstream(include) << R"(LightSource "infinite" "rgb L" [1 1 1]
Material "conductor" "spectrum eta" "eta.spd" "spectrum k" "metal-Cu-k"
Shape "sphere"
)";
    std::ofstream(spectrum) << "300 0.3\n900 0.4\n";
    std::string out = (dir.path / "out.exr").string();
    const std::vector<std::string> common = {scene.string(), "--spp", "64", "--threads", "2"};
    for (const fs::path* changed : {(const fs::path*)nullptr, &include, &spectrum}) {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"-o", out});
        KillAfterCheckpoints(args);
        if (changed) std::ofstream(*changed, std::ios::app) << "# changed\n";
        std::string resumed = RunToEnd(common, {"-o", out, "--checkpoint", "0"});
        if (changed) {
            EXPECT_NE(resumed.find("another render"), std::string::npos) << *changed << resumed;
            EXPECT_EQ(resumed.find("resuming from"), std::string::npos) << *changed << resumed;
        } else {
            EXPECT_NE(resumed.find("resuming from"), std::string::npos) << resumed;
        }
    }
}

// What else may be found where the checkpoint goes: a directory, a FIFO, a link to /dev/zero, a
// link planted at any name kiln might write through. None of them hangs, crashes or is written
// through: each is ignored with a warning, the render ends as an uninterrupted one, and what the
// name pointed at is untouched.
TEST(Checkpoints, HostileCheckpointFilesAreIgnoredNotFollowed) {
    SceneDir dir;
    std::string scene = (dir.path / "scene.pbrt").string();
    std::string ref = (dir.path / "ref.exr").string(), out = (dir.path / "out.exr").string();
    const std::string checkpoint = out + ".checkpoint";
    const std::vector<std::string> common = {scene, "--spp", "24", "--seed", "3", "--threads", "2"};
    auto run = [&](const std::vector<std::string>& extra) { return RunToEnd(common, extra); };
    run({"-o", ref, "--quiet"});
    const fs::path victim = dir.path / "victim.txt";
    auto plant = [&](const std::string& kind) {
        fs::remove_all(checkpoint);
        if (kind == "directory") fs::create_directories(fs::path(checkpoint) / "inside");
        if (kind == "fifo") {
            ASSERT_EQ(mkfifo(checkpoint.c_str(), 0644), 0);
        }
        if (kind == "devzero") fs::create_symlink("/dev/zero", checkpoint);
        if (kind == "link") {
            std::ofstream(victim) << "precious";
            fs::create_symlink(victim, checkpoint);
            for (const char* suffix : {".writing", ".tmp"})
                fs::create_symlink(victim, checkpoint + suffix);
        }
    };
    for (const std::string kind : {"directory", "fifo", "devzero", "link"}) {
        SCOPED_TRACE(kind);
        plant(kind);
        std::string seen = run({"-o", out, "--checkpoint", "0"});
        if (kind != "link") {
            EXPECT_NE(seen.find("ignoring"), std::string::npos) << seen;
        }
        EXPECT_EQ(testing::Pixels(out), testing::Pixels(ref));
        if (kind == "directory") {
            EXPECT_TRUE(fs::is_directory(fs::path(checkpoint) / "inside"));
        }
        if (kind == "link") {
            EXPECT_EQ(testing::ReadAll(victim.string()), "precious");
        }
        fs::remove_all(checkpoint);
        for (const char* suffix : {".writing", ".tmp"}) fs::remove(checkpoint + suffix);
    }
}

}  // namespace
}  // namespace kiln
