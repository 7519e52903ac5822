// animation.h — Bezier paths, looped timelines, orientation interpolation.
#ifndef TINY3D_ANIMATION_H
#define TINY3D_ANIMATION_H

#include "math3d.h"

#endif
