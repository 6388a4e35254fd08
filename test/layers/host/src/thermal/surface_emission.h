// Fixture: the host interface including a kiln material
#include "materials/material.h"
