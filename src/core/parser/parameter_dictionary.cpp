// ParameterDictionary: typed parameter lookups (pbrt-v4's paramdict.cpp semantics).

#include "core/parser/parameter_dictionary.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/parser/parameter_names.h"
#include "core/parser/search_path.h"
#include "core/parser/suggestions.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

namespace kiln {

namespace {

[[noreturn]] void Fail(const ParsedParameter& p, const std::string& message) {
    throw SceneError(p.loc, message, p.Declaration());
}

// The values of a parameter, checked for a whole number of items.
template <typename T>
void CheckCount(const ParsedParameter& p, const std::vector<T>& values, size_t perItem) {
    if (values.empty()) Fail(p, "no values provided for parameter '" + p.name + "'");
    if (values.size() % perItem != 0)
        Fail(p, "number of values provided for '" + p.name + "' is not a multiple of " +
                    std::to_string(perItem));
}

template <typename T, typename V, typename C>
std::vector<T> ToArray(const ParsedParameter& p, const std::vector<V>& values, size_t perItem,
                       C convert) {
    CheckCount(p, values, perItem);
    p.lookedUp = true;
    std::vector<T> result;
    result.reserve(values.size() / perItem);
    for (size_t i = 0; i < values.size(); i += perItem) result.push_back(convert(&values[i]));
    return result;
}

template <typename T, typename V, typename C>
T ToOne(const ParsedParameter& p, const std::vector<V>& values, size_t perItem, C convert) {
    CheckCount(p, values, perItem);
    if (values.size() > perItem)
        Fail(p, "more than one value provided for parameter '" + p.name + "'");
    p.lookedUp = true;
    return convert(values.data());
}

}  // namespace

// Construction
ParameterDictionary::ParameterDictionary(ParsedParameterVector p, const RGBColorSpace* cs)
    : params(std::move(p)), nOwn(params.size()), colorSpace(cs) {}

ParameterDictionary::ParameterDictionary(ParsedParameterVector p,
                                         const ParsedParameterVector& attributes,
                                         const RGBColorSpace* cs)
    : params(std::move(p)), nOwn(params.size()), colorSpace(cs) {
    for (const ParsedParameter& a : attributes) {
        params.push_back(a);
        params.back().mayBeUnused = true;
    }
}

void ParameterDictionary::AddDefault(ParsedParameter p) {
    p.mayBeUnused = true;
    params.insert(params.begin() + std::ptrdiff_t(nOwn), std::move(p));
}

const ParsedParameter* ParameterDictionary::Find(const std::string& name,
                                                 std::string_view type) const {
    // Own parameters last to first, then attributes last to first (pbrt-v4's order).
    auto search = [&](size_t begin, size_t end) -> const ParsedParameter* {
        for (size_t i = end; i > begin; --i)
            if (params[i - 1].name == name && (type.empty() || params[i - 1].type == type))
                return &params[i - 1];
        return nullptr;
    };
    if (const ParsedParameter* p = search(0, nOwn)) return p;
    return search(nOwn, params.size());
}

// Single values
Float ParameterDictionary::GetOneFloat(const std::string& name, Float def) const {
    const ParsedParameter* p = Find(name, "float");
    return p ? ToOne<Float>(*p, p->floats, 1, [](const Float* v) { return v[0]; }) : def;
}

int ParameterDictionary::GetOneInt(const std::string& name, int def) const {
    const ParsedParameter* p = Find(name, "integer");
    return p ? ToOne<int>(*p, p->ints, 1, [](const int* v) { return v[0]; }) : def;
}

bool ParameterDictionary::GetOneBool(const std::string& name, bool def) const {
    const ParsedParameter* p = Find(name, "bool");
    return p ? ToOne<bool>(*p, p->bools, 1, [](const uint8_t* v) { return v[0] != 0; }) : def;
}

std::string ParameterDictionary::GetOneString(const std::string& name,
                                              const std::string& def) const {
    const ParsedParameter* p = Find(name, "string");
    return p ? ToOne<std::string>(*p, p->strings, 1, [](const std::string* v) { return *v; }) : def;
}

std::string ParameterDictionary::GetOneFilename(const std::string& name,
                                                const std::string& def) const {
    const ParsedParameter* p = Find(name, "string");
    if (!p) return def;
    std::string f = ToOne<std::string>(*p, p->strings, 1, [](const std::string* v) { return *v; });
    return ResolveFilename(p->searchDirectory, f);
}

Point2f ParameterDictionary::GetOnePoint2f(const std::string& name, Point2f def) const {
    const ParsedParameter* p = Find(name, "point2");
    return p ? ToOne<Point2f>(*p, p->floats, 2, [](const Float* v) { return Point2f(v[0], v[1]); })
             : def;
}

Vector2f ParameterDictionary::GetOneVector2f(const std::string& name, Vector2f def) const {
    const ParsedParameter* p = Find(name, "vector2");
    return p ? ToOne<Vector2f>(*p, p->floats, 2,
                               [](const Float* v) { return Vector2f(v[0], v[1]); })
             : def;
}

Point3f ParameterDictionary::GetOnePoint3f(const std::string& name, Point3f def) const {
    const ParsedParameter* p = Find(name, "point3");
    return p ? ToOne<Point3f>(*p, p->floats, 3,
                              [](const Float* v) { return Point3f(v[0], v[1], v[2]); })
             : def;
}

Vector3f ParameterDictionary::GetOneVector3f(const std::string& name, Vector3f def) const {
    const ParsedParameter* p = Find(name, "vector3");
    return p ? ToOne<Vector3f>(*p, p->floats, 3,
                               [](const Float* v) { return Vector3f(v[0], v[1], v[2]); })
             : def;
}

Normal3f ParameterDictionary::GetOneNormal3f(const std::string& name, Normal3f def) const {
    const ParsedParameter* p = Find(name, "normal");
    return p ? ToOne<Normal3f>(*p, p->floats, 3,
                               [](const Float* v) { return Normal3f(v[0], v[1], v[2]); })
             : def;
}

// Spectra
std::vector<Spectrum> ParameterDictionary::ExtractSpectra(const ParsedParameter& p,
                                                          SpectrumType type) const {
    const RGBColorSpace& cs = *ColorSpace();
    if (p.type == "rgb") {
        return ToArray<Spectrum>(p, p.floats, 3, [&](const Float* v) -> Spectrum {
            RGB rgb(v[0], v[1], v[2]);
            if (rgb.r < 0 || rgb.g < 0 || rgb.b < 0)
                Fail(p, "RGB parameter '" + p.name + "' has a negative component");
            // (An RGB's spectrum is twice its largest component times a sigmoid)
            if (std::max({rgb.r, rgb.g, rgb.b}) > std::numeric_limits<Float>::max() / 2)
                Fail(p, "RGB parameter '" + p.name +
                            "' has a component above 1.7e38, beyond what its spectrum can hold in "
                            "single precision");
            if (type == SpectrumType::Albedo) {
                if (rgb.r > 1 || rgb.g > 1 || rgb.b > 1)
                    Fail(p, "RGB reflectance parameter '" + p.name +
                                "' has a component greater than 1");
                return RGBAlbedoSpectrum(cs, rgb);
            }
            if (type == SpectrumType::Unbounded) return RGBUnboundedSpectrum(cs, rgb);
            return RGBIlluminantSpectrum(cs, rgb);
        });
    }
    if (p.type == "blackbody")
        return ToArray<Spectrum>(
            p, p.floats, 1, [](const Float* v) -> Spectrum { return BlackbodySpectrum(v[0]); });
    if (p.type != "spectrum") return {};
    if (!p.floats.empty()) {
        // One spectrum from (wavelength nm, value) pairs.
        if (p.floats.size() % 2 != 0)
            Fail(p, "odd number of values for spectrum parameter '" + p.name + "'");
        std::vector<Float> lambda, value;
        for (size_t i = 0; i < p.floats.size(); i += 2) {
            if (!lambda.empty() && p.floats[i] <= lambda.back())
                Fail(p, "spectrum wavelengths are not increasing: " + std::to_string(p.floats[i]) +
                            " after " + std::to_string(lambda.back()));
            lambda.push_back(p.floats[i]);
            value.push_back(p.floats[i + 1]);
        }
        p.lookedUp = true;
        PiecewiseLinearSpectrum s(lambda, value);
        if (type != SpectrumType::Illuminant) s.HoldEndsBeyondVisible();
        return {Spectrum(std::move(s))};
    }
    // Named spectra or files, one spectrum per string.
    return ToArray<Spectrum>(p, p.strings, 1, [&](const std::string* s) -> Spectrum {
        if (const Spectrum* named = GetNamedSpectrum(*s)) return *named;
        if (s->size() > 2 && s->compare(s->size() - 2, 1, "_") == 0 &&
            IsPbrtSensorWithoutData(std::string_view(*s).substr(0, s->size() - 2)))
            Fail(p, "'" + *s +
                        "' is one of pbrt-v4's camera sensor curves, which are not available to "
                        "kiln from any public source");
        std::string error;
        std::string filename = ResolveFilename(p.searchDirectory, *s);
        std::optional<PiecewiseLinearSpectrum> read =
            PiecewiseLinearSpectrum::Read(filename, &error);
        if (!read)
            Fail(p, "'" + *s + "' is neither a named spectrum nor a readable spectrum file" +
                        (error.empty() ? std::string() : " (" + error + ")"));
        if (type != SpectrumType::Illuminant) read->HoldEndsBeyondVisible();
        return std::move(*read);
    });
}

std::optional<Spectrum> ParameterDictionary::GetOneSpectrum(const std::string& name,
                                                            std::optional<Spectrum> def,
                                                            SpectrumType type) const {
    auto search = [&](size_t begin, size_t end) -> std::optional<Spectrum> {
        for (size_t i = end; i > begin; --i) {
            const ParsedParameter& p = params[i - 1];
            if (p.name != name) continue;
            std::vector<Spectrum> s = ExtractSpectra(p, type);
            if (s.empty()) continue;
            if (s.size() > 1) Fail(p, "more than one value provided for parameter '" + name + "'");
            return std::move(s[0]);
        }
        return std::nullopt;
    };
    if (std::optional<Spectrum> s = search(0, nOwn)) return s;
    if (std::optional<Spectrum> s = search(nOwn, params.size())) return s;
    return def;
}

std::vector<Spectrum> ParameterDictionary::GetSpectrumArray(const std::string& name,
                                                            SpectrumType type) const {
    auto search = [&](size_t begin, size_t end) -> std::vector<Spectrum> {
        for (size_t i = end; i > begin; --i) {
            const ParsedParameter& p = params[i - 1];
            if (p.name != name) continue;
            std::vector<Spectrum> s = ExtractSpectra(p, type);
            if (!s.empty()) return s;
        }
        return {};
    };
    std::vector<Spectrum> s = search(0, nOwn);
    return s.empty() ? search(nOwn, params.size()) : s;
}

// Arrays
std::vector<Float> ParameterDictionary::GetFloatArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "float");
    if (!p) return {};
    return ToArray<Float>(*p, p->floats, 1, [](const Float* v) { return v[0]; });
}

