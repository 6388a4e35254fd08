// ParameterDictionary: typed lookups of a directive's parameters, with pbrt-v4 semantics.
//
// A lookup only sees parameters of its own type (GetOneInt sees "integer" ones, GetOneFloat
// "float" ones, ...); a parameter of another type under the same name is ignored and, never
// being looked up, is reported by ReportUnused (a warning, or an error for a name nobody knows).
// When a name appears more than once the last occurrence wins; the directive's own parameters take
// precedence over graphics-state attributes (Attribute "shape" ...), which are all mayBeUnused.
// GetOne* with more than one value (or none) throws SceneError at the parameter. Every successful
// lookup marks the parameter lookedUp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/vecmath.h"
#include "core/parser/diagnostics.h"
#include "core/parser/file_loc.h"
#include "core/parser/parsed_parameter.h"
#include "spectral/spectrum.h"

namespace kiln {

class RGBColorSpace;

// How an "rgb" value becomes a spectrum (pbrt-v4): reflectances (components in [0, 1]),
// unbounded non-negative quantities (e.g. scattering coefficients), or emission.
enum class SpectrumType { Albedo, Unbounded, Illuminant };

class ParameterDictionary {
  public:
    ParameterDictionary() = default;
    // A null colorSpace means sRGB.
    ParameterDictionary(ParsedParameterVector params, const RGBColorSpace* colorSpace);
    // params first, then graphics-state attributes (marked mayBeUnused), which apply when
    // params lacks the name.
    ParameterDictionary(ParsedParameterVector params, const ParsedParameterVector& attributes,
                        const RGBColorSpace* colorSpace);

    // Single values
    Float GetOneFloat(const std::string& name, Float def) const;
    int GetOneInt(const std::string& name, int def) const;
    bool GetOneBool(const std::string& name, bool def) const;
    std::string GetOneString(const std::string& name, const std::string& def) const;
    // A "string" parameter naming a file, resolved against the parameter's searchDirectory
    // (ResolveFilename); def (unresolved) if absent.
    std::string GetOneFilename(const std::string& name, const std::string& def) const;
    // A "string" array of file names, each resolved as GetOneFilename's.
    std::vector<std::string> GetFilenameArray(const std::string& name) const;
    Point2f GetOnePoint2f(const std::string& name, Point2f def) const;
    Vector2f GetOneVector2f(const std::string& name, Vector2f def) const;
    Point3f GetOnePoint3f(const std::string& name, Point3f def) const;
    Vector3f GetOneVector3f(const std::string& name, Vector3f def) const;
    Normal3f GetOneNormal3f(const std::string& name, Normal3f def) const;
    // "rgb", "spectrum" (wavelength/value pairs in nm, a named spectrum, or a file resolved
    // via searchDirectory and read with PiecewiseLinearSpectrum::Read) or "blackbody"
    // (temperature in K; BlackbodySpectrum, peak normalised to 1 as in pbrt-v4). rgb
    // components must be >= 0, and <= 1 for Albedo (else SceneError); Albedo ->
    // RGBAlbedoSpectrum, Unbounded -> RGBUnboundedSpectrum, Illuminant ->
    // RGBIlluminantSpectrum, in the dictionary's colour space.
    std::optional<Spectrum> GetOneSpectrum(const std::string& name, std::optional<Spectrum> def,
                                           SpectrumType type) const;

    // Arrays (empty if absent)
    std::vector<Float> GetFloatArray(const std::string& name) const;
    std::vector<int> GetIntArray(const std::string& name) const;
    std::vector<uint8_t> GetBoolArray(const std::string& name) const;
    std::vector<std::string> GetStringArray(const std::string& name) const;
    std::vector<Point2f> GetPoint2fArray(const std::string& name) const;
    std::vector<Vector2f> GetVector2fArray(const std::string& name) const;
    std::vector<Point3f> GetPoint3fArray(const std::string& name) const;
    std::vector<Vector3f> GetVector3fArray(const std::string& name) const;
    std::vector<Normal3f> GetNormal3fArray(const std::string& name) const;
    std::vector<Spectrum> GetSpectrumArray(const std::string& name, SpectrumType type) const;

    // The value of a "texture name" parameter, "" if none.
    std::string GetTexture(const std::string& name) const;
    // The name of the named spectrum ("metal-W-eta") a "spectrum" parameter gives, "" if it
    // gives anything else or is absent (does not mark it as looked up).
    std::string GetSpectrumName(const std::string& name) const;

    // Queries (do not mark parameters as looked up)
    bool Has(const std::string& name) const;
    // Canonical type of the parameter that lookups would find first, "" if absent.
    std::string TypeOf(const std::string& name) const;
    // Where the parameter is: a default FileLoc if it is not given; `absent` if it is not given
    // or has no location (parameters made by the Python API).
    FileLoc Loc(const std::string& name) const;
    FileLoc Loc(const std::string& name, const FileLoc& absent) const;
    const RGBColorSpace* ColorSpace() const;
    // In the order given (params, then attributes).
    const ParsedParameterVector& Parameters() const { return params; }

    // Replaces (every parameter of that name) or adds a parameter, e.g. for command-line
    // overrides.
    void Set(ParsedParameter p);
    // Removes every parameter of that name (a command-line override replacing another).
    void Erase(const std::string& name);
    // Adds p with the lowest precedence of all: found only where neither the parameters nor
    // the attributes give its name, and never reported unused (a scene-wide default, e.g.
    // Option "ambienttemperature" for media).
    void AddDefault(ParsedParameter p);

    // For every parameter never looked up and not mayBeUnused (unless shadowed by a looked-up
    // one of the same type and name): a warning "unused parameter 'float foo'" when kiln or
    // pbrt-v4 knows the name (parameter_names.h: a pbrt-v4 parameter kiln does not use, or a
    // name in the wrong place), else SceneError "unknown parameter 'float temprature'; did
    // you mean "temperature"?" at the parameter (pbrt-v4 stops at every unused parameter).
    void ReportUnused(Diagnostics& diag) const;
    // Marks every parameter looked up: for a directive that is skipped with a warning of its
    // own, so that its parameters are not also reported as unused.
    void MarkAllUsed() const;

  private:
    // Last match first: the directive's parameters, then the attributes.
    const ParsedParameter* Find(const std::string& name, std::string_view type) const;
    std::vector<Spectrum> ExtractSpectra(const ParsedParameter& p, SpectrumType type) const;

    ParsedParameterVector params;
    size_t nOwn = 0;  // params[0, nOwn) are the directive's own, the rest attributes.
    const RGBColorSpace* colorSpace = nullptr;
};

}  // namespace kiln
