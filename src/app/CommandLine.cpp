#include "app/CommandLine.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

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

namespace {

// What the options set besides Options: the device the user asked for, resolved once every
// option is read (headless runs take WARP unless --hardware or --adapter).
struct Parsing {
    Options& options;
    bool hardware = false;
    bool warp = false;
};

// Reads one option's value (empty for a flag) into the parse; returns "" or the problem, which
// the parser prefixes with the option as typed ("--frames: ...").
using Apply = std::string (*)(Parsing&, const std::string& value);

// One row of the table that drives both the parser and the usage text.
struct OptionRow {
    std::string_view group;    // the usage text's heading
    std::string_view name;     // "--frames"
    std::string_view value;    // the value's placeholder in the usage text; empty: a flag
    std::string_view example;  // a valid value (the tests pass it); empty for a flag
    std::string_view help;     // the usage text's lines, separated by '\n'
    Apply apply;
    std::string_view alias = {}, otherAlias = {};  // other spellings ("-h", "/?")
};

template <auto Member>
std::string setFlag(Parsing& p, const std::string&) {
    p.options.*Member = true;
    return {};
}

template <auto Member>
std::string setPath(Parsing& p, const std::string& value) {
    if (value.empty()) return "the path is empty";
    p.options.*Member = std::filesystem::path(value);
    return {};
}

// A frame from 1 to kMaxFrames, named `what` in the message.
std::optional<int> frameNumber(const std::string& value, std::string& error, const char* what) {
    const auto n = parseInteger(value);
    if (!n || *n < 1 || *n > kMaxFrames) {
        error = "'" + value + "' is not a " + what + " from 1 to " + std::to_string(kMaxFrames);
        return std::nullopt;
    }
    return static_cast<int>(*n);
}

std::string setFrames(Parsing& p, const std::string& value) {
    std::string error;
    p.options.frames = frameNumber(value, error, "frame count");
    return error;
}

std::string setDeviceLoss(Parsing& p, const std::string& value) {
    std::string error;
    p.options.simulateDeviceLoss = frameNumber(value, error, "frame number");
    return error;
}

std::string setAdapter(Parsing& p, const std::string& value) {
    const auto n = parseInteger(value);
    if (!n || *n < 0 || *n > 64) return "'" + value + "' is not an adapter index (0, 1, ...)";
    p.options.adapter = static_cast<unsigned>(*n);
    return {};
}

std::string setTimeStep(Parsing& p, const std::string& value) {
    double seconds = -1.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), seconds);
    if (ec != std::errc() || end != value.data() + value.size() || !(seconds >= 0.0 && seconds <= 1.0))
        return "'" + value + "' is not a number of seconds from 0 to 1";
    p.options.timeStep = seconds;
    return {};
}

std::string setResolution(Parsing& p, const std::string& value) {
    const auto x = lowercase(value).find('x');
    const auto w = x == std::string::npos ? std::nullopt : parseInteger(value.substr(0, x));
    const auto h = x == std::string::npos ? std::nullopt : parseInteger(value.substr(x + 1));
    if (!w || !h) return "'" + value + "' is not WIDTHxHEIGHT (for example 1280x720)";
    if (*w < kMinFrameSide || *h < kMinFrameSide || *w > kMaxFrameSide || *h > kMaxFrameSide)
        return value + " is out of range (each side " + std::to_string(kMinFrameSide) + " to " + std::to_string(kMaxFrameSide) + ")";
    p.options.width = static_cast<int>(*w);
    p.options.height = static_cast<int>(*h);
    return {};
}

std::string setVsync(Parsing& p, const std::string& value) {
    const auto s = lowercase(value);
    if (s != "on" && s != "off") return "'" + value + "' is not 'on' or 'off'";
    p.options.vsync = s == "on";
    return {};
}

std::string setCapture(Parsing& p, const std::string& value) {
    const std::filesystem::path path(value);
    const auto extension = lowercase(path.extension().string());
    if (value.empty() || (extension != ".png" && extension != ".exr")) return "'" + value + "' must end in .png or .exr (both files are written)";
    p.options.capture = path;
    return {};
}

std::string setShaderCompiler(Parsing& p, const std::string& value) {
    if (value != "auto" && value != "d3dcompile" && value != "vkd3d" && value != "fxc" && value != "none")
        return "'" + value + "' is not one of auto, d3dcompile, vkd3d, fxc, none";
    p.options.shaderCompiler = value;
    return {};
}

std::string addAssignment(Parsing& p, const std::string& value) {
    const auto eq = value.find('='), dot = value.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || eq == dot + 1)
        return "'" + value + "' is not section.key=value (for example camera.fieldOfView=60)";
    p.options.assignments.push_back(value);
    return {};
}

std::string requestWarp(Parsing& p, const std::string&) {
    p.warp = true;
    return {};
}

std::string requestHardware(Parsing& p, const std::string&) {
    p.hardware = true;
    return {};
}

