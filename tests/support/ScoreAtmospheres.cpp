// firmament_score_atmospheres PLAN.json SCORES.json: the atmosphere models' captures scored
// against the reference atmosphere (tools/score-atmospheres; docs/atmosphere.md, "Scores").
// PLAN lists, for each point of the grid (altitude, sun elevation, aerosol density), each model's
// capture of a wide view and of a narrow view 1 degree from the zenith (the nadir from above
// the atmosphere), and the sampling: "paths" per reference pixel (a point's own "paths" where
// it has them), a grid of "columns" x "rows" pixels, "sunMarginDegrees" left out about the sun;
// each point's "sunIntensity", the captures' sun irradiance, is divided out. Inside the atmosphere only views of the sky are scored (those
// that meet the black ground say little of a sky model). The reference (support/SkyScore.h) is
// computed once per pixel for all the models, on every hardware thread, its paths drawn toward the
// sunlit air (ReferenceAtmosphere::PathSampling::TowardSunlight), and with kZenithTwilightPaths
// times the paths at the zenith when the sun is below the horizon. SCORES gets, per point,
// the reference's luminance noise and each model's HDR PSNR, median and 95th-percentile relative
// error of the luminance, and zenith luminance beside the reference's.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/AtmosphereSettings.h"
#include "core/ExrImage.h"
#include "core/FileIO.h"
#include "support/SkyScore.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace firmament;
using Estimate = atmosphere::ReferenceAtmosphere::Estimate;

constexpr int kZenithTwilightPaths = 32;

struct Point {
    std::string name;
    double altitude = 0.0, sunElevation = 0.0, aerosolDensity = 1.0, sunIntensity = 1.0;
    int paths = 0;  // the reference's paths a pixel
    std::map<std::string, FloatExrFile> wide, zenith;
    std::vector<test::PixelRay> rays;  // the wide view's, then the zenith view's centre last
    std::vector<Estimate> reference;
};

