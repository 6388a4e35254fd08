// kiln_microbench: Google Benchmark microbenchmarks of kiln's hot paths.
//
// Spectral: Planck's law (scalar and per path), Fresnel, SpectrumToXYZ, RGB-to-spectrum lookup.
// Scattering: BSDF::Sample_f and BSDF::f for diffuse, rough conductor, rough dielectric and
// coated diffuse BxDFs. Ray tracing: Accelerator::Intersect against raw rtcIntersect1 on the
// same RTCScene with the same incoherent random rays in the Cornell box (scenes/cornell-box),
// camera rays traced one by one and in Embree packets, and the whole renderer's camera paths
// per second on that scene.
//
// Each benchmark cycles through a fixed table of pre-drawn random inputs, so the measured loop
// holds no random number generation and the compiler cannot fold the work away.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <time.h>

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/rng.h"
#include "base/sampling.h"
#include "core/geometry/accelerator.h"
#include "core/parser/parser.h"
#include "materials/bxdfs/bsdf.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/microfacet.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "render/scene_builder.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"
#include "spectral/planck.h"
#include "spectral/rgb_to_spectrum.h"
#include "spectral/sampled_spectrum.h"

#ifndef KILN_SOURCE_DIR
#define KILN_SOURCE_DIR "."
#endif

