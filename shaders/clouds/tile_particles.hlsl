// Light-space tiling (Yusov 2014, "Computing light occlusion: tiling"; docs/clouds.md): every
// particle rasterized from the sun into the light-space grid, its footprint (its bounding sphere's
// circle, widened by a tile so that every tile it touches has a pixel centre inside) appending the
// particle to the list of each tile it covers. Unordered here; clouds/order_tiles.hlsl orders them.
#include "clouds/light_space.hlsli"
#include "clouds/particle_shape.hlsli"

RWTexture2D<uint> tileHeads : register(u1);
RWStructuredBuffer<uint3> tileNodes : register(u2);  // the particle's slot, the next node, asuint(towardSun)

struct TileVertex {
    float4 position : SV_Position;
    nointerpolation uint slot : PARTICLE;
    nointerpolation float3 footprint : FOOTPRINT;  // the centre in the map (-1..1), the radius there (widened)
};

TileVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) {
    TileVertex output;
    output.slot = sortedKeys[instance].y;
    CloudParticle p = particles[output.slot];
    float tile = 2.0 / lightSpace.right.w;
    float radius = max(p.centre.w, p.shape.x) / lightSpace.centre.w + tile;
    float2 centre = lightSpacePosition(p.centre.xyz);
    float2 corner = float2(vertexId & 1u, vertexId >> 1) * 2.0 - 1.0;
    output.footprint = float3(centre, radius - 0.2929 * tile);  // the circle plus a tile's half-diagonal
    output.position = float4(centre + corner * radius, 0.5, 1.0);
    return output;
}

void ps_main(TileVertex input) {
    float n = lightSpace.right.w;
    float2 tileCentre = float2(input.position.x / n * 2.0 - 1.0, 1.0 - input.position.y / n * 2.0);
    if (length(tileCentre - input.footprint.xy) > input.footprint.z) discard;
    uint node;
    InterlockedAdd(tileHeads[uint2(0, uint(n))], 1, node);
    if (node >= uint(lightSpace.sun.w)) return;
    uint previous;
    InterlockedExchange(tileHeads[uint2(input.position.xy)], node, previous);
    tileNodes[node] = uint3(input.slot, previous, asuint(towardSun(particles[input.slot].centre.xyz)));
}
