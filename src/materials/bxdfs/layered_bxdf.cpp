#include "materials/bxdfs/layered_bxdf.h"

namespace kiln {

using layered_detail::Flip;

namespace {
// Uniform in [0, 1) from the walk's generator.
inline Float Next(RNG& rng) { return std::min<Float>(rng.UniformFloat(), OneMinusEpsilon); }
}  // namespace

// Flags
template <typename TopBxDF, typename BottomBxDF, bool twoSided>
BxDFFlags LayeredBxDF<TopBxDF, BottomBxDF, twoSided>::Flags() const {
    BxDFFlags topFlags = top.Flags(), bottomFlags = bottom.Flags();
    BxDFFlags flags = BxDFFlags::Reflection;
    if (IsSpecular(topFlags)) flags = flags | BxDFFlags::Specular;
    if (IsDiffuse(topFlags) || IsDiffuse(bottomFlags) || albedo)
        flags = flags | BxDFFlags::Diffuse;
    else if (IsGlossy(topFlags) || IsGlossy(bottomFlags))
        flags = flags | BxDFFlags::Glossy;
    if (IsTransmissive(topFlags) && IsTransmissive(bottomFlags))
        flags = flags | BxDFFlags::Transmission;
    return flags;
}

// Evaluation: random walks between the interfaces with next-event estimation towards wi
//
// Deliberate deviation from pbrt-v4: when a direction sampled inside the layer (phase function
// or non-exit interface) is weighted against the "virtual light" strategy that sampled wis from
// wi, the competing density is that of sampling the inner direction from wi,
// exitInterface.PDF(wi, -w, !mode), not pbrt-v4's exitInterface.PDF(-w, wi, mode). The two
// differ for rough interfaces, so pbrt-v4's MIS weights do not sum to one and its f is brighter
// than the random walk of Sample_f by 1-14 % (most for bright bases under rough coats; test
// LayeredConsistency.EvaluationMatchesTheRandomWalkAtAllAngles, which fails with pbrt-v4's
// weight). Renders of coated materials are therefore darker than pbrt-v4's by up to that much.
template <typename TopBxDF, typename BottomBxDF, bool twoSided>
SampledSpectrum LayeredBxDF<TopBxDF, BottomBxDF, twoSided>::f(Vector3f wo, Vector3f wi,
                                                              TransportMode mode) const {
    SampledSpectrum f(0.f);
    if (twoSided && wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    // Entrance, exit and non-exit interfaces
    Interface enterInterface;
    bool enteredTop = twoSided || wo.z > 0;
    if (enteredTop)
        enterInterface = &top;
    else
        enterInterface = &bottom;
    Interface exitInterface, nonExitInterface;
    bool exitBottom = SameHemisphere(wo, wi) ^ enteredTop;
    if (exitBottom) {
        exitInterface = &bottom;
        nonExitInterface = &top;
    } else {
        exitInterface = &top;
        nonExitInterface = &bottom;
    }
    Float exitZ = exitBottom ? 0 : thickness;
    // The virtual-light strategy's density for a direction wIn leaving through the exit
    // interface towards wi (the MIS weight of that direction; see LayeredMIS)
    auto exitPDF = [&](Vector3f wIn) {
        return mis == LayeredMIS::Kiln
                   ? exitInterface.PDF(wi, wIn, Flip(mode), BxDFReflTransFlags::Transmission)
                   : exitInterface.PDF(wIn, wi, mode, BxDFReflTransFlags::Transmission);
    };

    // Reflection at the entrance interface is evaluated directly.
    if (SameHemisphere(wo, wi)) f = Float(nSamples) * enterInterface.f(wo, wi, mode);

    RNG rng(Hash(wo), Hash(wi));
    auto r = [&rng]() { return Next(rng); };

    for (int s = 0; s < nSamples; ++s) {
        // Transmission through the entrance interface
        Float uc = r();
        std::optional<BSDFSample> wos = enterInterface.Sample_f(wo, uc, Point2f(r(), r()), mode,
                                                                BxDFReflTransFlags::Transmission);
        if (!wos || !wos->f || wos->pdf == 0 || wos->wi.z == 0) continue;
        // Virtual light path from wi through the exit interface (adjoint transport)
        uc = r();
        std::optional<BSDFSample> wis = exitInterface.Sample_f(
            wi, uc, Point2f(r(), r()), Flip(mode), BxDFReflTransFlags::Transmission);
        if (!wis || !wis->f || wis->pdf == 0 || wis->wi.z == 0) continue;

        SampledSpectrum beta = wos->f * AbsCosTheta(wos->wi) / wos->pdf;
        Float z = enteredTop ? thickness : 0;
        Vector3f w = wos->wi;
        HGPhaseFunction phase(g);

        for (int depth = 0; depth < maxDepth; ++depth) {
            // Russian roulette
            if (depth > 3 && beta.MaxComponentValue() < 0.25f) {
                Float q = std::max<Float>(0, 1 - beta.MaxComponentValue());
                if (r() < q) break;
                beta /= 1 - q;
            }
            if (!albedo) {
                // No medium: go straight to the other interface.
                z = (z == thickness) ? 0 : thickness;
                beta *= Tr(thickness, w);
            } else {
                // Sample a scattering event in the medium (sigma_t = 1).
                Float sigma_t = 1;
                Float dz = SampleExponential(r(), sigma_t / std::abs(w.z));
                Float zp = w.z > 0 ? (z + dz) : (z - dz);
                if (z == zp) continue;
                if (0 < zp && zp < thickness) {
                    // NEE through the exit interface along wis, MIS against the phase function.
                    Float wt = 1;
                    if (!IsSpecular(exitInterface.Flags()))
                        wt = PowerHeuristic(1, wis->pdf, 1, phase.PDF(-w, -wis->wi));
                    f += beta * albedo * phase.p(-w, -wis->wi) * wt * Tr(zp - exitZ, wis->wi) *
                         wis->f / wis->pdf;
                    // Continue the walk with a phase-function sample.
                    std::optional<PhaseFunctionSample> ps = phase.Sample_p(-w, {r(), r()});
                    if (!ps || ps->pdf == 0 || ps->wi.z == 0) continue;
                    beta *= albedo * ps->p / ps->pdf;
                    w = ps->wi;
                    z = zp;
                    // The phase sample may leave through the exit interface directly.
                    if (((z < exitZ && w.z > 0) || (z > exitZ && w.z < 0)) &&
                        !IsSpecular(exitInterface.Flags())) {
                        SampledSpectrum fExit = exitInterface.f(-w, wi, mode);
                        if (fExit) {
                            Float wt2 = PowerHeuristic(1, ps->pdf, 1, exitPDF(-w));
                            f += beta * Tr(zp - exitZ, ps->wi) * fExit * wt2;
                        }
                    }
                    continue;
                }
                z = Clamp(zp, 0, thickness);
            }

            if (z == exitZ) {
                // Reflection back into the layer at the exit interface
                Float uc2 = r();
                std::optional<BSDFSample> bs = exitInterface.Sample_f(
                    -w, uc2, Point2f(r(), r()), mode, BxDFReflTransFlags::Reflection);
                if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) break;
                beta *= bs->f * AbsCosTheta(bs->wi) / bs->pdf;
                w = bs->wi;
            } else {
                // Scattering at the non-exit interface, with NEE along wis.
                if (!IsSpecular(nonExitInterface.Flags())) {
                    Float wt = 1;
                    if (!IsSpecular(exitInterface.Flags()))
                        wt = PowerHeuristic(1, wis->pdf, 1,
                                            nonExitInterface.PDF(-w, -wis->wi, mode));
                    f += beta * nonExitInterface.f(-w, -wis->wi, mode) * AbsCosTheta(wis->wi) * wt *
                         Tr(thickness, wis->wi) * wis->f / wis->pdf;
                }
                Float uc2 = r();
                Point2f u(r(), r());
                std::optional<BSDFSample> bs =
                    nonExitInterface.Sample_f(-w, uc2, u, mode, BxDFReflTransFlags::Reflection);
                if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) break;
                beta *= bs->f * AbsCosTheta(bs->wi) / bs->pdf;
                w = bs->wi;
                // NEE along the sampled direction through the exit interface.
                if (!IsSpecular(exitInterface.Flags())) {
                    SampledSpectrum fExit = exitInterface.f(-w, wi, mode);
                    if (fExit) {
                        Float wt = 1;
                        if (!IsSpecular(nonExitInterface.Flags())) {
                            wt = PowerHeuristic(1, bs->pdf, 1, exitPDF(-w));
                        }
                        f += beta * Tr(thickness, bs->wi) * fExit * wt;
                    }
                }
            }
        }
    }
    return f / Float(nSamples);
}

