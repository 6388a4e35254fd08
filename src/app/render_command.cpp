#include "app/render_command.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "app/checkpoint.h"
#include "app/display_server.h"
#include "app/image_diff.h"
#include "app/output_check.h"
#include "app/progress.h"
#include "app/scene_formatter.h"
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

// The wave length --display-server aims for, seconds (a wave still has at least one sample
// per pixel)
constexpr double kDisplayUpdateSeconds = 1;

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

// The R, G, B of the reference image over a film's pixels (full-frame coordinates): the
// reference's own data window when it has one (an EXR), else the whole frame. Throws
// std::runtime_error when the reference lacks R, G, B or does not cover the film.
Image MSEReference(const std::string& file, const Bounds2i& filmPixels) {
    ImageMetadata metadata;
    Image image = Image::Read(file, &metadata);
    if (image.ChannelIndex("R") < 0 || image.ChannelIndex("G") < 0 || image.ChannelIndex("B") < 0)
        throw std::runtime_error(file + ": the MSE reference has no R, G, B channels");
    Bounds2i bounds = metadata.pixelBounds.value_or(Bounds2i{{0, 0}, image.Resolution()});
    if (filmPixels.pMin.x < bounds.pMin.x || filmPixels.pMin.y < bounds.pMin.y ||
        filmPixels.pMax.x > bounds.pMax.x || filmPixels.pMax.y > bounds.pMax.y)
        throw std::runtime_error(file + ": the MSE reference's pixels do not cover the image's");
    Point2i size = filmPixels.pMax - filmPixels.pMin, offset = filmPixels.pMin - bounds.pMin;
    Image rgb(PixelFormat::Float, size, {"R", "G", "B"});
    const int channel[3] = {image.ChannelIndex("R"), image.ChannelIndex("G"),
                            image.ChannelIndex("B")};
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            for (int c = 0; c < 3; ++c)
                rgb.SetChannel({x, y}, c,
                               image.GetChannel({x + offset.x, y + offset.y}, channel[c]));
    return rgb;
}

// Mean over pixels and R, G, B of the squared difference of an image's R, G, B from a
// reference of the same size (pbrt-v4's Image::MSE averaged over the channels): kiln diff's
// rmse, squared.
double MeanSquaredError(const Image& image, const Image& reference) {
    double rmse = CompareImages(image.SelectChannels({"R", "G", "B"}), reference).rmse;
    return rmse * rmse;
}

// The file name without folder and extension ("scenes/forge.pbrt" -> "forge")
std::string FileStem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

// A scene parsed and created once, with what identifies its renders.

struct LoadedScene {
    std::unique_ptr<Scene> scene;
    double loadSeconds = 0;  // parsing and scene creation
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
    if (options.mediumEmission)
        renderOptions.mediumEmissionSampling = ParseMediumEmissionSampling(*options.mediumEmission);
    if (options.glassWindows) renderOptions.glassWindows = *options.glassWindows == "on";
    if (options.exactMediumEmission)
        renderOptions.exactMediumEmission = *options.exactMediumEmission == "on";
    if (options.weightAbsorption)
        renderOptions.weightAbsorption = *options.weightAbsorption == "on";
    if (options.collisionLightSampling)
        renderOptions.collisionLightSampling = *options.collisionLightSampling == "on";
    if (options.splitDielectrics)
        renderOptions.splitDielectrics = *options.splitDielectrics == "on";
    if (options.skipUniformEnvironment)
        renderOptions.skipUniformEnvironment = *options.skipUniformEnvironment == "on";
    if (options.reconstruction) renderOptions.spreadSamples = *options.reconstruction == "spread";
    if (options.wavelengthSampling)
        renderOptions.emissionWavelengths = *options.wavelengthSampling == "emission";
    if (options.wavelengths) renderOptions.singleWavelength = *options.wavelengths == 1;
    return renderOptions;
}