// Every option, in the usage text's order.
constexpr OptionRow kOptions[] = {
    {"Device", "--warp", "", "", "use the WARP software rasterizer", requestWarp},
    {"Device", "--hardware", "", "", "use the default hardware adapter (also when headless)", requestHardware},
    {"Device", "--adapter", "N", "1", "use DXGI adapter N", setAdapter},
    {"Device", "--simulate-device-loss", "N", "12",
     "after frame N, act as if Present had returned\n"
     "DXGI_ERROR_DEVICE_REMOVED: every GPU resource is made\n"
     "again; settings and camera are kept (a test of the path)",
     setDeviceLoss},
    {"Running", "--time-step", "SECONDS", "0.5",
     "each frame advances the clock by exactly this (headless\n"
     "default 1/60; a headless --flight is flown at this step);\n"
     "0 holds the clouds and the sun still",
     setTimeStep},
    {"Running", "--headless", "", "",
     "no visible window; WARP unless --hardware or --adapter;\n"
     "renders --frames frames (default 30), prints GPU times",
     setFlag<&Options::headless>},
    {"Running", "--frames", "N", "12", "stop after N frames", setFrames},
    {"Running", "--resolution", "WxH", "320x180", "frame size (default 1280x720; 16 to 16384 a side)", setResolution},
    {"Running", "--vsync", "on|off", "off", "wait for vertical blank when presenting (default on)", setVsync},
    {"Running", "--capture", "PATH", "shot.png",
     "after the last frame write PATH.png (display) and\n"
     "PATH.exr (HDR, half float unless --hdr-float32, with the\n"
     "settings in its header);\n"
     "F12 captures PATH-shot-N.png and .exr (without --capture,\n"
     "firmament-shot-N.png in the working folder)",
     setCapture},
    {"Running", "--capture-ui", "", "", "include the GUI in the capture (left out by default)", setFlag<&Options::captureUi>},
    {"Running", "--hdr-float32", "", "",
     "draw the HDR frame in 32-bit floats and write 32-bit EXRs,\n"
     "for measurement (half floats end at 6e-8: deep twilight)",
     setFlag<&Options::hdrFloat32>},
    {"Settings", "--settings", "FILE", "state.json", "load settings, camera and sun from a JSON state file", setPath<&Options::settingsFile>},
    {"Settings", "--set", "SECTION.KEY=VAL", "camera.fieldOfView=60",
     "change one setting (repeatable, after --settings);\n"
     "for example --set camera.fieldOfView=60",
     addAssignment},
    {"Settings", "--state-file", "FILE", "state.json",
     "where F5 saves and F9 loads the state\n"
     "(default firmament-state.json in the working folder)",
     setPath<&Options::stateFile>},
    {"Settings", "--flight", "FILE", "flight.json",
     "play a recorded camera flight (JSON keyframes); headless\n"
     "runs render its whole length unless --frames is given",
     setPath<&Options::flight>},
    {"Settings", "--record-flight", "FILE", "flight.json", "write the camera and sun, ten keyframes a second, on exit",
     setPath<&Options::recordFlight>},
    {"Settings", "--batch", "FILE|-", "views.json",
     "headless: capture each view of FILE (views.json's form:\n"
     "name, settings, set, resolution, frames, captureUi) from a fresh\n"
     "start into --capture's PATH-name.png and .exr; with -, the\n"
     "views are read one a line (JSON, with \"capture\") from standard\n"
     "input, each answered \"batch: done ID\"",
     setPath<&Options::batch>},
    {"Benchmark", "--benchmark", "FILE", "scenarios.json",
     "run the scenario file's views x variants x resolutions\n"
     "headless, print a table of GPU times per pass and write\n"
     "them as JSON (docs/performance.md)",
     setPath<&Options::benchmark>},
    {"Benchmark", "--benchmark-output", "F", "results.json", "where the JSON goes (default benchmark-results.json)",
     setPath<&Options::benchmarkOutput>},
    {"Soak (docs/reliability.md)", "--soak", "FILE", "schedule.json",
     "apply the schedule file's settings changes in a loop, play\n"
     "--flight in a loop, sample the live Direct3D objects, handles\n"
     "and private memory at the end of every loop, and fail (exit 1)\n"
     "on growth after the warm-up beyond the file's bounds;\n"
     "--frames defaults to 10000",
     setPath<&Options::soak>},
    {"Soak (docs/reliability.md)", "--soak-report", "FILE", "soak.json", "where the samples and verdict go (default soak-report.json)",
     setPath<&Options::soakReport>},
    {"Atmosphere", "--export-luts", "DIR", "tables",
     "write every look-up table as a self-describing EXR into DIR\n"
     "once computed (or loaded)",
     setPath<&Options::exportLuts>},
    {"Atmosphere", "--cache-dir", "DIR", "cache",
     "where computed tables are kept and reused\n"
     "(default: %LOCALAPPDATA%\\Firmament\\cache)",
     setPath<&Options::cacheDir>},
    {"Atmosphere", "--no-cache", "", "", "compute the tables every run; read and write no cache", setFlag<&Options::noCache>},
    {"Clouds", "--generate-cloud-scattering", "FILE", "table.exr",
     "compute the cloud particle's scattering table on the CPU\n"
     "(about a minute) into FILE and exit; the program reads\n"
     "media/clouds/particle-scattering.exr (tools/generate-cloud-scattering)",
     setPath<&Options::generateCloudScattering>},
    {"Clouds", "--generate-deck-diffusion", "FILE", "table.exr",
     "compute deck diffusion's table (the light scattered more than\n"
     "once in a slab of cloud) on the CPU into FILE and exit; the\n"
     "program reads media/clouds/deck-diffusion.exr\n"
     "(tools/generate-cloud-scattering)",
     setPath<&Options::generateDeckDiffusion>},
    {"Shaders", "--shader-dir", "DIR", "shaders", "compiled shaders (default: 'shaders' beside the program)", setPath<&Options::shaderDir>},
    {"Shaders", "--shader-source", "DIR", "src",
     "HLSL folder that F8 and file changes reload from\n"
     "(default: the folder the build compiled)",
     setPath<&Options::shaderSource>},
    {"Shaders", "--shader-compiler", "NAME", "vkd3d",
     "hot-reload compiler: auto, d3dcompile, vkd3d, fxc, none\n"
     "(auto: vkd3d-compiler under Wine, else D3DCompile)",
     setShaderCompiler},
    {"About", "--version", "", "", "print the version", setFlag<&Options::version>},
    {"About", "--help", "", "", "print this text", setFlag<&Options::help>, "-h", "/?"},
};

