// `kiln farm`: a render split into tiles and frames as a Slurm job array, plus a merge job
// that runs when every task has succeeded (sbatch --dependency=afterok). kiln writes the batch
// scripts and calls sbatch; Slurm does the scheduling (no scheduler or protocol of kiln's own).
//
//   kiln farm SCENE [--tiles N] [--frames A-B] [--spp N] [-o OUT] [--dry-run] [--status]
//                   [-- SBATCH OPTIONS...]
//
// Task i of the array renders frame A + i / N, tile i % N (a grid of about square tiles over
// the film's resolution) with --pixelbounds into DIR/parts/, DIR = OUT's name (without '#')
// + ".farm", with
// --checkpoint so a requeued or resubmitted task resumes; a task only ever replaces its own
// part, atomically, so requeues and manual resubmission of failed indices are safe. The merge
// job runs `kiln merge` per frame into OUT ('#'s in OUT become the frame number, as with
// kiln --frames). --dry-run prints the scripts and the sbatch commands instead of submitting;
// --status lists the parts that are missing. The scripts assume what a cluster's shared
// filesystem gives: the scene, kiln and DIR at the same paths on every node.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct FarmPlan {
    std::string kiln;   // absolute path of the kiln binary
    std::string scene;  // absolute path of the scene file
    std::string output;
    std::string dir;  // output without '#' + ".farm"
    Point2i resolution;
    std::vector<Bounds2i> tiles;
    std::pair<int, int> frames{0, 0};
    bool animation = false;  // --frames given
    std::optional<int> spp;
    std::vector<std::string> sbatchOptions;

    int Tasks() const { return int(tiles.size()) * (frames.second - frames.first + 1); }
    // The part file of (frame, tile).
    std::string PartFile(int frame, int tile) const;
    // The merged output of a frame.
    std::string FrameOutput(int frame) const;
};

// Tiles of a film: a grid of rows x columns with rows * columns = n (as square as n allows),
// covering every pixel exactly once.
std::vector<Bounds2i> TileGrid(Point2i resolution, int n);

// The job-array script and the merge script of a plan.
std::string RenderScript(const FarmPlan& plan);
std::string MergeScript(const FarmPlan& plan);

// `kiln farm ...` (args without "farm"): exit status 0, 1 (scene or submission errors) or 2
// (usage).
int RunFarm(const std::vector<std::string>& args);

}  // namespace kiln
