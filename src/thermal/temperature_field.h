// Temperature fields: where a hot surface's temperature comes from, in kelvin, as kiln float
// textures (`Texture "name" "float" "class" ...`, then `"texture temperature" "name"` on a
// shape or material). They compose with the other float textures ("scale", "mix", ...) like
// any float texture. Classes:
//   gradient         linear ramp between two points                 spatial_temperature_fields.h
//   noise            3D gradient-noise fBm mapped into [min, max]   spatial_temperature_fields.h
//   vertexattribute  per-vertex mesh attribute                      spatial_temperature_fields.h
//   heatmap          image (sequence) lookup                        heat_map_field.h
//   cooling          lumped-capacitance cooling T(time)             time_temperature_fields.h
//   keyframes        piecewise-linear T(time)                       time_temperature_fields.h
//
// A field enters kiln's closed FloatTexture set as its one extension
// (textures/float_texture_extension.h). Fields that follow the animation (heat-map sequences,
// cooling and keyframes without their own "frame" / "time") are Animated: a scene renders
// another frame by calling SetAnimation on them and nothing else is re-created.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/object_arena.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "textures/float_texture_extension.h"
#include "textures/texture.h"

namespace kiln {

class TextureParameterDictionary;

// TemperatureAnimation Definition
// The frame being rendered and its time in seconds (RenderOptions::frame, timeSeconds).
struct TemperatureAnimation {
    std::optional<int> frame;
    std::optional<Float> timeSeconds;
};

// TemperatureField Definition
class TemperatureField : public FloatTextureExtension {
  public:
    // Whether the value depends on the animation (and SetAnimation changes it).
    virtual bool Animated() const { return false; }
    // Sets the frame and time the field is evaluated at; throws SceneError (at the texture's
    // directive) if a frame's data cannot be read. Not to be called while a render runs.
    virtual void SetAnimation(const TemperatureAnimation&) {}
};

// Whether `className` is one of the temperature fields above.
bool IsTemperatureFieldClass(const std::string& className);

// Creates the temperature field `className` (IsTemperatureFieldClass) at `animation`. Animated
// fields are appended to *animated when it is given. Throws SceneError for invalid parameters.
FloatTexture CreateTemperatureField(const std::string& className,
                                    const Transform& renderFromTexture,
                                    const TextureParameterDictionary& params, const FileLoc& loc,
                                    ObjectArena& arena, Diagnostics& diag,
                                    const TemperatureAnimation& animation = {},
                                    std::vector<TemperatureField*>* animated = nullptr);

// The closed set's handle of a field (FloatTexture holds it as its extension).
inline FloatTexture AsFloatTexture(const TemperatureField* field) {
    return FloatTexture(static_cast<const FloatTextureExtension*>(field));
}

}  // namespace kiln
