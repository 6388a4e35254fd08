#include "app/render_command.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "app/checkpoint.h"
#include "app/output_check.h"
#include "app/progress.h"
#include "base/atomic_file.h"
#include "core/film/film.h"
#include "core/image/polarization_view.h"
#include "core/parser/parser.h"
#include "render/auto_exposure.h"
#include "render/renderer.h"
#include "render/scene_builder.h"
#include "render/scene_inputs.h"

namespace kiln {

namespace {

// SIGINT (Ctrl-C) and SIGTERM (what schedulers send before they kill a job): the first stops
// loading or rendering and lets the image so far be written; a second ends the process at
// once, removing a temporary file being written. The exit status is 128 + the first signal's
// number. A signal handler can only reach static storage, hence these process-wide atomics.
std::atomic<bool> interruptRequested{false};
std::atomic<int> interruptSignal{0};

extern "C" void HandleInterrupt(int signal) {
    int none = 0;
    interruptSignal.compare_exchange_strong(none, signal);  // set before the flag is seen
    if (interruptRequested.exchange(true)) {
        RemovePendingTemporaryFile();
        _exit(128 + signal);
    }
}

int InterruptStatus() { return 128 + interruptSignal.load(); }

void InstallInterruptHandlers() {
    struct sigaction action = {};
    action.sa_handler = HandleInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

// A scene parsed and created once, with what identifies its renders.
struct LoadedScene {
    std::unique_ptr<Scene> scene;
    RenderOptions renderOptions;
    std::string optionsKey;  // RenderOptionsKey: in the output's metadata and the checkpoints
    std::string inputsHash;  // of every file the scene read (render/scene_inputs.h): likewise
};

// The render options of the command line at a frame (nullopt: no animation).
RenderOptions RenderOptionsFor(const CommandLineOptions& options, std::optional<int> frame) {
    RenderOptions renderOptions{options.spp, options.seed, options.crop, std::nullopt};
    renderOptions.pixelBounds = options.pixelBounds;
    renderOptions.genericFootprints = options.genericFootprints;
    renderOptions.genericAOVs = options.genericAOVs;
    renderOptions.genericVolumes = options.genericVolumes;
    if (options.stokes) renderOptions.stokes = true;
    renderOptions.memoryLimitBytes = options.memoryLimit;
    if (options.emission) renderOptions.emission = ParseEmissionModel(*options.emission);
    if (options.pbrtv4LayeredMIS) renderOptions.layeredMIS = LayeredMIS::PbrtV4;
    if (frame) {
        renderOptions.frame = *frame;
        renderOptions.timeSeconds = Float(*frame / options.fps);
    }
    // Integrator settings from the command line (for comparisons; validated when parsed)
    if (options.lightSampler)
        renderOptions.lightSelection = ParseLightSelection(*options.lightSampler);
    if (options.strategy) renderOptions.strategy = ParseLightStrategy(*options.strategy);
    if (options.emitterSampling)
        renderOptions.emitterPowerSampling = ParseEmitterPowerSampling(*options.emitterSampling);
    if (options.wavelengths) renderOptions.singleWavelength = *options.wavelengths == 1;
    return renderOptions;
}

// Parses the scene file and creates the scene at `frame`; nullopt after reporting an error
// (status: the exit status).
std::optional<LoadedScene> LoadScene(const CommandLineOptions& options, std::optional<int> frame,
                                     Diagnostics& diag, int& status) {
    LoadedScene loaded;
    try {
        // --memory-limit bounds each file read and the parsed description, as it does what
        // scene creation allocates
        SceneBuilder builder(diag);
        uint64_t maxFileBytes = DefaultMaxInputBytes();
        if (options.memoryLimit) {
            builder.SetMemoryLimit(*options.memoryLimit);
            maxFileBytes = std::min(maxFileBytes, uint64_t(*options.memoryLimit));
        }
        std::vector<std::string> parsedFiles =
            ParseFile(builder, options.sceneFile, diag, maxFileBytes);
        loaded.renderOptions = RenderOptionsFor(options, frame);
        loaded.optionsKey = RenderOptionsKey(loaded.renderOptions);
        loaded.scene = Scene::Create(builder.Description(), loaded.renderOptions, diag);
        loaded.inputsHash = HashInputFiles(SceneInputFiles(builder.Description(), parsedFiles));
        diag.ReportRepeats();
        if (interruptRequested.load()) {
            std::cerr << "kiln: interrupted while loading the scene; nothing written\n";
            status = InterruptStatus();
            return std::nullopt;
        }
        if (options.verbose) {
            const Scene& scene = *loaded.scene;
            double embree = double(scene.aggregate->EmbreePeakBytes());
            std::fprintf(stderr,
                         "kiln: %d shapes, %zu lights (%d thermal); Embree peak %.1f MB (%.0f "
                         "bytes per shape%s)\n",
                         scene.shapeCount, scene.lights.size(), scene.thermalEmitterCount,
                         embree * 1e-6, scene.shapeCount > 0 ? embree / scene.shapeCount : 0.0,
                         scene.aggregate->Compact() ? ", compact BVH" : "");
            std::fprintf(stderr, "kiln: chosen: %s\n", scene.features.ToString().c_str());
        }
    } catch (const SceneError& e) {
        diag.ReportRepeats();
        std::cerr << e.what() << "\n";
        status = 1;
        return std::nullopt;
    } catch (const std::exception& e) {
        std::cerr << "kiln: error: " << e.what() << "\n";
        status = 1;
        return std::nullopt;
    }
    return loaded;
}

// Moves a loaded scene to another frame: its animated temperatures and a new render job (an
// empty film); false after reporting an error.
bool MoveToFrame(LoadedScene& loaded, const CommandLineOptions& options, int frame,
                 Diagnostics& diag) {
    try {
        loaded.renderOptions = RenderOptionsFor(options, frame);
        loaded.scene->SetAnimation(
            TemperatureAnimation{loaded.renderOptions.frame, loaded.renderOptions.timeSeconds});
        loaded.scene->SetJob(loaded.renderOptions, diag);
    } catch (const SceneError& e) {
        std::cerr << e.what() << "\n";
        return false;
    } catch (const std::exception& e) {
        std::cerr << "kiln: error: " << e.what() << "\n";
        return false;
    }
    return true;
}

// Renders one image (one frame of an animation) of a loaded scene and writes it to every
// output; returns the exit status.
int RenderFrame(const CommandLineOptions& options, LoadedScene& loaded, std::optional<int> frame,
                const std::vector<std::string>& outputPatterns, Diagnostics& diag) {
    Scene* scene = loaded.scene.get();
    const std::string& optionsKey = loaded.optionsKey;
    const std::string& inputsHash = loaded.inputsHash;
    std::vector<std::string> outputs;
    for (const std::string& pattern : outputPatterns.empty()
                                          ? std::vector<std::string>{scene->job->film->Filename()}
                                          : outputPatterns)
        outputs.push_back(frame ? FrameFilename(pattern, *frame) : pattern);
    // The scene file's own output is known only now: checked before rendering, as -o was
    // before parsing
    if (outputPatterns.empty()) {
        try {
            CheckImageOutput(outputs[0], options.view);
        } catch (const std::invalid_argument& e) {
            std::cerr << "kiln: error: Film \"filename\": " << e.what() << "; nothing rendered\n";
            return 1;
        }
    }

    RenderSettings settings;
    settings.threads = options.threads.value_or(0);
    settings.cancel = &interruptRequested;
    ProgressReporter progress(options.quiet ? nullptr : &std::cerr, isatty(STDERR_FILENO));
    settings.observer = &progress;
    // What identifies this render (its output's metadata, its checkpoints); --checkpoint:
    // resume from this render's checkpoint, and write one periodically
    std::string checkpoint;
    CheckpointIdentity identity{inputsHash,
                                optionsKey,
                                frame ? std::to_string(*frame) : "",
                                scene->job->sampler->Seed(),
                                scene->job->sampler->SamplesPerPixel(),
                                scene->job->film->PixelBounds()};
    if (options.checkpointSeconds && !outputs.empty()) {
        checkpoint = CheckpointFile(outputs[0]);
        std::string why;
        settings.startSample = ReadCheckpoint(checkpoint, identity, *scene->job->film, &why);
        if (!why.empty()) std::cerr << "kiln: warning: ignoring " << why << "\n";
        if (settings.startSample > 0 && !options.quiet)
            std::cerr << "kiln: resuming from " << checkpoint << " at " << settings.startSample
                      << " spp\n";
        settings.checkpointSeconds = *options.checkpointSeconds;
        settings.checkpoint = [&](int completed) {
            try {
                WriteCheckpoint(checkpoint, identity, completed, *scene->job->film);
                if (options.verbose)
                    std::cerr << "kiln: checkpoint at " << completed << " spp in " << checkpoint
                              << "\n";
            } catch (const std::exception& e) {
                std::cerr << "kiln: warning: " << e.what() << "\n";
            }
        };
    }
    RenderStats stats;
    try {
        stats = Render(*scene, settings);
    } catch (const std::exception& e) {
        std::cerr << "kiln: error: " << e.what() << "; nothing written\n";
        return 1;
    }

    if (int64_t bad = scene->job->film->NonFiniteSampleCount(); bad > 0) {
        Point2i p = scene->job->film->FirstNonFinitePixel().value_or(Point2i(-1, -1));
        std::cerr << "kiln: warning: " << bad << " NaN/Inf radiance samples were discarded "
                  << "(first at pixel " << p.x << ", " << p.y << ")\n";
    }
    // Exposure: the film's "exposure", plus --exposure stops or automatic exposure
    Float ev = scene->job->film->GetOptions().exposureEV;
    if (options.exposure && *options.exposure != "auto") ev += std::stof(*options.exposure);
    if (scene->autoExposure || (options.exposure && *options.exposure == "auto")) {
        ev += AutoExposureEV(*scene->job->film);
        if (options.verbose) std::fprintf(stderr, "kiln: automatic exposure %+.2f EV\n", ev);
    }
    // The sum (film, --exposure, automatic) is held to the same bound as each part, so that
    // 2^ev times any radiance stays finite in float
    ev = std::clamp(ev, -RGBFilm::kMaxExposureEV, RGBFilm::kMaxExposureEV);
    scene->job->film->SetExposureEV(ev);
    ImageMetadata metadata;
    metadata.strings["kiln:exposureEV"] = std::to_string(ev);
    metadata.renderTimeSeconds = float(stats.seconds);
    metadata.samplesPerPixel = stats.cancelled ? stats.completedSamples : stats.samplesPerPixel;
    if (stats.cancelled) metadata.strings["kiln:partial"] = "true";
    // What kiln merge checks parts against: the same scene (its file's bytes), frame and seed
    metadata.strings["kiln:seed"] = std::to_string(scene->job->sampler->Seed());
    metadata.strings["kiln:scene"] = identity.scene;
    metadata.strings["kiln:options"] = optionsKey;
    if (frame) metadata.strings["kiln:frame"] = std::to_string(*frame);
    int status = 0;
    for (const std::string& out : outputs) {
        try {
            scene->job->film->WriteImage(out, metadata, options.view, &diag);
        } catch (const std::exception& e) {
            std::cerr << "kiln: error: " << e.what() << "\n";
            status = 1;
        }
    }
    // A finished render needs its checkpoint no more (an interrupted one resumes from it)
    if (!checkpoint.empty() && status == 0 && !stats.cancelled) RemoveCheckpoint(checkpoint);
    // --polarisation: pictures of the degree and angle of polarisation beside each output
    if (options.polarisation)
        for (const std::string& out : outputs) {
            std::string stem = out.substr(
                0, out.size() - FileExtension(out).size() - (FileExtension(out).empty() ? 0 : 1));
            try {
                for (const auto& [name, picture] : PolarizationViews(
                         scene->job->film->GetImage(nullptr), *scene->job->film->ColorSpace()))
                    picture.Write(stem + "-" + name + ".png", metadata);
            } catch (const std::exception& e) {
                std::cerr << "kiln: error: " << e.what() << "\n";
                status = 1;
            }
        }
    diag.ReportRepeats();
    if (!options.quiet) {
        double mpaths = stats.seconds > 0 ? stats.cameraPaths / stats.seconds * 1e-6 : 0;
        std::fprintf(stderr, "kiln: %dx%d, %d spp, %.2fs wall, %.2f Mpaths/s%s\n",
                     stats.resolution.x, stats.resolution.y, stats.samplesPerPixel, stats.seconds,
                     mpaths, stats.cancelled ? " (interrupted)" : "");
    }
    if (status == 0 && (stats.cancelled || interruptRequested.load())) status = InterruptStatus();
    return status;
}

}  // namespace

int RenderCommand(const CommandLineOptions& options) {
    std::optional<int> first;
    if (options.frames) first = options.frames->first;
    // Every output can be written before anything is parsed or rendered
    try {
        CheckDisplayView(options.view);
        for (const std::string& pattern : options.outputs)
            CheckImageOutput(first ? FrameFilename(pattern, *first) : pattern, options.view);
    } catch (const std::invalid_argument& e) {
        std::cerr << "kiln: " << e.what() << "\n";
        return 2;
    }
    InstallInterruptHandlers();
    Diagnostics diag(&std::cerr);
    int status = 0;
    std::optional<LoadedScene> loaded = LoadScene(options, first, diag, status);
    if (!loaded) return status;
    if (!options.frames) return RenderFrame(options, *loaded, std::nullopt, options.outputs, diag);
    // Animation: the scene is parsed and created once; each frame moves its animated
    // temperatures and renders with a new film. Every frame is what a run of that frame
    // alone renders (deterministic and independent, so frames can be rendered on different
    // machines).
    for (int f = options.frames->first; f <= options.frames->second; ++f) {
        if (!options.quiet)
            std::fprintf(stderr, "kiln: frame %d (t = %.4g s)\n", f, f / options.fps);
        if (f != options.frames->first && !MoveToFrame(*loaded, options, f, diag)) return 1;
        status = RenderFrame(options, *loaded, f, options.outputs, diag);
        if (status != 0) return status;
        if (interruptRequested.load()) return InterruptStatus();
    }
    return 0;
}

}  // namespace kiln
