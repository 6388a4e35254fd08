// Fixture: lights include the thermal module below them, and their own folder
#include "light_sample.h"
#include "thermal/thermal_emission.h"
