#include "lights/light.h"

#include "spectral/cie.h"

namespace kiln {

Float EmissionLuminance(const Spectrum& s) { return SpectrumToPhotometric(s) / CIE_Y_integral; }

}  // namespace kiln
