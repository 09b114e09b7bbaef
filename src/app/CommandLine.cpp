#include "app/CommandLine.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace firmament {

namespace {

constexpr int kMaxFrames = 10'000'000;

std::optional<long long> parseInteger(const std::string& text) {
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace

namespace {
std::filesystem::path captureNamed(const std::filesystem::path& capture, const std::string& name, const char* extension) {
    std::filesystem::path path = capture;
    if (!name.empty()) path.replace_filename(capture.stem().string() + "-" + name);
    return path.replace_extension(extension);
}
}  // namespace

std::filesystem::path Options::capturePng(const std::string& name) const {
    return captureNamed(capture.value_or("firmament.png"), name, ".png");
}

std::filesystem::path Options::captureExr(const std::string& name) const {
    return captureNamed(capture.value_or("firmament.png"), name, ".exr");
}

ParsedCommandLine parseCommandLine(const std::vector<std::string>& arguments) {
    ParsedCommandLine result;
    Options& o = result.options;
    bool hardwareRequested = false, warpRequested = false;

    for (size_t i = 0; i < arguments.size(); ++i) {
        std::string flag = arguments[i];
        std::optional<std::string> inlineValue;
        if (const auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
            inlineValue = flag.substr(eq + 1);
            flag = flag.substr(0, eq);
        }
        auto value = [&]() -> std::optional<std::string> {
            if (inlineValue) return inlineValue;
            if (i + 1 < arguments.size()) return arguments[++i];
            result.error = flag + " needs a value";
            return std::nullopt;
        };
        auto noValue = [&]() {
            if (inlineValue) result.error = flag + " takes no value";
            return !inlineValue;
        };
        // The flag's value as a frame from 1 to kMaxFrames; else the error, naming it as `what`.
        auto frameValue = [&](const char* what) -> std::optional<int> {
            const auto v = value();
            if (!v) return std::nullopt;
            const auto n = parseInteger(*v);
            if (!n || *n < 1 || *n > kMaxFrames) {
                result.error = flag + ": '" + *v + "' is not a " + what + " from 1 to " + std::to_string(kMaxFrames);
                return std::nullopt;
            }
            return static_cast<int>(*n);
        };

        if (flag == "--help" || flag == "-h" || flag == "/?") {
            if (!noValue()) return result;
            o.help = true;
        } else if (flag == "--version") {
            if (!noValue()) return result;
            o.version = true;
        } else if (flag == "--headless") {
            if (!noValue()) return result;
            o.headless = true;
        } else if (flag == "--warp") {
            if (!noValue()) return result;
            warpRequested = true;
        } else if (flag == "--hardware") {
            if (!noValue()) return result;
            hardwareRequested = true;
        } else if (flag == "--adapter") {
            const auto v = value();
            if (!v) return result;
            const auto n = parseInteger(*v);
            if (!n || *n < 0 || *n > 64) {
                result.error = "--adapter: '" + *v + "' is not an adapter index (0, 1, ...)";
                return result;
            }
            o.adapter = static_cast<unsigned>(*n);
        } else if (flag == "--frames") {
            if (!(o.frames = frameValue("frame count"))) return result;
        } else if (flag == "--time-step") {
            const auto v = value();
            if (!v) return result;
            double seconds = -1.0;
            const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), seconds);
            if (ec != std::errc() || end != v->data() + v->size() || !(seconds >= 0.0 && seconds <= 1.0)) {
                result.error = "--time-step: '" + *v + "' is not a number of seconds from 0 to 1";
                return result;
            }
            o.timeStep = seconds;
        } else if (flag == "--simulate-device-loss") {
            if (!(o.simulateDeviceLoss = frameValue("frame number"))) return result;
        } else if (flag == "--resolution") {
            const auto v = value();
            if (!v) return result;
            const auto x = lowercase(*v).find('x');
            const auto w = x == std::string::npos ? std::nullopt : parseInteger(v->substr(0, x));
            const auto h = x == std::string::npos ? std::nullopt : parseInteger(v->substr(x + 1));
            if (!w || !h) {
                result.error = "--resolution: '" + *v + "' is not WIDTHxHEIGHT (for example 1280x720)";
                return result;
            }
            if (*w < kMinFrameSide || *h < kMinFrameSide || *w > kMaxFrameSide || *h > kMaxFrameSide) {
                result.error = "--resolution: " + *v + " is out of range (each side " + std::to_string(kMinFrameSide) +
                               " to " + std::to_string(kMaxFrameSide) + ")";
                return result;
            }
            o.width = static_cast<int>(*w);
            o.height = static_cast<int>(*h);
        } else if (flag == "--vsync") {
            const auto v = value();
            if (!v) return result;
            const auto s = lowercase(*v);
            if (s != "on" && s != "off") {
                result.error = "--vsync: '" + *v + "' is not 'on' or 'off'";
                return result;
            }
            o.vsync = s == "on";
        } else if (flag == "--capture") {
            const auto v = value();
            if (!v) return result;
            const std::filesystem::path path(*v);
            const auto ext = lowercase(path.extension().string());
            if (v->empty() || (ext != ".png" && ext != ".exr")) {
                result.error = "--capture: '" + *v + "' must end in .png or .exr (both files are written)";
                return result;
            }
            o.capture = path;
        } else if (flag == "--capture-ui") {
            if (!noValue()) return result;
            o.captureUi = true;
        } else if (flag == "--shader-compiler") {
            const auto v = value();
            if (!v) return result;
            if (*v != "auto" && *v != "d3dcompile" && *v != "vkd3d" && *v != "fxc" && *v != "none") {
                result.error = "--shader-compiler: '" + *v + "' is not one of auto, d3dcompile, vkd3d, fxc, none";
                return result;
            }
            o.shaderCompiler = *v;
        } else if (flag == "--no-cache") {
            if (!noValue()) return result;
            o.noCache = true;
        } else if (flag == "--shader-source" || flag == "--settings" || flag == "--state-file" || flag == "--flight" ||
                   flag == "--record-flight" || flag == "--export-luts" || flag == "--cache-dir" || flag == "--benchmark" ||
                   flag == "--benchmark-output" || flag == "--generate-cloud-scattering" || flag == "--soak" || flag == "--soak-report" ||
                   flag == "--batch") {
            const auto v = value();
            if (!v) return result;
            if (v->empty()) {
                result.error = flag + ": the path is empty";
                return result;
            }
            if (flag == "--shader-source") o.shaderSource = std::filesystem::path(*v);
            else if (flag == "--settings") o.settingsFile = std::filesystem::path(*v);
            else if (flag == "--flight") o.flight = std::filesystem::path(*v);
            else if (flag == "--record-flight") o.recordFlight = std::filesystem::path(*v);
            else if (flag == "--export-luts") o.exportLuts = std::filesystem::path(*v);
            else if (flag == "--cache-dir") o.cacheDir = std::filesystem::path(*v);
            else if (flag == "--benchmark") o.benchmark = std::filesystem::path(*v);
            else if (flag == "--benchmark-output") o.benchmarkOutput = std::filesystem::path(*v);
            else if (flag == "--generate-cloud-scattering") o.generateCloudScattering = std::filesystem::path(*v);
            else if (flag == "--soak") o.soak = std::filesystem::path(*v);
            else if (flag == "--soak-report") o.soakReport = std::filesystem::path(*v);
            else if (flag == "--batch") o.batch = std::filesystem::path(*v);
            else o.stateFile = std::filesystem::path(*v);
        } else if (flag == "--set") {
            const auto v = value();
            if (!v) return result;
            const auto eq = v->find('='), dot = v->find('.');
            if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || eq == dot + 1) {
                result.error = "--set: '" + *v + "' is not section.key=value (for example camera.fieldOfView=60)";
                return result;
            }
            o.assignments.push_back(*v);
        } else if (flag == "--shader-dir") {
            const auto v = value();
            if (!v) return result;
            if (v->empty()) {
                result.error = "--shader-dir: the folder name is empty";
                return result;
            }
            o.shaderDir = std::filesystem::path(*v);
        } else {
            result.error = "unknown option '" + arguments[i] + "'";
            return result;
        }
    }

    if (o.benchmark) {
        if (o.flight || o.recordFlight || o.capture || o.frames) {
            result.error = "--benchmark takes its views and frame counts from its scenario file: leave out --flight, --record-flight, "
                           "--capture and --frames";
            return result;
        }
        o.headless = true;  // a benchmark runs unattended
    } else if (o.benchmarkOutput) {
        result.error = "--benchmark-output needs --benchmark";
        return result;
    }
    if (o.batch) {
        if (o.benchmark || o.soak || o.flight || o.recordFlight) {
            result.error = "--batch renders its views each from a fresh start: leave out --benchmark, --soak, --flight and --record-flight";
            return result;
        }
        if (*o.batch != "-" && !o.capture) {
            result.error = "--batch " + o.batch->string() + " writes each view to --capture's PATH-name.png: give --capture PATH.png";
            return result;
        }
        if (*o.batch == "-" && o.capture) {
            result.error = "--batch - takes each capture's path from its request: leave out --capture";
            return result;
        }
        o.headless = true;  // a batch runs unattended
    }
    if (o.soak && o.benchmark) {
        result.error = "--soak and --benchmark exclude each other";
        return result;
    }
    if (o.soakReport && !o.soak) {
        result.error = "--soak-report needs --soak";
        return result;
    }
    if (hardwareRequested && warpRequested) {
        result.error = "--warp and --hardware exclude each other";
        return result;
    }
    const bool warp = warpRequested || (o.headless && !hardwareRequested && !o.adapter);
    o.driver = warp ? DriverType::Warp : DriverType::Hardware;
    if (warp && o.adapter) {
        result.error = "--warp and --adapter exclude each other";
        return result;
    }
    return result;
}

