#include "app/merge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "base/memory_budget.h"
#include "base/rng.h"
#include "core/film/thermal_sensor.h"

namespace kiln {

namespace {

constexpr float kMaxHalf = 65504;

std::string Meta(const RenderPart& p, const std::string& key) {
    auto it = p.metadata.strings.find(key);
    return it == p.metadata.strings.end() ? "" : it->second;
}

Point2i FullResolution(const RenderPart& p) {
    return p.metadata.fullResolution.value_or(p.image.Resolution());
}

Bounds2i PixelBounds(const RenderPart& p) {
    return p.metadata.pixelBounds.value_or(Bounds2i{{0, 0}, FullResolution(p)});
}

std::string ToString(const Bounds2i& b) {
    return "[" + std::to_string(b.pMin.x) + ", " + std::to_string(b.pMax.x) + ") x [" +
           std::to_string(b.pMin.y) + ", " + std::to_string(b.pMax.y) + ")";
}

// Parts must agree on what makes them pieces of one render (sameSeed false for --samples).
void CheckConsistent(const std::vector<RenderPart>& parts, bool tiles) {
    if (parts.empty()) throw std::runtime_error("no parts to merge");
    const RenderPart& first = parts[0];
    for (const RenderPart& p : parts) {
        auto differ = [&](const std::string& what, const std::string& a, const std::string& b) {
            throw std::runtime_error(p.file + " and " + first.file + " are from different " + what +
                                     " (" + b + " and " + a + ")");
        };
        if (Meta(p, "kiln:scene").empty())
            throw std::runtime_error(p.file + " was not rendered by kiln (no kiln:scene)");
        if (Meta(p, "kiln:scene") != Meta(first, "kiln:scene"))
            differ("scenes", Meta(first, "kiln:scene"), Meta(p, "kiln:scene"));
        if (Meta(p, "kiln:options") != Meta(first, "kiln:options"))
            differ("render options", Meta(first, "kiln:options"), Meta(p, "kiln:options"));
        if (Meta(p, "kiln:frame") != Meta(first, "kiln:frame"))
            differ("frames", Meta(first, "kiln:frame"), Meta(p, "kiln:frame"));
        if (Meta(p, "kiln:exposureEV") != Meta(first, "kiln:exposureEV"))
            differ("exposures", Meta(first, "kiln:exposureEV"), Meta(p, "kiln:exposureEV"));
        Point2i a = FullResolution(first), b = FullResolution(p);
        if (a != b)
            differ("resolutions", std::to_string(a.x) + "x" + std::to_string(a.y),
                   std::to_string(b.x) + "x" + std::to_string(b.y));
        if (p.image.ChannelNames() != first.image.ChannelNames())
            throw std::runtime_error(p.file + " and " + first.file + " have different channels");
        // kiln writes no NaN or infinity: a part that has one is damaged
        std::vector<std::string> names = p.image.ChannelNames();
        for (int y = 0; y < p.image.Resolution().y; ++y)
            for (int x = 0; x < p.image.Resolution().x; ++x)
                for (int c = 0; c < p.image.NChannels(); ++c)
                    if (!std::isfinite(p.image.GetChannel({x, y}, c)))
                        throw std::runtime_error(p.file + ": pixel " + std::to_string(x) + ", " +
                                                 std::to_string(y) + " " + names[size_t(c)] +
                                                 " is not finite; kiln writes no such value, so "
                                                 "the part is damaged");
        if (tiles) {
            if (Meta(p, "kiln:seed") != Meta(first, "kiln:seed"))
                differ("seeds", Meta(first, "kiln:seed"), Meta(p, "kiln:seed"));
            if (p.metadata.samplesPerPixel != first.metadata.samplesPerPixel)
                differ("sample counts", std::to_string(first.metadata.samplesPerPixel.value_or(0)),
                       std::to_string(p.metadata.samplesPerPixel.value_or(0)));
            if (Meta(p, "kiln:partial") == "true")
                throw std::runtime_error(p.file + " is a partial (interrupted) render of " +
                                         std::to_string(p.metadata.samplesPerPixel.value_or(0)) +
                                         " spp; render that tile again");
        }
    }
}

}  // namespace

namespace {

// Whether the parts' pixel bounds tile the frame exactly: each inside it and of its image's
// size, no two overlapping, no pixel left out. Works on the rectangles (bands of intervals for
// the holes), so a frame that the parts' headers claim to be huge is refused before anything of its
// size is allocated.
void CheckTiling(const std::vector<RenderPart>& parts, Point2i res) {
    std::vector<Bounds2i> bounds;
    for (const RenderPart& p : parts) {
        Bounds2i b = PixelBounds(p);
        if (b.pMin.x < 0 || b.pMin.y < 0 || b.pMax.x > res.x || b.pMax.y > res.y ||
            p.image.Resolution() != Point2i(b.pMax.x - b.pMin.x, b.pMax.y - b.pMin.y))
            throw std::runtime_error(p.file + ": its pixels " + ToString(b) +
                                     " do not fit the frame");
        for (size_t o = 0; o < bounds.size(); ++o) {
            Point2i lo(std::max(b.pMin.x, bounds[o].pMin.x), std::max(b.pMin.y, bounds[o].pMin.y));
            Point2i hi(std::min(b.pMax.x, bounds[o].pMax.x), std::min(b.pMax.y, bounds[o].pMax.y));
            if (lo.x < hi.x && lo.y < hi.y)
                throw std::runtime_error(p.file + " and " + parts[o].file +
                                         " overlap (both have pixel " + std::to_string(lo.x) +
                                         ", " + std::to_string(lo.y) + ")");
        }
        bounds.push_back(b);
    }
    // Holes, band by band: between consecutive part edges in y every row is covered alike, so
    // a frame whose header claims 2^30 rows costs as little as one of 20 (a row-by-row sweep
    // took minutes: fuzz_exr_part)
    std::vector<int> edges = {0, res.y};
    for (const Bounds2i& b : bounds) edges.insert(edges.end(), {b.pMin.y, b.pMax.y});
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    int64_t missing = 0;
    Bounds2i hole{{res.x, res.y}, {0, 0}};
    std::vector<std::pair<int, int>> spans;
    for (size_t band = 0; band + 1 < edges.size(); ++band) {
        const int y0 = edges[band], y1 = edges[band + 1];
        spans.clear();
        for (const Bounds2i& b : bounds)
            if (y0 >= b.pMin.y && y0 < b.pMax.y) spans.push_back({b.pMin.x, b.pMax.x});
        std::sort(spans.begin(), spans.end());
        int x = 0;
        spans.push_back({res.x, res.x});
        for (const auto& [x0, x1] : spans) {
            if (x0 > x) {
                missing += int64_t(x0 - x) * (y1 - y0);
                hole.pMin = Point2i(std::min(hole.pMin.x, x), std::min(hole.pMin.y, y0));
                hole.pMax = Point2i(std::max(hole.pMax.x, x0), std::max(hole.pMax.y, y1));
            }
            x = std::max(x, x1);
        }
    }
    if (missing > 0)
        throw std::runtime_error(std::to_string(missing) + " of the frame's " +
                                 std::to_string(int64_t(res.x) * res.y) +
                                 " pixels are in no part (all within " + ToString(hole) + ")");
}

}  // namespace

Image MergeTiles(const std::vector<RenderPart>& parts, ImageMetadata* metadata) {
    CheckConsistent(parts, true);
    const RenderPart& first = parts[0];
    Point2i res = FullResolution(first);
    CheckTiling(parts, res);
    // The parts tile the frame: it holds no more pixels than they do
    Image full(PixelFormat::Float, res, first.image.ChannelNames());
    float seconds = 0;
    for (const RenderPart& p : parts) {
        Bounds2i b = PixelBounds(p);
        for (int y = b.pMin.y; y < b.pMax.y; ++y)
            for (int x = b.pMin.x; x < b.pMax.x; ++x)
                for (int c = 0; c < full.NChannels(); ++c)
                    full.SetChannel({x, y}, c, p.image.GetChannel({x - b.pMin.x, y - b.pMin.y}, c));
        seconds += p.metadata.renderTimeSeconds.value_or(0);
    }
    *metadata = first.metadata;
    metadata->pixelBounds.reset();
    metadata->fullResolution.reset();
    metadata->renderTimeSeconds = seconds;
    bool half = true;
    for (const RenderPart& p : parts) half &= Meta(p, "kiln:savefp16") != "false";
    metadata->strings["kiln:savefp16"] = half ? "true" : "false";
    return full;
}

Image MergeSamples(const std::vector<RenderPart>& parts, ImageMetadata* metadata) {
    CheckConsistent(parts, false);
    const RenderPart& first = parts[0];
    double total = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        const RenderPart& p = parts[i];
        if (!(PixelBounds(p).pMin == PixelBounds(first).pMin) ||
            !(PixelBounds(p).pMax == PixelBounds(first).pMax))
            throw std::runtime_error(p.file + " and " + first.file + " cover different pixels (" +
                                     ToString(PixelBounds(p)) + " and " +
                                     ToString(PixelBounds(first)) + ")");
        for (size_t j = 0; j < i; ++j)
            if (Meta(parts[j], "kiln:seed") == Meta(p, "kiln:seed"))
                throw std::runtime_error(p.file + " and " + parts[j].file +
                                         " were rendered with the same seed (" +
                                         Meta(p, "kiln:seed") + "): the same samples");
        if (!p.metadata.samplesPerPixel || *p.metadata.samplesPerPixel <= 0)
            throw std::runtime_error(p.file + " does not say how many samples per pixel it holds");
        total += *p.metadata.samplesPerPixel;
    }
    Point2i res = first.image.Resolution();
    Image out(PixelFormat::Float, res, first.image.ChannelNames());
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < out.NChannels(); ++c) {
                double sum = 0;
                for (const RenderPart& p : parts)
                    sum += double(*p.metadata.samplesPerPixel) * p.image.GetChannel({x, y}, c);
                out.SetChannel({x, y}, c, float(sum / total));
            }
    // A thermal film's temperature is that of the merged radiance, not the mean temperature
    if (std::optional<ThermalSensor> sensor =
            ThermalSensor::FromSettings(Meta(first, "kiln:thermal"))) {
        int L = out.ChannelIndex("L"), T = out.ChannelIndex("T");
        if (L >= 0 && T >= 0)
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x)
                    out.SetChannel({x, y}, T,
                                   float(sensor->ApparentTemperature(out.GetChannel({x, y}, L))));
    }
    *metadata = first.metadata;
    metadata->samplesPerPixel = int(std::min<double>(total, std::numeric_limits<int>::max()));
    metadata->strings.erase("kiln:partial");
    std::string seeds;
    for (const RenderPart& p : parts) {
        if (!seeds.empty()) seeds += ',';
        seeds += Meta(p, "kiln:seed");
    }
    metadata->strings["kiln:seed"] = seeds;
    bool half = true;
    for (const RenderPart& p : parts) half &= Meta(p, "kiln:savefp16") != "false";
    metadata->strings["kiln:savefp16"] = half ? "true" : "false";
    return out;
}

