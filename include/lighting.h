// lighting.h — Lambert lighting (per edge and per face), flat / Gouraud / Phong, lights.
#ifndef TINY3D_LIGHTING_H
#define TINY3D_LIGHTING_H

#include "math3d.h"

#endif