// Sampling: one random walk; the returned pdf is only proportional to the true density
template <typename TopBxDF, typename BottomBxDF, bool twoSided>
std::optional<BSDFSample> LayeredBxDF<TopBxDF, BottomBxDF, twoSided>::Sample_f(
    Vector3f wo, Float uc, Point2f u, TransportMode mode, BxDFReflTransFlags sampleFlags) const {
    // Only "All" is supported (as pbrt-v4); a caller restricting to transmission gets nothing
    // unless both interfaces transmit.
    if (!(sampleFlags & BxDFReflTransFlags::Reflection) && !IsTransmissive(Flags())) return {};
    bool flipWi = false;
    if (twoSided && wo.z < 0) {
        wo = -wo;
        flipWi = true;
    }
    // Entrance interface
    bool enteredTop = twoSided || wo.z > 0;
    std::optional<BSDFSample> bs =
        enteredTop ? top.Sample_f(wo, uc, u, mode) : bottom.Sample_f(wo, uc, u, mode);
    if (!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0) return {};
    if (bs->IsReflection()) {
        if (flipWi) bs->wi = -bs->wi;
        bs->pdfIsProportional = true;
        return bs;
    }
    Vector3f w = bs->wi;
    bool specularPath = bs->IsSpecular();

    RNG rng(Hash(wo), Hash(uc, u));
    auto r = [&rng]() { return Next(rng); };

    SampledSpectrum f = bs->f * AbsCosTheta(bs->wi);
    Float pdf = bs->pdf;
    Float z = enteredTop ? thickness : 0;
    HGPhaseFunction phase(g);

    for (int depth = 0; depth < maxDepth; ++depth) {
        // Russian roulette on the path throughput
        Float rrBeta = f.MaxComponentValue() / pdf;
        if (depth > 3 && rrBeta < 0.25f) {
            Float q = std::max<Float>(0, 1 - rrBeta);
            if (r() < q) return {};
            pdf *= 1 - q;
        }
        if (w.z == 0) return {};

        if (albedo) {
            // Possible scattering in the medium
            Float sigma_t = 1;
            Float dz = SampleExponential(r(), sigma_t / AbsCosTheta(w));
            Float zp = w.z > 0 ? (z + dz) : (z - dz);
            if (zp == z) return {};
            if (0 < zp && zp < thickness) {
                std::optional<PhaseFunctionSample> ps = phase.Sample_p(-w, Point2f(r(), r()));
                if (!ps || ps->pdf == 0 || ps->wi.z == 0) return {};
                f *= albedo * ps->p;
                pdf *= ps->pdf;
                specularPath = false;
                w = ps->wi;
                z = zp;
                continue;
            }
            z = Clamp(zp, 0, thickness);
        } else {
            z = (z == thickness) ? 0 : thickness;
            f *= Tr(thickness, w);
        }

        // Scattering at the interface reached
        Interface interface;
        if (z == 0)
            interface = &bottom;
        else
            interface = &top;
        Float uc2 = r();
        Point2f u2(r(), r());
        std::optional<BSDFSample> is = interface.Sample_f(-w, uc2, u2, mode);
        if (!is || !is->f || is->pdf == 0 || is->wi.z == 0) return {};
        f *= is->f;
        pdf *= is->pdf;
        specularPath &= is->IsSpecular();
        w = is->wi;

        if (is->IsTransmission()) {
            // Left the layers.
            BxDFFlags flags =
                SameHemisphere(wo, w) ? BxDFFlags::Reflection : BxDFFlags::Transmission;
            flags = flags | (specularPath ? BxDFFlags::Specular : BxDFFlags::Glossy);
            if (flipWi) w = -w;
            return BSDFSample(f, w, pdf, flags, 1.f, true);
        }
        f *= AbsCosTheta(is->wi);
    }
    return {};
}