void WriteMerged(const Image& image, const ImageMetadata& metadata, const std::string& filename) {
    if (FileExtension(filename) != "exr")
        throw std::runtime_error(filename + ": kiln merge writes OpenEXR (.exr) files");
    bool half = true;
    if (auto it = metadata.strings.find("kiln:savefp16"); it != metadata.strings.end())
        half = it->second != "false";
    for (int y = 0; y < image.Resolution().y && half; ++y)
        for (int x = 0; x < image.Resolution().x && half; ++x)
            for (int c = 0; c < image.NChannels(); ++c)
                if (std::abs(image.GetChannel({x, y}, c)) > kMaxHalf) half = false;
    (half ? image.ConvertToFormat(PixelFormat::Half) : image).Write(filename, metadata);
}

int RunMerge(const std::vector<std::string>& args) {
    std::vector<std::string> files;
    std::string out;
    bool samples = false;
    MemoryBudget budget;  // the machine's memory, or --memory-limit
    auto usage = [](const std::string& message) {
        std::cerr << "kiln merge: " << message << "\n"
                  << "usage: kiln merge PART.exr... -o FULL.exr [--memory-limit SIZE]\n"
                  << "       kiln merge --samples RENDER.exr... -o OUT.exr [--memory-limit SIZE]\n";
        return 2;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-o" || args[i] == "--outfile") {
            if (i + 1 >= args.size()) return usage("-o needs a file name");
            out = args[++i];
        } else if (args[i] == "--samples") {
            samples = true;
        } else if (args[i] == "--memory-limit") {
            std::optional<double> bytes;
            if (i + 1 < args.size()) bytes = MemoryBudget::ParseSize(args[++i]);
            if (!bytes) return usage("--memory-limit needs a size (8G, 512M, ...)");
            budget.SetLimit(*bytes);
        } else if (args[i] == "--quiet") {
            // merge prints only errors

        } else if (args[i] == "-h" || args[i] == "--help") {
            usage("assembles tiles, or combines renders with different seeds");
            return 0;
        } else if (!args[i].empty() && args[i][0] == '-') {
            return usage("unknown option '" + args[i] + "'");
        } else {
            files.push_back(args[i]);
        }
    }
    if (files.empty()) return usage("no parts given");
    if (out.empty()) return usage("no output (-o FULL.exr)");
    try {
        std::vector<RenderPart> parts;
        for (const std::string& f : files) {
            RenderPart p;
            p.file = f;
            p.image = Image::Read(f, &p.metadata, std::nullopt, &budget);
            parts.push_back(std::move(p));
        }
        // The merged frame holds as many pixels as the parts (tiles) or as one of them
        // (samples), in float; checked against the parts' own claims by the merges
        double frame = 0;
        for (const RenderPart& p : parts)
            frame = samples ? std::max(frame, double(p.image.Resolution().x) *
                                                  p.image.Resolution().y * p.image.NChannels())
                            : frame + double(p.image.Resolution().x) * p.image.Resolution().y *
                                          p.image.NChannels();
        budget.Charge(frame * sizeof(float) * (samples ? 3 : 1),
                      "the merged frame (" + std::to_string(int64_t(frame)) + " samples)");
        ImageMetadata metadata;
        Image merged = samples ? MergeSamples(parts, &metadata) : MergeTiles(parts, &metadata);
        WriteMerged(merged, metadata, out);
    } catch (const std::exception& e) {
        std::cerr << "kiln merge: error: " << e.what() << "; nothing written\n";
        return 1;
    }
    return 0;
}

}  // namespace kiln
