#pragma once
// Where the terrain's clipmap levels lie around the camera (geometry clipmaps, Losasso and
// Hoppe 2004, simplified): level L is a grid of kClipmapCells x kClipmapCells cells of
// spacing 2^L metres, centred on the camera snapped to twice its spacing so that its edges fall
// on the next coarser level's vertices. Each level but the finest leaves a hole of half its
// width where the finer level lies; the hole is off centre by -1, 0 or 1 of its cells in x and
// z, so nine index ranges cover every case (ClipmapMesh). Levels much finer than the camera's
// height above the ground would be sub-pixel: the finest drawn level is the first whose
// half-width reaches kLevelReachOverHeight times that height.
#include <glm/vec2.hpp>

#include <vector>

namespace firmament {

inline constexpr int kClipmapCells = 64;   // cells per side of a level (even; the hole is half of it)
// Spacings 1 m .. 131 km: the coarsest reaches 4,194 km, beyond the horizon from 1,000 km up
// (3,709 km), its corners (5,932 km) still inside the Earth's radius, where the drop is defined.
inline constexpr int kClipmapLevels = 18;
inline constexpr double kFinestSpacing = 1.0;
inline constexpr double kLevelReachOverHeight = 2.5;

struct ClipmapLevel {
    int index = 0;        // L
    double spacing = 1;   // 2^L metres
    glm::dvec2 origin{};  // (x, z) of vertex (0, 0); a multiple of 2 * spacing
    bool hasHole = false;
    glm::ivec2 holeOffset{};  // the hole's offset from centre in cells, each -1, 0 or 1
};

// The levels to draw, finest first. heightAboveGround: metres, >= 0.
std::vector<ClipmapLevel> clipmapLevels(glm::dvec2 camera, double heightAboveGround);

// The square the terrain covers around the camera: the coarsest level's, centre (x, z) and
// half-width (4,194 km).
struct ClipmapExtent {
    glm::dvec2 centre{};
    double halfWidth = 0;
};
ClipmapExtent clipmapExtent(glm::dvec2 camera);

// The cells [first, first + kClipmapCells / 2) of each axis are the hole for this offset.
int holeFirstCell(int offset);

}  // namespace firmament
