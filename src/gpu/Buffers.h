#pragma once
// Buffers that shaders read and write: structured buffers of fixed-size elements, and the
// eight-uint argument buffers of indirect dispatches and draws, with the views they need.
#include <d3d11.h>
#include <wrl/client.h>

namespace firmament {

using Microsoft::WRL::ComPtr;

struct StructuredBuffer {
    ComPtr<ID3D11Buffer> buffer;
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;  // none for an immutable buffer
};

// `count` elements of `stride` bytes. With `initial` data the buffer is immutable and only
// readable (SRV); without, it is readable and writable (SRV and UAV). `what` names it in errors.
StructuredBuffer createStructuredBuffer(ID3D11Device* device, unsigned count, unsigned stride, const void* initial, const char* what);

// Eight uints, readable and writable by shaders through R32_UINT views (so that shaders can add
// to them atomically), and usable as the arguments of DispatchIndirect and Draw*Indirect.
struct IndirectArguments {
    ComPtr<ID3D11Buffer> buffer;
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;
};

IndirectArguments createIndirectArguments(ID3D11Device* device, const char* what);

}  // namespace firmament
