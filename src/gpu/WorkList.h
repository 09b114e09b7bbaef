#pragma once
// A list of work items, one uint each, that one compute pass appends to and a later pass runs
// over with an indirect dispatch, so that only the listed items cost work (the epipolar
// sampling's ray-marching samples and depth-break pixels). Two buffers, both readable and
// writable by shaders: the items (a structured buffer of `capacity` uints) and the arguments (a
// typed R32_UINT buffer of eight uints, so that shaders can add to it atomically): the x, y, z
// thread groups of the dispatch, the count the appending pass increments, then the x, y, z
// groups of a layered dispatch (a layer per cascade). A small pass turns the count into groups
// (shaders/lightshafts/work_list_arguments.hlsl).
#include "gpu/Buffers.h"

#include <d3d11.h>

namespace firmament {

using Microsoft::WRL::ComPtr;

class WorkList {
public:
    WorkList(ID3D11Device* device, unsigned capacity);

    // Empties the list: the count and the groups to 0.
    void clear(ID3D11DeviceContext* context) const;
    // Runs the compute shader that is bound over the list's groups; `layered`: over the layered
    // arguments (a layer of groups per cascade).
    void dispatch(ID3D11DeviceContext* context, bool layered = false) const;

    ID3D11UnorderedAccessView* itemsUav() const { return items_.uav.Get(); }
    ID3D11UnorderedAccessView* argumentsUav() const { return arguments_.uav.Get(); }
    ID3D11ShaderResourceView* itemsSrv() const { return items_.srv.Get(); }
    ID3D11ShaderResourceView* argumentsSrv() const { return arguments_.srv.Get(); }
    ID3D11Buffer* items() const { return items_.buffer.Get(); }
    ID3D11Buffer* arguments() const { return arguments_.buffer.Get(); }
    unsigned capacity() const { return capacity_; }

private:
    unsigned capacity_;
    StructuredBuffer items_;
    IndirectArguments arguments_;
};

}  // namespace firmament
