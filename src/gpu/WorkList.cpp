#include "gpu/WorkList.h"

namespace firmament {

WorkList::WorkList(ID3D11Device* device, unsigned capacity)
    : capacity_(capacity > 0 ? capacity : 1),
      items_(createStructuredBuffer(device, capacity_, sizeof(unsigned), nullptr, "work list")),
      arguments_(createIndirectArguments(device, "work list arguments")) {}

void WorkList::clear(ID3D11DeviceContext* context) const {
    const UINT zero[4] = {0, 0, 0, 0};
    context->ClearUnorderedAccessViewUint(arguments_.uav.Get(), zero);
}

void WorkList::dispatch(ID3D11DeviceContext* context, bool layered) const {
    context->DispatchIndirect(arguments_.buffer.Get(), layered ? 4 * sizeof(unsigned) : 0);
}

}  // namespace firmament
