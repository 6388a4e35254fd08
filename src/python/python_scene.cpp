#include "python/python_scene.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "base/plugin.h"
#include "core/parser/parser.h"
#include "render/renderer.h"
#include "render/scene_builder.h"
#include "render/scene_edits.h"

namespace py = pybind11;

namespace kiln {

namespace {

// Image: a render's pixels with named channels, and its metadata

struct PythonImage {
    Image image;
    ImageMetadata metadata;
    RenderStats stats;
    bool rendered = false;  // by Scene.render (else read from a file)

    // Channels `names` (all when empty) as a float32 array, height x width x channels.
    py::array_t<float> Array(const std::vector<std::string>& names) const {
        std::vector<int> channels;
        for (const std::string& n : names.empty() ? image.ChannelNames() : names) {
            int c = image.ChannelIndex(n);
            if (c < 0)
                throw py::key_error("no channel \"" + n + "\" (channels: " + ChannelList() + ")");
            channels.push_back(c);
        }
        Point2i res = image.Resolution();
        py::array_t<float> a(
            {py::ssize_t(res.y), py::ssize_t(res.x), py::ssize_t(channels.size())});
        auto out = a.mutable_unchecked<3>();
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x)
                for (size_t k = 0; k < channels.size(); ++k)
                    out(y, x, py::ssize_t(k)) = float(image.GetChannel({x, y}, channels[k]));
        return a;
    }
    std::string ChannelList() const {
        std::string s;
        for (const std::string& n : image.ChannelNames()) s += (s.empty() ? "" : ", ") + n;
        return s;
    }
    py::dict Metadata() const {
        py::dict d;
        if (metadata.samplesPerPixel) d["samples_per_pixel"] = *metadata.samplesPerPixel;
        if (metadata.renderTimeSeconds) d["render_seconds"] = *metadata.renderTimeSeconds;
        if (auto seed = metadata.strings.find("kiln:seed"); seed != metadata.strings.end())
            d["seed"] = std::stoi(seed->second);
        if (rendered) {
            d["camera_paths"] = stats.cameraPaths;
            d["interrupted"] = stats.cancelled;
        }
        if (metadata.fullResolution)
            d["full_resolution"] =
                py::make_tuple(metadata.fullResolution->x, metadata.fullResolution->y);
        if (metadata.pixelBounds) {
            const Bounds2i& b = *metadata.pixelBounds;
            d["pixel_bounds"] = py::make_tuple(b.pMin.x, b.pMax.x, b.pMin.y, b.pMax.y);
        }
        if (metadata.colorSpace)
            d["color_space"] = metadata.colorSpace == &RGBColorSpace::sRGB() ? "srgb" : "other";
        for (const auto& [k, v] : metadata.strings) d[py::str(k)] = v;
        return d;
    }
};

// Scene: the parsed description and the scene created from it

class PythonScene {
  public:
    // Parses a file (searchDirectory its folder) or text (relative names against
    // searchDirectory); throws SceneError with the file, line and column.
    PythonScene(const std::string* file, const std::string* text, const std::string& directory)
        : diag(&warnings) {
        SceneBuilder builder(diag);
        if (file)
            ParseFile(builder, *file, diag);
        else
            ParseString(builder, *text, diag, "<string>", directory);
        description = std::move(builder.Description());
        Create(RenderOptions{});
    }

    py::array_t<float> Render(std::optional<int> spp, std::optional<int> seed, int threads,
                              std::optional<std::array<Float, 4>> crop, std::optional<int> frame,
                              std::optional<double> time, double fps,
                              std::optional<std::string> emission, std::optional<bool> stokes,
                              std::optional<std::string> reconstruction) {
        RenderOptions options = created;
        options.samplesPerPixel = spp;
        options.seed = seed;
        options.cropWindow.reset();
        if (crop) {
            const auto& c = *crop;
            if (!(c[0] >= 0 && c[0] < c[1] && c[1] <= 1 && c[2] >= 0 && c[2] < c[3] && c[3] <= 1))
                throw py::value_error(
                    "crop expects (x0, x1, y0, y1) with 0 <= x0 < x1 <= 1 and "
                    "0 <= y0 < y1 <= 1");
            options.cropWindow = Bounds2f{Point2f(c[0], c[2]), Point2f(c[1], c[3])};
        }
        if (!(fps > 0)) throw py::value_error("fps must be positive");
        options.frame = frame;
        options.timeSeconds.reset();
        if (time)
            options.timeSeconds = Float(*time);
        else if (frame)
            options.timeSeconds = Float(*frame / fps);
        if (emission) {
            options.emission = ParseEmissionModel(*emission);
            if (!options.emission)
                throw py::value_error("emission \"" + *emission +
                                      "\": expected kirchhoff, additive, diffuse or none");
        } else
            options.emission.reset();
        options.stokes = stokes;
        options.spreadSamples.reset();
        if (reconstruction) {
            if (*reconstruction != "spread" && *reconstruction != "importance")
                throw py::value_error("reconstruction \"" + *reconstruction +
                                      "\": expected spread or importance");
            options.spreadSamples = *reconstruction == "spread";
        }
        if (threads < 0) throw py::value_error("threads must be >= 0 (0: all)");

        // What was built at load changes: create the scene again from the description
        if (!scene || options.emission != created.emission || options.stokes != created.stokes)
            Create(options);
        else {
            TemperatureAnimation animation{options.frame, options.timeSeconds};
            if (animation.frame != scene->Animation().frame ||
                animation.timeSeconds != scene->Animation().timeSeconds)
                scene->SetAnimation(animation);
            scene->SetJob(options, diag);
        }
        // A thermal film's in-band radiance and temperature; any other film's RGB
        if (scene->job->film->Thermal()) return RenderNow(threads).Array({"L", "T"});
        return RenderNow(threads).Array({"R", "G", "B"});
    }

