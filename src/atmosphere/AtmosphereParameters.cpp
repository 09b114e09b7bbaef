#include "atmosphere/AtmosphereParameters.h"

#include <cstdio>

namespace firmament {

LutDimensions LutDimensions::of(LutResolution resolution) {
    switch (resolution) {
        case LutResolution::Small: return {8, 32, 16, 8, 128, 128, 64};
        case LutResolution::Medium: return {16, 64, 32, 8, 512, 512, 256};
        case LutResolution::Full: return {32, 128, 64, 16, 1024, 1024, 1024};
    }
    return {};
}

AtmosphereParameters AtmosphereParameters::from(const AtmosphereSettings& s) {
    AtmosphereParameters p;
    const glm::dvec3 mieColour = s.customCoefficients ? glm::dvec3(s.mieColour) : glm::dvec3(1.0);
    if (s.customCoefficients) p.rayleighScattering = glm::dvec3(s.rayleighColour) * kRayleighColourScale;
    p.mieScattering = mieColour * kMieColourScale * static_cast<double>(s.aerosolDensity);
    p.mieExtinction = p.mieScattering * (1.0 + static_cast<double>(s.aerosolAbsorption));
    p.mieAsymmetry = s.mieAsymmetry;
    p.ozoneAbsorption = s.ozone ? kOzoneAbsorptionAtPeak : glm::dvec3(0.0);
    p.scatteringOrders = s.scatteringOrders;
    p.lut = LutDimensions::of(s.resolution);
    return p;
}

gpu::AtmosphereConstants AtmosphereParameters::constants() const {
    gpu::AtmosphereConstants c{};
    c.earth = glm::vec4(static_cast<float>(earthRadius), static_cast<float>(atmosphereHeight), static_cast<float>(topRadius()), 0.0f);
    c.scaleHeights = glm::vec4(static_cast<float>(rayleighScaleHeight), static_cast<float>(mieScaleHeight), 0.0f, 0.0f);
    c.rayleighScattering = glm::vec4(glm::vec3(rayleighScattering), 0.0f);
    c.mieScattering = glm::vec4(glm::vec3(mieScattering), static_cast<float>(mieAsymmetry));
    c.mieExtinction = glm::vec4(glm::vec3(mieExtinction), 0.0f);
    c.ozone = glm::vec4(glm::vec3(ozoneAbsorption), 0.0f);
    c.ozoneLayer = glm::vec4(static_cast<float>(ozoneCentre), static_cast<float>(ozoneHalfWidth), 0.0f, 0.0f);
    c.scatteringLutSize = glm::vec4(lut.height, lut.viewZenith, lut.sunZenith, lut.sunView);
    c.netDensityLutSize = glm::vec4(lut.netDensityHeight, lut.netDensityZenith, lut.ambientLight, sphereSamples);
    return c;
}

ExrAttributes AtmosphereParameters::exrAttributes() const {
    return {
        {"firmament.atmosphere.parameters", describe()},
        {"firmament.atmosphere.earthRadius", static_cast<float>(earthRadius)},
        {"firmament.atmosphere.atmosphereHeight", static_cast<float>(atmosphereHeight)},
        {"firmament.atmosphere.scaleHeights", glm::vec3(static_cast<float>(rayleighScaleHeight), static_cast<float>(mieScaleHeight), 0.0f)},
        {"firmament.atmosphere.rayleighScattering", glm::vec3(rayleighScattering)},
        {"firmament.atmosphere.mieScattering", glm::vec3(mieScattering)},
        {"firmament.atmosphere.mieExtinction", glm::vec3(mieExtinction)},
        {"firmament.atmosphere.mieAsymmetry", static_cast<float>(mieAsymmetry)},
        {"firmament.atmosphere.ozoneAbsorption", glm::vec3(ozoneAbsorption)},
    };
}

std::string AtmosphereParameters::describe() const {
    char text[1024];
    std::snprintf(text, sizeof(text),
                  "earthRadius=%.17g atmosphereHeight=%.17g rayleighScaleHeight=%.17g mieScaleHeight=%.17g "
                  "rayleighScattering=%.17g,%.17g,%.17g mieScattering=%.17g,%.17g,%.17g mieExtinction=%.17g,%.17g,%.17g "
                  "mieAsymmetry=%.17g ozoneAbsorption=%.17g,%.17g,%.17g ozoneCentre=%.17g ozoneHalfWidth=%.17g "
                  "lut=%dx%dx%dx%d netDensity=%dx%d ambient=%d orders=%d sphereSamples=%d",
                  earthRadius, atmosphereHeight, rayleighScaleHeight, mieScaleHeight, rayleighScattering.r, rayleighScattering.g,
                  rayleighScattering.b, mieScattering.r, mieScattering.g, mieScattering.b, mieExtinction.r, mieExtinction.g,
                  mieExtinction.b, mieAsymmetry, ozoneAbsorption.r, ozoneAbsorption.g, ozoneAbsorption.b, ozoneCentre,
                  ozoneHalfWidth, lut.height, lut.viewZenith, lut.sunZenith, lut.sunView, lut.netDensityHeight, lut.netDensityZenith,
                  lut.ambientLight, scatteringOrders, sphereSamples);
    return text;
}

}  // namespace firmament