// PDF: stochastic estimate of the density of Sample_f, mixed with a uniform density
template <typename TopBxDF, typename BottomBxDF, bool twoSided>
Float LayeredBxDF<TopBxDF, BottomBxDF, twoSided>::PDF(Vector3f wo, Vector3f wi, TransportMode mode,
                                                      BxDFReflTransFlags sampleFlags) const {
    if (twoSided && wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    RNG rng(Hash(wi), Hash(wo));
    auto r = [&rng]() { return Next(rng); };

    bool enteredTop = twoSided || wo.z > 0;
    Float pdfSum = 0;
    if (SameHemisphere(wo, wi)) {
        auto reflFlag = BxDFReflTransFlags::Reflection;
        pdfSum += enteredTop ? nSamples * top.PDF(wo, wi, mode, reflFlag)
                             : nSamples * bottom.PDF(wo, wi, mode, reflFlag);
    }

    for (int s = 0; s < nSamples; ++s) {
        if (SameHemisphere(wo, wi)) {
            // Transmission-reflection-transmission (TRT) term
            Interface rInterface, tInterface;
            if (enteredTop) {
                rInterface = &bottom;
                tInterface = &top;
            } else {
                rInterface = &top;
                tInterface = &bottom;
            }
            auto trans = BxDFReflTransFlags::Transmission;
            Float uc0 = r();
            Point2f u0(r(), r());
            std::optional<BSDFSample> wos = tInterface.Sample_f(wo, uc0, u0, mode, trans);
            Float uc1 = r();
            Point2f u1(r(), r());
            std::optional<BSDFSample> wis = tInterface.Sample_f(wi, uc1, u1, Flip(mode), trans);
            if (wos && wos->f && wos->pdf > 0 && wis && wis->f && wis->pdf > 0) {
                if (!IsNonSpecular(tInterface.Flags())) {
                    pdfSum += rInterface.PDF(-wos->wi, -wis->wi, mode);
                } else {
                    // MIS estimate of the product of the three densities
                    Float uc2 = r();
                    Point2f u2(r(), r());
                    std::optional<BSDFSample> rs = rInterface.Sample_f(-wos->wi, uc2, u2, mode);
                    if (rs && rs->f && rs->pdf > 0) {
                        if (!IsNonSpecular(rInterface.Flags())) {
                            pdfSum += tInterface.PDF(-rs->wi, wi, mode);
                        } else {
                            Float rPDF = rInterface.PDF(-wos->wi, -wis->wi, mode);
                            Float wt = PowerHeuristic(1, wis->pdf, 1, rPDF);
                            pdfSum += wt * rPDF;
                            Float tPDF = tInterface.PDF(-rs->wi, wi, mode);
                            wt = PowerHeuristic(1, rs->pdf, 1, tPDF);
                            pdfSum += wt * tPDF;
                        }
                    }
                }
            }
        } else {
            // Transmission-transmission (TT) term
            Interface toInterface, tiInterface;
            if (enteredTop) {
                toInterface = &top;
                tiInterface = &bottom;
            } else {
                toInterface = &bottom;
                tiInterface = &top;
            }
            Float uc = r();
            Point2f u(r(), r());
            std::optional<BSDFSample> wos = toInterface.Sample_f(wo, uc, u, mode);
            if (!wos || !wos->f || wos->pdf == 0 || wos->wi.z == 0 || wos->IsReflection()) continue;
            uc = r();
            u = Point2f(r(), r());
            std::optional<BSDFSample> wis = tiInterface.Sample_f(wi, uc, u, Flip(mode));
            if (!wis || !wis->f || wis->pdf == 0 || wis->wi.z == 0 || wis->IsReflection()) continue;
            if (IsSpecular(toInterface.Flags()))
                pdfSum += tiInterface.PDF(-wos->wi, wi, mode);
            else if (IsSpecular(tiInterface.Flags()))
                pdfSum += toInterface.PDF(wo, -wis->wi, mode);
            else
                pdfSum +=
                    (toInterface.PDF(wo, -wis->wi, mode) + tiInterface.PDF(-wos->wi, wi, mode)) / 2;
        }
    }
    // Mix with a uniform sphere density to cover what the estimate misses.
    return Lerp(0.9f, 1 / (4 * Pi), pdfSum / nSamples);
}

template class LayeredBxDF<DielectricBxDF, DiffuseBxDF, true>;
template class LayeredBxDF<DielectricBxDF, ConductorBxDF, true>;

}  // namespace kiln