namespace kiln {
namespace {

constexpr int kTableSize = 1024;  // power of two: index with & (kTableSize - 1)

std::vector<Float> UniformTable(uint64_t seed, int n = kTableSize) {
    RNG rng(seed);
    std::vector<Float> u(n);
    for (Float& v : u) v = rng.UniformFloat();
    return u;
}

std::vector<SampledWavelengths> WavelengthTable(uint64_t seed) {
    std::vector<SampledWavelengths> t;
    for (Float u : UniformTable(seed)) t.push_back(SampledWavelengths::SampleVisible(u));
    return t;
}

// ---------------------------------------------------------------------------------------------
// Spectral

void BM_PlanckRadianceScalar(benchmark::State& state) {
    std::vector<Float> u = UniformTable(1);
    size_t i = 0;
    for (auto _ : state) {
        double lambda = 360 + 470 * u[i & (kTableSize - 1)];    // nm
        double T = 500 + 5500 * u[(i + 7) & (kTableSize - 1)];  // K
        benchmark::DoNotOptimize(planck_radiance(lambda, T));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PlanckRadianceScalar);

void BM_PlanckRadianceSampled(benchmark::State& state) {
    std::vector<SampledWavelengths> lambdas = WavelengthTable(2);
    std::vector<Float> u = UniformTable(3);
    size_t i = 0;
    for (auto _ : state) {
        double T = 500 + 5500 * u[i & (kTableSize - 1)];
        benchmark::DoNotOptimize(planck_radiance(lambdas[i & (kTableSize - 1)], T));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());  // items: SampledSpectrum evaluations
}
BENCHMARK(BM_PlanckRadianceSampled);

void BM_FrDielectric(benchmark::State& state) {
    std::vector<Float> u = UniformTable(4);
    size_t i = 0;
    for (auto _ : state) {
        Float cosTheta = 2 * u[i & (kTableSize - 1)] - 1;  // both sides of the interface
        benchmark::DoNotOptimize(FrDielectric(cosTheta, 1.5f));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrDielectric);

void BM_FrComplexScalar(benchmark::State& state) {
    std::vector<Float> u = UniformTable(5);
    const std::complex<Float> eta(0.2f, 3.4f);  // about gold at 600 nm
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(FrComplex(u[i & (kTableSize - 1)], eta));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrComplexScalar);

void BM_FrComplexSampled(benchmark::State& state) {
    std::vector<Float> u = UniformTable(6);
    std::vector<SampledWavelengths> lambdas = WavelengthTable(7);
    const Spectrum* etaAu = GetNamedSpectrum("metal-Au-eta");
    const Spectrum* kAu = GetNamedSpectrum("metal-Au-k");
    std::vector<SampledSpectrum> eta, k;
    for (const SampledWavelengths& l : lambdas) {
        eta.push_back(etaAu->Sample(l));
        k.push_back(kAu->Sample(l));
    }
    size_t i = 0;
    for (auto _ : state) {
        size_t j = i & (kTableSize - 1);
        benchmark::DoNotOptimize(FrComplex(u[j], eta[j], k[j]));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrComplexSampled);

void BM_SpectrumToXYZ(benchmark::State& state) {
    std::vector<SampledWavelengths> lambdas = WavelengthTable(8);
    std::vector<Float> u = UniformTable(9, 4 * kTableSize);
    std::vector<SampledSpectrum> s;
    for (int j = 0; j < kTableSize; ++j)
        s.push_back(SampledSpectrum({u[4 * j], u[4 * j + 1], u[4 * j + 2], u[4 * j + 3]}));
    size_t i = 0;
    for (auto _ : state) {
        size_t j = i & (kTableSize - 1);
        benchmark::DoNotOptimize(SpectrumToXYZ(s[j], lambdas[j]));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SpectrumToXYZ);

// RGB -> sigmoid polynomial coefficients (trilinear lookup in the 64^3 x 3 table, pbrt-v4's
// RGBToSpectrumTable), then evaluation at the path's 4 wavelengths as a texture lookup does.
void BM_RGBToSpectrum(benchmark::State& state) {
    const RGBToSpectrumTable* table = RGBToSpectrumTable::Get("srgb");
    std::vector<Float> u = UniformTable(10, 3 * kTableSize);
    std::vector<SampledWavelengths> lambdas = WavelengthTable(11);
    size_t i = 0;
    for (auto _ : state) {
        size_t j = i & (kTableSize - 1);
        RGBSigmoidPolynomial rsp = (*table)(RGB(u[3 * j], u[3 * j + 1], u[3 * j + 2]));
        Float sum = 0;
        for (int c = 0; c < NSpectrumSamples; ++c) sum += rsp(lambdas[j][c]);
        benchmark::DoNotOptimize(sum);
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RGBToSpectrum);

// ---------------------------------------------------------------------------------------------
// BSDFs: a shading frame with normal +z, outgoing directions on the upper hemisphere.

enum class BxDFKind { Diffuse, RoughConductor, RoughDielectric, CoatedDiffuse };

BxDF MakeBxDF(BxDFKind kind, const SampledWavelengths& lambda) {
    TrowbridgeReitzDistribution rough(TrowbridgeReitzDistribution::RoughnessToAlpha(0.1f),
                                      TrowbridgeReitzDistribution::RoughnessToAlpha(0.1f));
    switch (kind) {
        case BxDFKind::Diffuse:
            return DiffuseBxDF(SampledSpectrum(0.5f));
        case BxDFKind::RoughConductor:
            return ConductorBxDF(rough, GetNamedSpectrum("metal-Cu-eta")->Sample(lambda),
                                 GetNamedSpectrum("metal-Cu-k")->Sample(lambda));
        case BxDFKind::RoughDielectric:
            return DielectricBxDF(1.5f, rough);
        case BxDFKind::CoatedDiffuse:
            // pbrt-v4's coateddiffuse defaults: thickness 0.01, maxdepth 10, nsamples 1, no medium
            return CoatedDiffuseBxDF(DielectricBxDF(1.5f, TrowbridgeReitzDistribution(0, 0)),
                                     DiffuseBxDF(SampledSpectrum(0.5f)), 0.01f, SampledSpectrum(0),
                                     0, 10, 1);
    }
    return {};
}

struct BSDFInputs {
    std::vector<Vector3f> wo, wi;
    std::vector<Float> uc;
    std::vector<Point2f> u2;
};

BSDFInputs MakeBSDFInputs(uint64_t seed) {
    BSDFInputs in;
    RNG rng(seed);
    for (int i = 0; i < kTableSize; ++i) {
        in.wo.push_back(SampleUniformHemisphere({rng.UniformFloat(), rng.UniformFloat()}));
        in.wi.push_back(SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()}));
        in.uc.push_back(rng.UniformFloat());
        in.u2.push_back({rng.UniformFloat(), rng.UniformFloat()});
    }
    return in;
}

void BM_BSDF_Sample_f(benchmark::State& state, BxDFKind kind) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    BSDF bsdf(Normal3f(0, 0, 1), Vector3f(1, 0, 0), MakeBxDF(kind, lambda));
    BSDFInputs in = MakeBSDFInputs(12);
    size_t i = 0;
    for (auto _ : state) {
        size_t j = i & (kTableSize - 1);
        benchmark::DoNotOptimize(bsdf.Sample_f(in.wo[j], in.uc[j], in.u2[j]));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_BSDF_Sample_f, diffuse, BxDFKind::Diffuse);
BENCHMARK_CAPTURE(BM_BSDF_Sample_f, rough_conductor, BxDFKind::RoughConductor);
BENCHMARK_CAPTURE(BM_BSDF_Sample_f, rough_dielectric, BxDFKind::RoughDielectric);
BENCHMARK_CAPTURE(BM_BSDF_Sample_f, coated_diffuse, BxDFKind::CoatedDiffuse);

void BM_BSDF_f(benchmark::State& state, BxDFKind kind) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    BSDF bsdf(Normal3f(0, 0, 1), Vector3f(1, 0, 0), MakeBxDF(kind, lambda));
    BSDFInputs in = MakeBSDFInputs(13);
    size_t i = 0;
    for (auto _ : state) {
        size_t j = i & (kTableSize - 1);
        benchmark::DoNotOptimize(bsdf.f(in.wo[j], in.wi[j]));
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_BSDF_f, diffuse, BxDFKind::Diffuse);
BENCHMARK_CAPTURE(BM_BSDF_f, rough_conductor, BxDFKind::RoughConductor);
BENCHMARK_CAPTURE(BM_BSDF_f, rough_dielectric, BxDFKind::RoughDielectric);
BENCHMARK_CAPTURE(BM_BSDF_f, coated_diffuse, BxDFKind::CoatedDiffuse);

// ---------------------------------------------------------------------------------------------
// Ray tracing in the Cornell box

std::string CornellBoxPath() {
    return std::string(KILN_SOURCE_DIR) + "/scenes/cornell-box/cornell-box.pbrt";
}

std::unique_ptr<Scene> LoadScene(const std::string& file, const RenderOptions& overrides) {
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    ParseFile(builder, file, diag);
    return Scene::Create(builder.Description(), overrides, diag);
}

// The scene is loaded once per benchmark run (a few ms) and shared by the ray benchmarks; it
// is immutable after creation.
const Scene& CornellBox() {
    static const std::unique_ptr<Scene> scene = LoadScene(CornellBoxPath(), {});
    return *scene;
}

constexpr int kNumRays = 1 << 16;

// Incoherent rays: origins uniform in the scene's bounding box, directions uniform on the
// sphere (the worst case for BVH traversal coherence, like deep path vertices).
std::vector<Ray> IncoherentRays(const Scene& scene) {
    Bounds3f b = scene.aggregate->Bounds();
    RNG rng(14);
    std::vector<Ray> rays;
    rays.reserve(kNumRays);
    for (int i = 0; i < kNumRays; ++i) {
        Point3f t(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat());
        Point3f o(Lerp(t.x, b.pMin.x, b.pMax.x), Lerp(t.y, b.pMin.y, b.pMax.y),
                  Lerp(t.z, b.pMin.z, b.pMax.z));
        rays.push_back(Ray(o, SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()})));
    }
    return rays;
}

// Raw Embree closest hit on kiln's RTCScene; returns whether something was hit.
bool RawIntersect(RTCScene scene, const Ray& ray) {
    EmbreeQueryContext ctx;
    RTCRayHit rh = MakeEmbreeRayHit(ray, Infinity);
    rtcIntersect1(scene, &ctx.context, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

int64_t TraceKiln(const Scene& scene, const std::vector<Ray>& rays) {
    int64_t hits = 0;
    for (const Ray& r : rays) hits += scene.aggregate->Intersect(r, Infinity).has_value();
    return hits;
}

int64_t TraceRaw(const Scene& scene, const std::vector<Ray>& rays) {
    RTCScene rtc = scene.aggregate->EmbreeScene();
    int64_t hits = 0;
    for (const Ray& r : rays) hits += RawIntersect(rtc, r);
    return hits;
}

void BM_AcceleratorIntersect(benchmark::State& state) {
    const Scene& scene = CornellBox();
    std::vector<Ray> rays = IncoherentRays(scene);
    int64_t hits = 0;
    for (auto _ : state) hits = TraceKiln(scene, rays);
    state.SetItemsProcessed(state.iterations() * kNumRays);  // items/s = rays/s
    state.counters["hit_fraction"] = double(hits) / kNumRays;
}
BENCHMARK(BM_AcceleratorIntersect)->Unit(benchmark::kMillisecond);

void BM_RawRtcIntersect1(benchmark::State& state) {
    const Scene& scene = CornellBox();
    std::vector<Ray> rays = IncoherentRays(scene);
    int64_t hits = 0;
    for (auto _ : state) hits = TraceRaw(scene, rays);
    state.SetItemsProcessed(state.iterations() * kNumRays);  // items/s = rays/s
    state.counters["hit_fraction"] = double(hits) / kNumRays;
}
BENCHMARK(BM_RawRtcIntersect1)->Unit(benchmark::kMillisecond);

// Both in one benchmark, interleaved, so that the ratio is measured under the same machine
// load: kiln_over_raw = time(Accelerator::Intersect) / time(rtcIntersect1), >= 1; the excess
// is kiln's hit record construction (SurfaceInteraction, material and light lookup). Times are
// this thread's CPU time, so other processes on the machine disturb the ratio little.
double ThreadCPUSeconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void BM_IntersectOverheadRatio(benchmark::State& state) {
    const Scene& scene = CornellBox();
    std::vector<Ray> rays = IncoherentRays(scene);
    double kilnSeconds = 0, rawSeconds = 0;
    for (auto _ : state) {
        double t0 = ThreadCPUSeconds();
        benchmark::DoNotOptimize(TraceKiln(scene, rays));
        double t1 = ThreadCPUSeconds();
        benchmark::DoNotOptimize(TraceRaw(scene, rays));
        double t2 = ThreadCPUSeconds();
        kilnSeconds += t1 - t0;
        rawSeconds += t2 - t1;
    }
    state.counters["kiln_over_raw"] = rawSeconds > 0 ? kilnSeconds / rawSeconds : 0;
    double n = double(state.iterations()) * kNumRays;
    state.counters["kiln_Mrays/s"] = kilnSeconds > 0 ? n / kilnSeconds * 1e-6 : 0;
    state.counters["raw_Mrays/s"] = rawSeconds > 0 ? n / rawSeconds * 1e-6 : 0;
}
BENCHMARK(BM_IntersectOverheadRatio)->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------
// Camera rays in packets (issue 27: "coherent camera rays traced in packets where Embree gains
// from it"). A 256 x 256 height field (130,050 triangles) under a perspective camera at
// 192 x 128 pixels; one jittered camera ray per pixel, 4 passes, ordered in blocks of
// neighbouring pixels (2 x 2, 4 x 2 or 4 x 4 for packets of 4, 8 or 16). The same rays are
// traced with rtcIntersect1 each and as rtcIntersect4/8/16 packets (Embree's coherent flag),
// interleaved; counter packet_over_single = CPU time of packets / of single rays (< 1: Embree
// gains from packets). Raw traversal only: kiln's hit record is built per ray either way.
std::string HeightFieldScene() {
    constexpr int n = 256;
    std::string s =
        "LookAt 0 6 -9  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
        "Film \"rgb\" \"integer xresolution\" 192 \"integer yresolution\" 128\nWorldBegin\n"
        "Material \"diffuse\"\nShape \"trianglemesh\" \"point3 P\" [";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Float u = Float(x) / (n - 1), v = Float(y) / (n - 1);
            Float h = 0.4f * std::sin(23 * u) * std::cos(17 * v) + 0.2f * std::sin(61 * u * v);
            s += std::to_string(20 * u - 10) + " " + std::to_string(h) + " " +
                 std::to_string(20 * v - 10) + " ";
        }
    s += "] \"integer indices\" [";
    for (int y = 0; y + 1 < n; ++y)
        for (int x = 0; x + 1 < n; ++x) {
            int a = y * n + x, b = a + 1, c = a + n, d = c + 1;
            for (int i : {a, b, d, a, d, c}) s += std::to_string(i) + " ";
        }
    return s + "]\n";
}

const Scene& HeightField() {
    static const std::unique_ptr<Scene> scene = [] {
        Diagnostics diag(nullptr);
        SceneBuilder builder(diag);
        ParseString(builder, HeightFieldScene(), diag);
        return Scene::Create(builder.Description(), {}, diag);
    }();
    return *scene;
}

// Camera rays of the scene's film, one per pixel per pass, block by block (bw x bh pixels).
std::vector<Ray> CameraRaysInBlocks(const Scene& scene, int bw, int bh) {
    Point2i res = scene.job->film->FullResolution();
    RNG rng(7);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    std::vector<Ray> rays;
    for (int pass = 0; pass < 4; ++pass)
        for (int by = 0; by + bh <= res.y; by += bh)
            for (int bx = 0; bx + bw <= res.x; bx += bw)
                for (int y = by; y < by + bh; ++y)
                    for (int x = bx; x < bx + bw; ++x) {
                        CameraSample cs;
                        cs.pFilm = Point2f(x + rng.UniformFloat(), y + rng.UniformFloat());
                        cs.pLens = Point2f(0.5f, 0.5f);
                        std::optional<CameraRay> cr = scene.camera->GenerateRay(cs, lambda);
                        rays.push_back(cr ? cr->ray : Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1)));
                    }
    return rays;
}

// One packet of N rays (SOA); returns the number of hits.
template <int N, typename RayHitN, typename IntersectN>
int64_t TracePacket(RTCScene scene, const Ray* rays, IntersectN intersect) {
    RayHitN rh;
    alignas(64) int valid[N];
    for (int i = 0; i < N; ++i) {
        const Ray& r = rays[i];
        valid[i] = -1;
        rh.ray.org_x[i] = r.o.x, rh.ray.org_y[i] = r.o.y, rh.ray.org_z[i] = r.o.z;
        rh.ray.dir_x[i] = r.d.x, rh.ray.dir_y[i] = r.d.y, rh.ray.dir_z[i] = r.d.z;
        rh.ray.tnear[i] = 0, rh.ray.tfar[i] = Infinity, rh.ray.time[i] = 0;
        rh.ray.mask[i] = ~0u, rh.ray.id[i] = unsigned(i), rh.ray.flags[i] = 0;
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    EmbreeQueryContext ctx;
    ctx.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    intersect(valid, scene, &ctx.context, &rh);
    int64_t hits = 0;
    for (int i = 0; i < N; ++i) hits += rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    return hits;
}

template <int N>
int64_t TracePackets(RTCScene scene, const std::vector<Ray>& rays) {
    int64_t hits = 0;
    for (size_t i = 0; i + N <= rays.size(); i += N) {
        if constexpr (N == 4)
            hits += TracePacket<4, RTCRayHit4>(scene, &rays[i], rtcIntersect4);
        else if constexpr (N == 8)
            hits += TracePacket<8, RTCRayHit8>(scene, &rays[i], rtcIntersect8);
        else
            hits += TracePacket<16, RTCRayHit16>(scene, &rays[i], rtcIntersect16);
    }
    return hits;
}

template <int N>
void BM_CameraRayPackets(benchmark::State& state) {
    const Scene& scene = HeightField();
    int bw = N == 4 ? 2 : 4, bh = N / bw;
    std::vector<Ray> rays = CameraRaysInBlocks(scene, bw, bh);
    RTCScene rtc = scene.aggregate->EmbreeScene();
    double singleSeconds = 0, packetSeconds = 0;
    int64_t singleHits = 0, packetHits = 0;
    for (auto _ : state) {
        double t0 = ThreadCPUSeconds();
        singleHits = 0;
        for (const Ray& r : rays) singleHits += RawIntersect(rtc, r);
        double t1 = ThreadCPUSeconds();
        packetHits = TracePackets<N>(rtc, rays);
        double t2 = ThreadCPUSeconds();
        singleSeconds += t1 - t0;
        packetSeconds += t2 - t1;
    }
    if (singleHits != packetHits) state.SkipWithError("packets and single rays hit differently");
    double n = double(state.iterations()) * double(rays.size());
    state.counters["packet_over_single"] = singleSeconds > 0 ? packetSeconds / singleSeconds : 0;
    state.counters["single_Mrays/s"] = singleSeconds > 0 ? n / singleSeconds * 1e-6 : 0;
    state.counters["packet_Mrays/s"] = packetSeconds > 0 ? n / packetSeconds * 1e-6 : 0;
    state.counters["hit_fraction"] = double(packetHits) / double(rays.size());
}
BENCHMARK_TEMPLATE(BM_CameraRayPackets, 4)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_CameraRayPackets, 8)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_CameraRayPackets, 16)->Unit(benchmark::kMillisecond);

// The whole renderer on the Cornell box (400x400, maxdepth 8) at state.range(0) spp with
// state.range(1) threads (0 = all). Counter: camera paths per second of wall time (render
// loop only; scene loading excluded) and per CPU second of the process (all threads: per-core
// throughput, robust when other processes share the machine). Rays per second need a ray
// counter in the integrator.
double ProcessCPUSeconds() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void BM_RenderCornellBox(benchmark::State& state) {
    RenderOptions overrides;
    overrides.samplesPerPixel = int(state.range(0));
    std::unique_ptr<Scene> scene = LoadScene(CornellBoxPath(), overrides);
    RenderSettings settings;
    settings.threads = int(state.range(1));
    int64_t paths = 0;
    double seconds = 0, cpuSeconds = 0;
    for (auto _ : state) {
        scene->job->film->Clear();
        double c0 = ProcessCPUSeconds();
        RenderStats stats = Render(*scene, settings);
        cpuSeconds += ProcessCPUSeconds() - c0;
        paths += stats.cameraPaths;
        seconds += stats.seconds;
    }
    state.counters["Mpaths/s"] = seconds > 0 ? paths / seconds * 1e-6 : 0;
    state.counters["Mpaths/cpu_s"] = cpuSeconds > 0 ? paths / cpuSeconds * 1e-6 : 0;
    state.counters["paths"] = double(paths) / state.iterations();
}
BENCHMARK(BM_RenderCornellBox)
    ->Args({4, 1})
    ->Args({4, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace kiln

BENCHMARK_MAIN();