std::vector<int> ParameterDictionary::GetIntArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "integer");
    if (!p) return {};
    return ToArray<int>(*p, p->ints, 1, [](const int* v) { return v[0]; });
}

std::vector<uint8_t> ParameterDictionary::GetBoolArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "bool");
    if (!p) return {};
    return ToArray<uint8_t>(*p, p->bools, 1, [](const uint8_t* v) { return v[0]; });
}

std::vector<std::string> ParameterDictionary::GetFilenameArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "string");
    if (!p) return {};
    std::vector<std::string> files = GetStringArray(name);
    for (std::string& f : files) f = ResolveFilename(p->searchDirectory, f);
    return files;
}

std::vector<std::string> ParameterDictionary::GetStringArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "string");
    if (!p) return {};
    return ToArray<std::string>(*p, p->strings, 1, [](const std::string* v) { return *v; });
}

std::vector<Point2f> ParameterDictionary::GetPoint2fArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "point2");
    if (!p) return {};
    return ToArray<Point2f>(*p, p->floats, 2, [](const Float* v) { return Point2f(v[0], v[1]); });
}

std::vector<Vector2f> ParameterDictionary::GetVector2fArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "vector2");
    if (!p) return {};
    return ToArray<Vector2f>(*p, p->floats, 2, [](const Float* v) { return Vector2f(v[0], v[1]); });
}

