#include "app/command_line.h"

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "app/farm.h"
#include "app/image_diff.h"
#include "app/image_tools.h"
#include "app/merge.h"
#include "app/render_command.h"
#include "base/memory_budget.h"
#include "base/plugin.h"
#include "core/film/film.h"
#include "core/image/display.h"
#include "core/image/image.h"
#include "core/parser/suggestions.h"
#include "render/render_options.h"

#ifndef KILN_VERSION
#define KILN_VERSION "0.0.0"
#endif

namespace kiln {

namespace {

int ParseInt(const std::string& flag, const std::string& v, int minValue) {
    size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(v, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != v.size() || v.empty() || value < minValue)
        throw std::invalid_argument(flag + " expects an integer >= " + std::to_string(minValue) +
                                    ", got '" + v + "'");
    return value;
}

Float ParseFloat(const std::string& flag, const std::string& v) {
    size_t used = 0;
    Float value = 0;
    try {
        value = std::stof(v, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != v.size() || v.empty() || !std::isfinite(value))
        throw std::invalid_argument(flag + " expects a number, got '" + v + "'");
    return value;
}

}  // namespace

std::string UsageText() {
    return "usage: kiln SCENE.pbrt [options]   (options also as --name=value, as pbrt-v4)\n"
           "  -o, --output FILE     output image (EXR, PNG, JPEG, TIFF, ... by extension);\n"
           "                        may repeat; default: the scene's Film \"filename\"\n"
           "  --spp N               samples per pixel (overrides the scene's sampler)\n"
           "  --threads N           worker threads (default: all cores)\n"
           "  --seed S              sampler seed\n"
           "  --crop x0 x1 y0 y1    render only this window (NDC, as Film \"cropwindow\";\n"
           "                        also --cropwindow; or x0,x1,y0,y1 as pbrt-v4)\n"
           "  --write-partial-images  write the outputs after every wave of samples (pbrt-v4)\n"
           "  --format              print the scene reformatted (Includes spliced in) to\n"
           "                        standard output; render nothing (pbrt-v4)\n"
           "  --toply               as --format, with every trianglemesh written to a PLY\n"
           "                        file (mesh_00001.ply, ... in the working folder) (pbrt-v4)\n"
           "  --display-server HOST:PORT\n"
           "                        show the image in tev (or any viewer speaking its protocol)\n"
           "                        after every wave of samples, about once a second (pbrt-v4)\n"
           "  --stats               print statistics after rendering: time per phase, camera\n"
           "                        paths, memory (pbrt-v4)\n"
           "  --log-level L         verbose (as --verbose), warning (default), error or fatal\n"
           "                        (no scene warnings) (pbrt-v4)\n"
           "  --mse-reference-image REF --mse-reference-out FILE\n"
           "                        after every sample per pixel, append \"spp, MSE\" against\n"
           "                        REF's R, G, B to FILE (pbrt-v4)\n"
           "  --checkpoint SECONDS  write the film's state to OUT.checkpoint every SECONDS (0:\n"
           "                        after every wave of samples); the same command run again\n"
           "                        resumes from it and ends bit-identical to an uninterrupted\n"
           "                        render; removed when the render is written\n"
           "  --pixelbounds x0 x1 y0 y1  (or x0,x1,y0,y1)\n"
           "                        render only pixels [x0, x1) x [y0, y1) of the image (as\n"
           "                        pbrt-v4): a tile, bit-identical to the same pixels of a\n"
           "                        full render, written as 32-bit float EXR for kiln merge\n"
           "  --emission MODEL      thermal emission model for every hot surface:\n"
           "                        kirchhoff (default), additive, diffuse or none\n"
           "  --layered-mis W       MIS weights inside coateddiffuse and coatedconductor:\n"
           "                        kiln (default: f agrees with sampling) or pbrt-v4 (as\n"
           "                        pbrt-v4 renders them: 1-14 % brighter with rough coats)\n"
           "  --frames A-B          render frames A..B of an animation (time = frame / fps);\n"
           "                        '#'s in -o are replaced by the frame number (####: 0007)\n"
           "  --fps F               frames per second for --frames (default 24)\n"
           "  --light-sampler S     how lights are picked: bvh (default), power, uniform,\n"
           "                        area\n"
           "  --exposure EV|auto    exposure change in stops, or automatic (the 99th\n"
           "                        percentile luminance goes to 0.9; film \"autoexposure\")\n"
           "  --emitter-sampling S  points on a hot shape whose emission varies over it: in\n"
           "                        proportion to power (default) or by the shape's own\n"
           "                        sampling (shape)\n"
           "  --medium-emission M   emissive media: sampled as light sources by power\n"
           "                        (sampled, default) or found by tracking alone (tracked,\n"
           "                        as pbrt-v4)\n"
           "  --glass-windows W     media glowing inside glass: sampled through the glass\n"
           "                        (on, default) or found by chance refractions (off)\n"
           "  --exact-medium-emission E  emission of uniform media along each ray segment:\n"
           "                        integrated exactly (on, default) or met at collisions\n"
           "                        (off, as pbrt-v4)\n"
           "  --weight-absorption A  in media, absorption weighs paths that carry much (on,\n"
           "                        default) or ends them by chance (off, as pbrt-v4)\n"
           "  --collision-light-sampling C  on camera rays in media, lights sampled at\n"
           "                        tentative collisions (on, default) or at real\n"
           "                        scatterings only (off, as pbrt-v4)\n"
           "  --split-dielectrics S  a camera ray's first smooth dielectric: both reflection\n"
           "                        and transmission traced (on, default) or one by chance\n"
           "                        (off, as pbrt-v4)\n"
           "  --skip-uniform-environment S  light samples go to the lights they can draw\n"
           "                        from, not to a uniform environment that BSDF sampling\n"
           "                        covers (on, default) or to it too (off, as pbrt-v4)\n"
           "  --reconstruction R    pixel samples: uniform over a pixel and spread over the\n"
           "                        pixels within the filter's radius (spread, default) or\n"
           "                        drawn from the filter for one pixel (importance, as\n"
           "                        pbrt-v4)\n"
           "  --wavelength-sampling W  wavelengths in scenes with hot matter: partly by the\n"
           "                        spectrum it radiates (emission, default) or by the\n"
           "                        visible density alone (visible, as pbrt-v4)\n"
           "  --strategy S          direct light by mis (default), light or bsdf sampling\n"
           "  --wavelengths N       wavelengths per path: 4 (hero, default) or 1\n"
           "  --view NAME           display view for PNG/JPEG/TIFF outputs: Standard, Filmic,\n"
           "                        ACES, Glow (24 stops of log luminance) or Raw\n"
           "  --stokes              render polarised light; the EXR gains Stokes layers\n"
           "                        S0.R ... S3.B (as Film \"bool stokes\" true)\n"
           "  --polarisation        --stokes, and pictures of the polarisation beside each\n"
           "                        output: OUT-dolp.png, OUT-aolp.png (degree and angle of\n"
           "                        linear polarisation) and Wilkie & Weidlich 2010's\n"
           "                        OUT-dop.png, -aop.png, -type.png, -chirality.png\n"
           "  --memory-limit SIZE   the most memory the scene may take (e.g. 8G, 512M; default:\n"
           "                        the machine's): a film, mesh, curve, image or volume that\n"
           "                        would pass it is an error naming it and its estimate\n"
           "  --verbose             print what kiln chose for the scene (code paths, tables)\n"
           "  --generic LIST        run generic code paths instead of the chosen ones, to\n"
           "                        measure what the choices save: footprints (texture\n"
           "                        footprints at every hit), aovs (AOV work per camera\n"
           "                        ray), volpath (the volumetric integrator without\n"
           "                        media), all\n"
           "  --quiet               no progress output\n"
           "  --help, --version\n"
           "   or: kiln diff A B [--metric M] [--threshold X] [--out DIFF] (kiln diff --help)\n"
           "   or: kiln convert IN.exr -o OUT.png [--view V] [--exposure EV|auto]\n"
           "   or: kiln info IMAGE (resolution, channels, kiln's metadata)\n"
           "   or: kiln merge PART.exr... -o FULL.exr (tiles of one frame)\n"
           "   or: kiln merge --samples RENDER.exr... -o OUT.exr (renders with other seeds)\n"
           "       (either with [--memory-limit SIZE])\n"
           "   or: kiln farm SCENE [--tiles N] [--frames A-B] [--spp N] [-o OUT] [--dry-run]\n"
           "                 [--status] [-- SBATCH OPTIONS] (a Slurm job array, then merges)\n";
}

namespace {

// Every option the render command knows (for "did you mean" suggestions)
const char* const kOptions[] = {"--help",
                                "--version",
                                "--output",
                                "--outfile",
                                "--spp",
                                "--threads",
                                "--nthreads",
                                "--memory-limit",
                                "--seed",
                                "--crop",
                                "--cropwindow",
                                "--checkpoint",
                                "--pixelbounds",
                                "--frames",
                                "--fps",
                                "--emission",
                                "--layered-mis",
                                "--light-sampler",
                                "--stokes",
                                "--polarisation",
                                "--polarization",
                                "--generic",
                                "--emitter-sampling",
                                "--medium-emission",
                                "--glass-windows",
                                "--exact-medium-emission",
                                "--weight-absorption",
                                "--collision-light-sampling",
                                "--split-dielectrics",
                                "--skip-uniform-environment",
                                "--reconstruction",
                                "--wavelength-sampling",
                                "--strategy",
                                "--wavelengths",
                                "--view",
                                "--exposure",
                                "--verbose",
                                "--quiet",
                                "--write-partial-images",
                                "--mse-reference-image",
                                "--mse-reference-out",
                                "--stats",
                                "--display-server",
                                "--format",
                                "--toply",
                                "--log-level"};

// "unknown option 'X'", with the nearest known option when it is close
std::string UnknownOption(const std::string& option) {
    std::vector<std::string_view> known(std::begin(kOptions), std::end(kOptions));
    std::optional<std::string> nearest = NearestName(option, known);
    return "unknown option '" + option + "'" + (nearest ? "; did you mean " + *nearest + "?" : "");
}

// pbrt-v4's "--name=value" as "--name" "value"
std::vector<std::string> SplitAssignments(const std::vector<std::string>& args) {
    std::vector<std::string> out;
    for (const std::string& a : args) {
        size_t eq = a.find('=');
        if (a.rfind("--", 0) == 0 && eq != std::string::npos && eq > 2) {
            out.push_back(a.substr(0, eq));
            out.push_back(a.substr(eq + 1));
        } else {
            out.push_back(a);
        }
    }
    return out;
}

}  // namespace

CommandLineOptions ParseCommandLine(const std::vector<std::string>& givenArgs) {
    CommandLineOptions o;
    const std::vector<std::string> args = SplitAssignments(givenArgs);
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](int n = 1) -> const std::string& {
            if (i + n >= args.size()) throw std::invalid_argument(a + " needs a value");
            return args[++i];
        };
        // The value, which must be one of two words
        auto either = [&](const char* x, const char* y) -> const std::string& {
            const std::string& v = value();
            if (v != x && v != y) throw std::invalid_argument(a + " expects " + x + " or " + y);
            return v;
        };
        // x0 x1 y0 y1 as four arguments, or as pbrt-v4's one "x0,x1,y0,y1"
        auto four = [&]() {
            std::vector<std::string> v;
            if (i + 1 < args.size() && args[i + 1].find(',') != std::string::npos) {
                std::string list = args[++i];
                for (size_t start = 0;;) {
                    size_t comma = list.find(',', start);
                    v.push_back(list.substr(start, comma - start));
                    if (comma == std::string::npos) break;
                    start = comma + 1;
                }
                if (v.size() != 4)
                    throw std::invalid_argument(a + " needs x0,x1,y0,y1 (four values), got '" +
                                                list + "'");
                return v;
            }
            if (i + 4 >= args.size()) throw std::invalid_argument(a + " needs x0 x1 y0 y1");
            for (int k = 0; k < 4; ++k) v.push_back(args[++i]);
            return v;
        };
        if (a == "-h" || a == "--help")
            o.help = true;
        else if (a == "--version")
            o.version = true;
        else if (a == "-o" || a == "--output" || a == "--outfile")
            o.outputs.push_back(value());
        else if (a == "--spp")
            o.spp = ParseInt(a, value(), 1);
        else if (a == "--threads" || a == "--nthreads")
            o.threads = ParseInt(a, value(), 1);
        else if (a == "--memory-limit") {
            std::optional<double> bytes = MemoryBudget::ParseSize(value());
            if (!bytes)
                throw std::invalid_argument(
                    "--memory-limit expects a positive size such as 8G, 512M or 1.5GB");
            o.memoryLimit = bytes;
        } else if (a == "--seed")
            o.seed = ParseInt(a, value(), std::numeric_limits<int>::min());
        else if (a == "--crop" || a == "--cropwindow") {
            std::vector<std::string> v = four();
            Float c[4];
            for (int k = 0; k < 4; ++k) c[k] = ParseFloat(a, v[k]);
            if (!(c[0] >= 0 && c[0] < c[1] && c[1] <= 1 && c[2] >= 0 && c[2] < c[3] && c[3] <= 1))
                throw std::invalid_argument(a + " expects 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
            o.crop = Bounds2f{Point2f(c[0], c[2]), Point2f(c[1], c[3])};
        } else if (a == "--format") {
            o.format = true;
        } else if (a == "--toply") {
            o.format = o.toPly = true;
        } else if (a == "--display-server") {
            o.displayServer = value();
        } else if (a == "--stats") {
            o.stats = true;
        } else if (a == "--log-level") {
            const std::string& level = value();
            if (level == "verbose")
                o.verbose = true;
            else if (level == "error" || level == "fatal")
                o.warnings = false;
            else if (level != "warning")
                throw std::invalid_argument(
                    "--log-level expects verbose, warning, error or fatal, got '" + level + "'");
        } else if (a == "--write-partial-images") {
            o.writePartialImages = true;
        } else if (a == "--mse-reference-image") {
            o.mseReferenceImage = value();
        } else if (a == "--mse-reference-out") {
            o.mseReferenceOut = value();
        } else if (a == "--checkpoint") {
            o.checkpointSeconds = ParseFloat(a, value());
            if (!(*o.checkpointSeconds >= 0) || !std::isfinite(*o.checkpointSeconds))
                throw std::invalid_argument("--checkpoint expects seconds >= 0");
        } else if (a == "--pixelbounds") {
            std::vector<std::string> v = four();
            int c[4];
            for (int k = 0; k < 4; ++k) c[k] = ParseInt(a, v[k], 0);
            if (!(c[0] < c[1] && c[2] < c[3]))
                throw std::invalid_argument(a + " expects 0 <= x0 < x1 and 0 <= y0 < y1 (pixels)");
            o.pixelBounds = Bounds2i{Point2i(c[0], c[2]), Point2i(c[1], c[3])};
        } else if (a == "--frames") {
            const std::string& v = value();
            size_t dash = v.find('-', 1);
            int first = ParseInt(a, v.substr(0, dash), 0);
            int last = dash == std::string::npos ? first : ParseInt(a, v.substr(dash + 1), 0);
            if (last < first)
                throw std::invalid_argument("--frames expects FIRST-LAST, FIRST <= LAST");
            o.frames = std::pair(first, last);
        } else if (a == "--fps") {
            o.fps = ParseFloat(a, value());
            if (!(o.fps > 0)) throw std::invalid_argument("--fps must be positive");
        } else if (a == "--emission") {
            o.emission = value();
            if (!ParseEmissionModel(*o.emission))
                throw std::invalid_argument(
                    "--emission expects kirchhoff, additive, diffuse or "
                    "none, got '" +
                    *o.emission + "'");
        } else if (a == "--layered-mis") {
            const std::string& w = value();
            if (w != "kiln" && w != "pbrt-v4")
                throw std::invalid_argument("--layered-mis expects kiln or pbrt-v4, got '" + w +
                                            "'");
            o.pbrtv4LayeredMIS = w == "pbrt-v4";
        } else if (a == "--light-sampler") {
            o.lightSampler = value();
            if (*o.lightSampler != "bvh" && *o.lightSampler != "power" &&
                *o.lightSampler != "uniform" && *o.lightSampler != "area")
                throw std::invalid_argument("--light-sampler expects bvh, power, uniform or area");
        } else if (a == "--stokes") {
            o.stokes = true;
        } else if (a == "--polarisation" || a == "--polarization") {
            o.stokes = o.polarisation = true;
        } else if (a == "--generic") {
            std::string list = value();
            size_t start = 0;
            while (start <= list.size()) {
                size_t comma = list.find(',', start);
                std::string item = list.substr(start, comma - start);
                if (item == "footprints" || item == "all") o.genericFootprints = true;
                if (item == "aovs" || item == "all") o.genericAOVs = true;
                if (item == "volpath" || item == "all") o.genericVolumes = true;
                if (item != "footprints" && item != "aovs" && item != "volpath" && item != "all")
                    throw std::invalid_argument(
                        "--generic expects footprints, aovs, volpath or all");
                if (comma == std::string::npos) break;
                start = comma + 1;
            }
        } else if (a == "--emitter-sampling") {
            o.emitterSampling = either("power", "shape");
        } else if (a == "--medium-emission") {
            o.mediumEmission = either("sampled", "tracked");
        } else if (a == "--glass-windows") {
            o.glassWindows = either("on", "off");
        } else if (a == "--exact-medium-emission") {
            o.exactMediumEmission = either("on", "off");
        } else if (a == "--weight-absorption") {
            o.weightAbsorption = either("on", "off");
        } else if (a == "--collision-light-sampling") {
            o.collisionLightSampling = either("on", "off");
        } else if (a == "--split-dielectrics") {
            o.splitDielectrics = either("on", "off");
        } else if (a == "--skip-uniform-environment") {
            o.skipUniformEnvironment = either("on", "off");
        } else if (a == "--reconstruction") {
            o.reconstruction = either("spread", "importance");
        } else if (a == "--wavelength-sampling") {
            o.wavelengthSampling = either("emission", "visible");
        } else if (a == "--strategy") {
            o.strategy = value();
            if (*o.strategy != "mis" && *o.strategy != "light" && *o.strategy != "bsdf")
                throw std::invalid_argument("--strategy expects mis, light or bsdf");
        } else if (a == "--wavelengths") {
            o.wavelengths = ParseInt(a, value(), 1);
            if (*o.wavelengths != 1 && *o.wavelengths != 4)
                throw std::invalid_argument("--wavelengths expects 1 or 4");
        } else if (a == "--view") {
            o.view = value();
        } else if (a == "--exposure") {
            o.exposure = value();
            if (*o.exposure != "auto" &&
                !(std::abs(ParseFloat(a, *o.exposure)) <= RGBFilm::kMaxExposureEV))
                throw std::invalid_argument("--exposure must be within +-" +
                                            std::to_string(int(RGBFilm::kMaxExposureEV)) +
                                            " stops");
        } else if (a == "--verbose" || a == "-v") {
            o.verbose = true;
        } else if (a == "--quiet" || a == "-q")
            o.quiet = true;
        else if (!a.empty() && a[0] == '-')
            throw std::invalid_argument(UnknownOption(a));
        else if (o.sceneFile.empty())
            o.sceneFile = a;
        else
            throw std::invalid_argument("more than one scene file given ('" + o.sceneFile +
                                        "' and '" + a + "')");
    }
    if (o.mseReferenceImage.empty() != o.mseReferenceOut.empty())
        throw std::invalid_argument(
            "--mse-reference-image and --mse-reference-out go together (the reference, and the "
            "file of \"spp, MSE\" lines)");
    if (std::string ext = FileExtension(o.sceneFile);
        ext == "exr" || ext == "png" || ext == "pfm" || ext == "hdr" || ext == "jpg" ||
        ext == "jpeg" || ext == "tif" || ext == "tiff")
        throw std::invalid_argument("'" + o.sceneFile +
                                    "' is an image, not a scene; to turn it into another format: "
                                    "kiln convert " +
                                    o.sceneFile + " -o OUT.png");
    if (o.frames) {
        for (const std::string& out : o.outputs)
            if (out.find('#') == std::string::npos && o.frames->first != o.frames->second)
                throw std::invalid_argument("with --frames, -o needs '#' for the frame number ('" +
                                            out + "')");
    }
    return o;
}

std::string FrameFilename(const std::string& pattern, int frame) {
    // The last run of '#' becomes the zero-padded frame number.
    size_t last = pattern.rfind('#');
    if (last == std::string::npos) return pattern;
    size_t first = last;
    while (first > 0 && pattern[first - 1] == '#') --first;
    std::string number = std::to_string(frame);
    size_t width = last - first + 1;
    if (number.size() < width) number.insert(0, width - number.size(), '0');
    return pattern.substr(0, first) + number + pattern.substr(last + 1);
}

int RunKiln(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "diff")
        return RunImageDiff(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::string(argv[1]) == "farm")
        return RunFarm(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::string(argv[1]) == "merge")
        return RunMerge(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::string(argv[1]) == "convert")
        return RunConvert(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::string(argv[1]) == "info")
        return RunInfo(std::vector<std::string>(argv + 2, argv + argc));
    CommandLineOptions options;
    try {
        options = ParseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
        if (!options.help && !options.version && options.sceneFile.empty())
            throw std::invalid_argument("no scene file given");
    } catch (const std::invalid_argument& e) {
        std::cerr << "kiln: " << e.what() << "\nsee kiln --help\n";
        return 2;
    }
    if (options.help) {
        std::cout << UsageText();
        return 0;
    }
    if (options.version) {
        std::cout << "kiln " << KILN_VERSION << "\n";
        // Where this kiln finds what it loads at run time (an installed tree or the build tree)
        std::cout << "  display config: " << OCIOConfigPath() << "\n";
        for (const char* plugin : {"libkiln_oiio.so", "libkiln_openvdb.so"}) {
            std::string dir = PluginDirectory(plugin);
            std::cout << "  plugin: "
                      << (dir.empty() ? std::string("(not found) ") + plugin : dir + "/" + plugin)
                      << "\n";
        }
        return 0;
    }

    return RenderCommand(options);
}

}  // namespace kiln
