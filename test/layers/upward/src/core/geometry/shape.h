// Fixture: geometry (rank 21) including textures (rank 30)
#include "textures/texture.h"
