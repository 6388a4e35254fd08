// Tables of metals' optical constants measured at several temperatures
// (metal_temperature_data.cpp cites the sources).
#pragma once

#include <span>
#include <string_view>

namespace kiln {

struct MeasuredMetalTemperatures {
    std::string_view symbol;              // "Au", "Ag"
    std::span<const float> temperatures;  // kelvin, increasing; the first is room temperature
    // Rows of 1 + 2 * temperatures.size() floats: wavelength (nm, increasing), then n and k
    // at each temperature
    std::span<const float> rows;
};

std::span<const MeasuredMetalTemperatures> MeasuredMetalTemperatureTables();

}  // namespace kiln
