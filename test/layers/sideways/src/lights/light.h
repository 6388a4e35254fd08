// Fixture: lights and media share a rank and may not include each other
#include "media/medium.h"
