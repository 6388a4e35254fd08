// Material: the closed set of surface materials (pbrt-v4's Material). A material evaluates its
// textures at a surface point and returns the BSDF there.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <variant>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "core/parser/diagnostics.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/spectrum.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class DiffuseMaterial;
class DiffuseTransmissionMaterial;
class ConductorMaterial;
class DielectricMaterial;
class ThinDielectricMaterial;
class CoatedDiffuseMaterial;
class CoatedConductorMaterial;
class MixMaterial;
class InterfaceMaterial;
class PolarizingFilterMaterial;
class HairMaterial;
class MeasuredMaterial;
class SubsurfaceMaterial;
class BSSRDFTableCache;
class TextureParameterDictionary;
struct ShadingPerturbation;

// Material Definition
class Material
    : public ClosedSet<const DiffuseMaterial*, const ConductorMaterial*, const DielectricMaterial*,
                       const ThinDielectricMaterial*, const CoatedDiffuseMaterial*,
                       const CoatedConductorMaterial*, const MixMaterial*, const InterfaceMaterial*,
                       const PolarizingFilterMaterial*, const HairMaterial*,
                       const DiffuseTransmissionMaterial*, const MeasuredMaterial*,
                       const SubsurfaceMaterial*> {
  public:
    using ClosedSet::ClosedSet;

    // The BSDF at the point, in the shading frame (ctx.ns, ctx.dpdus). Materials whose index
    // of refraction varies with wavelength call lambda.TerminateSecondary(). The interface
    // material returns an invalid BSDF (BSDF()); a mix material first resolves to one of its
    // components with ChooseMaterial.
    BSDF GetBSDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const;

    // Resolves mix materials (recursively) to a non-mix material, chosen deterministically
    // from a hash of ctx.p and ctx.wo in proportion to the mix amount (pbrt-v4). Returns this
    // material for non-mix materials.
    const Material* ChooseMaterial(const MaterialEvalContext& ctx) const;

    // Whether the BSDF depends on the screen-space footprint (a texture filters with it):
    // shading computes footprints only then (decided at creation).
    bool UsesFootprint() const;
    // Whether the BSDF depends on the surface's temperature (a named metal's optical constants
    // follow it, spectral/metal_temperature.h): shading evaluates the temperature for the
    // textures only then (MaterialEvalContext::temperature; decided at creation).
    bool UsesTemperature() const;

    // The material's bump or normal map (shading_perturbation.h); none for mix and interface.
    const ShadingPerturbation& Perturbation() const;

    // The refractive index of the body whose surface this is: a dielectric's eta; nullopt for
    // every other material (thin dielectrics enclose nothing; conductors and coatings are
    // opaque; a mix has no single one).
    std::optional<Spectrum> InteriorEta() const;
    // The extinction coefficient k of that body (a dielectric's "spectrum k", dimensionless;
    // nullopt without one): it absorbs 4 pi k / lambda per unit length, which scene creation
    // gives a body without an interior medium of its own as one (render/scene_media.h).
    std::optional<Spectrum> InteriorExtinction() const;

    // Whether some point of the surface may pass light straight through (BxDFFlags::
    // StraightThrough: a non-dispersive thindielectric, alone or in a mix): the integrators
    // then let shadow rays cross such surfaces (decided at load, SceneFeatures::sheets).
    bool MayPassLightStraightThrough() const;

    bool IsInterface() const { return Is<InterfaceMaterial>(); }
    bool IsMix() const { return Is<MixMaterial>(); }

    // Creates a material of pbrt-v4 type `type` ("diffuse", "conductor", "dielectric",
    // "thindielectric", "coateddiffuse", "coatedconductor", "mix", "interface", "hair",
    // "diffusetransmission", "measured", "subsurface"; "" and "none" give interface), and kiln's
    // polarising filters "polarizer" ("float angle", degrees) and "retarder" ("float angle", "float
    // retardance" in degrees, default 90: a quarter-wave plate), see
    // bxdfs/polarizing_filter_bxdf.h. Other pbrt-v4 types are replaced by diffuse with a warning at
    // loc; unknown types throw SceneError. namedMaterials resolves the components of "mix".
    // layeredMIS: the MIS weights of the coated materials' layered walk (LayeredMIS). bssrdfTables:
    // where "subsurface" materials find their tables (one per g and eta); null: a table of the
    // material's own, kept in arena.
    static Material Create(const std::string& type, const TextureParameterDictionary& params,
                           const std::map<std::string, Material>& namedMaterials,
                           const FileLoc& loc, ObjectArena& arena, Diagnostics& diag,
                           LayeredMIS layeredMIS = LayeredMIS::Kiln,
                           BSSRDFTableCache* bssrdfTables = nullptr);
};

}  // namespace kiln
