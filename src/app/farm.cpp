#include "app/farm.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "app/command_line.h"
#include "base/atomic_file.h"
#include "core/parser/parser.h"
#include "render/scene_builder.h"

namespace kiln {

namespace {

namespace fs = std::filesystem;

// A word for bash: single-quoted, quotes escaped
std::string Quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string Join(const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) {
        if (!s.empty()) s += ' ';
        s += Quote(w);
    }
    return s;
}

// Runs a command and returns its standard output (throws if it fails).
std::string Capture(const std::string& command) {
    FILE* p = popen(command.c_str(), "r");
    if (!p) throw std::runtime_error("cannot run: " + command);
    std::string out;
    char buf[512];
    while (size_t n = fread(buf, 1, sizeof(buf), p)) out.append(buf, n);
    int status = pclose(p);
    if (status != 0)
        throw std::runtime_error("failed (status " + std::to_string(status) + "): " + command +
                                 (out.empty() ? "" : "\n" + out));
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    return out;
}

}  // namespace

std::string FarmPlan::PartFile(int frame, int tile) const {
    char name[64];
    std::snprintf(name, sizeof(name), "frame%06d.tile%04d.exr", frame, tile);
    return dir + "/parts/" + name;
}

std::string FarmPlan::FrameOutput(int frame) const {
    return animation ? FrameFilename(output, frame) : output;
}

std::vector<Bounds2i> TileGrid(Point2i resolution, int n) {
    // The factor pair of n closest to the film's aspect
    int bestRows = 1;
    double best = HUGE_VAL;
    for (int rows = 1; rows <= n; ++rows) {
        if (n % rows) continue;
        int cols = n / rows;
        double tileAspect = (double(resolution.x) / cols) / (double(resolution.y) / rows);
        double cost = std::abs(std::log(tileAspect));
        if (cost < best) best = cost, bestRows = rows;
    }
    int rows = std::min(bestRows, resolution.y), cols = std::min(n / bestRows, resolution.x);
    std::vector<Bounds2i> tiles;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            tiles.push_back(
                Bounds2i{{resolution.x * c / cols, resolution.y * r / rows},
                         {resolution.x * (c + 1) / cols, resolution.y * (r + 1) / rows}});
    return tiles;
}

std::string RenderScript(const FarmPlan& p) {
    std::ostringstream s;
    const int n = int(p.tiles.size());
    s << "#!/bin/bash\n"
      << "# kiln farm: one task per tile and frame (array index = (frame - " << p.frames.first
      << ") * " << n << " + tile)\n"
      << "#SBATCH --job-name=kiln-render\n"
      << "#SBATCH --output=/dev/null\n"
      << "set -euo pipefail\n"
      << "exec >> " << Quote(p.dir + "/logs/render-")
      << "\"${SLURM_ARRAY_JOB_ID:-local}_${SLURM_ARRAY_TASK_ID:-0}.log\" 2>&1\n"
      << "TILES=(";
    for (const Bounds2i& b : p.tiles)
        s << " \"" << b.pMin.x << " " << b.pMax.x << " " << b.pMin.y << " " << b.pMax.y << "\"";
    s << " )\n"
      << "i=${SLURM_ARRAY_TASK_ID:?run as a Slurm array task}\n"
      << "frame=$(( " << p.frames.first << " + i / " << n << " ))\n"
      << "tile=$(( i % " << n << " ))\n"
      << "read -r x0 x1 y0 y1 <<< \"${TILES[$tile]}\"\n"
      << "part=" << Quote(p.dir + "/parts/frame") << "$(printf %06d \"$frame\").tile$(printf "
      << "%04d \"$tile\").exr\n"
      << "exec " << Quote(p.kiln) << " " << Quote(p.scene);
    if (p.animation) s << " --frames \"$frame-$frame\"";
    if (p.spp) s << " --spp " << *p.spp;
    s << " --pixelbounds \"$x0\" \"$x1\" \"$y0\" \"$y1\" --checkpoint 60 --quiet -o \"$part\"\n";
    return s.str();
}