std::vector<Point3f> ParameterDictionary::GetPoint3fArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "point3");
    if (!p) return {};
    return ToArray<Point3f>(*p, p->floats, 3,
                            [](const Float* v) { return Point3f(v[0], v[1], v[2]); });
}

std::vector<Vector3f> ParameterDictionary::GetVector3fArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "vector3");
    if (!p) return {};
    return ToArray<Vector3f>(*p, p->floats, 3,
                             [](const Float* v) { return Vector3f(v[0], v[1], v[2]); });
}

std::vector<Normal3f> ParameterDictionary::GetNormal3fArray(const std::string& name) const {
    const ParsedParameter* p = Find(name, "normal");
    if (!p) return {};
    return ToArray<Normal3f>(*p, p->floats, 3,
                             [](const Float* v) { return Normal3f(v[0], v[1], v[2]); });
}

std::string ParameterDictionary::GetTexture(const std::string& name) const {
    const ParsedParameter* p = Find(name, "texture");
    if (!p) return "";
    return ToOne<std::string>(*p, p->strings, 1, [](const std::string* v) { return *v; });
}

std::string ParameterDictionary::GetSpectrumName(const std::string& name) const {
    const ParsedParameter* p = Find(name, {});
    if (!p || p->type != "spectrum" || !p->floats.empty() || p->strings.size() != 1) return "";
    return GetNamedSpectrum(p->strings[0]) ? p->strings[0] : "";
}

