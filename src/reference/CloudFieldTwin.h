#pragma once
// The tests' twin of the clouds' valid-cell and generation passes (shaders/clouds/cloud_field.hlsli;
// docs/clouds.md, "Cloudiness" and "Generation"): the valid cells and the particles the GPU
// generates from the field's constants and density map, computed the same way in C++.
#include "clouds/CloudField.h"
#include "clouds/CloudStructures.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace firmament {

struct ModelParticle {
    glm::vec3 centre{0.0f};
    float horizontalRadius = 0.0f;
    float verticalRadius = 0.0f;
    float density = 0.0f;
    float azimuth = 0.0f;
    int ring = 0;
    unsigned cell = 0;  // index in the cell list
    int layer = 0;
};

struct CloudFieldModel {
    std::vector<unsigned> validCells;  // indices in the cell list, in list order
    // Per cell of the list: its coverage before it is clamped to 0..1 (not above 0: clear sky),
    // and how far it reaches: its middle's distance from the camera less its radius (m).
    std::vector<float> coverage;
    std::vector<float> reach;
    std::vector<ModelParticle> particles;
};

// What the GPU's valid-cell and generation passes produce for `constants`, `cells` (the packed
// list, CloudGrid order) and `map`, with the camera at `camera` on a planet of `earthRadius`.
CloudFieldModel modelCloudField(const gpu::CloudFieldConstants& constants, const std::vector<std::uint32_t>& cells, const std::vector<float>& map,
                                glm::vec3 camera, float earthRadius);

}  // namespace firmament
