#pragma once
// The single-source model compiled as C++ for the CPU backend. Include this (not the individual
// *.glsl.h headers) from C++ code that evaluates textured model functions; the texture reads are
// served by src/cpu/cpu_textures.cpp from the thread's bound TextureSet.
#include "cpu/cpu_textures.h"
#include "model/camera.glsl.h"
#include "model/cloud_shadow.glsl.h"
#include "model/density.glsl.h"
#include "model/lighting.glsl.h"
#include "model/march.glsl.h"
#include "model/output.glsl.h"
#include "model/params.glsl.h"
#include "model/phase.glsl.h"
#include "model/pixel.glsl.h"
#include "model/profiles.glsl.h"
#include "model/shell.glsl.h"
#include "model/sky.glsl.h"
#include "model/weather.glsl.h"