std::string MergeScript(const FarmPlan& p) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# kiln farm: each frame's tiles merged (kiln merge refuses missing or foreign parts)\n"
      << "#SBATCH --job-name=kiln-merge\n"
      << "#SBATCH --output=/dev/null\n"
      << "set -euo pipefail\n"
      << "exec >> " << Quote(p.dir + "/logs/merge-") << "\"${SLURM_JOB_ID:-local}.log\" 2>&1\n";
    for (int f = p.frames.first; f <= p.frames.second; ++f) {
        std::vector<std::string> words = {p.kiln, "merge"};
        for (int t = 0; t < int(p.tiles.size()); ++t) words.push_back(p.PartFile(f, t));
        words.insert(words.end(), {"-o", p.FrameOutput(f)});
        s << Join(words) << "\n";
    }
    return s.str();
}

int RunFarm(const std::vector<std::string>& args) {
    const char* synopsis =
        "usage: kiln farm SCENE [--tiles N] [--frames A-B] [--spp N] [-o OUT]\n"
        "                 [--dry-run] [--status] [-- SBATCH OPTIONS...]\n";
    auto usage = [&](const std::string& message) {
        std::cerr << "kiln farm: " << message << "\n" << synopsis;
        return 2;
    };
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
        std::cout << synopsis;
        return 0;
    }
    FarmPlan plan;
    int tiles = 4;
    bool dryRun = false, status = false;
    std::string scene;
    try {
        for (size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            auto value = [&]() -> const std::string& {
                if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
                return args[++i];
            };
            if (a == "--") {
                plan.sbatchOptions.assign(args.begin() + long(i) + 1, args.end());
                break;
            } else if (a == "--tiles") {
                tiles = std::stoi(value());
                if (tiles < 1) throw std::invalid_argument("--tiles expects N >= 1");
            } else if (a == "--frames") {
                const std::string& v = value();
                size_t dash = v.find('-', 1);
                plan.frames.first = std::stoi(v.substr(0, dash));
                plan.frames.second =
                    dash == std::string::npos ? plan.frames.first : std::stoi(v.substr(dash + 1));
                if (plan.frames.second < plan.frames.first || plan.frames.first < 0)
                    throw std::invalid_argument("--frames expects FIRST-LAST, 0 <= FIRST <= LAST");
                plan.animation = true;
            } else if (a == "--spp") {
                plan.spp = std::stoi(value());
                if (*plan.spp < 1) throw std::invalid_argument("--spp expects N >= 1");
            } else if (a == "-o" || a == "--outfile") {
                plan.output = value();
            } else if (a == "--dry-run") {
                dryRun = true;
            } else if (a == "--status") {
                status = true;
            } else if (!a.empty() && a[0] == '-') {
                throw std::invalid_argument("unknown option '" + a + "'");
            } else if (scene.empty()) {
                scene = a;
            } else {
                throw std::invalid_argument("more than one scene file given");
            }
        }
    } catch (const std::exception& e) {
        return usage(e.what());
    }
    if (scene.empty()) return usage("no scene file given");

    // The film's resolution and file name, from the scene description
    Diagnostics diag(nullptr);
    try {
        SceneBuilder builder(diag);
        ParseFile(builder, scene, diag);
        const ParameterDictionary& film = builder.Description().film.parameters;
        plan.resolution =
            Point2i(film.GetOneInt("xresolution", 1280), film.GetOneInt("yresolution", 720));
        if (plan.output.empty()) plan.output = film.GetOneString("filename", "pbrt.exr");
    } catch (const SceneError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    if (plan.resolution.x < 1 || plan.resolution.y < 1) return usage("the film has no pixels");
    // Paths go into shell scripts quoted, and into Slurm's options: no control characters (a
    // newline would end a script line); the merge writes EXR only
    auto hasControl = [](const std::string& s) {
        return std::any_of(s.begin(), s.end(), [](char c) {
            return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        });
    };
    if (hasControl(scene)) return usage("the scene path contains a control character");
    if (hasControl(plan.output)) return usage("-o contains a control character");
    std::string extension = fs::path(plan.output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (extension != ".exr")
        return usage("kiln merge writes OpenEXR: -o must end in .exr (got '" + plan.output + "')");
    if (plan.animation && plan.frames.first != plan.frames.second &&
        plan.output.find('#') == std::string::npos)
        return usage("with --frames, -o needs '#' for the frame number");
    plan.scene = fs::absolute(scene).string();
    plan.output = fs::absolute(plan.output).string();
    std::string stem = plan.output;
    stem.erase(std::remove(stem.begin(), stem.end(), '#'), stem.end());
    plan.dir = stem + ".farm";
    plan.kiln = fs::read_symlink("/proc/self/exe").string();
    plan.tiles = TileGrid(plan.resolution, tiles);

    if (status) {
        int missing = 0;
        for (int f = plan.frames.first; f <= plan.frames.second; ++f) {
            bool merged = fs::exists(plan.FrameOutput(f));
            for (int t = 0; t < int(plan.tiles.size()); ++t)
                if (!merged && !fs::exists(plan.PartFile(f, t))) {
                    std::cout << "missing: frame " << f << " tile " << t << " (array index "
                              << (f - plan.frames.first) * int(plan.tiles.size()) + t << ")\n";
                    ++missing;
                }
        }
        std::cout << (missing ? std::to_string(missing) + " parts missing\n" : "complete\n");
        return missing ? 1 : 0;
    }

    std::string render = RenderScript(plan), merge = MergeScript(plan);
    std::string renderFile = plan.dir + "/render.sbatch", mergeFile = plan.dir + "/merge.sbatch";
    // The jobs run in the farm folder. Slurm expands '%' anywhere in a log path it is given,
    // the working folder included, so it is given none (/dev/null): the scripts send their
    // output to logs/ themselves, with bash's quoting; no path of the user's is in an #SBATCH
    // line.
    std::string chdir = " " + Quote("--chdir=" + plan.dir);
    std::string submitRender = "sbatch --parsable --array=0-" + std::to_string(plan.Tasks() - 1) +
                               chdir +
                               (plan.sbatchOptions.empty() ? "" : " " + Join(plan.sbatchOptions)) +
                               " " + Quote(renderFile);
    std::string submitMerge = "sbatch --parsable --dependency=afterok:JOB" + chdir +
                              (plan.sbatchOptions.empty() ? "" : " " + Join(plan.sbatchOptions)) +
                              " " + Quote(mergeFile);
    if (dryRun) {
        std::cout << "# " << renderFile << "\n"
                  << render << "\n# " << mergeFile << "\n"
                  << merge << "\n# submitted with\n"
                  << submitRender << "\n"
                  << submitMerge << "   (JOB: the array's job id)\n";
        return 0;
    }
    try {
        fs::create_directories(plan.dir + "/parts");
        fs::create_directories(plan.dir + "/logs");
        WriteFileAtomically(renderFile, render, true);
        WriteFileAtomically(mergeFile, merge, true);
        std::string job = Capture(submitRender);
        job = job.substr(0, job.find(';'));  // "id;cluster"
        std::string mergeCommand = submitMerge;
        mergeCommand.replace(mergeCommand.find("JOB"), 3, job);
        std::string mergeJob = Capture(mergeCommand);
        mergeJob = mergeJob.substr(0, mergeJob.find(';'));
        std::cout << "render job " << job << " (" << plan.Tasks() << " tasks), merge job "
                  << mergeJob << "\n";
    } catch (const std::exception& e) {
        std::cerr << "kiln farm: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace kiln