    void SetTemperature(const std::string& name, double kelvin, const std::string& kind) {
        TemperatureTarget target = TemperatureTarget::Any;
        if (kind == "material")
            target = TemperatureTarget::Material;
        else if (kind == "texture")
            target = TemperatureTarget::Texture;
        else if (kind == "object")
            target = TemperatureTarget::Object;
        else if (!kind.empty())
            throw py::value_error("kind \"" + kind + "\": expected material, texture or object");
        try {
            kiln::SetTemperature(description, name, kelvin, target);
        } catch (const std::invalid_argument& e) {
            throw py::key_error(e.what());
        }
        scene.reset();  // created again, with the new temperature, by the next render
    }
    void SetShapeTemperature(int index, double kelvin) {
        try {
            kiln::SetShapeTemperature(description, index, kelvin);
        } catch (const std::invalid_argument& e) {
            throw py::index_error(e.what());
        }
        scene.reset();
    }

    py::dict Names() const {
        TemperatureNames n = ListTemperatureNames(description);
        py::dict d;
        d["materials"] = n.materials;
        d["textures"] = n.textures;
        d["objects"] = n.objects;
        d["shapes"] = n.shapes;
        return d;
    }
    const PythonImage& LastImage() const {
        if (!last) throw std::runtime_error("nothing rendered yet: call render() first");
        return *last;
    }
    // Writes the last render as the kiln command writes its outputs (by extension; display
    // formats through `view`).
    void Write(const std::string& path, const std::string& view) const {
        const PythonImage& image = LastImage();
        if (!scene)
            throw std::runtime_error("the scene changed since the last render: render again");
        ImageMetadata metadata = image.metadata;
        scene->job->film->WriteImage(path, metadata, view, &diag);
    }
    py::tuple Resolution() {
        EnsureScene();
        Point2i r = scene->job->film->FullResolution();
        return py::make_tuple(r.x, r.y);
    }
    std::vector<std::string> Warnings() const {
        std::vector<std::string> out;
        for (const Diagnostics::Warning& w : diag.Warnings())
            out.push_back(w.loc.ToString().empty() ? w.message
                                                   : w.loc.ToString() + ": " + w.message);
        return out;
    }

  private:
    void Create(const RenderOptions& options) {
        scene.reset();  // its memory is free before the next is made
        scene = Scene::Create(description, options, diag);
        created = options;
        created.samplesPerPixel.reset();
        created.seed.reset();
        created.cropWindow.reset();
    }
    void EnsureScene() {
        if (!scene) Create(created);
    }