// Parses the scene file and creates the scene at `frame`; nullopt after reporting an error
// (status: the exit status).
std::optional<LoadedScene> LoadScene(const CommandLineOptions& options, std::optional<int> frame,
                                     Diagnostics& diag, int& status) {
    LoadedScene loaded;
    const auto started = std::chrono::steady_clock::now();
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
        loaded.loadSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
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

// pbrt-v4's --stats, kiln's quantities: what the scene holds, time per phase, camera paths and
// memory. (kiln counts camera paths, not rays.)
void PrintStatistics(const LoadedScene& loaded, const RenderStats& stats, double writeSeconds) {
    const Scene& scene = *loaded.scene;
    rusage usage = {};
    getrusage(RUSAGE_SELF, &usage);
    auto row = [](const char* name, const std::string& value) {
        std::fprintf(stderr, "    %-40s %s\n", name, value.c_str());
    };
    auto number = [](double v, const char* format) {
        char buf[64];
        std::snprintf(buf, sizeof(buf), format, v);
        return std::string(buf);
    };
    std::fprintf(stderr, "Statistics:\n  Scene\n");
    row("Shapes", std::to_string(scene.shapeCount));
    row("Lights (thermal)", std::to_string(scene.lights.size()) + " (" +
                                std::to_string(scene.thermalEmitterCount) + ")");
    row("Emissivity tables", std::to_string(scene.features.emissivityTables));
    std::fprintf(stderr, "  Time\n");
    row("Parsing and scene creation", number(loaded.loadSeconds, "%.3f s"));
    row("Emissivity tables (of the above)", number(scene.features.emissivitySeconds, "%.3f s"));
    row("Rendering", number(stats.seconds, "%.3f s"));
    row("Writing images", number(writeSeconds, "%.3f s"));
    std::fprintf(stderr, "  Rendering\n");
    row("Resolution",
        std::to_string(stats.resolution.x) + " x " + std::to_string(stats.resolution.y));
    row("Samples per pixel",
        std::to_string(stats.completedSamples) + " of " + std::to_string(stats.samplesPerPixel));
    row("Camera paths", std::to_string(stats.cameraPaths));
    row("Camera paths per second",
        number(stats.seconds > 0 ? stats.cameraPaths / stats.seconds * 1e-6 : 0, "%.3f M"));
    std::fprintf(stderr, "  Memory\n");
    row("Peak resident set size", number(double(usage.ru_maxrss) / 1024.0, "%.1f MB"));
    row("Embree BVH peak", number(double(scene.aggregate->EmbreePeakBytes()) * 1e-6, "%.1f MB"));
    row("Committed to the scene (estimated)",
        number(scene.arena.Budget().Committed() * 1e-6, "%.1f MB"));
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
    // What the film writes is known only now: -o outputs in formats this film cannot write
    // (a thermal film's PFM) fail before rendering
    for (const std::string& out : outputPatterns.empty() ? std::vector<std::string>{} : outputs)
        if (std::string why = scene->job->film->OutputFormatProblem(out); !why.empty()) {
            std::cerr << "kiln: " << out << ": " << why << "; nothing rendered\n";
            return 2;
        }
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
    // pbrt-v4's --mse-reference-image: "spp, MSE" after every sample per pixel (one-sample
    // waves), against the reference's R, G, B over this film's pixels
    std::optional<Image> reference;
    std::string mseLines;
    if (!options.mseReferenceImage.empty()) {
        try {
            reference = MSEReference(options.mseReferenceImage, scene->job->film->PixelBounds());
        } catch (const std::exception& e) {
            std::cerr << "kiln: error: " << e.what() << "; nothing rendered\n";
            return 1;
        }
        settings.maxWaveSize = 1;
    }
    // pbrt-v4's --write-partial-images: the outputs after every wave but the last (which the
    // render writes below), marked partial, at the film's exposure
    auto partialMetadata = [&](int completed) {
        ImageMetadata m;
        m.strings["kiln:exposureEV"] = std::to_string(scene->job->film->GetOptions().exposureEV);
        m.samplesPerPixel = completed;
        m.strings["kiln:partial"] = "true";
        m.strings["kiln:seed"] = std::to_string(scene->job->sampler->Seed());
        m.strings["kiln:scene"] = identity.scene;
        m.strings["kiln:options"] = optionsKey;
        if (frame) m.strings["kiln:frame"] = std::to_string(*frame);
        return m;
    };
    // pbrt-v4's --display-server: the image after every wave, in tev, waves kept to about a
    // second each so that the view follows the render. A viewer that cannot be reached is a
    // warning: the render goes on.
    std::unique_ptr<DisplayServerClient> display;
    std::string displayName =
        FileStem(options.sceneFile) + (frame ? " " + std::to_string(*frame) : "");
    if (!options.displayServer.empty()) {
        try {
            display = DisplayServerClient::Connect(options.displayServer);
            Bounds2i b = scene->job->film->PixelBounds();
            display->CreateImage(displayName, b.pMax - b.pMin, {"R", "G", "B"});
            settings.waveSeconds = kDisplayUpdateSeconds;
        } catch (const std::exception& e) {
            std::cerr << "kiln: warning: " << e.what() << "; rendering without it\n";
        }
    }
    const int spp = scene->job->sampler->SamplesPerPixel();
    settings.afterWave = [&](int completed) {
        if (display && display->Connected())
            display->UpdateImage(
                displayName, scene->job->film->GetImage(nullptr).SelectChannels({"R", "G", "B"}));
        if (reference) {
            char line[64];
            std::snprintf(line, sizeof(line), "%d, %.9g\n", completed,
                          MeanSquaredError(scene->job->film->GetImage(nullptr), *reference));
            mseLines += line;
            try {
                WriteFileAtomically(options.mseReferenceOut, mseLines);
            } catch (const std::exception& e) {
                std::cerr << "kiln: warning: " << e.what() << "\n";
            }
        }
        if (options.writePartialImages && completed < spp)
            for (const std::string& out : outputs) try {
                    scene->job->film->WriteImage(out, partialMetadata(completed), options.view,
                                                 &diag);
                } catch (const std::exception& e) {
                    std::cerr << "kiln: warning: " << e.what() << "\n";
                }
    };
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
    const auto writeStarted = std::chrono::steady_clock::now();
    for (const std::string& out : outputs) {
        try {
            scene->job->film->WriteImage(out, metadata, options.view, &diag);
        } catch (const std::exception& e) {
            std::cerr << "kiln: error: " << e.what() << "\n";
            status = 1;
        }
    }
    // A finished render needs its checkpoint no more (an interrupted one resumes from it)
    double writeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - writeStarted).count();
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
    if (options.stats) PrintStatistics(loaded, stats, writeSeconds);
    if (status == 0 && (stats.cancelled || interruptRequested.load())) status = InterruptStatus();
    return status;
}

}  // namespace

int RenderCommand(const CommandLineOptions& options) {
    if (options.format) {  // pbrt-v4's --format / --toply: print, render nothing
        Diagnostics diag(options.warnings ? &std::cerr : nullptr);
        SceneFormatter formatter(std::cout, options.toPly);
        try {
            ParseFile(formatter, options.sceneFile, diag, DefaultMaxInputBytes());
        } catch (const SceneError& e) {
            std::cerr << e.what() << "\n";
            return 1;
        } catch (const std::exception& e) {
            std::cerr << "kiln: error: " << e.what() << "\n";
            return 1;
        }
        return 0;
    }
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
    Diagnostics diag(options.warnings ? &std::cerr : nullptr);
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
