// Spectra known by name, as in pbrt-v4 scene files ("metal-Cu-eta", "stdillum-D65", ...).
//
// pbrt-v4's names give pbrt-v4's values: metals' and glasses' n and k (dimensionless), and
// standard illuminants (relative SPDs normalised to luminance Y = 1, i.e. integral(s ybar) =
// CIE_Y_integral). kiln adds measured optical constants of the metals of Wilkie & Weidlich
// (2011): metal-{Pt,Ni,Fe,W,Cr,Ti,Se}-{eta,k} and glass-SiO2 (fused silica, n only), and glass
// through the infrared: glass-fused-silica-{eta,k} and glass-soda-lime-{eta,k} (300 nm - 20 um).
// pbrt-v4's camera sensor curves <sensor>_r/_g/_b are available for the sensors in
// CameraNamedSpectrumTables() only (measured by the Academy's rawtoaces project, not pbrt-v4's
// data). Sources are cited beside the tables (named_spectra_*_data.cpp). Note: metal-Se-* is a
// 25 nm selenium film (n about 1.4), not bulk selenium, and MgO, TiO2 and Se are not metals (the
// names are pbrt-v4's and the paper's).
#pragma once

#include <string_view>
#include <vector>

#include "spectral/spectrum.h"

namespace kiln {

// The named spectrum, or nullptr if the name is unknown. Spectra are built on first use and
// live for the program's life.
const Spectrum* GetNamedSpectrum(std::string_view name);

// Whether name is one of pbrt-v4's camera sensors ("nikon_d850", ...) whose measured curves
// kiln lacks because no public source of them is known (their <name>_r/_g/_b are not named
// spectra here).
bool IsPbrtSensorWithoutData(std::string_view name);

// Every name GetNamedSpectrum knows, pbrt-v4's first.
std::vector<std::string_view> NamedSpectrumNames();

}  // namespace kiln