std::string usageText() {
    return R"(Usage: firmament [options]

Real-time outdoor renderer (Direct3D 11).

Device
  --warp                 use the WARP software rasterizer
  --hardware             use the default hardware adapter (also when headless)
  --adapter N            use DXGI adapter N
  --simulate-device-loss N
                         after frame N, act as if Present had returned
                         DXGI_ERROR_DEVICE_REMOVED: every GPU resource is made
                         again; settings and camera are kept (a test of the path)
Running
  --time-step SECONDS    each frame advances the clock by exactly this (headless
                         default 1/60; a headless --flight is flown at this step);
                         0 holds the clouds and the sun still
  --headless             no visible window; WARP unless --hardware or --adapter;
                         renders --frames frames (default 30), prints GPU times
  --frames N             stop after N frames
  --resolution WxH       frame size (default 1280x720; 16 to 16384 a side)
  --vsync on|off         wait for vertical blank when presenting (default on)
  --capture PATH         after the last frame write PATH.png (display) and
                         PATH.exr (HDR, half float, with the settings in its header)
  --capture-ui           include the GUI in the capture (left out by default)
                         (F12 captures PATH-shot-N.png and .exr, or without
                         --capture firmament-shot-N.png in the working folder)
Settings
  --settings FILE        load settings, camera and sun from a JSON state file
  --set SECTION.KEY=VAL  change one setting (repeatable, after --settings);
                         for example --set camera.fieldOfView=60
  --state-file FILE      where F5 saves and F9 loads the state
                         (default firmament-state.json in the working folder)
  --flight FILE          play a recorded camera flight (JSON keyframes); headless
                         runs render its whole length unless --frames is given
  --record-flight FILE   write the camera and sun, ten keyframes a second, on exit
  --batch FILE           headless: capture each view of FILE (views.json's form:
                         name, settings, set, resolution, frames, captureUi) from a fresh
                         start into --capture's PATH-name.png and .exr
  --batch -              the same for views read one a line (JSON, with "capture")
                         from standard input, each answered "batch: done ID"
Benchmark
  --benchmark FILE       run the scenario file's views x variants x resolutions
                         headless, print a table of GPU times per pass and write
                         them as JSON (docs/performance.md)
  --benchmark-output F   where the JSON goes (default benchmark-results.json)
Soak (docs/reliability.md)
  --soak FILE            apply the schedule file's settings changes in a loop, play
                         --flight in a loop, sample the live Direct3D objects, handles
                         and private memory at the end of every loop, and fail (exit 1)
                         on growth after the warm-up beyond the file's bounds;
                         --frames defaults to 10000
  --soak-report FILE     where the samples and verdict go (default soak-report.json)
Atmosphere
  --export-luts DIR      write every look-up table as a self-describing EXR into DIR
                         once computed (or loaded)
  --cache-dir DIR        where computed tables are kept and reused
                         (default: %LOCALAPPDATA%\Firmament\cache)
  --no-cache             compute the tables every run; read and write no cache
Clouds
  --generate-cloud-scattering FILE
                         compute the cloud particle's scattering table on the CPU
                         (about a minute) into FILE and exit; the program reads
                         media/clouds/particle-scattering.exr (tools/generate-cloud-scattering)
Shaders
  --shader-dir DIR       compiled shaders (default: 'shaders' beside the program)
  --shader-source DIR    HLSL folder that F8 and file changes reload from
                         (default: the folder the build compiled)
  --shader-compiler NAME hot-reload compiler: auto, d3dcompile, vkd3d, fxc, none
                         (auto: vkd3d-compiler under Wine, else D3DCompile)
  --version              print the version
  --help                 print this text
Exit codes: 0 success, 1 runtime error, 2 bad command line or settings.
)";
}

}  // namespace firmament
