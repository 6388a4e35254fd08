#include "python/material_probe.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "core/parser/parser.h"
#include "materials/material.h"
#include "render/scene_builder.h"
#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"
#include "spectral/planck.h"
#include "spectral/spectral_range.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/material_albedo.h"

namespace py = pybind11;

namespace kiln {

namespace {

// One material at the point (0.5, 0.5, 0) of the plane z = 0 (normal +z, dp/du +x, uv (0.5,
// 0.5)), seen from directions in the xz plane at angle theta from the normal.
class MaterialProbe {
  public:
    // `parameters`: the material's parameter list in scene-file syntax ("spectrum eta"
    // "metal-Au-eta" ...). Throws SceneError (at "<material>", with the column of the token)
    // for an unknown type, a bad or unused parameter.
    MaterialProbe(const std::string& type, const std::string& parameters) : diag(nullptr) {
        SceneBuilder builder(diag);
        std::string text =
            "WorldBegin MakeNamedMaterial \"probe\" \"string type\" \"" + type + "\" " + parameters;
        ParseString(builder, text, diag, "<material>");
        SceneDescription& d = builder.Description();
        if (d.namedMaterials.size() != 1)
            throw SceneError(FileLoc(), "expected one material, from \"" + text + "\"");
        entity = std::move(d.namedMaterials[0].second);
        entity.name = entity.parameters.GetOneString("type", "");
        TextureParameterDictionary params(&entity.parameters, &textures);
        material =
            arena.New<Material>(Material::Create(entity.name, params, {}, entity.loc, arena, diag));
        entity.parameters.ReportUnused(diag);
        albedo = MaterialAlbedo::Create(*material, tables, arena);
    }

    // The directional albedo A, and R_s = A + a1, R_p = A - a1, at theta (radians), lambda
    // (nm) and the surface's temperature T (K; 0: none, for the materials whose optical
    // constants follow it).
    struct Reflectance {
        double A, Rs, Rp;
    };
    Reflectance At(double theta, double lambda_nm, double T) const {
        if (!(theta >= 0 && theta <= M_PI / 2))
            throw py::value_error("theta must be in [0, pi/2] radians (from the normal)");
        if (!(lambda_nm >= kSpectralRangeMin && lambda_nm <= kSpectralRangeMax))
            throw py::value_error("wavelength must be within kiln's " +
                                  std::to_string(int(kSpectralRangeMin)) + "-" +
                                  std::to_string(int(kSpectralRangeMax)) + " nm");
        if (!(T >= 0 && std::isfinite(T)))
            throw py::value_error("temperature must be a finite number of kelvin >= 0");
        // The visible range's tables (as a render of the visible), else those over kiln's
        // whole range (as a render with Film "thermal"), built when first needed
        const bool visible = lambda_nm >= Lambda_min && lambda_nm <= Lambda_max;
        if (!visible && !wideAlbedo) {
            wideTables = std::make_unique<EmissivityTables>(
                SpectralRange{kSpectralRangeMin, kSpectralRangeMax});
            wideTables->polarized = tables.polarized;
            wideAlbedo = MaterialAlbedo::Create(*material, *wideTables, arena);
        }
        const MaterialAlbedo* albedo = visible ? this->albedo : wideAlbedo;
        // cos theta = 0 would be a direction in the surface: kept just above it
        double mu = std::max(std::cos(theta), 1e-6);
        Vector3f wo(Float(std::sqrt(1 - mu * mu)), 0, Float(mu));
        MaterialEvalContext ctx;
        ctx.p = Point3f(0.5f, 0.5f, 0);
        ctx.n = ctx.ns = Normal3f(0, 0, 1);
        ctx.dpdus = Vector3f(1, 0, 0);
        ctx.uv = Point2f(0.5f, 0.5f);
        ctx.wo = wo;
        ctx.temperature = Float(T);
        SampledWavelengths lambda = SampledWavelengths::FromWavelength(Float(lambda_nm));
        BSDF bsdf = material->GetBSDF(ctx, lambda);
        double A = albedo->Evaluate(material, bsdf, wo, lambda)[0];
        double a1 = albedo->LinearPolarization(material, bsdf, wo).s1[0];
        return {A, A + a1, A - a1};
    }
    double Albedo(double theta, double lambda, double T) const { return At(theta, lambda, T).A; }
    double AlbedoS(double theta, double lambda, double T) const { return At(theta, lambda, T).Rs; }
    double AlbedoP(double theta, double lambda, double T) const { return At(theta, lambda, T).Rp; }

  private:
    Diagnostics diag;
    mutable ObjectArena arena;
    NamedTextures textures;
    EmissivityTables tables;
    SceneEntity entity;
    const Material* material = nullptr;
    const MaterialAlbedo* albedo = nullptr;
    mutable std::unique_ptr<EmissivityTables> wideTables;
    mutable const MaterialAlbedo* wideAlbedo = nullptr;
};

}  // namespace

void RegisterMaterialProbe(py::module_& m) {
    py::class_<MaterialProbe>(m, "_MaterialProbe")
        .def(py::init<const std::string&, const std::string&>(), py::arg("type"),
             py::arg("parameters"))
        .def("albedo", py::vectorize(&MaterialProbe::Albedo))
        .def("albedo_s", py::vectorize(&MaterialProbe::AlbedoS))
        .def("albedo_p", py::vectorize(&MaterialProbe::AlbedoP));
    // Planck's law, W m^-2 sr^-1 nm^-1 (spectral/planck.h)
    m.def("_planck", py::vectorize([](double lambda_nm, double kelvin) {
              return planck_radiance(lambda_nm, kelvin);
          }));
    // Planck's law inverted: radiance temperatures, K (spectral/planck.h)
    m.def("_radiance_temperature", py::vectorize([](double lambda_nm, double L) {
              return radiance_temperature(lambda_nm, L);
          }));
    m.def("_band_radiance_temperature",
          py::vectorize([](double lambda1_nm, double lambda2_nm, double L) {
              return band_radiance_temperature(lambda1_nm, lambda2_nm, L);
          }));
    m.def("_named_spectrum", [](const std::string& name, py::array_t<double> lambda) {
        const Spectrum* s = GetNamedSpectrum(name);
        if (!s) throw py::key_error("no named spectrum \"" + name + "\"");
        return py::vectorize([s](double l) { return double((*s)(Float(l))); })(lambda);
    });
    // The CIE 1931 2-degree colour-matching functions (spectral/cie.h) at lambda, nm
    m.def("_cie_xyz", [](py::array_t<double> lambda) {
        auto l = lambda.unchecked<1>();
        py::array_t<double> out({l.shape(0), py::ssize_t(3)});
        auto o = out.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < l.shape(0); ++i) {
            o(i, 0) = CIE_X(Float(l(i)));
            o(i, 1) = CIE_Y(Float(l(i)));
            o(i, 2) = CIE_Z(Float(l(i)));
        }
        return out;
    });
    m.def("_xyz_to_srgb", [](double X, double Y, double Z) {
        RGB rgb = RGBColorSpace::sRGB().ToRGB(XYZ(Float(X), Float(Y), Float(Z)));
        return py::make_tuple(rgb.r, rgb.g, rgb.b);
    });
    m.attr("_cie_y_integral") = CIE_Y_integral;
    m.attr("_lambda_min") = Lambda_min;
    m.attr("_lambda_max") = Lambda_max;
}

}  // namespace kiln
