#pragma once
// Tables computed on the GPU in units of work of a fraction of a second each on the WARP
// device, so that a window computes one unit per frame and stays responsive, while a headless
// run computes them all at once. A computation lists its units when it is made (a stage, a
// range of rows, slices or layers, and a scattering order) and runs the one it is given; this
// class keeps the list and the progress, makes the scratch textures before the first unit and
// releases them after the last, and logs a run to the end. Both atmosphere models' tables are
// computed this way (YusovPrecomputation, BrunetonPrecomputation).
#include "core/Log.h"
#include "gpu/ShaderLibrary.h"

#include <d3d11.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace firmament {

// Runs `step` until it returns false, logging every 10% of `progress` with the next stage's
// name; then waits for the GPU and logs the time taken.
struct UnitsOfWork {
    std::function<bool()> step;              // runs the next unit; false when none was left
    std::function<double()> progress;        // 0..1
    std::function<std::string()> nextStage;  // what the next unit does
};
void runAllUnits(ID3D11DeviceContext* context, const std::string& logPrefix, const UnitsOfWork& work);

// Blocks until the GPU has finished the work submitted so far.
void waitForGpu(ID3D11DeviceContext* context);

// One unit of work of a stage of type `Stage`.
template <typename Stage>
struct WorkUnit {
    Stage stage;
    unsigned first = 0, end = 1;  // rows, slices or layers of the table the unit computes
    int order = 0;                // the scattering order, for stages that compute one
};

// A set of tables of type `Tables` computed for `Parameters` in units of work of stages `Stage`.
// The model's class makes the tables' textures and lists the units in its constructor, and
// gives the function that runs one unit. `Scratch` holds what only computing needs (scratch
// textures, the shaders' constant buffers): it is made from (device, parameters, tables) before
// the first unit and destroyed after the last, so tables read from files never make it. The
// model's header declares, in the model's namespace, the two functions the log uses:
// std::string stageName(Stage, int order) and std::string describeTables(const Parameters&).
template <typename Stage, typename Parameters, typename Tables, typename Scratch>
class StagedComputation {
public:
    using Unit = WorkUnit<Stage>;
    using RunUnit = void (*)(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit, const Parameters& parameters,
                             const Tables& tables, Scratch& scratch);

    StagedComputation(const StagedComputation&) = delete;
    StagedComputation& operator=(const StagedComputation&) = delete;
    virtual ~StagedComputation() = default;

    // Runs the next unit of work; false once everything has run.
    bool step(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
        if (done()) return false;
        if (next_ == 0) scratch_.emplace(device_, parameters_, tables_);
        runUnit_(context, shaders, units_[next_++], parameters_, tables_, *scratch_);
        if (done()) scratch_.reset();
        return true;
    }
    // One unit, as a window runs them (one a frame so that it stays responsive), logging the
    // start and every 10%.
    void stepInFrame(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
        if (next_ == 0)
            log::info(logPrefix_ + "pre-computing " + describeTables(parameters_) + ": " + std::to_string(units_.size()) +
                      " units of work, one a frame");
        const int before = percentDone();
        if (step(context, shaders) && percentDone() / 10 > before / 10)
            log::info(logPrefix_ + std::to_string(percentDone()) + "%, next: " + currentStage());
    }
    // Runs every remaining unit, logging progress; waits for the GPU at the end.
    void runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
        log::info(logPrefix_ + "pre-computing " + describeTables(parameters_));
        runAllUnits(context, logPrefix_, {[&] { return step(context, shaders); }, [&] { return progress(); }, [&] { return currentStage(); }});
    }

    bool done() const { return next_ >= units_.size(); }
    int percentDone() const { return static_cast<int>(progress() * 100.0); }
    double progress() const { return units_.empty() ? 1.0 : static_cast<double>(next_) / static_cast<double>(units_.size()); }
    std::string currentStage() const { return done() ? "done" : stageName(units_[next_].stage, units_[next_].order); }
    // The tables were filled another way (from files): nothing is left to run.
    void markComplete() {
        next_ = units_.size();
        scratch_.reset();
    }

    const Tables& tables() const { return tables_; }
    const Parameters& parameters() const { return parameters_; }

protected:
    // `logPrefix` starts every log line, for example "atmosphere: ".
    StagedComputation(std::string logPrefix, ID3D11Device* device, const Parameters& parameters, RunUnit runUnit)
        : device_(device), parameters_(parameters), logPrefix_(std::move(logPrefix)), runUnit_(runUnit) {}

    void addUnit(Stage stage, int order = 0) { units_.push_back({stage, 0, 1, order}); }
    // Units of `perUnit` of `count` rows (slices, layers) each, the last one shorter.
    void addSlabs(Stage stage, unsigned count, unsigned perUnit, int order = 0) {
        for (unsigned first = 0; first < count; first += perUnit) units_.push_back({stage, first, first + perUnit < count ? first + perUnit : count, order});
    }

    ID3D11Device* device_;
    Parameters parameters_;
    Tables tables_;

private:
    std::string logPrefix_;
    RunUnit runUnit_;
    std::vector<Unit> units_;
    size_t next_ = 0;
    std::optional<Scratch> scratch_;
};

// The compute stage's bindings for one dispatch: the shader, its inputs from t0 and its outputs
// from u0; and clearing them again, so that the next unit can read what this one wrote.
void bindCompute(ID3D11DeviceContext* context, ID3D11ComputeShader* shader, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                 std::initializer_list<ID3D11UnorderedAccessView*> outputs);
void unbindCompute(ID3D11DeviceContext* context, unsigned inputs, unsigned outputs);
// Thread groups of `size` threads that cover `count` items.
constexpr unsigned groupCount(unsigned count, unsigned size) { return (count + size - 1) / size; }

}  // namespace firmament