const OptionRow* findOption(const std::string& flag) {
    for (const OptionRow& row : kOptions)
        if (flag == row.name || (!row.alias.empty() && flag == row.alias) || (!row.otherAlias.empty() && flag == row.otherAlias)) return &row;
    return nullptr;
}

}  // namespace

std::vector<CommandLineOption> commandLineOptions() {
    std::vector<CommandLineOption> options;
    for (const OptionRow& row : kOptions) options.push_back({std::string(row.name), std::string(row.value), std::string(row.example)});
    return options;
}

ParsedCommandLine parseCommandLine(const std::vector<std::string>& arguments) {
    ParsedCommandLine result;
    Options& o = result.options;
    Parsing parsing{o};

    for (size_t i = 0; i < arguments.size(); ++i) {
        std::string flag = arguments[i];
        std::optional<std::string> inlineValue;
        if (const auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
            inlineValue = flag.substr(eq + 1);
            flag = flag.substr(0, eq);
        }
        const OptionRow* row = findOption(flag);
        if (!row) {
            result.error = "unknown option '" + arguments[i] + "'";
            return result;
        }
        std::string value;
        if (row->value.empty()) {
            if (inlineValue) {
                result.error = flag + " takes no value";
                return result;
            }
        } else if (inlineValue) {
            value = *inlineValue;
        } else if (i + 1 < arguments.size()) {
            value = arguments[++i];
        } else {
            result.error = flag + " needs a value";
            return result;
        }
        if (const std::string problem = row->apply(parsing, value); !problem.empty()) {
            result.error = flag + ": " + problem;
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
    if (parsing.hardware && parsing.warp) {
        result.error = "--warp and --hardware exclude each other";
        return result;
    }
    const bool warp = parsing.warp || (o.headless && !parsing.hardware && !o.adapter);
    o.driver = warp ? DriverType::Warp : DriverType::Hardware;
    if (warp && o.adapter) {
        result.error = "--warp and --adapter exclude each other";
        return result;
    }
    return result;
}

// The usage text, from the table: each option and its value in a column of 23 characters (the
// help on the next line when they are longer), then its help, heading by heading.
std::string usageText() {
    constexpr size_t kHelpColumn = 25;
    std::string text = "Usage: firmament [options]\n\nReal-time outdoor renderer (Direct3D 11).\n\n";
    std::string_view group;
    for (const OptionRow& row : kOptions) {
        if (row.group != group) {
            group = row.group;
            text += std::string(group) + "\n";
        }
        std::string head = "  " + std::string(row.name);
        if (!row.value.empty()) head += " " + std::string(row.value);
        for (const std::string_view alias : {row.alias, row.otherAlias})
            if (!alias.empty()) head += ", " + std::string(alias);
        text += head;
        if (head.size() + 1 > kHelpColumn) text += "\n" + std::string(kHelpColumn, ' ');
        else text += std::string(kHelpColumn - head.size(), ' ');
        for (const char c : row.help) text += c == '\n' ? "\n" + std::string(kHelpColumn, ' ') : std::string(1, c);
        text += "\n";
    }
    return text + "Exit codes: 0 success, 1 runtime error, 2 bad command line or settings.\n";
}

}  // namespace firmament