    // Renders the current job on a worker thread while this thread, holding the GIL between
    // waits, lets Python's signal handlers run: Ctrl-C cancels the render (after its tile) and
    // raises KeyboardInterrupt.
    const PythonImage& RenderNow(int threads) {
        std::atomic<bool> cancel{false};
        RenderSettings settings;
        settings.threads = threads;
        settings.cancel = &cancel;
        RenderStats stats;
        std::exception_ptr failure;
        std::mutex mutex;
        std::condition_variable finished;
        bool done = false;
        {
            py::gil_scoped_release release;
            std::thread worker([&] {
                try {
                    stats = kiln::Render(*scene, settings);
                } catch (...) {
                    failure = std::current_exception();
                }
                std::lock_guard<std::mutex> lock(mutex);
                done = true;
                finished.notify_all();
            });
            bool interrupted = false;
            std::unique_lock<std::mutex> lock(mutex);
            // Wakes when the render ends, or every 100 ms to run Python's signal handlers
            while (!finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) {
                if (interrupted) continue;
                lock.unlock();
                {
                    py::gil_scoped_acquire acquire;
                    if (PyErr_CheckSignals() != 0) {
                        interrupted = true;
                        cancel = true;
                        // The exception stays set in the interpreter until it is raised below
                    }
                }
                lock.lock();
            }
            lock.unlock();
            worker.join();
            if (interrupted) {
                py::gil_scoped_acquire acquire;
                throw py::error_already_set();
            }
        }
        if (failure) std::rethrow_exception(failure);
        if (int64_t bad = scene->job->film->NonFiniteSampleCount(); bad > 0)
            diag.Warn(std::to_string(bad) + " NaN/Inf radiance samples were discarded");
        auto image = std::make_unique<PythonImage>();
        image->image = scene->job->film->GetImage(&image->metadata);
        image->stats = stats;
        image->rendered = true;
        image->metadata.renderTimeSeconds = float(stats.seconds);
        image->metadata.samplesPerPixel =
            stats.cancelled ? stats.completedSamples : stats.samplesPerPixel;
        image->metadata.strings["kiln:seed"] = std::to_string(scene->job->sampler->Seed());
        image->metadata.strings["kiln:options"] = RenderOptionsKey(created);
        image->metadata.strings["kiln:exposureEV"] =
            std::to_string(scene->job->film->GetOptions().exposureEV);
        if (scene->Animation().frame)
            image->metadata.strings["kiln:frame"] = std::to_string(*scene->Animation().frame);
        last = std::move(image);
        return *last;
    }

    std::ostringstream warnings;  // printed nowhere: Warnings() lists them
    mutable Diagnostics diag;
    SceneDescription description;
    RenderOptions created;  // what the scene was created with (per-render options unset)
    std::unique_ptr<Scene> scene;
    std::unique_ptr<PythonImage> last;
};

}  // namespace

void RegisterScene(py::module_& m) {
    py::class_<PythonImage>(m, "Image",
                            "A render: its channels (R, G, B, and AOVs or Stokes layers when the "
                            "film records them) and metadata.")
        .def_property_readonly("channels",
                               [](const PythonImage& i) { return i.image.ChannelNames(); })
        .def_property_readonly("metadata", &PythonImage::Metadata)
        .def("array", &PythonImage::Array, py::arg("channels") = std::vector<std::string>{},
             "The channels (all by default) as float32, height x width x channels.")
        .def("__getitem__", [](const PythonImage& i, const std::string& name) {
            py::array_t<float> a = i.Array({name});
            return a.attr("reshape")(a.shape(0), a.shape(1));
        });

    py::class_<PythonScene>(m, "Scene", "A parsed pbrt-v4 scene, rendered as often as asked.")
        .def("render", &PythonScene::Render, py::kw_only(), py::arg("spp") = py::none(),
             py::arg("seed") = py::none(), py::arg("threads") = 0, py::arg("crop") = py::none(),
             py::arg("frame") = py::none(), py::arg("time") = py::none(), py::arg("fps") = 24.0,
             py::arg("emission") = py::none(), py::arg("stokes") = py::none(),
             py::arg("reconstruction") = py::none())
        .def("set_temperature", &PythonScene::SetTemperature, py::arg("name"), py::arg("kelvin"),
             py::kw_only(), py::arg("kind") = "")
        .def("set_shape_temperature", &PythonScene::SetShapeTemperature, py::arg("index"),
             py::arg("kelvin"))
        .def_property_readonly("names", &PythonScene::Names)
        .def_property_readonly("resolution", &PythonScene::Resolution)
        .def_property_readonly("warnings", &PythonScene::Warnings)
        .def("image", &PythonScene::LastImage, py::return_value_policy::copy)
        .def("write", &PythonScene::Write, py::arg("path"), py::kw_only(), py::arg("view") = "");

    m.def(
        "read_image",
        [](const std::string& path) {
            PythonImage image;
            image.image = Image::Read(path, &image.metadata);
            return image;
        },
        py::arg("path"),
        "Reads an image (EXR with every layer and kiln's metadata, or any format OpenImageIO "
        "reads) as a kiln.Image.");
    m.def("_install_prefix", &InstallPrefix);  // where the module finds plugins (tests)
    py::register_exception<SceneError>(m, "SceneError", PyExc_ValueError);
    m.def(
        "_load",
        [](const std::string& file) { return std::make_unique<PythonScene>(&file, nullptr, ""); },
        py::arg("file"));
    m.def(
        "_load_string",
        [](const std::string& text, const std::string& directory) {
            return std::make_unique<PythonScene>(nullptr, &text, directory);
        },
        py::arg("text"), py::arg("directory") = "");
}

}  // namespace kiln