double finiteOr999(double db) { return std::isfinite(db) ? db : 999.0; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: firmament_score_atmospheres PLAN.json SCORES.json\n");
        return 2;
    }
    try {
        std::ifstream planFile(argv[1]);
        if (!planFile) throw std::runtime_error(std::string("cannot read ") + argv[1]);
        const nlohmann::json plan = nlohmann::json::parse(planFile);
        const int paths = plan.at("paths"), columns = plan.at("columns"), rows = plan.at("rows");
        const double sunMargin = static_cast<double>(plan.at("sunMarginDegrees")) * 3.14159265358979323846 / 180.0;
        std::vector<Point> points;
        for (const auto& p : plan.at("points")) {
            Point point;
            point.name = p.at("name");
            point.altitude = p.at("altitude");
            point.sunElevation = p.at("sunElevation");
            point.aerosolDensity = p.at("aerosolDensity");
            point.sunIntensity = p.at("sunIntensity");
            point.paths = p.value("paths", paths);
            for (const auto& [model, path] : p.at("wide").items()) point.wide[model] = readFloatExr(path.get<std::string>());
            for (const auto& [model, path] : p.at("zenith").items()) point.zenith[model] = readFloatExr(path.get<std::string>());
            const FloatExrFile& first = point.wide.begin()->second;
            point.rays = test::sampledRays(first, columns, rows, sunMargin);
            AtmosphereSettings settings;
            settings.aerosolDensity = static_cast<float>(point.aerosolDensity);
            const atmosphere::ReferenceAtmosphere reference(AtmosphereParameters::from(settings));
            const glm::dvec3 camera(0.0, reference.parameters().earthRadius + point.altitude, 0.0);
            if (point.altitude < reference.parameters().atmosphereHeight)
                std::erase_if(point.rays, [&](const test::PixelRay& r) { return reference.hitsGround(camera, r.direction); });
            const FloatExrFile& zenith = point.zenith.begin()->second;
            const std::vector<test::PixelRay> centre = test::sampledRays(zenith, 1, 1, 0.0);
            if (centre.size() != 1) throw std::runtime_error(point.name + ": the zenith view's centre is the sun");
            point.rays.push_back(centre[0]);
            points.push_back(std::move(point));
        }
        // Every pixel's reference, on every hardware thread.
        struct Job {
            size_t point, ray;
        };
        std::vector<Job> jobs;
        for (size_t i = 0; i < points.size(); ++i) {
            points[i].reference.resize(points[i].rays.size());
            for (size_t r = 0; r < points[i].rays.size(); ++r) jobs.push_back({i, r});
        }
        std::atomic<size_t> next{0}, done{0};
        const auto work = [&] {
            for (size_t j = next++; j < jobs.size(); j = next++) {
                Point& point = points[jobs[j].point];
                AtmosphereSettings settings;
                settings.aerosolDensity = static_cast<float>(point.aerosolDensity);
                const atmosphere::ReferenceAtmosphere reference(AtmosphereParameters::from(settings));
                const glm::dvec3 start(0.0, reference.parameters().earthRadius + point.altitude, 0.0);
                const FloatExrFile& capture = point.wide.begin()->second;
                // The zenith's light in twilight comes from air the sun lights hundreds of
                // kilometres off: kZenithTwilightPaths times the paths there.
                const bool twilightZenith = jobs[j].ray + 1 == point.rays.size() && point.sunElevation < 0.0;
                point.reference[jobs[j].ray] =
                    test::referenceRadiance(reference, start, point.rays[jobs[j].ray].direction, test::directionToSun(capture),
                                            twilightZenith ? point.paths * kZenithTwilightPaths : point.paths, 1000u + static_cast<unsigned>(j),
                                            atmosphere::ReferenceAtmosphere::PathSampling::TowardSunlight);
                if (++done % 200 == 0) std::fprintf(stderr, "reference: %zu of %zu pixels\n", done.load(), jobs.size());
            }
        };
        std::vector<std::thread> threads;
        for (unsigned t = 0; t < std::max(1u, std::thread::hardware_concurrency()); ++t) threads.emplace_back(work);
        for (std::thread& t : threads) t.join();

        nlohmann::json out = nlohmann::json::array();
        for (const Point& point : points) {
            const size_t wideRays = point.rays.size() - 1;
            std::vector<glm::dvec3> reference;
            std::vector<double> noise;
            for (size_t r = 0; r < wideRays; ++r) {
                reference.push_back(point.reference[r].mean);
                const double y = test::luminance(point.reference[r].mean);
                if (y > 0.0) noise.push_back(test::luminance(point.reference[r].standardError) / y);
            }
            std::sort(noise.begin(), noise.end());
            nlohmann::json models = nlohmann::json::object();
            for (const auto& [model, capture] : point.wide) {
                std::vector<glm::dvec3> radiance;
                for (size_t r = 0; r < wideRays; ++r)
                    radiance.push_back(test::capturedRadiance(capture, point.rays[r].x, point.rays[r].y) / point.sunIntensity);
                const test::SkyScore s = test::scoreSky(radiance, reference);
                const FloatExrFile& zenith = point.zenith.at(model);
                const test::PixelRay& centre = point.rays.back();
                models[model] = {{"hdrPsnrDb", finiteOr999(s.hdrPsnrDb)},
                                 {"medianRelativeError", s.medianRelativeError},
                                 {"p95RelativeError", s.p95RelativeError},
                                 {"pixels", s.pixels},
                                 {"zenithLuminance", test::luminance(test::capturedRadiance(zenith, centre.x, centre.y)) / point.sunIntensity}};
            }
            const Estimate& zenith = point.reference.back();
            out.push_back({{"name", point.name},
                           {"altitude", point.altitude},
                           {"sunElevation", point.sunElevation},
                           {"aerosolDensity", point.aerosolDensity},
                           {"sunIntensity", point.sunIntensity},
                           {"referencePixels", wideRays},
                           {"referencePaths", point.paths},
                           {"referenceMedianNoise", noise.empty() ? 0.0 : noise[noise.size() / 2]},
                           {"referenceZenithLuminance", test::luminance(zenith.mean)},
                           {"referenceZenithNoise", test::luminance(zenith.standardError)},
                           {"models", models}});
        }
        const std::string text = out.dump(1) + "\n";
        writeFileBytes(argv[2], std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "firmament_score_atmospheres: %s\n", e.what());
        return 1;
    }
}
