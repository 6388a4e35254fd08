// The `kiln` command: options, scene loading, rendering and output (main() only calls this).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct CommandLineOptions {
    std::string sceneFile;
    std::vector<std::string> outputs;  // -o, may repeat: one render, several files
    std::optional<int> spp, threads, seed;
    std::optional<Bounds2f> crop;
    std::optional<Bounds2i> pixelBounds;        // --pixelbounds x0 x1 y0 y1 (pbrt-v4)
    std::optional<std::string> emission;        // kirchhoff | additive | diffuse | none
    bool pbrtv4LayeredMIS = false;              // --layered-mis pbrt-v4 (else kiln)
    std::optional<std::pair<int, int>> frames;  // first and last frame, inclusive
    double fps = 24;
    bool quiet = false;
    bool verbose = false;
    std::string view;  // display view override for PNG/JPEG/... outputs ("" = the film's)
    std::optional<std::string> exposure;                // EV stops added to the film's, or "auto"
    std::optional<std::string> lightSampler;            // bvh | power | uniform | area
    std::optional<std::string> strategy;                // mis | light | bsdf
    std::optional<std::string> emitterSampling;         // power | shape
    std::optional<std::string> mediumEmission;          // sampled | tracked
    std::optional<std::string> glassWindows;            // on | off
    std::optional<std::string> exactMediumEmission;     // on | off
    std::optional<std::string> weightAbsorption;        // on | off
    std::optional<std::string> collisionLightSampling;  // on | off
    std::optional<std::string> splitDielectrics;        // on | off
    std::optional<std::string> skipUniformEnvironment;  // on | off
    std::optional<std::string> reconstruction;          // spread | importance
    std::optional<std::string> wavelengthSampling;      // emission | visible
    // --generic footprints,aovs: run those generic code paths (measuring specialisation)
    bool genericFootprints = false, genericAOVs = false, genericVolumes = false;
    std::optional<int> wavelengths;           // 1 | 4
    std::optional<double> memoryLimit;        // --memory-limit, bytes
    std::optional<double> checkpointSeconds;  // --checkpoint SECONDS
    bool writePartialImages = false;          // --write-partial-images (pbrt-v4)
    bool stats = false;                       // --stats (pbrt-v4): statistics after rendering
    std::string displayServer;                // --display-server host:port (pbrt-v4; tev)
    bool format = false, toPly = false;       // --format, --toply (pbrt-v4): print the scene
    bool warnings = true;                     // --log-level error|fatal (pbrt-v4): none
    // --mse-reference-image and --mse-reference-out (pbrt-v4): the mean squared error against
    // a reference after every sample per pixel
    std::string mseReferenceImage, mseReferenceOut;
    bool stokes = false;        // --stokes: polarised rendering with Stokes layers
    bool polarisation = false;  // --polarisation: also degree/angle pictures
    bool help = false, version = false;
};

// Parses argv; throws std::invalid_argument with a message naming the bad argument.
CommandLineOptions ParseCommandLine(const std::vector<std::string>& args);

std::string UsageText();

// pattern with its last run of '#' replaced by the zero-padded frame number ("f.####.exr", 7
// -> "f.0007.exr"); pattern itself if it has no '#'.
std::string FrameFilename(const std::string& pattern, int frame);

// Runs the command; returns the process exit code (0 ok, 1 scene or I/O error, 2 usage error,
// 128 + the signal's number when SIGINT (130) or SIGTERM (143) stopped it: after writing the
// image so far, marked "kiln:partial" with the samples per pixel it holds, or, during loading,
// with nothing written). A second signal ends the process at once.
int RunKiln(int argc, char** argv);

}  // namespace kiln
