// The CPU twin of the particles' walk along the sun (src/reference/SunColumnTwin) on a few
// particles stacked along a vertical sun, where every chord is known: the column sums every chord,
// and the deck only those that reach the particle without a gap of clear air, whatever the order
// in which the particles are listed (the GPU test holds the walk on the tile lists to this).
#include "reference/SunColumnTwin.h"

#include "clouds/LightSpace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace firmament {
namespace {

constexpr double kEarthRadius = 6371000.0;
constexpr ParticleDensityMethod kMethod = ParticleDensityMethod::RadialNoise;

// A particle over the world's origin, at `height`, 200 m wide and `verticalRadius` tall.
ModelParticle stacked(float height, float verticalRadius) {
    ModelParticle p;
    p.centre = glm::vec3(0.0f, height, 0.0f);
    p.horizontalRadius = 200.0f;
    p.verticalRadius = verticalRadius;
    p.density = 1.0f;
    return p;
}

TEST(SunColumnTwin, TheDeckEndsAtTheFirstLongGapOfClearAirAndABridgeJoinsWhatLiesPastIt) {
    ASSERT_EQ(kDeckGapShare, 0.25) << "the gaps below are set for a 50 m bridge";
    const glm::dvec3 up(0.0, 1.0, 0.0);
    // The particle (its chord [0, 100] either way), one overlapping it above ([50, 250]), one past
    // a gap above ([500, 700]) and one past a gap below ([200, 400] away from the sun).
    std::vector<ModelParticle> particles{stacked(3000.0f, 100.0f), stacked(3150.0f, 100.0f), stacked(3600.0f, 100.0f), stacked(2700.0f, 100.0f)};
    const double touching = opticalDepthThrough(particles[1], glm::dvec3(particles[0].centre), up, kEarthRadius, kMethod);
    const double past = opticalDepthThrough(particles[2], glm::dvec3(particles[0].centre), up, kEarthRadius, kMethod);
    const double below = opticalDepthThrough(particles[3], glm::dvec3(particles[0].centre), -up, kEarthRadius, kMethod);
    ASSERT_GT(touching, 1.0);
    ASSERT_GT(past, 1.0);
    ASSERT_GT(below, 1.0);
    const Chord chord = chordThrough(particles[2], glm::dvec3(particles[0].centre), up, kEarthRadius, kMethod);
    EXPECT_NEAR(chord.start, 500.0, 0.5);
    EXPECT_NEAR(chord.end, 700.0, 0.5);

    SunColumn column = sunColumn(particles, 0, up, kEarthRadius, kMethod, 0.0);
    EXPECT_NEAR(column.above, touching + past, 1e-9);
    EXPECT_NEAR(column.deckAbove, touching, 1e-9);
    EXPECT_NEAR(column.beyond, below, 1e-9);
    EXPECT_EQ(column.deckBeyond, 0.0);

    // A tall particle listed last that spans the gap ([150, 550]) joins what lies past it.
    particles.push_back(stacked(3350.0f, 200.0f));
    const double bridge = opticalDepthThrough(particles[4], glm::dvec3(particles[0].centre), up, kEarthRadius, kMethod);
    std::reverse(particles.begin() + 1, particles.end());
    column = sunColumn(particles, 0, up, kEarthRadius, kMethod, 0.0);
    EXPECT_NEAR(column.above, touching + past + bridge, 1e-9);
    EXPECT_NEAR(column.deckAbove, touching + past + bridge, 1e-9);
    EXPECT_EQ(column.deckBeyond, 0.0);

    // Below, one 40 m past the particle's own chord ([140, 180]): within the 50 m bridged, and the
    // one past the gap below is now 20 m past it.
    particles.push_back(stacked(2840.0f, 20.0f));
    const double justBelow = opticalDepthThrough(particles.back(), glm::dvec3(particles[0].centre), -up, kEarthRadius, kMethod);
    ASSERT_GT(justBelow, 0.1);
    column = sunColumn(particles, 0, up, kEarthRadius, kMethod, 0.0);
    EXPECT_NEAR(column.beyond, below + justBelow, 1e-9);
    EXPECT_NEAR(column.deckBeyond, below + justBelow, 1e-9);
}

}  // namespace
}  // namespace firmament
