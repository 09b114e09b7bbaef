#pragma once
// How the atmosphere's models share the frame (AtmosphereSettings: model, comparison and
// comparedModel), in the order they draw:
//  - None: the model over the whole frame;
//  - Split: the model left of the middle column, the compared model from it on;
//  - Difference: the model, then the compared model, both over the whole frame (the view shows
//    |second - first|); the ground is lit by the first;
//  - Three-way: Yusov 2013, Bruneton 2008 and Hillaire 2020 in thirds, from the left.
#include "atmosphere/AtmosphereSettings.h"
#include "gpu/FullscreenPass.h"

#include <algorithm>
#include <vector>

namespace firmament {

struct ModelRegion {
    AtmosphereModel model = AtmosphereModel::Yusov2013;
    Columns columns;
};

inline std::vector<ModelRegion> modelRegions(const AtmosphereSettings& s, int width) {
    switch (s.comparison) {
        case ModelComparison::None: return {{s.model, {0, width}}};
        case ModelComparison::Split: return {{s.model, {0, width / 2}}, {s.comparedModel, {width / 2, width}}};
        case ModelComparison::Difference: return {{s.model, {0, width}}, {s.comparedModel, {0, width}}};
        case ModelComparison::ThreeWay:
            return {{AtmosphereModel::Yusov2013, {0, width / 3}},
                    {AtmosphereModel::Bruneton2008, {width / 3, 2 * width / 3}},
                    {AtmosphereModel::Hillaire2020, {2 * width / 3, width}}};
    }
    return {};
}

// Whether the settings draw `model` anywhere in the frame.
inline bool drawsModel(const AtmosphereSettings& s, AtmosphereModel model) {
    const std::vector<ModelRegion> regions = modelRegions(s, 2);
    return std::any_of(regions.begin(), regions.end(), [&](const ModelRegion& r) { return r.model == model; });
}

}  // namespace firmament
