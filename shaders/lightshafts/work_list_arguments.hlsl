// The dispatch arguments of a pass over a list (samples to march, pixels to correct) from the
// list's count: groups of LIST_GROUP entries, in rows of at most kListRow groups (Direct3D 11
// allows 65535 groups along each axis); then the same with cascadePass.cascades.z layers, for the
// instanced march through the cascades (src/gpu/WorkList.h).
#include "lightshafts/epipolar_inputs.hlsli"

cbuffer CascadePassBuffer : register(b5) { CascadePassConstants cascadePass; };

// Four components per element, though the view is R32_UINT: Wine's translation of a typed
// store of a single constant (z = 1) makes GLSL that does not compile (docs/building.md).
RWBuffer<uint4> argumentsOut : register(u0);  // x, y, z groups, the count; x, y, z groups with layers

[numthreads(1, 1, 1)]
void main() {
    uint count = argumentsOut[3].x;
    uint groups = (count + LIST_GROUP - 1) / LIST_GROUP;
    uint rows = (groups + kListRow - 1) / kListRow;
    argumentsOut[0] = uint4(min(groups, kListRow), 0, 0, 0);
    argumentsOut[1] = uint4(max(rows, 1u), 0, 0, 0);
    argumentsOut[2] = uint4(1, 0, 0, 0);
    argumentsOut[4] = uint4(min(groups, kListRow), 0, 0, 0);
    argumentsOut[5] = uint4(max(rows, 1u), 0, 0, 0);
    argumentsOut[6] = uint4(max(cascadePass.cascades.z, 1u), 0, 0, 0);
}