// Queries
bool ParameterDictionary::Has(const std::string& name) const { return Find(name, {}) != nullptr; }

std::string ParameterDictionary::TypeOf(const std::string& name) const {
    const ParsedParameter* p = Find(name, {});
    return p ? p->type : std::string();
}

FileLoc ParameterDictionary::Loc(const std::string& name) const {
    const ParsedParameter* p = Find(name, {});
    return p ? p->loc : FileLoc();
}

FileLoc ParameterDictionary::Loc(const std::string& name, const FileLoc& absent) const {
    const ParsedParameter* p = Find(name, {});
    return p && (p->loc.line > 0 || !p->loc.filename.empty()) ? p->loc : absent;
}

const RGBColorSpace* ParameterDictionary::ColorSpace() const {
    return colorSpace ? colorSpace : &RGBColorSpace::sRGB();
}

void ParameterDictionary::Erase(const std::string& name) {
    ParsedParameterVector kept;
    size_t keptOwn = 0;
    for (size_t i = 0; i < params.size(); ++i) {
        if (params[i].name == name) continue;
        kept.push_back(std::move(params[i]));
        if (i < nOwn) ++keptOwn;
    }
    params = std::move(kept);
    nOwn = keptOwn;
}

void ParameterDictionary::Set(ParsedParameter p) {
    ParsedParameterVector kept;
    size_t keptOwn = 0;
    for (size_t i = 0; i < params.size(); ++i) {
        if (params[i].name == p.name) continue;
        kept.push_back(std::move(params[i]));
        if (i < nOwn) ++keptOwn;
    }
    kept.insert(kept.begin() + keptOwn, std::move(p));
    params = std::move(kept);
    nOwn = keptOwn + 1;
}

// Unused parameters
void ParameterDictionary::MarkAllUsed() const {
    for (const ParsedParameter& p : params) p.lookedUp = true;
}

void ParameterDictionary::ReportUnused(Diagnostics& diag) const {
    std::vector<const ParsedParameter*> seen;  // looked-up parameters, by type and name
    auto visit = [&](const ParsedParameter& p) {
        if (p.mayBeUnused) return;
        bool shadowed = false;
        for (const ParsedParameter* s : seen)
            if (s->type == p.type && s->name == p.name) shadowed = true;
        if (p.lookedUp)
            seen.push_back(&p);
        else if (!shadowed && IsKnownParameterName(p.name))
            diag.Warn(p.loc, "unused parameter '" + p.Declaration() + "'");
        else if (!shadowed)  // neither kiln nor pbrt-v4 knows it: stop, as pbrt-v4 does
            throw SceneError(p.loc,
                             "unknown parameter '" + p.Declaration() + "'" +
                                 DidYouMean(p.name, KnownParameterNames()),
                             p.name);
    };
    for (size_t i = nOwn; i > 0; --i) visit(params[i - 1]);
    for (size_t i = params.size(); i > nOwn; --i) visit(params[i - 1]);
}

}  // namespace kiln
