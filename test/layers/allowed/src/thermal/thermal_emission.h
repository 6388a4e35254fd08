// Fixture
#pragma once
#include "thermal/surface_emission.h"
