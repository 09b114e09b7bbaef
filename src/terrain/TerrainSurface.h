#pragma once
// The terrain's surface as the shaders build it (shaders/terrain/surface.hlsli), on the CPU: the
// range mask times the height field's bilinear height at a mip chosen by the level's vertex spacing, plus metre-scale
// detail noise that fades out on levels too coarse to carry it, lowered by the Earth's curvature.
// Used to keep the camera above the ground, and by the tests as the shaders' reference.
#include "terrain/HeightField.h"

namespace firmament {

// Detail noise: octaves of value noise of wavelengths 64, 32, 16, 8 and 4 m, amplitude 6% of the
// wavelength, each weighted by saturate(wavelength / (2 spacing) - 1) so that a grid of vertex
// spacing `spacing` carries only the octaves it resolves (4 or more vertices to a wavelength).
inline constexpr int kDetailOctaves = 5;
inline constexpr double kDetailLongestWavelength = 64.0;
inline constexpr double kDetailAmplitude = 0.06;  // of the wavelength
double detailHeight(double x, double z, double spacing);

// Where mountain ranges stand: a mask in [kPlainsRelief, 1] that scales the height field, made
// of value noise on lattices of 30 to 160 km that do not repeat with the 32.8 km tile. Long
// sinuous bands (where a warped noise crosses zero) broken into massifs by a second noise; the
// plains between them keep a tenth of the tile's relief. Offset so that the origin, where the
// program starts, lies in a range.
inline constexpr double kPlainsRelief = 0.1;
double rangeMask(double x, double z);

// The height-field mip a grid of this vertex spacing samples: one texel per vertex or finer.
int heightMipFor(double spacing, const HeightField& field);

// Height above the sea-level sphere of the surface a grid of vertex spacing `spacing` draws:
// rangeMask times the height field at the spacing's mip, plus the detail noise.
double surfaceHeight(const HeightField& field, double x, double z, double spacing);

// How far the sphere of radius R through the origin (centre (0, -R, 0)) lies below the plane
// y = 0 at horizontal distance sqrt(x^2 + z^2): r^2 / (R + sqrt(R^2 - r^2)), free of cancellation.
double earthDrop(double x, double z, double earthRadius);

}  // namespace firmament
