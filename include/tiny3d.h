// tiny3d.h — all of libtiny3d.
#ifndef TINY3D_H
#define TINY3D_H

#include "canvas.h"
#include "math3d.h"
#include "renderer.h"
#include "lighting.h"
#include "animation.h"
#include "scene.h"

#endif
