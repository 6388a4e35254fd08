// kiln farm on a real Slurm cluster. The test starts a single-node cluster on localhost from
// Debian's packages (scripts/slurm-localhost.sh: munged, slurmctld and slurmd, all files in a
// temporary directory). It submits a 4-tile, 2-frame render of a cooling hot blade with
// `kiln farm` and waits for the merge job (bounded, by a dependent `srun`). The merged
// frames must equal single-process renders bit for bit. It then re-submits one finished array
// index and the merge, as a requeue or a manual re-run would, and the frames must stay the same.
// The scene and the frames live in a folder whose name has spaces, quotes and '%'. When Slurm
// cannot start, the test fails and prints the daemons' logs; it never skips.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "app_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

struct Result {
    int status;
    std::string output;  // standard output and error
};

Result Shell(const std::string& command) {
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return {-1, "popen failed: " + command};
    std::string out;
    char buf[512];
    while (size_t n = fread(buf, 1, sizeof(buf), p)) out.append(buf, n);
    return {pclose(p), out};
}

// Every log the render and merge jobs wrote, for failure messages
std::string JobLogs(const fs::path& farmDir) {
    std::string all;
    if (fs::is_directory(farmDir / "logs"))
        for (const fs::directory_entry& e : fs::directory_iterator(farmDir / "logs"))
            all +=
                "--- " + e.path().filename().string() + "\n" + testing::ReadAll(e.path().string());
    return all;
}

// The cluster's daemons stop when the test ends, however it ends
struct Cluster {
    std::string script, dir;
    ~Cluster() { Shell("'" + script + "' stop '" + dir + "'"); }
};

TEST(SlurmCluster, FarmOnLocalhostGivesTheSingleProcessRender) {
    const fs::path dir =
        fs::path(::testing::TempDir()) / ("kiln_slurm_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    Cluster cluster{std::string(KILN_SOURCE_DIR) + "/scripts/slurm-localhost.sh",
                    (dir / "cluster").string()};
    Result start = Shell("'" + cluster.script + "' start '" + cluster.dir + "'");
    ASSERT_EQ(start.status, 0) << "a single-node Slurm cluster could not start on localhost "
                                  "(munge, slurmctld and slurmd from Debian's packages):\n"
                               << start.output;
    const std::string env = "SLURM_CONF='" + cluster.dir + "/slurm.conf' ";

    // A steel blade cooling from 1500 K: the two frames differ in time, so in temperature. In
    // a folder whose name the farm's scripts and Slurm's options must quote or escape.
    const fs::path work = dir / "farm 'q' \"dq\" 100%A";
    fs::create_directories(work);
    const auto Q = testing::ShellQuote;
    const fs::path scene = work / "blade.pbrt";
    std::ofstream(scene)
        << "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 20\n"
           "Sampler \"zsobol\" \"integer pixelsamples\" 8\n"
           "LookAt 0 0.3 -0.4  0 0 0.02  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.2 0.2 0.25]\n"
           "Texture \"heat\" \"float\" \"cooling\" \"float T0\" 1500 \"float emissivity\" 0.8\n"
           "    \"float area\" 0.048 \"float mass\" 0.094 \"float specificheat\" 490\n"
           "Material \"conductor\" \"spectrum eta\" \"metal-Fe-eta\" \"spectrum k\" "
           "\"metal-Fe-k\"\n"
           "    \"float roughness\" 0.2 \"texture temperature\" \"heat\"\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2  0 2 3]\n"
           "    \"point3 P\" [-0.2 0 -0.03  0.12 0 -0.03  0.12 0 0.03  -0.2 0 0.03]\n";
    const fs::path farmDir = work / "blade.exr.farm";
    const std::string farm = env + Q(kiln) + " farm " + Q(scene.string()) +
                             " --tiles 4 --frames 0-1 --spp 8 -o " +
                             Q((work / "blade#.exr").string());
    Result submit = Shell(farm);
    ASSERT_EQ(submit.status, 0) << submit.output;
    std::smatch ids;
    ASSERT_TRUE(std::regex_search(submit.output, ids,
                                  std::regex(R"(render job (\d+) \(8 tasks\), merge job (\d+))")))
        << submit.output;
    const std::string renderJob = ids[1], mergeJob = ids[2];

    // Waits for a job (bounded) and checks that it, and every task of an array, completed.
    // srun blocks until a step that depends on the job can run (a failed render cancels the
    // merge: kill_invalid_depend) and is woken by slurmctld, with no polling.
    auto expectCompleted = [&](const std::string& job, int tasks) {
        Result wait =
            Shell(env + "timeout 300 srun --quiet --dependency=afterany:" + job + " true");
        ASSERT_EQ(wait.status, 0) << "waiting for job " << job << ": " << wait.output
                                  << JobLogs(farmDir);
        Result state = Shell(env + "scontrol -o show job " + job);
        std::istringstream lines(state.output);  // one line per array task
        std::string line;
        int n = 0;
        for (; std::getline(lines, line); ++n)
            EXPECT_NE(line.find("JobState=COMPLETED"), std::string::npos) << line << "\n"
                                                                          << JobLogs(farmDir);
        EXPECT_EQ(n, tasks) << state.output;
    };
    expectCompleted(renderJob, 8);
    expectCompleted(mergeJob, 1);
    Result status = Shell(env + farm.substr(env.size()) + " --status");
    EXPECT_EQ(status.status, 0) << status.output;

    // Each frame as one process renders it
    std::vector<float> single[2];
    for (int f = 0; f < 2; ++f) {
        const fs::path out = work / ("single" + std::to_string(f) + ".exr");
        Result r = Shell(Q(kiln) + " " + Q(scene.string()) + " --frames " + std::to_string(f) +
                         "-" + std::to_string(f) + " --spp 8 --quiet -o " + Q(out.string()));
        ASSERT_EQ(r.status, 0) << r.output;
        single[f] = testing::Pixels(out.string());
        EXPECT_EQ(testing::Pixels((work / ("blade" + std::to_string(f) + ".exr")).string()),
                  single[f])
            << "frame " << f;
    }
    EXPECT_NE(single[0], single[1]) << "the frames should differ (the blade cools)";

    // A re-run of a finished task (Slurm's requeue, or a manual re-submit) and of the merge
    // overwrite their own outputs with the same pixels
    for (const char* script : {"--array=5 render.sbatch", "merge.sbatch"}) {
        Result job = Shell("cd " + Q(farmDir.string()) + " && " + env + "sbatch --parsable " +
                           std::string(script));
        ASSERT_EQ(job.status, 0) << job.output;
        expectCompleted(job.output.substr(0, job.output.find_first_of(";\n")), 1);
    }
    for (int f = 0; f < 2; ++f)
        EXPECT_EQ(testing::Pixels((work / ("blade" + std::to_string(f) + ".exr")).string()),
                  single[f])
            << "frame " << f << " after a re-run";
    Shell("'" + cluster.script + "' stop '" + cluster.dir + "'");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
