// Renders of a window of a scene file for the regression tests that compare two ways of
// rendering every scene in scenes/ (polarised against unpolarised, volpath against path).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "../render/render_test_util.h"
#include "core/image/image.h"
#include "noise_comparison.h"

namespace kiln::testing {

// A scene file loaded once with the "independent" sampler (renders with different seeds must
// be independent for the across-seed variance to measure the error, as in regression_test.cpp)
// and options o; edit changes the description first. Nothing if accept rejects the scene.
inline std::unique_ptr<Scene> LoadScene(const std::string& file, const RenderOptions& o,
                                        const std::function<void(SceneDescription&)>& edit = {},
                                        const std::function<bool(const Scene&)>& accept = {}) {
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    ParseFile(builder, file, diag);
    builder.Description().sampler.name = "independent";
    if (edit) edit(builder.Description());
    std::unique_ptr<Scene> scene = Scene::Create(builder.Description(), o, diag);
    if (accept && !accept(*scene)) return nullptr;
    return scene;
}

// A window (NDC) of a loaded scene at spp samples per pixel with the given seed: a new render
// job of the same scene (Scene::SetJob), nothing re-parsed or rebuilt. R, G and B, or a thermal
// film's in-band radiance L (its temperature T is not linear in the samples).
inline Image RenderWindow(Scene& scene, const Bounds2f& window, int spp, int seed) {
    Diagnostics diag(nullptr);
    RenderOptions job;
    job.samplesPerPixel = spp;
    job.seed = seed;
    job.cropWindow = window;
    scene.SetJob(job, diag);
    RenderSettings settings;
    Render(scene, settings);
    EXPECT_EQ(scene.job->film->NonFiniteSampleCount(), 0);
    Image image = scene.job->film->GetImage(nullptr);
    return scene.job->film->Thermal() ? image.SelectChannels({"L"})
                                      : image.SelectChannels({"R", "G", "B"});
}

inline bool IsBlack(const Image& image) {
    for (int y = 0; y < image.Resolution().y; ++y)
        for (int x = 0; x < image.Resolution().x; ++x)
            for (int c = 0; c < image.NChannels(); ++c)
                if (image.GetChannel({x, y}, c) != 0) return false;
    return true;
}

// A scene file: NAME.pbrt, or NAME.pbrt.gz (gzip-compressed, as pbrt-v4 reads them).
inline bool IsSceneFile(const std::string& path) {
    auto endsWith = [&](const std::string& tail) {
        return path.size() >= tail.size() &&
               path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
    };
    return endsWith(".pbrt") || endsWith(".pbrt.gz");
}

// Every .pbrt (or .pbrt.gz) file under scenes/, sorted.
inline std::vector<std::string> SceneFiles() {
    std::vector<std::string> files;
    for (const auto& e :
         std::filesystem::recursive_directory_iterator(std::string(KILN_SOURCE_DIR) + "/scenes"))
        if (IsSceneFile(e.path().string())) files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// One scene file of every folder under scenes/ (one of each kind): the first whose text names
// no medium ("MakeNamedMedium") and no absorbing glass (a "spectrum k" of kiln's named glasses,
// which scene creation fills with media) and that is not gzip-compressed (pbrt-v4's format for
// large scenes: showcase/bulbs.pbrt.gz's volpath comparison took 37 s, six times any other's);
// failing that the first without media, else the folder's first. Compressed scenes are taken
// to have no media (their text is not read).
inline std::vector<std::string> OneScenePerFolder() {
    auto rank = [](const std::string& file) {
        if (file.size() > 3 && file.compare(file.size() - 3, 3, ".gz") == 0) return 1;
        std::ifstream in(file);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        bool media = text.find("MakeNamedMedium") != std::string::npos ||
                     text.find("\"spectrum k\" \"glass-") != std::string::npos;
        return media ? 2 : 0;
    };
    std::vector<std::string> files, all = SceneFiles();
    std::vector<int> chosenRank;
    for (const std::string& f : all) {
        int r = rank(f);
        if (files.empty() || std::filesystem::path(files.back()).parent_path() !=
                                 std::filesystem::path(f).parent_path()) {
            files.push_back(f);
            chosenRank.push_back(r);
        } else if (r < chosenRank.back()) {
            files.back() = f;
            chosenRank.back() = r;
        }
    }
    return files;
}

// The name of a scene file for a parameterised test: its path under scenes/ with every
// character that is not a letter or digit replaced by '_' ("wilkie2011_fig5_pbrt").
inline std::string SceneTestName(const ::testing::TestParamInfo<std::string>& info) {
    std::string rel =
        std::filesystem::relative(info.param, std::string(KILN_SOURCE_DIR) + "/scenes").string();
    for (char& c : rel)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return rel;
}

// A scene rendered two ways and compared within the Monte Carlo noise: load(file,
// alternative) loads the scene the plain way (alternative false) or the way under test
// (LoadScene), or returns nothing to skip it. A render of the plain scene at referenceSpp is
// the reference for `seeds` renders of the alternative at spp samples per pixel with
// independent seeds (noise_comparison.h), over the centre of the image (or below it, where the
// centre is black), a tenth of it on a side and at most 64 x 64 pixels; each scene is loaded once
// and rendered as new jobs. Accepted within `sigmas` (noise_comparison.h); the comparison must also
// see a 10 % error. Returns whether the scene was compared (false: load skipped it).
using SceneLoader =
    std::function<std::unique_ptr<Scene>(const std::string& file, bool alternative)>;
inline bool CompareScene(const std::string& file, const SceneLoader& load, int kSpp, int kSeeds,
                         int kReferenceSpp, double sigmas = 4) {
    SCOPED_TRACE(file);
    std::string name = std::filesystem::path(file).filename().string();
    std::unique_ptr<Scene> plain = load(file, false);
    if (!plain) return false;
    // A tenth of the image on a side, at most 64 x 64 pixels (enough pixels to see a 10 %
    // error; large films cost no more than small ones)
    Point2i res = plain->job->film->FullResolution();
    Vector2f half(std::min(0.05f, 32.f / float(res.x)), std::min(0.05f, 32.f / float(res.y)));
    auto around = [&](Point2f c) { return Bounds2f{c + -half, c + half}; };
    Bounds2f window = around({0.5f, 0.5f});
    Image reference = RenderWindow(*plain, window, kReferenceSpp, 1000);
    if (IsBlack(reference)) {
        window = around({0.5f, 0.75f});
        reference = RenderWindow(*plain, window, kReferenceSpp, 1000);
    }
    plain.reset();
    std::unique_ptr<Scene> alternative = load(file, true);
    if (!alternative) {
        ADD_FAILURE() << "the alternative of a compared scene did not load";
        return false;
    }
    std::vector<Image> renders;
    for (int k = 0; k < kSeeds; ++k)
        renders.push_back(RenderWindow(*alternative, window, kSpp, k + 1));
    NoiseComparison c = CompareWithNoise(renders, reference, kSpp, kReferenceSpp, sigmas);
    EXPECT_TRUE(c.Pass()) << c;
    EXPECT_FALSE(CompareWithNoise(renders, reference, kSpp, kReferenceSpp, sigmas, 1.1).Pass());
    std::printf("%s: %s\n", name.c_str(), ::testing::PrintToString(c).c_str());
    return true;
}

}  // namespace kiln::testing
