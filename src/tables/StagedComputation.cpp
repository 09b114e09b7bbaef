#include "tables/StagedComputation.h"

#include "core/Log.h"
#include "gpu/Hresult.h"

#include <windows.h>

#include <chrono>
#include <cstdio>

namespace firmament {

void waitForGpu(ID3D11DeviceContext* context) {
    D3D11_QUERY_DESC desc{D3D11_QUERY_EVENT, 0};
    ComPtr<ID3D11Device> device;
    context->GetDevice(&device);
    ComPtr<ID3D11Query> finished;
    check(device->CreateQuery(&desc, &finished), "CreateQuery (event)");
    context->End(finished.Get());
    BOOL signalled = FALSE;
    // S_FALSE while the GPU works; a removed device answers with its error, and waits no more.
    while (context->GetData(finished.Get(), &signalled, sizeof(signalled), 0) == S_FALSE) Sleep(1);
}

void runAllUnits(ID3D11DeviceContext* context, const std::string& logPrefix, const UnitsOfWork& work) {
    const auto start = std::chrono::steady_clock::now();
    int reported = 0;
    while (work.step()) {
        const int percent = static_cast<int>(work.progress() * 100.0);
        if (percent >= reported + 10 || percent >= 100) {
            context->Flush();
            log::info(logPrefix + std::to_string(percent) + "%, next: " + work.nextStage());
            reported = percent;
        }
    }
    waitForGpu(context);  // so that the time said is the pre-computation's
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char what[100];
    std::snprintf(what, sizeof(what), "tables ready in %.2f s", seconds);
    log::info(logPrefix + what);
}

void bindCompute(ID3D11DeviceContext* context, ID3D11ComputeShader* shader, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                 std::initializer_list<ID3D11UnorderedAccessView*> outputs) {
    context->CSSetShader(shader, nullptr, 0);
    context->CSSetShaderResources(0, static_cast<UINT>(inputs.size()), inputs.begin());
    context->CSSetUnorderedAccessViews(0, static_cast<UINT>(outputs.size()), outputs.begin(), nullptr);
}

void unbindCompute(ID3D11DeviceContext* context, unsigned inputs, unsigned outputs) {
    ID3D11ShaderResourceView* noInputs[D3D11_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT] = {};
    ID3D11UnorderedAccessView* noOutputs[D3D11_1_UAV_SLOT_COUNT] = {};
    context->CSSetUnorderedAccessViews(0, outputs, noOutputs, nullptr);
    context->CSSetShaderResources(0, inputs, noInputs);
}

}  // namespace firmament
