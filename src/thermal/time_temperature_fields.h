// Temperature fields that depend only on time (temperature_field.h): the same value over the
// surface, changing from frame to frame.
#pragma once

#include <vector>

#include "thermal/cooling.h"
#include "thermal/temperature_field.h"

namespace kiln {

// TimeTemperatureField Definition
// T(t) for t = "float time" (s) when given, else the animation's time (0 without one); without
// "float time" the field is Animated and SetAnimation moves it to the animation's time.
class TimeTemperatureField : public TemperatureField {
  public:
    Float Evaluate(const TextureEvalContext&) const final { return value; }
    bool UsesFootprint() const final { return false; }  // a function of time only
    bool Animated() const final { return followsAnimation; }
    void SetAnimation(const TemperatureAnimation& animation) final;
    // The value at the current time.
    Float Value() const { return value; }
    // T(t), K, for t in s.
    virtual Float At(Float t) const = 0;

  protected:
    // Sets the time from the parameters and the animation (Create's last step).
    void Start(const TextureParameterDictionary& params, const TemperatureAnimation& animation);

  private:
    bool followsAnimation = false;
    Float time = 0, value = 0;
};

// CoolingField Definition ("cooling")
// T(time) of CoolingModel (cooling.h) with "float T0" (1000 K), "float emissivity" (1),
// "float area" (m^2, 1), "float mass" (kg) or "float density" (kg m^-3) with "float thickness"
// (m; mass = density thickness area) or "float volume" (m^3), "float specificheat"
// (J kg^-1 K^-1, 500), "float h" (W m^-2 K^-1, 0), "float Tambient" (K, 0).
class CoolingField final : public TimeTemperatureField {
  public:
    explicit CoolingField(const CoolingParameters& parameters) : model(parameters) {}
    Float At(Float t) const override { return Float(model.Temperature(t)); }

    static CoolingField* Create(const TextureParameterDictionary& params, const FileLoc& loc,
                                ObjectArena& arena, const TemperatureAnimation& animation);

  private:
    CoolingModel model;
};

// KeyframeField Definition ("keyframes")
// "float times" [...] (non-decreasing, s) and "float values" [...], interpolated linearly,
// the first / last value outside.
class KeyframeField final : public TimeTemperatureField {
  public:
    KeyframeField(std::vector<Float> times, std::vector<Float> values)
        : times(std::move(times)), values(std::move(values)) {}
    Float At(Float t) const override;

    static KeyframeField* Create(const TextureParameterDictionary& params, const FileLoc& loc,
                                 ObjectArena& arena, const TemperatureAnimation& animation);

  private:
    std::vector<Float> times, values;
};

}  // namespace kiln
